//! The trochoid sea with its shorter waves gathered into periodic grids, traced as the FFT sea's
//! cascades are (docs/models/brine-waves.md, "Many waves on grids"; the measurements in
//! docs/dev/wave-scaling.md).
//!
//! Every evaluation of a trochoid sum pays for all its waves, and the sum's bounds grow with their
//! number, so a sea of hundreds of waves costs the tracer several times one of fifty. Here the
//! waves at least the last band's cut long stay trochoids, traced by their tiers. The shorter
//! ones are snapped band by band to the lattice of a square tile ([`TileLattice::snap`]) once per
//! scene ([`BandedTrochoids`]); at each instant their sum is synthesised on the tile's grid by one
//! inverse FFT, and its cubic B-spline traced as one tier with the bounds of an [`FftCascade`]
//! (its own extreme values and slopes, instead of the sums of the waves' amplitudes and slopes).
//! Where no band is blended, the bands stand for the snapped waves: a bound of their distance to
//! them joins the tracer's evaluation error ([`GriddedTrochoids::error_bound`]), so the crossings
//! are certified for the snapped sea, which is what the renderer shades, exports and queries.
//! Each band fades whole with the pixel footprint, at its longest wave's distance (the shading
//! fades wave by wave).

use std::cell::RefCell;
use std::f64::consts::TAU;

use brine_trace::{Aabb, LipschitzSum, Ray, RayTiers, TierBounds, TierSample, TierScratch};
use glam::DVec3;
use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;

use crate::fft::lipschitz::{CascadeOnRay, CascadeTiers};
use crate::fft::ocean::inverse_fft_2d;
use crate::tracing::traced::tiers::{RayState, SeaTiers};
use crate::{
    FftCascade, FftFrame, TileBlend, TileLattice, TracedTrochoids, TrochoidSet, WaveError, solve_trochoid_phase,
};

/// The trochoid sea at one instant with its shorter waves on grids (see the module): what the
/// tracer meets, certified for [`BandedTrochoids::set`] within [`Self::error_bound`].
#[derive(Debug)]
pub struct GriddedTrochoids {
    long: TracedTrochoids,
    band: FftFrame,
    /// Waves in `long`.
    long_count: usize,
    /// Waves gathered into the bands.
    short_count: usize,
    /// The long waves and the snapped short ones: the sea the bands stand for.
    snapped: TrochoidSet,
    /// Bound of `|bands − snapped short waves|` (m) over the unblended bands.
    error: f64,
}

/// One grid of a [`BandedTrochoids`] layout: the waves shorter than `shorter_than_m` (and not
/// shorter than the previous band's cut) on a tile of side `tile_m` at `n × n` points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridBandSpec {
    /// The band's upper wavelength (m).
    pub shorter_than_m: f64,
    /// Its tile's side (m).
    pub tile_m: f64,
    /// Its resolution, a power of two `≥ 4`.
    pub n: usize,
    /// Read through a blend of randomly offset tiles (as the FFT sea's cascades), so that it
    /// does not repeat.
    pub blended: bool,
}

/// The waves of a trochoid sea split for [`GriddedTrochoids`], once per scene: those shorter
/// than each band's cut snapped to its tile's lattice ([`TileLattice::snap`]), the rest kept as
/// they are, and the bound of the distance between the grids and the snapped waves (the same at
/// every instant). [`Self::set`] is the sea the grids stand for: what the renderer shades,
/// exports and queries.
#[derive(Debug, Clone)]
pub struct BandedTrochoids {
    /// The waves at least the last cut long, traced as trochoids.
    long: TrochoidSet,
    /// Each band's layout and its snapped waves.
    bands: Vec<(GridBandSpec, TrochoidSet)>,
    /// The snapped bands' waves, then the long ones.
    snapped: TrochoidSet,
    /// Bound of `|grids − snapped short waves|` (m) over the unblended bands.
    error: f64,
}

impl BandedTrochoids {
    /// The waves of `set` split into the `bands` (by increasing cut) and snapped to their tiles.
    ///
    /// # Arguments
    /// - `set`: the fitted waves; `bands`: the layout, by increasing `shorter_than_m`.
    ///
    /// # Returns
    /// The split: [`Self::set`] the snapped sea, [`Self::error_bound`] the grids' distance to it.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a tile out of [`TileLattice::new`]'s range, cuts that leave
    /// no long wave or an empty band, a resolution that is not a power of two `≥ 4`, or a grid
    /// too coarse for its band's shortest wave.
    ///
    /// # References
    /// Tessendorf 2001 (waves on a tile's lattice, `k = 2π(m, n)/L`); Hall & Meyer 1976 (the
    /// spline's bound in [`Self::error_bound`]); docs/models/brine-waves.md, "Many waves on grids".
    pub fn new(set: &TrochoidSet, bands: &[GridBandSpec]) -> Result<Self, WaveError> {
        let mut rest: Vec<_> = set.waves().to_vec();
        let mut split = Vec::with_capacity(bands.len());
        let (mut snapped, mut error) = (TrochoidSet::new(Vec::new()), 0.0);
        for b in bands {
            crate::error::check("n", b.n as f64, b.n.is_power_of_two() && b.n >= 4, "a power of two ≥ 4")?;
            let (short, long): (Vec<_>, Vec<_>) =
                std::mem::take(&mut rest).into_iter().partition(|w| w.wavelength() < b.shorter_than_m);
            crate::error::check(
                "shorter_than_m",
                b.shorter_than_m,
                !short.is_empty(),
                "above the previous cut's waves",
            )?;
            rest = long;
            let short = TileLattice::new(b.tile_m, None)?.snap(&TrochoidSet::new(short))?;
            // Every wave's fundamental below the grid's Nyquist wavenumber: `|m| < n/2` on both axes.
            let dk = TAU / b.tile_m;
            let finest = short.waves().iter().fold(0.0f64, |r, w| {
                let kv = w.wavenumber() * w.direction_vector();
                r.max((kv.x / dk).round().abs()).max((kv.y / dk).round().abs())
            });
            crate::error::check(
                "n",
                b.n as f64,
                finest < (b.n / 2) as f64,
                "above twice the band's finest lattice index",
            )?;
            if !b.blended {
                error += band_error(&short, b.tile_m, b.n);
            }
            snapped.extend(&short);
            split.push((*b, short));
        }
        crate::error::check(
            "shorter_than_m",
            bands.last().map_or(0.0, |b| b.shorter_than_m),
            !rest.is_empty(),
            "below the longest wave",
        )?;
        let long = TrochoidSet::new(rest);
        snapped.extend(&long);
        Ok(Self { long, bands: split, snapped, error })
    }

