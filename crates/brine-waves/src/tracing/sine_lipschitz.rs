//! The sine-wave surface as a [`brine_trace::LipschitzSum`].
//!
//! `F(p) = y − Σᵢ Aᵢ cos(kᵢ·(x, z) + offᵢ)`: component 0 is `n₀ = y` (`L₀ = 1`, directional
//! `|d̂_y|`), component `i ≥ 1` is `nᵢ = −A_{i−1} cos(…)` with `Lᵢ = kA` (Hart 1996:
//! `Lip(A sin(k·x)) = A‖k‖`), directional `kA |k̂·d̂_xz|`, and `−A ≤ nᵢ ≤ A`. The detail waves
//! only shade and are not traced.

use brine_trace::{Aabb, LipschitzSum};
use glam::DVec3;

use crate::SineField;

impl LipschitzSum for SineField<'_> {
    fn component_count(&self) -> usize {
        self.len() + 1
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.wave_height(i - 1, p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 {
            1.0
        } else {
            let (a, kx, kz) = self.wave(i - 1);
            a * (kx * kx + kz * kz).sqrt()
        }
    }

    /// Along `d̂`, `nᵢ(p + t d̂) = −A cos(k·p_xz + t k·d̂_xz + off)`, whose rate is at most
    /// `A |k·d̂_xz|`.
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            d.y.abs()
        } else {
            let (a, kx, kz) = self.wave(i - 1);
            a * (kx * d.x + kz * d.z).abs()
        }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.wave(i - 1).0 }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { self.wave(i - 1).0 }
    }

    /// `d nᵢ/dt = Aᵢ sin(kᵢ·p_xz + offᵢ) (kᵢ·d̂_xz)` (and `d̂_y` for `n₀ = y`).
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        if i == 0 {
            return Some(d.y);
        }
        let (a, kx, kz) = self.wave(i - 1);
        Some(a * self.wave_phase(i - 1, p.x, p.z).sin() * (kx * d.x + kz * d.z))
    }

    /// `|d² nᵢ/dt²| ≤ Aᵢ (kᵢ·d̂_xz)²` (0 for the plane `n₀ = y`).
    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return 0.0;
        }
        let (a, kx, kz) = self.wave(i - 1);
        let s = kx * d.x + kz * d.z;
        a * s * s
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 {
            f64::INFINITY
        } else {
            let (_, kx, kz) = self.wave(i - 1);
            std::f64::consts::TAU / (kx * kx + kz * kz).sqrt()
        }
    }

    /// `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²))`, `σᵢ = kᵢ·d̂_xz`: the rule of the trochoid tracer.
    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 {
            return f64::INFINITY;
        }
        let (_, kx, kz) = self.wave(i - 1);
        crate::tracing::fade::wave_fade_distance(kx, kz, d, footprint_angle)
    }

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height_lanes(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        let a = self.set().total_amplitude;
        Aabb::slab_y(-a, a)
    }
}
