//! # brine-sky — the sky by day and night
//!
//! The analytic daylight model of Preetham, Shirley & Smits (1999) that Darles et al. 2007 use
//! for sky and sun: the Perez et al. (1993) sky luminance and chromaticity distributions with the
//! turbidity-linear coefficients, the zenith luminance and chromaticity fits, and the sun's
//! spectral radiance through an atmosphere of a given turbidity (Rayleigh, aerosol, ozone,
//! mixed-gas and water-vapour transmittances, integrated against the CIE 1931 matching
//! functions). The aerial perspective of Hoffman & Preetham (2002) used by Chen et al. 2007
//! (§3.2). Beyond the papers, for the time-and-place-driven scenes of Li Ying et al. 2018
//! (§2.1, §3.1): twilight (the sunset sky darkened and coloured by a sky of single and second scattering), the night-sky
//! glow and moonlight (Krisciunas & Schaefer 1991; Jensen et al. 2001), and procedural cloud
//! layers after Chen et al.'s texture perturbation (§3.1). As an alternative clear day sky, the
//! Hosek & Wilkie (2012) model of pbrt-v4, Mitsuba 3 and Blender Cycles ([`HosekWilkieSky`],
//! chosen by [`DaylightModel`]). [`Sky`] puts them together for every sun elevation from −90°
//! to 90°.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `T` | `turbidity` | 1 | atmospheric turbidity, `[1.7, 10]` |
//! | `θ_s` | `theta_s` | rad | sun zenith angle |
//! | `θ`, `γ` | `cos_theta`, `gamma` | 1, rad | view zenith angle, view–sun angle |
//! | `Y_z`, `x_z`, `y_z` | [`zenith_luminance`], [`zenith_chromaticity_xy`] | kcd m⁻², 1 | zenith values |
//! | `F(θ, γ)` | [`perez`] | 1 | Perez distribution |
//! | `A…I`, `L_M` | [`HosekWilkieSky::coefficients`] | 1, W m⁻² sr⁻¹ | Hosek–Wilkie coefficients, channel scale |
//! | `m` | [`relative_air_mass`] | 1 | relative optical air mass |
//! | `L(λ)` | [`sun_spectral_radiance`] | W m⁻² sr⁻¹ nm⁻¹ | sun's spectral radiance |
//! | `β_R`, `β_M` | [`rayleigh_beta`], [`mie_beta`] | m⁻¹ | scattering coefficients at sea level |
//! | `Φ_R`, `Φ_HG` | [`rayleigh_phase`], [`henyey_greenstein`] | sr⁻¹ | phase functions |
//! | `F_ex`, `L_in` | [`AerialPerspective`] | 1, kcd m⁻² | extinction, in-scattering |
//! | `φ` | `phase_angle` | rad | Moon's phase angle |
//!
//! Radiances are CIE XYZ or linear sRGB (Rec. 709, D65) with Y in kcd m⁻²; irradiances in klx.
//! Directions are unit vectors, y up, x east, z south.
//!
//! ## Validity
//!
//! Hosek–Wilkie: clear skies, turbidity 1–10, sun elevation 0–90°, ground albedo 0–1.
//! Preetham's sky: clear skies, turbidity 1.7–10 (best 2–6), sun elevation 0–90°, view
//! directions above the horizon (clamped at `cos θ = 0.01`). [`Sky`] accepts any sun elevation:
//! below the horizon the twilight ratio (single and second scattering) and the night glow are
//! approximations, documented in `docs/models/brine-sky.md`.
//!
//! ## Example
//!
//! ```
//! use brine_sky::{MoonParams, Sky, SkyParams};
//! use glam::DVec3;
//! // 23:00 under a full moon: the sun 30° below the horizon, the Moon 25° up in the south-east.
//! let sun = DVec3::new(0.0, -0.5, -0.866);
//! let moon = MoonParams { direction: DVec3::new(0.6, 0.42, 0.68).normalize(), phase_angle: 0.05, distance_km: 380_000.0 };
//! let sky = Sky::new(&SkyParams { moon: Some(moon), ..SkyParams::new(3.0, sun) })?;
//! let zenith = sky.radiance_rgb(DVec3::Y);
//! assert!(zenith.min_element() > 0.0 && zenith.max_element() < 1e-4); // < 0.1 cd m⁻²: a dark sky
//! assert!(sky.moon().unwrap().irradiance_rgb.y > 1e-4); // about 0.1 lx of moonlight
//! assert_eq!(sky.sun().irradiance_rgb, DVec3::ZERO);
//! # Ok::<(), brine_sky::SkyError>(())
//! ```
//!
//! ## References
//!
//! - Preetham A.J., Shirley P., Smits B. 1999, "A practical analytic model for daylight",
//!   SIGGRAPH 91–100.
//! - Hosek L., Wilkie A. 2012, "An analytic model for full spectral sky-dome radiance", ACM
//!   Trans. Graph. 31(4):95.
//! - Perez R., Seals R., Michalsky J. 1993, Solar Energy 50(3):235–245.
//! - Hoffman N., Preetham A.J. 2002, "Rendering outdoor light scattering in real time", GDC.
//! - Iqbal M. 1983, *An Introduction to Solar Radiation*, Academic Press.
//! - Nishita T., Sirai T., Tadamura K., Nakamae E. 1993, SIGGRAPH 175–182.
//! - Krisciunas K., Schaefer B.E. 1991, "A model of the brightness of moonlight", PASP 103:1033.
//! - Jensen H.W., Durand F., Stark M., Premože S., Dorsey J., Shirley P. 2001, "A
//!   physically-based night sky model", SIGGRAPH 399–408.
//! - Chen et al. 2007, "An efficient method for real-time ocean simulation", §3.1–3.2.
//! - CIE 15:2004 *Colorimetry*.

