//! The Preetham, Shirley & Smits (1999) analytic daylight sky.

use glam::DVec3;

use crate::error::{SkyError, check};
use crate::{xyy_to_xyz, xyz_to_linear_srgb};

/// Coefficients `(A, B, C, D, E)` of the Perez distribution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerezCoefficients {
    /// Darkening or brightening toward the horizon.
    pub a: f64,
    /// Luminance gradient near the horizon.
    pub b: f64,
    /// Relative intensity of the circumsolar region.
    pub c: f64,
    /// Width of the circumsolar region.
    pub d: f64,
    /// Relative backscattered light.
    pub e: f64,
}

impl PerezCoefficients {
    /// The Perez coefficients of the sky luminance `Y`, linear in turbidity:
    /// `A = 0.1787 T − 1.4630`, `B = −0.3554 T + 0.4275`, `C = −0.0227 T + 5.3251`,
    /// `D = 0.1206 T − 2.5771`, `E = −0.0670 T + 0.3703`.
    ///
    /// # Arguments
    /// - `t`: turbidity `T`, `[1.7, 10]`.
    ///
    /// # Returns
    /// The [`PerezCoefficients`] (dimensionless; `D` in rad⁻¹).
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.2 (fit to the Perez et al. 1993 distribution).
    pub fn luminance(t: f64) -> Self {
        Self {
            a: 0.1787 * t - 1.4630,
            b: -0.3554 * t + 0.4275,
            c: -0.0227 * t + 5.3251,
            d: 0.1206 * t - 2.5771,
            e: -0.0670 * t + 0.3703,
        }
    }

    /// The Perez coefficients of the sky chromaticity `x`, linear in turbidity:
    /// `A = −0.0193 T − 0.2592`, `B = −0.0665 T + 0.0008`, `C = −0.0004 T + 0.2125`,
    /// `D = −0.0641 T − 0.8989`, `E = −0.0033 T + 0.0452`.
    ///
    /// # Arguments
    /// - `t`: turbidity `T`, `[1.7, 10]`.
    ///
    /// # Returns
    /// The [`PerezCoefficients`] (dimensionless; `D` in rad⁻¹).
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.2.
    pub fn chromaticity_x(t: f64) -> Self {
        Self {
            a: -0.0193 * t - 0.2592,
            b: -0.0665 * t + 0.0008,
            c: -0.0004 * t + 0.2125,
            d: -0.0641 * t - 0.8989,
            e: -0.0033 * t + 0.0452,
        }
    }

    /// The Perez coefficients of the sky chromaticity `y`, linear in turbidity:
    /// `A = −0.0167 T − 0.2608`, `B = −0.0950 T + 0.0092`, `C = −0.0079 T + 0.2102`,
    /// `D = −0.0441 T − 1.6537`, `E = −0.0109 T + 0.0529`.
    ///
    /// # Arguments
    /// - `t`: turbidity `T`, `[1.7, 10]`.
    ///
    /// # Returns
    /// The [`PerezCoefficients`] (dimensionless; `D` in rad⁻¹).
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.2.
    pub fn chromaticity_y(t: f64) -> Self {
        Self {
            a: -0.0167 * t - 0.2608,
            b: -0.0950 * t + 0.0092,
            c: -0.0079 * t + 0.2102,
            d: -0.0441 * t - 1.6537,
            e: -0.0109 * t + 0.0529,
        }
    }
}

/// The Perez sky distribution `F(θ, γ) = (1 + A e^{B/cos θ})(1 + C e^{Dγ} + E cos²γ)`.
///
/// # Arguments
/// - `cos_theta`: cosine of the view zenith angle, `(0, 1]` (callers clamp near the horizon).
/// - `gamma`: angle between the view and the sun (rad), `[0, π]`.
/// - `k`: the coefficients.
///
/// # Returns
/// The relative luminance or chromaticity distribution (dimensionless).
///
/// # References
/// Perez R., Seals R., Michalsky J. 1993, "All-weather model for sky luminance distribution",
/// Solar Energy 50(3); Preetham et al. 1999, Eq. 3; docs/equations.md §8.
pub fn perez(cos_theta: f64, gamma: f64, k: &PerezCoefficients) -> f64 {
    debug_assert!(cos_theta > 0.0, "cos θ must be positive, got {cos_theta}");
    let cg = gamma.cos();
    (1.0 + k.a * (k.b / cos_theta).exp()) * (1.0 + k.c * (k.d * gamma).exp() + k.e * cg * cg)
}

