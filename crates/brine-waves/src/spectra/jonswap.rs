//! The JONSWAP spectrum of a fetch-limited sea.

use crate::Spectrum;
use crate::error::{WaveError, check};
use crate::spectra::dispersion::G;

/// The JONSWAP spectrum (Hasselmann et al. 1973) of a fetch-limited, growing wind sea.
///
/// `S(ω) = α g² ω⁻⁵ exp[−(5/4)(ω_p/ω)⁴] γ^r`, `r = exp[−(ω − ω_p)²/(2σ²ω_p²)]`,
/// `σ = σ_a` (0.07) for `ω ≤ ω_p`, `σ_b` (0.09) above, `γ = 3.3`; from the wind `U₁₀` and the
/// fetch `F`: `α = 0.076 (U₁₀²/(F g))^{0.22}`, `ω_p = 22 (g²/(U₁₀ F))^{1/3}`.
///
/// With `γ = 1` it is the Pierson–Moskowitz form with the same `α` and `ω_p`.
///
/// # Validity
/// The fetch relations were fitted for dimensionless fetches `X̃ = gF/U₁₀²` of about 10²–10⁴.
/// Beyond [`Jonswap::fully_developed_fetch`] (`X̃ ≈ 1.70×10⁴`) the sea stops growing: the peak
/// would fall below Pierson–Moskowitz's `0.855 g/U₁₀`, so the fetch is clamped there (documented
/// clamp, see [`Jonswap::from_fetch`]).
///
/// # References
/// Hasselmann K. et al. 1973, "Measurements of wind-wave growth and swell decay during the Joint
/// North Sea Wave Project (JONSWAP)", Dtsch. Hydrogr. Z. A8(12); docs/equations.md §4 (Horvath 2015
/// prints `ω_p` without the cube root: erratum).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jonswap {
    alpha: f64,
    omega_p: f64,
    gamma: f64,
    sigma_a: f64,
    sigma_b: f64,
}

impl Jonswap {
    /// Mean peak enhancement `γ` of the JONSWAP data.
    pub const GAMMA: f64 = 3.3;
    /// Peak width `σ_a` below the peak.
    pub const SIGMA_A: f64 = 0.07;
    /// Peak width `σ_b` above the peak.
    pub const SIGMA_B: f64 = 0.09;

    /// Dimensionless fetch `X̃ = gF/U₁₀²` at which the JONSWAP peak `22 X̃^{−1/3} g/U₁₀` equals the
    /// Pierson–Moskowitz peak `(4β/5)^{1/4} g/(1.026 U₁₀)`: `X̃ = (22 · 1.026/(4β/5)^{1/4})³ ≈ 1.70×10⁴`.
    ///
    /// # Returns
    /// `X̃` (dimensionless).
    ///
    /// # References
    /// Derived from Hasselmann et al. 1973 and Pierson & Moskowitz 1964 (docs/equations.md §4).
    pub fn fully_developed_fetch() -> f64 {
        let pm_peak = libm::pow(0.8 * crate::PiersonMoskowitz::BETA, 0.25) / crate::PiersonMoskowitz::U19_5_OVER_U10;
        libm::pow(22.0 / pm_peak, 3.0)
    }

