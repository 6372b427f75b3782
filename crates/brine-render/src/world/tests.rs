use super::*;
use crate::scene::SurfaceKind;

/// The band ends where the spectrum's slope integral reaches the target (bisection to 10⁻¹⁸ in
/// ln k); the grid's cells cut the band's ring corners and hold 1–5 % less than that integral
/// (brine-waves' detail tests), which the BRDF keeps.
const SCALES_SUM_REL: f64 = 0.06;

/// Geometry, detail normals and BRDF share Cox & Munk's total: at 8, 12 and 16 m/s the traced
/// waves' slope variance, the detail band's and the BRDF's unresolved one add up to it, and the
/// detail band is not empty (the trochoid band stops far short of the total).
#[test]
fn the_three_scales_add_up_to_cox_and_munk() {
    for wind in [8.0, 12.0, 16.0] {
        let mut scene = Scene::default_scene();
        scene.sea.wind_speed_m_s = wind;
        let world = World::new(&scene).expect("a valid scene");
        let (along, across) = world.set.slope_variances(scene.sea.wind_direction_deg.to_radians());
        let detail = world.detail.as_ref().expect("a detail band").expected_slope_covariance();
        let total = world.variance_total.sigma_x2() + world.variance_total.sigma_y2();
        let unresolved = world.variance_unresolved.sigma_x2() + world.variance_unresolved.sigma_y2();
        assert!(detail.x + detail.z > 0.1 * total, "{wind} m/s: detail {} of {total}", detail.x + detail.z);
        approx::assert_relative_eq!(
            along + across + detail.x + detail.z + unresolved,
            total,
            max_relative = SCALES_SUM_REL
        );
    }
}

/// The FFT sea has no detail band (its cascades reach the centimetre waves) but is read
/// through the footprint; a calm has neither.
#[test]
fn detail_normals_belong_to_the_fitted_seas() {
    let mut scene = Scene::default_scene();
    scene.sea.surface = SurfaceKind::Fft;
    let world = World::new(&scene).expect("a valid scene");
    assert!(world.detail.is_none() && world.fft_slopes.is_some());
    scene.sea.surface = SurfaceKind::Trochoids;
    scene.sea.wind_speed_m_s = 0.0;
    let world = World::new(&scene).expect("a valid scene");
    assert!(world.detail.is_none() && world.fft_slopes.is_none());
}

/// `[sea.fft] blend` chooses between the tile and blend (the default) and the periodic tiles;
/// the FFT sea's footprint-filtered slopes follow the same choice, so they differ.
#[test]
fn the_fft_blend_key_chooses_the_blend_or_the_periodic_tiles() {
    let mut scene = Scene::default_scene();
    scene.sea.surface = SurfaceKind::Fft;
    let blended = World::new(&scene).expect("a valid scene");
    scene.sea.fft.blend = false;
    let periodic = World::new(&scene).expect("a valid scene");
    let cascades = |w: &World| match w.ocean() {
        Ocean::Fft { ocean } => (0..ocean.cascade_count()).map(|c| ocean.tile_blend(c).is_some()).collect::<Vec<_>>(),
        _ => panic!("an FFT sea"),
    };
    assert!(cascades(&blended).iter().all(|&b| b), "every cascade blended by default");
    assert!(cascades(&periodic).iter().all(|&b| !b), "no cascade blended with blend = false");
    let (a, b) = (blended.fft_slopes.as_ref().expect("slopes"), periodic.fft_slopes.as_ref().expect("slopes"));
    assert_ne!(a.filtered(3.7, -12.1, 0.0).gradient, b.filtered(3.7, -12.1, 0.0).gradient);
}

