//! `cargo xtask bench frame`: one 640×480 frame of the default scene with 100 waves and every
//! phenomenon on (foam, whitecaps, spray, sub-surface crests, aerial perspective, clouds, glare),
//! 1 sample per pixel: the median of 5 renders, then one profiled render for the share of each
//! stage (the paper's Table 3; Darles et al. report about 3 minutes for a frame of 50 waves).

use std::time::Instant;

use brine_render::scene::CloudConfig;
use brine_render::{RenderOptions, Scene, World, render_world};

fn main() {
    let mut scene = Scene::default_scene();
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.camera.spp = 1;
    scene.sea.waves = 100;
    scene.sky.clouds = Some(CloudConfig::default());
    let runs = 5;
    println!(
        "frame benchmark: 640×480, 100 waves, every phenomenon on, 1 spp, {} threads, median of {runs}",
        rayon::current_num_threads()
    );
    let (mut setup, mut total) = (Vec::new(), Vec::new());
    let mut last = None;
    for _ in 0..runs {
        let t0 = Instant::now();
        let world = World::new(&scene).expect("bench scene is valid");
        let t1 = Instant::now();
        let frame = render_world(&scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
        let t2 = Instant::now();
        setup.push((t1 - t0).as_secs_f64());
        total.push((t2 - t0).as_secs_f64());
        last = Some(frame);
    }
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (s, f) = (median(&mut setup), median(&mut total));
    let frame = last.expect("ran");
    println!("whole frame (median)          {f:>8.3} s   (target ≤ 0.5 s)");
    println!("  scene setup (fit, sky, calibration)  {s:>8.3} s");
    println!(
        "evaluations of F per primary ray: {:.2}; secondary rays: {} ({:.2} evaluations each)",
        frame.stats.evaluations_per_ray(),
        frame.secondary_stats.rays,
        frame.secondary_stats.evaluations_per_ray()
    );
    let world = World::new(&scene).expect("bench scene is valid");
    let profiled = render_world(&scene, &world, &RenderOptions { profile: true, ..RenderOptions::default() }, &|| {})
        .expect("renders");
    let stages = profiled.stages.expect("profiled");
    let named = stages.named();
    let sum: f64 = named.iter().map(|(_, t)| t).sum();
    println!("\nshare of each stage (one profiled frame, thread time):");
    for (name, t) in named {
        println!("  {name:<36} {:>6.1} %  ({:.3} s)", 100.0 * t / sum, t);
    }
}