    /// The layout the renderer gives a fitted sea: bands cut at `λ_max/2.5` of its longest wave
    /// `λ_max` and down from there by [`DEFAULT_BAND_RATIO`] until the shortest wave, each on a
    /// tile [`DEFAULT_TILE_PER_CUT`] times its cut, with [`DEFAULT_POINTS_PER_WAVE`] grid
    /// points along its shortest wave (a power of two, at least 16). For the Pierson–Moskowitz sea
    /// at 10 m/s fitted with 400 waves (`λ_max` ≈ 350 m, the shortest 0.6 m): seven bands of 256²
    /// cut at 1.2, 2.7, 5.9, 13, 29, 63 and 139 m, on tiles from 9.8 m to 1.1 km. A band that
    /// would hold no wave is dropped (its range joins the next band).
    ///
    /// Narrow bands on tiles of different sides make the sea repeat little: each band's
    /// slopes repeat over its own tile only, and each holds a small share of the slopes
    /// ([`Self::repeating_slope_shares`]). Three wide bands cost the same frame time but put
    /// 58 % of the slopes on one tile.
    ///
    /// # Arguments
    /// - `set`: the fitted waves (any number; their wavelengths set the cuts).
    ///
    /// # Returns
    /// The layout; `None` when no band would hold a wave, no wave would stay long, or a band
    /// would need more than 2048² points (waves under a millimetre, whose tiles are out of
    /// [`TileLattice::new`]'s range, left to a wider band).
    ///
    /// # References
    /// The measurements behind the constants: [`DEFAULT_BAND_RATIO`]; docs/benchmarks.md, "Wave
    /// count".
    pub fn default_layout(set: &TrochoidSet) -> Option<Vec<GridBandSpec>> {
        let longest = set.waves().iter().map(|w| w.wavelength()).fold(0.0f64, f64::max);
        let shortest = set.waves().iter().map(|w| w.wavelength()).fold(f64::INFINITY, f64::min);
        if !(longest > 0.0) {
            return None;
        }
        let mut cuts = vec![longest * DEFAULT_LONG_FRACTION];
        while let Some(&c) = cuts.last().filter(|&&c| c / DEFAULT_BAND_RATIO > shortest) {
            cuts.push(c / DEFAULT_BAND_RATIO);
        }
        let mut layout: Vec<GridBandSpec> = Vec::new();
        for &cut in cuts.iter().rev() {
            let tile = DEFAULT_TILE_PER_CUT * cut;
            let below = layout.last().map_or(0.0, |b| b.shorter_than_m);
            let band = set.waves().iter().map(|w| w.wavelength()).filter(|&l| l >= below && l < cut);
            let lo = band.fold(f64::INFINITY, f64::min);
            // A tile out of the lattice's range (sub-millimetre waves) leaves its waves to the next band.
            if lo.is_finite() && (1e-3..=1e6).contains(&tile) {
                let n = ((DEFAULT_POINTS_PER_WAVE * tile / lo).ceil() as usize).next_power_of_two().max(16);
                if n > 2048 {
                    return None;
                }
                layout.push(GridBandSpec { shorter_than_m: cut, tile_m: tile, n, blended: false });
            }
        }
        let cut = layout.last()?.shorter_than_m;
        set.waves().iter().any(|w| w.wavelength() >= cut).then_some(layout)
    }

    /// The sea the grids stand for: each band's snapped waves, then the long waves.
    pub fn set(&self) -> &TrochoidSet {
        &self.snapped
    }

    /// `(long, short)`: the waves traced as trochoids and those gathered into grids.
    pub fn counts(&self) -> (usize, usize) {
        (self.long.len(), self.snapped.len() - self.long.len())
    }

    /// Bound of the distance (m) between the grids and the snapped waves over the unblended
    /// bands, at any instant (see [`GriddedTrochoids::error_bound`]).
    pub fn error_bound(&self) -> f64 {
        self.error
    }

    /// The bands' layouts.
    pub fn layout(&self) -> impl Iterator<Item = &GridBandSpec> {
        self.bands.iter().map(|(b, _)| b)
    }

    /// How much of the sea repeats, band by band: each band's tile (m) and its waves' share of
    /// the whole set's mean-square slope `Σ ⟨|∇hᵢ|²⟩` (dimensionless, `[0, 1]`). A periodic band's
    /// slopes correlate fully with themselves one tile away, so its share is what it adds to
    /// the sea's slope autocorrelation at that lag (the measure of the FFT sea's tile lags).
    ///
    /// # Returns
    /// `(L_j, share_j)` per band, by increasing cut: the tile (m) and the share (the long waves
    /// hold the rest).
    pub fn repeating_slope_shares(&self) -> Vec<(f64, f64)> {
        let slope = |set: &TrochoidSet| set.waves().iter().map(|w| w.mean_square_slope()).sum::<f64>();
        let total = slope(&self.snapped);
        self.bands.iter().map(|(b, w)| (b.tile_m, if total > 0.0 { slope(w) / total } else { 0.0 })).collect()
    }
}

/// The longest band's cut in [`BandedTrochoids::default_layout`], as a fraction of the longest
/// wave: the waves above it (about one in seven at 400 waves) stay trochoids.
pub const DEFAULT_LONG_FRACTION: f64 = 0.4;

/// The ratio of consecutive cuts in [`BandedTrochoids::default_layout`]. Measured by rendering
/// the reference frame at 400 waves (time against the 50-wave frame traced whole, single runs
/// unless said) and a top-down view from 150 m (the excess autocorrelation of the shading normals
/// over the sea traced wave by wave, at the bands' tile lags):
/// - 4, three bands: 1.9–2.1× with the finest on 1024² over 8× its cut (1.88 in the wave-count
///   bench); 0.38 with it on 512² over 4× its cut (58 % of the slopes on that tile either way);
/// - 2.6, six bands: 1.9–2.3×, at most 0.19;
/// - **2.2**, seven bands of 256²: 2.0–2.3× (2.20 in the wave-count bench), 0.08–0.20, and at
///   most 0.23 over every lag from 3 to 170 m;
/// - 1.618, twelve bands of 128²: 2.6× (the twelve grids' bounds add up), at most 0.13.
pub const DEFAULT_BAND_RATIO: f64 = 2.2;

/// Tile side over cut in [`BandedTrochoids::default_layout`]: a wave shorter than the cut moves
/// by at most `√2/(2·8)` ≈ 9 % in wavenumber and direction when snapped.
pub const DEFAULT_TILE_PER_CUT: f64 = 8.0;

