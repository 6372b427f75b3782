//! Bounds, invariants and analytic limits, on random points (proptest) and by quadrature.

use std::f64::consts::PI;

use approx::assert_relative_eq;
use brine_optics::*;
use glam::DVec3;
use proptest::prelude::*;

/// Composite Gauss–Legendre integral of `f` over `[a, b]`, `panels` panels of 16 points.
fn integrate(a: f64, b: f64, panels: usize, f: &mut impl FnMut(f64) -> f64) -> f64 {
    brine_testkit::quadrature::gauss_legendre_composite(f, a, b, panels, 16)
}

/// Reference integral over facet slopes `ζ` of `g(ζ, n)` for facets facing `v`, in coordinates
/// `(s, t)` along and across `v`'s azimuth so that the visibility cut `v·n = 0`
/// (`s = v_z/|v_h|`) is a panel edge; `±10σ` around the mean.
fn slope_integral(v: DVec3, var: &SlopeVariance, mut g: impl FnMut(f64, f64, DVec3) -> f64) -> f64 {
    let vh = (v.x * v.x + v.y * v.y).sqrt();
    let (c, s) = if vh > 0.0 { (v.x / vh, v.y / vh) } else { (1.0, 0.0) };
    let l = 10.0 * var.sigma_x2().max(var.sigma_y2()).sqrt();
    let s_max = if vh > 0.0 { (v.z / vh).min(l) } else { l };
    if s_max <= -l {
        return 0.0;
    }
    integrate(-l, s_max, 48, &mut |ss| {
        integrate(-l, l, 48, &mut |tt| {
            let (zx, zy) = (ss * c - tt * s, ss * s + tt * c);
            let n = DVec3::new(-zx, -zy, 1.0).normalize();
            g(zx, zy, n)
        })
    })
}

/// Rounding budget of the reverse Fresnel evaluation: `4ε` (two roundings of order-one terms in
/// `g′²`, with a factor-2 margin), divided by the 2 of the square root.
const RECIPROCITY_ROUNDING: f64 = 2.0 * f64::EPSILON;

/// Floor of a comparison between two evaluations of order-one quantities by different operation
/// orders: a few thousand ulps, far below any modelling difference.
const ROUNDING: f64 = 1e-12;

/// Total internal reflection returns exactly 1; this allows for the last ulp of `1 − F` paths.
const EXACT: f64 = 1e-15;

use brine_testkit::directions::from_polar as dir;

/// Transmitted fraction of the power from the Fresnel amplitude coefficients, computed here
/// independently of the crate's `g` form:
/// `t_s = 2n_i cos θ_i/(n_i cos θ_i + n_t cos θ_t)`, `t_p = 2n_i cos θ_i/(n_t cos θ_i + n_i cos θ_t)`,
/// `T = (n_t cos θ_t)/(n_i cos θ_i) · ½(t_s² + t_p²)` (Born & Wolf 1999, *Principles of Optics*,
/// 7th ed., §1.5.2 Eq. 20 and §1.5.3 Eq. 40–41; Hecht 2002, *Optics*, §4.6.2 Eq. 4.43, 4.44, 4.62).
/// `cos θ_t = √(1 − (n_i/n_t)² sin²θ_i)` with `sin²θ_i = (1 − cos θ_i)(1 + cos θ_i)`; `None` beyond
/// the critical angle.
fn amplitude_transmittance(cos_i: f64, n_i: f64, n_t: f64) -> Option<f64> {
    let sin2_t = (n_i / n_t).powi(2) * (1.0 - cos_i) * (1.0 + cos_i);
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let t_s = 2.0 * n_i * cos_i / (n_i * cos_i + n_t * cos_t);
    let t_p = 2.0 * n_i * cos_i / (n_t * cos_i + n_i * cos_t);
    Some(n_t * cos_t / (n_i * cos_i) * 0.5 * (t_s * t_s + t_p * t_p))
}

/// Rounding of `R + T` with `R` from the `g` form and `T` from the amplitudes away from the
/// critical and grazing angles: each is a handful of correctly rounded operations on terms of
/// order one (`8ε` each, with margin).
const FRESNEL_SUM_ROUNDING: f64 = 16.0 * f64::EPSILON;

