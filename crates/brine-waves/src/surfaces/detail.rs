//! Detail normals: the middle of Bruneton et al. (2010)'s three scales. The waves too short to be
//! traced as geometry but long enough to be seen in a pixel are synthesised as slopes only, on a
//! few FFT tiles read through a tile and blend (so they do not repeat), and read at the hit with
//! a footprint filter; what the footprint hides goes to the BRDF.

use std::f64::consts::TAU;

use glam::DVec3;

use crate::error::{WaveError, check};
use crate::{
    Dispersion, FFT_DEFAULT_TILE_RATIO, FftOcean, FftOptions, FftSlopeFilter, FilteredSlopes, Spectrum, Spreading,
};

/// Shortest wavelength the detail layer draws by default (m): 1 cm, where the capillary range
/// starts (Elfouhaily et al. 1997's `k_m = 370` rad m⁻¹ is a 1.7 cm wave). The gravity-range spectra
/// (Pierson–Moskowitz, JONSWAP, TMA, Phillips) are not models of shorter waves.
pub const DETAIL_MIN_WAVELENGTH_M: f64 = 0.01;

/// Longest detail wave per tile of the first detail cascade: the band's longest wave sits at grid
/// index 8 (about 50 wave vectors on its ring), as the FFT sea's peak does.
const DETAIL_WAVELENGTHS_PER_TILE: f64 = 8.0;

/// At most this many detail cascades: with the default tile ratio `φ⁴` four cascades at `N = 256`
/// span a factor of about 5000 in wavenumber, far more than any band between a traced sea and
/// the 1 cm wave.
const DETAIL_MAX_CASCADES: usize = 4;

/// Mixed into the sea's seed so that the detail's amplitudes are not those of an FFT sea of the
/// same seed.
const DETAIL_SEED_MIX: u64 = 0x00de_7a11;

/// Where the detail band starts and ends, and how it is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DetailOptions {
    /// Longest detail wavenumber `k_lo` (rad m⁻¹), `> 0`: the top of the traced band.
    pub k_lo: f64,
    /// Shortest detail wavenumber `k_hi` (rad m⁻¹), `> k_lo`.
    pub k_hi: f64,
    /// Grid resolution `N` of each tile, a power of two in `[16, 1024]` (default 256).
    pub resolution: usize,
    /// Seed of the random amplitudes.
    pub seed: u64,
    /// Mean wind direction `θ_w` (rad) from +x toward +z.
    pub wind_direction: f64,
    /// Loop period (s) of an animation, or `None`.
    pub loop_period: Option<f64>,
}

impl DetailOptions {
    /// The band `[k_lo, k_hi]` of a sea traced up to `k_lo`, ending where the detail's mean-square
    /// slope reaches `target_mss` or at [`DETAIL_MIN_WAVELENGTH_M`], whichever is longer:
    /// `k_hi = min(k : ∫_{k_lo}^{k} k² S(k) dk = target_mss, 2π/λ_min)`.
    ///
    /// # Arguments
    /// - `spectrum`: the sea's spectrum.
    /// - `k_lo`: top of the traced band (rad m⁻¹), `> 0`.
    /// - `target_mss`: the mean-square slope left to draw (dimensionless), `≥ 0`: the total (Cox &
    ///   Munk's) minus the traced waves'.
    ///
    /// # Returns
    /// The options with the default resolution (256), seed 1 and wind direction 0, or `None` when
    /// nothing is left to draw (`target_mss = 0` or `k_lo` beyond the 1 cm wave).
    ///
    /// # References
    /// Bruneton E., Neyret F., Holzschuch N. 2010, "Real-time realistic ocean lighting using
    /// seamless transitions from geometry to BRDF", CGF 29(2), §4 (the three scales); Cox C.,
    /// Munk W. 1954, JOSA 44(11).
    pub fn for_band(spectrum: &dyn Spectrum, k_lo: f64, target_mss: f64) -> Option<Self> {
        let k_cap = TAU / DETAIL_MIN_WAVELENGTH_M;
        if !(k_lo > 0.0 && k_lo < k_cap && target_mss > 0.0) {
            return None;
        }
        let k_hi = wavenumber_of_slope(spectrum, k_lo, target_mss, k_cap);
        (k_hi > k_lo * (1.0 + 1e-9)).then_some(Self {
            k_lo,
            k_hi,
            resolution: 256,
            seed: 1,
            wind_direction: 0.0,
            loop_period: None,
        })
    }
}

