//! Analytic limits and closed forms: the fit's variance against `∫ S dω`, spectra that reduce to
//! one another, the sine set as the `Q → 0` trochoid sum, and determinism.

use std::f64::consts::TAU;

use brine_waves::{
    AmplitudeRule, CosineTwoS, DonelanBanner, Elfouhaily, FitOptions, FrequencyPartition, G, Jonswap, Phillips,
    PiersonMoskowitz, SeaComponent, SineSet, Spectrum, SteepnessLimit, Tma, Trochoid, TrochoidSet, TrochoidSum,
    WaveSurface, fit_sea_state, fit_trochoids,
};

/// The acceptance bound: the fitted variance is within 1 % of the band integral.
const VARIANCE_REL: f64 = 0.01;

/// `∫_a^b S_PM dω = (αg²/(4βω₀⁴)) [exp(−β(ω₀/b)⁴) − exp(−β(ω₀/a)⁴)]` (substitute `x = β(ω₀/ω)⁴`).
fn pm_band_variance(pm: &PiersonMoskowitz, a: f64, b: f64) -> f64 {
    let (al, be, w0) = (PiersonMoskowitz::ALPHA, PiersonMoskowitz::BETA, pm.omega_0());
    al * G * G / (4.0 * be * w0.powi(4)) * ((-be * (w0 / b).powi(4)).exp() - (-be * (w0 / a).powi(4)).exp())
}

fn spectra() -> Vec<(&'static str, Box<dyn Spectrum>)> {
    vec![
        ("Pierson–Moskowitz", Box::new(PiersonMoskowitz::from_u10(10.0).unwrap())),
        ("JONSWAP", Box::new(Jonswap::from_fetch(10.0, 1e5).unwrap())),
        ("TMA", Box::new(Tma::from_fetch(10.0, 1e5, 10.0).unwrap())),
        ("Phillips", Box::new(Phillips::from_wind(10.0).unwrap())),
        ("Elfouhaily", Box::new(Elfouhaily::from_fetch(10.0, 5e4).unwrap())),
    ]
}

fn check_variance(name: &str, s: &dyn Spectrum, o: FitOptions, n: usize) {
    let d = DonelanBanner::new(s.peak_omega()).unwrap();
    let set = fit_trochoids(s, &d, n, 11, &o).unwrap();
    let wp = s.peak_omega();
    let band = s.variance_between(o.omega_min_factor * wp, o.omega_max_factor * wp);
    let err = set.variance() / band - 1.0;
    assert!(
        err.abs() < VARIANCE_REL,
        "{name} {:?} {:?} n = {n}: relative error {err:.3e}",
        o.partition,
        o.amplitude_rule
    );
}

#[test]
fn fitted_variance_matches_the_band_integral_for_every_spectrum() {
    for (name, s) in spectra() {
        for partition in
            [FrequencyPartition::Logarithmic, FrequencyPartition::EqualEnergy, FrequencyPartition::EqualSpacing]
        {
            for n in [30, 64, 200] {
                check_variance(name, s.as_ref(), FitOptions { partition, ..FitOptions::default() }, n);
            }
        }
        // The paper's midpoint amplitudes √(2 S(ωᵢ)Δωᵢ): log bins from 30 waves, equal spacing
        // from 100 (see AmplitudeRule::Midpoint).
        for (partition, n) in [
            (FrequencyPartition::Logarithmic, 30),
            (FrequencyPartition::Logarithmic, 50),
            (FrequencyPartition::EqualSpacing, 100),
        ] {
            let o = FitOptions { partition, amplitude_rule: AmplitudeRule::Midpoint, ..FitOptions::default() };
            check_variance(name, s.as_ref(), o, n);
        }
    }
}

#[test]
fn pm_fit_variance_against_the_closed_form_band_integral() {
    let pm = PiersonMoskowitz::from_u10(15.0).unwrap();
    let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let o = FitOptions::default();
    let wp = pm.peak_omega();
    let exact = pm_band_variance(&pm, o.omega_min_factor * wp, o.omega_max_factor * wp);
    // Simpson's rule on the quadrature is accurate to ~10⁻¹⁰ here; the fit adds bookkeeping only.
    assert!((pm.variance_between(o.omega_min_factor * wp, o.omega_max_factor * wp) / exact - 1.0).abs() < 1e-9);
    for n in [30, 100, 1000] {
        let set = fit_trochoids(&pm, &d, n, 5, &o).unwrap();
        assert!((set.variance() / exact - 1.0).abs() < 1e-8, "n = {n}");
    }
    // The trait's numeric m₀ over [ω_p/20, 1000 ω_p] against αg²/(4βω₀⁴).
    assert!((Spectrum::m0(&pm) / pm.m0() - 1.0).abs() < 1e-9);
}

