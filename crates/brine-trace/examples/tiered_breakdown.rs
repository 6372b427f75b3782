//! Where the tiered method spends its evaluations: on the three cameras of the benchmark
//! (`benches/methods.rs`), N = 50 fitted trochoids, every `STRIDE`-th pixel, tiered + footprint,
//! at the benchmark's tolerance (0.1 mm + 10⁻⁶ t) and the renderer's (1 mm + 10⁻⁵ t).
//!
//! Per hitting ray: evaluations (mean / median / p99), split into pruned points (only the long
//! tiers evaluated), full certified points, probes (Newton probes and probes ≤ h) and refinement;
//! on stderr, the histogram of refinement evaluations per hitting ray.
//!
//! Run: `cargo run --release -p brine-trace --example tiered_breakdown [N] [STRIDE]`.
//!
//! With a third argument `oracle`: how far the tiered method is from the best step that per-wave
//! second-order information certifies, on the unfaded surface (like for like). The oracle bounds
//! each wave on its own by its exact f64 value, derivative and one-sided curvature bound,
//! clamped at its minimum, `F(t + s) ≥ y(t + s) + Σᵢ max(nᵢ + nᵢ′s − ½cᵢs², −Aᵢ)`, and steps to
//! the first root of that bound (found by a march in 0.5 % increments, so an idealisation, not a
//! certified method), with every wave sampled exactly (no tiers, no f32, no pruning). Printed per
//! hitting ray: certified steps until within 10 cm of the hit for the oracle and for the tiered
//! method (its accepted certified steps), the tiered method's evaluations in all, and the median
//! over the oracle's steps of the distance left to the hit divided by the step.

use brine_trace::{Method, Ray, StepKind, TraceOptions, TraceStats, trace, trace_logged};
use brine_waves::{
    CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TracedTrochoids, TrochoidSet, fit_trochoids,
    solve_trochoid_phase,
};
use glam::DVec3;

const WIDTH: usize = 640;
const HEIGHT: usize = 480;
const FOV_DEG: f64 = 50.0;

/// The benchmark's cameras: name, height (m), pitch (degrees).
const CAMERAS: [(&str, f64, f64); 3] =
    [("2 m grazing", 2.0, -2.0), ("10 m horizon", 10.0, -9.0), ("50 m down", 50.0, -50.0)];

/// The benchmark's tracer options (tiered, [`TraceOptions::comparison`]) at a tolerance and a
/// footprint angle (rad, 0: no fading).
fn bench_options(tolerance: f64, tolerance_relative: f64, footprint_angle: f64) -> TraceOptions {
    TraceOptions { tolerance, tolerance_relative, ..TraceOptions::comparison(Method::Tiered, footprint_angle) }
}

/// Directions of every `stride`-th pixel of a benchmark camera (bearing 100°, pitch in degrees).
fn directions(pitch_deg: f64, stride: usize) -> Vec<DVec3> {
    let (b, e) = (100f64.to_radians(), pitch_deg.to_radians());
    let forward = DVec3::new(b.sin() * e.cos(), e.sin(), -b.cos() * e.cos());
    let right = forward.cross(DVec3::Y).normalize();
    let up = right.cross(forward);
    let tan_half = (0.5 * FOV_DEG.to_radians()).tan();
    let aspect = WIDTH as f64 / HEIGHT as f64;
    let mut out = Vec::new();
    for y in (0..HEIGHT).step_by(stride).map(|y| y + stride / 2) {
        for x in (0..WIDTH).step_by(stride).map(|x| x + stride / 2) {
            let sx = (2.0 * (x as f64 + 0.5) / WIDTH as f64 - 1.0) * tan_half * aspect;
            let sy = (1.0 - 2.0 * (y as f64 + 0.5) / HEIGHT as f64) * tan_half;
            out.push((forward + sx * right + sy * up).normalize());
        }
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(50);
    let stride: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(8);
    let pm = PiersonMoskowitz::from_u10(10.0).expect("valid wind");
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).expect("valid spreading");
    let fit = FitOptions { wind_direction: 20f64.to_radians(), choppiness: 2.5, ..FitOptions::default() };
    let set = fit_trochoids(&pm, &spreading, n, 1, &fit).expect("valid fit");
    let sea = TracedTrochoids::new(&set, 0.0);
    let footprint = 2.0 * (0.5 * FOV_DEG.to_radians()).tan() / HEIGHT as f64;
    if args.get(3).is_some_and(|a| a == "oracle") {
        oracle_table(&set, &sea, n, stride);
        return;
    }
    println!("N = {n}, every {stride}th pixel, tiered + footprint");
    println!(
        "| camera | tolerance | hits | mean | median | p99 | pruned | full certified | probe | refinement | time µs/ray |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for (name, height, pitch) in CAMERAS {
        let dirs = directions(pitch, stride);
        for (tol_name, tol, tol_rel) in [("0.1 mm + 1e-6 t", 1e-4, 1e-6), ("1 mm + 1e-5 t", 1e-3, 1e-5)] {
            let o = bench_options(tol, tol_rel, footprint);
            let mut per_hit = Vec::new();
            let mut parts = TraceStats::default();
            let start = std::time::Instant::now();
            let mut histo = [0u32; 8];
            for d in &dirs {
                let ray = Ray::new(DVec3::new(0.0, height, 0.0), *d).expect("unit direction");
                let mut s = TraceStats::default();
                if trace(&sea, &ray, &o, &mut s).is_some() {
                    per_hit.push(s.evaluations as f64);
                    parts.merge(&s);
                    histo[(s.refinement_evaluations as usize).min(7)] += 1;
                }
            }
            eprintln!("refinement histogram {histo:?}");
            let us = start.elapsed().as_secs_f64() * 1e6 / dirs.len() as f64;
            per_hit.sort_by(f64::total_cmp);
            let h = per_hit.len().max(1) as f64;
            let q =
                |p: f64| per_hit.get(((per_hit.len().max(1) - 1) as f64 * p).round() as usize).copied().unwrap_or(0.0);
            let full =
                parts.evaluations - parts.pruned_evaluations - parts.probe_evaluations - parts.refinement_evaluations;
            println!(
                "| {name} | {tol_name} | {} | {:.2} | {:.0} | {:.0} | {:.2} | {:.2} | {:.2} | {:.2} | {us:.2} |",
                per_hit.len(),
                parts.evaluations as f64 / h,
                q(0.5),
                q(0.99),
                parts.pruned_evaluations as f64 / h,
                full as f64 / h,
                parts.probe_evaluations as f64 / h,
                parts.refinement_evaluations as f64 / h,
            );
        }
    }
}

