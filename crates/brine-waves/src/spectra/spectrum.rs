//! The `Spectrum` trait: one-dimensional spectra of the surface elevation and their moments.

use crate::Dispersion;
use crate::spectra::integrate::simpson_log;

pub use crate::spectra::pierson_moskowitz::PiersonMoskowitz;

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
///
/// `Sync`: the FFT ocean integrates its grids over rows in parallel.
pub trait Spectrum: Sync {
    /// One-sided frequency spectrum of the surface elevation, `S(ω)`: the elevation variance per
    /// unit angular frequency, `m₀ = ∫₀^∞ S(ω) dω`.
    ///
    /// # Arguments
    /// - `omega`: angular frequency `ω` (rad s⁻¹), `> 0`.
    ///
    /// # Returns
    /// `S(ω)` (m² s rad⁻¹), finite and `≥ 0`; `0` for `ω ≤ 0` or NaN.
    ///
    /// # References
    /// docs/equations.md §4 (each implementation cites its paper and equation).
    fn s_omega(&self, omega: f64) -> f64;

    /// Angular frequency `ω_p` of the spectral peak. For Pierson–Moskowitz, JONSWAP, TMA and
    /// Phillips it is the maximum of `S(ω)` (closed form, or golden-section search for TMA); for
    /// Elfouhaily it is `ω(k_p)`, the spectrum's peak parameter (see [`crate::Elfouhaily`]).
    ///
    /// # Returns
    /// `ω_p` (rad s⁻¹), `> 0`.
    ///
    /// # References
    /// docs/equations.md §4 (PM: `ω_p = (4β/5)^{1/4} g/U₁₉.₅`; JONSWAP: `22 X̃^{−1/3} g/U₁₀`).
    fn peak_omega(&self) -> f64;

    /// Elevation variance of the waves between two frequencies, `∫_{ω_a}^{ω_b} S(ω) dω`, by
    /// Simpson's rule in `ln ω` with 2000 intervals (relative error below 10⁻⁸ for the smooth
    /// spectra here).
    ///
    /// # Arguments
    /// - `omega_a`, `omega_b`: band (rad s⁻¹), `0 < ω_a < ω_b`.
    ///
    /// # Returns
    /// The variance (m²); `0` unless `0 < ω_a < ω_b`.
    ///
    /// # References
    /// docs/equations.md §4 (`m₀ = ∫ S dω`).
    fn variance_between(&self, omega_a: f64, omega_b: f64) -> f64 {
        if !(omega_a > 0.0 && omega_b > omega_a) {
            return 0.0;
        }
        simpson_log(|w| self.s_omega(w), omega_a, omega_b, 1000)
    }

    /// The dispersion relation `ω(k)` the spectrum's frequencies and wavenumbers obey.
    ///
    /// # Returns
    /// Deep water `ω² = gk` unless the spectrum says otherwise: finite depth
    /// `ω² = gk tanh(kh)` for TMA, capillary–gravity `ω² = gk(1 + (k/k_m)²)` for Elfouhaily.
    ///
    /// # References
    /// docs/equations.md §1 and §4; Elfouhaily et al. 1997, Eq. 24.
    fn dispersion(&self) -> Dispersion {
        Dispersion::DEEP_WATER
    }

    /// Wavenumber spectrum of the elevation, `S(k) = S(ω(k)) dω/dk`, so that
    /// `∫ S(k) dk = ∫ S(ω) dω`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `S(k)` (m³ rad⁻¹), `≥ 0`; `0` for `k ≤ 0`.
    ///
    /// # References
    /// docs/equations.md §4 (change of variable).
    fn s_k(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let d = self.dispersion();
        self.s_omega(d.omega(k)) * d.group_velocity(k)
    }

    /// Elevation variance of the whole sea, `m₀ = ∫₀^∞ S(ω) dω`, by Simpson's rule in `ln ω` over
    /// `[ω_p/20, 1000 ω_p]` (implementations with a closed form may use it).
    ///
    /// # Returns
    /// `m₀` (m²).
    ///
    /// # References
    /// docs/equations.md §4; WMO 1998, *Guide to wave analysis and forecasting* (spectral moments).
    fn m0(&self) -> f64 {
        let wp = self.peak_omega();
        simpson_log(|w| self.s_omega(w), MOMENT_LOW * wp, M0_HIGH * wp, MOMENT_PAIRS)
    }

    /// Significant wave height, the spectral estimate `H_s = H_m0 = 4 √m₀`.
    ///
    /// # Returns
    /// `H_s` (m).
    ///
    /// # References
    /// docs/equations.md §4; the spectral definition `H_m0` of WMO 1998, *Guide to wave analysis*.
    fn significant_wave_height(&self) -> f64 {
        4.0 * self.m0().sqrt()
    }

    /// Mean-square slope of the waves with `k_lo ≤ k ≤ k_hi`, `mss = ∫ k² S(k) dk`: the sum of the
    /// up-wind and cross-wind slope variances of the linear surface.
    ///
    /// # Arguments
    /// - `k_lo`, `k_hi`: wavenumber band (rad m⁻¹), `0 < k_lo < k_hi`.
    ///
    /// # Returns
    /// The mean-square slope (dimensionless); `0` unless `0 < k_lo < k_hi`.
    ///
    /// # References
    /// Cox & Munk 1954; docs/equations.md §11 (`σ_x² + σ_y² = ∫∫ |k|² Ψ(k) d²k`).
    fn mean_square_slope_between(&self, k_lo: f64, k_hi: f64) -> f64 {
        if !(k_lo > 0.0 && k_hi > k_lo) {
            return 0.0;
        }
        simpson_log(|k| k * k * self.s_k(k), k_lo, k_hi, MOMENT_PAIRS)
    }

    /// Mean-square slope of every wave up to `k_max`, `mss = ∫₀^{k_max} k² S(k) dk`, integrated
    /// from `k(ω_p/20)` where the spectrum starts.
    ///
    /// A `k⁻³` tail (Pierson–Moskowitz, JONSWAP) makes it grow like `ln k_max` without bound;
    /// Elfouhaily's spectrum converges (by `k ≈ 5000` rad m⁻¹).
    ///
    /// # Arguments
    /// - `k_max`: largest wavenumber (rad m⁻¹), `> k(ω_p/20)`.
    ///
    /// # Returns
    /// The mean-square slope (dimensionless).
    ///
    /// # References
    /// Cox & Munk 1954; docs/equations.md §11.
    fn mean_square_slope(&self, k_max: f64) -> f64 {
        let k_lo = self.dispersion().wavenumber(MOMENT_LOW * self.peak_omega());
        self.mean_square_slope_between(k_lo, k_max)
    }
}
