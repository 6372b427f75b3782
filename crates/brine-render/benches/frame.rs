//! `cargo xtask bench frame`: one 640×480 frame of the default scene with 100 waves and every
//! phenomenon on (foam, whitecaps, spray, sub-surface crests, aerial perspective, clouds, glare),
//! 1 sample per pixel: the median of 5 renders, then one profiled render for the share of each
//! stage (the paper's Table 3; Darles et al. report about 3 minutes for a frame of 50 waves).
//! The same scene on the FFT ocean (`surface = "fft"`, 4 cascades of 256²) is measured alongside,
//! in the same process, and the ratio printed.

#[path = "common/mod.rs"]
mod common;

use std::time::Instant;

use brine_render::scene::SurfaceKind;
use brine_render::{RenderOptions, Scene, World, render_world};

/// Renders per variant; the median is reported.
const RUNS: usize = 5;

/// The median of `v`.
fn median(v: &mut [f64]) -> f64 {
    brine_testkit::timing::median(v.to_vec())
}

/// Median whole-frame and setup times (s) of `scene`, with its summary and stage shares printed.
fn measure(label: &str, scene: &Scene) -> f64 {
    let (mut setup, mut total) = (Vec::new(), Vec::new());
    let mut last = None;
    for _ in 0..RUNS {
        let t0 = Instant::now();
        let world = World::new(scene).expect("bench scene is valid");
        let t1 = Instant::now();
        let frame = render_world(scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
        let t2 = Instant::now();
        setup.push((t1 - t0).as_secs_f64());
        total.push((t2 - t0).as_secs_f64());
        last = Some(frame);
    }
    let (s, f) = (median(&mut setup), median(&mut total));
    let frame = last.expect("ran");
    println!("\n{label}");
    println!("whole frame (median)                   {f:>8.3} s");
    println!("  scene setup (fit or FFT, sky, calibration)  {s:>8.3} s");
    println!(
        "evaluations of F per primary ray: {:.2}; secondary rays: {} ({:.2} evaluations each)",
        frame.stats.evaluations_per_ray(),
        frame.secondary_stats.rays,
        frame.secondary_stats.evaluations_per_ray()
    );
    let world = World::new(scene).expect("bench scene is valid");
    let profiled = render_world(scene, &world, &RenderOptions { profile: true, ..RenderOptions::default() }, &|| {})
        .expect("renders");
    let stages = profiled.stages.expect("profiled");
    let named = stages.named();
    // The per-pixel stages are thread time summed over the workers; glare and exposure run after
    // the pixels and are wall-clock time: each is shown as a share of its own kind.
    let pixel_sum: f64 = named[..7].iter().map(|(_, t)| t).sum();
    println!("share of each per-pixel stage (one profiled frame, thread time summed over workers):");
    for (name, t) in &named[..7] {
        println!("  {name:<36} {:>6.1} %  ({:.3} s)", 100.0 * t / pixel_sum, t);
    }
    let (name, post) = named[7];
    println!("  {name:<36} {:>6.3} s wall ({:.1} % of the median frame)", post, 100.0 * post / f);
    f
}

fn main() {
    let mut scene = common::reference_frame_scene();
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines().find(|l| l.starts_with("model name")).map(|l| l.split(':').nth(1).unwrap_or("").trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".into());
    // The workspace builds for the x86-64 baseline: `wide` uses SSE2 whatever the CPU offers.
    println!(
        "CPU: {cpu}; SIMD of this build: {}",
        if cfg!(target_feature = "avx2") { "AVX2" } else { "SSE2 (baseline)" }
    );
    println!(
        "frame benchmark: 640×480, every phenomenon on, 1 spp, {} threads, median of {RUNS}",
        rayon::current_num_threads()
    );
    let trochoids = measure("trochoids, N = 100 (the reference frame)", &scene);
    scene.sea.surface = SurfaceKind::Fft;
    let fft = measure("FFT ocean, 4 cascades × 256² (same scene, surface = \"fft\")", &scene);
    println!("\nFFT / trochoids frame time: {:.2}×", fft / trochoids);

    // White water at 16 m/s: the foam left by breaking crests and remembered, against the foam and
    // whitecaps drawn separately (`foam_memory = false`), interleaved in this process.
    scene.sea.wind_speed_m_s = 16.0;
    let mut ratios = Vec::new();
    for surface in [SurfaceKind::Trochoids, SurfaceKind::Fft] {
        scene.sea.surface = surface;
        scene.phenomena.foam_memory = false;
        let separate = measure(&format!("{surface:?}, 16 m/s, foam and whitecaps separate"), &scene);
        scene.phenomena.foam_memory = true;
        let memory = measure(&format!("{surface:?}, 16 m/s, white water with memory"), &scene);
        ratios.push((surface, memory / separate));
    }
    for (surface, r) in ratios {
        println!("16 m/s {surface:?}: white water with memory / separate foam and whitecaps: {r:.2}×");
    }
}