/// Distance within which a ray counts as arrived (m): from there a Newton probe ends the trace.
const ARRIVED: f64 = 0.1;

/// The oracle's step from `t` along `o + t d` (see the module docs), found by the aggregate
/// quadratic's root (a lower bound of the oracle's) and then a march in 0.5 % increments.
fn oracle_step(set: &TrochoidSet, o: DVec3, d: DVec3, t: f64, t_exit: f64) -> f64 {
    let p = o + d * t;
    // (nᵢ, nᵢ′, cᵢ, Aᵢ) of each wave term nᵢ = −hᵢ along the ray.
    let terms: Vec<(f64, f64, f64, f64)> = set
        .waves()
        .iter()
        .map(|w| {
            let kv = w.direction_vector() * w.wavenumber();
            let phase = kv.x * p.x + kv.y * p.z + w.phase();
            let sigma = kv.x * d.x + kv.y * d.z;
            let (q, a) = (w.steepness(), w.amplitude());
            let (_, c, s) = solve_trochoid_phase(phase, q);
            let rate = sigma / w.wavenumber();
            (-a * c, a * s / (1.0 - q * c) * sigma, w.max_trough_curvature() * rate * rate, a)
        })
        .collect();
    let y = |s: f64| o.y + d.y * (t + s);
    let bound = |s: f64| y(s) + terms.iter().map(|&(v, g, c, a)| (v + g * s - 0.5 * c * s * s).max(-a)).sum::<f64>();
    let (v, g, c) = terms.iter().fold((y(0.0), d.y, 0.0), |acc, x| (acc.0 + x.0, acc.1 + x.1, acc.2 + x.2));
    // First root of v + g s − ½ c s².
    let mut s = if c > 0.0 {
        (g + (g * g + 2.0 * c * v).sqrt()) / c
    } else if g < 0.0 {
        -v / g
    } else {
        t_exit - t
    };
    s = s.clamp(0.0, t_exit - t);
    while s < t_exit - t && bound(s * 1.005 + 1e-6) > 0.0 {
        s = s * 1.005 + 1e-6;
    }
    s
}

fn oracle_table(set: &TrochoidSet, sea: &TracedTrochoids, n: usize, stride: usize) {
    println!("N = {n}, every {stride}th pixel, unfaded: certified steps per hitting ray until within {ARRIVED} m");
    println!(
        "| camera | hits | oracle steps: mean / median | tiered certified steps: mean / median | tiered evaluations (all): mean | distance to the hit / oracle step: median |"
    );
    println!("|---|---|---|---|---|---|");
    let amplitude = set.total_amplitude();
    for (name, height, pitch) in CAMERAS {
        let o = bench_options(1e-4, 1e-6, 0.0);
        let (mut oracle, mut tiered, mut slack, mut evals) = (Vec::new(), Vec::new(), Vec::new(), 0.0);
        for d in directions(pitch, stride) {
            let origin = DVec3::new(0.0, height, 0.0);
            let ray = Ray::new(origin, d).expect("unit direction");
            let (mut st, mut log) = (TraceStats::default(), Vec::new());
            let Some(hit) = trace_logged(sea, &ray, &o, &mut st, &mut log) else { continue };
            evals += st.evaluations as f64;
            let certified = log.iter().filter(|s| s.kind == StepKind::Certified && s.t_from < hit.t - ARRIVED).count();
            tiered.push(certified as f64);
            // The oracle from the slab's entry, as the tiered method.
            let mut t = if d.y < 0.0 { ((height - amplitude) / -d.y).max(0.0) } else { 0.0 };
            let mut steps = 0;
            while t < hit.t - ARRIVED && steps < 10_000 {
                let step = oracle_step(set, origin, d, t, hit.t).max(1e-6);
                // How much further the surface really is than the oracle could certify.
                slack.push((hit.t - t) / step);
                t += step;
                steps += 1;
            }
            oracle.push(f64::from(steps));
        }
        let stats = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            (v.iter().sum::<f64>() / v.len().max(1) as f64, v.get(v.len() / 2).copied().unwrap_or(0.0))
        };
        let hits = oracle.len();
        let ((om, omed), (tm, tmed), (_, smed)) = (stats(&mut oracle), stats(&mut tiered), stats(&mut slack));
        println!(
            "| {name} | {hits} | {om:.2} / {omed:.0} | {tm:.2} / {tmed:.0} | {:.2} | {smed:.1} |",
            evals / hits.max(1) as f64
        );
    }
}
