use super::*;

#[test]
fn the_embedded_scene_sets_a_place_and_the_rest_is_default() {
    let mut s = Scene::default_scene();
    assert!(s.place.is_some());
    s.place = None;
    // The file writes out the view and the water type that are also the defaults when absent.
    assert_eq!(
        (s.camera.yaw_deg, s.camera.pitch_deg, s.water.water_type.as_deref()),
        (Some(Scene::DEFAULT_YAW_DEG), Some(Scene::DEFAULT_PITCH_DEG), Some("IB"))
    );
    (s.camera.yaw_deg, s.camera.pitch_deg, s.water.water_type) = (None, None, None);
    assert_eq!(s, Scene::default());
}

#[test]
fn sun_angles_and_place_exclude_each_other() {
    let e = Scene::from_toml_str(
        "[place]\nlatitude_deg = 43.0\nlongitude_deg = 5.0\ntime_utc = \"2024-06-21T12:00:00Z\"\n[sky]\nsun_elevation_deg = 20.0\n",
        "s.toml",
    )
    .unwrap_err();
    assert!(e.message.contains("cannot be combined with [place]"), "{e}");
    assert_eq!(e.line, Some(6));
    let e =
        Scene::from_toml_str("[place]\nlatitude_deg = 43.0\nlongitude_deg = 5.0\ntime_utc = \"yesterday\"\n", "s.toml")
            .unwrap_err();
    assert!(e.message.starts_with("place.time_utc:"), "{e}");
    assert_eq!(e.line, Some(4));
}

#[test]
fn wrong_type_names_the_key_and_line() {
    let e = Scene::from_toml_str("[camera]\nwidth = 100\nfov_deg = \"wide\"\n", "s.toml").unwrap_err();
    assert_eq!(e.line, Some(3));
    assert!(e.message.contains("expected a number for camera.fov_deg"), "{e}");
    assert!(e.to_string().starts_with("s.toml line 3: "), "{e}");
}

/// A key set twice, or a table opened twice, is named with its line.
#[test]
fn duplicate_keys_are_named() {
    for (text, line, key) in [
        ("[output]\naovs = true\npath = \"x.exr\"\naovs = false\n", 4, "`aovs`"),
        ("[camera]\nwidth = 10\n\n[camera]\nheight = 10\n", 4, "`camera`"),
        ("camera.width = 10\n[camera]\nheight = 3\n", 2, "`camera`"),
        ("camera.width = 10\ncamera.width = 12\n", 2, "`width`"),
    ] {
        let e = parse(text).unwrap_err();
        assert_eq!(e.line, Some(line), "{e}");
        assert!(e.message.contains(&format!("duplicate key {key}")), "{e}");
    }
}

#[test]
fn unknown_key_is_an_error() {
    let e = Scene::from_toml_str("[sea]\nwind = 3.0\n", "s.toml").unwrap_err();
    assert!(e.message.starts_with("unknown key sea.wind (expected one of"), "{e}");
    assert_eq!(e.line, Some(2));
}

#[test]
fn out_of_range_values_are_errors_with_lines() {
    let e = Scene::from_toml_str("[sea]\n\nwind_speed_m_s = -1.0\n", "s.toml").unwrap_err();
    assert_eq!(e.line, Some(3));
    assert!(e.message.contains("sea.wind_speed_m_s = -1 is out of range"), "{e}");
    let e = Scene::from_toml_str("[camera]\nfov_deg = 180.0\n", "s.toml").unwrap_err();
    assert!(e.message.contains("camera.fov_deg"), "{e}");
    let e = Scene::from_toml_str("[camera]\nwidth = 0\n", "s.toml").unwrap_err();
    assert!(e.message.contains("camera.width"), "{e}");
}

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::from_toml_str(text, "s.toml")
}

#[test]
fn look_at_alone_is_accepted_and_with_an_angle_refused() {
    let s = parse("[camera]\nlook_at = [100.0, 0.0, 0.0]\n").unwrap();
    assert_eq!((s.camera.look_at, s.camera.yaw_deg, s.camera.pitch_deg), (Some([100.0, 0.0, 0.0]), None, None));
    let e = parse("[camera]\nlook_at = [100.0, 0.0, 0.0]\npitch_deg = -3.0\n").unwrap_err();
    assert!(e.message.contains("cannot be combined"), "{e}");
    assert_eq!(e.line, Some(2));
    // Without look_at and angles the default view is unchanged.
    let cam = crate::camera::from_config(&Scene::default().camera);
    let want = crate::camera::direction_from_bearing(Scene::DEFAULT_YAW_DEG, Scene::DEFAULT_PITCH_DEG);
    assert!((cam.forward - want).length() < 1e-12);
}

#[test]
fn chlorophyll_alone_is_accepted_and_with_a_type_refused() {
    let s = parse("[water]\nchlorophyll_mg_m3 = 1.0\n").unwrap();
    assert_eq!((s.water.water_type.as_deref(), s.water.chlorophyll_mg_m3), (None, Some(1.0)));
    let e = parse("[water]\ntype = \"II\"\nchlorophyll_mg_m3 = 1.0\n").unwrap_err();
    assert!(e.message.contains("exclude each other"), "{e}");
    assert_eq!(e.line, Some(3));
}

