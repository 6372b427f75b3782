//! The spectrum-to-trochoid fit (Thon & Ghazanfarpour 2002, as used by Darles et al. 2007).

use std::f64::consts::TAU;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::error::{WaveError, check};
use crate::spectra::integrate::simpson_log;
use crate::{Spectrum, Spreading, Trochoid, TrochoidSet};

/// How the fitted band `[ω_min, ω_max]` is cut into one frequency bin per wave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrequencyPartition {
    /// Bin edges equally spaced in `ln ω`; each wave sits at the geometric centre of its bin.
    /// Resolves the short waves of the tail with as many waves per decade as the peak.
    #[default]
    Logarithmic,
    /// Bins holding equal shares of `∫ S dω`; each wave sits at the bin's energy median.
    /// Every wave then has the same amplitude `√(2 ∫S dω / n)` ([`AmplitudeRule::BinVariance`],
    /// the only rule accepted with this partition); the tail is covered by few, wide bins.
    EqualEnergy,
    /// Bins of equal width `Δω`; each wave sits at the centre of its bin (the textbook random-phase
    /// discretisation; spends most waves on the tail).
    EqualSpacing,
}

/// How a bin's share of the spectrum becomes a wave amplitude.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum AmplitudeRule {
    /// `Aᵢ = √(2 ∫_{binᵢ} S dω)`: the bin's exact variance (Simpson's rule), so that
    /// `Σ Aᵢ²/2 = ∫ S dω` over the band to quadrature accuracy whatever the partition.
    #[default]
    BinVariance,
    /// `Aᵢ = √(2 S(ωᵢ) Δωᵢ)`, the paper's formula (midpoint rule): the same to second order in the
    /// bin width, but it misses the curvature of a sharp peak when bins are wide. Measured against
    /// an independent quadrature (`tests/analytic_limits.rs`) the fitted variance is within 1 % of
    /// `∫ S dω` from 30 log-spaced waves for all five spectra (JONSWAP, the sharpest peak, is the
    /// worst: +0.65 % at 30), but equally spaced bins need about 100 (−5 % for JONSWAP at 50).
    ///
    /// **Not defined on [`FrequencyPartition::EqualEnergy`]**: there the last bins are wide
    /// (the last of 30 spans about `2 ω_p` to the band's end) and no single `S(ωᵢ)Δωᵢ` represents
    /// them; at the energy median it overestimates the set's variance by 25–29 % at 30 waves and
    /// still 2.5–3.1 % at 200 (the five spectra here). [`fit_trochoids`] rejects that combination with
    /// [`WaveError::IncompatibleOptions`]; equal-energy bins carry `√(2 ∫S dω / n)` with
    /// [`AmplitudeRule::BinVariance`].
    Midpoint,
}

/// What the fit does when the waves' steepnesses `Qᵢ = c kᵢAᵢ` add up to more than the cap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SteepnessLimit {
    /// Scale every `Qᵢ` by the same factor `cap/ΣQᵢ`: amplitudes (hence the variance) are kept,
    /// crests become less sharp. Never fails.
    #[default]
    ScaleAll,
    /// Return [`WaveError::TooSteep`].
    Reject,
}

