//! One-dimensional frequency spectra of wind seas.

use crate::dispersion::G;
use crate::error::{WaveError, check};
use crate::integrate::simpson_log;

/// A one-sided frequency spectrum of surface elevation, `S(ω)` in m² s rad⁻¹.
///
/// `∫₀^∞ S(ω) dω = m₀`, the variance of the elevation (m²).
pub trait Spectrum {
    /// Spectral density `S(ω)` (m² s rad⁻¹) at angular frequency `omega` (rad s⁻¹, `> 0`).
    fn s_omega(&self, omega: f64) -> f64;

    /// Angular frequency `ω_p` of the spectral peak (rad s⁻¹).
    fn peak_omega(&self) -> f64;

    /// Elevation variance between two frequencies, `∫_{ω_a}^{ω_b} S(ω) dω` (m²), by Simpson's rule
    /// in `ln ω` with 2000 intervals (relative error below 10⁻⁸ for the smooth spectra here).
    fn variance_between(&self, omega_a: f64, omega_b: f64) -> f64 {
        simpson_log(|w| self.s_omega(w), omega_a, omega_b, 1000)
    }
}

/// The Pierson–Moskowitz spectrum of a fully developed sea.
///
/// `S(ω) = α g² ω⁻⁵ exp[−β (ω₀/ω)⁴]`, `α = 8.1×10⁻³`, `β = 0.74`, `ω₀ = g/U₁₉.₅`.
///
/// # References
/// Pierson W., Moskowitz L. 1964, "A proposed spectral form for fully developed wind seas based
/// on the similarity theory of S. A. Kitaigorodskii", JGR 69(24):5181–5190; equation sheet §4.
/// Used by Darles et al. 2007 (§3) for every picture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PiersonMoskowitz {
    u19_5: f64,
}

impl PiersonMoskowitz {
    /// Phillips' constant `α`.
    pub const ALPHA: f64 = 8.1e-3;
    /// Pierson–Moskowitz `β`.
    pub const BETA: f64 = 0.74;
    /// Ratio `U₁₉.₅/U₁₀` for a neutral logarithmic wind profile (equation sheet §4).
    pub const U19_5_OVER_U10: f64 = 1.026;
    /// Largest wind speed accepted (m s⁻¹): beyond hurricane force the fit has no data.
    pub const MAX_WIND: f64 = 60.0;

    /// The spectrum for a wind speed `U₁₉.₅` measured 19.5 m above the sea (m s⁻¹, `(0, 60]`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a wind outside `(0, 60]` m s⁻¹.
    pub fn from_u19_5(u19_5: f64) -> Result<Self, WaveError> {
        let u19_5 = check("u19_5_m_s", u19_5, u19_5 > 0.0 && u19_5 <= Self::MAX_WIND * 1.026, "(0, 61.56] m/s")?;
        Ok(Self { u19_5 })
    }

    /// The spectrum for a wind speed `U₁₀` measured 10 m above the sea (m s⁻¹, `(0, 60]`),
    /// converted with `U₁₉.₅ = 1.026 U₁₀`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a wind outside `(0, 60]` m s⁻¹.
    pub fn from_u10(u10: f64) -> Result<Self, WaveError> {
        let u10 = check("u10_m_s", u10, u10 > 0.0 && u10 <= Self::MAX_WIND, "(0, 60] m/s")?;
        Ok(Self { u19_5: u10 * Self::U19_5_OVER_U10 })
    }

    /// Wind speed at 19.5 m (m s⁻¹).
    pub fn u19_5(&self) -> f64 {
        self.u19_5
    }

    /// `ω₀ = g/U₁₉.₅` (rad s⁻¹).
    pub fn omega_0(&self) -> f64 {
        G / self.u19_5
    }

    /// Elevation variance `m₀ = ∫₀^∞ S dω = α g² / (4 β ω₀⁴)` (m²), in closed form.
    pub fn m0(&self) -> f64 {
        Self::ALPHA * G * G / (4.0 * Self::BETA * self.omega_0().powi(4))
    }

    /// Significant wave height `H_s = 4 √m₀` (m).
    pub fn significant_wave_height(&self) -> f64 {
        4.0 * self.m0().sqrt()
    }
}

impl Spectrum for PiersonMoskowitz {
    /// `S(ω) = α g² ω⁻⁵ exp[−β (ω₀/ω)⁴]` (m² s rad⁻¹); `0` for `ω ≤ 0`.
    fn s_omega(&self, omega: f64) -> f64 {
        if omega <= 0.0 {
            return 0.0;
        }
        let r = self.omega_0() / omega;
        Self::ALPHA * G * G * omega.powi(-5) * (-Self::BETA * r.powi(4)).exp()
    }

    /// `ω_p = (4β/5)^{1/4} ω₀ ≈ 0.877 g/U₁₉.₅`.
    fn peak_omega(&self) -> f64 {
        (0.8 * Self::BETA).powf(0.25) * self.omega_0()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The equation sheet's oracle values are printed to 4–5 significant digits.
    const ORACLE_REL: f64 = 1e-4;

    #[test]
    fn pm_oracle_at_10_m_s() {
        // Equation sheet, "Test oracles": U19.5 = 10 m/s.
        let pm = PiersonMoskowitz::from_u19_5(10.0).unwrap();
        assert_relative_eq!(pm.peak_omega(), 0.86050, max_relative = ORACLE_REL);
        assert_relative_eq!(2.0 * std::f64::consts::PI / pm.peak_omega(), 7.302, max_relative = ORACLE_REL);
        assert_relative_eq!(pm.s_omega(pm.peak_omega()), 0.4734, max_relative = ORACLE_REL);
        assert_relative_eq!(pm.significant_wave_height(), 2.133, max_relative = 2e-4);
    }

    #[test]
    fn pm_closed_form_variance_matches_quadrature() {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let numeric = pm.variance_between(0.05, 200.0);
        // The tail above 200 rad/s holds α g²/(4·200⁴) ≈ 1.2e-10 m².
        assert_relative_eq!(numeric, pm.m0(), max_relative = 1e-7);
    }

    #[test]
    fn pm_rejects_calm_and_hurricane_winds() {
        assert!(PiersonMoskowitz::from_u10(0.0).is_err());
        assert!(PiersonMoskowitz::from_u10(80.0).is_err());
        assert!(PiersonMoskowitz::from_u10(f64::NAN).is_err());
    }
}
