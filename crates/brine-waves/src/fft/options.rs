//! Options of the FFT ocean: grid resolution, cascade tile sizes, choppiness, looping, seed, wind.

use std::f64::consts::TAU;

use crate::Spectrum;
use crate::error::{WaveError, check};

/// Smallest grid resolution `N` (samples per tile side).
pub const FFT_MIN_RESOLUTION: usize = 16;
/// Largest grid resolution `N`.
pub const FFT_MAX_RESOLUTION: usize = 4096;
/// Largest number of cascades.
pub const FFT_MAX_CASCADES: usize = 8;
/// Largest choppiness `λ` (dimensionless).
pub const FFT_MAX_CHOPPINESS: f64 = 4.0;
/// Longest loop period `T` (s).
pub const FFT_MAX_LOOP_PERIOD_S: f64 = 1.0e6;

/// Where cascade `c ≥ 1` takes over from cascade `c − 1`, in units of its own fundamental
/// `Δk_c = 2π/L_c`: cascade `c` holds the wave vectors with `|k|_∞ ≥ 4 Δk_c` (wavelengths below
/// a quarter of its tile along either axis), cascade `c − 1` those below. A band that starts at
/// index 4 keeps at least 4 waves per tile (so one tile's repetition is not a single wave) while
/// leaving the lower cascade `4 L_{c−1}/L_c` indices, far below its Nyquist index `N/2` for the
/// default ratio (27 of 128 at `N = 256`: 9 samples per wavelength for its cubic B-spline).
pub const FFT_CASCADE_CUT_INDEX: f64 = 4.0;

/// Default ratio `L_c/L_{c+1}` of successive tile sizes: `φ⁴ = (7 + 3√5)/2 ≈ 6.854` (`φ` the
/// golden ratio). Its continued fraction `[6; 1, 5, 1, 5, …]` has no small-denominator
/// approximation, so two tiles never realign within a few hundred periods of the smaller one:
/// the tiling is not visible.
pub const FFT_DEFAULT_TILE_RATIO: f64 = 6.854_101_966_249_685;

/// Default size of the largest tile in peak wavelengths `2π/k_p`: 8 wavelengths put the spectral
/// peak at index 8 of cascade 0 (about 50 wave vectors on the peak's ring), and the energy below
/// the fundamental (the discarded `k = 0` cell) below `e⁻⁸⁰` of `m₀` for Pierson–Moskowitz-like
/// spectra.
pub const FFT_PEAK_WAVELENGTHS_PER_TILE: f64 = 8.0;

/// Largest denominator `q` for which a tile ratio close to a fraction `p/q` is rejected as
/// commensurate (the two tiles would realign every `q` tiles).
const COMMENSURATE_MAX_DENOMINATOR: u32 = 8;

/// Relative distance `|q r − p|/q` below which a ratio `r` counts as the fraction `p/q`.
const COMMENSURATE_TOLERANCE: f64 = 1e-3;

