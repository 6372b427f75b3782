//! The same scene gives the same bytes whatever the number of threads.

use brine_render::scene::{GridMode, SurfaceKind};
use brine_render::{RenderOptions, Scene, render, write_image};

#[test]
fn one_and_two_threads_write_identical_files() {
    // The trochoid sea with every wave traced, then with its shorter waves on grids (filled
    // band by band on the threads), and the FFT sea.
    for (surface, grid) in [
        (SurfaceKind::Trochoids, GridMode::Off),
        (SurfaceKind::Trochoids, GridMode::On),
        (SurfaceKind::Fft, GridMode::Auto),
    ] {
        same_bytes_at_one_and_two_threads(surface, grid);
    }
}

fn same_bytes_at_one_and_two_threads(surface: SurfaceKind, grid: GridMode) {
    let mut scene = Scene::default_scene();
    scene.sea.surface = surface;
    scene.sea.grid = grid;
    scene.sea.fft.resolution = 64;
    scene.camera.width = 64;
    scene.camera.height = 36;
    scene.camera.spp = 2;
    let dir = tempfile::tempdir().unwrap();
    let mut bytes = Vec::new();
    for threads in [1, 2] {
        let frame =
            render(&scene, &RenderOptions { threads: Some(threads), ..RenderOptions::default() }, &|| {}).unwrap();
        for ext in ["png", "exr"] {
            let path = dir.path().join(format!("t{threads}.{ext}"));
            write_image(&path, frame.width, frame.height, &frame.pixels, frame.exposure_ev).unwrap();
            bytes.push(std::fs::read(path).unwrap());
        }
    }
    assert!(bytes[0] == bytes[2], "{surface:?}, grid {grid:?}: PNG bytes differ between 1 and 2 threads");
    assert!(bytes[1] == bytes[3], "{surface:?}, grid {grid:?}: EXR bytes differ between 1 and 2 threads");
}
