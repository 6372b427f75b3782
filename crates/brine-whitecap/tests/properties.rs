//! Property tests: bounds and invariants on random inputs.

use brine_waves::{Trochoid, TrochoidSet};
use brine_whitecap::{
    ERF_AS_MAX_ERROR, ERF_FAST_MAX_ERROR, ErfMethod, FootprintFilter, JacobianStatistics, Moments,
    erf_abramowitz_stegun, erf_fast, erf_inv, whitecap_coverage,
};
use glam::DVec2;
use proptest::prelude::*;

/// Oddness of the erf approximations: `f(−x) = −f(x)` by construction (sign applied last), so
/// only a rounding of the magnitude can differ.
const ODD_ROUNDING: f64 = 1e-15;

/// `erf(erf⁻¹ y) − y` after Newton's method to ~10⁻¹⁵ relative in `x`, with `erf′` ≤ 1.13 and the
/// tails in `erfc`: a few ulps of `y`, plus `libm::erf`'s own error.
const INVERSE_ROUNDING: f64 = 1e-13;

/// `W` is monotone in `α` for every method; only the last ulp of `W ≤ 1` can step back.
const MONOTONE_ROUNDING: f64 = 1e-15;

/// Rounding of `J` and `μ` (sums of up to 30 products of order 1) against their bounds and
/// between two evaluation routes.
const JACOBIAN_ROUNDING: f64 = 1e-12;

/// A random trochoid set: 1–30 waves, steepnesses summing to at most 0.99 (no fold).
fn wave_set() -> impl Strategy<Value = TrochoidSet> {
    prop::collection::vec((0.01f64..5.0, -3.2f64..3.2, 0.0f64..6.3, 0.0f64..1.0), 1..30).prop_map(|raw| {
        let total: f64 = raw.iter().map(|w| w.3).sum::<f64>().max(1e-9);
        let scale = 0.99 / total.max(0.99);
        let waves = raw
            .into_iter()
            .map(|(k, dir, ph, q)| {
                let q = q * scale;
                Trochoid::new(q / k, k, dir, (9.81 * k).sqrt(), ph, q).unwrap()
            })
            .collect();
        TrochoidSet::new(waves)
    })
}

fn methods() -> [ErfMethod; 3] {
    [ErfMethod::Fast, ErfMethod::AbramowitzStegun, ErfMethod::Libm]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn erf_approximations_are_odd_bounded_and_within_their_error(x in -8.0f64..8.0) {
        for (f, bound) in [(erf_fast as fn(f64) -> f64, ERF_FAST_MAX_ERROR), (erf_abramowitz_stegun, ERF_AS_MAX_ERROR)] {
            let y = f(x);
            prop_assert!((-1.0..=1.0).contains(&y));
            prop_assert!((y + f(-x)).abs() < ODD_ROUNDING);
            prop_assert!((y - libm::erf(x)).abs() <= bound);
        }
    }

    #[test]
    fn erf_inverse_inverts(y in -0.999_999f64..0.999_999) {
        prop_assert!((libm::erf(erf_inv(y)) - y).abs() < INVERSE_ROUNDING);
    }

    #[test]
    fn coverage_is_a_fraction_and_monotone_in_alpha(
        mu in -2.0f64..4.0, sigma2 in 0.0f64..2.0, a1 in -3.0f64..5.0, da in 0.0f64..3.0,
    ) {
        let m = Moments { mu, sigma2 };
        for method in methods() {
            let w1 = whitecap_coverage(m, a1, method);
            let w2 = whitecap_coverage(m, a1 + da, method);
            prop_assert!((0.0..=1.0).contains(&w1) && (0.0..=1.0).contains(&w2));
            prop_assert!(w2 >= w1 - MONOTONE_ROUNDING, "{method:?}: W({a1}) = {w1} > W({}) = {w2}", a1 + da);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn jacobian_and_moments_stay_in_bounds(
        set in wave_set(), x in -500.0f64..500.0, z in -500.0f64..500.0, t in 0.0f64..100.0,
        s in prop_oneof![Just(0.0), 0.0f64..50.0, Just(1e7)],
    ) {
        let st = JacobianStatistics::new(&set).unwrap();
        let (lo, hi) = st.bounds();
        let u = DVec2::new(x, z);
        let j = st.jacobian_at(u, t);
        prop_assert!(j >= lo - JACOBIAN_ROUNDING && j <= hi + JACOBIAN_ROUNDING, "J = {j} outside [{lo}, {hi}]");
        prop_assert!((j - set.gerstner_jacobian(u, t)).abs() < JACOBIAN_ROUNDING);
        for filter in [FootprintFilter::Gaussian, FootprintFilter::Sharp] {
            let m = st.moments_at(u, t, s, filter);
            prop_assert!(m.mu.is_finite() && m.sigma2.is_finite() && m.sigma2 >= 0.0);
            prop_assert!(m.mu >= lo - JACOBIAN_ROUNDING && m.mu <= hi + JACOBIAN_ROUNDING);
        }
        // The cosine route agrees with the rest-position route.
        let cos: Vec<f64> = set
            .waves()
            .iter()
            .map(|w| (w.wavenumber() * w.direction_vector().dot(u) - w.omega() * t + w.phase()).cos())
            .collect();
        let a = st.moments_from_cosines(&cos, s, FootprintFilter::Gaussian);
        let b = st.moments_at(u, t, s, FootprintFilter::Gaussian);
        prop_assert!((a.mu - b.mu).abs() < JACOBIAN_ROUNDING && (a.sigma2 - b.sigma2).abs() < JACOBIAN_ROUNDING);
        prop_assert!((st.jacobian_from_cosines(&cos) - j).abs() < JACOBIAN_ROUNDING);
    }
}
