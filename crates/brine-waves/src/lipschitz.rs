//! The trochoid-sum surface as a [`brine_trace::LipschitzSum`].
//!
//! `F(p) = y − Σᵢ hᵢ(x, z)`: component 0 is `n₀ = y` (`L₀ = 1`), component `i ≥ 1` is
//! `nᵢ = −h_{i−1}(x, z)` with `Lᵢ = kA/√(1 − Q²)` and `−A ≤ nᵢ ≤ A` (equation sheet §1(a)).

use brine_trace::{Aabb, LipschitzSum};
use glam::DVec3;

use crate::TrochoidField;

impl LipschitzSum for TrochoidField<'_> {
    fn component_count(&self) -> usize {
        self.sum.len() + 1
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.wave_height(i - 1, p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.sum.max_slope[i - 1] }
    }

    /// Along `d̂`, `d nᵢ/dt = −hᵢ'(s) kᵢ (k̂ᵢ·d̂_xz)`, bounded by `Lᵢ |k̂ᵢ·d̂_xz|`; `n₀` changes at
    /// rate `|d̂_y|`.
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            d.y.abs()
        } else {
            let j = i - 1;
            let s = &self.sum;
            s.max_slope[j] * (s.kx[j] * d.x + s.kz[j] * d.z).abs() / s.wavenumber[j]
        }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.sum.amplitude[i - 1] }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { self.sum.amplitude[i - 1] }
    }

    /// The wavelength `2π/kᵢ` of a wave; `y` has none.
    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { std::f64::consts::TAU / self.sum.wavenumber[i - 1] }
    }

    /// `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/d_y²))`, `σᵢ = kᵢ d̂ᵢ·d̂_xz`: the pixel footprint on the sea is `αt`
    /// across the view and `αt/|d_y|` along it, so its extent along the wave direction `d̂ᵢ` is
    /// `αt √(1 + (d̂ᵢ·d̂_xz)²/d_y²)` (the same rule as [`crate::TracedTrochoids`]).
    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 {
            return f64::INFINITY;
        }
        let s = &self.sum;
        let (k, sigma) = (s.wavenumber[i - 1], s.kx[i - 1] * d.x + s.kz[i - 1] * d.z);
        std::f64::consts::TAU / (footprint_angle * (k * k + sigma * sigma / (d.y * d.y).max(1e-300)).sqrt())
    }

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.sum.total_amplitude, self.sum.total_amplitude)
    }
}