#[test]
fn sea_and_swell_variances_add() {
    let sea = PiersonMoskowitz::from_u10(8.0).unwrap();
    let swell = Jonswap::new(0.003, 0.45).unwrap().with_peak_shape(6.0, 0.07, 0.09).unwrap();
    let d_sea = CosineTwoS::hasselmann(sea.peak_omega()).unwrap();
    let d_swell = CosineTwoS::constant(30.0).unwrap();
    let o_sea = FitOptions::default();
    let o_swell =
        FitOptions { wind_direction: -0.8, omega_min_factor: 0.7, omega_max_factor: 2.0, ..FitOptions::default() };
    let set = fit_sea_state(
        &[
            SeaComponent { spectrum: &sea, spreading: &d_sea, n_waves: 40, options: o_sea },
            SeaComponent { spectrum: &swell, spreading: &d_swell, n_waves: 30, options: o_swell },
        ],
        3,
        0.9,
        SteepnessLimit::ScaleAll,
    )
    .unwrap();
    let (wa, wb) = (sea.peak_omega(), swell.peak_omega());
    let expected = pm_band_variance(&sea, 0.5 * wa, 12.0 * wa) + swell.variance_between(0.7 * wb, 2.0 * wb);
    assert!((set.variance() / expected - 1.0).abs() < 1e-7);
}

#[test]
fn tma_in_deep_water_is_jonswap() {
    // Φ(ω√(h/g)) = 1 for ω ≥ 2√(g/h): 0.063 rad/s at h = 10 km.
    let j = Jonswap::from_fetch(12.0, 2e5).unwrap();
    let t = Tma::new(j, 1e4).unwrap();
    for i in 0..100 {
        let w = 0.1 * 10f64.powf(i as f64 / 50.0);
        // Φ = 1 exactly: the product is bit-identical (and 0 = 0 far below the peak).
        assert!((t.s_omega(w) - j.s_omega(w)).abs() <= 1e-15 * j.s_omega(w), "ω = {w}");
    }
    // Golden-section search locates a smooth maximum to about √ε ≈ 10⁻⁸ (S is flat to second order).
    assert!((t.peak_omega() / j.peak_omega() - 1.0).abs() < 1e-7);
}

#[test]
fn phillips_without_cutoff_is_pierson_moskowitz_with_beta_one() {
    // With A = α/(2π) and ℓ = 0: S(ω) = α g² ω⁻⁵ exp[−(g/V)⁴/ω⁴] (equation sheet §4).
    let v = 9.0;
    let p = Phillips::new(v, Phillips::DEFAULT_SCALE, 0.0).unwrap();
    let w0 = G / v;
    for i in 0..100 {
        let w = 0.3 * 10f64.powf(i as f64 / 60.0);
        let expected = PiersonMoskowitz::ALPHA * G * G * w.powi(-5) * (-(w0 / w).powi(4)).exp();
        assert!((p.s_omega(w) / expected - 1.0).abs() < 1e-12, "ω = {w}");
    }
    assert!((p.peak_omega() / (0.8f64.powf(0.25) * w0) - 1.0).abs() < 1e-12);
}

#[test]
fn pm_wavenumber_form_is_the_sheets_closed_form() {
    // S(k) = (α/(2k³)) exp[−β g²/(k² U⁴)] (equation sheet §4) against the trait's S(ω) dω/dk.
    let pm = PiersonMoskowitz::from_u19_5(14.0).unwrap();
    let u = pm.u19_5();
    for i in 0..80 {
        let k = 0.005 * 10f64.powf(i as f64 / 20.0);
        let expected =
            PiersonMoskowitz::ALPHA / (2.0 * k.powi(3)) * (-PiersonMoskowitz::BETA * G * G / (k * k * u.powi(4))).exp();
        assert!((pm.s_k(k) / expected - 1.0).abs() < 1e-12, "k = {k}");
    }
}

