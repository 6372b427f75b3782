//! Footprint pruning reports what it drops: the weights of `component_weights` and the partition
//! of `faded_components`, against the documented rule computed independently from the waves'
//! wavelengths and directions, and against the surface the tiered tracer actually traces.

// Weights of exactly 0 and 1 are the documented values (`smoothstep` clamps), compared exactly.
#![allow(clippy::float_cmp)]

mod common;

use std::f64::consts::TAU;

use brine_trace::{
    ComponentTiers, LipschitzSum, Method, Ray, RayTiers, TraceOptions, TraceStats, component_weights, faded_components,
    footprint_weight, trace,
};
use brine_waves::{TracedTrochoids, TrochoidSet, TrochoidSum};
use common::{SineSum, random_ray, random_set};
use glam::DVec3;
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Weights computed two ways (the crate's and the test's formula) agree to f64 rounding of the
/// ratio `λ/(αt·stretch)`, amplified by at most 3 (the smoothstep's largest slope) times 2.
const WEIGHT_ROUNDING: f64 = 1e-12;

/// A unit direction from its vertical component and azimuth.
fn direction(dy: f64, azimuth: f64) -> DVec3 {
    let h = (1.0 - dy * dy).max(0.0).sqrt();
    DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin())
}

/// The documented rule, written out from the wave parameters alone: the pixel footprint `αt`
/// across the view is stretched by `1/max(|d_y|, 0.05)` along it, so along the wave direction
/// `k̂` it spans `αt·√(1 + (k̂·d̂_xz)²/max(|d_y|, 0.05)²)`; with `x = λ/(that span)`, the weight is 0 for `x ≤ 1`, 1 for
/// `x ≥ 1.5` and `3u² − 2u³`, `u = 2(x − 1)`, between (equations.md §1 "Antialiasing").
fn expected_weight(set: &TrochoidSet, wave: usize, d: DVec3, alpha: f64, t: f64) -> f64 {
    let w = &set.waves()[wave];
    let k_hat = w.direction_vector();
    let along = k_hat.x * d.x + k_hat.y * d.z;
    let grazing = d.y.abs().max(0.05);
    let span = alpha * t * (1.0 + along * along / (grazing * grazing)).sqrt();
    let x = w.wavelength() / span;
    if x <= 1.0 {
        0.0
    } else if x >= 1.5 {
        1.0
    } else {
        let u = 2.0 * (x - 1.0);
        u * u * (3.0 - 2.0 * u)
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    /// Without a footprint nothing is dropped; with one, every weight lies in `[0, 1]`, never
    /// increases along the ray, equals the documented rule, is 0 for every wave shorter than the
    /// footprint across the view (`λ ≤ αt`, whatever the direction) and 1 for `y`; the
    /// `dropped`/`fading` lists are exactly the waves of weight 0 and of weight in `(0, 1)`.
    #[test]
    fn weights_follow_the_documented_rule_and_only_decrease(
        n in 1usize..60,
        seed in 0u64..10_000,
        dy in -0.999f64..0.3,
        azimuth in 0.0f64..TAU,
        alpha in 1e-4f64..1e-2,
        t in 0.1f64..3000.0,
        growth in 1.0f64..3.0,
    ) {
        let set = random_set(n, 0.3, 0.9, 0.4, seed);
        let sea = TracedTrochoids::new(&set, 0.0);
        let field_sum = TrochoidSum::new(&set);
        let exact = field_sum.at_time(0.0);
        let d = direction(dy, azimuth);

        let unfaded = component_weights(&sea, d, 0.0, t);
        prop_assert!(unfaded.iter().all(|&w| w == 1.0));
        prop_assert!(faded_components(&sea, d, 0.0, t) == brine_trace::FadedComponents::default());

        let near = component_weights(&sea, d, alpha, t);
        let far = component_weights(&sea, d, alpha, t * growth);
        prop_assert_eq!(near.len(), n + 1);
        prop_assert!(near[0] == 1.0, "y is never faded");
        // The exact f64 field uses the same rule.
        let exact_weights = component_weights(&exact, d, alpha, t);
        let report = faded_components(&sea, d, alpha, t);
        for i in 0..=n {
            let w = near[i];
            prop_assert!((0.0..=1.0).contains(&w), "weight {w} of component {i}");
            prop_assert!(far[i] <= w, "component {i}: weight grew from {w} to {} along the ray", far[i]);
            prop_assert_eq!(report.dropped.contains(&i), w == 0.0, "component {} ({}) and the dropped list", i, w);
            prop_assert_eq!(report.fading.contains(&i), w > 0.0 && w < 1.0, "component {} ({}) and the fading list", i, w);
            if i > 0 {
                let expected = expected_weight(&set, i - 1, d, alpha, t);
                prop_assert!((w - expected).abs() <= WEIGHT_ROUNDING, "wave {}: {w} vs {expected}", i - 1);
                prop_assert!((exact_weights[i] - w).abs() <= WEIGHT_ROUNDING, "wave {}: f64 field {} vs {w}", i - 1, exact_weights[i]);
                // Well below the footprint across the view (whatever the direction): dropped.
                if set.waves()[i - 1].wavelength() <= 0.99 * alpha * t {
                    prop_assert!(w == 0.0, "wave {} of λ = {} under the footprint {}: weight {w}", i - 1, set.waves()[i - 1].wavelength(), alpha * t);
                }
                // The renderer's accessor reports the same weight.
                prop_assert!((sea.fade_weight(i - 1, d, alpha, t) - w).abs() <= WEIGHT_ROUNDING);
            }
        }
        prop_assert!(report.dropped.windows(2).all(|p| p[0] < p[1]) && report.fading.windows(2).all(|p| p[0] < p[1]));
    }
}

/// The generic tiers (what [`brine_trace::Method::Tiered`] and [`brine_trace::Method::Segment`]
/// trace for a surface without its own fast path) are the component sum re-weighted by
/// `component_weights`: the value on the trochoid f32 surface and on a sine sum, the derivative
/// along the ray (weights' change included) on the sine sum, whose components are exact in f64.
#[test]
fn generic_tiers_are_the_sum_reweighted_by_the_reported_weights() {
    /// The tier sums and the re-weighted components add the same f64 terms in another order.
    const SUM_ROUNDING: f64 = 1e-12;
    /// Central difference of `Σ wᵢ(t) nᵢ` with step 10⁻⁴ m on the sine sum: truncation
    /// `h²·|F⁽³⁾|/6` below 10⁻⁸ m⁻¹ (`|F⁽³⁾| ≤ Σ aσ³` plus the weights' terms, under 10² here),
    /// rounding 10⁻¹⁶/10⁻⁴.
    const SLOPE_DIFFERENCE: f64 = 1e-6;
    let set = random_set(40, 0.5, 0.6, 0.4, 7);
    let sea = TracedTrochoids::new(&set, 0.0);
    let sines = SineSum::random(30, 9);
    let alpha = 2e-3;
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let mut dropped_points = 0;
    for r in 0..40 {
        let ray = random_ray(set.total_amplitude(), &mut rng);
        let surfaces: [&dyn LipschitzSum; 2] = [&sea, &sines];
        for (which, surface) in surfaces.into_iter().enumerate() {
            let mut tiers = ComponentTiers::new(surface, &ray, 0.0, 400.0, alpha);
            let reweighted = |t: f64| -> f64 {
                let p = ray.at(t);
                component_weights(surface, ray.direction(), alpha, t)
                    .iter()
                    .enumerate()
                    .map(|(i, w)| w * surface.component(i, p))
                    .sum()
            };
            for j in 1..200 {
                let t = 2.0 * j as f64;
                let (mut value, mut slope) = (0.0, 0.0);
                for k in 0..tiers.tier_count() {
                    let s = tiers.sample(k, t);
                    value += s.value;
                    slope += s.slope;
                }
                let expected = reweighted(t);
                assert!(
                    (value - expected).abs() <= SUM_ROUNDING * (1.0 + expected.abs()),
                    "ray {r}, surface {which}, t = {t}: {value} vs {expected}"
                );
                if which == 1 {
                    let h = 1e-4;
                    let difference = (reweighted(t + h) - reweighted(t - h)) / (2.0 * h);
                    assert!(
                        (slope - difference).abs() <= SLOPE_DIFFERENCE,
                        "ray {r}, t = {t}: slope {slope} vs {difference}"
                    );
                }
                if !faded_components(surface, ray.direction(), alpha, t).dropped.is_empty() {
                    dropped_points += 1;
                }
            }
        }
    }
    assert!(dropped_points > 2000, "the rays must reach distances where components are dropped ({dropped_points})");
}

/// The fast SIMD path (`TracedTrochoids`, what the renderer traces): every tiered + footprint
/// hit lies on the surface re-weighted by the reported weights, `y − Σ wᵢ(t) hᵢ = 0` (exact f64
/// waves), and for many of those rays not on the unfaded surface: the report is what was traced.
#[test]
fn tiered_hits_lie_on_the_surface_reweighted_by_the_reported_weights() {
    let set = random_set(60, 0.4, 0.6, 0.5, 3);
    let field_sum = TrochoidSum::new(&set);
    let exact = field_sum.at_time(0.0);
    let sea = TracedTrochoids::new(&set, 0.0);
    let alpha = 3e-3;
    let options = TraceOptions {
        method: Method::Tiered,
        footprint_angle: alpha,
        t_max: 2000.0,
        tolerance: 1e-7,
        tolerance_relative: 0.0,
        ..TraceOptions::default()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let (mut hits, mut off_unfaded) = (0, 0);
    for _ in 0..400 {
        let ray = Ray::new(
            DVec3::new(0.0, rand::Rng::random_range(&mut rng, 2.0..20.0), 0.0),
            direction(-rand::Rng::random_range(&mut rng, 0.005..0.3), rand::Rng::random_range(&mut rng, 0.0..TAU)),
        )
        .unwrap();
        let Some(hit) = trace(&sea, &ray, &options, &mut TraceStats::default()) else { continue };
        hits += 1;
        let p = hit.point;
        let weights = component_weights(&sea, ray.direction(), alpha, hit.t);
        let faded: f64 = weights.iter().enumerate().map(|(i, w)| w * exact.component(i, p)).sum();
        // On the surface: the f32 error bound plus the refinement tolerance times the slope.
        let on_surface = sea.error_bound() + exact.directional_lipschitz(ray.direction()) * options.tolerance + 1e-12;
        assert!(faded.abs() <= on_surface, "hit at t = {}: faded surface {faded:e} > {on_surface:e}", hit.t);
        if exact.value(p).abs() > 100.0 * on_surface {
            off_unfaded += 1;
        }
    }
    assert!(hits > 300, "{hits} hits");
    assert!(off_unfaded > hits / 4, "only {off_unfaded} of {hits} hits off the unfaded surface: fading untested");
}

/// `footprint_weight` against its closed form at a few exact points, independent of the crate's
/// code: `smoothstep(1, 1.5, x)` at `x = 1.1, 1.25, 1.4`.
#[test]
fn weight_matches_the_smoothstep_at_exact_points() {
    for (x, expected) in [(1.1f64, 0.104f64), (1.25, 0.5), (1.4, 0.896)] {
        // u = 2(x − 1) = 0.2, 0.5, 0.8: 3u² − 2u³ = 0.104, 0.5, 0.896.
        assert!((footprint_weight(x * 10.0, 10.0) - expected).abs() <= WEIGHT_ROUNDING, "x = {x}");
    }
}

/// A level or rising ray from an eye below the crests meets them with the footprint fade on, where
/// it meets them without it: along the view the footprint is stretched by at most
/// `1/0.05`, so the long wave that makes the crests is not faded. (Stretched by `1/|d_y|`, the
/// wave faded at once along a level ray, which passed through every crest to the horizon.)
#[test]
fn a_level_ray_from_below_the_crests_meets_them() {
    // One wave 100 m long, 2 m high, running along x; the eye 0.5 m above the mean sea.
    let k = TAU / 100.0;
    let wave = brine_waves::Trochoid::new(2.0, k, 0.0, (9.81 * k).sqrt(), 0.0, 0.5).unwrap();
    let set = TrochoidSet::new(vec![wave]);
    let sea = TracedTrochoids::new(&set, 0.0);
    // A pixel of 1 mrad: with the stretch capped, the wave fades from `2π·0.05/(αk)` = 5 km.
    let faded = TraceOptions {
        method: Method::Tiered,
        footprint_angle: 1e-3,
        t_max: 3000.0,
        tolerance: 1e-6,
        tolerance_relative: 0.0,
        ..TraceOptions::default()
    };
    let whole = TraceOptions { footprint_angle: 0.0, ..faded };
    for (dy, azimuth) in [(0.0, 0.0), (0.0, 0.5), (0.005, 0.0), (-0.002, 3.0)] {
        let ray = Ray::new(DVec3::new(30.0, 0.5, 0.0), direction(dy, azimuth)).unwrap();
        let unfaded = trace(&sea, &ray, &whole, &mut TraceStats::default()).expect("the crest is in the way");
        let hit = trace(&sea, &ray, &faded, &mut TraceStats::default());
        let hit = hit.unwrap_or_else(|| {
            panic!("d_y = {dy}, azimuth {azimuth}: the faded ray passed through the crest at {}", unfaded.t)
        });
        assert!((hit.t - unfaded.t).abs() <= 1e-3, "d_y = {dy}: met at {} m, unfaded {} m", hit.t, unfaded.t);
    }
}
