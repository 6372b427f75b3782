//! Whitecap statistics of an FFT ocean: the pyramids against direct block averages, the limits
//! of the footprint moments, their bounds on random points, and the calibration of `α` against
//! fresh samples.

use std::sync::OnceLock;

use brine_waves::{Directions, Elfouhaily, FftFrame, FftOcean, FftOptions};
use brine_whitecap::{
    CalibrationOptions, ErfMethod, FftCalibration, FftInstantJacobian, FftJacobianHistory, FftJacobianStatistics,
    Moments,
};
use glam::DVec2;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A choppy 14 m/s sea (some folds), three 64² cascades, tiled: each cascade its periodic tile,
/// whose pyramids these tests check (the blend of an untiled sea: `blended_*` below).
fn frame() -> &'static (FftFrame, FftJacobianStatistics) {
    static FRAME: OnceLock<(FftFrame, FftJacobianStatistics)> = OnceLock::new();
    FRAME.get_or_init(|| {
        let elf = Elfouhaily::from_fetch(14.0, 1e5).unwrap();
        let d = elf.spreading(Directions::Downwind);
        let o = FftOptions { resolution: 64, choppiness: 2.0, tiled: true, ..FftOptions::for_spectrum(&elf, 3) };
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

/// `Σ_c (⟨J_c⟩ − 1)` and `Σ_c Var(J_c)` over the cascades' Jacobian grids.
fn grid_offset_and_variance(frame: &FftFrame) -> (f64, f64) {
    let (mut offset, mut var) = (0.0, 0.0);
    for c in frame.cascades() {
        let j: Vec<f64> = c.jacobians().iter().map(|&v| f64::from(v)).collect();
        let mean = j.iter().sum::<f64>() / j.len() as f64;
        offset += mean - 1.0;
        var += j.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / j.len() as f64;
    }
    (offset, var)
}

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
    let (offset, var) = grid_offset_and_variance(frame);
    let mu = 1.0 + offset;
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

    /// Without drift the history's means are the statistics' `μ` of each instant's own grids, at
    /// any point, footprint and breaking filter, but for the history's f32 storage.
    #[test]
    fn the_history_is_each_instants_mean(
        x in -500.0f64..500.0,
        z in -500.0f64..500.0,
        footprint in 0.0f64..50.0,
        breaking in 0.0f64..2.0,
    ) {
        let ocean = history_ocean();
        let (t0, step) = (1.5, 0.25);
        let instants: Vec<FftInstantJacobian> =
            (0..4).map(|j| FftInstantJacobian::new(ocean, t0 - f64::from(j) * step, breaking, DVec2::ZERO)).collect();
        let history = FftJacobianHistory::new(&instants);
        let mut out = [0.0; 5];
        history.mean_history(DVec2::new(x, z), t0, step, DVec2::ZERO, footprint, &mut out);
        for (j, &got) in out.iter().enumerate().take(4) {
            let fields = ocean.rest_jacobian_fields(t0 - j as f64 * step, breaking);
            let mu = FftJacobianStatistics::from_rest_jacobians(&fields, 2.0).moments_at(x, z, footprint).mu;
            prop_assert!((got - mu).abs() < HISTORY_F32, "instant {}: {} vs {}", j, got, mu);
        }
        // An instant not held: no breaking.
        prop_assert_eq!(out[4].to_bits(), 1f64.to_bits());
    }
}

/// The history stores `kᵢ` in f32 (`|kᵢ| ≲ 3` here: `3 · 2⁻²⁴ ≈ 2×10⁻⁷` each) and sums its 7
/// levels in f32 (about one rounding of the value per level), over 3 cascades: ≈ 4×10⁻⁶; 10⁻⁵.
const HISTORY_F32: f64 = 1e-5;

/// The sea of the history tests: the 14 m/s sea of [`frame`], three 64² cascades, choppiness 2,
/// tiled (the blended sea: [`blended_ocean`]).
fn history_ocean() -> &'static FftOcean {
    static OCEAN: OnceLock<FftOcean> = OnceLock::new();
    OCEAN.get_or_init(|| {
        let elf = Elfouhaily::from_fetch(14.0, 1e5).unwrap();
        let d = elf.spreading(Directions::Downwind);
        let o = FftOptions { resolution: 64, choppiness: 2.0, tiled: true, ..FftOptions::for_spectrum(&elf, 3) };
        FftOcean::new(&elf, &d, &o).unwrap()
    })
}

