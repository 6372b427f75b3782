//! The mission's bad inputs that are valid scenes get a correct image: a flat calm (wind 0), 10 000
//! waves, the sun below the horizon, a camera under water; and a full moon at night shows a dark
//! sea with the moon's glitter path under it, not black or NaN.

// A flat calm has the exact normal (0, 1, 0) and exactly no foam: exact comparisons.
#![allow(clippy::float_cmp)]

use brine_render::scene::SurfaceKind;
use brine_render::{RenderOptions, Scene, render};

/// Renders `scene` at `w × h` and checks every pixel.
fn finite_frame(mut scene: Scene, w: u32, h: u32) -> brine_render::Frame {
    scene.camera.width = w;
    scene.camera.height = h;
    let frame = render(&scene, &RenderOptions::default(), &|| {}).expect("a valid scene renders");
    for (i, p) in frame.pixels.iter().enumerate() {
        assert!(p.is_finite() && p.min_element() >= 0.0, "pixel {i} = {p:?}");
    }
    frame
}

#[test]
fn a_flat_calm_is_a_mirror_of_the_sky() {
    let mut scene = Scene::default_scene();
    scene.sea.wind_speed_m_s = 0.0;
    scene.phenomena.glare = false;
    let h = scene.camera.position[1];
    let frame = finite_frame(scene, 32, 18);
    // No waves: every sea pixel hits the Earth's mean sea, whose normal is the vertical tilted
    // by the central angle, at most the horizon's `√(2h/R)` (plus the f32 of the output).
    let horizon = (2.0 * h / brine_core::EARTH_RADIUS_M).sqrt();
    let sea: Vec<_> = frame.aovs.iter().filter(|a| a.depth.is_finite()).collect();
    assert!(!sea.is_empty());
    for a in &sea {
        let tilt = f64::from(a.normal[0]).hypot(f64::from(a.normal[2])).atan2(f64::from(a.normal[1]));
        assert!(tilt <= horizon * 1.01 + 1e-6, "normal {:?}: tilt {tilt} rad", a.normal);
        assert!(a.foam == 0.0 && a.whitecap == 0.0);
    }
}

#[test]
fn ten_thousand_waves_render() {
    let mut scene = Scene::default_scene();
    scene.sea.waves = Some(10_000);
    let frame = finite_frame(scene, 6, 4);
    assert!(frame.aovs.iter().any(|a| a.depth.is_finite()), "the sea is in view");
}

#[test]
fn the_sun_below_the_horizon_and_a_camera_under_water_render() {
    for surface in [SurfaceKind::Trochoids, SurfaceKind::Fft, SurfaceKind::Gerstner, SurfaceKind::Sine] {
        let mut scene = Scene::default_scene();
        scene.sea.surface = surface;
        scene.sea.fft.resolution = 64;
        scene.place.as_mut().unwrap().time_utc = "2024-09-20T19:30:00Z".into(); // sun ≈ −8°
        finite_frame(scene.clone(), 16, 9);
        scene.camera.position = [0.0, -3.0, 0.0];
        finite_frame(scene, 16, 9);
    }
}

#[test]
fn a_full_moon_night_shows_the_glitter_path() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/gallery/full-moon.toml")).unwrap();
    let mut scene = Scene::from_toml_str(&text, "full-moon.toml").unwrap();
    scene.phenomena.glare = false;
    let (w, h) = (160u32, 90u32);
    let frame = finite_frame(scene, w, h);
    // Mean luminance of the middle fifth of the columns (under the moon: bearing ≈ 170°, view
    // 171°; the path is about a fifth of the view wide) over that of the outer 30 % on each side,
    // for the sea pixels and, as the reference without glitter, for the sky pixels (the reflected
    // sky alone would have about the sky's own contrast).
    let ratio = |sea: bool| {
        let (mut middle, mut outer) = ((0.0, 0), (0.0, 0));
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) as usize;
                // Sky rows below the moon's disc and aureole (it stands at the top tenth).
                if frame.aovs[i].depth.is_finite() != sea || (!sea && y < 3 * h / 10) {
                    continue;
                }
                let l = frame.pixels[i].y;
                if (2 * w / 5..3 * w / 5).contains(&x) {
                    middle = (middle.0 + l, middle.1 + 1);
                } else if !(3 * w / 10..7 * w / 10).contains(&x) {
                    outer = (outer.0 + l, outer.1 + 1);
                }
            }
        }
        (middle.0 / f64::from(middle.1), outer.0 / f64::from(outer.1))
    };
    let (sea_middle, sea_outer) = ratio(true);
    let (sky_middle, sky_outer) = ratio(false);
    assert!(sea_outer > 0.0, "the night sea is dark, not black");
    let (sea, sky) = (sea_middle / sea_outer, sky_middle / sky_outer);
    /// Without glitter the sea under the moon would only mirror the sky's own contrast (×1); the
    /// glitter path must add at least half as much again (measured at 160 × 90: sea 2.34, sky 1.43,
    /// i.e. ×1.64).
    const GLITTER_CONTRAST: f64 = 1.5;
    assert!(sea > GLITTER_CONTRAST * sky, "glitter path: sea contrast {sea} vs the sky's {sky}");
    /// Night: a full moon gives about 0.25 lx, so a sea of reflectance ≤ 0.1 has a luminance of at
    /// most 0.25 × 0.1/π ≈ 10⁻² cd m⁻² beside the path; 1 cd m⁻² (10⁻³ kcd m⁻²) is a hundred
    /// times that and a thousandth of a sunlit sea's (1–5 kcd m⁻²).
    const NIGHT_SEA_MAX: f64 = 1e-3;
    assert!(sea_outer < NIGHT_SEA_MAX, "the sea beside the path: {sea_outer} kcd/m²");
}