/// Tolerance of `R + T = 1` at `cos θ_i = c` for `m = n_i/n_t`, `n = 1/m`. Beyond
/// [`FRESNEL_SUM_ROUNDING`], both forms take the square root of a quantity that vanishes at the
/// critical angle (dense side) or at grazing incidence between nearly matched media:
/// `g = √(n² + c² − 1) = n cos θ_t`. `g²` is rounded absolutely by `≈ 3ε max(n², 1)`, so
/// `δg ≈ 3ε max(n², 1)/(2g)`; `cos²θ_t = 1 − m² sin²θ_i` by `≈ 4ε`, so `δ(n cos θ_t) ≈ 2ε n²/g`.
/// `R` (and `T = 1 − R`) depends on `g` through `((c − g)/(c + g))²` and
/// `((n²c − g)/(n²c + g))²`, whose `g`-derivatives are at most `4/(c + g)` and `4/(n²c + g)`:
/// `|∂R/∂g| ≤ 4 max(1, m²)/(c + g)`. Hence
/// `|R + T − 1| ≲ ε max(1, m²)(6 max(n², 1) + 8n²)/(g (c + g))`, doubled. (Over 2×10⁵ random
/// cases the largest error is 0.15 of this tolerance.)
fn fresnel_sum_tolerance(cos_i: f64, n_i: f64, n_t: f64) -> f64 {
    let (m, n) = (n_i / n_t, n_t / n_i);
    let cos_t = (1.0 - m * m * (1.0 - cos_i) * (1.0 + cos_i)).max(0.0).sqrt();
    let g = n * cos_t;
    FRESNEL_SUM_ROUNDING
        + 2.0 * f64::EPSILON * m.max(1.0).powi(2) * (6.0 * (n * n).max(1.0) + 8.0 * n * n) / (g * (cos_i + g))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1024))]

    #[test]
    fn fresnel_is_a_fraction_and_t_is_reciprocal(cos_i in 0.0f64..=1.0, n in 1.0001f64..2.5) {
        let r = fresnel_dielectric(cos_i, 1.0, n);
        prop_assert!((0.0..=1.0).contains(&r));
        // Snell pair: sin θ_t = sin θ_i / n, so cos θ_t = √(n² − 1 + cos²θ_i)/n (the form without
        // the cancellation of 1 − sin²θ_t); the transmitted fraction is the same both ways.
        let cos_t = (n * n - 1.0 + cos_i * cos_i).sqrt() / n;
        let back = fresnel_transmittance(cos_t, n, 1.0);
        // The reverse evaluation forms g′² = 1/n² + cos²θ_t − 1 = cos²θ_i/n² from terms of order
        // one, so g′ carries a relative error ≈ 2ε·n²/(2cos²θ_i) and T (of unit sensitivity to
        // ln g′) an absolute one of the same size: the tolerance grows as 1/cos²θ_i at grazing.
        let tol = ROUNDING + RECIPROCITY_ROUNDING * n * n / (cos_i * cos_i);
        prop_assert!((fresnel_transmittance(cos_i, 1.0, n) - back).abs() < tol);
        // Total internal reflection beyond the critical angle from the dense side.
        let theta_c = critical_angle(n, 1.0).unwrap();
        let beyond = (theta_c + (0.5 * PI - theta_c) * (1.0 - cos_i).max(1e-9)).cos();
        prop_assert!((fresnel_dielectric(beyond, n, 1.0) - 1.0).abs() < EXACT);
    }

    #[test]
    fn reflectance_plus_amplitude_transmittance_is_one_both_ways(
        u in 1e-6f64..=1.0, n1 in 1.0f64..2.5, n2 in 1.0f64..2.5,
    ) {
        // Either direction: the denser side first or the rarer; below the critical angle.
        let c_min = if n1 > n2 { (1.0 - (n2 / n1).powi(2)).sqrt() } else { 0.0 };
        let cos_i = c_min + u * (1.0 - c_min);
        let r = fresnel_dielectric(cos_i, n1, n2);
        prop_assert!((0.0..=1.0).contains(&r));
        let Some(t) = amplitude_transmittance(cos_i, n1, n2) else {
            return Err(TestCaseError::fail("below the critical angle by construction"));
        };
        let tol = fresnel_sum_tolerance(cos_i, n1, n2);
        prop_assert!((r + t - 1.0).abs() <= tol, "R = {r}, T = {t}, R + T − 1 = {:e} > {tol:e}", r + t - 1.0);
    }

    #[test]
    fn normal_incidence_is_the_closed_form(n1 in 0.5f64..3.0, n2 in 0.5f64..3.0) {
        // R(θ = 0) = ((n₁ − n₂)/(n₁ + n₂))² for any pair, either way.
        /// `a = (n − 1)/(n + 1)` with `n = n₂/n₁` once rounded: `|δa| ≤ 4ε`, so `|δ(a²)| ≤
        /// 8ε|a|`, against the closed form's own `2ε|a|`; doubled.
        const NORMAL_ROUNDING: f64 = 20.0 * f64::EPSILON;
        let closed = ((n1 - n2) / (n1 + n2)).powi(2);
        let r = fresnel_dielectric(1.0, n1, n2);
        prop_assert!((r - closed).abs() <= NORMAL_ROUNDING * (closed.sqrt() + f64::EPSILON), "{r} vs {closed}");
        prop_assert!((fresnel_normal(n1, n2) - closed).abs() <= NORMAL_ROUNDING * closed);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "grazing incidence returns exactly 1")]
    fn reflectance_tends_to_one_at_grazing_both_ways(c in 1e-9f64..1e-5, n in 1.1f64..2.5, gt in 1e-5f64..1e-3) {
        // Air → n at grazing incidence, c = cos θ_i → 0, g₀ = √(n² − 1): from
        // R_s = ((c − g)/(c + g))² = 1 − 4c/g + 8c²/g² − …, R_p = ((n²c − g)/(n²c + g))² likewise
        // with c → n²c (independent expansion),
        //   1 − R = 2c(1 + n²)/g − 4c²(1 + n⁴)/g² + O(c³),   g = √(n² − 1 + c²).
        /// `1 − R` rounded absolutely at `≈ 8ε` (two roundings of `R ≈ 1`, margin 2) …
        const ONE_MINUS_ROUNDING: f64 = 8.0 * f64::EPSILON;
        let g = (n * n - 1.0 + c * c).sqrt();
        let first = 2.0 * c * (1.0 + n * n) / g;
        let second = 4.0 * c * c * (1.0 + n.powi(4)) / (g * g);
        let deficit = 1.0 - fresnel_dielectric(c, 1.0, n);
        // … and the third-order term, bounded by the second times 2c(1 + n⁴)/g (ratio of
        // successive terms of the geometric-like series), doubled.
        let tol = ONE_MINUS_ROUNDING + 2.0 * second * (2.0 * c * (1.0 + n.powi(4)) / g);
        prop_assert!((deficit - (first - second)).abs() <= tol, "{deficit} vs {}", first - second);

        // n → air just below the critical angle, g = n′ cos θ_t → 0 with n′ = 1/n and the
        // incidence cosine c = √(1 − n′² + g²): the same expansions with c and g exchanged,
        //   1 − R = 2g(1 + 1/n′²)/c − 4g²(1 + 1/n′⁴)/c² + O(g³).
        // Here the function recomputes g² = n′² + c² − 1 from c: absolute rounding ≈ 4ε, i.e.
        // δg ≈ 2ε/g, moving 1 − R by 2(1 + 1/n′²)/c per unit of g.
        let np = 1.0 / n;
        let c = (1.0 - np * np + gt * gt).sqrt();
        let deficit = 1.0 - fresnel_dielectric(c, n, 1.0);
        let first = 2.0 * gt * (1.0 + 1.0 / (np * np)) / c;
        let second = 4.0 * gt * gt * (1.0 + 1.0 / np.powi(4)) / (c * c);
        let recompute = 2.0 * (1.0 + 1.0 / (np * np)) / c * (8.0 * f64::EPSILON / gt);
        let tol = ONE_MINUS_ROUNDING + recompute + 2.0 * second * (2.0 * gt * (1.0 + 1.0 / np.powi(4)) / c);
        prop_assert!((deficit - (first - second)).abs() <= tol, "{deficit} vs {}", first - second);
        // Exactly at grazing from either side the interface reflects everything.
        prop_assert!(fresnel_dielectric(0.0, 1.0, n) == 1.0 && fresnel_dielectric(0.0, n, 1.0) == 1.0);
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "total internal reflection returns exactly 1 and 0")]
    fn water_to_air_is_a_fraction_below_and_total_beyond_the_critical_angle(
        u in 0.0f64..=1.0, n1 in 1.0001f64..2.5, ratio in 0.3f64..0.9999,
    ) {
        // From the dense side (n₂ = ratio · n₁ < n₁): R ∈ [0, 1) strictly below θ_c, R = 1 at
        // and beyond it (sin θ_t = (n₁/n₂) sin θ_i ≥ 1).
        let n2 = ratio * n1;
        let theta_c = critical_angle(n1, n2).unwrap();
        prop_assert!((theta_c.sin() - ratio).abs() <= 4.0 * f64::EPSILON);
        let below = (u * theta_c * (1.0 - 1e-9)).cos();
        let r = fresnel_dielectric(below, n1, n2);
        prop_assert!((0.0..1.0).contains(&r), "{r}");
        let beyond = (theta_c + u * (0.5 * PI - theta_c) + 1e-9).min(0.5 * PI).cos();
        prop_assert!(fresnel_dielectric(beyond, n1, n2) == 1.0);
        prop_assert!(fresnel_transmittance(beyond, n1, n2) == 0.0);
    }

    #[test]
    fn schlick_error_is_bounded(cos_i in 0.0f64..=1.0) {
        // Schlick's largest error against the exact form for air → water is 0.0592 at 83.8°
        // (dense scan, see the Fresnel plot).
        /// The scanned maximum with 1 % margin.
        const SCHLICK_MAX_ERROR: f64 = 0.0598;
        let err = (fresnel_schlick(cos_i, 1.0, 1.333) - fresnel_dielectric(cos_i, 1.0, 1.333)).abs();
        prop_assert!(err < SCHLICK_MAX_ERROR, "{err}");
    }

    #[test]
    fn case1_iops_are_positive_and_finite(lambda in 400.0f64..=700.0, c in 0.0f64..=100.0) {
        let i = case1_iops(lambda, Chlorophyll::new(c).unwrap());
        for v in [i.a, i.b, i.b_b, i.c, i.k_d] {
            prop_assert!(v.is_finite() && v > 0.0);
        }
        prop_assert!(i.b_b <= i.b);
        prop_assert!(irradiance_reflectance(i.b_b, i.a).is_finite());
    }

    #[test]
    fn iops_increase_with_chlorophyll(lambda in 400.0f64..=700.0, c in 0.0f64..30.0, dc in 0.01f64..5.0) {
        // a, b and K_d increase with C everywhere; b_b (Morel 1988) up to about 40 mg/m³, beyond
        // which its ratio term falls faster than C^0.62 rises.
        let lo = case1_iops(lambda, Chlorophyll::new(c).unwrap());
        let hi = case1_iops(lambda, Chlorophyll::new(c + dc).unwrap());
        prop_assert!(hi.a > lo.a && hi.b > lo.b && hi.k_d > lo.k_d && hi.b_b > lo.b_b);
    }

    #[test]
    fn refracted_ray_radiance_is_bounded(
        l_df in 0.0f64..10.0, l_b in 0.0f64..10.0, c in 0.01f64..2.0, k in 0.0f64..1.0,
        mu in 0.0f64..=1.0, path in 0.0f64..200.0,
    ) {
        let l = refracted_ray_radiance(l_df, c, k, mu, path, l_b);
        prop_assert!(l.is_finite() && l >= 0.0);
        prop_assert!(l <= l_df + l_b + ROUNDING);
        prop_assert!(l >= l_df.min(l_b) * (1.0 - ROUNDING));
        let deeper = refracted_ray_radiance(l_df, c, k, mu, path + 50.0 / c, l_b);
        prop_assert!((deeper - l_df).abs() <= (l - l_df).abs() + ROUNDING);
    }

    #[test]
    fn dipole_profile_is_nonnegative_finite_and_decreasing(
        sigma_a in 0.0f64..5.0, sigma_s in 0.01f64..20.0, g in -0.9f64..0.95, eta in 0.5f64..2.5, r in 0.0f64..50.0,
    ) {
        let m = DipoleMaterial::new(sigma_a, sigma_s, g, eta).unwrap();
        let rd = m.diffuse_reflectance(r);
        prop_assert!(rd.is_finite() && rd >= 0.0);
        prop_assert!(m.diffuse_reflectance(r + 0.1) <= rd);
        let total = m.total_diffuse_reflectance();
        prop_assert!((0.0..=1.0).contains(&total));
        prop_assert!(m.diffuse_reflectance_beyond(r) <= total * (1.0 + ROUNDING));
        let s = m.bssrdf(r, 0.7, 0.4);
        prop_assert!(s.is_finite() && s >= 0.0);
    }

    #[test]
    fn brdf_is_nonnegative_and_reciprocal(
        tv in 0.0f64..1.55, pv in 0.0f64..std::f64::consts::TAU, tl in 0.0f64..1.55, pl in 0.0f64..std::f64::consts::TAU,
        sx in 1e-4f64..0.2, sy in 1e-4f64..0.2,
    ) {
        let var = SlopeVariance::new(sx, sy).unwrap();
        let (v, l) = (dir(tv, pv), dir(tl, pl));
        let a = ocean_brdf(v, l, &var, WATER_IOR);
        let b = ocean_brdf(l, v, &var, WATER_IOR);
        prop_assert!(a.is_finite() && a >= 0.0);
        prop_assert!((a - b).abs() <= ROUNDING * a.max(f64::MIN_POSITIVE));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn dipole_integral_equals_the_closed_form(
        sigma_a in 0.001f64..2.0, sigma_s in 0.1f64..10.0, g in -0.9f64..=0.9, eta in 1.0f64..1.6,
    ) {
        // ∫₀^∞ R_d(r) 2πr dr by composite Gauss–Legendre on geometric panels, against Jensen's
        // closed form, for any phase-function asymmetry g (which enters through σ′_s = σ_s(1 − g)).
        /// The acceptance criterion; the panels resolve `R_d` to about 10⁻¹⁰.
        const CLOSED_FORM: f64 = 1e-6;
        let m = DipoleMaterial::new(sigma_a, sigma_s, g, eta).unwrap();
        let end = 60.0 / m.sigma_tr() + 60.0 * m.z_v();
        let mut edges = vec![0.0];
        let mut x = 1e-4 * m.z_r();
        while x < end {
            edges.push(x);
            x *= 1.5;
        }
        edges.push(end);
        let numeric: f64 = edges
            .windows(2)
            .map(|e| integrate(e[0], e[1], 1, &mut |r| m.diffuse_reflectance(r) * 2.0 * PI * r))
            .sum();
        prop_assert!((numeric / m.total_diffuse_reflectance() - 1.0).abs() < CLOSED_FORM, "{numeric}");
    }
}

