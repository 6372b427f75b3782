//! The sun as seen through the atmosphere.
//!
//! **Partial model.** Of Preetham et al.'s appendix this implements the Rayleigh and aerosol
//! (Ångström) transmittances with the Kasten relative air mass, evaluated at one wavelength per
//! sRGB channel (680, 550, 450 nm) and applied to an extraterrestrial sun of fixed luminance and
//! 5778 K chromaticity. The ozone, mixed-gas and water-vapour transmittances and the spectral
//! integration against the CIE matching functions are not yet implemented (issue #4).

use glam::DVec3;

use crate::error::{SkyError, check};
use crate::{xyy_to_xyz, xyz_to_linear_srgb};

/// Solid angle of the sun disc used by Preetham et al.'s code (sr).
pub const SUN_SOLID_ANGLE: f64 = 6.7443e-5;

/// Luminance of the sun disc outside the atmosphere (kcd m⁻²): the extraterrestrial solar
/// illuminance 133.3 klx (CIE) over [`SUN_SOLID_ANGLE`].
pub const SUN_TOA_LUMINANCE: f64 = 133.3 / SUN_SOLID_ANGLE;

/// Wavelengths (nm) at which the transmittances are evaluated for the R, G, B channels (the
/// wavelengths of Preetham's aerosol `K(λ)` table).
pub const RGB_WAVELENGTHS_NM: [f64; 3] = [680.0, 550.0, 450.0];

/// Relative optical air mass `m = 1/(cos θ_s + 0.15 (93.885 − θ_s°)^{−1.253})`.
///
/// # Arguments
/// - `theta_s`: sun zenith angle (rad), `[0, π/2]`.
///
/// # Returns
/// `m` (dimensionless), 1 at the zenith, about 38 at the horizon.
///
/// # References
/// Kasten F. 1966, as used in Preetham et al. 1999, Appendix A.1.
pub fn relative_air_mass(theta_s: f64) -> f64 {
    let deg = theta_s.to_degrees().clamp(0.0, 90.0);
    1.0 / (theta_s.cos().max(0.0) + 0.15 * (93.885 - deg).powf(-1.253))
}

/// Rayleigh transmittance `τ_R = exp(−0.008735 λ^{−4.08} m)` (λ in µm).
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm), `[300, 1000]`.
/// - `air_mass`: relative optical mass `m ≥ 1`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Leckner B. 1978; Preetham et al. 1999, Appendix A.1.
pub fn rayleigh_transmittance(wavelength_nm: f64, air_mass: f64) -> f64 {
    let lambda_um = wavelength_nm * 1e-3;
    (-0.008735 * lambda_um.powf(-4.08) * air_mass).exp()
}

/// Aerosol transmittance by Ångström's law, `τ_a = exp(−β λ^{−α} m)`, `α = 1.3`,
/// `β = 0.04608365822 T − 0.04586025928` (λ in µm).
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm), `[300, 1000]`.
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `air_mass`: relative optical mass `m ≥ 1`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Ångström A. 1929; Preetham et al. 1999, Appendix A.1.
pub fn aerosol_transmittance(wavelength_nm: f64, turbidity: f64, air_mass: f64) -> f64 {
    let beta = 0.04608365822 * turbidity - 0.04586025928;
    let lambda_um = wavelength_nm * 1e-3;
    (-beta * lambda_um.powf(-1.3) * air_mass).exp()
}

/// CIE chromaticity of a Planckian radiator of temperature `T` (K), 4000–25000 K, by the cubic
/// fit of Kim et al. 2002 (US patent 7024034; accurate to about 10⁻³ in x, y).
fn planckian_xy(t: f64) -> (f64, f64) {
    let x = -3.0258469e9 / t.powi(3) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
    let y = 3.0817580 * x.powi(3) - 5.8733867 * x * x + 3.75112997 * x - 0.37001483;
    (x, y)
}

/// The sun disc seen from sea level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sun {
    direction: DVec3,
    radiance_rgb: DVec3,
}

impl Sun {
    /// The sun in direction `direction` (y up) through an atmosphere of turbidity `T`
    /// (partial Preetham model, see the module docs).
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] for a turbidity outside `[1.7, 10]` or a sun below the horizon.
    pub fn through_atmosphere(turbidity: f64, direction: DVec3) -> Result<Self, SkyError> {
        let turbidity = check("turbidity", turbidity, (1.7..=10.0).contains(&turbidity), "[1.7, 10]")?;
        let d = direction.normalize_or_zero();
        check("sun_elevation_deg", d.y.asin().to_degrees(), d.y >= 0.0, "[0, 90]°")?;
        let m = relative_air_mass(d.y.clamp(0.0, 1.0).acos());
        let (x, y) = planckian_xy(5778.0);
        let top = xyz_to_linear_srgb(xyy_to_xyz(x, y, SUN_TOA_LUMINANCE)).max(DVec3::ZERO);
        let t = |i: usize| {
            rayleigh_transmittance(RGB_WAVELENGTHS_NM[i], m)
                * aerosol_transmittance(RGB_WAVELENGTHS_NM[i], turbidity, m)
        };
        Ok(Self { direction: d, radiance_rgb: top * DVec3::new(t(0), t(1), t(2)) })
    }

    /// Unit direction toward the sun.
    pub fn direction(&self) -> DVec3 {
        self.direction
    }

    /// Radiance of the disc, linear sRGB, Y in kcd m⁻².
    pub fn radiance_rgb(&self) -> DVec3 {
        self.radiance_rgb
    }

    /// Irradiance on a plane facing the sun, `E = L Ω` (linear sRGB, klx).
    pub fn irradiance_rgb(&self) -> DVec3 {
        self.radiance_rgb * SUN_SOLID_ANGLE
    }

    /// Cosine of the half-angle of the disc, `1 − Ω/2π`.
    pub fn cos_half_angle(&self) -> f64 {
        1.0 - SUN_SOLID_ANGLE / std::f64::consts::TAU
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn air_mass_is_one_at_zenith_and_36_5_at_horizon() {
        // Kasten 1966 gives m(0°) = 1 (to 3·10⁻⁴) and m(90°) = 1/(0.15·3.885^−1.253) = 36.51
        // (Kasten & Young 1989 later refit the horizon value to 38.09).
        assert!((relative_air_mass(0.0) - 1.0).abs() < 1e-3);
        let m = relative_air_mass(std::f64::consts::FRAC_PI_2);
        assert!((m - 36.51).abs() < 0.01, "m = {m}");
    }

    #[test]
    fn the_low_sun_is_redder_and_dimmer() {
        let high = Sun::through_atmosphere(3.0, DVec3::new(0.0, 1.0, 0.2)).unwrap().radiance_rgb();
        let low = Sun::through_atmosphere(3.0, DVec3::new(0.0, 0.05, 1.0)).unwrap().radiance_rgb();
        assert!(low.y < high.y);
        assert!(low.x / low.z > high.x / high.z);
    }
}
