//! # brine-sky — daylight sky and sun
//!
//! The analytic daylight model of Preetham, Shirley & Smits (1999) that Darles et al. 2007 use
//! for sky and sun: the Perez et al. (1993) sky luminance and chromaticity distributions with the
//! turbidity-linear coefficients, the zenith luminance and chromaticity fits, and the sun seen
//! through an atmosphere of a given turbidity.
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
//! | `m` | [`relative_air_mass`] | 1 | relative optical air mass |
//!
//! Radiances are CIE XYZ or linear sRGB (Rec. 709, D65) with Y in kcd m⁻².
//!
//! ## Validity
//!
//! Clear skies, turbidity 1.7–10 (best 2–6), sun elevation 0–90°, view directions above the
//! horizon (clamped at `cos θ = 0.01`).
//!
//! ## Status
//!
//! The Preetham sky is complete. The sun is a **partial** model (Rayleigh and aerosol
//! transmittance only, at three wavelengths; see [`Sun`]). Aerial perspective, twilight, the night
//! sky, moonlight and clouds are not yet implemented (issue #4).
//!
//! ## Example
//!
//! ```
//! use brine_sky::PreethamSky;
//! use glam::DVec3;
//! let sun = DVec3::new(0.0, 0.5, 0.866);
//! let sky = PreethamSky::new(3.0, sun)?;
//! let zenith = sky.radiance_rgb(DVec3::Y);
//! assert!(zenith.min_element() > 0.0);
//! # Ok::<(), brine_sky::SkyError>(())
//! ```
//!
//! ## References
//!
//! - Preetham A.J., Shirley P., Smits B. 1999, "A practical analytic model for daylight",
//!   SIGGRAPH 91–100.
//! - Perez R., Seals R., Michalsky J. 1993, Solar Energy 50(3):235–245.

mod colour;
mod error;
mod preetham;
mod sun;

pub use colour::{xyy_to_xyz, xyz_to_linear_srgb};
pub use error::SkyError;
pub use preetham::{MIN_COS_VIEW, PerezCoefficients, PreethamSky, perez, zenith_chromaticity_xy, zenith_luminance};
pub use sun::{
    RGB_WAVELENGTHS_NM, SUN_SOLID_ANGLE, SUN_TOA_LUMINANCE, Sun, aerosol_transmittance, rayleigh_transmittance,
    relative_air_mass,
};
