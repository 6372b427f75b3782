//! Image and temporal coherence: cones certify only what holds for every ray they contain, and the
//! coherent tracers return the first crossing of each ray.

mod common;

use brine_trace::{
    LipschitzSum, Method, Ray, RaySpan, RayTile, TraceOptions, TraceStats, trace, trace_temporal, trace_tile,
};
use brine_waves::{TracedTrochoids, TrochoidSum};
use common::{check_first_crossing, dense_crossings, random_set};
use glam::DVec3;
use proptest::prelude::*;

fn options(footprint_angle: f64) -> TraceOptions {
    TraceOptions {
        method: Method::Tiered,
        t_max: 60.0,
        max_steps: 1_000_000,
        min_step: 1e-4,
        min_step_relative: 0.0,
        tolerance: 1e-7,
        tolerance_relative: 0.0,
        footprint_angle,
        ..TraceOptions::default()
    }
}

/// A unit vector at angle `angle` from `axis`, around it by `phi`.
fn tilt(axis: DVec3, angle: f64, phi: f64) -> DVec3 {
    let u = axis.any_orthonormal_vector();
    let v = axis.cross(u);
    (axis * angle.cos() + (u * phi.cos() + v * phi.sin()) * angle.sin()).normalize()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// No ray of a cone crosses its own (faded) surface before the distance the cone certified.
    #[test]
    fn a_cone_certifies_every_ray_it_contains(
        n in 1usize..60,
        q_max in prop_oneof![Just(0.3), Just(0.99)],
        seed in 0u64..10_000,
        pitch in 0.02f64..1.2,
        half_angle in 1e-4f64..0.05,
        footprint in prop_oneof![Just(0.0), Just(0.01)],
    ) {
        let set = random_set(n, 1.0, q_max, 0.4, seed);
        let sea = TracedTrochoids::new(&set, 0.0);
        let exact = TrochoidSum::new(&set);
        let field = exact.at_time(0.0);
        let origin = DVec3::new(0.0, set.total_amplitude() * 1.5 + 0.5, 0.0);
        let axis = DVec3::new(pitch.cos(), -pitch.sin(), 0.3).normalize();
        let ray = Ray::new(origin, axis).unwrap();
        let o = options(footprint);
        let t_c = sea.certify_cone(RaySpan::new(&ray, 0.0, o.t_max), half_angle, &o, &mut TraceStats::default());
        prop_assert!(t_c >= 0.0 && t_c <= o.t_max);
        // The origin is ΣA/2 + 0.5 m above the highest crest: the sea's override (not the trait's
        // default, which gives up under fading) certifies at least its first step.
        prop_assert!(t_c > 0.0, "the cone certified nothing from {} m above the slab", 0.5 * set.total_amplitude() + 0.5);
        for k in 0..8 {
            let d = tilt(axis, half_angle * f64::from(k % 4) / 3.0, 0.9 * f64::from(k));
            let r = Ray::new(origin, d).unwrap();
            // This ray's own surface: faded by its own direction.
            let f = |t: f64| {
                let p = r.at(t);
                let mut h = 0.0;
                for i in 0..set.len() {
                    h -= sea.fade_weight(i, d, footprint, t) * field.component(i + 1, p);
                }
                p.y - h
            };
            let eps = sea.error_bound();
            for j in 0..=2000 {
                let t = t_c * f64::from(j) / 2000.0;
                prop_assert!(f(t) > -2.0 * eps, "ray {k} crosses at t = {t} < t_c = {t_c} (F = {})", f(t));
            }
        }
    }
}

/// A ray of the tile against the same ray traced alone (m): both refine the same first crossing
/// to the options' tolerance 10⁻⁷ m, but from different brackets (the tile starts each ray where
/// its cone stopped), so they may differ by about twice that; 10⁻⁶ is five times more.
const TILE_VS_SINGLE: f64 = 1e-6;

