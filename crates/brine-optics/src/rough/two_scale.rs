//! Where the reflections of a sea drawn in two scales go: the waves a renderer draws, and the
//! facets of its BRDF riding on them.
//!
//! **Why.** A renderer that draws the long waves and leaves the short ones to a BRDF masks a
//! reflection twice: the BRDF's integral ([`crate::RoughReflectance`]) sends part of the light
//! its facets reflect into their neighbours, in the frame of the drawn facet they ride on, and the
//! drawn waves around the point then stop part of what is left. The two masks are not
//! independent (a wave face that rises toward the horizon rises at every scale), so their product
//! masks too much: on Gaussian profiles of four decades split in two bands, seen 0.05 and 0.2
//! total slope deviations above grazing (`ν`), the product leaves 10–25 % less light to the sky
//! than the profile does. What the whole surface does is known: Smith's height-correlated
//! masking for the total slope deviation, corrected by the measured escape of the facets seen
//! ([`crate::SlopeVisibility::escape`]), gives a profile's share to 1 %. The drawn waves' factor
//! is that share over the BRDF's own, both taken over the BRDF's slopes about the drawn facet, so
//! that the product is the whole surface's.
//!
//! **Error model.** Measured on two-band profiles (a realisation the visibility table was not
//! measured on; views at `ν` = 0.05, 0.2 and 0.8): with three quarters of the slope variance in the
//! short band the composition leaves 3–5.4 % too little light to the sky, with half 1–5 %, with a
//! quarter it is within 2 % (tested). With nine tenths short and the view at `ν = 0.05` it is 13 %
//! low. There many facets seen lie on drawn facets that face away from the viewer, to which the
//! test's emulation gives no BRDF light, and which a renderer's primary rays never hit on drawn
//! geometry; how much of the 13 % they make is not measured. The factor is taken along the view's
//! vertical plane: a facet's slope across it, and a mirror direction that leaves it, do not enter.

use crate::error::{OpticsError, check};
use crate::ocean_brdf::smith_lambda;
use crate::quadrature::GaussHermite;
use crate::rough::SlopeVisibility;
use std::sync::OnceLock;

/// Points of the Gauss–Hermite rule over the BRDF's slopes.
const ORDER: usize = 5;

/// A facet of the drawn waves seen by a viewer, and the slopes of the sea along the view's
/// vertical plane, for [`drawn_escape`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoScaleFacet {
    cot_theta_v: f64,
    zeta: f64,
    sigma_total: f64,
    sigma_brdf: f64,
}

impl TwoScaleFacet {
    /// Checks the view and the slopes.
    ///
    /// # Arguments
    /// - `cot_theta_v`: `cot θ_v`, the view's angle to the mean sea's normal (the tangent of its
    ///   elevation above the horizon), `> 0`.
    /// - `zeta`: `ζ_d`, the drawn facet's slope along the view's azimuth, `∂h/∂x` with `x`
    ///   toward the viewer (dimensionless; positive for a facet tilted away from the viewer,
    ///   negative for one that faces it more than the mean sea, as `ζ` of
    ///   [`SlopeVisibility`]), finite.
    /// - `sigma_total`: `σ_t`, the slope deviation of every wave along the view's azimuth, `> 0`.
    /// - `sigma_brdf`: `σ_b`, that of the waves in the BRDF, `[0, σ_t]`.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming the first argument outside its domain.
    pub fn new(cot_theta_v: f64, zeta: f64, sigma_total: f64, sigma_brdf: f64) -> Result<Self, OpticsError> {
        check("cot_theta_v", cot_theta_v, cot_theta_v > 0.0, "(0, ∞)")?;
        check("zeta", zeta, true, "finite")?;
        check("sigma_total", sigma_total, sigma_total > 0.0, "(0, ∞)")?;
        check("sigma_brdf", sigma_brdf, (0.0..=sigma_total).contains(&sigma_brdf), "[0, sigma_total]")?;
        Ok(Self { cot_theta_v, zeta, sigma_total, sigma_brdf })
    }
}

/// Smith's `Λ` for a direction whose elevation's tangent is `t > 0` slope deviations.
fn lambda(t: f64) -> f64 {
    smith_lambda(t / (1.0 + t * t).sqrt(), 1.0)
}

