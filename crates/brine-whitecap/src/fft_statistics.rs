//! Mip-mapped statistics of the displacement Jacobian of an FFT ocean (Dupuy & Bruneton 2012):
//! the mean and variance of `J` over a pixel footprint from per-cascade pyramids.

use brine_waves::{FftFrame, FftPyramid, FftRestJacobian};

use crate::statistics::Moments;

/// Whitecap statistics of an FFT ocean frame: per cascade, a mip-mapped pyramid of
/// `kᵢ = Jᵢ − 1 + 1/n` and `kᵢ²` (Dupuy & Bruneton 2012; `jdupuy/whitecaps`, as in equation
/// equations.md §10), and the mean and variance of `J` over a pixel footprint:
///
/// `μ = Σᵢ ⟨kᵢ⟩`,   `σ² = Σᵢ (⟨kᵢ²⟩ − ⟨kᵢ⟩²)`.
///
/// `kᵢ = 1/n + aᵢ + bᵢ + aᵢbᵢ − cᵢ²` with `aᵢ = λ ∂Dₓ,ᵢ/∂x`, `bᵢ = λ ∂D_z,ᵢ/∂z`, `cᵢ = λ ∂Dₓ,ᵢ/∂z`
/// is `Jᵢ − 1 + 1/n`, so `μ` is `1 + Σ (Jᵢ − 1)` averaged over the footprint: the Jacobian of the sum
/// of the cascades' displacements without the cross-cascade products (the published
/// approximation). The variance neglects the correlation between cascades — independent draws on
/// non-commensurate tiles.
///
/// **Footprints.** Level 0 holds `kᵢ` at the grid points of cascade `i` (spacing `Δᵢ`); level `l`
/// the means over `2ˡ × 2ˡ` blocks, which stand for a box filter of width `2ˡΔᵢ`. A Gaussian
/// footprint of standard deviation `s` reads the level of width `√12 s` (same spread), linearly
/// between levels and bilinearly within one (trilinear filtering, as a GPU does with the
/// published mip-maps). The grid holds `Jᵢ` on the displaced surface (`brine-waves`' Eulerian
/// resampling: the sheet seen from above each grid point), so a footprint's mean is over the
/// surface's area, not over rest positions as in the published code.
///
/// # References
/// Dupuy J., Bruneton E. 2012, "Real-time animation and rendering of ocean whitecaps", SIGGRAPH
/// Asia Technical Briefs (mip-mapped `J` and `J²` per FFT cascade; `jdupuy/whitecaps`:
/// `whitecap_precompute.glsl`, `ocean.glsl`); docs/equations.md §10.
#[derive(Debug, Clone, PartialEq)]
pub struct FftJacobianStatistics {
    /// Per cascade, the pyramid of `(kᵢ, kᵢ²)`.
    cascades: Vec<FftPyramid<2>>,
}

impl FftJacobianStatistics {
    /// Builds the pyramids of every cascade of `frame` (`O(N²)` per cascade; once per frame).
    ///
    /// Level 0 of cascade `i` holds `(kᵢ, kᵢ²)`, `kᵢ = Jᵢ − 1 + 1/n` for `n` cascades (so that
    /// `Σᵢ kᵢ = 1 + Σᵢ (Jᵢ − 1)`); each level above holds the means of `2 × 2` blocks.
    ///
    /// # Arguments
    /// - `frame`: the FFT ocean at one instant (brine-waves), with its per-cascade Jacobian grids.
    ///
    /// # Returns
    /// The pyramids, for [`Self::moments_at`].
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (mip-mapped `J` and `J²`); docs/equations.md §10.
    pub fn new(frame: &FftFrame) -> Self {
        let share = 1.0 / frame.cascade_count() as f64;
        let cascades = frame
            .cascades()
            .iter()
            .map(|c| {
                let base = c
                    .jacobians()
                    .iter()
                    .map(|&j| {
                        let k = f64::from(j) - 1.0 + share;
                        [k, k * k]
                    })
                    .collect();
                FftPyramid::new(c.resolution(), c.spacing(), base)
            })
            .collect();
        Self { cascades }
    }

    /// The pyramids of the Jacobians of rest-grid derivative fields (brine-waves
    /// `FftOcean::rest_jacobian_fields`), read at rest positions: the long waves' Jacobian in the
    /// past, for the foam memory.
    ///
    /// # Arguments
    /// - `fields`: per cascade, the derivatives per unit choppiness.
    /// - `choppiness`: `λ ≥ 0`.
    ///
    /// # Returns
    /// The pyramids, as [`Self::new`] (`kᵢ = Jᵢ − 1 + 1/n`, `n = fields.len()`).
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (mip-mapped `J` and `J²`); Tessendorf 2001 (the choppy map).
    pub fn from_rest_jacobians(fields: &[FftRestJacobian], choppiness: f64) -> Self {
        let share = 1.0 / fields.len().max(1) as f64;
        let cascades = fields
            .iter()
            .map(|f| {
                let base = (0..f.dxx.len())
                    .map(|i| {
                        let k = f.jacobian(i, choppiness) - 1.0 + share;
                        [k, k * k]
                    })
                    .collect();
                FftPyramid::new(f.resolution, f.tile_size / f.resolution as f64, base)
            })
            .collect();
        Self { cascades }
    }

