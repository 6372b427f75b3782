//! The FFT ocean of Tessendorf (2001), as Li Ying et al. (2018, §2.2) and Dupuy & Bruneton (2012)
//! synthesise it: random complex amplitudes drawn from a directional spectrum, evolved by the
//! dispersion relation, summed by inverse FFTs on periodic cascades of tiles.

use std::f64::consts::TAU;
use std::sync::Arc;

use glam::{DVec2, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

use crate::fft::blend::TileBlend;
use crate::fft::options::FFT_CASCADE_CUT_INDEX;
use crate::fft::spectrum::{Band, cell_energy, directional_spectrum};
use crate::looping::{LoopDistortion, looped_omega};
use crate::{Dispersion, FftFrame, FftOptions, Spectrum, Spreading, WaveError};

mod kinematics;

use kinematics::*;
pub use kinematics::{FftKinematics, FftRestJacobian, ParticleState};

/// One wave vector of a cascade with energy at `k` or at `−k`.
#[derive(Debug, Clone, Copy)]
struct Mode {
    /// Index in the `N × N` spectral array, `(n_z mod N)·N + (n_x mod N)`.
    index: usize,
    kx: f64,
    kz: f64,
    k: f64,
    /// Angular frequency `ω(k)` (rad s⁻¹), quantised to `2π/T` multiples when looping.
    omega: f64,
    /// `h̃₀(k)` (m).
    h0: Complex64,
    /// `conj(h̃₀(−k))` (m).
    h0_minus_conj: Complex64,
}

/// The spectrum of one cascade: its grid, band and random amplitudes.
#[derive(Clone)]
pub(crate) struct CascadeSpectrum {
    pub(crate) tile: f64,
    pub(crate) n: usize,
    pub(crate) band: Band,
    modes: Vec<Mode>,
    /// `Σ E_cell` over the band (m²): the expected height variance of the cascade.
    pub(crate) variance: f64,
    /// `Σ E_cell (kx², kx kz, kz²)`: the expected slope covariance of the cascade.
    pub(crate) slope_covariance: [f64; 3],
    /// Wavenumber of the longest wave the cascade holds (rad m⁻¹).
    pub(crate) k_longest: f64,
    fft: Arc<dyn Fft<f64>>,
}

impl std::fmt::Debug for CascadeSpectrum {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CascadeSpectrum")
            .field("tile", &self.tile)
            .field("n", &self.n)
            .field("band", &self.band)
            .field("modes", &self.modes.len())
            .field("variance", &self.variance)
            .finish()
    }
}

/// The fields of one cascade at one instant on its rest-position grid `u = (iΔ, jΔ)`,
/// `i, j ∈ [0, N)`, `Δ = L/N`, stored row by row (`[j·N + i]`, `i` along x): the trig polynomials
/// of [`FftOcean`] sampled at the grid points, exactly (up to the FFT's rounding, ~10⁻¹⁵ of the
/// largest amplitude).
#[derive(Debug, Clone, PartialEq)]
pub struct FftRestFields {
    /// Grid resolution `N`.
    pub resolution: usize,
    /// Tile size `L` (m).
    pub tile_size: f64,
    /// Height `h(u) = Σ h̃ e^{ik·u}` (m).
    pub height: Vec<f64>,
    /// Slope `∂h/∂x = Σ i kₓ h̃ e^{ik·u}` (dimensionless).
    pub slope_x: Vec<f64>,
    /// Slope `∂h/∂z = Σ i k_z h̃ e^{ik·u}`.
    pub slope_z: Vec<f64>,
    /// Horizontal displacement per unit choppiness `Dₓ = Σ i (kₓ/k) h̃ e^{ik·u}` (m).
    pub displacement_x: Vec<f64>,
    /// `D_z = Σ i (k_z/k) h̃ e^{ik·u}` (m).
    pub displacement_z: Vec<f64>,
    /// `∂Dₓ/∂x = −Σ (kₓ²/k) h̃ e^{ik·u}` (dimensionless).
    pub dxx: Vec<f64>,
    /// `∂D_z/∂z = −Σ (k_z²/k) h̃ e^{ik·u}`.
    pub dzz: Vec<f64>,
    /// `∂Dₓ/∂z = ∂D_z/∂x = −Σ (kₓk_z/k) h̃ e^{ik·u}`.
    pub dxz: Vec<f64>,
}

impl FftRestFields {
    /// The Jacobian of the choppy map `x = u + λD(u)` at a grid point,
    /// `J = (1 + λ∂Dₓ/∂x)(1 + λ∂D_z/∂z) − λ²(∂Dₓ/∂z)²`.
    ///
    /// # Arguments
    /// - `idx`: grid index `j·N + i`, `< N²`.
    /// - `choppiness`: `λ ≥ 0`.
    ///
    /// # Returns
    /// `J` (dimensionless): `< 1` compressed, `< 0` folded.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; Tessendorf 2001 (choppy waves); docs/equations.md §10.
    pub fn jacobian(&self, idx: usize, choppiness: f64) -> f64 {
        let l = choppiness;
        (1.0 + l * self.dxx[idx]) * (1.0 + l * self.dzz[idx]) - l * l * self.dxz[idx] * self.dxz[idx]
    }
}

