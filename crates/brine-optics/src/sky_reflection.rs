//! Sky light reflected by the rough sea: the environment filtered by the facet-slope
//! distribution of Bruneton, Neyret & Holzschuch (2010).

use glam::DVec3;

use crate::error::{OpticsError, check};
use crate::ocean_brdf::{SlopeVariance, mean_fresnel, smith_lambda};
use crate::quadrature::{GaussHermite, MAX_HERMITE_ORDER};
use crate::{fresnel_dielectric, reflect};

/// A reusable quadrature over facet slopes for the reflected sky (no allocation per call).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SkyReflection {
    rule: GaussHermite,
    n_water: f64,
}

impl SkyReflection {
    /// An `order × order` Gauss–Hermite rule over the two slopes, for water of index `n_water`.
    ///
    /// # Arguments
    /// - `order`: points per slope axis, `[1, 16]` (the sky is called `order²` times per pixel;
    ///   4 is a good compromise, 8 a reference).
    /// - `n_water`: index of water, `(1, 2]`.
    ///
    /// # Returns
    /// The integrator (the rule's `order` nodes and weights, stored without allocation).
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming the parameter.
    ///
    /// # References
    /// Gauss–Hermite quadrature: Abramowitz & Stegun 1964 §25.4.46; the integrand: Bruneton et al.
    /// 2010, Eq. 7–8.
    pub fn new(order: usize, n_water: f64) -> Result<Self, OpticsError> {
        check("order", order as f64, (1..=MAX_HERMITE_ORDER).contains(&order), "[1, 16]")?;
        check("n_water", n_water, n_water > 1.0 && n_water <= 2.0, "(1, 2]")?;
        Ok(Self { rule: GaussHermite::new(order), n_water })
    }

    /// Self-normalised sum over facets: `Σ w f(v·n) sky(l) q / Σ w q₁`, with
    /// `q = (v·n)/(n_z v_z) / (1 + Λ(v) + Λ(l))` on facets facing `v` that reflect above the
    /// horizon, and `q₁ = (v·n)/(n_z v_z) / (1 + Λ(v))` on all facets facing `v` (whose exact
    /// integral is 1, Smith's normalisation). Dividing by the quadrature's own estimate of that 1
    /// cancels most of the error the visibility cut causes at grazing angles, and keeps the
    /// white-furnace sum `≤ 1` exactly (`q ≤ q₁` pointwise).
    fn integrate(
        &self,
        v: DVec3,
        variance: &SlopeVariance,
        fresnel: impl Fn(f64) -> f64,
        mut sky: impl FnMut(DVec3) -> DVec3,
    ) -> DVec3 {
        if v.z <= 0.0 {
            return DVec3::ZERO;
        }
        let (sx, sy) = ((2.0 * variance.sigma_x2()).sqrt(), (2.0 * variance.sigma_y2()).sqrt());
        let lambda_v = smith_lambda(v.z, variance.along(v));
        let mut sum = DVec3::ZERO;
        let mut norm = 0.0;
        for (ti, wi) in self.rule.points() {
            for (tj, wj) in self.rule.points() {
                let n = DVec3::new(-sx * ti, -sy * tj, 1.0).normalize();
                let vn = v.dot(n);
                if vn <= 0.0 {
                    continue;
                }
                let projected = wi * wj * vn / (n.z * v.z);
                norm += projected / (1.0 + lambda_v);
                let l = reflect(-v, n);
                if l.z <= 0.0 {
                    continue;
                }
                let lambda_l = smith_lambda(l.z, variance.along(l));
                sum += projected * fresnel(vn) / (1.0 + lambda_v + lambda_l) * sky(l);
            }
        }
        if norm > 0.0 { sum / norm } else { DVec3::ZERO }
    }

