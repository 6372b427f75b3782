//! `cargo xtask bench animation`: the per-frame time of a 24-frame animation against a still of
//! the same scene, the reference frame (640×480, 100 waves, every phenomenon, 1 spp) on both
//! surfaces, measured side by side in one process.
//!
//! A still builds its whole world ([`World::new`]) and renders it. An animation builds what does
//! not change with time once ([`Timeless::new`]: the fit, the FFT sea's amplitudes, the detail
//! band's spectrum, the white water's calibration) and per frame only what does
//! ([`World::at_instant`]: the sea at the frame's instant, the sky for the sun of that instant,
//! the white water's state), as `brine render --frames` does. Every frame is checked to be the
//! same image as its still.

#[path = "common/mod.rs"]
mod common;

use std::time::Instant;

use brine_render::cli::render::scene_at_frame;
use brine_render::scene::SurfaceKind;
use brine_render::{RenderOptions, Scene, Timeless, World, render_world};

/// Frames of the animation.
const FRAMES: u32 = 24;
/// Animations (and stills) per surface; the medians are reported.
const RUNS: usize = 3;

/// One still of `scene`: its world built and rendered (s), and the image.
fn still(scene: &Scene) -> (f64, Vec<glam::DVec3>) {
    let t0 = Instant::now();
    let world = World::new(scene).expect("bench scene is valid");
    let frame = render_world(scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
    (t0.elapsed().as_secs_f64(), frame.pixels)
}

/// One animation of `FRAMES` frames: the per-frame time (s), the per-frame setup (s), and the
/// image of frame `check`.
fn animation(scene: &Scene, check: u32) -> (f64, f64, Vec<glam::DVec3>) {
    let t0 = Instant::now();
    let mut setup = 0.0;
    let mut kept = Vec::new();
    let timeless = Timeless::new(scene, None).expect("bench scene is valid");
    for f in 0..FRAMES {
        let s = scene_at_frame(scene, f, (0, FRAMES), None).expect("frame scene");
        let t = Instant::now();
        let world = World::at_instant(&s, &timeless).expect("same scene");
        setup += t.elapsed().as_secs_f64();
        let frame = render_world(&s, &world, &RenderOptions::default(), &|| {}).expect("renders");
        if f == check {
            kept = frame.pixels;
        }
    }
    (t0.elapsed().as_secs_f64() / f64::from(FRAMES), setup / f64::from(FRAMES), kept)
}

fn main() {
    let mut scene = common::reference_frame_scene();
    println!(
        "animation benchmark: 640×480, every phenomenon on, 1 spp, {} threads, {FRAMES} frames at {} fps, median of {RUNS}",
        rayon::current_num_threads(),
        scene.animation.fps
    );
    for surface in [SurfaceKind::Trochoids, SurfaceKind::Fft] {
        scene.sea.surface = surface;
        let (mut stills, mut frames, mut setups) = (Vec::new(), Vec::new(), Vec::new());
        for run in 0..RUNS {
            // The still of one frame of the animation, then the animation, interleaved.
            let check = (run as u32 * 7 + 5) % FRAMES;
            let s = scene_at_frame(&scene, check, (0, FRAMES), None).expect("frame scene");
            let (t_still, image) = still(&s);
            let (t_frame, t_setup, frame) = animation(&scene, check);
            assert!(image == frame, "frame {check} of the animation differs from its still");
            stills.push(t_still);
            frames.push(t_frame);
            setups.push(t_setup);
        }
        let (st, fr, se) = (
            brine_testkit::timing::median(stills),
            brine_testkit::timing::median(frames),
            brine_testkit::timing::median(setups),
        );
        println!("\n{surface:?}");
        println!("  still (whole world built and rendered)      {st:>7.3} s");
        println!("  animation, per frame                        {fr:>7.3} s  (of which per-frame setup {se:.3} s)");
        println!("  per-frame / still                           {:>7.2}×  (goal ≤ 0.70×)", fr / st);
    }
}