mod aerial;
mod cie;
mod clouds;
mod colour;
mod dome;
mod error;
mod filtered;
mod hosek_wilkie;
mod night;
mod preetham;
mod sky;
mod solar_tables;
mod sun;
mod twilight;

pub use aerial::{
    AIR_DEPOLARISATION, AIR_NUMBER_DENSITY, AIR_REFRACTIVE_INDEX, AerialPerspective, HAZE_ASYMMETRY, JUNGE_EXPONENT,
    MIE_SCALE_HEIGHT_M, RAYLEIGH_SCALE_HEIGHT_M, Scattering, henyey_greenstein, mie_beta, optical_depth, rayleigh_beta,
    rayleigh_phase,
};
pub use cie::{CIE_1931_2DEG, CMF_START_NM, CMF_STEP_NM, MAX_LUMINOUS_EFFICACY, cmf};
pub use clouds::{CloudLayers, CloudParams};
pub use colour::{
    bradford_adaptation, chromaticity, daylight_locus_y, linear_srgb_to_xyz, white_balance_linear_srgb, xyy_to_xyz,
    xyz_to_linear_srgb,
};
pub use dome::{fisheye_direction, fisheye_pixel_direction};
pub use error::SkyError;
pub use filtered::{FILTERED_SKY_BASE_SIGMA, FILTERED_SKY_LEVELS, FilteredSky};
pub use hosek_wilkie::{HosekWilkieSky, SEA_GROUND_ALBEDO, hosek_wilkie_distribution};
pub use night::{
    MOON_MEAN_DISTANCE_KM, MOON_RADIUS_KM, NIGHT_ZENITH_LUMINANCE, SUN_V_MAGNITUDE, V_EXTINCTION, layer_air_mass,
    lommel_seeliger_phase, moon_to_sun_illuminance, moon_to_sun_illuminance_jensen, night_sky_luminance,
};
pub use preetham::{MIN_COS_VIEW, PerezCoefficients, PreethamSky, perez, zenith_chromaticity_xy, zenith_luminance};
pub use sky::{DaylightModel, Disc, MOONLIGHT_FADE, MoonParams, Sky, SkyParams, visible_fraction};
pub use solar_tables::{
    K_MIXED_GAS, K_OZONE, K_WATER_VAPOUR, SOLAR_RADIANCE_380_750, SOLAR_RADIANCE_SCALE, solar_radiance,
};
pub use sun::{
    ANGSTROM_ALPHA, AU_KM, OZONE_CM, RGB_WAVELENGTHS_NM, SUN_RADIUS_KM, SUN_SOLID_ANGLE, Sun, WATER_VAPOUR_CM,
    aerosol_transmittance, angstrom_beta, mixed_gas_transmittance, ozone_transmittance, rayleigh_transmittance,
    relative_air_mass, sun_angular_radius, sun_radiance_xyz, sun_spectral_radiance, water_vapour_transmittance,
};
pub use twilight::{ATMOSPHERE_TOP_M, EARTH_RADIUS_M, TwilightRatio};
