//! Jensen, Marschner, Levoy & Hanrahan (2001): the dipole diffusion approximation of sub-surface
//! scattering, as Li Ying et al. (2018) §3.3 use it for sea water.

use std::f64::consts::PI;

use crate::error::{OpticsError, check};
use crate::fresnel_dielectric;

/// Jensen's fit of the diffuse Fresnel reflectance inside a medium of relative index `η`
/// (Egan & Hilgeman 1973):
/// `F_dr = −1.440/η² + 0.710/η + 0.668 + 0.0636 η` for `η ≥ 1`,
/// `F_dr = −0.4399 + 0.7099/η − 0.3319/η² + 0.0636/η³` for `η < 1`.
///
/// # Arguments
/// - `eta`: index of the scattering medium relative to the outside, `(0, ∞)`; the fits are
///   accurate for about `[0.5, 2]` (against [`crate::hemispherical_fresnel_reflectance`]: within
///   0.01 absolute for `η ∈ [1, 2]`, see the tests).
///
/// # Returns
/// `F_dr` (dimensionless): 0.44476 at 1.3, 0.47236 at 1.33.
///
/// # References
/// Jensen et al. 2001, "A practical model for subsurface light transport", SIGGRAPH 511–518,
/// §2.3 (the `η ≥ 1` branch); Egan W., Hilgeman T. 1973 (both branches, as quoted by Donner &
/// Jensen 2005, "Light diffusion in multi-layered translucent materials"); docs/equations.md §12.
pub fn diffuse_fresnel_reflectance(eta: f64) -> f64 {
    if eta >= 1.0 {
        -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta
    } else {
        -0.4399 + 0.7099 / eta - 0.3319 / (eta * eta) + 0.0636 / (eta * eta * eta)
    }
}

/// Optical parameters of a dipole material at one wavelength (or one colour channel), with its
/// derived constants. Lengths in any unit, used consistently (coefficients per that unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DipoleMaterial {
    sigma_a: f64,
    sigma_s_prime: f64,
    eta: f64,
    sigma_t_prime: f64,
    alpha_prime: f64,
    sigma_tr: f64,
    f_dr: f64,
    a: f64,
    z_r: f64,
    z_v: f64,
}

impl DipoleMaterial {
    /// A material from its absorption `σ_a`, scattering `σ_s`, phase-function mean cosine `g` and
    /// relative index `η`: `σ′_s = σ_s(1 − g)`, `σ′_t = σ_a + σ′_s`, `α′ = σ′_s/σ′_t`,
    /// `σ_tr = √(3 σ_a σ′_t)`, `D = 1/(3σ′_t)`, `A = (1 + F_dr)/(1 − F_dr)`, `z_r = 1/σ′_t`,
    /// `z_v = z_r + 4AD`.
    ///
    /// # Arguments
    /// - `sigma_a`: absorption coefficient (length⁻¹), `≥ 0`.
    /// - `sigma_s`: scattering coefficient (length⁻¹), `≥ 0`, with `σ_a + σ_s(1 − g) > 0`.
    /// - `g`: mean cosine of the phase function, `(−1, 1)`.
    /// - `eta`: index of the medium relative to the outside, `[0.5, 2.5]` (1.33 for water seen
    ///   from air; Li Ying et al. print 0.74).
    ///
    /// # Returns
    /// The material with its derived constants `σ′_s`, `σ′_t`, `α′`, `σ_tr` (length⁻¹ except
    /// `α′`), `F_dr`, `A` (dimensionless), `z_r`, `z_v` (length).
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming the parameter.
    ///
    /// # References
    /// Jensen et al. 2001, Eq. 4–5 and §2.3–2.4; docs/equations.md §12 (with the Li Ying et al. 2018
    /// errata: `z_r = 1/σ′_t`, not 1; `A` a quotient).
    pub fn new(sigma_a: f64, sigma_s: f64, g: f64, eta: f64) -> Result<Self, OpticsError> {
        check("sigma_a", sigma_a, sigma_a >= 0.0, "[0, ∞) per unit length")?;
        check("sigma_s", sigma_s, sigma_s >= 0.0, "[0, ∞) per unit length")?;
        check("g", g, g > -1.0 && g < 1.0, "(-1, 1)")?;
        check("eta", eta, (0.5..=2.5).contains(&eta), "[0.5, 2.5]")?;
        let sigma_s_prime = sigma_s * (1.0 - g);
        let sigma_t_prime = sigma_a + sigma_s_prime;
        check("sigma_a + sigma_s (1 - g)", sigma_t_prime, sigma_t_prime > 0.0, "(0, ∞) per unit length")?;
        let f_dr = diffuse_fresnel_reflectance(eta);
        let a = (1.0 + f_dr) / (1.0 - f_dr);
        let z_r = 1.0 / sigma_t_prime;
        let d = 1.0 / (3.0 * sigma_t_prime);
        Ok(Self {
            sigma_a,
            sigma_s_prime,
            eta,
            sigma_t_prime,
            alpha_prime: sigma_s_prime / sigma_t_prime,
            sigma_tr: (3.0 * sigma_a * sigma_t_prime).sqrt(),
            f_dr,
            a,
            z_r,
            z_v: z_r + 4.0 * a * d,
        })
    }

