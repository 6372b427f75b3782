//! Slope variance that waves too small to be drawn add to the BRDF (Bruneton et al. 2010 §4).

/// One unresolved wave component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveComponent {
    /// Amplitude `A` (m), `≥ 0`.
    pub amplitude_m: f64,
    /// Wavenumber `k` (rad m⁻¹), `> 0`.
    pub wavenumber: f64,
    /// Direction of travel relative to the wind (the BRDF's x axis), `θ` (rad).
    pub angle_from_wind_rad: f64,
}

/// Slope variances `(σx², σy²)` of a sum of sine waves with independent phases:
/// `σx² = Σ ½ A_i² k_i² cos²θ_i`, `σy² = Σ ½ A_i² k_i² sin²θ_i`.
///
/// # Arguments
/// - `waves`: the components.
///
/// # Returns
/// `(σx², σy²)` (dimensionless), downwind and crosswind.
///
/// # References
/// Bruneton, Neyret & Holzschuch 2010, §4 (`σ² = Σ A_i² k_i²/2` per axis); docs/equations.md §11.
pub fn slope_variance_sines(waves: &[WaveComponent]) -> (f64, f64) {
    waves.iter().fold((0.0, 0.0), |(x, y), w| {
        let m = 0.5 * (w.amplitude_m * w.wavenumber).powi(2);
        let (s, c) = w.angle_from_wind_rad.sin_cos();
        (x + m * c * c, y + m * s * s)
    })
}

/// Exact mean-square slope of one trochoid (Gerstner wave) of steepness `Q = kA < 1`,
/// averaged over the surface: `⟨s²⟩ = 1 − √(1 − Q²)`.
///
/// # Arguments
/// - `steepness`: `Q = kA`, `[0, 1)`; values `≥ 1` (a cusp) are clamped to 1.
///
/// # Returns
/// The mean-square slope (dimensionless): 0.133975 at `Q = 0.5`, 0.4 at `Q = 0.8`; `Q²/2` for
/// small `Q` (the sine-wave value).
///
/// # References
/// docs/equations.md §1 and §11 (derived: the area-weighted mean of `tan²` of the trochoid profile).
pub fn trochoid_mean_square_slope(steepness: f64) -> f64 {
    let q = steepness.clamp(0.0, 1.0);
    // 1 − √(1 − q²) = q²/(1 + √(1 − q²)), without cancellation for small q.
    q * q / (1.0 + (1.0 - q * q).sqrt())
}

/// Slope variances `(σx², σy²)` of a set of trochoids:
/// `σx² = Σ cos²θ_i (1 − √(1 − k_i²A_i²))`, `σy² = Σ sin²θ_i (…)`.
///
/// # Arguments
/// - `waves`: the components (`k A < 1`).
///
/// # Returns
/// `(σx², σy²)` (dimensionless).
///
/// # References
/// docs/equations.md §11 (trochoid set); Bruneton et al. 2010 §4 for the split by direction.
pub fn slope_variance_trochoids(waves: &[WaveComponent]) -> (f64, f64) {
    waves.iter().fold((0.0, 0.0), |(x, y), w| {
        let m = trochoid_mean_square_slope(w.amplitude_m * w.wavenumber);
        let (s, c) = w.angle_from_wind_rad.sin_cos();
        (x + m * c * c, y + m * s * s)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn trochoid_oracles() {
        /// The sheet prints 6 significant digits (0.133975 = 1 − √3/2).
        const SIX_DIGITS: f64 = 1e-5;
        /// `1 − √(1 − 0.64) = 0.4` exactly up to rounding.
        const ROUNDING: f64 = 1e-12;
        assert_relative_eq!(trochoid_mean_square_slope(0.5), 0.133975, max_relative = SIX_DIGITS);
        assert_relative_eq!(trochoid_mean_square_slope(0.8), 0.4, max_relative = ROUNDING);
    }

    #[test]
    fn small_trochoids_are_sines() {
        let w = [WaveComponent { amplitude_m: 0.001, wavenumber: 2.0, angle_from_wind_rad: 0.3 }];
        let (sx, sy) = slope_variance_sines(&w);
        let (tx, ty) = slope_variance_trochoids(&w);
        /// `1 − √(1 − x) = x/2 + x²/8 + …` with `x = k²A² = 4×10⁻⁶`: the sine form differs by
        /// `x/4 = 10⁻⁶` relative; ×10.
        const SMALL_STEEPNESS: f64 = 1e-5;
        assert_relative_eq!(sx, tx, max_relative = SMALL_STEEPNESS);
        assert_relative_eq!(sy, ty, max_relative = SMALL_STEEPNESS);
    }
}
