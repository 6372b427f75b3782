//! The sun seen through the atmosphere: Preetham, Shirley & Smits (1999), Appendix A.1.
//!
//! The extraterrestrial spectral radiance of the disc is attenuated by five transmittances —
//! Rayleigh scattering, aerosols (Ångström's law with the turbidity), ozone, mixed gases and water
//! vapour, after Iqbal (1983) — at every 5 nm from 380 to 750 nm, then integrated against the CIE
//! 1931 colour-matching functions (`K_m = 683 lm W⁻¹`) to CIE XYZ in kcd m⁻², and converted to
//! linear sRGB.

use glam::DVec3;

use crate::cie::{MAX_LUMINOUS_EFFICACY, cmf};
use crate::error::{SkyError, check};
use crate::solar_tables::{K_MIXED_GAS, K_OZONE, K_WATER_VAPOUR, interpolate, solar_radiance};
use crate::xyz_to_linear_srgb;

/// The astronomical unit (km), IAU 2012.
pub const AU_KM: f64 = brine_core::AU_KM;

/// Nominal radius of the Sun (km), IAU 2015 Resolution B3.
pub const SUN_RADIUS_KM: f64 = 695_700.0;

/// Solid angle of the sun disc at 1 AU, `2π(1 − cos ρ)`, `ρ = asin(R_☉/1 AU) = 0.26645°` (sr).
/// (Preetham et al.'s code used 6.7443×10⁻⁵ sr, 0.7 % smaller.)
pub const SUN_SOLID_ANGLE: f64 = 6.794_310_7e-5;

/// Wavelengths (nm) standing for the R, G, B channels in the per-channel models (aerial
/// perspective, twilight): those of Preetham's aerosol `K(λ)` table.
pub const RGB_WAVELENGTHS_NM: [f64; 3] = [680.0, 550.0, 450.0];

/// Ozone column `l` (cm at NTP) of Preetham's code.
pub const OZONE_CM: f64 = 0.35;

/// Precipitable water `w` (cm) of Preetham's code ("standard = 2").
pub const WATER_VAPOUR_CM: f64 = 2.0;

/// Ångström's wavelength exponent `α` ("usually 1.3").
pub const ANGSTROM_ALPHA: f64 = 1.3;

/// Wavelength range and step (nm) of the spectral integration: the range of the solar table.
const SPECTRAL: (f64, f64, usize) = (380.0, 5.0, 75);

/// Angular radius of the sun disc at a distance, `ρ = asin(R_☉/r)`.
///
/// # Arguments
/// - `distance_au`: Earth–Sun distance (AU), `[0.98, 1.02]` in practice.
///
/// # Returns
/// `ρ` (rad): 0.2664° at 1 AU.
///
/// # References
/// IAU 2015 Resolution B3 (nominal solar radius).
pub fn sun_angular_radius(distance_au: f64) -> f64 {
    (SUN_RADIUS_KM / (distance_au * AU_KM)).clamp(0.0, 1.0).asin()
}

/// Relative optical air mass `m = 1/(cos θ_s + 0.15 (93.885 − θ_s°)^{−1.253})`.
///
/// # Arguments
/// - `theta_s`: sun zenith angle (rad), `[0, π/2]` (clamped).
///
/// # Returns
/// `m` (dimensionless), 1 at the zenith, 36.5 at the horizon.
///
/// # References
/// Kasten F. 1966, as used in Preetham et al. 1999, Appendix A.1.
pub fn relative_air_mass(theta_s: f64) -> f64 {
    let theta = theta_s.clamp(0.0, std::f64::consts::FRAC_PI_2);
    1.0 / (theta.cos() + 0.15 * (93.885 - theta.to_degrees()).powf(-1.253))
}

