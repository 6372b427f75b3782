//! The tiered method's shortcuts near the surface (Newton probe on a provably decreasing stretch,
//! certified crossing interval, over-relaxed steps checked backward) never skip a crest: rays
//! that graze a long swell carrying short steep waves, whose crests poke through the ray just
//! before the swell's crossing, against a dense f64 reference; segment tracing on the same rays.

mod common;

use brine_trace::{LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace_logged};
use brine_waves::{TracedTrochoids, Trochoid, TrochoidSet, TrochoidSum};
use common::{check_first_crossing, check_steps, dense_crossings};
use glam::DVec3;

#[test]
fn shortcuts_never_skip_a_short_crest_before_the_swell_crossing() {
    use std::f64::consts::TAU;
    // A 40 m swell and two 1.5–2.5 m steep waves across it (Q = 0.7–0.8: thin crests).
    let waves = vec![
        Trochoid::new(1.2, TAU / 40.0, 0.0, 0.0, 0.3, 0.2).unwrap(),
        Trochoid::new(0.12, TAU / 2.5, 1.1, 0.0, 1.7, 0.8).unwrap(),
        Trochoid::new(0.07, TAU / 1.5, -0.7, 0.0, 4.1, 0.7).unwrap(),
    ];
    let set = TrochoidSet::new(waves);
    let exact = TrochoidSum::new(&set);
    let field = exact.at_time(0.0);
    let fast = TracedTrochoids::new(&set, 0.0);
    let eps = fast.error_bound();
    let options = TraceOptions {
        method: Method::Tiered,
        t_max: 80.0,
        max_steps: 1_000_000,
        min_step: 1e-4,
        min_step_relative: 0.0,
        tolerance: 1e-7,
        tolerance_relative: 0.0,
        ..TraceOptions::default()
    };
    let mut hits = 0;
    for i in 0..300 {
        let azimuth = 0.021 * f64::from(i);
        let dy = -0.02 - 0.13 * f64::from(i % 17) / 17.0;
        let h = (1.0 - dy * dy).sqrt();
        let ray = Ray::new(DVec3::new(0.0, 1.6, 0.0), DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin())).unwrap();
        let f = |t: f64| field.value(ray.at(t));
        let Some((t0, t1)) = field.zero_set_bounds().clip(&ray, 0.0, options.t_max) else { continue };
        // λ_min/100: far below the thinnest crest that can cross a ray deeper than the skim.
        let crossings = dense_crossings(&f, t0, t1, 1.5 / 100.0);
        let lambda = field.directional_lipschitz(ray.direction());
        // Segment tracing (certified by its local bound alone) on the same rays.
        for method in [Method::Tiered, Method::Segment] {
            let options = TraceOptions { method, ..options };
            let mut log = Vec::new();
            let hit = trace_logged(&fast, &ray, &options, &mut TraceStats::default(), &mut log);
            let skim = 2.0 * eps + lambda * options.min_step;
            check_first_crossing(&f, &crossings, hit.map(|h| h.t), eps + lambda * options.tolerance + 1e-12, skim)
                .unwrap_or_else(|e| {
                    let th = hit.unwrap().t;
                    for j in -4..=4 {
                        let x = th + f64::from(j) * 2e-5;
                        eprintln!("x {x} F {:e} F~ {:e}", f(x), fast.value(ray.at(x)));
                    }
                    panic!("{method:?}, ray {i}: {e} {:?} eps {eps:e}", &log[log.len().saturating_sub(4)..])
                });
            check_steps(&f, &log, &options, 2.0 * eps + 1e-12, true)
                .unwrap_or_else(|e| panic!("{method:?}, ray {i}: {e}"));
            if method == Method::Tiered {
                hits += usize::from(hit.is_some());
            }
        }
    }
    assert!(hits > 200, "only {hits} hits: the test needs rays that hit");
}
