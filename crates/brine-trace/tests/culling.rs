//! Slab culling: rays that miss the slab `|y| ≤ Σ Aᵢ` holding the sea cost no evaluation, for
//! every method, and rays that enter it start at its entry, so a camera 100 km up pays what a
//! camera 1 km up pays along the same line.

mod common;

use std::f64::consts::TAU;

use brine_trace::{Method, Ray, TraceOptions, TraceStats, trace};
use brine_waves::TracedTrochoids;
use common::random_set;
use glam::DVec3;
use proptest::prelude::*;

/// Options without any distance-relative term (minimum step, tolerance) and without footprint
/// fading, so that the trace from the slab entry does not depend on how far the camera is; the
/// interval reaches beyond 100 km.
fn options(method: Method) -> TraceOptions {
    TraceOptions {
        method,
        t_max: 1e7,
        max_steps: 2_000_000,
        min_step: 1e-3,
        min_step_relative: 0.0,
        tolerance: 1e-5,
        tolerance_relative: 0.0,
        ..TraceOptions::default()
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Above the slab, looking up or level (or below it, looking down or level): no evaluation,
    /// the ray is counted as culled, for every method.
    #[test]
    fn rays_that_miss_the_slab_cost_nothing(
        n in 1usize..100,
        seed in 0u64..10_000,
        above in 1e-6f64..1e4,
        dy in prop_oneof![Just(0.0), 1e-9f64..1.0],
        azimuth in 0.0f64..TAU,
        x in -1e3f64..1e3,
        z in -1e3f64..1e3,
        below in any::<bool>(),
    ) {
        let set = random_set(n, 0.5, 0.9, 0.4, seed);
        let sea = TracedTrochoids::new(&set, 0.0);
        let top = set.total_amplitude();
        let sign = if below { -1.0 } else { 1.0 };
        let h = (1.0 - dy * dy).sqrt();
        let ray = Ray::new(
            DVec3::new(x, sign * (top + above), z),
            DVec3::new(h * azimuth.cos(), sign * dy, h * azimuth.sin()),
        )
        .unwrap();
        for method in Method::ALL {
            for footprint_angle in [0.0, 2e-3] {
                let mut stats = TraceStats::default();
                let hit = trace(&sea, &ray, &TraceOptions { footprint_angle, ..options(method) }, &mut stats);
                prop_assert!(hit.is_none(), "{method:?}");
                prop_assert_eq!(stats.evaluations, 0, "{:?}", method);
                prop_assert_eq!(stats.component_evaluations, 0, "{:?}", method);
                prop_assert_eq!((stats.rays, stats.culled), (1, 1), "{:?}", method);
            }
        }
    }
}

/// Hits of the same line traced from 1 km and from 100 km differ by f64 rounding of the far
/// origin (10⁵ m × 10⁻¹⁶) plus the refinement tolerance.
const SAME_HIT: f64 = 2e-5;

/// Along one line, a camera at 1 km and one at 100 km above the sea spend the same evaluations
/// up to the bracket of the hit, for every method: the trace starts at the slab entry, not at
/// the camera.
#[test]
fn rays_entering_the_slab_start_at_its_entry() {
    let set = random_set(60, 0.5, 0.6, 0.4, 17);
    let sea = TracedTrochoids::new(&set, 0.0);
    let mut checked = 0;
    for i in 0..24 {
        let azimuth = 0.37 * f64::from(i);
        // From 2.6° off the vertical to 6° below the horizon. (Exactly vertical, the waves are
        // constant along the ray and the bounds exact: a certified step lands on F = 0 ± 10⁻¹⁵, and
        // the rounding of the far origin decides whether one probe follows.)
        let dy = -(0.999 - 0.04 * f64::from(i)).max(0.1);
        let h = (1.0 - dy * dy).sqrt();
        let d = DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin());
        let target = DVec3::new(13.0 * f64::from(i), 0.0, -7.0 * f64::from(i));
        let (near, far) = (1e3, 1e5);
        let ray_near = Ray::new(target - d * (near / -dy), d).unwrap();
        let ray_far = Ray::new(target - d * (far / -dy), d).unwrap();
        for method in Method::ALL {
            let (mut s_near, mut s_far) = (TraceStats::default(), TraceStats::default());
            let hit_near = trace(&sea, &ray_near, &options(method), &mut s_near);
            let hit_far = trace(&sea, &ray_far, &options(method), &mut s_far);
            let (a, b) = (hit_near.expect("the near camera hits"), hit_far.expect("the far camera hits"));
            assert!((a.point - b.point).length() <= SAME_HIT, "{method:?}, ray {i}: {:?} vs {:?}", a.point, b.point);
            // The approach (every point before the bracket) is the same. The refinement of the
            // bracket is not compared point for point: inside it the f32 surface's rounding noise
            // (10⁻⁷ m) steers the Illinois iteration, and the 10⁻¹¹ m shift of the far entry
            // point changes that noise (measured: up to 6 refinement points apart, same hit).
            let approach = |s: &TraceStats| s.evaluations - s.refinement_evaluations;
            assert_eq!(approach(&s_near), approach(&s_far), "{method:?}, ray {i}: approach from 1 km and 100 km");
            assert!(s_near.evaluations > 0);
            checked += 1;
        }
    }
    assert_eq!(checked, 24 * Method::ALL.len());
}
