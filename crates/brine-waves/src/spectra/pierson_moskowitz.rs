//! The Pierson–Moskowitz spectrum of a fully developed sea.

use crate::Spectrum;
use crate::error::{WaveError, check};
use crate::spectra::dispersion::G;

/// The Pierson–Moskowitz spectrum of a fully developed sea.
///
/// `S(ω) = α g² ω⁻⁵ exp[−β (ω₀/ω)⁴]`, `α = 8.1×10⁻³`, `β = 0.74`, `ω₀ = g/U₁₉.₅`; in wavenumber
/// (deep water) `S(k) = (α/(2k³)) exp[−β g²/(k² U₁₉.₅⁴)]`.
///
/// # References
/// Pierson W., Moskowitz L. 1964, "A proposed spectral form for fully developed wind seas based
/// on the similarity theory of S. A. Kitaigorodskii", JGR 69(24):5181–5190; docs/equations.md §4.
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
    /// Ratio `U₁₉.₅/U₁₀` for a neutral logarithmic wind profile (docs/equations.md §4).
    pub const U19_5_OVER_U10: f64 = 1.026;
    /// Largest wind speed accepted (m s⁻¹): beyond hurricane force the fit has no data.
    pub const MAX_WIND: f64 = 60.0;

    /// The spectrum for a wind speed `U₁₉.₅` measured 19.5 m above the sea (m s⁻¹,
    /// `(0, 61.56]`, i.e. `U₁₀ ≤ 60`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a wind outside `(0, 61.56]` m s⁻¹.
    pub fn from_u19_5(u19_5: f64) -> Result<Self, WaveError> {
        let u19_5 =
            check("u19_5_m_s", u19_5, u19_5 > 0.0 && u19_5 <= Self::MAX_WIND * Self::U19_5_OVER_U10, "(0, 61.56] m/s")?;
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

    /// Elevation variance in closed form, `m₀ = ∫₀^∞ S dω = α g² / (4 β ω₀⁴)`.
    ///
    /// # Returns
    /// `m₀` (m²).
    ///
    /// # References
    /// Pierson & Moskowitz 1964 (integral of their spectrum); docs/equations.md §4.
    pub fn m0(&self) -> f64 {
        Self::ALPHA * G * G / (4.0 * Self::BETA * libm::pow(self.omega_0(), 4.0))
    }

    /// Significant wave height, `H_s = 4 √m₀ = 4 √(α/(4β)) U₁₉.₅²/g ≈ 0.209 U₁₉.₅²/g`.
    ///
    /// # Returns
    /// `H_s` (m).
    ///
    /// # References
    /// Pierson & Moskowitz 1964 (`0.21 U₁₉.₅²/g`); docs/equations.md §4.
    pub fn significant_wave_height(&self) -> f64 {
        4.0 * libm::sqrt(self.m0())
    }
}

impl Spectrum for PiersonMoskowitz {
    /// `S(ω) = α g² ω⁻⁵ exp[−β (ω₀/ω)⁴]` (m² s rad⁻¹); `0` for `ω ≤ 0`.
    fn s_omega(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        let r = self.omega_0() / omega;
        // Integer powers by products (within 3 ulp of `pow`, without its cost).
        let (omega2, r2) = (omega * omega, r * r);
        Self::ALPHA * G * G / (omega2 * omega2 * omega) * libm::exp(-Self::BETA * (r2 * r2))
    }

    /// `ω_p = (4β/5)^{1/4} ω₀ ≈ 0.877 g/U₁₉.₅`.
    fn peak_omega(&self) -> f64 {
        libm::pow(0.8 * Self::BETA, 0.25) * self.omega_0()
    }

    fn m0(&self) -> f64 {
        PiersonMoskowitz::m0(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The docs/equations.md's oracle values are printed to 4–5 significant digits.
    const ORACLE_REL: f64 = 1e-4;

    /// `H_s = 2.133` m is printed to 4 digits: ±0.0005 is 2.3×10⁻⁴ relative.
    const HS_ORACLE_REL: f64 = 2.5e-4;

    /// Simpson in `ln ω` over `[0.05, 200]` rad/s against the closed form: the tail above 200 rad/s
    /// holds `αg²/(4·200⁴)` ≈ 1.2×10⁻¹⁰ m² (10⁻¹⁰ relative), the quadrature ~10⁻¹⁰.
    const QUADRATURE_REL: f64 = 1e-7;

    #[test]
    fn pm_oracle_at_10_m_s() {
        // docs/equations.md, "Reference values": U19.5 = 10 m/s.
        let pm = PiersonMoskowitz::from_u19_5(10.0).unwrap();
        assert_relative_eq!(pm.peak_omega(), 0.86050, max_relative = ORACLE_REL);
        assert_relative_eq!(2.0 * std::f64::consts::PI / pm.peak_omega(), 7.302, max_relative = ORACLE_REL);
        assert_relative_eq!(pm.s_omega(pm.peak_omega()), 0.4734, max_relative = ORACLE_REL);
        assert_relative_eq!(pm.significant_wave_height(), 2.133, max_relative = HS_ORACLE_REL);
    }

    #[test]
    fn pm_closed_form_variance_matches_quadrature() {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let numeric = pm.variance_between(0.05, 200.0);
        assert_relative_eq!(numeric, pm.m0(), max_relative = QUADRATURE_REL);
    }

    #[test]
    fn pm_rejects_calm_and_hurricane_winds() {
        assert!(PiersonMoskowitz::from_u10(0.0).is_err());
        assert!(PiersonMoskowitz::from_u10(80.0).is_err());
        assert!(PiersonMoskowitz::from_u10(f64::NAN).is_err());
        assert!(PiersonMoskowitz::from_u19_5(62.0).unwrap_err().to_string().contains("u19_5_m_s"));
    }
}
