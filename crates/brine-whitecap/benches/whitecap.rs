//! Benchmarks of brine-whitecap: the three error functions side by side, the per-pixel footprint
//! moments, and the calibration of α.
//!
//! Run: `cargo xtask bench whitecap-erf` / `cargo xtask bench whitecap`.

use std::hint::black_box;

use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
use brine_whitecap::{
    Calibration, CalibrationOptions, FootprintFilter, JacobianStatistics, erf_abramowitz_stegun, erf_fast,
};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec2;

/// 1024 abscissae over [−4, 4], the range where W varies.
fn xs() -> Vec<f64> {
    (0..1024).map(|i| -4.0 + 8.0 * (i as f64 + 0.5) / 1024.0).collect()
}

fn erf(c: &mut Criterion) {
    let xs = xs();
    let mut g = c.benchmark_group("erf");
    g.throughput(Throughput::Elements(xs.len() as u64));
    g.bench_function("winitzki-0.147 (slides)", |b| {
        b.iter(|| black_box(&xs).iter().map(|&x| erf_fast(x)).sum::<f64>())
    });
    g.bench_function("abramowitz-stegun-7.1.26", |b| {
        b.iter(|| black_box(&xs).iter().map(|&x| erf_abramowitz_stegun(x)).sum::<f64>())
    });
    g.bench_function("libm::erf", |b| b.iter(|| black_box(&xs).iter().map(|&x| libm::erf(x)).sum::<f64>()));
    g.finish();
}

fn whitecap(c: &mut Criterion) {
    let mut g = c.benchmark_group("whitecap");
    for n in [50usize, 100] {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let set =
            fit_trochoids(&pm, &spreading, n, 1, &FitOptions { choppiness: 2.5, ..FitOptions::default() }).unwrap();
        let st = JacobianStatistics::new(&set).unwrap();
        for s in [0.0, 1.0, 20.0] {
            g.bench_function(format!("moments_at {n} waves, footprint {s} m"), |b| {
                b.iter(|| {
                    st.moments_at(black_box(DVec2::new(12.3, -4.5)), 0.0, black_box(s), FootprintFilter::Gaussian)
                })
            });
        }
        for s in [0.0, 1.0] {
            g.bench_function(format!("moments_at_f32 {n} waves, footprint {s} m"), |b| {
                b.iter(|| {
                    st.moments_at_f32(black_box(DVec2::new(12.3, -4.5)), 0.0, black_box(s), FootprintFilter::Gaussian)
                })
            });
        }
        g.bench_function(format!("moments_at {n} waves, footprint 1 m, sharp filter"), |b| {
            b.iter(|| st.moments_at(black_box(DVec2::new(12.3, -4.5)), 0.0, black_box(1.0), FootprintFilter::Sharp))
        });
        let cos: Vec<f64> = (0..n).map(|i| (0.37 * i as f64).cos()).collect();
        g.bench_function(format!("moments_from_cosines {n} waves, footprint 1 m"), |b| {
            b.iter(|| st.moments_from_cosines(black_box(&cos), black_box(1.0), FootprintFilter::Gaussian))
        });
        g.bench_function(format!("calibration {n} waves"), |b| {
            b.iter(|| Calibration::new(&st, black_box(9.87e-3), &CalibrationOptions::default()).unwrap())
        });
    }
    g.sample_size(10);
    g.finish();
}

criterion_group!(benches, erf, whitecap);
criterion_main!(benches);
