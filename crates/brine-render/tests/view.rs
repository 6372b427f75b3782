//! `brine view` in a real window under Xvfb: the window opens, its screenshot shows sky over
//! sea, scripted mouse input turns the camera and changes the image, "save" writes a scene that
//! `brine render` reads. Skipped with a message where Xvfb is not installed, unless
//! `BRINE_VIEW_TESTS=require` (CI installs Xvfb and sets it).
#![cfg(feature = "view")]

use std::path::Path;
use std::process::Command;

/// Whether `xvfb-run` is on the path; fails when the tests are required and it is not.
fn xvfb() -> bool {
    let found = Command::new("sh").args(["-c", "command -v xvfb-run"]).output().is_ok_and(|o| o.status.success());
    if !found {
        assert!(
            std::env::var("BRINE_VIEW_TESTS").as_deref() != Ok("require"),
            "BRINE_VIEW_TESTS=require but xvfb-run is not installed"
        );
        eprintln!("skipped: xvfb-run is not installed (Debian: apt-get install xvfb xauth)");
    }
    found
}

/// Runs `brine view` on `scene` under Xvfb with `script`; returns its standard error.
fn view(dir: &Path, scene: &Path, script: &str) -> String {
    let script_path = dir.join("script.txt");
    std::fs::write(&script_path, script).expect("script written");
    let out = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1280x800x24"])
        .arg(env!("CARGO_BIN_EXE_brine"))
        .arg("view")
        .arg(scene)
        .args(["--width", "200", "--height", "150", "--stats", "--script"])
        .arg(&script_path)
        .current_dir(dir)
        .output()
        .expect("xvfb-run runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "brine view failed: {stderr}");
    stderr
}

/// A screenshot's image area and its rows' mean colours.
struct Shot {
    rows: Vec<[f64; 3]>,
}

impl Shot {
    /// The rows of the part of the window right of the controls that is not the panel's flat
    /// background (the image, wherever the layout put it).
    fn read(path: &Path) -> Self {
        let img = image::open(path).expect("a PNG").to_rgb8();
        let (w, h) = img.dimensions();
        let background = *img.get_pixel(w - 1, h - 1);
        let x0 = w / 2;
        let mut rows = Vec::new();
        for y in 0..h {
            let px: Vec<[f64; 3]> = (x0..w)
                .map(|x| *img.get_pixel(x, y))
                .filter(|p| p.0.iter().zip(background.0).any(|(a, b)| a.abs_diff(b) > 3))
                .map(|p| p.0.map(f64::from))
                .collect();
            // A row of the image spans most of the columns.
            if px.len() as u32 > (w - x0) / 2 {
                let n = px.len() as f64;
                rows.push([0, 1, 2].map(|c| px.iter().map(|p| p[c]).sum::<f64>() / n));
            }
        }
        assert!(rows.len() > 50, "{}: no image found in the window", path.display());
        Self { rows }
    }

    /// The horizon: the row after which the mean brightness drops most.
    fn horizon(&self) -> usize {
        let l = |r: &[f64; 3]| r[0] + r[1] + r[2];
        (0..self.rows.len() - 1)
            .max_by(|&a, &b| {
                (l(&self.rows[a]) - l(&self.rows[a + 1])).total_cmp(&(l(&self.rows[b]) - l(&self.rows[b + 1])))
            })
            .expect("rows")
    }

    /// Mean colour of rows `a..b`.
    fn mean(&self, a: usize, b: usize) -> [f64; 3] {
        let n = (b - a) as f64;
        [0, 1, 2].map(|c| self.rows[a..b].iter().map(|r| r[c]).sum::<f64>() / n)
    }
}

#[test]
fn the_window_shows_sky_and_sea_and_follows_the_mouse() {
    if !xvfb() {
        return;
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut scene = brine_render::Scene::default_scene();
    scene.sea.waves = Some(24);
    (scene.camera.width, scene.camera.height) = (160, 90);
    scene.output.path = "rendered.png".into();
    let scene_path = dir.path().join("scene.toml");
    std::fs::write(&scene_path, scene.to_toml("scene.toml").expect("a valid scene")).expect("scene written");
    let stderr = view(
        dir.path(),
        &scene_path,
        "settle\nscreenshot a.png\ndrag 0 -50 1\nsettle\nscreenshot b.png\nsave saved.toml\nrender\nquit\n",
    );
    assert!(stderr.contains("first image"), "{stderr}");

    // A smooth sky above the horizon, brighter than the sea below it, whose waves make its rows
    // differ from one to the next.
    let a = Shot::read(&dir.path().join("a.png"));
    let h = a.horizon();
    let n = a.rows.len();
    assert!(h > n / 10 && h < n * 9 / 10, "horizon at row {h} of {n}");
    let (sky, sea) = (a.mean(0, h), a.mean(h + 2, n));
    assert!(sky.iter().sum::<f64>() > sea.iter().sum::<f64>(), "sky {sky:?} sea {sea:?}");
    let roughness = |r: std::ops::Range<usize>| {
        r.clone().map(|y| (0..3).map(|c| (a.rows[y + 1][c] - a.rows[y][c]).abs()).sum::<f64>()).sum::<f64>()
            / r.len() as f64
    };
    let (sky_rough, sea_rough) = (roughness(1..h - 1), roughness(h + 2..n - 1));
    assert!(sea_rough > sky_rough, "row-to-row change: sky {sky_rough}, sea {sea_rough}");

    // Dragging up by 50 points orbits the camera up, looking down more steeply: the horizon
    // rises and the image changes.
    let b = Shot::read(&dir.path().join("b.png"));
    assert!(b.horizon() + 5 < h, "horizon {} then {}", h, b.horizon());

    // The saved scene is the dragged view, and renders.
    let saved = brine_render::Scene::load(&dir.path().join("saved.toml")).expect("a valid scene file");
    let pitch = saved.camera.pitch_deg.expect("angles");
    assert!(pitch < brine_render::Scene::DEFAULT_PITCH_DEG - 1.0, "pitch {pitch}");
    assert_eq!(saved.sea, scene.sea);
    assert!(saved.camera.position[1] > scene.camera.position[1], "the camera rose");

    // The Render button wrote the output image at the output's size.
    let written = image::open(dir.path().join(&scene.output.path)).expect("the rendered image");
    assert_eq!((written.width(), written.height()), (scene.camera.width, scene.camera.height));
}

#[test]
fn without_a_display_the_viewer_says_so() {
    let out = Command::new(env!("CARGO_BIN_EXE_brine"))
        .arg("view")
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .expect("brine runs");
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("needs a display") && stderr.contains("xvfb-run"), "{stderr}");
}

#[test]
fn a_bad_script_names_its_line() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let script = dir.path().join("bad.txt");
    std::fs::write(&script, "wait 1\nfly 3\n").expect("script written");
    let out =
        Command::new(env!("CARGO_BIN_EXE_brine")).arg("view").arg("--script").arg(&script).output().expect("runs");
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("bad.txt") && stderr.contains("line 2") && stderr.contains("fly"), "{stderr}");
}
