//! Light scattered by spray along a camera ray: the per-sphere integration of Darles §4.2,
//! corrected to a product of transmittances.

use std::f64::consts::PI;

use crate::error::{FoamError, check};
use crate::medium::SprayMedium;
use crate::spume::SpumeLayer;

/// Henyey–Greenstein phase function
/// `p(Θ) = (1 − g²) / (4π (1 + g² − 2g cos Θ)^{3/2})`, normalised to `∫ p dω = 1`.
///
/// # Arguments
/// - `cos_theta`: cosine of the scattering angle `Θ` between the light's and the scattered
///   directions of travel, `[−1, 1]`.
/// - `g`: asymmetry parameter `(−1, 1)`.
///
/// # Returns
/// `p` (sr⁻¹).
///
/// # References
/// Henyey L., Greenstein J. 1941, Astrophys. J. 93:70–83; docs/equations.md §8 (Hoffman–Preetham
/// Mie phase).
pub fn henyey_greenstein(cos_theta: f64, g: f64) -> f64 {
    debug_assert!(g > -1.0 && g < 1.0);
    let d = 1.0 + g * g - 2.0 * g * cos_theta.clamp(-1.0, 1.0);
    (1.0 - g * g) / (4.0 * PI * d * d.sqrt())
}

/// Lighting of the spray seen along one camera ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SprayLighting {
    /// Sun irradiance on a plane normal to the sun, above the spray `E_sun` (any unit, e.g. klx),
    /// `≥ 0`.
    pub sun_irradiance: f64,
    /// Sine of the sun elevation, `(0, 1]`: sunlight crosses the spray above a point along a
    /// slant path `1/sin` times the vertical one.
    pub sin_sun_elevation: f64,
    /// Cosine of the scattering angle: `d·l` for a camera ray of unit direction `d` (from the
    /// camera) and the unit direction toward the sun `l`; 1 when looking into the sun.
    pub cos_view_sun: f64,
    /// Mean radiance of the sky over the upper hemisphere `L̄_sky` (irradiance unit per sr),
    /// `≥ 0`.
    pub sky_radiance: f64,
}

/// Optical properties of spray drops for scattering.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SprayScattering {
    /// Single-scattering albedo `ϖ`, `[0, 1]`; water drops barely absorb visible light: 0.99.
    pub albedo: f64,
    /// Henyey–Greenstein asymmetry `g`, `[0, 0.95]`; 0.75 for drops of a few micrometres,
    /// strongly forward-scattering.
    pub asymmetry: f64,
}

impl Default for SprayScattering {
    fn default() -> Self {
        Self { albedo: 0.99, asymmetry: 0.75 }
    }
}

impl SprayScattering {
    /// Checks the parameters.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the parameter.
    pub fn checked(self) -> Result<Self, FoamError> {
        check("albedo", self.albedo, (0.0..=1.0).contains(&self.albedo), "[0, 1]")?;
        check("asymmetry", self.asymmetry, (0.0..=0.95).contains(&self.asymmetry), "[0, 0.95]")?;
        Ok(self)
    }
}

/// Accumulates the transmittance and the in-scattered radiance of spray along a camera ray,
/// segment by segment (one per tracing sphere below `z_max`), from the camera outward.
///
/// Darles et al. sum `e^{−k_e Δz}` over spheres and multiply by `L_sky + L_sun cos θ_sun`. The
/// corrected single-scattering integral over segments `i` of optical depth `Δτᵢ` is
///
/// `T = Πᵢ e^{−Δτᵢ}`,
/// `L_in = Σᵢ T_{<i} (1 − e^{−Δτᵢ}) Jᵢ`,
/// `Jᵢ = ϖ (E_sun e^{−τ_above(zᵢ)/sin h} p_HG(cos Θ) + ½ L̄_sky)`,
///
/// with `T_{<i}` the transmittance from the camera to segment `i`, `zᵢ` its mid-height,
/// `τ_above` the spray optical depth above it (sunlight is dimmed on its way down) and `½ L̄_sky`
/// the sky seen through a phase function averaged over the upper hemisphere. The radiance reaching
/// the camera is `T L_surface + L_in` ([`SprayRay::radiance`]).
///
/// # References
/// Darles et al. 2007 §4.2 (per-sphere integration; errata in the docs/equations.md §6: a product of
/// transmittances, not a sum); Preetham, Shirley & Smits 1999 and Hoffman & Preetham 2002
/// (extinction plus in-scattering, docs/equations.md §8).
#[derive(Debug, Clone, Copy)]
pub struct SprayRay<'a> {
    medium: Option<&'a SprayMedium>,
    spume: Option<&'a SpumeLayer>,
    sun_term: f64,
    sky_term: f64,
    sin_sun: f64,
    transmittance: f64,
    in_scattered: f64,
    /// The sky's part of `in_scattered`.
    in_scattered_sky: f64,
}

