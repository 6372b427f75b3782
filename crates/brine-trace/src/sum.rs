//! The component-sum abstraction.

use glam::DVec3;

use crate::{Aabb, Hit, RaySpan, Step, TierScratch, TraceOptions, TraceStats};

/// An implicit function `F(p) = Σᵢ nᵢ(p)` of `N` bounded, Lipschitz-continuous components.
///
/// The surface is the zero set `F(p) = 0`. Implementors must guarantee, for every component `i`
/// and all points `p`, `q`:
///
/// - `|nᵢ(p) − nᵢ(q)| ≤ Lᵢ ‖p − q‖` with `Lᵢ` = [`component_lipschitz`](Self::component_lipschitz);
/// - `|nᵢ(p + t d̂) − nᵢ(p)| ≤ Lᵢ(d̂) |t|` with `Lᵢ(d̂)` =
///   [`component_directional_lipschitz`](Self::component_directional_lipschitz), `Lᵢ(d̂) ≤ Lᵢ`;
/// - `mᵢ ≤ nᵢ(p) ≤ Mᵢ` for `p` on the segment `[a, b]`, `mᵢ` = [`component_min`](Self::component_min),
///   `Mᵢ` = [`component_max`](Self::component_max);
/// - where given, `|d² nᵢ(p + t d̂)/dt²| ≤ Kᵢ(d̂)` =
///   [`component_directional_curvature`](Self::component_directional_curvature) and
///   [`component_directional_derivative`](Self::component_directional_derivative) is the exact
///   derivative along `d̂`;
/// - the zero set lies inside [`zero_set_bounds`](Self::zero_set_bounds).
///
/// The tracer's safety rests on these bounds alone; the property tests of each implementor check
/// them on random points. Only the first four methods are required; the others have conservative
/// defaults (unknown derivative, infinite curvature and maximum, no footprint fading).
///
/// # References
/// Hart 1996, §2 (Lipschitz calculus: the constant of a sum is at most the sum of the constants);
/// Darles et al. 2007, Eq. 1.
pub trait LipschitzSum {
    /// Number of components `N`.
    fn component_count(&self) -> usize;

    /// Value of component `i` at `p`.
    fn component(&self, i: usize, p: DVec3) -> f64;

    /// Lipschitz constant `Lᵢ` of component `i` (Euclidean norm), `Lᵢ ≥ 0`.
    fn component_lipschitz(&self, i: usize) -> f64;

    /// A lower bound `mᵢ` of component `i` over the segment `[a, b]`.
    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64;

