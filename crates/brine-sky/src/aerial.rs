//! Aerial perspective: Hoffman & Preetham (2002) extinction and in-scattering with the
//! scattering coefficients of Preetham et al. (1999, Appendix), in an exponential atmosphere.

use std::f64::consts::PI;

use glam::DVec3;

use crate::RGB_WAVELENGTHS_NM;
use crate::error::{SkyError, check};

/// Refractive index of air `n` used by Preetham et al. (1.000278 at 550 nm is closer).
pub const AIR_REFRACTIVE_INDEX: f64 = 1.0003;
/// Molecular number density at sea level `N` (m⁻³).
pub const AIR_NUMBER_DENSITY: f64 = 2.545e25;
/// Depolarisation factor of air `p_n`.
pub const AIR_DEPOLARISATION: f64 = 0.035;
/// Scale height of the molecules, `1/α_molecules` (m).
pub const RAYLEIGH_SCALE_HEIGHT_M: f64 = 8803.0;
/// Scale height of the haze, `1/α_haze` (m).
pub const MIE_SCALE_HEIGHT_M: f64 = 1200.0;
/// Junge exponent `v` of the haze size distribution.
pub const JUNGE_EXPONENT: f64 = 4.0;
/// Henyey–Greenstein asymmetry `g` of the haze (Hoffman & Preetham: 0.7–0.8).
pub const HAZE_ASYMMETRY: f64 = 0.76;

/// Preetham's `K(λ)` of the Mie coefficient at the three RGB wavelengths (680, 550, 450 nm).
const MIE_K_RGB: [f64; 3] = [0.686, 0.678, 0.666];

/// Rayleigh total scattering coefficient of air at sea level,
/// `β_R(λ) = 8π³(n² − 1)²/(3Nλ⁴) · (6 + 3p_n)/(6 − 7p_n)`.
///
/// # Arguments
/// - `wavelength_nm`: λ (nm), `[300, 1000]`.
///
/// # Returns
/// `β_R` (m⁻¹): 1.3563×10⁻⁵ at 550 nm.
///
/// # References
/// Preetham et al. 1999, Appendix A.3; docs/equations.md §8.
pub fn rayleigh_beta(wavelength_nm: f64) -> f64 {
    let n2m1 = AIR_REFRACTIVE_INDEX * AIR_REFRACTIVE_INDEX - 1.0;
    let lambda = wavelength_nm * 1e-9;
    let king = (6.0 + 3.0 * AIR_DEPOLARISATION) / (6.0 - 7.0 * AIR_DEPOLARISATION);
    8.0 * PI.powi(3) * n2m1 * n2m1 / (3.0 * AIR_NUMBER_DENSITY * lambda.powi(4)) * king
}

/// Mie (haze) total scattering coefficient at sea level,
/// `β_M(λ, T) = 0.434 c π (2π/λ)^{v−2} K(λ) · 0.01^{v−3}`, `c = (0.6544 T − 0.6510)×10⁻¹⁶`,
/// `v = 4` (the `0.01^{v−3}` is the authors' unit correction of `c`).
///
/// # Arguments
/// - `wavelength_nm`: λ (nm), `[300, 1000]`.
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `k`: Preetham's `K(λ)`, about 0.67–0.69 over the visible.
///
/// # Returns
/// `β_M` (m⁻¹): 7.936×10⁻⁵ at 550 nm for `T = 2`, `K = 0.678`.
///
/// # References
/// Preetham et al. 1999, Appendix A.3; the authors' `RiAtmConstants.C`; docs/equations.md §8.
pub fn mie_beta(wavelength_nm: f64, turbidity: f64, k: f64) -> f64 {
    let c = (0.6544 * turbidity - 0.6510) * 1e-16;
    let lambda = wavelength_nm * 1e-9;
    0.434 * c * PI * (2.0 * PI / lambda).powf(JUNGE_EXPONENT - 2.0) * k * 0.01f64.powf(JUNGE_EXPONENT - 3.0)
}

