//! `cargo xtask bench wave-count`: how the whole frame grows with the number of waves.
//!
//! The reference frame's scene (640×480, 1 sample per pixel, every phenomenon on, two threads)
//! with N = 50, 100, 200 and 400 fitted trochoids as the scene's default `sea.grid = "auto"`
//! draws them (the shorter waves on grids from 150 waves up), and each N the other way too
//! (`"on"` below 150, `"off"` from 150): the median of 3 whole frames each (world and pixels),
//! rendered in interleaved rounds so the machine's slow phases fall on every variant alike, then
//! one profiled frame per variant for the stages. Printed: each variant's time and its ratio to
//! N = 50, and where the extra time goes.

#[path = "common/mod.rs"]
mod common;

use std::time::Instant;

use brine_render::scene::{GRID_AUTO_WAVES, GridMode};
use brine_render::{RenderOptions, World, render_world};

/// Wave counts measured.
const COUNTS: [u32; 4] = [50, 100, 200, 400];

/// The variants: each count as `"auto"` draws it, then the other way.
fn variants() -> Vec<(u32, GridMode)> {
    let other = |n: u32| if n >= GRID_AUTO_WAVES { GridMode::Off } else { GridMode::On };
    COUNTS.iter().map(|&n| (n, GridMode::Auto)).chain(COUNTS.iter().map(|&n| (n, other(n)))).collect()
}

/// How a variant's waves are traced.
fn label(n: u32, grid: GridMode) -> &'static str {
    match grid {
        GridMode::Auto if n >= GRID_AUTO_WAVES => "auto (on grids)",
        GridMode::Auto => "auto (every wave)",
        GridMode::On => "on grids",
        GridMode::Off => "every wave",
    }
}
/// Interleaved rounds; the median is reported.
const ROUNDS: usize = 3;

fn main() {
    let variants = variants();
    let scenes: Vec<_> = variants
        .iter()
        .map(|&(n, grid)| {
            let mut s = common::reference_frame_scene();
            s.sea.waves = Some(n);
            s.sea.grid = grid;
            s
        })
        .collect();
    println!(
        "wave-count benchmark: the reference frame (640×480, every phenomenon, 1 spp, {} threads) at N = {COUNTS:?}, median of {ROUNDS} interleaved rounds",
        rayon::current_num_threads()
    );
    let mut times = vec![Vec::new(); variants.len()];
    let mut evaluations = vec![0.0; variants.len()];
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
    println!("\n| N | waves traced | whole frame (median) | t(N)/t(50) | evaluations of F per primary ray |");
    println!("|---|---|---|---|---|");
    for (i, &(n, grid)) in variants.iter().enumerate() {
        println!(
            "| {n} | {} | {:.3} s | {:.2} | {:.2} |",
            label(n, grid),
            medians[i],
            medians[i] / medians[0],
            evaluations[i]
        );
    }
    println!("\nthread time per stage (one profiled frame each, s):");
    let mut header = String::from("| stage |");
    for &(n, grid) in &variants {
        header.push_str(&format!(" N = {n}, {} |", label(n, grid)));
    }
    println!("{header}");
    println!("|---|{}", "---|".repeat(variants.len()));
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
    let at = |n: u32, grid: GridMode| medians[variants.iter().position(|v| *v == (n, grid)).expect("measured")];
    println!(
        "\nt(400)/t(50) = {:.2} (goal ≤ 2.5; {:.2} with every wave traced); t(200)/t(100) = {:.2}",
        at(400, GridMode::Auto) / at(50, GridMode::Auto),
        at(400, GridMode::Off) / at(50, GridMode::Auto),
        at(200, GridMode::Auto) / at(100, GridMode::Auto)
    );
}
