//! The error function: the slides' fast approximation, a 1.5×10⁻⁷ one, and libm's.

use std::f64::consts::PI;

/// Winitzki's `a` that minimises the maximum error, the value behind the talk's "max error
/// 0.00012".
pub const WINITZKI_A: f64 = 0.147;

/// The `a` of the published whitecaps demo code (`jdupuy/whitecaps`), max error 3.3×10⁻⁴.
pub const WINITZKI_A_DEMO: f64 = 0.140012;

/// Bound on `|erf_fast(x) − erf(x)|` over the real line: the measured maximum is 1.2406×10⁻⁴
/// at `x ≈ ±1.559` (docs/equations.md oracle), below the slides' "0.00012" rounded.
pub const ERF_FAST_MAX_ERROR: f64 = 1.25e-4;

/// Bound on `|erf_abramowitz_stegun(x) − erf(x)|`: 1.5×10⁻⁷ (Abramowitz & Stegun 7.1.26).
pub const ERF_AS_MAX_ERROR: f64 = 1.5e-7;

/// Winitzki's approximation of the error function with parameter `a`.
///
/// `erf x ≈ sgn(x) √(1 − exp(−x² (4/π + a x²)/(1 + a x²)))`, exact at 0 and ±∞ and to second
/// order at both ends for any `a`.
///
/// # Arguments
/// - `x`: any real; NaN gives NaN.
/// - `a`: shape parameter, `(0, 1)`; [`WINITZKI_A`] or [`WINITZKI_A_DEMO`].
///
/// # Returns
/// An approximation of `erf x`, in `[−1, 1]`.
///
/// # References
/// Winitzki S. 2008, "A handy approximation for the error function and its inverse"; Dupuy &
/// Bruneton 2012 (slides "Erf: approximation", "max error: 0.00012"); docs/equations.md §10.
#[inline]
pub fn erf_winitzki(x: f64, a: f64) -> f64 {
    debug_assert!(a > 0.0 && a < 1.0);
    let x2 = x * x;
    let r = (1.0 - (-x2 * (4.0 / PI + a * x2) / (1.0 + a * x2)).exp()).sqrt();
    if x < 0.0 { -r } else { r }
}

/// The slides' fast error function: [`erf_winitzki`] with `a = 0.147`.
///
/// # Arguments
/// - `x`: any real.
///
/// # Returns
/// `erf x` within [`ERF_FAST_MAX_ERROR`] (1.25×10⁻⁴).
///
/// # References
/// Dupuy & Bruneton 2012; Winitzki 2008; docs/equations.md §10 and Test oracles.
#[inline]
pub fn erf_fast(x: f64) -> f64 {
    erf_winitzki(x, WINITZKI_A)
}

/// Error function by Abramowitz & Stegun's rational approximation 7.1.26.
///
/// `erf x = 1 − (a₁t + a₂t² + a₃t³ + a₄t⁴ + a₅t⁵) e^{−x²}`, `t = 1/(1 + p x)` for `x ≥ 0`, odd
/// extension for `x < 0`; `p = 0.3275911`, `a₁ = 0.254829592`, `a₂ = −0.284496736`,
/// `a₃ = 1.421413741`, `a₄ = −1.453152027`, `a₅ = 1.061405429` (Hastings 1955).
///
/// # Arguments
/// - `x`: any real.
///
/// # Returns
/// `erf x` within [`ERF_AS_MAX_ERROR`] (1.5×10⁻⁷).
///
/// # References
/// Abramowitz M., Stegun I. 1964, *Handbook of Mathematical Functions*, Eq. 7.1.26.
#[inline]
pub fn erf_abramowitz_stegun(x: f64) -> f64 {
    /// `|x|` from which the approximation is ±1 in `f64`: at 6, `poly e^{−36} < 0.26 · 2.4×10⁻¹⁶`,
    /// below half an ulp of 1 (`1.1×10⁻¹⁶`).
    const SATURATED: f64 = 6.0;
    const P: f64 = 0.327_591_1;
    const A: [f64; 5] = [0.254_829_592, -0.284_496_736, 1.421_413_741, -1.453_152_027, 1.061_405_429];
    let ax = x.abs();
    if ax >= SATURATED {
        // `poly e^{−x²} < 10⁻¹⁶`: `1 − ` it rounds to 1, and `e^{−x²}` would take the slow
        // underflow path of the system's `exp` once it leaves the normal range (`x > 26.6`).
        return x.signum();
    }
    let t = 1.0 / (1.0 + P * ax);
    let poly = t * (A[0] + t * (A[1] + t * (A[2] + t * (A[3] + t * A[4]))));
    let r = 1.0 - poly * (-ax * ax).exp();
    if x < 0.0 { -r } else { r }
}

/// Which error function evaluates the coverage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ErfMethod {
    /// The slides' approximation (Winitzki, `a = 0.147`), error ≤ 1.25×10⁻⁴.
    Fast,
    /// Abramowitz & Stegun 7.1.26, error ≤ 1.5×10⁻⁷ (measured 1.39×10⁻⁷); the default: as fast
    /// as [`Self::Fast`] and three times faster than [`Self::Libm`] (`docs/benchmarks.md`).
    #[default]
    AbramowitzStegun,
    /// `libm::erf`, full double precision.
    Libm,
}