/// Options of [`crate::FftOcean::new`].
///
/// The sea is the sum of `tile_sizes.len()` periodic cascades, each an `N × N` grid over a square
/// tile of side `L_c` (m), holding the wave vectors of its band (see [`FFT_CASCADE_CUT_INDEX`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FftOptions {
    /// Grid resolution `N` of every cascade: a power of two in `[16, 4096]` (default 256).
    pub resolution: usize,
    /// Tile sizes `L_c` (m), strictly decreasing, each in `(0, 10⁵]`, 1 to 8 cascades; successive
    /// ratios in `[1.5, (N/2 − 1/2)/4]` and not within `10⁻³` of a fraction `p/q`, `q ≤ 8`
    /// (commensurate tiles repeat together). Default: [`FftOptions::tile_sizes_for`] of a
    /// 10 m s⁻¹ Elfouhaily sea (728 m, 106 m, 15.5 m, 2.27 m).
    pub tile_sizes: Vec<f64>,
    /// Choppiness `λ` of the horizontal displacement `x = u + λ D(u)` (dimensionless), `[0, 4]`
    /// (default 1; 0: no horizontal motion, the plain height field).
    pub choppiness: f64,
    /// Loop period `T` (s), `(0, 10⁶]`: when given, every angular frequency is rounded to a
    /// non-zero multiple of `2π/T` so that the sea repeats exactly after `T` (default `None`).
    pub loop_period: Option<f64>,
    /// Seed of the random amplitudes (ChaCha8).
    pub seed: u64,
    /// Mean wind (and wave) direction `θ_w` (rad), from +x toward +z, finite (default 0).
    pub wind_direction: f64,
    /// The cascades are meant to repeat together over the first tile (a tileable sea, as
    /// `brine bake` makes with [`crate::TileLattice::commensurate_tiles`]): commensurate tile
    /// ratios are then allowed, and each cascade is its periodic tile (default `false`: each
    /// cascade is read through a [`crate::TileBlend`], so that the sea does not repeat).
    pub tiled: bool,
}

impl Default for FftOptions {
    fn default() -> Self {
        // 8 peak wavelengths of the fully developed 10 m/s Elfouhaily sea (k_p = 0.06922 rad/m).
        let l0 = FFT_PEAK_WAVELENGTHS_PER_TILE * TAU / 0.069_22;
        Self {
            resolution: 256,
            tile_sizes: geometric_tiles(l0, 4),
            choppiness: 1.0,
            loop_period: None,
            seed: 1,
            wind_direction: 0.0,
            tiled: false,
        }
    }
}

/// `count` tiles from `l0` down by [`FFT_DEFAULT_TILE_RATIO`].
fn geometric_tiles(l0: f64, count: usize) -> Vec<f64> {
    (0..count).map(|c| l0 / libm::pow(FFT_DEFAULT_TILE_RATIO, c as f64)).collect()
}

impl FftOptions {
    /// Default tile sizes for a spectrum: the largest tile holds
    /// [`FFT_PEAK_WAVELENGTHS_PER_TILE`] peak wavelengths `2π/k(ω_p)`, each next one is
    /// [`FFT_DEFAULT_TILE_RATIO`] times smaller.
    ///
    /// # Arguments
    /// - `spectrum`: the sea's spectrum (its peak and dispersion set the first tile).
    /// - `cascades`: number of cascades, `[1, 8]` (values outside are clamped).
    ///
    /// # Returns
    /// The tile sizes `L_c` (m), decreasing. With 4 cascades at `N = 256` they resolve
    /// wavelengths from 8 peak wavelengths down to `8λ_p/(128 · 6.854³) ≈ λ_p/5000`.
    pub fn tile_sizes_for(spectrum: &dyn Spectrum, cascades: usize) -> Vec<f64> {
        let k_p = spectrum.dispersion().wavenumber(spectrum.peak_omega());
        let l0 = (FFT_PEAK_WAVELENGTHS_PER_TILE * TAU / k_p).min(1e5);
        geometric_tiles(l0, cascades.clamp(1, FFT_MAX_CASCADES))
    }

    /// The default options with the tile sizes of [`FftOptions::tile_sizes_for`].
    ///
    /// # Arguments
    /// - `spectrum`: the sea's spectrum.
    /// - `cascades`: number of cascades, `[1, 8]` (clamped).
    pub fn for_spectrum(spectrum: &dyn Spectrum, cascades: usize) -> Self {
        Self { tile_sizes: Self::tile_sizes_for(spectrum, cascades), ..Self::default() }
    }

