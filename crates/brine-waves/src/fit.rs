//! The spectrum-to-trochoid fit (Thon & Ghazanfarpour 2002, as used by Darles et al. 2007).

use std::f64::consts::TAU;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{WaveError, check};
use crate::{Spectrum, Spreading, Trochoid, TrochoidSet, wavenumber_deep_water};

/// How the fitted band `[ω_min, ω_max]` is cut into one frequency bin per wave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrequencyPartition {
    /// Bin edges equally spaced in `ln ω`; each wave sits at the geometric centre of its bin.
    /// Resolves the short waves of the tail with as many waves per decade as the peak.
    #[default]
    Logarithmic,
    /// Bins holding equal shares of `∫ S dω`; each wave sits at the bin's energy median.
    /// Every wave then has the same amplitude.
    EqualEnergy,
}

/// Options of [`fit_trochoids`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitOptions {
    /// Frequency partition.
    pub partition: FrequencyPartition,
    /// Lower band edge as a multiple of `ω_p`, `(0, omega_max_factor)`.
    pub omega_min_factor: f64,
    /// Upper band edge as a multiple of `ω_p`.
    pub omega_max_factor: f64,
    /// Mean wind (and wave) direction `θ_w` (rad) from +x toward +z.
    pub wind_direction: f64,
    /// Choppiness `c ≥ 0`: each wave's steepness is `Qᵢ = c kᵢ Aᵢ` before the cap (1 is the exact
    /// trochoid, larger values sharpen crests).
    pub choppiness: f64,
    /// Cap on `Σ Qᵢ`, `(0, 0.99]`; if the steepnesses ask for more, all are scaled by the same
    /// factor so that `Σ Qᵢ` equals the cap (the Gerstner sum then cannot fold).
    pub max_total_steepness: f64,
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
        }
    }
}