    /// Sky radiance reflected toward `v` by the unresolved waves:
    /// `I_sky(v) = ∫ ρ(v, l) L_sky(l) l_z dω_l = ∫ F(v·n) L_sky(l(n)) p(ζ) (v·n)/(n_z v_z) /
    /// (1 + Λ(v) + Λ(l)) d²ζ`, `l = 2(v·n)n − v`, over facets facing `v` and reflecting above the
    /// horizon, by self-normalised Gauss–Hermite quadrature in the slopes (see the crate docs:
    /// within 1 % of a fine reference integral for order 8 up to 85° from the zenith).
    ///
    /// # Arguments
    /// - `v`: unit direction toward the viewer in the local wind frame (z up, x downwind).
    /// - `variance`: slope variances of the unresolved waves.
    /// - `sky`: sky radiance (any unit, per channel) toward a unit direction of the same frame.
    ///
    /// # Returns
    /// The reflected radiance, in the unit of `sky`; zero for `v_z ≤ 0`.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, Eq. 7–8 and §5.2 (the filtered sky, which their
    /// real-time version approximates by [`reflected_sky_radiance_filtered`]); docs/equations.md §11.
    pub fn reflected_radiance(&self, v: DVec3, variance: &SlopeVariance, sky: impl FnMut(DVec3) -> DVec3) -> DVec3 {
        let n = self.n_water;
        self.integrate(v, variance, |c| fresnel_dielectric(c, 1.0, n), sky)
    }

    /// Directional reflectance of the rough surface for a uniform unit sky: the same integral with
    /// `L_sky = 1`, and with `F = 1` when `unit_fresnel` (the white-furnace check, `≤ 1`).
    ///
    /// # Arguments
    /// - `v`: unit direction toward the viewer, local wind frame.
    /// - `variance`: slope variances.
    /// - `unit_fresnel`: replace `F(v·n)` by 1.
    ///
    /// # Returns
    /// `∫ ρ(v, l) l_z dω_l` (dimensionless), in `[0, 1]`; `0` for `v_z ≤ 0`.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, Eq. 7–8; Smith 1967 (the normalisation).
    pub fn directional_reflectance(&self, v: DVec3, variance: &SlopeVariance, unit_fresnel: bool) -> f64 {
        let n = self.n_water;
        let f = move |c: f64| if unit_fresnel { 1.0 } else { fresnel_dielectric(c, 1.0, n) };
        self.integrate(v, variance, f, |_| DVec3::ONE).x
    }
}

/// Bruneton's real-time sky reflection: the mean Fresnel factor times a prefiltered sky looked up
/// at the mirror direction of `v` about the mean normal, `I_sky ≈ F̄(v) L̄_sky(r)`,
/// `r = (−v_x, −v_y, v_z)`, with a filter footprint given by the slope variances.
///
/// # Arguments
/// - `v`: unit view direction (toward the viewer), local wind frame.
/// - `variance`: slope variances of the unresolved waves.
/// - `prefiltered_sky`: the caller's filtered environment, `(direction, variance) → radiance`
///   (e.g. a mip-mapped sky map sampled with a footprint `∝ σ`).
///
/// # Returns
/// The reflected radiance in the unit of the lookup; zero for `v_z ≤ 0`.
///
/// # References
/// Bruneton et al. 2010 §5.2 (`meanFresnel` and the filtered sky map of their shader); equation
/// equations.md §11.
pub fn reflected_sky_radiance_filtered(
    v: DVec3,
    variance: &SlopeVariance,
    prefiltered_sky: impl FnOnce(DVec3, &SlopeVariance) -> DVec3,
) -> DVec3 {
    if v.z <= 0.0 {
        return DVec3::ZERO;
    }
    let f = mean_fresnel(v.z, variance.along(v).sqrt());
    f * prefiltered_sky(DVec3::new(-v.x, -v.y, v.z), variance)
}

