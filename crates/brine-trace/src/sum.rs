//! The component-sum abstraction.

use glam::DVec3;

use crate::Aabb;

/// An implicit function `F(p) = Σᵢ nᵢ(p)` of `N` bounded, Lipschitz-continuous components.
///
/// The surface is the zero set `F(p) = 0`. Implementors must guarantee, for every component `i`
/// and all points `p`, `q`:
///
/// - `|nᵢ(p) − nᵢ(q)| ≤ Lᵢ ‖p − q‖` with `Lᵢ` = [`component_lipschitz`](Self::component_lipschitz);
/// - `|nᵢ(p + t d̂) − nᵢ(p)| ≤ Lᵢ(d̂) |t|` with `Lᵢ(d̂)` =
///   [`component_directional_lipschitz`](Self::component_directional_lipschitz), `Lᵢ(d̂) ≤ Lᵢ`;
/// - `nᵢ(p) ≥ mᵢ` for `p` on the segment `[a, b]`, `mᵢ` = [`component_min`](Self::component_min);
/// - the zero set lies inside [`zero_set_bounds`](Self::zero_set_bounds).
///
/// The tracer's safety rests on these bounds alone; the property tests of each implementor check
/// them on random points.
///
/// # References
/// Hart 1996, §2 (Lipschitz calculus: the constant of a sum is at most the sum of the constants);
/// Darles et al. 2007, Eq. 1.
pub trait LipschitzSum {
    /// Number of components `N`.
    fn component_count(&self) -> usize;

    /// Value of component `i` at `p`.
    fn component(&self, i: usize, p: DVec3) -> f64;

    /// Lipschitz constant `Lᵢ` of component `i` (Euclidean norm), `Lᵢ ≥ 0`.
    fn component_lipschitz(&self, i: usize) -> f64;

    /// A lower bound `mᵢ` of component `i` over the segment `[a, b]`.
    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64;

    /// A bound of `|d nᵢ(p + t d̂)/dt|` along the unit direction `d̂` (defaults to `Lᵢ`).
    fn component_directional_lipschitz(&self, i: usize, direction: DVec3) -> f64 {
        let _ = direction;
        self.component_lipschitz(i)
    }

    /// `F(p) = Σ nᵢ(p)`. Implementors usually override this with a faster fused loop.
    fn value(&self, p: DVec3) -> f64 {
        (0..self.component_count()).map(|i| self.component(i, p)).sum()
    }

    /// Global Lipschitz constant `L = Σ Lᵢ` (Hart 1996: the constant of a sum).
    fn lipschitz(&self) -> f64 {
        (0..self.component_count()).map(|i| self.component_lipschitz(i)).sum()
    }

    /// Directional constant `L(d̂) = Σ Lᵢ(d̂)` along the unit direction `d̂`.
    fn directional_lipschitz(&self, direction: DVec3) -> f64 {
        (0..self.component_count()).map(|i| self.component_directional_lipschitz(i, direction)).sum()
    }

    /// An axis-aligned box that contains every zero of `F` (defaults to all of space).
    fn zero_set_bounds(&self) -> Aabb {
        Aabb::EVERYTHING
    }
}