/// Grid points along each band's shortest wave in [`BandedTrochoids::default_layout`]: the
/// spline's error bound per harmonic, `√2 (5/384) θ⁴` with `θ = 2π/8`, is 0.7 % of its
/// amplitude.
pub const DEFAULT_POINTS_PER_WAVE: f64 = 8.0;

impl GriddedTrochoids {
    /// The sea of `set` at time `time` (s), the waves gathered into the `bands` (by increasing
    /// cut), those at least the last cut long traced as trochoids: [`BandedTrochoids::new`] then
    /// [`Self::at_time`].
    ///
    /// # Errors
    /// As [`BandedTrochoids::new`].
    pub fn new(set: &TrochoidSet, time: f64, bands: &[GridBandSpec]) -> Result<Self, WaveError> {
        Ok(Self::at_time(&BandedTrochoids::new(set, bands)?, time))
    }

    /// The split sea `banded` at time `time` (s): each band's grid filled by one inverse FFT (the
    /// bands side by side on the threads; the same values whatever their number), the long waves
    /// laid out for the tiered tracer.
    ///
    /// # Arguments
    /// - `banded`: the split sea; `time`: the instant (s), finite.
    ///
    /// # Returns
    /// The sea to trace at `time`, certified for `banded.set()` within [`Self::error_bound`].
    pub fn at_time(banded: &BandedTrochoids, time: f64) -> Self {
        use rayon::prelude::*;
        let cascades: Vec<_> =
            banded.bands.par_iter().enumerate().map(|(i, (b, short))| Self::cascade(short, time, b, i)).collect();
        Self {
            long: TracedTrochoids::new(&banded.long, time),
            band: FftFrame::from_cascades(time, cascades),
            long_count: banded.long.len(),
            short_count: banded.snapped.len() - banded.long.len(),
            snapped: banded.snapped.clone(),
            error: banded.error,
        }
    }

    /// The snapped waves `short` tabulated on the band's grid by one inverse FFT
    /// ([`band_heights`]).
    fn cascade(short: &TrochoidSet, time: f64, b: &GridBandSpec, index: usize) -> FftCascade {
        let heights = band_heights(short, time, b.tile_m, b.n);
        let k_longest = short.waves().iter().map(|w| w.wavenumber()).fold(f64::INFINITY, f64::min);
        // The band `[k_lo, k_hi)` of `|k|_∞`, as an FFT cascade's.
        let k_inf = |w: &crate::Trochoid| w.wavenumber() * w.direction_vector().abs().max_element();
        let k_lo = short.waves().iter().map(k_inf).fold(f64::INFINITY, f64::min);
        let k_hi = short.waves().iter().map(k_inf).fold(0.0, f64::max).next_up();
        let covariance = short.waves().iter().fold(DVec3::ZERO, |c, w| {
            let d = w.direction_vector();
            c + w.mean_square_slope() * DVec3::new(d.x * d.x, d.x * d.y, d.y * d.y)
        });
        let blend = b.blended.then(|| TileBlend::new(b.tile_m, 0x9_71d, index));
        FftCascade::from_heights(b.tile_m, b.n, heights, (k_lo, k_hi), k_longest, short.variance(), covariance, blend)
    }

    /// `(long, short)`: the waves traced as trochoids and those gathered into the grid.
    pub fn counts(&self) -> (usize, usize) {
        (self.long_count, self.short_count)
    }

    /// The bands' cascades.
    pub fn bands(&self) -> &[FftCascade] {
        self.band.cascades()
    }

    /// The sea the bands stand for: the long waves and the short ones snapped to their bands'
    /// lattices (where a band is blended, the blend is the surface and this set is not).
    pub fn snapped(&self) -> &TrochoidSet {
        &self.snapped
    }

    /// Bound of the distance (m) between the traced surface and the snapped sea
    /// ([`Self::snapped`]) over the unblended bands: each band's [`band_error`]. The tracer adds
    /// it to its evaluation error, so that its crossings are certified for the snapped sea too.
    pub fn error_bound(&self) -> f64 {
        self.error
    }

    /// The instant of the grids (s).
    pub fn time(&self) -> f64 {
        self.band.time()
    }

    /// The height of the surface a primary ray traced with footprint fading draws at `(x, z)`,
    /// hit `t` metres along `direction`: the long waves faded one by one plus each band's spline
    /// weighted by its fade, `Σ wᵢ(t) hᵢ + Σ_j w_j(t) s_j` (the FFT sea's rule for the bands).
    ///
    /// # Arguments
    /// - `x`, `z`: position (m); `direction`: the ray's unit direction; `footprint_angle` (rad)
    ///   `≥ 0` (0 keeps every wave and band); `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// The height (m).
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 §4 (waves faded with the pixel footprint).
    pub fn faded_height(&self, x: f64, z: f64, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        self.long.faded_height(x, z, direction, footprint_angle, t)
            + self.band.faded_height(x, z, direction, footprint_angle, t)
    }

    /// The height of the surface at `(x, z)` (m): the long waves' plus the band's spline.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.long.height(x, z) + self.band.height(x, z)
    }

    /// The sum that holds component `i` of [`LipschitzSum`] and its index there: `y` and the long
    /// waves are the trochoids' components `0..=L`, the bands the cascades' `1..=C`.
    fn part(&self, i: usize) -> (&dyn LipschitzSum, usize) {
        if i <= self.long_count { (&self.long, i) } else { (&self.band, i - self.long_count) }
    }

    /// How far the surface reaches above and below the mean level (m).
    fn top(&self) -> f64 {
        let (lo, hi) = self.band.height_bounds();
        self.long.total_amplitude + lo.abs().max(hi.abs())
    }
}

