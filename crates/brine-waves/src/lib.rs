//! # brine-waves — ocean spectra, the spectrum-to-trochoid fit, and wave surfaces
//!
//! The wave model of Darles, Crespin & Ghazanfarpour (2007, §3), after Thon & Ghazanfarpour
//! (2002): a sea is a sum of trochoid (Gerstner) waves whose amplitudes, wavelengths, directions
//! and speeds are drawn from an ocean spectrum. With it, the spectra and surfaces of Li Ying et al.
//! (2018, §2.2: the Elfouhaily et al. 1997 unified spectrum) and Chen et al. (2007: sine waves with
//! bump-mapped normals).
//!
//! - **Spectra** ([`Spectrum`]: `S(ω)` in m² s rad⁻¹, `S(k)` in m³ rad⁻¹, `m₀`, `H_s`, mean-square
//!   slope): [`PiersonMoskowitz`], [`Jonswap`], [`Tma`], [`Phillips`], [`Elfouhaily`].
//! - **Spreading** ([`Spreading`]: `D(θ; ω)` and sampling): [`CosineTwoS`] (Longuet-Higgins,
//!   Mitsuyasu, Hasselmann), [`DonelanBanner`], [`ElfouhailySpreading`], [`CosineSquared`].
//! - **Dispersion** ([`Dispersion`]): deep water `ω² = gk`, finite depth `ω² = gk tanh(kh)`,
//!   capillary–gravity `ω² = (gk + σk³/ρ) tanh(kh)`.
//! - **Fit** ([`fit_trochoids`], [`fit_sea_state`] for sea + swell): amplitudes from a frequency
//!   partition, directions from the spreading, phases from a ChaCha8 seed, steepness capped so
//!   the surface never folds — a [`TrochoidSet`].
//! - **Surfaces** ([`WaveSurface`]: height, gradient, normal, displacement, Jacobian, velocity,
//!   batch heights): [`TrochoidSum`] (the sum of exact trochoid height fields that Darles et al.
//!   trace; the default for rendering), [`GerstnerSurface`] (the true Gerstner sum, by a Newton
//!   inversion of the horizontal displacement), [`SineSet`] (Chen et al.'s sinusoids with
//!   perturbed normals). With the feature `tracing` (on by default), their time-frozen fields
//!   [`TrochoidField`], [`GerstnerField`] and [`SineField`] implement `brine_trace::LipschitzSum`
//!   for the sphere tracer, and a [`SeaFrame`] is traced through `TracedSea`.
//! - **FFT ocean** ([`FftOcean`]; Tessendorf 2001, as Li Ying et al. 2018 §2.2 synthesise it): random
//!   amplitudes of any spectrum and spreading on periodic cascades of tiles (seeded by wave vector,
//!   so a finer grid keeps the large waves; exact looping), inverse FFTs of heights, slopes, choppy
//!   displacement and its Jacobian; its frames [`FftFrame`] (each cascade's displaced surface
//!   resampled on its grid and traced as a cubic B-spline with certified bounds) implement
//!   `brine_trace::LipschitzSum` (feature `tracing`).
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `S(ω)` | [`Spectrum::s_omega`] | m² s rad⁻¹ | frequency spectrum of elevation |
//! | `S(k)` | [`Spectrum::s_k`] | m³ rad⁻¹ | wavenumber spectrum, `S(k) = S(ω) dω/dk` |
//! | `Ψ(k, φ)` | [`Elfouhaily::directional`] | m⁴ | directional spectrum per `d²k` |
//! | `B_l`, `B_h` | [`Elfouhaily::curvature_long`] | 1 | long- and short-wave curvature spectra |
//! | `ω`, `ω_p` | `omega`, [`Spectrum::peak_omega`] | rad s⁻¹ | angular frequency, spectral peak |
//! | `m₀`, `H_s` | [`Spectrum::m0`], [`Spectrum::significant_wave_height`] | m², m | variance, `4√m₀` |
//! | `U₁₀`, `U₁₉.₅` | `u10`, `u19_5` | m s⁻¹ | wind speed 10 m / 19.5 m above the sea |
//! | `F`, `x` | `fetch_m` | m | fetch |
//! | `h` | `depth_m` | m | water depth |
//! | `Ω` | [`Elfouhaily::inverse_wave_age`] | 1 | inverse wave age `U₁₀/c_p` |
//! | `D(θ; ω)` | [`Spreading::density`] | rad⁻¹ | directional spreading, `∫D dθ = 1` |
//! | `k` | [`Trochoid::wavenumber`] | rad m⁻¹ | wavenumber, `λ = 2π/k` |
//! | `A` | [`Trochoid::amplitude`] | m | vertical radius of a wave |
//! | `Q` | [`Trochoid::steepness`] | 1 | steepness, `k ×` horizontal radius, `< 1` |
//! | `θ` | [`Trochoid::direction`] | rad | propagation angle from +x toward +z |
//! | `φ₀` | [`Trochoid::phase`] | rad | initial phase |
//! | `h(x, z, t)` | [`WaveSurface::height`] | m | surface height above mean sea level |
//! | `D`, `J` | [`WaveSurface::displacement`], [`WaveSurface::jacobian`] | m, 1 | displacement, Jacobian |
//! | `L` | [`WaveSurface::max_slope`] | 1 | Lipschitz constant of `h` |
//! | `L_c` | [`FftCascade::tile_size`] | m | side of FFT cascade `c`'s periodic tile |
//! | `S` | [`BLEND_SPACING_PER_TILE`] `× L_c` | m | spacing of a [`TileBlend`]'s lattice |
//! | `o_k` | [`BlendCorner::offset`] | m | random offset of lattice corner `k` into the tile |
//! | `ŵ_k` | [`BlendCorner::weight`] | 1 | variance-preserving blend weight, `Σ ŵ_k² = 1` |
//! | `f` | [`BLEND_TRANSITION`] | 1 | share of a cell over which one corner hands over to the next |
//! | `G₁`, `G₂` | — | 1 | suprema of `|a₀′| + |a₁′|`, `|a₀″| + |a₁″|` per unit cell coordinate |
//!
//! ## Validity
//!
//! Wind speeds `0 < U₁₀ ≤ 60` m s⁻¹ (Elfouhaily's data cover about 2–25 m s⁻¹), steepness
//! `Q ≤ 0.99`, `Σ Q < 1` for the Gerstner surface. Trochoid shapes are deep-water orbits even when
//! a finite-depth spectrum (TMA) sets their wavenumbers. Axes: y up, x east, z south, mean sea
//! level `y = 0`; angles from +x toward +z (see `docs/conventions.md`). Every random choice comes
//! from a seed (ChaCha8) and every transcendental function of the fit from `libm`: the same seed
//! gives the same set on every platform.
//!
//! ## Example
//!
//! ```
//! use brine_waves::{
//!     Directions, Elfouhaily, FitOptions, GerstnerSurface, Spectrum, TrochoidSum, WaveSurface, fit_trochoids,
//! };
//!
//! let spectrum = Elfouhaily::from_fetch(10.0, 50_000.0)?;
//! let spreading = spectrum.spreading(Directions::Downwind);
//! let set = fit_trochoids(&spectrum, &spreading, 50, 1, &FitOptions::default())?;
//! let sea = TrochoidSum::new(&set);
//! let (lo, hi) = sea.height_bounds();
//! let h = sea.height(3.0, -2.0, 0.0);
//! assert!(lo <= h && h <= hi);
//! // The same waves as a true Gerstner sum (its horizontal displacements composed).
//! let gerstner = GerstnerSurface::new(&set)?;
//! assert!(gerstner.jacobian(3.0, -2.0, 0.0) > 0.0);
//! # Ok::<(), brine_waves::WaveError>(())
//! ```
//!
//! ## References
//!
//! - Thon S., Ghazanfarpour D. 2002, "Ocean waves synthesis and animation using real world
//!   information", Computers & Graphics 26(1):99–108.
//! - Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
//!   realistic ocean scenes", WSCG, §3.
//! - Chen H. et al. 2007, "An efficient method for real-time ocean simulation", Edutainment,
//!   LNCS 4469, §3.3; Finch M. 2004, "Effective water simulation from physical models", GPU Gems 1.
//! - Li Ying, Tang Yong et al. 2018, "Real-time rendering of large-scale realistic ocean scenes
//!   driven by time and space" (in Chinese), §2.2, Eq. 1.
//! - Pierson W., Moskowitz L. 1964, JGR 69(24):5181–5190; Hasselmann K. et al. 1973 (JONSWAP),
//!   Dtsch. Hydrogr. Z. A8(12); Bouws E. et al. 1985 (TMA), JGR 90(C1):975–986; Tessendorf J. 2001,
//!   "Simulating Ocean Water" (Phillips); Elfouhaily T. et al. 1997, JGR 102(C7):15781–15796.
//! - Longuet-Higgins M.S. et al. 1963; Mitsuyasu H. et al. 1975, JPO 5; Hasselmann D. et al. 1980,
//!   JPO 10; Donelan M.A. et al. 1985, Phil. Trans. R. Soc. A315; Banner M.L. 1990, JPO 20
//!   (directional spreading).
//! - Cox C., Munk W. 1954, JOSA 44(11) (slope statistics); Dupuy J., Bruneton E. 2012 (Jacobian);
//!   Bruneton E. et al. 2010, CGF 29(2) (Gerstner sums).
//! - Heitz E., Neyret F. 2018, "High-performance by-example noise using a histogram-preserving
//!   blending operator", Proc. ACM Comput. Graph. Interact. Tech. 1(2) (HPG 2018), doi:10.1145/3233304
//!   (tile and blend, variance-preserving weights).

