//! The radiance of the water body seen along a refracted ray: Darles et al. 2007 §4.3 after
//! Premoze & Ashikhmin 2001, with the corrections of docs/equations.md §7.

use std::f64::consts::PI;

use crate::fresnel_dielectric;

/// Irradiance reflectance just below the surface, `R(0⁻) = 0.33 b_b/a`.
///
/// # Arguments
/// - `b_b`: backscattering coefficient (m⁻¹), `≥ 0`.
/// - `a`: absorption coefficient (m⁻¹), `> 0`.
///
/// # Returns
/// `R` (dimensionless, `E_u/E_d`); about 0.01–0.1 in the open ocean.
///
/// # References
/// Morel A., Prieur L. 1977, "Analysis of variations in ocean color", Limnol. Oceanogr. 22;
/// Darles et al. 2007 Eq. 9; Premoze & Ashikhmin 2001; docs/equations.md §7.
#[inline]
pub fn irradiance_reflectance(b_b: f64, a: f64) -> f64 {
    debug_assert!(a > 0.0 && b_b >= 0.0);
    0.33 * b_b / a
}

/// Morel's (1988) irradiance reflectance `R = 0.33 b_b/(u K_d)`, `u = 0.90 (1 − R)/(1 + 2.25 R)`,
/// solved by fixed-point iteration from `u = 0.75` to a relative change below 10⁻¹².
///
/// # Arguments
/// - `b_b`: backscattering coefficient (m⁻¹), `≥ 0`.
/// - `k_d`: diffuse attenuation coefficient (m⁻¹), `> 0`.
///
/// # Returns
/// `R` (dimensionless).
///
/// # References
/// Morel A. 1988, JGR 93(C9), Eq. 12–13 (as coded in 6S `morcasiwat`); docs/equations.md §7.
pub fn irradiance_reflectance_morel(b_b: f64, k_d: f64) -> f64 {
    debug_assert!(k_d > 0.0 && b_b >= 0.0);
    let mut r = 0.33 * b_b / (0.75 * k_d);
    for _ in 0..100 {
        let u = 0.90 * (1.0 - r) / (1.0 + 2.25 * r);
        let next = 0.33 * b_b / (u * k_d);
        if (next - r).abs() <= 1e-12 * next.abs() {
            return next;
        }
        r = next;
    }
    r
}

/// Diffuse (isotropic) upwelling radiance just below the surface, `L_df(0) = R E_d(0⁻)/π`.
///
/// # Arguments
/// - `reflectance`: `R(0⁻)` (dimensionless), `≥ 0`.
/// - `e_d_below`: downwelling irradiance just below the surface, `E_d(0⁻)`, in any unit (W m⁻² or
///   klx), `≥ 0`.
///
/// # Returns
/// `L_df(0)` in that unit per steradian.
///
/// # References
/// Darles et al. 2007 Eq. 9 (corrected: an irradiance `E_d`, not the radiance `L(0)` of their
/// second form); docs/equations.md §7.
#[inline]
pub fn diffuse_upwelling_radiance(reflectance: f64, e_d_below: f64) -> f64 {
    reflectance * e_d_below / PI
}

/// Upwelling radiance just below the surface along a refracted ray that meets the sea floor (or
/// not), `L(0, θ) = L_b e^{−c R_p} + L_df(0) [1 − e^{−(c + K_d cos θ) R_p}]`.
///
/// # Arguments
/// - `l_df0`: diffuse radiance `L_df(0)` of [`diffuse_upwelling_radiance`], `≥ 0`.
/// - `c`: beam attenuation `a + b` (m⁻¹), `> 0`.
/// - `k_d`: diffuse attenuation coefficient (m⁻¹), `≥ 0`.
/// - `cos_theta`: cosine of the zenith angle of the (upward) ray in water, `[0, 1]`.
/// - `path_m`: path length `R_p` from the surface to the floor along the ray (m), `≥ 0`, or
///   `f64::INFINITY` for deep water.
/// - `floor_radiance`: radiance `L_b` leaving the floor toward the surface, same unit as `l_df0`.
///
/// # Returns
/// `L(0, θ)` in the unit of `l_df0`; `L_df(0)` for deep water.
///
/// # References
/// Darles et al. 2007 Eq. 8 and 11 (corrected: `cos θ` kept in the exponent, path length not
/// depth, the floor term restored); Premoze & Ashikhmin 2001; docs/equations.md §7.
#[inline]
pub fn refracted_ray_radiance(l_df0: f64, c: f64, k_d: f64, cos_theta: f64, path_m: f64, floor_radiance: f64) -> f64 {
    debug_assert!(c > 0.0 && k_d >= 0.0 && path_m >= 0.0);
    let mu = cos_theta.clamp(0.0, 1.0);
    if path_m.is_infinite() {
        return l_df0;
    }
    floor_radiance * (-c * path_m).exp() + l_df0 * (1.0 - (-(c + k_d * mu) * path_m).exp())
}

