//! Rays with a unit direction.

use glam::DVec3;

/// Why a ray could not be built.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum RayError {
    /// The origin has a NaN or infinite coordinate.
    #[error("ray origin must be finite, got {0:?}")]
    NonFiniteOrigin(DVec3),
    /// The direction is zero, NaN or infinite.
    #[error("ray direction must be finite and non-zero, got {0:?}")]
    BadDirection(DVec3),
}

/// A half-line `p(t) = origin + t·direction`, `t ≥ 0`, with a unit `direction`.
///
/// `t` is then a distance in the unit of the coordinates (metres in Brine).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ray {
    origin: DVec3,
    direction: DVec3,
}

impl Ray {
    /// A ray from `origin` along `direction`, which is normalised here.
    ///
    /// # Errors
    /// [`RayError`] if the origin is not finite or the direction is zero or not finite.
    pub fn new(origin: DVec3, direction: DVec3) -> Result<Self, RayError> {
        if !origin.is_finite() {
            return Err(RayError::NonFiniteOrigin(origin));
        }
        let len = direction.length();
        if !direction.is_finite() || !(len > 0.0) || !len.is_finite() {
            return Err(RayError::BadDirection(direction));
        }
        Ok(Self { origin, direction: direction / len })
    }

    /// The origin.
    #[inline]
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The unit direction.
    #[inline]
    pub fn direction(&self) -> DVec3 {
        self.direction
    }

    /// The point at distance `t` along the ray.
    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.direction
    }
}
