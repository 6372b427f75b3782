//! `FoamHistory` in time: foam created at a rest position `x₀` at an instant `t₀` drifts to
//! `x₀ + v (t − t₀)` and is aged `t − t₀`; its area decays as `e^{−a/τ}` and its reflectance as
//! `e^{−a/τ_R}` with the life-mean reflectance of Koepke (1984); the result is deterministic.
//!
//! Expected values come from the documented kernel
//! `K(a) = min(a/Δt, 1) min((T − a)/Δt, 1) e^{−a/τ}`, re-derived here, not from the crate.

use brine_foam::{FoamHistory, FoamHistoryParams, FoamSample, FoamState, KOEPKE_EFFICIENCY, KoepkeFoam};
use proptest::prelude::*;

/// Radius (m) of the spot of foam created at `x₀`: the source is 1 within it, 0 outside.
const SPOT_RADIUS_M: f64 = 0.05;

/// Rounding of a lattice age `t − tⱼ` and of a normalised sum of 17 weighted terms of order 1.
const SUM_ROUNDING: f64 = 1e-12;

/// The constructor solves `τ_R` on a 64-phase midpoint average of the lattice sum, a periodic
/// function of the phase whose slope jumps (by ~0.3 relative) where instants enter and leave: the
/// midpoint error is about `(1/64)²/24 × 0.3` ≈ 3×10⁻⁶ of `f_ef`. Three times that.
const PHASE_AVERAGE_REL: f64 = 1e-5;

/// "No foam": the history returns exactly 0 where no instant it reads has foam.
const NO_FOAM: f64 = f64::MIN_POSITIVE;

/// Matching a lattice instant (s): instants are exact multiples of `Δt`, far apart.
const LATTICE_MATCH_S: f64 = 1e-9;

/// The documented defaults: `τ` = 4 s, `Δt` = 1 s, `T` = 4τ = 16 s, 17 instants.
const TAU_S: f64 = 4.0;
const STEP_S: f64 = 1.0;
const LENGTH_S: f64 = 16.0;

/// A wind drift of the foam relative to the water (m/s): ~3 % of a 10 m/s wind, at an angle.
const DRIFT: [f64; 2] = [0.3, -0.2];

fn history(drift_m_s: [f64; 2]) -> FoamHistory {
    FoamHistory::new(&FoamHistoryParams { drift_m_s, ..FoamHistoryParams::default() }, &KoepkeFoam::default()).unwrap()
}

/// The kernel, re-derived from its documentation.
fn kernel(a: f64) -> f64 {
    if !(0.0..=LENGTH_S).contains(&a) {
        return 0.0;
    }
    (a / STEP_S).min(1.0) * ((LENGTH_S - a) / STEP_S).min(1.0) * (-a / TAU_S).exp()
}

/// `Σⱼ K(t − tⱼ)` over the 17 lattice instants `tⱼ = Δt(⌊t/Δt⌋ − j)` read at `t`.
fn kernel_sum(t: f64) -> f64 {
    let newest = (t / STEP_S).floor();
    (0..17).map(|j| kernel(t - (newest - j as f64) * STEP_S)).sum()
}

/// Foam created only at the instant `t0` (on the lattice), in a spot of radius
/// [`SPOT_RADIUS_M`] around the rest position `x0`; the query is the particle at rest position `u`.
fn burst(u: [f64; 2], x0: [f64; 2], t0: f64) -> impl Fn(&FoamSample) -> f64 {
    move |s: &FoamSample| {
        let at = [u[0] + s.rest_offset_m[0], u[1] + s.rest_offset_m[1]];
        let near = (at[0] - x0[0]).hypot(at[1] - x0[1]) < SPOT_RADIUS_M;
        if (s.time_s - t0).abs() < LATTICE_MATCH_S && near { 1.0 } else { 0.0 }
    }
}

/// Where the drift has taken foam created at `x0` after `age` seconds.
fn drifted(x0: [f64; 2], drift: [f64; 2], age: f64) -> [f64; 2] {
    [x0[0] + drift[0] * age, x0[1] + drift[1] * age]
}

