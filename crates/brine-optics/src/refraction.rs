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
/// Law of reflection; equation sheet §9.
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

#[cfg(test)]
mod tests {
    use super::*;

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
