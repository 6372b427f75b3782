//! White water: Dupuy & Bruneton's active whitecaps and the foam they leave behind
//! (brine-foam `FoamMemory`), calibrated together on Monahan's coverage.

use brine_core::footprint::EllipticalFootprint;
use brine_foam::{FoamMemory, MAX_MEMORY_INSTANTS, MemoryClock, WhiteWater};
use std::sync::Arc;

use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

pub use crate::breaking::{BREAKING_SPEED_SHARE, breaking_footprint, breaking_wavenumber_cut, forward_face_offset};
use crate::error::{WhitecapError, check};
use crate::fft_statistics::{FftJacobianHistory, FftJacobianStatistics};
use crate::statistics::{FootprintFilter, HistoryRotation, HistoryStart, JacobianStatistics, Moments};

/// The breaking variable of a sea: the footprint moments of its displacement Jacobian now and
/// its footprint means along a drifting path in the past.
pub trait BreakingSource: Sync {
    /// `(μ, σ²)` of `J` over a Gaussian footprint of standard deviation `footprint_m` (m) at rest
    /// position `u` (m) and time `t` (s).
    fn moments(&self, u: DVec2, t: f64, footprint_m: f64) -> Moments;

    /// Footprint means `μⱼ` at `tⱼ = t₀ − jΔt`, `uⱼ = u₀ − v jΔt`, `j < out.len()` (as
    /// [`JacobianStatistics::mean_history`]); an instant the source does not hold gives `μ = 1`
    /// (no breaking).
    fn mean_history(&self, u0: DVec2, t0: f64, step_s: f64, drift_m_s: DVec2, footprint_m: f64, out: &mut [f64]);

    /// [`Self::moments`] at `(u, t)` and [`Self::mean_history`] from the lattice instant
    /// `lattice.t0 ≤ t` at `u − v(t − t₀)`, together (a source may share their work). Default:
    /// the two calls.
    fn moments_and_history(&self, u: DVec2, t: f64, footprint_m: f64, lattice: &Lattice, out: &mut [f64]) -> Moments {
        let m = self.moments(u, t, footprint_m);
        if !out.is_empty() {
            let Lattice { t0, step_s, drift_m_s } = *lattice;
            self.mean_history(u - drift_m_s * (t - t0), t0, step_s, drift_m_s, footprint_m, out);
        }
        m
    }

    /// The mean variance of `J` inside a footprint `s_b` (m): the short waves' share that the
    /// breaking variable leaves out. Default: the mean of [`Self::moments`]' `σ²` at `probe`.
    fn short_variance(&self, breaking_footprint_m: f64, probe: &[(DVec2, f64)]) -> f64 {
        probe.iter().map(|&(u, t)| self.moments(u, t, breaking_footprint_m).sigma2).sum::<f64>()
            / probe.len().max(1) as f64
    }
}

/// The memory lattice a history is read on: its newest instant before the present, its step and
/// the foam's drift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lattice {
    /// Instant 0, `t₀ ≤ t` (s).
    pub t0: f64,
    /// `Δt` (s), `> 0`.
    pub step_s: f64,
    /// `v` (m s⁻¹).
    pub drift_m_s: DVec2,
}

/// A trochoid set's Jacobian statistics with the phase advances of one memory lattice.
#[derive(Debug, Clone)]
pub struct TrochoidBreaking {
    stats: JacobianStatistics,
    rotation: HistoryRotation,
    /// The age of instant 0 at a frame's time and its rotation (`JacobianStatistics::
    /// moments_and_history_f32`), when set.
    offset: Option<(f64, HistoryRotation)>,
}

impl TrochoidBreaking {
    /// The statistics, with the rotations of the lattice `step_s` (s) and drift (m s⁻¹).
    pub fn new(stats: JacobianStatistics, step_s: f64, drift_m_s: DVec2) -> Self {
        let rotation = stats.history_rotation(step_s, drift_m_s);
        Self { stats, rotation, offset: None }
    }

    /// The same, with the present and the history read in one pass at times whose instant 0 is
    /// `age_s` (s, `[0, Δt)`) old — a frame's time (other times take two passes).
    pub fn for_age(mut self, age_s: f64) -> Self {
        let offset = self.stats.history_rotation(age_s, self.rotation.drift_m_s);
        self.offset = Some((age_s, offset));
        self
    }