impl<'a> SprayRay<'a> {
    /// Starts a ray at the camera.
    ///
    /// # Arguments
    /// - `medium`: the spray.
    /// - `scattering`: drop optics (checked with [`SprayScattering::checked`]).
    /// - `lighting`: sun and sky for this ray (irradiance `≥ 0` in any unit, sky radiance `≥ 0`
    ///   in that unit per sr); `sin_sun_elevation` is clamped to at least 10⁻³.
    ///
    /// # Returns
    /// A ray with `T = 1` and `L_in = 0`; its source terms are `ϖ E_sun p_HG(cos Θ)` and
    /// `ϖ ½ L̄_sky`.
    ///
    /// # References
    /// See [`SprayRay`] (Darles et al. 2007 §4.2, corrected; Henyey & Greenstein 1941).
    pub fn new(medium: &'a SprayMedium, scattering: &SprayScattering, lighting: &SprayLighting) -> Self {
        Self::start(Some(medium), None, scattering, lighting)
    }

    /// A ray at the camera through the given media, with its source terms.
    fn start(
        medium: Option<&'a SprayMedium>,
        spume: Option<&'a SpumeLayer>,
        scattering: &SprayScattering,
        lighting: &SprayLighting,
    ) -> Self {
        debug_assert!(lighting.sun_irradiance >= 0.0 && lighting.sky_radiance >= 0.0);
        let phase = henyey_greenstein(lighting.cos_view_sun, scattering.asymmetry);
        Self {
            medium,
            spume,
            sun_term: scattering.albedo * lighting.sun_irradiance * phase,
            sky_term: scattering.albedo * 0.5 * lighting.sky_radiance,
            sin_sun: lighting.sin_sun_elevation.clamp(1e-3, 1.0),
            transmittance: 1.0,
            in_scattered: 0.0,
            in_scattered_sky: 0.0,
        }
    }

    /// Adds a segment of the ray.
    ///
    /// # Arguments
    /// - `z0`, `z1`: heights above the sea of the segment's near and far ends (m).
    /// - `length_m`: its length (m), `≥ |z1 − z0|`.
    /// - `foam_factor`: `s′/W` at the orthogonal projection of the segment on the sea.
    ///
    /// # References
    /// See [`SprayRay`] (Darles et al. 2007 §4.2, corrected).
    pub fn step(&mut self, z0: f64, z1: f64, length_m: f64, foam_factor: f64) {
        let bubbles = self.medium.map_or(0.0, |m| m.segment_optical_depth(z0, z1, length_m, foam_factor));
        let spume = self.spume.map_or(0.0, |s| foam_factor * s.segment_optical_depth(z0, z1, length_m));
        self.add(bubbles + spume, 0.5 * (z0 + z1), foam_factor);
    }

    /// Adds the rest of a ray that leaves the sea behind: from height `y0` up to space at
    /// elevation sine `d_y ≥ 0` over the curved Earth. Only the spume layer counts there (the
    /// sky's own aerosol is in the sky model); sunlight reaching the drops is dimmed by the
    /// spume above `y0`, where most of the path's spume is.
    ///
    /// # Arguments
    /// - `y0`: height of the start (m), `≥ 0`.
    /// - `d_y`: sine of the ray's elevation, `[0, 1]`.
    ///
    /// # References
    /// [`SpumeLayer::optical_depth_to_space`].
    pub fn step_to_space(&mut self, y0: f64, d_y: f64) {
        let dtau = self.spume.map_or(0.0, |s| s.optical_depth_to_space(y0.max(0.0), d_y.clamp(0.0, 1.0)));
        self.add(dtau, y0, 1.0);
    }

