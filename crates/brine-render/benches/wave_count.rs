//! `cargo xtask bench wave-count`: how the whole frame grows with the number of waves.
//!
//! The reference frame's scene (640×480, 1 sample per pixel, every phenomenon on, two threads)
//! with N = 50, 100, 200 and 400 fitted trochoids: the median of 3 whole frames each (world and
//! pixels), rendered in interleaved rounds so the machine's slow phases fall on every N alike,
//! then one profiled frame per N for the stages. Printed: each N's time and its ratio to N = 50,
//! and where the extra time goes.

#[path = "common/mod.rs"]
mod common;

use std::time::Instant;

use brine_render::{RenderOptions, World, render_world};

/// Wave counts measured.
const COUNTS: [u32; 4] = [50, 100, 200, 400];
/// Interleaved rounds; the median is reported.
const ROUNDS: usize = 3;

fn main() {
    let scenes: Vec<_> = COUNTS
        .iter()
        .map(|&n| {
            let mut s = common::reference_frame_scene();
            s.sea.waves = n;
            s
        })
        .collect();
    println!(
        "wave-count benchmark: the reference frame (640×480, every phenomenon, 1 spp, {} threads) at N = {COUNTS:?}, median of {ROUNDS} interleaved rounds",
        rayon::current_num_threads()
    );
    let mut times = vec![Vec::new(); COUNTS.len()];
    let mut evaluations = vec![0.0; COUNTS.len()];
    for _ in 0..ROUNDS {
        for (i, scene) in scenes.iter().enumerate() {
            let t0 = Instant::now();
            let world = World::new(scene).expect("bench scene is valid");
            let frame = render_world(scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
            times[i].push(t0.elapsed().as_secs_f64());
            evaluations[i] = frame.stats.evaluations_per_ray();
        }
    }
    let medians: Vec<f64> = times.into_iter().map(brine_testkit::timing::median).collect();
    println!("\n| N | whole frame (median) | t(N)/t(50) | evaluations of F per primary ray |");
    println!("|---|---|---|---|");
    for (i, &n) in COUNTS.iter().enumerate() {
        println!("| {n} | {:.3} s | {:.2} | {:.2} |", medians[i], medians[i] / medians[0], evaluations[i]);
    }
    println!("\nthread time per stage (one profiled frame each, s):");
    let mut header = String::from("| stage |");
    for n in COUNTS {
        header.push_str(&format!(" N = {n} |"));
    }
    println!("{header}");
    println!("|---|{}", "---|".repeat(COUNTS.len()));
    let mut rows: Vec<(String, Vec<f64>)> = Vec::new();
    for scene in &scenes {
        let t0 = Instant::now();
        let world = World::new(scene).expect("bench scene is valid");
        let setup = t0.elapsed().as_secs_f64();
        let frame = render_world(scene, &world, &RenderOptions { profile: true, ..RenderOptions::default() }, &|| {})
            .expect("renders");
        let named = frame.stages.expect("profiled").named();
        let mut values: Vec<(String, f64)> = vec![("scene setup (wall)".into(), setup)];
        values.extend(named.iter().map(|(name, t)| ((*name).to_owned(), *t)));
        if rows.is_empty() {
            rows = values.iter().map(|(name, _)| (name.clone(), Vec::new())).collect();
        }
        for (row, (_, v)) in rows.iter_mut().zip(&values) {
            row.1.push(*v);
        }
    }
    for (name, values) in rows {
        let cells: String = values.iter().map(|v| format!(" {v:.3} |")).collect();
        println!("| {name} |{cells}");
    }
    println!(
        "\nt(400)/t(50) = {:.2} (goal ≤ 2.5); t(200)/t(100) = {:.2}",
        medians[3] / medians[0],
        medians[2] / medians[1]
    );
}