/// Zenith luminance `Y_z = (4.0453 T − 4.9710) tan χ − 0.2155 T + 2.4192`,
/// `χ = (4/9 − T/120)(π − 2θ_s)`.
///
/// # Arguments
/// - `turbidity`: `T`, `[1.7, 10]` (best 2–6).
/// - `theta_s`: sun zenith angle (rad), `[0, π/2]`.
///
/// # Returns
/// `Y_z` in kcd m⁻².
///
/// # References
/// Preetham et al. 1999, Appendix A.2; docs/equations.md §8.
pub fn zenith_luminance(turbidity: f64, theta_s: f64) -> f64 {
    let chi = (4.0 / 9.0 - turbidity / 120.0) * (std::f64::consts::PI - 2.0 * theta_s);
    (4.0453 * turbidity - 4.9710) * chi.tan() - 0.2155 * turbidity + 2.4192
}

/// Evaluates `[T² T 1] · M · [θ_s³ θ_s² θ_s 1]ᵀ`.
fn zenith_chromaticity(m: &[[f64; 4]; 3], t: f64, theta_s: f64) -> f64 {
    let tv = [t * t, t, 1.0];
    let sv = [theta_s.powi(3), theta_s * theta_s, theta_s, 1.0];
    (0..3).map(|i| tv[i] * (0..4).map(|j| m[i][j] * sv[j]).sum::<f64>()).sum()
}

/// Zenith chromaticity `(x_z, y_z)` (Preetham et al. 1999, Appendix A.2, 5-digit matrices).
///
/// # Arguments
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `theta_s`: sun zenith angle (rad), `[0, π/2]`.
///
/// # Returns
/// CIE `(x, y)` chromaticity of the zenith.
///
/// # References
/// Preetham et al. 1999, Appendix A.2; docs/equations.md §8.
pub fn zenith_chromaticity_xy(turbidity: f64, theta_s: f64) -> (f64, f64) {
    const MX: [[f64; 4]; 3] = [
        [0.00166, -0.00375, 0.00209, 0.0],
        [-0.02903, 0.06377, -0.03202, 0.00394],
        [0.11693, -0.21196, 0.06052, 0.25886],
    ];
    const MY: [[f64; 4]; 3] = [
        [0.00275, -0.00610, 0.00317, 0.0],
        [-0.04214, 0.08970, -0.04153, 0.00516],
        [0.15346, -0.26756, 0.06670, 0.26688],
    ];
    (zenith_chromaticity(&MX, turbidity, theta_s), zenith_chromaticity(&MY, turbidity, theta_s))
}

/// Lowest view elevation the Perez formula is evaluated at: its `e^{B/cos θ}` term has no
/// physical meaning at the horizon, so views below are evaluated at this cosine (documented
/// clamp, as in the authors' code).
pub const MIN_COS_VIEW: f64 = 0.01;

/// A Preetham sky for one turbidity and sun position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreethamSky {
    turbidity: f64,
    sun_direction: DVec3,
    theta_s: f64,
    k_y: PerezCoefficients,
    k_x: PerezCoefficients,
    k_yy: PerezCoefficients,
    zenith: (f64, f64, f64),
    /// `F(0, θ_s)` for Y, x, y (the normalisation, computed once).
    at_zenith: [f64; 3],
}

