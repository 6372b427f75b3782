//! Foam in time: foam that moves with the water and ages between frames.

use crate::error::{FoamError, check};
use crate::radiance::KoepkeFoam;

/// Largest number of past instants a [`FoamHistory`] reads.
pub const MAX_HISTORY_SAMPLES: usize = 256;

/// Parameters of the foam history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoamHistoryParams {
    /// E-folding time of the foam area `τ` (s), `(0, 60]`. Callaghan et al. (2012) observe
    /// whitecap foam areas decaying exponentially with `τ` from 0.5 to 8 s; default 4 s.
    pub decay_time_s: f64,
    /// Spacing `Δt` of the global time lattice at which the foam source is read (s),
    /// `(0, decay_time_s]`; default 1 s.
    pub step_s: f64,
    /// Length of the history in decay times `T/τ`, `[1, 10]`; default 4 (foam older than
    /// `4τ` keeps under 2 % of its area and is dropped).
    pub length_in_decay_times: f64,
    /// Foam drift relative to the water particles `(v_x, v_z)` (m s⁻¹), each within ±5; e.g. a
    /// wind drift of ~3 % of `U₁₀` downwind. Default zero: the foam stays on its particles.
    pub drift_m_s: [f64; 2],
}

impl Default for FoamHistoryParams {
    fn default() -> Self {
        Self { decay_time_s: 4.0, step_s: 1.0, length_in_decay_times: 4.0, drift_m_s: [0.0, 0.0] }
    }
}

/// Checks the time lattice shared by [`FoamHistory`] and [`crate::FoamMemory`]: the decay time
/// `τ` in `(0, 60]` s, the step in `(0, τ]`, the length in decay times within `length.1` (named
/// by `length.2`), each drift component within ±5 m s⁻¹. Returns `(τ, Δt, T/τ)`.
pub(crate) fn check_lattice(
    decay_time_s: f64,
    step_s: f64,
    length: (f64, (f64, f64), &'static str),
    drift_m_s: [f64; 2],
) -> Result<(f64, f64, f64), FoamError> {
    let tau = check("decay_time_s", decay_time_s, decay_time_s > 0.0 && decay_time_s <= 60.0, "(0, 60] s")?;
    let step = check("step_s", step_s, step_s > 0.0 && step_s <= tau, "(0, decay_time_s] s")?;
    let (ratio, (lo, hi), range) = length;
    let ratio = check("length_in_decay_times", ratio, (lo..=hi).contains(&ratio), range)?;
    for (name, v) in [("drift_x_m_s", drift_m_s[0]), ("drift_z_m_s", drift_m_s[1])] {
        check(name, v, v.abs() <= 5.0, "[-5, 5] m/s")?;
    }
    Ok((tau, step, ratio))
}

/// One past instant read by [`FoamHistory::accumulate`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoamSample {
    /// The lattice instant `tⱼ = Δt (⌊t/Δt⌋ − j)` (s).
    pub time_s: f64,
    /// Age of foam created then, `t − tⱼ` (s).
    pub age_s: f64,
    /// Offset to add to the undisplaced (rest) coordinates `(x, z)` of the current water particle
    /// to find where that foam was created: `−drift · age` (m).
    pub rest_offset_m: [f64; 2],
    /// Kernel weight `K(age)` (dimensionless, `≥ 0`).
    pub weight: f64,
}

/// Foam cover, brightness and age at one surface point and instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoamState {
    /// Fraction of the point's area covered by foam, `[0, 1]`.
    pub cover: f64,
    /// Reflectance of that foam relative to fresh foam, `ρ ∈ (0, 1]`: the foam reflectance is
    /// `R_f ρ`. 1 where there is no foam.
    pub brightness: f64,
    /// Cover-weighted mean age of the foam (s), `≥ 0`; 0 where there is no foam.
    pub mean_age_s: f64,
}

