//! Mip-mapped statistics of the displacement Jacobian of an FFT ocean (Dupuy & Bruneton 2012):
//! the mean and variance of `J` over a pixel footprint from per-cascade pyramids.

use std::borrow::Borrow;

use brine_waves::{FftFrame, FftOcean, FftPyramid, FftRestJacobian, FftStackPyramid, TileBlend};
use glam::DVec2;
use rayon::prelude::*;

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
    /// Per cascade, its tile-and-blend (brine-waves `TileBlend`; `None` for a tiled sea).
    blends: Vec<Option<TileBlend>>,
    /// `1/n`.
    share: f64,
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
        let blends = frame.cascades().iter().map(|c| c.blend().copied()).collect();
        Self { cascades, blends, share }
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
        let blends = fields.iter().map(|f| f.blend).collect();
        Self { cascades, blends, share }
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
        let p = &self.cascades[cascade];
        let Some(b) = &self.blends[cascade] else {
            let [m, m2] = p.footprint_mean(x, z, footprint_m);
            return (m, m2);
        };
        // A blended cascade: `kᵢ − 1/n = Σ ŵ_c (k_c − 1/n)` over its corners' reads, which are
        // independent: mean `1/n + Σ ŵ_c (⟨k⟩_c − 1/n)`, variance `Σ ŵ_c² Var_c`.
        let (mut m, mut var) = (self.share, 0.0);
        for c in b.corners(x, z) {
            if c.weight > 0.0 {
                let [mc, m2c] = p.footprint_mean(x + c.offset[0], z + c.offset[1], footprint_m);
                m += c.weight * (mc - self.share);
                var += c.weight * c.weight * (m2c - mc * mc).max(0.0);
            }
        }
        (m, m * m + var)
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
        for c in 0..self.cascades.len() {
            let (m, m2) = self.cascade_moments(c, x, z, footprint_m);
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
/// Two lattice instants closer than this (s) are the same.
const SAME_INSTANT_S: f64 = 1e-6;

/// One past instant of an FFT sea's breaking variable, for the foam memory: per cascade,
/// `kᵢ = Jᵢ − 1 + 1/n` on its rest grid (f32), the sea moved with the foam's drift so that every
/// instant's grid lines up ([`FftJacobianHistory`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FftInstantJacobian {
    time_s: f64,
    drift_m_s: DVec2,
    /// Per cascade kept: resolution, spacing (m), the `kᵢ` grid and the cascade's blend.
    cascades: Vec<(usize, f64, Vec<f32>, Option<TileBlend>)>,
}

impl FftInstantJacobian {
    /// The Jacobian of `ocean`'s waves longer than the breaking footprint at instant `t`, on rest
    /// grids moved by `−v t`: grid point `p` holds `kᵢ` at rest position `p + v t`.
    ///
    /// # Arguments
    /// - `ocean`: the FFT sea (its choppiness `λ` makes `J`).
    /// - `time_s`: the instant `t` (s), finite.
    /// - `breaking_footprint_m`: `s_b` (m), `≥ 0` (brine-waves `FftOcean::rest_jacobian_fields`).
    /// - `drift_m_s`: the foam's drift `v` relative to the water (m s⁻¹), finite.
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (`kᵢ`); Tessendorf 2001 (the choppy map); the Fourier shift theorem.
    pub fn new(ocean: &FftOcean, time_s: f64, breaking_footprint_m: f64, drift_m_s: DVec2) -> Self {
        let shift = drift_m_s * time_s;
        let fields = ocean.rest_jacobian_fields_shifted(time_s, breaking_footprint_m, shift.to_array());
        let chop = ocean.options().choppiness;
        let share = 1.0 / fields.len().max(1) as f64;
        let cascades = fields
            .iter()
            .map(|f| {
                let k = (0..f.dxx.len()).map(|i| (f.jacobian(i, chop) - 1.0 + share) as f32).collect();
                (f.resolution, f.tile_size / f.resolution as f64, k, f.blend)
            })
            .collect();
        Self { time_s, drift_m_s, cascades }
    }

    /// The instant `t` (s).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }
}

/// The footprint means of an FFT sea's breaking variable at the foam memory's past instants,
/// read together.
///
/// The memory asks, for a point `u₀` at the newest instant `t₀`, the means
/// `μⱼ = Σᵢ ⟨kᵢ⟩(uⱼ, tⱼ)` along the foam's drift path `uⱼ = u₀ − v jΔt`, `tⱼ = t₀ − jΔt`. Each
/// instant's grid is the sea moved by `−v tⱼ` ([`FftInstantJacobian`]), so every `uⱼ` falls on
/// the same grid position `y = uⱼ − v tⱼ = u₀ − v t₀`: one pyramid per cascade holds all the
/// instants in each texel (brine-waves `FftStackPyramid`), and one texel address and one set of
/// trilinear weights serve them all. The means are those of [`FftJacobianStatistics`] of the
/// same instant (the Dupuy & Bruneton pyramid), up to the f32 storage and to where the moved
/// grid's points fall (the interpolation of the same smooth field from other samples).
///
/// # References
/// Dupuy & Bruneton 2012 (mip-mapped `J`); brine-foam `FoamMemory` (the drift path).
#[derive(Debug, Clone, PartialEq)]
pub struct FftJacobianHistory {
    /// The instants, newest first.
    instants: Vec<f64>,
    drift_m_s: DVec2,
    /// Per cascade, the pyramid of `kᵢ` at every instant and the cascade's blend.
    cascades: Vec<(FftStackPyramid, Option<TileBlend>)>,
    /// `1/n`, `n` the cascades kept.
    share: f64,
}

