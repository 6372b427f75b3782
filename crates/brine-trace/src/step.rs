//! Safe step lengths: Darles' efficient bound (corrected) and the certified second-order step.

/// Darles' efficient step, Algorithm 1 as corrected in the docs/equations.md §2.
///
/// Along the ray each component obeys `nᵢ(p + s d̂) ≥ max(mᵢ, vᵢ − Lᵢ s)`, so for any subset `S`
/// `F ≥ Σ_{i∈S}(vᵢ − Lᵢ s) + Σ_{i∉S} mᵢ`, whose root
/// `c_S = (M + Σ_{i∈S}(vᵢ − mᵢ)) / Σ_{i∈S} Lᵢ` (`M = Σ mᵢ`) is a safe step. The best prefix of the
/// components sorted by decreasing `(vᵢ − mᵢ)/Lᵢ` is returned: the scan stops at the first
/// decrease of `c` once `c > 0` (the prefix sequence is unimodal).
///
/// # Arguments
/// - `values`: `vᵢ = nᵢ(p)` (or guaranteed lower bounds), any unit `U`; `Σ vᵢ > 0`.
/// - `minima`: `mᵢ ≤ vᵢ`, lower bounds of `nᵢ` on the marched segment (unit `U`).
/// - `lipschitz`: `Lᵢ ≥ 0` (unit `U` per metre).
///
/// # Returns
/// The step (m), `≥ F(p)/Σ Lᵢ`; `+∞` when `M + Σ_{Lᵢ=0}(vᵢ − mᵢ) > 0` (the surface is unreachable),
/// `0` when `F(p) ≤ 0`.
///
/// # References
/// Darles, Crespin & Ghazanfarpour 2007, §3.1 Algorithm 1; docs/equations.md §2 (corrected form and
/// its two test oracles).
pub fn efficient_lipschitz_step(values: &[f64], minima: &[f64], lipschitz: &[f64]) -> f64 {
    debug_assert!(values.len() == minima.len() && values.len() == lipschitz.len());
    let total: f64 = values.iter().sum();
    if !(total > 0.0) {
        return 0.0;
    }
    let key = |i: usize| {
        let r = values[i] - minima[i];
        if lipschitz[i] > 0.0 { r / lipschitz[i] } else { f64::INFINITY }
    };
    let mut order: Vec<usize> = (0..values.len()).collect();
    order.sort_by(|&a, &b| key(b).total_cmp(&key(a)));
    let mut scan = PrefixScan::new(minima.iter().sum());
    if scan.unreachable() {
        return f64::INFINITY;
    }
    for &i in &order {
        if !scan.add(values[i] - minima[i], lipschitz[i]) {
            break;
        }
    }
    scan.step()
}

/// The scan of Darles' efficient step over growing prefixes `S` of the sorted components:
/// `c_S = (M + Σ_{i∈S}(vᵢ − mᵢ)) / Σ_{i∈S} Lᵢ`, keeping the best, stopping at its first decrease
/// once positive ([`efficient_lipschitz_step`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct PrefixScan {
    num: f64,
    den: f64,
    best: f64,
}

impl PrefixScan {
    /// The empty prefix, from the sum of the minima `M`: unreachable when `M > 0`.
    pub(crate) fn new(minima_sum: f64) -> Self {
        let best = if minima_sum > 0.0 { f64::INFINITY } else { f64::NEG_INFINITY };
        Self { num: minima_sum, den: 0.0, best }
    }

    /// Whether the surface is out of reach whatever the prefix (`M > 0`).
    pub(crate) fn unreachable(&self) -> bool {
        self.best == f64::INFINITY
    }

    /// Adds the next component, of excess `vᵢ − mᵢ` and constant `Lᵢ`; `false` when the scan
    /// stops there (`c_S` decreased after a positive best).
    pub(crate) fn add(&mut self, excess: f64, lipschitz: f64) -> bool {
        self.num += excess;
        self.den += lipschitz;
        let c = if self.den > 0.0 {
            self.num / self.den
        } else if self.num > 0.0 {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        };
        if c <= self.best && self.best > 0.0 {
            return false;
        }
        self.best = self.best.max(c);
        true
    }

    /// The step: the best `c_S`, at least 0.
    pub(crate) fn step(&self) -> f64 {
        self.best.max(0.0)
    }
}

/// Algorithm 1 exactly as printed by Darles et al. (2007): sorted by `nᵢ/Lᵢ`, `L_e` starts at 0
/// and is returned at the first candidate that does not exceed it.
///
/// Kept only to document the erratum of the docs/equations.md §2: it returns 0 whenever the first
/// candidate is negative (the ray stalls near the surface). Never used to trace.
///
/// # Arguments
/// As [`efficient_lipschitz_step`].
///
/// # Returns
/// The printed algorithm's `L_e` (m).
///
/// # References
/// Darles et al. 2007, Algorithm 1 (as printed); docs/equations.md §2, "Is the printed algorithm
/// correct? No".
pub fn printed_darles_step(values: &[f64], minima: &[f64], lipschitz: &[f64]) -> f64 {
    let mut order: Vec<usize> = (0..values.len()).collect();
    order.sort_by(|&a, &b| (values[b] / lipschitz[b]).total_cmp(&(values[a] / lipschitz[a])));
    let mut l_e = 0.0;
    let mut den = 0.0;
    let mut num: f64 = minima.iter().sum();
    for &i in &order {
        num += values[i] - minima[i];
        den += lipschitz[i];
        if l_e > num / den {
            return l_e;
        }
        l_e = num / den;
    }
    l_e
}

