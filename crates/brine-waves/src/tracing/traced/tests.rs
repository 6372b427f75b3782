use proptest::prelude::*;

use super::tiers::*;
use super::*;
use crate::{FitOptions, PiersonMoskowitz, Spectrum, TrochoidSum, fit_trochoids, solve_trochoid_phase};
use brine_trace::{LipschitzSum, Ray};

/// A set with mixed steepness (series and Newton modes) from the fit, `Q` overridden per wave.
fn set(n: usize, q_max: f64, seed: u64) -> TrochoidSet {
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let spreading = crate::CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let fit = fit_trochoids(&pm, &spreading, n, seed, &FitOptions::default()).unwrap();
    let waves = fit
        .waves()
        .iter()
        .enumerate()
        .map(|(i, w)| {
            let q = q_max * ((i * 37 + seed as usize) % 11) as f64 / 10.0;
            w.with_steepness(q).unwrap()
        })
        .collect();
    TrochoidSet::new(waves)
}

#[test]
fn the_kinematics_height_is_the_traced_height_bit_for_bit() {
    // `SeaFrame::sample` reads the height from the kinematics: it must be the traced sum.
    for (n, q) in [(50, 0.6), (150, 0.9)] {
        let sea = TracedTrochoids::new(&set(n, q, 3), 2.7);
        for i in 0..2000 {
            let f = f64::from(i);
            let (x, z) = (400.0 * (f * 0.618_034).fract() - 200.0, 400.0 * (f * 0.754_878).fract() - 200.0);
            assert_eq!(sea.kinematics(x, z).height.to_bits(), sea.height(x, z).to_bits(), "({x}, {z})");
        }
    }
}

/// The exact f64 value of tier `tier` along the ray at `t` (faded like the lanes).
fn exact_tier(sea: &TracedTrochoids, state: &RayState, ray: &Ray, tier: usize, t: f64) -> f64 {
    if tier == 0 {
        return ray.at(t).y;
    }
    // Tracer tier `tier` holds the lane groups `(tier − 1)·group ..` (`SeaTiers::group`).
    let groups = (tier - 1) * sea.group..tier * sea.group;
    let p = ray.at(t);
    let mut sum = 0.0;
    let mut held = 0.0;
    for j in groups.clone().filter(|&j| j < sea.tiers.len()) {
        held += state.tier[j].held;
    }
    for (i, (w, offset)) in sea.waves.iter().enumerate() {
        let (j, l) = sea.lane_of_wave[i];
        if !groups.contains(&j) {
            continue;
        }
        let k = w.wavenumber() * w.direction_vector();
        let (_, c, _) = solve_trochoid_phase(k.x * p.x + k.y * p.z + offset, w.steepness());
        let weight = footprint_weight(f64::from(state.fade[j][l]), t);
        sum -= weight * state.mask[j][l] as f64 * w.amplitude() * c;
    }
    sum - held
}

/// Rounding of a second difference of f64 tier values (|T| ≲ 10 m) at a spacing of 1 cm:
/// about 4·10 m·2⁻⁵² / (10⁻² m)² ≈ 10⁻¹⁰ m⁻¹, with margin.
const SECOND_DIFFERENCE_ROUNDING: f64 = 1e-8;

/// Relative slack of `|ΔT| ≤ L Δt` between two samples: the f64 rounding of `L Δt` and of the
/// sums that form `L`, a few ulps; 10⁻¹² is a wide margin.
const LIPSCHITZ_ROUNDING_REL: f64 = 1e-12;

/// Relative slack of the curvature and concavity checks (`|ΔT′|/dt ≤ K`, second difference
/// `≥ −C`), which hold exactly by the mean value theorem once the f32 errors are added: the
/// bounds' fade terms use the f32-rounded amplitudes (6×10⁻⁸ relative) and f64 sums. 10⁻⁶ is
/// a margin over these, not a measured error.
const BOUND_ROUNDING_REL: f64 = 1e-6;