    /// The spectrum of a wind `U₁₀` blowing over a fetch `F`, with `γ = 3.3`, `σ_a = 0.07`,
    /// `σ_b = 0.09` ([`Jonswap::with_peak_shape`] changes them).
    ///
    /// # Arguments
    /// - `u10`: wind speed 10 m above the sea (m s⁻¹), `(0, 60]`.
    /// - `fetch_m`: fetch `F` (m), `(0, 10⁸]`; clamped to `X̃ = gF/U₁₀² ≤ 1.70×10⁴` (fully
    ///   developed sea, see the type's docs).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn from_fetch(u10: f64, fetch_m: f64) -> Result<Self, WaveError> {
        let u10 = check("u10_m_s", u10, u10 > 0.0 && u10 <= 60.0, "(0, 60] m/s")?;
        let fetch = check("fetch_m", fetch_m, fetch_m > 0.0 && fetch_m <= 1e8, "(0, 1e8] m")?;
        let x = (G * fetch / (u10 * u10)).min(Self::fully_developed_fetch());
        let alpha = 0.076 * libm::pow(x, -0.22);
        let omega_p = 22.0 * libm::pow(x, -1.0 / 3.0) * G / u10;
        Self::new(alpha, omega_p)
    }

    /// The spectrum with an explicit Phillips constant `α` and peak `ω_p` (γ = 3.3).
    ///
    /// # Arguments
    /// - `alpha`: Phillips constant (dimensionless), `(0, 1)`.
    /// - `omega_p`: peak angular frequency (rad s⁻¹), `(0, ∞)`, finite: as for
    ///   Pierson–Moskowitz, the peak [`Jonswap::from_fetch`] gives at a wind of `(0, 60]` m/s
    ///   down to 5×10⁻³⁰⁸ m/s, where `0.855 g/U₁₀` overflows (a peak of 500 rad/s is a wave a
    ///   quarter of a millimetre long).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn new(alpha: f64, omega_p: f64) -> Result<Self, WaveError> {
        let alpha = check("alpha", alpha, alpha > 0.0 && alpha < 1.0, "(0, 1)")?;
        let omega_p = check("omega_p_rad_s", omega_p, omega_p > 0.0 && omega_p.is_finite(), "(0, ∞) rad/s")?;
        Ok(Self { alpha, omega_p, gamma: Self::GAMMA, sigma_a: Self::SIGMA_A, sigma_b: Self::SIGMA_B })
    }

    /// The same spectrum with another peak shape.
    ///
    /// # Arguments
    /// - `gamma`: peak enhancement `γ` (dimensionless), `[1, 20]` (1 is Pierson–Moskowitz).
    /// - `sigma_a`, `sigma_b`: peak widths below / above `ω_p` (dimensionless), `(0, 1]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn with_peak_shape(self, gamma: f64, sigma_a: f64, sigma_b: f64) -> Result<Self, WaveError> {
        let gamma = check("gamma", gamma, (1.0..=20.0).contains(&gamma), "[1, 20]")?;
        let sigma_a = check("sigma_a", sigma_a, sigma_a > 0.0 && sigma_a <= 1.0, "(0, 1]")?;
        let sigma_b = check("sigma_b", sigma_b, sigma_b > 0.0 && sigma_b <= 1.0, "(0, 1]")?;
        Ok(Self { gamma, sigma_a, sigma_b, ..self })
    }

    /// A swell of significant height `H_s`: the spectrum of peak `ω_p = 2π/T_p` and enhancement `γ`
    /// (peak widths 0.07 / 0.09) with the Phillips constant that makes `4√m₀ = H_s` (`m₀` is linear
    /// in `α`), `α` kept within `[10⁻⁹, 0.99]`.
    ///
    /// # Arguments
    /// - `significant_height_m`: `H_s` (m), `(0, 30]`.
    /// - `peak_period_s`: `T_p` (s), `[1, 30]`.
    /// - `gamma`: `γ`, `[1, 20]` (swells are narrow: 3.3 to 10).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    ///
    /// # References
    /// Hasselmann et al. 1973 (JONSWAP); `H_s = 4√m₀` (Holthuijsen 2007, *Waves in Oceanic and
    /// Coastal Waters*, §4.2).
    pub fn swell(significant_height_m: f64, peak_period_s: f64, gamma: f64) -> Result<Self, WaveError> {
        let hs = check(
            "significant_height_m",
            significant_height_m,
            significant_height_m > 0.0 && significant_height_m <= 30.0,
            "(0, 30] m",
        )?;
        let tp = check("peak_period_s", peak_period_s, (1.0..=30.0).contains(&peak_period_s), "[1, 30] s")?;
        let omega_p = std::f64::consts::TAU / tp;
        let unit = Self::new(1e-3, omega_p)?.with_peak_shape(gamma, 0.07, 0.09)?;
        let target_m0 = (hs / 4.0).powi(2);
        let alpha = (1e-3 * target_m0 / unit.m0()).clamp(1e-9, 0.99);
        Self::new(alpha, omega_p)?.with_peak_shape(gamma, 0.07, 0.09)
    }

    /// Phillips constant `α` (dimensionless).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// Peak enhancement `γ` (dimensionless).
    pub fn gamma(&self) -> f64 {
        self.gamma
    }
    /// Peak widths `(σ_a, σ_b)` (dimensionless).
    pub fn sigmas(&self) -> (f64, f64) {
        (self.sigma_a, self.sigma_b)
    }

    /// Peak enhancement factor, `γ^r` with `r = exp[−(ω − ω_p)²/(2σ²ω_p²)]`.
    ///
    /// # Arguments
    /// - `omega`: angular frequency (rad s⁻¹).
    ///
    /// # Returns
    /// `γ^r` (dimensionless, in `[1, γ]`).
    ///
    /// # References
    /// Hasselmann et al. 1973; docs/equations.md §4.
    pub fn peak_enhancement(&self, omega: f64) -> f64 {
        let sigma = if omega <= self.omega_p { self.sigma_a } else { self.sigma_b };
        let d = (omega - self.omega_p) / (sigma * self.omega_p);
        libm::pow(self.gamma, libm::exp(-0.5 * d * d))
    }
}