    /// Absorption `σ_a` (length⁻¹).
    pub fn sigma_a(&self) -> f64 {
        self.sigma_a
    }
    /// Reduced scattering `σ′_s` (length⁻¹).
    pub fn sigma_s_prime(&self) -> f64 {
        self.sigma_s_prime
    }
    /// Reduced extinction `σ′_t` (length⁻¹).
    pub fn sigma_t_prime(&self) -> f64 {
        self.sigma_t_prime
    }
    /// Reduced albedo `α′`.
    pub fn alpha_prime(&self) -> f64 {
        self.alpha_prime
    }
    /// Effective transport coefficient `σ_tr` (length⁻¹).
    pub fn sigma_tr(&self) -> f64 {
        self.sigma_tr
    }
    /// Diffuse Fresnel reflectance `F_dr`.
    pub fn f_dr(&self) -> f64 {
        self.f_dr
    }
    /// Boundary coefficient `A`.
    pub fn a(&self) -> f64 {
        self.a
    }
    /// Depth of the real source `z_r` (length).
    pub fn z_r(&self) -> f64 {
        self.z_r
    }
    /// Height of the virtual source `z_v` (length).
    pub fn z_v(&self) -> f64 {
        self.z_v
    }
    /// Relative index `η`.
    pub fn eta(&self) -> f64 {
        self.eta
    }

    /// Diffuse reflectance profile of the dipole,
    /// `R_d(r) = (α′/4π) [z_r (1 + σ_tr d_r) e^{−σ_tr d_r}/d_r³ + z_v (1 + σ_tr d_v) e^{−σ_tr d_v}/d_v³]`,
    /// `d_r = √(r² + z_r²)`, `d_v = √(r² + z_v²)`.
    ///
    /// # Arguments
    /// - `r`: distance between the points of entry and exit (length), `≥ 0` (sign ignored).
    ///
    /// # Returns
    /// `R_d` (length⁻²), finite and `≥ 0`.
    ///
    /// # References
    /// Jensen et al. 2001, Eq. 4; Li Ying et al. 2018 Eq. 9; docs/equations.md §12.
    pub fn diffuse_reflectance(&self, r: f64) -> f64 {
        let r2 = r * r;
        let term = |z: f64| {
            let d = (r2 + z * z).sqrt();
            z * (1.0 + self.sigma_tr * d) * (-self.sigma_tr * d).exp() / (d * d * d)
        };
        self.alpha_prime / (4.0 * PI) * (term(self.z_r) + term(self.z_v))
    }

