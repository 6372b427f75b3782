//! Calibration of the breaking threshold `α` so that the whitecap coverage of a wave set equals
//! a target (Monahan's coverage at the same wind).

use std::f64::consts::{PI, SQRT_2};

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::bessel::ln_i0_and_ratio;
use crate::coverage::calibrated_coverage;
use crate::erf::{ErfMethod, erf_inv};
use crate::error::{WhitecapError, check};
use crate::statistics::{Accumulator, FootprintFilter, JacobianStatistics, Moments, WaveTerm};

/// Concentrations below this sample the phase uniformly (the tilt is then switched off for that
/// wave, exactly, in the weights).
const KAPPA_MIN: f64 = 1e-3;

/// Options of [`Calibration::new`] and [`surface_coverage`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CalibrationOptions {
    /// Number of phase samples, `[256, 2²⁰]`; `None` (default) picks `409 600/N` clamped to
    /// `[4096, 16 384]` for `N` waves, so the cost stays near 30 ms (relative standard error of
    /// the coverage ~3–5 % at Monahan's coverages, reported in
    /// [`Calibration::relative_std_error`]).
    pub samples: Option<usize>,
    /// Seed of the ChaCha8 generator: same set, target and seed, same `α` on every platform.
    pub seed: u64,
    /// Footprint filter that the renderer uses with [`crate::JacobianStatistics::moments_at`].
    pub filter: FootprintFilter,
    /// Number of footprint sizes in the table of `α(s)`, `[2, 64]`; default 8 (`α(s)` is smooth
    /// and monotone in `ln s`).
    pub footprint_levels: usize,
}

impl Default for CalibrationOptions {
    fn default() -> Self {
        Self { samples: None, seed: 1, filter: FootprintFilter::Gaussian, footprint_levels: 8 }
    }
}

impl CalibrationOptions {
    fn checked(&self) -> Result<Self, WhitecapError> {
        if let Some(m) = self.samples {
            check("samples", m as f64, (256..=1 << 20).contains(&m), "[256, 1048576]")?;
        }
        check("footprint_levels", self.footprint_levels as f64, (2..=64).contains(&self.footprint_levels), "[2, 64]")?;
        Ok(*self)
    }
}

/// An estimate of the fraction of the sea surface where `J < α`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CoverageEstimate {
    /// Estimated fraction, `[0, 1]`.
    pub coverage: f64,
    /// Its standard error (same unit).
    pub std_error: f64,
}

