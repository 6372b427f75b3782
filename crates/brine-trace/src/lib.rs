//! # brine-trace — sphere tracing of sums of Lipschitz components
//!
//! Ray–surface intersection for implicit surfaces `F(p) = 0` where `F` is a sum of bounded,
//! Lipschitz-continuous components, `F(p) = Σᵢ nᵢ(p)`. The method is sphere tracing
//! (Hart 1996): if `|F(p) − F(q)| ≤ L‖p − q‖` then no zero of `F` lies closer to `p` than
//! `|F(p)|/L`, so a ray may safely advance by that distance. Darles, Crespin & Ghazanfarpour
//! (2007, §3) apply it to a sum of trochoid waves with per-component bounds, sorted by Algorithm 1.
//!
//! The crate knows nothing about oceans: `brine-waves` implements [`LipschitzSum`] for its wave
//! sets (and a fast SIMD [`RayTiers`]), and the tests implement it for a weighted sum of sphere
//! distance functions.
//!
//! ## Methods ([`Method`]), all returning the first sign change
//!
//! | method | step | source |
//! |---|---|---|
//! | [`Method::BruteForce`] | fixed `Δ = λ_min/4`, bisection | Darles et al. 2007 §3.1 |
//! | [`Method::GlobalLipschitz`] | `|F|/Σ Lᵢ` | Hart 1996 |
//! | [`Method::Directional`] | `|F|/Σ Lᵢ(d̂)` | Hart 1996 along the ray |
//! | [`Method::Relaxed`] | `ω|F|/Σ Lᵢ(d̂)`, undone if the spheres do not overlap | Keinert et al. 2014 |
//! | [`Method::Darles`] | [`efficient_lipschitz_step`] over components sorted by stale estimates | Darles et al. 2007 Alg. 1, docs/equations.md §2 |
//! | [`Method::Segment`] | `min(s, |F|/λ_s)`, `λ_s = Σⱼ min(Lⱼ, |dⱼ| + Kⱼ s)` local to the candidate segment, next `s` = κ·step | Galin et al. 2020 Alg. 2 ([`trace_segments`]) |
//! | [`Method::Tiered`] | first root of the certified bound [`StepBound`] over tiers of decreasing scale, the short ones pruned; over-relaxed steps checked backward, Newton probes on certified-monotone stretches | Brine ([`trace_tiers`]) |
//!
//! plus image coherence ([`trace_tile`]: a quadtree of cones certified by
//! [`LipschitzSum::certify_cone`]), temporal coherence ([`trace_temporal`]) and footprint fading
//! ([`TraceOptions::footprint_angle`], [`footprint_weight`]; what was dropped at a hit:
//! [`component_weights`], [`faded_components`]).
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `F(p)` | [`LipschitzSum::value`] | m (or the component's unit) | implicit function, surface at `F = 0` |
//! | `nᵢ(p)` | [`LipschitzSum::component`] | as `F` | component `i` |
//! | `Lᵢ` | [`LipschitzSum::component_lipschitz`] | 1 | Lipschitz constant of `nᵢ` |
//! | `Lᵢ(d̂)` | [`LipschitzSum::component_directional_lipschitz`] | 1 | bound of `|d nᵢ(p + t d̂)/dt|` |
//! | `Kᵢ(d̂)` | [`LipschitzSum::component_directional_curvature`] | m⁻¹ | bound of `|d² nᵢ(p + t d̂)/dt²|` |
//! | `mᵢ`, `Mᵢ` | [`LipschitzSum::component_min`], [`LipschitzSum::component_max`] | as `F` | bounds of `nᵢ` on a segment |
//! | `λᵢ` | [`LipschitzSum::component_feature_size`] | m | length scale (wavelength) |
//! | `Tᵢ` | [`LipschitzSum::component_fade_distance`] | m | distance where the pixel footprint equals `λᵢ` |
//! | `wᵢ(t)` | [`footprint_weight`] | 1 | fade weight `smoothstep(1, 1.5, Tᵢ/t)` |
//! | `h(t)` | [`TraceOptions::min_step_at`] | m | minimum (probe) step |
//! | `t` | [`Hit::t`] | m | distance along the unit ray direction |
//! | `[t_enter, t_exit]` | [`RaySpan`] | m | the part of a ray traced, clipped to the zero-set bounds |
//!
//! ## What a hit is
//!
//! A hit is a *sign change* of `F` along the ray, bracketed and then refined by the Illinois
//! variant of regula falsi (bisection for brute force; Newton's method inside a certified
//! interval for the tiered method) until the bracket is shorter than the stated tolerance, or
//! (tiered method) a crossing of the exact `F` enclosed within the tolerance by certified lower
//! and upper bounds. A ray that only comes within `ε` of the surface without crossing it is not a
//! hit. Every step is either certified free of zeros by a bound (Lipschitz, efficient or
//! second-order) or, when that distance is smaller than the minimum step `h`, a probe step no
//! longer than `h` whose end is tested for a sign change. The only crossings that can be missed are
//! pairs of crossings closer than `h` to each other, whose excursion below the ray is at most
//! `L·h/2` (a skim), and, with an approximate evaluator, excursions within twice its error bound.
//! Brute force, the uncertified baseline, can miss pairs closer than its march step.
//!
//! ## Validity
//!
//! Components must be finite and obey the bounds they report; ray directions must be finite and
//! non-zero ([`Ray::new`] normalises and checks them); options are checked by
//! [`TraceOptions::validate`].
//!
//! ## Example
//!
//! ```
//! use brine_trace::{LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace};
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
//! for method in Method::ALL {
//!     let options = TraceOptions { method, march_step: 0.01, ..TraceOptions::default() };
//!     let mut stats = TraceStats::default();
//!     let hit = trace(&Plane, &ray, &options, &mut stats).unwrap();
//!     assert!((hit.t - 10.0 * 2f64.sqrt()).abs() < 1e-5, "{method:?}");
//! }
//! ```
//!
//! ## References
//!
//! - Hart J.C. 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of
//!   implicit surfaces", The Visual Computer 12(10):527–545.
//! - Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
//!   realistic ocean scenes", WSCG, §3, Algorithm 1, Tables 1–2.
//! - Keinert B., Schäfer H., Korndörfer J., Ganse U., Stamminger M. 2014, "Enhanced sphere
//!   tracing", Smart Tools and Apps for Graphics (Eurographics Italian Chapter).
//! - Galin E., Guérin E., Paris A., Peytavie A. 2020, "Segment tracing using local Lipschitz
//!   bounds", Computer Graphics Forum 39(2):545–554.
//! - Bruneton E., Neyret F., Holzschuch N. 2010, "Real-time realistic ocean lighting using
//!   seamless transitions from geometry to BRDF", CGF 29(2):487–496 (footprint fading).

mod bounds;
mod coherence;
mod darles;
mod footprint;
mod lowered;
mod options;
mod ray;
mod refine;
mod segment;
mod sphere;
mod stats;
mod step;
mod sum;
mod tiered;
mod tiers;
mod trace;

pub use bounds::Aabb;
pub use coherence::{MIN_CONE_RAYS, RayTile, trace_temporal, trace_tile};
pub use footprint::{
    FADE_CURVATURE, FADE_SLOPE, FadedComponents, component_weights, faded_components, footprint_weight,
    footprint_weight_slope,
};
pub use lowered::Lowered;
pub use options::{Hit, Method, Step, StepKind, TraceOptions, TraceOptionsError};
pub use ray::{Ray, RayError, RaySpan};
pub use refine::{bisect_crossing, refine_crossing};
pub use segment::{SEGMENT_GROWTH, local_lipschitz, trace_segments};
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