/// A certified lower bound of `G(t + s)` along a ray, `s ≥ 0`:
///
/// `G(t + s) ≥ c + ∫₀ˢ max(D − K u, −Λ_q) du − min(a, Λ_p s)`.
///
/// The integral is the "quadratic" part: components whose derivative `d` at `t` is known and whose
/// second derivative is bounded by `K` (their derivative then stays above `D − K u` and above
/// `−Λ_q`); the last term is the "reserve" part: components bounded by their Lipschitz constants
/// `Λ_p` and by how far they can fall, `a = Σ (vᵢ − mᵢ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepBound {
    /// `c`: a lower bound of `G(t)` (with the unevaluated components at their minima).
    pub value: f64,
    /// `D`: a lower bound of the derivative of the quadratic part at `t` (per metre).
    pub slope: f64,
    /// `K ≥ 0`: bound of the second derivative of the quadratic part (per metre²), may be `+∞`.
    pub curvature: f64,
    /// `Λ_q ≥ 0`: Lipschitz constant of the quadratic part along the ray.
    pub lipschitz: f64,
    /// `a ≥ 0`: how far the reserve part can fall below its value at `t`.
    pub reserve: f64,
    /// `Λ_p ≥ 0`: Lipschitz constant of the reserve part along the ray.
    pub reserve_lipschitz: f64,
}

impl StepBound {
    /// The bound itself at `s ≥ 0`: `c + Q(s) − min(a, Λ_p s)`.
    pub fn lower_bound(&self, s: f64) -> f64 {
        self.value + self.quadratic(s) - self.reserve.min(self.reserve_lipschitz * s)
    }

    /// `Q(s) = ∫₀ˢ max(D − K u, −Λ_q) du`.
    fn quadratic(&self, s: f64) -> f64 {
        let (d, k, l) = (self.slope.max(-self.lipschitz), self.curvature, self.lipschitz);
        let s1 = self.kink();
        if s1 <= 0.0 {
            -l * s
        } else if s <= s1 {
            d * s - 0.5 * k * s * s
        } else {
            d * s1 - 0.5 * k * s1 * s1 - l * (s - s1)
        }
    }

    /// Where the derivative bound `D − K u` reaches `−Λ_q`.
    fn kink(&self) -> f64 {
        let d = self.slope.max(-self.lipschitz);
        if self.curvature == f64::INFINITY {
            0.0
        } else if self.curvature > 0.0 {
            (d + self.lipschitz) / self.curvature
        } else {
            f64::INFINITY
        }
    }

    /// The first root `s* > 0` of [`lower_bound`](Self::lower_bound): a step that provably
    /// contains no zero of `G`.
    ///
    /// `c + Q(s) − Λ_p s` is concave on `[0, a/Λ_p]` and `c − a + Q(s)` is concave beyond, so the
    /// first root is the larger root of a quadratic or a linear piece, found in closed form. Near
    /// a transversal zero (`K c ≪ D²`) it tends to Newton's step `c/|D|`; with `K = ∞` it is the
    /// Lipschitz step.
    ///
    /// # Returns
    /// The step (m); `+∞` if the bound never reaches zero; `0` if `c ≤ 0`.
    ///
    /// # References
    /// Hart 1996 (Lipschitz step); docs/equations.md §2 (reserve = Darles' efficient bound);
    /// the second-order part is Brine's (docs/models/brine-trace.md).
    pub fn first_root(&self) -> f64 {
        if !(self.value > 0.0) {
            return 0.0;
        }
        let (a, lp) = (self.reserve.max(0.0), self.reserve_lipschitz);
        let s2 = if lp > 0.0 { a / lp } else { f64::INFINITY };
        let r1 = self.root_of_concave(self.value, lp, 0.0);
        if r1 <= s2 {
            return r1;
        }
        self.root_of_concave(self.value - a, 0.0, s2)
    }

