//! The trochoid-sum surface as a [`brine_trace::LipschitzSum`].
//!
//! `F(p) = y − Σᵢ hᵢ(x, z)`: component 0 is `n₀ = y` (`L₀ = 1`), component `i ≥ 1` is
//! `nᵢ = −h_{i−1}(x, z)` with `Lᵢ = kA/√(1 − Q²)` and `−A ≤ nᵢ ≤ A` (docs/equations.md §1(a)).

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

    /// `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²))`, `σᵢ = kᵢ d̂ᵢ·d̂_xz`: the pixel footprint on the sea is `αt`
    /// across the view and `αt/max(|d_y|, 0.05)` along it, so its extent along the wave direction `d̂ᵢ` is
    /// `αt √(1 + (d̂ᵢ·d̂_xz)²/max(|d_y|, 0.05)²)` (the same rule as [`crate::TracedTrochoids`]).
    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 {
            return f64::INFINITY;
        }
        let s = &self.sum;
        let (k, sigma) = (s.wavenumber[i - 1], s.kx[i - 1] * d.x + s.kz[i - 1] * d.z);
        std::f64::consts::TAU
            / (footprint_angle * (k * k + sigma * sigma * brine_core::footprint::footprint_stretch_squared(d.y)).sqrt())
    }

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.sum.total_amplitude, self.sum.total_amplitude)
    }
}

#[cfg(test)]
mod tests {
    use brine_trace::LipschitzSum;
    use glam::DVec3;
    use proptest::prelude::*;

    use crate::{TracedTrochoids, Trochoid, TrochoidSet, TrochoidSum};

    fn set(seed: u64, n: usize) -> TrochoidSet {
        let waves = (0..n)
            .map(|i| {
                let x = (seed as f64 * 0.618 + i as f64 * 0.377).fract();
                let k = 0.05 * 200f64.powf(x);
                let q = (0.99 * (i as f64 * 0.731 + seed as f64 * 0.1).fract()).min(0.99);
                Trochoid::new(0.3 * x / k, k, 6.0 * x, (9.81 * k).sqrt(), 2.0 * i as f64, q).unwrap()
            })
            .collect();
        TrochoidSet::new(waves)
    }

    /// Rounding slack of a Lipschitz or bound comparison of f64 sums of up to 40 terms below 3 m.
    const SLACK_REL: f64 = 1e-9;
    const SLACK_ABS: f64 = 1e-12;

    /// Central-difference step (m) along the ray, and the derivative's tolerance relative to
    /// `1 + |∂|`: the f32 kernel's derivative against the f64 difference (f32 rounding ~10⁻⁶ of
    /// the slope scale, difference rounding `10⁻¹⁶·3/h` = 3×10⁻¹²), plus the mean-value term
    /// `K h` added in the test.
    const FD_STEP: f64 = 1e-4;
    const DERIVATIVE_REL: f64 = 1e-4;

    /// The second difference against the curvature bound `K`: its rounding `4ε·3 m/h²` ≈
    /// 1.3×10⁻⁷ (covered by the absolute part) and its truncation `h²|n⁗|/12` ≲ `K h²k²/12` ≈
    /// 10⁻⁷ `K` for `k ≤ 10` rad/m (covered by the relative part).
    const CURVATURE_REL: f64 = 1e-3;
    const CURVATURE_ABS: f64 = 1e-5;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

        /// The per-component contract of `LipschitzSum` on random points, for the exact field and
        /// the fast one: Lipschitz (3D and directional), bounds, the f32 derivative against a
        /// central difference of the f64 component, and the curvature bound.
        #[test]
        fn component_bounds_hold_on_random_points(
            seed in 0u64..1000, n in 1usize..40,
            px in -100.0f64..100.0, pz in -100.0f64..100.0, py in -3.0f64..3.0,
            dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0, step in 1e-3f64..5.0,
        ) {
            let set = set(seed, n);
            let sum = TrochoidSum::new(&set);
            let exact = sum.at_time(0.3);
            let fast = TracedTrochoids::new(&set, 0.3);
            let d = DVec3::new(dx, dy, dz).normalize_or(DVec3::X);
            let p = DVec3::new(px, py, pz);
            let q = p + step * d;
            let eps = fast.error_bound();
            prop_assert_eq!(exact.component_count(), fast.component_count());
            for i in 0..exact.component_count() {
                let (np, nq) = (exact.component(i, p), exact.component(i, q));
                let l = exact.component_lipschitz(i);
                prop_assert!((np - nq).abs() <= l * step * (1.0 + SLACK_REL) + SLACK_ABS, "component {i}: Lipschitz");
                let ld = exact.component_directional_lipschitz(i, d);
                prop_assert!((np - nq).abs() <= ld * step * (1.0 + SLACK_REL) + SLACK_ABS, "component {i}: directional");
                prop_assert!(ld <= l * (1.0 + SLACK_ABS));
                prop_assert!(np >= exact.component_min(i, p, q) - SLACK_ABS && np <= exact.component_max(i, p, q) + SLACK_ABS);
                prop_assert!((fast.component(i, p) - np).abs() <= eps, "component {i}: fast vs exact");
                prop_assert!((fast.component_lipschitz(i) - l).abs() <= SLACK_ABS * (1.0 + l));
                prop_assert!((fast.component_feature_size(i) - exact.component_feature_size(i)).abs() <= SLACK_REL || i == 0);
                let (tf, te) = (fast.component_fade_distance(i, d, 0.003), exact.component_fade_distance(i, d, 0.003));
                prop_assert!(i == 0 || (tf - te).abs() <= SLACK_REL * te, "component {i}: fade distance {tf} vs {te}");
                // Derivative and curvature along d (central differences of the f64 component).
                let h = FD_STEP;
                let fd = (exact.component(i, p + h * d) - exact.component(i, p - h * d)) / (2.0 * h);
                let derivative = fast.component_directional_derivative(i, p, d).unwrap();
                let k = fast.component_directional_curvature(i, d);
                prop_assert!((derivative - fd).abs() <= DERIVATIVE_REL * (1.0 + fd.abs()) + k * h, "component {i}: derivative {derivative} vs {fd}");
                let second = (exact.component(i, p + h * d) - 2.0 * np + exact.component(i, p - h * d)) / (h * h);
                prop_assert!(second.abs() <= k * (1.0 + CURVATURE_REL) + CURVATURE_ABS, "component {i}: curvature {second} > {k}");
            }
        }
    }
}
