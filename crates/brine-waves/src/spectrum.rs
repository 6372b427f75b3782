//! The `Spectrum` trait: one-dimensional spectra of the surface elevation and their moments.

use crate::Dispersion;
use crate::integrate::simpson_log;

pub use crate::pierson_moskowitz::PiersonMoskowitz;

/// Simpson panel pairs of the moments over the whole spectrum (`m₀`, mean-square slope): 4000
/// pairs in `ln ω` or `ln k`, a step of about `2.5×10⁻³` in the logarithm, far finer than the
/// narrowest peak here (JONSWAP, `σ_a = 0.07`).
const MOMENT_PAIRS: usize = 4000;

/// Lower end of the moment integrals as a fraction of `ω_p`: below `ω_p/20` every spectrum here
/// holds less than `e⁻²⁰⁰⁰⁰⁰` of its variance (the `exp[−(5/4)(ω_p/ω)⁴]` factor).
const MOMENT_LOW: f64 = 1.0 / 20.0;

/// Upper end of `m₀` as a multiple of `ω_p`: the `ω⁻⁵` tail beyond `1000 ω_p` holds `~10⁻¹³` of
/// the variance.
const M0_HIGH: f64 = 1000.0;

/// A one-sided frequency spectrum of surface elevation, `S(ω)` in m² s rad⁻¹.
///
/// `∫₀^∞ S(ω) dω = m₀`, the variance of the elevation (m²). The wavenumber form
/// `S(k) = S(ω) dω/dk` (m³ rad⁻¹) follows from the spectrum's dispersion relation.
///
/// Implemented by [`PiersonMoskowitz`], [`crate::Jonswap`], [`crate::Tma`], [`crate::Phillips`]
/// and [`crate::Elfouhaily`].
pub trait Spectrum {
    /// Spectral density `S(ω)` (m² s rad⁻¹) at angular frequency `omega` (rad s⁻¹, `> 0`);
    /// `0` for `ω ≤ 0`.
    fn s_omega(&self, omega: f64) -> f64;

    /// Angular frequency `ω_p` of the spectral peak (rad s⁻¹). For Pierson–Moskowitz, JONSWAP,
    /// TMA and Phillips it is the exact maximum of `S(ω)`; for Elfouhaily it is `ω(k_p)`, the
    /// spectrum's peak parameter (see [`crate::Elfouhaily`]).
    fn peak_omega(&self) -> f64;

    /// Elevation variance between two frequencies, `∫_{ω_a}^{ω_b} S(ω) dω` (m²), by Simpson's rule
    /// in `ln ω` with 2000 intervals (relative error below 10⁻⁸ for the smooth spectra here).
    /// `0` unless `0 < ω_a < ω_b`.
    fn variance_between(&self, omega_a: f64, omega_b: f64) -> f64 {
        if !(omega_a > 0.0 && omega_b > omega_a) {
            return 0.0;
        }
        simpson_log(|w| self.s_omega(w), omega_a, omega_b, 1000)
    }

    /// The dispersion relation the spectrum's frequencies and wavenumbers obey (deep water unless
    /// the spectrum says otherwise: finite depth for TMA, capillary–gravity for Elfouhaily).
    fn dispersion(&self) -> Dispersion {
        Dispersion::DEEP_WATER
    }

    /// Wavenumber spectrum `S(k) = S(ω(k)) dω/dk` (m³ rad⁻¹), `∫ S(k) dk = ∫ S(ω) dω`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # References
    /// Equation sheet §4 (change of variable).
    fn s_k(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let d = self.dispersion();
        self.s_omega(d.omega(k)) * d.group_velocity(k)
    }

    /// Elevation variance `m₀ = ∫₀^∞ S(ω) dω` (m²), by Simpson's rule in `ln ω` over
    /// `[ω_p/20, 1000 ω_p]` (closed form where the spectrum has one).
    fn m0(&self) -> f64 {
        let wp = self.peak_omega();
        simpson_log(|w| self.s_omega(w), MOMENT_LOW * wp, M0_HIGH * wp, MOMENT_PAIRS)
    }

    /// Significant wave height `H_s = 4 √m₀` (m).
    ///
    /// # References
    /// Equation sheet §4; the spectral definition `H_m0` of WMO 1998, *Guide to wave analysis*.
    fn significant_wave_height(&self) -> f64 {
        4.0 * self.m0().sqrt()
    }

    /// Mean-square slope of the waves with `k_lo ≤ k ≤ k_hi`, `∫ k² S(k) dk` (dimensionless): the
    /// sum of the up-wind and cross-wind slope variances of the linear surface.
    ///
    /// # Arguments
    /// - `k_lo`, `k_hi`: wavenumber band (rad m⁻¹), `0 < k_lo < k_hi`; `0` otherwise.
    ///
    /// # References
    /// Cox & Munk 1954; equation sheet §11 (`σ_x² + σ_y² = ∫∫ |k|² Ψ(k) d²k`).
    fn mean_square_slope_between(&self, k_lo: f64, k_hi: f64) -> f64 {
        if !(k_lo > 0.0 && k_hi > k_lo) {
            return 0.0;
        }
        simpson_log(|k| k * k * self.s_k(k), k_lo, k_hi, MOMENT_PAIRS)
    }

    /// Mean-square slope of every wave up to `k_max` (rad m⁻¹), from `k(ω_p/20)` where the
    /// spectrum starts: `∫₀^{k_max} k² S(k) dk`.
    ///
    /// A `k⁻³` tail (Pierson–Moskowitz, JONSWAP) makes it grow like `ln k_max` without bound;
    /// Elfouhaily's spectrum converges (by `k ≈ 5000` rad m⁻¹).
    fn mean_square_slope(&self, k_max: f64) -> f64 {
        let k_lo = self.dispersion().wavenumber(MOMENT_LOW * self.peak_omega());
        self.mean_square_slope_between(k_lo, k_max)
    }
}
