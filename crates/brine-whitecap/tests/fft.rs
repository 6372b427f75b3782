//! Whitecap statistics of an FFT ocean: the pyramids against direct block averages, the limits
//! of the footprint moments, their bounds on random points, and the calibration of `α` against
//! fresh samples.

use std::sync::OnceLock;

use brine_waves::{Directions, Elfouhaily, FftFrame, FftOcean, FftOptions};
use brine_whitecap::{CalibrationOptions, ErfMethod, FftCalibration, FftJacobianMeans, FftJacobianStatistics, Moments};
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A choppy 14 m/s sea (some folds), three 64² cascades.
fn frame() -> &'static (FftFrame, FftJacobianStatistics) {
    static FRAME: OnceLock<(FftFrame, FftJacobianStatistics)> = OnceLock::new();
    FRAME.get_or_init(|| {
        let elf = Elfouhaily::from_fetch(14.0, 1e5).unwrap();
        let d = elf.spreading(Directions::Downwind);
        let o = FftOptions { resolution: 64, choppiness: 2.0, ..FftOptions::for_spectrum(&elf, 3) };
        let frame = FftOcean::new(&elf, &d, &o).unwrap().at_time(3.0);
        let stats = FftJacobianStatistics::new(&frame);
        (frame, stats)
    })
}

/// Sums of up to 4096 `f32`-rounded values of order 1 in `f64`: 10⁻¹² relative.
const SUM_ROUNDING: f64 = 1e-12;

/// A variance that must be exactly 0 (a grid point read with no footprint), up to rounding.
const ZERO_VARIANCE: f64 = 1e-15;

/// The Eulerian (area-weighted) mean of `J` is not 1 on a choppy sea; on this gently choppy one
/// (choppiness 2, 14 m/s) it stays within 0.1 of 1.
const EULERIAN_MEAN_OFFSET: f64 = 0.1;

/// The table's last level against the Gaussian quantile `μ + σ√2 erf⁻¹(2W* − 1)`: it solves the
/// Gaussian law with Abramowitz & Stegun's erf (error ≤ 1.5×10⁻⁷ in `W`, so ≤ 1.5×10⁻⁷/φ(1.645)
/// ≈ 1.5×10⁻⁶ σ in `α`) by bisection; 10⁻⁶ in `α` bounds it for `σ` < 0.5.
const QUANTILE_TOL: f64 = 1e-6;

/// `√12`, the box width per Gaussian standard deviation.
const BOX: f64 = 3.464_101_615_137_754_6;

#[test]
fn pyramid_levels_are_block_means_of_k_and_k_squared() {
    let (frame, stats) = frame();
    let share = 1.0 / frame.cascade_count() as f64;
    for (c, cascade) in frame.cascades().iter().enumerate() {
        let n = cascade.resolution();
        let dx = cascade.spacing();
        let k = |i: usize, j: usize| f64::from(cascade.jacobians()[(j % n) * n + i % n]) - 1.0 + share;
        for l in 0..=n.trailing_zeros() as usize {
            let b = 1usize << l;
            for (bi, bj) in [(0usize, 0usize), (1, 3), (5, 2)] {
                if bi * b >= n || bj * b >= n {
                    continue;
                }
                let (mut m, mut m2) = (0.0, 0.0);
                for j in bj * b..(bj + 1) * b {
                    for i in bi * b..(bi + 1) * b {
                        m += k(i, j);
                        m2 += k(i, j) * k(i, j);
                    }
                }
                let area = (b * b) as f64;
                // The texel's centre, read at exactly level l (box width 2ˡΔ = √12 s).
                let (x, z) = (
                    (bi * b) as f64 * dx + 0.5 * (b as f64 - 1.0) * dx,
                    (bj * b) as f64 * dx + 0.5 * (b as f64 - 1.0) * dx,
                );
                let (gm, gm2) = stats.cascade_moments(c, x, z, b as f64 * dx / BOX);
                assert!(
                    (gm - m / area).abs() < SUM_ROUNDING && (gm2 - m2 / area).abs() < SUM_ROUNDING,
                    "cascade {c} level {l}"
                );
            }
        }
    }
}

