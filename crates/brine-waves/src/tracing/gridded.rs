//! A study, not a surface of the renderer: the trochoid sea with its shorter waves gathered into
//! periodic grids, traced as the FFT sea's cascades are (docs/dev/wave-scaling.md, option 3).
//!
//! The waves at least the last band's cut long stay trochoids, traced by their tiers. The
//! shorter ones are snapped band by band to the lattice of a square tile
//! ([`TileLattice::snap`]), their sum synthesised on the tile's grid by one inverse FFT, and its
//! cubic B-spline traced as one tier with the bounds of an [`FftCascade`] (its own extreme values
//! and slopes, instead of the sums of the waves' amplitudes and slopes). What `cargo xtask bench
//! grid-band` measures: how much of the intersection's growth with the wave count such bands
//! remove. The bands are not shaded, not faded wave by wave (each fades whole, at its longest
//! wave's distance) and not exported.

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

/// The trochoid sea with its short waves on a grid (the gridded-band study; see the module).
#[doc(hidden)]
#[derive(Debug)]
pub struct GriddedTrochoids {
    long: TracedTrochoids,
    band: FftFrame,
    /// Waves in `long`.
    long_count: usize,
    /// Waves gathered into the band.
    short_count: usize,
}

/// One grid of the study's bands: the waves shorter than `shorter_than_m` (and not shorter than
/// the previous band's cut) on a tile of side `tile_m` at `n × n` points.
#[doc(hidden)]
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

