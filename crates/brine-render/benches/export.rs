//! `cargo xtask bench export`: the default sea handed to other tools — a 1024² bake frame, a
//! 1 M-vertex mesh and a million point queries, on the threads this machine has; medians of 5
//! (the world is built once, outside the timings, as `brine bake` builds it once per animation).
//! Side by side, the sea with its default 150 waves and with 50 (the count of the goals, set
//! when 50 was the default).

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
    let threads = rayon::current_num_threads();
    let counts = [None, Some(50)];
    let results: Vec<Times> = counts.iter().map(|&waves| measure(waves, &run)).collect();
    let label = |w: Option<u32>| {
        w.map_or(format!("default ({} waves)", brine_render::scene::DEFAULT_TROCHOID_WAVES), |n| format!("{n} waves"))
    };
    println!("export of the default sea ({threads} threads), medians of {RUNS}:");
    println!("| task | {} | {} | goal |", label(counts[0]), label(counts[1]));
    println!("|---|---|---|---|");
    let [a, b] = [&results[0], &results[1]];
    println!("| bake 1024² (6 maps, no file) | {:.2} s | {:.2} s | 1 s |", a.bake, b.bake);
    println!("| mesh 1000² vertices (no file) | {:.2} s | {:.2} s | 2 s |", a.mesh, b.mesh);
    println!(
        "| query 10⁶ points | {:.2} s ({:.2} M points/s) | {:.2} s ({:.2} M points/s) | 1 M points/s |",
        a.query,
        1.0 / a.query,
        b.query,
        1.0 / b.query
    );
    println!(
        "| query 10⁶ points, surface only (no white water) | {:.2} s ({:.2} M points/s) | {:.2} s ({:.2} M points/s) | — |",
        a.surface,
        1.0 / a.surface,
        b.surface,
        1.0 / b.surface
    );
}

/// Medians of the four tasks (s), NaN for a task not run.
struct Times {
    bake: f64,
    mesh: f64,
    query: f64,
    surface: f64,
}

/// The four tasks on the default scene with `waves` waves (the default's when `None`).
fn measure(waves: Option<u32>, run: &dyn Fn(&str) -> bool) -> Times {
    let mut scene = Scene::default_scene();
    scene.sea.waves = waves;
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
    Times { bake, mesh, query, surface }
}
