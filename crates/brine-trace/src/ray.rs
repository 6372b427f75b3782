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

/// The part of a ray to trace: `t ∈ [t_enter, t_exit]` (distances along the ray), already
/// clipped to the surface's zero-set bounds by the caller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RaySpan<'r> {
    /// The ray.
    pub ray: &'r Ray,
    /// Start of the interval (distance along the ray, `≥ 0`).
    pub t_enter: f64,
    /// End of the interval; the interval is empty unless `t_enter < t_exit`.
    pub t_exit: f64,
}

impl<'r> RaySpan<'r> {
    /// `ray` on `[t_enter, t_exit]`.
    pub const fn new(ray: &'r Ray, t_enter: f64, t_exit: f64) -> Self {
        Self { ray, t_enter, t_exit }
    }
}