/// A periodic FFT ocean (Tessendorf 2001) for any [`Spectrum`] with a directional [`Spreading`]:
/// the random amplitudes of every cascade, ready to be synthesised at any time.
///
/// **Spectrum.** Wave vectors `k = (2π/L)(nₓ, n_z)` on each cascade's grid, `|nₓ|, |n_z| ≤ N/2 − 1`
/// (the Nyquist row and column are left empty so that every wave has its opposite on the grid).
/// Each cell of the wave-vector plane carries its variance `E(k) = ∫_cell Ψ d²k` (m²), with
/// `Ψ(k) = S(k) D(θ − θ_w; ω(k))/k` ([`directional_spectrum`]), integrated by Gauss–Legendre
/// quadrature over the part of the cell inside the cascade's band, so that the cascades
/// partition the plane: cascade 0 holds `Δk₀/2 ≤ |k|_∞ < 4Δk₁`, cascade `c` holds
/// `4Δk_c ≤ |k|_∞ < 4Δk_{c+1}`, the last one up to `(N/2 − ½)Δk` ([`crate::FFT_CASCADE_CUT_INDEX`]).
/// The `k = 0` cell (waves longer than the largest tile, and the mean level) is empty.
///
/// **Amplitudes** (Tessendorf 2001, Eq. 42–43 with Brine's normalisation):
/// `h̃₀(k) = ½ (ξᵣ + i ξᵢ) √E(k)`, `ξ ~ N(0, 1)` independent, so `E|h̃₀(k)|² = E(k)/2`, and
/// `h̃(k, t) = h̃₀(k) e^{−iωt} + conj(h̃₀(−k)) e^{iωt}`, `ω = ω(|k|)` by the spectrum's dispersion
/// relation. Then `h̃(−k) = conj(h̃(k))` (the height is real), `E|h̃(k)|² = (E(k) + E(−k))/2` and the
/// expected variance of `h(x) = Σ h̃(k, t) e^{ik·x}` is `Σ E(k) = ∫_band Ψ d²k`. (Tessendorf writes
/// `h̃₀ = (ξᵣ + iξᵢ)√(P_h/2)`: his `P_h(k)` is `E(k)/2` here. His `e^{+iωt}` on `h̃₀(k)` makes the
/// energy at `k` travel toward `−k`; Brine uses `e^{−iωt}` so that a down-wind spreading gives
/// waves travelling with the wind.)
///
/// **Seeding.** The pair `(ξᵣ, ξᵢ)` of wave vector `(nₓ, n_z)` of cascade `c` comes from ChaCha8
/// seeded with the seed, on stream `c`, at the word position keyed by the integer pair
/// `(nₓ, n_z)` alone, by the Box–Muller transform: a change of resolution keeps every wave vector
/// that both grids hold, so the large waves stay the same.
///
/// **Choppiness** (Tessendorf 2001, §4.6): the horizontal displacement
/// `D(x, t) = Σ i (k/k) h̃(k, t) e^{ik·x}` moves the surface point of rest position `u` to
/// `u + λ D(u)`. For one wave `h = A cos φ` this is `−A k̂ sin φ`, Gerstner's `u − (Q/k) d̂ sin φ`
/// with `Q = λkA` (docs/equations.md §1): a positive `λ` sharpens the crests. Tessendorf prints
/// `−i`, which with `λ > 0` sharpens the troughs instead (so codes following him use `λ < 0`).
///
/// **Looping.** With a loop period `T`, `ω` is replaced by `(2π/T) max(1, round(ωT/2π))`: every
/// wave then repeats after `T` (and none is frozen), at the cost of a relative frequency error up
/// to `P/(2T)` for a wave of period `P ≤ 2T`, and of `P/T − 1` beyond, where the wave is sped up
/// to one turn per loop ([`crate::looped_omega`]; [`FftOcean::loop_distortion`] measures it).
///
/// **Cost.** Construction integrates `Ψ` over every cell of every band (one to 64 evaluations
/// per cell). Synthesis ([`FftOcean::rest_fields`], [`FftOcean::at_time`]) costs one `sincos` per
/// wave vector and four complex `N × N` inverse FFTs per cascade (the eight real fields packed
/// two by two), in parallel over the cascades (rayon); see `docs/benchmarks.md`.
///
/// # Example
///
/// ```
/// use brine_trace::{Method, Ray, TraceOptions, TraceStats, trace};
/// use brine_waves::{Directions, Elfouhaily, FftOcean, FftOptions};
/// use glam::DVec3;
///
/// let sea = Elfouhaily::from_fetch(10.0, 1e5)?;
/// let options = FftOptions { resolution: 64, ..FftOptions::for_spectrum(&sea, 2) };
/// let ocean = FftOcean::new(&sea, &sea.spreading(Directions::Downwind), &options)?;
/// let frame = ocean.at_time(12.5);
/// let (lo, hi) = frame.height_bounds();
/// assert!(lo <= frame.height(3.0, -2.0) && frame.height(3.0, -2.0) <= hi);
/// // The frame is a brine_trace::LipschitzSum: trace it like any other sea.
/// let ray = Ray::new(DVec3::new(0.0, 10.0, 0.0), DVec3::new(1.0, -0.2, 0.3)).unwrap();
/// let hit = trace(&frame, &ray, &TraceOptions { method: Method::Tiered, ..TraceOptions::default() }, &mut TraceStats::default());
/// assert!(hit.is_some());
/// # Ok::<(), brine_waves::WaveError>(())
/// ```
///
/// # References
/// Tessendorf J. 2001, "Simulating Ocean Water", SIGGRAPH course notes, §3.3–4.6; Li Ying et al.
/// 2018, §2.2; Dupuy J., Bruneton E. 2012 (cascades, Jacobian); docs/equations.md §4, §10.
#[derive(Debug, Clone)]
pub struct FftOcean {
    options: FftOptions,
    cascades: Vec<CascadeSpectrum>,
    dispersion: Dispersion,
    /// How far the loop period moved the modes' frequencies (with a loop period only).
    loop_distortion: Option<LoopDistortion>,
}

