//! Directions on the sky and their separations.

use glam::DVec3;

/// The unit vector at `elevation_deg` above the horizon and compass `azimuth_deg` (from north
/// toward east), in Brine's axes (`x` east, `y` up, `z` south).
pub fn from_elevation_azimuth_deg(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
    DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos())
}

/// The unit vector at polar angle `theta` from +z and azimuth `phi` from +x (rad): the
/// `z`-up frame of the BRDFs.
pub fn from_polar(theta: f64, phi: f64) -> DVec3 {
    DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos())
}

/// The angle (degrees) between two (altitude, azimuth) positions given in degrees, by the
/// haversine formula `2 asin √(sin²(Δh/2) + cos h₁ cos h₂ sin²(ΔA/2))` (`acos` of the dot product
/// loses precision at small angles).
///
/// # References
/// Sinnott R. W. 1984, "Virtues of the haversine", Sky and Telescope 68(2):159.
pub fn separation_deg(alt1: f64, az1: f64, alt2: f64, az2: f64) -> f64 {
    let (a1, a2) = (alt1.to_radians(), alt2.to_radians());
    let h = ((a2 - a1) / 2.0).sin().powi(2) + a1.cos() * a2.cos() * ((az2 - az1).to_radians() / 2.0).sin().powi(2);
    (2.0 * h.sqrt().asin()).to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of a few trigonometric calls.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn directions_are_unit_and_separations_add_up() {
        let d = from_elevation_azimuth_deg(30.0, 120.0);
        assert!((d.length() - 1.0).abs() < ROUNDING && (d.y - 0.5).abs() < ROUNDING);
        assert!((from_polar(0.3, 2.0).length() - 1.0).abs() < ROUNDING);
        assert!((separation_deg(10.0, 50.0, 10.0, 50.0)).abs() < ROUNDING);
        assert!((separation_deg(0.0, 0.0, 0.0, 90.0) - 90.0).abs() < ROUNDING);
        assert!((separation_deg(-90.0, 0.0, 90.0, 0.0) - 180.0).abs() < ROUNDING);
    }
}
