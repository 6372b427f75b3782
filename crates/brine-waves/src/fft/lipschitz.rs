//! The FFT ocean frame as a [`brine_trace::LipschitzSum`], with one tier per cascade for the
//! tiered method.
//!
//! `F(p) = y − Σ_c s_c(x, z)`: component 0 is `n₀ = y` (`L₀ = 1`, directional `|d_y|`, no
//! curvature), component `c + 1` is `−s_c(x, z)`, cascade `c`'s cubic B-spline, with the certified
//! bounds of [`crate::FftCascade`]: `L = √(a² + b²)`, directional `a|dₓ| + b|d_z|`, curvature
//! `A dₓ² + 2C|dₓd_z| + B d_z²`, `−max c ≤ n ≤ −min c`, and its exact derivative along a ray.

use std::cell::RefCell;

use crate::tracing::tiered_fast_path;
use brine_trace::{
    Aabb, FADE_CURVATURE, FADE_SLOPE, LipschitzSum, Ray, RayTiers, TierBounds, TierSample, TierScratch,
    footprint_weight, footprint_weight_slope,
};
use glam::DVec3;

use crate::FftFrame;

/// Relative bound (of the summed cascade height bounds) of the rounding of one f64 evaluation of
/// the cascades' cubic B-splines: each is 16 non-negative weights summing to 1 times coefficients
/// within the cascade's height bound, so about 20 roundings of terms below it (~2×10⁻¹⁵), with
/// margin.
const EVALUATION_ROUNDING: f64 = 1e-14;

impl LipschitzSum for FftFrame {
    fn component_count(&self) -> usize {
        self.cascade_count() + 1
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.cascade(i - 1).height(p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.cascade(i - 1).max_slope() }
    }

    /// `|d_y|` for `y`; `a|dₓ| + b|d_z|` for a cascade.
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 { d.y.abs() } else { self.cascade(i - 1).directional_max_slope(d.x, d.z) }
    }

    /// `d_y` for `y`; `−∇s·(dₓ, d_z)` for a cascade (the spline's exact derivative).
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        if i == 0 {
            return Some(d.y);
        }
        Some(-self.cascade(i - 1).height_and_derivative(p.x, p.z, d.x, d.z).1)
    }

    /// 0 for `y`; `A dₓ² + 2C|dₓd_z| + B d_z²` for a cascade.
    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 { 0.0 } else { self.cascade(i - 1).directional_curvature(d.x, d.z) }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.cascade(i - 1).height_bounds().1 }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { -self.cascade(i - 1).height_bounds().0 }
    }

    /// The longest wavelength of the cascade; `y` has none.
    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { self.cascade(i - 1).longest_wavelength() }
    }

    fn component_fade_distance(&self, i: usize, direction: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 { f64::INFINITY } else { self.cascade(i - 1).fade_distance(direction, footprint_angle) }
    }

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        let (lo, hi) = self.height_bounds();
        Aabb::slab_y(lo, hi)
    }

    // Cones need a surface that bounds every ray of the cone from below: with footprint fading
    // (weights that differ from ray to ray) a cascade that fades for some ray of the cone before
    // the cone's end is held at its lower bound `min(0, −max H)` (that of `w·n` for any weight
    // `w ∈ [0, 1]`), the others are used whole; as for the trochoids, a downward cone then
    // certifies at most `CONE_REACH` times where it starts or meets the slab (`cone_span`).
    tiered_fast_path!(SCRATCH, CascadeTiers, |f: &FftFrame| f.height_bounds().1);
}

thread_local! {
    static SCRATCH: RefCell<(TierScratch, Vec<CascadeOnRay>)> = RefCell::new((TierScratch::default(), Vec::new()));
}

/// One cascade along one ray.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CascadeOnRay {
    cascade: usize,
    /// `−max H`, `−min H`.
    min: f64,
    max: f64,
    /// Directional slope bound along the ray.
    lipschitz: f64,
    /// Directional curvature bound along the ray.
    curvature: f64,
    /// 3-D slope bound (cones).
    spread: f64,
    /// Fade distance `T` (m), `+∞` without fading.
    fade: f64,
    /// Cone mode: the cascade fades for some ray of the cone before the end and is held at its
    /// lower bound `min` (then `min = max`, no slope, no curvature, no spread).
    held: bool,
}

/// [`RayTiers`] of an [`FftFrame`] along one ray: tier 0 is `y`, then one tier per cascade, in
/// decreasing order of `(max − min)/L(d̂)` (the longest cascades first: far from the surface only
/// they are evaluated).
pub(crate) struct CascadeTiers<'a> {
    frame: &'a FftFrame,
    cascades: &'a [CascadeOnRay],
    origin: DVec3,
    direction: DVec3,
    t_exit: f64,
    error: f64,
}