/// Rayleigh transmittance `τ_R = exp(−0.008735 λ^{−4.08} m)` (λ in µm).
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm), `[300, 1000]`.
/// - `air_mass`: relative optical mass `m ≥ 0`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Leckner B. 1978, Solar Energy 20:143; Preetham et al. 1999, Appendix A.1.
pub fn rayleigh_transmittance(wavelength_nm: f64, air_mass: f64) -> f64 {
    let lambda_um = wavelength_nm * 1e-3;
    (-0.008735 * lambda_um.powf(-4.08) * air_mass).exp()
}

/// Ångström turbidity coefficient of Preetham's fit, `β = 0.04608365822 T − 0.04586025928`.
///
/// # Arguments
/// - `turbidity`: `T`, `[1.7, 10]`.
///
/// # Returns
/// `β` (dimensionless, aerosol optical depth at 1 µm).
///
/// # References
/// Preetham et al. 1999, Appendix A.1.
pub fn angstrom_beta(turbidity: f64) -> f64 {
    0.046_083_658_220_50 * turbidity - 0.045_860_259_285_22
}

/// Aerosol transmittance by Ångström's law, `τ_a = exp(−β λ^{−α} m)`, `α = 1.3` (λ in µm).
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm), `[300, 1000]`.
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `air_mass`: relative optical mass `m ≥ 0`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Ångström A. 1929, Geografiska Annaler 11:156; Preetham et al. 1999, Appendix A.1.
pub fn aerosol_transmittance(wavelength_nm: f64, turbidity: f64, air_mass: f64) -> f64 {
    let lambda_um = wavelength_nm * 1e-3;
    (-angstrom_beta(turbidity) * lambda_um.powf(-ANGSTROM_ALPHA) * air_mass).exp()
}

/// Ozone transmittance `τ_o = exp(−k_o(λ) l m)`, `l = 0.35 cm`.
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm); `k_o` from Iqbal's table (300–790 nm, 0 outside).
/// - `air_mass`: `m ≥ 0`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Iqbal 1983, p. 127; Preetham et al. 1999, Appendix A.1.
pub fn ozone_transmittance(wavelength_nm: f64, air_mass: f64) -> f64 {
    (-interpolate(&K_OZONE, wavelength_nm) * OZONE_CM * air_mass).exp()
}

/// Mixed-gas (oxygen) transmittance `τ_g = exp(−1.41 k_g m/(1 + 118.93 k_g m)^{0.45})`.
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm); `k_g` tabulated in 759–771 nm, 0 elsewhere.
/// - `air_mass`: `m ≥ 0`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Leckner 1978; Iqbal 1983, p. 130; Preetham et al. 1999, Appendix A.1.
pub fn mixed_gas_transmittance(wavelength_nm: f64, air_mass: f64) -> f64 {
    let km = interpolate(&K_MIXED_GAS, wavelength_nm) * air_mass;
    (-1.41 * km / (1.0 + 118.93 * km).powf(0.45)).exp()
}

/// Water-vapour transmittance `τ_wa = exp(−0.2385 k_wa w m/(1 + 20.07 k_wa w m)^{0.45})`,
/// `w = 2 cm`.
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm); `k_wa` tabulated in 689–800 nm, 0 elsewhere.
/// - `air_mass`: `m ≥ 0`.
///
/// # Returns
/// Transmittance in `(0, 1]`.
///
/// # References
/// Leckner 1978; Iqbal 1983, p. 130; Preetham et al. 1999, Appendix A.1.
pub fn water_vapour_transmittance(wavelength_nm: f64, air_mass: f64) -> f64 {
    let kwm = interpolate(&K_WATER_VAPOUR, wavelength_nm) * WATER_VAPOUR_CM * air_mass;
    (-0.2385 * kwm / (1.0 + 20.07 * kwm).powf(0.45)).exp()
}

