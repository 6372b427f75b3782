//! Monte Carlo checks of the analytic Jacobian statistics, of the Gaussian coverage law, and of
//! the calibration against Monahan's coverage.

use brine_foam::{CoverageParams, DARLES_ONSET_WIND_M_S, WhitecapLaw, whitecap_coverage as monahan};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TrochoidSet, fit_trochoids};
use brine_whitecap::{
    Calibration, CalibrationOptions, ErfMethod, FootprintFilter, JacobianStatistics, Moments, whitecap_coverage,
};
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The sea of the default scene at wind `u10`: Pierson–Moskowitz, Hasselmann spreading, 50
/// waves, choppiness 2.5, seed 1 (brine-render's `[sea]` defaults).
fn default_sea(u10: f64) -> TrochoidSet {
    let pm = PiersonMoskowitz::from_u10(u10).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    fit_trochoids(&pm, &spreading, 50, 1, &FitOptions { choppiness: 2.5, ..FitOptions::default() }).unwrap()
}

/// `n` uniform points over a square of side `side` (m): a footprint far larger than the longest
/// wave (≈ 200 m at 10 m/s), where the phases are independent and uniform.
fn points(n: usize, side: f64, seed: u64) -> impl Iterator<Item = DVec2> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n).map(move |_| DVec2::new(rng.random::<f64>() * side, rng.random::<f64>() * side))
}

#[test]
fn whole_sea_mean_and_variance() {
    let set = {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        fit_trochoids(&pm, &spreading, 100, 3, &FitOptions::default()).unwrap()
    };
    let st = JacobianStatistics::new(&set).unwrap();
    let n = 200_000;
    let (mut s, mut s2) = (0.0, 0.0);
    for u in points(n, 2.0e4, 11) {
        let j = set.gerstner_jacobian(u, 0.0);
        s += j;
        s2 += j * j;
    }
    let mean = s / n as f64;
    let var = s2 / n as f64 - mean * mean;
    let se_mean = (st.variance() / n as f64).sqrt();
    // 4 standard errors of the sample mean.
    assert!((mean - st.mean()).abs() < 4.0 * se_mean, "mean {mean}");
    // The sheet's oracle: variance within 1 % (the sample variance's own standard error is
    // √(2/n) ≈ 0.3 % for a near-Gaussian J).
    assert!((var / st.variance() - 1.0).abs() < 0.01, "variance {var} vs {}", st.variance());
}

#[test]
fn footprint_moments_against_footprint_samples() {
    // Gaussian footprints of several sizes: sample J at centre + N(0, s²) and compare with the
    // footprint moments. The derivation treats the waves' fluctuations over the footprint as
    // independent. That is exact on average over the sea, but neighbouring wave vectors beat
    // (wave groups), so one footprint's variance can differ from the model by tens of percent:
    // compare averages over 2000 random centres (50 points each; the n/(n − 1) correction makes
    // each footprint variance unbiased).
    let set = default_sea(10.0);
    let st = JacobianStatistics::new(&set).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for &s in &[0.3, 1.0, 3.0, 10.0] {
        let (centres, n) = (2000, 50);
        let (mut var_sampled, mut var_model, mut bias, mut spread) = (0.0, 0.0, 0.0, 0.0);
        for _ in 0..centres {
            let centre = DVec2::new(rng.random::<f64>() * 2e4, rng.random::<f64>() * 2e4);
            let m = st.moments_at(centre, 0.0, s, FootprintFilter::Gaussian);
            let (mut a, mut a2) = (0.0, 0.0);
            for _ in 0..n {
                // Box–Muller.
                let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
                let r = (-2.0 * u1.ln()).sqrt() * s;
                let (sn, cs) = (std::f64::consts::TAU * u2).sin_cos();
                let j = set.gerstner_jacobian(centre + DVec2::new(r * cs, r * sn), 0.0);
                a += j;
                a2 += j * j;
            }
            let mean = a / n as f64;
            var_sampled += (a2 / n as f64 - mean * mean) * n as f64 / (n as f64 - 1.0);
            var_model += m.sigma2;
            bias += mean - m.mu;
            spread += m.sigma2 / n as f64;
        }
        let (var_sampled, var_model) = (var_sampled / centres as f64, var_model / centres as f64);
        // Average variance within 5 % (its sampling error, dominated by the spread between
        // footprints, is ≈ 1.5 %).
        assert!((var_sampled / var_model - 1.0).abs() < 0.05, "s = {s}: variance {var_sampled} vs {var_model}");
        // Average bias of the mean within 4 standard errors of that average.
        let se = (spread / centres as f64).sqrt() / (centres as f64).sqrt();
        assert!((bias / centres as f64).abs() < 4.0 * se + 1e-12, "s = {s}: bias {}", bias / centres as f64);
    }
}

