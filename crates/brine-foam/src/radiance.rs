//! Foam radiance after Koepke (1984) and the surface radiance with foam (Darles et al. §4.1.2,
//! corrected).

use std::f64::consts::PI;

use crate::error::{FoamError, check};

/// Reflectance of fresh, dense sea foam in the visible, `R_f = 0.55` (Koepke 1984).
pub const FRESH_FOAM_REFLECTANCE: f64 = 0.55;

/// Koepke's efficiency factor `f_ef = 0.4` (±0.2): the mean reflectance of a whitecap over its
/// life, as a fraction of the fresh-foam value.
pub const KOEPKE_EFFICIENCY: f64 = 0.4;

/// Koepke's whitecap reflectance model.
///
/// The effective reflectance of whitecaps is `R_ef = f_ef R_f` (`0.4 × 0.55 = 0.22 ± 0.11`),
/// flat over 0.4–0.7 µm: fresh foam reflects `R_f`, and its reflectance fades as the foam ages
/// and thins, so that over a whitecap's life it averages `f_ef R_f`. Foam is Lambertian.
///
/// # References
/// Koepke P. 1984, "Effective reflectance of oceanic whitecaps", Appl. Opt. 23(11):1816–1824;
/// docs/equations.md §5 (Darles et al. print `f_ef = 0.4 + 0.2` for `0.4 ± 0.2` and call the
/// reflectance `R_f` a radiance).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KoepkeFoam {
    fresh_reflectance: f64,
    efficiency: f64,
}

impl Default for KoepkeFoam {
    fn default() -> Self {
        Self { fresh_reflectance: FRESH_FOAM_REFLECTANCE, efficiency: KOEPKE_EFFICIENCY }
    }
}

impl KoepkeFoam {
    /// Koepke's whitecap reflectance with other values than his: `R_ef = f_ef R_f`.
    ///
    /// # Arguments
    /// - `fresh_reflectance`: `R_f`, reflectance of fresh dense foam (dimensionless), `(0, 1]`
    ///   (0.55 in the visible).
    /// - `efficiency`: `f_ef`, the life-mean reflectance of a whitecap as a fraction of `R_f`
    ///   (dimensionless), `(0, 1)` (0.4 ± 0.2).
    ///
    /// # Returns
    /// The checked model.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the parameter.
    ///
    /// # References
    /// Koepke P. 1984, "Effective reflectance of oceanic whitecaps", Appl. Opt. 23(11):1816–1824
    /// (`R_f` ≈ 0.55, `f_ef` = 0.4 ± 0.2); docs/equations.md §5.
    pub fn new(fresh_reflectance: f64, efficiency: f64) -> Result<Self, FoamError> {
        check("fresh_reflectance", fresh_reflectance, fresh_reflectance > 0.0 && fresh_reflectance <= 1.0, "(0, 1]")?;
        check("efficiency", efficiency, efficiency > 0.0 && efficiency < 1.0, "(0, 1)")?;
        Ok(Self { fresh_reflectance, efficiency })
    }

    /// `R_f`, the reflectance of fresh foam (dimensionless).
    pub fn fresh_reflectance(&self) -> f64 {
        self.fresh_reflectance
    }

    /// `f_ef`, the efficiency factor (dimensionless).
    pub fn efficiency(&self) -> f64 {
        self.efficiency
    }

    /// Effective whitecap reflectance `R_ef = f_ef R_f`.
    ///
    /// # Returns
    /// `R_ef` (dimensionless), `0.22` with Koepke's values.
    ///
    /// # References
    /// Koepke 1984, §V (effective reflectance); docs/equations.md §5.
    pub fn effective_reflectance(&self) -> f64 {
        self.efficiency * self.fresh_reflectance
    }
}

/// Radiance of a Lambertian foam patch: `L_foam = R (E_sun max(cos θ, 0) + E_sky)/π`.
///
/// # Arguments
/// - `reflectance`: foam reflectance `R`, `[0, 1]` (`R_ef` for whitecaps of mixed ages, or
///   `R_f ρ(age)` from [`crate::FoamHistory`]).
/// - `sun_irradiance`: sun irradiance on a plane normal to the sun `E_sun` (any radiometric or
///   photometric unit, e.g. klx), `≥ 0`.
/// - `cos_sun_normal`: cosine between the surface normal and the sun direction; negative values
///   (sun behind the facet) count as 0.
/// - `sky_irradiance`: downwelling sky irradiance on the facet `E_sky` (same unit), `≥ 0`.
///
/// # Returns
/// `L_foam` in the irradiance unit per steradian (e.g. kcd m⁻² from klx).
///
/// # References
/// Koepke 1984 (Lambertian foam with reflectance `R_ef`); docs/equations.md §5 (`L_foam = R_ef E_d/π`,
/// the `E_d/π` missing from Darles et al.).
pub fn foam_radiance(reflectance: f64, sun_irradiance: f64, cos_sun_normal: f64, sky_irradiance: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&reflectance) && sun_irradiance >= 0.0 && sky_irradiance >= 0.0);
    reflectance * (sun_irradiance * cos_sun_normal.max(0.0) + sky_irradiance) / PI
}

/// Radiance leaving a surface partly covered by foam: `L = (1 − s′) L_water + s′ L_foam`.
///
/// `L_water = F L_reflected + (1 − F) L_refracted` is the foam-free sea (Fresnel-weighted
/// reflection and refraction). This replaces Darles' `L_tot = L(0) + (1 − k_r) L_r(0)` with
/// `L(0) = L_sky + L_sun cos θ_sun + L_foam`, which adds irradiance to radiance and omits the
/// Fresnel weights.
///
/// # Arguments
/// - `foam_cover`: the fraction `s′` of the pixel covered by foam, `[0, 1]`.
/// - `water_radiance`: `L_water` (any radiance unit), `≥ 0`.
/// - `foam_radiance`: `L_foam` from [`foam_radiance`] (same unit), `≥ 0`.
///
/// # Returns
/// `L` in the same unit.
///
/// # References
/// Darles et al. 2007 §4.1.2 (corrected in the docs/equations.md §5); Koepke 1984.
pub fn surface_radiance(foam_cover: f64, water_radiance: f64, foam_radiance: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&foam_cover));
    (1.0 - foam_cover) * water_radiance + foam_cover * foam_radiance
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of two or three flops on values of order 1–7: a few ulps (ε = 2.2×10⁻¹⁶).
    const ROUNDING: f64 = 1e-15;

    #[test]
    fn white_lambertian_under_unit_irradiance() {
        // A perfect white Lambertian surface under E = π has radiance 1.
        assert!((foam_radiance(1.0, PI, 1.0, 0.0) - 1.0).abs() < ROUNDING);
        assert!((foam_radiance(1.0, 2.0, -0.5, PI) - 1.0).abs() < ROUNDING);
    }

    #[test]
    fn composition_interpolates() {
        assert!((surface_radiance(0.0, 3.0, 7.0) - 3.0).abs() < ROUNDING);
        assert!((surface_radiance(1.0, 3.0, 7.0) - 7.0).abs() < ROUNDING);
        assert!((surface_radiance(0.25, 3.0, 7.0) - 4.0).abs() < ROUNDING);
        assert!(KoepkeFoam::new(0.55, 1.0).is_err());
    }
}
