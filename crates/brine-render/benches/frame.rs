//! `cargo xtask bench frame`: one 640×480 frame, 100 waves, every implemented phenomenon on,
//! 1 sample per pixel — the median of 5 renders and the tracer's counters (the paper's Table 3
//! yardstick: Darles et al. report about 3 minutes for 50 waves).

use std::time::Instant;

use brine_render::{RenderOptions, Scene, World, render_world};

fn main() {
    let mut scene = Scene::default_scene();
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.camera.spp = 1;
    scene.sea.waves = 100;
    let runs = 5;
    println!("frame benchmark: 640×480, 100 waves, 1 spp, {} threads, median of {runs}", rayon::current_num_threads());
    let mut build = Vec::new();
    let mut frame = Vec::new();
    let mut evals = 0.0;
    for _ in 0..runs {
        let t0 = Instant::now();
        let world = World::new(&scene).expect("bench scene is valid");
        let t1 = Instant::now();
        let f = render_world(&scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
        let t2 = Instant::now();
        build.push((t1 - t0).as_secs_f64());
        frame.push((t2 - t0).as_secs_f64());
        evals = f.stats.evaluations_per_ray();
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (b, f) = (median(&mut build), median(&mut frame));
    println!("{:<28} {:>10}", "stage", "median (s)");
    println!("{:<28} {:>10.4}", "scene setup (fit, sky)", b);
    println!("{:<28} {:>10.4}", "whole frame", f);
    println!("evaluations of F per primary ray: {evals:.1}");
}
