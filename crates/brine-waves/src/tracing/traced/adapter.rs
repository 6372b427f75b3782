//! The trochoid sea as the tracer sees it: [`LipschitzSum`] for [`TracedTrochoids`], its tiers
//! along a ray (feature `tracing`).

use std::cell::RefCell;

use brine_trace::{Aabb, LipschitzSum, RaySpan, TierScratch};
use glam::DVec3;

use super::TracedTrochoids;
use super::tiers::*;
use crate::tracing::fast_profile::profile1;

thread_local! {
    static SCRATCH: RefCell<(TierScratch, RayState)> = RefCell::new((TierScratch::default(), RayState::default()));
}

/// How far a downward cone of primary rays with footprint fading certifies, as a multiple of where
/// it starts (or enters the slab `|y| ≤ ΣA`, or 1 m): waves that fade for some ray of the cone
/// before `1.5×` that end are held at `−A`, so the shorter the cone's reach the fewer are held.
/// Measured on the bench frame (640×480, N = 100, every phenomenon, 16 × 16 tiles):
/// evaluations per frame 1.446 M without a limit, 1.581 M at 1.1, 1.307 M at 1.25, 1.141 M at
/// 1.4, **1.136 M at 1.5**, 1.137 M at 1.75, 1.139 M at 2, 1.157 M at 4, 1.193 M at 8.
pub(crate) const CONE_REACH: f64 = 1.5;

/// The part of `span` a cone of primary rays around it certifies: with footprint fading
/// (`footprint_angle > 0`) a downward cone ends at [`CONE_REACH`] times where it starts or meets
/// the slab below `top` (m), or 1 m, whichever is farthest; otherwise the whole span.
pub(crate) fn cone_span(span: RaySpan<'_>, top: f64, footprint_angle: f64) -> RaySpan<'_> {
    let RaySpan { ray, t_enter, t_exit } = span;
    let (o, d) = (ray.origin(), ray.direction());
    if footprint_angle > 0.0 && d.y < 0.0 {
        let slab = if o.y > top { (o.y - top) / -d.y } else { 0.0 };
        RaySpan::new(ray, t_enter, t_exit.min(CONE_REACH * t_enter.max(slab).max(1.0)))
    } else {
        span
    }
}

impl LipschitzSum for TracedTrochoids {
    fn component_count(&self) -> usize {
        self.waves.len() + 1
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.wave_height_fast(i - 1, p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.waves[i - 1].0.max_slope() }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.waves[i - 1].0.amplitude() }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { self.waves[i - 1].0.amplitude() }
    }

    /// `Lᵢ |k̂ᵢ·d̂_xz|` for a wave, `|d_y|` for `y`.
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return d.y.abs();
        }
        let w = &self.waves[i - 1].0;
        let k = w.direction_vector();
        w.max_slope() * (k.x * d.x + k.y * d.z).abs()
    }

    /// `d(−A cos θ)/dt = A sin θ/(1 − Q cos θ) · σ`, `σ = k d̂ᵢ·d̂_xz` (f32 kernel).
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        if i == 0 {
            return Some(d.y);
        }
        let (tier, lane) = self.lane_of_wave[i - 1];
        let t = &self.tiers[tier];
        let (_, g) =
            profile1(t.kx[lane] * p.x + t.kz[lane] * p.z + t.offset[lane], t.steepness[lane], &t.series, lane, t.mode);
        let sigma = t.kx[lane] * d.x + t.kz[lane] * d.z;
        Some(f64::from(t.amplitude[lane]) * f64::from(g) * sigma)
    }

    /// `A σ²/(1 − Q)²`: `|τ''_Q| = |Q − cos θ|/(1 − Q cos θ)³ ≤ 1/(1 − Q)²` (at the crest).
    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return 0.0;
        }
        let w = &self.waves[i - 1].0;
        let sigma = w.wavenumber() * (w.direction_vector().x * d.x + w.direction_vector().y * d.z);
        w.amplitude() * sigma * sigma / ((1.0 - w.steepness()).powi(2))
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { self.waves[i - 1].0.wavelength() }
    }

    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        self.fade_distance(i, d, footprint_angle)
    }

    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.total_amplitude, self.total_amplitude)
    }

    // With fading, a wave that fades for some ray of the cone before the cone's end is held at
    // −A: a downward cone certifies only up to CONE_REACH times where it starts or meets the
    // slab, so that the waves fading beyond are used whole; its children go on from there.
    tiered_fast_path!(SCRATCH, SeaTiers, |s: &TracedTrochoids| s.total_amplitude);
}