/// At light wind the drawn sea holds no more slope than Cox & Munk measured: the fitted band
/// and the FFT cascades stop where the spectrum reaches their total (at 2 m/s the trochoid
/// band `[0.5, 12] ω_p` held 1.4× of it). The fitted set's waves are the band's discrete
/// amplitudes and directions, not its integral.
#[test]
fn light_wind_seas_draw_no_more_slope_than_cox_and_munk() {
    const DISCRETE_REL: f64 = 0.05;
    for surface in [SurfaceKind::Trochoids, SurfaceKind::Fft] {
        for wind in [2.0, 3.0] {
            let mut scene = Scene::default_scene();
            scene.sea.wind_speed_m_s = wind;
            scene.sea.surface = surface;
            let world = World::new(&scene).expect("a valid scene");
            let drawn = match world.sea.surface() {
                FrameSurface::Fft(frame) => {
                    let c: DVec3 = frame.cascades().iter().map(|c| c.expected_slope_covariance()).sum();
                    c.x + c.z
                }
                _ => {
                    let (a, b) = world.set.slope_variances(0.0);
                    a + b
                }
            };
            let total = world.variance_total.sigma_x2() + world.variance_total.sigma_y2();
            assert!(drawn <= total * (1.0 + DISCRETE_REL), "{surface:?} at {wind} m/s: drawn {drawn}, total {total}");
            assert!(drawn > 0.5 * total, "{surface:?} at {wind} m/s: drawn {drawn}, total {total}");
        }
    }
}

/// Two temperatures at the ±30 °C envelope written in decimals differ by their rounding
/// (12.7 − 42.7 = −30.000000000000004): the scene accepts them and so does the world.
#[test]
fn a_temperature_difference_at_the_envelope_builds_a_world() {
    let scene = Scene::from_toml_str("[water]\ntemperature_c = 12.7\nair_temperature_c = 42.7\n", "envelope.toml")
        .expect("a scene at the envelope");
    let world = World::new(&scene);
    assert!(world.is_ok(), "{:?}", world.err());
}

/// The sampling error of the mean white cover on 40 000 grid points whose white water comes in
/// patches of a few metres (a few thousand independent patches) plus the calibration's
/// (16 384–32 768 points): ≈ 5 % of `W` at 5 %; 15 % is three of them.
const WHITE_WATER_REL_TOL: f64 = 0.15;

/// Both surfaces' white water, as the renderer builds it, has Monahan's mean over the sea.
#[test]
fn white_water_on_both_surfaces_has_monahans_mean() {
    for surface in ["trochoids", "fft"] {
        let text = format!("[sea]\nsurface = \"{surface}\"\nwind_speed_m_s = 16.0\nseed = 4\n");
        let world = World::new(&Scene::from_toml_str(&text, "ww.toml").unwrap()).unwrap();
        let Some(ww) = &world.white_water else { panic!("{surface}: no white water at 16 m/s") };
        let side = match ww {
            WhiteWaterSea::Fft(m) => m.source().now().largest_tile(),
            WhiteWaterSea::Trochoids(_) => 2000.0,
        };
        let target = match ww {
            WhiteWaterSea::Fft(m) => m.target(),
            WhiteWaterSea::Trochoids(m) => m.target(),
        };
        // Monahan & Ó Muircheartaigh 1980 at 16 m/s.
        assert!((target - 3.84e-6 * 16f64.powf(3.41)).abs() < 1e-9);
        let n = 200;
        let mut sum = 0.0;
        for a in 0..n {
            for b in 0..n {
                let u = DVec2::new((f64::from(a) + 0.5) / f64::from(n), (f64::from(b) + 0.5) / f64::from(n)) * side;
                sum += ww.at(u, world.time, 0.0).white;
            }
        }
        let mean = sum / f64::from(n * n);
        assert!((mean / target - 1.0).abs() < WHITE_WATER_REL_TOL, "{surface}: mean {mean}, W {target}");
    }
}

