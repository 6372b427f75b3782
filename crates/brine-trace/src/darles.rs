//! Darles et al. (2007) Algorithm 1, corrected, with spatial coherence for the sort.

use crate::options::log_step;
use crate::sphere::{Along, Bracket};
use crate::step::PrefixScan;
use crate::{Hit, LipschitzSum, Ray, Step, StepKind, TraceOptions, TraceStats};

/// Traces with the efficient bound of Darles et al. (docs/equations.md §2) on `[t0, t1]`.
///
/// At each point `p` the components are sorted by decreasing `(eᵢ − mᵢ)/Lᵢ(d̂)`, where `eᵢ` is
/// the value of component `i` at the last point where it was evaluated (spatial coherence, §3.3:
/// estimates are used for sorting only), and visited in that order: each visited component is
/// evaluated exactly, and the scan stops at the first decrease of the candidate step
/// `(M + Σ(vᵢ − mᵢ))/Σ Lᵢ` once it is positive. Unvisited components enter through their minima
/// `mᵢ` over the segment `[p, end]`. When the step falls below `h(t)`, the remaining components
/// are evaluated and the end of a probe step `h` is checked for a sign change, as in
/// [`crate::trace`]. A ray that starts inside (`F < 0`) traces `−F` with `−Mᵢ` as minima (it
/// falls back to every component when an `Mᵢ` is unknown).
pub(crate) fn darles_trace<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    t0: f64,
    t1: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    let n = surface.component_count();
    let along = Along { surface, ray, n: n as u64 };
    let d = ray.direction();
    let lipschitz: Vec<f64> = (0..n).map(|i| surface.component_directional_lipschitz(i, d)).collect();
    let end = ray.at(t1);

    // First point: every component (the sign of F is needed).
    let mut t = t0;
    let mut p = ray.at(t);
    let mut estimate: Vec<f64> = (0..n).map(|i| surface.component(i, p)).collect();
    stats.evaluations += 1;
    stats.component_evaluations += n as u64;
    let f0: f64 = estimate.iter().sum();
    if f0 == 0.0 {
        stats.hits += 1;
        return Some(Hit { t, point: p, entering: true, steps: 0 });
    }
    let sign = if f0 > 0.0 { 1.0 } else { -1.0 };
    let minimum = |i: usize, a| {
        if sign > 0.0 { surface.component_min(i, a, end) } else { -surface.component_max(i, a, end) }
    };

    let mut order: Vec<usize> = (0..n).collect();
    let mut value = vec![0.0; n];
    let mut visited = vec![false; n];
    let mut minima = vec![0.0; n];
    let mut fresh = true; // estimates at p are exact values (first point, or after a full evaluation)
    let mut steps = 0u32;
    loop {
        if !options.take_step(&mut steps, stats) {
            return None;
        }
        for (i, m) in minima.iter_mut().enumerate() {
            *m = minimum(i, p);
        }
        let key = |i: usize| {
            let r = sign * estimate[i] - minima[i];
            if lipschitz[i] > 0.0 { r / lipschitz[i] } else { f64::INFINITY }
        };
        order.sort_by(|&a, &b| key(b).total_cmp(&key(a)));
        visited.iter_mut().for_each(|v| *v = false);
        let mut scan = PrefixScan::new(minima.iter().sum());
        if !fresh {
            stats.evaluations += 1;
        }
        if !scan.unreachable() {
            for &i in &order {
                let v = if fresh {
                    estimate[i]
                } else {
                    stats.component_evaluations += 1;
                    surface.component(i, p)
                };
                value[i] = v;
                estimate[i] = v;
                visited[i] = true;
                if !scan.add(sign * v - minima[i], lipschitz[i]) {
                    break;
                }
            }
        }
        let step = scan.step();
        let h = options.min_step_at(t);
        if t + step >= t1 {
            log_step(&mut log, t, t1, StepKind::Certified);
            return None;
        }
        if step >= h {
            log_step(&mut log, t, t + step, StepKind::Certified);
            t += step;
            p = ray.at(t);
            fresh = false;
            continue;
        }
        // Short step: complete F at p, probe at t + h.
        for i in 0..n {
            if !visited[i] {
                value[i] = if fresh {
                    estimate[i]
                } else {
                    stats.component_evaluations += 1;
                    surface.component(i, p)
                };
                estimate[i] = value[i];
            }
        }
        let f: f64 = value.iter().sum();
        if f == 0.0 || (f > 0.0) != (sign > 0.0) {
            // The last certified step ended on the surface: its bound reached zero at t, and F
            // evaluated there is zero or a rounding error past it (a vertical ray over waves, whose
            // bound along the ray is exact, lands on F = 0 ± 10⁻¹⁵). The crossing is at t.
            log_step(&mut log, t, t, StepKind::Bracket);
            stats.hits += 1;
            return Some(Hit { t, point: p, entering: sign > 0.0, steps });
        }
        let t_next = (t + h).min(t1);
        let q = ray.at(t_next);
        for (i, e) in estimate.iter_mut().enumerate() {
            *e = surface.component(i, q);
        }
        stats.evaluations += 1;
        stats.component_evaluations += n as u64;
        let f_next: f64 = estimate.iter().sum();
        if f_next == 0.0 || (f_next > 0.0) != (sign > 0.0) {
            log_step(&mut log, t, t_next, StepKind::Bracket);
            return Some(along.finish(
                stats,
                options,
                Bracket { a: (t, f), b: (t_next, f_next), entering: sign > 0.0, steps },
                false,
            ));
        }
        log_step(&mut log, t, t_next, StepKind::Probe);
        if t_next >= t1 {
            return None;
        }
        t = t_next;
        p = q;
        fresh = true;
    }
}
