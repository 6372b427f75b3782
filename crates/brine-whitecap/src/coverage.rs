//! Whitecap coverage over a footprint from the Jacobian statistics, and whitecap radiance.

use std::f64::consts::PI;

use crate::erf::ErfMethod;
use crate::statistics::Moments;

/// Reflectance of whitecaps in Dupuy & Bruneton's shading, `ρ_wc = 0.4` (Lambertian).
pub const WHITECAP_REFLECTANCE: f64 = 0.4;

/// Fraction of a pixel footprint where the surface breaks, `J < α`, assuming `J` Gaussian over
/// the footprint.
///
/// `W = ½ [1 + erf((α − μ)/√(2σ²))]`; for `σ² = 0` the step `W = 1` if `α > μ`, 0 if `α < μ`, ½ at
/// equality.
///
/// # Arguments
/// - `moments`: mean `μ` and variance `σ² ≥ 0` of `J` over the footprint
///   ([`crate::JacobianStatistics::moments_at`]).
/// - `alpha`: breaking threshold `α` (dimensionless; the talk shows −0.1, 0.3, 0.7; use
///   [`crate::Calibration`] to match Monahan's coverage).
/// - `erf`: the error function to use ([`ErfMethod`]).
///
/// # Returns
/// `W`, in `[0, 1]`, non-decreasing in `α`.
///
/// # References
/// Dupuy & Bruneton 2012 (slides "Breaking waves": `W(ω) = ∫_ω H(p) dp`, `H = 1` where `J < α`,
/// and its Gaussian evaluation); docs/equations.md §10.
#[inline]
pub fn whitecap_coverage(moments: Moments, alpha: f64, erf: ErfMethod) -> f64 {
    debug_assert!(moments.sigma2 >= 0.0 && moments.mu.is_finite() && !alpha.is_nan());
    let d = alpha - moments.mu;
    if moments.sigma2 <= 0.0 {
        return if d > 0.0 {
            1.0
        } else if d < 0.0 {
            0.0
        } else {
            0.5
        };
    }
    let e = erf.erf(d / (2.0 * moments.sigma2).sqrt());
    // Every erf here is within [−1, 1] but for rounding (the approximations saturate): the
    // clamp below absorbs rounding only.
    debug_assert!(e.abs() <= 1.0 + ERF_ROUNDING, "erf = {e}");
    (0.5 * (1.0 + e)).clamp(0.0, 1.0)
}

/// Radiance of the whitecaps of a pixel: `I_wc = W ρ_wc (E_sun max(n·l, 0) + E_sky)/π`.
///
/// # Arguments
/// - `coverage`: whitecap coverage `W` of the pixel, `[0, 1]`.
/// - `reflectance`: `ρ_wc`, `[0, 1]` ([`WHITECAP_REFLECTANCE`] = 0.4 in the talk).
/// - `sun_irradiance`: sun irradiance normal to the sun `E_sun` (any unit, e.g. klx), `≥ 0`.
/// - `cos_sun_normal`: `n·l`, cosine between the surface normal and the sun direction.
/// - `sky_irradiance`: sky irradiance on the facet `E_sky` (same unit), `≥ 0`.
///
/// # Returns
/// `I_wc` in the irradiance unit per steradian.
///
/// # References
/// Dupuy & Bruneton 2012 (slides: `I_whitecap = W · Lambert₀.₄`); docs/equations.md §10.
pub fn whitecap_radiance(
    coverage: f64,
    reflectance: f64,
    sun_irradiance: f64,
    cos_sun_normal: f64,
    sky_irradiance: f64,
) -> f64 {
    debug_assert!((0.0..=1.0).contains(&coverage) && (0.0..=1.0).contains(&reflectance));
    coverage * reflectance * (sun_irradiance * cos_sun_normal.max(0.0) + sky_irradiance) / PI
}

/// The pixel radiance with whitecaps: `I = (1 − W)(I_sun + I_sky + I_sea) + I_wc`.
///
/// Dupuy & Bruneton add `I_wc` to the foam-free radiance; weighting the rest by `1 − W` keeps
/// the energy balance (a whitecap hides the water under it).
///
/// # Arguments
/// - `coverage`: `W ∈ [0, 1]`.
/// - `sea_radiance`: `I_sun + I_sky + I_sea` of the foam-free surface (any radiance unit).
/// - `whitecap_radiance`: `I_wc` from [`whitecap_radiance`] (same unit).
///
/// # Returns
/// `I` in the same unit.
///
/// # References
/// Dupuy & Bruneton 2012; docs/equations.md §10.
pub fn compose_with_whitecaps(coverage: f64, sea_radiance: f64, whitecap_radiance: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&coverage));
    (1.0 - coverage) * sea_radiance + whitecap_radiance
}

/// Rounding of an error function's value past ±1.
const ERF_ROUNDING: f64 = 1e-12;

/// [`whitecap_coverage`] at a threshold calibrated on the coverage `target`: exactly 0 (1) when
/// the target is 0 (1), whatever the moments; otherwise at the threshold `alpha()` (called only
/// then).
pub(crate) fn calibrated_coverage(target: f64, moments: Moments, erf: ErfMethod, alpha: impl FnOnce() -> f64) -> f64 {
    if target <= 0.0 {
        0.0
    } else if target >= 1.0 {
        1.0
    } else {
        whitecap_coverage(moments, alpha(), erf)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of a handful of flops on values of order 1.
    const ROUNDING: f64 = 1e-15;

    /// `½(1 + erf(−1/√2))` by `libm` against the 15-digit `Φ(−1)`: the last printed digit.
    const PHI_DIGITS: f64 = 1e-14;

    #[test]
    fn step_when_variance_is_zero() {
        let m = Moments { mu: 0.5, sigma2: 0.0 };
        assert!((whitecap_coverage(m, 0.6, ErfMethod::Libm) - 1.0).abs() < ROUNDING);
        assert!(whitecap_coverage(m, 0.4, ErfMethod::Libm).abs() < ROUNDING);
        assert!((whitecap_coverage(m, 0.5, ErfMethod::Libm) - 0.5).abs() < ROUNDING);
    }

    #[test]
    fn half_at_the_mean_and_one_sigma() {
        let m = Moments { mu: 1.0, sigma2: 0.04 };
        assert!((whitecap_coverage(m, 1.0, ErfMethod::Fast) - 0.5).abs() < ROUNDING);
        // Φ(−1) = 0.158655253931457.
        assert!((whitecap_coverage(m, 0.8, ErfMethod::Libm) - 0.158_655_253_931_457).abs() < PHI_DIGITS);
    }

    #[test]
    fn radiance_of_full_cover_is_lambertian() {
        // W = 1, ρ = 1, E = π: radiance 1.
        assert!((whitecap_radiance(1.0, 1.0, PI, 1.0, 0.0) - 1.0).abs() < ROUNDING);
        assert!((compose_with_whitecaps(0.25, 4.0, 1.0) - 4.0).abs() < ROUNDING);
    }
}