mod error;
mod fft;
mod fit;
mod looping;
mod sea;
mod spectra;
mod surfaces;
mod tracing;

pub use brine_core::footprint::{BOX_WIDTH_PER_SIGMA, EllipticalFootprint, MAX_ANISOTROPY};
#[cfg(feature = "tracing")]
pub use brine_trace::RayTile;
pub use error::WaveError;
pub use fft::blend::{BLEND_SPACING_PER_TILE, BLEND_TRANSITION, BlendCorner, TileBlend};
pub use fft::frame::{FftCascade, FftFrame};
pub use fft::ocean::{FftGridBand, FftKinematics, FftOcean, FftRestFields, FftRestJacobian, ParticleState};
pub use fft::options::{
    FFT_CASCADE_CUT_INDEX, FFT_DEFAULT_TILE_RATIO, FFT_MAX_CASCADES, FFT_MAX_CHOPPINESS, FFT_MAX_LOOP_PERIOD_S,
    FFT_MAX_RESOLUTION, FFT_MIN_RESOLUTION, FFT_PEAK_WAVELENGTHS_PER_TILE, FftOptions,
};
pub use fft::pyramid::{FftPyramid, FftStackPyramid};
pub use fft::resample::FFT_MAX_SHADING_SLOPE;
pub use fft::slopes::{FftSlopeFilter, FilteredSlopes};
pub use fft::spectrum::directional_spectrum;
pub use fit::extraction::{AmplitudeRule, FrequencyBin, SeaComponent, SteepnessLimit, fit_sea_state, frequency_bins};
pub use fit::extraction::{FitOptions, FrequencyPartition, fit_trochoids};
pub use fit::lattice::{GridBand, TileLattice, grid_band};
pub use fit::set::TrochoidSet;
pub use fit::trochoid::{MAX_STEEPNESS, Trochoid, solve_trochoid_phase};
pub use looping::{LOOP_TOLERANCE, LoopDistortion, looped_omega};
pub use sea::{FrameSurface, Ocean, SINE_DETAIL_WAVELENGTH_M, SeaFrame, SurfaceSample};
pub use spectra::dispersion::{Dispersion, ELFOUHAILY_K_M, SEA_WATER_DENSITY, SEA_WATER_SURFACE_TENSION};
pub use spectra::dispersion::{G, omega_deep_water, wavenumber_deep_water};
pub use spectra::elfouhaily::{Elfouhaily, ElfouhailySpreading};
pub use spectra::jonswap::Jonswap;
pub use spectra::phillips::Phillips;
pub use spectra::spectrum::{PiersonMoskowitz, Spectrum};
pub use spectra::spreading::{CosineSquared, Directions, DonelanBanner};
pub use spectra::spreading::{CosineTwoS, Spreading};
pub use spectra::summed::SummedSpectrum;
pub use spectra::tma::{Tma, kitaigorodskii_depth_factor};
pub use surfaces::detail::{
    BandLimited, DETAIL_MIN_WAVELENGTH_M, DetailOptions, DetailSlopes, DetailWaves, wavenumber_of_slope,
};
pub use surfaces::gerstner::{
    FadedWaves, GERSTNER_MAX_ITERATIONS, GERSTNER_TOLERANCE_M, GERSTNER_TOLERANCE_REL, GerstnerField, GerstnerPoint,
    GerstnerSurface, Inversion,
};
pub use surfaces::seabed::{SeabedRelief, seabed_relief};
pub use surfaces::sine::{SineField, SineSet};
pub use surfaces::surface::{TrochoidField, TrochoidSum, WaveSurface};
#[cfg(feature = "tracing")]
pub use tracing::gridded::{
    BandedTrochoids, DEFAULT_BAND_RATIO, DEFAULT_LONG_FRACTION, DEFAULT_POINTS_PER_WAVE, DEFAULT_TILE_PER_CUT,
    GridBandSpec, GriddedTrochoids,
};
#[cfg(feature = "tracing")]
pub use tracing::sea::TracedSea;
pub use tracing::traced::{LANES, TracedTrochoids};
