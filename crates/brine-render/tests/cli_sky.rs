//! `brine sun`, `brine moon` and `brine sky` from the command line: the JSON keys, the values
//! against an independent ephemeris, the sky-dome PNG, and a bad argument.
//!
//! Reference positions: astropy 8.0.2 (pyerfa 2.0.1.5), builtin ephemeris (ERFA `epv00` for the
//! Earth, `moon98` for the Moon), topocentric `AltAz` at 43.6° N 1.44° E, height 0 m, pressure 0
//! (airless, as the CLI without `--refraction`), UT1 = UTC (as brine-ephem takes it), for
//! 2024-06-21T12:00:00Z:
//!
//! ```python
//! t = Time("2024-06-21T12:00:00", scale="utc"); t.delta_ut1_utc = 0.0
//! loc = EarthLocation.from_geodetic(1.44 * u.deg, 43.6 * u.deg, 0 * u.m)
//! frame = AltAz(obstime=t, location=loc, pressure=0 * u.hPa)
//! with solar_system_ephemeris.set("builtin"):
//!     sun, moon = get_body("sun", t, loc), get_body("moon", t, loc)
//! sun.transform_to(frame), moon.transform_to(frame)
//! ```
//!
//! Sun: altitude 69.82052°, azimuth 182.55299°, distance 1.01623508 AU. Moon: altitude
//! −73.21924°, azimuth 27.02113°, geocentric distance 382 267.8 km, phase angle 8.3193°,
//! illuminated fraction 0.99474.

use std::path::Path;
use std::process::{Command, Output};

use brine_sky::{Sky, SkyParams};
use glam::DVec3;

/// Runs `brine` with `args` in `dir`.
fn brine(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).args(args).current_dir(dir).output().expect("brine runs")
}

/// Runs `brine` and parses its standard output as one JSON object.
/// `brine COMMAND` at the test's place and instant, as JSON.
fn json_at_place(command: &str) -> serde_json::Map<String, serde_json::Value> {
    let mut args = vec![command];
    args.extend(PLACE);
    args.push("--json");
    brine_json(&args)
}

