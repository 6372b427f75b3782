//! Axis-aligned boxes, possibly unbounded, used to clip rays to the region holding the zero set.

use glam::DVec3;

use crate::Ray;

/// An axis-aligned box `[min, max]`; coordinates may be infinite (a slab is a box infinite in two
/// axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub min: DVec3,
    /// Upper corner.
    pub max: DVec3,
}

impl Aabb {
    /// All of space.
    pub const EVERYTHING: Self = Self { min: DVec3::splat(f64::NEG_INFINITY), max: DVec3::splat(f64::INFINITY) };

    /// The horizontal slab `y_lo ≤ y ≤ y_hi`, unbounded in x and z.
    pub fn slab_y(y_lo: f64, y_hi: f64) -> Self {
        Self {
            min: DVec3::new(f64::NEG_INFINITY, y_lo, f64::NEG_INFINITY),
            max: DVec3::new(f64::INFINITY, y_hi, f64::INFINITY),
        }
    }

    /// The parameter interval `[t_enter, t_exit]` of `ray` inside the box, intersected with
    /// `[t_min, t_max]`; `None` if empty.
    pub fn clip(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64)> {
        let o = ray.origin();
        let d = ray.direction();
        let mut t0 = t_min;
        let mut t1 = t_max;
        for axis in 0..3 {
            let (lo, hi, oa, da) = (self.min[axis], self.max[axis], o[axis], d[axis]);
            if da == 0.0 {
                if oa < lo || oa > hi {
                    return None;
                }
                continue;
            }
            let inv = 1.0 / da;
            let (mut ta, mut tb) = ((lo - oa) * inv, (hi - oa) * inv);
            if ta > tb {
                std::mem::swap(&mut ta, &mut tb);
            }
            // NaN arises only from 0·∞ (origin on an infinite face): such an axis does not clip.
            if ta.is_finite() || ta == f64::NEG_INFINITY {
                t0 = t0.max(ta);
            }
            if tb.is_finite() || tb == f64::INFINITY {
                t1 = t1.min(tb);
            }
        }
        (t0 <= t1).then_some((t0, t1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An axis-aligned ray and faces at integer distances: `(±1 − 3)/(−1)` is exact in binary;
    /// 10⁻¹² is a rounding allowance only.
    const CLIP_ABS: f64 = 1e-12;

    #[test]
    fn slab_clip_of_a_descending_ray() {
        let slab = Aabb::slab_y(-1.0, 1.0);
        let ray = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::new(0.0, -1.0, 0.0)).unwrap();
        let (a, b) = slab.clip(&ray, 0.0, 100.0).unwrap();
        assert!((a - 2.0).abs() < CLIP_ABS && (b - 4.0).abs() < CLIP_ABS);
    }

    #[test]
    fn a_ray_parallel_to_and_outside_a_slab_misses() {
        let slab = Aabb::slab_y(-1.0, 1.0);
        let ray = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::X).unwrap();
        assert!(slab.clip(&ray, 0.0, 100.0).is_none());
    }

    #[test]
    fn an_upward_ray_above_the_slab_misses() {
        let slab = Aabb::slab_y(-1.0, 1.0);
        let ray = Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::new(1.0, 0.1, 0.0)).unwrap();
        assert!(slab.clip(&ray, 0.0, 1e9).is_none());
    }
}