/// Spectral radiance of the sun disc after the atmosphere,
/// `L(λ) = L₀(λ) τ_R τ_a τ_o τ_g τ_wa`.
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm), 380–750 (the solar table; 0 outside).
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `air_mass`: `m ≥ 0` (0 is the top of the atmosphere).
///
/// # Returns
/// `L(λ)` in W m⁻² sr⁻¹ nm⁻¹.
///
/// # References
/// Preetham et al. 1999, Appendix A.1 and the authors' `ComputeAttenuatedSunlight`.
pub fn sun_spectral_radiance(wavelength_nm: f64, turbidity: f64, air_mass: f64) -> f64 {
    let l = wavelength_nm;
    solar_radiance(l)
        * rayleigh_transmittance(l, air_mass)
        * aerosol_transmittance(l, turbidity, air_mass)
        * ozone_transmittance(l, air_mass)
        * mixed_gas_transmittance(l, air_mass)
        * water_vapour_transmittance(l, air_mass)
}

/// CIE XYZ radiance of the sun disc after the atmosphere,
/// `X = K_m ∫ L(λ) x̄(λ) dλ` (likewise Y, Z), by the rectangle rule every 5 nm over 380–750 nm.
///
/// # Arguments
/// - `turbidity`: `T`, `[1.7, 10]`.
/// - `air_mass`: `m ≥ 0` (see [`relative_air_mass`]).
///
/// # Returns
/// XYZ in kcd m⁻² (Y is the luminance of the disc).
///
/// # References
/// Preetham et al. 1999, Appendix A.1; CIE 15:2004.
pub fn sun_radiance_xyz(turbidity: f64, air_mass: f64) -> DVec3 {
    let (start, step, n) = SPECTRAL;
    let mut xyz = DVec3::ZERO;
    for i in 0..n {
        let l = start + step * i as f64;
        let c = cmf(l);
        xyz += DVec3::from(c) * sun_spectral_radiance(l, turbidity, air_mass);
    }
    xyz * step * MAX_LUMINOUS_EFFICACY * 1e-3
}

/// The sun disc seen from sea level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sun {
    direction: DVec3,
    radiance_rgb: DVec3,
}