    /// The precomputed lattice, bit for bit.
    fn same_lattice(&self, step_s: f64, drift_m_s: DVec2) -> bool {
        step_s.to_bits() == self.rotation.step_s.to_bits()
            && drift_m_s.to_array().map(f64::to_bits) == self.rotation.drift_m_s.to_array().map(f64::to_bits)
    }
}

impl BreakingSource for TrochoidBreaking {
    fn moments(&self, u: DVec2, t: f64, footprint_m: f64) -> Moments {
        self.stats.moments_at_f32(u, t, footprint_m, FootprintFilter::Gaussian)
    }

    fn moments_and_history(&self, u: DVec2, t: f64, footprint_m: f64, lattice: &Lattice, out: &mut [f64]) -> Moments {
        match &self.offset {
            Some((age, offset))
                if !out.is_empty()
                    && (t - lattice.t0).to_bits() == age.to_bits()
                    && self.same_lattice(lattice.step_s, lattice.drift_m_s) =>
            {
                let (filter, rotation) = (FootprintFilter::Gaussian, &self.rotation);
                self.stats.moments_and_history_f32(u, t, footprint_m, filter, &HistoryStart { offset, rotation }, out)
            }
            _ => {
                let m = self.moments(u, t, footprint_m);
                if !out.is_empty() {
                    let Lattice { t0, step_s, drift_m_s } = *lattice;
                    self.mean_history(u - drift_m_s * (t - t0), t0, step_s, drift_m_s, footprint_m, out);
                }
                m
            }
        }
    }

    fn mean_history(&self, u0: DVec2, t0: f64, step_s: f64, drift_m_s: DVec2, footprint_m: f64, out: &mut [f64]) {
        // The same lattice as precomputed (bit for bit), else rotations made for this call.
        if self.same_lattice(step_s, drift_m_s) {
            self.stats.mean_history(u0, t0, &self.rotation, footprint_m, FootprintFilter::Gaussian, out);
        } else {
            let rotation = self.stats.history_rotation(step_s, drift_m_s);
            self.stats.mean_history(u0, t0, &rotation, footprint_m, FootprintFilter::Gaussian, out);
        }
    }
}

/// The Jacobian pyramids of an FFT sea's long waves, already filtered by the breaking footprint
/// `s_b` (brine-waves `FftOcean::rest_jacobian_fields`), now and at the lattice instants of the
/// foam memory; a footprint `s_eff = √(s² + s_b²)` asked of it is read as the pixel's `s`.
#[derive(Debug, Clone)]
pub struct FftBreaking {
    now: Arc<FftJacobianStatistics>,
    /// Shared: a model cloned for a frame keeps one copy of the large stacks.
    history: Arc<FftJacobianHistory>,
    breaking_footprint: f64,
    short_variance: f64,
}

impl FftBreaking {
    /// The present statistics and the means of `J` at the memory's past instants, all filtered
    /// by `breaking_footprint_m` (m), and the variance of `J` that filter removed.
    pub fn new(
        now: FftJacobianStatistics,
        history: FftJacobianHistory,
        breaking_footprint_m: f64,
        short_variance: f64,
    ) -> Self {
        Self {
            now: Arc::new(now),
            history: Arc::new(history),
            breaking_footprint: breaking_footprint_m,
            short_variance,
        }
    }

    /// The pixel footprint inside an effective one.
    fn pixel(&self, s_eff: f64) -> f64 {
        (s_eff * s_eff - self.breaking_footprint * self.breaking_footprint).max(0.0).sqrt()
    }

    /// The present frame's statistics.
    pub fn now(&self) -> &FftJacobianStatistics {
        &self.now
    }
}

/// Points over which the short waves' mean Jacobian variance is averaged.
const SHORT_VARIANCE_SAMPLES: usize = 1024;

impl BreakingSource for FftBreaking {
    fn moments(&self, u: DVec2, _t: f64, footprint_m: f64) -> Moments {
        let m = self.now.moments_at(u.x, u.y, self.pixel(footprint_m));
        // The filtered-out short waves' variance is the model's to remove again.
        Moments { mu: m.mu, sigma2: m.sigma2 + self.short_variance }
    }

