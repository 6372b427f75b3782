//! The sun glint of a disc of finite angular size (`SunDisc`, `reflected_disc_radiance`): its
//! point-source limit, its energy against the point form, and its mirror limit, each against an
//! independent derivation. Every tolerance is a named constant with its reason.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use approx::assert_relative_eq;
use brine_optics::*;
use glam::DVec3;
use proptest::prelude::*;

use brine_testkit::directions::from_polar as dir;

/// Mirror direction of `l` about the mean normal `z`.
fn specular(l: DVec3) -> DVec3 {
    DVec3::new(-l.x, -l.y, l.z)
}

/// The calmest sea the BRDF allows, `σx² = σy² =` [`MIN_SLOPE_VARIANCE`].
fn calm() -> SlopeVariance {
    SlopeVariance::new(0.0, 0.0).unwrap()
}

/// Composite Gauss–Legendre integral of `f` over `[a, b]`, `panels` panels of 8 points.
fn integrate(a: f64, b: f64, panels: usize, f: &mut impl FnMut(f64) -> f64) -> f64 {
    brine_testkit::quadrature::gauss_legendre_composite(f, a, b, panels, 8)
}

/// `∫ I(v) v_z dω_v` over the upper hemisphere: Gauss–Legendre in `μ_v` with a panel edge at the
/// BRDF's clamp `μ = 0.01`, and the (spectrally accurate) periodic trapezoid in `φ_v`.
fn reflected_flux(mut radiance: impl FnMut(DVec3) -> f64) -> f64 {
    const AZIMUTHS: usize = 96;
    let mut ring = |mu: f64| {
        let sin = (1.0 - mu * mu).max(0.0).sqrt();
        let s: f64 = (0..AZIMUTHS)
            .map(|k| {
                let phi = TAU * k as f64 / AZIMUTHS as f64;
                radiance(DVec3::new(sin * phi.cos(), sin * phi.sin(), mu))
            })
            .sum();
        s * TAU / AZIMUTHS as f64 * mu
    };
    integrate(0.0, 0.01, 1, &mut ring) + integrate(0.01, 1.0, 40, &mut ring)
}

#[test]
fn bad_discs_are_rejected() {
    assert!(SunDisc::new(-1e-3).is_err());
    assert!(SunDisc::new(f64::NAN).is_err());
    assert!(SunDisc::new(1.0).is_err());
    assert!(SunDisc::with_rings(SunDisc::SUN_ANGULAR_RADIUS, 0).is_err());
    assert!(SunDisc::with_rings(SunDisc::SUN_ANGULAR_RADIUS, SunDisc::MAX_RINGS + 1).is_err());
    let d = SunDisc::sun();
    assert_eq!(d.ring_range(), SunDisc::ADAPTIVE_RINGS);
    assert_eq!(d.node_count(2), 2 * 8);
    assert_eq!(SunDisc::with_rings(0.01, 5).unwrap().ring_range(), (5, 5));
    // Ω = 2π(1 − cos r) = 6.7943×10⁻⁵ sr for the Sun (brine-sky's SUN_SOLID_ANGLE).
    /// brine-sky prints the solid angle to 8 digits.
    const EIGHT_DIGITS: f64 = 1e-7;
    assert_relative_eq!(d.solid_angle(), 6.794_310_7e-5, max_relative = EIGHT_DIGITS);
}