/// The same radiance as the discretised sum along the ray of Darles et al. Eq. 11 (corrected):
/// `L_b e^{−c R_p} + Σ_i L_df(0) (c + K_d cos θ) e^{−K_d z_i} e^{−c s_i} Δs`, midpoints
/// `s_i = (i + ½) Δs`, `z_i = s_i cos θ`, `Δs = R_p/n`. It tends to [`refracted_ray_radiance`]
/// as `n` grows (error `O(Δs²)`).
///
/// # Arguments
/// As [`refracted_ray_radiance`] with a finite `path_m`, plus `segments`, `n ≥ 1`.
///
/// # Returns
/// The radiance in the unit of `l_df0`.
///
/// # References
/// Darles et al. 2007 Eq. 10–11; docs/equations.md §7.
pub fn refracted_ray_radiance_sum(
    l_df0: f64,
    c: f64,
    k_d: f64,
    cos_theta: f64,
    path_m: f64,
    floor_radiance: f64,
    segments: usize,
) -> f64 {
    let n = segments.max(1);
    let mu = cos_theta.clamp(0.0, 1.0);
    let ds = path_m / n as f64;
    let sum: f64 = (0..n)
        .map(|i| {
            let s = (i as f64 + 0.5) * ds;
            l_df0 * (c + k_d * mu) * (-k_d * s * mu).exp() * (-c * s).exp() * ds
        })
        .sum();
    floor_radiance * (-c * path_m).exp() + sum
}

/// Radiance leaving a Lambertian sea floor of albedo `ρ_b` at depth `z_b`:
/// `L_b = ρ_b E_d(0⁻) e^{−K_d z_b}/π`.
///
/// # Arguments
/// - `albedo`: floor reflectance `ρ_b`, `[0, 1]`.
/// - `e_d_below`: downwelling irradiance just below the surface, any unit, `≥ 0`.
/// - `k_d`: diffuse attenuation coefficient (m⁻¹), `≥ 0`.
/// - `depth_m`: floor depth below the surface (m), `≥ 0`.
///
/// # Returns
/// `L_b`, in the unit of `e_d_below` per steradian.
///
/// # References
/// Lambert's law with `E_d(z) = E_d(0⁻) e^{−K_d z}` (definition of `K_d`); Premoze & Ashikhmin
/// 2001 (sea-floor term); docs/equations.md §7.
#[inline]
pub fn lambertian_floor_radiance(albedo: f64, e_d_below: f64, k_d: f64, depth_m: f64) -> f64 {
    albedo * e_d_below * (-k_d * depth_m.max(0.0)).exp() / PI
}

/// Radiance just above the surface from radiance `L` just below it, along the refracted pair of
/// directions: `L_air = (1 − F) L / n²` (`F` for the ray leaving the water, `n = n_water/n_air`).
///
/// # Arguments
/// - `radiance_below`: radiance in the water, any unit.
/// - `cos_theta_water`: cosine of the ray's angle to the normal in the water, `[0, 1]`.
/// - `n_water`: index of water relative to air, `> 1`.
///
/// # Returns
/// The radiance in air (same unit); `0` beyond the critical angle.
///
/// # References
/// The `n²` law of radiance across a refracting interface (e.g. Mobley 1994, *Light and Water*,
/// §4.3); Fresnel transmittance `1 − F`; docs/equations.md §7 and §9.
#[inline]
pub fn radiance_out_of_water(radiance_below: f64, cos_theta_water: f64, n_water: f64) -> f64 {
    let f = fresnel_dielectric(cos_theta_water, n_water, 1.0);
    (1.0 - f) * radiance_below / (n_water * n_water)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn deep_water_gives_the_diffuse_radiance_and_a_shallow_floor_shows() {
        /// `e^{−∞} = 0` and `e⁰ = 1` exactly: at most one rounding.
        const ROUNDING: f64 = 1e-15;
        let l = refracted_ray_radiance(1.0, 0.1, 0.05, 0.8, f64::INFINITY, 5.0);
        assert_relative_eq!(l, 1.0, max_relative = ROUNDING);
        let l0 = refracted_ray_radiance(1.0, 0.1, 0.05, 0.8, 0.0, 5.0);
        assert_relative_eq!(l0, 5.0, max_relative = ROUNDING);
    }

    #[test]
    fn the_sum_converges_to_the_closed_form() {
        let exact = refracted_ray_radiance(0.7, 0.3, 0.12, 0.6, 8.0, 0.2);
        let sum = refracted_ray_radiance_sum(0.7, 0.3, 0.12, 0.6, 8.0, 0.2, 4000);
        /// Midpoint rule: relative error ≈ `((c + K_d μ) Δs)²/24` ≈ 10⁻⁸ here (Δs = 2 mm); ×10.
        const MIDPOINT: f64 = 1e-7;
        assert_relative_eq!(sum, exact, max_relative = MIDPOINT);
    }

    #[test]
    fn morel_iteration_is_a_fixed_point() {
        let r = irradiance_reflectance_morel(0.006, 0.11);
        let u = 0.90 * (1.0 - r) / (1.0 + 2.25 * r);
        /// The iteration stops at a relative change below 10⁻¹²; ×10.
        const FIXED_POINT: f64 = 1e-11;
        assert_relative_eq!(r, 0.33 * 0.006 / (u * 0.11), max_relative = FIXED_POINT);
    }
}