/// Angular distribution of light scattered by molecules (much smaller than the wavelength),
/// normalised over the sphere: `Φ_R(θ) = 3/(16π)(1 + cos²θ)`.
///
/// # Arguments
/// - `cos_theta`: cosine of the scattering angle `θ` between the incident and scattered
///   directions, `[−1, 1]`.
///
/// # Returns
/// `Φ_R` (sr⁻¹), `[3/(16π), 3/(8π)]` = `[0.0597, 0.119]`; `∫ Φ_R dω = 1`.
///
/// # References
/// Hoffman & Preetham 2002; docs/equations.md §8 (Chen et al.'s `3/π` is an erratum).
pub fn rayleigh_phase(cos_theta: f64) -> f64 {
    3.0 / (16.0 * PI) * (1.0 + cos_theta * cos_theta)
}

/// Angular distribution of light scattered by haze particles, a one-parameter forward lobe
/// normalised over the sphere: `Φ_HG(θ) = (1 − g²)/(4π (1 + g² − 2g cos θ)^{3/2})`.
///
/// # Arguments
/// - `cos_theta`: cosine of the scattering angle `θ`, `[−1, 1]`.
/// - `g`: asymmetry `⟨cos θ⟩`, `(−1, 1)` (0 isotropic; haze 0.7–0.8, [`HAZE_ASYMMETRY`]).
///
/// # Returns
/// `Φ_HG` (sr⁻¹), `> 0`: `1/(4π)` for `g = 0`, `(1 + g)/(4π(1 − g)²)` forward; `∫ Φ_HG dω = 1`.
///
/// # References
/// Henyey & Greenstein 1941, Astrophys. J. 93:70; docs/equations.md §8 (Hoffman & Preetham and Chen et al.
/// print `(1 − g)²`, which integrates to `(1 − g)/(1 + g)`, not 1).
pub fn henyey_greenstein(cos_theta: f64, g: f64) -> f64 {
    (1.0 - g * g) / (4.0 * PI * (1.0 + g * g - 2.0 * g * cos_theta).powf(1.5))
}

/// Optical depth of an exponential species along a straight segment,
/// `τ = β₀ e^{−α h₀} (1 − e^{−α s cos θ})/(α cos θ)` (`→ β₀ e^{−α h₀} s` as `cos θ → 0`).
///
/// # Arguments
/// - `beta0`: sea-level coefficient (m⁻¹).
/// - `scale_height_m`: `1/α` (m).
/// - `height_m`: start height `h₀` (m).
/// - `cos_theta`: cosine of the segment's zenith angle (`d_y`), `[−1, 1]`.
/// - `length_m`: `s ≥ 0` (m).
///
/// # Returns
/// `τ ≥ 0` (dimensionless).
///
/// # References
/// Preetham et al. 1999, Appendix A.3 (flat exponential atmosphere); docs/equations.md §8.
pub fn optical_depth(beta0: f64, scale_height_m: f64, height_m: f64, cos_theta: f64, length_m: f64) -> f64 {
    let x = length_m * cos_theta / scale_height_m;
    let above = -height_m / scale_height_m;
    if x.abs() < 1e-8 {
        // (1 − e^{−x})/x → 1 − x/2 for small |x|.
        beta0 * above.exp() * length_m * (1.0 - 0.5 * x)
    } else if x > 0.0 {
        // Upward: e^{−x} ≤ 1, no overflow.
        beta0 * above.exp() * length_m * (-(-x).exp_m1() / x)
    } else {
        // Downward: e^{−αh₀}(e^{|x|} − 1) = e^{−αh₁} − e^{−αh₀} with h₁ = h₀ + s cos θ the end's
        // height. Written so, an eye far above the air (e^{−αh₀} underflowing to 0 while e^{|x|}
        // overflows) gives the finite depth of the air below instead of 0 × ∞. The exponent is
        // capped where e^{…} would overflow (an end hundreds of kilometres below sea level).
        let end = (above - x).min(EXP_MAX_ARGUMENT);
        beta0 * length_m * (end.exp() - above.exp()) / -x
    }
}

/// Largest argument of `exp` that stays finite in f64 (`ln(f64::MAX)` ≈ 709.78, rounded down).
const EXP_MAX_ARGUMENT: f64 = 709.0;

/// Extinction and in-scattering of a segment of air.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AerialPerspective {
    /// `F_ex` per channel, `(0, 1]`.
    pub extinction: DVec3,
    /// `L_in` per channel, linear sRGB radiance (kcd m⁻²).
    pub inscatter: DVec3,
}

