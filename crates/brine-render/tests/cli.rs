//! The `brine` command on bad input: a clear message, exit code 2, and no file written.

use std::path::Path;
use std::process::{Command, Output};

fn brine(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).args(args).current_dir(dir).output().expect("brine runs")
}

/// Writes `scene` to `scene.toml` in a fresh folder, runs `brine render scene.toml -o out.png`
/// and returns the folder, the exit code and stderr.
fn render_scene(scene: &str) -> (tempfile::TempDir, Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let out = brine(&["render", "scene.toml", "-o", "out.png", "--quiet"], dir.path());
    (dir, out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
}

/// Asserts that only the scene file is in the folder.
fn assert_nothing_written(dir: &Path) {
    let names: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, vec![std::ffi::OsString::from("scene.toml")], "files written: {names:?}");
}

#[test]
fn unknown_key() {
    let (dir, code, err) = render_scene("[camera]\nwidth = 16\nfovv = 40.0\n");
    assert_eq!(code, Some(2));
    assert_eq!(
        err.trim(),
        "error: scene.toml line 3: unknown key camera.fovv (expected one of position, look_at, yaw_deg, pitch_deg, fov_deg, width, height, spp)"
    );
    assert_nothing_written(dir.path());
}

#[test]
fn wrong_type() {
    let (dir, code, err) = render_scene("[camera]\nwidth = 16\n\nfov_deg = \"wide\"\n");
    assert_eq!(code, Some(2));
    assert!(err.starts_with("error: scene.toml line 4: expected a number for camera.fov_deg"), "{err}");
    assert_nothing_written(dir.path());
}

#[test]
fn missing_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = brine(&["render", "nope.toml", "-o", "out.png"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.starts_with("error: nope.toml: cannot read the scene file"), "{err}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn out_of_range_values() {
    for (scene, key, line) in [
        ("[sea]\nwind_speed_m_s = -5.0\n", "sea.wind_speed_m_s = -5 is out of range", 2),
        ("[camera]\nfov_deg = 180.0\n", "camera.fov_deg = 180 is out of range", 2),
        ("[camera]\nwidth = 0\n", "camera.width = 0 is out of range", 2),
        ("[camera]\nheight = 0\n", "camera.height = 0 is out of range", 2),
        ("[sea]\nsurface = \"fft\"\n\n[sea.fft]\nresolution = 100\n", "sea.fft.resolution = 100 is out of range", 5),
        ("[sea.fft]\ncascades = 9\n", "sea.fft.cascades = 9 is out of range", 2),
        // The mission's bad winds and wave counts.
        ("[sea]\nwind_speed_m_s = 80.0\n", "sea.wind_speed_m_s = 80 is out of range: expected [0, 60] m/s", 2),
        ("[sea]\nwaves = 10001\n", "sea.waves = 10001 is out of range", 2),
        ("[sea]\nspectrum = \"tma\"\n", "sea.spectrum = \"tma\" needs sea.depth_m", 2),
        ("[sea]\nfetch_km = 0.01\n", "sea.fetch_km = 0.01 is out of range", 2),
        ("[sea]\n[sea.swell]\nwaves = 5000\n", "sea.swell.waves = 5000 is out of range", 3),
        (
            "[sea.swell]\npeak_period_s = 5.0\nsignificant_height_m = 9.0\n",
            "sea.swell.significant_height_m = 9 is out of range",
            3,
        ),
        (
            "[water]\ntemperature_c = 30.0\nair_temperature_c = -20.0\n",
            "water.air_temperature_c = -20 is out of range",
            3,
        ),
        ("[output]\naovs = true\n", "output.aovs = true needs an .exr output", 2),
    ] {
        let (dir, code, err) = render_scene(scene);
        assert_eq!(code, Some(2), "{scene}");
        assert!(err.starts_with(&format!("error: scene.toml line {line}: {key}")), "{scene}: {err}");
        assert_nothing_written(dir.path());
    }
}

#[test]
fn a_small_render_writes_exactly_the_image() {
    let (dir, code, err) = render_scene("[camera]\nwidth = 12\nheight = 8\n[sea]\nwaves = 8\n");
    assert_eq!(code, Some(0), "{err}");
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names.len(), 2, "{names:?}");
    let img = image::open(dir.path().join("out.png")).unwrap();
    assert_eq!((img.width(), img.height()), (12, 8));
}

