//! Mirror reflection and Snell refraction of directions.

use glam::DVec3;

/// Mirror reflection of the direction `d` about the unit normal `n`: `r = d − 2(d·n)n`.
///
/// # Arguments
/// - `d`: incident direction (any length; the result has the same length).
/// - `n`: unit normal (either side).
///
/// # Returns
/// The reflected direction.
///
/// # References
/// Law of reflection; docs/equations.md §9.
#[inline]
pub fn reflect(d: DVec3, n: DVec3) -> DVec3 {
    d - 2.0 * d.dot(n) * n
}

/// Snell refraction of the unit direction `d` through an interface with unit normal `n`.
///
/// `n_i sin θᵢ = n_t sin θ_t`. `n` may face either side; it is flipped to face against `d`.
///
/// # Arguments
/// - `d`: unit incident direction (pointing toward the interface).
/// - `n`: unit normal of the interface.
/// - `n_i`: index of the incident medium, `> 0`.
/// - `n_t`: index of the transmitted medium, `> 0`.
///
/// # Returns
/// The unit transmitted direction, or `None` under total internal reflection.
///
/// # References
/// Snell–Descartes law; vector form as in pbrt-v4 §9.3 (`Refract`).
#[inline]
pub fn refract(d: DVec3, n: DVec3, n_i: f64, n_t: f64) -> Option<DVec3> {
    let n = if d.dot(n) > 0.0 { -n } else { n };
    let eta = n_i / n_t;
    let cos_i = -d.dot(n);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some((eta * d + (eta * cos_i - cos_t) * n).normalize())
}

/// What a viewer under water sees through a facet of the surface (Snell's window): inside the
/// critical angle `asin(1/n_w)` (48.6° for sea water) the sky refracted into the water, its
/// radiance raised by `n_w²` (the same flux in a smaller solid angle) and weighted by the Fresnel
/// transmittance; outside it total internal reflection of the water below.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SnellWindow {
    /// Fresnel reflectance `F` of the facet seen from the water, `[0, 1]` (1 beyond the critical
    /// angle).
    pub reflectance: f64,
    /// Direction above the surface the ray leaves along (unit), `None` under total internal
    /// reflection.
    pub refracted: Option<DVec3>,
}

impl SnellWindow {
    /// The window of the ray `d` (unit, from the water toward the surface) through a facet of unit
    /// normal `n` (either side).
    ///
    /// # References
    /// Snell–Descartes law and Fresnel's equations ([`crate::fresnel_dielectric`]); the `n²`
    /// radiance law (Nicodemus 1963, "Radiance", Am. J. Phys. 31:368).
    pub fn new(d: DVec3, n: DVec3) -> Self {
        let cos_i = d.dot(n).abs();
        let reflectance = crate::fresnel_dielectric(cos_i, crate::WATER_IOR, 1.0);
        Self { reflectance, refracted: refract(d, n, crate::WATER_IOR, 1.0) }
    }

    /// Radiance under the surface along the ray: `(1 − F) L_above n_w² + F L_below` (in the unit
    /// of the radiances given), `L_above` the radiance arriving along [`Self::refracted`] (0 under
    /// total internal reflection) and `L_below` the water's radiance reflected by the facet.
    pub fn radiance(&self, above: DVec3, below: DVec3) -> DVec3 {
        let n = crate::WATER_IOR;
        (1.0 - self.reflectance) * above * n * n + self.reflectance * below
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Inside the critical angle the sky shows through; beyond it the water is a mirror.
    #[test]
    fn snells_window_has_its_critical_angle() {
        let up = DVec3::Y;
        let straight = SnellWindow::new(up, up);
        assert!(straight.refracted.is_some() && straight.reflectance < 0.03);
        let critical = (1.0 / crate::WATER_IOR).asin();
        let steep = |a: f64| DVec3::new(a.sin(), a.cos(), 0.0);
        assert!(SnellWindow::new(steep(critical - 0.01), up).refracted.is_some());
        let outside = SnellWindow::new(steep(critical + 0.01), up);
        assert!(outside.refracted.is_none() && (outside.reflectance - 1.0).abs() < 1e-12);
        assert_eq!(outside.radiance(DVec3::ONE, DVec3::splat(0.2)), DVec3::splat(0.2));
    }

    #[test]
    fn refraction_obeys_snell_and_total_internal_reflection() {
        /// A few roundings of order-one terms.
        const ROUNDING: f64 = 1e-12;
        let n = DVec3::Y;
        let theta = 40f64.to_radians();
        let d = DVec3::new(theta.sin(), -theta.cos(), 0.0);
        let t = refract(d, n, 1.0, 1.333).unwrap();
        assert!((theta.sin() - 1.333 * t.x).abs() < ROUNDING);
        assert!(t.y < 0.0);
        // From water at 60° > 48.6°: total internal reflection.
        let up = DVec3::new(60f64.to_radians().sin(), 60f64.to_radians().cos(), 0.0);
        assert!(refract(up, n, 1.333, 1.0).is_none());
    }

    #[test]
    fn reflection_preserves_the_tangential_part() {
        /// `d − 2(d·n)n` with exact inputs: one rounding per component.
        const ROUNDING: f64 = 1e-15;
        let r = reflect(DVec3::new(0.6, -0.8, 0.0), DVec3::Y);
        assert!((r - DVec3::new(0.6, 0.8, 0.0)).length() < ROUNDING);
    }
}
