//! Quadrature rules for the tests' independent integrals.

/// Composite Simpson rule of `f` on `[a, b]` with `pairs ≥ 1` pairs of panels:
/// `h/3 (f₀ + 4f₁ + 2f₂ + … + 4f₂ₙ₋₁ + f₂ₙ)`, `h = (b − a)/2n`; exact for cubics, error
/// `O(h⁴)`. `a`, `b` in the unit of `f`'s argument; the result in that unit times `f`'s.
///
/// # References
/// Abramowitz & Stegun 1964, 25.4.5.
pub fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, pairs: usize) -> f64 {
    assert!(pairs >= 1, "Simpson's rule needs at least one pair of panels");
    let n = 2 * pairs;
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for j in 1..n {
        s += if j % 2 == 1 { 4.0 } else { 2.0 } * f(a + j as f64 * h);
    }
    s * h / 3.0
}

/// Simpson's rule on one panel `[a, b]` from its end and middle values.
fn panel(a: f64, b: f64, (fa, fm, fb): (f64, f64, f64)) -> f64 {
    (b - a) / 6.0 * (fa + 4.0 * fm + fb)
}

/// Deepest bisection of [`adaptive_simpson`]: 2⁻⁴⁰ of the interval, below any test's need.
const MAX_DEPTH: u32 = 40;

/// Adaptive Simpson quadrature of `f` on `[a, b]` to the absolute accuracy `eps > 0` (Lyness
/// 1969): a panel is split until its two halves agree with it within `15 eps`, and Richardson's
/// correction `(S₂ − S₁)/15` is added to each accepted panel.
///
/// # References
/// Lyness J. N. 1969, "Notes on the adaptive Simpson quadrature routine", J. ACM 16(3):483–495.
pub fn adaptive_simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, eps: f64) -> f64 {
    fn recurse(
        f: &dyn Fn(f64) -> f64,
        (a, b): (f64, f64),
        ends: (f64, f64, f64),
        whole: f64,
        eps: f64,
        depth: u32,
    ) -> f64 {
        let (fa, fm, fb) = ends;
        let m = 0.5 * (a + b);
        let (flm, frm) = (f(0.5 * (a + m)), f(0.5 * (m + b)));
        let left = panel(a, m, (fa, flm, fm));
        let right = panel(m, b, (fm, frm, fb));
        let delta = left + right - whole;
        if depth == 0 || delta.abs() <= 15.0 * eps {
            return left + right + delta / 15.0;
        }
        recurse(f, (a, m), (fa, flm, fm), left, 0.5 * eps, depth - 1)
            + recurse(f, (m, b), (fm, frm, fb), right, 0.5 * eps, depth - 1)
    }
    assert!(eps > 0.0, "adaptive Simpson needs an accuracy > 0, got {eps}");
    let ends = (f(a), f(0.5 * (a + b)), f(b));
    recurse(&f, (a, b), ends, panel(a, b, ends), eps, MAX_DEPTH)
}

/// Nodes `xᵢ` and weights `wᵢ` of the `n`-point Gauss–Legendre rule on `[−1, 1]` (`n ≥ 1`): the
/// roots of `Pₙ` by Newton's method from Tricomi's estimate `cos(π(i − ¼)/(n + ½))`, and
/// `wᵢ = 2/((1 − xᵢ²) Pₙ′(xᵢ)²)`; exact for polynomials of degree `2n − 1`.
///
/// # References
/// Abramowitz & Stegun 1964, 25.4.29; Press et al., Numerical Recipes, §4.6 (`gauleg`).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    assert!(n >= 1, "Gauss–Legendre needs at least one node");
    let (mut x, mut w) = (vec![0.0; n], vec![0.0; n]);
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            // Pₙ(z) and Pₙ₋₁(z) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, 0.0);
            for j in 0..n {
                (p0, p1) = (((2 * j + 1) as f64 * z * p0 - j as f64 * p1) / (j + 1) as f64, p0);
            }
            dp = n as f64 * (z * p0 - p1) / (z * z - 1.0);
            let step = p0 / dp;
            z -= step;
            if step.abs() <= 1e-15 {
                break;
            }
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        w[n - 1 - i] = w[i];
    }
    (x, w)
}

/// Composite Gauss–Legendre integral of `f` over `[a, b]`: `panels ≥ 1` equal panels of `points`
/// nodes each.
pub fn gauss_legendre_composite(f: &mut impl FnMut(f64) -> f64, a: f64, b: f64, panels: usize, points: usize) -> f64 {
    let (x, w) = gauss_legendre(points);
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|p| {
            let lo = a + h * p as f64;
            x.iter().zip(&w).map(|(x, w)| 0.5 * h * w * f(lo + 0.5 * h * (x + 1.0))).sum::<f64>()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of a few dozen flops of order 1.
    const ROUNDING: f64 = 1e-13;

    #[test]
    fn simpson_is_exact_for_cubics() {
        let got = simpson(|x| x * x * x - 2.0 * x, -1.0, 2.0, 3);
        assert!((got - (4.0 - 0.25 - 3.0)).abs() < ROUNDING, "{got}");
    }

    #[test]
    fn adaptive_simpson_reaches_its_accuracy() {
        // ∫₀^π sin = 2.
        let got = adaptive_simpson(f64::sin, 0.0, std::f64::consts::PI, 1e-10);
        assert!((got - 2.0).abs() < 1e-10, "{got}");
    }

    #[test]
    fn gauss_legendre_is_exact_to_degree_2n_minus_1() {
        for n in 1..=16 {
            let (x, w) = gauss_legendre(n);
            assert!((w.iter().sum::<f64>() - 2.0).abs() < ROUNDING, "weights of {n} nodes");
            let d = 2 * n - 1;
            // ∫₋₁¹ x^d = 0 for odd d, and ∫ x^(d−1) = 2/d.
            let odd: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(d as i32)).sum();
            let even: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(d as i32 - 1)).sum();
            assert!(odd.abs() < ROUNDING && (even - 2.0 / d as f64).abs() < ROUNDING, "{n} nodes");
        }
    }

    #[test]
    fn composite_rule_integrates_an_exponential() {
        let got = gauss_legendre_composite(&mut f64::exp, 0.0, 1.0, 4, 8);
        assert!((got - (std::f64::consts::E - 1.0)).abs() < ROUNDING, "{got}");
    }
}
