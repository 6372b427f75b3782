//! The default trochoid sea shows no lattice of glints: on a top-down view its slopes are not
//! held by a handful of crossing waves.
//!
//! The measure (brine-testkit `lattice::peak_share`, as under each image of docs/beaufort.md): on
//! a top-down view of the sea (50 m up, 256² shading normals over about 58 m), the share of the
//! slope power in the 20 strongest wave vectors of the slopes' 2-D spectrum. At 8 m/s, where the
//! longest waves are short enough not to tilt the whole view, a sea of few crossing waves puts
//! most of its slopes there. The bound is 0.35; the default (150 waves) measures 0.25–0.31 over
//! seeds 1–5, 50 waves 0.37–0.42.

use brine_render::{RenderOptions, Scene, render};
use brine_testkit::lattice::{PeakShare, peak_share};

/// The bound on the share of the slope power in the 20 strongest wave vectors.
const MAX_PEAK_SHARE: f64 = 0.35;

/// Side of the top-down view (pixels).
const SIDE: u32 = 256;

/// The top-down view of the trochoid sea at 8 m/s, seed `seed`, with `waves` waves (the
/// default's when `None`), as `cargo xtask gallery` renders it for docs/beaufort.md.
fn top_down(seed: u64, waves: Option<u32>) -> f64 {
    let waves = waves.map_or(String::new(), |n| format!("waves = {n}\n"));
    let text = format!(
        "[camera]\nposition = [0.0, 50.0, 0.0]\npitch_deg = -90.0\nyaw_deg = 0.0\nwidth = {SIDE}\nheight = {SIDE}\nfov_deg = 60.0\n\n\
         [sea]\nsurface = \"trochoids\"\nwind_speed_m_s = 8.0\nwind_direction_deg = 20.0\nseed = {seed}\n{waves}\n\
         [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 90.0\n\n[sky.clouds]\ncover = 0.35\n"
    );
    let scene = Scene::from_toml_str(&text, "top-down view").expect("valid scene");
    let frame = render(&scene, &RenderOptions::default(), &|| {}).expect("renders");
    let normals: Vec<[f32; 3]> = frame.aovs.iter().map(|a| a.normal).collect();
    peak_share(&normals, SIDE as usize, &PeakShare { peaks: 20, resolved_cycles: None })
}

#[test]
fn the_default_trochoid_sea_shows_no_lattice() {
    for seed in [1, 3] {
        let share = top_down(seed, None);
        assert!(share <= MAX_PEAK_SHARE, "seed {seed}: 20 wave vectors hold {share:.3} of the slope power");
    }
}

#[test]
fn fifty_waves_show_a_lattice() {
    // The measure tells: the sea of 50 waves (the default before) puts more than the bound there.
    let share = top_down(3, Some(50));
    assert!(share > MAX_PEAK_SHARE, "50 waves: 20 wave vectors hold only {share:.3} of the slope power");
}