#[test]
fn slope_pdf_integrates_to_one() {
    /// 24 × 24 panels of 16 Gauss points over ±10σ: the quadrature error of a Gaussian is
    /// below 10⁻¹², the truncated tails e^{−50}; the tolerance leaves room for rounding.
    const QUADRATURE: f64 = 1e-9;
    for (sx, sy) in [(0.01, 0.02), (0.05, 0.005), (2e-5, 0.1)] {
        let var = SlopeVariance::new(sx, sy).unwrap();
        let (lx, ly) = (10.0 * sx.sqrt(), 10.0 * sy.sqrt());
        let total = integrate(-lx, lx, 24, &mut |x| integrate(-ly, ly, 24, &mut |y| slope_pdf(x, y, &var)));
        assert_relative_eq!(total, 1.0, max_relative = QUADRATURE);
    }
}

#[test]
fn smith_normalisation_and_white_furnace() {
    // Smith's Λ satisfies ∫ p(ζ) (v·n)⁺/(n_z v_z) d²ζ = 1 + Λ(v) for Gaussian slopes; and the BRDF
    // with F = 1 reflects at most all of the light, ∫ ρ l_z dω ≤ 1 (the visibility-weighted
    // density 1/(1 + Λ(v) + Λ(l)) ≤ 1/(1 + Λ(v))).
    /// The reference quadrature resolves the smooth parts to ~10⁻⁸; the cut `l_z = 0` inside the
    /// domain is not a panel edge, which costs up to ~10⁻⁴.
    const CUT: f64 = 2e-4;
    /// Smith's identity: the cut `v·n = 0` is a panel edge, so the reference quadrature is
    /// resolved to ~10⁻⁸.
    const SMITH: f64 = 1e-6;
    for (sx, sy) in [(0.01, 0.006), (0.04, 0.03), (0.1, 0.02)] {
        let var = SlopeVariance::new(sx, sy).unwrap();
        for (theta_deg, phi) in [(0.0f64, 0.0), (30.0, 0.4), (60.0, 2.0), (80.0, 1.0), (87.0, 4.0)] {
            let v = dir(theta_deg.to_radians(), phi);
            let lambda_v = smith_lambda(v.z, var.along(v));
            let smith = slope_integral(v, &var, |zx, zy, n| slope_pdf(zx, zy, &var) * v.dot(n) / (n.z * v.z));
            assert_relative_eq!(smith, 1.0 + lambda_v, max_relative = SMITH);
            let furnace = slope_integral(v, &var, |_, _, n| {
                let l = reflect(-v, n);
                if l.z <= 0.0 {
                    return 0.0;
                }
                // ρ l_z dω_l = ρ l_z 4 (v·n) n_z³ d²ζ; the Fresnel factor divided out.
                let f = fresnel_dielectric(v.dot(n), 1.0, WATER_IOR);
                ocean_brdf(v, l, &var, WATER_IOR) / f * l.z * 4.0 * v.dot(n) * n.z.powi(3)
            });
            assert!(furnace <= 1.0 + CUT, "σ² = ({sx}, {sy}), θ = {theta_deg}: {furnace}");
            assert!(furnace > 0.5, "σ² = ({sx}, {sy}), θ = {theta_deg}: {furnace}");
            // The renderer's quadrature against the reference.
            let quick = SkyReflection::new(8, WATER_IOR).unwrap().directional_reflectance(v, &var, true);
            assert!(quick <= 1.0 + ROUNDING);
            /// Self-normalised 8 × 8 Gauss–Hermite against the reference, up to 87°.
            const QUICK: f64 = 0.03;
            assert!((quick - furnace).abs() < QUICK, "θ = {theta_deg}: {quick} vs {furnace}");
        }
    }
}

