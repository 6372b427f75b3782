//! Properties of the scene file over the whole key table (`brine_render::scene::keys::KEYS`):
//! every valid combination is accepted and renders finite pixels; every value just past a bound
//! or of a wrong type is refused with the file, the line and the key, in every form of TOML key,
//! and the command writes nothing.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use brine_render::scene::keys::{KEYS, KeySpec, Kind};
use brine_render::{RenderOptions, Scene, render};
use proptest::prelude::*;

/// A render of a few pixels that takes longer than this has hung or crawls (a grazing ray that
/// never ends); tiny scenes take well under a second here, the heaviest ones (10 000 waves, a
/// 2048² FFT) about 15 s in this profile.
const HANG_BUDGET: Duration = Duration::from_secs(120);

/// Tiny renders: the keys' effects, not the image, are under test.
const TINY: (u32, u32) = (6, 4);

/// A value of `spec` from a draw: `pick` chooses an end (0: low, 1: high) or the inside (2+),
/// `u` places it inside.
fn value_of(spec: &KeySpec, pick: u8, u: f64, bits: u64) -> toml::Value {
    let inside = |lo: f64, hi: f64| match pick {
        0 => lo,
        1 => hi,
        _ => lo + (hi - lo) * u,
    };
    match spec.kind {
        Kind::Float { lo, hi } => {
            // Open ends are approached, not reached; unbounded ones are drawn within ±10³.
            let l = lo.map_or(-1e3, |(v, inc)| if inc { v } else { v + 1e-9 * (1.0 + v.abs()) });
            let h = hi.map_or(1e3, |(v, inc)| if inc { v } else { v - 1e-9 * (1.0 + v.abs()) });
            toml::Value::Float(inside(l, h))
        }
        Kind::Int { lo, hi } => {
            let hi = hi.min(i128::from(i64::MAX));
            let n = match pick {
                0 => lo,
                1 => hi,
                _ => lo + (bits as i128).rem_euclid(hi - lo + 1),
            };
            toml::Value::Integer(n as i64)
        }
        Kind::PowerOfTwo { lo, hi } => {
            let (a, b) = (lo.trailing_zeros(), hi.trailing_zeros());
            let e = match pick {
                0 => a,
                1 => b,
                _ => a + (bits % u64::from(b - a + 1)) as u32,
            };
            toml::Value::Integer(1i64 << e)
        }
        Kind::Bool => toml::Value::Boolean(bits.is_multiple_of(2)),
        Kind::Enum { values, ignore_case } => {
            let v = values[(bits as usize) % values.len()];
            let v = if ignore_case && bits.is_multiple_of(3) { v.to_ascii_lowercase() } else { v.to_owned() };
            toml::Value::String(v)
        }
        Kind::Instant => {
            let year = match pick {
                0 => 1800,
                1 => 2200,
                _ => 1800 + (bits % 401) as i32,
            };
            let (month, day, hour) = match pick {
                0 => (1, 1, 0),
                1 => (12, 31, 23),
                _ => (1 + (bits >> 9) % 12, 1 + (bits >> 13) % 28, (bits >> 18) % 24),
            };
            toml::Value::String(format!("{year:04}-{month:02}-{day:02}T{hour:02}:00:00Z"))
        }
        Kind::ImagePath => toml::Value::String(if bits.is_multiple_of(2) { "out.png" } else { "out.exr" }.into()),
        Kind::FloatArray { len, lo, hi } => toml::Value::Array(
            (0..len)
                .map(|i| {
                    let ui = (u + 0.37 * i as f64).fract();
                    toml::Value::Float(match (pick, i) {
                        (0, _) => lo,
                        (1, _) => hi,
                        _ => lo + (hi - lo) * ui,
                    })
                })
                .collect(),
        ),
    }
}

/// Sets `section.key` in `root`, creating the section tables.
fn set(root: &mut toml::Table, section: &str, key: &str, v: toml::Value) {
    let mut t = root;
    for part in section.split('.') {
        t = t.entry(part).or_insert_with(|| toml::Value::Table(toml::Table::new())).as_table_mut().unwrap();
    }
    t.insert(key.to_owned(), v);
}

fn get<'a>(root: &'a toml::Table, section: &str, key: &str) -> Option<&'a toml::Value> {
    let mut t = root;
    for part in section.split('.') {
        t = t.get(part)?.as_table()?;
    }
    t.get(key)
}

fn remove(root: &mut toml::Table, section: &str, key: &str) {
    let mut t = root;
    for part in section.split('.') {
        match t.get_mut(part).and_then(toml::Value::as_table_mut) {
            Some(inner) => t = inner,
            None => return,
        }
    }
    t.remove(key);
}