/// What [`FftOcean::rest_fields_on_grid`] left out of the sea for a grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FftGridBand {
    /// Modes weighted below 1 (each wave vector of the spectral grid once).
    pub faded: usize,
    /// Slope covariance `(⟨ζx²⟩, ⟨ζx ζz⟩, ⟨ζz²⟩)` (dimensionless) the weights removed from the
    /// linear (undisplaced) sea at that time, `Σ (1 − w²) |ĥ(k)|² (kₓ², kₓk_z, k_z²)`, the
    /// modes' amplitudes at the time (Parseval over the tile).
    pub lost_slope_covariance: DVec3,
}

/// Word position of the random pair of wave vector `(nₓ, n_z)`: one `ChaCha` block (16 words) per
/// pair, keyed by the zig-zag codes of the two integers.
fn word_position(nx: i64, nz: i64) -> u128 {
    let zig = |v: i64| ((v << 1) ^ (v >> 63)) as u64 & 0xffff_ffff;
    (u128::from(zig(nx)) << 32 | u128::from(zig(nz))) * 16
}

/// The standard normal pair `(ξᵣ, ξᵢ)` of wave vector `(nₓ, n_z)` by Box–Muller.
fn gaussian_pair(rng: &mut ChaCha8Rng, nx: i64, nz: i64) -> (f64, f64) {
    rng.set_word_pos(word_position(nx, nz));
    let u1: f64 = 1.0 - rng.random::<f64>(); // (0, 1]
    let u2: f64 = rng.random();
    let r = libm::sqrt(-2.0 * libm::log(u1));
    let (s, c) = libm::sincos(TAU * u2);
    (r * c, r * s)
}

