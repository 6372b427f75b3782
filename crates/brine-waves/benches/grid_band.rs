//! `cargo xtask bench grid-band`: a study of the wave-count goal (docs/dev/wave-scaling.md,
//! option 3). How much of the intersection's growth with the number of waves goes away when the
//! shorter waves are gathered into one to three periodic grids, traced as FFT cascades are
//! (brine-waves `GriddedTrochoids`), certified against the snapped waves where no grid is
//! blended.
//!
//! The primary rays of the reference frame's view (640×480, a camera 10 m up looking 9° down, a
//! vertical field of 50°, the waves fading with the pixel), traced in 16 × 16 tiles with image
//! coherence on one thread, over a Pierson–Moskowitz sea at 10 m/s fitted with N = 50 and 400
//! trochoids: every wave traced (the renderer's trochoid sea), and the shorter waves gridded in
//! one to three nested bands ([`VARIANTS`]). Medians of interleaved rounds; ratios to the N = 50
//! sea traced whole.

use std::time::Instant;

use brine_trace::{Hit, LipschitzSum, Method, RayTile, TraceOptions, TraceStats};
use brine_waves::{
    CosineTwoS, FitOptions, GridBandSpec, GriddedTrochoids, PiersonMoskowitz, Spectrum, TracedTrochoids, fit_trochoids,
};
use glam::DVec3;

/// Image size and camera of the reference frame's view.
const WIDTH: usize = 640;
const HEIGHT: usize = 480;
const FOV_DEG: f64 = 50.0;
const PITCH_DEG: f64 = -9.0;
const EYE_M: f64 = 10.0;
/// Bearing of the view from the waves' mean direction (+x), toward +z.
const VIEW_FROM_WIND_DEG: f64 = 80.0;
/// Side of the tiles of rays sharing cones (the renderer's).
const TILE: usize = 16;
/// Wave counts measured.
const COUNTS: [usize; 2] = [50, 400];
/// The gridded variants: each band's `(cut, tile, n)` (m, m, points). The first band's spacing,
/// 6.25 cm, gives about ten points to the shortest wave fitted at N = 400 (0.6 m); the others
/// give their shortest wave at least 16.
/// The last variants read some bands through a blend of randomly offset tiles (the fourth
/// value), as the FFT sea does, so that the sea does not repeat, or give the finest band a tile
/// four times as large instead.
const VARIANTS: [&[(f64, f64, usize, bool)]; 7] = [
    &[(8.0, 32.0, 512, false)],
    &[(16.0, 64.0, 1024, false)],
    &[(8.0, 32.0, 512, false), (64.0, 512.0, 1024, false)],
    &[(8.0, 32.0, 512, false), (32.0, 256.0, 512, false), (128.0, 1024.0, 512, false)],
    &[(8.0, 32.0, 512, true), (32.0, 256.0, 512, false), (128.0, 1024.0, 512, false)],
    &[(8.0, 128.0, 2048, false), (32.0, 256.0, 512, false), (128.0, 1024.0, 512, false)],
    &[(8.0, 32.0, 512, true), (32.0, 256.0, 512, true), (128.0, 1024.0, 512, true)],
];
/// Interleaved rounds; the median is reported.
const ROUNDS: usize = 3;
/// The frame's time (s).
const TIME_S: f64 = 2.0;

/// The camera's ray directions, row by row, grouped tile by tile (each tile's rows contiguous).
fn tiles() -> Vec<(Vec<DVec3>, usize)> {
    let (yaw, pitch) = (VIEW_FROM_WIND_DEG.to_radians(), PITCH_DEG.to_radians());
    let forward = DVec3::new(yaw.cos() * pitch.cos(), pitch.sin(), yaw.sin() * pitch.cos());
    let right = forward.cross(DVec3::Y).normalize();
    let up = right.cross(forward);
    let h = (0.5 * FOV_DEG.to_radians()).tan();
    let aspect = WIDTH as f64 / HEIGHT as f64;
    let dir = |x: usize, y: usize| {
        let (u, v) = (
            (2.0 * (x as f64 + 0.5) / WIDTH as f64 - 1.0) * h * aspect,
            (1.0 - 2.0 * (y as f64 + 0.5) / HEIGHT as f64) * h,
        );
        (forward + u * right + v * up).normalize()
    };
    let mut out = Vec::new();
    for y0 in (0..HEIGHT).step_by(TILE) {
        for x0 in (0..WIDTH).step_by(TILE) {
            let (w, hgt) = (TILE.min(WIDTH - x0), TILE.min(HEIGHT - y0));
            let dirs = (y0..y0 + hgt).flat_map(|y| (x0..x0 + w).map(move |x| dir(x, y))).collect();
            out.push((dirs, w));
        }
    }
    out
}