    fn short_variance(&self, _breaking_footprint_m: f64, _probe: &[(DVec2, f64)]) -> f64 {
        self.short_variance
    }

    fn mean_history(&self, u0: DVec2, t0: f64, step_s: f64, drift_m_s: DVec2, footprint_m: f64, out: &mut [f64]) {
        self.history.mean_history(u0, t0, step_s, drift_m_s, self.pixel(footprint_m), out);
    }
}

/// Where and when the calibration samples the sea.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WhiteWaterOptions {
    /// Sample points at the point footprint, `[1024, 2²⁰]`; default 32 768.
    pub samples: usize,
    /// Sample points at each wider footprint, `[256, 2²⁰]`; default 2048.
    pub level_samples: usize,
    /// Side of the square of rest positions sampled (m), `(0, 10⁶]`, from the origin.
    pub region_m: f64,
    /// Times sampled (s), `[start, end]`, `start ≤ end`. A window that does not depend on the
    /// frame makes the threshold the same for every frame of an animation.
    pub times_s: (f64, f64),
    /// Seed of the sample points.
    pub seed: u64,
}

impl Default for WhiteWaterOptions {
    fn default() -> Self {
        Self { samples: 32_768, level_samples: 2048, region_m: 2000.0, times_s: (0.0, 3600.0), seed: 1 }
    }
}

/// Wider footprints at which the threshold is calibrated (m, standard deviation of the Gaussian
/// footprint); between them `α` is interpolated in `ln s`, beyond the last it is the last's. The
/// two smallest follow the fade of the foam lace's filaments (brine-foam `FoamLace`), across
/// which the threshold's softening changes.
pub const WHITE_WATER_FOOTPRINTS_M: [f64; 6] = [0.02, 0.04, 0.1, 0.5, 2.5, 12.5];

/// White water of a sea: active whitecaps where the breaking variable falls below a threshold,
/// the foam they leave, and one threshold for both calibrated on a target coverage.
///
/// The active cover at rest position `u`, time `t` and footprint `s` is Dupuy & Bruneton's
///
/// `A = ½(1 + erf((α(s) − μ − σ_e e)/√(2(σ² + σ_e²(1 − k) + k_L σ_L²))))`,
///
/// where `(μ, σ²)` are the Jacobian's footprint moments, `e` the foam memory's edge noise (unit
/// variance, carried by the water, share `k` of it resolved by the footprint) and `σ_e` the
/// share `edge_share` of the standard deviation `σ_s` of the Jacobian of the waves just shorter
/// than those drawn: their crests break the edge of a whitecap into lace. When the memory draws
/// its white water as lace (brine-foam `FoamLace`) the rest of their variance,
/// `σ_L² = (1 − edge_share²) σ_s²`, softens the threshold by the share `k_L` of the lace the
/// footprint resolves, and the lace draws that soft cover as broken foam of the same mean; a
/// pixel that resolves no lace keeps the sharp threshold. Without a lace `σ_L = 0`. The foam left is
/// `FoamMemory::combine` of the same `A` at the memory's past instants, read along the foam's
/// drift path, with the present `σ²` and `e`. `α(s)` is set so that the mean white cover
/// `1 − (1 − A)(1 − residual)(1 − c_w)` over the sea equals the target (Monahan's `W`), where
/// `c_w` is the cover of the memory's foam streaks along the wind (brine-foam `Windrows`, mean
/// `q_w = share · W`): at `s = 0` as the
/// `W`-quantile of each sample's lowest breaking variable among the instants whose foam survives
/// there (exact for the hard threshold), at the wider footprints by bisection on the mean.
///
/// # References
/// Dupuy J., Bruneton E. 2012, "Real-time animation and rendering of ocean whitecaps", SIGGRAPH
/// Asia Technical Briefs; Monahan E. C., Ó Muircheartaigh I. 1980, JPO 10:2094–2099 (target);
/// brine-foam `FoamMemory` (Monahan 1971, Callaghan et al. 2012).
#[derive(Debug, Clone)]
pub struct WhiteWaterModel<S> {
    source: S,
    memory: FoamMemory,
    breaking_footprint: f64,
    short_variance: f64,
    edge_std: f64,
    lace_variance: f64,
    forward: DVec2,
    target: f64,
    windrow_cover: f64,
    alpha0: f64,
    ln_levels: Vec<f64>,
    alphas: Vec<f64>,
    /// The memory seen from a frame's time ([`Self::for_time`]).
    clock: Option<Box<MemoryClock>>,
}

