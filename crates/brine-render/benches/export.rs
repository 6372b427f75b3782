//! `cargo xtask bench export`: the default sea (with 50 waves, the count of the figures in
//! docs/benchmarks.md; the default is 150) handed to other tools — a 1024² bake frame, a
//! 1 M-vertex mesh and a million point queries, on the threads this machine has; medians of 5
//! (the world is built once, outside the timings, as `brine bake` builds it once per animation).

use brine_render::export::{BakeOptions, MeshGrid, QueryPoint, UpAxis, bake_frame, grid_mesh, query_points};
use brine_render::{Scene, World};
use brine_testkit::timing::median_seconds;
use glam::DVec2;

/// Runs of each task, of which the median is reported: this 2-core machine's single timings
/// spread by about ±10 %.
const RUNS: usize = 5;

fn main() {
    // `cargo bench --bench export -- bake` (or mesh, query) runs one task, for profiling.
    let only: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    let run = |task: &str| only.is_empty() || only.iter().any(|o| o == task);
    let mut scene = Scene::default_scene();
    scene.sea.waves = Some(50);
    let threads = rayon::current_num_threads();
    let lattice = brine_waves::TileLattice::new(200.0, None).expect("a valid tile");
    let tiled = World::on_lattice(&scene, Some(&lattice)).expect("the default scene builds");
    let world = World::new(&scene).expect("the default scene builds");
    let options = BakeOptions { size: 1024, tile_m: 200.0, up: UpAxis::Y };
    let bake = if run("bake") {
        median_seconds(RUNS, || {
            std::hint::black_box(bake_frame(&tiled, 0.5, &options));
        })
    } else {
        f64::NAN
    };
    let grid = MeshGrid { center: DVec2::ZERO, size_m: 499.5, spacing_m: 0.5 };
    let mesh = if run("mesh") {
        median_seconds(RUNS, || {
            std::hint::black_box(grid_mesh(&world, scene.sea.time_s, &grid));
        })
    } else {
        f64::NAN
    };
    let n = 1_000_000;
    let points: Vec<QueryPoint> = (0..n)
        .map(|i| {
            let (a, b) = ((i as f64 * 0.618_034).fract(), (i as f64 * 0.754_878).fract());
            QueryPoint { x: 1000.0 * a - 500.0, z: 1000.0 * b - 500.0, t: scene.sea.time_s }
        })
        .collect();
    let (query, surface) = if run("query") {
        let query = median_seconds(RUNS, || {
            std::hint::black_box(query_points(&scene, &world, &points).expect("queries"));
        });
        // The surface alone (no white water): what the geometry costs.
        let surface = median_seconds(RUNS, || {
            use rayon::prelude::*;
            let v: Vec<f64> =
                points.par_iter().with_min_len(256).map(|p| world.sea().sample(p.x, p.z).height).collect();
            std::hint::black_box(v);
        });
        (query, surface)
    } else {
        (f64::NAN, f64::NAN)
    };
    println!("export of the default sea ({threads} threads), medians of {RUNS}:");
    println!("| task | time | goal | ratio to goal |");
    println!("|---|---|---|---|");
    println!("| bake 1024² (6 maps, no file) | {bake:.2} s | 1 s | {:.2} |", bake / 1.0);
    println!("| mesh 1000² vertices (no file) | {mesh:.2} s | 2 s | {:.2} |", mesh / 2.0);
    println!("| query 10⁶ points | {query:.2} s ({:.2} M points/s) | 1 M points/s | {:.2} |", 1.0 / query, query);
    println!(
        "| query 10⁶ points, surface only (no white water) | {surface:.2} s ({:.2} M points/s) | — | — |",
        1.0 / surface
    );
}
