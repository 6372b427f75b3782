//! Coordinate frames: ecliptic, equatorial, horizontal; topocentric parallax.

use std::f64::consts::{PI, TAU};

use crate::Observer;

/// Reduces an angle to `[0, 2π)` (Schlyter's `rev`).
pub(crate) fn rev(angle: f64) -> f64 {
    angle.rem_euclid(TAU)
}

/// Rectangular coordinates of a direction at longitude `lon`, latitude `lat`, distance `r`.
pub(crate) fn rectangular(lon: f64, lat: f64, r: f64) -> [f64; 3] {
    let (sl, cl) = lon.sin_cos();
    let (sb, cb) = lat.sin_cos();
    [r * cb * cl, r * cb * sl, r * sb]
}

/// `(longitude in [0, 2π), latitude, distance)` of a rectangular vector.
pub(crate) fn spherical(v: [f64; 3]) -> (f64, f64, f64) {
    let rxy = v[0].hypot(v[1]);
    (rev(v[1].atan2(v[0])), v[2].atan2(rxy), rxy.hypot(v[2]))
}

/// Ecliptic to equatorial rectangular coordinates: a rotation by the obliquity `ε` about x,
/// `y_e = y cos ε − z sin ε`, `z_e = y sin ε + z cos ε`.
pub(crate) fn ecliptic_to_equatorial(v: [f64; 3], obliquity: f64) -> [f64; 3] {
    let (se, ce) = obliquity.sin_cos();
    [v[0], v[1] * ce - v[2] * se, v[1] * se + v[2] * ce]
}

/// A direction in the observer's sky.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Horizontal {
    /// Altitude above the horizon (rad), `[−π/2, π/2]`.
    pub altitude: f64,
    /// Azimuth, compass bearing from north through east (rad), `[0, 2π)`.
    pub azimuth: f64,
}

impl Horizontal {
    /// The direction in the observer's sky of a body at hour angle `H` and declination `δ`, seen
    /// from latitude `φ` (a rotation of the equatorial frame about the east–west axis):
    /// `x = cos H cos δ`, `y = sin H cos δ`, `z = sin δ`; `x_hor = x sin φ − z cos φ`,
    /// `z_hor = x cos φ + z sin φ`; `A = atan2(y, x_hor) + π`, `h = asin(z_hor)`.
    ///
    /// # Arguments
    /// - `hour_angle`: `H` (rad), any value, west positive (`H = LST − α`).
    /// - `declination`: `δ` (rad), `[−π/2, π/2]`.
    /// - `latitude`: `φ` (rad), `[−π/2, π/2]`, north positive.
    ///
    /// # Returns
    /// The [`Horizontal`] direction: altitude `h` (rad), `[−π/2, π/2]`; azimuth `A` from north
    /// through east (rad), `[0, 2π)`.
    ///
    /// # References
    /// Schlyter, "How to compute planetary positions", §12b, and his tutorial §6 (worked
    /// example: H = 195.1808°, δ = 11.0084°, φ = 60° → A = 15.6767°, h = −17.9570°); equation
    /// equations.md §13.
    pub fn from_equatorial(hour_angle: f64, declination: f64, latitude: f64) -> Self {
        let (sh, ch) = hour_angle.sin_cos();
        let (sd, cd) = declination.sin_cos();
        let (sp, cp) = latitude.sin_cos();
        let (x, y, z) = (ch * cd, sh * cd, sd);
        let x_hor = x * sp - z * cp;
        let z_hor = x * cp + z * sp;
        // A unit vector's component: the clamp absorbs rounding only.
        debug_assert!(z_hor.abs() <= 1.0 + 1e-12, "z_hor = {z_hor}");
        Self { altitude: z_hor.clamp(-1.0, 1.0).asin(), azimuth: rev(y.atan2(x_hor) + PI) }
    }

    /// Altitude in degrees, `h · 180/π`, `[−90, 90]`.
    pub fn altitude_deg(&self) -> f64 {
        self.altitude.to_degrees()
    }

    /// Azimuth in degrees, `[0, 360)`.
    pub fn azimuth_deg(&self) -> f64 {
        self.azimuth.to_degrees()
    }

    /// The unit vector toward this direction in Brine's world frame (y up, x east, z south):
    /// `(sin A cos h, sin h, −cos A cos h)`.
    ///
    /// # Returns
    /// `[x, y, z]`, a unit vector (dimensionless).
    pub fn direction(&self) -> [f64; 3] {
        let (sa, ca) = self.azimuth.sin_cos();
        let (sh, ch) = self.altitude.sin_cos();
        [sa * ch, sh, -ca * ch]
    }
}

/// Moves a geocentric equatorial position (in Earth equatorial radii) to the observer:
/// subtracts the observer's position `(ρ cos φ′ cos θ, ρ cos φ′ sin θ, ρ sin φ′)` where `θ` is the
/// local sidereal time.
///
/// # References
/// Meeus 1998, ch. 40 (the rectangular form of Eq. 40.2–40.3).
pub(crate) fn topocentric(geocentric: [f64; 3], local_sidereal_time: f64, observer: &Observer) -> [f64; 3] {
    let (rc, rs) = observer.geocentric_terms();
    let (st, ct) = local_sidereal_time.sin_cos();
    [geocentric[0] - rc * ct, geocentric[1] - rc * st, geocentric[2] - rs]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact identities evaluated in double precision: a few ulps of the angles involved.
    const ROUNDING: f64 = 1e-12;
    /// The azimuth at the meridian comes from `atan2` of a rounding-level `y`: looser.
    const AZIMUTH_ROUNDING_DEG: f64 = 1e-9;

    #[test]
    fn meridian_transit_is_due_south_north_of_the_declination() {
        let h = Horizontal::from_equatorial(0.0, 10f64.to_radians(), 50f64.to_radians());
        assert!((h.altitude_deg() - 50.0).abs() < ROUNDING);
        assert!((h.azimuth_deg() - 180.0).abs() < AZIMUTH_ROUNDING_DEG);
        let d = h.direction();
        assert!(d[2] > 0.0 && d[0].abs() < ROUNDING, "south is +z: {d:?}");
    }

    #[test]
    fn spherical_round_trip() {
        let v = rectangular(1.0, -0.3, 2.0);
        let (l, b, r) = spherical(v);
        assert!((l - 1.0).abs() < ROUNDING && (b + 0.3).abs() < ROUNDING && (r - 2.0).abs() < ROUNDING);
    }
}
