//! The tiered method: frequency pruning and the certified second-order step.

use crate::options::log_step;
use crate::{Hit, RaySpan, RayTiers, Step, StepBound, StepKind, TierBounds, TraceOptions, TraceStats, refine_crossing};

mod refine;
mod scratch;

pub(crate) use refine::refine_tiers;
use refine::*;
pub use scratch::TierScratch;

/// How many tiers whose key falls below the last step are still evaluated at the next point,
/// as a fraction of the step: tiers with `key ≥ DEPTH_KEEP · step` are kept.
const DEPTH_KEEP: f64 = 0.5;

/// Bounds are re-read (they tighten as footprint fading removes components) once `t` has grown by
/// this factor since the last reading.
const REFRESH_GROWTH: f64 = 1.25;

/// The Newton probe is tried when `K·p < NEWTON_REACH·(|D| − η)` (`p` the Newton step, `D` the
/// derivative, `K` the curvature bound): for `NEWTON_REACH ≤ 1` the derivative provably stays
/// negative up to the probe; above, the probe's own derivative must confirm it (else it is wasted).
/// Measured on the benchmark's default view: 1.5 → 7.04, 2 → 7.01, 3 → 7.16.
const NEWTON_REACH: f64 = 2.0;

/// Over-relaxation factor `ω` of the tiered step (tiered + footprint on the benchmark's default
/// view, N = 50: 1.3 → 7.2, 1.4 → 7.0, 1.5 → 7.5, 2 → 11 evaluations per hitting ray).
const RELAXATION: f64 = 1.4;

/// Traces a ray given as tiers (see [`trace_tiers_with`]), with fresh buffers.
///
/// # Arguments
/// See [`trace_tiers_with`].
///
/// # Returns
/// The first sign change on `[t_enter, t_exit]`, or `None`.
pub fn trace_tiers<R: RayTiers + ?Sized>(
    tiers: &mut R,
    span: RaySpan<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    trace_tiers_with(&mut TierScratch::default(), tiers, span, options, stats, log)
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
/// - `span`: the ray (only used to report the hit point) and the traced interval
///   `[t_enter, t_exit]` (m), already clipped.
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
pub fn trace_tiers_with<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    span: RaySpan<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    if options.method == crate::Method::Segment {
        return crate::trace_segments(scratch, tiers, span, options, stats, log);
    }
    match run(scratch, tiers, span, options, stats, Mode::Ray(log)) {
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
pub fn certify_cone_with<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    span: RaySpan<'_>,
    half_angle: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
) -> f64 {
    match run(scratch, tiers, span, options, stats, Mode::Cone(half_angle)) {
        Outcome::Free(t) => t,
        Outcome::Miss => span.t_exit,
        Outcome::Hit(_) => span.t_enter,
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

/// What [`run`] is asked: the first crossing of one ray (its steps logged when a log is given),
/// or how far a cone of rays around it is certified free.
enum Mode<'l> {
    /// One ray ([`trace_tiers_with`]).
    Ray(Option<&'l mut Vec<Step>>),
    /// A cone of this half-angle (rad, `> 0`) around the ray ([`certify_cone_with`]).
    Cone(f64),
}

/// Traces one ray or certifies one cone ([`Mode`]): [`Walk::start`] finds the side the ray
/// starts on, then [`Walk::step`] runs until the walk ends.
fn run<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    span: RaySpan<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mode: Mode<'_>,
) -> Outcome {
    let (log, cone) = match mode {
        Mode::Ray(log) => (log, 0.0),
        Mode::Cone(half_angle) => (None, half_angle),
    };
    if tiers.tier_count() == 0 || !(span.t_enter < span.t_exit) {
        return Outcome::Miss;
    }
    let mut walk = match Walk::start(Tracer { scratch, tiers, stats, options, log }, span, cone) {
        Ok(walk) => walk,
        Err(outcome) => return outcome,
    };
    loop {
        if let Some(outcome) = walk.step() {
            return outcome;
        }
    }
}

/// What a walk works with: the buffers, the tiers, the counters, the options and the log.
struct Tracer<'w, R: RayTiers + ?Sized> {
    scratch: &'w mut TierScratch,
    tiers: &'w mut R,
    stats: &'w mut TraceStats,
    options: &'w TraceOptions,
    log: Option<&'w mut Vec<Step>>,
}

/// The state one walk along a ray (or along a cone's axis) carries from step to step.
struct Walk<'w, R: RayTiers + ?Sized> {
    w: Tracer<'w, R>,
    span: RaySpan<'w>,
    /// Half-angle of the cone (rad); 0 for one ray.
    cone: f64,
    /// Tiers in the sum.
    n: usize,
    /// Twice the sum's evaluation error bound.
    eps: f64,
    /// The bound of its slope's evaluation error.
    eta: f64,
    /// `+1` when the ray starts above the surface, `−1` below: the samples are `G = sign · F`.
    sign: f64,
    /// The present point.
    t: f64,
    /// Tiers the step reads at `t` (the depth), and how many of them are sampled there.
    k: usize,
    sampled: usize,
    /// The last step: the guess of the next one (`NaN` before the first).
    guess: f64,
    /// Whether the next step may be over-relaxed.
    relax: bool,
    steps: u32,
    /// Where the bounds were last read.
    t_refresh: f64,
}