/// A spectrum restricted to a band of frequencies: `S(ω)` for `ω ∈ [ω_lo, ω_hi]`, 0 outside; its
/// peak clamped into the band, its dispersion relation the spectrum's.
#[derive(Clone, Copy)]
pub struct BandLimited<'a> {
    spectrum: &'a dyn Spectrum,
    omega_lo: f64,
    omega_hi: f64,
}

impl std::fmt::Debug for BandLimited<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BandLimited").field("omega_lo", &self.omega_lo).field("omega_hi", &self.omega_hi).finish()
    }
}

impl<'a> BandLimited<'a> {
    /// `spectrum` between the frequencies of the wavenumbers `k_lo` and `k_hi` (rad m⁻¹),
    /// `0 ≤ k_lo < k_hi` (`k_hi` may be infinite), by the spectrum's dispersion relation.
    pub fn between_wavenumbers(spectrum: &'a dyn Spectrum, k_lo: f64, k_hi: f64) -> Self {
        debug_assert!(k_lo >= 0.0 && k_hi > k_lo);
        let d = spectrum.dispersion();
        let omega_hi = if k_hi.is_finite() { d.omega(k_hi) } else { f64::INFINITY };
        Self { spectrum, omega_lo: if k_lo > 0.0 { d.omega(k_lo) } else { 0.0 }, omega_hi }
    }
}

impl Spectrum for BandLimited<'_> {
    fn s_omega(&self, omega: f64) -> f64 {
        if (self.omega_lo..=self.omega_hi).contains(&omega) { self.spectrum.s_omega(omega) } else { 0.0 }
    }

    fn peak_omega(&self) -> f64 {
        self.spectrum.peak_omega().clamp(self.omega_lo, self.omega_hi)
    }

    fn dispersion(&self) -> Dispersion {
        self.spectrum.dispersion()
    }
}

/// The wavenumber `k ≥ k_lo` up to which the spectrum's mean-square slope from `k_lo` reaches
/// `target`: `∫_{k_lo}^{k} k² S(k) dk = target` (bisection in `ln k`), or `k_cap` if it holds less.
///
/// # Arguments
/// - `spectrum`: the spectrum; `k_lo` (rad m⁻¹) `> 0`; `target` (dimensionless) `≥ 0`;
///   `k_cap` (rad m⁻¹) `> k_lo`.
///
/// # Returns
/// `k` (rad m⁻¹) in `[k_lo, k_cap]`.
///
/// # References
/// Cox C., Munk W. 1954, JOSA 44(11) (the mean-square slope as the spectrum's second moment).
pub fn wavenumber_of_slope(spectrum: &dyn Spectrum, k_lo: f64, target: f64, k_cap: f64) -> f64 {
    debug_assert!(k_lo > 0.0 && k_cap > k_lo && target >= 0.0);
    let mss = |k: f64| spectrum.mean_square_slope_between(k_lo, k);
    if mss(k_cap) <= target {
        return k_cap;
    }
    let (mut a, mut b) = (k_lo.ln(), k_cap.ln());
    for _ in 0..60 {
        let m = 0.5 * (a + b);
        if mss(m.exp()) < target { a = m } else { b = m }
    }
    b.exp()
}

/// The detail waves of a sea: the band `[k_lo, k_hi]` of its directional spectrum as linear waves
/// (Tessendorf's random-phase sum, no horizontal displacement) on periodic tiles of incommensurate
/// sizes, drawn as slopes only.
///
/// The tiles are [`FftOcean`] cascades: the first holds the band's longest wave at index 8, each
/// next one is `φ⁴` smaller (never realigning), up to the band's shortest wave. Their shading
/// gradient is added to the traced surface's at the hit, and their slope covariance inside the
/// pixel footprint ([`DetailSlopes::filtered`], LEAN mapping) is added to the BRDF's. So the
/// traced waves, the detail and the BRDF share the spectrum's slopes without gap or overlap:
/// the mean slope variance of geometry + normals + BRDF is the same at every distance.
///
/// # References
/// Bruneton E., Neyret F., Holzschuch N. 2010, CGF 29(2), §4–5; Olano M., Baker D. 2010, "LEAN
/// mapping", I3D; Tessendorf J. 2001, "Simulating Ocean Water".
#[derive(Debug, Clone)]
pub struct DetailWaves {
    ocean: FftOcean,
    options: DetailOptions,
}