#[test]
fn elfouhaily_variance_is_the_same_in_omega_and_in_k() {
    // ∫ S(ω) dω over [ω_a, ω_b] equals ∫ S(k) dk over [k(ω_a), k(ω_b)] with the capillary
    // dispersion: checks S(ω) = S(k)/c_g and the inversion k(ω).
    let e = Elfouhaily::fully_developed(7.0).unwrap();
    let d = e.dispersion();
    for (a, b) in [(0.5, 1.5), (1.5, 10.0), (10.0, 200.0)] {
        let wp = e.peak_omega();
        let (wa, wb) = (a * wp, b * wp);
        let in_omega = e.variance_between(wa, wb);
        let (ka, kb) = (d.wavenumber(wa), d.wavenumber(wb));
        let n = 200_000;
        let h = (kb.ln() - ka.ln()) / n as f64;
        let in_k: f64 = (0..n)
            .map(|j| {
                let k = (ka.ln() + (j as f64 + 0.5) * h).exp();
                e.s_k(k) * k * h
            })
            .sum();
        // Simpson (10⁻⁸) against a 200 000-cell midpoint rule (10⁻⁹).
        assert!((in_omega / in_k - 1.0).abs() < 1e-7, "[{a}, {b}] ω_p");
    }
}

#[test]
fn sine_set_is_the_trochoid_sum_without_steepness() {
    let waves: Vec<Trochoid> = (0..9)
        .map(|i| {
            let k = 0.05 * 1.6f64.powi(i);
            Trochoid::new(0.8 / (1.0 + i as f64), k, 0.4 * i as f64, (G * k).sqrt(), 1.1 * i as f64, 0.0).unwrap()
        })
        .collect();
    let set = TrochoidSet::new(waves);
    let (sum, sine) = (TrochoidSum::new(&set), SineSet::new(&set));
    for j in 0..200 {
        let (x, z, t) = (j as f64 * 1.7 - 150.0, j as f64 * 0.9 - 40.0, j as f64 * 0.05);
        assert!((sum.height(x, z, t) - sine.height(x, z, t)).abs() < 1e-13);
        assert!((sum.gradient(x, z, t) - sine.gradient(x, z, t)).length() < 1e-13);
        assert!((sum.jacobian(x, z, t) - 1.0).abs() < 1e-15);
        // Vertical particle speeds agree; a Q = 0 trochoid has no horizontal orbit, the sine set
        // carries the Airy orbital velocity.
        assert!((sum.velocity(x, z, t).y - sine.velocity(x, z, t).y).abs() < 1e-12);
    }
}

#[test]
fn same_seed_same_set_on_every_platform() {
    // Determinism in one process…
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let a = fit_trochoids(&pm, &d, 50, 2024, &FitOptions::default()).unwrap();
    let b = std::thread::spawn(move || {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        fit_trochoids(&pm, &d, 50, 2024, &FitOptions::default()).unwrap()
    })
    .join()
    .unwrap();
    assert_eq!(a, b);
    // …and across platforms: a fingerprint of the set recorded on x86_64 Linux. The fit uses only
    // ChaCha8 (value-stable), IEEE arithmetic and libm (software, no platform libm), so every
    // platform must reproduce these values. This is a portability check, not a physics oracle:
    // the physics is tested above.
    let w = a.waves();
    let phase_sum: f64 = w.iter().map(|w| w.phase()).sum::<f64>() / TAU;
    let direction_sum: f64 = w.iter().map(|w| w.direction()).sum();
    assert!((phase_sum - PHASE_SUM).abs() < 1e-12, "Σφ/2π = {phase_sum:.15}");
    assert!((direction_sum - DIRECTION_SUM).abs() < 1e-12, "Σθ = {direction_sum:.15}");
}

/// `Σ φᵢ/2π` of the 50-wave PM set with seed 2024, recorded on `x86_64-unknown-linux-gnu`.
const PHASE_SUM: f64 = 29.62159035798196;
/// `Σ θᵢ` (rad) of the same set.
const DIRECTION_SUM: f64 = 10.229194281707798;