/// Foam advected with the surface and aged between frames — a stateless, deterministic filter.
///
/// Foam is attached to water particles, i.e. keyed by the undisplaced (rest) coordinates `u` of
/// the Gerstner map, so it follows the orbital motion for free; a crest passing by leaves its
/// foam behind. At each point the foam is a causal exponential moving average of the
/// instantaneous foam amount `s′(u, t)` (Darles Eq. 4, [`crate::FoamExtension`]) read at the
/// instants `tⱼ` of a global lattice of step `Δt`:
///
/// `cover(u, t) = Σⱼ K(aⱼ) s′(u − v aⱼ, tⱼ) / Σⱼ K(aⱼ)`, `aⱼ = t − tⱼ`,
/// `K(a) = min(a/Δt, 1) · min((T − a)/Δt, 1) · e^{−a/τ}` on `[0, T]`,
///
/// i.e. foam is created in proportion to `s′`, its area decays as `e^{−a/τ}` (the exponential
/// decay of whitecap foam measured by Callaghan et al. 2012), and it drifts at `v` relative to the
/// water. Its reflectance fades as `e^{−a/τ_R}`:
/// `ρ(u, t) = Σⱼ K(aⱼ) s′ⱼ e^{−aⱼ/τ_R} / Σⱼ K(aⱼ) s′ⱼ`, where `τ_R` is solved in the constructor so
/// that over a steady sea the cover-weighted mean of `ρ` equals Koepke's efficiency `f_ef`: the
/// mean foam reflectance is then exactly Koepke's `R_ef = f_ef R_f`, and the mean cover stays the
/// Monahan `W` (the weights are normalised).
///
/// The ramps at both ends of `K` make the result continuous in `t` as lattice instants enter and
/// leave. Because it is a pure function of `(u, t)` and the lattice is global, the same point at
/// the same time gets the same foam whatever the frame order, thread count or camera — unlike
/// the image-space texture of Darles et al. (§4.1.2), which depends on the previous frame.
///
/// Cost: one evaluation of `s′` per lattice instant (`T/Δt + 1`, 17 with the defaults).
///
/// # References
/// Darles et al. 2007 §4.1.2 (foam positions and ages kept between frames; its age term
/// `0.4 − 0.2 t·10⁻²` is replaced by this explicit model, docs/equations.md §5); Koepke 1984
/// (`f_ef`); Callaghan A., Deane G., Stokes M. 2012, "Observed variation in the decay time of
/// oceanic whitecap foam", JGR 117, C09015 (`τ` from 0.5 to 8 s).
#[derive(Debug, Clone, PartialEq)]
pub struct FoamHistory {
    tau: f64,
    tau_r: f64,
    step: f64,
    length: f64,
    count: usize,
    drift: [f64; 2],
}

impl FoamHistory {
    /// Checks the parameters and solves the brightness decay time `τ_R` for Koepke's `f_ef`.
    ///
    /// `τ_R` solves `⟨Σⱼ K(aⱼ) e^{−aⱼ/τ_R}⟩ / ⟨Σⱼ K(aⱼ)⟩ = f_ef` (means over the phase of `t`
    /// within a lattice step, 64 sub-steps), by 100 bisections in `ln τ_R` on `[10⁻⁴ τ, 10⁴ τ]`.
    ///
    /// # Arguments
    /// - `params`: [`FoamHistoryParams`] — `decay_time_s` `τ` (s, `(0, 60]`), `step_s` `Δt` (s,
    ///   `(0, τ]`), `length_in_decay_times` `T/τ` (`[1, 10]`), `drift_m_s` (m s⁻¹, each `[−5, 5]`).
    /// - `koepke`: the reflectance model whose efficiency `f_ef` sets `τ_R`.
    ///
    /// # Returns
    /// The history, reading `⌈(T/τ) τ/Δt⌉ + 1` lattice instants per evaluation.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the parameter, including a history needing more than
    /// [`MAX_HISTORY_SAMPLES`] instants.
    ///
    /// # References
    /// Callaghan, Deane & Stokes 2012 (`τ` from 0.5 to 8 s); Koepke 1984 (`f_ef`); Darles et al.
    /// 2007 §4.1.2; docs/equations.md §5 (explicit age model instead of `0.4 − 0.2 t·10⁻²`).
    pub fn new(params: &FoamHistoryParams, koepke: &KoepkeFoam) -> Result<Self, FoamError> {
        let (tau, step, ratio) = check_lattice(
            params.decay_time_s,
            params.step_s,
            (params.length_in_decay_times, (1.0, 10.0), "[1, 10]"),
            params.drift_m_s,
        )?;
        let count = (ratio * tau / step).ceil() as usize + 1;
        if count > MAX_HISTORY_SAMPLES {
            return Err(FoamError::OutOfRange(brine_core::OutOfRange {
                name: "step_s",
                value: step,
                range: "at least length_in_decay_times · decay_time_s / 255 s (at most 256 instants)",
            }));
        }
        let length = step * (count - 1) as f64;
        let mut history = Self { tau, tau_r: tau, step, length, count, drift: params.drift_m_s };
        history.tau_r = history.solve_brightness_decay(koepke.efficiency());
        Ok(history)
    }

    /// Foam-area decay time `τ` (s).
    pub fn decay_time(&self) -> f64 {
        self.tau
    }

    /// Brightness decay time `τ_R` (s) that makes the mean reflectance `f_ef R_f`.
    pub fn brightness_decay_time(&self) -> f64 {
        self.tau_r
    }

    /// Number of lattice instants read per evaluation.
    pub fn sample_count(&self) -> usize {
        self.count
    }