/// The heights of the trochoids `set`, snapped to the lattice of a tile `tile_m` (m), at the
/// `n × n` points of its grid at time `time` (s), by one inverse FFT: each wave's profile
/// `A τ_Q(k·x + φ − ωt) = A Σₕ aₕ(Q) cos(h(k·x + φ − ωt))` is a sum of harmonics on the lattice,
/// kept below the grid's Nyquist wavenumber (those beyond cannot be represented on the grid, and
/// sampled they would alias onto longer waves). The cost is `O(n² log n)` plus each wave's
/// harmonics, whatever the number of waves.
///
/// # Arguments
/// - `set`: waves whose wave vectors are on the lattice `(2π/L)(m, n)`.
/// - `time` (s), `tile_m` (m, `> 0`), `n`: a power of two `≥ 4`.
///
/// # Returns
/// The heights (m), row by row (`[j·n + i]` at `(iΔ, jΔ)`, `Δ = L/n`).
///
/// # References
/// Tessendorf 2001 (the sea as an inverse FFT); Watson 1944 §17.2 (the profile's harmonics).
fn band_heights(set: &TrochoidSet, time: f64, tile_m: f64, n: usize) -> Vec<f32> {
    let dk = TAU / tile_m;
    let size = n as i64;
    let mut spectrum = vec![Complex64::new(0.0, 0.0); n * n];
    let mut mean = 0.0;
    let mut planner = FftPlanner::new();
    for w in set.waves() {
        let kv = w.wavenumber() * w.direction_vector();
        let (mx, mz) = ((kv.x / dk).round() as i64, (kv.y / dk).round() as i64);
        // Harmonics h with |h m| < n/2 on both axes.
        let reach = mx.abs().max(mz.abs()).max(1);
        let harmonics = ((size / 2 - 1) / reach) as usize;
        if harmonics == 0 {
            continue;
        }
        let a = profile_harmonics(&mut planner, w.steepness(), harmonics);
        let offset = w.phase() - w.omega() * time;
        mean += w.amplitude() * a[0];
        for (h, &ah) in a.iter().enumerate().skip(1) {
            let (i, j) = ((h as i64 * mx).rem_euclid(size) as usize, (h as i64 * mz).rem_euclid(size) as usize);
            spectrum[j * n + i] += Complex64::from_polar(w.amplitude() * ah, h as f64 * offset);
        }
    }
    // Σ c e^{+2πi(p i + q j)/n}.
    inverse_fft_2d(&mut spectrum, n, planner.plan_fft_inverse(n).as_ref());
    spectrum.iter().map(|c| (c.re + mean) as f32).collect()
}

/// The Fourier coefficients `[a₀, …, a_H]` of the trochoid profile `τ_Q(s) = cos θ`,
/// `θ − Q sin θ = s` (even in `s`, so `τ_Q = Σ aₕ cos(h s)`), from `M ≥ 4H` samples of the exact
/// profile (aliasing from harmonics beyond `M − H`, which decay geometrically for `Q < 1`).
fn profile_harmonics(planner: &mut FftPlanner<f64>, q: f64, harmonics: usize) -> Vec<f64> {
    let m = (4 * harmonics).max(64).next_power_of_two();
    let mut samples: Vec<Complex64> =
        (0..m).map(|i| Complex64::new(solve_trochoid_phase(TAU * i as f64 / m as f64, q).1, 0.0)).collect();
    planner.plan_fft_forward(m).process(&mut samples);
    let scale = 1.0 / m as f64;
    (0..=harmonics).map(|h| samples[h].re * scale * if h == 0 { 1.0 } else { 2.0 }).collect()
}

/// Relative rounding of a band's stored grid: its f32 heights (2⁻²⁴ ≈ 6×10⁻⁸) through the
/// spline's interpolation, and its f32 coefficients (the prefilter amplifies up to 3×), about
/// 4×10⁻⁷ of the largest height; with a margin of 2.5.
const BAND_ROUNDING: f64 = 1e-6;

/// Bound of how far the traced band of the snapped waves `set` (a tile `tile_m` (m) on `n × n`
/// points) is from the waves themselves (m), at any time: for each wave of amplitude `A`, the
/// harmonics the grid leaves out, `A Σ_{h>H} |aₕ|` ([`profile_tail`]), the spline's
/// interpolation error of each harmonic kept, `A |aₕ| E₂(h θₓ, h θ_z)` ([`spline_error`],
/// `θ = 2π m/n` its phase step per grid spacing along each axis), and the grid's rounding.
///
/// # References
/// Hall C.A., Meyer W.W. 1976, "Optimal error bounds for cubic spline interpolation", J. Approx.
/// Theory 16, 105–122 (`‖f − s‖ ≤ (5/384) Δ⁴ ‖f⁽⁴⁾‖`); Watson 1944 §17.2 (the harmonics).
fn band_error(set: &TrochoidSet, tile_m: f64, n: usize) -> f64 {
    let dk = TAU / tile_m;
    let half = (n / 2) as i64;
    let mut planner = FftPlanner::new();
    let mut error = 0.0;
    for w in set.waves() {
        let kv = w.wavenumber() * w.direction_vector();
        let (mx, mz) = ((kv.x / dk).round() as i64, (kv.y / dk).round() as i64);
        let kept = ((half - 1) / mx.abs().max(mz.abs()).max(1)) as usize;
        let (a, tail) = profile_tail(&mut planner, w.steepness(), kept);
        let step = |m: i64| TAU * m as f64 / n as f64;
        let interpolation: f64 =
            (1..=kept).map(|h| a[h].abs() * spline_error(h as f64 * step(mx), h as f64 * step(mz))).sum();
        error += w.amplitude() * (tail + interpolation + BAND_ROUNDING * (1.0 + a[0].abs()));
    }
    error
}

/// Bound of the relative error of the periodic bicubic B-spline interpolating `e^{i(θₓu + θ_z v)}`
/// sampled at the integer points: `E₂ = e(θₓ) + (1 + e(θₓ)) e(θ_z)` with
/// `e(θ) = min(√2 (5/384) θ⁴, 4)`. Along one axis the interpolant of `e^{iθu}` is `R e^{iθu}`
/// with `|1 − R| ≤ e(θ)` (Hall & Meyer's bound on its real and imaginary parts, whose fourth
/// derivatives are at most `θ⁴`; and `|R| ≤ 3`, the B-spline's weights over its prefilter's
/// smallest gain `1/3`); the second axis interpolates that function again, of modulus at most
/// `1 + e(θₓ)`.
///
/// # Arguments
/// - `theta_x`, `theta_z`: phase steps per grid spacing (rad), `[−π, π]`.
///
/// # Returns
/// `E₂` (dimensionless).
fn spline_error(theta_x: f64, theta_z: f64) -> f64 {
    let e = |t: f64| (std::f64::consts::SQRT_2 * 5.0 / 384.0 * t.powi(4)).min(4.0);
    let ex = e(theta_x);
    ex + (1.0 + ex) * e(theta_z)
}

