//! The tiered method: frequency pruning and the certified second-order step.

use crate::options::log_step;
use crate::{Hit, Ray, RayTiers, Step, StepBound, StepKind, TierBounds, TraceOptions, TraceStats, refine_crossing};

/// How many tiers whose key falls below the last step are still evaluated at the next point,
/// as a fraction of the step: tiers with `key ≥ DEPTH_KEEP · step` are kept.
const DEPTH_KEEP: f64 = 0.5;

/// Bounds are re-read (they tighten as footprint fading removes components) once `t` has grown by
/// this factor since the last reading.
const REFRESH_GROWTH: f64 = 1.25;

/// Reusable buffers of [`trace_tiers_with`] (one per thread avoids an allocation per ray).
#[derive(Debug, Clone, Default)]
pub struct TierScratch {
    bounds: Vec<TierBounds>,
    /// Oriented lower bound of each tier.
    lo: Vec<f64>,
    /// `Σ_{j≥k} lo[j]`, length `n + 1`.
    lo_suffix: Vec<f64>,
    /// `(max − min)/L`: the largest step at which evaluating the tier can help.
    key: Vec<f64>,
    /// Oriented value of each sampled tier at the current point.
    value: Vec<f64>,
    /// Oriented derivative (a lower bound of it) of each sampled tier.
    slope: Vec<f64>,
    /// Bound of how concave the oriented tier can be, used with `slope` (0 when the slope is the
    /// Lipschitz lower bound).
    curvature: Vec<f64>,
    /// 3D Lipschitz constant of each tier (cone mode).
    spread: Vec<f64>,
    /// Unoriented derivative of the first samples (while the side is unknown).
    raw_slope: Vec<f64>,
    /// Whether the stored slope of each tier is its sampled derivative with a finite curvature
    /// bound (`false`: the slope is the Lipschitz lower bound `−L`).
    exact: Vec<bool>,
    /// Segment tracing ([`crate::trace_segments`]): the tiers' bounds and derivatives.
    pub(crate) segment_bounds: Vec<TierBounds>,
    pub(crate) segment_slopes: Vec<f64>,
}

impl TierScratch {
    fn reset(&mut self, n: usize) {
        for v in [
            &mut self.lo,
            &mut self.key,
            &mut self.value,
            &mut self.slope,
            &mut self.curvature,
            &mut self.spread,
            &mut self.raw_slope,
        ] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.exact.clear();
        self.exact.resize(n, false);
        self.lo_suffix.clear();
        self.lo_suffix.resize(n + 1, 0.0);
        self.bounds.clear();
        self.bounds.resize(n, TierBounds::ZERO);
    }

    /// Reads the bounds of every tier at `t` and orients them by `sign`.
    fn refresh<R: RayTiers + ?Sized>(&mut self, tiers: &mut R, t: f64, sign: f64, cone: bool) {
        let n = self.bounds.len();
        for j in 0..n {
            let b = tiers.bounds(j, t);
            if cone {
                self.spread[j] = tiers.spread_lipschitz(j);
            }
            self.bounds[j] = b;
            self.lo[j] = if sign > 0.0 { b.min } else { -b.max };
            let range = b.max - b.min;
            self.key[j] = if b.lipschitz > 0.0 {
                range / b.lipschitz
            } else if range > 0.0 {
                f64::INFINITY
            } else {
                0.0
            };
        }
        self.lo_suffix[n] = 0.0;
        for j in (0..n).rev() {
            self.lo_suffix[j] = self.lo_suffix[j + 1] + self.lo[j];
        }
    }

    /// Stores the sample of tier `j`, oriented.
    fn store(&mut self, j: usize, value: f64, slope: f64, sign: f64) {
        self.value[j] = sign * value;
        let b = self.bounds[j];
        // The oriented tier `sign·T` has `(sign·T)'' ≥ −concavity` on the positive side and
        // `≥ −curvature` on the negative side (the one-sided bound of `T'' ≤ curvature`).
        let curvature = if sign > 0.0 { b.concavity.min(b.curvature) } else { b.curvature };
        if slope.is_finite() && curvature.is_finite() {
            self.slope[j] = (sign * slope).max(-b.lipschitz);
            self.curvature[j] = curvature;
            self.exact[j] = true;
        } else {
            self.exact[j] = false;
            // Unknown derivative or curvature: the tier can only fall at its Lipschitz rate.
            self.slope[j] = -b.lipschitz;
            self.curvature[j] = 0.0;
        }
    }

