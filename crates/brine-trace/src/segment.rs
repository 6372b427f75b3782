//! Segment tracing (Galin et al. 2020) on the tiers of a ray: sphere tracing with a Lipschitz
//! bound local to a candidate segment instead of the global one.

use crate::options::log_step;
use crate::tiered::refine_tiers;
use crate::{Hit, RaySpan, RayTiers, Step, StepKind, TierBounds, TierScratch, TraceOptions, TraceStats};

/// Growth factor `κ` of the candidate segment (Galin et al. 2020, Algorithm 2: after a step `tₖ`
/// the next candidate segment is `κ tₖ`; `κ > 1` lets the segment grow after a step clamped to
/// it). Measured on the benchmark's cameras (fitted sea, N = 50, unfaded, every 8th pixel), mean
/// evaluations per hitting ray at 2 m / 10 m / 50 m: κ = 1 → 39.4 / 38.7 / 13.9, 1.1 → 36.6 / 33.1
/// / 13.9, 1.25 → 37.0 / 33.5 / 14.0, 1.5 → 37.8 / 34.2 / 14.2, 2 → 39.0 / 35.2 / 14.3, 3 → 40.7 /
/// 36.6 / 14.6, 4 → 41.9 / 37.5 / 14.8 (directional sphere tracing: 56.7 / 45.7 / 16.2). A shorter
/// candidate segment gives a tighter local bound; one no longer than the last step cannot grow.
pub const SEGMENT_GROWTH: f64 = 1.1;

/// Bounds are re-read (they tighten as footprint fading removes components) once `t` has grown by
/// this factor since the last reading (as in the tiered method).
const REFRESH_GROWTH: f64 = 1.25;

/// The Lipschitz bound of one tier local to the segment `[t, t + s]` of the ray.
///
/// The tier's derivative along the ray is `d` at `t` and changes at most at the rate `K` (its
/// curvature bound), so on the segment `|T'(t + u)| ≤ |d| + K u ≤ |d| + K s`; it is also at most
/// the tier's Lipschitz constant `L` along the ray. Hence
///
/// `λ_[t, t+s] = min(L, |d| + K s)`,
///
/// a bound of `|T(t + u) − T(t + v)|/|u − v|` for `u, v ∈ [0, s]` that tends to `|d|` on short
/// segments and to `L` (Hart's constant) on long ones. An unknown derivative (`NaN`) or curvature
/// (`+∞`) gives `L`.
///
/// # Arguments
/// - `bounds`: the tier's bounds along the ray (`lipschitz` = `L` ≥ 0, per metre; `curvature` = `K`
///   ≥ 0, per metre², may be `+∞`), valid on the segment.
/// - `slope`: the tier's derivative `d` along the ray at `t` (per metre), or `NaN` if unknown.
/// - `length`: the segment length `s` (m), `[0, ∞]`.
///
/// # Returns
/// `λ_[t, t+s]` (per metre), in `[0, L]`.
///
/// # References
/// Galin, Guérin, Paris & Peytavie 2020, "Segment tracing using local Lipschitz bounds", CGF
/// 39(2), §3 (local Lipschitz bound of a function over a segment) and §4 (bounds of primitives
/// from their derivatives); the curvature form is Brine's (docs/models/brine-trace.md).
#[inline]
pub fn local_lipschitz(bounds: &TierBounds, slope: f64, length: f64) -> f64 {
    let global = bounds.lipschitz;
    if slope.is_finite() && bounds.curvature.is_finite() {
        let growth = if bounds.curvature > 0.0 && length > 0.0 { bounds.curvature * length } else { 0.0 };
        let local = slope.abs() + growth;
        global.min(local)
    } else {
        global
    }
}