/// Absolute slack of `|ΔT′|/dt` (m⁻¹) for the f64 rounding of the slope difference over
/// `dt` = 10⁻³ m: about ulp(`L`)/`dt` ≈ 2×10⁻¹³ `L`; 10⁻⁹ covers it for any `L` below 10³.
const SLOPE_DIFFERENCE_ROUNDING: f64 = 1e-9;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Along random rays, every tier's samples stay within its bounds, its derivative within
    /// its Lipschitz bound, the change of the derivative within the curvature bound (and above
    /// the one-sided concavity bound), and the f32 sample within the error bound of the exact
    /// f64 tier.
    #[test]
    fn tier_samples_respect_their_bounds(
        n in 1usize..120,
        q_max in prop_oneof![Just(0.05), Just(0.6), Just(0.99)],
        seed in 0u64..1000,
        dy in -0.9f64..-0.01,
        azimuth in 0.0f64..std::f64::consts::TAU,
        fade in prop_oneof![Just(0.0), Just(0.002), Just(0.02)],
    ) {
        let set = set(n, q_max, seed);
        let sea = TracedTrochoids::new(&set, 1.3);
        let h = (1.0 - dy * dy).sqrt();
        let ray = Ray::new(DVec3::new(3.0, 2.0, -7.0), DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin())).unwrap();
        let t_exit = 80.0;
        let mut state = RayState::default();
        let mut tiers = SeaTiers::new(&sea, &mut state, &ray, t_exit, fade, 0.0);
        let eps = tiers.error_bound();
        let eta = tiers.slope_error_bound();
        for j in 0..tiers.tier_count() {
            for &t0 in &[0.5, 5.0, 30.0] {
                let b = tiers.bounds(j, t0);
                let dt = 1e-3;
                let mut previous: Option<(f64, f64)> = None;
                for i in 0..200 {
                    let t = t0 + (t_exit - t0) * i as f64 / 200.0;
                    let s = tiers.sample(j, t);
                    prop_assert!(s.value >= b.min - eps && s.value <= b.max + eps, "tier {j} t {t}: {} ∉ [{}, {}]", s.value, b.min, b.max);
                    prop_assert!(s.slope.abs() <= b.lipschitz + eta, "tier {j} t {t}: slope {} > {}", s.slope, b.lipschitz);
                    // The value itself between samples, not only the reported slope: each f32
                    // sample is within ε of the exact tier, which is L-Lipschitz on [t0, t_exit].
                    if let Some((tp, vp)) = previous {
                        prop_assert!((s.value - vp).abs() <= b.lipschitz * (t - tp) * (1.0 + LIPSCHITZ_ROUNDING_REL) + 2.0 * eps, "tier {j} t {t}: |Δvalue| {} > L Δt {}", (s.value - vp).abs(), b.lipschitz * (t - tp));
                    }
                    let s2 = tiers.sample(j, t + dt);
                    // Finite difference of the slope, with the f32 slope error over dt.
                    let second = (s2.slope - s.slope) / dt;
                    prop_assert!(second.abs() <= b.curvature * (1.0 + BOUND_ROUNDING_REL) + 2.0 * eta / dt + SLOPE_DIFFERENCE_ROUNDING, "tier {j} t {t}: curvature {second} > {}", b.curvature);
                    let exact = exact_tier(&sea, tiers.state, &ray, j, t);
                    prop_assert!((s.value - exact).abs() <= eps, "tier {j} t {t}: f32 {} vs f64 {exact} (ε = {eps:e})", s.value);
                    // One-sided: the second difference of the exact tier (a weighted mean of
                    // T'' over [t, t + 2h]) never falls below −concavity.
                    let h2 = 1e-2;
                    let (e1, e2) = (exact_tier(&sea, tiers.state, &ray, j, t + h2), exact_tier(&sea, tiers.state, &ray, j, t + 2.0 * h2));
                    let second_exact = (e2 - 2.0 * e1 + exact) / (h2 * h2);
                    prop_assert!(b.concavity <= b.curvature, "tier {j}: concavity {} > curvature {}", b.concavity, b.curvature);
                    prop_assert!(second_exact >= -b.concavity * (1.0 + BOUND_ROUNDING_REL) - SECOND_DIFFERENCE_ROUNDING, "tier {j} t {t}: T'' {second_exact} < −{}", b.concavity);
                    previous = Some((t, s.value));
                }
            }
        }
    }
}

/// The f32 gradient against the f64 one, relative to the slope sum `Σ Lᵢ` (at most the
/// largest possible slope): per wave the f32 slope error `PROFILE_ERROR·(1 + 1/(1 − Q)²)` in
/// units of `kA` is at most 2.9×10⁻⁶ of its `Lᵢ = kA/√(1 − Q²)` for `Q ≤ 0.6` (this set);
/// 10⁻⁵ leaves room for the f32 amplitudes and sums.
const F32_GRADIENT_REL: f64 = 1e-5;

/// At 1 m a footprint of 2 mrad is far below every wave, so no wave should have faded and the
/// lost covariance should be exactly 0; 10⁻¹² accepts rounding residue only.
const NOTHING_FADED: f64 = 1e-12;

/// At 1000 km every wave has faded: the lost covariance's trace is `Σ mssᵢ (d_x² + d_z²)` with
/// unit `d` in f64, against `Σ mssᵢ`: rounding of 80 terms, ~10⁻¹⁴ relative; 10⁻⁹ is loose.
const ALL_FADED_REL: f64 = 1e-9;