/// The breaking threshold `α` calibrated so that the whitecap coverage of a wave set equals a
/// target coverage `W*` (Monahan's law at the same wind, from brine-foam).
///
/// **Why.** Dupuy & Bruneton leave `α` to the artist. Matching the mean coverage to Monahan's
/// `W(U₁₀)` makes the whitecaps of a rendered sea agree with observations at every wind.
///
/// **The exact threshold.** The coverage of the sea is the fraction of the surface where
/// `J < α`, `P(J < α)` with `J = 1 − Σ aᵢcᵢ + Σ_{i<j} aᵢaⱼ sin²(θᵢ − θⱼ) cᵢcⱼ` and independent
/// uniform phases (see [`JacobianStatistics`]). `J` is far from Gaussian in its lower tail
/// (bounded, and skewed by the pair terms): the Gaussian quantile `1 + σ√2 erf⁻¹(2W* − 1)` gives
/// only 15–70 % of the target coverage for fitted seas at 6 m s⁻¹. So `P(J < α)` is estimated
/// by importance sampling of the phases, and `α` is its `W*` quantile:
///
/// 1. Tilt: each phase is drawn from a von Mises law `∝ e^{κᵢ cos φ}`, `κᵢ = λ aᵢ`, which pushes
///    the samples toward `J < α`. `λ` is the saddle point of the Lugannani–Rice approximation
///    for `Y = 1 − J`, with cumulant generating function
///    `K(λ) ≈ Σ ln I₀(λaᵢ) − λ E_λ[Σ_{i<j} aᵢaⱼ sin² cᵢcⱼ]` (the pair terms to first order),
///    capped so that the tilted mean of `J` stays above its corner value `det(I − Σ aᵢd̂ᵢd̂ᵢᵀ)`.
/// 2. Sample: half the samples tilted, half uniform (defensive mixture), with weights
///    `w = 1/(½ + ½ exp(Σ κᵢcᵢ − Σ ln I₀(κᵢ)))`, at most 2; `P̂(J < α) = (1/M) Σ wⱼ [Jⱼ < α]`.
/// 3. `α` interpolates the weighted empirical distribution at `W*`.
///
/// **Footprints.** A renderer evaluates `W = ½(1 + erf((α − μ)/√(2σ²)))` per pixel with the
/// footprint moments, which treat the unresolved waves as Gaussian; its mean over the sea is
/// then `W*` only in the fully resolved limit. The table [`Self::alpha_for_footprint`] solves, at
/// each footprint size `s`, `(1/M) Σ wⱼ W(α; μⱼ(s), σⱼ²(s)) = W*` on the same samples, so that
/// every distance shows the same mean coverage. Beyond the largest size every wave is unresolved
/// and `α = 1 + σ√2 erf⁻¹(2W* − 1)` (the Gaussian quantile).
///
/// Cost: one pass of `samples × N` phase draws and, per footprint level, `samples × N_active`
/// accumulations (measured in `docs/benchmarks.md`).
///
/// # References
/// Dupuy & Bruneton 2012 (threshold `α`); Monahan & Ó Muircheartaigh 1980 (target, via
/// brine-foam); Lugannani R., Rice S. 1980, "Saddle point approximation for the distribution of
/// the sum of independent random variables", Adv. Appl. Prob. 12:475–490; Best D., Fisher N.
/// 1979, "Efficient simulation of the von Mises distribution", Appl. Statist. 28:152–157;
/// Hesterberg T. 1995, "Weighted average importance sampling and defensive mixture
/// distributions", Technometrics 37:185–194.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibration {
    target: f64,
    alpha: f64,
    relative_std_error: f64,
    alpha_unresolved: f64,
    ln_footprints: Vec<f64>,
    alphas: Vec<f64>,
    filter: FootprintFilter,
}

impl Calibration {
    /// Calibrates `α` for a target coverage.
    ///
    /// # Arguments
    /// - `stats`: the wave set's statistics.
    /// - `target_coverage`: `W* ∈ [0, 1]`, e.g. `brine_foam::whitecap_coverage` at the set's
    ///   wind. 0 and 1 give thresholds below and above every `J`.
    /// - `options`: see [`CalibrationOptions`].
    ///
    /// # Returns
    /// The calibration: `α` with `P(J < α) = W*` (dimensionless), its relative standard error,
    /// and the table `α(s)` over 8 (by default) footprint sizes `s` (m).
    ///
    /// # Errors
    /// [`WhitecapError::OutOfRange`] for a target outside `[0, 1]` or a bad option.
    ///
    /// # References
    /// See [`Calibration`] (Dupuy & Bruneton 2012; Lugannani & Rice 1980; Best & Fisher 1979;
    /// Hesterberg 1995; Monahan & Ó Muircheartaigh 1980 for the usual target).
    pub fn new(
        stats: &JacobianStatistics,
        target_coverage: f64,
        options: &CalibrationOptions,
    ) -> Result<Self, WhitecapError> {
        let target = check("target_coverage", target_coverage, (0.0..=1.0).contains(&target_coverage), "[0, 1]")?;
        let options = options.checked()?;
        let (j_lo, j_hi) = stats.bounds();
        let footprints = footprint_levels(stats, &options);
        let ln_footprints: Vec<f64> = footprints.iter().map(|s| s.ln()).collect();
        if target <= 0.0 || target >= 1.0 {
            let alpha = if target <= 0.0 { j_lo - 1.0 } else { j_hi + 1.0 };
            return Ok(Self {
                target,
                alpha,
                relative_std_error: 0.0,
                alpha_unresolved: alpha,
                alphas: vec![alpha; footprints.len()],
                ln_footprints,
                filter: options.filter,
            });
        }
        let alpha_unresolved = 1.0 + (2.0 * stats.variance()).sqrt() * erf_inv(2.0 * target - 1.0);
        let lambda = lambda_for_coverage(stats.terms(), target);
        let samples = draw_samples(stats, lambda, &options, &footprints);
        let (alpha, relative_std_error) = samples.quantile(target);
        let mut alphas = Vec::with_capacity(footprints.len());
        for l in 0..footprints.len() {
            let guess = alpha + (alpha_unresolved - alpha) * l as f64 / (footprints.len() - 1) as f64;
            alphas.push(samples.smooth_quantile(l, target, guess));
        }
        Ok(Self { target, alpha, relative_std_error, alpha_unresolved, ln_footprints, alphas, filter: options.filter })
    }