/// The profile's harmonics `[a₀, …, a_H]` ([`profile_harmonics`]) and a bound of those beyond,
/// `Σ_{h>H} |aₕ|`: twice their sum up to `8(H + 1)` (at least 511), from an FFT of the exact
/// profile. A measured bound: the coefficients fall geometrically for `Q < 1` (ratio about
/// `Q e^{√(1−Q²)}/(1 + √(1−Q²))`, 0.97 at `Q = 0.9`), so for the steepnesses of fitted waves
/// (`Q ≤ 0.9`) the sum's remainder is far below it; a test checks the bound on dense grids.
fn profile_tail(planner: &mut FftPlanner<f64>, q: f64, kept: usize) -> (Vec<f64>, f64) {
    let count = (8 * (kept + 1)).max(511);
    let a = profile_harmonics(planner, q, count);
    let tail: f64 = a[kept + 1..].iter().map(|v| v.abs()).sum();
    (a[..=kept].to_vec(), 2.0 * tail)
}

thread_local! {
    static SCRATCH: RefCell<(TierScratch, (RayState, Vec<CascadeOnRay>))> =
        RefCell::new((TierScratch::default(), (RayState::default(), Vec::new())));
}

/// The long waves' tiers, then the band's: tier 0 (`y`) is the trochoids'.
struct GriddedTiers<'a> {
    long: SeaTiers<'a>,
    band: CascadeTiers<'a>,
    /// The long waves' tier count (with `y`).
    split: usize,
    /// The bands' distance to the snapped sea (m).
    band_error: f64,
}

impl<'a> GriddedTiers<'a> {
    fn new(
        sea: &'a GriddedTrochoids,
        state: &'a mut (RayState, Vec<CascadeOnRay>),
        ray: &Ray,
        t_exit: f64,
        footprint_angle: f64,
        cone: f64,
    ) -> Self {
        let (waves, cascades) = state;
        let long = SeaTiers::new(&sea.long, waves, ray, t_exit, footprint_angle, cone);
        let band = CascadeTiers::new(&sea.band, cascades, ray, t_exit, footprint_angle, cone);
        let split = long.tier_count();
        Self { long, band, split, band_error: sea.error }
    }
}

impl RayTiers for GriddedTiers<'_> {
    fn tier_count(&self) -> usize {
        self.split + self.band.tier_count() - 1
    }

    fn bounds(&mut self, tier: usize, t: f64) -> TierBounds {
        if tier < self.split { self.long.bounds(tier, t) } else { self.band.bounds(tier + 1 - self.split, t) }
    }

    fn sample(&mut self, tier: usize, t: f64) -> TierSample {
        if tier < self.split { self.long.sample(tier, t) } else { self.band.sample(tier + 1 - self.split, t) }
    }

    fn spread_lipschitz(&self, tier: usize) -> f64 {
        if tier < self.split {
            self.long.spread_lipschitz(tier)
        } else {
            self.band.spread_lipschitz(tier + 1 - self.split)
        }
    }

    fn error_bound(&self) -> f64 {
        self.long.error_bound() + self.band.error_bound() + self.band_error
    }

    fn slope_error_bound(&self) -> f64 {
        self.long.slope_error_bound() + self.band.slope_error_bound()
    }
}