    /// The certified step from the first `k` sampled tiers (the others at their bounds).
    ///
    /// Each sampled tier is assigned to the quadratic part (derivative + curvature) or to the
    /// reserve part (how far it can fall, at its Lipschitz rate), whichever costs less at the
    /// expected step; two passes refine the guess. Every assignment gives a valid bound, so the
    /// largest root is kept.
    fn step(&self, k: usize, eps: f64, eta: f64, guess: f64, spread: (f64, f64)) -> f64 {
        // Cone mode: every ray within `θ` of the axis is within `θ(t + s)` of the axis point, so
        // the evaluated tiers lose at most `θ(t + s) Σ Lⱼ³ᴰ`.
        let (margin, margin_rate) = if spread.0 > 0.0 {
            let l3: f64 = self.spread[..k].iter().sum();
            (spread.0 * spread.1 * l3, spread.0 * l3)
        } else {
            (0.0, 0.0)
        };
        let value: f64 = self.value[..k].iter().sum::<f64>() + self.lo_suffix[k] - eps - margin;
        if !(value > 0.0) {
            return 0.0;
        }
        let mut guess = if guess.is_finite() && guess > 0.0 {
            guess
        } else {
            let l: f64 = self.bounds[..k].iter().map(|b| b.lipschitz).sum();
            if l > 0.0 { value / l } else { f64::INFINITY }
        };
        let mut best = 0.0f64;
        for _ in 0..2 {
            let mut b = StepBound {
                value,
                slope: -eta - margin_rate,
                curvature: 0.0,
                lipschitz: eta + margin_rate,
                reserve: 0.0,
                reserve_lipschitz: 0.0,
            };
            for j in 0..k {
                let (d, kk, l) = (self.slope[j], self.curvature[j], self.bounds[j].lipschitz);
                let a = (self.value[j] - self.lo[j]).max(0.0);
                let fall_q = quadratic_fall(d, kk, l, guess);
                let fall_p = a.min(l * guess);
                if fall_q <= fall_p {
                    b.slope += d;
                    b.curvature += kk;
                    b.lipschitz += l;
                } else {
                    b.reserve += a;
                    b.reserve_lipschitz += l;
                }
            }
            let s = b.first_root();
            best = best.max(s);
            if !s.is_finite() {
                break;
            }
            guess = s;
        }
        best
    }

    /// The certified step *backward* (toward the ray origin) from the stored samples of the first
    /// `k` tiers: [`step`](Self::step) with every sampled derivative reversed. The bounds hold
    /// there too: they were read at or before the start of the step. A tier without a usable
    /// derivative keeps its slope `−L`: that is a lower bound of its rate of change in either
    /// direction (reversing it to `+L` would claim that the tier grows, and certify steps across
    /// crossings: found by the sphere-sum property test, seed 308).
    fn backward_step(&mut self, k: usize, eps: f64, eta: f64, guess: f64) -> f64 {
        for (d, &exact) in self.slope[..k].iter_mut().zip(&self.exact[..k]) {
            if exact {
                *d = -*d;
            }
        }
        let s = self.step(k, eps, eta, guess, (0.0, 0.0));
        for (d, &exact) in self.slope[..k].iter_mut().zip(&self.exact[..k]) {
            if exact {
                *d = -*d;
            }
        }
        s
    }

    /// Tiers to evaluate at the next point after a step `s`: those whose key is at least
    /// `DEPTH_KEEP·s`, stopping at the first that is not (at least one).
    fn next_depth(&self, s: f64) -> usize {
        let n = self.key.len();
        let mut k = 1;
        while k < n && self.key[k] >= DEPTH_KEEP * s {
            k += 1;
        }
        k
    }
}

/// The Newton probe is tried when `K·p < NEWTON_REACH·(|D| − η)` (`p` the Newton step, `D` the
/// derivative, `K` the curvature bound): for `NEWTON_REACH ≤ 1` the derivative provably stays
/// negative up to the probe; above, the probe's own derivative must confirm it (else it is wasted).
/// Measured on the benchmark's default view: 1.5 → 7.04, 2 → 7.01, 3 → 7.16.
const NEWTON_REACH: f64 = 2.0;

