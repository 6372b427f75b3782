//! # brine-trace — sphere tracing of sums of Lipschitz components
//!
//! Ray–surface intersection for implicit surfaces `F(p) = 0` where `F` is a sum of bounded,
//! Lipschitz-continuous components, `F(p) = Σᵢ nᵢ(p)`. The method is sphere tracing
//! (Hart 1996): if `|F(p) − F(q)| ≤ L‖p − q‖` then no zero of `F` lies closer to `p` than
//! `|F(p)|/L`, so a ray may safely advance by that distance. Darles, Crespin & Ghazanfarpour
//! (2007, §3) apply it to a sum of trochoid waves with per-component bounds.
//!
//! The crate knows nothing about oceans: `brine-waves` implements [`LipschitzSum`] for its wave
//! sets, and the tests implement it for a union-free sum of sphere distance functions.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `F(p)` | [`LipschitzSum::value`] | m (or the component's unit) | implicit function, surface at `F = 0` |
//! | `nᵢ(p)` | [`LipschitzSum::component`] | as `F` | component `i` |
//! | `Lᵢ` | [`LipschitzSum::component_lipschitz`] | 1 | Lipschitz constant of `nᵢ` |
//! | `Lᵢ(d̂)` | [`LipschitzSum::component_directional_lipschitz`] | 1 | bound of `|d nᵢ(p + t d̂)/dt|` |
//! | `mᵢ` | [`LipschitzSum::component_min`] | as `F` | lower bound of `nᵢ` on a segment |
//! | `t` | [`Hit::t`] | m | distance along the unit ray direction |
//!
//! ## What a hit is
//!
//! A hit is a *sign change* of `F` along the ray, bracketed and then refined by the Illinois
//! variant of regula falsi until the bracket is shorter than the stated tolerance. A ray that only
//! comes within `ε` of the surface without crossing it is not a hit. Every step is either a
//! certified unbounding-sphere step (`|F|/L`, no zero can lie inside it) or, when that distance is
//! smaller than the minimum step `h`, a probe step of length `h` whose end is tested for a sign
//! change. The only crossings that can be missed are pairs of crossings closer than `h` to each
//! other, whose excursion below the ray is at most `L·h/2` (a skim); [`TraceOptions`] documents
//! `h`.
//!
//! ## Validity
//!
//! Components must be finite and Lipschitz with the constants they report; ray directions must
//! be finite and non-zero ([`Ray::new`] normalises and checks them).
//!
//! ## Example
//!
//! ```
//! use brine_trace::{LipschitzSum, Ray, TraceOptions, TraceStats, trace};
//! use glam::DVec3;
//!
//! /// The plane y = 0 as a single component F(p) = y.
//! struct Plane;
//! impl LipschitzSum for Plane {
//!     fn component_count(&self) -> usize { 1 }
//!     fn component(&self, _i: usize, p: DVec3) -> f64 { p.y }
//!     fn component_lipschitz(&self, _i: usize) -> f64 { 1.0 }
//!     fn component_min(&self, _i: usize, a: DVec3, b: DVec3) -> f64 { a.y.min(b.y) }
//! }
//!
//! let ray = Ray::new(DVec3::new(0.0, 10.0, 0.0), DVec3::new(1.0, -1.0, 0.0)).unwrap();
//! let mut stats = TraceStats::default();
//! let hit = trace(&Plane, &ray, &TraceOptions::default(), &mut stats).unwrap();
//! assert!((hit.t - 10.0 * 2f64.sqrt()).abs() < 1e-6);
//! ```
//!
//! ## References
//!
//! - Hart J.C. 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of
//!   implicit surfaces", The Visual Computer 12(10):527–545.
//! - Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
//!   realistic ocean scenes", WSCG, §3 and Algorithm 1.

mod bounds;
mod coherence;
mod darles;
mod footprint;
mod options;
mod ray;
mod refine;
mod sphere;
mod stats;
mod step;
mod sum;
mod tiered;
mod tiers;
mod trace;

pub use bounds::Aabb;
pub use coherence::{MIN_CONE_RAYS, trace_temporal, trace_tile};
pub use footprint::{FADE_CURVATURE, FADE_SLOPE, component_weights, footprint_weight, footprint_weight_slope};
pub use options::{Hit, Method, Step, StepKind, TraceOptions, TraceOptionsError};
pub use ray::{Ray, RayError};
pub use refine::{bisect_crossing, refine_crossing};
pub use stats::TraceStats;
pub use step::{StepBound, efficient_lipschitz_step, printed_darles_step};
pub use sum::LipschitzSum;
pub use tiered::{TierScratch, certify_cone_with, trace_tiers, trace_tiers_with};
pub use tiers::{COMPONENTS_PER_TIER, ComponentTiers, RayTiers, TierBounds, TierSample};
pub use trace::{trace, trace_logged};

/// The SIMD vector types (the `wide` crate) used by lane-parallel [`RayTiers`] implementors, so that
/// they share the tracer's SIMD dependency and compile-time SIMD level.
pub mod simd {
    pub use wide::{f32x8, f64x4};
}