impl FftOcean {
    /// Draws the random amplitudes of every cascade.
    ///
    /// # Arguments
    /// - `spectrum`: the one-sided `S(ω)` (and its dispersion relation, which sets `ω(k)`).
    /// - `spreading`: `D(θ; ω)`, `θ` from the wind direction.
    /// - `options`: see [`FftOptions`].
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a bad option ([`FftOptions::validate`]);
    /// [`WaveError::EmptyBand`] if the spectrum holds no energy on the grids.
    pub fn new(spectrum: &dyn Spectrum, spreading: &dyn Spreading, options: &FftOptions) -> Result<Self, WaveError> {
        options.validate()?;
        let dispersion = spectrum.dispersion();
        let n = options.resolution;
        let count = options.tile_sizes.len();
        let mut planner = FftPlanner::new();
        let fft = planner.plan_fft_inverse(n);
        let mut cascades = Vec::with_capacity(count);
        let mut loop_distortion = LoopDistortion::default();
        for (c, &tile) in options.tile_sizes.iter().enumerate() {
            let dk = TAU / tile;
            let lo = if c == 0 { 0.5 * dk } else { FFT_CASCADE_CUT_INDEX * dk };
            let hi = if c + 1 == count {
                (n as f64 / 2.0 - 0.5) * dk
            } else {
                FFT_CASCADE_CUT_INDEX * TAU / options.tile_sizes[c + 1]
            };
            let band = Band { lo, hi };
            let psi = |kx: f64, kz: f64| {
                let k = (kx * kx + kz * kz).sqrt();
                directional_spectrum(spectrum, spreading, k, libm::atan2(kz, kx) - options.wind_direction)
            };
            let half = n as i64 / 2 - 1;
            let side = 2 * half as usize + 1;
            // Energy of every cell, indexed by (nz + half)·side + (nx + half).
            // Rows in parallel (each cell's quadrature is independent: the same numbers at any
            // thread count).
            let mut energy = vec![0.0; side * side];
            energy.par_chunks_mut(side).enumerate().for_each(|(row, cells)| {
                let nz = row as i64 - half;
                for (col, cell) in cells.iter_mut().enumerate() {
                    let nx = col as i64 - half;
                    let m = nx.abs().max(nz.abs()) as f64;
                    if (m + 0.5) * dk <= lo || (m - 0.5) * dk >= hi {
                        continue;
                    }
                    *cell = cell_energy(&psi, nx as f64 * dk, nz as f64 * dk, dk, band).max(0.0);
                }
            });
            let at = |nx: i64, nz: i64| energy[(nz + half) as usize * side + (nx + half) as usize];
            let mut rng = ChaCha8Rng::seed_from_u64(options.seed);
            rng.set_stream(c as u64);
            let mut modes = Vec::new();
            let (mut variance, mut cov) = (0.0, [0.0; 3]);
            let mut distortion = LoopDistortion::default();
            let amplitude = |rng: &mut ChaCha8Rng, nx: i64, nz: i64| {
                let e = at(nx, nz);
                if e > 0.0 {
                    let (a, b) = gaussian_pair(rng, nx, nz);
                    Complex64::new(a, b) * (0.5 * e.sqrt())
                } else {
                    Complex64::ZERO
                }
            };
            let nn = n as i64;
            for nz in -half..=half {
                for nx in -half..=half {
                    let (e, e_minus) = (at(nx, nz), at(-nx, -nz));
                    if !(e > 0.0 || e_minus > 0.0) {
                        continue;
                    }
                    let (kx, kz) = (nx as f64 * dk, nz as f64 * dk);
                    let k = (kx * kx + kz * kz).sqrt();
                    let omega = match options.loop_period {
                        Some(t) => {
                            let free = dispersion.omega(k);
                            let looped = looped_omega(free, t);
                            distortion.add(free, looped, e);
                            looped
                        }
                        None => dispersion.omega(k),
                    };
                    variance += e;
                    cov[0] += e * kx * kx;
                    cov[1] += e * kx * kz;
                    cov[2] += e * kz * kz;
                    modes.push(Mode {
                        index: (nz.rem_euclid(nn) * nn + nx.rem_euclid(nn)) as usize,
                        kx,
                        kz,
                        k,
                        omega,
                        h0: amplitude(&mut rng, nx, nz),
                        h0_minus_conj: amplitude(&mut rng, -nx, -nz).conj(),
                    });
                }
            }
            loop_distortion.merge(&distortion);
            let k_longest = if c == 0 { dk } else { lo };
            cascades.push(CascadeSpectrum {
                tile,
                n,
                band,
                modes,
                variance,
                slope_covariance: cov,
                k_longest,
                fft: Arc::clone(&fft),
            });
        }
        if !(cascades.iter().map(|c| c.variance).sum::<f64>() > 0.0) {
            let k_lo = TAU / options.tile_sizes[0];
            let k_hi = cascades.last().map_or(k_lo, |c| c.band.hi);
            return Err(WaveError::EmptyBand { omega_min: dispersion.omega(k_lo), omega_max: dispersion.omega(k_hi) });
        }
        let loop_distortion = options.loop_period.map(|_| loop_distortion);
        Ok(Self { options: options.clone(), cascades, dispersion, loop_distortion })
    }

    /// How far the loop period ([`FftOptions::loop_period`]) moved the modes from their
    /// dispersion relation, each weighted by its height variance (`None` without a loop).
    pub fn loop_distortion(&self) -> Option<&LoopDistortion> {
        self.loop_distortion.as_ref()
    }

    /// The options the ocean was built with.
    pub fn options(&self) -> &FftOptions {
        &self.options
    }

    /// The dispersion relation `ω(k)` of the waves.
    pub fn dispersion(&self) -> Dispersion {
        self.dispersion
    }

    /// Number of cascades.
    pub fn cascade_count(&self) -> usize {
        self.cascades.len()
    }

    pub(crate) fn cascade_spectrum(&self, c: usize) -> &CascadeSpectrum {
        &self.cascades[c]
    }

    /// The band `[k_lo, k_hi)` of `|k|_∞ = max(|kₓ|, |k_z|)` (rad m⁻¹) that cascade `c` holds.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()` (a programming error).
    pub fn band(&self, c: usize) -> (f64, f64) {
        let b = self.cascades[c].band;
        (b.lo, b.hi)
    }