#[test]
fn sky_reflection_of_a_uniform_sky_is_the_rough_fresnel_albedo() {
    // With a uniform sky of radiance 1 the reflected radiance is the directional albedo with the
    // Fresnel factor kept, ∫ ρ l_z dω_l: here by the test's own 48 × 48 slope quadrature.
    let var = SlopeVariance::cox_munk_clean(7.0).unwrap();
    let v = dir(1.0, 0.3);
    let reference = slope_integral(v, &var, |_, _, n| {
        let l = reflect(-v, n);
        if l.z <= 0.0 {
            return 0.0;
        }
        ocean_brdf(v, l, &var, WATER_IOR) * l.z * 4.0 * v.dot(n) * n.z.powi(3)
    });
    // The renderer's 8 × 8 self-normalised Gauss–Hermite quadrature. Its error relative to the
    // albedo is that of the unit-Fresnel furnace above (0.03 of an albedo ≤ 1, up to 87°): the
    // Fresnel factor varies slowly over the slope lobe.
    const QUICK_RELATIVE: f64 = 0.03;
    let rgb = SkyReflection::new(8, WATER_IOR).unwrap().reflected_radiance(v, &var, |_| DVec3::ONE);
    assert_relative_eq!(rgb.x, reference, max_relative = QUICK_RELATIVE);
    assert!(
        rgb.x.to_bits() == rgb.y.to_bits() && rgb.y.to_bits() == rgb.z.to_bits(),
        "a grey sky gives a grey reflection: {rgb}"
    );
    let filtered = reflected_sky_radiance_filtered(v, &var, |_, _| DVec3::ONE);
    /// Bruneton's mean-Fresnel fit against the quadrature at 57°: the fit's own accuracy
    /// (their §5.2 quotes a few per cent of F̄ ≈ 0.1).
    const MEAN_FRESNEL_FIT: f64 = 0.01;
    assert!((filtered.x - reference).abs() < MEAN_FRESNEL_FIT, "{} vs {reference}", filtered.x);
}