/// The same sea untiled: each cascade read through its blend (brine-waves `TileBlend`).
fn blended_ocean() -> &'static FftOcean {
    static OCEAN: OnceLock<FftOcean> = OnceLock::new();
    OCEAN.get_or_init(|| {
        let elf = Elfouhaily::from_fetch(14.0, 1e5).unwrap();
        let d = elf.spreading(Directions::Downwind);
        let o = FftOptions { resolution: 64, choppiness: 2.0, ..FftOptions::for_spectrum(&elf, 3) };
        FftOcean::new(&elf, &d, &o).unwrap()
    })
}

/// A blended sea's statistics read its blend: with no footprint `μ` is the blended Jacobian the
/// frame gives at the point; beyond the largest tile each cascade's variance is its tile's
/// (`Σ ŵ² = 1`), and `μ − 1` is `Σ_c Σ ŵ (⟨J_c⟩ − 1)`, between once and twice the tiles' `Σ (⟨J_c⟩ − 1)`
/// (`1 ≤ Σ ŵ ≤ 2`, and every cascade's mean has the same sign here).
#[test]
fn blended_statistics_read_the_blend() {
    let frame = blended_ocean().at_time(3.0);
    assert!(frame.cascades().iter().all(|c| c.blended()));
    let stats = FftJacobianStatistics::new(&frame);
    for i in 0..50 {
        let (x, z) = (i as f64 * 7.31 - 160.0, i as f64 * -3.9 + 55.0);
        let m = stats.moments_at(x, z, 0.0);
        assert!((m.mu - frame.jacobian(x, z)).abs() < SUM_ROUNDING, "({x}, {z}): {} vs {}", m.mu, frame.jacobian(x, z));
    }
    let (offset, var) = grid_offset_and_variance(&frame);
    for (x, z) in [(17.0, -3.0), (-901.0, 433.0), (5.5, 5.5)] {
        let big = stats.moments_at(x, z, 10.0 * stats.largest_tile());
        assert!((big.sigma2 - var).abs() < SUM_ROUNDING * 10.0, "{big:?} vs variance {var}");
        let got = big.mu - 1.0;
        let (lo, hi) = if offset >= 0.0 { (offset, 2.0 * offset) } else { (2.0 * offset, offset) };
        assert!(got >= lo - SUM_ROUNDING && got <= hi + SUM_ROUNDING, "μ − 1 = {got}, tiles' {offset}");
    }
}

/// The drift history of the tests below: six instants `Δt = 0.25 s` apart from `t₀ = 7.25 s`,
/// breaking footprint 0.8 m, drift `(0.41, −0.17)` m/s.
const DRIFT_CASE: (f64, f64, f64, DVec2) = (7.25, 0.25, 0.8, DVec2::new(0.41, -0.17));