/// One sample's footprint is the pixel's at one sample per pixel and shrinks as `1/√spp` down to
/// an eighth (pbrt-v4's rule, whose values these are: 1, 1/2, 1/4, 1/8 and the floor); the
/// world's filtering angle follows it, and the reference keeps none.
#[test]
fn samples_share_the_pixel_footprint() {
    for (spp, scale) in [(1, 1.0), (4, 0.5), (16, 0.25), (64, 0.125), (1024, 0.125)] {
        assert_eq!(sample_footprint_scale(spp).to_bits(), f64::to_bits(scale), "{spp} spp");
        let mut scene = Scene::default_scene();
        scene.camera.spp = spp;
        let mut world = World::new(&scene).expect("a valid scene");
        approx::assert_relative_eq!(world.filtering_angle(), world.camera.pixel_angle() * scale, max_relative = 1e-15);
        world.set_reference(true);
        assert!(world.filtering_angle() <= 0.0);
        approx::assert_relative_eq!(world.sample_angle(), world.camera.pixel_angle() * scale, max_relative = 1e-15);
    }
}

/// An animation builds the instant-free parts of its world once: a frame rendered from them,
/// after other frames in any order, is its still to the bit, on both surfaces with the white
/// water's memory (whose FFT history is kept from frame to frame), and with the trochoid sea's
/// shorter waves on grids (filled per frame).
#[test]
fn frames_built_on_shared_parts_are_their_stills() {
    for (surface, grid) in [
        (SurfaceKind::Trochoids, GridMode::Off),
        (SurfaceKind::Trochoids, GridMode::On),
        (SurfaceKind::Fft, GridMode::Auto),
    ] {
        let mut scene = Scene::default_scene();
        (scene.camera.width, scene.camera.height) = (40, 24);
        scene.sea.wind_speed_m_s = 14.0;
        scene.sea.surface = surface;
        scene.sea.grid = grid;
        let at = |f: u32| crate::cli::render::scene_at_frame(&scene, f, (0, 48), None).expect("a frame");
        let timeless = Timeless::new(&at(0), None).expect("a valid scene");
        for f in [0, 13, 12, 47] {
            let s = at(f);
            let shared = World::at_instant(&s, &timeless).expect("the same scene");
            let pixels =
                |w: &World| crate::render_world(&s, w, &crate::RenderOptions::default(), &|| {}).unwrap().pixels;
            assert!(pixels(&shared) == pixels(&World::new(&s).unwrap()), "{surface:?}, grid {grid:?}, frame {f}");
        }
    }
}

/// `sea.grid`: from 150 waves (`"auto"`) or always (`"on"`) the trochoid sea's shorter waves are
/// snapped and traced on grids, and the snapped set is the sea the world shades and exports;
/// `"off"`, fewer waves or another surface keep every wave; a set that cannot be split is refused
/// under `"on"` with a message naming the key, and kept whole under `"auto"`; a calm is drawn
/// without grids whatever the key.
#[test]
fn the_grid_key_puts_the_shorter_waves_on_grids() {
    let world = |waves: u32, grid: GridMode, surface: SurfaceKind| {
        let mut scene = Scene::default_scene();
        (scene.sea.waves, scene.sea.grid, scene.sea.surface) = (Some(waves), grid, surface);
        World::new(&scene)
    };
    let auto = world(200, GridMode::Auto, SurfaceKind::Trochoids).unwrap();
    let grid = auto.gridded.as_ref().expect("on grids from 150 waves");
    assert!(grid.snapped().waves() == auto.set.waves(), "the world's set is the snapped one");
    assert!(matches!(auto.traced_sea(), brine_waves::TracedSea::Gridded { .. }));
    assert!(world(100, GridMode::Auto, SurfaceKind::Trochoids).unwrap().gridded.is_none());
    assert!(world(200, GridMode::Off, SurfaceKind::Trochoids).unwrap().gridded.is_none());
    assert!(world(200, GridMode::On, SurfaceKind::Gerstner).unwrap().gridded.is_none());
    assert!(world(50, GridMode::On, SurfaceKind::Trochoids).unwrap().gridded.is_some());
    let e = world(1, GridMode::On, SurfaceKind::Trochoids).err().expect("one wave cannot be split");
    assert!(e.to_string().contains("sea.grid"), "{e}");
    assert!(world(1, GridMode::Auto, SurfaceKind::Trochoids).unwrap().gridded.is_none());
    // A calm has no wave to split: `on` draws it all the same.
    let mut calm = Scene::default_scene();
    (calm.sea.wind_speed_m_s, calm.sea.grid) = (0.0, GridMode::On);
    assert!(World::new(&calm).expect("a calm renders").gridded.is_none());
}

