//! # brine-foam — Monahan foam and sea spray
//!
//! Whitecap coverage after Monahan & Ó Muircheartaigh (1980, 1986), the foam that breaking crests
//! leave and that decays with Monahan's (1971) time constant ([`FoamMemory`]), the foam extension of
//! Darles, Crespin & Ghazanfarpour (2007, §4.1, Eq. 3–4, corrected in the docs/equations.md §5),
//! foam radiance after Koepke (1984), foam that moves with the water and ages between frames,
//! and the sea-spray source function of Monahan, Spiel & Davidson (1986) with its vertical
//! profile, extinction, optical depth and in-scattering (Darles et al. 2007, §4.2, equation
//! equations.md §6), and the spume torn from the crests (Fairall, Kepert & Holland 1994) as a
//! layer of haze over a windy sea.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `U₁₀` | `u10` | m s⁻¹ | wind speed 10 m above the sea |
//! | `ΔT = T_w − T_a` | `delta_t_c`, `t_water_c`, `t_air_c` | °C | water minus air temperature |
//! | `W` | [`whitecap_coverage`] | 1 | fraction of the sea covered by whitecaps |
//! | `n` | [`FoamExtensionParams::exponent`] | 1 | height exponent of the foam extension |
//! | `s′` | [`FoamExtension::foam_amount`] | 1 | local foam cover, `[0, 1]` |
//! | `ν` | [`FoamNoise::value`] | 1 | footprint-filtered noise, mean 1 |
//! | `ℓ` | `footprint_m` | m | pixel footprint on the sea |
//! | `R_f`, `f_ef`, `R_ef` | [`KoepkeFoam`] | 1 | fresh-foam reflectance, efficiency, effective reflectance |
//! | `τ`, `τ_R` | [`FoamHistory`], [`FoamMemory`] | s | foam-area and brightness decay times |
//! | `m(u)`, `θ(a)` | [`FoamMemory::survivals`] | 1 | uniform patch variable, survival threshold of foam of age `a` |
//! | `A₀` | [`FOAM_DENSITY`] | 1 | share of the swept water that the foam left behind covers |
//! | `m_L(u)`, `λ₀` | [`FoamLace`], [`LACE_CELL_M`] | 1, m | uniform lace variable, its coarsest cell |
//! | `q_L(u)` | [`FoamLace::local_cover`] | 1 | the cover the lace draws, mean the foam cover, `[0, 1]` |
//! | `v` | [`FoamMemoryParams::drift_m_s`] | m s⁻¹ | foam drift relative to the water |
//! | `r₈₀` | `r80_um` | µm | spray drop radius at 80 % humidity |
//! | `dF/dr₈₀` | [`msd86_flux`] | m⁻² s⁻¹ µm⁻¹ | spray source function |
//! | `v_s`, `v_d` | [`stokes_settling_velocity`], [`SprayMedium::deposition_velocity`] | m s⁻¹ | settling, deposition velocity |
//! | `n(r, z)` | [`SprayMedium::concentration`] | m⁻³ µm⁻¹ | drop concentration |
//! | `dF/dr₈₀` (spume) | [`f94_spume_flux`] | m⁻² s⁻¹ µm⁻¹ | spume source function |
//! | `v` | [`terminal_velocity`] | m s⁻¹ | fall speed of a drop |
//! | `u*`, `z_s` | [`SpumeParams`] | m s⁻¹, m | friction velocity, height where spume is torn off |
//! | `Hᵢ`, `kᵢ(0)` | [`SpumeClass`] | m, m⁻¹ | scale height and sea-level extinction of a spume class |
//! | `J(d)` | [`PhaseLobeTable`] | radiance | sky and sea seen through the drops' phase function |
//! | `H`, `z_max` | `scale_height_m`, `max_height_m` | m | profile scale height, top of the spray |
//! | `Q_e` | [`ExtinctionEfficiency`] | 1 | extinction efficiency |
//! | `k_e` | [`SprayMedium::extinction`] | m⁻¹ | extinction coefficient |
//! | `τ_aod` | [`SprayMedium::optical_depth`] | 1 | vertical optical depth of the spray |
//! | `T` | [`SprayMedium::transmittance`] | 1 | Beer–Lambert transmittance |
//!
//! ## Validity
//!
//! The coverage laws were fitted on `U₁₀` ≈ 4–20 m s⁻¹ (accepted on `[0, 60]`, zero below the
//! onset wind, clamped to 1); the stability forms accept `ΔT = T_w − T_a` on `[−30, 30]` °C
//! ([`MAX_ABS_DELTA_T_C`], an error beyond, never a clamp). The spray source was fitted on
//! `r₈₀` ∈ 0.8–15 µm (bubble-mediated drops); the spume function covers 15–250 µm and its
//! magnitude is uncertain by about an order of magnitude (published spume functions disagree that
//! much). Radiances are linear in the irradiances given, in any consistent unit.
//!
//! ## Example
//!
//! ```
//! use brine_foam::{CoverageParams, DARLES_ONSET_WIND_M_S, SprayMedium, SprayParams, WhitecapLaw, whitecap_coverage};
//!
//! // Darles' figure 6 conditions, with the wind in m/s: U10 = 10 m/s, T_w = 12 °C, T_a = 20 °C.
//! let law = WhitecapLaw::monahan_1986_from_temperatures(12.0, 20.0)?;
//! let w = whitecap_coverage(&CoverageParams::new(10.0, law, DARLES_ONSET_WIND_M_S)?);
//! assert!((w - 3.475e-3).abs() < 1e-5);
//!
//! let spray = SprayMedium::new(&SprayParams { u10: 10.0, ..SprayParams::default() })?;
//! let t = spray.transmittance(2.0, 2.0, 1000.0, 1.0); // 1 km just above the sea
//! assert!(t > 0.0 && t < 1.0);
//! # Ok::<(), brine_foam::FoamError>(())
//! ```
//!
//! ## References
//!
//! - Monahan E., Ó Muircheartaigh I. 1980, JPO 10:2094–2099; 1986, Int. J. Remote Sens.
//!   7(5):627–642.
//! - Monahan E., Spiel D., Davidson K. 1986, in *Oceanic Whitecaps*, Reidel, 167–174.
//! - Koepke P. 1984, "Effective reflectance of oceanic whitecaps", Appl. Opt. 23(11):1816–1824.
//! - Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
//!   realistic ocean scenes", WSCG, §4.1–4.2.
//! - Shettle E., Fenn R. 1979, AFGL-TR-79-0214 (aerosol profiles).
//! - Callaghan A., Deane G., Stokes M. 2012, JGR 117, C09015 (foam decay times).
//! - Monahan E. C. 1971, "Oceanic whitecaps", JPO 1:139–144 (decay time 3.85 s); Monahan E. C.,
//!   Lu M. 1990, IEEE J. Oceanic Eng. 15(4):340–349 (stages A and B).
//! - Fairall C. W., Kepert J. D., Holland G. J. 1994, Global Atmos. Ocean Syst. 2:121–142 (spume);
//!   Andreas E. L. 1992, JGR 97:11429–11441; Andreas E. L. 2002, in *Atmosphere–Ocean
//!   Interactions* 1, WIT Press, 1–46 (review); Gunn R., Kinzer G. 1949, J. Meteor. 6:243–248
//!   (fall speeds); Schiller L., Naumann A. 1933 (drag).
//! - Worley S. 1996, "A cellular texture basis function", SIGGRAPH, 291–294 (the foam lace).
//! - Wu J. 1983, "Sea-surface drift currents induced by wind and waves", JPO 13:1441–1451.

