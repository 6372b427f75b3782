//! Property tests of brine-sky: bounds, symmetry and normalisation over the documented domain.

use brine_sky::{CloudLayers, CloudParams, MoonParams, PreethamSky, Scattering, Sky, SkyParams};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

use brine_testkit::directions::from_elevation_azimuth_deg as dir;

/// Mirror of `v` across the vertical plane containing the sun direction `s`.
fn mirror(v: DVec3, s: DVec3) -> DVec3 {
    let n = DVec3::new(-s.z, 0.0, s.x).normalize();
    v - n * (2.0 * v.dot(n))
}

/// The zenith value is `Y_z F(0, θ_s)/F(0, θ_s)`: exact up to the rounding of the division.
const NORMALISATION_ROUNDING: f64 = 1e-12;
/// Mirror directions differ by the rounding of the reflection: relative 10⁻⁹ (with a 10⁻¹²
/// kcd m⁻² floor for dark views); below the horizon the twilight table's bilinear reads add
/// rounding: 10⁻⁶.
const MIRROR_ROUNDING: f64 = 1e-9;
const MIRROR_FLOOR: f64 = 1e-12;
const TWILIGHT_MIRROR_ROUNDING: f64 = 1e-6;
/// Elevation (degrees) below which the whole sun disc (angular radius ≤ 0.2711°) has set.
const SUN_SET_DEG: f64 = 0.3;
/// "Darker as the sun sinks", up to the rounding of the twilight table.
const DARKENING_ROUNDING: f64 = 1e-9;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn preetham_radiance_is_finite_and_non_negative(
        t in 2.0f64..=10.0, sun_e in 0.0f64..=90.0, sun_a in 0.0f64..360.0,
        view_e in -10.0f64..=90.0, view_a in 0.0f64..360.0,
    ) {
        let sky = PreethamSky::new(t, dir(sun_e, sun_a)).unwrap();
        let l = sky.radiance_rgb(dir(view_e, view_a));
        prop_assert!(l.is_finite() && l.min_element() >= 0.0, "{l:?}");
        let xyz = sky.xyz(dir(view_e, view_a));
        prop_assert!(xyz.is_finite() && xyz.y >= 0.0);
    }

    #[test]
    fn perez_is_normalised_at_the_zenith(t in 1.7f64..=10.0, sun_e in 0.0f64..=90.0) {
        // Y(zenith) = Y_z F(0, θ_s)/F(0, θ_s) = Y_z, likewise x and y.
        let sky = PreethamSky::new(t, dir(sun_e, 30.0)).unwrap();
        // θ_s as the sky took it from its normalised sun direction: `(90° − e)` in radians differs
        // from it by up to 10⁻⁹ relative near the zenith (acos is ill-conditioned at 1), enough
        // to move Y_z by 10⁻¹².
        let theta_s = sky.theta_s();
        let (y, x, yy) = sky.yxy(DVec3::Y);
        let (xz, yz) = brine_sky::zenith_chromaticity_xy(t, theta_s);
        prop_assert!((y / brine_sky::zenith_luminance(t, theta_s) - 1.0).abs() < NORMALISATION_ROUNDING);
        prop_assert!((x - xz).abs() < NORMALISATION_ROUNDING && (yy - yz).abs() < NORMALISATION_ROUNDING);
    }

    #[test]
    fn symmetric_about_the_solar_meridian(
        t in 2.0f64..=10.0, sun_e in 0.0f64..=90.0, sun_a in 0.0f64..360.0,
        view_e in 0.0f64..=90.0, view_a in 0.0f64..360.0,
    ) {
        let s = dir(sun_e.min(89.9), sun_a);
        let sky = PreethamSky::new(t, s).unwrap();
        let v = dir(view_e, view_a);
        let (a, b) = (sky.radiance_rgb(v), sky.radiance_rgb(mirror(v, s)));
        prop_assert!(((a - b).abs()).max_element() <= MIRROR_ROUNDING * a.max_element().max(MIRROR_FLOOR), "{a:?} {b:?}");
    }

    #[test]
    fn aerial_perspective_bounds(
        t in 1.7f64..=10.0, h in 0.0f64..5000.0, view_e in -90.0f64..=90.0, view_a in 0.0f64..360.0,
        s in 0.0f64..2e5, sun_e in -90.0f64..=90.0,
    ) {
        let sc = Scattering::new(t).unwrap();
        let d = dir(view_e, view_a);
        // Segments stay above the sea (y ≥ 0), as in a scene.
        let s = if d.y < 0.0 { s.min(h / -d.y) } else { s };
        let lights = [(dir(sun_e, 120.0), DVec3::new(90.0, 95.0, 100.0))];
        let ap = sc.aerial_perspective(h, d, s, &lights, DVec3::splat(2.0));
        prop_assert!(ap.extinction.min_element() > 0.0 && ap.extinction.max_element() <= 1.0, "{:?}", ap.extinction);
        prop_assert!(ap.inscatter.is_finite() && ap.inscatter.min_element() >= 0.0);
        // Longer segments transmit less: the first half transmits at least as much as the whole.
        let half = sc.aerial_perspective(h, d, s * 0.5, &lights, DVec3::splat(2.0));
        prop_assert!((ap.extinction - half.extinction).max_element() <= 0.0);
    }
}