/// Standard normal distribution function of `d/√var` (a step for `var = 0`): the coverage law
/// with `μ = 0`, `σ² = var`, `α = d`.
#[inline]
fn phi(d: f64, var: f64) -> f64 {
    crate::coverage::whitecap_coverage(Moments { mu: 0.0, sigma2: var }, d, crate::erf::ErfMethod::AbramowitzStegun)
}

/// One calibration sample at one footprint: the present breaking variable, its variance, and
/// the past ones with their survivals.
struct Sample {
    x0: f64,
    var: f64,
    past: Vec<(f64, f64)>,
    /// Cover of the foam streaks.
    windrow: f64,
}

impl<S: BreakingSource> WhiteWaterModel<S> {
    /// Calibrates the threshold on `target`.
    ///
    /// # Arguments
    /// - `source`: the sea's [`BreakingSource`].
    /// - `memory`: the foam memory (brine-foam).
    /// - `breaking_footprint_m`: `s_b` (m), `[0, 10³]`: waves shorter than about `2π s_b` do not
    ///   take part in the breaking (see [`breaking_footprint`]).
    /// - `edge_share`: `σ_e` as a share of the standard deviation of the short waves' Jacobian
    ///   (the waves `s_b` filters out), `[0, 1]`.
    /// - `target`: mean white cover to reach, `[0, 1]` (Monahan's `W`).
    /// - `options`: [`WhiteWaterOptions`].
    ///
    /// # Errors
    /// [`WhitecapError::OutOfRange`] naming the parameter.
    pub fn new(
        source: S,
        memory: FoamMemory,
        breaking_footprint_m: f64,
        edge_share: f64,
        target: f64,
        options: &WhiteWaterOptions,
    ) -> Result<Self, WhitecapError> {
        check(
            "breaking_footprint_m",
            breaking_footprint_m,
            (0.0..=1e3).contains(&breaking_footprint_m),
            "[0, 1000] m",
        )?;
        check("edge_share", edge_share, (0.0..=1.0).contains(&edge_share), "[0, 1]")?;
        check("target", target, (0.0..=1.0).contains(&target), "[0, 1]")?;
        check("samples", options.samples as f64, (1024..=1 << 20).contains(&options.samples), "[1024, 1048576]")?;
        check(
            "level_samples",
            options.level_samples as f64,
            (256..=1 << 20).contains(&options.level_samples),
            "[256, 1048576]",
        )?;
        check("region_m", options.region_m, options.region_m > 0.0 && options.region_m <= 1e6, "(0, 1e6] m")?;
        check("times_s", options.times_s.1, options.times_s.1 >= options.times_s.0, "[start, end] s, start ≤ end")?;
        let mut model = Self {
            source,
            memory,
            breaking_footprint: breaking_footprint_m,
            short_variance: 0.0,
            edge_std: 0.0,
            lace_variance: 0.0,
            forward: DVec2::ZERO,
            target,
            windrow_cover: 0.0,
            alpha0: 0.0,
            ln_levels: WHITE_WATER_FOOTPRINTS_M.iter().map(|s| s.ln()).collect(),
            alphas: vec![0.0; WHITE_WATER_FOOTPRINTS_M.len()],
            clock: None,
        };
        if target <= 0.0 || target >= 1.0 {
            // Nothing or everything white: no threshold to find.
            let a = if target <= 0.0 { f64::NEG_INFINITY } else { f64::INFINITY };
            model.alpha0 = a;
            model.alphas.fill(a);
            return Ok(model);
        }
        // The streaks hold their share of the target; the breaking makes the rest.
        model.windrow_cover =
            if model.memory.windrows().is_some() { model.memory.windrow_share() * target } else { 0.0 };
        let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
        let points: Vec<(DVec2, f64)> = (0..options.samples)
            .map(|_| {
                let u = DVec2::new(rng.random::<f64>(), rng.random::<f64>()) * options.region_m;
                (u, options.times_s.0 + rng.random::<f64>() * (options.times_s.1 - options.times_s.0))
            })
            .collect();
        // The short waves' Jacobian variance: the mean footprint variance at `s_b`.
        let probe = &points[..SHORT_VARIANCE_SAMPLES.min(points.len())];
        model.short_variance = model.source.short_variance(breaking_footprint_m, probe);
        model.edge_std = edge_share * model.short_variance.sqrt();
        // The rest of the short waves' variance softens the threshold; a lace draws the soft
        // cover as broken foam (brine-foam `FoamLace`), so it is kept only with one.
        if model.memory.lace().is_some() {
            model.lace_variance = (1.0 - edge_share * edge_share) * model.short_variance;
        }
        // Point footprint: each sample is white at α exactly when α exceeds its lowest breaking
        // variable among the present and the instants whose foam survives there.
        let point: Vec<Sample> = points.par_iter().map(|&(u, t)| model.sample(u, t, 0.0)).collect();
        let mut lowest: Vec<f64> = point.iter().map(Sample::lowest).collect();
        lowest.sort_by(f64::total_cmp);
        // The quantile is exact for hard thresholds; the pixel's leftover variance softens them a
        // little, so the mean is then solved near it.
        let guess = quantile(&lowest, (target - model.windrow_cover) / (1.0 - model.windrow_cover));
        model.alpha0 = brine_foam::calibrate_threshold(
            target,
            (guess - POINT_BRACKET, guess + POINT_BRACKET),
            ALPHA_TOLERANCE,
            |alpha| mean_white(&point, alpha),
        );
        for (l, &s) in WHITE_WATER_FOOTPRINTS_M.iter().enumerate() {
            let samples: Vec<Sample> = points[..options.level_samples.min(points.len())]
                .par_iter()
                .map(|&(u, t)| model.sample(u, t, s))
                .collect();
            model.alphas[l] = brine_foam::calibrate_threshold(
                target,
                (model.alpha0 - 4.0, model.alpha0 + 4.0),
                ALPHA_TOLERANCE,
                |a| mean_white(&samples, a),
            );
        }
        Ok(model)
    }

