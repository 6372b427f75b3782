//! The pinhole camera.

use glam::DVec3;

use crate::scene::CameraConfig;

/// The pinhole camera: brine-texture's `Pinhole` (one type for the renderer and the photo-based
/// ocean), built from a scene by [`from_config`].
pub use brine_texture::Pinhole as Camera;

/// Unit direction of a compass bearing and an elevation, y up, north = −z, east = +x.
///
/// # Arguments
/// - `bearing_deg`: compass bearing (°, 0 north, 90 east).
/// - `elevation_deg`: elevation above the horizon (°, `[−90, 90]`).
///
/// # Returns
/// `(sin B cos E, sin E, −cos B cos E)`.
pub fn direction_from_bearing(bearing_deg: f64, elevation_deg: f64) -> DVec3 {
    let (b, e) = (bearing_deg.to_radians(), elevation_deg.to_radians());
    DVec3::new(b.sin() * e.cos(), e.sin(), -b.cos() * e.cos())
}

/// The camera of a (validated) `[camera]` section: looking at `look_at`, or along the compass
/// bearing `yaw_deg` and the elevation `pitch_deg` (the scene's defaults when absent).
pub fn from_config(c: &CameraConfig) -> Camera {
    let position = DVec3::from_array(c.position);
    let forward = match c.look_at {
        Some(t) => (DVec3::from_array(t) - position).normalize(),
        None => direction_from_bearing(
            c.yaw_deg.unwrap_or(crate::Scene::DEFAULT_YAW_DEG),
            c.pitch_deg.unwrap_or(crate::Scene::DEFAULT_PITCH_DEG),
        ),
    };
    Camera::from_forward(position, forward, c.fov_deg, c.width, c.height)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unit vectors from sines and cosines of round angles, cross products and normalisations:
    /// `cos 90°` rounds to 6×10⁻¹⁷ instead of 0 and the rest is exact or a few ulps of 1;
    /// 10⁻¹² is a wide margin.
    const UNIT_VECTOR_ROUNDING: f64 = 1e-12;

    #[test]
    fn bearing_90_is_east_and_right_of_north_is_east() {
        assert!((direction_from_bearing(90.0, 0.0) - DVec3::X).length() < UNIT_VECTOR_ROUNDING);
        let c = CameraConfig { yaw_deg: Some(0.0), pitch_deg: Some(0.0), ..CameraConfig::default() };
        let cam = from_config(&c);
        assert!((cam.forward - DVec3::NEG_Z).length() < UNIT_VECTOR_ROUNDING);
        assert!((cam.right - DVec3::X).length() < UNIT_VECTOR_ROUNDING);
        assert!(
            (cam.direction(f64::from(cam.width) / 2.0, f64::from(cam.height) / 2.0) - cam.forward).length()
                < UNIT_VECTOR_ROUNDING
        );
    }
}
