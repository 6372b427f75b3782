//! # brine-whitecap — whitecaps from the displacement Jacobian
//!
//! Whitecap coverage `W = ½(1 + erf((α − μ)/√(2σ²)))` from the mean `μ` and variance `σ²` of the
//! Jacobian `J` of the horizontal displacement of the sea surface over a pixel footprint
//! (Dupuy & Bruneton 2012), with the statistics derived analytically for trochoid sets
//! (brine-waves), the slides' fast error function and a more accurate one, whitecap radiance
//! `W · Lambert(0.4)`, and a calibration of the threshold `α` against a target coverage — the
//! Monahan coverage of brine-foam at the same wind.
//!
//! For an FFT ocean (brine-waves' `FftFrame`), [`FftJacobianStatistics`] holds per cascade a
//! mip-mapped pyramid of `kᵢ = Jᵢ − 1 + 1/n` and `kᵢ²` and reads `μ = Σᵢ⟨kᵢ⟩`,
//! `σ² = Σᵢ(⟨kᵢ²⟩ − ⟨kᵢ⟩²)` over a footprint, as Dupuy & Bruneton publish it; [`FftCalibration`]
//! calibrates `α(s)` per footprint size on sample points of the frame.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `J` | [`JacobianStatistics::jacobian_at`] | 1 | determinant of `∂x/∂u` of the Gerstner map; `< 1` compressed, `< 0` folded |
//! | `aᵢ = Qᵢ` | `Trochoid::steepness` | 1 | wave steepness (horizontal radius × `k`) |
//! | `θᵢ`, `d̂ᵢ` | `Trochoid::direction` | rad | wave direction, from +x toward +z |
//! | `φᵢ` | — | rad | wave phase `kᵢd̂ᵢ·u − ωᵢt + φ₀ᵢ` |
//! | `s` | `footprint_m` | m | pixel footprint size (std of a Gaussian footprint) |
//! | `μ`, `σ²` | [`Moments`] | 1 | mean and variance of `J` over the footprint |
//! | `α` | `alpha` | 1 | breaking threshold: whitecaps where `J < α` |
//! | `W` | [`whitecap_coverage`] | 1 | whitecap coverage of the footprint, `[0, 1]` |
//! | `ρ_wc` | [`WHITECAP_REFLECTANCE`] | 1 | whitecap reflectance, 0.4 |
//! | `I_wc` | [`whitecap_radiance`] | irradiance unit sr⁻¹ | whitecap radiance |
//! | `n` | [`FftJacobianStatistics::cascade_count`] | 1 | number of FFT cascades |
//! | `λ` | `FftOptions::choppiness` | 1 | choppiness of the FFT displacement, one for all cascades |
//! | `Jᵢ` | `FftCascade::jacobians` | 1 | Jacobian of cascade `i`'s displacement alone, on its displaced grid |
//! | `aᵢ`, `bᵢ`, `cᵢ` | — | 1 | `λ∂Dₓ,ᵢ/∂x`, `λ∂D_z,ᵢ/∂z`, `λ∂Dₓ,ᵢ/∂z`; `Jᵢ = (1 + aᵢ)(1 + bᵢ) − cᵢ²` |
//! | `⟨kᵢ⟩`, `⟨kᵢ²⟩` | [`FftJacobianStatistics::cascade_moments`] | 1 | footprint means of `kᵢ = 1/n + aᵢ + bᵢ + aᵢbᵢ − cᵢ²` and of `kᵢ²` |
//! | `Δ_min`, `L_max` | [`FftJacobianStatistics::finest_spacing`], [`FftJacobianStatistics::largest_tile`] | m | finest grid spacing, largest tile |
//! | `α(s)` | [`FftCalibration::alpha_for_footprint`] | 1 | threshold calibrated for the footprint size `s` |
//! | `s_b` | [`breaking_footprint`] | m | footprint keeping the breaking waves (faster than `c_p/4`) |
//! | `σ_e` | [`WhiteWaterModel::edge_std`] | 1 | short waves' share of the breaking variable (edge noise) |
//!
//! [`WhiteWaterModel`] composes the whitecaps of the breaking waves with the foam they leave
//! (brine-foam `FoamMemory`) and calibrates one threshold for both on Monahan's coverage.
//!
//! ## Validity
//!
//! Any trochoid set (the Gerstner map folds where `J < 0`, possible when `Σ Qᵢ > 1`). The whole-sea
//! moments assume independent, uniformly distributed phases: true for a set whose wave vectors are
//! incommensurate, over an area much larger than the longest wave. The per-pixel Gaussian law of
//! `J` is the model's assumption (Dupuy & Bruneton); the calibration does not rely on it.
//!
//! FFT route: any `FftFrame` (1–8 cascades, `λ ∈ [0, 4]`; `λ = 0` gives `J = 1`). Its moments are
//! the published approximation: the cross-cascade products of `J` and the covariances between
//! cascades are neglected, the footprint is a box of width `√12 s` read trilinearly (isotropic),
//! and the means are over the displaced surface (so the tile mean of `J` is not exactly 1). The
//! calibration is plain Monte Carlo over the largest tile (relative error `√((1 − W*)/(W* M))` for
//! a target `W*` and `M` points); `α(s)` holds the target at its table sizes (to sampling) and is
//! interpolated in `ln s` between them.
//!
//! ## Example
//!
//! ```
//! use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
//! use brine_whitecap::{Calibration, CalibrationOptions, ErfMethod, FootprintFilter, JacobianStatistics};
//! use glam::DVec2;
//!
//! let pm = PiersonMoskowitz::from_u10(10.0)?;
//! let set = fit_trochoids(&pm, &CosineTwoS::hasselmann(pm.peak_omega())?, 40, 1, &FitOptions::default())?;
//! let stats = JacobianStatistics::new(&set)?;
//! // Monahan 1980 at 10 m/s (brine_foam::whitecap_coverage gives the same).
//! let calibration = Calibration::new(&stats, 9.87e-3, &CalibrationOptions::default())?;
//! // Per pixel: footprint moments, then the coverage with the threshold for that footprint.
//! let footprint = 0.5; // m
//! let m = stats.moments_at(DVec2::new(12.0, -3.0), 0.0, footprint, FootprintFilter::Gaussian);
//! let w = calibration.coverage(m, footprint, ErfMethod::Libm);
//! assert!((0.0..=1.0).contains(&w));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! ## References
//!
//! - Dupuy J., Bruneton E. 2012, "Real-time animation and rendering of ocean whitecaps",
//!   SIGGRAPH Asia Technical Briefs (and the talk's slides).
//! - Winitzki S. 2008, "A handy approximation for the error function and its inverse".
//! - Abramowitz M., Stegun I. 1964, *Handbook of Mathematical Functions*, 7.1.26, 9.6, 9.7.
//! - Monahan E., Ó Muircheartaigh I. 1980, JPO 10:2094–2099 (calibration target).
//! - Melville W. K., Matusov P. 2002, Nature 417:58–63; Gemmrich J. R., Banner M. L., Garrett C.
//!   2008, JPO 38:1296–1312 (the speed of breaking crests).