    /// Total diffuse reflectance `R = ∫₀^∞ R_d(r) 2πr dr =
    /// (α′/2)(1 + e^{−(4/3) A √(3(1 − α′))}) e^{−√(3(1 − α′))}`.
    ///
    /// # Returns
    /// `R` (dimensionless), `[0, 1]`.
    ///
    /// # References
    /// Jensen et al. 2001, Eq. 7 (the paper's `R_d` integral); docs/equations.md §12.
    pub fn total_diffuse_reflectance(&self) -> f64 {
        let s = (3.0 * (1.0 - self.alpha_prime)).sqrt();
        0.5 * self.alpha_prime * (1.0 + (-(4.0 / 3.0) * self.a * s).exp()) * (-s).exp()
    }

    /// Diffuse reflectance from entry points farther than `r0`:
    /// `∫_{r0}^∞ R_d(r) 2πr dr = (α′/2) [z_r e^{−σ_tr u_r}/u_r + z_v e^{−σ_tr u_v}/u_v]`,
    /// `u = √(r0² + z²)` (exact: `d/du(−e^{−σu}/u) = (1 + σu)e^{−σu}/u²`). At `r0 = 0` it is
    /// [`Self::total_diffuse_reflectance`].
    ///
    /// # Arguments
    /// - `r0`: inner radius (length), `≥ 0`.
    ///
    /// # Returns
    /// The fraction (dimensionless), `[0, R]`, decreasing in `r0`.
    ///
    /// # References
    /// Integral of Jensen et al. 2001 Eq. 4 (derived, Brine).
    pub fn diffuse_reflectance_beyond(&self, r0: f64) -> f64 {
        let r2 = r0 * r0;
        let term = |z: f64| {
            let u = (r2 + z * z).sqrt();
            z * (-self.sigma_tr * u).exp() / u
        };
        0.5 * self.alpha_prime * (term(self.z_r) + term(self.z_v))
    }

    /// The diffusion term of the BSSRDF with Fresnel transmission in and out,
    /// `S_d = (1/π) F_t(η, ω_i) R_d(‖x_i − x_o‖) F_t(η, ω_o)`, `F_t = 1 − F` from the outside
    /// (index 1) into the medium (index `η`).
    ///
    /// # Arguments
    /// - `r`: distance `‖x_i − x_o‖` (length), `≥ 0`.
    /// - `cos_theta_i`, `cos_theta_o`: cosines of the incident and outgoing directions to the
    ///   surface normal, `[0, 1]`.
    ///
    /// # Returns
    /// `S_d` (length⁻² sr⁻¹).
    ///
    /// # References
    /// Jensen et al. 2001, Eq. 5; Li Ying et al. 2018 Eq. 10; docs/equations.md §12.
    pub fn bssrdf(&self, r: f64, cos_theta_i: f64, cos_theta_o: f64) -> f64 {
        let t_i = 1.0 - fresnel_dielectric(cos_theta_i, 1.0, self.eta);
        let t_o = 1.0 - fresnel_dielectric(cos_theta_o, 1.0, self.eta);
        t_i * self.diffuse_reflectance(r) * t_o / PI
    }

    /// Radiance leaving a flat, uniformly lit surface of this material (the BSSRDF integrated
    /// over the whole plane of entry points for a distant source):
    /// `L_o = F_t(ω_i) F_t(ω_o) E cos θ_i R / π`, `R` = [`Self::total_diffuse_reflectance`].
    ///
    /// # Arguments
    /// - `irradiance_normal`: irradiance of the source on a plane facing it, `E`, any unit, `≥ 0`.
    /// - `cos_theta_i`, `cos_theta_o`: cosines of the source and view directions to the normal.
    ///
    /// # Returns
    /// `L_o` in the unit of `E` per steradian.
    ///
    /// # References
    /// Jensen et al. 2001, Eq. 5 integrated over area and Li Ying et al. 2018 Eq. 11 for a
    /// directional source (derived, Brine).
    pub fn radiance_uniform(&self, irradiance_normal: f64, cos_theta_i: f64, cos_theta_o: f64) -> f64 {
        let t_i = 1.0 - fresnel_dielectric(cos_theta_i, 1.0, self.eta);
        let t_o = 1.0 - fresnel_dielectric(cos_theta_o, 1.0, self.eta);
        t_i * t_o * irradiance_normal * cos_theta_i.max(0.0) * self.total_diffuse_reflectance() / PI
    }

