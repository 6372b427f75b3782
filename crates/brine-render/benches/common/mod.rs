//! What the frame benches share: the reference frame's scene.

use brine_render::Scene;
use brine_render::scene::CloudConfig;

/// The reference frame: the default scene at 640×480, 1 sample per pixel, 100 waves and every
/// phenomenon on (clouds included).
pub fn reference_frame_scene() -> Scene {
    let mut scene = Scene::default_scene();
    scene.camera.width = 640;
    scene.camera.height = 480;
    scene.camera.spp = 1;
    scene.sea.waves = Some(100);
    scene.sky.clouds = Some(CloudConfig::default());
    scene
}