impl FftJacobianHistory {
    /// Stacks instants made with one drift and one sea (owned or shared, e.g. `Arc`s kept from
    /// frame to frame).
    ///
    /// # Arguments
    /// - `instants`: newest first, all from [`FftInstantJacobian::new`] with the same ocean,
    ///   breaking footprint and drift; may be empty (no history: every mean is 1).
    ///
    /// # Panics
    /// If the instants differ in drift or cascades (a programming error).
    pub fn new<I: Borrow<FftInstantJacobian> + Sync>(instants: &[I]) -> Self {
        let Some(first) = instants.first().map(Borrow::borrow) else {
            return Self { instants: Vec::new(), drift_m_s: DVec2::ZERO, cascades: Vec::new(), share: 1.0 };
        };
        let count = instants.len();
        for i in instants.iter().map(Borrow::borrow) {
            assert!(
                i.drift_m_s == first.drift_m_s
                    && i.cascades.len() == first.cascades.len()
                    && i.cascades
                        .iter()
                        .zip(&first.cascades)
                        .all(|(a, b)| a.0 == b.0 && a.1.to_bits() == b.1.to_bits()),
                "FftJacobianHistory: instants of different seas or drifts"
            );
        }
        let cascades = (0..first.cascades.len())
            .into_par_iter()
            .map(|c| {
                let (n, spacing, _, blend) = first.cascades[c];
                // Written in order, read from `count` streams.
                let grids: Vec<&[f32]> = instants.iter().map(|i| i.borrow().cascades[c].2.as_slice()).collect();
                let base = (0..n * n).flat_map(|texel| grids.iter().map(move |g| g[texel])).collect();
                (FftStackPyramid::new(n, spacing, count, base), blend)
            })
            .collect();
        Self {
            instants: instants.iter().map(|i| i.borrow().time_s).collect(),
            drift_m_s: first.drift_m_s,
            cascades,
            share: 1.0 / first.cascades.len().max(1) as f64,
        }
    }

    /// `kᵢ` of a blended cascade at instant `instant` over a footprint: its corners at the rest
    /// position `u`, each read at grid position `y + o` (the instant's grid holds rest position
    /// `p + v tᵢ` at `p`, and `y = u − v tᵢ`); `1/n + Σ ŵ (⟨k⟩_c − 1/n)`.
    fn blended_mean(
        &self,
        stack: &FftStackPyramid,
        blend: &TileBlend,
        u: DVec2,
        y: DVec2,
        footprint_m: f64,
        instant: usize,
    ) -> f64 {
        let mut m = self.share;
        for c in blend.corners(u.x, u.y) {
            if c.weight > 0.0 {
                let mut v = [0.0];
                stack.add_footprint_mean(y.x + c.offset[0], y.y + c.offset[1], footprint_m, instant, &mut v);
                m += c.weight * (v[0] - self.share);
            }
        }
        m
    }

    /// Number of instants held.
    pub fn instant_count(&self) -> usize {
        self.instants.len()
    }

    /// The footprint means `μⱼ` at `tⱼ = t₀ − jΔt`, `uⱼ = u₀ − v jΔt`, `j < out.len()`; an
    /// instant not held gives `μ = 1` (no breaking).
    ///
    /// # Arguments
    /// - `u0`: rest position at `t₀` (m); `t0`: the newest instant (s).
    /// - `step_s`: `Δt` (s), `> 0`; `drift_m_s`: `v` (m s⁻¹).
    /// - `footprint_m`: standard deviation of the Gaussian footprint (m), `≥ 0`.
    /// - `out`: receives `μⱼ` (dimensionless).
    pub fn mean_history(&self, u0: DVec2, t0: f64, step_s: f64, drift_m_s: DVec2, footprint_m: f64, out: &mut [f64]) {
        debug_assert!(footprint_m >= 0.0 && step_s > 0.0);
        out.fill(0.0);
        let first = self.instants.iter().position(|t| (t - t0).abs() < SAME_INSTANT_S);
        let consecutive = first.is_some_and(|i| {
            self.instants[i..]
                .iter()
                .enumerate()
                .take(out.len())
                .all(|(j, t)| (t - (t0 - j as f64 * step_s)).abs() < SAME_INSTANT_S)
        });
        if let (Some(i0), true, true) = (first, consecutive, drift_m_s == self.drift_m_s) {
            // Every instant at the same grid position.
            let y = u0 - drift_m_s * t0;
            let held = (self.instants.len() - i0).min(out.len());
            for (stack, blend) in &self.cascades {
                match blend {
                    None => stack.add_footprint_mean(y.x, y.y, footprint_m, i0, &mut out[..held]),
                    // The drift moves each instant's rest position `y + v tⱼ` across the blend's
                    // lattice: instant by instant.
                    Some(b) => {
                        for (j, o) in out[..held].iter_mut().enumerate() {
                            let u = y + self.drift_m_s * self.instants[i0 + j];
                            *o += self.blended_mean(stack, b, u, y, footprint_m, i0 + j);
                        }
                    }
                }
            }
            out[held..].fill(1.0);
            return;
        }
        // Another lattice or drift: instant by instant.
        for (j, o) in out.iter_mut().enumerate() {
            let (tj, uj) = (t0 - j as f64 * step_s, u0 - drift_m_s * (j as f64 * step_s));
            *o = match self.instants.iter().position(|t| (t - tj).abs() < SAME_INSTANT_S) {
                Some(i) => {
                    let y = uj - self.drift_m_s * self.instants[i];
                    let mut m = [0.0];
                    for (stack, blend) in &self.cascades {
                        match blend {
                            None => stack.add_footprint_mean(y.x, y.y, footprint_m, i, &mut m),
                            Some(b) => m[0] += self.blended_mean(stack, b, uj, y, footprint_m, i),
                        }
                    }
                    m[0]
                }
                None => 1.0,
            };
        }
    }
}
