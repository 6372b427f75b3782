//! Atmospheric refraction near the horizon.

use crate::EphemError;
use crate::error::check;

/// Altitude (degrees) below which the refraction formula is faded out; the value is NREL SPA's
/// cut-off, −(0.26667° + 0.5667°), the true altitude of the sun's centre at sunset.
pub const REFRACTION_CUTOFF_DEG: f64 = -0.83337;

/// Width (degrees) of the linear fade of the refraction below [`REFRACTION_CUTOFF_DEG`].
pub const REFRACTION_FADE_DEG: f64 = 1.0;

/// The air at the observer, for the refraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Atmosphere {
    pressure_hpa: f64,
    temperature_c: f64,
}

impl Atmosphere {
    /// Air at `pressure_hpa` and `temperature_c`.
    ///
    /// # Arguments
    /// - `pressure_hpa`: local (not sea-level-reduced) pressure, `(0, 2000]` hPa.
    /// - `temperature_c`: air temperature, `(−273, 100]` °C.
    ///
    /// # Returns
    /// The [`Atmosphere`], scaling the refraction by `(P/1010)(283/(273 + T))`.
    ///
    /// # Errors
    /// [`EphemError::OutOfRange`] naming the parameter.
    pub fn new(pressure_hpa: f64, temperature_c: f64) -> Result<Self, EphemError> {
        let p = check("pressure_hpa", pressure_hpa, pressure_hpa > 0.0 && pressure_hpa <= 2000.0, "(0, 2000] hPa")?;
        let t =
            check("temperature_c", temperature_c, temperature_c > -273.0 && temperature_c <= 100.0, "(-273, 100] °C")?;
        Ok(Self { pressure_hpa: p, temperature_c: t })
    }

    /// The standard atmosphere of NREL SPA: 1013.25 hPa, 15 °C.
    pub fn standard() -> Self {
        Self { pressure_hpa: 1013.25, temperature_c: 15.0 }
    }

    /// Pressure (hPa).
    pub fn pressure_hpa(&self) -> f64 {
        self.pressure_hpa
    }

    /// Temperature (°C).
    pub fn temperature_c(&self) -> f64 {
        self.temperature_c
    }