impl DetailWaves {
    /// Draws the random amplitudes of the detail band.
    ///
    /// # Arguments
    /// - `spectrum`, `spreading`: the sea's directional spectrum `S(ω) D(θ; ω)`.
    /// - `options`: see [`DetailOptions`].
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a band that is not `0 < k_lo < k_hi`, a bad resolution or
    /// loop period; [`WaveError::EmptyBand`] if the spectrum has no energy in the band.
    pub fn new(spectrum: &dyn Spectrum, spreading: &dyn Spreading, options: &DetailOptions) -> Result<Self, WaveError> {
        Self::build(spectrum, spreading, options, false)
    }

    /// [`Self::new`], with the tiles read through the blend (`tiled = false`) or periodic.
    fn build(
        spectrum: &dyn Spectrum,
        spreading: &dyn Spreading,
        options: &DetailOptions,
        tiled: bool,
    ) -> Result<Self, WaveError> {
        check("detail k_lo", options.k_lo, options.k_lo > 0.0, "(0, ∞) rad/m")?;
        check("detail k_hi", options.k_hi, options.k_hi > options.k_lo, "(k_lo, ∞) rad/m")?;
        let n = options.resolution;
        check(
            "detail resolution",
            n as f64,
            n.is_power_of_two() && (16..=1024).contains(&n),
            "a power of two in [16, 1024]",
        )?;
        let band = BandLimited::between_wavenumbers(spectrum, options.k_lo, options.k_hi);
        let l0 = DETAIL_WAVELENGTHS_PER_TILE * TAU / options.k_lo;
        let mut tiles = vec![l0];
        // Add tiles until the last one's Nyquist wavenumber reaches k_hi.
        while tiles.len() < DETAIL_MAX_CASCADES && (n as f64 / 2.0 - 0.5) * TAU / tiles[tiles.len() - 1] < options.k_hi
        {
            tiles.push(tiles[tiles.len() - 1] / FFT_DEFAULT_TILE_RATIO);
        }
        let fft = FftOptions {
            resolution: n,
            tile_sizes: tiles,
            choppiness: 0.0,
            loop_period: options.loop_period,
            seed: options.seed ^ DETAIL_SEED_MIX,
            wind_direction: options.wind_direction,
            // Each tile is read through the tile and blend (`TileBlend`): the detail does not
            // repeat with its tiles.
            tiled,
        };
        let ocean = FftOcean::new(&band, spreading, &fft)?;
        Ok(Self { ocean, options: *options })
    }

    /// The options the detail was built with.
    pub fn options(&self) -> &DetailOptions {
        &self.options
    }

    /// Tile sizes of the detail cascades (m), decreasing.
    pub fn tile_sizes(&self) -> &[f64] {
        &self.ocean.options().tile_sizes
    }

    /// Expected slope covariance of the whole detail band, `Σ ½|a|² (kₓ², kₓk_z, k_z²)`
    /// (dimensionless, world axes `(xx, xz, zz)`).
    pub fn expected_slope_covariance(&self) -> DVec3 {
        (0..self.ocean.cascade_count()).map(|c| DVec3::from_array(self.ocean.expected_slope_covariance(c))).sum()
    }

    /// The detail slopes at time `t` (s), mip-mapped for footprint reads (`O(N² log N)` per tile).
    pub fn at_time(&self, t: f64) -> DetailSlopes {
        let frame = self.ocean.at_time(t);
        DetailSlopes { filter: FftSlopeFilter::new(&frame), covariance: self.expected_slope_covariance() }
    }
}

/// The detail slopes at one instant ([`DetailWaves::at_time`]).
#[derive(Debug, Clone, PartialEq)]
pub struct DetailSlopes {
    filter: FftSlopeFilter,
    covariance: DVec3,
}

