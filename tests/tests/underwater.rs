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
    scene.sea.waves = Some(waves);
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

/// A wind so light that even the longest waves the fit would draw are under a millimetre is a
/// calm: no wind sea is drawn, and the view up from under it is the calm's, pixel for pixel
/// within the BRDF's roughness change. (At 10⁻⁷–10⁻⁹ m/s the fit once drew waves nanometres long,
/// numerically meaningless: the window dissolved into noise or a grey field.)
#[test]
fn a_wind_too_light_for_any_wave_is_a_calm() {
    // Cox & Munk's variance at 10⁻⁷ m/s differs from the calm's by 5×10⁻¹⁰ (of 0.003).
    const CALM_ROUGHNESS_REL: f64 = 1e-6;
    let calm = snells_window(0.0, 8);
    for wind in [1e-9, 1e-8, 1e-7] {
        let (centre, corner) = snells_window(wind, 8);
        assert!(centre > 10.0 * corner, "{wind} m/s: centre {centre} vs corners {corner}");
        assert!((centre - calm.0).abs() <= CALM_ROUGHNESS_REL * calm.0, "{wind} m/s: centre {centre}, calm {}", calm.0);
        assert!((corner - calm.1).abs() <= CALM_ROUGHNESS_REL * calm.1, "{wind} m/s: corner {corner}, calm {}", calm.1);
    }
}