/// Options of [`fit_trochoids`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitOptions {
    /// Frequency partition (default logarithmic).
    pub partition: FrequencyPartition,
    /// Lower band edge as a multiple of `ω_p`, `(0, omega_max_factor)` (default 0.5).
    pub omega_min_factor: f64,
    /// Upper band edge as a multiple of `ω_p` (default 12).
    pub omega_max_factor: f64,
    /// Mean wind (and wave) direction `θ_w` (rad) from +x toward +z (default 0).
    pub wind_direction: f64,
    /// Choppiness `c ≥ 0`: each wave's steepness is `Qᵢ = c kᵢ Aᵢ` before the cap (1, the default,
    /// is the exact trochoid, larger values sharpen crests, 0 gives sinusoids).
    pub choppiness: f64,
    /// Cap on `Σ Qᵢ`, `(0, 0.99]` (default 0.9): below 1 the Gerstner sum cannot fold (equation
    /// equations.md §1). What happens above it is [`FitOptions::steepness_limit`].
    pub max_total_steepness: f64,
    /// Amplitude rule (default the bin's exact variance). [`AmplitudeRule::Midpoint`] with
    /// [`FrequencyPartition::EqualEnergy`] is refused ([`WaveError::IncompatibleOptions`]).
    pub amplitude_rule: AmplitudeRule,
    /// Behaviour when `Σ Qᵢ` exceeds the cap (default: scale all steepnesses down together).
    pub steepness_limit: SteepnessLimit,
    /// Amplification `g ≥ 1` of the high-frequency waves, Darles et al.'s "high-frequency
    /// trochoids were amplified to represent capillary waves created by the wind": every wave
    /// with `ωᵢ ≥ high_frequency_start_factor · ω_p` has its amplitude multiplied by `g`
    /// (`[1, 100]`, default 1 = off). The set's variance then exceeds `∫ S dω` by
    /// `(g² − 1)` times the amplified waves' share.
    pub high_frequency_gain: f64,
    /// Start of the amplified range as a multiple of `ω_p`, `> 0` (default 6).
    pub high_frequency_start_factor: f64,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            partition: FrequencyPartition::Logarithmic,
            omega_min_factor: 0.5,
            omega_max_factor: 12.0,
            wind_direction: 0.0,
            choppiness: 1.0,
            max_total_steepness: 0.9,
            amplitude_rule: AmplitudeRule::BinVariance,
            steepness_limit: SteepnessLimit::ScaleAll,
            high_frequency_gain: 1.0,
            high_frequency_start_factor: 6.0,
        }
    }
}

/// One frequency bin of a partition.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FrequencyBin {
    /// Lower edge (rad s⁻¹).
    pub omega_lo: f64,
    /// Upper edge (rad s⁻¹).
    pub omega_hi: f64,
    /// The wave's frequency `ωᵢ` (rad s⁻¹): geometric centre, energy median or centre.
    pub omega: f64,
    /// The bin's variance `∫_{binᵢ} S dω` (m²).
    pub variance: f64,
}

impl FrequencyBin {
    /// The wave amplitude of this bin under `rule`, before any amplification:
    /// `A = √(2 ∫_{bin} S dω)` ([`AmplitudeRule::BinVariance`]) or `A = √(2 S(ωᵢ)(ω_hi − ω_lo))`
    /// ([`AmplitudeRule::Midpoint`]; meaningful on log or equally spaced bins, see its doc).
    ///
    /// # Arguments
    /// - `spectrum`: the spectrum the bin was cut from (`S(ωᵢ)` for the midpoint rule).
    /// - `rule`: the amplitude rule.
    ///
    /// # Returns
    /// `A` (m), `≥ 0`.
    ///
    /// # References
    /// Thon & Ghazanfarpour 2002; docs/equations.md §1, "Extraction from a spectrum".
    pub fn amplitude(&self, spectrum: &dyn Spectrum, rule: AmplitudeRule) -> f64 {
        match rule {
            AmplitudeRule::BinVariance => libm::sqrt(2.0 * self.variance),
            AmplitudeRule::Midpoint => libm::sqrt(2.0 * spectrum.s_omega(self.omega) * (self.omega_hi - self.omega_lo)),
        }
    }
}

/// Cuts `[omega_lo, omega_hi]` into `n` bins and integrates the spectrum over each.
///
/// Bin variances use Simpson's rule in `ln ω` with `max(8, 4096/n)` panel pairs per bin (log and
/// equal spacing), or a cumulative table of `max(4096, 16n)` Simpson panels (equal energy, whose
/// edges are found by inverting it).
///
/// # Arguments
/// - `spectrum`: the spectrum.
/// - `partition`: see [`FrequencyPartition`].
/// - `omega_lo`, `omega_hi`: band (rad s⁻¹), `0 < omega_lo < omega_hi`.
/// - `n`: number of bins, `≥ 1`.
///
/// # Returns
/// The bins in increasing frequency.
pub fn frequency_bins(
    spectrum: &dyn Spectrum,
    partition: FrequencyPartition,
    omega_lo: f64,
    omega_hi: f64,
    n: usize,
) -> Vec<FrequencyBin> {
    debug_assert!(omega_lo > 0.0 && omega_hi > omega_lo && n >= 1);
    let pairs = (4096 / n).max(8);
    let bin = |a: f64, b: f64, omega: f64| FrequencyBin {
        omega_lo: a,
        omega_hi: b,
        omega,
        variance: simpson_log(|w| spectrum.s_omega(w), a, b, pairs),
    };
    match partition {
        FrequencyPartition::Logarithmic => {
            let step = libm::log(omega_hi / omega_lo) / n as f64;
            (0..n)
                .map(|i| {
                    let a = omega_lo * libm::exp(step * i as f64);
                    let b = if i + 1 == n { omega_hi } else { omega_lo * libm::exp(step * (i + 1) as f64) };
                    bin(a, b, libm::sqrt(a * b))
                })
                .collect()
        }
        FrequencyPartition::EqualSpacing => {
            let step = (omega_hi - omega_lo) / n as f64;
            (0..n)
                .map(|i| {
                    let a = omega_lo + step * i as f64;
                    let b = if i + 1 == n { omega_hi } else { omega_lo + step * (i + 1) as f64 };
                    bin(a, b, 0.5 * (a + b))
                })
                .collect()
        }
        FrequencyPartition::EqualEnergy => equal_energy_bins(spectrum, omega_lo, omega_hi, n),
    }
}

