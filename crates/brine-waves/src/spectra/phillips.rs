//! The Phillips spectrum of Tessendorf's FFT ocean.

use std::f64::consts::PI;

use crate::error::{WaveError, check};
use crate::spectra::dispersion::G;
use crate::{PiersonMoskowitz, Spectrum};

/// The Phillips spectrum as Tessendorf (2001) uses it, with its small-wave cutoff.
///
/// Directional form per unit `d²k` (m⁴): `P_h(k) = A exp(−1/(kL)²)/k⁴ · |k̂·ŵ|² · exp(−k²ℓ²)`,
/// `L = V²/g` the largest wave a wind `V` makes, `ℓ ≪ L` the small-wave cutoff. Integrating
/// `|k̂·ŵ|² = cos²θ` over all directions (`π`) gives the omnidirectional wavenumber spectrum
/// `S(k) = π A exp(−1/(kL)²) exp(−k²ℓ²)/k³` (m³) and, in deep water,
/// `S(ω) = S(k) 2ω/g ∝ ω⁻⁵ exp[−(g/V)⁴/ω⁴ − ℓ²ω⁴/g²]` (m² s rad⁻¹).
///
/// `A` is a free scale in Tessendorf; here it is dimensionless and defaults to
/// `α/(2π) = 1.289×10⁻³` (`α = 8.1×10⁻³`, Phillips' constant), which gives the same `k⁻³`
/// saturation range as Pierson–Moskowitz: with `ℓ = 0` this spectrum *is* Pierson–Moskowitz
/// with `β = 1` and `U₁₉.₅ = V`.
///
/// The `|k̂·ŵ|²` factor keeps up- and down-wind waves alike; its directional distribution is
/// [`crate::CosineSquared::both_ways`].
///
/// # References
/// Tessendorf J. 2001, "Simulating Ocean Water", SIGGRAPH course notes, §3.3 (Eq. 40–41);
/// Phillips O.M. 1958, JFM 4; docs/equations.md §4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phillips {
    wind_speed: f64,
    scale: f64,
    cutoff: f64,
}

impl Phillips {
    /// Default scale `A = α/(2π)` (dimensionless), matching Pierson–Moskowitz's `k⁻³` range.
    pub const DEFAULT_SCALE: f64 = PiersonMoskowitz::ALPHA / (2.0 * PI);
    /// Default small-wave cutoff `ℓ/L = 10⁻³` (the usual choice in Tessendorf-style codes).
    pub const DEFAULT_CUTOFF_RATIO: f64 = 1e-3;

    /// The spectrum of a wind `V` with the default scale `A = α/(2π)` and cutoff `ℓ = 10⁻³ L`.
    ///
    /// # Arguments
    /// - `wind_speed`: wind speed `V` (m s⁻¹), `(0, 60]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a wind outside `(0, 60]` m s⁻¹.
    pub fn from_wind(wind_speed: f64) -> Result<Self, WaveError> {
        let v = check("wind_speed_m_s", wind_speed, wind_speed > 0.0 && wind_speed <= 60.0, "(0, 60] m/s")?;
        Self::new(v, Self::DEFAULT_SCALE, Self::DEFAULT_CUTOFF_RATIO * v * v / G)
    }

    /// The spectrum with an explicit scale and cutoff.
    ///
    /// # Arguments
    /// - `wind_speed`: wind speed `V` (m s⁻¹), `(0, 60]`.
    /// - `scale`: `A` (dimensionless), `(0, 1]`.
    /// - `small_wave_cutoff_m`: `ℓ` (m), `[0, L)` with `L = V²/g` (0 disables the cutoff).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn new(wind_speed: f64, scale: f64, small_wave_cutoff_m: f64) -> Result<Self, WaveError> {
        let v = check("wind_speed_m_s", wind_speed, wind_speed > 0.0 && wind_speed <= 60.0, "(0, 60] m/s")?;
        let scale = check("scale", scale, scale > 0.0 && scale <= 1.0, "(0, 1]")?;
        let l = v * v / G;
        let cutoff = check(
            "small_wave_cutoff_m",
            small_wave_cutoff_m,
            small_wave_cutoff_m >= 0.0 && small_wave_cutoff_m < l,
            "[0, V²/g) m",
        )?;
        Ok(Self { wind_speed: v, scale, cutoff })
    }

    /// Wind speed `V` (m s⁻¹).
    pub fn wind_speed(&self) -> f64 {
        self.wind_speed
    }

    /// `L = V²/g` (m), the largest wave the wind makes.
    pub fn largest_wave(&self) -> f64 {
        self.wind_speed * self.wind_speed / G
    }

    /// Scale `A` (dimensionless).
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Small-wave cutoff `ℓ` (m).
    pub fn small_wave_cutoff(&self) -> f64 {
        self.cutoff
    }

    /// The directional spectrum `P_h(k) = A exp(−1/(kL)²)/k⁴ |k̂·ŵ|² exp(−k²ℓ²)` (m⁴).
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    /// - `theta`: angle of the wave vector from the wind (rad).
    ///
    /// # Returns
    /// `P_h` (m⁴, variance per unit `d²k`); `∫∫ P_h k dk dθ = m₀`.
    ///
    /// # References
    /// Tessendorf 2001, §3.3, Eq. 40–41.
    pub fn directional(&self, k: f64, theta: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let c = libm::cos(theta);
        self.envelope(k) / (k * k * k * k) * c * c
    }

    /// `A exp(−1/(kL)²) exp(−k²ℓ²)`.
    fn envelope(&self, k: f64) -> f64 {
        let kl = k * self.largest_wave();
        self.scale * libm::exp(-1.0 / (kl * kl) - k * k * self.cutoff * self.cutoff)
    }
}