impl Sun {
    /// The sun in direction `direction` (y up) through an atmosphere of turbidity `T`, at 1 AU:
    /// `L = M_{XYZ→sRGB} · XYZ(T, m(θ_s))` ([`sun_radiance_xyz`] at the [`relative_air_mass`] of
    /// its zenith angle `θ_s`), negative channels clipped to 0.
    ///
    /// # Arguments
    /// - `turbidity`: `T`, `[1.7, 10]`.
    /// - `direction`: toward the sun, y up (normalised here); elevation `[0°, 90°]`.
    ///
    /// # Returns
    /// The [`Sun`]: its unit direction and disc radiance (linear sRGB, kcd m⁻²).
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] for a turbidity outside `[1.7, 10]` or a sun below the horizon
    /// (use [`crate::Sky`] for all elevations).
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.1.
    pub fn through_atmosphere(turbidity: f64, direction: DVec3) -> Result<Self, SkyError> {
        let turbidity = check("turbidity", turbidity, (1.7..=10.0).contains(&turbidity), "[1.7, 10]")?;
        let d = direction.normalize_or_zero();
        check("sun_elevation_deg", d.y.asin().to_degrees(), d.y >= 0.0, "[0, 90]°")?;
        let m = relative_air_mass(d.y.clamp(0.0, 1.0).acos());
        Ok(Self { direction: d, radiance_rgb: xyz_to_linear_srgb(sun_radiance_xyz(turbidity, m)).max(DVec3::ZERO) })
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

    /// Cosine of the angular radius of the disc at 1 AU, `1 − Ω/2π`.
    pub fn cos_half_angle(&self) -> f64 {
        1.0 - SUN_SOLID_ANGLE / std::f64::consts::TAU
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Kasten's fit gives m(0°) = 1 to 3×10⁻⁴.
    const KASTEN_ZENITH: f64 = 1e-3;
    /// m(90°) = 36.51 printed to 2 decimals: half a unit plus rounding.
    const KASTEN_HORIZON: f64 = 0.01;
    /// Leckner's 1978 Rayleigh fit against Bucholtz 1995: 5 %.
    const LECKNER_FIT: f64 = 0.05;
    /// The solar illuminance constant 128–134 klx around 131 klx (±2.3 %), and the table
    /// stopping at 750 nm (ȳ(750) = 1.2×10⁻⁴) and its 10 nm steps: ±8 %.
    const SOLAR_CONSTANT: f64 = 0.08;
    /// Measured clear-sky direct normal illuminance at air mass 1.5: 90–110 klx, widened for one
    /// turbidity standing for many atmospheres.
    const DIRECT_NORMAL_KLX: std::ops::RangeInclusive<f64> = 85.0..=115.0;

    #[test]
    fn air_mass_is_one_at_zenith_and_36_5_at_horizon() {
        // Kasten 1966 gives m(0°) = 1 (to 3·10⁻⁴) and m(90°) = 1/(0.15·3.885^−1.253) = 36.51
        // (Kasten & Young 1989 later refit the horizon value to 38.09).
        assert!((relative_air_mass(0.0) - 1.0).abs() < KASTEN_ZENITH);
        let m = relative_air_mass(std::f64::consts::FRAC_PI_2);
        assert!((m - 36.51).abs() < KASTEN_HORIZON, "m = {m}");
    }

    #[test]
    fn rayleigh_depth_matches_bucholtz() {
        // Leckner's fit against Bucholtz 1995 (Appl. Opt. 34:2765, US standard atmosphere):
        // τ_R(550 nm) = 0.09726, τ_R(450 nm) = 0.2245. Tolerance 5 % (Leckner's 1978 fit).
        for (l, tau) in [(550.0, 0.09726), (450.0, 0.2245)] {
            let got = -rayleigh_transmittance(l, 1.0).ln();
            assert!((got / tau - 1.0).abs() < LECKNER_FIT, "τ_R({l}) = {got}");
        }
    }

    #[test]
    fn solar_constant_and_daylight() {
        // Outside the atmosphere the disc's illuminance L Ω should be the solar illuminance
        // constant, 128–134 klx (Darula, Kittler & Gueymard 2005, Solar Energy 79:559: 133.8 klx;
        // CIE 85: 128 klx). The table stops at 750 nm (ȳ(750) = 1.2×10⁻⁴): tolerance ±8 %.
        let top = sun_radiance_xyz(2.0, 0.0);
        let e0 = top.y * SUN_SOLID_ANGLE;
        assert!((e0 / 131.0 - 1.0).abs() < SOLAR_CONSTANT, "E0 = {e0} klx");
        // Direct normal illuminance at air mass 1.5 in clean air (T = 2): measured clear-sky
        // values are 90–110 klx (e.g. Darula et al.); a wide band because T = 2 is one atmosphere.
        let e = sun_radiance_xyz(2.0, 1.5).y * SUN_SOLID_ANGLE;
        assert!(DIRECT_NORMAL_KLX.contains(&e), "E(m = 1.5) = {e} klx");
    }

    #[test]
    fn the_low_sun_is_redder_and_dimmer() {
        let high = Sun::through_atmosphere(3.0, DVec3::new(0.0, 1.0, 0.2)).unwrap().radiance_rgb();
        let low = Sun::through_atmosphere(3.0, DVec3::new(0.0, 0.05, 1.0)).unwrap().radiance_rgb();
        assert!(low.y < high.y);
        assert!(low.x / low.z > high.x / high.z);
    }

    /// Half a unit of the Astronomical Almanac's solar semidiameter, 15′59.63″ (0.005″), plus
    /// the radius convention: the Almanac's 696 000 km against IAU 2015's 695 700 km, 0.043 %.
    const SEMIDIAMETER_REL: f64 = 0.005 / 959.63 + 300.0 / 696_000.0;
    /// Half a unit of the Nautical Almanac's semidiameters printed to 0.1′.
    const NAUTICAL_HALF_UNIT_ARCMIN: f64 = 0.05;
    /// Half a unit of the published ±1.7 % swing.
    const SWING_HALF_UNIT: f64 = 5e-4;
    /// [`SUN_SOLID_ANGLE`] is printed with 8 significant digits.
    const SOLID_ANGLE_DIGITS: f64 = 1e-7;

    #[test]
    fn sun_disc_has_the_published_semidiameter() {
        // The Astronomical Almanac's solar semidiameter at 1 AU: 15′59.63″ = 959.63″ (the mean
        // 16′, 0.2666°); it varies as 1/r, ±1.7 % between perihelion (0.98329 AU, early January)
        // and aphelion (1.01671 AU, early July), where the Nautical Almanac prints 16.3′ and
        // 15.7′ (its Sun table, January and July).
        let at_1au = sun_angular_radius(1.0).to_degrees() * 3600.0;
        assert!((at_1au / 959.63 - 1.0).abs() < SEMIDIAMETER_REL, "ρ(1 AU) = {at_1au}″");
        let (peri, aph) = (sun_angular_radius(0.98329), sun_angular_radius(1.01671));
        assert!((peri.to_degrees() * 60.0 - 16.3).abs() < NAUTICAL_HALF_UNIT_ARCMIN + 16.0 * SEMIDIAMETER_REL);
        assert!((aph.to_degrees() * 60.0 - 15.7).abs() < NAUTICAL_HALF_UNIT_ARCMIN + 16.0 * SEMIDIAMETER_REL);
        let swing = peri / sun_angular_radius(1.0) - 1.0;
        assert!((swing - 0.017).abs() < SWING_HALF_UNIT, "perihelion +{swing}");
        // The constant solid angle is that of the 1 AU disc.
        let omega = std::f64::consts::TAU * (1.0 - sun_angular_radius(1.0).cos());
        assert!((omega / SUN_SOLID_ANGLE - 1.0).abs() < SOLID_ANGLE_DIGITS, "Ω = {omega}");
    }

    #[test]
    fn gas_transmittances_are_bounded_and_confined_to_their_bands() {
        // Leckner's mixed-gas (O₂ A band, 759–771 nm) and water-vapour (689–800 nm) laws: no
        // published transmittance at these wavelengths was found to test against; their
        // invariants are: 1 outside the band and at zero air mass, in (0, 1] and decreasing with
        // the air mass inside it, and saturating (the (1 + c k m)^0.45 denominator).
        for l in [380.0, 550.0, 688.0, 758.0, 772.0] {
            assert!((mixed_gas_transmittance(l, 5.0) - 1.0).abs() < f64::EPSILON, "{l}");
        }
        for l in [380.0, 550.0, 688.0] {
            assert!((water_vapour_transmittance(l, 5.0) - 1.0).abs() < f64::EPSILON, "{l}");
        }
        for l in [760.0, 765.0, 720.0, 730.0] {
            assert!((mixed_gas_transmittance(l, 0.0) - 1.0).abs() < f64::EPSILON);
            assert!((water_vapour_transmittance(l, 0.0) - 1.0).abs() < f64::EPSILON);
            let mut last = (1.0, 1.0);
            for m in [0.5, 1.0, 2.0, 5.0, 10.0, 36.5] {
                let (g, w) = (mixed_gas_transmittance(l, m), water_vapour_transmittance(l, m));
                assert!(g > 0.0 && g <= last.0 && w > 0.0 && w <= last.1, "{l} nm, m = {m}: {g} {w}");
                last = (g, w);
            }
        }
        // Saturation: at the A-band peak (k_g = 3.0) the optical depth grows as m^0.55, not m.
        let tau = |m: f64| -mixed_gas_transmittance(760.0, m).ln();
        assert!(tau(10.0) / tau(1.0) < 10f64.powf(0.56), "{}", tau(10.0) / tau(1.0));
    }
}