/// Over-relaxation factor `ω` of the tiered step (tiered + footprint on the benchmark's default
/// view, N = 50: 1.3 → 7.2, 1.4 → 7.0, 1.5 → 7.5, 2 → 11 evaluations per hitting ray).
const RELAXATION: f64 = 1.4;

/// The oriented function `G` and its derivative `G'` sampled (every tier) at `t`.
#[derive(Debug, Clone, Copy)]
struct Sample {
    t: f64,
    g: f64,
    d: f64,
}

impl Sample {
    /// Offsets `(l, u)` from `t` of the interval that holds the crossing of a decreasing `G`,
    /// given `|G − g| ≤ ε` and `G'(t + s) ∈ [d − η − K|s|, d + η + K|s|]` (`K` the curvature
    /// bound): `G > 0` is certified up to `t + l` by the lower bound `g − ε + (d − η)s − Ks²/2`
    /// (or, when `g ≤ ε`, backward from `t` by the upper-bound form), and `G < 0` from `t + u` on
    /// by the upper bound `g + ε + (d + η)s + Ks²/2` (or, when `g < −ε`, backward by the lower
    /// one). `l = −∞` or `u = ∞` when a side cannot be certified.
    fn crossing_interval(&self, curvature: f64, eps: f64, eta: f64) -> (f64, f64) {
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
fn first_root(c: f64, d: f64, k: f64) -> f64 {
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
fn first_reach(c: f64, m: f64, k: f64) -> f64 {
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
#[allow(clippy::too_many_arguments)]
fn refine_monotone(
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
fn quadratic_fall(d: f64, k: f64, l: f64, s: f64) -> f64 {
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

/// Traces a ray given as tiers (see [`trace_tiers_with`]), with fresh buffers.
///
/// # Arguments
/// See [`trace_tiers_with`].
///
/// # Returns
/// The first sign change on `[t_enter, t_exit]`, or `None`.
pub fn trace_tiers<R: RayTiers + ?Sized>(
    tiers: &mut R,
    ray: &Ray,
    t_enter: f64,
    t_exit: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    trace_tiers_with(&mut TierScratch::default(), tiers, ray, t_enter, t_exit, options, stats, log)
}

/// The tiered method ([`crate::Method::Tiered`]) on a ray given as tiers `F = Σⱼ Tⱼ`, or segment
/// tracing on the same tiers when `options.method` is [`crate::Method::Segment`] (then this is
/// [`crate::trace_segments`]; every other method selects the tiered method, so that implementors
/// of [`crate::LipschitzSum::trace_tiered`] serve both by passing the options through).
///
/// At each point only the first `k` tiers are evaluated; the others enter through their bounds
/// (frequency pruning: far from the surface only long waves are evaluated). Tier `k` is added
/// while the step is shorter than its key `(maxₖ − minₖ)/Lₖ` (Darles' criterion: beyond that
/// length its bound costs no more than its value). The step is the first root of the certified
/// lower bound of [`StepBound`], `G(t + s) ≥ c + ∫₀ˢ max(D − K u, −Λ) du − min(a, Λ_p s)`
/// (`G = ±F`, oriented to be positive at the start), minus twice the evaluation error. When that
/// step falls below the minimum step `h(t)` with every tier evaluated, a probe at Newton's estimate
/// plus half the tolerance (at most `h`) looks for the sign change; its bracket is refined by
/// [`refine_crossing`].
///
/// Safety: every certified step contains no zero of the sampled `F̃` (whose distance to the exact
/// `F` is at most [`RayTiers::error_bound`]); only the probe steps, no longer than `h`, are
/// checked at their end alone, as in [`crate::trace`].
///
/// # Arguments
/// - `scratch`: reusable buffers.
/// - `tiers`: the function along the ray.
/// - `ray`: the ray (only used to report the hit point).
/// - `t_enter`, `t_exit`: the traced interval (m), already clipped.
/// - `options`: minimum step, tolerance, step cap, footprint (for bound refreshing).
/// - `stats`: counters; one evaluation per point visited, terms as reported by the tiers.
/// - `log`: receives each step when given.
///
/// # Returns
/// The first sign change on `[t_enter, t_exit]`, or `None`.
///
/// # References
/// Hart 1996 (sphere tracing); Darles et al. 2007 §3.1–3.2 (efficient bound, neglected high
/// frequencies); Keinert et al. 2014 (over-relaxation); docs/equations.md §2. The second-order bound
/// holds on the step only, like the local bounds of segment tracing (Galin et al. 2020), but it is
/// Brine's; segment tracing proper is [`crate::Method::Segment`].
#[allow(clippy::too_many_arguments)]
pub fn trace_tiers_with<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    ray: &Ray,
    t_enter: f64,
    t_exit: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    if options.method == crate::Method::Segment {
        return crate::trace_segments(scratch, tiers, ray, t_enter, t_exit, options, stats, log);
    }
    match run(scratch, tiers, ray, t_enter, t_exit, options, stats, log, 0.0) {
        Outcome::Hit(hit) => Some(hit),
        Outcome::Miss | Outcome::Free(_) => None,
    }
}

/// Image coherence: certifies a cone of rays sharing `ray`'s origin.
///
/// Steps along the axis `ray` as [`trace_tiers_with`] does, but every bound loses
/// `θ(t + s) Σⱼ Lⱼ³ᴰ` over the evaluated tiers (`Lⱼ³ᴰ` = [`RayTiers::spread_lipschitz`]): a ray
/// within angle `θ` of the axis is within `θ t` of the axis point at the same `t`, so the lower
/// bound holds for every ray of the cone. The cone stops (without probing) once its step is
/// shorter than its radius `θ t`, or when the axis starts below the surface.
///
/// # Arguments
/// - `half_angle`: `θ` (rad), `> 0`; `tiers` must be built for the cone (its tiers bound every
///   ray of the cone, e.g. footprint-faded components at their amplitude).
/// - The others as [`trace_tiers_with`].
///
/// # Returns
/// `t_c ∈ [t_enter, t_exit]`: no ray of the cone crosses the surface on `[t_enter, t_c]`.
///
/// # References
/// Darles et al. 2007 §3.3 (image coherence: unbounding spheres reused by neighbouring rays, in
/// a quadtree); Hart 1996 (Lipschitz bound).
#[allow(clippy::too_many_arguments)]
pub fn certify_cone_with<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    ray: &Ray,
    half_angle: f64,
    t_enter: f64,
    t_exit: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
) -> f64 {
    match run(scratch, tiers, ray, t_enter, t_exit, options, stats, None, half_angle) {
        Outcome::Free(t) => t,
        Outcome::Miss => t_exit,
        Outcome::Hit(_) => t_enter,
    }
}

/// What [`run`] found.
enum Outcome {
    /// A crossing.
    Hit(Hit),
    /// No crossing up to `t_exit`.
    Miss,
    /// (Cone mode) certified free up to this `t`.
    Free(f64),
}

#[allow(clippy::too_many_arguments)]
fn run<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    ray: &Ray,
    t_enter: f64,
    t_exit: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
    cone: f64,
) -> Outcome {
    let n = tiers.tier_count();
    if n == 0 || !(t_enter < t_exit) {
        return Outcome::Miss;
    }
    let eps = 2.0 * tiers.error_bound();
    let eta = tiers.slope_error_bound();
    scratch.reset(n);
    let mut t = t_enter;
    scratch.refresh(tiers, t, 1.0, cone > 0.0);
    let mut t_refresh = t;

    // Which side of the surface the ray starts on: add tiers until the bounds decide. The samples
    // are stored as if the side were positive and flipped below if not.
    let hi_total: f64 = scratch.bounds.iter().map(|b| b.max).sum();
    let (mut sum, mut k, mut hi_rest) = (0.0, 0, hi_total);
    stats.evaluations += 1;
    let sign = loop {
        let s = tiers.sample(k, t);
        stats.component_evaluations += u64::from(s.terms);
        scratch.store(k, s.value, s.slope, 1.0);
        scratch.raw_slope[k] = s.slope;
        sum += s.value;
        hi_rest -= scratch.bounds[k].max;
        k += 1;
        if sum + scratch.lo_suffix[k] > eps {
            break 1.0;
        }
        if sum + hi_rest < -eps {
            break -1.0;
        }
        if k == n {
            if cone > 0.0 {
                return Outcome::Free(t);
            }
            if sum == 0.0 {
                stats.hits += 1;
                return Outcome::Hit(Hit { t, point: ray.at(t), entering: true, steps: 0 });
            }
            break sum.signum();
        }
    };
    if sign < 0.0 {
        if cone > 0.0 {
            return Outcome::Free(t);
        }
        scratch.refresh(tiers, t, sign, false);
        for j in 0..k {
            let (v, d) = (scratch.value[j], scratch.raw_slope[j]);
            scratch.store(j, v, d, sign);
        }
    }
    let mut sampled = k;
    let mut guess = f64::NAN;
    let mut relax = RELAXATION > 1.0;
    let mut steps = 0u32;

    // Samples every tier of [from, to) at t (the caller counts the point).
    let sample_range = |scratch: &mut TierScratch, tiers: &mut R, stats: &mut TraceStats, from: usize, to: usize, t| {
        for j in from..to {
            let s = tiers.sample(j, t);
            stats.component_evaluations += u64::from(s.terms);
            scratch.store(j, s.value, s.slope, sign);
        }
    };

    loop {
        if steps >= options.max_steps {
            if cone > 0.0 {
                return Outcome::Free(t);
            }
            stats.exhausted += 1;
            return Outcome::Miss;
        }
        steps += 1;
        if sampled < k {
            if sampled == 0 {
                stats.evaluations += 1;
            }
            sample_range(scratch, tiers, stats, sampled, k, t);
        }
        let mut s = scratch.step(k, eps, eta, guess, (cone, t));
        while k < n && s < scratch.key[k] {
            let mut k2 = k + 1;
            while k2 < n && scratch.key[k2] > s {
                k2 += 1;
            }
            sample_range(scratch, tiers, stats, k, k2, t);
            k = k2;
            s = scratch.step(k, eps, eta, guess, (cone, t));
        }
        let h = options.min_step_at(t);
        if s < h && k < n {
            sample_range(scratch, tiers, stats, k, n, t);
            k = n;
            s = scratch.step(k, eps, eta, guess, (cone, t));
        }
        if !(s >= 0.0) {
            s = 0.0;
        }
        if k < n {
            stats.pruned_evaluations += 1;
        }
        if t + s >= t_exit {
            log_step(&mut log, t, t_exit, StepKind::Certified);
            return Outcome::Miss;
        }
        if cone > 0.0 && (s < cone * t || s < h) {
            // The cone is as wide as its step: its children take over from here.
            return Outcome::Free(t + s);
        }
        // Every tier evaluated: the crossing may be certified from this point alone, or bracketed
        // by a Newton probe on a stretch where `G` provably decreases.
        let tol = options.tolerance_at(t);
        let mut full = None;
        if cone == 0.0 && k == n && scratch.exact.iter().all(|&e| e) {
            let g: f64 = scratch.value.iter().sum();
            let d: f64 = scratch.slope.iter().sum();
            let curvature: f64 = scratch.bounds.iter().map(|b| b.curvature).sum();
            full = Some((g, d));
            let here = Sample { t, g, d };
            // The exact F is within ε/2 of the samples (eps = 2ε guards the sampled F̃ too).
            let (lo, hi) = here.crossing_interval(curvature, 0.5 * eps, eta);
            let lo = lo.max(s);
            if lo <= hi && hi - lo <= tol && t + hi <= t_exit {
                // The lower bound is positive up to t + lo, the upper bound negative at t + hi: the
                // first crossing lies between, no further evaluation needed.
                log_step(&mut log, t + lo, t + hi, StepKind::Bracket);
                let t_hit = t + 0.5 * (lo + hi);
                stats.hits += 1;
                return Outcome::Hit(Hit { t: t_hit, point: ray.at(t_hit), entering: sign > 0.0, steps });
            }
            let newton = if d + eta < 0.0 && g > 0.0 { g / -d + 0.5 * tol } else { 0.0 };
            if newton > s && t + newton < t_exit && curvature * newton < NEWTON_REACH * (-d - eta) {
                let tp = t + newton;
                stats.evaluations += 1;
                stats.probe_evaluations += 1;
                sample_range(scratch, tiers, stats, 0, n, tp);
                let gp: f64 = scratch.value.iter().sum();
                let dp: f64 = scratch.slope.iter().sum();
                // G' ≤ min(d + η + K(u − t), dp + η + K(tp − u)) < 0 on [t, tp]: G decreases.
                let monotone = d + dp + 2.0 * eta + curvature * newton < 0.0;
                if monotone && gp > 0.0 {
                    log_step(&mut log, t, tp, StepKind::Certified);
                    t = tp;
                    guess = newton;
                    k = n;
                    sampled = n;
                    continue;
                }
                if monotone {
                    log_step(&mut log, t, tp, StepKind::Bracket);
                    let mut refinement = 0u64;
                    let t_hit =
                        refine_monotone(here, Sample { t: tp, g: gp, d: dp }, curvature, 0.5 * eps, eta, tol, |x| {
                            refinement += 1;
                            sample_range(scratch, tiers, stats, 0, n, x);
                            (scratch.value.iter().sum(), scratch.slope.iter().sum())
                        });
                    stats.evaluations += refinement;
                    stats.refinement_evaluations += refinement;
                    stats.hits += 1;
                    return Outcome::Hit(Hit { t: t_hit, point: ray.at(t_hit), entering: sign > 0.0, steps });
                }
                // Not provably monotone: the probe is wasted; go on from t.
            }
        }
        if s >= h {
            let relaxed = t + RELAXATION * s;
            if relax && cone == 0.0 && relaxed < t_exit {
                // Over-relaxed step (Keinert et al. 2014, with certified bounds): sample every tier
                // at t + ωs; the step is kept if the certified step *backward* from there reaches
                // t + s, so that [t, t + ωs] is free; otherwise the sample is wasted and the next
                // step is not relaxed.
                stats.evaluations += 1;
                sample_range(scratch, tiers, stats, 0, n, relaxed);
                let back = scratch.backward_step(n, eps, eta, (RELAXATION - 1.0) * s);
                if relaxed - back <= t + s {
                    log_step(&mut log, t, relaxed, StepKind::Certified);
                    t = relaxed;
                    guess = RELAXATION * s;
                    k = n;
                    sampled = n;
                    if options.footprint_angle > 0.0 && t >= REFRESH_GROWTH * t_refresh {
                        scratch.refresh(tiers, t, sign, false);
                        t_refresh = t;
                    }
                    continue;
                }
                log_step(&mut log, t, relaxed, StepKind::Rejected);
                relax = false;
            } else {
                relax = RELAXATION > 1.0;
            }
            log_step(&mut log, t, t + s, StepKind::Certified);
            t += s;
            guess = s;
            k = scratch.next_depth(s);
            sampled = 0;
            if options.footprint_angle > 0.0 && t >= REFRESH_GROWTH * t_refresh {
                scratch.refresh(tiers, t, sign, cone > 0.0);
                t_refresh = t;
            }
            continue;
        }

        // Every tier is evaluated and the certified step is shorter than h: probe.
        let (g, slope) = full.unwrap_or_else(|| (scratch.value.iter().sum(), scratch.slope.iter().sum()));
        let newton = if slope < 0.0 { g / -slope + 0.5 * tol } else { h };
        let p = newton.clamp(s, h).min(t_exit - t);
        let tp = t + p;
        stats.evaluations += 1;
        stats.probe_evaluations += 1;
        sample_range(scratch, tiers, stats, 0, n, tp);
        let gp: f64 = scratch.value.iter().sum();
        if gp <= 0.0 {
            log_step(&mut log, t + s, tp, StepKind::Bracket);
            let t_hit = if gp == 0.0 {
                tp
            } else if p - s <= tol {
                t + 0.5 * (s + p)
            } else {
                refine_tiers(tiers, sign, (t, g), (tp, gp), tol, stats)
            };
            stats.hits += 1;
            return Outcome::Hit(Hit { t: t_hit, point: ray.at(t_hit), entering: sign > 0.0, steps });
        }
        log_step(&mut log, t, tp, StepKind::Probe);
        t = tp;
        if t >= t_exit {
            return Outcome::Miss;
        }
        guess = p;
        k = n;
        sampled = n;
    }
}