mod coverage;
mod error;
mod extension;
mod history;
mod inscatter;
mod lace;
mod medium;
mod memory;
mod noise;
mod radiance;
mod scattering;
mod spray;
mod spume;
mod tiling;
mod windrows;

pub use coverage::{
    CoverageParams, DARLES_ONSET_WIND_M_S, MAX_ABS_DELTA_T_C, MAX_WIND_M_S, WhitecapLaw, whitecap_coverage,
};
pub use error::FoamError;
pub use extension::{FoamExtension, FoamExtensionParams, FoamPoint, SurfaceStatistics};
pub use history::{FoamHistory, FoamHistoryParams, FoamSample, FoamState, MAX_HISTORY_SAMPLES};
pub use inscatter::{LOBE_TABLE_AZIMUTHS, LOBE_TABLE_ELEVATIONS, PhaseLobeTable};
pub use lace::{FoamLace, LACE_CELL_M, LACE_THICKNESS_CONTRAST};
pub use medium::{ExtinctionEfficiency, SprayMedium, SprayParams};
pub use memory::{
    FOAM_DENSITY, FoamMemory, FoamMemoryParams, MAX_MEMORY_INSTANTS, MONAHAN_1971_DECAY_TIME_S, MemoryClock,
    MemorySample, PeriodicPatches, STREAK_STRETCH, STREAK_WINDS_M_S, WIND_DRIFT_FRACTION, WhiteWater,
    calibrate_threshold, periodic_patches,
};
pub use noise::FoamNoise;
pub use radiance::{FRESH_FOAM_REFLECTANCE, KOEPKE_EFFICIENCY, KoepkeFoam, foam_radiance, surface_radiance};
pub use scattering::{SprayLighting, SprayRay, SprayScattering, henyey_greenstein};
pub use spray::{
    AIR_VISCOSITY, G, MSD86_RADIUS_RANGE_UM, SEA_WATER_DENSITY, msd86_flux, spray_foam_factor, stokes_settling_velocity,
};
pub use spume::{
    AIR_DENSITY, F94_REFERENCE_WIND_M_S, MONAHAN_1980_EXPONENT, SPUME_CLASSES, SPUME_RADIUS_RANGE_UM, SpumeClass,
    SpumeLayer, SpumeParams, VON_KARMAN, f94_spume_flux, production_velocity, terminal_velocity,
};
pub use windrows::{WINDROW_DENSITY, WINDROW_SHARE, WINDROW_SPACING_M, WINDROW_STRETCH, Windrows};