    /// Number of cascades.
    pub fn cascade_count(&self) -> usize {
        self.cascades.len()
    }

    /// Grid spacing `Δᵢ` (m) of the finest cascade: footprints below `Δ/√12` read level 0 only.
    pub fn finest_spacing(&self) -> f64 {
        self.cascades.iter().map(FftPyramid::spacing).fold(f64::INFINITY, f64::min)
    }

    /// Tile size (m) of the largest cascade: footprints beyond it read every cascade's tile mean.
    pub fn largest_tile(&self) -> f64 {
        self.cascades.iter().map(|p| p.spacing() * p.resolution() as f64).fold(0.0, f64::max)
    }

    /// `(⟨kᵢ⟩, ⟨kᵢ²⟩)` of cascade `i` over a Gaussian footprint of standard deviation
    /// `footprint_m` centred at `(x, z)`.
    ///
    /// # Panics
    /// If `cascade ≥ cascade_count()`.
    pub fn cascade_moments(&self, cascade: usize, x: f64, z: f64, footprint_m: f64) -> (f64, f64) {
        let [m, m2] = self.cascades[cascade].footprint_mean(x, z, footprint_m);
        (m, m2)
    }

    /// Mean and variance of `J` over a pixel footprint.
    ///
    /// # Arguments
    /// - `x`, `z`: centre of the footprint on the sea (m), the hit point's horizontal position.
    /// - `footprint_m`: standard deviation `s` (m) of a Gaussian footprint, `≥ 0` (for a square
    ///   pixel of side `ℓ` on the sea, `s ≈ ℓ/√12`, as for [`crate::JacobianStatistics::moments_at`]).
    ///
    /// # Returns
    /// [`Moments`] `(μ, σ²)`; at `s = 0` `μ` is `1 + Σᵢ (Jᵢ − 1)` interpolated at the point and
    /// `σ²` the spread of the bilinear interpolation (0 on a grid point); beyond the largest tile
    /// both are the whole sea's.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10 (`μ = Σ⟨kᵢ⟩`, `σ² = Σ⟨kᵢ²⟩ − Σ⟨kᵢ⟩²`).
    #[inline]
    pub fn moments_at(&self, x: f64, z: f64, footprint_m: f64) -> Moments {
        debug_assert!(footprint_m >= 0.0);
        let (mut mu, mut sigma2) = (0.0, 0.0);
        for p in &self.cascades {
            let [m, m2] = p.footprint_mean(x, z, footprint_m);
            mu += m;
            // Footprint means are convex combinations: m2 ≥ m² (Jensen) but for the f32 storage.
            debug_assert!(m2 - m * m >= -1e-5 * (m2.abs() + m * m) - 1e-12, "m2 = {m2}, m = {m}");
            sigma2 += (m2 - m * m).max(0.0);
        }
        Moments { mu, sigma2 }
    }

    /// Mean and variance of `J` over the whole sea (every cascade's tile mean).
    pub fn sea_moments(&self) -> Moments {
        let (mut mu, mut sigma2) = (0.0, 0.0);
        for p in &self.cascades {
            let [m, m2] = p.mean();
            mu += m;
            sigma2 += (m2 - m * m).max(0.0);
        }
        Moments { mu, sigma2 }
    }
}
/// The footprint means of `J` alone, on rest grids: [`FftJacobianStatistics::from_rest_jacobians`]
/// without the pyramid of `kᵢ²` — what a history of past instants reads (the foam memory asks
/// only `μ` of the past), in half the memory. `μ` is the same to the bit.
#[derive(Debug, Clone, PartialEq)]
pub struct FftJacobianMeans {
    /// Per cascade, the pyramid of `kᵢ`.
    cascades: Vec<FftPyramid<1>>,
}

impl FftJacobianMeans {
    /// The pyramids of `kᵢ = Jᵢ − 1 + 1/n` of rest-grid derivative fields, as
    /// [`FftJacobianStatistics::from_rest_jacobians`].
    ///
    /// # Arguments
    /// - `fields`: per cascade, the derivatives per unit choppiness.
    /// - `choppiness`: `λ ≥ 0`.
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (mip-mapped `J`); Tessendorf 2001 (the choppy map).
    pub fn from_rest_jacobians(fields: &[FftRestJacobian], choppiness: f64) -> Self {
        let share = 1.0 / fields.len().max(1) as f64;
        let cascades = fields
            .iter()
            .map(|f| {
                let base = (0..f.dxx.len()).map(|i| [f.jacobian(i, choppiness) - 1.0 + share]).collect();
                FftPyramid::new(f.resolution, f.tile_size / f.resolution as f64, base)
            })
            .collect();
        Self { cascades }
    }

    /// `μ`, the mean of `J` over a Gaussian footprint of standard deviation `footprint_m` (m,
    /// `≥ 0`) centred at `(x, z)`: [`FftJacobianStatistics::moments_at`]'s `μ`.
    #[inline]
    pub fn mean_at(&self, x: f64, z: f64, footprint_m: f64) -> f64 {
        debug_assert!(footprint_m >= 0.0);
        self.cascades.iter().map(|p| p.footprint_mean(x, z, footprint_m)[0]).fold(0.0, |mu, m| mu + m)
    }
}
