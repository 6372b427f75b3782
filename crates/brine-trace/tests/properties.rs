//! Property tests: the certified step bound, and "every method's hit is the first crossing" on
//! random sums of spheres and random trochoid sets, against a dense f64 reference.

mod common;

use brine_trace::{
    ComponentTiers, LipschitzSum, Method, Ray, RayTiers, StepBound, TraceOptions, TraceStats, local_lipschitz,
    trace_logged,
};
use brine_waves::{TracedTrochoids, TrochoidSum};
use common::{
    Crossing, SineSum, SphereSum, check_first_crossing, check_steps, dense_crossings, random_ray, random_set,
};
use glam::DVec3;
use proptest::prelude::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Options of the safety tests: a small minimum step (so that only skims thinner than 10⁻⁴ m can
/// be skipped), a tight tolerance, and no practical step cap.
/// Traces `ray` on `surface` with every method (options `options(method)`): each hit must be the
/// first of the `crossings` of `F` along the ray, skims thinner than the method's probe `h` (or
/// its march step) excepted, and each logged step safe. `case` names the case in failures.
fn check_every_method<S: LipschitzSum>(
    surface: &S,
    ray: &Ray,
    crossings: &[Crossing],
    options: impl Fn(Method) -> TraceOptions,
    case: &str,
) -> Result<(), TestCaseError> {
    let f = |t: f64| surface.value(ray.at(t));
    let lambda = surface.directional_lipschitz(ray.direction());
    for method in Method::ALL {
        let options = options(method);
        let mut log = Vec::new();
        let hit = trace_logged(surface, ray, &options, &mut TraceStats::default(), &mut log);
        let march = 0.25 * surface.min_feature_size();
        // Skims a method may skip: thinner than its probe (h) or its march step.
        let skim = lambda * if method == Method::BruteForce { march } else { options.min_step } + 1e-12;
        let on_surface = lambda * options.tolerance + 1e-12;
        let fail = |e: String| TestCaseError::fail(format!("{method:?}, {case}: {e}"));
        check_first_crossing(&f, crossings, hit.map(|h| h.t), on_surface, skim).map_err(fail)?;
        check_steps(&f, &log, &options, 1e-12, method != Method::BruteForce).map_err(fail)?;
    }
    Ok(())
}

fn test_options(method: Method) -> TraceOptions {
    TraceOptions {
        method,
        t_max: 60.0,
        max_steps: 2_000_000,
        min_step: 1e-4,
        min_step_relative: 0.0,
        tolerance: 1e-7,
        tolerance_relative: 0.0,
        ..TraceOptions::default()
    }
}

/// Rounding of the closed-form bound before its root, relative to `1 + c`: a few ulps of its
/// terms; 10⁻¹² (about 4500 ulps of 1) is a wide margin.
const BOUND_ROUNDING_REL: f64 = 1e-12;

/// The bound at its closed-form root, relative to `1 + c + Λ_q s*`: its terms (`c`, `D s`,
/// `K s²/2`, `Λ s`, `min(a, Λ_p s)`, inputs all below 10) cancel there, each rounded by a few
/// ulps of its size, and the rounding of `s*` enters times the bound's slope; 10⁻⁹ (about
/// 4.5×10⁶ ulps of 1) is a wide margin over both.
const ROOT_ROUNDING_REL: f64 = 1e-9;

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// The certified lower bound is positive on `[0, s*)` and vanishes at `s*`.
    #[test]
    fn certified_step_bound_is_positive_before_its_root(
        value in 1e-6f64..10.0,
        slope in -3.0f64..3.0,
        curvature in prop_oneof![Just(0.0), 0.0f64..10.0, Just(f64::INFINITY)],
        lipschitz in 0.0f64..5.0,
        reserve in 0.0f64..5.0,
        reserve_lipschitz in 0.0f64..5.0,
    ) {
        let b = StepBound { value, slope, curvature, lipschitz, reserve, reserve_lipschitz };
        let r = b.first_root();
        prop_assert!(r > 0.0, "root {r}");
        let span = if r.is_finite() { r } else { 1e4 };
        for j in 0..2000 {
            let s = span * j as f64 / 2000.0;
            prop_assert!(b.lower_bound(s) > -BOUND_ROUNDING_REL * (1.0 + value), "bound {} < 0 at s = {s} < root {r}", b.lower_bound(s));
        }
        if r.is_finite() {
            prop_assert!(b.lower_bound(r).abs() <= ROOT_ROUNDING_REL * (1.0 + value + lipschitz * r), "bound at root {}", b.lower_bound(r));
        }
    }
}

