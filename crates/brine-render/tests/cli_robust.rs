//! The `brine` command where a sweep of random and broken scenes found it wanting: outputs that
//! cannot be written refused before the render, signals that leave no temporary file, `--resume`
//! that trusts only complete frames, flags checked and named as typed.

use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Duration;

fn brine(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).args(args).current_dir(dir).output().expect("brine runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A scene that renders in a few milliseconds.
const TINY: &str = "[camera]\nwidth = 8\nheight = 6\n[phenomena]\nglare = false\n";

fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".tmp"))
        .collect()
}

#[test]
fn an_output_that_cannot_be_written_is_refused_before_the_render() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), TINY).unwrap();
    std::fs::create_dir(dir.path().join("folder.png")).unwrap();
    for (out, says) in [
        ("folder.png", "it is a folder"),
        ("missing/x.png", "does not exist"),
        ("/proc/x.png", "cannot create a file in /proc"),
        ("/sys/x.exr", "cannot create a file in /sys"),
    ] {
        let o = brine(&["render", "scene.toml", "-o", out, "--quiet"], dir.path());
        assert_eq!(o.status.code(), Some(2), "{out}: {}", stderr(&o));
        assert!(stderr(&o).contains(says), "{out}: {}", stderr(&o));
    }
    assert!(temporaries(dir.path()).is_empty());
}

