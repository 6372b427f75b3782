//! `cargo bench -p brine-texture --bench texture` (or `cargo xtask bench texture`): preprocessing
//! time and per-frame time at 384×384 of the photo-based ocean, on the shipped example photos,
//! side by side with one thread and with all threads; ratios to Lai & Wu's 0.187 s and 0.281 s
//! per 384×384 frame (Intel Core 2, 1.8 GHz).

use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use brine_sky::{Sky, SkyParams};
use brine_texture::{
    OceanParams, PhotoOcean, Pinhole, ProjectionOptions, ProjectionView, Texture, TracedParams, TracedScene,
    render_projection, render_traced,
};
use glam::DVec3;

use brine_testkit::timing::median_seconds as median;

/// Lai & Wu §IV: 0.187 s (Fig. 6) and 0.281 s (Fig. 8) per 384×384 frame.
const PAPER_S: [f64; 2] = [0.187, 0.281];

fn row(what: &str, one: f64, all: f64) {
    let ratio = |t: f64| format!("{:.0}× / {:.0}×", PAPER_S[0] / t, PAPER_S[1] / t);
    println!("| {what} | {:.2} ms | {:.2} ms | {} |", one * 1e3, all * 1e3, ratio(all));
}

fn main() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let small = Texture::load(&dir.join("small-waves.png"), "small").expect("example photo");
    let main = Texture::load(&dir.join("main-structure.png"), "main").expect("example photo");
    let bed = Texture::from_fn(256, 256, |i, j| {
        let v = 90.0 + 60.0 * (((i / 16 + j / 16) % 2) as f32);
        [v, 0.9 * v, 0.7 * v]
    });
    let params = OceanParams::default();
    let threads = rayon::current_num_threads();
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("pool");
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("brine-texture bench: {threads} threads; load average before: {}", load.trim());
    println!();
    let build = || PhotoOcean::new(&small, &main, None, &params, 1, &|_| {}).expect("ocean");
    let pre_one = one.install(|| median(3, || drop(black_box(build()))));
    let pre_all = median(3, || drop(black_box(build())));
    println!(
        "preprocessing (256² main texture, {} basis frames of 256², links, morph meshes, heights): {:.2} s on 1 thread, {:.2} s on {threads}",
        params.frames, pre_one, pre_all
    );
    println!();
    let ocean = build();
    let ocean_bed = PhotoOcean::new(&small, &main, Some(&bed), &params, 1, &|_| {}).expect("ocean");
    let camera = Pinhole::from_angles(DVec3::new(0.0, 8.0, 0.0), 225.0, -20.0, 60.0, 384, 384).expect("camera");
    let sun = DVec3::new(-0.28, 0.57, 0.77).normalize();
    let sky = Sky::new(&SkyParams::new(3.0, sun)).expect("sky");
    let view = ProjectionView::new(&camera, &sky);
    let options = ProjectionOptions::default();
    let plain = ProjectionOptions { mipmaps: false, ..options };
    // Frames 1..=N mix basis frames (every 8th) and morph in-betweens.
    let n = 48u64;
    let per_frame = |f: &dyn Fn(u64)| -> f64 {
        let mut t: Vec<f64> = (1..=n)
            .map(|k| {
                let s = Instant::now();
                f(k);
                s.elapsed().as_secs_f64()
            })
            .collect();
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    };
    let both = |f: &(dyn Fn(u64) + Sync)| (one.install(|| per_frame(f)), per_frame(f));
    println!(
        "| per frame at 384×384 (median of {n} frames) | 1 thread | {threads} threads | vs paper (0.187 / 0.281 s) |"
    );
    println!("|---|---|---|---|");
    let (a, b) = both(&|k| drop(black_box(ocean.frame(k))));
    row("frame state: walk, morph in-between, mip levels", a, b);
    let f0 = ocean.frame(3);
    let (a, b) = both(&|_| drop(black_box(render_projection(&f0, &view, &options))));
    row("projection, mip-mapped (render only)", a, b);
    let (a, b) = both(&|_| drop(black_box(render_projection(&f0, &view, &plain))));
    row("projection, bilinear as the paper (render only)", a, b);
    let (a, b) = both(&|k| drop(black_box(render_projection(&ocean.frame(k), &view, &options))));
    row("**projection, whole frame** (state + render)", a, b);
    let (a, b) = both(&|k| drop(black_box(render_projection(&ocean_bed.frame(k), &view, &options))));
    row("projection with bed refraction, whole frame", a, b);
    let (a, b) = both(&|_| drop(black_box(ProjectionView::new(&camera, &sky))));
    row("projection view (per camera: plane hits, sky)", a, b);
    let scene =
        TracedScene::new(&TracedParams { sun_direction: sun, ..TracedParams::default() }, &ocean_bed).expect("scene");
    let f = ocean_bed.frame(3);
    let traced_one = one.install(|| median(3, || drop(black_box(render_traced(&f, &camera, &scene).expect("traced")))));
    let traced_all = median(3, || drop(black_box(render_traced(&f, &camera, &scene).expect("traced"))));
    row("traced with bed (median of 3)", traced_one, traced_all);
    let img = render_traced(&f, &camera, &scene).expect("traced");
    println!();
    println!("traced: {:.1} evaluations per ray", img.stats.evaluations as f64 / img.stats.rays as f64);
}