#[test]
fn an_interrupted_animation_resumed_gives_the_same_frames() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("scene.toml"), "[camera]\nwidth = 16\nheight = 9\n[sea]\nwaves = 6\n").unwrap();
    for sub in ["a", "b"] {
        std::fs::create_dir(root.join(sub)).unwrap();
    }
    let run = |args: &[&str]| {
        let out = brine(args, root);
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    run(&["render", "scene.toml", "--frames", "0..3", "-o", "a/f_##.png", "--quiet"]);
    // "Interrupted" after the first frame, with a stale temporary file of the second.
    run(&["render", "scene.toml", "--frames", "0..1", "-o", "b/f_##.png", "--quiet"]);
    std::fs::write(root.join("b/.f_01.png.abc123.tmp"), b"half an image").unwrap();
    let log = run(&["render", "scene.toml", "--frames", "0..3", "--resume", "-o", "b/f_##.png"]);
    assert!(log.contains("2 frames (1 skipped)"), "{log}");
    for f in ["f_00.png", "f_01.png", "f_02.png"] {
        let a = std::fs::read(root.join("a").join(f)).unwrap();
        let b = std::fs::read(root.join("b").join(f)).unwrap();
        assert!(a == b, "{f} differs between the uninterrupted and the resumed run");
    }
    // Frames differ in time, so consecutive frames are different images.
    assert!(std::fs::read(root.join("a/f_00.png")).unwrap() != std::fs::read(root.join("a/f_02.png")).unwrap());
}

/// `brine bake --resume` keeps the frames whose maps are all complete and bakes the others
/// (a missing map, a truncated one), removing a killed run's temporaries: the folder is then
/// the uninterrupted bake's, `bake.json` included (its grid limit is frame 0's, kept, also on
/// the FFT sea, whose limit changes with time), for EXR and 16-bit PNG maps. A resume with
/// other arguments is refused, naming what differs.
#[test]
fn an_interrupted_bake_resumed_gives_the_same_maps() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("fft.toml"), "[sea]\nsurface = \"fft\"\n").unwrap();
    for (png, fft) in [(false, false), (true, false), (false, true)] {
        let bake = |out: &str, extra: &[&str]| {
            let mut args = vec!["bake", "-o", out, "--size", "16", "--tile-m", "40", "--frames", "0..4"];
            if png {
                args.push("--png16");
            }
            if fft {
                args.push("fft.toml");
            }
            args.extend(extra);
            let o = brine(&args, root);
            assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
            String::from_utf8_lossy(&o.stderr).into_owned()
        };
        let ext = if png { "png" } else { "exr" };
        let (a, b) = (format!("a{ext}{fft}"), format!("b{ext}{fft}"));
        bake(&a, &["-q"]);
        bake(&b, &["-q"]);
        // Interrupted: frame 2 lost a map, frame 3 one was cut short, a temporary is left, and
        // no bake.json was written.
        let (fb, fa) = (root.join(&b), root.join(&a));
        std::fs::remove_file(fb.join(format!("normal_0002.{ext}"))).unwrap();
        let foam = fb.join(format!("foam_0003.{ext}"));
        let bytes = std::fs::read(&foam).unwrap();
        std::fs::write(&foam, &bytes[..bytes.len() / 2]).unwrap();
        std::fs::write(fb.join(format!(".spray_0001.{ext}.abc123.tmp")), b"half a map").unwrap();
        std::fs::remove_file(fb.join("bake.json")).unwrap();
        let log = bake(&b, &["--resume"]);
        assert!(log.contains("2 frame(s) of 6 maps (2 more kept from an earlier run)"), "{log}");
        let listing = |d: &std::path::Path| {
            let mut names: Vec<String> =
                std::fs::read_dir(d).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
            names.sort();
            names
        };
        assert_eq!(listing(&fa), listing(&fb));
        assert!(listing(&fa).contains(&".bake-settings.json".to_owned()));
        for name in listing(&fa) {
            let (x, y) = (std::fs::read(fa.join(&name)).unwrap(), std::fs::read(fb.join(&name)).unwrap());
            if name == "bake.json" {
                assert_eq!(String::from_utf8_lossy(&x), String::from_utf8_lossy(&y));
            } else {
                assert!(x == y, "{name} differs between the uninterrupted and the resumed bake");
            }
        }
        if !fft {
            // Maps of another size are not the same bake.
            let mut args =
                vec!["bake", "-o", b.as_str(), "--size", "8", "--tile-m", "40", "--frames", "0..4", "--resume"];
            if png {
                args.push("--png16");
            }
            let o = brine(&args, root);
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{err}");
            assert!(err.contains("baked with another size"), "{err}");
        }
    }
}

