//! brine-render's `Camera` is brine-texture's `Pinhole`, built from a scene's `[camera]` by
//! `camera::from_config` and by `brine texture` from its angles (`Pinhole::from_angles`): for the
//! same yaw, pitch, field of view and image size both routes give the same frame and the same ray
//! through every pixel, so `brine texture` and `brine render` frame a scene identically.

use brine_render::camera::Camera;
use brine_render::scene::CameraConfig;
use brine_texture::Pinhole;
use glam::DVec3;
use proptest::prelude::*;

/// Largest difference allowed between the two cameras' unit ray directions (and frame vectors).
/// Both evaluate the same closed forms (`sin`, `cos`, `tan`, one cross product, one
/// normalisation) in `f64`: identical code gives identical bits, and a reordering of the same
/// operations moves a unit vector by a few ulps (~10⁻¹⁶). 10⁻¹² leaves room for that and is still
/// far below any real difference (a different convention — yaw sign, image-up rule, horizontal
/// field of view — moves rays by 10⁻³ or more).
const SAME_RAY: f64 = 1e-12;

/// Both cameras for one setting.
fn both(position: [f64; 3], yaw_deg: f64, pitch_deg: f64, fov_deg: f64, width: u32, height: u32) -> (Camera, Pinhole) {
    let config = CameraConfig {
        position,
        look_at: None,
        yaw_deg: Some(yaw_deg),
        pitch_deg: Some(pitch_deg),
        fov_deg,
        width,
        height,
        spp: 1,
    };
    let render = brine_render::camera::from_config(&config);
    let texture =
        Pinhole::from_angles(DVec3::from_array(position), yaw_deg, pitch_deg, fov_deg, width, height).unwrap();
    (render, texture)
}

/// Compares the frames, the pixel angle and the rays through every pixel centre and the four image
/// corners; returns the largest ray difference.
fn assert_same(render: &Camera, texture: &Pinhole, what: &str) -> f64 {
    assert_eq!((render.width, render.height), (texture.width, texture.height), "{what}: size");
    assert_eq!(render.position, texture.position, "{what}: position");
    for (name, a, b) in [
        ("forward", render.forward, texture.forward),
        ("right", render.right, texture.right),
        ("up", render.up, texture.up),
    ] {
        assert!((a - b).length() <= SAME_RAY, "{what}: {name} {a} vs {b}");
    }
    assert!((render.tan_half_fov - texture.tan_half_fov).abs() <= SAME_RAY * render.tan_half_fov, "{what}: fov");
    assert!((render.pixel_angle() - texture.pixel_angle()).abs() <= SAME_RAY * render.pixel_angle(), "{what}");
    let (w, h) = (f64::from(render.width), f64::from(render.height));
    let mut worst = 0.0f64;
    let mut check = |x: f64, y: f64| {
        let (a, b) = (render.direction(x, y), texture.direction(x, y));
        let d = (a - b).length();
        assert!(d <= SAME_RAY, "{what}: ray through ({x}, {y}): {a} vs {b}");
        worst = worst.max(d);
    };
    for j in 0..render.height {
        for i in 0..render.width {
            check(f64::from(i) + 0.5, f64::from(j) + 0.5);
        }
    }
    for (x, y) in [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)] {
        check(x, y);
    }
    worst
}

#[test]
fn pinhole_and_camera_give_the_same_ray_through_every_pixel() {
    // (yaw °, pitch °, vertical fov °, width, height): the renderer's default view, the
    // cardinal bearings, bearings past 360° and negative, straight up and straight down (north
    // is the image's up), a narrow and a very wide field, portrait, landscape and 1-pixel images.
    let settings: [(f64, f64, f64, u32, u32); 12] = [
        (100.0, -9.0, 50.0, 64, 36),
        (0.0, 0.0, 60.0, 32, 32),
        (90.0, -30.0, 45.0, 40, 30),
        (180.0, 12.0, 20.0, 17, 23),
        (270.0, -60.0, 90.0, 50, 20),
        (225.0, -25.0, 55.0, 48, 40),
        (-45.0, 5.0, 10.0, 21, 9),
        (725.0, -89.0, 150.0, 30, 31),
        (33.0, -90.0, 20.0, 25, 25),
        (200.0, 90.0, 70.0, 16, 24),
        (10.0, -45.0, 179.0, 8, 8),
        (300.0, -15.0, 1.0, 1, 1),
    ];
    for (yaw, pitch, fov, w, h) in settings {
        let (render, texture) = both([1.5, 8.0, -3.25], yaw, pitch, fov, w, h);
        assert_same(&render, &texture, &format!("yaw {yaw}, pitch {pitch}, fov {fov}, {w}×{h}"));
    }
}

#[test]
fn the_comparison_can_fail() {
    // A camera turned by 0.01° or with a field of view 0.01° wider is told apart.
    let (render, _) = both([0.0, 5.0, 0.0], 120.0, -20.0, 40.0, 32, 24);
    for (yaw, fov) in [(120.01, 40.0), (120.0, 40.01)] {
        let other = Pinhole::from_angles(DVec3::new(0.0, 5.0, 0.0), yaw, -20.0, fov, 32, 24).unwrap();
        let d = (render.direction(0.5, 0.5) - other.direction(0.5, 0.5)).length();
        assert!(d > 1e3 * SAME_RAY, "yaw {yaw}, fov {fov}: {d}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_settings_give_the_same_rays(
        yaw in -720.0f64..720.0,
        pitch in -90.0f64..=90.0,
        fov in 0.5f64..179.5,
        w in 1u32..40,
        h in 1u32..40,
        x in -100.0f64..100.0,
        y in 0.5f64..500.0,
        z in -100.0f64..100.0,
    ) {
        let (render, texture) = both([x, y, z], yaw, pitch, fov, w, h);
        assert_same(&render, &texture, &format!("yaw {yaw}, pitch {pitch}, fov {fov}, {w}×{h}"));
    }
}
