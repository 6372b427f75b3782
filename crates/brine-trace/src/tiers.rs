//! A sum restricted to one ray and split into tiers: the input of the tiered method.

use glam::DVec3;

use crate::footprint::{FADE_CURVATURE, FADE_SLOPE, footprint_weight, footprint_weight_slope};
use crate::{LipschitzSum, Ray};

/// Bounds of one tier (a group of components, including their fade weights) along a ray, valid
/// for every `t` from the point where they were asked for to the end of the traced interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TierBounds {
    /// Lower bound of the tier's sum.
    pub min: f64,
    /// Upper bound of the tier's sum (may be `+∞`).
    pub max: f64,
    /// Bound of its derivative along the ray, `|d/dt|` (per metre).
    pub lipschitz: f64,
    /// Bound of its second derivative along the ray, `|d²/dt²|` (per metre²), `+∞` if unknown.
    pub curvature: f64,
    /// One-sided bound `d²/dt² ≥ −concavity` (per metre², `0 ≤ concavity ≤ curvature`): how
    /// concave the tier can be. It alone limits a certified step toward a crossing from the
    /// positive side (a lower bound of the sum needs only the lower bound of its second
    /// derivative); a trochoid's sharp crest is convex in `F = y − h`, so there it is much smaller
    /// than `curvature` (brine-waves `TracedTrochoids`). Set it to `curvature` when no better
    /// one-sided bound is known.
    pub concavity: f64,
}

impl TierBounds {
    /// A tier that is identically zero (e.g. faded out).
    pub const ZERO: Self = Self { min: 0.0, max: 0.0, lipschitz: 0.0, curvature: 0.0, concavity: 0.0 };

    /// Bounds with the same second-derivative bound on both sides (`concavity = curvature`).
    ///
    /// # Arguments
    /// - `min`, `max`: bounds of the tier's sum (m, or the unit of `F`), `min ≤ max`.
    /// - `lipschitz`: bound of `|d/dt|` along the ray (per metre), `≥ 0`.
    /// - `curvature`: bound of `|d²/dt²|` (per metre²), `≥ 0`, `+∞` if unknown.
    pub const fn symmetric(min: f64, max: f64, lipschitz: f64, curvature: f64) -> Self {
        Self { min, max, lipschitz, curvature, concavity: curvature }
    }
}

/// A tier evaluated at one point of the ray.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TierSample {
    /// The tier's sum at `t`.
    pub value: f64,
    /// Its derivative along the ray at `t`; `NaN` if unknown.
    pub slope: f64,
    /// Number of single-component evaluations spent (for [`crate::TraceStats`]).
    pub terms: u32,
}

/// `F` restricted to one ray `t ↦ F(o + t d̂)`, split into tiers `F = Σⱼ Tⱼ` ordered by decreasing
/// length scale (tier 0 first): what [`crate::trace_tiers`] steps on.
///
/// Implementors guarantee that [`bounds`](Self::bounds) hold for the exact tier sums and that
/// [`sample`](Self::sample) differs from them by at most [`error_bound`](Self::error_bound) in
/// total (value) and [`slope_error_bound`](Self::slope_error_bound) (derivative). The order is a
/// cost hint only; any order is safe.
pub trait RayTiers {
    /// Number of tiers.
    fn tier_count(&self) -> usize;

    /// Bounds of tier `tier` valid for all `t' ∈ [t, t_exit]`.
    fn bounds(&mut self, tier: usize, t: f64) -> TierBounds;

    /// Tier `tier` evaluated at `t`.
    fn sample(&mut self, tier: usize, t: f64) -> TierSample;

    /// A bound of `|Tⱼ(q) − Tⱼ(p)|/‖q − p‖` for any two points (the tier's 3D Lipschitz constant),
    /// used by the cone of [`crate::certify_cone_with`]; `+∞` (the default) disables cones.
    fn spread_lipschitz(&self, tier: usize) -> f64 {
        let _ = tier;
        f64::INFINITY
    }

    /// Bound of `|Σⱼ sampleⱼ − F|` at any `t` (0 for an exact evaluator).
    fn error_bound(&self) -> f64 {
        0.0
    }

    /// Bound of the error of `Σⱼ slopeⱼ` at any `t`.
    fn slope_error_bound(&self) -> f64 {
        0.0
    }
}

/// Up to this many components per tier in [`ComponentTiers`].
pub const COMPONENTS_PER_TIER: usize = 8;

/// Per-component data of [`ComponentTiers`] along one ray.
#[derive(Debug, Clone, Copy)]
struct ComponentOnRay {
    index: usize,
    min: f64,
    max: f64,
    lipschitz: f64,
    curvature: f64,
    fade_distance: f64,
}