impl DetailSlopes {
    /// Mean detail gradient over a Gaussian footprint and the slope covariance it hides.
    ///
    /// `s = 0` gives the detail's slope at the point (its whole variance drawn); a footprint
    /// larger than the first tile gives a zero gradient and the whole band's covariance (all of it
    /// in the BRDF). The sum `E[ζζᵀ]` of the two parts is the band's covariance at any `s`.
    ///
    /// # Arguments
    /// - `x`, `z`: point on the sea (m), finite.
    /// - `footprint_m`: standard deviation `s` of the footprint (m), `≥ 0` (a pixel of side `ℓ` on
    ///   the sea: `s = ℓ/√12`).
    ///
    /// # Returns
    /// [`FilteredSlopes`]: the gradient to add to the traced surface's, the covariance (world
    /// axes) to add to the BRDF's.
    ///
    /// # References
    /// Olano & Baker 2010 (LEAN mapping); Bruneton et al. 2010, §5.
    pub fn filtered(&self, x: f64, z: f64, footprint_m: f64) -> FilteredSlopes {
        debug_assert!(footprint_m >= 0.0);
        self.filter.filtered(x, z, footprint_m)
    }

    /// [`Self::filtered`] over an elliptical footprint ([`FftSlopeFilter::filtered_elliptical`]):
    /// a pixel seen at a slant averages the detail along the view over its length.
    ///
    /// # Arguments
    /// - `x`, `z`: point on the sea (m), finite; `footprint`: the ellipse.
    ///
    /// # Returns
    /// [`FilteredSlopes`], as [`Self::filtered`].
    ///
    /// # References
    /// Olano & Baker 2010 (LEAN mapping); Heckbert 1989 (elliptical footprints).
    pub fn filtered_elliptical(&self, x: f64, z: f64, footprint: &crate::EllipticalFootprint) -> FilteredSlopes {
        self.filter.filtered_elliptical(x, z, footprint)
    }

    /// Expected slope covariance of the detail band (world axes `(xx, xz, zz)`).
    pub fn expected_slope_covariance(&self) -> DVec3 {
        self.covariance
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineTwoS, PiersonMoskowitz};

    /// Quadrature of the cells (Simpson per cell) against the spectrum's own moment integral: the
    /// grids cover the band's ring with square cells, so the corners of the band are cut (1–3 %).
    const BAND_MSS_REL: f64 = 0.05;

    fn sea() -> (PiersonMoskowitz, CosineTwoS) {
        let s = PiersonMoskowitz::from_u10(12.0).expect("valid");
        let d = CosineTwoS::hasselmann(s.peak_omega()).expect("valid");
        (s, d)
    }

    #[test]
    fn the_band_ends_where_the_target_slope_is_reached() {
        let (s, _) = sea();
        let k_lo = 2.0;
        let o = DetailOptions::for_band(&s, k_lo, 0.005).expect("a band");
        let mss = s.mean_square_slope_between(k_lo, o.k_hi);
        approx::assert_relative_eq!(mss, 0.005, max_relative = 1e-6);
        // A target beyond what the spectrum holds to the 1 cm wave stops there.
        let o = DetailOptions::for_band(&s, k_lo, 10.0).expect("a band");
        approx::assert_relative_eq!(o.k_hi, TAU / DETAIL_MIN_WAVELENGTH_M, max_relative = 1e-12);
        assert!(DetailOptions::for_band(&s, k_lo, 0.0).is_none());
        assert!(DetailOptions::for_band(&s, 1000.0, 0.01).is_none());
    }

    /// The drawn covariance is the spectrum's slope in the band, and the footprint splits it: at
    /// a point the sample variance of the gradients holds it, over a footprint wider than every
    /// tile it is all in the hidden covariance.
    #[test]
    fn the_footprint_splits_the_band_between_normals_and_brdf() {
        let (s, d) = sea();
        let o = DetailOptions { resolution: 128, ..DetailOptions::for_band(&s, 2.0, 0.01).expect("a band") };
        let detail = DetailWaves::new(&s, &d, &o).expect("valid");
        let c = detail.expected_slope_covariance();
        let expected = s.mean_square_slope_between(o.k_lo, o.k_hi);
        approx::assert_relative_eq!(c.x + c.z, expected, max_relative = BAND_MSS_REL);
        let slopes = detail.at_time(3.0);
        // Sample the gradient on a grid of points across the first tile.
        let l0 = detail.tile_sizes()[0];
        let (mut sum, mut n) = (0.0, 0.0);
        for i in 0..64 {
            for j in 0..64 {
                let f = slopes.filtered(l0 * f64::from(i) / 64.0 + 0.013, l0 * f64::from(j) / 64.0 + 0.029, 0.0);
                sum += f.gradient.length_squared() + f.covariance.x + f.covariance.z;
                n += 1.0;
            }
        }
        // One random draw of the amplitudes: the sample variance is within 15 % of its mean.
        approx::assert_relative_eq!(sum / n, c.x + c.z, max_relative = 0.15);
        let wide = slopes.filtered(0.3, 0.7, 10.0 * l0);
        assert!(wide.gradient.length() < 1e-6, "a footprint over every tile averages the slopes away");
        approx::assert_relative_eq!(wide.covariance.x + wide.covariance.z, sum / n, max_relative = 0.15);
    }