    /// Expected height variance of cascade `c`, `Σ E(k) = ∫_band Ψ d²k` (m²).
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn expected_variance(&self, c: usize) -> f64 {
        self.cascades[c].variance
    }

    /// Expected height variance of the whole sea, the sum over the cascades (m²).
    pub fn total_expected_variance(&self) -> f64 {
        self.cascades.iter().map(|c| c.variance).sum()
    }

    /// Expected slope covariance `(⟨ζₓ²⟩, ⟨ζₓζ_z⟩, ⟨ζ_z²⟩)` of cascade `c`, `Σ E(k) (kₓ², kₓk_z, k_z²)`
    /// (dimensionless), of the un-displaced surface.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn expected_slope_covariance(&self, c: usize) -> [f64; 3] {
        self.cascades[c].slope_covariance
    }

    /// The largest wavenumber on any grid, `(N/2 − ½)·2π/L_last` (rad m⁻¹): shorter waves are left
    /// to the renderer's BRDF.
    pub fn k_max(&self) -> f64 {
        self.cascades.last().map_or(0.0, |c| c.band.hi)
    }

    /// The random amplitude `h̃₀(k)` (m) of wave vector `(nₓ, n_z)` of cascade `c`, as
    /// `(re, im)`; `(0, 0)` outside the band or the grid.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn amplitude(&self, c: usize, nx: i64, nz: i64) -> (f64, f64) {
        let cs = &self.cascades[c];
        let n = cs.n as i64;
        let index = (nz.rem_euclid(n) * n + nx.rem_euclid(n)) as usize;
        if nx.abs() > n / 2 - 1 || nz.abs() > n / 2 - 1 {
            return (0.0, 0.0);
        }
        cs.modes.iter().find(|m| m.index == index).map_or((0.0, 0.0), |m| (m.h0.re, m.h0.im))
    }

    /// The angular frequency `ω` (rad s⁻¹) used for wave vector `(nₓ, n_z)` of cascade `c`
    /// (quantised when looping); `None` if the cascade holds no energy there.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn mode_omega(&self, c: usize, nx: i64, nz: i64) -> Option<f64> {
        let cs = &self.cascades[c];
        let n = cs.n as i64;
        let index = (nz.rem_euclid(n) * n + nx.rem_euclid(n)) as usize;
        cs.modes.iter().find(|m| m.index == index).map(|m| m.omega)
    }

    /// The time-dependent amplitudes `h̃(k, t)` of cascade `c` as a list of
    /// `((kₓ, k_z) rad m⁻¹, (re, im) m)`, for an independent evaluation of the trig polynomial
    /// `h(x) = Σ h̃ e^{ik·x}` (tests, diagnostics).
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn amplitudes_at(&self, c: usize, t: f64) -> Vec<((f64, f64), (f64, f64))> {
        let tau = self.phase_time(t);
        self.cascades[c]
            .modes
            .iter()
            .map(|m| {
                let h = evolve(m, tau);
                ((m.kx, m.kz), (h.re, h.im))
            })
            .collect()
    }

    /// The time the phases are evaluated at: `t mod T` when looping (exact periodicity), `t`.
    fn phase_time(&self, t: f64) -> f64 {
        match self.options.loop_period {
            Some(period) => t.rem_euclid(period),
            None => t,
        }
    }

    /// Synthesises the eight fields of every cascade at time `t` on the rest-position grids.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// One [`FftRestFields`] per cascade.
    ///
    /// # References
    /// Tessendorf 2001, Eq. 36, 43, 44 (heights, slopes, displacement); Dupuy & Bruneton 2012
    /// (Jacobian derivatives).
    pub fn rest_fields(&self, t: f64) -> Vec<FftRestFields> {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        let tau = self.phase_time(t);
        self.cascades.par_iter().map(|c| synthesise(c, tau)).collect()
    }

    /// The horizontal-displacement derivatives at time `t` on the cascades' rest grids, filtered
    /// by a Gaussian footprint of standard deviation `footprint_m` (each mode times
    /// `e^{−k²s²/2}`; modes below `10⁻⁶` of their amplitude and cascades made only of them left
    /// out): the Jacobian of the long waves, at a fraction of a frame's cost.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    /// - `footprint_m`: `s` (m), `≥ 0`.
    ///
    /// # Returns
    /// One [`FftRestJacobian`] per cascade kept (in cascade order).
    ///
    /// # References
    /// Tessendorf 2001, Eq. 44 (choppy displacement); Dupuy & Bruneton 2012 (its derivatives).
    pub fn rest_jacobian_fields(&self, t: f64, footprint_m: f64) -> Vec<FftRestJacobian> {
        self.rest_jacobian_fields_shifted(t, footprint_m, [0.0, 0.0])
    }

    /// [`Self::rest_jacobian_fields`] of the sea moved by `−shift`: grid point `p` holds the
    /// fields at rest position `p + shift`. The shift is exact (each mode times
    /// `e^{i k·shift}`, the shift reduced modulo each tile first), not an interpolation; a zero
    /// shift gives the same bits as [`Self::rest_jacobian_fields`].
    ///
    /// # Arguments
    /// - `t`: time (s), finite; `footprint_m`: `s` (m), `≥ 0`.
    /// - `shift_m`: `(sₓ, s_z)` (m), finite.
    ///
    /// # Returns
    /// One [`FftRestJacobian`] per cascade kept (in cascade order).
    ///
    /// # References
    /// The Fourier shift theorem; Tessendorf 2001, Eq. 44.
    pub fn rest_jacobian_fields_shifted(&self, t: f64, footprint_m: f64, shift_m: [f64; 2]) -> Vec<FftRestJacobian> {
        debug_assert!(t.is_finite() && footprint_m >= 0.0 && shift_m.iter().all(|v| v.is_finite()));
        let tau = self.phase_time(t);
        let k_max = GAUSSIAN_KEEP / footprint_m.max(f64::MIN_POSITIVE);
        self.cascades
            .par_iter()
            .enumerate()
            .filter(|(i, _)| self.band(*i).0 < k_max)
            .map(|(i, c)| FftRestJacobian {
                blend: self.tile_blend(i),
                ..synthesise_jacobian(c, tau, footprint_m, k_max, shift_m)
            })
            .collect()
    }

    /// Expected variance of the linear part of the Jacobian, `λ(∂Dₓ/∂x + ∂D_z/∂z)`, that a
    /// Gaussian footprint `s` removes: `λ² Σ k² (|h̃₀(k)|² + |h̃₀(−k)|²)(1 − e^{−k²s²})` over every
    /// mode (dimensionless).
    ///
    /// # Arguments
    /// - `footprint_m`: `s` (m), `≥ 0`; `choppiness`: `λ ≥ 0`.
    ///
    /// # Returns
    /// The variance (dimensionless): the expected one over the random phases, the quadratic
    /// terms of `J` left out.
    ///
    /// # References
    /// Tessendorf 2001, Eq. 44 (the choppy map; `Var(∂Dₓ/∂x + ∂D_z/∂z) = Σ k²E(k)` follows from it);
    /// Dupuy & Bruneton 2012 (the Jacobian's variance over a footprint).
    pub fn jacobian_variance_removed(&self, footprint_m: f64, choppiness: f64) -> f64 {
        let s2 = footprint_m * footprint_m;
        self.cascades
            .iter()
            .flat_map(|c| c.modes.iter())
            .map(|m| m.k * m.k * (m.h0.norm_sqr() + m.h0_minus_conj.norm_sqr()) * (1.0 - (-m.k * m.k * s2).exp()))
            .sum::<f64>()
            * choppiness
            * choppiness
    }

    /// The particle kinematics of every cascade at time `t` on its rest grid: the horizontal
    /// displacement and its derivatives, and the time derivatives of height and displacement
    /// (what [`crate::SeaFrame::sample`] reads at the rest position under a point).
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// The [`FftKinematics`].
    ///
    /// # References
    /// Tessendorf 2001, Eq. 36, 44 (height and choppy displacement; their time derivatives follow
    /// from `h̃(k, t)`).
    pub fn kinematics(&self, t: f64) -> FftKinematics {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        let tau = self.phase_time(t);
        let cascades = self.cascades.par_iter().map(|c| synthesise_kinematics(c, tau)).collect();
        let blends = (0..self.cascades.len()).map(|c| self.tile_blend(c)).collect();
        FftKinematics { choppiness: self.options.choppiness, cascades, blends }
    }

    /// [`Self::kinematics`] of the sea of [`Self::rest_fields_on_grid`]: the same mode weights,
    /// so that the displacement a grid of spacing `Δ` reads holds no mode it cannot carry.
    ///
    /// # Arguments
    /// - `t`: time (s), finite; `spacing_m`: `Δ` (m), `> 0` and finite.
    ///
    /// # Returns
    /// The [`FftKinematics`].
    ///
    /// # References
    /// Shannon 1949 (sampling); Tessendorf 2001, Eq. 36, 44 (height and choppy displacement).
    pub fn kinematics_on_grid(&self, t: f64, spacing_m: f64) -> FftKinematics {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        debug_assert!(spacing_m > 0.0 && spacing_m.is_finite(), "spacing {spacing_m} m");
        let tau = self.phase_time(t);
        let weight = |m: &Mode| grid_weight(m, spacing_m);
        let cascades = self.cascades.par_iter().map(|c| synthesise_kinematics_weighted(c, tau, &weight)).collect();
        let blends = (0..self.cascades.len()).map(|c| self.tile_blend(c)).collect();
        FftKinematics { choppiness: self.options.choppiness, cascades, blends }
    }

    /// The tile-and-blend of cascade `c` (`None` for a tiled sea, [`FftOptions::tiled`]): the
    /// same for the traced surface, the shading, the white water and the kinematics, keyed by
    /// the seed and the cascade.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn tile_blend(&self, c: usize) -> Option<TileBlend> {
        (!self.options.tiled).then(|| TileBlend::new(self.options.tile_sizes[c], self.options.seed, c))
    }

    /// The sea at time `t`, ready to trace and shade: each cascade's displaced surface resampled
    /// on its grid (see [`FftFrame`]).
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// The [`FftFrame`].
    pub fn at_time(&self, t: f64) -> FftFrame {
        let rest = self.rest_fields(t);
        FftFrame::from_rest_fields(self, &rest, t)
    }

    /// [`Self::rest_fields`] of the sea a square grid of spacing `Δ` samples without aliasing:
    /// every mode of wavelength `λ = 2π/|k|` weighted by
    ///
    /// `w(λ) = smoothstep(0, 1, 2 (λ/(2Δ) − 1))`
    ///
    /// (0 for `λ ≤ 2Δ`, 1 for `λ ≥ 3Δ`), as brine-waves `grid_band` weights a trochoid: a mode
    /// with a wave-vector component at or beyond the grid's Nyquist wavenumber `π/Δ` would read,
    /// sampled on the grid, as a longer wave of another direction. The cut is on `|k|`, not on
    /// the components: it also leaves out the diagonal modes between `π/Δ` and `√2 π/Δ` a square
    /// grid could carry, so that the band does not depend on the grid's orientation. Each cascade
    /// is still synthesised on its own grid; only its amplitudes change.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    /// - `spacing_m`: `Δ` (m), `> 0` and finite.
    ///
    /// # Returns
    /// The fields (bit for bit those of [`Self::rest_fields`] when no mode is shorter than
    /// `3Δ`) and what was left out ([`FftGridBand`]).
    ///
    /// # References
    /// Shannon 1949 (sampling); Tessendorf 2001, Eq. 36, 43, 44.
    pub fn rest_fields_on_grid(&self, t: f64, spacing_m: f64) -> (Vec<FftRestFields>, FftGridBand) {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        debug_assert!(spacing_m > 0.0 && spacing_m.is_finite(), "spacing {spacing_m} m");
        let tau = self.phase_time(t);
        let weight = |m: &Mode| grid_weight(m, spacing_m);
        let mut band = FftGridBand { faded: 0, lost_slope_covariance: DVec3::ZERO };
        for m in self.cascades.iter().flat_map(|c| &c.modes) {
            let w = weight(m);
            if w < 1.0 {
                // Parseval: the mode adds |ĥ|² (kₓ², kₓk_z, k_z²) to the tile's mean slope products.
                band.faded += 1;
                band.lost_slope_covariance +=
                    (1.0 - w * w) * evolve(m, tau).norm_sqr() * DVec3::new(m.kx * m.kx, m.kx * m.kz, m.kz * m.kz);
            }
        }
        let fields = self.cascades.par_iter().map(|c| synthesise_weighted(c, tau, &weight)).collect();
        (fields, band)
    }

    /// The number of modes of wavelength `wavelength_m` (m) or shorter: those a grid of half
    /// that spacing aliases (and [`Self::rest_fields_on_grid`] leaves out).
    pub fn modes_shorter_than(&self, wavelength_m: f64) -> usize {
        let k = TAU / wavelength_m;
        self.cascades.iter().flat_map(|c| &c.modes).filter(|m| m.k >= k).count()
    }

    /// The number of modes [`Self::rest_fields_on_grid`] weights below 1 for a grid of spacing
    /// `spacing_m` (m, `> 0`): without any, the sea on the grid is the sea itself.
    pub fn modes_faded_on_grid(&self, spacing_m: f64) -> usize {
        self.cascades.iter().flat_map(|c| &c.modes).filter(|m| grid_weight(m, spacing_m) < 1.0).count()
    }

    /// The number of modes of the sea (each wave vector of its spectral grids once).
    pub fn mode_count(&self) -> usize {
        self.cascades.iter().map(|c| c.modes.len()).sum()
    }

    /// [`Self::at_time`] of the sea of [`Self::rest_fields_on_grid`]: what a map of texels `Δ`
    /// can hold without aliasing.
    ///
    /// # Arguments
    /// - `t`: time (s), finite; `spacing_m`: `Δ` (m), `> 0` and finite.
    ///
    /// # Returns
    /// The [`FftFrame`] and what was left out.
    ///
    /// # References
    /// As [`Self::rest_fields_on_grid`].
    pub fn at_time_on_grid(&self, t: f64, spacing_m: f64) -> (FftFrame, FftGridBand) {
        let (rest, band) = self.rest_fields_on_grid(t, spacing_m);
        (FftFrame::from_rest_fields(self, &rest, t), band)
    }
}