mod bessel;
mod breaking;
mod calibration;
mod coverage;
mod erf;
mod error;
mod fft_calibration;
mod fft_statistics;
mod statistics;
mod white_water;

pub use calibration::{Calibration, CalibrationOptions, CoverageEstimate, surface_coverage};
pub use coverage::{WHITECAP_REFLECTANCE, compose_with_whitecaps, whitecap_coverage, whitecap_radiance};
pub use erf::{
    ERF_AS_MAX_ERROR, ERF_FAST_MAX_ERROR, ErfMethod, WINITZKI_A, WINITZKI_A_DEMO, erf_abramowitz_stegun, erf_fast,
    erf_inv, erf_winitzki,
};
pub use error::WhitecapError;
pub use fft_calibration::{FFT_CALIBRATION_SAMPLES, FftCalibration};
pub use fft_statistics::{FftInstantJacobian, FftJacobianHistory, FftJacobianStatistics};
pub use statistics::{F32_MOMENTS_ERROR, FootprintFilter, HistoryRotation, HistoryStart, JacobianStatistics, Moments};
pub use white_water::{
    BREAKING_SPEED_SHARE, BreakingSource, FftBreaking, Lattice, TrochoidBreaking, WHITE_WATER_FOOTPRINTS_M,
    WhiteWaterModel, WhiteWaterOptions, breaking_footprint, breaking_wavenumber_cut, forward_face_offset,
};