#[test]
fn coverage_law_against_the_fraction_of_the_footprint() {
    // A large footprint of a many-wave set: the fraction of points with J < α against
    // W(α) = ½(1 + erf((α − μ)/√(2σ²))), near the centre of the law (at ±1σ the skewness term of
    // the Edgeworth correction vanishes, and kurtosis and skewness are O(1/√N)).
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let set = fit_trochoids(&pm, &spreading, 200, 9, &FitOptions::default()).unwrap();
    let st = JacobianStatistics::new(&set).unwrap();
    let m = st.moments_at(DVec2::ZERO, 0.0, 1e6, FootprintFilter::Gaussian);
    let sd = m.sigma2.sqrt();
    let alphas = [m.mu - sd, m.mu - 0.5 * sd, m.mu + sd];
    let n = 200_000;
    let mut below = [0usize; 3];
    for u in points(n, 2.0e4, 13) {
        let j = set.gerstner_jacobian(u, 0.0);
        for (b, &a) in below.iter_mut().zip(&alphas) {
            *b += usize::from(j < a);
        }
    }
    for (&b, &a) in below.iter().zip(&alphas) {
        let frac = b as f64 / n as f64;
        let w = whitecap_coverage(m, a, ErfMethod::Libm);
        let se = (w * (1.0 - w) / n as f64).sqrt();
        // 4 standard errors of the fraction, plus 0.005 for the departure from Gaussian.
        assert!((frac - w).abs() < 4.0 * se + 0.005, "α = {a}: fraction {frac} vs W {w}");
    }
    // W is monotone in α on this set.
    let ws: Vec<f64> =
        (0..50).map(|i| whitecap_coverage(m, m.mu - 3.0 * sd + 0.12 * sd * i as f64, ErfMethod::Fast)).collect();
    assert!(ws.windows(2).all(|p| p[1] >= p[0]));
}

#[test]
fn calibrated_coverage_matches_monahan() {
    // The rendered-free estimate: sample J over the sea surface and count J < α.
    for &(u10, n) in &[(6.0, 1_000_000), (10.0, 300_000), (15.0, 100_000)] {
        let set = default_sea(u10);
        let st = JacobianStatistics::new(&set).unwrap();
        let target = monahan(&CoverageParams::new(u10, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).unwrap());
        let cal = Calibration::new(&st, target, &CalibrationOptions::default()).unwrap();
        let below = points(n, 2.0e4, 17).filter(|&u| st.jacobian_at(u, 0.0) < cal.alpha()).count();
        let frac = below as f64 / n as f64;
        eprintln!(
            "U10 = {u10}: α = {:.4}, surface {frac:.5} vs Monahan {target:.5} (ratio {:.3})",
            cal.alpha(),
            frac / target
        );
        // The acceptance tolerance.
        assert!((frac / target - 1.0).abs() < 0.10, "U10 = {u10}: {frac} vs {target}");
    }
}

#[test]
fn calibrated_table_keeps_the_mean_coverage_at_every_footprint() {
    let set = default_sea(10.0);
    let st = JacobianStatistics::new(&set).unwrap();
    let target = 9.87e-3;
    let cal = Calibration::new(&st, target, &CalibrationOptions::default()).unwrap();
    for (s, _) in cal.table().collect::<Vec<_>>().iter().step_by(2) {
        let n = 40_000;
        let mean: f64 = points(n, 2.0e4, 19)
            .map(|u| cal.coverage(st.moments_at(u, 0.0, *s, FootprintFilter::Gaussian), *s, ErfMethod::Libm))
            .sum::<f64>()
            / n as f64;
        // The sampled mean of a smooth coverage: its error is well under the binary count's
        // 5 %; the table was itself solved on 8192 importance samples (~3 % error).
        assert!((mean / target - 1.0).abs() < 0.15, "s = {s}: {mean} vs {target}");
    }
    // Without the table, the Gaussian law at large footprints overshoots the target.
    let far = 1e4;
    let m: Moments = st.moments_at(DVec2::ZERO, 0.0, far, FootprintFilter::Gaussian);
    let w_exact_alpha = whitecap_coverage(m, cal.alpha(), ErfMethod::Libm);
    assert!(w_exact_alpha > 1.1 * target, "{w_exact_alpha}");
}
