//! The fisheye (all-sky) view of the dome used by `brine sky` and the plots.

use glam::DVec3;

/// The view direction at a point of an equidistant fisheye image of the sky: zenith at the
/// centre, the horizon on the unit circle, the zenith angle proportional to the distance from
/// the centre; north up and east to the left (the sky seen from below, as by an all-sky camera).
///
/// # Arguments
/// - `x`, `y`: image coordinates in `[−1, 1]`, `x` to the right, `y` down.
///
/// # Returns
/// The unit direction (y up, x east, z south), or `None` outside the horizon circle.
///
/// # References
/// The equidistant fisheye projection (zenith angle `= (π/2) r`), as used by all-sky cameras.
pub fn fisheye_direction(x: f64, y: f64) -> Option<DVec3> {
    let r = x.hypot(y);
    if r > 1.0 {
        return None;
    }
    let zenith_angle = std::f64::consts::FRAC_PI_2 * r;
    let bearing = (-x).atan2(-y);
    let (se, ce) = (std::f64::consts::FRAC_PI_2 - zenith_angle).sin_cos();
    Some(DVec3::new(bearing.sin() * ce, se, -bearing.cos() * ce))
}

/// The view direction of pixel `(i, j)` (column, row from the top) of an `n × n` fisheye image,
/// at the pixel's centre: [`fisheye_direction`] at `x = (i + ½ − n/2)/(n/2)`,
/// `y = (j + ½ − n/2)/(n/2)`.
///
/// # Arguments
/// - `i`, `j`: column and row, `[0, n)`.
/// - `n`: image size (pixels), `≥ 1`.
///
/// # Returns
/// The unit direction, or `None` for a pixel outside the horizon circle.
///
/// # References
/// The equidistant fisheye projection (see [`fisheye_direction`]).
pub fn fisheye_pixel_direction(i: u32, j: u32, n: u32) -> Option<DVec3> {
    let half = n as f64 / 2.0;
    fisheye_direction((i as f64 + 0.5 - half) / half, (j as f64 + 0.5 - half) / half)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact geometry evaluated in double precision.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn centre_is_zenith_top_is_north_left_is_east() {
        let z = fisheye_direction(0.0, 0.0).unwrap();
        assert!((z.y - 1.0).abs() < ROUNDING);
        let north = fisheye_direction(0.0, -1.0).unwrap();
        assert!((north - DVec3::NEG_Z).length() < ROUNDING, "{north:?}");
        let east = fisheye_direction(-1.0, 0.0).unwrap();
        assert!((east - DVec3::X).length() < ROUNDING, "{east:?}");
        let half = fisheye_direction(0.5, 0.0).unwrap();
        assert!((half.y - 45f64.to_radians().sin()).abs() < ROUNDING);
        assert!(fisheye_direction(0.8, 0.8).is_none());
    }
}