#[test]
fn water_rgb_is_blue_for_clear_water_and_physical() {
    for body in [WaterBody::case1(0.05).unwrap(), WaterBody::jerlov(JerlovType::IB)] {
        for bands in [RgbBands::SrgbAverage, RgbBands::Wavelengths([650.0, 550.0, 450.0])] {
            let w = WaterRgb::new(&body, bands);
            assert!(w.a.x > w.a.y && w.a.y > w.a.z, "{:?}", w.a);
            assert!(w.reflectance.z > w.reflectance.x);
            for v in [w.a, w.b, w.b_b, w.c, w.k_d, w.reflectance] {
                assert!(v.is_finite() && v.min_element() > 0.0);
            }
            let deep = w.refracted_ray_radiance(DVec3::splat(10.0), 0.8, f64::INFINITY, DVec3::ZERO);
            assert!((deep - w.diffuse_upwelling_radiance(DVec3::splat(10.0))).length() < ROUNDING);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The reflectance from entry points beyond `r0` lies in `[0, R]` and decreases with `r0`, and
    /// equals the dipole's `R_d(r) 2πr` integrated from `r0` (Gauss–Legendre on geometric panels,
    /// as `dipole_integral_equals_the_closed_form`).
    #[test]
    fn diffuse_reflectance_beyond_is_the_tail_integral(
        sigma_a in 0.001f64..2.0, sigma_s in 0.1f64..10.0, g in -0.9f64..=0.9, eta in 1.0f64..1.6,
        r0_over_mfp in 0.0f64..20.0, dr_over_mfp in 0.0f64..5.0,
    ) {
        /// The panels resolve `R_d` to about 10⁻¹⁰ of `R`; relative to the tail, which is down to
        /// ~10⁻⁹ of `R` at 20 mean free paths, plus an absolute floor for those far tails.
        const TAIL_REL: f64 = 1e-6;
        const TAIL_ABS: f64 = 1e-12;
        let m = DipoleMaterial::new(sigma_a, sigma_s, g, eta).unwrap();
        let total = m.total_diffuse_reflectance();
        let r0 = r0_over_mfp * m.z_r();
        let r1 = r0 + dr_over_mfp * m.z_r();
        let (b0, b1) = (m.diffuse_reflectance_beyond(r0), m.diffuse_reflectance_beyond(r1));
        prop_assert!(b0 >= 0.0 && b0 <= total * (1.0 + 1e-12), "{b0} ∉ [0, {total}]");
        prop_assert!(b1 <= b0 * (1.0 + 1e-12), "not decreasing: {b1} at {r1} > {b0} at {r0}");
        let end = r0 + 60.0 / m.sigma_tr() + 60.0 * m.z_v();
        let mut edges = vec![r0];
        let mut x = r0 + 1e-4 * m.z_r();
        while x < end {
            edges.push(x);
            x = r0 + (x - r0) * 1.5;
        }
        edges.push(end);
        let numeric: f64 = edges
            .windows(2)
            .map(|e| integrate(e[0], e[1], 1, &mut |r| m.diffuse_reflectance(r) * 2.0 * PI * r))
            .sum();
        prop_assert!((numeric - b0).abs() <= TAIL_REL * b0 + TAIL_ABS * total, "{numeric} vs {b0}");
    }

    /// Smith's `Λ` for Gaussian slopes is `≥ 0`, `0` at normal incidence, decreases as the
    /// direction rises (`μ` up) and grows with the slope variance: more shadowing of lower, rougher
    /// views.
    #[test]
    fn smith_lambda_is_nonnegative_and_monotone(
        mu in 0.01f64..1.0, dmu in 0.0f64..0.5, sigma2 in 1e-4f64..0.2, dsigma2 in 0.0f64..0.2,
    ) {
        let l = smith_lambda(mu, sigma2);
        prop_assert!(l.is_finite() && l >= 0.0, "Λ({mu}, {sigma2}) = {l}");
        prop_assert!(smith_lambda(1.0, sigma2).abs() < f64::MIN_POSITIVE, "Λ(1) = {}", smith_lambda(1.0, sigma2));
        prop_assert!(smith_lambda((mu + dmu).min(1.0), sigma2) <= l * (1.0 + 1e-12) + 1e-300);
        prop_assert!(smith_lambda(mu, sigma2 + dsigma2) >= l * (1.0 - 1e-12));
    }

    /// The rough-surface reflectance table stays in `[0, 1]`, its roughness factor is finite,
    /// `≥ 0` and 1 on smooth water, anywhere in (and beyond) the documented domain.
    #[test]
    fn rough_reflectance_is_a_reflectance(cos_v in -0.5f64..1.5, sigma in -0.1f64..1.0) {
        let t = rough_table();
        let r = t.reflectance(cos_v, sigma);
        prop_assert!((0.0..=1.0).contains(&r), "R({cos_v}, {sigma}) = {r}");
        let f = t.roughness_factor(cos_v, sigma);
        prop_assert!(f.is_finite() && f >= 0.0, "factor {f}");
        // R(θ, 0)/R(θ, 0), or 1 where R(θ, 0) = 0: one division of a number by itself.
        prop_assert!((t.roughness_factor(cos_v, 0.0) - 1.0).abs() <= f64::EPSILON);
        // The light reflected into the waves: finite, ≥ 0, none on smooth water, and with the
        // sky's share at most the visible facets' whole reflectance (R_seen ≤ 1 ≤ R(θ, 0)·…).
        let m = t.met_factor(cos_v, sigma);
        prop_assert!(m.is_finite() && m >= 0.0, "met factor {m}");
        prop_assert!(t.met_factor(cos_v, 0.0) == 0.0);
        let seen = t.seen_reflectance(cos_v, sigma);
        prop_assert!((0.0..=1.0).contains(&seen) && r <= seen + 1e-12, "R {r}, R_seen {seen}");
    }

    /// The split integral at any view and roughness: `0 ≤ R ≤ R_seen ≤ max F`, and the visible
    /// normals' normalisation (`R_seen = 1` for `F = 1`), checked away from the table's nodes:
    /// exact to the quadrature with Smith's visibility, to the visibility table's interpolation
    /// with the measured one.
    #[test]
    fn the_reflectance_split_is_bounded(cos_v in 0.005f64..=1.0, sigma in 0.002f64..=0.6) {
        /// The Gauss–Legendre rules on the exact domains (measured below 10⁻¹⁰).
        const QUADRATURE: f64 = 1e-9;
        /// The measured visibility's rows are renormalised, its interpolation between them is
        /// not (`SlopeVisibility`'s tests: 2×10⁻³).
        const BETWEEN_ROWS: f64 = 2.5e-3;
        let white = reflectance_split_uncorrelated(cos_v, sigma, |_| 1.0);
        prop_assert!((white.seen - 1.0).abs() < QUADRATURE, "Smith: R_seen(F = 1) = {}", white.seen);
        prop_assert!(white.to_sky > 0.0 && white.to_sky <= white.seen + QUADRATURE, "{white:?}");
        let white = reflectance_split(cos_v, sigma, |_| 1.0);
        prop_assert!((white.seen - 1.0).abs() < BETWEEN_ROWS, "R_seen(F = 1) = {}", white.seen);
        prop_assert!(white.to_sky > 0.0 && white.to_sky <= white.seen + QUADRATURE, "{white:?}");
        let water = water_reflectance_split(cos_v, sigma, WATER_IOR);
        prop_assert!(water.to_sky >= 0.0 && water.to_sky <= water.seen + QUADRATURE, "{water:?}");
        // F ≤ 1 for every facet; R_seen is F's mean over the visible facets.
        let normal = fresnel_dielectric(1.0, 1.0, WATER_IOR);
        prop_assert!(water.seen <= 1.0 + BETWEEN_ROWS && water.seen >= normal * (1.0 - BETWEEN_ROWS), "{water:?}");
    }

    /// The diffuse Fresnel reflectance lies in `[0, 1]` on both sides, and the two sides obey
    /// the reciprocity of radiance across an interface: `1 − F_dr(n → 1) = (1 − F_dr(1 → n))/n²`
    /// (Stern 1964, "Transmission of isotropic radiation across an interface between two
    /// dielectrics", Appl. Opt. 3, 111).
    #[test]
    fn hemispherical_fresnel_is_reciprocal(n in 1.0001f64..2.5) {
        /// 64-point Gauss–Legendre on the smooth integrand after the `t²` substitution.
        const QUADRATURE: f64 = 1e-10;
        let (outside, inside) = (hemispherical_fresnel_reflectance(1.0, n), hemispherical_fresnel_reflectance(n, 1.0));
        prop_assert!((0.0..=1.0).contains(&outside) && (0.0..=1.0).contains(&inside), "{outside}, {inside}");
        prop_assert!(((1.0 - inside) - (1.0 - outside) / (n * n)).abs() < QUADRATURE, "n = {n}: {inside} vs {outside}");
    }
}

/// One rough-reflectance table for the property cases (building it takes a few ms).
fn rough_table() -> &'static RoughReflectance {
    static TABLE: std::sync::OnceLock<RoughReflectance> = std::sync::OnceLock::new();
    TABLE.get_or_init(RoughReflectance::water)
}
