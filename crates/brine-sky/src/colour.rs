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

/// The CIE daylight locus: the chromaticity `y_D` of daylight of chromaticity `x_D`,
/// `y_D = −3.000 x_D² + 2.870 x_D − 0.275`.
///
/// # Arguments
/// - `x`: CIE 1931 chromaticity `x_D` (1), `[0.250, 0.380]` (daylight of correlated colour
///   temperatures from 25 000 K down to 4 000 K).
///
/// # Returns
/// `y_D` (1).
///
/// # References
/// CIE 15:2004 *Colorimetry*, §3.1 (the CIE daylight illuminants).
pub fn daylight_locus_y(x: f64) -> f64 {
    -3.0 * x * x + 2.870 * x - 0.275
}

/// CIE 1931 chromaticity `(x, y)` of a tristimulus value, `None` for black.
pub fn chromaticity(xyz: DVec3) -> Option<(f64, f64)> {
    let sum = xyz.element_sum();
    (sum > 0.0).then(|| (xyz.x / sum, xyz.y / sum))
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

    /// The CIE daylight illuminants lie on the locus: D65 (0.31271, 0.32902) and D50 (0.34567,
    /// 0.35850), CIE 15:2004; the locus is computed from the illuminants' `x_D` of 5
    /// digits, so the tabulated `y` agrees to the last digit plus the formula's rounding.
    #[test]
    fn the_daylight_illuminants_lie_on_the_daylight_locus() {
        /// Published chromaticities have 5 digits; the locus' coefficients 3–4.
        const LOCUS_DIGITS: f64 = 2e-4;
        for (x, y) in [(0.31271, 0.32902), (0.34567, 0.35850)] {
            assert!((daylight_locus_y(x) - y).abs() < LOCUS_DIGITS, "x = {x}: {} vs {y}", daylight_locus_y(x));
        }
        assert_eq!(chromaticity(DVec3::ZERO), None);
        let (x, y) = chromaticity(DVec3::new(1.0, 2.0, 1.0)).unwrap();
        assert!((x - 0.25).abs() < 1e-15 && (y - 0.5).abs() < 1e-15);
    }

    proptest::proptest! {
        /// Two lights mix on the straight segment between their chromaticities, weighted by
        /// their `X + Y + Z`; the daylight locus is a parabola of second derivative −6, so the
        /// mixture's offset below it is the parts' offsets, weighted, plus the chord's gap
        /// `3 (x − x₁)(x₂ − x)` (docs/models/brine-sky.md, "Sun plus sky on a horizontal plane").
        #[test]
        fn a_mixture_lies_below_the_daylight_locus_by_the_chord(
            a in proptest::array::uniform3(0.01f64..10.0),
            b in proptest::array::uniform3(0.01f64..10.0),
        ) {
            /// Sums of a few products of values of order 1: rounding of order 10⁻¹⁵.
            const ROUNDING: f64 = 1e-12;
            let (a, b) = (DVec3::from_array(a), DVec3::from_array(b));
            let ((x1, y1), (x2, y2)) = (chromaticity(a).unwrap(), chromaticity(b).unwrap());
            let (x, y) = chromaticity(a + b).unwrap();
            let w = a.element_sum() / (a + b).element_sum();
            let parts = w * (daylight_locus_y(x1) - y1) + (1.0 - w) * (daylight_locus_y(x2) - y2);
            let gap = 3.0 * (x - x1) * (x2 - x);
            proptest::prop_assert!(gap >= -ROUNDING, "a chord of a concave curve runs below it: {gap}");
            proptest::prop_assert!(
                (daylight_locus_y(x) - y - (parts + gap)).abs() < ROUNDING,
                "{} vs {} + {}", daylight_locus_y(x) - y, parts, gap
            );
        }
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