    /// Radiance seen through a thin wave crest of thickness `d` lit from behind.
    ///
    /// **Approximation (Brine's):** light enters the sunlit face of the crest and leaves the
    /// viewed face after crossing at least `d` of water; it is modelled as the semi-infinite
    /// dipole's diffuse reflectance from entry points farther than `d` from the exit point,
    /// `L_o = F_t(ω_i) F_t(ω_o) E cos θ_i ∫_d^∞ R_d 2πr dr / π` (see
    /// [`Self::diffuse_reflectance_beyond`]). It ignores the crest's curvature and the second
    /// boundary (a slab needs the multipole of Donner & Jensen 2005), so it is a shading cue, not
    /// a transport solution: it decays like `e^{−σ_tr d}/d` for thick crests, as diffusion does.
    ///
    /// # Arguments
    /// - `irradiance_normal`: sun irradiance on a plane facing it, any unit, `≥ 0`.
    /// - `cos_theta_i`: cosine of the sun to the sunlit face's normal, `[0, 1]`.
    /// - `cos_theta_o`: cosine of the view to the viewed face's normal, `[0, 1]`.
    /// - `thickness`: crest thickness along the refracted sun ray (length), `≥ 0`.
    ///
    /// # Returns
    /// The radiance in the unit of `irradiance_normal` per steradian.
    ///
    /// # References
    /// Jensen et al. 2001 Eq. 4–5; Li Ying et al. 2018 §3.3 (sub-surface light through waves).
    pub fn crest_radiance(&self, irradiance_normal: f64, cos_theta_i: f64, cos_theta_o: f64, thickness: f64) -> f64 {
        let t_i = 1.0 - fresnel_dielectric(cos_theta_i, 1.0, self.eta);
        let t_o = 1.0 - fresnel_dielectric(cos_theta_o, 1.0, self.eta);
        t_i * t_o * irradiance_normal * cos_theta_i.max(0.0) * self.diffuse_reflectance_beyond(thickness.max(0.0)) / PI
    }
}

/// One of the three sub-surface parameter sets of Li Ying et al. (2018), Table 3 (no units
/// printed; one value per R, G, B channel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiYingParameters {
    /// Absorption `σ_a` per channel (R, G, B).
    pub sigma_a: [f64; 3],
    /// Scattering `σ_s` per channel (R, G, B).
    pub sigma_s: [f64; 3],
    /// Irradiance per unit area `Φ`.
    pub phi: f64,
    /// `(g, η)` where legible: set 1 prints `g = 0.5`, `η = 0.74`; the digits of sets 2–3 are
    /// unreadable in the source ("12"), so `None`.
    pub g_eta: Option<(f64, f64)>,
}