#[test]
fn footprint_limits_are_the_point_jacobian_and_the_whole_sea() {
    let (frame, stats) = frame();
    // At a grid point of every cascade (the origin) with no footprint: μ = 1 + Σ(Jᵢ − 1), σ² = 0.
    let m = stats.moments_at(0.0, 0.0, 0.0);
    assert!((m.mu - frame.jacobian(0.0, 0.0)).abs() < SUM_ROUNDING && m.sigma2.abs() < ZERO_VARIANCE, "{m:?}");
    // Beyond the largest tile: the grid means and variances of every cascade.
    let (mut mu, mut var) = (1.0, 0.0);
    for c in frame.cascades() {
        let j: Vec<f64> = c.jacobians().iter().map(|&v| f64::from(v)).collect();
        let mean = j.iter().sum::<f64>() / j.len() as f64;
        mu += mean - 1.0;
        var += j.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / j.len() as f64;
    }
    let big = stats.moments_at(17.0, -3.0, 10.0 * stats.largest_tile());
    assert!((big.mu - mu).abs() < SUM_ROUNDING && (big.sigma2 - var).abs() < SUM_ROUNDING, "{big:?} vs ({mu}, {var})");
    let sea = stats.sea_moments();
    assert!((sea.mu - mu).abs() < SUM_ROUNDING && (sea.sigma2 - var).abs() < SUM_ROUNDING);
    assert!((mu - 1.0).abs() < EULERIAN_MEAN_OFFSET, "mean J = {mu}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// `σ² ≥ 0` and finite, `μ` within the cascades' bounds `1 + Σ(min Jᵢ − 1) … 1 + Σ(max Jᵢ − 1)`
    /// (a footprint mean is a convex combination), coverage in `[0, 1]`.
    #[test]
    fn moments_are_bounded_on_random_footprints(x in -500.0f64..500.0, z in -500.0f64..500.0, log_s in -4.0f64..4.0, alpha in -1.0f64..1.5) {
        let (frame, stats) = frame();
        let s = 10f64.powf(log_s);
        let m = stats.moments_at(x, z, s);
        let (mut lo, mut hi) = (1.0, 1.0);
        for c in frame.cascades() {
            let j = c.jacobians();
            lo += f64::from(j.iter().copied().fold(f32::INFINITY, f32::min)) - 1.0;
            hi += f64::from(j.iter().copied().fold(f32::NEG_INFINITY, f32::max)) - 1.0;
        }
        prop_assert!(m.sigma2 >= 0.0 && m.sigma2.is_finite());
        prop_assert!(m.mu >= lo - SUM_ROUNDING && m.mu <= hi + SUM_ROUNDING, "{} ∉ [{lo}, {hi}]", m.mu);
        let w = brine_whitecap::whitecap_coverage(m, alpha, ErfMethod::AbramowitzStegun);
        prop_assert!((0.0..=1.0).contains(&w));
    }
}

/// Standard errors allowed between the calibration sample and a fresh one.
const SIGMAS: f64 = 5.0;

#[test]
fn calibrated_coverage_holds_on_fresh_points_at_every_footprint() {
    let (_, stats) = frame();
    let target = 0.05;
    let samples = 32_768;
    let cal = FftCalibration::new(stats, target, &CalibrationOptions { samples: Some(samples), ..Default::default() })
        .unwrap();
    let fresh = 65_536;
    let mut rng = ChaCha8Rng::seed_from_u64(77);
    let tile = stats.largest_tile();
    let points: Vec<(f64, f64)> =
        (0..fresh).map(|_| (rng.random::<f64>() * tile, rng.random::<f64>() * tile)).collect();
    let table: Vec<(f64, f64)> = cal.table().collect();
    // The pointwise coverage is a Bernoulli mean; footprint coverages vary less. Both samples
    // err: σ = √(W(1 − W)(1/M + 1/M')).
    let sigma = (target * (1.0 - target) * (1.0 / samples as f64 + 1.0 / fresh as f64)).sqrt();
    for (s, alpha) in table.iter().step_by(2) {
        let mean: f64 = points
            .iter()
            .map(|&(x, z)| cal.coverage(stats.moments_at(x, z, *s), *s, ErfMethod::AbramowitzStegun))
            .sum::<f64>()
            / fresh as f64;
        assert!((mean - target).abs() < SIGMAS * sigma, "s = {s} m, α = {alpha}: coverage {mean} vs {target}");
    }
    // Beyond the largest tile: the Gaussian quantile of the whole sea.
    let sea: Moments = stats.sea_moments();
    let quantile = sea.mu + (2.0 * sea.sigma2).sqrt() * brine_whitecap::erf_inv(2.0 * target - 1.0);
    assert!(
        (cal.alpha_for_footprint(1e9) - quantile).abs() < QUANTILE_TOL,
        "{} vs {quantile}",
        cal.alpha_for_footprint(1e9)
    );
    // Degenerate targets.
    let none =
        FftCalibration::new(stats, 0.0, &CalibrationOptions { samples: Some(256), ..Default::default() }).unwrap();
    assert!(none.coverage(sea, 1.0, ErfMethod::Fast).abs() < ZERO_VARIANCE);
    assert!(FftCalibration::new(stats, 1.5, &CalibrationOptions::default()).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The history's means of `J` (one pyramid per cascade, half the memory) are the statistics'
    /// `μ` to the bit, at any point, footprint and breaking filter.
    #[test]
    fn jacobian_means_are_the_statistics_mean_to_the_bit(
        x in -500.0f64..500.0,
        z in -500.0f64..500.0,
        footprint in 0.0f64..50.0,
        breaking in 0.0f64..2.0,
    ) {
        let elf = Elfouhaily::from_fetch(14.0, 1e5).unwrap();
        let d = elf.spreading(Directions::Downwind);
        let o = FftOptions { resolution: 64, choppiness: 2.0, ..FftOptions::for_spectrum(&elf, 3) };
        let fields = FftOcean::new(&elf, &d, &o).unwrap().rest_jacobian_fields(1.5, breaking);
        let stats = FftJacobianStatistics::from_rest_jacobians(&fields, 2.0);
        let means = FftJacobianMeans::from_rest_jacobians(&fields, 2.0);
        let (mu, m) = (stats.moments_at(x, z, footprint).mu, means.mean_at(x, z, footprint));
        prop_assert_eq!(mu.to_bits(), m.to_bits(), "{} vs {}", mu, m);
    }
}