impl PreethamSky {
    /// The sky for turbidity `T` and a unit direction toward the sun (y up).
    ///
    /// # Arguments
    /// - `turbidity`: `T`, `[1.7, 10]`.
    /// - `sun_direction`: direction toward the sun, y up; its elevation must be in `[0°, 90°]`.
    ///
    /// # Returns
    /// The sky, with the Perez coefficients, the zenith values `Y_z`, `x_z`, `y_z` and the
    /// normalisations `F(0, θ_s)` computed once.
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] for a turbidity outside `[1.7, 10]` or a sun below the horizon
    /// (the daylight model does not hold there).
    ///
    /// # References
    /// Preetham et al. 1999, §3 and Appendix A.2.
    pub fn new(turbidity: f64, sun_direction: DVec3) -> Result<Self, SkyError> {
        let turbidity = check("turbidity", turbidity, (1.7..=10.0).contains(&turbidity), "[1.7, 10]")?;
        let d = sun_direction.normalize_or_zero();
        check("sun_elevation_deg", d.y.asin().to_degrees(), d.y >= 0.0, "[0, 90]°")?;
        let theta_s = d.y.clamp(0.0, 1.0).acos();
        let (xz, yz) = zenith_chromaticity_xy(turbidity, theta_s);
        let (k_y, k_x, k_yy) = (
            PerezCoefficients::luminance(turbidity),
            PerezCoefficients::chromaticity_x(turbidity),
            PerezCoefficients::chromaticity_y(turbidity),
        );
        Ok(Self {
            turbidity,
            sun_direction: d,
            theta_s,
            k_y,
            k_x,
            k_yy,
            zenith: (zenith_luminance(turbidity, theta_s), xz, yz),
            at_zenith: [perez(1.0, theta_s, &k_y), perez(1.0, theta_s, &k_x), perez(1.0, theta_s, &k_yy)],
        })
    }

    /// Sun zenith angle `θ_s` (rad).
    pub fn theta_s(&self) -> f64 {
        self.theta_s
    }

    /// Turbidity `T`.
    pub fn turbidity(&self) -> f64 {
        self.turbidity
    }

    /// Unit direction toward the sun.
    pub fn sun_direction(&self) -> DVec3 {
        self.sun_direction
    }

    /// Sky `(Y, x, y)` for a view direction: `Y = Y_z F(θ, γ)/F(0, θ_s)` and likewise for `x`, `y`.
    ///
    /// # Arguments
    /// - `view`: unit view direction, y up; below [`MIN_COS_VIEW`] it is evaluated at that cosine.
    ///
    /// # Returns
    /// Luminance `Y` (kcd m⁻²) and chromaticity `(x, y)`.
    ///
    /// # References
    /// Preetham et al. 1999, Eq. 3–4.
    pub fn yxy(&self, view: DVec3) -> (f64, f64, f64) {
        let v = view.normalize_or_zero();
        let cos_theta = v.y.max(MIN_COS_VIEW);
        let gamma = v.dot(self.sun_direction).clamp(-1.0, 1.0).acos();
        let (yz, xz, yyz) = self.zenith;
        let [ny, nx, nyy] = self.at_zenith;
        (
            yz * perez(cos_theta, gamma, &self.k_y) / ny,
            xz * perez(cos_theta, gamma, &self.k_x) / nx,
            yyz * perez(cos_theta, gamma, &self.k_yy) / nyy,
        )
    }

    /// Sky radiance as CIE XYZ for a view direction, from [`PreethamSky::yxy`]:
    /// `X = xY/y`, `Y`, `Z = (1 − x − y)Y/y` (`Y` clamped at 0).
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here); below [`MIN_COS_VIEW`] it is evaluated
    ///   at that cosine.
    ///
    /// # Returns
    /// `(X, Y, Z)` in kcd m⁻² (Y is the luminance), finite and `Y ≥ 0`.
    ///
    /// # References
    /// Preetham et al. 1999, Eq. 3–4; CIE 15:2004 (xyY to XYZ).
    pub fn xyz(&self, view: DVec3) -> DVec3 {
        let (lum, x, y) = self.yxy(view);
        // Perez's luminance is positive over the model's turbidities and sun positions: the
        // clamp absorbs rounding only.
        debug_assert!(lum >= -1e-12, "Perez luminance {lum} toward {view}");
        xyy_to_xyz(x, y, lum.max(0.0))
    }

    /// Sky radiance as linear sRGB, `RGB = M_{XYZ→sRGB} · XYZ` ([`PreethamSky::xyz`], Rec. 709
    /// primaries, D65), negative components (out of gamut) clipped to 0.
    ///
    /// # Arguments
    /// - `view`: view direction, y up.
    ///
    /// # Returns
    /// Linear sRGB radiance, each channel `≥ 0`, scaled so that its luminance is in kcd m⁻².
    ///
    /// # References
    /// Preetham et al. 1999; IEC 61966-2-1 (sRGB).
    pub fn radiance_rgb(&self, view: DVec3) -> DVec3 {
        xyz_to_linear_srgb(self.xyz(view)).max(DVec3::ZERO)
    }

    /// Irradiance from the sky dome on a horizontal surface facing up,
    /// `E = ∫ L(ω) cos θ dω` (linear sRGB, klx), by the midpoint rule on 48 × 96 cells.
    ///
    /// # Returns
    /// `E` per linear sRGB channel (klx), `≥ 0` (the sun's disc excluded).
    ///
    /// # References
    /// Preetham et al. 1999 (the radiance integrated over the upper hemisphere).
    pub fn horizontal_irradiance_rgb(&self) -> DVec3 {
        horizontal_irradiance(|v| self.radiance_rgb(v))
    }
}