/// The directional reflectance of the rough sea for a uniform sky, `R(θ_v, σ_v) =
/// ∫ ρ(v, l) l_z dω_l` ([`SkyReflection::directional_reflectance`], 8 × 8 rule), tabulated once
/// over `cos θ_v` and the slope deviation `σ_v` along the view's azimuth (isotropic slopes of that
/// deviation, as Bruneton et al.'s `F̄(v)`), for a renderer that looks the sky up once at the
/// mirror direction of the resolved normal and weights it by the rough surface's reflectance
/// instead of the smooth Fresnel factor: at grazing views the unresolved facets hide part of the
/// mirror image (Smith masking) and reflect the rest from other directions, so the distant sea
/// reflects less than a mirror (`R = 0.31` instead of `F = 0.80` at 88° for `σ² = 0.03`).
///
/// Grid: `cos θ_v = u²`, `u` in 65 uniform steps on `[0, 1]` (dense at grazing); `σ_v = 0.6 w²`,
/// `w` in 41 uniform steps on `[0, 1]` (dense on calm water, where `R` leaves the Fresnel value
/// fast; `σ² ≤ 0.36`, beyond any wind sea); bilinear in `(u, w)`, clamped at the ends.
#[derive(Debug, Clone, PartialEq)]
pub struct RoughReflectance {
    n_water: f64,
    /// `table[j·U + i]`: `R` at `u_i`, `σ_j`.
    table: Vec<f64>,
}

impl RoughReflectance {
    /// Steps of `u = √cos θ_v`.
    const U: usize = 65;
    /// Steps of `w = √(σ_v/0.6)`.
    const S: usize = 41;
    /// Largest tabulated slope deviation.
    pub const MAX_SIGMA: f64 = 0.6;

    /// The table for water of index `n_water` (about 2.7×10⁵ facet evaluations, a few ms).
    ///
    /// # Arguments
    /// - `n_water`: index of water, `(1, 2]`.
    ///
    /// # Returns
    /// The table.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming `n_water`.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, Eq. 7–8 (the integrand) and §5.2 (`F̄(v)`, the role the
    /// table plays); docs/equations.md §11.
    pub fn new(n_water: f64) -> Result<Self, OpticsError> {
        let rule = SkyReflection::new(8, n_water)?;
        let mut table = Vec::with_capacity(Self::U * Self::S);
        for j in 0..Self::S {
            let w = j as f64 / (Self::S - 1) as f64;
            let sigma = Self::MAX_SIGMA * w * w;
            let variance = SlopeVariance::new(sigma * sigma, sigma * sigma)?;
            for i in 0..Self::U {
                let u = i as f64 / (Self::U - 1) as f64;
                let c = u * u;
                let v = DVec3::new((1.0 - c * c).max(0.0).sqrt(), 0.0, c);
                table.push(if c > 0.0 { rule.directional_reflectance(v, &variance, false) } else { 0.0 });
            }
        }
        Ok(Self { n_water, table })
    }

    /// Index of water the table was made for.
    pub fn n_water(&self) -> f64 {
        self.n_water
    }

