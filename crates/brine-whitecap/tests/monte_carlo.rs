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

/// Standard errors allowed between a Monte Carlo estimate and its expectation: 4σ, a chance of
/// 6×10⁻⁵ per comparison for samples this large (normal approximation).
const BINOMIAL_Z: f64 = 4.0;

/// Factor on the first-order Edgeworth correction that bounds the departure of the CDF of `J` from
/// the Gaussian law: the omitted terms are of the next order in `1/√N`, and the sample excess
/// kurtosis that sizes part of it carries a sampling error of `√(96/n)` = 0.022 at `n` = 2·10⁵
/// (about its own value).
const EDGEWORTH_MARGIN: f64 = 2.0;

/// The sheet's oracle for the whole-sea variance: "Monte-Carlo within 1 %" (the sample variance's
/// own standard error is `√(2/n)` ≈ 0.3 % at `n` = 2·10⁵ for a near-Gaussian `J`).
const SHEET_VARIANCE_REL: f64 = 0.01;

/// Mean footprint variance, sampled against the model: its sampling error, dominated by the
/// spread between footprints (wave groups), is ≈ 1.5 % over 2000 footprints; 5 % is three of
/// them plus the independence approximation of the derivation.
const FOOTPRINT_VARIANCE_REL: f64 = 0.05;

/// Absolute floor on the footprint-mean bias (rounding of 2000 sums of 50 values of order 1).
const BIAS_ROUNDING: f64 = 1e-12;

/// The acceptance tolerance for the calibrated coverage against Monahan's (the
/// calibration's own standard error is 3–4 %, the surface sample's ≤ 3 %).
const CALIBRATION_REL: f64 = 0.10;

/// Mean per-pixel coverage with the table `α(s)` against the target: the table was solved on
/// 8192 importance samples (~3 % standard error) and is checked on 4·10⁴ fresh points of a smooth
/// coverage (≲ 3 %), plus the interpolation of `α` in `ln s` between levels.
const TABLE_REL: f64 = 0.15;

/// Least overshoot of the Gaussian law with the point `α` at a 10 km footprint: the Gaussian lower
/// tail is heavier than `J`'s (docs/models/brine-whitecap.md: the Gaussian quantile reaches only
/// 70 % of the target at 10 m/s), so at the point `α` it covers more; 1.1 asks for a clear effect.
const GAUSSIAN_OVERSHOOT: f64 = 1.1;

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
    assert!((mean - st.mean()).abs() < BINOMIAL_Z * se_mean, "mean {mean}");
    assert!((var / st.variance() - 1.0).abs() < SHEET_VARIANCE_REL, "variance {var} vs {}", st.variance());
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
                let (u1, u2): (f64, f64) = (rng.random::<f64>().max(f64::MIN_POSITIVE), rng.random());
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
        assert!(
            (var_sampled / var_model - 1.0).abs() < FOOTPRINT_VARIANCE_REL,
            "s = {s}: variance {var_sampled} vs {var_model}"
        );
        // Average bias of the mean within BINOMIAL_Z standard errors of that average.
        let se = (spread / centres as f64).sqrt() / (centres as f64).sqrt();
        assert!(
            (bias / centres as f64).abs() < BINOMIAL_Z * se + BIAS_ROUNDING,
            "s = {s}: bias {}",
            bias / centres as f64
        );
    }
}

/// Third central moment of `J` over the sea for independent uniform phases (derived, not in the
/// crate): with `J − 1 = −L + P`, `L = Σ aᵢcᵢ`, `P = Σ_{i<j} bᵢⱼ cᵢcⱼ`, `bᵢⱼ = aᵢaⱼ sin²(θᵢ − θⱼ)`,
/// `E[L³] = E[LP²] = 0` (odd powers), `E[L²P] = Σ_{i<j} bᵢⱼ aᵢaⱼ/2` and
/// `E[P³] = (3/4) Σ_{i<j<k} bᵢⱼ bⱼₖ bᵢₖ` (a triangle of pairs, `E[cᵢ²cⱼ²cₖ²] = 1/8`, 3! orders), so
/// `μ₃ = (3/2) Σ_{i<j} aᵢ²aⱼ² sin²(θᵢ − θⱼ) + (3/4) Σ_{i<j<k} bᵢⱼ bⱼₖ bᵢₖ`.
fn third_central_moment(set: &TrochoidSet) -> f64 {
    let w = set.waves();
    let b = |i: usize, j: usize| {
        let s = (w[i].direction() - w[j].direction()).sin();
        w[i].steepness() * w[j].steepness() * s * s
    };
    let (mut pairs, mut triangles) = (0.0, 0.0);
    for i in 0..w.len() {
        for j in i + 1..w.len() {
            let bij = b(i, j);
            pairs += bij * w[i].steepness() * w[j].steepness();
            for k in j + 1..w.len() {
                triangles += bij * b(j, k) * b(i, k);
            }
        }
    }
    1.5 * pairs + 0.75 * triangles
}

