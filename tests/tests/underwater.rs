//! A camera under water sees the underside of the surface: Snell's window.

use brine_render::{RenderOptions, Scene, render};

#[test]
fn looking_up_from_under_water_shows_snells_window() {
    let mut scene = Scene::default_scene();
    scene.camera.position = [0.0, -6.0, 0.0];
    scene.camera.yaw_deg = Some(0.0);
    scene.camera.pitch_deg = Some(90.0);
    scene.camera.fov_deg = 150.0;
    scene.camera.width = 41;
    scene.camera.height = 41;
    scene.sea.wind_speed_m_s = 2.0;
    scene.sea.waves = 8;
    scene.phenomena.glare = false;
    let frame = render(&scene, &RenderOptions::default(), &|| {}).unwrap();
    let lum = |x: usize, y: usize| frame.pixels[y * 41 + x].y;
    assert!(frame.pixels.iter().all(|p| p.is_finite() && p.min_element() >= 0.0));
    // The centre looks at the sky through the surface (inside the 48.6° critical cone); the
    // corners, 75° off the zenith, see total internal reflection of the dark water.
    let centre = lum(20, 20);
    let corner = lum(0, 0).max(lum(40, 0)).max(lum(0, 40)).max(lum(40, 40));
    assert!(centre > 10.0 * corner, "centre {centre} vs corners {corner}");
}