fn brine_json(args: &[&str]) -> serde_json::Map<String, serde_json::Value> {
    let dir = tempfile::tempdir().unwrap();
    let out = brine(args, dir.path());
    assert_eq!(out.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    match serde_json::from_str::<serde_json::Value>(text.trim()) {
        Ok(serde_json::Value::Object(m)) => m,
        other => panic!("not a JSON object: {text:?} ({other:?})"),
    }
}

/// The sorted keys of a JSON object.
fn keys(m: &serde_json::Map<String, serde_json::Value>) -> Vec<&str> {
    let mut k: Vec<&str> = m.keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}

/// A number of a JSON object.
fn num(m: &serde_json::Map<String, serde_json::Value>, key: &str) -> f64 {
    m[key].as_f64().unwrap_or_else(|| panic!("{key} is not a number: {:?}", m[key]))
}

use brine_testkit::directions::separation_deg;

const PLACE: [&str; 6] = ["--lat", "43.6", "--lon", "1.44", "--time", "2024-06-21T12:00:00Z"];

/// The target for the SPA Sun: 0.01° from a high-precision ephemeris.
const SUN_DEG: f64 = 0.01;
/// The Earth–Sun distance comes from Schlyter's elements: 7.6×10⁻⁵ AU measured over 1950–2050
/// (`brine-ephem/tests/reference_values.rs`), bounded by 10⁻⁴ AU.
const SUN_AU: f64 = 1e-4;
/// The target for the Schlyter Moon: 0.1° from a high-precision ephemeris.
const MOON_DEG: f64 = 0.1;
/// Moon distance: Schlyter's two distance terms, 0.34 % measured over 1950–2050.
const MOON_KM_REL: f64 = 3.4e-3;
/// Phase angle: the elongation carries the 0.1° position error, and Schlyter's Sun (0.01°).
const MOON_PHASE_DEG: f64 = 0.11;
/// Illuminated fraction: `dk = sin(i)/2 · di` with `di` ≤ 0.11°: 1.4×10⁻⁴ here; the measured
/// bound over 1950–2050 is 9×10⁻⁴.
const MOON_FRACTION: f64 = 9e-4;
/// The CLI prints `f64` through `serde_json` (shortest round-trip form): its values are the
/// library's to the last bit; 10⁻¹² relative leaves room for nothing else.
const SAME_NUMBER: f64 = 1e-12;

#[test]
fn sun_json_has_the_keys_and_matches_astropy() {
    let m = json_at_place("sun");
    assert_eq!(keys(&m), ["altitude_deg", "azimuth_deg", "distance_au"]);
    let (alt, az, r) = (num(&m, "altitude_deg"), num(&m, "azimuth_deg"), num(&m, "distance_au"));
    assert!((alt - 69.82052).abs() < SUN_DEG, "altitude {alt}");
    assert!((az - 182.55299).abs() < SUN_DEG, "azimuth {az}");
    assert!(separation_deg(alt, az, 69.82052, 182.55299) < SUN_DEG);
    assert!((r - 1.01623508).abs() < SUN_AU, "distance {r} AU");
}

#[test]
fn moon_json_has_the_keys_ranges_and_matches_astropy() {
    let m = json_at_place("moon");
    assert_eq!(keys(&m), ["altitude_deg", "azimuth_deg", "distance_km", "illuminated_fraction", "phase_angle_deg"]);
    let (alt, az) = (num(&m, "altitude_deg"), num(&m, "azimuth_deg"));
    let (km, phase, k) = (num(&m, "distance_km"), num(&m, "phase_angle_deg"), num(&m, "illuminated_fraction"));
    // Ranges: altitude [−90, 90], azimuth [0, 360), distance within perigee/apogee extremes,
    // phase angle [0, 180], fraction [0, 1] and equal to (1 + cos i)/2.
    assert!((-90.0..=90.0).contains(&alt) && (0.0..360.0).contains(&az), "{alt} {az}");
    assert!((355_000.0..=408_000.0).contains(&km), "{km} km");
    assert!((0.0..=180.0).contains(&phase) && (0.0..=1.0).contains(&k), "{phase} {k}");
    assert!((k - 0.5 * (1.0 + phase.to_radians().cos())).abs() < SAME_NUMBER, "{k} vs {phase}");
    // Against astropy: the direction (the azimuth alone is stretched by 1/cos(alt) = 3.5 here).
    let sep = separation_deg(alt, az, -73.21924, 27.02113);
    assert!(sep < MOON_DEG, "moon {sep}° from astropy ({alt}, {az})");
    assert!((km / 382_267.8 - 1.0).abs() < MOON_KM_REL, "{km} km");
    assert!((phase - 8.3193).abs() < MOON_PHASE_DEG, "phase angle {phase}");
    assert!((k - 0.99474).abs() < MOON_FRACTION, "fraction {k}");
}

#[test]
fn sky_writes_a_fisheye_png() {
    let dir = tempfile::tempdir().unwrap();
    let out = brine(&["sky", "--turbidity", "3", "--sun-elevation-deg", "20", "--out", "x.png"], dir.path());
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let path = dir.path().join("x.png");
    let bytes = std::fs::read(&path).expect("x.png written");
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    let img = image::open(&path).expect("a readable PNG").to_rgb8();
    assert_eq!(img.dimensions(), (512, 512), "the default --size");
    // The dome is lit (the zenith pixel is not black) and the corners, outside the horizon
    // circle, are.
    assert!(img.get_pixel(256, 256).0.iter().any(|&c| c > 0));
    assert_eq!(img.get_pixel(0, 0).0, [0, 0, 0]);
}

#[test]
fn sky_json_is_finite_non_negative_and_the_library_value() {
    let m = brine_json(&[
        "sky",
        "--turbidity",
        "3",
        "--sun-elevation-deg",
        "20",
        "--json",
        "--view-elevation-deg",
        "30",
        "--view-azimuth-deg",
        "90",
    ]);
    let triple = |key: &str| -> [f64; 3] {
        let v: Vec<f64> =
            m[key].as_array().unwrap_or_else(|| panic!("{key}")).iter().map(|x| x.as_f64().unwrap()).collect();
        v.try_into().unwrap_or_else(|v| panic!("{key}: {v:?}"))
    };
    let (xyz, rgb) = (triple("xyz_kcd_m2"), triple("rgb_kcd_m2"));
    for c in xyz.iter().chain(&rgb) {
        assert!(c.is_finite() && *c >= 0.0, "{xyz:?} {rgb:?}");
    }
    assert!(xyz[1] > 0.0, "a daylight sky is not black: {xyz:?}");
    assert!((num(&m, "view_elevation_deg") - 30.0).abs() < SAME_NUMBER);
    assert!((num(&m, "view_azimuth_deg") - 90.0).abs() < SAME_NUMBER);
    // The same numbers as the library for the same sky and view (sun due south, 20° up; view
    // due east, 30° up; y up, x east, z south).
    let (e, a) = (20f64.to_radians(), 180f64.to_radians());
    let sun = DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos());
    let sky = Sky::new(&SkyParams::new(3.0, sun)).unwrap();
    let (e, a) = (30f64.to_radians(), 90f64.to_radians());
    let view = DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos());
    let (want_xyz, want_rgb) = (sky.radiance_xyz(view).to_array(), sky.radiance_rgb(view).to_array());
    for k in 0..3 {
        assert!((xyz[k] / want_xyz[k] - 1.0).abs() < SAME_NUMBER, "{xyz:?} vs {want_xyz:?}");
        assert!((rgb[k] / want_rgb[k] - 1.0).abs() < SAME_NUMBER, "{rgb:?} vs {want_rgb:?}");
    }
    // What lights a horizontal plane: the sky's irradiance and the sun's times the sine of its
    // elevation; and its chromaticity's offset below the daylight locus.
    let (sun_e, sky_e, global) = (
        triple("sun_irradiance_rgb_klx"),
        triple("sky_horizontal_irradiance_rgb_klx"),
        triple("global_horizontal_irradiance_rgb_klx"),
    );
    let sum = DVec3::from_array(sky_e) + DVec3::from_array(sun_e) * 20f64.to_radians().sin();
    for k in 0..3 {
        assert!((global[k] / sum[k] - 1.0).abs() < SAME_NUMBER, "{global:?} vs {sum:?}");
    }
    let g = brine_sky::linear_srgb_to_xyz(sum);
    let (x, y) = (g.x / g.element_sum(), g.y / g.element_sum());
    let offset = -3.0 * x * x + 2.870 * x - 0.275 - y;
    assert!((num(&m, "global_below_daylight_locus") - offset).abs() < SAME_NUMBER, "{offset}");
}

#[test]
fn bad_turbidity_exits_2_naming_the_parameter() {
    let dir = tempfile::tempdir().unwrap();
    let out = brine(&["sky", "--turbidity", "50", "--sun-elevation-deg", "20", "--out", "x.png"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("turbidity") && err.contains("50") && err.contains("[1.7, 10]"), "{err}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "nothing written");
}
