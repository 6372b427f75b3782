//! The pinhole camera.

use glam::DVec3;

use crate::scene::CameraConfig;

/// A pinhole camera with an orthonormal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Eye position (m).
    pub position: DVec3,
    /// Unit view direction.
    pub forward: DVec3,
    /// Unit right vector.
    pub right: DVec3,
    /// Unit up vector of the image.
    pub up: DVec3,
    /// `tan(fov/2)` of the vertical field of view.
    pub tan_half_fov: f64,
    /// Image width (pixels).
    pub width: u32,
    /// Image height (pixels).
    pub height: u32,
}

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

impl Camera {
    /// The camera of a (validated) `[camera]` section.
    pub fn from_config(c: &CameraConfig) -> Self {
        let position = DVec3::from_array(c.position);
        let forward = match c.look_at {
            Some(t) => (DVec3::from_array(t) - position).normalize(),
            None => direction_from_bearing(
                c.yaw_deg.unwrap_or(crate::Scene::DEFAULT_YAW_DEG),
                c.pitch_deg.unwrap_or(crate::Scene::DEFAULT_PITCH_DEG),
            ),
        };
        // Looking straight up or down: pick north as the image's up.
        let world_up = if forward.cross(DVec3::Y).length_squared() < 1e-12 { DVec3::NEG_Z } else { DVec3::Y };
        let right = forward.cross(world_up).normalize();
        let up = right.cross(forward);
        Self {
            position,
            forward,
            right,
            up,
            tan_half_fov: (0.5 * c.fov_deg.to_radians()).tan(),
            width: c.width,
            height: c.height,
        }
    }

    /// Unit direction through the image point `(x, y)` in pixels (`(0, 0)` the top-left corner,
    /// `(width, height)` the bottom-right).
    pub fn direction(&self, x: f64, y: f64) -> DVec3 {
        let aspect = f64::from(self.width) / f64::from(self.height);
        let sx = (2.0 * x / f64::from(self.width) - 1.0) * self.tan_half_fov * aspect;
        let sy = (1.0 - 2.0 * y / f64::from(self.height)) * self.tan_half_fov;
        (self.forward + sx * self.right + sy * self.up).normalize()
    }

    /// Angle subtended by one pixel at the image centre (rad).
    pub fn pixel_angle(&self) -> f64 {
        2.0 * self.tan_half_fov / f64::from(self.height)
    }
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
        let cam = Camera::from_config(&c);
        assert!((cam.forward - DVec3::NEG_Z).length() < UNIT_VECTOR_ROUNDING);
        assert!((cam.right - DVec3::X).length() < UNIT_VECTOR_ROUNDING);
        assert!(
            (cam.direction(f64::from(cam.width) / 2.0, f64::from(cam.height) / 2.0) - cam.forward).length()
                < UNIT_VECTOR_ROUNDING
        );
    }
}