#[test]
fn coverage_law_against_the_fraction_of_the_footprint() {
    // A large footprint of a many-wave set: the fraction of points with J < α against
    // W(α) = ½(1 + erf((α − μ)/√(2σ²))) at α = μ + kσ, k = −2 … 2, across the distribution.
    let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let set = fit_trochoids(&pm, &spreading, 200, 9, &FitOptions::default()).unwrap();
    let st = JacobianStatistics::new(&set).unwrap();
    let m = st.moments_at(DVec2::ZERO, 0.0, 1e6, FootprintFilter::Gaussian);
    let sd = m.sigma2.sqrt();
    let ks = [-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0];
    let n = 200_000;
    let mut below = [0usize; 9];
    let (mut s3, mut s4) = (0.0, 0.0);
    for u in points(n, 2.0e4, 13) {
        let j = set.gerstner_jacobian(u, 0.0);
        for (b, &k) in below.iter_mut().zip(&ks) {
            *b += usize::from(j < m.mu + k * sd);
        }
        let x = (j - m.mu) / sd;
        s3 += x * x * x;
        s4 += x * x * x * x;
    }
    // Skewness γ₁ (derived) and excess kurtosis γ₂ (sampled) of J. The sample skewness,
    // standardised with the analytic μ and σ, has the standard error √(Var x³/n) = √(15/n)
    // = 0.0087 (Gaussian sixth moment 15): checked against the derivation.
    let g1_sampled = s3 / n as f64;
    let g2 = s4 / n as f64 - 3.0;
    let g1 = third_central_moment(&set) / (sd * sd * sd);
    eprintln!("200 waves: σ = {sd:.5}, skewness {g1:.4} (sampled {g1_sampled:.4}), excess kurtosis {g2:.4}");
    assert!((g1_sampled - g1).abs() < BINOMIAL_Z * (15.0 / n as f64).sqrt(), "skewness {g1_sampled} vs {g1}");
    for (&b, &k) in below.iter().zip(&ks) {
        let a = m.mu + k * sd;
        let frac = b as f64 / n as f64;
        let w = whitecap_coverage(m, a, ErfMethod::Libm);
        // Binomial standard error of a fraction of n independent points, √(W(1 − W)/n).
        let se = (w * (1.0 - w) / n as f64).sqrt();
        // Non-Gaussian J: the first Edgeworth terms of F(x) − Φ(x), x = k,
        // −φ(x)[γ₁(x² − 1)/6 + γ₂(x³ − 3x)/24 + γ₁²(x⁵ − 10x³ + 15x)/72], in absolute value.
        let phi = (-0.5 * k * k).exp() / (2.0 * std::f64::consts::PI).sqrt();
        let edgeworth = phi
            * ((g1 * (k * k - 1.0) / 6.0).abs()
                + (g2 * (k * k * k - 3.0 * k) / 24.0).abs()
                + (g1 * g1 * (k.powi(5) - 10.0 * k * k * k + 15.0 * k) / 72.0).abs());
        let tol = BINOMIAL_Z * se + EDGEWORTH_MARGIN * edgeworth;
        eprintln!(
            "α = μ {k:+.1}σ: fraction {frac:.5}, W {w:.5}, |Δ| {:.2e} (binomial se {se:.1e}, Edgeworth {edgeworth:.1e})",
            (frac - w).abs()
        );
        assert!((frac - w).abs() < tol, "α = μ {k:+}σ: fraction {frac} vs W {w} (tolerance {tol})");
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
        assert!((frac / target - 1.0).abs() < CALIBRATION_REL, "U10 = {u10}: {frac} vs {target}");
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
        assert!((mean / target - 1.0).abs() < TABLE_REL, "s = {s}: {mean} vs {target}");
    }
    // Without the table, the Gaussian law at large footprints overshoots the target.
    let far = 1e4;
    let m: Moments = st.moments_at(DVec2::ZERO, 0.0, far, FootprintFilter::Gaussian);
    let w_exact_alpha = whitecap_coverage(m, cal.alpha(), ErfMethod::Libm);
    assert!(w_exact_alpha > GAUSSIAN_OVERSHOOT * target, "{w_exact_alpha}");
}