/// Segment tracing ([`crate::Method::Segment`]) on a ray given as tiers `F = Σⱼ Tⱼ`.
///
/// At each point `t` every tier is evaluated (value and derivative). With a candidate segment of
/// length `s`, `F` is `λ`-Lipschitz on `[t, t + s]` with
///
/// `λ = η + Σⱼ min(Lⱼ, |dⱼ| + Kⱼ s)` ([`local_lipschitz`]; `η` the evaluator's derivative error),
///
/// so no zero of `F` lies in `[t, t + tₖ)` for `tₖ = min(s, (|F̃(t)| − 2ε)/λ)` (`ε` the evaluator's
/// value error: the exact `F` stays above `ε` there, so the sampled `F̃` keeps its sign too). The
/// ray moves by `tₖ` and the next candidate segment is `κ tₖ` ([`SEGMENT_GROWTH`]); the first
/// candidate is the whole ray (`s = ∞`: the first step is the directional Lipschitz step). As in
/// [`crate::trace`], a certified step shorter than the minimum step `h(t)` is replaced by a probe
/// of length `h` checked at its end, and a sign change is refined by [`refine_crossing`].
///
/// Safety: a certified step never contains a zero of the exact `F` (nor of `F̃`), whatever `κ`:
/// the bound holds on the candidate segment and the step never leaves it.
///
/// # Arguments
/// - `scratch`: reusable buffers.
/// - `tiers`: the function along the ray; their bounds must hold from the point where they are
///   read to `t_exit` (the [`RayTiers`] contract).
/// - `span`: the ray (only used to report the hit point) and the traced interval
///   `[t_enter, t_exit]` (m), already clipped.
/// - `options`: minimum step, tolerance, step cap, footprint (for bound refreshing).
/// - `stats`: counters; one evaluation per point visited (all tiers), terms as reported by the
///   tiers.
/// - `log`: receives each step when given.
///
/// # Returns
/// The first sign change on `[t_enter, t_exit]` (up to skims thinner than `h`), or `None`.
///
/// # References
/// Galin et al. 2020, Algorithm 2 (segment tracing: `tₖ = |f|/λ_S`, clamped to the segment `S`,
/// next segment `κ tₖ`); Hart 1996 (sphere tracing).
pub fn trace_segments<R: RayTiers + ?Sized>(
    scratch: &mut TierScratch,
    tiers: &mut R,
    span: RaySpan<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    let RaySpan { ray, t_enter, t_exit } = span;
    let n = tiers.tier_count();
    if n == 0 || !(t_enter < t_exit) {
        return None;
    }
    let eps = 2.0 * tiers.error_bound();
    let eta = tiers.slope_error_bound();
    let (bounds, slopes) = (&mut scratch.segment_bounds, &mut scratch.segment_slopes);
    bounds.clear();
    bounds.extend((0..n).map(|j| tiers.bounds(j, t_enter)));
    slopes.clear();
    slopes.resize(n, f64::NAN);
    let mut t_refresh = t_enter;

    // Samples every tier at t: returns F̃(t), stores the derivatives.
    let sample = |tiers: &mut R, slopes: &mut Vec<f64>, stats: &mut TraceStats, t: f64| {
        stats.evaluations += 1;
        let mut sum = 0.0;
        for (j, slope) in slopes.iter_mut().enumerate() {
            let s = tiers.sample(j, t);
            stats.component_evaluations += u64::from(s.terms);
            sum += s.value;
            *slope = s.slope;
        }
        sum
    };

    let mut t = t_enter;
    let mut g = sample(tiers, slopes, stats, t);
    if g == 0.0 {
        stats.hits += 1;
        return Some(Hit { t, point: ray.at(t), entering: true, steps: 0 });
    }
    let positive = g > 0.0;
    let mut segment = f64::INFINITY;
    let mut steps = 0u32;
    loop {
        if !options.take_step(&mut steps, stats) {
            return None;
        }
        let lambda = eta + bounds.iter().zip(slopes.iter()).map(|(b, &d)| local_lipschitz(b, d, segment)).sum::<f64>();
        let c = g.abs() - eps;
        let free = if !(c > 0.0) {
            0.0
        } else if lambda > 0.0 {
            c / lambda
        } else {
            f64::INFINITY
        };
        let step = free.min(segment);
        let h = options.min_step_at(t);
        let certified = step >= h;
        if certified && t + step >= t_exit {
            log_step(&mut log, t, t_exit, StepKind::Certified);
            return None;
        }
        let t_next = if certified { t + step } else { (t + h).min(t_exit) };
        if !certified {
            stats.probe_evaluations += 1;
        }
        let g_next = sample(tiers, slopes, stats, t_next);
        if g_next == 0.0 || (g_next > 0.0) != positive {
            log_step(&mut log, t, t_next, StepKind::Bracket);
            let tolerance = options.tolerance_at(t_next);
            let t_hit = refine_tiers(tiers, 1.0, (t, g), (t_next, g_next), tolerance, stats);
            stats.hits += 1;
            return Some(Hit { t: t_hit, point: ray.at(t_hit), entering: positive, steps });
        }
        log_step(&mut log, t, t_next, if certified { StepKind::Certified } else { StepKind::Probe });
        if t_next >= t_exit {
            return None;
        }
        segment = SEGMENT_GROWTH * (t_next - t);
        t = t_next;
        g = g_next;
        if options.footprint_angle > 0.0 && t >= REFRESH_GROWTH * t_refresh {
            for (j, b) in bounds.iter_mut().enumerate() {
                *b = tiers.bounds(j, t);
            }
            t_refresh = t;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `local_lipschitz` is exact arithmetic on its inputs.
    const EXACT: f64 = 1e-15;

    #[test]
    fn local_bound_is_the_slope_on_a_point_and_the_lipschitz_constant_far_away() {
        let b = TierBounds::symmetric(-1.0, 1.0, 2.0, 4.0);
        // s = 0: |d|; s = 0.25: |−0.5| + 4·0.25 = 1.5; s = 1: min(2, 4.5) = 2.
        assert!((local_lipschitz(&b, -0.5, 0.0) - 0.5).abs() < EXACT);
        assert!((local_lipschitz(&b, -0.5, 0.25) - 1.5).abs() < EXACT);
        assert!((local_lipschitz(&b, -0.5, 1.0) - 2.0).abs() < EXACT);
        assert!((local_lipschitz(&b, -0.5, f64::INFINITY) - 2.0).abs() < EXACT);
        // Unknown derivative or curvature: the global constant.
        assert!((local_lipschitz(&b, f64::NAN, 0.0) - 2.0).abs() < EXACT);
        let unknown = TierBounds::symmetric(-1.0, 1.0, 2.0, f64::INFINITY);
        assert!((local_lipschitz(&unknown, 0.1, 0.0) - 2.0).abs() < EXACT);
    }
}
