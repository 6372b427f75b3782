//! Fresnel reflectance of a smooth dielectric interface.

/// Refractive index of sea water in the visible used by default (Darles, Chen, Bruneton: 1.333).
pub const WATER_IOR: f64 = 1.333;

/// Exact unpolarised Fresnel reflectance of a dielectric interface, `F = ½(r_s² + r_p²)`.
///
/// With `c = |cos θᵢ|`, `n = n_t/n_i` and `g² = n² + c² − 1`:
/// `F = ½ (g − c)²/(g + c)² · [1 + ((c(g + c) − 1)/(c(g − c) + 1))²]`, and `F = 1` when `g² < 0`
/// (total internal reflection, `sin θᵢ > n_t/n_i`).
///
/// # Arguments
/// - `cos_theta_i`: cosine of the angle of incidence, `[−1, 1]` (the sign is ignored).
/// - `n_i`: index of the medium the light comes from, `> 0` (1.0 for air).
/// - `n_t`: index of the medium across the interface, `> 0` (1.333 for water).
///
/// # Returns
/// The reflected fraction of the power, in `[0, 1]`; the transmitted fraction is `1 − F`.
///
/// # References
/// Cook R., Torrance K. 1982, "A reflectance model for computer graphics", ACM TOG 1(1), Eq. (the
/// unpolarised form); Chen et al. 2007 §3.4 (with the erratum of docs/equations.md §9: `g` is
/// `√((n_b/n_a)² + k² − 1)`).
#[inline]
pub fn fresnel_dielectric(cos_theta_i: f64, n_i: f64, n_t: f64) -> f64 {
    debug_assert!(n_i > 0.0 && n_t > 0.0, "indices must be positive: {n_i}, {n_t}");
    let c = cos_theta_i.abs().min(1.0);
    let n = n_t / n_i;
    let g2 = n * n + c * c - 1.0;
    if g2 < 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    if g + c == 0.0 {
        return 1.0;
    }
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    let r = 0.5 * a * a * (1.0 + b * b);
    // The clamp absorbs rounding only: the formula is a fraction.
    debug_assert!(r <= 1.0 + FRACTION_ROUNDING, "R = {r} at cos θ = {c}, n = {n}");
    r.clamp(0.0, 1.0)
}

/// Rounding of the Fresnel formula's terms of order one, which may carry `R` past 1.
const FRACTION_ROUNDING: f64 = 1e-12;

/// Reflectance at normal incidence, `F₀ = ((n_i − n_t)/(n_i + n_t))²`.
///
/// # Arguments
/// - `n_i`, `n_t`: indices on either side, `> 0`.
///
/// # Returns
/// `F₀` in `[0, 1)`; `0.0204` for air–water at `n = 1.333`.
///
/// # References
/// Fresnel equations at `θ = 0`; docs/equations.md §9.
#[inline]
pub fn fresnel_normal(n_i: f64, n_t: f64) -> f64 {
    let r = (n_i - n_t) / (n_i + n_t);
    r * r
}

/// Schlick's approximation `F ≈ F₀ + (1 − F₀)(1 − c)⁵`.
///
/// When light goes from the denser medium (`n_i > n_t`), `c` is the cosine on the transmitted
/// side, `√(1 − (n_i/n_t)² sin²θᵢ)`, and `F = 1` beyond the critical angle.
///
/// # Arguments
/// - `cos_theta_i`: cosine of the angle of incidence, `[−1, 1]` (sign ignored).
/// - `n_i`, `n_t`: indices, `> 0`.
///
/// # Returns
/// The approximate reflectance in `[0, 1]`. Its error against [`fresnel_dielectric`] for
/// air → water is at most 0.0592 (at 83.8°; see the tests and `docs/models/brine-optics.md`).
///
/// # References
/// Schlick C. 1994, "An inexpensive BRDF model for physically-based rendering", CGF 13(3), Eq. 24.
#[inline]
pub fn fresnel_schlick(cos_theta_i: f64, n_i: f64, n_t: f64) -> f64 {
    let f0 = fresnel_normal(n_i, n_t);
    let mut c = cos_theta_i.abs().min(1.0);
    if n_i > n_t {
        let sin2_t = (n_i / n_t).powi(2) * (1.0 - c * c);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        c = (1.0 - sin2_t).sqrt();
    }
    f0 + (1.0 - f0) * (1.0 - c).powi(5)
}