/// `∫ L(ω) cos θ dω` over the upper hemisphere by the midpoint rule on 48 × 96 cells.
pub(crate) fn horizontal_irradiance(radiance_rgb: impl Fn(DVec3) -> DVec3) -> DVec3 {
    let mut e = DVec3::ZERO;
    for_each_dome_cell((48, 96), |v, (ct, st), (dt, dp)| e += radiance_rgb(v) * ct * st * dt * dp);
    e
}

/// Calls `f(v, (cos θ, sin θ), (dθ, dφ))` at the centre `v` (unit, `y` up) of each of the
/// `nθ × nφ` cells of the midpoint rule over the upper hemisphere (zenith angle `θ ∈ [0, π/2]`,
/// azimuth `φ ∈ [0, 2π)`), whose solid angle is `sin θ dθ dφ`.
pub(crate) fn for_each_dome_cell((n_theta, n_phi): (usize, usize), mut f: impl FnMut(DVec3, (f64, f64), (f64, f64))) {
    let d_theta = std::f64::consts::FRAC_PI_2 / n_theta as f64;
    let d_phi = std::f64::consts::TAU / n_phi as f64;
    for i in 0..n_theta {
        let theta = (i as f64 + 0.5) * d_theta;
        let (sin_theta, cos_theta) = theta.sin_cos();
        for j in 0..n_phi {
            let phi = (j as f64 + 0.5) * d_phi;
            let v = DVec3::new(sin_theta * phi.cos(), cos_theta, sin_theta * phi.sin());
            f(v, (cos_theta, sin_theta), (d_theta, d_phi));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Oracle values are computed from 4-digit coefficients and printed with 4–5 digits.
    const ORACLE: f64 = 1e-4;
    /// Chromaticity tolerance of docs/equations.md (5-digit vs 4-digit matrices).
    const CHROMA: f64 = 5e-4;
    /// The reference's Perez ratios are printed with 4 digits: 2×10⁻⁴ relative.
    const PEREZ_RATIO: f64 = 2e-4;

    #[test]
    fn zenith_values() {
        let ts = 30f64.to_radians();
        assert_relative_eq!(zenith_luminance(2.0, ts), 5.8867, max_relative = ORACLE);
        let (x, y) = zenith_chromaticity_xy(2.0, ts);
        assert!((x - 0.2514).abs() < CHROMA && (y - 0.2559).abs() < CHROMA, "({x}, {y})");
        assert_relative_eq!(zenith_luminance(3.0, 45f64.to_radians()), 7.3204, max_relative = ORACLE);
        assert_relative_eq!(zenith_luminance(6.0, 0.0), 57.180, max_relative = ORACLE);
    }

    #[test]
    fn perez_ratio_oracles() {
        // T = 3, θs = 45°: view θ = 60°, γ = 90° ⇒ Y/Yz = 0.8407; θ = 45°, γ = 0.5° ⇒ 3.853.
        let k = PerezCoefficients::luminance(3.0);
        let ts = 45f64.to_radians();
        let r1 = perez(60f64.to_radians().cos(), 90f64.to_radians(), &k) / perez(1.0, ts, &k);
        assert_relative_eq!(r1, 0.8407, max_relative = PEREZ_RATIO);
        let r2 = perez(45f64.to_radians().cos(), 0.5f64.to_radians(), &k) / perez(1.0, ts, &k);
        assert_relative_eq!(r2, 3.853, max_relative = PEREZ_RATIO);
    }

    #[test]
    fn zenith_view_returns_zenith_values() {
        let sun = DVec3::new(0.0, 30f64.to_radians().cos(), 30f64.to_radians().sin());
        let sky = PreethamSky::new(2.0, sun).unwrap();
        let (y, x, yy) = sky.yxy(DVec3::Y);
        assert_relative_eq!(y, 5.8867, max_relative = ORACLE);
        assert!((x - 0.2514).abs() < CHROMA && (yy - 0.2559).abs() < CHROMA);
    }
}