    /// The breaking variable at `(u, t)` and pixel footprint `s`: its mean and the variance
    /// left inside the pixel, and the edge noise (with the footprint of the breaking waves); its
    /// means at the memory's instants go to `history` (its length: how many are read).
    fn breaking(&self, u: DVec2, t: f64, s: f64, history: &mut [f64]) -> (f64, f64, f64) {
        // `√(s² + s_b²)` (a square root of a square is exact, so `s = 0` gives `s_b`).
        let s_eff = (s * s + self.breaking_footprint * self.breaking_footprint).sqrt();
        let lattice = Lattice {
            t0: self.memory.instant(t, 0).0,
            step_s: self.memory.step(),
            drift_m_s: DVec2::from_array(self.memory.drift()),
        };
        let m = self.source.moments_and_history(u - self.forward, t, s_eff, &lattice, history);
        let (e, k) = self.memory.edge_noise(u.x, u.y, s);
        let x0 = m.mu + self.edge_std * e;
        // The lace's softening only where a lace is drawn: a pixel that resolves none keeps the
        // sharp threshold (else its white water would be a veil).
        let lace = if self.lace_variance > 0.0 {
            self.lace_variance * self.memory.lace().map_or(0.0, |l| l.resolved_share(s))
        } else {
            0.0
        };
        let var = (m.sigma2 - self.short_variance).max(0.0) + self.edge_std * self.edge_std * (1.0 - k) + lace;
        (x0, var, e)
    }

    /// The calibration sample at `(u, t)` and footprint `s`.
    fn sample(&self, u: DVec2, t: f64, s: f64) -> Sample {
        let mut surv = [0.0; MAX_MEMORY_INSTANTS];
        let n = self.memory.survivals(u.to_array(), t, s, &mut surv);
        let mut mu = [0.0; MAX_MEMORY_INSTANTS];
        let (x0, var, e) = self.breaking(u, t, s, &mut mu[..n]);
        let past = (0..n).filter(|&j| surv[j] > 0.0).map(|j| (mu[j] + self.edge_std * e, surv[j])).collect();
        Sample { x0, var, past, windrow: self.windrow(u, s) }
    }