/// The camera and the output do not enter a bake's maps (those of two cameras are the same
/// bytes): `--resume` keeps the maps of a scene that differs from theirs only there, and still
/// refuses one whose sea differs, naming its key and not the camera's.
#[test]
fn a_bake_resumes_over_another_camera_but_not_another_sea() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("a.toml"), "[camera]\nyaw_deg = 10.0\n").unwrap();
    std::fs::write(root.join("b.toml"), "[camera]\nyaw_deg = 200.0\nfov_deg = 30.0\n[output]\npath = \"x.png\"\n")
        .unwrap();
    std::fs::write(root.join("c.toml"), "[camera]\nyaw_deg = 200.0\n[sea]\nwind_speed_m_s = 12.0\n").unwrap();
    let bake = |scene: &str, resume: bool| {
        let mut args = vec!["bake", "-o", "maps", "--size", "8", "--tile-m", "40", "--frames", "0..2", scene];
        if resume {
            args.push("--resume");
        }
        brine(&args, root)
    };
    let o = bake("a.toml", false);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let o = bake("b.toml", true);
    let log = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{log}");
    assert!(log.contains("every frame (2) kept from an earlier run"), "{log}");
    // The maps are those of a fresh bake of the other camera's scene, byte for byte.
    let o = brine(&["bake", "-o", "fresh", "--size", "8", "--tile-m", "40", "--frames", "0..2", "b.toml"], root);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for name in ["displacement_0001.exr", "normal_0000.exr", "foam_0001.exr", "spray_0000.exr"] {
        let (x, y) = (
            std::fs::read(root.join("maps").join(name)).unwrap(),
            std::fs::read(root.join("fresh").join(name)).unwrap(),
        );
        assert!(x == y, "{name}: the camera changed the maps");
    }
    let o = bake("c.toml", true);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("sea.wind_speed_m_s") && !err.contains("camera."), "{err}");
}