#[test]
fn faded_gradient_matches_the_f64_gradient_and_fades() {
    let set = set(80, 0.6, 5);
    let sea = TracedTrochoids::new(&set, 0.4);
    let sum = TrochoidSum::new(&set);
    let exact = sum.at_time(0.4);
    let d = DVec3::new(0.9, -0.1, 0.3).normalize();
    for i in 0..200 {
        let (x, z) = (i as f64 * 2.37 - 200.0, i as f64 * -0.71 + 40.0);
        let (fast, reference) = (sea.faded_gradient(x, z, d, 0.0, 10.0), exact.gradient(x, z));
        let scale: f64 = set.waves().iter().map(Trochoid::max_slope).sum();
        assert!((fast - reference).length() <= F32_GRADIENT_REL * scale, "{fast} vs {reference}");
    }
    // Far away every short wave has faded: the gradient loses them and the covariance gains them.
    let near = sea.faded_slope_covariance(d, 0.002, 1.0);
    let far = sea.faded_slope_covariance(d, 0.002, 1e6);
    assert!(near.x.abs() < NOTHING_FADED && far.x > 0.0 && far.z > 0.0);
    let total: f64 = set.waves().iter().map(Trochoid::mean_square_slope).sum();
    assert!(((far.x + far.z) - total).abs() < ALL_FADED_REL * total, "all waves faded at 1000 km");
}

/// The one-pass covariance against the wave-by-wave one: the same terms summed in another
/// order, rounding of a sum of ≤ 80 positive terms.
const ORDER_ROUNDING: f64 = 1e-13;

/// The one-pass covariance equals the wave-by-wave one of `faded_slope_covariance` (set
/// order, weights from `fade_weight`) at distances where the waves fade one after the other;
/// the gradient of the one pass is tested against the f64 surface above.
#[test]
fn fused_covariance_equals_the_wave_by_wave_one() {
    let set = set(80, 0.6, 9);
    let sea = TracedTrochoids::new(&set, 0.7);
    let d = DVec3::new(0.6, -0.08, -0.8).normalize();
    let mut faded_some = 0;
    for (i, t) in [0.5, 3.0, 20.0, 150.0, 900.0, 5e3].into_iter().enumerate() {
        let (x, z) = (i as f64 * 13.1 - 7.0, 2.0 - i as f64 * 5.3);
        let (_, c) = sea.faded_gradient_and_covariance(x, z, d, 0.0015, t);
        let reference = sea.faded_slope_covariance(d, 0.0015, t);
        let scale = reference.abs().max_element();
        assert!((c - reference).abs().max_element() <= ORDER_ROUNDING * scale, "t = {t}: {c} vs {reference}");
        faded_some += usize::from(scale > 0.0);
    }
    assert!(faded_some >= 3, "the distances must fade some waves");
}

#[test]
fn fast_height_matches_the_f64_surface_within_its_error_bound() {
    for (q_max, seed) in [(0.05, 1), (0.5, 2), (0.99, 3)] {
        let set = set(150, q_max, seed);
        let sea = TracedTrochoids::new(&set, 0.4);
        let sum = TrochoidSum::new(&set);
        let exact = sum.at_time(0.4);
        for i in 0..500 {
            let (x, z) = (i as f64 * 1.37 - 300.0, i as f64 * -0.61 + 40.0);
            let (fast, reference) = (sea.height(x, z), exact.height(x, z));
            assert!((fast - reference).abs() <= sea.error_bound(), "{fast} vs {reference}");
            let component = (1..=set.len()).map(|c| -sea.component(c, DVec3::new(x, 0.0, z))).sum::<f64>();
            assert!((component - reference).abs() <= sea.error_bound(), "{component} vs {reference}");
        }
    }
}

/// The faded height against the f64 sum of each wave's height weighted by its own fade weight
/// (`fade_weight`, from `fade_distance` and brine-core's smoothstep, wave by wave in set order):
/// the kernel's f32 error bound covers the difference, each weight in `[0, 1]` only shrinking a
/// wave's error.
#[test]
fn faded_height_is_each_wave_weighted_by_its_fade() {
    let set = set(80, 0.6, 11);
    let time = 0.9;
    let sea = TracedTrochoids::new(&set, time);
    let d = DVec3::new(-0.5, -0.12, 0.85).normalize();
    let angle = 0.0015;
    let mut faded_some = 0;
    for (i, t) in [0.0, 2.0, 25.0, 180.0, 1500.0, 1e5].into_iter().enumerate() {
        let (x, z) = (i as f64 * 31.7 - 60.0, 14.0 - i as f64 * 9.1);
        let fast = sea.faded_height(x, z, d, angle, t);
        let mut reference = 0.0;
        let mut weights = 0.0;
        for (k, w) in set.waves().iter().enumerate() {
            let weight = if t > 0.0 { sea.fade_weight(k, d, angle, t) } else { 1.0 };
            let dir = w.direction_vector();
            let s = w.wavenumber() * (dir.x * x + dir.y * z) - w.omega() * time + w.phase();
            let (_, c, _) = solve_trochoid_phase(s, w.steepness());
            reference += weight * w.amplitude() * c;
            weights += weight;
        }
        assert!((fast - reference).abs() <= sea.error_bound(), "t = {t}: {fast} vs {reference}");
        faded_some += usize::from(weights < set.len() as f64 - 0.5);
    }
    // Without a footprint angle nothing fades: the traced height.
    assert_eq!(sea.faded_height(3.0, 4.0, d, 0.0, 50.0).to_bits(), sea.height(3.0, 4.0).to_bits());
    assert!(faded_some >= 3, "the distances must fade some waves");
}