#[test]
fn a_tile_of_coherent_rays_finds_each_first_crossing() {
    let set = random_set(24, 1.5, 0.5, 0.35, 7);
    let sea = TracedTrochoids::new(&set, 0.2);
    let exact = TrochoidSum::new(&set);
    let field = exact.at_time(0.2);
    let origin = DVec3::new(1.0, 6.0, -2.0);
    let forward = DVec3::new(0.8, -0.35, 0.2).normalize();
    let right = forward.cross(DVec3::Y).normalize();
    let up = right.cross(forward);
    let (w, h) = (16, 12);
    let directions: Vec<DVec3> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| (forward + (x as f64 - 7.5) * 0.01 * right + (y as f64 - 5.5) * 0.01 * up).normalize())
        .collect();
    let o = options(0.0);
    let mut hits = vec![None; directions.len()];
    let mut stats = TraceStats::default();
    trace_tile(&sea, &RayTile { origin, directions: &directions, width: w }, &o, &mut stats, &mut hits, None);
    let mut hit_count = 0;
    for (d, hit) in directions.iter().zip(&hits) {
        let ray = Ray::new(origin, *d).unwrap();
        if !check_against_exact(&field, &ray, hit.map(|h| h.t), sea.error_bound(), &o, 1.5 / 50.0).unwrap() {
            continue;
        }
        // The same as tracing the ray alone.
        let single = trace(&sea, &ray, &o, &mut TraceStats::default());
        match (single, hit) {
            (Some(a), Some(b)) => assert!((a.t - b.t).abs() < TILE_VS_SINGLE, "{} vs {}", a.t, b.t),
            (None, None) => {}
            other => panic!("alone {:?} vs tile {:?}", other.0, other.1),
        }
        hit_count += usize::from(hit.is_some());
    }
    assert!(hit_count > directions.len() / 2, "only {hit_count} hits: the test needs rays that hit");
}

/// Checks that `hit` is the first crossing along `ray` of the exact surface `field` (sampled every
/// `delta` m), for a traced surface of evaluation error `eps` traced with options `o`: within the
/// tolerance of a crossing, and skipping none wider than the minimum step. `Ok(false)` when the
/// ray misses the surface's slab.
fn check_against_exact<S: LipschitzSum>(
    field: &S,
    ray: &Ray,
    hit: Option<f64>,
    eps: f64,
    o: &TraceOptions,
    delta: f64,
) -> Result<bool, String> {
    let f = |t: f64| field.value(ray.at(t));
    let Some((t0, t1)) = field.zero_set_bounds().clip(ray, 0.0, o.t_max) else { return Ok(false) };
    let crossings = dense_crossings(&f, t0, t1, delta);
    let lambda = field.directional_lipschitz(ray.direction());
    check_first_crossing(&f, &crossings, hit, eps + lambda * o.tolerance, 2.0 * eps + lambda * o.min_step)?;
    Ok(true)
}

#[test]
fn temporal_coherence_finds_the_first_crossing_of_the_next_frame() {
    let set = random_set(30, 1.0, 0.8, 0.4, 11);
    let exact = TrochoidSum::new(&set);
    let o = options(0.0);
    let origin = DVec3::new(0.0, 5.0, 0.0);
    let mut hits = 0;
    for k in 0..60 {
        let d =
            DVec3::new((0.1 * f64::from(k)).cos(), -0.1 - 0.01 * f64::from(k), (0.1 * f64::from(k)).sin()).normalize();
        let ray = Ray::new(origin, d).unwrap();
        let previous = trace(&TracedTrochoids::new(&set, 0.0), &ray, &o, &mut TraceStats::default()).map(|h| h.t);
        let next = TracedTrochoids::new(&set, 0.04);
        let hit = trace_temporal(&next, &ray, previous, &o, &mut TraceStats::default());
        let field = exact.at_time(0.04);
        if !check_against_exact(&field, &ray, hit.map(|h| h.t), next.error_bound(), &o, 1.0 / 50.0).unwrap() {
            continue;
        }
        hits += usize::from(hit.is_some());
    }
    assert!(hits > 30, "only {hits} hits");
}
