//! # brine-waves — ocean spectra, the spectrum-to-trochoid fit, and wave surfaces
//!
//! The wave model of Darles, Crespin & Ghazanfarpour (2007, §3), after Thon & Ghazanfarpour
//! (2002): a sea is a sum of trochoid (Gerstner) waves whose amplitudes, wavelengths, directions
//! and speeds are drawn from a measured ocean spectrum — here Pierson–Moskowitz (1964), with the
//! cos-2s directional spreading of Hasselmann et al. (1980) and the deep-water dispersion relation.
//! The surface Darles et al. trace is the sum of the waves' exact trochoid height profiles,
//! [`TrochoidSum`], which implements [`brine_trace::LipschitzSum`] with per-wave Lipschitz
//! constants `kA/√(1 − Q²)`.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `S(ω)` | [`Spectrum::s_omega`] | m² s rad⁻¹ | frequency spectrum of elevation |
//! | `ω`, `ω_p` | `omega`, [`Spectrum::peak_omega`] | rad s⁻¹ | angular frequency, spectral peak |
//! | `U₁₀`, `U₁₉.₅` | `u10`, `u19_5` | m s⁻¹ | wind speed 10 m / 19.5 m above the sea |
//! | `D(θ; ω)` | [`Spreading::density`] | rad⁻¹ | directional spreading, `∫D dθ = 1` |
//! | `k` | [`Trochoid::wavenumber`] | rad m⁻¹ | wavenumber, `λ = 2π/k` |
//! | `A` | [`Trochoid::amplitude`] | m | vertical radius of a wave |
//! | `Q` | [`Trochoid::steepness`] | 1 | steepness, `k ×` horizontal radius, `< 1` |
//! | `θ` | [`Trochoid::direction`] | rad | propagation angle from +x toward +z |
//! | `φ₀` | [`Trochoid::phase`] | rad | initial phase |
//! | `h(x, z, t)` | [`WaveSurface::height`] | m | surface height above mean sea level |
//!
//! ## Validity
//!
//! Deep water (`kh ≫ 1`), wind speeds `0 < U₁₀ ≤ 60` m s⁻¹, steepness `Q ≤ 0.99`. Axes: y up,
//! mean sea level `y = 0` (see `docs/conventions.md`).
//!
//! ## Example
//!
//! ```
//! use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TrochoidSum, WaveSurface, fit_trochoids};
//!
//! let pm = PiersonMoskowitz::from_u10(10.0)?;
//! let spreading = CosineTwoS::hasselmann(pm.peak_omega())?;
//! let set = fit_trochoids(&pm, &spreading, 50, 1, &FitOptions::default())?;
//! let sea = TrochoidSum::new(&set);
//! let (lo, hi) = sea.height_bounds();
//! let h = sea.height(3.0, -2.0, 0.0);
//! assert!(lo <= h && h <= hi);
//! # Ok::<(), brine_waves::WaveError>(())
//! ```
//!
//! ## References
//!
//! - Thon S., Ghazanfarpour D. 2002, "Ocean waves synthesis and animation using real world
//!   information", Computers & Graphics 26(1):99–108.
//! - Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
//!   realistic ocean scenes", WSCG, §3.
//! - Pierson W., Moskowitz L. 1964, JGR 69(24):5181–5190.
//! - Hasselmann D., Dunckel M., Ewing J. 1980, JPO 10 (directional spreading).

mod dispersion;
mod error;
mod fast_profile;
mod fit;
mod integrate;
mod lipschitz;
mod set;
mod spectrum;
mod spreading;
mod surface;
mod traced;
mod trochoid;

pub use dispersion::{G, omega_deep_water, wavenumber_deep_water};
pub use error::WaveError;
pub use fit::{FitOptions, FrequencyPartition, fit_trochoids};
pub use set::TrochoidSet;
pub use spectrum::{PiersonMoskowitz, Spectrum};
pub use spreading::{CosineTwoS, Spreading};
pub use surface::{TrochoidField, TrochoidSum, WaveSurface};
pub use traced::{LANES, TracedTrochoids};
pub use trochoid::{MAX_STEEPNESS, Trochoid, solve_trochoid_phase};