/// `G(ν, z)`: the share of the light reflected by a facet at slope `z` (`∂h/∂x` with `x` away from
/// the viewer, in slope deviations: positive for a facet that faces the viewer more than the mean
/// sea, `z = −ζ/σ`) seen
/// at `ν = cot θ_v/σ` (both in slope deviations of one Gaussian surface; `lambda_v = Λ(ν)`) that
/// leaves it unobstructed, `e(ν, s)·(1 + Λ(ν))/(1 + Λ(ν) + Λ(ν + 2z))`, `s = ν + z`; 0 for a
/// facet that does not face the viewer or reflects into the sea.
fn seen_escape(table: &SlopeVisibility, nu: f64, lambda_v: f64, z: f64) -> f64 {
    let (s, m) = (nu + z, nu + 2.0 * z);
    if s <= 0.0 || m <= 0.0 {
        return 0.0;
    }
    table.escape(nu, s) * (1.0 + lambda_v) / (1.0 + lambda_v + lambda(m))
}

/// The drawn waves' share of a reflection's escape: how much more (`> 1`) or less light than the
/// BRDF's own rough reflectance sends to the sky reaches it from a facet of the drawn waves,
///
/// `E_d = Σ_k w_k s_k G(ν, z_d + ẑ_k) ⁄ Σ_k w_k s_k G(ν′, ẑ_k/σ̂_b)`,
///
/// the whole surface's escape over the BRDF's, both over the BRDF's slopes `ẑ_k = √2 σ̂_b x_k`
/// about the drawn facet (Gauss–Hermite nodes `x_k`, weights `w_k`, 5 points) weighted by their
/// projected area `s_k = ν′ + ẑ_k/σ̂_b`; `G` is the escape of a facet seen on one Gaussian
/// surface (Smith's height-correlated form times the measured `e(ν, s)`,
/// [`SlopeVisibility::escape`]); in units of the total slope deviation `σ_t`: `ν = cot θ_v/σ_t`,
/// `z_d = −ζ_d/σ_t`, `σ̂_b = σ_b/σ_t`, and the view in the drawn facet's frame
/// `ν′ = (ν + z_d)/σ̂_b`. Without BRDF slopes (`σ_b = 0`), `E_d = G(ν, z_d)`; with every slope in
/// the BRDF and the facet level, `E_d = 1`. See the module's notes for why and how well.
///
/// # Arguments
/// - `facet`: the view, the drawn facet's slope and the sea's slope deviations.
///
/// # Returns
/// `E_d ≥ 0` (dimensionless); 1 for a facet that faces away from the viewer (`ν′ ≤ 0`).
///
/// # References
/// Smith B.G. 1967, IEEE Trans. Antennas Propag. 15(5); Heitz E. 2014, JCGT 3(2), §6 (the
/// height-correlated form); Bruneton E., Neyret F., Holzschuch N. 2010, CGF 29(2), §4 (the
/// geometry-to-BRDF split); the measured correction in [`SlopeVisibility`].
pub fn drawn_escape(facet: &TwoScaleFacet) -> f64 {
    static RULE: OnceLock<GaussHermite> = OnceLock::new();
    let TwoScaleFacet { cot_theta_v, zeta, sigma_total, sigma_brdf } = *facet;
    debug_assert!(cot_theta_v > 0.0 && sigma_total > 0.0 && (0.0..=sigma_total).contains(&sigma_brdf));
    let table = SlopeVisibility::stored();
    let (nu, z_d, sigma_b) = (cot_theta_v / sigma_total, -zeta / sigma_total, sigma_brdf / sigma_total);
    if sigma_b <= 0.0 {
        return seen_escape(table, nu, lambda(nu), z_d);
    }
    let nu_local = (nu + z_d) / sigma_b;
    if nu_local <= 0.0 {
        return 1.0;
    }
    let rule = RULE.get_or_init(|| GaussHermite::new(ORDER));
    let (lambda_whole, lambda_brdf) = (lambda(nu), lambda(nu_local));
    let (mut whole, mut brdf) = (0.0, 0.0);
    for (x, w) in rule.points() {
        let z = std::f64::consts::SQRT_2 * sigma_b * x;
        let s = nu_local + z / sigma_b;
        if s <= 0.0 {
            continue;
        }
        whole += w * s * seen_escape(table, nu, lambda_whole, z_d + z);
        brdf += w * s * seen_escape(table, nu_local, lambda_brdf, z / sigma_b);
    }
    if brdf > 0.0 { whole / brdf } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The two ends of the split: without BRDF slopes the drawn waves mask as one Gaussian
    /// surface (Smith's height-correlated form times the measured escape, computed here from
    /// `smith_lambda` and the table directly); with every slope in the BRDF and a level facet
    /// they add nothing.
    #[test]
    fn the_split_keeps_its_ends() {
        const ROUNDING: f64 = 1e-12;
        let table = SlopeVisibility::stored();
        // The last facet is tilted away enough that its reflection goes into the sea (0).
        for (cot, zeta, sigma) in
            [(0.02, -0.1, 0.15), (0.05, 0.0, 0.2), (0.3, -0.3, 0.1), (1.0, 0.2, 0.2), (0.1, 0.06, 0.2)]
        {
            let facet = TwoScaleFacet::new(cot, zeta, sigma, 0.0).unwrap();
            let (nu, s) = (cot / sigma, (cot - zeta) / sigma);
            let m = 2.0 * s - nu;
            let up = |t: f64| smith_lambda(t / (1.0 + t * t).sqrt(), 1.0);
            let expected = if m > 0.0 { table.escape(nu, s) * (1.0 + up(nu)) / (1.0 + up(nu) + up(m)) } else { 0.0 };
            assert!((drawn_escape(&facet) - expected).abs() < ROUNDING, "{cot} {zeta}: {}", drawn_escape(&facet));
            if m <= 0.0 {
                assert!(drawn_escape(&facet).abs() < ROUNDING, "{cot} {zeta}: into the sea");
            }
            let level = TwoScaleFacet::new(cot, 0.0, sigma, sigma).unwrap();
            assert!((drawn_escape(&level) - 1.0).abs() < ROUNDING, "{cot}: {}", drawn_escape(&level));
        }
    }

    /// The quadrature's branch tends to the closed form as the BRDF's slopes vanish: with a BRDF
    /// of a thousandth of the total deviation, `E_d` is the whole sea's escape at the drawn
    /// facet's slope (Smith's height-correlated form times the measured `e`, computed apart).
    #[test]
    fn a_vanishing_brdf_leaves_the_whole_sea_s_escape() {
        // The nodes lie within ±0.003 σ of the drawn slope: the table's bilinear slope over that
        // span, and the BRDF's own escape 1 − O(10⁻⁶) at ν′ ≥ 10³.
        const NEAR: f64 = 5e-3;
        let table = SlopeVisibility::stored();
        let up = |t: f64| smith_lambda(t / (1.0 + t * t).sqrt(), 1.0);
        for (cot, zeta, sigma) in [(0.02, -0.1, 0.15), (0.05, -0.05, 0.2), (0.3, -0.3, 0.1)] {
            let facet = TwoScaleFacet::new(cot, zeta, sigma, 1e-3 * sigma).unwrap();
            let (nu, s) = (cot / sigma, (cot - zeta) / sigma);
            let m = 2.0 * s - nu;
            let expected = table.escape(nu, s) * (1.0 + up(nu)) / (1.0 + up(nu) + up(m));
            let got = drawn_escape(&facet);
            assert!((got - expected).abs() < NEAR * expected, "{cot} {zeta}: {got} vs {expected}");
        }
    }

    /// Out-of-range arguments name themselves.
    #[test]
    fn bad_arguments_name_themselves() {
        let err = |r: Result<TwoScaleFacet, OpticsError>| r.unwrap_err().to_string();
        assert!(err(TwoScaleFacet::new(0.0, 0.0, 0.1, 0.0)).contains("cot_theta_v"));
        assert!(err(TwoScaleFacet::new(0.1, f64::NAN, 0.1, 0.0)).contains("zeta"));
        assert!(err(TwoScaleFacet::new(0.1, 0.0, 0.0, 0.0)).contains("sigma_total"));
        assert!(err(TwoScaleFacet::new(0.1, 0.0, 0.1, 0.2)).contains("sigma_brdf"));
    }
}