    /// Kernel `K(a)` (dimensionless) of foam of age `a` (s).
    fn kernel(&self, age: f64) -> f64 {
        if !(0.0..=self.length).contains(&age) {
            return 0.0;
        }
        (age / self.step).min(1.0) * ((self.length - age) / self.step).min(1.0) * libm::exp(-age / self.tau)
    }

    /// The lattice instants read at time `t`, youngest first.
    ///
    /// `tⱼ = Δt (⌊t/Δt⌋ − j)`, `aⱼ = t − tⱼ`, offset `−v aⱼ`, weight `K(aⱼ)`, for
    /// `j = 0 … sample_count() − 1`.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// [`Self::sample_count`] [`FoamSample`]s (times and ages in s, offsets in m, weights
    /// dimensionless `≥ 0`).
    ///
    /// # References
    /// See [`FoamHistory`].
    pub fn samples(&self, t: f64) -> impl Iterator<Item = FoamSample> + '_ {
        debug_assert!(t.is_finite());
        let newest = (t / self.step).floor();
        (0..self.count).map(move |j| {
            let time_s = (newest - j as f64) * self.step;
            let age_s = (t - time_s).max(0.0);
            FoamSample {
                time_s,
                age_s,
                rest_offset_m: [-self.drift[0] * age_s, -self.drift[1] * age_s],
                weight: self.kernel(age_s),
            }
        })
    }

    /// Foam cover, brightness and mean age at time `t` of the water particle whose foam source is
    /// `source`.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    /// - `source`: returns the instantaneous foam amount `s′ ∈ [0, 1]` for a lattice instant;
    ///   evaluate it at the particle's rest coordinates plus [`FoamSample::rest_offset_m`] and at
    ///   [`FoamSample::time_s`].
    ///
    /// # Returns
    /// The [`FoamState`]; `cover` is in `[0, 1]`.
    ///
    /// # References
    /// See [`FoamHistory`] (Darles et al. 2007 §4.1.2; Koepke 1984; Callaghan et al. 2012).
    pub fn accumulate(&self, t: f64, mut source: impl FnMut(&FoamSample) -> f64) -> FoamState {
        let (mut wsum, mut cover, mut bright, mut age) = (0.0, 0.0, 0.0, 0.0);
        for s in self.samples(t) {
            if s.weight <= 0.0 {
                continue;
            }
            let amount = source(&s).clamp(0.0, 1.0);
            wsum += s.weight;
            let c = s.weight * amount;
            cover += c;
            bright += c * libm::exp(-s.age_s / self.tau_r);
            age += c * s.age_s;
        }
        if cover <= 0.0 || wsum <= 0.0 {
            return FoamState { cover: 0.0, brightness: 1.0, mean_age_s: 0.0 };
        }
        // Amounts ≤ 1 and brightnesses e^{−a/τ_R} ≤ 1 weigh in: cover ≤ Σ w and bright ≤ cover but
        // for rounding, which alone the clamps absorb.
        debug_assert!(cover <= wsum * (1.0 + SUM_ROUNDING) && bright <= cover * (1.0 + SUM_ROUNDING));
        FoamState {
            cover: (cover / wsum).clamp(0.0, 1.0),
            brightness: (bright / cover).clamp(0.0, 1.0),
            mean_age_s: age / cover,
        }
    }

    /// Mean brightness over a steady foam source, averaged over the position of `t` within a
    /// lattice step (64 sub-steps), for a brightness decay time `tau_r`.
    fn steady_brightness(&self, tau_r: f64) -> f64 {
        let m = 64;
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..m {
            let t = self.step * (i as f64 + 0.5) / m as f64;
            for s in self.samples(t) {
                num += s.weight * libm::exp(-s.age_s / tau_r);
                den += s.weight;
            }
        }
        num / den
    }

    /// Solves `steady_brightness(τ_R) = f_ef` by bisection in `ln τ_R` (the left side increases
    /// with `τ_R` from 0 to 1).
    fn solve_brightness_decay(&self, efficiency: f64) -> f64 {
        let (mut lo, mut hi) = (libm::log(self.tau * 1e-4), libm::log(self.tau * 1e4));
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if self.steady_brightness(libm::exp(mid)) < efficiency {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        libm::exp(0.5 * (lo + hi))
    }
}

