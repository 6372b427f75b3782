//! One point × N waves: the scalar wave loop against four waves per SIMD lane group, for the
//! trochoid sum, the sine set and the Gerstner inversion.
//!
//! Run with `cargo xtask bench waves` (or `cargo bench -p brine-waves --bench surface_eval`).

use std::hint::black_box;
use std::time::Duration;

use brine_waves::{
    CosineTwoS, FitOptions, GerstnerSurface, PiersonMoskowitz, SineSet, Spectrum, TrochoidSum, fit_trochoids,
};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_group, criterion_main};

/// Wave counts of the paper's tables (30–50) and the mission's 100–200.
const COUNTS: [usize; 4] = [30, 50, 100, 200];

/// Eight evaluation points spread over 100 m, cycled so the work is not constant-folded.
const POINTS: [(f64, f64); 8] =
    [(0.0, 0.0), (13.1, -7.2), (-41.5, 22.0), (77.7, 3.3), (-5.5, -60.2), (30.0, 30.0), (-90.1, 11.9), (55.4, -48.8)];

fn set(n: usize) -> brine_waves::TrochoidSet {
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    fit_trochoids(&pm, &d, n, 7, &FitOptions::default()).unwrap()
}

/// Benchmarks `height(x, z)` at the cycled points as `group/variant/n`.
fn bench_height(g: &mut BenchmarkGroup<'_, WallTime>, variant: &str, n: usize, height: impl Fn(f64, f64) -> f64) {
    let mut i = 0;
    g.bench_with_input(BenchmarkId::new(variant, n), &n, |b, _| {
        b.iter(|| {
            i = (i + 1) % POINTS.len();
            let (x, z) = black_box(POINTS[i]);
            height(x, z)
        })
    });
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("trochoid_height");
    for n in COUNTS {
        let sum = TrochoidSum::new(&set(n));
        let f = sum.at_time(1.0);
        bench_height(&mut g, "scalar", n, |x, z| f.height(x, z));
        bench_height(&mut g, "lanes", n, |x, z| f.height_lanes(x, z));
    }
    g.finish();

    let mut g = c.benchmark_group("sine_height");
    for n in COUNTS {
        let sine = SineSet::new(&set(n));
        let f = sine.at_time(1.0);
        bench_height(&mut g, "scalar", n, |x, z| f.height(x, z));
        bench_height(&mut g, "lanes", n, |x, z| f.height_lanes(x, z));
    }
    g.finish();

    let mut g = c.benchmark_group("gerstner_height");
    for n in COUNTS {
        let gerstner = GerstnerSurface::new(&set(n)).unwrap();
        let f = gerstner.at_time(1.0);
        bench_height(&mut g, "scalar", n, |x, z| f.height(x, z));
        bench_height(&mut g, "lanes", n, |x, z| f.height_lanes(x, z));
    }
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(40)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! { name = benches; config = config(); targets = bench }
criterion_main!(benches);