impl LiYingParameters {
    /// Parameter set `1`, `2` or `3` of Li Ying et al. 2018, Table 3 (as extracted; equation
    /// equations.md §12 flags the extraction as ambiguous): `σ_a` = (0.7, 0.9, 1.4), (0.12, 0.89, 1.2),
    /// (0.12, 1.02, 1.2); `σ_s` = (0.2, 0.38, 1) for all; `Φ` = 1, 63.7, 63.7.
    ///
    /// # Arguments
    /// - `set`: the column of Table 3, `1`, `2` or `3`.
    ///
    /// # Returns
    /// The set's `σ_a`, `σ_s` per R, G, B channel (per unit length; the paper prints no unit),
    /// `Φ`, and `(g, η)` where legible (set 1: `(0.5, 0.74)`; `None` for sets 2–3).
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] for another set number.
    ///
    /// # References
    /// Li Ying et al. 2018, "Real-time rendering of large-scale realistic ocean scenes driven by
    /// time and space" (in Chinese), Table 3; docs/equations.md §12.
    pub fn table3(set: u8) -> Result<Self, OpticsError> {
        let sigma_s = [0.2, 0.38, 1.0];
        match set {
            1 => Ok(Self { sigma_a: [0.7, 0.9, 1.4], sigma_s, phi: 1.0, g_eta: Some((0.5, 0.74)) }),
            2 => Ok(Self { sigma_a: [0.12, 0.89, 1.2], sigma_s, phi: 63.7, g_eta: None }),
            3 => Ok(Self { sigma_a: [0.12, 1.02, 1.2], sigma_s, phi: 63.7, g_eta: None }),
            _ => Err(OpticsError::OutOfRange(brine_core::OutOfRange {
                name: "set",
                value: f64::from(set),
                range: "1, 2 or 3",
            })),
        }
    }

    /// The three channel materials with the given `g` and `η` (use [`Self::g_eta`] where the
    /// paper prints them).
    ///
    /// # Arguments
    /// - `g`: mean cosine of the phase function, `(−1, 1)`.
    /// - `eta`: relative index, `[0.5, 2.5]`.
    ///
    /// # Returns
    /// `[R, G, B]` materials, each [`DipoleMaterial::new`]`(σ_a[c], σ_s[c], g, η)`.
    ///
    /// # Errors
    /// As [`DipoleMaterial::new`].
    ///
    /// # References
    /// Li Ying et al. 2018, Table 3; Jensen et al. 2001 §2.4.
    pub fn materials(&self, g: f64, eta: f64) -> Result<[DipoleMaterial; 3], OpticsError> {
        Ok([
            DipoleMaterial::new(self.sigma_a[0], self.sigma_s[0], g, eta)?,
            DipoleMaterial::new(self.sigma_a[1], self.sigma_s[1], g, eta)?,
            DipoleMaterial::new(self.sigma_a[2], self.sigma_s[2], g, eta)?,
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Oracle values of docs/equations.md are printed to 5 significant digits.
    const ORACLE: f64 = 1e-4;

    #[test]
    fn f_dr_and_a_oracles() {
        for (eta, f, a) in [(1.3, 0.44476, 2.60206), (1.33, 0.47236, 2.79044)] {
            let m = DipoleMaterial::new(0.01, 1.0, 0.0, eta).unwrap();
            assert_relative_eq!(m.f_dr(), f, max_relative = ORACLE);
            assert_relative_eq!(m.a(), a, max_relative = ORACLE);
        }
    }

    #[test]
    fn apple_oracles() {
        // Jensen et al. 2001 apple (green channel), mm⁻¹: σ_a = 0.0034, σ′_s = 2.39, η = 1.3.
        let m = DipoleMaterial::new(0.0034, 2.39, 0.0, 1.3).unwrap();
        assert_relative_eq!(m.diffuse_reflectance(0.0), 0.47626, max_relative = ORACLE);
        assert_relative_eq!(m.diffuse_reflectance(1.0), 4.0672e-2, max_relative = ORACLE);
        assert_relative_eq!(m.total_diffuse_reflectance(), 0.84068, max_relative = ORACLE);
        /// Two closed forms of the same integral, a dozen roundings each.
        const ROUNDING: f64 = 1e-12;
        assert_relative_eq!(m.diffuse_reflectance_beyond(0.0), m.total_diffuse_reflectance(), max_relative = ROUNDING);
    }

    #[test]
    fn bad_parameters_are_rejected() {
        assert!(DipoleMaterial::new(-1.0, 1.0, 0.0, 1.33).is_err());
        assert!(DipoleMaterial::new(0.1, 1.0, 1.0, 1.33).is_err());
        assert!(DipoleMaterial::new(0.0, 0.0, 0.0, 1.33).is_err());
        assert!(DipoleMaterial::new(0.1, 1.0, 0.0, 3.0).is_err());
        assert!(LiYingParameters::table3(4).is_err());
    }
}
