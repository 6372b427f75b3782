//! No NaN or infinite pixel over a sweep of random valid scenes (wind 0–40 m/s, sun −20°–90°,
//! camera height −5–500 m, 1–500 waves, every spectrum, swell, water type, floor, trochoid and FFT
//! surfaces), rendered at a tiny size.

use brine_render::scene::{SpectrumKind, SurfaceKind, SwellConfig};
use brine_render::{RenderOptions, Scene, render};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn every_pixel_is_finite_and_non_negative(
        wind in 0.0f64..40.0,
        sun_elevation in 0.0f64..90.0,
        sun_azimuth in 0.0f64..360.0,
        camera_y in -5.0f64..500.0,
        pitch in -89.0f64..89.0,
        waves in 1u32..500,
        seed in 0u64..1000,
        water in prop::sample::select(vec!["I", "IB", "III", "5C", "clear", "very-turbid"]),
        floor in prop::option::of(1.0f64..50.0),
        spectrum in prop::sample::select(vec![
            SpectrumKind::PiersonMoskowitz, SpectrumKind::Jonswap, SpectrumKind::Phillips,
            SpectrumKind::Tma, SpectrumKind::Elfouhaily,
        ]),
        swell in prop::option::of((0.2f64..6.0, 5.0f64..25.0)),
        sun_below in prop::bool::ANY,
        fft in prop::bool::ANY,
    ) {
        let mut scene = Scene::default_scene();
        scene.camera.position = [0.0, camera_y, 0.0];
        scene.camera.pitch_deg = Some(pitch);
        scene.camera.width = 8;
        scene.camera.height = 6;
        scene.sea.wind_speed_m_s = wind;
        scene.sea.waves = waves;
        scene.sea.seed = seed;
        if fft {
            scene.sea.surface = SurfaceKind::Fft;
            scene.sea.fft.resolution = 64;
        }
        // Half the cases put the sun below the horizon (twilight and night, −20° to 0°).
        scene.place = None;
        scene.sky.sun_elevation_deg = Some(if sun_below { -sun_elevation / 4.5 } else { sun_elevation });
        scene.sky.sun_azimuth_deg = Some(sun_azimuth);
        scene.sea.spectrum = spectrum;
        scene.sea.depth_m = Some(30.0);
        scene.sea.swell = swell.map(|(h, t)| SwellConfig { significant_height_m: h, peak_period_s: t, ..Default::default() });
        scene.water.water_type = Some(water.to_owned());
        scene.water.floor = floor.map(|depth_m| brine_render::scene::FloorConfig { depth_m, ..Default::default() });
        let frame = render(&scene, &RenderOptions::default(), &|| {}).unwrap();
        for (i, p) in frame.pixels.iter().enumerate() {
            prop_assert!(p.is_finite() && p.min_element() >= 0.0, "pixel {i} = {p:?}");
        }
    }
}
