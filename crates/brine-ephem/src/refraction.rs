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

    #[test]
    fn horizon_refraction_is_about_34_arcmin() {
        // Meeus 1998 ch. 16: at the horizon, R ≈ 34′ (Sæmundsson at 1010 hPa, 10 °C gives 28.9′ for
        // h = 0 true; the apparent-altitude formula (Bennett) gives 34.5′ at h0 = 0 apparent).
        let air = Atmosphere::new(1010.0, 10.0).unwrap();
        let r = air.refraction(0.0).to_degrees() * 60.0;
        assert!((r - 28.9).abs() < 0.2, "R(0) = {r}′");
        // At h = 10° (true): 1.02/tan(10 + 10.3/15.11) = 5.40′.
        let r10 = air.refraction(10f64.to_radians()).to_degrees() * 60.0;
        assert!((r10 - 5.40).abs() < 0.02, "R(10°) = {r10}′");
        assert!(air.refraction(std::f64::consts::FRAC_PI_2).abs() < 1e-6);
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