    /// The target coverage `W*`.
    pub fn target(&self) -> f64 {
        self.target
    }

    /// The threshold `α` with `P(J < α) = W*` over the sea: the one to use where every wave is
    /// resolved, and the answer to "which α gives Monahan's coverage".
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Relative standard error of the sampled coverage at [`Self::alpha`] (e.g. 0.03 for 3 %).
    pub fn relative_std_error(&self) -> f64 {
        self.relative_std_error
    }

    /// The threshold for a footprint that resolves no wave: `1 + σ√2 erf⁻¹(2W* − 1)`.
    pub fn alpha_unresolved(&self) -> f64 {
        self.alpha_unresolved
    }

    /// The footprint filter the table was computed for.
    pub fn filter(&self) -> FootprintFilter {
        self.filter
    }

    /// The table `(s, α(s))` (m, dimensionless), increasing `s`.
    pub fn table(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.ln_footprints.iter().zip(&self.alphas).map(|(l, a)| (l.exp(), *a))
    }

    /// Threshold for a footprint of size `s`: linear in `ln s` between the table's sizes,
    /// [`Self::alpha`] below the smallest and [`Self::alpha_unresolved`] above the largest.
    ///
    /// # Arguments
    /// - `footprint_m`: footprint size `s` (m), `≥ 0` (as in
    ///   [`JacobianStatistics::moments_at`]).
    ///
    /// # Returns
    /// `α(s)` (dimensionless).
    ///
    /// # References
    /// See [`Calibration`] ("Footprints").
    pub fn alpha_for_footprint(&self, footprint_m: f64) -> f64 {
        debug_assert!(footprint_m >= 0.0);
        let first = self.ln_footprints[0];
        if !(footprint_m > 0.0) || footprint_m.ln() <= first {
            return self.alpha;
        }
        let ls = footprint_m.ln();
        let i = self.ln_footprints.partition_point(|&l| l < ls);
        if i >= self.ln_footprints.len() {
            return self.alpha_unresolved;
        }
        let (l0, l1) = (self.ln_footprints[i - 1], self.ln_footprints[i]);
        let f = (ls - l0) / (l1 - l0);
        self.alphas[i - 1] + f * (self.alphas[i] - self.alphas[i - 1])
    }

    /// Whitecap coverage of a pixel with the calibrated threshold for its footprint.
    ///
    /// # Arguments
    /// - `moments`: `(μ, σ²)` of the pixel ([`JacobianStatistics::moments_at`], same filter).
    /// - `footprint_m`: the pixel's footprint size `s` (m).
    /// - `erf`: error function.
    ///
    /// # Returns
    /// `W ∈ [0, 1]`; exactly 0 (1) when the target is 0 (1).
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (`W = ½(1 + erf((α − μ)/√(2σ²)))`); docs/equations.md §10.
    pub fn coverage(&self, moments: Moments, footprint_m: f64, erf: ErfMethod) -> f64 {
        calibrated_coverage(self.target, moments, erf, || self.alpha_for_footprint(footprint_m))
    }
}

