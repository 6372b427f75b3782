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
    /// Curvature bound used with `slope` (0 when the slope is the Lipschitz lower bound).
    curvature: Vec<f64>,
}

impl TierScratch {
    fn reset(&mut self, n: usize) {
        for v in [&mut self.lo, &mut self.key, &mut self.value, &mut self.slope, &mut self.curvature] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.lo_suffix.clear();
        self.lo_suffix.resize(n + 1, 0.0);
        self.bounds.clear();
        self.bounds.resize(n, TierBounds::ZERO);
    }

    /// Reads the bounds of every tier at `t` and orients them by `sign`.
    fn refresh<R: RayTiers + ?Sized>(&mut self, tiers: &mut R, t: f64, sign: f64) {
        let n = self.bounds.len();
        for j in 0..n {
            let b = tiers.bounds(j, t);
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
        if slope.is_finite() && b.curvature.is_finite() {
            self.slope[j] = (sign * slope).max(-b.lipschitz);
            self.curvature[j] = b.curvature;
        } else {
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
    fn step(&self, k: usize, eps: f64, eta: f64, guess: f64) -> f64 {
        let value: f64 = self.value[..k].iter().sum::<f64>() + self.lo_suffix[k] - eps;
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
                slope: -eta,
                curvature: 0.0,
                lipschitz: 0.0,
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

/// How far one tier can fall over `s` by its quadratic bound: `−∫₀ˢ max(d − K u, −L) du`.
fn quadratic_fall(d: f64, k: f64, l: f64, s: f64) -> f64 {
    if k <= 0.0 {
        return -d * s;
    }
    let s1 = (d + l) / k;
    if s <= s1 { -(d * s - 0.5 * k * s * s) } else { -(d * s1 - 0.5 * k * s1 * s1) + l * (s - s1) }
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

/// The tiered method ([`crate::Method::Tiered`]) on a ray given as tiers `F = Σⱼ Tⱼ`.
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
/// frequencies); Galin et al. 2020 (segment tracing: local bounds over the step); equation sheet §2.
#[allow(clippy::too_many_arguments)]
pub fn trace_tiers_with<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    ray: &Ray,
    t_enter: f64,
    t_exit: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    let n = tiers.tier_count();
    if n == 0 || !(t_enter < t_exit) {
        return None;
    }
    let eps = 2.0 * tiers.error_bound();
    let eta = tiers.slope_error_bound();
    scratch.reset(n);
    let mut t = t_enter;
    scratch.refresh(tiers, t, 1.0);
    let mut t_refresh = t;

    // Which side of the surface the ray starts on: add tiers until the bounds decide.
    let mut raw = Vec::with_capacity(4);
    let (mut sum, mut k) = (0.0, 0);
    stats.evaluations += 1;
    let sign = loop {
        let s = tiers.sample(k, t);
        stats.component_evaluations += u64::from(s.terms);
        raw.push((s.value, s.slope));
        sum += s.value;
        k += 1;
        let lo_rest: f64 = scratch.bounds[k..].iter().map(|b| b.min).sum();
        let hi_rest: f64 = scratch.bounds[k..].iter().map(|b| b.max).sum();
        if sum + lo_rest > eps {
            break 1.0;
        }
        if sum + hi_rest < -eps {
            break -1.0;
        }
        if k == n {
            if sum == 0.0 {
                stats.hits += 1;
                return Some(Hit { t, point: ray.at(t), entering: true, steps: 0 });
            }
            break sum.signum();
        }
    };
    if sign < 0.0 {
        scratch.refresh(tiers, t, sign);
    }
    for (j, &(v, d)) in raw.iter().enumerate() {
        scratch.store(j, v, d, sign);
    }
    let mut sampled = k;
    let mut guess = f64::NAN;
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
            stats.exhausted += 1;
            return None;
        }
        steps += 1;
        if sampled < k {
            if sampled == 0 {
                stats.evaluations += 1;
            }
            sample_range(scratch, tiers, stats, sampled, k, t);
        }
        let mut s = scratch.step(k, eps, eta, guess);
        while k < n && s < scratch.key[k] {
            let mut k2 = k + 1;
            while k2 < n && scratch.key[k2] > s {
                k2 += 1;
            }
            sample_range(scratch, tiers, stats, k, k2, t);
            k = k2;
            s = scratch.step(k, eps, eta, guess);
        }
        let h = options.min_step_at(t);
        if s < h && k < n {
            sample_range(scratch, tiers, stats, k, n, t);
            k = n;
            s = scratch.step(k, eps, eta, guess);
        }
        if !(s >= 0.0) {
            s = 0.0;
        }
        if t + s >= t_exit {
            log_step(&mut log, t, t_exit, StepKind::Certified);
            return None;
        }
        if s >= h {
            log_step(&mut log, t, t + s, StepKind::Certified);
            t += s;
            guess = s;
            k = scratch.next_depth(s);
            sampled = 0;
            if options.footprint_angle > 0.0 && t >= REFRESH_GROWTH * t_refresh {
                scratch.refresh(tiers, t, sign);
                t_refresh = t;
            }
            continue;
        }

        // Every tier is evaluated and the certified step is shorter than h: probe.
        let g: f64 = scratch.value.iter().sum();
        let slope: f64 = scratch.slope.iter().sum();
        let tol = options.tolerance_at(t);
        let newton = if slope < 0.0 { g / -slope + 0.5 * tol } else { h };
        let p = newton.clamp(s, h).min(t_exit - t);
        let tp = t + p;
        stats.evaluations += 1;
        sample_range(scratch, tiers, stats, 0, n, tp);
        let gp: f64 = scratch.value.iter().sum();
        if gp <= 0.0 {
            log_step(&mut log, t + s, tp, StepKind::Bracket);
            let t_hit = if gp == 0.0 {
                tp
            } else if p - s <= tol {
                t + 0.5 * (s + p)
            } else {
                let mut refinement = 0u64;
                let mut terms = 0u64;
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
                    t,
                    g,
                    tp,
                    gp,
                    tol,
                );
                stats.evaluations += refinement;
                stats.refinement_evaluations += refinement;
                stats.component_evaluations += terms;
                t_hit
            };
            stats.hits += 1;
            return Some(Hit { t: t_hit, point: ray.at(t_hit), entering: sign > 0.0, steps });
        }
        log_step(&mut log, t, tp, StepKind::Probe);
        t = tp;
        if t >= t_exit {
            return None;
        }
        guess = p;
        k = n;
        sampled = n;
    }
}
