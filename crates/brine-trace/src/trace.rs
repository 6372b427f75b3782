//! The entry point: clip, then step with the chosen method.

use crate::darles::darles_trace;
use crate::sphere::{Along, march, sphere_trace};
use crate::{Hit, LipschitzSum, Method, Ray, Step, TraceOptions, TraceStats};

/// Traces `ray` against the zero set of `surface` and returns the first sign change of `F`.
///
/// Clips the ray to [`LipschitzSum::zero_set_bounds`] and `[t_min, t_max]` (a ray that misses the
/// box costs nothing), then steps with [`TraceOptions::method`]. Every method either takes steps
/// certified free of zeros by a bound, or probe steps no longer than `h(t)` checked at their end;
/// a bracketed sign change is refined to the tolerance ([`crate::refine_crossing`], or
/// [`crate::bisect_crossing`] for brute force).
///
/// # Arguments
/// - `surface`: the implicit function.
/// - `ray`: the ray; `t` is measured along its unit direction (m).
/// - `options`: see [`TraceOptions`]; checked with `debug_assert!` (validate user input with
///   [`TraceOptions::validate`]).
/// - `stats`: counters to accumulate into.
///
/// # Returns
/// The hit, or `None` if `F` keeps its sign on the traced interval (up to skims thinner than the
/// minimum step) or the step cap is reached.
///
/// # References
/// Hart 1996, §3 (sphere tracing); Darles et al. 2007, §3.1 (brute force, Algorithm 1); Keinert
/// et al. 2014 (over-relaxation); Galin et al. 2020 (segment tracing); docs/equations.md §2–3.
pub fn trace<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    options: &TraceOptions,
    stats: &mut TraceStats,
) -> Option<Hit> {
    trace_impl(surface, ray, options, stats, None)
}

/// [`trace`], recording every step in `log` (appended): certified steps, probes, rejected
/// over-relaxed steps and the final bracket. Used by the safety tests.
///
/// # Arguments
/// As [`trace`], plus the log to append to.
///
/// # Returns
/// As [`trace`].
pub fn trace_logged<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: &mut Vec<Step>,
) -> Option<Hit> {
    trace_impl(surface, ray, options, stats, Some(log))
}

/// The crossing of a flat zero set: bounds that are a horizontal slab too thin for the ray to
/// resolve (a height field `F = y − h` with no waves, `y = c`, or waves thinner than the ray's
/// rounding) are crossed where the ray meets them. A ray that crosses the slab crosses its zero
/// set there (below the slab `F < 0`, above it `F > 0`), but the methods' sign test cannot see
/// it: at the one point of the span, `F` is the rounding of the ray's height, of either sign.
fn plane_crossing(bounds: &crate::Aabb, ray: &Ray, t0: f64, t1: f64, stats: &mut TraceStats) -> Option<Hit> {
    let horizontal = bounds.min.x == f64::NEG_INFINITY
        && bounds.min.z == f64::NEG_INFINITY
        && bounds.max.x == f64::INFINITY
        && bounds.max.z == f64::INFINITY;
    let d = ray.direction();
    // Exact: the clipped span is one point, and the slab alone (not cut by `t_min` or `t_max`,
    // which would leave the zero set beyond) spans that one point too.
    if !(horizontal && d.y != 0.0 && t1 - t0 == 0.0) {
        return None;
    }
    let (a, b) = bounds.clip(ray, f64::NEG_INFINITY, f64::INFINITY)?;
    if b - a != 0.0 {
        return None;
    }
    stats.hits += 1;
    let mut point = ray.at(t0);
    point.y = point.y.clamp(bounds.min.y, bounds.max.y);
    Some(Hit { t: t0, point, entering: d.y < 0.0, steps: 0 })
}

fn trace_impl<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    options: &TraceOptions,
    stats: &mut TraceStats,
    log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    debug_assert!(options.validate().is_ok(), "invalid trace options {options:?}");
    stats.rays += 1;
    let bounds = surface.zero_set_bounds();
    let Some((t0, t1)) = bounds.clip(ray, options.t_min, options.t_max) else {
        stats.culled += 1;
        return None;
    };
    if let Some(hit) = plane_crossing(&bounds, ray, t0, t1, stats) {
        return Some(hit);
    }
    let along = Along { surface, ray, n: surface.component_count() as u64 };
    let d = ray.direction();
    match options.method {
        Method::BruteForce => {
            let delta = if options.march_step > 0.0 {
                options.march_step
            } else {
                let size = surface.min_feature_size();
                if size.is_finite() { 0.25 * size } else { options.min_step }
            };
            march(&along, t0, t1, delta, options, stats, log)
        }
        Method::GlobalLipschitz => sphere_trace(&along, (t0, t1), surface.lipschitz(), 1.0, options, stats, log),
        Method::Directional => {
            sphere_trace(&along, (t0, t1), surface.directional_lipschitz(d), 1.0, options, stats, log)
        }
        Method::Relaxed => {
            sphere_trace(&along, (t0, t1), surface.directional_lipschitz(d), options.relaxation, options, stats, log)
        }
        Method::Darles => darles_trace(surface, ray, t0, t1, options, stats, log),
        // Both trace the surface's tiers; `trace_tiers_with` dispatches on the method.
        Method::Tiered | Method::Segment => surface.trace_tiered(crate::RaySpan::new(ray, t0, t1), options, stats, log),
    }
}
