//! Tests of the Jacobian statistics: f32 lanes and history against the f64 moments, limits.

use super::*;
use brine_waves::Trochoid;

/// f32 sums of ~100 terms of size ≤ 0.3, rotated up to 16 times: a few 10⁻⁶.
const HISTORY_F32: f64 = 2e-5;

/// The statistics of a 100-wave Pierson–Moskowitz set fitted at `u10` (m s⁻¹).
fn fitted(u10: f64) -> JacobianStatistics {
    use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
    let pm = PiersonMoskowitz::from_u10(u10).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    JacobianStatistics::new(&fit_trochoids(&pm, &spreading, 100, 4, &FitOptions::default()).unwrap()).unwrap()
}

#[test]
fn the_history_follows_the_moments_along_the_path() {
    let stats = fitted(14.0);
    let (u0, t0, dt, v) = (DVec2::new(3.0, -7.0), 12.0, 0.5, DVec2::new(0.4, 0.15));
    for s in [0.0, 0.3, 2.0] {
        let mut out = [0.0; 16];
        stats.mean_history(u0, t0, &stats.history_rotation(dt, v), s, FootprintFilter::Gaussian, &mut out);
        for (j, &mu) in out.iter().enumerate() {
            let a = dt * j as f64;
            let m = stats.moments_at(u0 - v * a, t0 - a, s, FootprintFilter::Gaussian);
            assert!((mu - m.mu).abs() < HISTORY_F32, "s {s}, j {j}: {mu} vs {}", m.mu);
        }
    }
}

#[test]
fn the_fused_history_matches_the_separate_calls() {
    let stats = fitted(16.0);
    let (dt, v) = (0.25, DVec2::new(0.45, 0.16));
    let rotation = stats.history_rotation(dt, v);
    for (u, t) in [(DVec2::new(3.0, -7.0), 12.07), (DVec2::new(-812.5, 1203.25), 3599.9)] {
        let t0 = (t / dt).floor() * dt;
        let a0 = t - t0;
        let offset = stats.history_rotation(a0, v);
        for s in [0.0, 0.3, 2.0] {
            let (mut fused, mut apart) = ([0.0; 24], [0.0; 24]);
            let start = HistoryStart { offset: &offset, rotation: &rotation };
            let m = stats.moments_and_history_f32(u, t, s, FootprintFilter::Gaussian, &start, &mut fused);
            let m0 = stats.moments_at_f32(u, t, s, FootprintFilter::Gaussian);
            stats.mean_history(u - v * a0, t0, &rotation, s, FootprintFilter::Gaussian, &mut apart);
            // The present is the same arithmetic (the cosine of `sin_cos` against `cos`).
            assert!((m.mu - m0.mu).abs() < F32_MOMENTS_ERROR && (m.sigma2 - m0.sigma2).abs() < F32_MOMENTS_ERROR);
            for j in 0..24 {
                // One more f32 rotation than the separate route: within the history's own bound.
                assert!((fused[j] - apart[j]).abs() < HISTORY_F32, "s {s}, j {j}: {} vs {}", fused[j], apart[j]);
            }
        }
    }
}

/// Two routes to `J` (sorted accumulation here, set order in brine-waves) on values of order 1,
/// at positions up to 65 m: phases up to ~100 rad lose ~10⁻¹⁴ each.
const ROUTES: f64 = 1e-13;

/// Rounding of a few flops on values of order 1.
const ROUNDING: f64 = 1e-14;

/// Exactly the closed form (same sums, a different order): one or two ulps.
const ULPS: f64 = 1e-15;

fn two_waves() -> TrochoidSet {
    TrochoidSet::new(vec![
        Trochoid::new(0.3, 0.5, 0.2, 0.0, 0.1, 0.3).unwrap(),
        Trochoid::new(0.1, 2.0, 1.3, 0.0, 2.0, 0.4).unwrap(),
    ])
}

#[test]
fn jacobian_matches_brine_waves() {
    let set = two_waves();
    let st = JacobianStatistics::new(&set).unwrap();
    for i in 0..50 {
        let u = DVec2::new(i as f64 * 0.77, -(i as f64) * 1.3);
        assert!((st.jacobian_at(u, 0.3) - set.gerstner_jacobian(u, 0.3)).abs() < ROUTES);
    }
}

