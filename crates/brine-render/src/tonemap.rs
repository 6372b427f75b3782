//! Exposure, tone curve and sRGB encoding.

use glam::DVec3;
use palette::{LinSrgb, Srgb};

/// Scale from scene luminance in kcd m⁻² to the exposure-normalised value where 1 is the
/// saturation luminance `1.2 · 2^EV` cd m⁻² (ISO 12232 saturation-based exposure at ISO 100).
///
/// # Arguments
/// - `exposure_ev`: EV₁₀₀, `[−10, 30]`.
///
/// # Returns
/// The multiplier (m² kcd⁻¹).
pub fn exposure_scale(exposure_ev: f64) -> f64 {
    1000.0 / (1.2 * exposure_ev.exp2())
}

/// The ACES filmic tone curve fitted by Narkowicz (2015),
/// `f(x) = x(2.51x + 0.03)/(x(2.43x + 0.59) + 0.14)`, clamped to `[0, 1]`, per channel.
///
/// The fit rises monotonically from 0, passes 1 at `x = (0.56 + √0.3584)/0.16 ≈ 7.24` (the root
/// of `0.08x² − 0.56x − 0.14`) and tends to `2.51/2.43 ≈ 1.033`: the clamp turns everything above
/// 7.24 white, as Narkowicz's own code does (`saturate`).
///
/// # Arguments
/// - `x`: exposure-normalised linear value, `≥ 0` (NaN maps to 0).
///
/// # Returns
/// Display-linear value in `[0, 1]`.
///
/// # References
/// Narkowicz K. 2015, "ACES Filmic Tone Mapping Curve" (blog post), fit of the ACES RRT+ODT.
pub fn aces_filmic(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        return 0.0;
    }
    (x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)).clamp(0.0, 1.0)
}

/// Tone-maps one linear sRGB radiance (kcd m⁻²) to 8-bit sRGB.
pub fn to_srgb8(radiance: DVec3, scale: f64) -> [u8; 3] {
    let v = radiance * scale;
    let lin = LinSrgb::new(aces_filmic(v.x) as f32, aces_filmic(v.y) as f32, aces_filmic(v.z) as f32);
    let s: Srgb<u8> = Srgb::from_linear(lin);
    [s.red, s.green, s.blue]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of the rational (a few flops of order 1).
    const ROUNDING: f64 = 1e-15;

    /// The rational written out here, unclamped.
    fn narkowicz(x: f64) -> f64 {
        x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)
    }

    #[test]
    fn tone_curve_is_the_monotone_fit_up_to_white() {
        // The unclamped fit: monotone, below its asymptote 2.51/2.43; the curve is the fit up to
        // where it passes 1, at the root (0.56 + √0.3584)/0.16 of 0.08x² − 0.56x − 0.14, then white.
        let white_from = (0.56 + 0.3584f64.sqrt()) / 0.16;
        let mut prev = 0.0;
        for i in 0..1000 {
            let x = i as f64 * 0.02;
            let raw = narkowicz(x);
            assert!(raw >= prev && raw < 2.51 / 2.43, "the fit at {x}: {raw}");
            prev = raw;
            let expected = if x < white_from { raw } else { 1.0 };
            assert!((aces_filmic(x) - expected).abs() < ROUNDING, "{x}: {} vs {expected}", aces_filmic(x));
        }
        assert!(narkowicz(white_from - 1e-6) < 1.0 && narkowicz(white_from + 1e-6) > 1.0);
        assert_eq!(to_srgb8(DVec3::splat(f64::NAN), 1.0), [0, 0, 0]);
        assert_eq!(to_srgb8(DVec3::splat(1e12), 1.0), [255, 255, 255]);
    }
}
