//! Composite Simpson quadrature used for spectral moments (through `libm`, so that fitted sets are
//! bit-identical on every platform).

/// `∫_a^b f(x) dx` by the composite Simpson rule on `2·pairs` intervals (error `O(h⁴)`).
pub(crate) fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, pairs: usize) -> f64 {
    let n = 2 * pairs.max(1);
    let h = (b - a) / n as f64;
    let mut sum = f(a) + f(b);
    for j in 1..n {
        let w = if j % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(a + j as f64 * h);
    }
    sum * h / 3.0
}

/// `∫_a^b f(ω) dω` for `0 < a < b` by Simpson's rule in `ln ω` (suited to spectra spanning
/// decades): `∫ f(ω) ω d(ln ω)`.
pub(crate) fn simpson_log(f: impl Fn(f64) -> f64, a: f64, b: f64, pairs: usize) -> f64 {
    debug_assert!(a > 0.0 && b > a);
    simpson(
        |u| {
            let w = libm::exp(u);
            f(w) * w
        },
        libm::log(a),
        libm::log(b),
        pairs,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Simpson's rule is exact for cubics: rounding of 3 terms.
    const ROUND_ABS: f64 = 1e-14;

    /// 400 intervals in `u = ln ω` over a decade, integrand `e⁻⁴ᵘ`: error
    /// `≈ h⁴ [f‴]ₐᵇ/180 ≈ 4×10⁻¹⁰` (`h = ln 10/400`, `f‴ = −64 e⁻⁴ᵘ`).
    const POWER_LAW_ABS: f64 = 1e-9;

    #[test]
    fn simpson_is_exact_for_cubics() {
        let v = simpson(|x| x * x * x - 2.0 * x + 1.0, 0.0, 2.0, 1);
        assert!((v - 2.0).abs() < ROUND_ABS, "{v}");
    }

    #[test]
    fn log_simpson_integrates_a_power_law() {
        // ∫_1^10 ω⁻⁵ dω = (1 − 10⁻⁴)/4
        let v = simpson_log(|w| w.powi(-5), 1.0, 10.0, 200);
        assert!((v - (1.0 - 1e-4) / 4.0).abs() < POWER_LAW_ABS, "{v}");
    }
}