/// Estimates the fraction of the sea surface where `J < α` (the coverage of a raw threshold), by
/// the importance sampling of [`Calibration`], tilted at the saddle point for `α`.
///
/// # Arguments
/// - `stats`: the wave set's statistics.
/// - `alpha`: threshold `α` (finite).
/// - `options`: `samples` and `seed` are used.
///
/// # Returns
/// The [`CoverageEstimate`].
///
/// # Errors
/// [`WhitecapError::OutOfRange`] for a non-finite `α` or a bad option.
///
/// # References
/// See [`Calibration`] (importance sampling with a von Mises tilt at the Lugannani–Rice saddle
/// point; Hesterberg 1995's defensive mixture).
pub fn surface_coverage(
    stats: &JacobianStatistics,
    alpha: f64,
    options: &CalibrationOptions,
) -> Result<CoverageEstimate, WhitecapError> {
    let alpha = check("alpha", alpha, true, "finite")?;
    let options = options.checked()?;
    let lambda = lambda_for_threshold(stats.terms(), alpha);
    let samples = draw_samples(stats, lambda, &options, &[]);
    Ok(samples.fraction_below(alpha))
}

/// Footprint sizes of the table: log-spaced from where every wave is resolved (`k_max s = 0.01`)
/// to where none is (`k_min s` at the filter's cut-off).
fn footprint_levels(stats: &JacobianStatistics, options: &CalibrationOptions) -> Vec<f64> {
    let terms = stats.terms();
    let (k_min, k_max) = (terms[0].k, terms[terms.len() - 1].k);
    let cut = match options.filter {
        FootprintFilter::Gaussian => 5.26,
        FootprintFilter::Sharp => 1.0,
    };
    let (lo, hi) = ((0.01 / k_max).ln(), (cut / k_min).ln().max((0.01 / k_max).ln() + 1e-3));
    let n = options.footprint_levels;
    (0..n).map(|i| (lo + (hi - lo) * i as f64 / (n - 1) as f64).exp()).collect()
}

/// `(Σ ln I₀(λaᵢ), Σ pᵢ, H₂ = Σ pᵢ e^{2iθᵢ})` with `pᵢ = aᵢ I₁(λaᵢ)/I₀(λaᵢ) = aᵢ E_λ[cᵢ]`.
fn tilted_sums(terms: &[WaveTerm], lambda: f64) -> (f64, f64, f64, f64) {
    let (mut k, mut sp, mut hc, mut hs) = (0.0, 0.0, 0.0, 0.0);
    for t in terms {
        let (l, r) = ln_i0_and_ratio(lambda * t.a);
        k += l;
        let p = t.a * r;
        sp += p;
        hc += p * t.harm[0];
        hs += p * t.harm[1];
    }
    (k, sp, hc, hs)
}

/// Tilted mean of the pair terms `E_λ[Σ_{i<j} aᵢaⱼ sin²(θᵢ − θⱼ) cᵢcⱼ] = ((Σp)² − |H₂|²)/4`.
fn pair_mean(sp: f64, hc: f64, hs: f64) -> f64 {
    0.25 * (sp * sp - hc * hc - hs * hs)
}

/// Cumulant generating function of `Y = 1 − J` under the first-order pair correction.
fn cgf(terms: &[WaveTerm], lambda: f64) -> f64 {
    let (k, sp, hc, hs) = tilted_sums(terms, lambda);
    k - lambda * pair_mean(sp, hc, hs)
}

/// Exact tilted mean of `J`: `1 − Σ pᵢ + ((Σp)² − |H₂|²)/4` (independent tilted phases).
fn tilted_mean_j(terms: &[WaveTerm], lambda: f64) -> f64 {
    let (_, sp, hc, hs) = tilted_sums(terms, lambda);
    1.0 - sp + pair_mean(sp, hc, hs)
}

/// `(K′(λ), K″(λ))` by central differences.
fn cgf_derivatives(terms: &[WaveTerm], lambda: f64) -> (f64, f64) {
    let h = 1e-4 * lambda.abs().max(1.0);
    let (km, k0, kp) = (cgf(terms, lambda - h), cgf(terms, lambda), cgf(terms, lambda + h));
    ((kp - km) / (2.0 * h), ((kp - 2.0 * k0 + km) / (h * h)).max(1e-300))
}

/// Lugannani–Rice `P(Y ≥ K′(λ))` at the tilt `λ`.
fn lugannani_rice(terms: &[WaveTerm], lambda: f64) -> f64 {
    if lambda.abs() < 1e-6 {
        return 0.5;
    }
    let (y, k2) = cgf_derivatives(terms, lambda);
    let arg = 2.0 * (lambda * y - cgf(terms, lambda));
    if !(arg > 1e-12) {
        return 0.5;
    }
    let w = arg.sqrt().copysign(lambda);
    let u = lambda * k2.sqrt();
    let density = (-0.5 * w * w).exp() / (2.0 * PI).sqrt();
    (0.5 * libm::erfc(w / SQRT_2) + density * (1.0 / u - 1.0 / w)).clamp(0.0, 1.0)
}