    /// Cover of the foam streaks at `u` for a footprint `s`.
    fn windrow(&self, u: DVec2, s: f64) -> f64 {
        self.memory.windrow_cover(u.x, u.y, s, self.windrow_cover)
    }

    /// The threshold `α(s)` for a footprint `s` (m).
    pub fn alpha_for_footprint(&self, footprint_m: f64) -> f64 {
        if !self.alpha0.is_finite() {
            return self.alpha0;
        }
        let first = self.ln_levels[0];
        if !(footprint_m > 0.0) {
            return self.alpha0;
        }
        let ls = footprint_m.ln();
        if ls <= first {
            // Between the point and the first level: interpolate in s.
            let f = footprint_m / WHITE_WATER_FOOTPRINTS_M[0];
            return self.alpha0 + f * (self.alphas[0] - self.alpha0);
        }
        let i = self.ln_levels.partition_point(|&l| l < ls);
        if i >= self.ln_levels.len() {
            return self.alphas[self.alphas.len() - 1];
        }
        let (l0, l1) = (self.ln_levels[i - 1], self.ln_levels[i]);
        let f = (ls - l0) / (l1 - l0);
        self.alphas[i - 1] + f * (self.alphas[i] - self.alphas[i - 1])
    }

    /// The same thresholds (and edge noise) over another source of the same sea: for a sea whose
    /// calibration is made at a reference instant and read at another (the FFT sea of an
    /// animation frame, calibrated once for the animation).
    pub fn with_source<T: BreakingSource>(self, source: T) -> WhiteWaterModel<T> {
        WhiteWaterModel {
            source,
            memory: self.memory,
            breaking_footprint: self.breaking_footprint,
            short_variance: self.short_variance,
            edge_std: self.edge_std,
            lace_variance: self.lace_variance,
            forward: self.forward,
            target: self.target,
            windrow_cover: self.windrow_cover,
            alpha0: self.alpha0,
            ln_levels: self.ln_levels,
            alphas: self.alphas,
            clock: self.clock,
        }
    }

    /// The same model with the memory's thresholds and brightnesses at time `t` (s) computed
    /// once: [`Self::at`] at `t` (or at any time as far past a lattice instant) reads them
    /// instead of recomputing them point by point (the same values); other times compute their
    /// own.
    pub fn for_time(mut self, t: f64) -> Self {
        self.clock = Some(Box::new(self.memory.clock(t)));
        self
    }

    /// The whitecaps drawn `offset` (m) ahead of where the breaking variable is lowest: on the
    /// forward face of the crest ([`forward_face_offset`]). A constant shift of a stationary sea:
    /// the calibration holds unchanged.
    pub fn with_forward_face(mut self, offset_m: DVec2) -> Self {
        self.forward = offset_m;
        self
    }

    /// `s_b`, the footprint of the breaking waves (m).
    pub fn breaking_footprint(&self) -> f64 {
        self.breaking_footprint
    }

    /// `σ_e`, the standard deviation of the edge noise (dimensionless).
    pub fn edge_std(&self) -> f64 {
        self.edge_std
    }

    /// The target cover.
    pub fn target(&self) -> f64 {
        self.target
    }

    /// The foam memory.
    pub fn memory(&self) -> &FoamMemory {
        &self.memory
    }

    /// The breaking source.
    pub fn source(&self) -> &S {
        &self.source
    }

    /// White water at rest position `u` (m), time `t` (s) and Gaussian footprint `footprint_m`
    /// (m, standard deviation, `≥ 0`).
    ///
    /// # Returns
    /// brine-foam [`WhiteWater`]: the active cover, the foam left, the white cover and its
    /// brightness relative to fresh foam.
    pub fn at(&self, u: DVec2, t: f64, footprint_m: f64) -> WhiteWater {
        self.at_over(u, t, &EllipticalFootprint::round(footprint_m))
    }