/// Component 0 is `y`, components `1..=L` the long waves (as [`TracedTrochoids`]'), components
/// `L + 1..=L + C` the bands (as [`FftFrame`]'s cascades).
impl LipschitzSum for GriddedTrochoids {
    fn component_count(&self) -> usize {
        self.long_count + 1 + self.band.cascade_count()
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        let (sum, j) = self.part(i);
        sum.component(j, p)
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_lipschitz(j)
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_min(j, a, b)
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_max(j, a, b)
    }

    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_directional_lipschitz(j, d)
    }

    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        let (sum, j) = self.part(i);
        sum.component_directional_derivative(j, p, d)
    }

    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_directional_curvature(j, d)
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_feature_size(j)
    }

    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        let (sum, j) = self.part(i);
        sum.component_fade_distance(j, d, footprint_angle)
    }

    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.top(), self.top())
    }

    tiered_fast_path!(SCRATCH, GriddedTiers, |s: &GriddedTrochoids| s.top());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
    use brine_trace::{Method, TraceOptions, TraceStats};

    /// The default sea at 10 m/s, 100 fitted trochoids.
    fn fitted() -> TrochoidSet {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        fit_trochoids(&pm, &d, 100, 7, &FitOptions::default()).unwrap()
    }

    /// The renderer's options of a primary ray (the tiered method, 1 mm), faded by a pixel of
    /// `footprint_angle` rad (0: no fading).
    fn options(footprint_angle: f64) -> TraceOptions {
        TraceOptions {
            method: Method::Tiered,
            t_max: 3000.0,
            tolerance: 1e-3,
            min_step: 1e-3,
            min_step_relative: 1e-4,
            tolerance_relative: 1e-5,
            footprint_angle,
            ..TraceOptions::default()
        }
    }

    /// The traced hits lie on the surface the sea defines (long waves plus the bands' splines):
    /// the tracer's tolerance, 1 mm, with the same for rounding.
    const ON_SURFACE_M: f64 = 2e-3;

    /// Spacing (m) of the march that looks for a crossing before the traced one: a fifth of the
    /// grid spacing of the finer band (the sampled surface cannot cross and come back between
    /// two samples unless a feature is narrower than that).
    const MARCH_M: f64 = 0.025;

    #[test]
    fn the_tracer_finds_the_first_crossing_of_the_gridded_surface() {
        let set = fitted();
        let bands = [
            GridBandSpec { shorter_than_m: 4.0, tile_m: 16.0, n: 128, blended: false },
            GridBandSpec { shorter_than_m: 16.0, tile_m: 64.0, n: 128, blended: true },
        ];
        let sea = GriddedTrochoids::new(&set, 2.0, &bands).unwrap();
        let (long, short) = sea.counts();
        assert!(long + short == 100 && long > 0 && short > 0 && sea.bands().len() == 2);
        // The components add up to the sum (each wave's f32 profile within the sea's own error).
        for k in 0..50 {
            let p = DVec3::new(37.0 * (k as f64 * 0.618_034).fract(), 0.1, 91.0 * (k as f64 * 0.414_214).fract());
            let sum: f64 = (0..sea.component_count()).map(|i| sea.component(i, p)).sum();
            assert!((sum - sea.value(p)).abs() <= 1e-5, "point {k}: {sum} against {}", sea.value(p));
        }
        let options = options(0.0);
        let mut stats = TraceStats::default();
        let mut hits = 0;
        for i in 0..200 {
            let a = 0.1 + 0.004 * i as f64;
            let dir = DVec3::new(a.cos() * 0.3, -a.sin(), a.cos()).normalize();
            let ray = Ray::new(DVec3::new(0.3 * i as f64, 10.0, 0.0), dir).unwrap();
            let Some(hit) = brine_trace::trace(&sea, &ray, &options, &mut stats) else { continue };
            // Darles' efficient method steps on the components one by one: the same first
            // crossing, each within its refinement tolerance.
            let darles = TraceOptions { method: Method::Darles, ..options };
            let other = brine_trace::trace(&sea, &ray, &darles, &mut stats).expect("the same crossing");
            let agree = 2.0 * (options.tolerance + options.tolerance_relative * hit.t);
            assert!((other.t - hit.t).abs() <= agree, "ray {i}: {} against {}", other.t, hit.t);
            let p = hit.point;
            assert!(
                (p.y - sea.height(p.x, p.z)).abs() < ON_SURFACE_M,
                "ray {i}: {} against {}",
                p.y,
                sea.height(p.x, p.z)
            );
            // No crossing before the one found. (The tracer may step over a skim thinner than its
            // minimum step; none occurs on these rays, so the check is the stricter one.)
            let steps = ((hit.t - ON_SURFACE_M) / MARCH_M) as usize;
            for s in 0..steps {
                let q = ray.origin() + (s as f64 * MARCH_M) * dir;
                assert!(
                    sea.value(q) > 0.0,
                    "ray {i}: below the surface at t = {} before the hit at {}",
                    s as f64 * MARCH_M,
                    hit.t
                );
            }
            hits += 1;
        }
        assert_eq!(hits, 200, "every ray points down: each must meet the sea");
    }

    /// The FFT fill equals the waves summed at the grid points, to the harmonics it leaves out
    /// above the grid's Nyquist wavenumber (each wave's `A Σ_{h>H} |aₕ|`, from 2048 harmonics),
    /// the reference's f32 profile error and the stored heights' f32 rounding.
    #[test]
    fn the_fft_fill_is_the_sum_of_the_waves_at_the_grid_points() {
        let set = fitted();
        let short: Vec<_> = set.waves().iter().filter(|w| w.wavelength() < 8.0).copied().collect();
        let (tile, n, time) = (32.0, 256usize, 2.0);
        let short = TileLattice::new(tile, None).unwrap().snap(&TrochoidSet::new(short)).unwrap();
        let filled = band_heights(&short, time, tile, n);
        let exact = TracedTrochoids::new(&short, time);
        let mut planner = FftPlanner::new();
        let dk = TAU / tile;
        let mut tail = 0.0;
        for w in short.waves() {
            let kv = w.wavenumber() * w.direction_vector();
            let reach = ((kv.x / dk).round().abs()).max((kv.y / dk).round().abs()).max(1.0) as usize;
            let kept = (n / 2 - 1) / reach;
            let a = profile_harmonics(&mut planner, w.steepness(), 2048);
            tail += w.amplitude() * a.iter().skip(kept + 1).map(|v| v.abs()).sum::<f64>();
        }
        // The reference's own error (its f32 profile) and the f32 rounding of the stored heights.
        let peak = filled.iter().fold(0.0f32, |m, v| m.max(v.abs()));
        let tolerance = tail + exact.error_bound() + f64::from(peak) * f64::from(f32::EPSILON);
        let dx = tile / n as f64;
        let mut worst = 0.0f64;
        for j in (0..n).step_by(7) {
            for i in (0..n).step_by(5) {
                let e = (f64::from(filled[j * n + i]) - exact.height(i as f64 * dx, j as f64 * dx)).abs();
                worst = worst.max(e);
            }
        }
        assert!(worst <= tolerance, "worst {worst} m against {tolerance} m");
        // The comparison is not vacuous: the band's heights reach many times the tolerance.
        assert!(f64::from(peak) > 10.0 * tolerance, "peak {peak} m against {tolerance} m");
    }

    /// Ray `i`'s `hit` is certified for the snapped sea `exact` within the grids' bound `eps` (m):
    /// on it within the tracer's tolerance, and no point of a [`MARCH_M`] march before it lies
    /// below it by `eps` or more.
    fn assert_certified_for(exact: &TracedTrochoids, ray: &Ray, hit: &brine_trace::Hit, eps: f64, i: usize) {
        let p = hit.point;
        let gap = (p.y - exact.height(p.x, p.z)).abs();
        assert!(gap < ON_SURFACE_M + eps, "ray {i}: {gap} m off the snapped sea");
        for s in 0..((hit.t - ON_SURFACE_M) / MARCH_M) as usize {
            let q = ray.origin() + (s as f64 * MARCH_M) * ray.direction();
            let below = exact.height(q.x, q.z) - q.y;
            assert!(below < eps, "ray {i}: {below} m below the snapped sea at t = {}", s as f64 * MARCH_M);
        }
    }

    /// Without blends the bands stand for the snapped sea: the traced crossings are certified
    /// for it within the bands' error bound, which stays well under the tracer's tolerance.
    #[test]
    fn unblended_bands_trace_the_snapped_sea() {
        let set = fitted();
        let bands = [
            GridBandSpec { shorter_than_m: 4.0, tile_m: 16.0, n: 256, blended: false },
            GridBandSpec { shorter_than_m: 16.0, tile_m: 128.0, n: 256, blended: false },
        ];
        let time = 2.0;
        let sea = GriddedTrochoids::new(&set, time, &bands).unwrap();
        let eps = sea.error_bound();
        assert!(eps > 0.0 && eps < 1e-3, "band error {eps} m");
        let exact = TracedTrochoids::new(sea.snapped(), time);
        assert_eq!(sea.snapped().len(), 100);
        let options = options(0.0);
        let mut stats = TraceStats::default();
        let mut hits = 0;
        for i in 0..150 {
            let a = 0.1 + 0.005 * i as f64;
            let dir = DVec3::new(-0.4, -a.sin(), a.cos()).normalize();
            let ray = Ray::new(DVec3::new(0.7 * i as f64, 10.0, -3.0), dir).unwrap();
            let Some(hit) = brine_trace::trace(&sea, &ray, &options, &mut stats) else { continue };
            assert_certified_for(&exact, &ray, &hit, eps, i);
            hits += 1;
        }
        assert_eq!(hits, 150, "every ray points down: each must meet the sea");
    }

    /// The bicubic spline of a sampled harmonic stays within `E₂` of it (plus the f32 grid's
    /// rounding): single harmonics on a 64² grid, at phase steps from 0.2 to 2.9 rad per spacing,
    /// checked at 4 000 points; and the bound is not loose by orders of magnitude at ten points
    /// per wave.
    #[test]
    fn the_spline_error_bound_holds_for_one_harmonic() {
        let (n, tile) = (64usize, 64.0);
        for (mx, mz) in [(2i64, 0i64), (5, 3), (-7, 11), (20, -9), (29, 1)] {
            let (tx, tz) = (TAU * mx as f64 / n as f64, TAU * mz as f64 / n as f64);
            let heights: Vec<f32> =
                (0..n * n).map(|i| ((i % n) as f64 * tx + (i / n) as f64 * tz + 0.3).cos() as f32).collect();
            let c = FftCascade::from_heights(tile, n, heights, (0.1, 1.0), 0.1, 0.5, DVec3::ZERO, None);
            let bound = spline_error(tx, tz) + BAND_ROUNDING;
            let mut worst = 0.0f64;
            for k in 0..4000 {
                let (x, z) = ((k as f64 * 0.618_034).fract() * tile, (k as f64 * 0.414_214).fract() * tile);
                worst = worst.max((c.height(x, z) - (x * tx + z * tz + 0.3).cos()).abs());
            }
            assert!(worst <= bound, "({mx}, {mz}): {worst} against {bound}");
            if mx.abs().max(mz.abs()) <= 6 {
                assert!(bound < 20.0 * worst.max(1e-7), "({mx}, {mz}): bound {bound} against {worst}");
            }
        }
    }

    /// The tail bound of the profile's harmonics holds: `|τ_Q(s) − Σ_{h≤H} aₕ cos hs|` at 20 000
    /// points of `s` is within it, for steepnesses up to 0.9 and 1 to 32 harmonics kept.
    #[test]
    fn the_profile_tail_bounds_the_harmonics_left_out() {
        let mut planner = FftPlanner::new();
        for q in [0.05, 0.3, 0.6, 0.9] {
            for kept in [1usize, 2, 4, 8, 32] {
                let (a, tail) = profile_tail(&mut planner, q, kept);
                let mut worst = 0.0f64;
                for i in 0..20_000 {
                    let s = TAU * i as f64 / 20_000.0;
                    let series: f64 = a.iter().enumerate().map(|(h, ah)| ah * (h as f64 * s).cos()).sum();
                    worst = worst.max((solve_trochoid_phase(s, q).1 - series).abs());
                }
                assert!(worst <= tail + 1e-12, "Q = {q}, H = {kept}: {worst} against {tail}");
            }
        }
    }

    /// Steep waves (Q 0.5–0.8) with few harmonics below the grid's Nyquist wavenumber: the FFT
    /// fill equals the profiles solved in f64 at the grid points, to the harmonics left out (from
    /// 2048 harmonics) and the f32 rounding of the stored heights.
    #[test]
    fn steep_waves_near_the_grid_limit_are_filled_to_their_tail() {
        let (tile, n, time) = (16.0, 64usize, 0.7);
        let dk = TAU / tile;
        // Lattice indices (m, n) with reaches 4, 7 and 10 of the grid's 31: 7, 4 and 3 harmonics.
        let waves: Vec<_> = [((4.0, 1.0), 0.8, 0.02), ((-7.0, 3.0), 0.6, 0.01), ((2.0, -10.0), 0.5, 0.006)]
            .iter()
            .map(|&((mx, mz), q, a): &((f64, f64), f64, f64)| {
                let k = dk * f64::hypot(mx, mz);
                crate::Trochoid::new(a, k, f64::atan2(mz, mx), crate::omega_deep_water(k), 0.4 * mx, q).unwrap()
            })
            .collect();
        let set = TrochoidSet::new(waves);
        let filled = band_heights(&set, time, tile, n);
        let mut planner = FftPlanner::new();
        let mut tail = 0.0;
        for w in set.waves() {
            let kv = w.wavenumber() * w.direction_vector();
            let reach = (kv.x / dk).round().abs().max((kv.y / dk).round().abs()) as usize;
            let a = profile_harmonics(&mut planner, w.steepness(), 2048);
            tail += w.amplitude() * a.iter().skip((n / 2 - 1) / reach + 1).map(|v| v.abs()).sum::<f64>();
        }
        let peak = filled.iter().fold(0.0f32, |m, v| m.max(v.abs()));
        let tolerance = tail + f64::from(peak) * f64::from(f32::EPSILON);
        let dx = tile / n as f64;
        let mut worst = 0.0f64;
        for j in 0..n {
            for i in 0..n {
                let (x, z) = (i as f64 * dx, j as f64 * dx);
                let exact: f64 = set
                    .waves()
                    .iter()
                    .map(|w| {
                        let kv = w.wavenumber() * w.direction_vector();
                        let s = kv.x * x + kv.y * z + w.phase() - w.omega() * time;
                        w.amplitude() * solve_trochoid_phase(s, w.steepness()).1
                    })
                    .sum();
                worst = worst.max((f64::from(filled[j * n + i]) - exact).abs());
            }
        }
        assert!(worst <= tolerance, "worst {worst} m against {tolerance} m");
        // The harmonics left out matter here: the tail is above the rounding.
        assert!(tail > 1e-6 && worst > 0.1 * tail, "tail {tail} m, worst {worst} m");
    }

    /// The primary rays of a tile, traced together (cones, footprint fading, held waves and
    /// bands) meet the sea where each traced alone does.
    #[test]
    fn a_tile_of_rays_meets_the_sea_where_each_ray_does() {
        let set = fitted();
        let bands = [
            GridBandSpec { shorter_than_m: 4.0, tile_m: 16.0, n: 128, blended: true },
            GridBandSpec { shorter_than_m: 16.0, tile_m: 64.0, n: 128, blended: false },
        ];
        let sea = GriddedTrochoids::new(&set, 2.0, &bands).unwrap();
        let options = options(1.8e-3);
        let origin = DVec3::new(0.0, 10.0, 0.0);
        let width = 16;
        let directions: Vec<DVec3> = (0..width * width)
            .map(|i| DVec3::new(0.02 * (i % width) as f64 - 0.16, -0.05 - 0.015 * (i / width) as f64, 1.0).normalize())
            .collect();
        let mut hits = vec![None; directions.len()];
        let mut stats = TraceStats::default();
        brine_trace::trace_tile(
            &sea,
            &brine_trace::RayTile { origin, directions: &directions, width },
            &options,
            &mut stats,
            &mut hits,
            None,
        );
        for (i, (dir, tiled)) in directions.iter().zip(&hits).enumerate() {
            let alone = brine_trace::trace(&sea, &Ray::new(origin, *dir).unwrap(), &options, &mut stats);
            let (Some(a), Some(b)) = (alone, tiled) else { panic!("ray {i}: a miss") };
            let agree = 2.0 * (options.tolerance + options.tolerance_relative * a.t);
            assert!((a.t - b.t).abs() <= agree, "ray {i}: {} alone against {} in the tile", a.t, b.t);
        }
    }

    /// 400 waves fitted to the Pierson–Moskowitz sea at `u10` (m/s).
    fn fitted_400(u10: f64) -> TrochoidSet {
        let pm = PiersonMoskowitz::from_u10(u10).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        fit_trochoids(&pm, &d, 400, 3, &FitOptions::default()).unwrap()
    }

    /// The renderer's layout splits the fitted sea at every wind into five to nine bands that
    /// hold most waves, each band's waves on its tile's lattice and moved by the snap at most by half a
    /// lattice diagonal, `√2/2 · 2π/L` in wave vector (so shorter than the cut by that margin).
    #[test]
    fn the_default_layout_splits_the_sea_at_every_wind() {
        for u in [2.0, 5.0, 10.0, 16.0, 22.0] {
            let set = fitted_400(u);
            let layout = BandedTrochoids::default_layout(&set).expect("a layout");
            assert!((5..=9).contains(&layout.len()), "{u} m/s: {layout:?}");
            let banded = BandedTrochoids::new(&set, &layout).unwrap();
            let (long, short) = banded.counts();
            assert_eq!(long + short, 400, "{u} m/s");
            assert!((1..100).contains(&long), "{u} m/s: {long} waves left long");
            let mut band_waves = banded.bands.iter().flat_map(|(b, w)| w.waves().iter().map(move |w| (b, w)));
            assert!(band_waves.all(|(b, w)| {
                let dk = TAU / b.tile_m;
                let kv = w.wavenumber() * w.direction_vector() / dk;
                let on_lattice = (kv.x - kv.x.round()).abs() < 1e-6 && (kv.y - kv.y.round()).abs() < 1e-6;
                let k_cut = TAU / b.shorter_than_m;
                on_lattice && w.wavenumber() > k_cut - std::f64::consts::FRAC_1_SQRT_2 * dk
            }));
            // The amplitudes and steepnesses are the fitted ones: the snap moves wave vectors only.
            assert!((banded.set().variance() - set.variance()).abs() <= 1e-12 * set.variance(), "{u} m/s");
            // The bands' slope shares are shares: each in (0, 1), their sum below 1 (the long
            // waves keep some); and none holds more than a quarter of the slopes, so the sea
            // repeats little over any one tile.
            let shares = banded.repeating_slope_shares();
            let sum: f64 = shares.iter().map(|s| s.1).sum();
            assert!(shares.iter().all(|s| s.1 > 0.0 && s.1 <= 0.25) && sum < 1.0, "{u} m/s: {shares:?}");
        }
    }

    /// The grids of the renderer's layout stay close to the snapped sea relative to the waves'
    /// size: the bound is at most 2.5×10⁻⁴ of the sea's total amplitude `ΣA` at every wind
    /// (measured 1.34×10⁻⁴ at each: the fitted Pierson–Moskowitz sea scales with `U²` as a whole,
    /// so the ratio does not change; 1.5 mm at 10 m/s, 7.2 mm at 22 m/s, which the tracer adds to
    /// its 1 mm tolerance). The limit is about twice the measured ratio: a regression guard.
    #[test]
    fn the_default_grids_are_close_to_the_snapped_sea() {
        for u in [2.0, 10.0, 22.0] {
            let set = fitted_400(u);
            let banded = BandedTrochoids::new(&set, &BandedTrochoids::default_layout(&set).unwrap()).unwrap();
            let total: f64 = set.waves().iter().map(|w| w.amplitude()).sum();
            let eps = banded.error_bound();
            assert!(eps > 0.0 && eps <= 2.5e-4 * total, "{u} m/s: bound {eps} m against ΣA = {total} m");
        }
    }

    /// A set that cannot be split has no layout: no wave, or waves all of one length.
    #[test]
    fn sets_that_cannot_be_split_have_no_layout() {
        assert!(BandedTrochoids::default_layout(&TrochoidSet::new(Vec::new())).is_none());
        let one: Vec<_> = fitted().waves().iter().take(1).copied().collect();
        assert!(BandedTrochoids::default_layout(&TrochoidSet::new(one.clone())).is_none());
        let twins = TrochoidSet::new(vec![one[0]; 5]);
        assert!(BandedTrochoids::default_layout(&twins).is_none());
    }

    /// The bands are filled side by side on the threads: the same grids, bit for bit, on one
    /// thread and on two.
    #[test]
    fn the_grids_are_the_same_whatever_the_threads() {
        let set = fitted_400(10.0);
        let banded = BandedTrochoids::new(&set, &BandedTrochoids::default_layout(&set).unwrap()).unwrap();
        let grids = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let sea = pool.install(|| GriddedTrochoids::at_time(&banded, 3.5));
            sea.bands().iter().map(|c| c.heights().iter().map(|h| h.to_bits()).collect::<Vec<_>>()).collect::<Vec<_>>()
        };
        assert!(grids(1) == grids(2));
    }

    /// With the renderer's layout at 400 waves, rays from 10 m up meet the sea with footprint
    /// fading (as primary rays), and without it they are certified for the snapped sea: the hit
    /// on it and no earlier crossing along a 2.5 cm march, within the grids' bound.
    #[test]
    fn the_default_grids_trace_the_snapped_sea() {
        let set = fitted_400(10.0);
        let banded = BandedTrochoids::new(&set, &BandedTrochoids::default_layout(&set).unwrap()).unwrap();
        let time = 1.5;
        let sea = GriddedTrochoids::at_time(&banded, time);
        let eps = sea.error_bound();
        let exact = TracedTrochoids::new(banded.set(), time);
        let mut stats = TraceStats::default();
        for i in 0..40 {
            let a = 0.12 + 0.01 * i as f64;
            let dir = DVec3::new(0.3 - 0.015 * i as f64, -a.sin(), a.cos()).normalize();
            let ray = Ray::new(DVec3::new(1.3 * i as f64, 10.0, 2.0), dir).unwrap();
            // Faded as a 1 mrad pixel fades it, the ray still meets the sea.
            assert!(brine_trace::trace(&sea, &ray, &options(1e-3), &mut stats).is_some(), "ray {i} misses");
            let hit = brine_trace::trace(&sea, &ray, &options(0.0), &mut stats).expect("a downward ray hits");
            assert_certified_for(&exact, &ray, &hit, eps, i);
        }
    }
}