#[test]
fn the_documented_ends_of_ranges_are_accepted() {
    // Fetches up to 10⁵ km, the year 2200, 30 °C between water and air written in decimals.
    parse("[sea]\nspectrum = \"jonswap\"\nfetch_km = 100000.0\n").unwrap();
    parse("[place]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\ntime_utc = \"2200-12-31T23:59:59Z\"\n").unwrap();
    parse("[water]\ntemperature_c = 12.7\nair_temperature_c = 42.7\n").unwrap();
    let e = parse("[water]\ntemperature_c = 12.7\nair_temperature_c = 42.8\n").unwrap_err();
    assert!(e.message.contains("water.air_temperature_c"), "{e}");
    let e =
        parse("[place]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\ntime_utc = \"2201-01-01T00:00:00Z\"\n").unwrap_err();
    assert!(e.message.contains("1800–2200") && e.line == Some(4), "{e}");
}

#[test]
fn arrays_must_have_their_length() {
    let e = parse("[camera]\nposition = [0.0, 10.0, 0.0, 1.0]\n").unwrap_err();
    assert!(e.message.contains("camera.position has 4 elements"), "{e}");
    assert_eq!(e.line, Some(2));
    let e = parse("[sky.clouds]\nwind_m_s = [1.0, 2.0, 3.0]\n").unwrap_err();
    assert!(e.message.contains("sky.clouds.wind_m_s has 3 elements"), "{e}");
    let e = parse("[water.floor]\nalbedo = [0.5, 0.5]\n").unwrap_err();
    assert!(e.message.contains("water.floor.albedo has 2 elements"), "{e}");
}

#[test]
fn range_errors_keep_their_line_in_every_form_of_key() {
    let forms = [
        ("sea.wind_speed_m_s = 70.0\n", 1),
        ("sea = { wind_speed_m_s = 70.0 }\n", 1),
        ("[sea]\n\"wind_speed_m_s\" = 70.0\n", 2),
        ("[sea] # the sea\nwind_speed_m_s = 70.0\n", 2),
        ("\u{feff}[sea]\nwind_speed_m_s = 70.0\n", 2),
        ("[camera]\nwidth = 10\n[sea]\nseed = 3\n\n  wind_speed_m_s   =   70.0 # gale\n", 6),
    ];
    for (text, line) in forms {
        let e = parse(text).unwrap_err();
        assert!(e.message.contains("sea.wind_speed_m_s = 70 is out of range"), "{text:?}: {e}");
        assert_eq!(e.line, Some(line), "{text:?}: {e}");
    }
    let e = parse("[[sea]]\nwind_speed_m_s = 7.0\n").unwrap_err();
    assert!(e.message.contains("not as an array of tables [[sea]]"), "{e}");
    assert_eq!(e.line, Some(1));
}

#[test]
fn a_file_that_is_not_utf8_gets_the_line_of_its_first_bad_byte() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("latin1.toml");
    std::fs::write(&path, b"[sea]\n# caf\xe9\nwind_speed_m_s = 7.0\n").unwrap();
    let e = Scene::load(&path).unwrap_err();
    assert_eq!(e.line, Some(2), "{e}");
    assert!(e.message.contains("not UTF-8"), "{e}");
}

#[test]
fn aovs_are_checked_against_the_final_output_path() {
    let mut s = parse("[output]\naovs = true\n").unwrap();
    assert!(s.check_output().unwrap_err().contains("output.aovs"));
    s.output.path = "x.exr".into();
    s.check_output().unwrap();
}

/// A scene written as TOML reads back as the same scene, for every gallery scene and for a
/// scene edited as `brine view` edits one; a scene out of range is refused with its key.
#[test]
fn a_scene_written_as_toml_reads_back_the_same() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/gallery");
    let mut scenes = vec![Scene::default_scene()];
    for entry in std::fs::read_dir(&dir).expect("the gallery") {
        let path = entry.expect("an entry").path();
        if path.extension().is_some_and(|e| e == "toml") {
            scenes.push(Scene::load(&path).expect("a gallery scene"));
        }
    }
    assert!(scenes.len() > 5);
    for scene in &mut scenes {
        let text = scene.to_toml("edited.toml").expect("writable");
        assert_eq!(&Scene::from_toml_str(&text, "edited.toml").expect("readable"), scene);
        scene.sea.wind_speed_m_s = 13.25;
        scene.camera.fov_deg = 37.5;
        scene.phenomena.spray = !scene.phenomena.spray;
        let text = scene.to_toml("edited.toml").expect("writable");
        assert_eq!(&Scene::from_toml_str(&text, "edited.toml").expect("readable"), scene);
    }
    let mut bad = Scene::default_scene();
    bad.sea.wind_speed_m_s = 75.0;
    let e = bad.to_toml("edited.toml").unwrap_err().to_string();
    assert!(e.contains("wind_speed_m_s") && e.contains("edited.toml"), "{e}");
}
