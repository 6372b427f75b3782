//! A component sum moved down: the same surface at another level.

use glam::DVec3;

use crate::{Aabb, LipschitzSum};

/// `G(p) = F(p + (0, depth, 0))`: the zero set of `F` moved down by `depth` (a sea floor shaped
/// like a wave field, `y = −depth + h(x, z)`). Translation keeps every Lipschitz constant and
/// bound of `F`, so `G` traces as certifiably as `F`.
///
/// # References
/// Hart 1996, §2 (Lipschitz constants are invariant under translation).
#[derive(Debug, Clone, Copy)]
pub struct Lowered<'a, S> {
    inner: &'a S,
    depth: f64,
}

impl<'a, S: LipschitzSum> Lowered<'a, S> {
    /// `inner` moved down by `depth` (m, finite; negative moves it up).
    pub fn new(inner: &'a S, depth: f64) -> Self {
        debug_assert!(depth.is_finite());
        Self { inner, depth }
    }
}

impl<S: LipschitzSum> LipschitzSum for Lowered<'_, S> {
    fn component_count(&self) -> usize {
        self.inner.component_count()
    }
    fn component(&self, i: usize, p: DVec3) -> f64 {
        self.inner.component(i, p + DVec3::Y * self.depth)
    }
    fn component_lipschitz(&self, i: usize) -> f64 {
        self.inner.component_lipschitz(i)
    }
    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        self.inner.component_min(i, a + DVec3::Y * self.depth, b + DVec3::Y * self.depth)
    }
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        self.inner.component_directional_lipschitz(i, d)
    }
    fn value(&self, p: DVec3) -> f64 {
        self.inner.value(p + DVec3::Y * self.depth)
    }
    fn zero_set_bounds(&self) -> Aabb {
        let b = self.inner.zero_set_bounds();
        Aabb { min: b.min - DVec3::Y * self.depth, max: b.max - DVec3::Y * self.depth }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Method, Ray, TraceOptions, TraceStats, trace};

    /// `F(p) = y − a sin(kx)`.
    struct Sine;

    impl LipschitzSum for Sine {
        fn component_count(&self) -> usize {
            2
        }
        fn component(&self, i: usize, p: DVec3) -> f64 {
            if i == 0 { p.y } else { -0.5 * (0.8 * p.x).sin() }
        }
        fn component_lipschitz(&self, i: usize) -> f64 {
            if i == 0 { 1.0 } else { 0.4 }
        }
        fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
            if i == 0 { a.y.min(b.y) } else { -0.5 }
        }
        fn zero_set_bounds(&self) -> Aabb {
            Aabb::slab_y(-0.5, 0.5)
        }
    }

    /// The lowered surface's hit is the surface's hit moved down (to the tracer's tolerance).
    #[test]
    fn a_lowered_surface_is_hit_lower_down() {
        let (s, depth) = (Sine, 7.0);
        let lowered = Lowered::new(&s, depth);
        let o = TraceOptions { method: Method::Directional, ..TraceOptions::default() };
        let ray = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::new(1.0, -0.4, 0.2).normalize()).unwrap();
        let hit = trace(&lowered, &ray, &o, &mut TraceStats::default()).unwrap();
        // On the surface y = −depth + 0.5 sin(0.8 x).
        assert!((hit.point.y - (-depth + 0.5 * (0.8 * hit.point.x).sin())).abs() < 1e-5, "{hit:?}");
        let b = lowered.zero_set_bounds();
        assert!((b.min.y + depth + 0.5).abs() < 1e-12 && (b.max.y + depth - 0.5).abs() < 1e-12);
    }
}