impl Spectrum for Phillips {
    /// `S(ω) = S(k) dk/dω`, `k = ω²/g`, `dk/dω = 2ω/g`.
    fn s_omega(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        self.s_k(omega * omega / G) * 2.0 * omega / G
    }

    /// Maximum of `S(ω) ∝ ω⁻⁵ exp[−ω₀⁴/ω⁴ − ℓ²ω⁴/g²]`, `ω₀ = g/V`: with `x = ω⁴`,
    /// `(4ℓ²/g²) x² + 5x − 4ω₀⁴ = 0`, so `x = (√(25 + 64 ℓ²ω₀⁴/g²) − 5)/(8ℓ²/g²)`
    /// (`x = 4ω₀⁴/5` without cutoff).
    fn peak_omega(&self) -> f64 {
        let w0 = G / self.wind_speed;
        let w04 = libm::pow(w0, 4.0);
        let c = self.cutoff * self.cutoff / (G * G);
        let x = if c * w04 < 1e-12 {
            // Series of the root for a vanishing cutoff: x = (4/5)ω₀⁴ (1 − 0.64 c ω₀⁴ + …), c = ℓ²/g².
            0.8 * w04 * (1.0 - 0.64 * c * w04)
        } else {
            (libm::sqrt(25.0 + 64.0 * c * w04) - 5.0) / (8.0 * c)
        };
        libm::pow(x, 0.25)
    }

    /// `S(k) = π A exp(−1/(kL)²) exp(−k²ℓ²)/k³` (m³): `P_h` integrated over direction.
    fn s_k(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        PI * self.envelope(k) / (k * k * k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reference prints `L = 10.194` m: half a unit of the last decimal.
    const PRINTED_3_DECIMALS_M: f64 = 5e-4;

    /// The midpoint rule on a trigonometric polynomial over its period is exact up to rounding
    /// (4000 terms of ~ε each).
    const PERIODIC_MIDPOINT_REL: f64 = 1e-12;

    #[test]
    fn largest_wave_oracle() {
        // Reference value (docs/equations.md): V = 10 m/s ⇒ L = 10.194 m.
        let p = Phillips::from_wind(10.0).unwrap();
        assert!((p.largest_wave() - 10.194).abs() < PRINTED_3_DECIMALS_M);
    }

    #[test]
    fn directional_form_integrates_to_the_omnidirectional_one() {
        let p = Phillips::from_wind(8.0).unwrap();
        let k = 0.7;
        let n = 4000;
        let h = 2.0 * PI / n as f64;
        let s: f64 = (0..n).map(|j| p.directional(k, -PI + (j as f64 + 0.5) * h) * k * h).sum();
        assert!((s / p.s_k(k) - 1.0).abs() < PERIODIC_MIDPOINT_REL);
    }

    #[test]
    fn peak_is_the_maximum_of_s_omega() {
        for (v, l) in [(10.0, 0.0), (10.0, 0.5), (5.0, 0.01)] {
            let p = Phillips::new(v, Phillips::DEFAULT_SCALE, l).unwrap();
            let wp = p.peak_omega();
            let s = p.s_omega(wp);
            assert!(s >= p.s_omega(wp * 1.0001) && s >= p.s_omega(wp * 0.9999), "V = {v}, ℓ = {l}");
        }
    }

    #[test]
    fn bad_cutoff_is_named() {
        assert!(Phillips::new(10.0, 0.001, 20.0).unwrap_err().to_string().contains("small_wave_cutoff_m"));
    }
}
