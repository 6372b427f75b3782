//! Mip-mapped statistics of the displacement Jacobian of an FFT ocean (Dupuy & Bruneton 2012):
//! the mean and variance of `J` over a pixel footprint from per-cascade pyramids.

use brine_waves::{FftCascade, FftFrame};

use crate::statistics::Moments;

/// `√12`: a box of width `w` has the standard deviation `w/√12` of a Gaussian of the same spread,
/// so a Gaussian footprint of standard deviation `s` reads the pyramid level of texel width
/// `√12 s`.
const BOX_PER_SIGMA: f64 = 3.464_101_615_137_754_6;

/// One level of a pyramid: `n × n` texels, each the mean of `k` and `k²` over a `2ˡ × 2ˡ` block of
/// grid points.
#[derive(Debug, Clone, PartialEq)]
struct Level {
    n: usize,
    /// `(⟨k⟩, ⟨k²⟩)` per texel, `[j·n + i]`.
    texels: Vec<(f64, f64)>,
}

/// The pyramid of one cascade.
#[derive(Debug, Clone, PartialEq)]
struct Pyramid {
    spacing: f64,
    levels: Vec<Level>,
}

impl Pyramid {
    /// Level 0 holds `k = J − 1 + 1/n_c` and `k²` at the grid points; level `l + 1` averages
    /// `2 × 2` texels of level `l`.
    fn new(cascade: &FftCascade, share: f64) -> Self {
        let n = cascade.resolution();
        let base: Vec<(f64, f64)> = cascade
            .jacobians()
            .iter()
            .map(|&j| {
                let k = f64::from(j) - 1.0 + share;
                (k, k * k)
            })
            .collect();
        let mut levels = vec![Level { n, texels: base }];
        while levels.last().is_some_and(|l| l.n > 1) {
            let prev = levels.last().expect("non-empty");
            let m = prev.n / 2;
            let mut texels = Vec::with_capacity(m * m);
            for j in 0..m {
                for i in 0..m {
                    let at = |di: usize, dj: usize| prev.texels[(2 * j + dj) * prev.n + 2 * i + di];
                    let (a, b, c, d) = (at(0, 0), at(1, 0), at(0, 1), at(1, 1));
                    texels.push((0.25 * (a.0 + b.0 + c.0 + d.0), 0.25 * (a.1 + b.1 + c.1 + d.1)));
                }
            }
            levels.push(Level { n: m, texels });
        }
        Self { spacing: cascade.spacing(), levels }
    }

    /// Bilinear `(⟨k⟩, ⟨k²⟩)` of level `l` at `(x, z)`: texel `i` of level `l` is centred at
    /// `(i 2ˡ + (2ˡ − 1)/2) Δ`; periodic.
    fn sample(&self, l: usize, x: f64, z: f64) -> (f64, f64) {
        let level = &self.levels[l];
        let n = level.n;
        if n == 1 {
            return level.texels[0];
        }
        let scale = (1usize << l) as f64;
        let offset = 0.5 * (scale - 1.0);
        let (u, v) = ((x / self.spacing - offset) / scale, (z / self.spacing - offset) / scale);
        let (fu, fv) = (u.floor(), v.floor());
        let (s, t) = (u - fu, v - fv);
        let mask = n as i64 - 1;
        let (i0, j0) = (fu as i64 & mask, fv as i64 & mask);
        let (i1, j1) = ((i0 + 1) & mask, (j0 + 1) & mask);
        let at = |i: i64, j: i64| level.texels[(j * n as i64 + i) as usize];
        let (a, b, c, d) = (at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1));
        let lerp = |p: f64, q: f64, r: f64, w: f64| {
            let top = p + (q - p) * s;
            let bottom = r + (w - r) * s;
            top + (bottom - top) * t
        };
        (lerp(a.0, b.0, c.0, d.0), lerp(a.1, b.1, c.1, d.1))
    }

    /// Trilinear `(⟨k⟩, ⟨k²⟩)` over a box of width `w` (m): level `log₂(w/Δ)`, clamped to the
    /// pyramid.
    fn box_moments(&self, x: f64, z: f64, width: f64) -> (f64, f64) {
        let top = (self.levels.len() - 1) as f64;
        let level = if width > self.spacing { (width / self.spacing).log2().min(top) } else { 0.0 };
        let l0 = level.floor();
        let f = level - l0;
        let a = self.sample(l0 as usize, x, z);
        if f <= 0.0 {
            return a;
        }
        let b = self.sample(l0 as usize + 1, x, z);
        (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f)
    }
}