fn float(root: &toml::Table, section: &str, key: &str) -> Option<f64> {
    get(root, section, key).and_then(|v| v.as_float().or_else(|| v.as_integer().map(|i| i as f64)))
}

/// A valid scene from one draw per key (`None`: the key is left out), with the constraints
/// between keys (docs/scene.md's range column) respected.
fn scene_of(draws: &[(Option<u8>, f64, u64)]) -> toml::Table {
    let mut root = toml::Table::new();
    for (spec, &(pick, u, bits)) in KEYS.iter().zip(draws) {
        if let Some(pick) = pick {
            set(&mut root, spec.section, spec.key, value_of(spec, pick, u, bits));
        }
    }
    // [place] needs its three keys and then sets the sun.
    if root.contains_key("place") {
        for key in ["latitude_deg", "longitude_deg", "time_utc"] {
            if get(&root, "place", key).is_none() {
                let spec = KEYS.iter().find(|s| s.section == "place" && s.key == key).unwrap();
                set(&mut root, "place", key, value_of(spec, 2, 0.5, 12_345));
            }
        }
        remove(&mut root, "sky", "sun_elevation_deg");
        remove(&mut root, "sky", "sun_azimuth_deg");
    }
    if get(&root, "camera", "look_at").is_some() {
        remove(&mut root, "camera", "yaw_deg");
        remove(&mut root, "camera", "pitch_deg");
        let p = get(&root, "camera", "position").cloned();
        if p.is_some() && p.as_ref() == get(&root, "camera", "look_at") {
            remove(&mut root, "camera", "look_at");
        }
        if p.is_none() && get(&root, "camera", "look_at") == Some(&toml::Value::try_from([0.0, 10.0, 0.0]).unwrap()) {
            remove(&mut root, "camera", "look_at");
        }
    }
    if get(&root, "sea", "spectrum").and_then(toml::Value::as_str) == Some("tma")
        && get(&root, "sea", "depth_m").is_none()
    {
        set(&mut root, "sea", "depth_m", toml::Value::Float(30.0));
    }
    if get(&root, "sea", "swell").is_some() {
        let t = float(&root, "sea.swell", "peak_period_s").unwrap_or(12.0);
        let limit = brine_waves::G * t * t / std::f64::consts::TAU / 7.0;
        let h = float(&root, "sea.swell", "significant_height_m").unwrap_or(1.0);
        set(&mut root, "sea.swell", "significant_height_m", toml::Value::Float(h.min(limit)));
    }
    if get(&root, "water", "type").is_some() {
        remove(&mut root, "water", "chlorophyll_mg_m3");
    }
    if let (Some(tw), Some(ta)) = (float(&root, "water", "temperature_c"), float(&root, "water", "air_temperature_c")) {
        set(&mut root, "water", "air_temperature_c", toml::Value::Float(ta.clamp(tw - 30.0, tw + 30.0)));
    }
    if get(&root, "water", "floor").is_some() {
        let depth = float(&root, "water.floor", "depth_m").unwrap_or(6.0);
        let a = float(&root, "water.floor", "amplitude_m").unwrap_or(0.4);
        set(&mut root, "water.floor", "amplitude_m", toml::Value::Float(a.min(0.5 * depth)));
        if let Some(r) = get(&root, "water.floor", "wavelength_range_m").and_then(toml::Value::as_array) {
            let mut v: Vec<f64> = r.iter().map(|x| x.as_float().unwrap()).collect();
            v.sort_by(f64::total_cmp);
            set(&mut root, "water.floor", "wavelength_range_m", toml::Value::try_from(v).unwrap());
        }
    }
    if get(&root, "output", "aovs").and_then(toml::Value::as_bool) == Some(true) {
        set(&mut root, "output", "path", toml::Value::String("out.exr".into()));
    }
    root
}

/// One draw per key: left out (40 %), the low end, the high end or inside.
fn draws() -> impl Strategy<Value = Vec<(Option<u8>, f64, u64)>> {
    prop::collection::vec(
        (prop_oneof![4 => Just(None), 6 => (0u8..4).prop_map(Some)], 0.0f64..1.0, any::<u64>()),
        KEYS.len(),
    )
}