/// `brine mesh --frames … --resume` keeps the meshes written in full and makes again those cut
/// short (and a `.gltf` whose `.bin` is gone), in every format: the files are then the
/// uninterrupted run's.
#[test]
fn an_interrupted_mesh_sequence_resumed_gives_the_same_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    for ext in ["glb", "gltf", "obj", "ply"] {
        let run = |out: &str, extra: &[&str]| {
            let mut args = vec!["mesh", "--size-m", "8", "--spacing-m", "1", "--frames", "0..3", "-o", out];
            args.extend(extra);
            let o = brine(&args, root);
            assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
            String::from_utf8_lossy(&o.stderr).into_owned()
        };
        let (a, b) = (format!("a_#.{ext}"), format!("b_#.{ext}"));
        run(&a, &["-q"]);
        run(&b, &["-q"]);
        // Frame 1 cut short (or, for .gltf, its buffer lost; for .obj, at a line's end among the
        // faces), and a temporary left beside frame 2.
        if ext == "gltf" {
            std::fs::remove_file(root.join("b_1.bin")).unwrap();
        } else if ext == "obj" {
            let p = root.join("b_1.obj");
            let text = std::fs::read_to_string(&p).unwrap();
            let cut = text.rfind("\nf ").unwrap() + 1;
            std::fs::write(&p, &text[..cut]).unwrap();
        } else {
            let p = root.join(format!("b_1.{ext}"));
            let bytes = std::fs::read(&p).unwrap();
            std::fs::write(&p, &bytes[..bytes.len() * 2 / 3]).unwrap();
        }
        std::fs::write(root.join(format!(".b_2.{ext}.abc123.tmp")), b"half a mesh").unwrap();
        let log = run(&b, &["--resume"]);
        assert!(log.contains("(2 more kept from an earlier run)"), "{ext}: {log}");
        assert!(!root.join(format!(".b_2.{ext}.abc123.tmp")).exists(), "{ext}: the temporary is left");
        let exts: &[&str] = if ext == "gltf" { &["gltf", "bin"] } else { &[ext] };
        for f in 0..3 {
            for e in exts {
                let (x, y) =
                    (std::fs::read(root.join(format!("a_{f}.{e}"))), std::fs::read(root.join(format!("b_{f}.{e}"))));
                let (x, y) = (x.unwrap(), y.unwrap());
                if *e == "gltf" {
                    // The buffer's URI names its own file.
                    let y = String::from_utf8_lossy(&y).replace("b_", "a_");
                    assert_eq!(String::from_utf8_lossy(&x), y, "frame {f}");
                } else {
                    assert!(x == y, "frame {f} .{e} differs between the uninterrupted and the resumed run");
                }
            }
        }
    }
}

#[test]
fn an_animation_needs_a_frame_number_in_the_path() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), "").unwrap();
    let out = brine(&["render", "scene.toml", "--frames", "0..2", "-o", "out.png"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("needs a run of #"));
}