proptest! {
    // Each case below the horizon tabulates the twilight ratio (about 50 ms unoptimised).
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn sky_is_finite_for_every_sun_elevation(
        t in 1.7f64..=10.0, sun_e in -90.0f64..=90.0, sun_a in 0.0f64..360.0,
        moon_e in -90.0f64..=90.0, phase in 0.0f64..=std::f64::consts::PI, cover in 0.0f64..=1.0,
        time in 0.0f64..1e4,
    ) {
        let moon = MoonParams { direction: dir(moon_e, 77.0), phase_angle: phase, distance_km: 384_400.0 };
        let clouds = CloudParams { cover, wind_m_s: DVec2::new(5.0, -3.0), ..CloudParams::default() };
        let params = SkyParams { moon: Some(moon), clouds: Some(clouds), time_s: time, ..SkyParams::new(t, dir(sun_e, sun_a)) };
        let sky = Sky::new(&params).unwrap();
        for (e, a) in [(90.0, 0.0), (30.0, sun_a), (1.0, sun_a + 180.0), (-20.0, 10.0), (45.0, 77.0), (moon_e, 77.0)] {
            let v = dir(e, a);
            let l = sky.background_rgb(v);
            prop_assert!(l.is_finite() && l.min_element() >= 0.0, "{e} {a}: {l:?}");
            let ap = sky.aerial_perspective(2.0, v, 3000.0);
            prop_assert!(ap.inscatter.is_finite() && ap.inscatter.min_element() >= 0.0);
            prop_assert!(ap.extinction.min_element() > 0.0 && ap.extinction.max_element() <= 1.0);
        }
        let (sun, moon) = (sky.sun(), sky.moon().unwrap());
        for d in [sun, moon] {
            prop_assert!(d.irradiance_rgb.is_finite() && d.irradiance_rgb.min_element() >= 0.0);
            prop_assert!((0.0..=1.0).contains(&d.visible_fraction));
        }
        // The sun's disc (radius 0.27°) has wholly set below −0.27°.
        if sun_e < -SUN_SET_DEG {
            prop_assert!(sun.irradiance_rgb == DVec3::ZERO, "a set sun gives no light");
        }
        prop_assert!(sky.horizontal_irradiance_rgb().min_element() > 0.0);
    }

    #[test]
    fn twilight_is_symmetric_and_darkens(sun_e in -17.0f64..-0.5, sun_a in 0.0f64..360.0, view_e in 0.0f64..=90.0, view_a in 0.0f64..360.0) {
        let s = dir(sun_e, sun_a);
        let sky = Sky::new(&SkyParams::new(3.0, s)).unwrap();
        let v = dir(view_e, view_a);
        let (a, b) = (sky.radiance_rgb(v), sky.radiance_rgb(mirror(v, s)));
        prop_assert!(((a - b).abs()).max_element() <= TWILIGHT_MIRROR_ROUNDING * a.max_element(), "{a:?} {b:?}");
        let deeper = Sky::new(&SkyParams::new(3.0, dir(sun_e - 1.0, sun_a))).unwrap();
        prop_assert!(deeper.radiance_rgb(v).y <= a.y * (1.0 + DARKENING_ROUNDING), "darker as the sun sinks");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn cloud_opacity_is_in_the_unit_interval(
        cover in 0.0f64..=1.0, altitude in 100.0f64..=20_000.0, scale in 10.0f64..=1e6,
        wind_e in -100.0f64..=100.0, wind_s in -100.0f64..=100.0, seed in any::<u64>(),
        view_e in -90.0f64..=90.0, view_a in 0.0f64..360.0, time in -1e6f64..1e6,
    ) {
        let params = CloudParams { cover, altitude_m: altitude, scale_m: scale, wind_m_s: DVec2::new(wind_e, wind_s), seed, ..CloudParams::default() };
        let c = CloudLayers::new(&params).unwrap();
        let a = c.opacity(dir(view_e, view_a), time);
        prop_assert!((0.0..=1.0).contains(&a), "α = {a}");
        if view_e <= 0.0 || cover == 0.0 {
            prop_assert!(a <= 0.0, "no cloud below the horizon or without cover: {a}");
        }
    }
}