/// Parts built for another scene (other than by its instants) are refused with a message.
#[test]
fn shared_parts_of_another_scene_are_refused() {
    let scene = Scene::default_scene();
    let timeless = Timeless::new(&scene, None).expect("a valid scene");
    let mut other = scene.clone();
    other.sea.time_s += 3.0;
    assert!(World::at_instant(&other, &timeless).is_ok());
    other.sea.wind_speed_m_s += 1.0;
    let e = World::at_instant(&other, &timeless).err().expect("refused");
    assert!(e.to_string().contains("another scene"), "{e}");
}

/// A sea the spectrum's model refuses is reported with the scene keys that made it. A scene in
/// the documented ranges reaches no refusal (the next test), so the message is built from a model
/// error directly.
#[test]
fn a_refused_spectrum_names_the_scene_keys() {
    let mut scene = Scene::default_scene();
    scene.sea.spectrum = SpectrumKind::Tma;
    scene.sea.wind_speed_m_s = 0.05;
    scene.sea.fetch_km = Some(3.0);
    scene.sea.depth_m = Some(4.0);
    let model = brine_waves::Jonswap::new(0.01, f64::NAN).expect_err("a NaN peak is refused");
    let message = super::sea::refused_spectrum(&scene.sea, &model).to_string();
    for part in
        ["sea.spectrum = \"tma\"", "sea.wind_speed_m_s = 0.05", "sea.fetch_km = 3", "sea.depth_m = 4", "omega_p_rad_s"]
    {
        assert!(message.contains(part), "{part}: {message}");
    }
}

/// Every spectrum and surface builds a sea at the lightest winds of the scene's range, down to
/// 10⁻³⁰⁰ m/s. Pierson–Moskowitz, JONSWAP and TMA (whose fully developed peak is PM's,
/// `0.855 g/U₁₀`) are a calm, with no wave fitted, where even half the peak frequency is a wave
/// under the shortest drawn, 1 mm (in deep water `k = ω²/g` at `ω_p/2` = 419 rad/s for 0.01 m/s:
/// 0.35 mm), and draw ripples from 0.03 m/s (`ω_p/2` = 140 rad/s: a 3 mm wave).
#[test]
fn the_lightest_winds_build_a_sea_with_every_spectrum() {
    let spectra = [
        SpectrumKind::PiersonMoskowitz,
        SpectrumKind::Jonswap,
        SpectrumKind::Tma,
        SpectrumKind::Phillips,
        SpectrumKind::Elfouhaily,
    ];
    for surface in [SurfaceKind::Trochoids, SurfaceKind::Gerstner, SurfaceKind::Sine, SurfaceKind::Fft] {
        for spectrum in spectra {
            for wind in [1e-300, 1e-4, 0.01, 0.03, 0.05, 0.08] {
                let mut scene = Scene::default_scene();
                scene.sea.spectrum = spectrum;
                scene.sea.surface = surface;
                scene.sea.wind_speed_m_s = wind;
                scene.sea.depth_m = Some(20.0);
                scene.sea.fft.resolution = 64;
                scene.camera.width = 8;
                scene.camera.height = 6;
                (scene.phenomena.whitecaps, scene.phenomena.foam) = (false, false);
                let world = match World::new(&scene) {
                    Ok(w) => w,
                    Err(e) => panic!("{surface:?}, {spectrum:?} at {wind} m/s: {e}"),
                };
                let pm_like =
                    matches!(spectrum, SpectrumKind::PiersonMoskowitz | SpectrumKind::Jonswap | SpectrumKind::Tma);
                if pm_like && surface != SurfaceKind::Fft {
                    let calm = world.fitted_set().is_empty();
                    assert_eq!(calm, wind <= 0.01, "{surface:?}, {spectrum:?} at {wind} m/s: calm = {calm}");
                }
            }
        }
    }
}

