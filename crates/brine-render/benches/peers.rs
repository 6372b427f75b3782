//! `cargo xtask bench peers`: Brine against the mesh route a user would pick instead — the same
//! sea as a camera-adaptive mesh (the same camera, the same footprint fade), built and traced by
//! Mitsuba 3 (`llvm_ad_rgb`, its BVH), at an accuracy matched on Brine's own depth AOV.
//!
//! The scene is the frame bench's (640×480, 100 waves, every phenomenon, 1 spp). Brine's times are
//! whole frames (world and shading included); Mitsuba's are its scene load (BVH build) and one
//! 1-spp pass of its depth AOV integrator (intersection only, no shading). Per animation frame the
//! mesh route also regenerates the mesh (`camera_mesh`), which is timed here too.
//!
//! Mitsuba runs in a Python virtual environment this bench makes under `target/peers/venv`
//! (`pip install mitsuba==3.9.1 numpy`); where it cannot be made the bench says so and stops.

#[path = "common/mod.rs"]
mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use brine_render::cli::render::scene_at_frame;
use brine_render::export::{camera_mesh, write_mesh};
use brine_render::{RenderOptions, Timeless, World, render_world};
use brine_testkit::timing::median;

/// Runs per timing; the median is reported (this 2-core machine spreads by about ±10 %).
const RUNS: usize = 3;

/// Footprints per mesh edge tried, coarse to fine; the table reports each, and the ratios use the
/// coarsest that meets [`MATCHED_P99_M`].
const PIXELS: [f64; 5] = [2.0, 1.0, 0.5, 0.25, 0.125];

/// The accuracy the mesh must reach: over the pixels within [`MATCHED_RANGE_M`], 99 % of the
/// mesh's hit points within 5 mm (vertically) of Brine's surface: `|Δdepth| |d_y|`, the depth
/// difference along the pixel's ray times the ray's vertical component. (The depth difference
/// itself grows as `1/|d_y|` at grazing angles, 15× at 150 m here, whatever the surfaces.)
const MATCHED_P99_M: f64 = 0.005;

/// Range over which the accuracy is matched (m).
const MATCHED_RANGE_M: f64 = 150.0;

/// The near range the depth difference itself is also given for (m).
const NEAR_RANGE_M: f64 = 30.0;

/// Mitsuba's version, pinned.
const MITSUBA: &str = "mitsuba==3.9.1";

fn seconds(f: impl Fn()) -> f64 {
    let v: Vec<f64> = (0..RUNS)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .collect();
    median(v)
}

/// The venv's Python with Mitsuba, made on first use; `Err` says why not.
fn mitsuba_python(dir: &Path) -> Result<PathBuf, String> {
    let venv = dir.join("venv");
    let python = venv.join("bin").join("python");
    let has = |p: &Path| {
        Command::new(p).args(["-c", "import mitsuba, numpy"]).output().map(|o| o.status.success()).unwrap_or(false)
    };
    if python.exists() && has(&python) {
        return Ok(python);
    }
    let made = Command::new("python3").args(["-m", "venv"]).arg(&venv).status();
    if !made.map(|s| s.success()).unwrap_or(false) {
        return Err("python3 -m venv failed (is python3 with venv installed?)".into());
    }
    let pip = venv.join("bin").join("pip");
    let installed = Command::new(&pip).args(["install", "--quiet", MITSUBA, "numpy"]).status();
    if !installed.map(|s| s.success()).unwrap_or(false) {
        return Err(format!("pip install {MITSUBA} numpy failed (no wheel for this platform, or no network)"));
    }
    if has(&python) { Ok(python) } else { Err("mitsuba installed but does not import".into()) }
}

