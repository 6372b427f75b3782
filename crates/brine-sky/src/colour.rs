//! Colour conversions (through the `palette` crate).

use glam::DVec3;
use palette::convert::FromColorUnclamped;
use palette::{LinSrgb, Xyz, white_point::D65};

/// CIE 1931 XYZ to linear sRGB (Rec. 709 primaries, D65 white), as `palette` defines it,
/// without clamping (radiances are unbounded).
///
/// # Arguments
/// - `xyz`: tristimulus values in any photometric unit (Y is luminance).
///
/// # Returns
/// Linear sRGB in the same unit; may have negative components for colours outside the gamut.
///
/// # References
/// IEC 61966-2-1:1999 (sRGB) matrix.
pub fn xyz_to_linear_srgb(xyz: DVec3) -> DVec3 {
    let c: Xyz<D65, f64> = Xyz::new(xyz.x, xyz.y, xyz.z);
    let rgb = LinSrgb::from_color_unclamped(c);
    DVec3::new(rgb.red, rgb.green, rgb.blue)
}

/// Linear sRGB to CIE 1931 XYZ (D65), the inverse of [`xyz_to_linear_srgb`], through `palette`.
///
/// # Arguments
/// - `rgb`: linear sRGB in any photometric unit.
///
/// # Returns
/// XYZ in the same unit (Y is luminance).
///
/// # References
/// IEC 61966-2-1:1999 (sRGB) matrix.
pub fn linear_srgb_to_xyz(rgb: DVec3) -> DVec3 {
    let c: LinSrgb<f64> = LinSrgb::new(rgb.x, rgb.y, rgb.z);
    let xyz: Xyz<D65, f64> = Xyz::from_color_unclamped(c);
    DVec3::new(xyz.x, xyz.y, xyz.z)
}

/// CIE xyY chromaticity and luminance to XYZ: `X = xY/y`, `Z = (1 − x − y)Y/y`.
///
/// # Arguments
/// - `x`, `y`: chromaticity coordinates, `y > 0`.
/// - `luminance`: `Y`.
///
/// # Returns
/// `(X, Y, Z)` in the unit of `Y`.
///
/// # References
/// CIE 15:2004; Preetham et al. 1999, §3.
pub fn xyy_to_xyz(x: f64, y: f64, luminance: f64) -> DVec3 {
    if y <= 0.0 {
        return DVec3::ZERO;
    }
    DVec3::new(x * luminance / y, luminance, (1.0 - x - y) * luminance / y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// palette derives both matrices from the primaries; they invert each other to ~10⁻⁷.
    const MATRIX_INVERSE: f64 = 1e-6;
    /// The D65 chromaticity printed to 5 digits moves sRGB white by up to 2×10⁻³.
    const D65_DIGITS: f64 = 2e-3;

    #[test]
    fn round_trip() {
        let v = DVec3::new(0.2, 0.5, 0.9);
        let back = linear_srgb_to_xyz(xyz_to_linear_srgb(v));
        // palette derives both matrices from the primaries; they invert each other to ~10⁻⁷.
        assert!((back - v).abs().max_element() < MATRIX_INVERSE, "{back:?}");
    }

    #[test]
    fn d65_white_maps_to_equal_rgb() {
        // D65 chromaticity (0.31271, 0.32902) with Y = 1 is sRGB white (1, 1, 1).
        let rgb = xyz_to_linear_srgb(xyy_to_xyz(0.31271, 0.32902, 1.0));
        for c in rgb.to_array() {
            assert!((c - 1.0).abs() < D65_DIGITS, "{rgb:?}");
        }
    }
}