#[test]
fn a_closed_pipe_ends_quietly() {
    use std::io::Read;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_brine"))
        .args(["fit", "--model", "pm", "--u10", "10", "--waves", "2000", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The pipe is closed here, long before the 2000 waves are printed.
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn a_time_lapse_needs_a_place_and_moves_the_sun() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    std::fs::write(root.join("noplace.toml"), "[camera]\nwidth = 8\nheight = 6\n").unwrap();
    let out = brine(
        &[
            "render",
            "noplace.toml",
            "--time-lapse",
            "2024-06-21T04:00Z..2024-06-21T23:00Z",
            "--frames",
            "2",
            "-o",
            "f_#.png",
        ],
        root,
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--time-lapse needs a [place]"));
    std::fs::write(
        root.join("place.toml"),
        "[place]\nlatitude_deg = 43.3\nlongitude_deg = 5.37\ntime_utc = \"2024-06-21T12:00:00Z\"\n[camera]\nwidth = 16\nheight = 9\n[sea]\nwaves = 4\n",
    )
    .unwrap();
    let out = brine(
        &[
            "render",
            "place.toml",
            "--time-lapse",
            "2024-06-21T10:00Z..2024-06-21T22:00Z",
            "--frames",
            "2",
            "-o",
            "f_#.png",
            "--quiet",
        ],
        root,
    );
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    // Frame 0 is late morning, frame 1 is night (22:00 UTC, after sunset in Marseille).
    let day = image::open(root.join("f_0.png")).unwrap().to_rgb8();
    let night = image::open(root.join("f_1.png")).unwrap().to_rgb8();
    let mean =
        |im: &image::RgbImage| im.pixels().map(|p| u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2])).sum::<u32>();
    assert!(mean(&day) > 2 * mean(&night), "day {} vs night {}", mean(&day), mean(&night));
}

/// `bake.json` says what the grid left out: a trochoid sea on 2 m texels loses its waves under
/// 4 m, the covariance in the maps' axes (`X = x`, `Y = −z` with `--up z`: the cross term changes
/// sign); on texels fine enough for every wave nothing is lost.
#[test]
fn a_bake_says_what_its_grid_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let read = |name: &str| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(dir.path().join(name).join("bake.json")).unwrap()).unwrap()
    };
    for (name, size, up) in [("y", "32", "y"), ("z", "32", "z"), ("fine", "512", "y")] {
        let out = brine(&["bake", "-q", "-o", name, "--size", size, "--tile-m", "64", "--up", up], dir.path());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let (y, z, fine) =
        (read("y")["grid_limit"].clone(), read("z")["grid_limit"].clone(), read("fine")["grid_limit"].clone());
    assert_eq!(y["shortest_wave_m"], 4.0);
    assert!(y["faded_waves"].as_u64().unwrap() > 0 && y["lost_mean_square_slope"].as_f64().unwrap() > 0.0, "{y}");
    let c = |v: &serde_json::Value, k: &str| v["lost_slope_covariance"][k].as_f64().unwrap();
    assert_eq!(
        (y["lost_slope_covariance"]["axes"].as_str(), z["lost_slope_covariance"]["axes"].as_str()),
        (Some("x z"), Some("X Y"))
    );
    assert_eq!((c(&z, "xx"), c(&z, "xy"), c(&z, "yy")), (c(&y, "xx"), -c(&y, "xy"), c(&y, "yy")));
    // The same f64 sum, written once by the command and once here.
    assert_eq!((c(&y, "xx") + c(&y, "yy")).to_bits(), y["lost_mean_square_slope"].as_f64().unwrap().to_bits());
    assert_eq!((fine["faded_waves"].as_u64(), fine["lost_mean_square_slope"].as_f64()), (Some(0), Some(0.0)));
}

/// A loop period far shorter than the sea's periods is warned of, with a period that would keep
/// the waves within 5 %; that period draws no warning, and `bake.json` holds both figures. The
/// renderer warns of the FFT sea's `sea.fft.loop_period_s` the same way.
#[test]
fn a_loop_that_moves_the_waves_is_warned_of() {
    let dir = tempfile::tempdir().unwrap();
    let bake = |name: &str, period: &str| {
        let out = brine(&["bake", "-q", "-o", name, "--size", "16", "--loop-s", period], dir.path());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.path().join(name).join("bake.json")).unwrap()).unwrap();
        (String::from_utf8_lossy(&out.stderr).into_owned(), json["loop_distortion"].clone())
    };
    // The default sea (10 m/s, a peak period of about 7 s) looped every 2 s.
    let (err, short) = bake("short", "2");
    assert!(err.contains("warning: --loop-s = 2 s moves") && err.contains("at least"), "{err}");
    assert!(short["variance_share_moved_over_5_percent"].as_f64().unwrap() > 0.9, "{short}");
    let suggested = short["suggested_period_s"].as_f64().unwrap();
    assert!((50.0..300.0).contains(&suggested), "{short}");
    let (err, long) = bake("long", &format!("{}", suggested.ceil()));
    assert!(!err.contains("warning"), "{err}");
    assert!(long["variance_share_moved_over_5_percent"].as_f64().unwrap() <= 0.05, "{long}");
    assert!(long["frequency_change_rms"].as_f64().unwrap() < short["frequency_change_rms"].as_f64().unwrap());
    let out = brine(&["bake", "-q", "-o", "none", "--size", "16"], dir.path());
    assert!(out.status.success());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("none/bake.json")).unwrap()).unwrap();
    assert!(json["loop_distortion"].is_null(), "{json}");
    std::fs::write(
        dir.path().join("fft.toml"),
        "[camera]\nwidth = 8\nheight = 6\n[sea]\nsurface = \"fft\"\n[sea.fft]\nresolution = 64\nloop_period_s = 4\n",
    )
    .unwrap();
    let out = brine(&["render", "fft.toml", "-q", "-o", "fft.png"], dir.path());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && err.contains("warning: sea.fft.loop_period_s = 4 s moves"), "{err}");
    // An FFT sea baked without `--loop-s` loops at its own period, said as such.
    let out = brine(&["bake", "fft.toml", "-q", "-o", "fft", "--size", "16"], dir.path());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && err.contains("warning: sea.fft.loop_period_s = 4 s moves"), "{err}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("fft/bake.json")).unwrap()).unwrap();
    assert_eq!(json["loop_period_s"].as_f64(), Some(4.0), "{json}");
    assert!(json["loop_distortion"]["variance_share_moved_over_5_percent"].as_f64().unwrap() > 0.05, "{json}");
}

