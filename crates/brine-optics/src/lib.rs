//! # brine-optics — light at and under the sea surface
//!
//! The optics of Darles et al. 2007, Chen et al. 2007 and Li Ying et al. 2018, each from its
//! primary source:
//!
//! - **Fresnel and refraction** — exact unpolarised reflectance of a dielectric interface both
//!   ways with total internal reflection (Chen et al. 2007 §3.4 after Cook & Torrance 1982),
//!   Schlick's approximation, Snell refraction, the hemispherical (diffuse) Fresnel reflectance,
//!   and the index of sea water by wavelength, temperature and salinity (Quan & Fry 1995).
//! - **Natural water** (Premoze & Ashikhmin 2001, Darles §4.3) — pure-water absorption (Pope &
//!   Fry 1997), sea-water scattering (Morel 1974), the Case-1 bio-optical model of absorption,
//!   scattering and backscattering by chlorophyll (Morel 1988, 1991; Prieur & Sathyendranath
//!   1981), `K_d` (Morel 1988), Jerlov's water types (Jerlov 1976), the diffuse upwelling
//!   radiance along a refracted ray with a sea floor (Darles Eq. 8–11, corrected), and band
//!   averages per linear-sRGB channel for the renderer.
//! - **Dipole BSSRDF** (Jensen et al. 2001, as Li Ying et al. 2018 §3.3 use it) — `R_d(r)`,
//!   `F_dr`, `A`, `z_r`, `z_v`, `σ_tr`, `α′`, the BSSRDF with Fresnel in and out, its total
//!   diffuse reflectance, Li Ying's Table 3, and light through thin crests.
//! - **Ocean BRDF** (Bruneton, Neyret & Holzschuch 2010) — Gaussian slopes with anisotropic
//!   variances (Cox & Munk 1954), Smith shadowing, Fresnel at the half vector, the reflected sun (a point or a disc of finite size),
//!   the reflected sky from a filtered environment, and the slope variance of unresolved waves;
//!   the rough sea's reflectance over the visible normals (Heitz 2014), split between the sky and
//!   the neighbouring waves, with the visibility of a facet given its slope and the escape of its
//!   reflection measured on Gaussian profiles (Smith's masking and shadowing take both to be the
//!   same for every facing slope); the drawn waves' share of that escape for a sea drawn in two
//!   scales.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `θᵢ` | `cos_theta_i` | 1 (cosine) | angle of incidence to the normal |
//! | `n_i`, `n_t` | `n_i`, `n_t` | 1 | refractive indices on either side |
//! | `F` | [`fresnel_dielectric`] | 1 | unpolarised reflectance, `[0, 1]` |
//! | `λ` | `lambda_nm` | nm | wavelength of light |
//! | `C` | [`Chlorophyll`] | mg m⁻³ | chlorophyll-a concentration |
//! | `a`, `b`, `b_b`, `c` | [`Iops`] | m⁻¹ | absorption, scattering, backscattering, beam attenuation |
//! | `K_d` | `k_d` | m⁻¹ | diffuse attenuation of downwelling irradiance |
//! | `R(0⁻)` | [`irradiance_reflectance`] | 1 | irradiance reflectance below the surface |
//! | `E_d(0⁻)` | `e_d_below` | klx or W m⁻² | downwelling irradiance just below the surface |
//! | `L_df(0)` | [`diffuse_upwelling_radiance`] | kcd m⁻² or W m⁻² sr⁻¹ | diffuse upwelling radiance |
//! | `σ_a`, `σ_s`, `σ′_s` | [`DipoleMaterial`] | length⁻¹ | absorption, scattering, reduced scattering |
//! | `R_d(r)` | [`DipoleMaterial::diffuse_reflectance`] | length⁻² | dipole diffuse reflectance |
//! | `σx²`, `σy²` | [`SlopeVariance`] | 1 | facet slope variances downwind, crosswind |
//! | `p(ζ)` | [`slope_pdf`] | 1 | slope density |
//! | `R`, `R_seen` | [`ReflectanceSplit`], [`RoughReflectance`] | 1 | rough reflectance: from the sky; of the visible facets in all |
//! | `μ_r` | [`RoughReflectance::mirror_cosine`] | 1 | mean cosine of the seen facets' mirror directions to the mean normal |
//! | `r(ν, s)` | [`SlopeVisibility::ratio`] | 1 | visibility of a facing facet given its slope, over Smith's `G₁` |
//! | `e(ν, s)` | [`SlopeVisibility::escape`] | 1 | escape of a seen facet's reflection given its slope, over Smith's height-correlated `G` |
//! | `E_d` | [`drawn_escape`] | 1 | the drawn waves' share of a reflection's escape, over the BRDF's |
//! | `Λ` | [`smith_lambda`] | 1 | Smith shadowing function |
//! | `ρ(v, l)` | [`ocean_brdf`] | sr⁻¹ | BRDF |
//!
//! ## Validity
//!
//! Non-absorbing dielectric interfaces (real indices). Water properties 400–700 nm (the tables'
//! common range), chlorophyll 0–100 mg m⁻³ (fitted on about 0.02–10, open-ocean Case-1 water).
//! The dipole needs `σ′_s ≫ σ_a`, which sea water does not satisfy in the red. The BRDF assumes
//! Gaussian slopes, in a local frame with z along the mean normal and x downwind.
//!
//! ## Example
//!
//! ```
//! use brine_optics::{RgbBands, WaterBody, WaterRgb, WATER_IOR, fresnel_dielectric};
//! use glam::DVec3;
//! let f = fresnel_dielectric(60f64.to_radians().cos(), 1.0, WATER_IOR);
//! assert!((f - 0.059691).abs() < 1e-5);
//! // Deep Case-1 water with 0.3 mg/m³ chlorophyll, seen straight down, under 50 klx.
//! let water = WaterRgb::new(&WaterBody::case1(0.3).unwrap(), RgbBands::SrgbAverage);
//! let below = water.refracted_ray_radiance(DVec3::splat(50.0), 1.0, f64::INFINITY, DVec3::ZERO);
//! assert!(below.z > below.x); // blue water
//! ```

