//! A camera under water sees the underside of the surface: Snell's window.

use brine_render::{RenderOptions, Scene, render};

/// Snell's window over a camera 6 m under the sea of `wind_speed_m_s` and `waves`: the luminance at the
/// centre of a view straight up and the brightest corner (75° off the zenith).
fn snells_window(wind_speed_m_s: f64, waves: u32) -> (f64, f64) {
    let mut scene = Scene::default_scene();
    scene.camera.position = [0.0, -6.0, 0.0];
    scene.camera.yaw_deg = Some(0.0);
    scene.camera.pitch_deg = Some(90.0);
    scene.camera.fov_deg = 150.0;
    scene.camera.width = 41;
    scene.camera.height = 41;
    scene.sea.wind_speed_m_s = wind_speed_m_s;
    scene.sea.waves = waves;
    scene.phenomena.glare = false;
    let frame = render(&scene, &RenderOptions::default(), &|| {}).unwrap();
    let lum = |x: usize, y: usize| frame.pixels[y * 41 + x].y;
    assert!(frame.pixels.iter().all(|p| p.is_finite() && p.min_element() >= 0.0));
    (lum(20, 20), lum(0, 0).max(lum(40, 0)).max(lum(0, 40)).max(lum(40, 40)))
}

#[test]
fn looking_up_from_under_water_shows_snells_window() {
    // The centre looks at the sky through the surface (inside the 48.6° critical cone); the
    // corners, 75° off the zenith, see total internal reflection of the dark water.
    let (centre, corner) = snells_window(2.0, 8);
    assert!(centre > 10.0 * corner, "centre {centre} vs corners {corner}");
}

/// A flat calm (no wind: no waves) is a plane the camera's rays meet from below as from above:
/// the same window, where it once saw only the water's colour.
#[test]
fn a_flat_calm_shows_snells_window_from_below() {
    let (centre, corner) = snells_window(0.0, 8);
    assert!(centre > 10.0 * corner, "centre {centre} vs corners {corner}");
}