/// Fresnel transmittance `T = 1 − F` of a dielectric interface (fraction of the power).
///
/// # Arguments
/// As [`fresnel_dielectric`].
///
/// # Returns
/// `T` in `[0, 1]`; `0` under total internal reflection. Reciprocal: `T(θᵢ; n_i → n_t) =
/// T(θ_t; n_t → n_i)` for the Snell pair `(θᵢ, θ_t)`.
///
/// # References
/// Energy conservation at a non-absorbing interface; docs/equations.md §9.
#[inline]
pub fn fresnel_transmittance(cos_theta_i: f64, n_i: f64, n_t: f64) -> f64 {
    1.0 - fresnel_dielectric(cos_theta_i, n_i, n_t)
}

/// Critical angle of total internal reflection from the denser side, `θ_c = asin(n_t/n_i)`.
///
/// # Arguments
/// - `n_i`, `n_t`: indices, `n_i > n_t > 0`.
///
/// # Returns
/// `θ_c` (rad); `None` if `n_i ≤ n_t` (no total internal reflection). 48.607° from water (1.333).
///
/// # References
/// Snell's law at `θ_t = 90°`; docs/equations.md §9.
pub fn critical_angle(n_i: f64, n_t: f64) -> Option<f64> {
    (n_i > n_t).then(|| (n_t / n_i).asin())
}

/// Hemispherical (diffuse) Fresnel reflectance for uniform radiance incident from the side of
/// index `n_i`: `F_dr = 2 ∫₀¹ F(μ) μ dμ`, computed exactly (the part beyond the critical angle,
/// where `F = 1`, in closed form; the rest by 64-point Gauss–Legendre quadrature in
/// `t`, `μ = μ_c + (1 − μ_c) t²`).
///
/// # Arguments
/// - `n_i`: index on the incident side, `> 0`.
/// - `n_t`: index across the interface, `> 0`.
///
/// # Returns
/// `F_dr` in `[0, 1]`: 0.0664 for a uniform sky on water (1 → 1.333), 0.4746 for light inside
/// water (1.333 → 1); Jensen's `F_dr(η)` is this with `n_i = η`, `n_t = 1`.
///
/// # References
/// Jensen et al. 2001 §2.3 (definition of `F_dr`); Egan & Hilgeman 1973 (its fit).
pub fn hemispherical_fresnel_reflectance(n_i: f64, n_t: f64) -> f64 {
    // μ_c = cosine of the critical angle (0 when there is none).
    let mu_c = if n_i > n_t { (1.0 - (n_t / n_i).powi(2)).sqrt() } else { 0.0 };
    let (x, w) = crate::quadrature::gauss_legendre(64);
    // μ = μ_c + (1 − μ_c) t² removes the square-root kink of F at μ_c; t ∈ [0, 1].
    let span = 1.0 - mu_c;
    let smooth: f64 = x
        .iter()
        .zip(&w)
        .map(|(x, w)| {
            let t = 0.5 * (x + 1.0);
            let mu = mu_c + span * t * t;
            0.5 * w * fresnel_dielectric(mu, n_i, n_t) * mu * 2.0 * span * t
        })
        .sum();
    mu_c * mu_c + 2.0 * smooth
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The oracle values of docs/equations.md are printed with 6 significant digits.
    const ORACLE: f64 = 2e-5;

    fn cos_deg(d: f64) -> f64 {
        d.to_radians().cos()
    }

    #[test]
    fn exact_fresnel_oracles_air_to_water() {
        for (deg, f) in [(0.0, 0.020373), (45.0, 0.027898), (60.0, 0.059691), (80.0, 0.347917)] {
            assert_relative_eq!(fresnel_dielectric(cos_deg(deg), 1.0, 1.333), f, max_relative = ORACLE);
        }
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "total internal reflection returns exactly 1")]
    fn schlick_oracles_and_total_internal_reflection() {
        assert_relative_eq!(fresnel_schlick(cos_deg(45.0), 1.0, 1.333), 0.022485, max_relative = ORACLE);
        assert_relative_eq!(fresnel_schlick(cos_deg(80.0), 1.0, 1.333), 0.397846, max_relative = ORACLE);
        // Critical angle from water: asin(1/1.333) = 48.607°.
        assert!(fresnel_dielectric(cos_deg(48.7), 1.333, 1.0) == 1.0);
        assert!(fresnel_dielectric(cos_deg(48.5), 1.333, 1.0) < 1.0);
    }

    #[test]
    fn normal_incidence_matches_the_closed_form() {
        /// Two formulas of a handful of roundings each (≈ 10ε), with margin.
        const ROUNDING: f64 = 1e-12;
        assert_relative_eq!(fresnel_dielectric(1.0, 1.0, 1.333), fresnel_normal(1.0, 1.333), max_relative = ROUNDING);
    }
}