impl AerialPerspective {
    /// The radiance of an object seen through the segment, `L = L₀ ⊙ F_ex + L_in`.
    ///
    /// # Arguments
    /// - `l0`: radiance leaving the object (linear sRGB, kcd m⁻²), `≥ 0`.
    ///
    /// # Returns
    /// `L` at the eye (linear sRGB, kcd m⁻²).
    ///
    /// # References
    /// Hoffman & Preetham 2002; Chen et al. 2007, Eq. 2.
    pub fn apply(&self, l0: DVec3) -> DVec3 {
        l0 * self.extinction + self.inscatter
    }
}

/// Sea-level scattering coefficients for one turbidity, per RGB channel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scattering {
    /// `β_R` at 680, 550, 450 nm (m⁻¹).
    pub rayleigh: DVec3,
    /// `β_M` at 680, 550, 450 nm (m⁻¹).
    pub mie: DVec3,
}

impl Scattering {
    /// The sea-level coefficients for turbidity `T`: `β_R(λ)` ([`rayleigh_beta`]) and
    /// `β_M(λ, T)` ([`mie_beta`] with Preetham's `K(λ)` = 0.686, 0.678, 0.666) at the three
    /// [`RGB_WAVELENGTHS_NM`] (680, 550, 450 nm).
    ///
    /// # Arguments
    /// - `turbidity`: `T`, `[1.7, 10]` (Preetham's domain).
    ///
    /// # Returns
    /// The [`Scattering`] coefficients (m⁻¹).
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming `turbidity` outside `[1.7, 10]` or not finite.
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.3; Hoffman & Preetham 2002.
    pub fn new(turbidity: f64) -> Result<Self, SkyError> {
        let turbidity = check("turbidity", turbidity, (1.7..=10.0).contains(&turbidity), "[1.7, 10]")?;
        let [r, g, b] = RGB_WAVELENGTHS_NM;
        Ok(Self {
            rayleigh: DVec3::new(rayleigh_beta(r), rayleigh_beta(g), rayleigh_beta(b)),
            mie: DVec3::new(
                mie_beta(r, turbidity, MIE_K_RGB[0]),
                mie_beta(g, turbidity, MIE_K_RGB[1]),
                mie_beta(b, turbidity, MIE_K_RGB[2]),
            ),
        })
    }

    /// Optical depths `(τ_R, τ_M)` per channel of the segment from height `h₀` in direction `d`
    /// over `s`: `τ = β₀ e^{−h₀/H}(1 − e^{−s d_y/H})/(d_y/H)` for each species ([`optical_depth`],
    /// `H` = 8803 m and 1200 m).
    ///
    /// # Arguments
    /// - `height_m`: `h₀` (m).
    /// - `direction`: unit direction of the segment (its `y` is `cos θ`).
    /// - `length_m`: `s ≥ 0` (m).
    ///
    /// # Returns
    /// `(τ_R, τ_M)` per RGB channel (dimensionless, `≥ 0`).
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.3.
    pub fn optical_depths(&self, height_m: f64, direction: DVec3, length_m: f64) -> (DVec3, DVec3) {
        let c = direction.y;
        let fr = optical_depth(1.0, RAYLEIGH_SCALE_HEIGHT_M, height_m, c, length_m);
        let fm = optical_depth(1.0, MIE_SCALE_HEIGHT_M, height_m, c, length_m);
        (self.rayleigh * fr, self.mie * fm)
    }

