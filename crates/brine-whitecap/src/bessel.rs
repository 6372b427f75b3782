//! Modified Bessel functions `I₀`, `I₁` in the form the von Mises tilt needs: `ln I₀(x)` and
//! `I₁(x)/I₀(x)`.

/// Where the power series hands over to the asymptotic expansion.
const SWITCH: f64 = 15.0;

/// `(ln I₀(x), I₁(x)/I₀(x))` for real `x` (`I₀` even, the ratio odd).
///
/// Power series `I_ν(x) = Σ (x/2)^{2k+ν}/(k! (k+ν)!)` for `|x| < 15` (terms to 10⁻¹⁷); above,
/// Hankel's asymptotic expansion `I_ν(x) ≈ eˣ/√(2πx) Σ (−1)ᵏ aₖ(ν)/xᵏ`,
/// `aₖ(ν) = (4ν² − 1)(4ν² − 9)…(4ν² − (2k − 1)²)/(k! 8ᵏ)`, summed while its terms shrink (at
/// `x = 15` the smallest term is below 10⁻¹⁶). Relative error ~10⁻¹⁵.
///
/// # References
/// Abramowitz & Stegun 1964, Eqs. 9.6.10 (series) and 9.7.1 (asymptotic expansion); checked
/// against their Table 9.8.
pub(crate) fn ln_i0_and_ratio(x: f64) -> (f64, f64) {
    let ax = x.abs();
    let (ln_i0, ratio) = if ax < SWITCH { series(ax) } else { asymptotic(ax) };
    (ln_i0, ratio.copysign(x))
}

/// Power series (A&S 9.6.10) for `x ≥ 0`.
fn series(ax: f64) -> (f64, f64) {
    let q = 0.25 * ax * ax;
    let (mut t0, mut s0) = (1.0, 1.0);
    let (mut t1, mut s1) = (0.5 * ax, 0.5 * ax);
    for k in 1..200 {
        let kf = k as f64;
        t0 *= q / (kf * kf);
        t1 *= q / (kf * (kf + 1.0));
        s0 += t0;
        s1 += t1;
        if t0 < 1e-17 * s0 {
            break;
        }
    }
    (s0.ln(), s1 / s0)
}

/// Hankel's asymptotic expansion (A&S 9.7.1) for `x ≥ 15`.
fn asymptotic(ax: f64) -> (f64, f64) {
    let (mut a0, mut s0, mut a1, mut s1) = (1.0f64, 1.0, 1.0f64, 1.0);
    for k in 1..40 {
        let kf = k as f64;
        let odd = 2.0 * kf - 1.0;
        // (−1)ᵏ aₖ(ν)/xᵏ from the previous term: × −(4ν² − (2k − 1)²)/(8kx).
        let n0 = a0 * (odd * odd) / (8.0 * ax * kf);
        let n1 = a1 * (odd * odd - 4.0) / (8.0 * ax * kf);
        if n0.abs() >= a0.abs() {
            break;
        }
        a0 = n0;
        a1 = n1;
        s0 += a0;
        s1 += a1;
        if a0.abs() < 1e-17 {
            break;
        }
    }
    (ax - 0.5 * (2.0 * std::f64::consts::PI * ax).ln() + s0.ln(), s1 / s0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative tolerance on the table's 10 significant digits (half a unit is ≤ 5×10⁻¹⁰
    /// relative at a leading 1; a ratio of two such values doubles it, plus a margin).
    const TEN_DIGITS: f64 = 2e-9;

    /// Both branches at the switch against 50-digit values: the asymptotic expansion's smallest
    /// term there is ~`e^{−30}` ≈ 10⁻¹³.
    const SWITCH_TOL: f64 = 1e-12;

    /// `I₀` is even and `I₁/I₀` odd: the same flops up to one rounding.
    const SYMMETRY_ROUNDING: f64 = 1e-15;

    /// `ln I₀(0) = 0` and `I₁/I₀(0) = 0` exactly.
    const EXACT_ZERO: f64 = f64::MIN_POSITIVE;

    /// `(x, I₀(x), I₁(x))` from Abramowitz & Stegun Table 9.8 (tabulated as `e^{−x}I_n(x)` to
    /// 10 significant digits for x ≤ 20); x = 20 lies in the asymptotic branch.
    const TABLE: [(f64, f64, f64); 4] = [
        (1.0, 1.266_065_878, 0.565_159_104_0),
        (5.0, 27.239_871_82, 24.335_642_14),
        (10.0, 2_815.716_628, 2_670.988_304),
        (20.0, 4.355_828_256e7, 4.245_497_339e7),
    ];

    #[test]
    fn against_abramowitz_stegun_table_9_8() {
        for &(x, i0, i1) in &TABLE {
            let (ln_i0, ratio) = ln_i0_and_ratio(x);
            assert!((ln_i0.exp() / i0 - 1.0).abs() < TEN_DIGITS, "I0({x}) = {}", ln_i0.exp());
            assert!((ratio / (i1 / i0) - 1.0).abs() < TEN_DIGITS, "I1/I0({x}) = {ratio}");
        }
        // Both branches at the switch x = 15, against the series summed in 50-digit decimal
        // arithmetic: ln I₀(15) = 12.73566910947691, I₁/I₀(15) = 0.9660695639865081. The
        // asymptotic expansion's smallest term there is ~e^{−30} ≈ 10⁻¹³.
        for (l, r) in [series(SWITCH), asymptotic(SWITCH)] {
            assert!(
                (l - 12.735_669_109_476_91).abs() < SWITCH_TOL && (r - 0.966_069_563_986_508_1).abs() < SWITCH_TOL,
                "{l} {r}"
            );
        }
        let (l, r) = ln_i0_and_ratio(-5.0);
        assert!((l - ln_i0_and_ratio(5.0).0).abs() < SYMMETRY_ROUNDING && r < 0.0);
        assert!(ln_i0_and_ratio(0.0).0.abs() < EXACT_ZERO && ln_i0_and_ratio(0.0).1.abs() < EXACT_ZERO);
    }
}