    /// The root beyond `s_lo` of `h(s) = c + Q(s) − λ s`, concave and positive at `s_lo`.
    fn root_of_concave(&self, c: f64, lambda: f64, s_lo: f64) -> f64 {
        let d = self.slope.max(-self.lipschitz);
        let k = self.curvature;
        let s1 = self.kink();
        let (mut s_start, mut h_start) = (s_lo, c + self.quadratic(s_lo) - lambda * s_lo);
        if s1 > s_lo {
            let b = d - lambda;
            let r = if k > 0.0 && k.is_finite() {
                let disc = (b * b + 2.0 * k * c).max(0.0).sqrt();
                if b >= 0.0 {
                    (b + disc) / k
                } else if c > 0.0 {
                    2.0 * c / (disc - b)
                } else {
                    s_lo
                }
            } else if b < 0.0 {
                c / -b
            } else {
                f64::INFINITY
            };
            if r <= s1 {
                return r.max(s_lo);
            }
            s_start = s1;
            h_start = c + self.quadratic(s1) - lambda * s1;
        }
        let fall = self.lipschitz + lambda;
        if fall > 0.0 { s_start + h_start.max(0.0) / fall } else { f64::INFINITY }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The oracles are printed to one or two significant digits but are exact rationals.
    const ORACLE_TOLERANCE: f64 = 1e-12;

    #[test]
    fn darles_step_oracle_1_and_the_printed_algorithm_stalls() {
        // docs/equations.md, Test oracles: v = (1, 0.2, −0.5), m = −1 each, L = (1, 2, 0.5) ⇒ 0.2
        // (= F/ΣL); the printed algorithm returns 0.
        let (v, m, l) = ([1.0, 0.2, -0.5], [-1.0; 3], [1.0, 2.0, 0.5]);
        assert!((efficient_lipschitz_step(&v, &m, &l) - 0.2).abs() < ORACLE_TOLERANCE);
        assert!(printed_darles_step(&v, &m, &l).abs() < ORACLE_TOLERANCE);
    }

    #[test]
    fn darles_step_oracle_2_beats_the_global_step() {
        // v = (3, 0.5, 0.5), m = −0.5 each, L = 0.5 each ⇒ 4.0 (global F/ΣL = 4/1.5 = 8/3).
        let (v, m, l) = ([3.0, 0.5, 0.5], [-0.5; 3], [0.5; 3]);
        let efficient = efficient_lipschitz_step(&v, &m, &l);
        assert!((efficient - 4.0).abs() < ORACLE_TOLERANCE);
        // The global (Hart) step through the code, two ways: the efficient bound of the whole sum
        // lumped into one component (the only prefix is every component), and the certified bound
        // with an unknown curvature (the Lipschitz step c/Λ).
        let lumped = efficient_lipschitz_step(&[v.iter().sum()], &[m.iter().sum()], &[l.iter().sum()]);
        let hart = StepBound {
            value: v.iter().sum(),
            slope: 0.0,
            curvature: f64::INFINITY,
            lipschitz: l.iter().sum(),
            reserve: 0.0,
            reserve_lipschitz: 0.0,
        }
        .first_root();
        for global in [lumped, hart] {
            assert!((global - 8.0 / 3.0).abs() < ORACLE_TOLERANCE, "global step {global}");
            assert!(efficient > 1.4 * global, "efficient {efficient} vs global {global}");
        }
    }

    /// The Lipschitz step `c/Λ = 2/4` is exact in binary; 10⁻¹⁵ (about 9 ulps of 0.5) only
    /// allows for rounding.
    const LIPSCHITZ_STEP_ABS: f64 = 1e-15;

    /// The root `c/|D| = 1/0.1` carries the representation error of 0.1 (relative 5.6×10⁻¹⁷,
    /// below half an ulp of 10, so it rounds away); 10⁻¹² is a wide rounding allowance.
    const LINEAR_ROOT_ABS: f64 = 1e-12;

    /// Lower limit of the small-`c` step: Newton's `c/|D|` = 10⁻⁵ less 0.1 %. The certified step
    /// falls short of Newton's by `≈ K c/(2D²)` = 1.5×10⁻⁴ relative (`c` = 10⁻⁶, `|D|` = 0.1,
    /// `K` = 3), so the limit is about 7 times that deficit below Newton's step.
    const NEWTON_STEP_FLOOR: f64 = 0.999e-5;

    #[test]
    fn certified_step_reduces_to_lipschitz_and_newton() {
        let lipschitz = StepBound {
            value: 2.0,
            slope: 0.0,
            curvature: f64::INFINITY,
            lipschitz: 4.0,
            reserve: 0.0,
            reserve_lipschitz: 0.0,
        };
        assert!((lipschitz.first_root() - 0.5).abs() < LIPSCHITZ_STEP_ABS);
        // Exact linear function g = 1 − 0.1 s: root 10.
        let linear = StepBound { value: 1.0, slope: -0.1, curvature: 0.0, lipschitz: 1.0, ..lipschitz };
        assert!((linear.first_root() - 10.0).abs() < LINEAR_ROOT_ABS);
        // Small c: the step approaches Newton's c/|D| from below.
        let newton = StepBound { value: 1e-6, slope: -0.1, curvature: 3.0, lipschitz: 1.0, ..lipschitz };
        let s = newton.first_root();
        assert!(s < 1e-5 && s > NEWTON_STEP_FLOOR, "{s}");
    }
}
