//! The ocean BRDF of Bruneton, Neyret & Holzschuch (2010): Gaussian facet slopes with Smith
//! shadowing and Fresnel at the half vector.
//!
//! Vectors are in the local *wind frame*: z along the mean (geometric) normal, x downwind in the
//! tangent plane, y crosswind.

use std::f64::consts::PI;

use glam::DVec3;

use crate::error::{OpticsError, check};
use crate::{WATER_IOR, fresnel_dielectric};

/// Smallest slope variance used, `2×10⁻⁵` (Bruneton et al. 2010 clamp; keeps the lobe finite).
pub const MIN_SLOPE_VARIANCE: f64 = 2e-5;

/// Variances of the facet slopes `(ζx, ζy)` of the waves not drawn as geometry (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeVariance {
    sigma_x2: f64,
    sigma_y2: f64,
}

impl SlopeVariance {
    /// Slope variances downwind (`σx²`) and crosswind (`σy²`), each clamped below at
    /// [`MIN_SLOPE_VARIANCE`].
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] if either is negative, NaN or infinite.
    pub fn new(sigma_x2: f64, sigma_y2: f64) -> Result<Self, OpticsError> {
        check("sigma_x2", sigma_x2, sigma_x2 >= 0.0, "[0, ∞)")?;
        check("sigma_y2", sigma_y2, sigma_y2 >= 0.0, "[0, ∞)")?;
        Ok(Self::clamped(sigma_x2, sigma_y2))
    }

    pub(crate) fn clamped(sigma_x2: f64, sigma_y2: f64) -> Self {
        Self { sigma_x2: sigma_x2.max(MIN_SLOPE_VARIANCE), sigma_y2: sigma_y2.max(MIN_SLOPE_VARIANCE) }
    }

    /// Cox & Munk (1954) slope variances of a clean sea for the wind speed `U₁₂.₅` 12.5 m above
    /// it: `σ_u² = 3.16×10⁻³ U` upwind, `σ_c² = 0.003 + 1.92×10⁻³ U` crosswind.
    ///
    /// # Arguments
    /// - `u12_5`: wind speed (m s⁻¹), `[0, 60]` (measured range about 1–14 m s⁻¹).
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] outside `[0, 60]`.
    ///
    /// # References
    /// Cox C., Munk W. 1954, "Measurement of the roughness of the sea surface from photographs of
    /// the sun's glitter", JOSA 44(11), clean-surface fits; equation sheet §11.
    pub fn cox_munk_clean(u12_5: f64) -> Result<Self, OpticsError> {
        let u = check("u12_5_m_s", u12_5, (0.0..=60.0).contains(&u12_5), "[0, 60] m/s")?;
        Ok(Self::clamped(3.16e-3 * u, 0.003 + 1.92e-3 * u))
    }

    /// Downwind slope variance `σx²`.
    pub fn sigma_x2(&self) -> f64 {
        self.sigma_x2
    }

    /// Crosswind slope variance `σy²`.
    pub fn sigma_y2(&self) -> f64 {
        self.sigma_y2
    }

    /// `σx² + σy²`, the mean-square slope.
    pub fn total(&self) -> f64 {
        self.sigma_x2 + self.sigma_y2
    }

    /// These variances minus those of waves drawn as geometry (the seamless transition of
    /// Bruneton et al. 2010 §4: `σ²_BRDF = σ²_total − σ²_resolved`), clamped at the minimum.
    pub fn minus(&self, resolved_x2: f64, resolved_y2: f64) -> Self {
        Self::clamped(self.sigma_x2 - resolved_x2, self.sigma_y2 - resolved_y2)
    }

    /// Slope variance in the azimuth plane of the direction `s` (local frame):
    /// `σ_s² = σx² cos²φ + σy² sin²φ`, `cos²φ = s_x²/(s_x² + s_y²)` (the tangent form; the
    /// published shader's angle form is an erratum, equation sheet §11).
    pub fn along(&self, s: DVec3) -> f64 {
        let h2 = s.x * s.x + s.y * s.y;
        if h2 <= 0.0 {
            return 0.5 * (self.sigma_x2 + self.sigma_y2);
        }
        (self.sigma_x2 * s.x * s.x + self.sigma_y2 * s.y * s.y) / h2
    }
}

/// Gaussian probability density of facet slopes,
/// `p(ζ) = exp(−½(ζx²/σx² + ζy²/σy²)) / (2π σx σy)`.
///
/// # Arguments
/// - `zeta_x`, `zeta_y`: facet slopes (dimensionless), any real.
/// - `variance`: the slope variances.
///
/// # Returns
/// The density per unit slope² (dimensionless), `∫∫ p dζx dζy = 1`.
///
/// # References
/// Bruneton, Neyret & Holzschuch 2010, "Real-time realistic ocean lighting using seamless
/// transitions from geometry to BRDF", CGF 29(2), Eq. 4; equation sheet §11.
pub fn slope_pdf(zeta_x: f64, zeta_y: f64, variance: &SlopeVariance) -> f64 {
    let (sx2, sy2) = (variance.sigma_x2, variance.sigma_y2);
    (-0.5 * (zeta_x * zeta_x / sx2 + zeta_y * zeta_y / sy2)).exp() / (2.0 * PI * (sx2 * sy2).sqrt())
}