/// Reference step of the dense march on the sphere sums (m): far below the smallest radius 0.3.
const SPHERE_REFERENCE_STEP: f64 = 2e-3;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// A sum of sphere distance functions (not an ocean): every method finds the first crossing.
    #[test]
    fn every_method_finds_the_first_crossing_of_a_sphere_sum(n in 1usize..12, seed in 0u64..1000) {
        let surface = SphereSum::random(n, seed);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for _ in 0..4 {
            let origin = DVec3::new(rand::Rng::random_range(&mut rng, -6.0..6.0), rand::Rng::random_range(&mut rng, -6.0..6.0), 7.0);
            let target = DVec3::new(rand::Rng::random_range(&mut rng, -2.0..2.0), rand::Rng::random_range(&mut rng, -2.0..2.0), rand::Rng::random_range(&mut rng, -2.0..2.0));
            let ray = Ray::new(origin, target - origin).unwrap();
            let f = |t: f64| surface.value(ray.at(t));
            let t_max = 30.0;
            let crossings = dense_crossings(&f, 0.0, t_max, SPHERE_REFERENCE_STEP);
            let options = |method| TraceOptions { t_max, ..test_options(method) };
            check_every_method(&surface, &ray, &crossings, options, &format!("seed {seed}"))?;
        }
    }
}

/// Tolerance of the hit (m) against the closed form: the tracers refine to the options'
/// tolerance 10⁻⁷ m (brute force: bisection of its march to the same); 10⁻⁶ is ten times that.
const SPHERE_HIT_TOLERANCE: f64 = 1e-6;

/// A component without a curvature bound (a sphere distance) is stored as falling at its
/// Lipschitz rate; the over-relaxed step's backward check once reversed that rate and certified a
/// step over the whole sphere. This ray (a case of the sphere-sum property, `n = 1`, seed 413,
/// with the sphere's weight set to 1)
/// crosses a sphere of radius 0.80 along a chord of 0.67 m at t = 9.704.
#[test]
fn a_relaxed_step_never_jumps_a_sphere_without_curvature_bound() {
    let surface = SphereSum {
        centres: vec![DVec3::new(0.5638158406960141, -1.3046755282586586, -0.26693099085014893)],
        radii: vec![0.7987164493006111],
        weights: vec![1.0],
    };
    let origin = DVec3::new(-1.8971519453338406, 5.213190751009499, 7.0);
    let ray = Ray::new(origin, DVec3::new(0.1954872461585758, -0.6152964767887651, -0.763672038404359)).unwrap();
    // The first crossing by the closed form of a line and a sphere.
    let oc = origin - surface.centres[0];
    let b = oc.dot(ray.direction());
    let expected = -b - (b * b - oc.length_squared() + surface.radii[0].powi(2)).sqrt();
    for method in Method::ALL {
        let options = TraceOptions { t_max: 30.0, ..test_options(method) };
        let hit = brine_trace::trace(&surface, &ray, &options, &mut TraceStats::default());
        let t = hit.map(|h| h.t);
        assert!(t.is_some_and(|t| (t - expected).abs() < SPHERE_HIT_TOLERANCE), "{method:?}: {t:?} vs {expected}");
    }
}

/// Cases of the trochoid safety test and rays per case (256 random rays, each traced by every
/// method on the f32 surface, three on the f64 one and two with fading, against dense f64
/// references; formerly 20 × 2). Measured in the dev profile (opt-level 1, dependencies 3) on the
/// shared 2-core machine of docs/benchmarks.md: this file takes 23–42 s (the cases are random: N
/// up to 200), the whole `cargo test -p brine-trace` 29–44 s of CPU after the build; 192 cases
/// took 54 s for this file alone.
const TROCHOID_CASES: u32 = 128;
const TROCHOID_RAYS: usize = 2;

