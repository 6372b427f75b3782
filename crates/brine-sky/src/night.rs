//! The night: the natural glow of the night sky and the Moon's light.

use std::f64::consts::PI;

/// Zenith luminance of a dark, moonless night sky (airglow, zodiacal light, starlight), V band:
/// 79 nL = 2.5×10⁻⁴ cd m⁻² (21.6 mag arcsec⁻²), in kcd m⁻².
///
/// # References
/// Krisciunas K., Schaefer B.E. 1991, "A model of the brightness of moonlight", PASP 103:1033,
/// §2 (`B_zen = 79 nL` at Mauna Kea); 1 nL = 10⁻⁹/π cd cm⁻².
pub const NIGHT_ZENITH_LUMINANCE: f64 = 79e-9 / PI * 1e4 * 1e-3;

/// Extinction coefficient of the V band used for the night sky, `k = 0.172` mag per air mass.
pub const V_EXTINCTION: f64 = 0.172;

/// Apparent V magnitude of the Sun, `−26.74`.
pub const SUN_V_MAGNITUDE: f64 = -26.74;

/// Mean Earth–Moon distance (km) at which the moon's magnitude law is given.
pub const MOON_MEAN_DISTANCE_KM: f64 = 384_400.0;

/// Mean radius of the Moon (km).
pub const MOON_RADIUS_KM: f64 = 1737.4;

/// The optical path through a thin layer, `X(Z) = (1 − 0.96 sin² Z)^{−1/2}`.
///
/// # Arguments
/// - `cos_z`: cosine of the zenith angle, `[0, 1]` (clamped).
///
/// # Returns
/// `X` (1 at the zenith, 5 at the horizon).
///
/// # References
/// Krisciunas & Schaefer 1991, Eq. 3.
pub fn layer_air_mass(cos_z: f64) -> f64 {
    let c = cos_z.clamp(0.0, 1.0);
    (1.0 - 0.96 * (1.0 - c * c)).powf(-0.5)
}

/// Luminance of the moonless night sky toward zenith angle `Z`:
/// `B(Z) = B_zen 10^{−0.4 k (X − 1)} X` (van Rhijn brightening of a glowing layer, dimmed by
/// extinction).
///
/// # Arguments
/// - `cos_z`: cosine of the view zenith angle (clamped to `[0, 1]`).
///
/// # Returns
/// Luminance (kcd m⁻²): 2.5×10⁻⁷ at the zenith, 2.6 times more at the horizon.
///
/// # References
/// Krisciunas & Schaefer 1991, Eq. 2.
pub fn night_sky_luminance(cos_z: f64) -> f64 {
    let x = layer_air_mass(cos_z);
    NIGHT_ZENITH_LUMINANCE * 10f64.powf(-0.4 * V_EXTINCTION * (x - 1.0)) * x
}

/// Disc-integrated Lommel–Seeliger phase law of a sphere,
/// `Φ(φ) = 1 − sin(φ/2) tan(φ/2) ln cot(φ/4)`.
///
/// # Arguments
/// - `phase_angle`: Sun–Moon–observer angle `φ` (rad), `[0, π]`.
///
/// # Returns
/// `Φ ∈ [0, 1]`: 1 at full moon, 0.377 at quarter, 0 at new moon.
///
/// # References
/// Jensen H.W. et al. 2001, "A physically-based night sky model", SIGGRAPH, §4 (docs/equations.md
/// §13).
pub fn lommel_seeliger_phase(phase_angle: f64) -> f64 {
    let phi = phase_angle.clamp(0.0, PI);
    if phi < 1e-9 {
        return 1.0;
    }
    if phi > PI - 1e-9 {
        return 0.0;
    }
    let h = 0.5 * phi;
    (1.0 - h.sin() * h.tan() * (1.0 / (0.25 * phi).tan()).ln()).clamp(0.0, 1.0)
}

/// Illuminance of the Moon outside the atmosphere relative to the Sun's, from its measured
/// V magnitude `m(φ) = −12.73 + 0.026|φ°| + 4×10⁻⁹ φ°⁴` at the mean distance (the full-moon
/// opposition surge included): `E_moon/E_sun = 10^{−0.4(m − m_☉)} (384400 km/Δ)²`.
///
/// # Arguments
/// - `phase_angle`: `φ` (rad), `[0, π]`.
/// - `distance_km`: Earth–Moon distance `Δ` (km), > 0.
///
/// # Returns
/// The ratio (dimensionless): 2.6×10⁻⁶ at full moon (0.33 lx for 128 klx of sunlight).
///
/// # References
/// Krisciunas & Schaefer 1991, Eq. 9 (after Allen 1973, *Astrophysical Quantities*); the law is
/// fitted for `φ` up to about 150°, beyond which the Moon is a thin crescent near the Sun.
pub fn moon_to_sun_illuminance(phase_angle: f64, distance_km: f64) -> f64 {
    let a = phase_angle.clamp(0.0, PI).to_degrees();
    let m = -12.73 + 0.026 * a + 4e-9 * a.powi(4);
    10f64.powf(-0.4 * (m - SUN_V_MAGNITUDE)) * (MOON_MEAN_DISTANCE_KM / distance_km).powi(2)
}

