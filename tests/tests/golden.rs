//! Golden images: small renders of reference scenes compared with stored PNGs.
//!
//! Metric: on 8-bit sRGB channels, the mean absolute difference must not exceed
//! [`MAX_MEAN_ABS_DIFF`] and at most [`MAX_OUTLIER_FRACTION`] of the channel values may differ by
//! more than [`OUTLIER_THRESHOLD`]. Small differences come from floating-point `sin`/`cos` of other
//! platforms moving a glint or a wave edge by a pixel; a real change of the models moves many
//! pixels by more. On failure `NAME.actual.png` and `NAME.diff.png` (|difference| × 8) are written
//! beside the golden image. `cargo xtask golden --bless` (env `BRINE_BLESS=1`) rewrites them.

use std::path::PathBuf;

use brine_render::{RenderOptions, Scene, render, tonemap};

/// Largest mean |difference| over all channels (8-bit levels).
const MAX_MEAN_ABS_DIFF: f64 = 0.5;
/// A channel differing by more than this many 8-bit levels is an outlier.
const OUTLIER_THRESHOLD: u8 = 8;
/// Largest share of outlier channels.
const MAX_OUTLIER_FRACTION: f64 = 0.005;

fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("golden")
}

/// Renders `scene` and returns its 8-bit sRGB bytes.
fn render_rgb8(scene: &Scene) -> Vec<u8> {
    let frame = render(scene, &RenderOptions::default(), &|| {}).expect("scene renders");
    let scale = tonemap::exposure_scale(frame.exposure_ev);
    frame.pixels.iter().flat_map(|p| tonemap::to_srgb8(*p, scale)).collect()
}

fn check_golden(name: &str, scene: &Scene) {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let actual = render_rgb8(scene);
    let path = golden_dir().join(format!("{name}.png"));
    if std::env::var_os("BRINE_BLESS").is_some() {
        image::save_buffer(&path, &actual, w, h, image::ColorType::Rgb8).unwrap();
        eprintln!("blessed {}", path.display());
        return;
    }
    let expected = image::open(&path)
        .unwrap_or_else(|e| panic!("cannot open {}: {e} (run `cargo xtask golden --bless`)", path.display()))
        .to_rgb8();
    assert_eq!(expected.dimensions(), (w, h), "golden image size");
    let expected = expected.into_raw();
    let diffs: Vec<u8> = actual.iter().zip(&expected).map(|(a, b)| a.abs_diff(*b)).collect();
    let mean = diffs.iter().map(|&d| f64::from(d)).sum::<f64>() / diffs.len() as f64;
    let outliers = diffs.iter().filter(|&&d| d > OUTLIER_THRESHOLD).count() as f64 / diffs.len() as f64;
    if mean > MAX_MEAN_ABS_DIFF || outliers > MAX_OUTLIER_FRACTION {
        let dir = golden_dir();
        image::save_buffer(dir.join(format!("{name}.actual.png")), &actual, w, h, image::ColorType::Rgb8).unwrap();
        let amplified: Vec<u8> = diffs.iter().map(|d| d.saturating_mul(8)).collect();
        image::save_buffer(dir.join(format!("{name}.diff.png")), &amplified, w, h, image::ColorType::Rgb8).unwrap();
        panic!(
            "{name}: mean |diff| {mean:.3} (max {MAX_MEAN_ABS_DIFF}), outliers {:.3}% (max {:.3}%); \
             wrote {name}.actual.png and {name}.diff.png in {}",
            outliers * 100.0,
            MAX_OUTLIER_FRACTION * 100.0,
            dir.display()
        );
    }
}

/// A gallery scene (`docs/gallery/NAME.toml`) at 160 × 90.
fn gallery_scene(name: &str) -> Scene {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/gallery").join(format!("{name}.toml"));
    let mut scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    scene.camera.width = 160;
    scene.camera.height = 90;
    scene
}

#[test]
fn calm_dawn_160x90() {
    check_golden("calm-dawn-160x90", &gallery_scene("calm-dawn"));
}

#[test]
fn windy_noon_160x90() {
    check_golden("windy-noon-160x90", &gallery_scene("windy-noon"));
}

#[test]
fn coastal_floor_160x90() {
    check_golden("coastal-floor-160x90", &gallery_scene("coastal-floor"));
}

#[test]
fn full_moon_160x90() {
    check_golden("full-moon-160x90", &gallery_scene("full-moon"));
}

#[test]
fn default_scene_160x90() {
    let mut scene = Scene::default_scene();
    scene.camera.width = 160;
    scene.camera.height = 90;
    check_golden("default-160x90", &scene);
}

/// The FFT ocean (`surface = "fft"`): Li Ying et al.'s morning still.
#[test]
fn li_ying_morning_fft_160x90() {
    check_golden("li-ying-morning-160x90", &gallery_scene("li-ying-morning"));
}