    /// Refraction `R` to add to a true (airless) altitude `h` to get the apparent altitude:
    /// `R = (P/1010)(283/(273 + T)) · 1.02′/tan(h + 10.3/(h + 5.11))` (h in degrees, R in
    /// arcminutes), Sæmundsson's formula as used by NREL SPA. Below [`REFRACTION_CUTOFF_DEG`] the
    /// value is faded linearly to 0 over [`REFRACTION_FADE_DEG`] (SPA stops abruptly there), so the
    /// apparent altitude stays continuous and increasing in `h`.
    ///
    /// # Arguments
    /// - `true_altitude`: airless altitude (rad), `[−π/2, π/2]`.
    ///
    /// # Returns
    /// `R` (rad), ≥ 0: 0.48° at the horizon, 1′ at 45°, 0 at the zenith.
    ///
    /// # References
    /// Sæmundsson Þ. 1986, Sky & Telescope 72:70; Meeus 1998, Eq. 16.4; Reda & Andreas 2004,
    /// NREL/TP-560-34302, Eq. 42.
    pub fn refraction(&self, true_altitude: f64) -> f64 {
        let h = true_altitude.to_degrees();
        let scale = (self.pressure_hpa / 1010.0) * (283.0 / (273.0 + self.temperature_c));
        let r = |h: f64| scale * 1.02 / (60.0 * (h + 10.3 / (h + 5.11)).to_radians().tan());
        let deg = if h >= REFRACTION_CUTOFF_DEG {
            r(h.min(90.0)).max(0.0)
        } else {
            let w = ((h - (REFRACTION_CUTOFF_DEG - REFRACTION_FADE_DEG)) / REFRACTION_FADE_DEG).clamp(0.0, 1.0);
            r(REFRACTION_CUTOFF_DEG) * w
        };
        deg.to_radians()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Refraction (arcminutes) of the ray seen at apparent altitude `h0_deg`: the true altitude
    /// `h` with `h + R(h) = h0` by bisection (the apparent altitude increases with `h`), then `R(h)`.
    fn at_apparent(air: &Atmosphere, h0_deg: f64) -> f64 {
        let (mut lo, mut hi) = ((h0_deg - 2.0).to_radians(), h0_deg.to_radians());
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if mid + air.refraction(mid) < h0_deg.to_radians() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        air.refraction(0.5 * (lo + hi)).to_degrees() * 60.0
    }

    /// Sæmundsson's formula is consistent with Bennett's to 0.1′, and Bennett's reproduces
    /// Garfinkel's refraction tables to 0.07′ over 0–90° (Meeus 1998 ch. 16): 0.17′.
    const SAEMUNDSSON_ARCMIN: f64 = 0.1 + 0.07;
    /// Half a unit of a table printed to 0.1′.
    const TABLE_HALF_UNIT_ARCMIN: f64 = 0.05;
    /// The published horizontal refractions at 10 °C differ by 1.8′ (33.6′ Pulkovo, 33.8′ the
    /// Nautical Almanac, 34.5′ Bennett, 35.4′ Allen), from the temperature lapse rate assumed
    /// near the ground; a one-number formula can be asked to fall within half that spread of each.
    const HORIZON_SPREAD_ARCMIN: f64 = 0.9;

    #[test]
    fn refraction_matches_published_tables() {
        // Allen C.W. 1976, Astrophysical Quantities, 3rd ed., p. 125 (10 °C, 1013 hPa, visible):
        // apparent altitude 10° → 5.3′, 5° → 9.9′, 2° → 18.4′; "less than 1′" at 45°.
        let allen = Atmosphere::new(1013.0, 10.0).unwrap();
        for (h0, r) in [(10.0, 5.3), (5.0, 9.9), (2.0, 18.4)] {
            let got = at_apparent(&allen, h0);
            assert!((got - r).abs() < SAEMUNDSSON_ARCMIN + TABLE_HALF_UNIT_ARCMIN, "R({h0}°) = {got}′, Allen {r}′");
        }
        assert!(at_apparent(&allen, 45.0) < 1.0 + SAEMUNDSSON_ARCMIN);
        // At the horizon (apparent altitude 0): Bennett 1982 (J. Navigation 35:255; Meeus 1998
        // ch. 16, Eq. 16.3) 34.5′ at 1010 hPa, 10 °C: the formula's stated accuracy applies.
        let standard = Atmosphere::new(1010.0, 10.0).unwrap();
        let r0 = at_apparent(&standard, 0.0);
        assert!((r0 - 34.5).abs() < SAEMUNDSSON_ARCMIN, "R(0) = {r0}′");
        // The other published horizontal refractions: Allen 35.4′ (10 °C, 1013 hPa); the
        // Nautical Almanac 2017, table A3, 33.8′ (10 °C, 1010 hPa); the Pulkovo Refraction
        // Tables (5th ed., 1985) 1977.97″ = 32.97′ at 15 °C, 1013.25 hPa (dry air, 590 nm).
        for (air, r) in [(allen, 35.4), (standard, 33.8), (Atmosphere::standard(), 1977.97 / 60.0)] {
            let got = at_apparent(&air, 0.0);
            assert!((got - r).abs() < HORIZON_SPREAD_ARCMIN, "R(0) = {got}′ vs {r}′");
        }
        // At the zenith Sæmundsson's formula gives −0.0019′ (Meeus), clamped to 0 here.
        assert!(standard.refraction(std::f64::consts::FRAC_PI_2).abs() < f64::EPSILON);
    }

    #[test]
    fn apparent_altitude_is_continuous_and_increasing() {
        let air = Atmosphere::standard();
        let mut last = f64::NEG_INFINITY;
        for i in 0..=2000 {
            let h = (-5.0 + i as f64 * 0.005).to_radians();
            let a = h + air.refraction(h);
            assert!(a > last, "not increasing at {}", h.to_degrees());
            last = a;
        }
    }
}