#[test]
fn foam_drifts_with_the_wind_and_ages() {
    let h = history(DRIFT);
    assert_eq!(h.sample_count(), 17);
    let (x0, t0) = ([12.5, -7.25], 10.0);
    for &age in &[0.5, 1.0, 2.3, 5.0, 11.7, 15.5] {
        let t = t0 + age;
        let here = drifted(x0, DRIFT, age);
        let s = h.accumulate(t, burst(here, x0, t0));
        // Cover: the burst's kernel weight over the normalisation, K(a)/Σ K.
        let expected = kernel(age) / kernel_sum(t);
        assert!((s.cover - expected).abs() < SUM_ROUNDING, "age {age}: cover {} vs {expected}", s.cover);
        assert!(s.cover > 0.0);
        // Aged by t − t₀, and dimmed by e^{−a/τ_R}.
        assert!((s.mean_age_s - age).abs() < SUM_ROUNDING, "age {age}: mean age {}", s.mean_age_s);
        let rho = (-age / h.brightness_decay_time()).exp();
        assert!((s.brightness - rho).abs() < SUM_ROUNDING, "age {age}: brightness {} vs {rho}", s.brightness);
        // The instant t₀ is read with exactly that age and the offset back to x₀.
        let sample = h.samples(t).find(|p| (p.time_s - t0).abs() < LATTICE_MATCH_S).unwrap();
        assert!((sample.age_s - age).abs() < SUM_ROUNDING);
        for (offset, v) in sample.rest_offset_m.iter().zip(DRIFT) {
            assert!((offset + v * age).abs() < SUM_ROUNDING);
        }
        // Not where it was created (the drift moved it |v| a ≥ 0.18 m > the spot radius), and not
        // where the undrifted water is.
        assert!(h.accumulate(t, burst(x0, x0, t0)).cover < NO_FOAM, "age {age}: foam left behind");
        let beside = [here[0] + 2.0 * SPOT_RADIUS_M, here[1]];
        assert!(h.accumulate(t, burst(beside, x0, t0)).cover < NO_FOAM);
    }
    // Before its creation and after the history's length, no foam.
    assert!(h.accumulate(t0 - 0.01, burst(x0, x0, t0)).cover < NO_FOAM);
    let late = LENGTH_S + 0.5;
    assert!(h.accumulate(t0 + late, burst(drifted(x0, DRIFT, late), x0, t0)).cover < NO_FOAM);
}

#[test]
fn without_drift_foam_stays_on_its_particle() {
    let h = history([0.0, 0.0]);
    let (x0, t0) = ([-3.0, 4.0], 20.0);
    for &age in &[0.5, 3.0, 9.0] {
        let s = h.accumulate(t0 + age, burst(x0, x0, t0));
        assert!((s.cover - kernel(age) / kernel_sum(t0 + age)).abs() < SUM_ROUNDING);
        assert!((s.mean_age_s - age).abs() < SUM_ROUNDING);
    }
}

#[test]
fn foam_area_and_reflectance_decay_as_koepke_and_callaghan() {
    let h = history(DRIFT);
    let tau_r = h.brightness_decay_time();
    let (x0, t0) = ([0.0, 0.0], 40.0);
    let state = |age: f64| h.accumulate(t0 + age, burst(drifted(x0, DRIFT, age), x0, t0));
    // Ages 2.3 s and 5.3 s share the phase within a step, so the normalisations cancel: the
    // area ratio is e^{−3/τ} (Callaghan et al. 2012) and the reflectance ratio e^{−3/τ_R}.
    let (young, old) = (state(2.3), state(5.3));
    assert!((old.cover / young.cover - (-3.0 / TAU_S).exp()).abs() < SUM_ROUNDING);
    assert!((old.brightness / young.brightness - (-3.0 / tau_r).exp()).abs() < SUM_ROUNDING);
    // The reflectance fades monotonically from fresh foam (R_f) as the foam ages.
    let ages: Vec<f64> = (1..32).map(|i| 0.5 * i as f64).collect();
    let b: Vec<f64> = ages.iter().map(|&a| state(a).brightness).collect();
    assert!(b.windows(2).all(|w| w[1] < w[0]), "{b:?}");
    // Koepke's effective reflectance: the area-weighted life mean of R_f e^{−a/τ_R} is
    // f_ef R_f = 0.22. Closed form with the kernel, c = 1/τ (+ 1/τ_R in the numerator), Δt = 1:
    // ∫₀^T K e^{−a/τ_R} da / ∫₀^T K da, ∫ K = (1 − e^{−c}(1 + c))/c² + (e^{−c} − e^{−c(T−1)})/c
    // + e^{−cT}(e^{c}(c − 1) + 1)/c².
    let integral = |c: f64| {
        (1.0 - (-c).exp() * (1.0 + c)) / (c * c)
            + ((-c).exp() - (-c * (LENGTH_S - 1.0)).exp()) / c
            + (-c * LENGTH_S).exp() * (c.exp() * (c - 1.0) + 1.0) / (c * c)
    };
    let life_mean = integral(1.0 / TAU_S + 1.0 / tau_r) / integral(1.0 / TAU_S);
    eprintln!("τ_R = {tau_r:.6} s; life-mean brightness {life_mean:.7} (Koepke f_ef = {KOEPKE_EFFICIENCY})");
    assert!((life_mean / KOEPKE_EFFICIENCY - 1.0).abs() < PHASE_AVERAGE_REL, "{life_mean}");
    let koepke = KoepkeFoam::default();
    let r_ef = koepke.fresh_reflectance() * life_mean;
    assert!((r_ef / 0.22 - 1.0).abs() < PHASE_AVERAGE_REL, "R_ef = {r_ef}");
}

