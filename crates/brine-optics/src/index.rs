//! Refractive index of sea water by wavelength, temperature and salinity (Quan & Fry 1995).

use crate::error::{OpticsError, check};

/// Sea water of a given temperature and salinity, for its refractive index.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seawater {
    temperature_c: f64,
    salinity_psu: f64,
}

impl Seawater {
    /// Typical open-ocean surface water: 20 °C, 35 PSU.
    pub const TYPICAL: Seawater = Seawater { temperature_c: 20.0, salinity_psu: 35.0 };

    /// Water at `temperature_c` (°C, `[0, 30]`) and `salinity_psu` (‰ ≈ PSU, `[0, 35]`), the
    /// range of the data Quan & Fry fitted (Austin & Halikas 1976).
    ///
    /// # Arguments
    /// - `temperature_c`: temperature `T` (°C), `[0, 30]`.
    /// - `salinity_psu`: salinity `S` (PSU), `[0, 35]`.
    ///
    /// # Returns
    /// The water, for [`Self::refractive_index`].
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming the parameter.
    ///
    /// # References
    /// Quan X., Fry E. S. 1995, Applied Optics 34(18):3477–3480 (validity of their Eq. 3).
    pub fn new(temperature_c: f64, salinity_psu: f64) -> Result<Self, OpticsError> {
        check("temperature_c", temperature_c, (0.0..=30.0).contains(&temperature_c), "[0, 30] degC")?;
        check("salinity_psu", salinity_psu, (0.0..=35.0).contains(&salinity_psu), "[0, 35] PSU")?;
        Ok(Self { temperature_c, salinity_psu })
    }

    /// Quan & Fry's empirical index of refraction,
    /// `n = n₀ + (n₁ + n₂T + n₃T²)S + n₄T² + (n₅ + n₆S + n₇T)/λ + n₈/λ² + n₉/λ³`,
    /// `n₀ = 1.31405`, `n₁ = 1.779×10⁻⁴`, `n₂ = −1.05×10⁻⁶`, `n₃ = 1.6×10⁻⁸`, `n₄ = −2.02×10⁻⁶`,
    /// `n₅ = 15.868`, `n₆ = 0.01155`, `n₇ = −0.00423`, `n₈ = −4382`, `n₉ = 1.1455×10⁶` (λ in nm).
    ///
    /// # Arguments
    /// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped to it (the fit's range).
    ///
    /// # Returns
    /// `n` (relative to air at standard conditions, as fitted): 1.3330 for pure water at 20 °C and
    /// 589.3 nm; about 1.339 for sea water at 450 nm.
    ///
    /// # References
    /// Quan X., Fry E. S. 1995, "Empirical equation for the index of refraction of seawater",
    /// Applied Optics 34(18):3477–3480, Eq. 3.
    pub fn refractive_index(&self, lambda_nm: f64) -> f64 {
        let l = lambda_nm.clamp(400.0, 700.0);
        let (t, s) = (self.temperature_c, self.salinity_psu);
        1.31405 + (1.779e-4 - 1.05e-6 * t + 1.6e-8 * t * t) * s - 2.02e-6 * t * t
            + (15.868 + 0.01155 * s - 0.00423 * t) / l
            - 4382.0 / (l * l)
            + 1.1455e6 / (l * l * l)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pure_water_sodium_d_line() {
        // n_D of pure water at 20 °C is 1.33299 (IAPWS 1997 formulation, 589.26 nm); Quan & Fry
        // quote their fit's accuracy as about 3×10⁻⁵ over the fitted data.
        /// Quan & Fry's accuracy plus the 0.04 nm rounding of the D line (dn/dλ ≈ 3×10⁻⁵/nm).
        const FIT: f64 = 1e-4;
        let n = Seawater::new(20.0, 0.0).unwrap().refractive_index(589.3);
        assert!((n - 1.33299).abs() < FIT, "{n}");
    }

    #[test]
    fn index_falls_with_wavelength_and_rises_with_salinity() {
        let w = Seawater::TYPICAL;
        assert!(w.refractive_index(450.0) > w.refractive_index(650.0));
        let fresh = Seawater::new(20.0, 0.0).unwrap();
        assert!(w.refractive_index(550.0) > fresh.refractive_index(550.0));
        assert!(Seawater::new(40.0, 35.0).is_err());
    }
}
