//! No NaN or infinite pixel over a sweep of random valid scenes (wind 0–40 m/s and exactly 0, sun
//! −20°–90° or a place at night under a full moon, camera height −5–500 m, 1–500 waves, every
//! spectrum, swell, water type, floor, clouds, the four surfaces), rendered at a tiny size.

use brine_render::scene::{CloudConfig, PlaceConfig, SpectrumKind, SurfaceKind, SwellConfig};
use brine_render::{RenderOptions, Scene, render};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    #[test]
    fn every_pixel_is_finite_and_non_negative(
        wind in prop_oneof![Just(0.0f64), 0.0f64..40.0],
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
        surface in prop::sample::select(vec![SurfaceKind::Trochoids, SurfaceKind::Fft, SurfaceKind::Gerstner, SurfaceKind::Sine]),
        clouds in prop::option::of(0.0f64..1.0),
        moonlit_place in prop::option::of((-60.0f64..60.0, -180.0f64..180.0)),
    ) {
        let mut scene = Scene::default_scene();
        scene.camera.position = [0.0, camera_y, 0.0];
        scene.camera.pitch_deg = Some(pitch);
        scene.camera.width = 8;
        scene.camera.height = 6;
        scene.sea.wind_speed_m_s = wind;
        scene.sea.waves = Some(waves);
        scene.sea.seed = seed;
        scene.sea.surface = surface;
        scene.sea.fft.resolution = 64;
        // Half the cases put the sun below the horizon (twilight and night, −20° to 0°); some are
        // at a place at the full moon of 2024-09-17/18, by night or day depending on the longitude.
        match moonlit_place {
            Some((latitude_deg, longitude_deg)) => {
                scene.place = Some(PlaceConfig {
                    latitude_deg,
                    longitude_deg,
                    time_utc: "2024-09-17T23:00:00Z".into(),
                    ..scene.place.clone().unwrap()
                });
            }
            None => {
                scene.place = None;
                scene.sky.sun_elevation_deg = Some(if sun_below { -sun_elevation / 4.5 } else { sun_elevation });
                scene.sky.sun_azimuth_deg = Some(sun_azimuth);
            }
        }
        scene.sky.clouds = clouds.map(|cover| CloudConfig { cover, ..CloudConfig::default() });
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