impl GriddedTrochoids {
    /// The sea of `set` at time `time` (s), the waves gathered into the `bands` (by increasing
    /// cut), those at least the last cut long traced as trochoids.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a tile out of [`TileLattice::new`]'s range, cuts that leave
    /// no long wave or an empty band, or a resolution that is not a power of two `≥ 4`.
    pub fn new(set: &TrochoidSet, time: f64, bands: &[GridBandSpec]) -> Result<Self, WaveError> {
        let mut rest: Vec<_> = set.waves().to_vec();
        let mut cascades = Vec::with_capacity(bands.len());
        let mut short_count = 0;
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
            short_count += short.len();
            let lattice = TileLattice::new(b.tile_m, None)?;
            cascades.push(Self::cascade(&lattice.snap(&TrochoidSet::new(short))?, time, b, cascades.len()));
        }
        crate::error::check(
            "shorter_than_m",
            bands.last().map_or(0.0, |b| b.shorter_than_m),
            !rest.is_empty(),
            "below the longest wave",
        )?;
        Ok(Self {
            long: TracedTrochoids::new(&TrochoidSet::new(rest.clone()), time),
            band: FftFrame::from_cascades(time, cascades),
            long_count: rest.len(),
            short_count,
        })
    }

    /// The snapped waves `short` tabulated on the band's grid by one inverse FFT
    /// ([`band_heights`]).
    fn cascade(short: &TrochoidSet, time: f64, b: &GridBandSpec, index: usize) -> FftCascade {
        let heights = band_heights(short, time, b.tile_m, b.n);
        let k_longest = short.waves().iter().map(|w| w.wavenumber()).fold(f64::INFINITY, f64::min);
        let k_shortest = short.waves().iter().map(|w| w.wavenumber()).fold(0.0, f64::max);
        let covariance = short.waves().iter().fold(DVec3::ZERO, |c, w| {
            let d = w.direction_vector();
            c + w.mean_square_slope() * DVec3::new(d.x * d.x, d.x * d.y, d.y * d.y)
        });
        let blend = b.blended.then(|| TileBlend::new(b.tile_m, 0x9_71d, index));
        FftCascade::from_heights(
            b.tile_m,
            b.n,
            heights,
            (k_longest, k_shortest),
            k_longest,
            short.variance(),
            covariance,
            blend,
        )
    }

    /// `(long, short)`: the waves traced as trochoids and those gathered into the grid.
    pub fn counts(&self) -> (usize, usize) {
        (self.long_count, self.short_count)
    }

    /// The bands' cascades.
    pub fn bands(&self) -> &[FftCascade] {
        self.band.cascades()
    }

    /// The height of the surface at `(x, z)` (m): the long waves' plus the band's spline.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.long.height(x, z) + self.band.height(x, z)
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
        Self { long, band, split }
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
        self.long.error_bound() + self.band.error_bound()
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
        if i <= self.long_count { self.long.component(i, p) } else { self.band.component(i - self.long_count, p) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i <= self.long_count {
            self.long.component_lipschitz(i)
        } else {
            self.band.component_lipschitz(i - self.long_count)
        }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i <= self.long_count {
            self.long.component_min(i, a, b)
        } else {
            self.band.component_min(i - self.long_count, a, b)
        }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i <= self.long_count {
            self.long.component_max(i, a, b)
        } else {
            self.band.component_max(i - self.long_count, a, b)
        }
    }

    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i <= self.long_count {
            self.long.component_directional_lipschitz(i, d)
        } else {
            self.band.component_directional_lipschitz(i - self.long_count, d)
        }
    }

    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        if i <= self.long_count {
            self.long.component_directional_derivative(i, p, d)
        } else {
            self.band.component_directional_derivative(i - self.long_count, p, d)
        }
    }

    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i <= self.long_count {
            self.long.component_directional_curvature(i, d)
        } else {
            self.band.component_directional_curvature(i - self.long_count, d)
        }
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        if i <= self.long_count {
            self.long.component_feature_size(i)
        } else {
            self.band.component_feature_size(i - self.long_count)
        }
    }

    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i <= self.long_count {
            self.long.component_fade_distance(i, d, footprint_angle)
        } else {
            self.band.component_fade_distance(i - self.long_count, d, footprint_angle)
        }
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

    /// The traced hits lie on the surface the sea defines (long waves plus the bands' splines):
    /// the tracer's tolerance, 1 mm, with the same for rounding.
    const ON_SURFACE_M: f64 = 2e-3;

    /// Spacing (m) of the march that looks for a crossing before the traced one: a fifth of the
    /// grid spacing of the finer band (the sampled surface cannot cross and come back between
    /// two samples unless a feature is narrower than that).
    const MARCH_M: f64 = 0.025;

    #[test]
    fn the_tracer_finds_the_first_crossing_of_the_gridded_surface() {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let set = fit_trochoids(&pm, &d, 100, 7, &FitOptions::default()).unwrap();
        let bands = [
            GridBandSpec { shorter_than_m: 4.0, tile_m: 16.0, n: 128, blended: false },
            GridBandSpec { shorter_than_m: 16.0, tile_m: 64.0, n: 128, blended: true },
        ];
        let sea = GriddedTrochoids::new(&set, 2.0, &bands).unwrap();
        let (long, short) = sea.counts();
        assert!(long + short == 100 && long > 0 && short > 0 && sea.bands().len() == 2);
        let options = TraceOptions {
            method: Method::Tiered,
            t_max: 3000.0,
            tolerance: 1e-3,
            min_step: 1e-3,
            min_step_relative: 1e-4,
            tolerance_relative: 1e-5,
            ..TraceOptions::default()
        };
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
            // No crossing before the one found.
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
        assert!(hits > 150, "{hits} hits");
    }

    /// The FFT fill equals the waves summed at the grid points, to the harmonics it leaves out
    /// above the grid's Nyquist wavenumber (each wave's `A Σ_{h>H} |aₕ|`, computed from 64
    /// harmonics) and the f32 profile's and the stored heights' rounding (10⁻⁶ of `Σ A`).
    #[test]
    fn the_fft_fill_is_the_sum_of_the_waves_at_the_grid_points() {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let set = fit_trochoids(&pm, &d, 100, 7, &FitOptions::default()).unwrap();
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
            let a = profile_harmonics(&mut planner, w.steepness(), 64);
            tail += w.amplitude() * a.iter().skip(kept + 1).map(|v| v.abs()).sum::<f64>();
        }
        let tolerance = tail + 1e-6 * short.total_amplitude();
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
        let peak = filled.iter().fold(0.0f32, |m, v| m.max(v.abs()));
        assert!(f64::from(peak) > 10.0 * tolerance, "peak {peak} m against {tolerance} m");
    }
}