/// What the Newton phase of a step decided.
enum Newton {
    /// The walk ends.
    Done(Outcome),
    /// The walk moved to the probe: the next step starts there.
    Moved,
    /// Nothing: go on with the certified step.
    Stay,
}

impl<'w, R: RayTiers + ?Sized> Walk<'w, R> {
    /// Reads the bounds at `t_enter` and adds tiers until they decide which side of the surface
    /// the ray starts on (the samples are stored as if the side were positive and flipped below
    /// if not). `Err` when that alone ends the walk.
    fn start(w: Tracer<'w, R>, span: RaySpan<'w>, cone: f64) -> Result<Self, Outcome> {
        let n = w.tiers.tier_count();
        let eps = 2.0 * w.tiers.error_bound();
        let eta = w.tiers.slope_error_bound();
        let t = span.t_enter;
        let mut walk = Self {
            w,
            span,
            cone,
            n,
            eps,
            eta,
            sign: 1.0,
            t,
            k: 0,
            sampled: 0,
            guess: f64::NAN,
            relax: RELAXATION > 1.0,
            steps: 0,
            t_refresh: t,
        };
        let Tracer { scratch, tiers, stats, .. } = &mut walk.w;
        scratch.reset(n);
        scratch.refresh(*tiers, t, 1.0, cone > 0.0);
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
                    return Err(Outcome::Free(t));
                }
                if sum == 0.0 {
                    stats.hits += 1;
                    return Err(Outcome::Hit(Hit { t, point: span.ray.at(t), entering: true, steps: 0 }));
                }
                break sum.signum();
            }
        };
        if sign < 0.0 {
            if cone > 0.0 {
                return Err(Outcome::Free(t));
            }
            scratch.refresh(*tiers, t, sign, false);
            for j in 0..k {
                let (v, d) = (scratch.value[j], scratch.raw_slope[j]);
                scratch.store(j, v, d, sign);
            }
        }
        walk.sign = sign;
        walk.k = k;
        walk.sampled = k;
        Ok(walk)
    }

    /// Samples every tier of `[from, to)` at `t` (the caller counts the point).
    fn sample_range(&mut self, from: usize, to: usize, t: f64) {
        let Tracer { scratch, tiers, stats, .. } = &mut self.w;
        for j in from..to {
            let s = tiers.sample(j, t);
            stats.component_evaluations += u64::from(s.terms);
            scratch.store(j, s.value, s.slope, self.sign);
        }
    }

    /// `(G, G')` of the stored samples.
    fn sums(&self) -> (f64, f64) {
        (self.w.scratch.value.iter().sum(), self.w.scratch.slope.iter().sum())
    }

    fn log_step(&mut self, t_from: f64, t_to: f64, kind: StepKind) {
        log_step(&mut self.w.log, t_from, t_to, kind);
    }

    /// The hit at `t_hit`, counted.
    fn hit(&mut self, t_hit: f64) -> Outcome {
        self.w.stats.hits += 1;
        Outcome::Hit(Hit { t: t_hit, point: self.span.ray.at(t_hit), entering: self.sign > 0.0, steps: self.steps })
    }

    /// One step of the walk from `t`; `Some` when the walk ends.
    fn step(&mut self) -> Option<Outcome> {
        if self.steps >= self.w.options.max_steps {
            if self.cone > 0.0 {
                return Some(Outcome::Free(self.t));
            }
            self.w.stats.exhausted += 1;
            return Some(Outcome::Miss);
        }
        self.steps += 1;
        let (s, h) = self.certified_step();
        let t = self.t;
        if t + s >= self.span.t_exit {
            self.log_step(t, self.span.t_exit, StepKind::Certified);
            return Some(Outcome::Miss);
        }
        if self.cone > 0.0 && (s < self.cone * t || s < h) {
            // The cone is as wide as its step: its children take over from here.
            return Some(Outcome::Free(t + s));
        }
        // Every tier evaluated: the crossing may be certified from this point alone, or bracketed
        // by a Newton probe on a stretch where `G` provably decreases.
        let tol = self.w.options.tolerance_at(t);
        let mut full = None;
        if self.cone == 0.0 && self.k == self.n && self.w.scratch.exact.iter().all(|&e| e) {
            let (g, d) = self.sums();
            full = Some((g, d));
            match self.newton(Sample { t, g, d }, s, tol) {
                Newton::Done(outcome) => return Some(outcome),
                Newton::Moved => return None,
                Newton::Stay => {}
            }
        }
        if s >= h {
            self.advance(s);
            return None;
        }
        self.probe(s, h, tol, full)
    }

    /// The certified step from `t`: tiers are added while the step is shorter than the next
    /// one's key, and all of them when it is shorter than the minimum step `h`. Returns `(s, h)`.
    fn certified_step(&mut self) -> (f64, f64) {
        let (n, t, eps, eta, guess, spread) = (self.n, self.t, self.eps, self.eta, self.guess, (self.cone, self.t));
        if self.sampled < self.k {
            if self.sampled == 0 {
                self.w.stats.evaluations += 1;
            }
            self.sample_range(self.sampled, self.k, t);
        }
        let mut k = self.k;
        let mut s = self.w.scratch.step(k, eps, eta, guess, spread);
        while k < n && s < self.w.scratch.key[k] {
            let mut k2 = k + 1;
            while k2 < n && self.w.scratch.key[k2] > s {
                k2 += 1;
            }
            self.sample_range(k, k2, t);
            k = k2;
            s = self.w.scratch.step(k, eps, eta, guess, spread);
        }
        let h = self.w.options.min_step_at(t);
        if s < h && k < n {
            self.sample_range(k, n, t);
            k = n;
            s = self.w.scratch.step(k, eps, eta, guess, spread);
        }
        if !(s >= 0.0) {
            s = 0.0;
        }
        if k < n {
            self.w.stats.pruned_evaluations += 1;
        }
        self.k = k;
        (s, h)
    }

    /// With every tier sampled exactly at `here`: the crossing certified from this point alone,
    /// or a Newton probe past the certified step `s` on a stretch where `G` provably decreases
    /// (a move there, or the crossing bracketed and refined).
    fn newton(&mut self, here: Sample, s: f64, tol: f64) -> Newton {
        let (n, t, eps, eta, t_exit) = (self.n, self.t, self.eps, self.eta, self.span.t_exit);
        let (g, d) = (here.g, here.d);
        let curvature: f64 = self.w.scratch.bounds.iter().map(|b| b.curvature).sum();
        // The exact F is within ε/2 of the samples (eps = 2ε guards the sampled F̃ too).
        let (lo, hi) = here.crossing_interval(curvature, 0.5 * eps, eta);
        let lo = lo.max(s);
        if lo <= hi && hi - lo <= tol && t + hi <= t_exit {
            // The lower bound is positive up to t + lo, the upper bound negative at t + hi: the
            // first crossing lies between, no further evaluation needed.
            self.log_step(t + lo, t + hi, StepKind::Bracket);
            return Newton::Done(self.hit(t + 0.5 * (lo + hi)));
        }
        let newton = if d + eta < 0.0 && g > 0.0 { g / -d + 0.5 * tol } else { 0.0 };
        if !(newton > s && t + newton < t_exit && curvature * newton < NEWTON_REACH * (-d - eta)) {
            return Newton::Stay;
        }
        let tp = t + newton;
        self.w.stats.evaluations += 1;
        self.w.stats.probe_evaluations += 1;
        self.sample_range(0, n, tp);
        let (gp, dp) = self.sums();
        // G' ≤ min(d + η + K(u − t), dp + η + K(tp − u)) < 0 on [t, tp]: G decreases.
        let monotone = d + dp + 2.0 * eta + curvature * newton < 0.0;
        if monotone && gp > 0.0 {
            self.log_step(t, tp, StepKind::Certified);
            self.t = tp;
            self.guess = newton;
            self.k = n;
            self.sampled = n;
            return Newton::Moved;
        }
        if !monotone {
            // Not provably monotone: the probe is wasted; go on from t.
            return Newton::Stay;
        }
        self.log_step(t, tp, StepKind::Bracket);
        let mut refinement = 0u64;
        let t_hit = refine_monotone(here, Sample { t: tp, g: gp, d: dp }, curvature, 0.5 * eps, eta, tol, |x| {
            refinement += 1;
            self.sample_range(0, n, x);
            self.sums()
        });
        self.w.stats.evaluations += refinement;
        self.w.stats.refinement_evaluations += refinement;
        Newton::Done(self.hit(t_hit))
    }

    /// Moves by the certified step `s ≥ h`, over-relaxed when the relaxed point proves free.
    fn advance(&mut self, s: f64) {
        let (n, t) = (self.n, self.t);
        let relaxed = t + RELAXATION * s;
        if self.relax && self.cone == 0.0 && relaxed < self.span.t_exit {
            // Over-relaxed step (Keinert et al. 2014, with certified bounds): sample every tier
            // at t + ωs; the step is kept if the certified step *backward* from there reaches
            // t + s, so that [t, t + ωs] is free; otherwise the sample is wasted and the next
            // step is not relaxed.
            self.w.stats.evaluations += 1;
            self.sample_range(0, n, relaxed);
            let back = self.w.scratch.backward_step(n, self.eps, self.eta, (RELAXATION - 1.0) * s);
            if relaxed - back <= t + s {
                self.log_step(t, relaxed, StepKind::Certified);
                self.t = relaxed;
                self.guess = RELAXATION * s;
                self.k = n;
                self.sampled = n;
                self.refresh_if_grown(false);
                return;
            }
            self.log_step(t, relaxed, StepKind::Rejected);
            self.relax = false;
        } else {
            self.relax = RELAXATION > 1.0;
        }
        self.log_step(t, t + s, StepKind::Certified);
        self.t = t + s;
        self.guess = s;
        self.k = self.w.scratch.next_depth(s);
        self.sampled = 0;
        self.refresh_if_grown(self.cone > 0.0);
    }

    /// Re-reads the bounds once `t` has grown by [`REFRESH_GROWTH`] since the last reading (they
    /// tighten as the footprint fades components).
    fn refresh_if_grown(&mut self, cone: bool) {
        if self.w.options.footprint_angle > 0.0 && self.t >= REFRESH_GROWTH * self.t_refresh {
            self.w.scratch.refresh(self.w.tiers, self.t, self.sign, cone);
            self.t_refresh = self.t;
        }
    }

    /// Every tier is evaluated and the certified step `s` is shorter than `h`: a probe at
    /// Newton's estimate (within `[s, h]`) looks for the sign change.
    fn probe(&mut self, s: f64, h: f64, tol: f64, full: Option<(f64, f64)>) -> Option<Outcome> {
        let (n, t, t_exit) = (self.n, self.t, self.span.t_exit);
        let (g, slope) = full.unwrap_or_else(|| self.sums());
        let newton = if slope < 0.0 { g / -slope + 0.5 * tol } else { h };
        let p = newton.clamp(s, h).min(t_exit - t);
        let tp = t + p;
        self.w.stats.evaluations += 1;
        self.w.stats.probe_evaluations += 1;
        self.sample_range(0, n, tp);
        let gp: f64 = self.w.scratch.value.iter().sum();
        if gp <= 0.0 {
            self.log_step(t + s, tp, StepKind::Bracket);
            let t_hit = if gp == 0.0 {
                tp
            } else if p - s <= tol {
                t + 0.5 * (s + p)
            } else {
                refine_tiers(self.w.tiers, self.sign, (t, g), (tp, gp), tol, self.w.stats)
            };
            return Some(self.hit(t_hit));
        }
        self.log_step(t, tp, StepKind::Probe);
        self.t = tp;
        if self.t >= t_exit {
            return Some(Outcome::Miss);
        }
        self.guess = p;
        self.k = n;
        self.sampled = n;
        None
    }
}