impl Spectrum for Jonswap {
    /// `S(ω) = α g² ω⁻⁵ exp[−(5/4)(ω_p/ω)⁴] γ^r` (m² s rad⁻¹); `0` for `ω ≤ 0`.
    fn s_omega(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        let r = self.omega_p / omega;
        // Integer powers by products (within 3 ulp of `pow`, without its cost).
        let (omega2, r2) = (omega * omega, r * r);
        self.alpha * G * G / (omega2 * omega2 * omega) * libm::exp(-1.25 * (r2 * r2)) * self.peak_enhancement(omega)
    }

    /// `ω_p`, where both the Pierson–Moskowitz factor and `γ^r` peak.
    fn peak_omega(&self) -> f64 {
        self.omega_p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `4√m₀` of the swell is its significant height (to the quadrature of `m0`).
    #[test]
    fn a_swell_has_its_significant_height() {
        for (hs, tp, gamma) in [(1.5, 10.0, 3.3), (4.0, 14.0, 7.0)] {
            let s = Jonswap::swell(hs, tp, gamma).unwrap();
            assert!((4.0 * s.m0().sqrt() / hs - 1.0).abs() < 1e-6, "{hs} {tp}");
            assert!((s.peak_omega() - std::f64::consts::TAU / tp).abs() < 1e-12);
        }
        assert!(Jonswap::swell(0.0, 10.0, 3.3).is_err() && Jonswap::swell(2.0, 0.5, 3.3).is_err());
    }

    /// `γ^r` with `r = 1` (peak) or `r = e^{−200}` (far): rounding of `pow` and `exp`; the clamped
    /// fetch reproduces PM's `ω_p` through the same constants, to rounding.
    const ROUND_ABS: f64 = 1e-12;

    #[test]
    fn enhancement_is_gamma_at_the_peak_and_one_far_away() {
        let j = Jonswap::from_fetch(10.0, 1e5).unwrap();
        assert!((j.peak_enhancement(j.peak_omega()) - 3.3).abs() < ROUND_ABS);
        assert!((j.peak_enhancement(3.0 * j.peak_omega()) - 1.0).abs() < ROUND_ABS);
    }

    /// The lightest winds give a peak of capillary ripples (`0.855 g/U₁₀`, over 8 000 rad/s at
    /// 1 mm/s), still a spectrum, as Pierson–Moskowitz's at the same wind; a peak of 0, infinite
    /// or NaN is refused.
    #[test]
    fn the_lightest_winds_give_a_spectrum_of_ripples() {
        for u10 in [1e-3, 0.01, 0.03, 0.08] {
            let j = Jonswap::from_fetch(u10, 1e8).unwrap();
            let pm = crate::PiersonMoskowitz::from_u10(u10).unwrap();
            assert!(j.peak_omega() > 100.0 && j.peak_omega().is_finite(), "{u10}: {}", j.peak_omega());
            assert!((j.peak_omega() / pm.peak_omega() - 1.0).abs() < ROUND_ABS, "{u10}");
            assert!(crate::Tma::new(j, 20.0).is_ok(), "{u10}");
        }
        for bad in [0.0, f64::INFINITY, f64::NAN, -1.0] {
            assert!(Jonswap::new(0.01, bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn very_long_fetches_are_clamped_to_a_fully_developed_sea() {
        let a = Jonswap::from_fetch(10.0, 5e6).unwrap();
        let b = Jonswap::from_fetch(10.0, 1e7).unwrap();
        assert_eq!(a, b);
        let pm = crate::PiersonMoskowitz::from_u10(10.0).unwrap();
        assert!((a.peak_omega() / pm.peak_omega() - 1.0).abs() < ROUND_ABS);
    }

    #[test]
    fn bad_parameters_are_named() {
        assert!(Jonswap::from_fetch(10.0, 0.0).unwrap_err().to_string().contains("fetch_m"));
        assert!(Jonswap::from_fetch(0.0, 1e4).unwrap_err().to_string().contains("u10_m_s"));
        let j = Jonswap::new(0.01, 1.0).unwrap();
        assert!(j.with_peak_shape(0.5, 0.07, 0.09).unwrap_err().to_string().contains("gamma"));
    }
}
