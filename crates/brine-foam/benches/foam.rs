//! Benchmarks of brine-foam's per-pixel calls: foam amount, foam history, spray segment.
//!
//! Run: `cargo xtask bench foam`.

use std::hint::black_box;

use brine_foam::{
    FoamExtension, FoamExtensionParams, FoamHistory, FoamHistoryParams, FoamPoint, KoepkeFoam, SprayLighting,
    SprayMedium, SprayParams, SprayRay, SprayScattering, SurfaceStatistics,
};
use criterion::{Criterion, criterion_group, criterion_main};

fn foam(c: &mut Criterion) {
    let surface =
        SurfaceStatistics { y_min: -2.0, y_max: 2.0, height_std: 0.55, slope_variance_x: 0.03, slope_variance_z: 0.02 };
    let ext = FoamExtension::new(&FoamExtensionParams::default(), &surface).unwrap();
    let history = FoamHistory::new(&FoamHistoryParams::default(), &KoepkeFoam::default()).unwrap();
    let medium = SprayMedium::new(&SprayParams::default()).unwrap();
    let mut g = c.benchmark_group("foam");
    g.bench_function("foam_amount, noise on, near pixel", |b| {
        b.iter(|| {
            ext.foam_amount(
                0.01,
                &black_box(FoamPoint { height: 1.1, slope: [0.2, -0.1], rest: [13.7, 4.2], footprint_m: 0.05 }),
            )
        })
    });
    g.bench_function("foam_amount, noise filtered out", |b| {
        b.iter(|| {
            ext.foam_amount(
                0.01,
                &black_box(FoamPoint { height: 1.1, slope: [0.2, -0.1], rest: [13.7, 4.2], footprint_m: 500.0 }),
            )
        })
    });
    g.bench_function("history accumulate (17 instants, trivial source)", |b| {
        b.iter(|| history.accumulate(black_box(123.4), |s| 0.01 * (1.0 + (0.3 * s.time_s).sin())))
    });
    g.bench_function("SprayMedium::new (512-panel integral)", |b| {
        b.iter(|| SprayMedium::new(black_box(&SprayParams::default())))
    });
    g.bench_function("spray ray, 32 segments", |b| {
        let light =
            SprayLighting { sun_irradiance: 80.0, sin_sun_elevation: 0.4, cos_view_sun: 0.3, sky_radiance: 5.0 };
        b.iter(|| {
            let mut ray = SprayRay::new(&medium, &SprayScattering::default(), &light);
            for i in 0..32 {
                let z = 10.0 - 0.3 * i as f64;
                ray.step(z, z - 0.3, 20.0, black_box(1.2));
            }
            ray.radiance(3.0)
        })
    });
    g.finish();
}

criterion_group!(benches, foam);
criterion_main!(benches);