/// The weight of a mode on a grid of spacing `Δ`: `smoothstep(0, 1, 2 (λ/(2Δ) − 1))`,
/// `λ = 2π/|k|` (brine-core `footprint_weight` with a footprint of `2Δ`).
fn grid_weight(m: &Mode, spacing_m: f64) -> f64 {
    brine_core::footprint::footprint_weight(TAU / m.k, 2.0 * spacing_m)
}

/// `h̃(k, τ) = h̃₀(k) e^{−iωτ} + conj(h̃₀(−k)) e^{iωτ}`.
#[inline]
fn evolve(m: &Mode, tau: f64) -> Complex64 {
    let (s, c) = libm::sincos(m.omega * tau);
    m.h0 * Complex64::new(c, -s) + m.h0_minus_conj * Complex64::new(c, s)
}

/// `a + i b` for two Hermitian spectra `a`, `b`: its inverse FFT is `IFFT(a) + i IFFT(b)`, both real.
#[inline]
fn pack(a: Complex64, b: Complex64) -> Complex64 {
    Complex64::new(a.re - b.im, a.im + b.re)
}

/// The eight fields of one cascade at phase time `tau`.
fn synthesise(c: &CascadeSpectrum, tau: f64) -> FftRestFields {
    synthesise_weighted(c, tau, &|_| 1.0)
}

