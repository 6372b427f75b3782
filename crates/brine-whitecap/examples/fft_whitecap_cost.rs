//! `cargo xtask bench whitecap-fft`: the cost of the FFT ocean's whitecap statistics, side by side
//! in one process — building the mip pyramids (per frame), the footprint moments (per pixel) and
//! the calibration of `α` (per scene). Medians of repeated runs; all three are single-threaded.
//!
//! Sea: Elfouhaily at U10 = 10 m/s, fetch 100 km, 4 cascades (default tiles), choppiness 1.

use std::hint::black_box;

use brine_testkit::timing::median_seconds;
use brine_waves::{Directions, Elfouhaily, FftOcean, FftOptions};
use brine_whitecap::{CalibrationOptions, FftCalibration, FftJacobianStatistics};

fn main() {
    let elf = Elfouhaily::from_fetch(10.0, 1e5).expect("valid sea");
    let spreading = elf.spreading(Directions::Downwind);
    println!(
        "| N | pyramids (per frame) | moments, s = 0 | s = 0.1 m | s = 1 m | s = 10 m | calibration (16 384 points, 8 sizes) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for n in [256usize, 512] {
        let o = FftOptions { resolution: n, ..FftOptions::for_spectrum(&elf, 4) };
        let frame = FftOcean::new(&elf, &spreading, &o).expect("ocean").at_time(3.0);
        let build = median_seconds(7, || {
            black_box(FftJacobianStatistics::new(&frame));
        });
        let stats = FftJacobianStatistics::new(&frame);
        let points: Vec<(f64, f64)> = (0..4096).map(|i| (i as f64 * 0.731 - 500.0, i as f64 * -0.377 + 80.0)).collect();
        let per_call = |s: f64| {
            1e9 * median_seconds(9, || {
                for &(x, z) in &points {
                    black_box(stats.moments_at(x, z, s));
                }
            }) / points.len() as f64
        };
        let (m0, m1, m2, m3) = (per_call(0.0), per_call(0.1), per_call(1.0), per_call(10.0));
        let calibration = median_seconds(3, || {
            black_box(FftCalibration::new(&stats, 0.01, &CalibrationOptions::default()).expect("calibration"));
        });
        println!(
            "| {n}² | {:.1} ms | {m0:.0} ns | {m1:.0} ns | {m2:.0} ns | {m3:.0} ns | {:.0} ms |",
            1e3 * build,
            1e3 * calibration
        );
    }
}
