//! The filtered frame keeps the light of the reference rendering, band by band: the proof that
//! moving the waves from geometry to shading normals to the BRDF, as the pixel footprint grows,
//! adds and loses no light (brine-render `energy_bands`).

use brine_render::{Scene, World, energy_bands};

/// Samples per pixel of the reference rendering.
const REFERENCE_SPP: u32 = 16;
/// The goal: each sea band within 5 % of the reference.
const BAND: f64 = 0.05;
/// The view of `docs/beaufort.md`'s energy table: 10 m up, 9° down, the sun behind the camera (no
/// glitter to sample), white water, spray and glare off, 256 × 144.
fn scene(surface: &str, wind: f64, sea: &str) -> Scene {
    let text = format!(
        "[camera]\nposition = [0.0, 10.0, 0.0]\nyaw_deg = 100.0\npitch_deg = -9.0\nwidth = 256\nheight = 144\n\n\
         [sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = 20.0\n{sea}\n\
         [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 280.0\n\n\
         [phenomena]\nfoam = false\nwhitecaps = false\nspray = false\nglare = false\n"
    );
    Scene::from_toml_str(&text, "energy.toml").expect("a valid scene")
}

fn check(surface: &str, wind: f64) {
    check_sea(surface, wind, "");
}

/// As [`check`], with more `[sea]` keys.
fn check_sea(surface: &str, wind: f64, sea: &str) {
    let bands = energy_bands(&scene(surface, wind, sea), REFERENCE_SPP).expect("renders");
    // The first three tenths are sky, the same in both renderings.
    for (b, ratio) in bands.iter().enumerate().take(3) {
        assert!((ratio - 1.0).abs() < 1e-3, "{surface} {wind} m/s, sky band {}: {ratio}", b + 1);
    }
    for (b, ratio) in bands.iter().enumerate().skip(3) {
        assert!((ratio - 1.0).abs() < BAND, "{surface} {wind} m/s, band {}: {:+.1} %", b + 1, 100.0 * (ratio - 1.0));
    }
}

#[test]
fn the_trochoid_sea_keeps_its_light_band_by_band() {
    for wind in [3.0, 10.0, 18.0] {
        check("trochoids", wind);
    }
}

#[test]
fn the_fft_sea_keeps_its_light_band_by_band() {
    for wind in [3.0, 10.0, 18.0] {
        check("fft", wind);
    }
}

/// 200 waves, the shorter ones on grids (`sea.grid = "auto"`): the bands fade whole in the traced
/// surface while the shading fades the snapped waves one by one, and the light is kept all the
/// same (measured −4.0 … +3.3 % over the sea's bands at 3, 10 and 18 m/s).
#[test]
fn the_gridded_trochoid_sea_keeps_its_light_band_by_band() {
    for wind in [3.0, 10.0, 18.0] {
        let world = World::new(&scene("trochoids", wind, "waves = 200\n")).expect("a valid scene");
        assert!(matches!(world.traced_sea(), brine_waves::TracedSea::Gridded { .. }), "{wind} m/s: not on grids");
        check_sea("trochoids", wind, "waves = 200\n");
    }
}