    /// Largest correlation of the detail's slopes with themselves a whole number of one of its
    /// tiles away (20 000 points): as for the FFT sea's cascades (`tests/fft_tracing.rs`), the
    /// blend's lattice gives two points a tile apart no common corner; 0.05 allows the sampling
    /// error of 20 000 points (about 0.007 one sigma) several times over.
    const TILE_LAG_CORRELATION: f64 = 0.05;

    /// The detail does not repeat with any of its tiles; periodic tiles correlate there by the
    /// tile's share of the slope variance (0.09–0.57 here, measured). The lags are the multiples
    /// of each tile just beyond twice the first, where the longer tiles' own waves (a first tile
    /// holds eight of its longest) no longer correlate.
    #[test]
    fn the_detail_does_not_repeat_with_its_tiles() {
        let (s, d) = sea();
        let o = DetailOptions { resolution: 64, ..DetailOptions::for_band(&s, 2.0, 0.02).expect("a band") };
        let (a1, a2) = (0.754_877_666_246_692_7, 0.569_840_290_998_053_3);
        let correlation = |slopes: &DetailSlopes, lag: (f64, f64)| {
            let side = 40.0 * lag.0.abs().max(lag.1.abs());
            let (mut sxy, mut sxx, mut syy, mut sx, mut sy, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            for i in 1..=20_000 {
                let (x, z) = (side * (0.5 + a1 * f64::from(i)).fract(), side * (0.5 + a2 * f64::from(i)).fract());
                let p = slopes.filtered(x, z, 0.0).gradient.x;
                let q = slopes.filtered(x + lag.0, z + lag.1, 0.0).gradient.x;
                (sxy, sxx, syy, sx, sy, n) = (sxy + p * q, sxx + p * p, syy + q * q, sx + p, sy + q, n + 1.0);
            }
            let cov = sxy / n - sx * sy / n / n;
            cov / ((sxx / n - (sx / n).powi(2)) * (syy / n - (sy / n).powi(2))).sqrt()
        };
        let blended = DetailWaves::new(&s, &d, &o).expect("valid").at_time(2.0);
        let tiled = DetailWaves::build(&s, &d, &o, true).expect("valid");
        let tiles = tiled.tile_sizes().to_vec();
        assert!(tiles.len() >= 2, "{tiles:?}");
        let tiled = tiled.at_time(2.0);
        for &l in &tiles {
            let m = (2.0 * tiles[0] / l).ceil();
            for lag in [(m * l, 0.0), (0.0, m * l), (m * l, m * l)] {
                let (rb, rt) = (correlation(&blended, lag), correlation(&tiled, lag));
                assert!(rb.abs() <= TILE_LAG_CORRELATION, "blended: {rb} at {lag:?}");
                assert!(rt > TILE_LAG_CORRELATION, "tiled: {rt} at {lag:?}");
            }
        }
    }

    #[test]
    fn bad_bands_are_refused() {
        let (s, d) = sea();
        let good = DetailOptions::for_band(&s, 2.0, 0.01).expect("a band");
        for bad in [
            DetailOptions { k_lo: 0.0, ..good },
            DetailOptions { k_hi: 1.0, ..good },
            DetailOptions { resolution: 100, ..good },
            DetailOptions { resolution: 4096, ..good },
        ] {
            assert!(
                matches!(DetailWaves::new(&s, &d, &bad), Err(WaveError::OutOfRange(brine_core::OutOfRange { .. }))),
                "{bad:?}"
            );
        }
    }
}