/// The generic [`RayTiers`] of any [`LipschitzSum`]: components sorted by decreasing
/// `(Mᵢ − mᵢ)/Lᵢ(d̂)` over the traced segment (the key of Darles' Algorithm 1 at its largest),
/// grouped by [`COMPONENTS_PER_TIER`], evaluated with [`LipschitzSum::component`] and
/// [`LipschitzSum::component_directional_derivative`], each weighted by its footprint fade.
pub struct ComponentTiers<'a, S: LipschitzSum + ?Sized> {
    surface: &'a S,
    ray: Ray,
    t_exit: f64,
    fading: bool,
    components: Vec<ComponentOnRay>,
}

impl<'a, S: LipschitzSum + ?Sized> ComponentTiers<'a, S> {
    /// The tiers of `surface` along `ray` on `[t_enter, t_exit]`, with fading for a pixel of
    /// `footprint_angle` rad (0: none).
    pub fn new(surface: &'a S, ray: &Ray, t_enter: f64, t_exit: f64, footprint_angle: f64) -> Self {
        let d = ray.direction();
        let (a, b) = (ray.at(t_enter), ray.at(t_exit));
        let mut components: Vec<ComponentOnRay> = (0..surface.component_count())
            .map(|i| ComponentOnRay {
                index: i,
                min: surface.component_min(i, a, b),
                max: surface.component_max(i, a, b),
                lipschitz: surface.component_directional_lipschitz(i, d),
                curvature: surface.component_directional_curvature(i, d),
                fade_distance: if footprint_angle > 0.0 {
                    surface.component_fade_distance(i, d, footprint_angle)
                } else {
                    f64::INFINITY
                },
            })
            .collect();
        let key = |c: &ComponentOnRay| {
            if c.lipschitz > 0.0 { (c.max - c.min) / c.lipschitz } else { f64::INFINITY }
        };
        components.sort_by(|x, y| key(y).total_cmp(&key(x)));
        Self { surface, ray: *ray, t_exit, fading: footprint_angle > 0.0, components }
    }

    fn tier(&self, tier: usize) -> &[ComponentOnRay] {
        let lo = tier * COMPONENTS_PER_TIER;
        &self.components[lo..(lo + COMPONENTS_PER_TIER).min(self.components.len())]
    }
}

impl<S: LipschitzSum + ?Sized> RayTiers for ComponentTiers<'_, S> {
    fn tier_count(&self) -> usize {
        self.components.len().div_ceil(COMPONENTS_PER_TIER)
    }

    fn bounds(&mut self, tier: usize, t: f64) -> TierBounds {
        let mut b = TierBounds::ZERO;
        for c in self.tier(tier) {
            if c.fade_distance <= t {
                continue; // faded out for good: contributes 0 from here on
            }
            if c.fade_distance >= 1.5 * self.t_exit {
                b.min += c.min;
                b.max += c.max;
                b.lipschitz += c.lipschitz;
                b.curvature += c.curvature;
                b.concavity += c.curvature;
            } else {
                // w·n with w ∈ [0, 1] falling: bounds of the product (footprint.rs constants).
                let size = c.min.abs().max(c.max.abs());
                let tt = t.max(c.fade_distance / 1.5);
                b.min += c.min.min(0.0);
                b.max += c.max.max(0.0);
                b.lipschitz += c.lipschitz + FADE_SLOPE * size / tt;
                let k = c.curvature + 2.0 * FADE_SLOPE * c.lipschitz / tt + FADE_CURVATURE * size / (tt * tt);
                b.curvature += k;
                b.concavity += k;
            }
        }
        b
    }

    /// `Σ Lᵢ` over the tier (not available with footprint fading: the weights differ per ray).
    fn spread_lipschitz(&self, tier: usize) -> f64 {
        if self.fading {
            return f64::INFINITY;
        }
        self.tier(tier).iter().map(|c| self.surface.component_lipschitz(c.index)).sum()
    }

    fn sample(&mut self, tier: usize, t: f64) -> TierSample {
        let p: DVec3 = self.ray.at(t);
        let d = self.ray.direction();
        let mut out = TierSample { value: 0.0, slope: 0.0, terms: 0 };
        let lo = tier * COMPONENTS_PER_TIER;
        let hi = (lo + COMPONENTS_PER_TIER).min(self.components.len());
        for c in &self.components[lo..hi] {
            let w = footprint_weight(c.fade_distance, t);
            if w == 0.0 {
                continue;
            }
            let v = self.surface.component(c.index, p);
            let dv = self.surface.component_directional_derivative(c.index, p, d).unwrap_or(f64::NAN);
            out.value += w * v;
            out.slope += w * dv + footprint_weight_slope(c.fade_distance, t) * v;
            out.terms += 1;
        }
        out
    }
}
