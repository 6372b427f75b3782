//! Where the tiered method spends its evaluations: on the three cameras of the benchmark
//! (`benches/methods.rs`), N = 50 fitted trochoids, every `STRIDE`-th pixel, tiered + footprint,
//! at the benchmark's tolerance (0.1 mm + 10⁻⁶ t) and the renderer's (1 mm + 10⁻⁵ t).
//!
//! Per hitting ray: evaluations (mean / median / p99), split into pruned points (only the long
//! tiers evaluated), full certified points, probes (Newton probes and probes ≤ h) and refinement;
//! on stderr, the histogram of refinement evaluations per hitting ray.
//!
//! Run: `cargo run --release -p brine-trace --example tiered_breakdown [N] [STRIDE]`.

use brine_trace::{Method, Ray, TraceOptions, TraceStats, trace};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TracedTrochoids, fit_trochoids};
use glam::DVec3;

const WIDTH: usize = 640;
const HEIGHT: usize = 480;
const FOV_DEG: f64 = 50.0;

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
    println!("N = {n}, every {stride}th pixel, tiered + footprint");
    println!(
        "| camera | tolerance | hits | mean | median | p99 | pruned | full certified | probe | refinement | time µs/ray |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for (name, height, pitch) in [("2 m grazing", 2.0, -2.0), ("10 m horizon", 10.0, -9.0), ("50 m down", 50.0, -50.0)]
    {
        let dirs = directions(pitch, stride);
        for (tol_name, tol, tol_rel) in [("0.1 mm + 1e-6 t", 1e-4, 1e-6), ("1 mm + 1e-5 t", 1e-3, 1e-5)] {
            let o = TraceOptions {
                method: Method::Tiered,
                t_max: 3000.0,
                max_steps: 200_000,
                min_step: 1e-3,
                min_step_relative: 1e-4,
                tolerance: tol,
                tolerance_relative: tol_rel,
                footprint_angle: footprint,
                ..TraceOptions::default()
            };
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