fn main() {
    let scene = common::reference_frame_scene();
    let threads = rayon::current_num_threads();
    println!(
        "peers: Brine against Mitsuba 3 on the mesh of the same sea (640×480, 100 waves, 1 spp, {threads} threads)"
    );

    // Brine: whole frames, a still and animation frames. An animation builds what does not change
    // with time once (`Timeless`, its cost shared by the frames of a 24-frame animation) and the
    // rest per frame, at another instant each.
    let frames = 24;
    let still = seconds(|| {
        let world = World::new(&scene).expect("valid");
        render_world(&scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
    });
    let t = Instant::now();
    let timeless = Timeless::new(&scene, None).expect("valid");
    let shared = t.elapsed().as_secs_f64() / f64::from(frames);
    let mut k = 0u32;
    let animated = {
        let v: Vec<f64> = (0..RUNS)
            .map(|_| {
                k += 1;
                let s = scene_at_frame(&scene, k, (0, frames), None).expect("a frame");
                let t = Instant::now();
                let world = World::at_instant(&s, &timeless).expect("valid");
                render_world(&s, &world, &RenderOptions::default(), &|| {}).expect("renders");
                t.elapsed().as_secs_f64() + shared
            })
            .collect();
        median(v)
    };
    println!("Brine whole frame: still {still:.3} s, animation frame {animated:.3} s (medians of {RUNS})");

    // The reference depth, the camera and the meshes for Mitsuba.
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target/peers");
    std::fs::create_dir_all(&dir).expect("target/peers");
    let world = World::new(&scene).expect("valid");
    let frame = render_world(&scene, &world, &RenderOptions::default(), &|| {}).expect("renders");
    let depth: Vec<u8> = frame.aovs.iter().flat_map(|a| a.depth.to_le_bytes()).collect();
    std::fs::write(dir.join("depth.f32"), depth).expect("depth");
    let cam = world.camera();
    let fov_deg = 2.0 * cam.tan_half_fov.atan().to_degrees();
    let camera = serde_json::json!({
        "position": cam.position.to_array(),
        "forward": cam.forward.to_array(),
        "up": cam.up.to_array(),
        "right": cam.right.to_array(),
        "fov_y_deg": fov_deg,
        "width": cam.width,
        "height": cam.height,
    });
    std::fs::write(dir.join("camera.json"), camera.to_string()).expect("camera");
    let t = scene.sea.time_s;
    let mut meshes = Vec::new();
    for p in PIXELS {
        let build = seconds(|| {
            std::hint::black_box(camera_mesh(&world, t, p, true));
        });
        let mesh = camera_mesh(&world, t, p, true);
        let path = dir.join(format!("sea_{p}.ply"));
        write_mesh(&path, &mesh).expect("mesh written");
        meshes.push((p, mesh.indices.len() / 3, build, path));
    }

    let python = match mitsuba_python(&dir) {
        Ok(p) => p,
        Err(why) => {
            println!("Mitsuba 3: skipped — {why}");
            return;
        }
    };
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("benches/peers_mitsuba.py");
    let mut cmd = Command::new(&python);
    cmd.arg(&script).arg(dir.join("camera.json")).arg(dir.join("depth.f32")).arg(RUNS.to_string());
    cmd.arg(format!("{NEAR_RANGE_M},{MATCHED_RANGE_M}"));
    for (_, _, _, path) in &meshes {
        cmd.arg(path);
    }
    let out = cmd.output().expect("python runs");
    if !out.status.success() {
        println!("Mitsuba 3: failed — {}", String::from_utf8_lossy(&out.stderr));
        return;
    }
    let stdout = String::from_utf8_lossy(&out.stdout);
    let last = stdout.lines().last().unwrap_or("");
    let results: Vec<serde_json::Value> = serde_json::from_str(last).expect("the script's last line is JSON");
    println!();
    println!(
        "| mesh (footprints per edge) | triangles | mesh build | Mitsuba load | Mitsuba trace | p99 depth difference within {NEAR_RANGE_M} m | p99 height difference within {MATCHED_RANGE_M} m | still: Brine faster by | animation frame: Brine faster by |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let mut chosen = None;
    for ((p, tris, build, _), r) in meshes.iter().zip(&results) {
        let load = r["load_s"].as_f64().unwrap_or(f64::NAN);
        let trace = r["trace_s"].as_f64().unwrap_or(f64::NAN);
        let near = r["depth_p99_m"][0].as_f64().unwrap_or(f64::NAN);
        let p99 = r["height_p99_m"][1].as_f64().unwrap_or(f64::NAN);
        let static_ratio = (load + trace) / still;
        let anim_ratio = (build + load + trace) / animated;
        println!(
            "| {p} | {:.2} M | {build:.2} s | {load:.2} s | {trace:.2} s | {:.1} mm | {:.1} mm | {static_ratio:.2}× | {anim_ratio:.2}× |",
            *tris as f64 / 1e6,
            near * 1e3,
            p99 * 1e3
        );
        if chosen.is_none() && p99 <= MATCHED_P99_M {
            chosen = Some((*p, static_ratio, anim_ratio));
        }
    }
    match chosen {
        Some((p, s, a)) => println!(
            "\nmatched accuracy ({} mm p99 within {MATCHED_RANGE_M} m) from {p} footprints per edge: Brine is {s:.2}× faster for a still (goal ≥ 5×), {a:.2}× per animation frame (goal ≥ 10×)",
            MATCHED_P99_M * 1e3
        ),
        None => {
            println!("\nno mesh tried reached {} mm p99: the ratios above are at lower accuracy", MATCHED_P99_M * 1e3)
        }
    }
}