    /// Hoffman & Preetham's aerial perspective for a segment of length `s` from the eye at
    /// height `h₀` in unit direction `d`, lit by point sources of irradiance `E_k` in
    /// directions `l_k` and an isotropic ambient radiance `L̄`:
    ///
    /// `F_ex = exp(−τ_R − τ_M)`,
    /// `L_in = (1 − F_ex) ⊙ [Σ_k E_k ⊙ (τ_R Φ_R(θ_k) + τ_M Φ_HG(θ_k))/(τ_R + τ_M) + L̄]`,
    /// `cos θ_k = d · l_k`.
    ///
    /// With a homogeneous atmosphere this is Hoffman & Preetham's closed form; with the two
    /// exponential species it uses the path-averaged phase mixture (exact when both species have
    /// the same profile along the path). The ambient term (skylight scattered isotropically,
    /// single scattering) is Brine's addition so that twilight and night air is not black.
    ///
    /// # Arguments
    /// - `height_m`: eye height `h₀` (m), ≥ 0 in practice (the formula holds for any).
    /// - `direction`: unit view direction (eye → point).
    /// - `length_m`: `s ≥ 0` (m).
    /// - `lights`: `(direction toward the source, irradiance on a plane facing it, klx)` pairs.
    /// - `ambient`: `L̄`, the sky radiance averaged over the whole sphere (kcd m⁻²).
    ///
    /// # Returns
    /// The [`AerialPerspective`]; `F_ex ∈ (0, 1]` per channel, `L_in ≥ 0`.
    ///
    /// # References
    /// Hoffman N., Preetham A.J. 2002, "Rendering outdoor light scattering in real time", GDC;
    /// Chen et al. 2007, Eq. 2–8 (with the reference's errata); Preetham et al. 1999, Appendix A.3.
    pub fn aerial_perspective(
        &self,
        height_m: f64,
        direction: DVec3,
        length_m: f64,
        lights: &[(DVec3, DVec3)],
        ambient: DVec3,
    ) -> AerialPerspective {
        let (tr, tm) = self.optical_depths(height_m, direction, length_m.max(0.0));
        let tau = tr + tm;
        let extinction = (-tau).exp();
        let one_minus = DVec3::ONE - extinction;
        let mut source = ambient;
        if tau.min_element() > 0.0 && tau.is_finite() {
            for &(l, e) in lights {
                let c = direction.dot(l).clamp(-1.0, 1.0);
                let phase = (tr * rayleigh_phase(c) + tm * henyey_greenstein(c, HAZE_ASYMMETRY)) / tau;
                source += e * phase;
            }
        }
        // Optical depths and sources are ≥ 0: the clamp absorbs rounding only.
        debug_assert!(tau.min_element() >= -1e-12 && source.min_element() >= -1e-12, "τ = {tau}, source = {source}");
        AerialPerspective { extinction, inscatter: (one_minus * source).max(DVec3::ZERO) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The reference values are printed to 5 significant digits.
    const ORACLE: f64 = 1e-4;
    /// 3/(16π) = 0.0596831 and 1/(4π) = 0.0795775 printed to 6 significant digits.
    const SIX_DIGITS: f64 = 1e-6;
    /// Midpoint rule in μ over 20 000 cells: < 10⁻⁶ for Rayleigh, < 10⁻⁴ for the g = 0.76 lobe.
    const QUADRATURE_RAYLEIGH: f64 = 1e-6;
    const QUADRATURE_HG: f64 = 1e-4;
    /// Closed forms evaluated in double precision.
    const ROUNDING: f64 = 1e-12;
    /// The optical depth at cos θ = 10⁻⁹ against the horizontal limit: the first-order term
    /// `α s cos θ/2` is 2×10⁻⁵ × 10⁻⁹ here; 10⁻⁶ leaves rounding room.
    const GRAZING_LIMIT: f64 = 1e-6;
    /// Depths at cos θ = ±10⁻⁶ over 50 km (|x| = 4.2×10⁻⁵) differ by about |x| to first order.
    const ACROSS_HORIZONTAL: f64 = 1e-4;

    #[test]
    fn coefficient_oracles() {
        assert_relative_eq!(rayleigh_beta(550.0), 1.3563e-5, max_relative = ORACLE);
        assert_relative_eq!(rayleigh_beta(450.0), 3.0266e-5, max_relative = ORACLE);
        assert_relative_eq!(rayleigh_beta(650.0), 6.9526e-6, max_relative = ORACLE);
        assert_relative_eq!(mie_beta(550.0, 2.0, 0.678), 7.936e-5, max_relative = ORACLE);
        assert_relative_eq!(rayleigh_phase(0.0), 0.0596831, max_relative = SIX_DIGITS);
        assert_relative_eq!(henyey_greenstein(0.5, 0.0), 0.0795775, max_relative = SIX_DIGITS);
    }

    #[test]
    fn phase_functions_integrate_to_one() {
        // Midpoint rule in μ = cos θ over 20 000 cells: error < 10⁻⁶ for these smooth lobes.
        let n = 20_000;
        let (mut r, mut h) = (0.0, 0.0);
        for i in 0..n {
            let mu = -1.0 + (i as f64 + 0.5) * 2.0 / n as f64;
            r += rayleigh_phase(mu) * 2.0 * PI * 2.0 / n as f64;
            h += henyey_greenstein(mu, HAZE_ASYMMETRY) * 2.0 * PI * 2.0 / n as f64;
        }
        assert!((r - 1.0).abs() < QUADRATURE_RAYLEIGH && (h - 1.0).abs() < QUADRATURE_HG, "{r} {h}");
    }

    #[test]
    fn optical_depth_limits() {
        // Horizontal: τ = β₀ e^{−h/H} s. Vertical to infinity: τ = β₀ H e^{−h/H}.
        let t = optical_depth(2.0, 1000.0, 0.0, 0.0, 500.0);
        assert_relative_eq!(t, 1000.0, max_relative = ROUNDING);
        let t = optical_depth(1e-5, 8803.0, 100.0, 1.0, 1e9);
        assert_relative_eq!(t, 1e-5 * 8803.0 * (-100.0f64 / 8803.0).exp(), max_relative = ROUNDING);
        // Continuity through cos θ = 0.
        let a = optical_depth(1e-5, 1200.0, 10.0, 1e-9, 5e4);
        let b = optical_depth(1e-5, 1200.0, 10.0, 0.0, 5e4);
        assert_relative_eq!(a, b, max_relative = GRAZING_LIMIT);
    }

    #[test]
    fn an_eye_far_above_the_air_sees_the_air_below_it() {
        // From 900 km down to the sea at 23.7° below the horizon: the whole column of air below
        // the eye, τ = β₀ H (1 − e^{−h₀/H})/sin(23.7°) → β₀ H / sin(23.7°), not 0 × ∞ = NaN.
        let h0 = 9e5;
        let sin_dip = 23.7f64.to_radians().sin();
        let s = h0 / sin_dip;
        for scale in [8803.0, 1200.0] {
            let t = optical_depth(1e-5, scale, h0, -sin_dip, s);
            assert_relative_eq!(t, 1e-5 * scale / sin_dip, max_relative = ROUNDING);
        }
        // And the downward branch agrees with the small-|x| and upward forms where they meet.
        let a = optical_depth(1e-5, 1200.0, 10.0, -1e-6, 5e4);
        let b = optical_depth(1e-5, 1200.0, 10.0, 1e-6, 5e4);
        assert_relative_eq!(a, b, max_relative = ACROSS_HORIZONTAL);
        let sc = Scattering::new(3.0).unwrap();
        let d = DVec3::new(0.0, -sin_dip, (1.0 - sin_dip * sin_dip).sqrt());
        let ap = sc.aerial_perspective(h0, d, s, &[(DVec3::Y, DVec3::splat(100.0))], DVec3::splat(1.0));
        assert!(ap.extinction.is_finite() && ap.inscatter.is_finite(), "{ap:?}");
        assert!(ap.extinction.min_element() > 0.0 && ap.extinction.max_element() < 1.0, "{ap:?}");
    }

    #[test]
    fn bad_turbidity_is_named() {
        for t in [1.0, 12.0, f64::NAN] {
            let e = Scattering::new(t).unwrap_err();
            assert!(e.to_string().contains("turbidity"), "{e}");
        }
        assert!(Scattering::new(1.7).is_ok() && Scattering::new(10.0).is_ok());
    }

    #[test]
    fn homogeneous_limit_is_hoffman_preetham() {
        // A horizontal ray at constant height sees a homogeneous medium: L_in must be the closed
        // form [β_R Φ_R + β_M Φ_M]/(β_R + β_M) E (1 − e^{−(β_R+β_M)s}).
        let sc = Scattering::new(3.0).unwrap();
        let d = DVec3::X;
        let sun = DVec3::new(0.6, 0.0, 0.8);
        let e = DVec3::new(80.0, 90.0, 100.0);
        let ap = sc.aerial_perspective(0.0, d, 20_000.0, &[(sun, e)], DVec3::ZERO);
        let c = d.dot(sun);
        let bsum = sc.rayleigh + sc.mie;
        let want = (sc.rayleigh * rayleigh_phase(c) + sc.mie * henyey_greenstein(c, HAZE_ASYMMETRY)) / bsum
            * e
            * (DVec3::ONE - (-bsum * 20_000.0).exp());
        for k in 0..3 {
            assert_relative_eq!(ap.inscatter[k], want[k], max_relative = ROUNDING);
        }
    }
}
