//! Gauss quadrature rules computed on demand (Legendre on `[−1, 1]`, Hermite with weight `e^{−x²}`).

/// Largest Gauss–Hermite order supported by [`GaussHermite`].
pub const MAX_HERMITE_ORDER: usize = 16;

/// Nodes and weights of the `n`-point Gauss–Legendre rule on `[−1, 1]` (Newton iteration on
/// `P_n` from the guesses `cos(π(i − ¼)/(n + ½))`).
///
/// # Arguments
/// - `n`: number of points, `≥ 1`.
///
/// # Returns
/// `(nodes, weights)`, exact for polynomials of degree `2n − 1`.
///
/// # References
/// Abramowitz M., Stegun I. 1964, *Handbook of Mathematical Functions*, §25.4.29.
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let n = n.max(1);
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    for i in 0..n.div_ceil(2) {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            // P_n(x) and P_{n−1}(x) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 1 { x } else { p1 };
            let pm = if n == 1 { 1.0 } else { p0 };
            dp = n as f64 * (x * pn - pm) / (x * x - 1.0);
            let dx = pn / dp;
            x -= dx;
            if dx.abs() < 1e-15 {
                break;
            }
        }
        nodes[i] = -x;
        nodes[n - 1 - i] = x;
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        weights[i] = w;
        weights[n - 1 - i] = w;
    }
    (nodes, weights)
}

/// The `n`-point Gauss–Hermite rule `∫ e^{−x²} f(x) dx ≈ Σ w_i f(x_i)`, stored without allocation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussHermite {
    n: usize,
    nodes: [f64; MAX_HERMITE_ORDER],
    weights: [f64; MAX_HERMITE_ORDER],
}

/// Orthonormal Hermite polynomials `p_n(x)`, `p_{n−1}(x)` (weight `e^{−x²}`).
fn hermite_pair(n: usize, x: f64) -> (f64, f64) {
    let mut p0 = 0.0;
    let mut p1 = std::f64::consts::PI.powf(-0.25);
    for j in 1..=n {
        let p2 = x * (2.0 / j as f64).sqrt() * p1 - ((j - 1) as f64 / j as f64).sqrt() * p0;
        p0 = p1;
        p1 = p2;
    }
    (p1, p0)
}

impl GaussHermite {
    /// The rule of order `n`, `1 ≤ n ≤ 16` (clamped): nodes found by bracketing the sign changes of
    /// `p_n` on a fine grid and refining by bisection; weights `w = 2/p_n′(x)²`,
    /// `p_n′ = √(2n) p_{n−1}`.
    ///
    /// # Returns
    /// The rule, exact for polynomials of degree `2n − 1` times `e^{−x²}`.
    ///
    /// # References
    /// Abramowitz & Stegun 1964, §25.4.46.
    pub fn new(n: usize) -> Self {
        let n = n.clamp(1, MAX_HERMITE_ORDER);
        let mut nodes = [0.0; MAX_HERMITE_ORDER];
        let mut weights = [0.0; MAX_HERMITE_ORDER];
        let limit = (2.0 * n as f64 + 1.0).sqrt() + 1.0;
        let steps = 4000;
        let h = 2.0 * limit / steps as f64;
        let mut found = 0;
        let mut x0 = -limit;
        let mut f0 = hermite_pair(n, x0).0;
        for s in 1..=steps {
            let x1 = -limit + h * s as f64;
            let f1 = hermite_pair(n, x1).0;
            if f0 == 0.0 || f0 * f1 < 0.0 {
                let (mut lo, mut hi) = (x0, x1);
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if hermite_pair(n, lo).0 * hermite_pair(n, mid).0 <= 0.0 {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                let x = 0.5 * (lo + hi);
                if found < n {
                    let dp = (2.0 * n as f64).sqrt() * hermite_pair(n, x).1;
                    nodes[found] = x;
                    weights[found] = 2.0 / (dp * dp);
                    found += 1;
                }
            }
            x0 = x1;
            f0 = f1;
        }
        debug_assert_eq!(found, n, "all Hermite roots bracketed");
        Self { n, nodes, weights }
    }

    /// Number of points.
    pub fn order(&self) -> usize {
        self.n
    }

    /// The `(node, weight)` pairs.
    pub fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.nodes[..self.n].iter().copied().zip(self.weights[..self.n].iter().copied())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn legendre_integrates_polynomials_exactly() {
        let (x, w) = gauss_legendre(7);
        /// Exact for degree 13; the Newton iteration stops at |dx| < 10⁻¹⁵, seven terms.
        const ROUNDING: f64 = 1e-13;
        let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(12)).sum();
        assert_relative_eq!(s, 2.0 / 13.0, max_relative = ROUNDING);
    }

    #[test]
    fn hermite_integrates_moments_exactly() {
        /// Exact moments; rounding of up to 16 weights spanning 10⁻¹⁰ to 1.
        const ROUNDING: f64 = 1e-12;
        for n in [1, 3, 8, 16] {
            let g = GaussHermite::new(n);
            let m0: f64 = g.points().map(|(_, w)| w).sum();
            assert_relative_eq!(m0, std::f64::consts::PI.sqrt(), max_relative = ROUNDING);
            if n >= 2 {
                // ∫ x² e^{−x²} = √π/2.
                let m2: f64 = g.points().map(|(x, w)| w * x * x).sum();
                assert_relative_eq!(m2, 0.5 * std::f64::consts::PI.sqrt(), max_relative = ROUNDING);
            }
        }
    }
}