proptest! {
    #![proptest_config(ProptestConfig { cases: TROCHOID_CASES, ..ProptestConfig::default() })]

    /// Random trochoid sets (N up to 200, steepness up to 0.99) and random rays, grazing ones
    /// included: on the fast f32 surface every method returns the first crossing of the exact f64
    /// surface (up to skims thinner than its minimum step or 2ε, ε the f32 error bound); the
    /// generic directional, segment and tiered tracers on the exact surface do too; and the tiered
    /// and segment methods with footprint fading return the first crossing of the faded f64
    /// surface.
    #[test]
    fn every_method_finds_the_first_crossing_of_a_trochoid_sum(
        n in prop_oneof![1usize..20, 20usize..201],
        lambda_min in 1.0f64..5.0,
        q_max in prop_oneof![Just(0.3), Just(0.9), Just(0.99)],
        slope_sum in 0.05f64..0.6,
        seed in 0u64..100_000,
    ) {
        let set = random_set(n, lambda_min, q_max, slope_sum, seed);
        let sum = TrochoidSum::new(&set);
        let exact = sum.at_time(0.7);
        let fast = TracedTrochoids::new(&set, 0.7);
        let eps = fast.error_bound();
        let half = set.total_amplitude();
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x5eed);
        for _ in 0..TROCHOID_RAYS {
            let ray = random_ray(half, &mut rng);
            let f = |t: f64| exact.value(ray.at(t));
            let Some((t0, t1)) = exact.zero_set_bounds().clip(&ray, 0.0, 60.0) else { continue };
            let lambda = exact.directional_lipschitz(ray.direction());
            let crossings = dense_crossings(&f, t0, t1, lambda_min / 50.0);
            let run = |surface: &dyn LipschitzSum, method: Method, fp: f64, reference: &dyn Fn(f64) -> f64, crossings: &[common::Crossing], err: f64| -> Result<(), TestCaseError> {
                let options = TraceOptions { footprint_angle: fp, ..test_options(method) };
                let mut log = Vec::new();
                let hit = trace_logged(surface, &ray, &options, &mut TraceStats::default(), &mut log);
                let march = 0.25 * surface.min_feature_size();
                let skim = 2.0 * err + lambda * if method == Method::BruteForce { march } else { options.min_step };
                let on_surface = err + lambda * options.tolerance + 1e-12;
                check_first_crossing(reference, crossings, hit.map(|h| h.t), on_surface, skim)
                    .map_err(|e| TestCaseError::fail(format!("{method:?} fp {fp}, n {n}, seed {seed}, ray {ray:?}: {e}")))?;
                check_steps(reference, &log, &options, 2.0 * err + 1e-12, method != Method::BruteForce)
                    .map_err(|e| TestCaseError::fail(format!("{method:?} fp {fp}, n {n}, seed {seed}: {e}")))
            };
            for method in Method::ALL {
                run(&fast, method, 0.0, &f, &crossings, eps)?;
            }
            for method in [Method::Directional, Method::Segment, Method::Tiered] {
                run(&exact, method, 0.0, &f, &crossings, 0.0)?;
            }
            // Footprint fading: the reference is the faded surface y − Σ wᵢ(t) hᵢ.
            let fp = 0.02;
            let d = ray.direction();
            let faded = |t: f64| {
                let p = ray.at(t);
                let mut h = 0.0;
                for i in 0..set.len() {
                    let w = fast.fade_weight(i, d, fp, t);
                    if w > 0.0 {
                        h += w * -exact.component(i + 1, p);
                    }
                }
                p.y - h
            };
            let faded_crossings = dense_crossings(&faded, t0, t1, lambda_min / 50.0);
            run(&fast, Method::Tiered, fp, &faded, &faded_crossings, eps)?;
            run(&fast, Method::Segment, fp, &faded, &faded_crossings, eps)?;
        }
    }
}

/// Slack of a chord slope over the local bound (per metre): f64 rounding of values up to 100 m
/// (10⁻¹⁴) over grid steps of at least 2.5×10⁻⁵ m.
const CHORD_SLACK: f64 = 1e-8;

/// Reference step of the dense march on the sine sums (m): a fiftieth of the shortest wavelength 1 m.
const SINE_REFERENCE_STEP: f64 = 0.02;

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    /// Segment tracing's local bound: on the segment `[t, t + s]`, every chord slope of every tier
    /// is at most `min(L, |d(t)| + K s)` (the tiers of a sine sum, exact derivative and curvature).
    #[test]
    fn segment_local_lipschitz_bound_holds_on_its_segment(
        n in 1usize..40,
        seed in 0u64..10_000,
        t in 0.0f64..50.0,
        s in 1e-2f64..30.0,
        dy in -0.99f64..-0.001,
        azimuth in 0.0f64..std::f64::consts::TAU,
    ) {
        let surface = SineSum::random(n, seed);
        let h = (1.0 - dy * dy).sqrt();
        let ray = Ray::new(DVec3::new(1.0, 2.0, -3.0), DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin())).unwrap();
        let mut tiers = ComponentTiers::new(&surface, &ray, 0.0, 100.0, 0.0);
        let m = 400;
        for j in 0..tiers.tier_count() {
            let b = tiers.bounds(j, t);
            let start = tiers.sample(j, t);
            // The smaller of the global bound and `|F'(t)| + K s`: every chord below it checks both.
            let lambda = local_lipschitz(&b, start.slope, s);
            let mut previous = start.value;
            for i in 1..=m {
                let v = tiers.sample(j, t + s * i as f64 / m as f64).value;
                let chord = (v - previous).abs() / (s / m as f64);
                prop_assert!(chord <= lambda + CHORD_SLACK, "tier {j}, s = {s}: chord slope {chord} > {lambda}");
                previous = v;
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, ..ProptestConfig::default() })]

    /// Sums of sines (exact derivatives and curvature bounds, generic `ComponentTiers`): every
    /// method, segment and tiered included, returns the first crossing and takes no certified
    /// step across one.
    #[test]
    fn every_method_finds_the_first_crossing_of_a_sine_sum(n in 1usize..40, seed in 0u64..10_000) {
        let surface = SineSum::random(n, seed);
        let half = surface.amplitudes.iter().sum::<f64>();
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0xabc);
        for _ in 0..4 {
            let ray = random_ray(half, &mut rng);
            let f = |t: f64| surface.value(ray.at(t));
            let Some((t0, t1)) = surface.zero_set_bounds().clip(&ray, 0.0, 60.0) else { continue };
            let crossings = dense_crossings(&f, t0, t1, SINE_REFERENCE_STEP);
            check_every_method(&surface, &ray, &crossings, test_options, &format!("n {n}, seed {seed}"))?;
        }
    }
}