impl<'a> CascadeTiers<'a> {
    /// The tiers along `ray` up to `t_exit`, faded for a pixel of `footprint_angle` rad; with
    /// `cone > 0`, tiers that bound every ray within `cone` rad of `ray` (see
    /// [`FftFrame::certify_cone`]).
    pub(crate) fn new(
        frame: &'a FftFrame,
        state: &'a mut Vec<CascadeOnRay>,
        ray: &Ray,
        t_exit: f64,
        footprint_angle: f64,
        cone: f64,
    ) -> Self {
        let d = ray.direction();
        state.clear();
        let mut size = 0.0f64;
        for (c, cascade) in frame.cascades().iter().enumerate() {
            let (lo, hi) = cascade.height_bounds();
            size += lo.abs().max(hi.abs());
            let mut on_ray = CascadeOnRay {
                cascade: c,
                min: -hi,
                max: -lo,
                lipschitz: cascade.directional_max_slope(d.x, d.z),
                curvature: cascade.directional_curvature(d.x, d.z),
                spread: cascade.max_slope(),
                fade: if footprint_angle > 0.0 { cascade.fade_distance(d, footprint_angle) } else { f64::INFINITY },
                held: false,
            };
            if cone > 0.0 && footprint_angle > 0.0 {
                // T grows with |d_y|, which is at least |d_y| − θ within the cone.
                let lowest = DVec3::new(0.0, (d.y.abs() - cone).max(0.0), 0.0);
                if cascade.fade_distance(lowest, footprint_angle) < 1.5 * t_exit {
                    let v = on_ray.min.min(0.0);
                    on_ray = CascadeOnRay {
                        min: v,
                        max: v,
                        lipschitz: 0.0,
                        curvature: 0.0,
                        spread: 0.0,
                        held: true,
                        ..on_ray
                    };
                }
                // Used whole (w = 1 on the interval for every ray of the cone) or held.
                on_ray.fade = f64::INFINITY;
            }
            state.push(on_ray);
        }
        let key = |c: &CascadeOnRay| if c.lipschitz > 0.0 { (c.max - c.min) / c.lipschitz } else { f64::INFINITY };
        state.sort_by(|a, b| key(b).total_cmp(&key(a)));
        Self { frame, cascades: state, origin: ray.origin(), direction: d, t_exit, error: EVALUATION_ROUNDING * size }
    }
}

impl RayTiers for CascadeTiers<'_> {
    fn tier_count(&self) -> usize {
        self.cascades.len() + 1
    }

    fn bounds(&mut self, tier: usize, t: f64) -> TierBounds {
        if tier == 0 {
            let (y0, y1) = (self.origin.y + self.direction.y * t, self.origin.y + self.direction.y * self.t_exit);
            return TierBounds::symmetric(y0.min(y1), y0.max(y1), self.direction.y.abs(), 0.0);
        }
        let c = self.cascades[tier - 1];
        if c.fade <= t {
            return TierBounds::ZERO; // faded out for good
        }
        if c.fade >= 1.5 * self.t_exit {
            return TierBounds::symmetric(c.min, c.max, c.lipschitz, c.curvature);
        }
        // w·n with w ∈ [0, 1] non-increasing (brine-trace footprint.rs): |(wn)'| ≤ L + |w'| size,
        // |(wn)''| ≤ K + 2|w'| L + |w''| size, |w'| ≤ 4.5/t and |w''| ≤ 63/t² while fading.
        let size = c.min.abs().max(c.max.abs());
        let tt = t.max(c.fade / 1.5);
        TierBounds::symmetric(
            c.min.min(0.0),
            c.max.max(0.0),
            c.lipschitz + FADE_SLOPE * size / tt,
            c.curvature + 2.0 * FADE_SLOPE * c.lipschitz / tt + FADE_CURVATURE * size / (tt * tt),
        )
    }

    fn sample(&mut self, tier: usize, t: f64) -> TierSample {
        if tier == 0 {
            return TierSample { value: self.origin.y + self.direction.y * t, slope: self.direction.y, terms: 0 };
        }
        let c = self.cascades[tier - 1];
        if c.held {
            return TierSample { value: c.min, slope: 0.0, terms: 0 };
        }
        let w = footprint_weight(c.fade, t);
        if w == 0.0 {
            return TierSample { value: 0.0, slope: 0.0, terms: 0 };
        }
        let p = self.origin + t * self.direction;
        let d = self.direction;
        let (h, dh) = self.frame.cascade(c.cascade).height_and_derivative(p.x, p.z, d.x, d.z);
        // n = −w h;  dn/dt = −(w' h + w dh/dt).
        TierSample { value: -w * h, slope: -(footprint_weight_slope(c.fade, t) * h + w * dh), terms: 1 }
    }

    fn spread_lipschitz(&self, tier: usize) -> f64 {
        if tier == 0 { 1.0 } else { self.cascades[tier - 1].spread }
    }

    fn error_bound(&self) -> f64 {
        self.error
    }
}