    /// `R(θ_v, σ_v)`, bilinear in the table.
    ///
    /// # Arguments
    /// - `cos_theta_v`: `cos θ_v` to the mean (resolved) normal, `[0, 1]` (clamped).
    /// - `sigma_v`: slope deviation of the unresolved waves along the view's azimuth, `≥ 0`
    ///   (clamped to [`Self::MAX_SIGMA`]).
    ///
    /// # Returns
    /// `R` (dimensionless), in `[0, 1]`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn reflectance(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        let u = cos_theta_v.clamp(0.0, 1.0).sqrt() * (Self::U - 1) as f64;
        let s = (sigma_v.max(0.0) / Self::MAX_SIGMA).min(1.0).sqrt() * (Self::S - 1) as f64;
        let (i, j) = ((u as usize).min(Self::U - 2), (s as usize).min(Self::S - 2));
        let (fu, fs) = (u - i as f64, s - j as f64);
        let at = |i: usize, j: usize| self.table[j * Self::U + i];
        let low = at(i, j) * (1.0 - fu) + at(i + 1, j) * fu;
        let high = at(i, j + 1) * (1.0 - fu) + at(i + 1, j + 1) * fu;
        (low * (1.0 - fs) + high * fs).clamp(0.0, 1.0)
    }

    /// The rough surface's reflectance relative to the smooth one's at the same angle,
    /// `R(θ_v, σ_v)/R(θ_v, 0)`: the factor that turns the exact Fresnel reflectance of the resolved
    /// facet into the reflectance of the rough surface around it (1 at `σ_v = 0`).
    ///
    /// # Arguments
    /// As [`Self::reflectance`].
    ///
    /// # Returns
    /// The ratio (dimensionless), `≥ 0`; 1 where `R(θ_v, 0) = 0`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn roughness_factor(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        let smooth = self.reflectance(cos_theta_v, 0.0);
        if smooth > 0.0 { self.reflectance(cos_theta_v, sigma_v) / smooth } else { 1.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn smooth_water_reflects_the_mirror_direction_with_fresnel() {
        let s = SkyReflection::new(8, 1.333).unwrap();
        let var = SlopeVariance::new(0.0, 0.0).unwrap();
        let v = DVec3::new(60f64.to_radians().sin(), 0.0, 60f64.to_radians().cos());
        let r = s.directional_reflectance(v, &var, false);
        // σ² clamped to 2×10⁻⁵: the lobe is a near-mirror and Λ ≈ 0 at 60°.
        /// The facets' spread of incidence angles (σ ≈ 4.5 mrad) changes the mean F by ½σ²F″/F ≈
        /// 2×10⁻⁴ at 60°; the rest is the 8 × 8 rule's error on the varying F.
        const NEAR_MIRROR: f64 = 2e-3;
        assert_relative_eq!(r, fresnel_dielectric(0.5, 1.0, 1.333), max_relative = NEAR_MIRROR);
    }

    /// The table against the quadrature it samples, half-way between its nodes, and its limits.
    #[test]
    fn rough_reflectance_table_interpolates_the_quadrature() {
        // Bilinear error half-way between nodes, measured: 0.011 up to 82° (at σ ≈ 0.04, where R
        // leaves the Fresnel value fastest), 0.027 up to 89° (R ≈ 0.8 there: 3 %). The last
        // grazing steps (θ > 89.4°) are only checked for bounds.
        const BILINEAR: f64 = 0.012;
        const BILINEAR_GRAZING: f64 = 0.03;
        let t = RoughReflectance::new(1.333).unwrap();
        let rule = SkyReflection::new(8, 1.333).unwrap();
        for j in 0..40 {
            let w = (j as f64 + 0.5) / 40.0;
            let sigma = 0.6 * w * w;
            let var = SlopeVariance::new(sigma * sigma, sigma * sigma).unwrap();
            for i in 6..64 {
                let u = (i as f64 + 0.5) / 64.0;
                let c = u * u;
                let v = DVec3::new((1.0 - c * c).sqrt(), 0.0, c);
                let direct = rule.directional_reflectance(v, &var, false);
                let got = t.reflectance(c, sigma);
                let tolerance = if c >= 0.14 { BILINEAR } else { BILINEAR_GRAZING };
                assert!((got - direct).abs() < tolerance, "cos θ {c}, σ {sigma}: {got} vs {direct}");
            }
        }
        // Smooth water: the Fresnel reflectance; the factor is 1 there; all values in [0, 1].
        assert_relative_eq!(t.reflectance(0.5, 0.0), fresnel_dielectric(0.5, 1.0, 1.333), max_relative = 2e-3);
        assert_relative_eq!(t.roughness_factor(0.3, 0.0), 1.0, max_relative = 1e-12);
        // The table's own entries (the clamp of the lookup would hide one above 1): each a
        // reflectance, up to the quadrature's rounding.
        const ENTRY_ROUNDING: f64 = 1e-12;
        for (k, r) in t.table.iter().enumerate() {
            assert!((-ENTRY_ROUNDING..=1.0 + ENTRY_ROUNDING).contains(r), "entry {k}: {r}");
        }
    }
}