/// Equal-variance bins from the cumulative variance tabulated on log-spaced Simpson panels.
fn equal_energy_bins(spectrum: &dyn Spectrum, w_lo: f64, w_hi: f64, n: usize) -> Vec<FrequencyBin> {
    let m = (16 * n).max(4096);
    let step = libm::log(w_hi / w_lo) / m as f64;
    let grid: Vec<f64> = (0..=m).map(|j| w_lo * libm::exp(step * j as f64)).collect();
    let mut cdf = Vec::with_capacity(m + 1);
    cdf.push(0.0);
    let mut s_a = spectrum.s_omega(grid[0]) * grid[0];
    for j in 0..m {
        // Simpson in u = ln ω on [u_j, u_j+1]: ∫ S(ω) ω du.
        let mid = w_lo * libm::exp(step * (j as f64 + 0.5));
        let s_b = spectrum.s_omega(grid[j + 1]) * grid[j + 1];
        let piece = step / 6.0 * (s_a + 4.0 * spectrum.s_omega(mid) * mid + s_b);
        cdf.push(cdf[j] + piece);
        s_a = s_b;
    }
    let total = cdf[m];
    let at = |target: f64| -> f64 {
        if target <= 0.0 {
            return w_lo;
        }
        if target >= total {
            return w_hi;
        }
        let j = cdf.partition_point(|&c| c < target).clamp(1, m);
        let (c0, c1) = (cdf[j - 1], cdf[j]);
        let f = if c1 > c0 { (target - c0) / (c1 - c0) } else { 0.5 };
        grid[j - 1] * libm::exp(step * f)
    };
    (0..n)
        .map(|i| FrequencyBin {
            omega_lo: at(total * i as f64 / n as f64),
            omega_hi: at(total * (i + 1) as f64 / n as f64),
            omega: at(total * (i as f64 + 0.5) / n as f64),
            variance: total / n as f64,
        })
        .collect()
}

/// Fits `n_waves` trochoids to a spectrum.
///
/// 1. The band `[f_min ω_p, f_max ω_p]` is cut into `n_waves` bins ([`FrequencyPartition`]).
/// 2. Amplitude `Aᵢ = √(2 S(ωᵢ) Δωᵢ)` (m), by default as the bin's exact variance
///    `Aᵢ = √(2 ∫_{binᵢ} S dω)` so that `Σ Aᵢ²/2 = ∫ S dω` over the band ([`AmplitudeRule`]);
///    optionally amplified above `start · ω_p` ([`FitOptions::high_frequency_gain`]).
/// 3. `kᵢ = k(ωᵢ)` from the spectrum's dispersion relation ([`Spectrum::dispersion`]: deep
///    water, finite depth for TMA, capillary–gravity for Elfouhaily); direction
///    `θᵢ = θ_w + δ` with `δ` drawn from the spreading `D(·; ωᵢ)`; phase `φᵢ ~ U[0, 2π)`; both
///    from a ChaCha8 generator seeded with `seed`.
/// 4. Steepness `Qᵢ = c kᵢAᵢ`; if `Σ Qᵢ` exceeds the cap, [`SteepnessLimit`] decides (by
///    default all are scaled down together, so the surface never folds).
///
/// Transcendental functions go through `libm` and the generator is ChaCha8, so the same seed gives
/// the same set on every platform.
///
/// # Arguments
/// - `spectrum`: the frequency spectrum `S(ω)`.
/// - `spreading`: the directional spreading `D(θ; ω)`.
/// - `n_waves`: number of waves, `[1, 10 000]`.
/// - `seed`: random seed for directions and phases.
/// - `options`: see [`FitOptions`].
///
/// # Errors
/// [`WaveError::OutOfRange`] for a bad count or option; [`WaveError::IncompatibleOptions`] for
/// [`AmplitudeRule::Midpoint`] with [`FrequencyPartition::EqualEnergy`]; [`WaveError::EmptyBand`]
/// if the spectrum has no energy in the band; [`WaveError::TooSteep`] with
/// [`SteepnessLimit::Reject`].
///
/// # References
/// Thon & Ghazanfarpour 2002 (parameters from a measured spectrum); Darles et al. 2007, §3;
/// docs/equations.md §1, "Extraction from a spectrum".
pub fn fit_trochoids(
    spectrum: &dyn Spectrum,
    spreading: &dyn Spreading,
    n_waves: usize,
    seed: u64,
    options: &FitOptions,
) -> Result<TrochoidSet, WaveError> {
    let component = SeaComponent { spectrum, spreading, n_waves, options: *options };
    fit_sea_state(&[component], seed, options.max_total_steepness, options.steepness_limit)
}

