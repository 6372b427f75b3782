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

fn run<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    span: RaySpan<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mode: Mode<'_>,
) -> Outcome {
    let RaySpan { ray, t_enter, t_exit } = span;
    let (mut log, cone) = match mode {
        Mode::Ray(log) => (log, 0.0),
        Mode::Cone(half_angle) => (None, half_angle),
    };
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
