//! Spectral weights of the linear-sRGB channels, for band-averaging water properties.

use crate::iop::{LAMBDA_MAX_NM, LAMBDA_MIN_NM};

/// The CIE 1931 2° colour-matching functions `(x̄, ȳ, z̄)` by the multi-lobe piecewise-Gaussian fit
/// of Wyman, Sloan & Shirley (2013): `g(λ; μ, τ₁, τ₂) = exp(−½ ((λ − μ) τ)²)`, `τ = τ₁` below
/// `μ`, `τ₂` above;
/// `x̄ = 1.056 g(599.8; 0.0264, 0.0323) + 0.362 g(442.0; 0.0624, 0.0374) − 0.065 g(501.1; 0.0490, 0.0382)`,
/// `ȳ = 0.821 g(568.8; 0.0213, 0.0247) + 0.286 g(530.9; 0.0613, 0.0322)`,
/// `z̄ = 1.217 g(437.0; 0.0845, 0.0278) + 0.681 g(459.0; 0.0385, 0.0725)`.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), any (the fit is for 360–830 nm).
///
/// # Returns
/// `(x̄, ȳ, z̄)` (dimensionless), within about 1 % of the CIE tables at their peaks.
///
/// # References
/// Wyman C., Sloan P.-P., Shirley P. 2013, "Simple analytic approximations to the CIE XYZ color
/// matching functions", JCGT 2(2):1–11, Eq. 2 (multi-lobe fit).
pub fn cie1931_xyz_bar(lambda_nm: f64) -> [f64; 3] {
    let g = |mu: f64, t1: f64, t2: f64| {
        let t = (lambda_nm - mu) * if lambda_nm < mu { t1 } else { t2 };
        (-0.5 * t * t).exp()
    };
    [
        1.056 * g(599.8, 0.0264, 0.0323) + 0.362 * g(442.0, 0.0624, 0.0374) - 0.065 * g(501.1, 0.0490, 0.0382),
        0.821 * g(568.8, 0.0213, 0.0247) + 0.286 * g(530.9, 0.0613, 0.0322),
        1.217 * g(437.0, 0.0845, 0.0278) + 0.681 * g(459.0, 0.0385, 0.0725),
    ]
}

/// CIE XYZ → linear sRGB (IEC 61966-2-1, D65 white).
const XYZ_TO_SRGB: [[f64; 3]; 3] = [[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]];

/// Number of 5 nm samples from 400 to 700 nm.
pub const BAND_SAMPLES: usize = 61;

/// Band-averaging weights of the linear-sRGB channels on the 5 nm grid 400–700 nm:
/// `w_c(λ) = max(0, Σ_k M_ck x̄_k(λ))`, normalised so that `Σ_λ w_c(λ) Δλ = 1` (trapezoid rule).
///
/// The channel sensitivities of linear sRGB are rows of the XYZ → sRGB matrix `M` applied to the
/// CIE colour-matching functions; their negative lobes are clipped so that the average of a
/// positive quantity stays positive and is not pulled by wavelengths the channel subtracts. Only
/// 400–700 nm is used (the range of the water tables): the truncated tails hold 1.3 % (R),
/// 0.1 % (G) and 2.6 % (B) of the clipped weights over 360–830 nm (see the tests).
///
/// # Returns
/// `weights[c][i]` for channel `c` (R, G, B) at `λ_i = 400 + 5i` nm, in nm⁻¹.
///
/// # References
/// IEC 61966-2-1:1999 (sRGB); Wyman, Sloan & Shirley 2013 (colour-matching functions).
pub fn srgb_band_weights() -> [[f64; BAND_SAMPLES]; 3] {
    let mut w = [[0.0; BAND_SAMPLES]; 3];
    for (c, row) in XYZ_TO_SRGB.iter().enumerate() {
        for (i, wi) in w[c].iter_mut().enumerate() {
            let xyz = cie1931_xyz_bar(LAMBDA_MIN_NM + 5.0 * i as f64);
            *wi = (row[0] * xyz[0] + row[1] * xyz[1] + row[2] * xyz[2]).max(0.0);
        }
        let sum: f64 = (0..BAND_SAMPLES)
            .map(|i| if i == 0 || i == BAND_SAMPLES - 1 { 0.5 * w[c][i] } else { w[c][i] })
            .sum::<f64>()
            * 5.0;
        w[c].iter_mut().for_each(|x| *x /= sum);
    }
    debug_assert!((LAMBDA_MAX_NM - LAMBDA_MIN_NM - 5.0 * (BAND_SAMPLES - 1) as f64).abs() < 1e-9);
    w
}

/// The trapezoid-rule band average `∫ w_c(λ) f(λ) dλ` of a spectral function over 400–700 nm
/// with the weights of [`srgb_band_weights`].
///
/// # Arguments
/// - `weights`: the channel weights.
/// - `f`: the spectral quantity as a function of wavelength (nm).
///
/// # Returns
/// `[R, G, B]` averages, in the unit of `f`.
///
/// # References
/// Trapezoid rule on the 5 nm grid (Abramowitz & Stegun 1964 §25.4.2).
pub fn band_average(weights: &[[f64; BAND_SAMPLES]; 3], mut f: impl FnMut(f64) -> f64) -> [f64; 3] {
    let mut out = [0.0; 3];
    for i in 0..BAND_SAMPLES {
        let v = f(LAMBDA_MIN_NM + 5.0 * i as f64);
        let end = if i == 0 || i == BAND_SAMPLES - 1 { 0.5 } else { 1.0 };
        for (o, w) in out.iter_mut().zip(weights) {
            *o += w[i] * v * end * 5.0;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn cmf_fit_matches_cie_peaks() {
        // CIE 1931 2° tables: ȳ(555) = 1.0000, x̄(600) = 1.0622, z̄(445) = 1.7826 (1 nm table).
        /// The fit's stated accuracy is about 1 % of the peak.
        const FIT: f64 = 0.015;
        assert_relative_eq!(cie1931_xyz_bar(555.0)[1], 1.0, max_relative = FIT);
        assert_relative_eq!(cie1931_xyz_bar(600.0)[0], 1.0622, max_relative = FIT);
        assert_relative_eq!(cie1931_xyz_bar(445.0)[2], 1.7826, max_relative = FIT);
    }

    #[test]
    fn weights_are_normalised_and_truncation_is_small() {
        let w = srgb_band_weights();
        let avg = band_average(&w, |_| 1.0);
        /// The weights are normalised by the same trapezoid sum: rounding of 61 terms.
        const ROUNDING: f64 = 1e-12;
        for v in avg {
            assert_relative_eq!(v, 1.0, max_relative = ROUNDING);
        }
        // Share of each clipped channel weight outside 400–700 nm (1 nm sums over 360–830 nm).
        /// The truncation the model documentation states for R, G, B (docs/models/brine-optics.md).
        const TRUNCATION: [f64; 3] = [0.02, 0.005, 0.035];
        for (c, bound) in TRUNCATION.into_iter().enumerate() {
            let row = XYZ_TO_SRGB[c];
            let weight = |l: f64| {
                let x = cie1931_xyz_bar(l);
                (row[0] * x[0] + row[1] * x[1] + row[2] * x[2]).max(0.0)
            };
            let total: f64 = (360..=830).map(|l| weight(f64::from(l))).sum();
            let inside: f64 = (400..=700).map(|l| weight(f64::from(l))).sum();
            assert!(1.0 - inside / total < bound, "channel {c}: {}", 1.0 - inside / total);
        }
    }
}