impl ErfMethod {
    /// The error function `erf x = (2/√π) ∫₀ˣ e^{−t²} dt` by this method.
    ///
    /// # Arguments
    /// - `x`: any real (dimensionless); NaN gives NaN.
    ///
    /// # Returns
    /// `erf x` (dimensionless), in `[−1, 1]`, odd in `x`, within [`Self::max_error`] of the exact
    /// value.
    ///
    /// # References
    /// Winitzki 2008 ([`Self::Fast`]); Abramowitz & Stegun 1964 Eq. 7.1.26
    /// ([`Self::AbramowitzStegun`]); the `libm` crate, a port of musl's `erf` from Sun's fdlibm
    /// ([`Self::Libm`]).
    #[inline]
    pub fn erf(self, x: f64) -> f64 {
        match self {
            Self::Fast => erf_fast(x),
            Self::AbramowitzStegun => erf_abramowitz_stegun(x),
            Self::Libm => libm::erf(x),
        }
    }

    /// Largest absolute error of this method on the real line.
    ///
    /// # Returns
    /// A bound on `|erf_method(x) − erf x|` (dimensionless): [`ERF_FAST_MAX_ERROR`],
    /// [`ERF_AS_MAX_ERROR`], or `2ε` for `libm`.
    ///
    /// # References
    /// Winitzki 2008 and the reference's (docs/equations.md) oracle (1.2406×10⁻⁴); Abramowitz & Stegun 1964,
    /// 7.1.26 (1.5×10⁻⁷).
    pub fn max_error(self) -> f64 {
        match self {
            Self::Fast => ERF_FAST_MAX_ERROR,
            Self::AbramowitzStegun => ERF_AS_MAX_ERROR,
            Self::Libm => 2.0 * f64::EPSILON,
        }
    }
}

/// Inverse error function, by Newton's method on `libm::erf` from Winitzki's inverse.
///
/// # Arguments
/// - `y`: `(−1, 1)`; ±1 give ±∞.
///
/// # Returns
/// `x` with `erf x = y` to about 10⁻¹⁵ relative.
///
/// # References
/// Winitzki 2008 (starting value); Newton's method with `erf′ x = (2/√π) e^{−x²}`.
pub fn erf_inv(y: f64) -> f64 {
    debug_assert!((-1.0..=1.0).contains(&y));
    if y >= 1.0 {
        return f64::INFINITY;
    }
    if y <= -1.0 {
        return f64::NEG_INFINITY;
    }
    let a = WINITZKI_A;
    let ln = (1.0 - y * y).ln();
    let b = 2.0 / (PI * a) + 0.5 * ln;
    let mut x = (((b * b) - ln / a).sqrt() - b).sqrt().copysign(y);
    for _ in 0..6 {
        // Newton on f = erf(x) − y, written with erfc in the tails to keep it accurate for
        // |y| → 1: erf x − y = (1 − y) − erfc x = erfc(−x) − (1 + y).
        let f = if x > 1.0 {
            (1.0 - y) - libm::erfc(x)
        } else if x < -1.0 {
            libm::erfc(-x) - (1.0 + y)
        } else {
            libm::erf(x) - y
        };
        let d = 2.0 / PI.sqrt() * (-x * x).exp();
        if d <= 0.0 {
            break;
        }
        x -= f / d;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `erf(erf⁻¹ y) − y`: Newton's method converges to a few ulps of `y`.
    const INVERSE_ROUNDING: f64 = 1e-14;

    /// The saturated branch changes no value: the rational form itself is ±1 in `f64` from
    /// `|x| = 6` on (its tail `poly e^{−x²}` is under half an ulp of 1), as is the true `erf`.
    #[test]
    fn the_saturated_tail_is_the_formula_rounded() {
        let formula = |x: f64| {
            let t = 1.0 / (1.0 + 0.327_591_1 * x);
            let poly = t
                * (0.254_829_592
                    + t * (-0.284_496_736 + t * (1.421_413_741 + t * (-1.453_152_027 + t * 1.061_405_429))));
            1.0 - poly * (-x * x).exp()
        };
        // Bit comparisons: the point is that no rounding differs.
        let bits = |x: f64| x.to_bits();
        for x in [6.0, 6.5, 8.0, 12.0, 26.0] {
            assert_eq!(bits(formula(x)), bits(1.0), "x = {x}");
            assert_eq!(bits(erf_abramowitz_stegun(x)), bits(1.0));
            assert_eq!(bits(erf_abramowitz_stegun(-x)), bits(-1.0));
            assert_eq!(bits(libm::erf(x)), bits(1.0));
        }
        // Just below, the formula still differs from 1 by the tail: the branch starts at the
        // first point where it may.
        assert!(formula(5.5) < 1.0 && bits(erf_abramowitz_stegun(5.5)) == bits(formula(5.5)));
        assert_eq!(bits(erf_abramowitz_stegun(f64::INFINITY)), bits(1.0));
        assert_eq!(bits(erf_abramowitz_stegun(1e300)), bits(1.0));
    }

    #[test]
    fn inverse_round_trips() {
        for &y in &[-0.999_999, -0.9, -0.3, 0.0, 1e-9, 0.5, 0.99, 0.999_999_9] {
            let x = erf_inv(y);
            assert!((libm::erf(x) - y).abs() < INVERSE_ROUNDING, "y = {y}: erf(x) = {}", libm::erf(x));
        }
    }
}