#[test]
fn the_same_point_and_time_give_the_same_foam_whatever_the_order() {
    let h = history(DRIFT);
    let source = |u: [f64; 2]| {
        move |s: &FoamSample| {
            let (x, z) = (u[0] + s.rest_offset_m[0], u[1] + s.rest_offset_m[1]);
            (0.5 + 0.5 * (0.37 * x - 0.21 * z + 0.9 * s.time_s).sin()).powi(3)
        }
    };
    let queries: Vec<([f64; 2], f64)> =
        (0..64).map(|i| ([i as f64 * 1.7 - 30.0, 11.0 - i as f64 * 0.9], 100.0 + 0.37 * i as f64)).collect();
    let run = |order: &[usize], h: &FoamHistory| -> Vec<FoamState> {
        let mut out = vec![FoamState { cover: -1.0, brightness: -1.0, mean_age_s: -1.0 }; queries.len()];
        for &i in order {
            let (u, t) = queries[i];
            out[i] = h.accumulate(t, source(u));
        }
        out
    };
    let forward: Vec<usize> = (0..queries.len()).collect();
    let backward: Vec<usize> = forward.iter().rev().copied().collect();
    let shuffled: Vec<usize> = (0..queries.len()).map(|i| (i * 37 + 11) % queries.len()).collect();
    let a = run(&forward, &h);
    // Bit-identical in any order, from a second history built from the same parameters, and on
    // another thread.
    assert_eq!(a, run(&backward, &h));
    assert_eq!(a, run(&shuffled, &h));
    let h2 = history(DRIFT);
    assert_eq!(h, h2);
    assert_eq!(a, run(&forward, &h2));
    let threaded = std::thread::scope(|s| s.spawn(|| run(&shuffled, &h2)).join().unwrap());
    assert_eq!(a, threaded);
    // The instants read lie on one global lattice, multiples of Δt whatever t.
    for &t in &[0.3, 123.4, 7777.77] {
        assert!(h.samples(t).all(|s| s.time_s.to_bits() == ((s.time_s / STEP_S).round() * STEP_S).to_bits()));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn a_burst_is_found_where_the_drift_took_it(
        vx in -5.0f64..=5.0, vz in -5.0f64..=5.0, x in -1e3f64..1e3, z in -1e3f64..1e3,
        t0_steps in 0i32..100_000, age in 0.01f64..15.99,
    ) {
        let drift = [vx, vz];
        let h = history(drift);
        let (x0, t0) = ([x, z], f64::from(t0_steps) * STEP_S);
        let t = t0 + age;
        // t − t₀ in floating point (t₀ up to 10⁵ s) is the age to ~10⁻¹¹ s.
        let a = t - t0;
        let here = drifted(x0, drift, a);
        let s = h.accumulate(t, burst(here, x0, t0));
        prop_assert!(s.cover > 0.0 && s.cover <= 1.0, "cover {}", s.cover);
        prop_assert!((s.cover - kernel(a) / kernel_sum(t)).abs() < SUM_ROUNDING);
        prop_assert!((s.mean_age_s - a).abs() < SUM_ROUNDING);
        prop_assert!(s.brightness > 0.0 && s.brightness <= 1.0);
        // One spot diameter away from the drifted position, there is none of it.
        let beside = [here[0], here[1] + 2.0 * SPOT_RADIUS_M];
        prop_assert!(h.accumulate(t, burst(beside, x0, t0)).cover < NO_FOAM);
    }
}
