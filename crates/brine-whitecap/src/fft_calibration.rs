//! Calibration of the breaking threshold `α` of an FFT ocean so that its mean whitecap coverage
//! equals a target at every footprint size.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::calibration::CalibrationOptions;
use crate::coverage::{calibrated_coverage, whitecap_coverage};
use crate::erf::ErfMethod;
use crate::error::{WhitecapError, check};
use crate::fft_statistics::FftJacobianStatistics;
use crate::statistics::Moments;

/// Default number of sample points when [`CalibrationOptions::samples`] is `None`: the relative
/// standard error of a coverage `W` is `√((1 − W)/(W M))`, 7.8 % at `W = 1 %`, 2.3 % at 10 %.
pub const FFT_CALIBRATION_SAMPLES: usize = 16_384;

/// Bisection steps for `α(s)`: the bracket (a few units wide) shrinks by `2⁻⁴⁰`, to ~10⁻¹².
const BISECTION_STEPS: usize = 40;

/// The error function of the calibration: the renderer's (Abramowitz & Stegun 7.1.26, error
/// 1.4×10⁻⁷, far below the sampling error of the mean coverage).
const CALIBRATION_ERF: ErfMethod = ErfMethod::AbramowitzStegun;

/// The breaking threshold `α` of an FFT ocean frame calibrated so that its mean whitecap coverage
/// equals a target `W*` (e.g. Monahan's, `brine_foam::whitecap_coverage`, at the same wind), for
/// every footprint size.
///
/// Dupuy & Bruneton leave `α` to the artist. The FFT surface is a finite sample of the sea, so
/// the coverage is an empirical quantity: `M` points `xⱼ` are drawn uniformly over the largest tile
/// (ChaCha8, seeded; the smaller, non-commensurate tiles are then sampled at effectively random
/// phases), and at each footprint size `s` of a table (log-spaced from a tenth of the finest grid
/// spacing to twice the largest tile) `α(s)` solves
///
/// `(1/M) Σⱼ ½[1 + erf((α − μⱼ(s))/√(2σⱼ²(s)))] = W*`
///
/// by bisection (the left side increases with `α`), `(μⱼ, σⱼ²)` the footprint moments of
/// [`FftJacobianStatistics::moments_at`]. At the smallest size the moments are nearly the pointwise
/// `J` (the interpolated reads between grid points leave a little variance), and `α` is close to
/// the `W*` quantile of `J` over the sea; at the largest they are the
/// whole sea's and `α = μ + σ√2 erf⁻¹(2W* − 1)`. Between table sizes `α` is linear in `ln s`.
///
/// # References
/// Dupuy & Bruneton 2012 (threshold `α`, coverage law); Monahan & Ó Muircheartaigh 1980 (the
/// usual target); docs/equations.md §5, §10.
#[derive(Debug, Clone, PartialEq)]
pub struct FftCalibration {
    target: f64,
    ln_footprints: Vec<f64>,
    alphas: Vec<f64>,
}