#[test]
fn aovs_with_the_default_path_and_an_exr_on_the_command_line_render() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), format!("{TINY}[output]\naovs = true\n")).unwrap();
    let o = brine(&["render", "scene.toml", "-o", "x.exr", "--quiet"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(dir.path().join("x.exr").exists());
    // Without -o the default ocean.png cannot hold them: refused with the file named.
    let o = brine(&["render", "scene.toml", "--quiet"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).starts_with("error: scene.toml line 7: output.aovs = true needs an .exr output"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn long_fetches_and_the_largest_wave_sets_render() {
    let dir = tempfile::tempdir().unwrap();
    for scene in [
        "[sea]\nspectrum = \"jonswap\"\nfetch_km = 10001.0\n",
        "[sea]\nspectrum = \"tma\"\ndepth_m = 40.0\nfetch_km = 100000.0\n",
    ] {
        std::fs::write(dir.path().join("scene.toml"), format!("{TINY}{scene}")).unwrap();
        let o = brine(&["render", "scene.toml", "-o", "x.png", "--quiet"], dir.path());
        assert_eq!(o.status.code(), Some(0), "{scene}: {}", stderr(&o));
    }
}

/// Sends `signal` to the process.
fn kill(pid: u32, signal: &str) {
    Command::new("kill").args([signal, &pid.to_string()]).status().expect("kill runs");
}

/// Animations of tiny frames spend much of their time writing: signals during them must leave no
/// temporary file (before, 12 kills of 12 left a 0-byte `.f_NNN.png.XXXXXX.tmp`), and every frame
/// on disk is complete.
#[test]
fn a_signal_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), TINY).unwrap();
    let mut runs = 0;
    for (k, (signal, ext)) in
        [("-TERM", "png"), ("-INT", "exr"), ("-INT", "png"), ("-TERM", "exr")].iter().cycle().take(8).enumerate()
    {
        let out = dir.path().join(format!("run{k}"));
        std::fs::create_dir(&out).unwrap();
        let pattern = format!("run{k}/f_###.{ext}");
        let mut child = Command::new(env!("CARGO_BIN_EXE_brine"))
            .args(["render", "scene.toml", "--frames", "0..2000", "-o", &pattern, "--quiet"])
            .current_dir(dir.path())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        // Let it write some frames first (the world of each frame takes tens of milliseconds).
        std::thread::sleep(Duration::from_millis(400 + 97 * k as u64));
        kill(child.id(), signal);
        let status = child.wait().unwrap();
        assert!(!status.success(), "the render was stopped");
        assert_eq!(temporaries(&out), Vec::<String>::new(), "run {k} ({signal}, {ext})");
        for e in std::fs::read_dir(&out).unwrap() {
            let p = e.unwrap().path();
            assert!(brine_render::output::decodes_completely(&p), "{} is not a complete image", p.display());
        }
        runs += 1;
    }
    assert_eq!(runs, 8);
}

#[test]
fn resume_makes_again_the_frames_that_do_not_decode_and_removes_stale_temporaries() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), TINY).unwrap();
    let o = brine(&["render", "scene.toml", "--frames", "0..4", "-o", "f_#.png", "--quiet"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let good = std::fs::read(dir.path().join("f_3.png")).unwrap();
    // Frame 0 truncated, frame 1 empty, frame 2 missing with a temporary left by a SIGKILL.
    let f0 = std::fs::read(dir.path().join("f_0.png")).unwrap();
    std::fs::write(dir.path().join("f_0.png"), &f0[..f0.len() / 2]).unwrap();
    std::fs::write(dir.path().join("f_1.png"), b"").unwrap();
    std::fs::remove_file(dir.path().join("f_2.png")).unwrap();
    std::fs::write(dir.path().join(".f_2.png.Ab12Cd.tmp"), b"").unwrap();
    // Someone else's file of a similar name is left alone.
    std::fs::write(dir.path().join(".f_2.png.notes.tmp"), b"mine").unwrap();
    let o = brine(&["render", "scene.toml", "--frames", "0..4", "-o", "f_#.png", "--resume"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("3 frames (1 skipped)"), "{}", stderr(&o));
    for f in 0..4 {
        assert!(brine_render::output::decodes_completely(&dir.path().join(format!("f_{f}.png"))), "frame {f}");
    }
    assert_eq!(std::fs::read(dir.path().join("f_3.png")).unwrap(), good, "the complete frame is kept");
    assert_eq!(std::fs::read(dir.path().join("f_0.png")).unwrap(), f0, "frame 0 made again, the same bytes");
    assert_eq!(temporaries(dir.path()), vec![".f_2.png.notes.tmp".to_owned()]);
}

#[test]
fn sky_flags_are_checked_and_named() {
    let dir = tempfile::tempdir().unwrap();
    let base = ["sky", "--sun-elevation-deg", "30", "--json"];
    for (flag, value, says) in [
        ("--clouds", "nan", "--clouds"),
        ("--clouds", "-0.1", "--clouds"),
        ("--moon-elevation-deg", "91", "--moon-elevation-deg"),
        ("--view-elevation-deg", "91", "--view-elevation-deg"),
        ("--view-elevation-deg", "nan", "--view-elevation-deg"),
        ("--view-azimuth-deg", "nan", "--view-azimuth-deg"),
        ("--exposure-ev", "nan", "--exposure-ev"),
        ("--exposure-ev", "1e308", "--exposure-ev"),
        ("--sun-azimuth-deg", "inf", "--sun-azimuth-deg"),
        ("--out", "/missing/s.png", "--out"),
    ] {
        let mut args: Vec<&str> = base.to_vec();
        let typed = format!("{flag}={value}");
        args.push(&typed);
        if flag == "--moon-elevation-deg" {
            args.extend(["--moon-azimuth-deg", "10"]);
        }
        let o = brine(&args, dir.path());
        assert_eq!(o.status.code(), Some(2), "{flag} {value}: {}", stderr(&o));
        assert!(stderr(&o).contains(says), "{flag} {value}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{flag} {value}: printed {:?}", String::from_utf8_lossy(&o.stdout));
    }
}

#[test]
fn model_errors_name_the_flags_typed() {
    let dir = tempfile::tempdir().unwrap();
    let o = brine(&["foam", "--u10", "10", "--t-water-c", "50", "--t-air-c", "10"], dir.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).starts_with("error: --t-water-c = 50 is out of range"), "{}", stderr(&o));
    let o = brine(&["foam", "--u10", "70"], dir.path());
    assert!(stderr(&o).starts_with("error: --u10 = 70 is out of range"), "{}", stderr(&o));
    let o = brine(&["sun", "--lat", "95", "--lon", "0", "--time", "2024-01-01T00:00:00Z"], dir.path());
    assert!(stderr(&o).starts_with("error: --lat = 95 is out of range"), "{}", stderr(&o));
}

#[test]
fn the_camera_mesh_spacing_is_checked_and_named() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.toml"), TINY).unwrap();
    for value in ["0.1", "65", "nan"] {
        let typed = format!("--pixels={value}");
        let o = brine(&["mesh", "scene.toml", "-o", "m.glb", "--camera", &typed, "-q"], dir.path());
        assert_eq!(o.status.code(), Some(2), "{value}: {}", stderr(&o));
        assert!(stderr(&o).contains("--pixels"), "{value}: {}", stderr(&o));
        assert!(!dir.path().join("m.glb").exists());
    }
    // The finest spacing the layout allows (⅛ footprint) is accepted: a tiny camera's mesh.
    let o = brine(&["mesh", "scene.toml", "-o", "m.glb", "--camera", "--pixels", "0.125", "-q"], dir.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(dir.path().join("m.glb").exists());
    assert!(temporaries(dir.path()).is_empty());
}