/// Illuminance of the Moon outside the atmosphere relative to the Sun's by Jensen et al.'s
/// Lommel–Seeliger model, `E_m/E_☉ = (2/3) C (r_m/Δ)² [Φ(φ) + (E_em/E_☉) Φ(π − φ)]`, with the
/// earthshine at the Moon `E_em = 0.095 W m⁻²` over the solar constant 1361 W m⁻².
///
/// # Arguments
/// - `phase_angle`: `φ` (rad), `[0, π]`.
/// - `distance_km`: `Δ` (km), > 0.
/// - `albedo`: mean lunar albedo `C`, `[0.07, 0.12]` in the literature.
///
/// # Returns
/// The ratio (dimensionless); with `C = 0.12` it is 1.6×10⁻⁶ at full moon and, at quarter,
/// four times the measured value (Lommel–Seeliger has no shadow-hiding opposition effect): kept
/// for comparison, [`moon_to_sun_illuminance`] is the default.
///
/// # References
/// Jensen et al. 2001, §4.1; docs/equations.md §13.
pub fn moon_to_sun_illuminance_jensen(phase_angle: f64, distance_km: f64, albedo: f64) -> f64 {
    let earthshine = 0.095 / 1361.0;
    let phi = phase_angle.clamp(0.0, PI);
    2.0 / 3.0
        * albedo
        * (MOON_RADIUS_KM / distance_km).powi(2)
        * (lommel_seeliger_phase(phi) + earthshine * lommel_seeliger_phase(PI - phi))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2.4889×10⁻⁶ is printed with 5 digits: half a unit is 5×10⁻¹¹.
    const HALF_UNIT_5_DIGITS: f64 = 5e-11;
    /// Measured full-moon illuminances outside the atmosphere, 0.26–0.32 lx, over the solar
    /// 128–134 klx: (2.0–2.5)×10⁻⁶, widened to 1.9–2.6×10⁻⁶.
    const MEASURED_FULL_MOON: std::ops::RangeInclusive<f64> = 1.9e-6..=2.6e-6;
    /// The quarter moon is about 1/11 of the full (2.6 magnitudes fainter, Krisciunas & Schaefer).
    const QUARTER_OF_FULL: std::ops::Range<f64> = 0.08..0.1;
    /// Closed forms evaluated in double precision.
    const ROUNDING: f64 = 1e-12;
    /// Half a unit of the 5th decimal (0.37677).
    const HALF_UNIT_5_DECIMALS: f64 = 5e-6;
    /// 2.515×10⁻⁷ kcd m⁻² printed with 4 digits: half a unit 5×10⁻¹¹.
    const HALF_UNIT_GLOW: f64 = 5e-11;
    /// Half a unit of the 2nd decimal (2.65).
    const HALF_UNIT_2_DECIMALS: f64 = 5e-3;

    #[test]
    fn full_moon_illuminance() {
        // The full Moon at mean distance is m = −12.73 (Krisciunas & Schaefer 1991, Eq. 9):
        // 10^{−0.4·14.01} = 2.489×10⁻⁶ of sunlight. Measured full-moon illuminances at the top of
        // the atmosphere are 0.26–0.32 lx (e.g. Kyba et al. 2017), i.e. (2.0–2.5)×10⁻⁶ of
        // 128–134 klx: tolerance band 1.9–2.6×10⁻⁶.
        let r = moon_to_sun_illuminance(0.0, MOON_MEAN_DISTANCE_KM);
        assert!((r - 2.4889e-6).abs() < HALF_UNIT_5_DIGITS, "{r}");
        assert!(MEASURED_FULL_MOON.contains(&r));
        // Quarter moon is about 1/11 of full (2.6 magnitudes fainter).
        let q = moon_to_sun_illuminance(PI / 2.0, MOON_MEAN_DISTANCE_KM) / r;
        assert!((q - 10f64.powf(-0.4 * (0.026 * 90.0 + 4e-9 * 90f64.powi(4)))).abs() < ROUNDING);
        assert!(QUARTER_OF_FULL.contains(&q), "{q}");
    }

    #[test]
    fn lommel_seeliger_values() {
        // Φ(90°) = 1 − (√2/2)·1·ln(cot 22.5°) = 1 − 0.70711·0.88137 = 0.37677.
        assert!((lommel_seeliger_phase(PI / 2.0) - 0.37677).abs() < HALF_UNIT_5_DECIMALS);
        assert!((lommel_seeliger_phase(0.0) - 1.0).abs() < ROUNDING);
        assert!(lommel_seeliger_phase(PI) < ROUNDING);
        let mut last = 1.0;
        for i in 1..=180 {
            let v = lommel_seeliger_phase((i as f64).to_radians());
            assert!(v <= last && v >= 0.0);
            last = v;
        }
    }

    #[test]
    fn night_sky_is_brighter_toward_the_horizon() {
        assert!((night_sky_luminance(1.0) - 2.515e-7).abs() < HALF_UNIT_GLOW);
        let h = night_sky_luminance(0.0) / night_sky_luminance(1.0);
        // X(90°) = 5: 10^{−0.4·0.172·4}·5 = 2.65.
        assert!((h - 2.65).abs() < HALF_UNIT_2_DECIMALS, "{h}");
    }
}
