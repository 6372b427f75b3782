//! The observer: a place on the WGS84 ellipsoid.

use crate::EphemError;
use crate::error::check;

/// WGS84 equatorial radius (km).
pub const EARTH_EQUATORIAL_RADIUS_KM: f64 = 6378.137;

/// WGS84 flattening `f`.
pub const EARTH_FLATTENING: f64 = 1.0 / 298.257_223_563;

/// A place on Earth: geodetic latitude, longitude (east positive) and height above the ellipsoid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observer {
    latitude: f64,
    longitude: f64,
    height_m: f64,
}

impl Observer {
    /// An observer at geodetic latitude and longitude given in degrees and a height in metres.
    ///
    /// # Arguments
    /// - `latitude_deg`: `[−90, 90]`, north positive.
    /// - `longitude_deg`: `[−180, 360]`, east positive.
    /// - `height_m`: height above the ellipsoid, `[−500, 10 000]` m.
    ///
    /// # Returns
    /// The [`Observer`] (angles stored in radians).
    ///
    /// # Errors
    /// [`EphemError::OutOfRange`] naming the parameter outside its range.
    pub fn from_degrees(latitude_deg: f64, longitude_deg: f64, height_m: f64) -> Result<Self, EphemError> {
        let lat = check("latitude_deg", latitude_deg, (-90.0..=90.0).contains(&latitude_deg), "[-90, 90]°")?;
        let lon = check("longitude_deg", longitude_deg, (-180.0..=360.0).contains(&longitude_deg), "[-180, 360]°")?;
        let h = check("height_m", height_m, (-500.0..=10_000.0).contains(&height_m), "[-500, 10000] m")?;
        Ok(Self { latitude: lat.to_radians(), longitude: lon.to_radians(), height_m: h })
    }

    /// Geodetic latitude (rad).
    pub fn latitude(&self) -> f64 {
        self.latitude
    }

    /// Longitude, east positive (rad).
    pub fn longitude(&self) -> f64 {
        self.longitude
    }

    /// Height above the ellipsoid (m).
    pub fn height_m(&self) -> f64 {
        self.height_m
    }

    /// The observer's geocentric position terms `(ρ cos φ′, ρ sin φ′)` in equatorial Earth radii:
    /// `u = atan((1 − f) tan φ)`, `ρ sin φ′ = (1 − f) sin u + (H/a) sin φ`,
    /// `ρ cos φ′ = cos u + (H/a) cos φ`.
    ///
    /// # Returns
    /// `(ρ cos φ′, ρ sin φ′)` (dimensionless, Earth equatorial radii).
    ///
    /// # References
    /// Meeus J. 1998, Astronomical Algorithms, 2nd ed., ch. 11 (WGS84 constants).
    pub fn geocentric_terms(&self) -> (f64, f64) {
        let u = ((1.0 - EARTH_FLATTENING) * self.latitude.tan()).atan();
        let h = self.height_m / (EARTH_EQUATORIAL_RADIUS_KM * 1000.0);
        let (sp, cp) = self.latitude.sin_cos();
        let (su, cu) = u.sin_cos();
        (cu + h * cp, (1.0 - EARTH_FLATTENING) * su + h * sp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meeus_example_11a() {
        // Meeus Example 11.a: Palomar, φ = 33°21′22″ N, H = 1706 m: ρ sin φ′ = 0.546861,
        // ρ cos φ′ = 0.836339 (printed to 6 digits; his ellipsoid is IAU 1976, a = 6378.14 km,
        // f = 1/298.257, within 10⁻⁶ of WGS84 here): half a unit plus that, 1.5×10⁻⁶.
        const MEEUS_11A: f64 = 5e-7 + 1e-6;
        let o = Observer::from_degrees(33.0 + 21.0 / 60.0 + 22.0 / 3600.0, -116.8625, 1706.0).unwrap();
        let (c, s) = o.geocentric_terms();
        assert!((s - 0.546861).abs() < MEEUS_11A, "{s}");
        assert!((c - 0.836339).abs() < MEEUS_11A, "{c}");
    }

    #[test]
    fn rejects_bad_places() {
        assert!(Observer::from_degrees(91.0, 0.0, 0.0).is_err());
        assert!(Observer::from_degrees(0.0, f64::NAN, 0.0).is_err());
        assert!(Observer::from_degrees(0.0, 0.0, 20_000.0).is_err());
    }
}
