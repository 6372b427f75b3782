//! The sine and Gerstner surfaces traced by `brine-trace`: the hit is on the surface and no
//! earlier crossing exists (checked by a dense march).

mod common;

use std::f64::consts::PI;

use brine_trace::{LipschitzSum, Ray, TraceOptions, TraceStats, trace};
use brine_waves::{CosineTwoS, FitOptions, GerstnerSurface, PiersonMoskowitz, SineSet, Spectrum, fit_trochoids};
use glam::DVec3;
use proptest::prelude::*;

/// March step of the reference (m): a tenth of the shortest wavelength of the set below (~0.6 m).
const MARCH: f64 = 0.06;

/// `|F|` at a reported hit: the tracer's final bracket is at most `10⁻⁶ m + 10⁻⁹ t` (the default
/// `TraceOptions`; ≤ 1.4×10⁻⁶ m to 400 m), times `|∂F/∂t| ≤ 1 + L` (`ΣQ ≤ 0.5` keeps `L` of these
/// 20-wave PM sets at a few): below 10⁻⁵.
const AT_HIT_ABS: f64 = 1e-5;

/// The hit against the march's bisected first crossing: both brackets are far below the tracer's
/// minimum step (10⁻⁴ m), the largest gap two crossings may hide in.
const HIT_AGREEMENT_M: f64 = 1e-4;

/// A 20-wave PM sea at 8 m/s with `ΣQ ≤ 0.5`, and a ray from `height` m down at `dip` rad.
fn gentle_sea_and_ray(seed: u64, height: f64, azimuth: f64, dip: f64) -> (brine_waves::TrochoidSet, Ray) {
    let pm = PiersonMoskowitz::from_u10(8.0).unwrap();
    let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let o = FitOptions { max_total_steepness: 0.5, ..FitOptions::default() };
    let set = fit_trochoids(&pm, &d, 20, seed, &o).unwrap();
    let dir = DVec3::new(dip.cos() * azimuth.cos(), -dip.sin(), dip.cos() * azimuth.sin());
    (set, Ray::new(DVec3::new(0.0, height, 0.0), dir).unwrap())
}

fn check(f: &dyn LipschitzSum, ray: &Ray) -> Result<(), TestCaseError> {
    let opts = TraceOptions { t_max: 400.0, ..TraceOptions::default() };
    check_with(f, &|t: f64| f.value(ray.at(t)), ray, &opts)
}

/// The trace of `traced` with `opts` against the march of `f(t)`, the function it claims to
/// trace along `ray`.
fn check_with(
    traced: &dyn LipschitzSum,
    f: &dyn Fn(f64) -> f64,
    ray: &Ray,
    opts: &TraceOptions,
) -> Result<(), TestCaseError> {
    let hit = trace(traced, ray, opts, &mut TraceStats::default());
    match (hit, common::first_crossing(f, opts.t_max, MARCH)) {
        (Some(h), Some(r)) => {
            prop_assert!(f(h.t).abs() < AT_HIT_ABS, "F(hit) = {}", f(h.t));
            // The tracer may only miss crossing pairs closer than its minimum step (1e-4 m); the
            // reference march may miss pairs closer than MARCH. Either way the hits agree unless
            // such a skim exists, which these gentle seas (ΣQ ≤ 0.5) do not produce at 1 cm.
            prop_assert!((h.t - r).abs() < HIT_AGREEMENT_M, "trace {} vs march {r}", h.t);
        }
        (None, None) => {}
        (a, b) => prop_assert!(false, "trace {a:?} vs march {b:?}"),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn traced_hits_are_the_first_crossing(
        seed in 0u64..1000,
        height in 2.0f64..30.0,
        azimuth in -PI..PI,
        dip in 0.02f64..1.2,
    ) {
        let (set, ray) = gentle_sea_and_ray(seed, height, azimuth, dip);
        let sine = SineSet::new(&set);
        check(&sine.at_time(1.5), &ray)?;
        let gerstner = GerstnerSurface::new(&set).unwrap();
        check(&gerstner.at_time(1.5), &ray)?;
    }
}

/// Footprint angle of the faded traces below (rad): a 0.05° pixel, so that over 400 m every wave
/// shorter than ~0.35 m per 100 m fades, and grazing rays fade most of the set.
const PIXEL: f64 = 8.7e-4;

/// A faded trace (the tiered method with a footprint) against the march of the faded function it
/// claims to trace, `F(t) = y − h_{w(t)}`.
fn check_faded(traced: &dyn LipschitzSum, faded: &dyn Fn(f64) -> f64, ray: &Ray) -> Result<(), TestCaseError> {
    let opts = TraceOptions {
        t_max: 400.0,
        method: brine_trace::Method::Tiered,
        footprint_angle: PIXEL,
        ..TraceOptions::default()
    };
    check_with(traced, faded, ray, &opts)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// With footprint fading the Gerstner and sine seas are traced to the first crossing of their
    /// faded surface (each wave weighted by smoothstep(1, 1.5, Tᵢ/t)), as the trochoids are.
    #[test]
    fn faded_hits_are_the_first_crossing_of_the_faded_surface(
        seed in 0u64..1000,
        height in 2.0f64..30.0,
        azimuth in -PI..PI,
        dip in 0.02f64..0.6,
    ) {
        let (set, ray) = gentle_sea_and_ray(seed, height, azimuth, dip);
        let dir = ray.direction();

        let gerstner = GerstnerSurface::new(&set).unwrap();
        let g = gerstner.at_time(1.5);
        let fade = g.fade_distances(dir, PIXEL);
        let faded_g = |t: f64| {
            let w: Vec<f64> = fade.iter().map(|&f| brine_trace::footprint_weight(f, t)).collect();
            let p = ray.at(t);
            p.y - g.faded_height(p.x, p.z, &w)
        };
        check_faded(&g, &faded_g, &ray)?;

        let sine = SineSet::new(&set);
        let s = sine.at_time(1.5);
        let faded_s = |t: f64| {
            let w = brine_trace::component_weights(&s, dir, PIXEL, t);
            let p = ray.at(t);
            w.iter().enumerate().map(|(i, wi)| wi * s.component(i, p)).sum::<f64>()
        };
        check_faded(&s, &faded_s, &ray)?;
    }
}

/// All weights 1 is the whole Gerstner sum; the faded gradient and lost slopes vanish without
/// fading and the lost slopes grow with the distance.
#[test]
fn the_faded_gerstner_sum_tends_to_the_whole_one() {
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let set = fit_trochoids(&pm, &d, 30, 3, &FitOptions::default()).unwrap();
    let g = GerstnerSurface::new(&set).unwrap();
    let f = g.at_time(2.0);
    let ones = vec![1.0; g.len()];
    for (x, z) in [(0.0, 0.0), (3.7, -12.0), (150.0, 40.0)] {
        // The same inversion on the same waves: only the order of a few roundings differs.
        assert!((f.faded_height(x, z, &ones) - f.height(x, z)).abs() < 1e-12);
        assert_eq!(f.faded_gradient(x, z, DVec3::X, 0.0, 10.0), f.gradient(x, z));
    }
    let dir = DVec3::new(0.99, -0.1, 0.0).normalize();
    assert_eq!(f.faded_slope_covariance(dir, 0.0, 100.0), DVec3::ZERO);
    let near = f.faded_slope_covariance(dir, 1e-3, 10.0);
    let far = f.faded_slope_covariance(dir, 1e-3, 1000.0);
    assert!(far.x > near.x && far.z > near.z && far.x > 0.0, "{near} {far}");
}
