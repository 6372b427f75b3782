//! Refining the crossing of the tiered sum: the certified crossing interval of a sample, Newton steps inside a bracket where the sum provably decreases (else bisection), and the quadratic bounds of how far a tier can fall.

use super::*;

/// The oriented function `G` and its derivative `G'` sampled (every tier) at `t`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sample {
    pub(super) t: f64,
    pub(super) g: f64,
    pub(super) d: f64,
}

impl Sample {
    /// Offsets `(l, u)` from `t` of the interval that holds the crossing of a decreasing `G`,
    /// given `|G − g| ≤ ε` and `G'(t + s) ∈ [d − η − K|s|, d + η + K|s|]` (`K` the curvature
    /// bound): `G > 0` is certified up to `t + l` by the lower bound `g − ε + (d − η)s − Ks²/2`
    /// (or, when `g ≤ ε`, backward from `t` by the upper-bound form), and `G < 0` from `t + u` on
    /// by the upper bound `g + ε + (d + η)s + Ks²/2` (or, when `g < −ε`, backward by the lower
    /// one). `l = −∞` or `u = ∞` when a side cannot be certified.
    pub(super) fn crossing_interval(&self, curvature: f64, eps: f64, eta: f64) -> (f64, f64) {
        let (g, d) = (self.g, self.d);
        let l = if g - eps > 0.0 {
            first_root(g - eps, d - eta, curvature)
        } else {
            -first_reach(eps - g, -(d + eta), curvature)
        };
        let u = if -g - eps > 0.0 {
            -first_root(-g - eps, d - eta, curvature)
        } else {
            first_reach(g + eps, -(d + eta), curvature)
        };
        (l, u)
    }
}

/// First root `s > 0` of `c + d s − k s²/2` (`k ≥ 0`; `0` if `c ≤ 0`, `∞` if none).
pub(super) fn first_root(c: f64, d: f64, k: f64) -> f64 {
    if !(c > 0.0) || k == f64::INFINITY {
        return 0.0;
    }
    if k > 0.0 {
        let disc = (d * d + 2.0 * k * c).sqrt();
        if d > 0.0 { (d + disc) / k } else { 2.0 * c / (disc - d) }
    } else if d < 0.0 {
        c / -d
    } else {
        f64::INFINITY
    }
}

/// First `s > 0` where `c − m s + k s²/2` reaches 0 (`c ≥ 0`, `k ≥ 0`), `∞` if it never does.
pub(super) fn first_reach(c: f64, m: f64, k: f64) -> f64 {
    if !(m > 0.0) || !k.is_finite() {
        return f64::INFINITY;
    }
    let disc = m * m - 2.0 * k * c;
    if disc < 0.0 { f64::INFINITY } else { 2.0 * c / (m + disc.sqrt()) }
}

/// Refines the crossing of a `G` that provably decreases on `[a.t, b.t]` (`a.g > 0 ≥ b.g`):
/// each point narrows the interval certified by [`Sample::crossing_interval`] and the sign-change
/// bracket `[a, b]`; the next point is Newton's estimate from the end nearer the surface (a
/// bisection of the bracket when it lies outside, or when the last point did not halve it).
/// Stops when either is no longer than `tolerance` and returns its midpoint.
pub(super) fn refine_monotone(
    mut a: Sample,
    mut b: Sample,
    curvature: f64,
    error: f64,
    eta: f64,
    tolerance: f64,
    mut sample: impl FnMut(f64) -> (f64, f64),
) -> f64 {
    let (la, ua) = a.crossing_interval(curvature, error, eta);
    let (lb, ub) = b.crossing_interval(curvature, error, eta);
    let mut lo = (a.t + la).max(b.t + lb);
    let mut hi = (a.t + ua).min(b.t + ub);
    let mut width = f64::INFINITY;
    let mut stalled = 0;
    for _ in 0..200 {
        if !(hi - lo > tolerance) && lo <= hi {
            // Certified for the exact F.
            return 0.5 * (lo + hi);
        }
        if b.t - a.t <= tolerance {
            // The sampled F̃ changes sign within the tolerance (the certified interval cannot
            // be narrower than about 2ε/|G'|).
            break;
        }
        let newton = if a.g.abs() * b.d.abs() <= b.g.abs() * a.d.abs() {
            a.t + a.g / a.d.abs().max(f64::MIN_POSITIVE)
        } else {
            b.t + b.g / b.d.abs().max(f64::MIN_POSITIVE)
        };
        // Newton inside the bracket, unless the last two points did not halve it; an estimate within
        // half the tolerance of an end is pushed 0.9 tolerance past that end, so that the next
        // sign change closes the bracket.
        stalled = if b.t - a.t > 0.5 * width { stalled + 1 } else { 0 };
        let slow = stalled >= 2;
        width = b.t - a.t;
        let mid = 0.5 * (a.t + b.t);
        let x = if slow || !(newton > a.t && newton < b.t) {
            mid
        } else if newton - a.t < 0.5 * tolerance {
            (a.t + 0.9 * tolerance).min(mid)
        } else if b.t - newton < 0.5 * tolerance {
            (b.t - 0.9 * tolerance).max(mid)
        } else {
            newton
        };
        let (g, d) = sample(x);
        let p = Sample { t: x, g, d };
        let (l, u) = p.crossing_interval(curvature, error, eta);
        if g > 0.0 {
            a = p;
            lo = lo.max(x + l);
            hi = hi.min(x + u);
        } else {
            b = p;
            hi = hi.min(x + u);
            lo = lo.max(x + l);
        }
    }
    0.5 * (a.t + b.t)
}

/// How far one tier can fall over `s` by its quadratic bound: `−∫₀ˢ max(d − K u, −L) du`.
pub(super) fn quadratic_fall(d: f64, k: f64, l: f64, s: f64) -> f64 {
    if k <= 0.0 {
        return -d * s;
    }
    let s1 = (d + l) / k;
    if s <= s1 { -(d * s - 0.5 * k * s * s) } else { -(d * s1 - 0.5 * k * s1 * s1) + l * (s - s1) }
}

/// Refines the sign change of `sign · Σⱼ Tⱼ` bracketed by `(a, g_a)` and `(b, g_b)` (values
/// already oriented by `sign`) to `tolerance`, sampling every tier at each point and counting the
/// points as evaluations (refinement) and the tiers' terms in `stats`.
pub(crate) fn refine_tiers<R: RayTiers + ?Sized>(
    tiers: &mut R,
    sign: f64,
    (a, g_a): (f64, f64),
    (b, g_b): (f64, f64),
    tolerance: f64,
    stats: &mut TraceStats,
) -> f64 {
    let n = tiers.tier_count();
    let (mut refinement, mut terms) = (0u64, 0u64);
    let (t_hit, _) = refine_crossing(
        |x| {
            refinement += 1;
            let mut sum = 0.0;
            for j in 0..n {
                let smp = tiers.sample(j, x);
                terms += u64::from(smp.terms);
                sum += smp.value;
            }
            sign * sum
        },
        a,
        g_a,
        b,
        g_b,
        tolerance,
    );
    stats.evaluations += refinement;
    stats.refinement_evaluations += refinement;
    stats.component_evaluations += terms;
    t_hit
}
