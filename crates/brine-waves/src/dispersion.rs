//! Dispersion relations of surface gravity waves.

/// Standard gravity `g` (m s⁻²), the value of the equation sheet.
pub const G: f64 = 9.81;

/// Angular frequency of a deep-water gravity wave, `ω = √(g k)`.
///
/// # Arguments
/// - `k`: wavenumber (rad m⁻¹), `k ≥ 0`.
///
/// # Returns
/// `ω` (rad s⁻¹).
///
/// # References
/// Airy linear wave theory, deep-water limit `kh → ∞` of `ω² = g k tanh(k h)`; equation sheet §1.
pub fn omega_deep_water(k: f64) -> f64 {
    debug_assert!(k >= 0.0, "wavenumber must be non-negative, got {k}");
    (G * k).sqrt()
}

/// Wavenumber of a deep-water gravity wave of angular frequency `ω`, `k = ω²/g`.
///
/// # Arguments
/// - `omega`: angular frequency (rad s⁻¹), `ω ≥ 0`.
///
/// # Returns
/// `k` (rad m⁻¹); the wavelength is `λ = 2π/k`.
///
/// # References
/// Inverse of [`omega_deep_water`]; equation sheet §1.
pub fn wavenumber_deep_water(omega: f64) -> f64 {
    debug_assert!(omega >= 0.0, "angular frequency must be non-negative, got {omega}");
    omega * omega / G
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_100_m_wave_has_an_8_s_period() {
        // λ = 100 m ⇒ T = √(2πλ/g) = √(628.3185/9.81) = 8.0030 s.
        let k = 2.0 * std::f64::consts::PI / 100.0;
        let t = 2.0 * std::f64::consts::PI / omega_deep_water(k);
        assert!((t - 8.0030).abs() < 1e-4, "T = {t}");
        assert!((wavenumber_deep_water(omega_deep_water(k)) - k).abs() < 1e-15);
    }
}
