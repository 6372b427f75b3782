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

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.sum.total_amplitude, self.sum.total_amplitude)
    }
}