/// Reads `ocean`'s drift history ([`DRIFT_CASE`]) at three points and footprints and checks each
/// instant `j` against `expected(j, tⱼ, uⱼ, y = uⱼ − v tⱼ, footprint)`. Returns the history
/// and, per point, its means.
fn check_drift_history(
    ocean: &FftOcean,
    expected: impl Fn(f64, DVec2, DVec2, f64) -> f64,
) -> (FftJacobianHistory, Vec<(DVec2, f64, [f64; 6])>) {
    let (t0, step, breaking, drift) = DRIFT_CASE;
    let instants: Vec<FftInstantJacobian> =
        (0..6).map(|j| FftInstantJacobian::new(ocean, t0 - f64::from(j) * step, breaking, drift)).collect();
    let history = FftJacobianHistory::new(&instants);
    let mut read = Vec::new();
    for (x, z, footprint) in [(0.3, 1.7, 0.0), (-41.2, 77.7, 0.7), (250.0, -13.3, 6.0)] {
        let u0 = DVec2::new(x, z);
        let mut out = [0.0; 6];
        history.mean_history(u0, t0, step, drift, footprint, &mut out);
        for (j, &got) in out.iter().enumerate() {
            let tj = t0 - j as f64 * step;
            let uj = u0 - drift * (j as f64 * step);
            let mu = expected(tj, uj, uj - drift * tj, footprint);
            assert!((got - mu).abs() < HISTORY_F32, "({x}, {z}) instant {j}: {got} vs {mu}");
        }
        read.push((u0, footprint, out));
    }
    (history, read)
}

/// A blended sea's history, with the foam's drift, reads at each instant the blend of that
/// instant's rest position `uⱼ = u₀ − v jΔt`: `μⱼ = 1 + Σ_c Σ_k ŵ_k(uⱼ)(⟨k_c⟩(y + o_k) − 1/n)`,
/// `y = uⱼ − v tⱼ` on the instant's grid moved by `−v tⱼ`, read here corner by corner from the
/// moved grids' own (unblended) statistics, but for the history's f32 storage.
#[test]
fn the_blended_history_reads_each_instant_where_the_foam_was() {
    let ocean = blended_ocean();
    let (_, _, breaking, drift) = DRIFT_CASE;
    check_drift_history(ocean, |tj, uj, y, footprint| {
        let mut moved = ocean.rest_jacobian_fields_shifted(tj, breaking, (drift * tj).to_array());
        let blends: Vec<_> = moved.iter_mut().map(|f| f.blend.take().expect("an untiled sea blends")).collect();
        let tiles = FftJacobianStatistics::from_rest_jacobians(&moved, 2.0);
        let share = 1.0 / moved.len() as f64;
        let mut mu = 1.0;
        for (c, b) in blends.iter().enumerate() {
            for k in b.corners(uj.x, uj.y) {
                let (m, _) = tiles.cascade_moments(c, y.x + k.offset[0], y.y + k.offset[1], footprint);
                mu += k.weight * (m - share);
            }
        }
        mu
    });
}

/// With the foam's drift, instant `j` is read where the foam now at `u₀` was, `uⱼ = u₀ − v jΔt`:
/// on the instant's grid moved by `−v tⱼ` (whose values brine-waves checks against the direct
/// trig sums at the moved points), that is the point `uⱼ − v tⱼ = u₀ − v t₀` for every `j`. The
/// history matches each instant's statistics built on its own moved grid and read there (the
/// f64 pyramid of `(k, k²)`), at several footprints, but for its f32 storage.
#[test]
fn the_history_follows_the_drift() {
    let ocean = history_ocean();
    let (t0, step, breaking, drift) = DRIFT_CASE;
    let (history, read) = check_drift_history(ocean, |tj, _, y, footprint| {
        let moved = ocean.rest_jacobian_fields_shifted(tj, breaking, (drift * tj).to_array());
        FftJacobianStatistics::from_rest_jacobians(&moved, 2.0).moments_at(y.x, y.y, footprint).mu
    });
    for (u0, footprint, out) in read {
        // Asked on another lattice (half the step) it reads instant by instant: the held
        // instants agree with the fast path, the others have no breaking.
        let mut half = [0.0; 6];
        history.mean_history(u0, t0, 0.5 * step, drift, footprint, &mut half);
        for (j, &h) in half.iter().enumerate() {
            let want = if j % 2 == 0 { out[j / 2] } else { 1.0 };
            assert!((h - want).abs() < 1e-12, "half step, instant {j}: {h} vs {want}");
        }
    }
}