/// Smith's shadowing term `Λ` for Gaussian slopes,
/// `Λ = (e^{−ν²} − ν√π erfc ν) / (2ν√π)`, `ν = μ/√(2σ_s²(1 − μ²))`.
///
/// # Arguments
/// - `cos_theta`: `μ`, cosine of the direction's angle to the mean normal, `(0, 1]`.
/// - `sigma_s2`: slope variance in the direction's azimuth plane, `> 0`.
///
/// # Returns
/// `Λ ≥ 0` (dimensionless); `0` at normal incidence. Uses `libm::erfc` (full precision).
///
/// # References
/// Smith 1967; Bruneton et al. 2010, Eq. 6; equation sheet §11.
pub fn smith_lambda(cos_theta: f64, sigma_s2: f64) -> f64 {
    debug_assert!(sigma_s2 > 0.0);
    let mu = cos_theta.clamp(1e-6, 1.0);
    if mu >= 1.0 {
        return 0.0;
    }
    let nu = mu / (2.0 * sigma_s2 * (1.0 - mu * mu)).sqrt();
    let sqrt_pi = PI.sqrt();
    ((-nu * nu).exp() - nu * sqrt_pi * libm::erfc(nu)) / (2.0 * nu * sqrt_pi)
}

/// The ocean BRDF `ρ(v, l) = F(v·h) p(ζ_h) / (4 h_z⁴ v_z l_z (1 + Λ(v) + Λ(l)))`,
/// `h = (v + l)/‖v + l‖`, `ζ_h = (h_x, h_y)/h_z`.
///
/// # Arguments
/// - `v`: unit direction toward the viewer, local wind frame, `v_z > 0`.
/// - `l`: unit direction toward the light, local wind frame, `l_z > 0`.
/// - `variance`: slope variances of the unresolved waves.
/// - `n_water`: index of refraction of water (1.333).
///
/// # Returns
/// `ρ` (sr⁻¹), `0` if either direction is below the mean surface. Directions within 0.01 of
/// the horizon are clamped to `z = 0.01` as in the authors' shader.
///
/// # References
/// Bruneton et al. 2010, Eq. 7–8; equation sheet §11 (with the visibility-weighted density of the
/// Li Ying et al. 2018 erratum).
pub fn ocean_brdf(v: DVec3, l: DVec3, variance: &SlopeVariance, n_water: f64) -> f64 {
    if v.z <= 0.0 || l.z <= 0.0 {
        return 0.0;
    }
    let h = (v + l).normalize();
    let (vz, lz) = (v.z.max(0.01), l.z.max(0.01));
    let zeta = (h.x / h.z, h.y / h.z);
    let p = slope_pdf(zeta.0, zeta.1, variance);
    let lambda_v = smith_lambda(vz, variance.along(v));
    let lambda_l = smith_lambda(lz, variance.along(l));
    let f = fresnel_dielectric(v.dot(h), 1.0, n_water);
    f * p / (4.0 * h.z.powi(4) * vz * lz * (1.0 + lambda_v + lambda_l))
}

/// Sun radiance reflected toward `v`: `I_sun = ρ(v, l) E_sun l_z`, for a sun of irradiance
/// `E_sun = L_sun Ω_sun` on a plane facing it (a sun small against the BRDF lobe).
///
/// # Arguments
/// - `v`, `l`: unit view and sun directions, local wind frame.
/// - `variance`: slope variances.
/// - `sun_irradiance`: `E_sun` in any radiometric or photometric unit (W m⁻² or lx), `≥ 0`.
///
/// # Returns
/// The reflected radiance, in that unit per steradian.
///
/// # References
/// Bruneton et al. 2010, Eq. 9 ("reflectedSunRadiance" in the authors' shader); equation sheet §11.
pub fn reflected_sun_radiance(v: DVec3, l: DVec3, variance: &SlopeVariance, sun_irradiance: f64) -> f64 {
    ocean_brdf(v, l, variance, WATER_IOR) * sun_irradiance * l.z.max(0.0)
}

/// The authors' fit of the Fresnel reflectance averaged over the facet slopes seen from `v`:
/// `F̄(v) = 0.02 + 0.98 (1 − v_z)^{5 exp(−2.69 σ_v)} / (1 + 22.7 σ_v^{1.5})`.
///
/// # Arguments
/// - `cos_theta_v`: `v_z`, cosine of the view angle to the mean normal, `[0, 1]`.
/// - `sigma_v`: slope standard deviation in the view's azimuth plane, `√σ_v²`, `≥ 0`.
///
/// # Returns
/// `F̄` in `[0.02, 1]`.
///
/// # References
/// Bruneton et al. 2010, §5.2 (`meanFresnel` in the authors' shader); equation sheet §11.
pub fn mean_fresnel(cos_theta_v: f64, sigma_v: f64) -> f64 {
    let vz = cos_theta_v.clamp(0.0, 1.0);
    let s = sigma_v.max(0.0);
    (0.02 + 0.98 * (1.0 - vz).powf(5.0 * (-2.69 * s).exp()) / (1.0 + 22.7 * s.powf(1.5))).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Oracle values of the equation sheet are given to 5 significant digits.
    const ORACLE: f64 = 1e-4;

    #[test]
    fn smith_lambda_oracles() {
        assert_relative_eq!(smith_lambda(0.3, 0.05), 2.5705e-2, max_relative = ORACLE);
        assert_relative_eq!(smith_lambda(0.1, 0.1), 0.81811, max_relative = ORACLE);
    }

    #[test]
    fn mean_fresnel_oracle() {
        assert_relative_eq!(mean_fresnel(0.5, 0.1), 0.06037, max_relative = ORACLE);
    }

    #[test]
    fn brdf_is_reciprocal() {
        let var = SlopeVariance::new(0.02, 0.01).unwrap();
        let v = DVec3::new(0.3, -0.2, 0.7).normalize();
        let l = DVec3::new(-0.5, 0.1, 0.4).normalize();
        assert_relative_eq!(ocean_brdf(v, l, &var, 1.333), ocean_brdf(l, v, &var, 1.333), max_relative = 1e-12);
    }
}