/// `brine mesh` says when its grid aliases waves and, with `--band-limit`, what it left out (the
/// FFT sea's modes too); the sine sea, whose short waves are normals, is refused with a message
/// and nothing written.
#[test]
fn a_mesh_says_which_waves_its_grid_cannot_carry() {
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| {
        let out = brine(args, dir.path());
        (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
    };
    let coarse = ["mesh", "-o", "sea.ply", "--size-m", "20", "--spacing-m", "2"];
    let (code, err) = run(&coarse);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("shorter than two spacings (4.000 m): the grid aliases them"), "{err}");
    let (code, err) = run(&[&coarse[..], &["--band-limit"]].concat());
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("those under 4.000 m left out"), "{err}");
    // The slope left out is printed, and is not nothing (waves of 4–6 m carry a good part).
    let lost: f64 = err.rsplit("mean-square slope ").next().unwrap().trim().parse().unwrap();
    assert!(lost > 1e-3, "{err}");
    let (code, err) = run(&["mesh", "-o", "fine.ply", "--size-m", "4", "--spacing-m", "0.1", "--band-limit"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("nothing left out") && !err.contains("note:"), "{err}");
    // The FFT sea: its modes too short for the grid alias, and --band-limit leaves them out.
    std::fs::write(dir.path().join("fft.toml"), "[sea]\nsurface = \"fft\"\n\n[sea.fft]\nresolution = 64\n").unwrap();
    let (code, err) = run(&["mesh", "fft.toml", "-o", "fft.ply", "--size-m", "20", "--spacing-m", "2"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("modes are shorter than two spacings (4.000 m): the grid aliases them"), "{err}");
    let (code, err) = run(&["mesh", "fft.toml", "-o", "fft.ply", "--size-m", "20", "--spacing-m", "2", "--band-limit"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("those under 4.000 m left out"), "{err}");
    // The sine sea's short waves are normals: nothing a grid can leave out.
    std::fs::write(dir.path().join("sine.toml"), "[sea]\nsurface = \"sine\"\n").unwrap();
    let (code, err) = run(&["mesh", "sine.toml", "-o", "sine.ply", "--band-limit"]);
    assert_eq!(code, Some(2));
    assert!(err.starts_with("error: --band-limit: the sine sea"), "{err}");
    assert!(!dir.path().join("sine.ply").exists());
}

/// `brine mesh --frames`: frame `f` of a sequence is the mesh `--time sea.time_s + f/fps` makes
/// alone, byte for byte (each frame's world is the one its instant alone builds); a path without
/// `#` is refused before anything is written.
#[test]
fn a_mesh_sequence_is_its_frames_made_alone() {
    let dir = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| {
        let out = brine(args, dir.path());
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    };
    let grid = ["--size-m", "8", "--spacing-m", "0.5", "--band-limit", "-q"];
    run(&[&["mesh", "-o", "sea_##.ply", "--frames", "2..4", "--time", "5"][..], &grid].concat());
    // 5 + 3/24, written as Rust writes the f64 (the shortest text that reads back the same).
    let t3 = format!("{}", 5.0 + 3.0 / 24.0);
    run(&[&["mesh", "-o", "alone.ply", "--time", &t3][..], &grid].concat());
    let read = |name: &str| std::fs::read(dir.path().join(name)).unwrap();
    assert!(read("sea_03.ply") == read("alone.ply"), "frame 3 of the sequence differs from the mesh made alone");
    assert!(read("sea_02.ply") != read("sea_03.ply"), "the sea did not move between frames");
    assert!(!dir.path().join("sea_04.ply").exists() && !dir.path().join("sea_01.ply").exists());
    let out = brine(&["mesh", "-o", "plain.ply", "--frames", "2"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("needs a run of # in the file name"));
    assert!(!dir.path().join("plain.ply").exists());
}

/// A key left at its default that another key's value puts out of range (a floor 0.5 m deep
/// holds trochoids of at most 0.25 m, the default amplitude is 0.4 m): the message says the
/// value is the default and points at the line of the key that set the bound.
#[test]
fn a_default_put_out_of_range_by_another_key_is_reported_at_that_key() {
    let (dir, code, err) = render_scene("[camera]\nwidth = 16\n\n[water.floor]\ndepth_m = 0.5\n");
    assert_eq!(code, Some(2));
    assert!(err.starts_with("error: scene.toml line 5: water.floor.amplitude_m = 0.4 is out of range"), "{err}");
    assert!(err.contains("is not in the file: that is its default"), "{err}");
    assert_nothing_written(dir.path());
}

/// A 16-bit PNG bake holds the values of the EXR bake, read as PNG readers read it (big-endian
/// samples) through `bake.json`'s encoding, within a quantisation step; and a sequence of the FFT
/// sea encodes every frame on that one range. (The samples were once written byte-swapped; and
/// the FFT sea's height bound changes from frame to frame, and the range was the running maximum
/// of the bounds, so that the first frames were encoded on a smaller range than the one written.)
#[test]
fn a_png_bake_holds_the_exr_bake_on_one_encoding() {
    let dir = tempfile::tempdir().unwrap();
    let scene = "[sea]\nsurface = \"fft\"\n[sea.fft]\nresolution = 64\ncascades = 2\n[animation]\nfps = 1.0\n";
    std::fs::write(dir.path().join("fft.toml"), scene).unwrap();
    for (name, frames, png) in [("seq", "0..4", true), ("one", "0..1", true), ("exr", "0..1", false)] {
        let mut args = vec!["bake", "fft.toml", "-q", "-o", name, "--size", "16", "--frames", frames];
        args.extend(png.then_some("--png16"));
        let out = brine(&args, dir.path());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let decode = |name: &str| -> (f64, Vec<f64>) {
        let meta: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.path().join(name).join("bake.json")).unwrap()).unwrap();
        let e = &meta["png16_encodings"]["displacement"];
        let (offset, scale) = (e["offset"].as_f64().unwrap(), e["scale"].as_f64().unwrap());
        let map = image::open(dir.path().join(name).join("displacement_0000.png")).unwrap().into_rgb16();
        (scale / 65535.0, map.as_raw().iter().map(|&c| offset + scale * f64::from(c) / 65535.0).collect())
    };
    let ((step_seq, seq), (step_one, one)) = (decode("seq"), decode("one"));
    let image = exr::prelude::read_all_flat_layers_from_file(dir.path().join("exr/displacement_0000.exr")).unwrap();
    let layer = &image.layer_data[0];
    let channel = |name: &str| -> Vec<f32> {
        let c = layer.channel_data.list.iter().find(|c| c.name.to_string() == name).expect(name);
        match &c.sample_data {
            exr::prelude::FlatSamples::F32(v) => v.clone(),
            other => panic!("{name}: {other:?}"),
        }
    };
    let (r, g, b) = (channel("R"), channel("G"), channel("B"));
    let exact: Vec<f64> = (0..r.len()).flat_map(|k| [r[k], g[k], b[k]]).map(f64::from).collect();
    assert_eq!(exact.len(), one.len());
    // Half a step of rounding, and the f32 maps' rounding far below it.
    for (k, (e, p)) in exact.iter().zip(&one).enumerate() {
        assert!((e - p).abs() <= 0.5 * step_one + 1e-5, "sample {k}: EXR {e} m, PNG {p} m");
    }
    assert!(step_seq > step_one, "a later frame of the sequence reaches higher than frame 0");
    for (e, p) in exact.iter().zip(&seq) {
        assert!((e - p).abs() <= 0.5 * step_seq + 1e-5, "frame 0: EXR {e} m, the sequence's PNG {p} m");
    }
}

/// A 16-bit displacement map holds the horizontal displacement too, which the height bound does
/// not (a sea of two trochoids moves 2.0 m sideways and 0.9 m up and down: on a range set by the
/// height bound, 1 900 of 4 096 texels were once clipped, in silence); and a value no encoding
/// holds (a Jacobian beyond the `[−1, 3]` of its encoding, on a very choppy sea) is refused with
/// a message naming the frame, nothing written.
#[test]
fn a_png_bake_holds_its_values_or_says_which_it_cannot() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("two.toml"), "[sea]\nwaves = 2\n").unwrap();
    for (name, png) in [("png", true), ("exr", false)] {
        let mut args = vec!["bake", "two.toml", "-q", "-o", name, "--size", "16"];
        args.extend(png.then_some("--png16"));
        let out = brine(&args, dir.path());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let meta: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("png/bake.json")).unwrap()).unwrap();
    let e = &meta["png16_encodings"]["displacement"];
    let (offset, scale) = (e["offset"].as_f64().unwrap(), e["scale"].as_f64().unwrap());
    let map = image::open(dir.path().join("png/displacement_0000.png")).unwrap().into_rgb16();
    let image = exr::prelude::read_all_flat_layers_from_file(dir.path().join("exr/displacement_0000.exr")).unwrap();
    let channel = |name: &str| {
        let c = image.layer_data[0].channel_data.list.iter().find(|c| c.name.to_string() == name).expect(name);
        let exr::prelude::FlatSamples::F32(v) = &c.sample_data else { panic!("f32 samples") };
        v.clone()
    };
    let (x, y) = (channel("R"), channel("G"));
    let largest = |v: &[f32]| v.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    assert!(largest(&x) > 2.0 * largest(&y), "the sea moves sideways more than up and down");
    for (k, v) in x.iter().enumerate() {
        let decoded = offset + scale * f64::from(map.as_raw()[3 * k]) / 65535.0;
        assert!(
            (decoded - f64::from(*v)).abs() <= 0.5 * scale / 65535.0 + 1e-5,
            "texel {k}: EXR {v} m, PNG {decoded} m"
        );
    }
    // Frame 0 fits; one texel of frame 1 has J = 3.25: the sequence is refused before frame 0 is
    // written (it was once refused after, leaving frame 0's maps without `bake.json`).
    let choppy = "[sea]\nsurface = \"fft\"\nwind_speed_m_s = 30.0\n[sea.fft]\nresolution = 64\nchoppiness = 4\n\
                  [animation]\nfps = 1.0\n";
    std::fs::write(dir.path().join("choppy.toml"), choppy).unwrap();
    let out = brine(
        &["bake", "choppy.toml", "-q", "-o", "choppy", "--size", "512", "--frames", "0..3", "--png16"],
        dir.path(),
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("frame 1: jacobian") && stderr.contains("without --png16"), "{stderr}");
    assert!(std::fs::read_dir(dir.path().join("choppy")).map_or(true, |mut d| d.next().is_none()), "nothing written");
}