    /// [`Self::at`] seen through an elliptical pixel footprint (brine-core
    /// [`EllipticalFootprint`]): the breaking statistics, the memory and the streaks are filtered
    /// over the round footprint of the same area, the lace along the footprint's long axis
    /// ([`FoamMemory::laced`]).
    pub fn at_over(&self, u: DVec2, t: f64, footprint: &EllipticalFootprint) -> WhiteWater {
        let footprint_m = footprint.area_sigma_m();
        debug_assert!(footprint_m >= 0.0);
        if self.target <= 0.0 {
            return WhiteWater { active: 0.0, residual: 0.0, white: 0.0, brightness: 1.0 };
        }
        if self.target >= 1.0 {
            return WhiteWater { active: 1.0, residual: 0.0, white: 1.0, brightness: 1.0 };
        }
        let alpha = self.alpha_for_footprint(footprint_m);
        let clock = self.clock.as_deref().filter(|c| c.holds(&self.memory, t));
        let mut surv = [0.0; MAX_MEMORY_INSTANTS];
        let n = match clock {
            Some(c) => self.memory.survivals_at(c, u.to_array(), footprint_m, &mut surv),
            None => self.memory.survivals(u.to_array(), t, footprint_m, &mut surv),
        };
        let mut src = [0.0; MAX_MEMORY_INSTANTS];
        let (x0, var, e) = self.breaking(u, t, footprint_m, &mut src[..n]);
        let active = phi(alpha - x0, var);
        for j in 0..n {
            src[j] = if surv[j] > 0.0 { phi(alpha - src[j] - self.edge_std * e, var) } else { 0.0 };
        }
        let mut ww = match clock {
            Some(c) => self.memory.combine_at(c, active, &surv[..n], &src[..n]),
            None => self.memory.combine(t, active, &surv[..n], &src[..n]),
        };
        if self.windrow_cover > 0.0 {
            ww = self.memory.with_windrows(ww, self.windrow(u, footprint_m));
        }
        // Drawn as lace, of the same area mean: the calibration holds.
        self.memory.laced(ww, u.x, u.y, footprint)
    }

    /// Mean cover of the foam streaks along the wind, `q_w` (0 when the memory has none).
    pub fn windrow_cover(&self) -> f64 {
        self.windrow_cover
    }
}

impl Sample {
    /// The lowest breaking variable that makes the point white at the point footprint.
    fn lowest(&self) -> f64 {
        self.past.iter().filter(|&&(_, s)| s >= 0.5).fold(self.x0, |m, &(x, _)| m.min(x))
    }

    /// The white cover at threshold `alpha`.
    fn white(&self, alpha: f64) -> f64 {
        let mut clear = 1.0 - phi(alpha - self.x0, self.var);
        for &(x, s) in &self.past {
            clear *= 1.0 - phi(alpha - x, self.var) * s;
        }
        1.0 - clear * (1.0 - self.windrow)
    }
}

/// Width at which the bisection of `α` stops: `10⁻⁴`, a thousandth of the spread of the breaking
/// variable (its standard deviation is above 0.1 for every sea that breaks), so the coverage moves
/// by far less than its sampling error.
const ALPHA_TOLERANCE: f64 = 1e-4;

/// Half-width of the bracket around the hard-threshold quantile in which the point footprint's
/// threshold is solved: far wider than the softening (the leftover variance is `≪ 0.1²`).
const POINT_BRACKET: f64 = 0.25;

/// The mean white cover of samples at threshold `alpha` (chunked, so the sum's order is fixed).
fn mean_white(samples: &[Sample], alpha: f64) -> f64 {
    let parts: Vec<f64> = samples.par_chunks(256).map(|c| c.iter().map(|smp| smp.white(alpha)).sum::<f64>()).collect();
    parts.iter().sum::<f64>() / samples.len().max(1) as f64
}

/// The `q`-quantile of sorted values (linear between order statistics).
fn quantile(sorted: &[f64], q: f64) -> f64 {
    if q <= 0.0 {
        return f64::NEG_INFINITY;
    }
    if q >= 1.0 {
        return f64::INFINITY;
    }
    let x = q * sorted.len() as f64 - 0.5;
    let i = (x.floor().max(0.0) as usize).min(sorted.len() - 1);
    let j = (i + 1).min(sorted.len() - 1);
    let f = (x - i as f64).clamp(0.0, 1.0);
    sorted[i] + f * (sorted[j] - sorted[i])
}

#[cfg(test)]
mod tests;
