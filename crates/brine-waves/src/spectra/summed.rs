//! A sea state of several components as one directional spectrum.

use crate::{Dispersion, Spectrum, Spreading};

/// The directional spectrum of several components (a wind sea and swells) as one spectrum and one
/// spreading: `S(ω) = Σᵢ Sᵢ(ω)` and `D(θ; ω) = Σᵢ Sᵢ(ω) Dᵢ(θ − Δᵢ; ω) / S(ω)`, `Δᵢ` the direction of
/// component `i` relative to the first (the wind), so that `S(ω) D(θ; ω)` is the sum of the
/// components' directional spectra exactly (what the FFT sea draws its amplitudes from). The
/// dispersion relation is the first component's.
///
/// # References
/// Linear superposition of independent wave systems (Holthuijsen 2007, *Waves in Oceanic and
/// Coastal Waters*, §3.5).
pub struct SummedSpectrum<'a> {
    spectra: &'a [Box<dyn Spectrum>],
    spreadings: &'a [Box<dyn Spreading>],
    offsets: Vec<f64>,
}

impl<'a> SummedSpectrum<'a> {
    /// The sum of `spectra[i]` spread by `spreadings[i]` around the directions `directions[i]`
    /// (rad, from +x toward +z; relative to the first).
    ///
    /// # Panics
    /// If the three slices differ in length or are empty (a programming error).
    pub fn new(spectra: &'a [Box<dyn Spectrum>], spreadings: &'a [Box<dyn Spreading>], directions: &[f64]) -> Self {
        assert!(!spectra.is_empty() && spectra.len() == spreadings.len() && spectra.len() == directions.len());
        let first = directions[0];
        Self { spectra, spreadings, offsets: directions.iter().map(|d| d - first).collect() }
    }
}

impl Spectrum for SummedSpectrum<'_> {
    fn s_omega(&self, omega: f64) -> f64 {
        self.spectra.iter().map(|s| s.s_omega(omega)).sum()
    }

    /// The lowest peak (the swell's, usually): the largest FFT tile is sized on it.
    fn peak_omega(&self) -> f64 {
        self.spectra.iter().map(|s| s.peak_omega()).fold(f64::INFINITY, f64::min)
    }

    fn dispersion(&self) -> Dispersion {
        self.spectra[0].dispersion()
    }
}

impl Spreading for SummedSpectrum<'_> {
    fn density(&self, theta: f64, omega: f64) -> f64 {
        let (mut num, mut den) = (0.0, 0.0);
        for ((s, d), off) in self.spectra.iter().zip(self.spreadings).zip(&self.offsets) {
            let si = s.s_omega(omega);
            if si > 0.0 {
                // θ − Δ wrapped to (−π, π].
                let rel =
                    std::f64::consts::PI - (std::f64::consts::PI - (theta - off)).rem_euclid(std::f64::consts::TAU);
                num += si * d.density(rel, omega);
                den += si;
            }
        }
        if den > 0.0 { num / den } else { self.spreadings[0].density(theta, omega) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineTwoS, Jonswap, PiersonMoskowitz};

    /// `S(ω) D(θ; ω)` is the sum of the components' directional spectra, and `D` integrates to 1.
    #[test]
    fn the_sum_is_the_sum_of_the_components() {
        let sea = PiersonMoskowitz::from_u10(10.0).unwrap();
        let swell = Jonswap::swell(2.0, 12.0, 5.0).unwrap();
        let spectra: Vec<Box<dyn Spectrum>> = vec![Box::new(sea), Box::new(swell)];
        let spreadings: Vec<Box<dyn Spreading>> = vec![
            Box::new(CosineTwoS::hasselmann(sea.peak_omega()).unwrap()),
            Box::new(CosineTwoS::constant(20.0).unwrap()),
        ];
        let sum = SummedSpectrum::new(&spectra, &spreadings, &[0.3, 1.1]);
        for omega in [0.4, 0.6, 0.9, 1.5] {
            for theta in [-2.0, -0.2, 0.0, 0.8, 3.0] {
                let parts: f64 = spectra
                    .iter()
                    .zip(&spreadings)
                    .zip([0.0, 0.8])
                    .map(|((s, d), off)| {
                        let rel = std::f64::consts::PI
                            - (std::f64::consts::PI - (theta - off)).rem_euclid(std::f64::consts::TAU);
                        s.s_omega(omega) * d.density(rel, omega)
                    })
                    .sum();
                let whole = sum.s_omega(omega) * sum.density(theta, omega);
                assert!((whole - parts).abs() <= 1e-12 * parts.abs().max(1e-12), "{omega} {theta}");
            }
            // ∫ D dθ = 1 (midpoint rule over 2000 steps).
            let n = 2000;
            let h = std::f64::consts::TAU / f64::from(n);
            let total: f64 =
                (0..n).map(|i| sum.density(-std::f64::consts::PI + (f64::from(i) + 0.5) * h, omega) * h).sum();
            assert!((total - 1.0).abs() < 1e-3, "{total}");
        }
        assert!((sum.peak_omega() - swell.peak_omega()).abs() < 1e-12);
    }
}