/// Rounding of the history's weighted sums (a few dozen terms) relative to their size.
const SUM_ROUNDING: f64 = 1e-12;

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounding of a normalised sum of 17 weighted terms of order 1.
    const SUM_ROUNDING: f64 = 1e-12;

    /// The mean brightness over 1000 instants (7.3 steps) against the constructor's 64-phase
    /// average, and the continuous kernel integral (midpoint, 10⁵ points) against it: both
    /// quadratures agree to ~10⁻⁵ (the phase average has kinks where instants enter and leave).
    const PHASE_AVERAGE: f64 = 1e-3;

    /// Exactly zero up to the rounding of `0/Σ K`.
    const NO_FOAM: f64 = 1e-15;

    /// Largest change of the cover over 1 ms for a source varying at 0.7 rad/s and kernel ramps
    /// one step long: the ramps change the weights at a rate ≤ 1/Δt relative, i.e. ≤ 10⁻³ per
    /// millisecond, plus the source's own 0.35 × 10⁻³; 2×10⁻³ bounds a jump-free cover.
    const CONTINUITY_PER_MS: f64 = 2e-3;

    #[test]
    fn steady_source_keeps_cover_and_gives_koepke_brightness() {
        let h = FoamHistory::new(&FoamHistoryParams::default(), &KoepkeFoam::default()).unwrap();
        let (mut b, m) = (0.0, 1000);
        for i in 0..m {
            let t = 100.0 + 7.3 * i as f64 / m as f64;
            let s = h.accumulate(t, |_| 0.3);
            assert!((s.cover - 0.3).abs() < SUM_ROUNDING);
            b += s.brightness;
        }
        // The constructor solves τ_R on a 64-point average over a step; this average uses 1000
        // points over 7.3 steps, so the two means agree to the quadrature error (< 1e-4).
        assert!((b / m as f64 - KOEPKE_EFFICIENCY_FOR_TEST).abs() < PHASE_AVERAGE, "{}", b / m as f64);
        // Averaged over the phase of t within a step, the lattice sum is the continuous
        // integral ∫ K(a) e^{−a/τ_R} da / ∫ K(a) da: check the solved τ_R against it (midpoint
        // rule, 10⁵ points: error < 1e-8).
        let (tau, tau_r, len) = (4.0, h.brightness_decay_time(), 16.0);
        let kernel = |a: f64| a.min(1.0) * (len - a).min(1.0) * (-a / tau).exp();
        let n = 100_000;
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..n {
            let a = len * (i as f64 + 0.5) / n as f64;
            num += kernel(a) * (-a / tau_r).exp();
            den += kernel(a);
        }
        assert!((num / den - KOEPKE_EFFICIENCY_FOR_TEST).abs() < PHASE_AVERAGE, "{}", num / den);
        // Without ramps and truncation, ρ̄ = τ_R/(τ + τ_R) gives τ_R = τ f_ef/(1 − f_ef) = 2.67 s;
        // the ramp at age 0 shifts foam older, so τ_R is longer.
        assert!(tau_r > 4.0 * 0.4 / 0.6);
    }

    const KOEPKE_EFFICIENCY_FOR_TEST: f64 = crate::radiance::KOEPKE_EFFICIENCY;

    #[test]
    fn foam_created_once_decays_with_tau() {
        let h = FoamHistory::new(&FoamHistoryParams::default(), &KoepkeFoam::default()).unwrap();
        // A single burst of foam at the instant t = 10 s.
        let burst = |s: &FoamSample| if (s.time_s - 10.0).abs() < 1e-9 { 1.0 } else { 0.0 };
        let c1 = h.accumulate(12.0, burst).cover;
        let c2 = h.accumulate(14.0, burst).cover;
        // Between ages 2 s and 4 s (both inside the ramps' flat part) the kernel ratio is
        // e^{−2/τ}; the normalisation Σ K is periodic in t with period Δt, so it cancels.
        assert!((c2 / c1 - (-2.0f64 / 4.0).exp()).abs() < SUM_ROUNDING, "{}", c2 / c1);
        assert!(h.accumulate(9.99, burst).cover.abs() < NO_FOAM);
        assert!(h.accumulate(10.0 + 17.0, burst).cover.abs() < NO_FOAM);
    }

    #[test]
    fn continuous_in_time() {
        let h = FoamHistory::new(&FoamHistoryParams::default(), &KoepkeFoam::default()).unwrap();
        let src = |s: &FoamSample| 0.5 + 0.5 * (0.7 * s.time_s).sin();
        let mut prev = h.accumulate(0.0, src).cover;
        for i in 1..4000 {
            let c = h.accumulate(i as f64 * 0.001, src).cover;
            assert!((c - prev).abs() < CONTINUITY_PER_MS, "jump {} at {}", c - prev, i as f64 * 0.001);
            prev = c;
        }
    }

    #[test]
    fn bad_parameters_are_named() {
        let p = FoamHistoryParams { step_s: 5.0, ..FoamHistoryParams::default() };
        assert!(FoamHistory::new(&p, &KoepkeFoam::default()).unwrap_err().to_string().contains("step_s"));
        let p = FoamHistoryParams { step_s: 0.001, ..FoamHistoryParams::default() };
        assert!(FoamHistory::new(&p, &KoepkeFoam::default()).is_err());
    }
}