/// Traces every tile; returns the wall time (s), the evaluations of `F` per ray, and the hits.
fn trace_all<S: LipschitzSum + ?Sized>(sea: &S, tiles: &[(Vec<DVec3>, usize)]) -> (f64, f64, Vec<Option<Hit>>) {
    let options = TraceOptions {
        method: Method::Tiered,
        t_max: 3000.0,
        max_steps: 20_000,
        min_step: 1e-3,
        min_step_relative: 1e-4,
        tolerance: 1e-3,
        tolerance_relative: 1e-5,
        footprint_angle: FOV_DEG.to_radians() / HEIGHT as f64,
        ..TraceOptions::default()
    };
    let origin = DVec3::new(0.0, EYE_M, 0.0);
    let mut stats = TraceStats::default();
    let mut all = Vec::with_capacity(WIDTH * HEIGHT);
    let t0 = Instant::now();
    for (dirs, w) in tiles {
        let mut hits = vec![None; dirs.len()];
        brine_trace::trace_tile(
            sea,
            &RayTile { origin, directions: dirs, width: *w },
            &options,
            &mut stats,
            &mut hits,
            None,
        );
        all.extend(hits);
    }
    let elapsed = t0.elapsed().as_secs_f64();
    (elapsed, stats.evaluations as f64 / (WIDTH * HEIGHT) as f64, all)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let pm = PiersonMoskowitz::from_u10(10.0).expect("valid wind");
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).expect("valid spreading");
    let tiles = tiles();
    println!(
        "grid-band study: the primary rays of the reference view ({WIDTH}×{HEIGHT}, one thread, {TILE}² tiles), \
         Pierson–Moskowitz at 10 m/s, median of {ROUNDS} interleaved rounds"
    );
    // (label, N, setup time, sea, distance bound to the snapped sea (m))
    enum Sea {
        Whole(TracedTrochoids),
        Gridded(GriddedTrochoids),
    }
    let mut seas: Vec<(String, usize, f64, Sea, Option<f64>)> = Vec::new();
    for n in COUNTS {
        let set = fit_trochoids(&pm, &spreading, n, 7, &FitOptions::default()).expect("fit");
        let t0 = Instant::now();
        let whole = TracedTrochoids::new(&set, TIME_S);
        seas.push(("every wave traced".into(), n, t0.elapsed().as_secs_f64(), Sea::Whole(whole), None));
        for bands in VARIANTS {
            let t0 = Instant::now();
            let specs: Vec<_> = bands
                .iter()
                .map(|&(shorter_than_m, tile_m, n, blended)| GridBandSpec { shorter_than_m, tile_m, n, blended })
                .collect();
            let sea = GriddedTrochoids::new(&set, TIME_S, &specs).expect("gridded sea");
            let (long, short) = sea.counts();
            let grids: Vec<String> = bands
                .iter()
                .map(|(cut, tile, n, blended)| {
                    format!("< {cut} m: {n}² over {tile} m{}", if *blended { ", blended" } else { "" })
                })
                .collect();
            let label = format!("{long} traced, {short} gridded ({})", grids.join("; "));
            let error = (!bands.iter().any(|b| b.3)).then(|| sea.error_bound());
            seas.push((label, n, t0.elapsed().as_secs_f64(), Sea::Gridded(sea), error));
        }
    }
    let mut times = vec![Vec::new(); seas.len()];
    let mut evaluations = vec![0.0; seas.len()];
    let mut hit_counts = vec![0usize; seas.len()];
    for _ in 0..ROUNDS {
        for (i, (_, _, _, sea, _)) in seas.iter().enumerate() {
            let (t, e, hits) = match sea {
                Sea::Whole(s) => trace_all(s, &tiles),
                Sea::Gridded(s) => trace_all(s, &tiles),
            };
            times[i].push(t);
            evaluations[i] = e;
            hit_counts[i] = hits.iter().filter(|h| h.is_some()).count();
        }
    }
    let medians: Vec<f64> = times.into_iter().map(median).collect();
    println!(
        "\n| N | sea | setup | primary rays (median) | ÷ N = 50 whole | evaluations per ray | rays that hit | bound to the snapped sea |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for (i, (label, n, setup, _, error)) in seas.iter().enumerate() {
        let error = error.map_or("—".to_owned(), |e| format!("{:.3} mm", 1e3 * e));
        println!(
            "| {n} | {label} | {:.3} s | {:.3} s | {:.2} | {:.2} | {} | {error} |",
            setup,
            medians[i],
            medians[i] / medians[0],
            evaluations[i],
            hit_counts[i]
        );
    }
}