/// Fits `n_waves` trochoids to a spectrum.
///
/// 1. The band `[f_min ω_p, f_max ω_p]` is cut into `n_waves` bins ([`FrequencyPartition`]).
/// 2. Amplitude `Aᵢ = √(2 ∫_{binᵢ} S dω)` (m): the bin's exact variance, which is
///    `√(2 S(ωᵢ) Δωᵢ)` to second order, so that `Σ Aᵢ²/2 = ∫ S dω` over the band.
/// 3. `kᵢ = ωᵢ²/g` (deep water), direction `θᵢ = θ_w + δ` with `δ` drawn from the spreading
///    `D(·; ωᵢ)`, phase `φᵢ ~ U[0, 2π)`, both from a ChaCha8 generator seeded with `seed`.
/// 4. Steepness `Qᵢ = c kᵢAᵢ`, scaled down together if `Σ Qᵢ` exceeds the cap.
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
/// [`WaveError::OutOfRange`] for a bad count or option; [`WaveError::EmptyBand`] if the spectrum
/// has no energy in the band.
///
/// # References
/// Thon & Ghazanfarpour 2002 (parameters from a measured spectrum); equation sheet §1,
/// "Extraction from a spectrum".
pub fn fit_trochoids(
    spectrum: &dyn Spectrum,
    spreading: &dyn Spreading,
    n_waves: usize,
    seed: u64,
    options: &FitOptions,
) -> Result<TrochoidSet, WaveError> {
    check("n_waves", n_waves as f64, (1..=10_000).contains(&n_waves), "[1, 10000]")?;
    check("omega_min_factor", options.omega_min_factor, options.omega_min_factor > 0.0, "(0, omega_max_factor)")?;
    check(
        "omega_max_factor",
        options.omega_max_factor,
        options.omega_max_factor > options.omega_min_factor,
        "(omega_min_factor, ∞)",
    )?;
    check("wind_direction_rad", options.wind_direction, true, "finite")?;
    check("choppiness", options.choppiness, options.choppiness >= 0.0, "[0, ∞)")?;
    check(
        "max_total_steepness",
        options.max_total_steepness,
        options.max_total_steepness > 0.0 && options.max_total_steepness <= crate::MAX_STEEPNESS,
        "(0, 0.99]",
    )?;
    let omega_p = spectrum.peak_omega();
    let (w_lo, w_hi) = (options.omega_min_factor * omega_p, options.omega_max_factor * omega_p);
    let bins = match options.partition {
        FrequencyPartition::Logarithmic => logarithmic_bins(spectrum, w_lo, w_hi, n_waves),
        FrequencyPartition::EqualEnergy => equal_energy_bins(spectrum, w_lo, w_hi, n_waves),
    };
    let total: f64 = bins.iter().map(|b| b.1).sum();
    if !(total > 0.0) {
        return Err(WaveError::EmptyBand { omega_min: w_lo, omega_max: w_hi });
    }

    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut raw = Vec::with_capacity(n_waves);
    for &(omega, variance) in &bins {
        let u_dir: f64 = rng.random();
        let u_phase: f64 = rng.random();
        let amplitude = libm::sqrt(2.0 * variance);
        let k = wavenumber_deep_water(omega);
        let direction = options.wind_direction + spreading.sample(omega, u_dir);
        raw.push((amplitude, k, direction, omega, TAU * u_phase, options.choppiness * k * amplitude));
    }
    let q_sum: f64 = raw.iter().map(|w| w.5).sum();
    let scale = if q_sum > options.max_total_steepness { options.max_total_steepness / q_sum } else { 1.0 };
    let waves = raw
        .into_iter()
        .map(|(a, k, dir, w, ph, q)| Trochoid::new(a, k, dir, w, ph, (q * scale).min(crate::MAX_STEEPNESS)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(TrochoidSet::new(waves))
}

/// `(ωᵢ, ∫_{binᵢ} S dω)` for log-spaced bins.
fn logarithmic_bins(spectrum: &dyn Spectrum, w_lo: f64, w_hi: f64, n: usize) -> Vec<(f64, f64)> {
    let ratio = libm::log(w_hi / w_lo) / n as f64;
    (0..n)
        .map(|i| {
            let a = w_lo * libm::exp(ratio * i as f64);
            let b = w_lo * libm::exp(ratio * (i + 1) as f64);
            (libm::sqrt(a * b), spectrum.variance_between(a, b))
        })
        .collect()
}

/// `(ωᵢ, ∫_{binᵢ} S dω)` for bins of equal variance, from the cumulative variance tabulated on
/// 64 log-spaced Simpson panels per wave.
fn equal_energy_bins(spectrum: &dyn Spectrum, w_lo: f64, w_hi: f64, n: usize) -> Vec<(f64, f64)> {
    let m = 64 * n;
    let step = libm::log(w_hi / w_lo) / m as f64;
    let grid: Vec<f64> = (0..=m).map(|j| w_lo * libm::exp(step * j as f64)).collect();
    let mut cdf = Vec::with_capacity(m + 1);
    cdf.push(0.0);
    for j in 0..m {
        let (a, b) = (grid[j], grid[j + 1]);
        let mid = 0.5 * (a + b);
        let piece = (b - a) / 6.0 * (spectrum.s_omega(a) + 4.0 * spectrum.s_omega(mid) + spectrum.s_omega(b));
        cdf.push(cdf[j] + piece);
    }
    let total = cdf[m];
    let at = |target: f64| -> f64 {
        let j = cdf.partition_point(|&c| c < target).clamp(1, m);
        let (c0, c1) = (cdf[j - 1], cdf[j]);
        let f = if c1 > c0 { (target - c0) / (c1 - c0) } else { 0.5 };
        grid[j - 1] * libm::exp(step * f)
    };
    (0..n)
        .map(|i| {
            let median = at(total * (i as f64 + 0.5) / n as f64);
            (median, total / n as f64)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineTwoS, PiersonMoskowitz};

    fn pm10() -> (PiersonMoskowitz, CosineTwoS) {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        (pm, d)
    }

    #[test]
    fn fitted_variance_matches_the_band_integral() {
        let (pm, d) = pm10();
        for partition in [FrequencyPartition::Logarithmic, FrequencyPartition::EqualEnergy] {
            let o = FitOptions { partition, ..FitOptions::default() };
            let set = fit_trochoids(&pm, &d, 30, 7, &o).unwrap();
            let wp = pm.peak_omega();
            let band = pm.variance_between(o.omega_min_factor * wp, o.omega_max_factor * wp);
            assert!((set.variance() / band - 1.0).abs() < 0.01, "{partition:?}: {} vs {band}", set.variance());
        }
    }

    #[test]
    fn same_seed_same_set_and_steepness_cap_holds() {
        let (pm, d) = pm10();
        let o = FitOptions { choppiness: 50.0, ..FitOptions::default() };
        let a = fit_trochoids(&pm, &d, 50, 42, &o).unwrap();
        let b = fit_trochoids(&pm, &d, 50, 42, &o).unwrap();
        assert_eq!(a, b);
        assert!(a.total_steepness() <= o.max_total_steepness + 1e-12);
        let c = fit_trochoids(&pm, &d, 50, 43, &o).unwrap();
        assert_ne!(a, c);
    }
}
