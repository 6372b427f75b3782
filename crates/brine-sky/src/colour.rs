//! Colour conversions (through the `palette` crate).

use glam::{DMat3, DVec3};
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

/// The Bradford matrix `M_BFD`: CIE 1931 XYZ to the sharpened cone responses `(ρ, γ, β)` of
/// the Bradford chromatic-adaptation transform (rows as printed by Lam 1985 and ICC.1:2010).
const BRADFORD: DMat3 = DMat3::from_cols_array(&[
    0.8951, -0.7502, 0.0389, // first column
    0.2664, 1.7135, -0.0685, // second column
    -0.1614, 0.0367, 1.0296, // third column
]);

/// Smallest cone response of a white (its `Y` scaled to 1) that the Bradford transform
/// divides by: below it the light is too far from any white (or black) to adapt to.
const MIN_CONE_RESPONSE: f64 = 1e-3;

/// Chromatic adaptation of colours seen under the white `source` to the corresponding colours
/// under the white `target`, by the linear Bradford transform (a von Kries scaling of
/// sharpened cone responses):
///
/// `M = M_BFD⁻¹ · diag(ρ_t/ρ_s, γ_t/γ_s, β_t/β_s) · M_BFD`, `(ρ, γ, β) = M_BFD · (X, Y, Z)/Y`.
///
/// The source white goes to the target white of the same luminance: `M · source =
/// (Y_source/Y_target) · target`.
///
/// # Arguments
/// - `source`, `target`: the two whites as CIE 1931 XYZ (any photometric unit, `Y > 0`).
///
/// # Returns
/// The 3 × 3 matrix acting on XYZ columns; `None` when either white is black, not finite, or
/// has a cone response below 10⁻³ of its luminance (no daylight or moonlight does; a
/// low-pressure sodium lamp does).
///
/// # References
/// Lam K. M. 1985, *Metamerism and colour constancy*, doctoral thesis, University of Bradford;
/// ICC.1:2010 (profile version 4.3), Annex E (the linearised Bradford transform);
/// Lindbloom B., "Chromatic adaptation" (brucelindbloom.com), for the worked matrices.
pub fn bradford_adaptation(source: DVec3, target: DVec3) -> Option<DMat3> {
    let cones = |w: DVec3| {
        let c = BRADFORD * (w / w.y);
        (w.is_finite() && w.y > 0.0 && c.min_element() > MIN_CONE_RESPONSE).then_some(c)
    };
    let (s, t) = (cones(source)?, cones(target)?);
    Some(BRADFORD.inverse() * DMat3::from_diagonal(t / s) * BRADFORD)
}

/// The white balance of a camera that shows the illuminant `illuminant` as white: linear sRGB
/// seen under it to the linear sRGB of the same scene seen under D65, the display's white, by
/// [`bradford_adaptation`] from the illuminant's white to D65's.
///
/// The illuminant itself comes out neutral (`R = G = B`) with its luminance kept.
///
/// # Arguments
/// - `illuminant`: the light's colour as linear sRGB (any photometric unit; e.g. the
///   irradiance of sun, moon and sky on a horizontal plane).
///
/// # Returns
/// The 3 × 3 matrix acting on linear sRGB columns; `None` for a light [`bradford_adaptation`]
/// cannot adapt to.
///
/// # References
/// As [`bradford_adaptation`]; IEC 61966-2-1:1999 (sRGB, D65 white).
pub fn white_balance_linear_srgb(illuminant: DVec3) -> Option<DMat3> {
    let to_xyz =
        DMat3::from_cols(linear_srgb_to_xyz(DVec3::X), linear_srgb_to_xyz(DVec3::Y), linear_srgb_to_xyz(DVec3::Z));
    let adapt = bradford_adaptation(to_xyz * illuminant, to_xyz * DVec3::ONE)?;
    Some(to_xyz.inverse() * adapt * to_xyz)
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
    /// Lindbloom's worked Bradford matrices between D50 (0.96422, 1, 0.82521) and D65
    /// (0.95047, 1, 1.08883), printed to 7 decimals.
    #[test]
    fn bradford_matches_the_published_d50_d65_matrices() {
        /// Half a unit of the 7th decimal the matrices are printed to.
        const PRINTED: f64 = 5e-8;
        let (d50, d65) = (DVec3::new(0.96422, 1.0, 0.82521), DVec3::new(0.95047, 1.0, 1.08883));
        let d50_to_d65 = [
            [0.9555766, -0.0230393, 0.0631636],
            [-0.0282895, 1.0099416, 0.0210077],
            [0.0122982, -0.0204830, 1.3299098],
        ];
        let d65_to_d50 = [
            [1.0478112, 0.0228866, -0.0501270],
            [0.0295424, 0.9904844, -0.0170491],
            [-0.0092345, 0.0150436, 0.7521316],
        ];
        for (m, rows) in
            [(bradford_adaptation(d50, d65).unwrap(), d50_to_d65), (bradford_adaptation(d65, d50).unwrap(), d65_to_d50)]
        {
            for (i, row) in rows.iter().enumerate() {
                for (j, &v) in row.iter().enumerate() {
                    assert!((m.row(i)[j] - v).abs() < PRINTED, "({i}, {j}): {} vs {v}", m.row(i)[j]);
                }
            }
        }
        // Black, a non-finite light, and a monochromatic-like one far from any white are refused.
        assert!(bradford_adaptation(DVec3::ZERO, d65).is_none());
        assert!(bradford_adaptation(DVec3::new(f64::NAN, 1.0, 1.0), d65).is_none());
        assert!(bradford_adaptation(d65, DVec3::new(0.1, 1.0, 0.0)).is_none());
        assert!(white_balance_linear_srgb(DVec3::ZERO).is_none());
    }

    proptest::proptest! {
        /// Under the white balance of a light, that light is neutral of its own luminance, D65 is
        /// left as it is, and adapting there and back is the identity.
        #[test]
        fn the_white_balance_makes_its_light_neutral(
            x in 0.25f64..0.45,
            dy in -0.02f64..0.02,
            luminance in 1e-3f64..1e3,
        ) {
            /// Products of a few 3 × 3 matrices of entries of order 1 and their inverses.
            const ROUNDING: f64 = 1e-12;
            let light_xyz = xyy_to_xyz(x, daylight_locus_y(x.min(0.38)) + dy, luminance);
            let light = xyz_to_linear_srgb(light_xyz);
            let m = white_balance_linear_srgb(light).unwrap();
            let seen = m * light;
            let y = linear_srgb_to_xyz(seen).y;
            proptest::prop_assert!(((seen - DVec3::splat(seen.x)).abs().max_element()) < ROUNDING * luminance, "{seen:?}");
            // The light's luminance through the same matrix (palette's two matrices invert each
            // other only to about 10⁻⁷).
            let light_y = linear_srgb_to_xyz(light).y;
            proptest::prop_assert!((y - light_y).abs() < ROUNDING * luminance, "{y} vs {light_y}");
            let d65 = white_balance_linear_srgb(DVec3::ONE).unwrap();
            proptest::prop_assert!((d65 - DMat3::IDENTITY).abs().to_cols_array().iter().all(|e| *e < ROUNDING));
            let (a, b) = (bradford_adaptation(light_xyz, DVec3::new(0.95047, 1.0, 1.08883)).unwrap(),
                          bradford_adaptation(DVec3::new(0.95047, 1.0, 1.08883), light_xyz).unwrap());
            proptest::prop_assert!(((a * b) - DMat3::IDENTITY).abs().to_cols_array().iter().all(|e| *e < ROUNDING));
        }
    }
}