/// [`synthesise`] with each mode's amplitude times `weight(mode)` (`[0, 1]`; modes of weight 0
/// left out, those of weight 1 unchanged to the bit).
fn synthesise_weighted(c: &CascadeSpectrum, tau: f64, weight: &(dyn Fn(&Mode) -> f64 + Sync)) -> FftRestFields {
    let n = c.n;
    let mut packs: Vec<Vec<Complex64>> = (0..4).map(|_| vec![Complex64::ZERO; n * n]).collect();
    for m in &c.modes {
        let w = weight(m);
        if w <= 0.0 {
            continue;
        }
        let h = if w < 1.0 { evolve(m, tau) * w } else { evolve(m, tau) };
        let ih = Complex64::new(-h.im, h.re);
        let inv_k = 1.0 / m.k;
        let (ux, uz) = (m.kx * inv_k, m.kz * inv_k);
        packs[0][m.index] = pack(h, ih * m.kx);
        packs[1][m.index] = pack(ih * m.kz, ih * ux);
        packs[2][m.index] = pack(ih * uz, -h * (m.kx * ux));
        packs[3][m.index] = pack(-h * (m.kz * uz), -h * (m.kx * uz));
    }
    packs.par_iter_mut().for_each(|p| inverse_fft_2d(p, n, c.fft.as_ref()));
    let re = |p: &[Complex64]| p.iter().map(|v| v.re).collect::<Vec<f64>>();
    let im = |p: &[Complex64]| p.iter().map(|v| v.im).collect::<Vec<f64>>();
    FftRestFields {
        resolution: n,
        tile_size: c.tile,
        height: re(&packs[0]),
        slope_x: im(&packs[0]),
        slope_z: re(&packs[1]),
        displacement_x: im(&packs[1]),
        displacement_z: re(&packs[2]),
        dxx: im(&packs[2]),
        dzz: re(&packs[3]),
        dxz: im(&packs[3]),
    }
}

