//! The TMA spectrum: JONSWAP in water of finite depth.

use crate::error::{WaveError, check};
use crate::spectra::dispersion::G;
use crate::{Dispersion, Jonswap, Spectrum};

/// Kitaigorodskii's depth factor in the approximation of Thompson & Vincent (1983),
/// `Φ(ω_h) = ½ ω_h²` for `ω_h ≤ 1`, `1 − ½ (2 − ω_h)²` for `1 < ω_h < 2`, `1` for `ω_h ≥ 2`.
///
/// # Arguments
/// - `omega_h`: depth-scaled frequency `ω_h = ω √(h/g)` (dimensionless), `≥ 0`.
///
/// # Returns
/// `Φ` (dimensionless, in `[0, 1]`).
///
/// # References
/// Bouws E. et al. 1985, "Similarity of the wind wave spectrum in finite depth water", JGR
/// 90(C1):975–986; Thompson E.F., Vincent C.L. 1983; docs/equations.md §4.
pub fn kitaigorodskii_depth_factor(omega_h: f64) -> f64 {
    debug_assert!(omega_h >= 0.0, "ω_h must be non-negative, got {omega_h}");
    if omega_h <= 1.0 {
        0.5 * omega_h * omega_h
    } else if omega_h < 2.0 {
        1.0 - 0.5 * (2.0 - omega_h) * (2.0 - omega_h)
    } else {
        1.0
    }
}

/// The TMA spectrum (Texel, MARSEN, ARSLOE; Bouws et al. 1985): a JONSWAP spectrum times
/// Kitaigorodskii's depth factor, `S_TMA(ω) = S_JONSWAP(ω) Φ(ω √(h/g))`, paired with the
/// finite-depth dispersion `ω² = g k tanh(k h)`.
///
/// As `h → ∞`, `Φ → 1` and TMA is JONSWAP. The trochoids fitted to it keep the deep-water orbit
/// shape; only their wavenumbers come from the finite-depth relation.
///
/// # References
/// Bouws et al. 1985; docs/equations.md §4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tma {
    jonswap: Jonswap,
    depth: f64,
    peak: f64,
}

impl Tma {
    /// The TMA spectrum of a JONSWAP sea over water of depth `h`.
    ///
    /// # Arguments
    /// - `jonswap`: the deep-water spectrum.
    /// - `depth_m`: water depth `h` (m), `(0, 10⁴]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a depth outside `(0, 10⁴]` m, or a JONSWAP peak so high
    /// (over about 10⁶¹ rad/s) that the spectrum underflows to 0.
    pub fn new(jonswap: Jonswap, depth_m: f64) -> Result<Self, WaveError> {
        let depth = check("depth_m", depth_m, depth_m > 0.0 && depth_m <= 1e4, "(0, 1e4] m")?;
        let mut tma = Self { jonswap, depth, peak: jonswap.peak_omega() };
        tma.peak = argmax_log(|w| tma.s_omega(w), 0.5 * tma.peak, 4.0 * tma.peak);
        // A JONSWAP peak past about 10⁶¹ rad/s (a wind under 10⁻⁶⁰ m/s) leaves `ω⁻⁵` no room in
        // f64: the spectrum underflows to 0 and has no maximum to find.
        check(
            "peak_omega_rad_s",
            tma.peak,
            tma.peak.is_finite() && tma.peak > 0.0 && tma.s_omega(tma.peak) > 0.0,
            "a finite peak of a spectrum that does not underflow",
        )?;
        Ok(tma)
    }

    /// The TMA spectrum of a wind `U₁₀` (m s⁻¹) over a fetch (m) and a depth (m); see
    /// [`Jonswap::from_fetch`] and [`Tma::new`].
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn from_fetch(u10: f64, fetch_m: f64, depth_m: f64) -> Result<Self, WaveError> {
        Self::new(Jonswap::from_fetch(u10, fetch_m)?, depth_m)
    }

    /// The underlying deep-water JONSWAP spectrum.
    pub fn jonswap(&self) -> &Jonswap {
        &self.jonswap
    }

    /// Water depth `h` (m).
    pub fn depth(&self) -> f64 {
        self.depth
    }
}

impl Spectrum for Tma {
    /// `S(ω) = S_JONSWAP(ω) Φ(ω √(h/g))` (m² s rad⁻¹).
    fn s_omega(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        self.jonswap.s_omega(omega) * kitaigorodskii_depth_factor(omega * libm::sqrt(self.depth / G))
    }

    /// The maximum of `S_TMA(ω)`, found by golden-section search (the depth factor moves it above
    /// the JONSWAP `ω_p` in shallow water).
    fn peak_omega(&self) -> f64 {
        self.peak
    }

    fn dispersion(&self) -> Dispersion {
        Dispersion::finite_depth(self.depth).unwrap_or(Dispersion::DEEP_WATER)
    }
}

/// The maximum of a unimodal `f` on `[a, b]` by golden-section search in `ln ω`, run to a bracket
/// of 10⁻¹²; a smooth maximum is flat to second order, so the result is good to about
/// `√ε ≈ 10⁻⁸` relative.
///
/// Logarithms and exponentials go through `libm` (not the platform's `ln`/`exp`): the peak feeds
/// the fitted band `[f_min ω_p, f_max ω_p]`, so it must be bit-identical on every platform.
fn argmax_log(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let inv_phi = 0.5 * (libm::sqrt(5.0) - 1.0);
    let (mut lo, mut hi) = (libm::log(a), libm::log(b));
    let mut x1 = hi - inv_phi * (hi - lo);
    let mut x2 = lo + inv_phi * (hi - lo);
    let (mut f1, mut f2) = (f(libm::exp(x1)), f(libm::exp(x2)));
    while hi - lo > 1e-12 {
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + inv_phi * (hi - lo);
            f2 = f(libm::exp(x2));
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - inv_phi * (hi - lo);
            f1 = f(libm::exp(x1));
        }
    }
    libm::exp(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_factor_oracle() {
        // Reference value (docs/equations.md): ω_h = 0.5, 1, 1.5, 2 ⇒ Φ = 0.125, 0.5, 0.875, 1 (exact fractions).
        for (wh, phi) in [(0.5, 0.125), (1.0, 0.5), (1.5, 0.875), (2.0, 1.0), (0.0, 0.0), (7.0, 1.0)] {
            assert_eq!(kitaigorodskii_depth_factor(wh).to_bits(), f64::to_bits(phi), "ω_h = {wh}");
        }
    }

    #[test]
    fn peak_is_a_maximum() {
        let t = Tma::from_fetch(10.0, 1e5, 5.0).unwrap();
        let wp = t.peak_omega();
        assert!(wp > t.jonswap().peak_omega());
        assert!(t.s_omega(wp) >= t.s_omega(wp * 1.001) && t.s_omega(wp) >= t.s_omega(wp * 0.999));
        assert_eq!(t.dispersion().depth().to_bits(), 5f64.to_bits());
    }
}
