//! A rippled sea floor as a static trochoid relief.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{WaveError, check};
use crate::{Trochoid, TrochoidSet};

/// Parameters of a rippled sea floor ([`seabed_relief`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeabedRelief {
    /// Sum of the ripples' amplitudes (m), `[0, 1000]`.
    pub amplitude_m: f64,
    /// Shortest and longest ripple wavelength (m), `0 < λ_min ≤ λ_max ≤ 10⁴`.
    pub wavelength_range_m: [f64; 2],
    /// Number of ripple trains, `[0, 256]` (0: a flat floor).
    pub waves: u32,
    /// Seed of their directions and phases.
    pub seed: u64,
}

/// A static relief of `waves` trochoid ripple trains: wavelengths log-spaced over the range,
/// amplitudes proportional to wavelength (equal slopes) summing to `amplitude_m`, steepness
/// `min(kA, 0.5)`, frequency 0, directions and phases uniform from the seed (ChaCha8).
///
/// A stand-in for sand ripples and megaripples, whose wavelength grows with their height
/// (ripple steepness `H/λ` is nearly constant for a given sediment, Nielsen 1981); it is not a
/// sediment-transport model.
///
/// # Errors
/// [`WaveError::OutOfRange`] naming the parameter out of its range.
///
/// # References
/// Nielsen P. 1981, "Dynamics and geometry of wave-generated ripples", JGR 86(C7):6467–6472
/// (ripple steepness); the trochoid profile of [`Trochoid`].
pub fn seabed_relief(p: &SeabedRelief) -> Result<TrochoidSet, WaveError> {
    check("amplitude_m", p.amplitude_m, (0.0..=1000.0).contains(&p.amplitude_m), "[0, 1000] m")?;
    let [lo, hi] = p.wavelength_range_m;
    check("wavelength_min_m", lo, lo > 0.0 && lo <= 1e4, "(0, 1e4] m")?;
    check("wavelength_max_m", hi, hi >= lo && hi <= 1e4, "[wavelength_min_m, 1e4] m")?;
    check("waves", f64::from(p.waves), p.waves <= 256, "[0, 256]")?;
    let mut rng = ChaCha8Rng::seed_from_u64(p.seed);
    let n = p.waves as usize;
    let lambdas: Vec<f64> =
        (0..n).map(|i| lo * (hi / lo).powf(if n > 1 { i as f64 / (n - 1) as f64 } else { 0.0 })).collect();
    let total: f64 = lambdas.iter().sum();
    let mut waves = Vec::with_capacity(n);
    for lambda in lambdas {
        let amplitude = p.amplitude_m * lambda / total;
        let k = std::f64::consts::TAU / lambda;
        let (dir, phase): (f64, f64) =
            (rng.random::<f64>() * std::f64::consts::TAU, rng.random::<f64>() * std::f64::consts::TAU);
        let q = (k * amplitude).min(0.5);
        waves.push(Trochoid::new(amplitude, k, dir, 0.0, phase, q)?);
    }
    Ok(TrochoidSet::new(waves))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_relief_has_its_amplitude_and_equal_slopes() {
        let p = SeabedRelief { amplitude_m: 0.3, wavelength_range_m: [0.5, 8.0], waves: 6, seed: 3 };
        let set = seabed_relief(&p).unwrap();
        assert_eq!(set.len(), 6);
        assert!((set.total_amplitude() - 0.3).abs() < 1e-12);
        let slopes: Vec<f64> = set.waves().iter().map(|w| w.wavenumber() * w.amplitude()).collect();
        assert!(slopes.iter().all(|s| (s - slopes[0]).abs() < 1e-12), "{slopes:?}");
        assert!(set.waves().iter().all(|w| w.omega() == 0.0));
        assert_eq!(seabed_relief(&p).unwrap(), set);
        assert!(seabed_relief(&SeabedRelief { waves: 0, ..p }).unwrap().is_empty());
        assert!(seabed_relief(&SeabedRelief { waves: 300, ..p }).is_err());
        assert!(seabed_relief(&SeabedRelief { wavelength_range_m: [2.0, 1.0], ..p }).is_err());
    }
}