impl FftCalibration {
    /// Calibrates `α(s)` for a target coverage.
    ///
    /// # Arguments
    /// - `stats`: the frame's statistics.
    /// - `target_coverage`: `W* ∈ [0, 1]`; 0 and 1 give thresholds below and above every `J`.
    /// - `options`: `samples` (default [`FFT_CALIBRATION_SAMPLES`]), `seed` and
    ///   `footprint_levels` are used (`filter` does not apply: the pyramids filter as boxes).
    ///
    /// # Returns
    /// The table `α(s)` (dimensionless) over `footprint_levels` sizes `s` (m), log-spaced from a
    /// tenth of the finest grid spacing to twice the largest tile.
    ///
    /// # Errors
    /// [`WhitecapError::OutOfRange`] for a target outside `[0, 1]` or a bad option.
    ///
    /// # References
    /// See [`FftCalibration`] (Dupuy & Bruneton 2012; docs/equations.md §10).
    pub fn new(
        stats: &FftJacobianStatistics,
        target_coverage: f64,
        options: &CalibrationOptions,
    ) -> Result<Self, WhitecapError> {
        let target = check("target_coverage", target_coverage, (0.0..=1.0).contains(&target_coverage), "[0, 1]")?;
        if let Some(m) = options.samples {
            check("samples", m as f64, (256..=1 << 20).contains(&m), "[256, 1048576]")?;
        }
        let levels = options.footprint_levels;
        check("footprint_levels", levels as f64, (2..=64).contains(&levels), "[2, 64]")?;
        let m = options.samples.unwrap_or(FFT_CALIBRATION_SAMPLES);
        let (s_lo, s_hi) = (0.1 * stats.finest_spacing(), 2.0 * stats.largest_tile());
        let ln_footprints: Vec<f64> =
            (0..levels).map(|i| s_lo.ln() + (s_hi / s_lo).ln() * i as f64 / (levels - 1) as f64).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
        let tile = stats.largest_tile();
        let points: Vec<(f64, f64)> =
            (0..m).map(|_| (rng.random::<f64>() * tile, rng.random::<f64>() * tile)).collect();
        let alphas = ln_footprints
            .iter()
            .map(|&ls| {
                let s = ls.exp();
                let moments: Vec<Moments> = points.iter().map(|&(x, z)| stats.moments_at(x, z, s)).collect();
                solve_alpha(&moments, target)
            })
            .collect();
        Ok(Self { target, ln_footprints, alphas })
    }

    /// The target coverage `W*`.
    pub fn target(&self) -> f64 {
        self.target
    }

    /// The threshold at the smallest footprint: the `W*` quantile of the pointwise `J`.
    pub fn alpha(&self) -> f64 {
        self.alphas[0]
    }

    /// The table `(s, α(s))` (m, dimensionless), increasing `s`.
    pub fn table(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.ln_footprints.iter().zip(&self.alphas).map(|(l, a)| (l.exp(), *a))
    }

    /// Threshold for a Gaussian footprint of standard deviation `footprint_m` (m, `≥ 0`): linear in
    /// `ln s` between the table's sizes, the end values beyond.
    pub fn alpha_for_footprint(&self, footprint_m: f64) -> f64 {
        debug_assert!(footprint_m >= 0.0);
        let n = self.ln_footprints.len();
        if !(footprint_m > 0.0) || footprint_m.ln() <= self.ln_footprints[0] {
            return self.alphas[0];
        }
        let ls = footprint_m.ln();
        let i = self.ln_footprints.partition_point(|&l| l < ls);
        if i >= n {
            return self.alphas[n - 1];
        }
        let (l0, l1) = (self.ln_footprints[i - 1], self.ln_footprints[i]);
        self.alphas[i - 1] + (ls - l0) / (l1 - l0) * (self.alphas[i] - self.alphas[i - 1])
    }

    /// Whitecap coverage of a pixel with the calibrated threshold for its footprint.
    ///
    /// # Arguments
    /// - `moments`: `(μ, σ²)` of the pixel ([`FftJacobianStatistics::moments_at`]).
    /// - `footprint_m`: the same footprint `s` (m).
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

/// The `α` whose mean coverage over `moments` is `target` (bisection).
fn solve_alpha(moments: &[Moments], target: f64) -> f64 {
    let lo0 = moments.iter().map(|m| m.mu - 10.0 * m.sigma2.sqrt()).fold(f64::INFINITY, f64::min) - 1.0;
    let hi0 = moments.iter().map(|m| m.mu + 10.0 * m.sigma2.sqrt()).fold(f64::NEG_INFINITY, f64::max) + 1.0;
    if target <= 0.0 {
        return lo0;
    }
    if target >= 1.0 {
        return hi0;
    }
    let mean = |alpha: f64| moments.iter().map(|&m| whitecap_coverage(m, alpha, CALIBRATION_ERF)).sum::<f64>();
    let goal = target * moments.len() as f64;
    let (mut lo, mut hi) = (lo0, hi0);
    for _ in 0..BISECTION_STEPS {
        let mid = 0.5 * (lo + hi);
        if mean(mid) < goal {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
