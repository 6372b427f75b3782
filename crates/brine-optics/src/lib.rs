//! # brine-optics — light at and under the sea surface
//!
//! The optics of Darles et al. 2007, Chen et al. 2007 and Li Ying et al. 2018: the exact Fresnel
//! reflectance of the air–water interface and Snell refraction (Chen et al. 2007 §3.4, after
//! Cook & Torrance 1982), and the ocean BRDF of Bruneton, Neyret & Holzschuch (2010): Gaussian
//! facet slopes of the waves too small to be drawn, Smith shadowing and Fresnel at the half vector,
//! used for the reflected sun and sky.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `θᵢ` | `cos_theta_i` | 1 (cosine) | angle of incidence to the normal |
//! | `n_i`, `n_t` | `n_i`, `n_t` | 1 | refractive indices on either side |
//! | `F` | [`fresnel_dielectric`] | 1 | unpolarised reflectance, `[0, 1]` |
//! | `σx²`, `σy²` | [`SlopeVariance`] | 1 | facet slope variances downwind, crosswind |
//! | `p(ζ)` | [`slope_pdf`] | 1 | slope density |
//! | `Λ` | [`smith_lambda`] | 1 | Smith shadowing function |
//! | `ρ(v, l)` | [`ocean_brdf`] | sr⁻¹ | BRDF |
//!
//! ## Validity
//!
//! Non-absorbing dielectric (real indices); the BRDF assumes a Gaussian slope distribution and is
//! evaluated in a local frame with z along the mean normal and x downwind.
//!
//! ## Status
//!
//! Fresnel, refraction and the Bruneton BRDF's sun and mean-Fresnel terms are implemented. The
//! natural-water inherent optical properties (Premoze & Ashikhmin 2001), Jerlov water types, the
//! diffuse radiance of Darles §4.3 and the dipole BSSRDF (Jensen et al. 2001) are not yet
//! (issue #5).
//!
//! ## Example
//!
//! ```
//! use brine_optics::{WATER_IOR, fresnel_dielectric};
//! let f = fresnel_dielectric(60f64.to_radians().cos(), 1.0, WATER_IOR);
//! assert!((f - 0.059691).abs() < 1e-5);
//! ```

mod error;
mod fresnel;
mod ocean_brdf;
mod refraction;

pub use error::OpticsError;
pub use fresnel::{WATER_IOR, fresnel_dielectric, fresnel_normal, fresnel_schlick};
pub use ocean_brdf::{
    MIN_SLOPE_VARIANCE, SlopeVariance, mean_fresnel, ocean_brdf, reflected_sun_radiance, slope_pdf, smith_lambda,
};
pub use refraction::{reflect, refract};