#[test]
fn footprint_limits() {
    let set = two_waves();
    let st = JacobianStatistics::new(&set).unwrap();
    let u = DVec2::new(3.0, 1.0);
    for filter in [FootprintFilter::Gaussian, FootprintFilter::Sharp] {
        let m0 = st.moments_at(u, 0.0, 0.0, filter);
        assert!((m0.mu - set.gerstner_jacobian(u, 0.0)).abs() < ROUNDING && m0.sigma2.abs() < ULPS);
        let m_inf = st.moments_at(u, 0.0, 1e6, filter);
        assert!((m_inf.mu - 1.0).abs() < ULPS && (m_inf.sigma2 - st.variance()).abs() < ULPS);
    }
    // Closed form for two waves: ½(a₁² + a₂²) + ¼ a₁²a₂² sin⁴(Δθ).
    let expected = 0.5 * (0.09 + 0.16) + 0.25 * 0.09 * 0.16 * (1.1f64).sin().powi(4);
    assert!((st.variance() - expected).abs() < ULPS);
}

/// The precondition `Σ Qᵢ ≤ 1` of [`F32_MOMENTS_ERROR`], up to the rounding of a sum of 100
/// steepnesses (the fit caps the sum at 0.9 by default, so it holds with room).
const STEEPNESS_SUM_ROUNDING: f64 = 1e-12;

/// The f32 route against the f64 one on the fitted sea of `simd_moments_match_the_scalar_ones`.
#[test]
fn f32_moments_match_the_f64_ones() {
    use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let set = fit_trochoids(&pm, &spreading, 100, 4, &FitOptions { choppiness: 2.5, ..FitOptions::default() }).unwrap();
    let st = JacobianStatistics::new(&set).unwrap();
    assert!(st.total_steepness() <= 1.0 + STEEPNESS_SUM_ROUNDING);
    let mut worst = 0.0f64;
    for i in 0..300 {
        let u = DVec2::new(i as f64 * 37.1 - 3000.0, 1200.0 - i as f64 * 11.3);
        for s in [0.0, 0.003, 0.05, 0.7, 4.0] {
            for filter in [FootprintFilter::Gaussian, FootprintFilter::Sharp] {
                let (a, b) = (st.moments_at_f32(u, 1.7, s, filter), st.moments_at(u, 1.7, s, filter));
                worst = worst.max((a.mu - b.mu).abs()).max((a.sigma2 - b.sigma2).abs());
            }
        }
    }
    eprintln!("largest f32 − f64 difference: {worst:.2e}");
    assert!(worst < F32_MOMENTS_ERROR, "{worst:e}");
    assert!(worst > 0.0, "the routes differ in rounding");
}

/// The SIMD cosines and gains of `moments_at` against `f64::cos` and `f64::exp` wave by wave,
/// on a fitted many-wave sea at phases up to 10⁵ rad (points kilometres away).
#[test]
fn simd_moments_match_the_scalar_ones() {
    // Phase reduction and polynomial of the VCL sin/cos: a few ulps of phases ≤ 10⁵ rad
    // (≈ 10⁻¹¹ absolute), times Σ Qᵢ ≤ 1 in μ and σ².
    const SIMD_TRIG: f64 = 1e-9;
    use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let set = fit_trochoids(&pm, &spreading, 53, 4, &FitOptions { choppiness: 2.5, ..FitOptions::default() }).unwrap();
    let st = JacobianStatistics::new(&set).unwrap();
    for i in 0..200 {
        let u = DVec2::new(i as f64 * 37.1 - 3000.0, 1200.0 - i as f64 * 11.3);
        for s in [0.0, 0.05, 0.7, 4.0] {
            for filter in [FootprintFilter::Gaussian, FootprintFilter::Sharp] {
                let (a, b) = (st.moments_at(u, 1.7, s, filter), st.moments_at_scalar(u, 1.7, s, filter));
                assert!((a.mu - b.mu).abs() < SIMD_TRIG && (a.sigma2 - b.sigma2).abs() < SIMD_TRIG, "{a:?} vs {b:?}");
            }
        }
    }
}

#[test]
fn empty_set_is_an_error() {
    assert_eq!(JacobianStatistics::new(&TrochoidSet::default()).unwrap_err(), WhitecapError::EmptySet);
}