/// The spray of a gale: bubble drops and spume, both extinguishing at the sea, the spume thinning
/// upward, and its light table built from the scene's sky.
#[test]
fn a_gale_has_spume_over_it() {
    let mut scene = Scene::default_scene();
    scene.sea.wind_speed_m_s = 20.0;
    let world = World::new(&scene).expect("a valid scene");
    let spray = world.spray.as_ref().expect("spray at 20 m/s");
    assert!(spray.spume.extinction(0.0) > spray.spume.extinction(10.0) && spray.spume.extinction(10.0) > 0.0);
    assert!(spray.medium.extinction(0.0, 1.0) > 0.0);
    let v = world.spray_visibility_m(0.0).expect("spray");
    // The Beaufort scale's force 8–9 (17.2–24.4 m/s): spray "may affect visibility" — reduced,
    // not fog. A range of 1–10 km at the sea is that description; a settling balance for the
    // spume (a few hundred metres) or no spray at all (unlimited) would fall outside it.
    assert!((1000.0..10_000.0).contains(&v), "{v} m");
    // The horizon's light: brighter looking along the horizon than straight down at the sea.
    let along = spray.light.lookup([1.0, 0.0, 0.0]);
    let down = spray.light.lookup([0.0, -1.0, 0.0]);
    assert!(along[1] > down[1], "{along:?} {down:?}");
}

/// The clouds are fixed over the sea and seen from the camera: a camera kilometres off the origin
/// sees straight up the cloud whose shadow a zenith sun casts at its foot, wherever it stands, and
/// a world moved by `set_camera` keeps the clouds seen from where it was built.
#[test]
fn the_clouds_over_an_off_origin_camera_are_those_that_shade_it() {
    // Rounding of the view's distance fade, divided out.
    const ROUNDING: f64 = 1e-12;
    let mut scene = Scene::default_scene();
    scene.sky.clouds = Some(crate::scene::CloudConfig { cover: 0.5, ..crate::scene::CloudConfig::default() });
    let (mut cloudy, mut clear) = (0, 0);
    for i in 0..12 {
        let (x, z) = (6000.0 + 1733.0 * f64::from(i), -2500.0 + 911.0 * f64::from(i));
        scene.camera.position = [x, 10.0, z];
        let world = World::new(&scene).expect("a valid scene");
        assert_eq!(world.cloud_origin(), Some(DVec2::new(x, z)));
        let clouds = world.sky.clouds().expect("clouds");
        let fade = (-clouds.distance(DVec3::Y) / 80_000.0).exp();
        let seen = clouds.opacity(DVec3::Y, world.sky.time_s());
        let shade = 1.0 - world.sky.cloud_transmittance(DVec3::new(x, 0.0, z), DVec3::Y);
        assert!((shade * fade - seen).abs() < ROUNDING, "camera at ({x}, {z}): seen {seen}, shade {shade}");
        cloudy += usize::from(shade > 0.5);
        clear += usize::from(shade < 0.5);
    }
    // Half the sky is covered: the cameras stand both under clouds and under clear sky.
    assert!(cloudy > 0 && clear > 0, "{cloudy} under clouds, {clear} under clear sky");
    let mut moved = World::new(&scene).expect("a valid scene");
    let built_at = moved.cloud_origin();
    scene.camera.position = [0.0, 10.0, 0.0];
    moved.set_camera(&scene.camera);
    assert_eq!(moved.cloud_origin(), built_at, "set_camera keeps the clouds seen from where the world was built");
}
