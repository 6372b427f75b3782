//! The Gerstner surface as a [`brine_trace::LipschitzSum`].
//!
//! `F(p) = y − h(x, z)` in two components: `n₀ = y` (`L₀ = 1`, directional `|d̂_y|`) and
//! `n₁ = −h(x, z)` with the conservative bound of docs/equations.md §1(b),
//! `L₁ = ρ*`, the root of `Σ √((kᵢAᵢ)² + ρ²Qᵢ²) = ρ` ([`crate::GerstnerSurface::slope_bound`]),
//! directional `L₁ |d̂_xz|`, and `−Σ Aᵢ ≤ n₁ ≤ Σ Aᵢ`. The waves cannot
//! be split into independent components: each needs the same inversion of the horizontal
//! displacement, so per-wave terms would repeat it `N` times. The height is evaluated with the
//! SIMD passes ([`GerstnerField::height_lanes`], about 1.8× faster than the scalar passes).

use brine_trace::{Aabb, LipschitzSum};
use glam::DVec3;

use crate::GerstnerField;

impl LipschitzSum for GerstnerField<'_> {
    fn component_count(&self) -> usize {
        2
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.height_lanes(p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.surface().slope_bound() }
    }

    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 { d.y.abs() } else { self.surface().slope_bound() * (d.x * d.x + d.z * d.z).sqrt() }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.surface().total_amplitude() }
    }

    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height_lanes(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        let a = self.surface().total_amplitude();
        Aabb::slab_y(-a, a)
    }

    /// With footprint fading, the faded Gerstner sum of `FadedGerstnerRay` (the waves cannot be
    /// faded one component at a time: they share the inversion); without, the two components.
    fn trace_tiered(
        &self,
        span: brine_trace::RaySpan<'_>,
        options: &brine_trace::TraceOptions,
        stats: &mut brine_trace::TraceStats,
        log: Option<&mut Vec<brine_trace::Step>>,
    ) -> Option<brine_trace::Hit> {
        let brine_trace::RaySpan { ray, t_enter, t_exit } = span;
        if options.footprint_angle > 0.0 {
            let mut tiers = FadedGerstnerRay::new(self, ray, t_exit, options.footprint_angle);
            brine_trace::trace_tiers(&mut tiers, span, options, stats, log)
        } else {
            let mut tiers = brine_trace::ComponentTiers::new(self, ray, t_enter, t_exit, 0.0);
            brine_trace::trace_tiers(&mut tiers, span, options, stats, log)
        }
    }
}

/// The faded Gerstner sum along one primary ray, as two tiers for brine-trace's tiered method:
/// tier 0 is `y`, tier 1 is `−h_w(t)(x, z)`, the Gerstner sum whose waves carry the footprint
/// weights `wᵢ(t) = smoothstep(1, 1.5, Tᵢ/t)` of the distance along the ray (amplitude and
/// steepness both scaled, so the faded sum is itself a Gerstner sum and folds no more than the
/// whole one).
///
/// Bounds from `t` on (the waves with `Tᵢ ≤ t` are gone for good): `|h_w| ≤ Σ' Aᵢ` and
/// `|d h_w/dt| ≤ L' |d̂_xz| + Σ'' |∂h/∂wᵢ| |dwᵢ/dt|` with `L'` the slope bound of the waves left
/// (that of [`crate::GerstnerSurface::slope_bound`] over them, without Newton steps; weights below 1
/// only lower it), `|∂h/∂wᵢ| ≤ Aᵢ + L' Rᵢ` (the explicit term and the shift of the rest position:
/// `J ∂u/∂wᵢ = −Dᵢ`, so `∇ᵤh·∂u/∂wᵢ = −∇ₓh·Dᵢ`, with `|Dᵢ| ≤ Rᵢ = Qᵢ/kᵢ`) and
/// `|dwᵢ/dt| ≤ FADE_SLOPE / max(t, Tᵢ/1.5)`; `Σ'` runs over the waves left, `Σ''` over those
/// still fading before the end of the segment. No curvature bound is given (first-order steps).
struct FadedGerstnerRay<'f, 'a> {
    field: &'f GerstnerField<'a>,
    ray: brine_trace::Ray,
    t_exit: f64,
    fade: Vec<f64>,
    weights: Vec<f64>,
    scratch: crate::FadedWaves,
    /// The inversion solved at the last sample: the next solve's start.
    last: Option<crate::surfaces::gerstner::WarmStart>,
}

impl<'f, 'a> FadedGerstnerRay<'f, 'a> {
    fn new(field: &'f GerstnerField<'a>, ray: &brine_trace::Ray, t_exit: f64, footprint_angle: f64) -> Self {
        let fade = field.fade_distances(ray.direction(), footprint_angle);
        let weights = vec![1.0; fade.len()];
        Self { field, ray: *ray, t_exit, fade, weights, scratch: crate::FadedWaves::default(), last: None }
    }
}

impl brine_trace::RayTiers for FadedGerstnerRay<'_, '_> {
    fn tier_count(&self) -> usize {
        2
    }

    fn bounds(&mut self, tier: usize, t: f64) -> brine_trace::TierBounds {
        let d = self.ray.direction();
        if tier == 0 {
            let (a, b) = (self.ray.at(t).y, self.ray.at(self.t_exit).y);
            return brine_trace::TierBounds::symmetric(a.min(b), a.max(b), d.y.abs(), 0.0);
        }
        let field = self.field;
        let left = self.fade.iter().enumerate().filter(|&(_, &f)| f > t).map(|(i, _)| field.wave_terms(i));
        let amplitude: f64 = left.clone().map(|(a, ..)| a).sum();
        let slope = crate::surfaces::gerstner::slope_bound_of(left.map(|(_, ka, q, _)| (ka, q)), 0);
        let mut lipschitz = slope * (d.x * d.x + d.z * d.z).sqrt();
        for (i, &f) in self.fade.iter().enumerate() {
            if f > t && f < 1.5 * self.t_exit {
                let (a, _, _, r) = self.field.wave_terms(i);
                lipschitz += (a + slope * r) * brine_trace::FADE_SLOPE / t.max(f / 1.5);
            }
        }
        brine_trace::TierBounds::symmetric(-amplitude, amplitude, lipschitz, f64::INFINITY)
    }

    fn sample(&mut self, tier: usize, t: f64) -> brine_trace::TierSample {
        if tier == 0 {
            return brine_trace::TierSample { value: self.ray.at(t).y, slope: self.ray.direction().y, terms: 1 };
        }
        let mut alive = 0;
        for (w, &f) in self.weights.iter_mut().zip(&self.fade) {
            *w = brine_trace::footprint_weight(f, t);
            alive += u32::from(*w > 0.0);
        }
        let p = self.ray.at(t);
        let (h, solved) =
            self.field.faded_height_lanes_from(p.x, p.z, &self.weights, &mut self.scratch, self.last.as_ref());
        self.last = Some(solved);
        brine_trace::TierSample { value: -h, slope: f64::NAN, terms: alive }
    }
}