    /// Checks every option against its range.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first bad option (`resolution`, `tile_sizes_m`,
    /// `tile_ratio`, `choppiness`, `loop_period_s`, `wind_direction_rad`).
    pub fn validate(&self) -> Result<(), WaveError> {
        let n = self.resolution;
        check(
            "resolution",
            n as f64,
            n.is_power_of_two() && (FFT_MIN_RESOLUTION..=FFT_MAX_RESOLUTION).contains(&n),
            "a power of two in [16, 4096]",
        )?;
        let count = self.tile_sizes.len();
        check("tile_sizes_m (count)", count as f64, (1..=FFT_MAX_CASCADES).contains(&count), "1 to 8 cascades")?;
        for &l in &self.tile_sizes {
            check("tile_sizes_m", l, l > 0.0 && l <= 1e5, "(0, 1e5] m")?;
        }
        let max_ratio = (n as f64 / 2.0 - 0.5) / FFT_CASCADE_CUT_INDEX;
        for pair in self.tile_sizes.windows(2) {
            let r = pair[0] / pair[1];
            check("tile_ratio", r, (1.5..=max_ratio).contains(&r), "L_c/L_(c+1) in [1.5, (N/2 − 1/2)/4]")?;
            check(
                "tile_ratio",
                r,
                self.tiled || !commensurate(r),
                "not within 1e-3 of a fraction p/q with q ≤ 8 (tiles would realign)",
            )?;
        }
        check("choppiness", self.choppiness, (0.0..=FFT_MAX_CHOPPINESS).contains(&self.choppiness), "[0, 4]")?;
        if let Some(t) = self.loop_period {
            check("loop_period_s", t, t > 0.0 && t <= FFT_MAX_LOOP_PERIOD_S, "(0, 1e6] s")?;
        }
        check("wind_direction_rad", self.wind_direction, self.wind_direction.is_finite(), "finite")?;
        Ok(())
    }
}

/// `true` if `r` is within [`COMMENSURATE_TOLERANCE`] of a fraction `p/q` with `q ≤ 8`.
fn commensurate(r: f64) -> bool {
    (1..=COMMENSURATE_MAX_DENOMINATOR).any(|q| {
        let qr = f64::from(q) * r;
        (qr - qr.round()).abs() < COMMENSURATE_TOLERANCE * f64::from(q)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The printed constant against `3φ + 2` in f64: a few ulp of 6.85.
    const ROUND_ABS: f64 = 1e-12;

    #[test]
    fn default_options_are_valid_and_incommensurate() {
        let o = FftOptions::default();
        assert!(o.validate().is_ok());
        assert!(!commensurate(FFT_DEFAULT_TILE_RATIO));
        // φ⁴ = 3φ + 2.
        let phi = (1.0 + 5f64.sqrt()) / 2.0;
        assert!((FFT_DEFAULT_TILE_RATIO - (3.0 * phi + 2.0)).abs() < ROUND_ABS);
    }

    #[test]
    fn bad_options_are_named() {
        let bad = |o: FftOptions, name: &str| {
            let e = o.validate().unwrap_err().to_string();
            assert!(e.contains(name), "{e}");
        };
        bad(FftOptions { resolution: 100, ..FftOptions::default() }, "resolution");
        bad(FftOptions { resolution: 8, ..FftOptions::default() }, "resolution");
        bad(FftOptions { tile_sizes: vec![], ..FftOptions::default() }, "tile_sizes_m");
        bad(FftOptions { tile_sizes: vec![100.0, -1.0], ..FftOptions::default() }, "tile_sizes_m");
        bad(FftOptions { tile_sizes: vec![100.0, 50.0], ..FftOptions::default() }, "tile_ratio");
        bad(FftOptions { tile_sizes: vec![100.0, 40.0], ..FftOptions::default() }, "tile_ratio");
        bad(FftOptions { tile_sizes: vec![100.0, 1.0], ..FftOptions::default() }, "tile_ratio");
        bad(FftOptions { choppiness: -0.1, ..FftOptions::default() }, "choppiness");
        bad(FftOptions { loop_period: Some(0.0), ..FftOptions::default() }, "loop_period_s");
        bad(FftOptions { wind_direction: f64::NAN, ..FftOptions::default() }, "wind_direction_rad");
    }
}