/// Whitecap statistics of an FFT ocean frame: per cascade, a mip-mapped pyramid of
/// `kᵢ = Jᵢ − 1 + 1/n` and `kᵢ²` (Dupuy & Bruneton 2012; `jdupuy/whitecaps`, as in equation
/// sheet §10), and the mean and variance of `J` over a pixel footprint:
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
/// `whitecap_precompute.glsl`, `ocean.glsl`); equation sheet §10.
#[derive(Debug, Clone, PartialEq)]
pub struct FftJacobianStatistics {
    cascades: Vec<Pyramid>,
}

impl FftJacobianStatistics {
    /// Builds the pyramids of every cascade of `frame` (`O(N²)` per cascade; once per frame).
    pub fn new(frame: &FftFrame) -> Self {
        let share = 1.0 / frame.cascade_count() as f64;
        Self { cascades: frame.cascades().iter().map(|c| Pyramid::new(c, share)).collect() }
    }

    /// Number of cascades.
    pub fn cascade_count(&self) -> usize {
        self.cascades.len()
    }

    /// Grid spacing `Δᵢ` (m) of the finest cascade: footprints below `Δ/√12` read level 0 only.
    pub fn finest_spacing(&self) -> f64 {
        self.cascades.iter().map(|p| p.spacing).fold(f64::INFINITY, f64::min)
    }

    /// Tile size (m) of the largest cascade: footprints beyond it read every cascade's tile mean.
    pub fn largest_tile(&self) -> f64 {
        self.cascades.iter().map(|p| p.spacing * p.levels[0].n as f64).fold(0.0, f64::max)
    }

    /// `(⟨kᵢ⟩, ⟨kᵢ²⟩)` of cascade `i` over a Gaussian footprint of standard deviation
    /// `footprint_m` centred at `(x, z)`.
    ///
    /// # Panics
    /// If `cascade ≥ cascade_count()`.
    pub fn cascade_moments(&self, cascade: usize, x: f64, z: f64, footprint_m: f64) -> (f64, f64) {
        self.cascades[cascade].box_moments(x, z, BOX_PER_SIGMA * footprint_m)
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
    /// Dupuy & Bruneton 2012; equation sheet §10 (`μ = Σ⟨kᵢ⟩`, `σ² = Σ⟨kᵢ²⟩ − Σ⟨kᵢ⟩²`).
    #[inline]
    pub fn moments_at(&self, x: f64, z: f64, footprint_m: f64) -> Moments {
        debug_assert!(footprint_m >= 0.0);
        let width = BOX_PER_SIGMA * footprint_m;
        let (mut mu, mut sigma2) = (0.0, 0.0);
        for p in &self.cascades {
            let (m, m2) = p.box_moments(x, z, width);
            mu += m;
            sigma2 += (m2 - m * m).max(0.0);
        }
        Moments { mu, sigma2 }
    }

    /// Mean and variance of `J` over the whole sea (every cascade's tile mean).
    pub fn sea_moments(&self) -> Moments {
        let (mut mu, mut sigma2) = (0.0, 0.0);
        for p in &self.cascades {
            let (m, m2) = p.levels.last().expect("a pyramid has a 1×1 level").texels[0];
            mu += m;
            sigma2 += (m2 - m * m).max(0.0);
        }
        Moments { mu, sigma2 }
    }
}