/// Transposition block (elements).
const TRANSPOSE_BLOCK: usize = 16;

/// In-place transpose of a square `n × n` matrix, by blocks.
fn transpose(data: &mut [Complex64], n: usize) {
    for jb in (0..n).step_by(TRANSPOSE_BLOCK) {
        for ib in (jb..n).step_by(TRANSPOSE_BLOCK) {
            for j in jb..(jb + TRANSPOSE_BLOCK).min(n) {
                let start = if ib == jb { j + 1 } else { ib };
                for i in start..(ib + TRANSPOSE_BLOCK).min(n) {
                    data.swap(j * n + i, i * n + j);
                }
            }
        }
    }
}

/// Unnormalised 2-D inverse DFT `f[j][i] = Σ F[m][l] e^{2πi(li + mj)/N}` in place: the rows, a
/// transpose, the rows again, a transpose back.
pub(crate) fn inverse_fft_2d(data: &mut [Complex64], n: usize, fft: &dyn Fft<f64>) {
    let mut scratch = vec![Complex64::ZERO; fft.get_inplace_scratch_len()];
    fft.process_with_scratch(data, &mut scratch);
    transpose(data, n);
    fft.process_with_scratch(data, &mut scratch);
    transpose(data, n);
}

#[cfg(test)]
mod tests;