mod colour;
mod dipole;
mod error;
mod fresnel;
mod index;
mod iop;
mod jerlov;
mod ocean_brdf;
mod quadrature;
mod refraction;
mod rough;
mod sky_reflection;
mod subsurface;
mod tables;
mod water;
mod wave_slopes;

pub use colour::{BAND_SAMPLES, band_average, cie1931_xyz_bar, srgb_band_weights};
pub use dipole::{DipoleMaterial, LiYingParameters, diffuse_fresnel_reflectance};
pub use error::OpticsError;
pub use fresnel::{
    WATER_IOR, critical_angle, fresnel_dielectric, fresnel_normal, fresnel_schlick, fresnel_transmittance,
    hemispherical_fresnel_reflectance,
};
pub use index::Seawater;
pub use iop::{
    Chlorophyll, Iops, LAMBDA_MAX_NM, LAMBDA_MIN_NM, case1_iops, check_wavelength, chlorophyll_specific_absorption,
    morel_kd, morel_kd_coefficients, pure_seawater_scattering, pure_seawater_scattering_power_law,
    pure_water_absorption,
};
pub use jerlov::{DarlesWater, JERLOV_LAMBDA_RANGE_NM, JerlovType};
pub use ocean_brdf::{
    MIN_SLOPE_VARIANCE, POINT_DISC_Q, POINT_DISC_TAIL, SEA_ROUGHNESS_LENGTH_M, SMITH_NEGLIGIBLE_NU, SlopeVariance,
    SunDisc, glitter_slope_density, mean_fresnel, ocean_brdf, reflected_disc_radiance, reflected_source_radiance,
    reflected_sun_radiance, slope_pdf, smith_lambda, u12_5_from_u10,
};
pub use quadrature::{GaussHermite, MAX_HERMITE_ORDER, gauss_legendre};
pub use refraction::{SnellWindow, reflect, refract};
pub use rough::{
    ReflectanceSplit, RoughReflectance, SlopeVisibility, TwoScaleFacet, drawn_escape, reflectance_split,
    reflectance_split_uncorrelated, water_reflectance_split,
};
pub use sky_reflection::{SkyReflection, reflected_sky_radiance_filtered};
pub use subsurface::{
    diffuse_upwelling_radiance, irradiance_reflectance, irradiance_reflectance_morel, lambertian_floor_radiance,
    radiance_out_of_water, refracted_ray_radiance, refracted_ray_radiance_sum,
};
pub use water::{RgbBands, WaterBody, WaterKind, WaterRgb};
pub use wave_slopes::{WaveComponent, slope_variance_sines, slope_variance_trochoids, trochoid_mean_square_slope};