/// Largest `|λ|` (with the sign of `lambda`) keeping the tilted mean of `J` a twentieth of the way
/// from the corner value toward 1, where the tilted law still spreads over the tail.
fn cap_lambda(terms: &[WaveTerm], lambda: f64) -> f64 {
    let corner = tilted_mean_j(terms, lambda.signum() * 1e9);
    let floor = corner + 0.05 * (1.0 - corner);
    let beyond = |l: f64| if lambda > 0.0 { tilted_mean_j(terms, l) < floor } else { tilted_mean_j(terms, l) > floor };
    if !beyond(lambda) {
        return lambda;
    }
    bisect(0.0, lambda, beyond).0
}

/// Bisection (60 halvings) between `lo`, where `past` is false, and `hi`, where it is true;
/// returns the final bracket.
fn bisect(mut lo: f64, mut hi: f64, past: impl Fn(f64) -> bool) -> (f64, f64) {
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if past(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    (lo, hi)
}

/// The `λ` of sign `sign` where `past` turns true: doubles `|λ|` from 1 until it does (at most
/// 10⁶), then bisects from 0.
fn boundary(sign: f64, past: impl Fn(f64) -> bool) -> f64 {
    let mut hi = sign;
    while !past(hi) && hi.abs() < 1e6 {
        hi *= 2.0;
    }
    let (lo, hi) = bisect(0.0, hi, past);
    0.5 * (lo + hi)
}

/// Tilt for a target coverage: bisection on `λ` for Lugannani–Rice `P(Y ≥ y(λ)) = W*`.
fn lambda_for_coverage(terms: &[WaveTerm], target: f64) -> f64 {
    if (target - 0.5).abs() < 1e-9 {
        return 0.0;
    }
    let sign = if target < 0.5 { 1.0 } else { -1.0 };
    // For λ < 0 the formula gives P(Y ≥ y) > ½; the lower tail of J is the upper tail of Y.
    let below = |l: f64| lugannani_rice(terms, l) < target;
    cap_lambda(terms, boundary(sign, |l| (sign > 0.0) == below(l)))
}

/// Tilt for a threshold: the saddle point `K′(λ) = 1 − α`.
fn lambda_for_threshold(terms: &[WaveTerm], alpha: f64) -> f64 {
    let y = 1.0 - alpha;
    let sign = if y > 0.0 { 1.0 } else { -1.0 };
    let past = |l: f64| (cgf_derivatives(terms, l).0 - y) * sign > 0.0;
    cap_lambda(terms, boundary(sign, past))
}

/// `cos θ` of a von Mises draw of concentration `κ > 0` (Best & Fisher 1979), with
/// `r = (1 + ρ²)/(2ρ)` precomputed.
fn von_mises_cos(kappa: f64, r: f64, rng: &mut ChaCha8Rng) -> f64 {
    loop {
        let u1: f64 = rng.random();
        let u2: f64 = rng.random();
        let z = (PI * u1).cos();
        let f = (1.0 + r * z) / (r + z);
        let c = kappa * (r - f);
        if c * (2.0 - c) - u2 > 0.0 || (c / u2).ln() + 1.0 - c >= 0.0 {
            return f.clamp(-1.0, 1.0);
        }
    }
}

/// The weighted phase samples: `J`, weight, and the footprint moments per level.
struct Samples {
    j: Vec<f64>,
    w: Vec<f64>,
    levels: usize,
    moments: Vec<Moments>,
}

fn draw_samples(stats: &JacobianStatistics, lambda: f64, options: &CalibrationOptions, footprints: &[f64]) -> Samples {
    let terms = stats.terms();
    let n = terms.len();
    // Per-wave tilt: κ, Best–Fisher r, and Σ ln I₀(κ).
    let mut kappa = vec![0.0; n];
    let mut bf_r = vec![0.0; n];
    let mut log_norm = 0.0;
    for (i, t) in terms.iter().enumerate() {
        let k = lambda * t.a;
        if k.abs() >= KAPPA_MIN {
            let ka = k.abs();
            let tau = 1.0 + (1.0 + 4.0 * ka * ka).sqrt();
            let rho = (tau - (2.0 * tau).sqrt()) / (2.0 * ka);
            kappa[i] = k;
            bf_r[i] = (1.0 + rho * rho) / (2.0 * rho);
            log_norm += ln_i0_and_ratio(k).0;
        }
    }
    let tilted_any = kappa.iter().any(|&k| k != 0.0);
    // Per-level active counts and gains.
    let level_data: Vec<(usize, Vec<f64>)> = footprints
        .iter()
        .map(|&s| {
            let m = stats.active_count(s, options.filter);
            (m, terms[..m].iter().map(|t| JacobianStatistics::gain(t.k, s, options.filter)).collect())
        })
        .collect();
    let m = options.samples.unwrap_or((409_600 / n.max(1)).clamp(4096, 16_384));
    let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
    let mut cos = vec![0.0; n];
    let mut out = Samples {
        j: Vec::with_capacity(m),
        w: Vec::with_capacity(m),
        levels: footprints.len(),
        moments: Vec::with_capacity(m * footprints.len()),
    };
    for s in 0..m {
        let tilted = tilted_any && s % 2 == 1;
        let mut exponent = 0.0;
        let mut acc = Accumulator::new();
        for i in 0..n {
            let k = kappa[i];
            let c = if tilted && k != 0.0 {
                let c = von_mises_cos(k.abs(), bf_r[i], &mut rng);
                if k > 0.0 { c } else { -c }
            } else {
                (PI * rng.random::<f64>()).cos()
            };
            cos[i] = c;
            exponent += k * c;
            acc.add(&terms[i], 1.0, c);
        }
        let weight = if tilted_any { 1.0 / (0.5 + 0.5 * (exponent - log_norm).min(700.0).exp()) } else { 1.0 };
        out.j.push(acc.p * acc.r - acc.q * acc.q);
        out.w.push(weight);
        for (active, gains) in &level_data {
            let mut acc = Accumulator::new();
            for i in 0..*active {
                acc.add(&terms[i], gains[i], cos[i]);
            }
            out.moments.push(acc.moments(stats.tail(*active)));
        }
    }
    out
}

impl Samples {
    /// `P̂(J < α)` and its standard error.
    fn fraction_below(&self, alpha: f64) -> CoverageEstimate {
        let m = self.j.len() as f64;
        let (mut s, mut s2) = (0.0, 0.0);
        for (&j, &w) in self.j.iter().zip(&self.w) {
            if j < alpha {
                s += w;
                s2 += w * w;
            }
        }
        let mean = s / m;
        let var = ((s2 / m - mean * mean) * m / (m - 1.0)).max(0.0);
        CoverageEstimate { coverage: mean.clamp(0.0, 1.0), std_error: (var / m).sqrt() }
    }

    /// `α` with `P̂(J < α) = target`, and the relative standard error of `P̂` there.
    fn quantile(&self, target: f64) -> (f64, f64) {
        let m = self.j.len();
        let mut idx: Vec<usize> = (0..m).collect();
        idx.sort_by(|&a, &b| self.j[a].total_cmp(&self.j[b]));
        let goal = target * m as f64;
        let mut cum = 0.0;
        let mut alpha = self.j[idx[m - 1]];
        for (pos, &i) in idx.iter().enumerate() {
            let next = cum + self.w[i];
            if next >= goal {
                let f = ((goal - cum) / self.w[i]).clamp(0.0, 1.0);
                let prev = if pos == 0 { self.j[i] } else { self.j[idx[pos - 1]] };
                alpha = prev + f * (self.j[i] - prev);
                break;
            }
            cum = next;
        }
        let est = self.fraction_below(alpha);
        (alpha, est.std_error / target)
    }

    /// `α` with `(1/M) Σ wⱼ W(α; μⱼ, σⱼ²) = target` at footprint level `l`, by Newton's method
    /// safeguarded by bisection.
    fn smooth_quantile(&self, level: usize, target: f64, guess: f64) -> f64 {
        let m = self.j.len() as f64;
        let at = |alpha: f64| -> (f64, f64) {
            let (mut f, mut df) = (0.0, 0.0);
            for (s, &w) in self.w.iter().enumerate() {
                let mo = self.moments[s * self.levels + level];
                if mo.sigma2 <= 0.0 {
                    if alpha > mo.mu {
                        f += w;
                    }
                    continue;
                }
                let sd = mo.sigma2.sqrt();
                let z = (alpha - mo.mu) / sd;
                f += w * 0.5 * libm::erfc(-z / SQRT_2);
                df += w * (-0.5 * z * z).exp() / ((2.0 * PI).sqrt() * sd);
            }
            (f / m - target, df / m)
        };
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for mo in self.moments.iter().skip(level).step_by(self.levels) {
            let spread = 12.0 * mo.sigma2.sqrt() + 1e-9;
            lo = lo.min(mo.mu - spread);
            hi = hi.max(mo.mu + spread);
        }
        let mut x = guess.clamp(lo, hi);
        for _ in 0..100 {
            let (f, df) = at(x);
            if f.abs() <= 1e-9 * target {
                return x;
            }
            if f > 0.0 {
                hi = x;
            } else {
                lo = x;
            }
            let newton = if df > 0.0 { x - f / df } else { f64::NAN };
            x = if newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
            if hi - lo < 1e-12 {
                break;
            }
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use brine_waves::{Trochoid, TrochoidSet};

    /// Standard errors allowed between the sampled coverage and the closed form (4σ).
    const STD_ERRORS: f64 = 4.0;

    /// Floor on the relative standard error used in that test: the reported error can be tiny
    /// where the tilt fits the single wave exactly, while `α` is interpolated between samples
    /// (≤ 0.5 % of the target with 8192 samples).
    const MIN_REL_ERROR: f64 = 0.005;

    /// Exactly 0 or 1 (the degenerate targets return constants).
    const EXACT: f64 = 1e-15;

    #[test]
    fn single_wave_has_a_closed_form() {
        // One wave: J = 1 − Q cos φ, P(J < α) = P(cos φ > (1 − α)/Q) = arccos((1 − α)/Q)/π.
        let q = 0.6;
        let set = TrochoidSet::new(vec![Trochoid::new(0.1, 1.0, 0.3, 1.0, 0.0, q).unwrap()]);
        let st = JacobianStatistics::new(&set).unwrap();
        for &target in &[0.01, 0.1, 0.4, 0.8] {
            let cal = Calibration::new(&st, target, &CalibrationOptions::default()).unwrap();
            let exact = 1.0 - q * (PI * target).cos();
            let p_at = ((1.0 - cal.alpha()) / q).clamp(-1.0, 1.0).acos() / PI;
            // The sampled coverage at the calibrated α is within 4 standard errors of the target.
            assert!(
                (p_at / target - 1.0).abs() < STD_ERRORS * cal.relative_std_error().max(MIN_REL_ERROR),
                "target {target}: α = {} (exact {exact}), P = {p_at}, rse {}",
                cal.alpha(),
                cal.relative_std_error()
            );
        }
    }

    #[test]
    fn degenerate_targets() {
        let set = TrochoidSet::new(vec![Trochoid::new(0.1, 1.0, 0.3, 1.0, 0.0, 0.5).unwrap()]);
        let st = JacobianStatistics::new(&set).unwrap();
        let none = Calibration::new(&st, 0.0, &CalibrationOptions::default()).unwrap();
        assert!(none.alpha() < st.bounds().0);
        let m = Moments { mu: 0.7, sigma2: 0.1 };
        assert!(none.coverage(m, 1.0, ErfMethod::Libm).abs() < EXACT);
        assert!(Calibration::new(&st, 1.5, &CalibrationOptions::default()).is_err());
        let all = Calibration::new(&st, 1.0, &CalibrationOptions::default()).unwrap();
        assert!((all.coverage(m, 1.0, ErfMethod::Libm) - 1.0).abs() < EXACT);
    }
}