    /// One segment of optical depth `dtau` whose middle is at height `zmid`.
    fn add(&mut self, dtau: f64, zmid: f64, foam_factor: f64) {
        if dtau <= 0.0 {
            return;
        }
        let above = self.medium.map_or(0.0, |m| m.optical_depth_above(zmid, foam_factor))
            + self.spume.map_or(0.0, |s| foam_factor * s.optical_depth_above(zmid));
        let sun = self.sun_term * libm::exp(-above / self.sin_sun);
        let t_seg = libm::exp(-dtau);
        let weight = self.transmittance * (1.0 - t_seg);
        self.in_scattered += weight * (sun + self.sky_term);
        self.in_scattered_sky += weight * self.sky_term;
        self.transmittance *= t_seg;
    }

    /// The same ray through the spume layer as well ([`SpumeLayer`]), its optical depth added to
    /// the bubble drops' in every segment.
    pub fn with_spume(mut self, spume: &'a SpumeLayer) -> Self {
        self.spume = Some(spume);
        self
    }

    /// A ray through the spume layer alone (no bubble-drop medium): for rays that leave the sea
    /// behind, whose own aerosol the sky model holds.
    ///
    /// # Arguments
    /// As [`SprayRay::new`], with the spume layer in place of the medium.
    pub fn spume_only(spume: &'a SpumeLayer, scattering: &SprayScattering, lighting: &SprayLighting) -> Self {
        Self::start(None, Some(spume), scattering, lighting)
    }

    /// Transmittance from the camera to the end of the last segment, in `(0, 1]`.
    pub fn transmittance(&self) -> f64 {
        self.transmittance
    }

    /// Radiance scattered toward the camera by the spray so far (irradiance unit per sr).
    pub fn in_scattered(&self) -> f64 {
        self.in_scattered
    }

    /// The in-scattered radiance split into its sun's and its sky's parts, `(L_in,sun, L_in,sky)`
    /// (their sum is [`SprayRay::in_scattered`]): one ray lit by a unit sun and a unit sky serves
    /// callers that colour the two lights differently.
    pub fn in_scattered_parts(&self) -> (f64, f64) {
        (self.in_scattered - self.in_scattered_sky, self.in_scattered_sky)
    }

    /// Radiance reaching the camera from a surface of radiance `surface_radiance` behind the
    /// spray: `T L_surface + L_in`.
    pub fn radiance(&self, surface_radiance: f64) -> f64 {
        self.transmittance * surface_radiance + self.in_scattered
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SprayParams;

    /// Midpoint rule in `cos Θ` on 2·10⁴ points: the g = 0.9 forward peak (width ~`1 − g` = 0.1
    /// in `cos Θ`, 10³ points) is resolved to better than 10⁻⁴.
    const PHASE_NORM: f64 = 1e-3;

    /// 2000 segments of 10 km at `k_e` ≈ 10⁻² m⁻¹ (40 m/s): optical depth ~2×10⁵, `T` = 0
    /// exactly; 10⁻⁶ only asks for an opaque path.
    const OPAQUE: f64 = 1e-6;

    /// The radiance of an opaque path is the source `ϖ ½ L̄ = 1` up to the surface term `T·100`
    /// and the rounding of 2000 accumulations.
    const SOURCE_TOL: f64 = 1e-4;

    #[test]
    fn phase_function_is_normalised() {
        for &g in &[0.0, 0.5, 0.75, 0.9] {
            let n = 20_000;
            let mut s = 0.0;
            for i in 0..n {
                let mu = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
                s += 2.0 * PI * henyey_greenstein(mu, g) * 2.0 / n as f64;
            }
            assert!((s - 1.0).abs() < PHASE_NORM, "g = {g}: {s}");
        }
    }

    #[test]
    fn thick_uniform_spray_tends_to_its_source() {
        // An optically thick horizontal path through uniform spray: the radiance tends to the
        // source J and the surface behind vanishes.
        let m = SprayMedium::new(&SprayParams { u10: 40.0, ..SprayParams::default() }).unwrap();
        let sc = SprayScattering { albedo: 1.0, asymmetry: 0.0 };
        let light = SprayLighting { sun_irradiance: 0.0, sin_sun_elevation: 1.0, cos_view_sun: 0.0, sky_radiance: 2.0 };
        let mut ray = SprayRay::new(&m, &sc, &light);
        for _ in 0..2000 {
            ray.step(1.0, 1.0, 1e4, 1.0);
        }
        assert!(ray.transmittance() < OPAQUE, "{}", ray.transmittance());
        assert!((ray.radiance(100.0) - 1.0).abs() < SOURCE_TOL, "{}", ray.radiance(100.0));
    }
}