/// Renders a tiny version of `scene` and checks every pixel is finite, within the budget.
fn render_tiny(mut scene: Scene, what: &str) {
    (scene.camera.width, scene.camera.height, scene.camera.spp) = (TINY.0, TINY.1, 1);
    let start = Instant::now();
    let frame = render(&scene, &RenderOptions { threads: Some(1), ..RenderOptions::default() }, &|| {})
        .unwrap_or_else(|e| panic!("{what}: a valid scene failed to render: {e}"));
    let took = start.elapsed();
    assert!(took < HANG_BUDGET, "{what}: {took:?} for {}×{} pixels", TINY.0, TINY.1);
    for (i, p) in frame.pixels.iter().enumerate() {
        assert!(p.is_finite() && p.min_element() >= 0.0, "{what}: pixel {i} = {p}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, failure_persistence: None, ..ProptestConfig::default() })]

    /// Any scene whose keys are within the documented ranges (both ends included, every enum
    /// value, combined) is accepted and renders finite, non-negative radiance.
    #[test]
    fn every_documented_scene_is_accepted_and_renders(d in draws()) {
        let table = scene_of(&d);
        let text = toml::to_string(&table).unwrap();
        let scene = Scene::from_toml_str(&text, "random.toml").unwrap_or_else(|e| panic!("{e}\n--- scene:\n{text}"));
        // The heaviest settings are rendered once each in `the_heaviest_ends_render`; here they
        // are kept small so that the cases stay quick.
        let mut s = scene;
        s.sea.waves = s.sea.waves.map(|n| n.min(300));
        s.sea.fft.resolution = s.sea.fft.resolution.min(256);
        render_tiny(s, &text);
    }
}

/// The costly ends of the ranges, one render each: 10 000 waves with a swell of 1 000, the
/// 2048² FFT, eight cascades, 60 m/s, the camera at the ends of its range.
#[test]
fn the_heaviest_ends_render() {
    let scenes = [
        "[sea]\nwaves = 10000\nwind_speed_m_s = 60.0\nchoppiness = 100.0\n[sea.swell]\nwaves = 1000\n",
        "[sea]\nsurface = \"fft\"\nwind_speed_m_s = 60.0\n[sea.fft]\nresolution = 2048\ncascades = 1\n",
        "[sea]\nsurface = \"fft\"\nwind_speed_m_s = 0.0\n[sea.fft]\nresolution = 64\ncascades = 8\nchoppiness = 4.0\n",
        "[camera]\nposition = [1000000.0, 1000000.0, -1000000.0]\npitch_deg = -90.0\n",
        "[camera]\nposition = [0.0, 900000.0, 0.0]\npitch_deg = -23.7\n",
        "[camera]\nposition = [0.0, -1000000.0, 0.0]\npitch_deg = 90.0\n",
    ];
    for text in scenes {
        render_tiny(Scene::from_toml_str(text, "heavy.toml").unwrap(), text);
    }
}

/// A camera high above the air (900 km, inside the documented ±10⁶ m) used to give NaN pixels
/// through the aerial perspective; with glare, an all-white PNG.
#[test]
fn a_camera_far_above_the_air_sees_a_finite_sea() {
    let mut s =
        Scene::from_toml_str("[camera]\nposition = [0.0, 900000.0, 0.0]\npitch_deg = -23.7\n", "high.toml").unwrap();
    (s.camera.width, s.camera.height) = (48, 27);
    let frame = render(&s, &RenderOptions { threads: Some(2), ..RenderOptions::default() }, &|| {}).unwrap();
    assert!(frame.pixels.iter().all(|p| p.is_finite()));
    let mean = frame.pixels.iter().map(|p| p.y).sum::<f64>() / frame.pixels.len() as f64;
    assert!(mean > 0.0, "the sea seen from orbit is lit");
}

/// Values that cross each bound, or have the wrong type, for `spec`.
fn bad_values(spec: &KeySpec) -> Vec<String> {
    let mut out = Vec::new();
    match spec.kind {
        Kind::Float { lo, hi } => {
            if let Some((v, inc)) = lo {
                out.push(format!("{:?}", if inc { v - 1e-6 * (1.0 + v.abs()) } else { v }));
            }
            if let Some((v, inc)) = hi {
                out.push(format!("{:?}", if inc { v + 1e-6 * (1.0 + v.abs()) } else { v }));
            }
            out.push("nan".into());
            out.push("inf".into());
            out.push("\"ten\"".into());
        }
        Kind::Int { lo, hi } | Kind::PowerOfTwo { lo, hi } => {
            if lo > i128::from(i64::MIN) {
                out.push(format!("{}", lo - 1));
            }
            if hi < i128::from(i64::MAX) {
                out.push(format!("{}", hi + 1));
            }
            if matches!(spec.kind, Kind::PowerOfTwo { .. }) {
                out.push(format!("{}", lo + 1));
            }
            out.push("1.5".into());
            out.push("true".into());
        }
        Kind::Bool => out.extend(["1".to_owned(), "\"yes\"".to_owned()]),
        Kind::Enum { .. } => out.extend(["\"no-such-value\"".to_owned(), "3".to_owned()]),
        Kind::Instant => {
            out.extend(["\"2201-01-01T00:00:00Z\"".to_owned(), "\"1799-12-31T23:59:59Z\"".to_owned(), "1".to_owned()])
        }
        Kind::ImagePath => out.extend(["\"out.jpg\"".to_owned(), "2".to_owned()]),
        Kind::FloatArray { len, lo, hi } => {
            let ok = vec![format!("{lo:?}"); len];
            out.push(format!("[{}]", vec![format!("{lo:?}"); len + 1].join(", ")));
            out.push(format!("[{}]", vec![format!("{lo:?}"); len - 1].join(", ")));
            let mut below = ok.clone();
            below[0] = format!("{:?}", lo - 1e-6 * (1.0 + lo.abs()));
            out.push(format!("[{}]", below.join(", ")));
            let mut above = ok.clone();
            above[len - 1] = format!("{:?}", hi + 1e-6 * (1.0 + hi.abs()));
            out.push(format!("[{}]", above.join(", ")));
            out.push("1.0".into());
        }
    }
    out
}

/// The three ways of writing `section.key = value`, with the line the key is on.
fn forms(spec: &KeySpec, value: &str) -> Vec<(String, usize)> {
    let (section, key) = (spec.section, spec.key);
    let place = if section == "place" {
        ""
    } else {
        "[place]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\ntime_utc = \"2024-01-01T00:00:00Z\"\n"
    };
    let extra = if section == "place" {
        // The other required keys of [place], so that only the bad one is wrong.
        ["latitude_deg = 0.0", "longitude_deg = 0.0", "time_utc = \"2024-01-01T00:00:00Z\""]
            .iter()
            .filter(|l| !l.starts_with(key))
            .map(|l| format!("{l}\n"))
            .collect::<String>()
    } else {
        String::new()
    };
    let lead = if place.is_empty() { 0 } else { 4 };
    let mut out = vec![(
        format!("{place}[{section}] # a comment\n{extra}\"{key}\" = {value}\n"),
        lead + 2 + extra.lines().count(),
    )];
    if section == "place" {
        // place = { … } and place.key lines: the other keys go in the same form.
        let others = extra.lines().map(str::to_owned).collect::<Vec<_>>();
        let inline = others.iter().cloned().chain([format!("{key} = {value}")]).collect::<Vec<_>>().join(", ");
        out.push((format!("place = {{ {inline} }}\n"), 1));
        let dotted: String = others.iter().map(|l| format!("place.{l}\n")).collect();
        out.push((format!("{dotted}place.{key} = {value}\n"), others.len() + 1));
    } else {
        // Dotted and inline keys before any header (after one they would belong to it).
        out.push((format!("\n{section}.{key} = {value}\n{place}"), 2));
        let (outer, inner) = match section.split_once('.') {
            Some((a, b)) => (a.to_owned(), format!("{b}.{key}")),
            None => (section.to_owned(), key.to_owned()),
        };
        out.push((format!("{outer} = {{ {inner} = {value} }}\n{place}"), 1));
    }
    out
}

/// Every value past a bound or of a wrong type, for every key, in every form: refused, with the
/// file, the line of the key and the key's full name.
#[test]
fn every_bad_value_is_refused_with_its_file_line_and_key() {
    let mut checked = 0;
    for spec in KEYS {
        for value in bad_values(spec) {
            for (text, line) in forms(spec, &value) {
                let e = Scene::from_toml_str(&text, "bad.toml")
                    .err()
                    .unwrap_or_else(|| panic!("accepted {}.{} = {value}:\n{text}", spec.section, spec.key));
                assert_eq!(e.file, "bad.toml");
                assert_eq!(e.line, Some(line), "{e}\n--- scene:\n{text}");
                assert!(e.message.contains(&spec.path()), "{e}\n--- scene:\n{text}");
                checked += 1;
            }
        }
    }
    assert!(checked > 3 * KEYS.len(), "{checked} cases");
}

/// The command on each bad key (header form): exit code 2, `FILE line N: …` naming the key, and
/// nothing written.
#[test]
fn the_command_refuses_every_bad_key_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    for spec in KEYS {
        let value = &bad_values(spec)[0];
        let (text, line) = forms(spec, value).swap_remove(0);
        std::fs::write(dir.path().join("scene.toml"), &text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_brine"))
            .args(["render", "scene.toml", "-o", "out.png", "--quiet"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{}: {err}", spec.path());
        assert!(err.starts_with(&format!("error: scene.toml line {line}: ")), "{}: {err}", spec.path());
        assert!(err.contains(&spec.path()), "{}: {err}", spec.path());
        assert_only_scene(dir.path());
    }
}

fn assert_only_scene(dir: &Path) {
    let names: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, vec![std::ffi::OsString::from("scene.toml")], "files written: {names:?}");
}
