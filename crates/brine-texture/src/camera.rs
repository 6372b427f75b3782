//! The pinhole camera of Brine (brine-render's `Camera` is this type): y up, compass-bearing
//! yaw, pitch, vertical field of view. It lives here so that brine-texture does not depend on
//! the renderer.

use glam::DVec3;

use crate::TextureError;
use crate::error::check;

/// A pinhole camera with an orthonormal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pinhole {
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

impl Pinhole {
    /// The camera at `position` looking along the compass bearing `yaw_deg` and the elevation
    /// `pitch_deg`, as brine-render builds it from a scene's `[camera]` (looking straight up or
    /// down, north is the image's up).
    ///
    /// # Arguments
    /// - `position`: eye (m), finite.
    /// - `yaw_deg`: compass bearing of the view (°, 0 north = −z, 90 east = +x), finite.
    /// - `pitch_deg`: elevation of the view (°), `[−90, 90]`.
    /// - `fov_deg`: vertical field of view (°), `(0, 180)`.
    /// - `width`, `height`: image size (pixels), `[1, 16384]`.
    ///
    /// # Returns
    /// The camera: `forward = (sin B cos E, sin E, −cos B cos E)`, `right = forward × world_up`
    /// normalised (`world_up = y`, or `−z` looking straight up or down), `up = right × forward`.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] naming the first bad argument.
    ///
    /// # References
    /// brine-render's `camera::from_config` builds the same frame from a scene's `[camera]`
    /// (tested ray for ray in `crates/brine-render/tests/texture_camera.rs`).
    pub fn from_angles(
        position: DVec3,
        yaw_deg: f64,
        pitch_deg: f64,
        fov_deg: f64,
        width: u32,
        height: u32,
    ) -> Result<Self, TextureError> {
        check("camera.position.x", position.x, position.x.is_finite(), "finite m")?;
        check("camera.position.y", position.y, position.y.is_finite(), "finite m")?;
        check("camera.position.z", position.z, position.z.is_finite(), "finite m")?;
        check("camera.yaw_deg", yaw_deg, yaw_deg.is_finite(), "finite °")?;
        check("camera.pitch_deg", pitch_deg, (-90.0..=90.0).contains(&pitch_deg), "[-90, 90] °")?;
        check("camera.fov_deg", fov_deg, fov_deg > 0.0 && fov_deg < 180.0, "(0, 180) °")?;
        check("camera.width", f64::from(width), (1..=16384).contains(&width), "[1, 16384] px")?;
        check("camera.height", f64::from(height), (1..=16384).contains(&height), "[1, 16384] px")?;
        let (b, e) = (yaw_deg.to_radians(), pitch_deg.to_radians());
        let forward = DVec3::new(b.sin() * e.cos(), e.sin(), -b.cos() * e.cos());
        Ok(Self::from_forward(position, forward, fov_deg, width, height))
    }

    /// The camera at `position` looking along the unit vector `forward` (checked arguments):
    /// `right = forward × world_up` normalised (`world_up = y`, or `−z` looking straight up or
    /// down, so that north is the image's up), `up = right × forward`.
    ///
    /// # Arguments
    /// - `position`: eye (m), finite; `forward`: unit view direction.
    /// - `fov_deg`: vertical field of view (°), `(0, 180)`.
    /// - `width`, `height`: image size (pixels), `≥ 1`.
    pub fn from_forward(position: DVec3, forward: DVec3, fov_deg: f64, width: u32, height: u32) -> Self {
        debug_assert!((forward.length() - 1.0).abs() < 1e-9 && fov_deg > 0.0 && fov_deg < 180.0);
        debug_assert!(width >= 1 && height >= 1);
        let world_up = if forward.cross(DVec3::Y).length_squared() < 1e-12 { DVec3::NEG_Z } else { DVec3::Y };
        let right = forward.cross(world_up).normalize();
        let up = right.cross(forward);
        Self { position, forward, right, up, tan_half_fov: (0.5 * fov_deg.to_radians()).tan(), width, height }
    }

    /// Unit direction through the image point `(x, y)` in pixels (`(0, 0)` the top-left corner,
    /// `(width, height)` the bottom-right): the pinhole projection
    /// `d ∝ forward + s_x right + s_y up`, `s_x = (2x/W − 1) tan(fov/2) W/H`,
    /// `s_y = (1 − 2y/H) tan(fov/2)`.
    ///
    /// # Arguments
    /// - `x`, `y`: image point (pixels), any finite value (outside `[0, W] × [0, H]` extrapolates).
    ///
    /// # Returns
    /// The unit ray direction (world frame, y up).
    ///
    /// # References
    /// The pinhole camera model (e.g. Pharr, Jakob & Humphreys, *Physically Based Rendering*,
    /// §5.2), as in brine-render's `Camera::direction`.
    #[inline]
    pub fn direction(&self, x: f64, y: f64) -> DVec3 {
        let aspect = f64::from(self.width) / f64::from(self.height);
        let sx = (2.0 * x / f64::from(self.width) - 1.0) * self.tan_half_fov * aspect;
        let sy = (1.0 - 2.0 * y / f64::from(self.height)) * self.tan_half_fov;
        (self.forward + sx * self.right + sy * self.up).normalize()
    }

    /// Angle subtended by one pixel at the image centre, `2 tan(fov/2)/H` (rad, small-angle).
    ///
    /// # Returns
    /// The angle (rad), `> 0`: the footprint of a pixel at distance `t` is `t` times it.
    pub fn pixel_angle(&self) -> f64 {
        2.0 * self.tan_half_fov / f64::from(self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unit vectors from `sin`/`cos` of whole degrees and one cross product in `f64`: a few ulps
    /// (~10⁻¹⁶); a wrong axis or sign is off by ~1.
    const FRAME: f64 = 1e-12;

    #[test]
    fn bearing_90_looks_east_and_straight_down_has_north_up() {
        let c = Pinhole::from_angles(DVec3::new(0.0, 5.0, 0.0), 90.0, 0.0, 60.0, 64, 48).unwrap();
        assert!((c.forward - DVec3::X).length() < FRAME);
        assert!((c.direction(32.0, 24.0) - c.forward).length() < FRAME);
        let down = Pinhole::from_angles(DVec3::new(0.0, 5.0, 0.0), 0.0, -90.0, 60.0, 64, 64).unwrap();
        assert!((down.up - DVec3::NEG_Z).length() < FRAME);
        assert!(Pinhole::from_angles(DVec3::ZERO, 0.0, 0.0, 180.0, 1, 1).is_err());
    }
}