/// One spectrum of a sea state: a wind sea or a swell, with its own spreading, wave count and
/// options (direction, band, partition, choppiness…).
#[derive(Clone, Copy)]
pub struct SeaComponent<'a> {
    /// The spectrum.
    pub spectrum: &'a dyn Spectrum,
    /// Its directional spreading.
    pub spreading: &'a dyn Spreading,
    /// Number of waves, `[1, 10 000]`.
    pub n_waves: usize,
    /// Its options; `max_total_steepness` and `steepness_limit` are ignored here (the cap of
    /// [`fit_sea_state`] applies to the whole set).
    pub options: FitOptions,
}

impl std::fmt::Debug for SeaComponent<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SeaComponent").field("n_waves", &self.n_waves).field("options", &self.options).finish()
    }
}

/// Fits several spectra (a wind sea and swells, each with its own direction) into one set, with
/// one steepness cap over all of them so that the combined surface cannot fold.
///
/// Component `j` draws its directions and phases from ChaCha8 seeded with `seed` on stream `j`,
/// so [`fit_trochoids`] is exactly component 0 of this function, and adding a swell does not
/// change the sea's waves (only, through the cap, their steepness).
///
/// # Arguments
/// - `components`: the spectra, at least one, at most 11 000 waves in all (a wind sea of
///   10 000 and swells of up to 1 000).
/// - `seed`: random seed.
/// - `max_total_steepness`: cap on `Σ Qᵢ` over the whole set, `(0, 0.99]`.
/// - `limit`: what to do above the cap.
///
/// # Errors
/// As [`fit_trochoids`], naming the first bad component's parameter.
///
/// # References
/// Thon & Ghazanfarpour 2002; docs/equations.md §1.
pub fn fit_sea_state(
    components: &[SeaComponent<'_>],
    seed: u64,
    max_total_steepness: f64,
    limit: SteepnessLimit,
) -> Result<TrochoidSet, WaveError> {
    check(
        "max_total_steepness",
        max_total_steepness,
        max_total_steepness > 0.0 && max_total_steepness <= crate::MAX_STEEPNESS,
        "(0, 0.99]",
    )?;
    let total_waves: usize = components.iter().map(|c| c.n_waves).sum();
    check("n_waves", total_waves as f64, (1..=MAX_TOTAL_WAVES).contains(&total_waves), "[1, 11000] in all")?;
    let mut raw = Vec::with_capacity(total_waves);
    for (j, c) in components.iter().enumerate() {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(j as u64);
        raw.extend(fit_component(c, &mut rng)?);
    }
    let q_sum: f64 = raw.iter().map(|&(_, q)| q).sum();
    let scale = if q_sum > max_total_steepness {
        match limit {
            SteepnessLimit::ScaleAll => max_total_steepness / q_sum,
            SteepnessLimit::Reject => {
                return Err(WaveError::TooSteep { total_steepness: q_sum, limit: max_total_steepness });
            }
        }
    } else {
        1.0
    };
    let waves = raw
        .into_iter()
        .map(|(w, q)| w.with_steepness((q * scale).min(crate::MAX_STEEPNESS)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(TrochoidSet::new(waves))
}

/// Most waves a fitted set may hold in all: a wind sea of 10 000 waves and swells of up to 1 000.
const MAX_TOTAL_WAVES: usize = 11_000;

fn check_options(o: &FitOptions, n_waves: usize) -> Result<(), WaveError> {
    check("n_waves", n_waves as f64, (1..=10_000).contains(&n_waves), "[1, 10000]")?;
    check("omega_min_factor", o.omega_min_factor, o.omega_min_factor > 0.0, "(0, omega_max_factor)")?;
    check("omega_max_factor", o.omega_max_factor, o.omega_max_factor > o.omega_min_factor, "(omega_min_factor, ∞)")?;
    check("wind_direction_rad", o.wind_direction, true, "finite")?;
    check("choppiness", o.choppiness, o.choppiness >= 0.0, "[0, ∞)")?;
    check("high_frequency_gain", o.high_frequency_gain, (1.0..=100.0).contains(&o.high_frequency_gain), "[1, 100]")?;
    check("high_frequency_start_factor", o.high_frequency_start_factor, o.high_frequency_start_factor > 0.0, "(0, ∞)")?;
    if o.partition == FrequencyPartition::EqualEnergy && o.amplitude_rule == AmplitudeRule::Midpoint {
        // The midpoint rule does not represent the wide tail bins of an equal-energy partition
        // (see AmplitudeRule::Midpoint): refuse rather than silently use the bin variance.
        return Err(WaveError::IncompatibleOptions {
            option: "amplitude_rule",
            value: "midpoint",
            other: "partition = equal-energy",
            reason: "S(ω)Δω misrepresents the wide tail bins of an equal-energy partition (+25–29 % \
                     variance at 30 waves); use bin-variance amplitudes, or the log or equal-spacing partition",
        });
    }
    Ok(())
}

/// The waves of one component, each with steepness 0 and, beside it, its steepness before the
/// set's cap `Q = c kA` (`c` the choppiness).
fn fit_component(c: &SeaComponent<'_>, rng: &mut ChaCha8Rng) -> Result<Vec<(Trochoid, f64)>, WaveError> {
    let o = &c.options;
    check_options(o, c.n_waves)?;
    let omega_p = c.spectrum.peak_omega();
    let (w_lo, w_hi) = (o.omega_min_factor * omega_p, o.omega_max_factor * omega_p);
    let bins = frequency_bins(c.spectrum, o.partition, w_lo, w_hi, c.n_waves);
    let total: f64 = bins.iter().map(|b| b.variance).sum();
    if !(total > 0.0) {
        return Err(WaveError::EmptyBand { omega_min: w_lo, omega_max: w_hi });
    }
    let dispersion = c.spectrum.dispersion();
    let amplified_from = o.high_frequency_start_factor * omega_p;
    // The variates in the generator's order; then each wave's direction (an inverse transform
    // of its own, 2048 density evaluations) in parallel: the same numbers at any thread count.
    let variates: Vec<(f64, f64)> = bins.iter().map(|_| (rng.random(), rng.random())).collect();
    let directions: Vec<f64> =
        bins.par_iter().zip(&variates).map(|(bin, &(u_dir, _))| c.spreading.sample(bin.omega, u_dir)).collect();
    let mut raw = Vec::with_capacity(bins.len());
    for ((bin, &(_, u_phase)), theta) in bins.iter().zip(&variates).zip(directions) {
        let gain = if bin.omega >= amplified_from { o.high_frequency_gain } else { 1.0 };
        let amplitude = gain * bin.amplitude(c.spectrum, o.amplitude_rule);
        let k = dispersion.wavenumber(bin.omega);
        let wave = Trochoid::new(amplitude, k, o.wind_direction + theta, bin.omega, TAU * u_phase, 0.0)?;
        raw.push((wave, o.choppiness * k * amplitude));
    }
    Ok(raw)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineTwoS, PiersonMoskowitz};

    /// Rounding of a sum of up to 50 steepnesses scaled by `cap/ΣQ`, or of a ratio of amplitudes.
    const ROUND_ABS: f64 = 1e-12;

    /// The mean of 10 directions drawn from cos-2s with `s = 40` (standard deviation
    /// `√(2/(s + 1))` ≈ 0.22 rad per draw, 0.07 rad for the mean): 0.3 rad is over 4 standard
    /// deviations.
    const SWELL_MEAN_DIRECTION_RAD: f64 = 0.3;

    fn pm10() -> (PiersonMoskowitz, CosineTwoS) {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        (pm, d)
    }

    #[test]
    fn same_seed_same_set_and_steepness_cap_holds() {
        let (pm, d) = pm10();
        let o = FitOptions { choppiness: 50.0, ..FitOptions::default() };
        let a = fit_trochoids(&pm, &d, 50, 42, &o).unwrap();
        let b = fit_trochoids(&pm, &d, 50, 42, &o).unwrap();
        assert_eq!(a, b);
        assert!(a.total_steepness() <= o.max_total_steepness + ROUND_ABS);
        let c = fit_trochoids(&pm, &d, 50, 43, &o).unwrap();
        assert_ne!(a, c);
    }

    #[test]
    fn reject_reports_the_total_steepness() {
        let (pm, d) = pm10();
        let o = FitOptions { choppiness: 50.0, steepness_limit: SteepnessLimit::Reject, ..FitOptions::default() };
        match fit_trochoids(&pm, &d, 50, 1, &o) {
            Err(WaveError::TooSteep { total_steepness, limit }) => assert!(total_steepness > limit),
            other => panic!("expected TooSteep, got {other:?}"),
        }
    }

    #[test]
    fn high_frequency_gain_multiplies_only_the_amplified_waves() {
        let (pm, d) = pm10();
        let plain = fit_trochoids(&pm, &d, 40, 3, &FitOptions::default()).unwrap();
        let o = FitOptions { high_frequency_gain: 3.0, high_frequency_start_factor: 4.0, ..FitOptions::default() };
        let loud = fit_trochoids(&pm, &d, 40, 3, &o).unwrap();
        let wp = pm.peak_omega();
        for (a, b) in plain.waves().iter().zip(loud.waves()) {
            let expected = if a.omega() >= 4.0 * wp { 3.0 } else { 1.0 };
            assert!((b.amplitude() / a.amplitude() - expected).abs() < ROUND_ABS);
            assert_eq!((a.direction().to_bits(), a.phase().to_bits()), (b.direction().to_bits(), b.phase().to_bits()));
        }
    }

    #[test]
    fn a_swell_does_not_change_the_sea_waves_phases() {
        let (pm, d) = pm10();
        let swell = crate::Jonswap::new(0.002, 0.4).unwrap().with_peak_shape(7.0, 0.07, 0.09).unwrap();
        let narrow = CosineTwoS::constant(40.0).unwrap();
        let sea_only = fit_trochoids(&pm, &d, 30, 9, &FitOptions::default()).unwrap();
        let both = fit_sea_state(
            &[
                SeaComponent { spectrum: &pm, spreading: &d, n_waves: 30, options: FitOptions::default() },
                SeaComponent {
                    spectrum: &swell,
                    spreading: &narrow,
                    n_waves: 10,
                    options: FitOptions { wind_direction: 1.2, omega_max_factor: 3.0, ..FitOptions::default() },
                },
            ],
            9,
            0.9,
            SteepnessLimit::ScaleAll,
        )
        .unwrap();
        assert_eq!(both.len(), 40);
        for (a, b) in sea_only.waves().iter().zip(both.waves()) {
            assert_eq!((a.amplitude().to_bits(), a.phase().to_bits()), (b.amplitude().to_bits(), b.phase().to_bits()));
        }
        let mean: f64 = both.waves()[30..].iter().map(|w| w.direction()).sum::<f64>() / 10.0;
        assert!((mean - 1.2).abs() < SWELL_MEAN_DIRECTION_RAD, "mean swell direction {mean}");
        assert!(both.total_steepness() <= 0.9 + ROUND_ABS);
    }

    #[test]
    fn bad_options_are_named() {
        let (pm, d) = pm10();
        let e = fit_trochoids(&pm, &d, 0, 1, &FitOptions::default()).unwrap_err();
        assert!(e.to_string().contains("n_waves"), "{e}");
        let o = FitOptions { high_frequency_gain: 0.5, ..FitOptions::default() };
        assert!(fit_trochoids(&pm, &d, 5, 1, &o).unwrap_err().to_string().contains("high_frequency_gain"));
        let o = FitOptions { omega_max_factor: 0.1, ..FitOptions::default() };
        assert!(fit_trochoids(&pm, &d, 5, 1, &o).unwrap_err().to_string().contains("omega_max_factor"));
    }
}