    /// An upper bound `Mᵢ` of component `i` over the segment `[a, b]` (defaults to `+∞`, unknown).
    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        let _ = (i, a, b);
        f64::INFINITY
    }

    /// A bound of `|d nᵢ(p + t d̂)/dt|` along the unit direction `d̂` (defaults to `Lᵢ`).
    fn component_directional_lipschitz(&self, i: usize, direction: DVec3) -> f64 {
        let _ = direction;
        self.component_lipschitz(i)
    }

    /// The exact derivative `d nᵢ(p + t d̂)/dt` at `t = 0` along the unit direction `d̂`, if the
    /// component knows it (defaults to `None`).
    fn component_directional_derivative(&self, i: usize, p: DVec3, direction: DVec3) -> Option<f64> {
        let _ = (i, p, direction);
        None
    }

    /// A bound `Kᵢ(d̂)` of `|d² nᵢ(p + t d̂)/dt²|` over all `p` along the unit direction `d̂`
    /// (defaults to `+∞`, unknown). Used by the certified second-order step of
    /// [`crate::Method::Tiered`].
    fn component_directional_curvature(&self, i: usize, direction: DVec3) -> f64 {
        let _ = (i, direction);
        f64::INFINITY
    }

    /// The length scale of component `i` (m): a wavelength for a wave, `+∞` (the default) for a
    /// component that is never faded or marched finely. Sets the brute-force step
    /// (`min_feature_size / 4`) and, through
    /// [`component_fade_distance`](Self::component_fade_distance), footprint fading.
    fn component_feature_size(&self, i: usize) -> f64 {
        let _ = i;
        f64::INFINITY
    }

    /// The distance `Tᵢ` (m) along a ray of direction `d̂` at which the footprint of a pixel of
    /// angular width `footprint_angle` (rad) equals the feature size of component `i`; the tiered
    /// method weights the component by `smoothstep(1, 1.5, Tᵢ/t)` (see [`crate::footprint_weight`]).
    ///
    /// Defaults to the isotropic `feature_size / footprint_angle`; a height field seen at a grazing
    /// angle may return a shorter distance (its footprint is stretched along the view).
    fn component_fade_distance(&self, i: usize, direction: DVec3, footprint_angle: f64) -> f64 {
        let _ = direction;
        self.component_feature_size(i) / footprint_angle
    }

    /// `F(p) = Σ nᵢ(p)`. Implementors usually override this with a faster fused loop.
    fn value(&self, p: DVec3) -> f64 {
        (0..self.component_count()).map(|i| self.component(i, p)).sum()
    }

    /// Global Lipschitz constant `L = Σ Lᵢ` (Hart 1996: the constant of a sum).
    fn lipschitz(&self) -> f64 {
        (0..self.component_count()).map(|i| self.component_lipschitz(i)).sum()
    }

    /// Directional constant `L(d̂) = Σ Lᵢ(d̂)` along the unit direction `d̂`.
    fn directional_lipschitz(&self, direction: DVec3) -> f64 {
        (0..self.component_count()).map(|i| self.component_directional_lipschitz(i, direction)).sum()
    }

    /// The smallest feature size over the components (m), `+∞` if none has one.
    fn min_feature_size(&self) -> f64 {
        (0..self.component_count()).map(|i| self.component_feature_size(i)).fold(f64::INFINITY, f64::min)
    }

    /// An axis-aligned box that contains every zero of `F` (defaults to all of space).
    fn zero_set_bounds(&self) -> Aabb {
        Aabb::EVERYTHING
    }

    /// Traces `span`, a ray on `[t_enter, t_exit]` (already clipped to the zero-set bounds) with
    /// [`crate::Method::Tiered`], or with [`crate::Method::Segment`] when `options.method` says so
    /// (both step on the same [`crate::RayTiers`]; [`crate::trace_tiers_with`] dispatches).
    ///
    /// The default groups the components into tiers by the generic adapter
    /// [`crate::ComponentTiers`]; an implementor with a fast ray-restricted evaluator (SIMD, pruned)
    /// overrides this to call [`crate::trace_tiers`] with its own [`crate::RayTiers`]. `log`, when
    /// given, receives every step (see [`crate::trace_logged`]).
    fn trace_tiered(
        &self,
        span: RaySpan<'_>,
        options: &TraceOptions,
        stats: &mut TraceStats,
        log: Option<&mut Vec<Step>>,
    ) -> Option<Hit> {
        let mut tiers = crate::ComponentTiers::new(self, span.ray, span.t_enter, span.t_exit, options.footprint_angle);
        crate::trace_tiers(&mut tiers, span, options, stats, log)
    }

    /// Image coherence: the largest `t_c` such that no ray from `ray`'s origin within
    /// `half_angle` of its direction crosses the surface on `[t_enter, t_c]` (see
    /// [`crate::certify_cone_with`]).
    ///
    /// The default uses [`crate::ComponentTiers`] and gives up (returns `t_enter`) with footprint
    /// fading, whose weights differ from ray to ray; implementors may override it.
    fn certify_cone(&self, span: RaySpan<'_>, half_angle: f64, options: &TraceOptions, stats: &mut TraceStats) -> f64 {
        if options.footprint_angle > 0.0 {
            return span.t_enter;
        }
        let mut tiers = crate::ComponentTiers::new(self, span.ray, span.t_enter, span.t_exit, 0.0);
        crate::certify_cone_with(&mut TierScratch::default(), &mut tiers, span, half_angle, options, stats)
    }
}