#[test]
fn the_rule_integrates_the_cap_area_and_its_moments() {
    // Closed forms on the cap θ′ ≤ r: ∫ dω′ = 2π(1 − cos r); ∫ l′·l dω′ = π sin²r (the
    // irradiance of a disc of unit radiance on a plane facing it); ∫ (l′·e)² dω′ =
    // (π/3)(1 − cos r)²(2 + cos r) for a unit e ⟂ l (∫ sin³θ′ cos²φ dθ′ dφ).
    /// The integrands are polynomials of degree ≤ 2 in `s = 1 − cos θ′` and in `cos φ`,
    /// `sin φ`, which a rule of ≥ 2 rings and ≥ 8 spokes integrates exactly: rounding only.
    const ROUNDING: f64 = 1e-12;
    for r in [1e-3, 0.05, 0.7] {
        for rings in [2, 5] {
            let d = SunDisc::with_rings(r, rings).unwrap();
            let l = dir(0.4, 1.1);
            let e = l.any_orthonormal_vector();
            let c = r.cos();
            assert_relative_eq!(d.integrate(l, rings, |_| 1.0), TAU * (1.0 - c), max_relative = ROUNDING);
            assert_relative_eq!(d.solid_angle(), TAU * (1.0 - c), max_relative = ROUNDING);
            assert_relative_eq!(d.integrate(l, rings, |q| q.dot(l)), PI * r.sin().powi(2), max_relative = ROUNDING);
            let second = PI / 3.0 * (1.0 - c).powi(2) * (2.0 + c);
            assert_relative_eq!(d.integrate(l, rings, |q| q.dot(e).powi(2)), second, max_relative = ROUNDING);
            // Every node lies on the cap.
            assert!(d.integrate(l, rings, |q| if q.dot(l) < c - 1e-15 { 1.0 } else { 0.0 }) == 0.0);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    #[expect(clippy::float_cmp, reason = "a point disc returns the point form itself")]
    fn a_tiny_disc_is_the_point_sun(
        tv in 0.0f64..1.45, pv in 0.0f64..TAU, tl in 0.0f64..1.45, pl in 0.0f64..TAU,
        sx in 1e-4f64..0.2, sy in 1e-4f64..0.2,
    ) {
        // r = 10⁻⁷ rad: the image of the disc in slope space, a ≈ r/(2 v·h), is below 10⁻⁵ σ
        // for these angles, and the cap average of ρ l_z differs from its centre value by
        // O((ζ a/σ²)²) ≲ 10⁻⁸ even ten standard deviations into the lobe's tail.
        /// The acceptance criterion for the limit r → 0.
        const POINT_LIMIT: f64 = 1e-6;
        let var = SlopeVariance::new(sx, sy).unwrap();
        let (v, l) = (dir(tv, pv), dir(tl, pl));
        let disc = SunDisc::new(1e-7).unwrap();
        let point = reflected_sun_radiance(v, l, &var, 1.0);
        let extended = reflected_disc_radiance(v, l, &var, 1.0, &disc);
        prop_assert!(extended.is_finite() && extended >= 0.0);
        prop_assert!((extended - point).abs() <= POINT_LIMIT * point.max(1e-300), "{extended} vs {point}");
        // r = 0 exactly is the point form itself.
        let zero = SunDisc::new(0.0).unwrap();
        prop_assert!(reflected_disc_radiance(v, l, &var, 1.0, &zero) == point);
    }

    #[test]
    fn disc_glint_is_nonnegative_and_finite(
        tv in 0.0f64..FRAC_PI_2, pv in 0.0f64..TAU, tl in 0.0f64..FRAC_PI_2, pl in 0.0f64..TAU,
        sx in 0.0f64..0.5, sy in 0.0f64..0.5, r in 0.0f64..0.7,
    ) {
        let var = SlopeVariance::new(sx, sy).unwrap();
        let disc = SunDisc::new(r).unwrap();
        let i = reflected_disc_radiance(dir(tv, pv), dir(tl, pl), &var, 1.0, &disc);
        prop_assert!(i.is_finite() && i >= 0.0, "{i}");
    }
}

#[test]
fn on_a_calm_sea_at_normal_incidence_the_glint_is_the_gaussian_mass_inside_the_disc_image() {
    // Sun overhead, viewer overhead (v = z). A direction l′ at θ′ from the zenith has the half
    // vector at θ′/2, i.e. the facet slope |ζ| = tan(θ′/2): the cap θ′ ≤ r maps onto the slope
    // disc |ζ| ≤ tan(r/2). With dω′ = 4(v·h)h_z³ d²ζ and v = z the integrand ρ l′_z dω′ reduces to
    // F(h_z) p(ζ) d²ζ/(1 + Λ(l′)), Λ(v = z) = 0 and Λ(l′) = 0 in floating point (ν > 10³). For
    // isotropic slopes the Gaussian mass in the disc is M = 1 − exp(−tan²(r/2)/(2σ²)), and F rises
    // monotonically from F(1) to F(cos(r/2)) over the disc, so (independent derivation)
    //   M ≤ I/(L F(1)) ≤ M F(cos(r/2))/F(1),   L = E/Ω.
    // For the Sun M = 0.126 (the point form gives r²/(8σ²) = 0.135: 7 % too bright); for
    // r = 0.05 M = 1 − 2×10⁻⁷: the mirror limit I = F L.
    /// The 16-ring rule on `exp(−s/(4σ²))`, `s ≤ 2 sin²(r/2)`: Gauss–Legendre error bound
    /// ≈ 10⁻¹² at r = 0.05 (A&S 25.4.30 with `f⁽³²⁾ ≤ (r²/(8σ²))³²`), plus rounding.
    const QUADRATURE: f64 = 1e-9;
    let sigma2 = MIN_SLOPE_VARIANCE;
    for r in [SunDisc::SUN_ANGULAR_RADIUS, 0.01, 0.02, 0.05] {
        let disc = SunDisc::with_rings(r, 16).unwrap();
        let l = DVec3::Z;
        let i = reflected_disc_radiance(DVec3::Z, l, &calm(), disc.solid_angle(), &disc);
        let mass = 1.0 - (-(0.5 * r).tan().powi(2) / (2.0 * sigma2)).exp();
        let f0 = fresnel_dielectric(1.0, 1.0, WATER_IOR);
        let f_edge = fresnel_dielectric((0.5 * r).cos(), 1.0, WATER_IOR);
        let ratio = i / f0; // L = 1
        assert!(ratio >= mass * (1.0 - QUADRATURE), "r = {r}: {ratio} < {mass}");
        assert!(ratio <= mass * f_edge / f0 * (1.0 + QUADRATURE), "r = {r}: {ratio} > {mass}·{}", f_edge / f0);
    }
}

#[test]
fn a_sea_much_smoother_than_the_disc_mirrors_the_disc() {
    // r = 0.05 rad against σ = 4.5 mrad: the disc's image in slope space (radius ≥ r/2 = 25 mrad)
    // holds all the facets but a mass ≈ exp(−(r/2)²/(2σ²)) ≈ 2×10⁻⁷. A mirror shows the disc at
    // its reflected position with radiance F(v·n) L, n = z: I = F(v_z) L for a view within r of
    // the specular direction, 0 beyond.
    /// The facets spread the incidence angle on them by `δ` of variance `σ²` about `v_z`'s, so
    /// the mean Fresnel factor differs from `F(v_z)` by `½σ²|F″/F|` to second order, with
    /// `F″/F ≈ 19 rad⁻²` at 60° (second difference of `F` over ±5°): `1.9×10⁻⁴`; plus the tail
    /// beyond the disc image, `1.3×10⁻⁵` at a quarter radius off (below). Margin 1.5.
    /// (Measured with the 32-ring rule: `1.2×10⁻⁴` at 60°, `3×10⁻⁵` at 30°, `2×10⁻⁷` overhead.)
    const MIRROR: f64 = 3e-4;
    /// The adaptive rule against the 32-ring one, as in `the_adaptive_rule_is_close_to_a_fine_rule`.
    const ADAPTIVE: f64 = 1e-4;
    /// Two radii off the specular direction the disc's edge is r away, ≥ r/2 = 5.6 σ in slope:
    /// a Gaussian tail of 10⁻⁸.
    const DARK: f64 = 1e-6;
    let r = 0.05;
    let disc = SunDisc::with_rings(r, 32).unwrap();
    let adaptive = SunDisc::new(r).unwrap();
    for theta_deg in [0.0f64, 30.0, 60.0] {
        let l = dir(theta_deg.to_radians(), 0.7);
        let mirror = |v: DVec3| fresnel_dielectric(v.z, 1.0, WATER_IOR);
        let glint = |v: DVec3| reflected_disc_radiance(v, l, &calm(), disc.solid_angle(), &disc);
        let s = specular(l);
        let quick = reflected_disc_radiance(s, l, &calm(), adaptive.solid_angle(), &adaptive);
        assert_relative_eq!(quick, mirror(s), max_relative = MIRROR + ADAPTIVE);
        assert_relative_eq!(glint(s), mirror(s), max_relative = MIRROR);
        // A quarter radius off the specular direction, in and across the plane of incidence: the
        // disc's edge is then 0.75 r away, i.e. ≥ 0.375 r = 4.2 σ in slope, which leaves a
        // Gaussian tail of 1.3×10⁻⁵ outside. (At half a radius it would be 2.8 σ and 0.26 %.)
        let across = s.cross(DVec3::Z).normalize_or(DVec3::X);
        let along = across.cross(s).normalize();
        for axis in [along, across] {
            let inside = (s * (0.25 * r).cos() + axis * (0.25 * r).sin()).normalize();
            assert_relative_eq!(glint(inside), mirror(inside), max_relative = MIRROR);
            let outside = (s * (2.0 * r).cos() + axis * (2.0 * r).sin()).normalize();
            assert!(glint(outside) < DARK * mirror(outside), "θ = {theta_deg}: {}", glint(outside));
        }
    }
}

#[test]
fn the_disc_reflects_the_energy_of_the_point_sun_on_a_rough_sea() {
    // ∫ I(v) v_z dω_v is the flux the sea reflects per unit area. For the disc it is the cap
    // average of the point form's l′_z A(l′) (A = directional albedo), which differs from the
    // centre value by the cap's second moment (r²/8) Δ(A l_z) = O(r²) (Laplacian on the sphere;
    // Δ l_z = −2 l_z). The same view quadrature is used for both, so its own error (≈ 10⁻⁶)
    // nearly cancels.
    /// `r²` bounds `(r²/8)|Δ(A l_z)|/(A l_z)` for `|Δ(A l_z)|/(A l_z) ≤ 8` (`l_z` gives 2, the
    /// albedo's curvature at these sun angles less than 6), plus the view quadrature's 10⁻⁶.
    fn tolerance(r: f64) -> f64 {
        r * r + 1e-6
    }
    let var = SlopeVariance::cox_munk_clean(5.0).unwrap();
    for r in [SunDisc::SUN_ANGULAR_RADIUS, 0.05] {
        let disc = SunDisc::new(r).unwrap();
        for theta_deg in [0.0f64, 30.0, 60.0] {
            let l = dir(theta_deg.to_radians(), 0.3);
            let point = reflected_flux(|v| reflected_sun_radiance(v, l, &var, 1.0));
            let extended = reflected_flux(|v| reflected_disc_radiance(v, l, &var, 1.0, &disc));
            let rel = (extended / point - 1.0).abs();
            assert!(rel < tolerance(r), "r = {r}, θ = {theta_deg}: {extended} vs {point} ({rel:.2e})");
            // And both are a fraction of the incident l_z E (Fresnel ≤ 1 keeps it well below).
            assert!(point > 0.0 && point < l.z, "{point}");
        }
    }
}

#[test]
fn the_adaptive_rule_is_close_to_a_fine_rule() {
    // SunDisc::sun() (1–16 rings chosen per call) against a fixed 32-ring rule for the Sun,
    // near the specular direction where the glint is bright, for sun zenith angles to 85°.
    /// The target of `rings_for`'s error model, wherever the glint exceeds 10⁻⁶ of its peak
    /// (measured: 7.6×10⁻⁶ on the calmest sea, σ = 4.5 mrad, where the Sun's image is 0.5 to 6
    /// times the lobe's width; 2.9×10⁻⁵ at 4×10⁻⁶ of the peak of a σ² = (2, 1)×10⁻³ sea, one
    /// ring; 4×10⁻⁷ at U = 7 m/s).
    const ADAPTIVE: f64 = 1e-4;
    let fine = SunDisc::with_rings(SunDisc::SUN_ANGULAR_RADIUS, 32).unwrap();
    let quick = SunDisc::sun();
    let seas = [calm(), SlopeVariance::new(2e-3, 1e-3).unwrap(), SlopeVariance::cox_munk_clean(7.0).unwrap()];
    let mut worst = [0.0f64; 3];
    let mut most_rings = 0;
    for (k, var) in seas.iter().enumerate() {
        for tl in [0.0f64, 20.0, 40.0, 60.0, 70.0, 80.0, 85.0] {
            let l = dir(tl.to_radians(), 0.0);
            let peak = reflected_disc_radiance(specular(l), l, var, 1.0, &fine);
            for tv in [0.0f64, 20.0, 40.0, 60.0, 80.0] {
                for pv in [0.0, PI / 2.0, PI] {
                    // Views within 3 mrad·(angle to the specular) on the calm sea, anywhere on
                    // the rough ones.
                    let step = if k == 0 { 0.003 } else { 0.5 };
                    let v = (specular(l) + step * (dir(tv.to_radians(), pv) - specular(l))).normalize();
                    let a = reflected_disc_radiance(v, l, var, 1.0, &quick);
                    let b = reflected_disc_radiance(v, l, var, 1.0, &fine);
                    most_rings = most_rings.max(quick.rings_for(v, l, var));
                    if b > 1e-6 * peak {
                        worst[k] = worst[k].max((a / b - 1.0).abs());
                    }
                }
            }
        }
    }
    for (k, w) in worst.iter().enumerate() {
        assert!(*w < ADAPTIVE, "sea {k}: {w:.2e}");
    }
    assert!(most_rings <= SunDisc::ADAPTIVE_RINGS.1);
}
