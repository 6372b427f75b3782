//! Mip pyramids of periodic grid quantities, read with trilinear filtering over a footprint.

/// `√12`: a box of width `w` has the standard deviation `w/√12`, so a Gaussian footprint of
/// standard deviation `s` reads the pyramid level of texel width `√12 s` (same spread).
pub const BOX_WIDTH_PER_SIGMA: f64 = 3.464_101_615_137_754_6;

/// A mip pyramid of `C` channels over a periodic `N × N` grid of spacing `Δ` (`N` a power of
/// two): level 0 holds the grid values at the grid points `(iΔ, jΔ)`, level `l` the means over
/// `2ˡ × 2ˡ` blocks (texel `i` of level `l` centred at `(i 2ˡ + (2ˡ − 1)/2)Δ`), down to the
/// `1 × 1` level, the grid mean.
///
/// A footprint is read as a GPU reads a mip-mapped texture (trilinear filtering): the level of
/// texel width equal to the footprint's box width, bilinearly within the two nearest levels and
/// linearly between them. Each texel is a mean, so any convex quantity of the channels (e.g.
/// `⟨x²⟩ − ⟨x⟩² ≥ 0` when the channels hold `x` and `x²`) keeps its sign through the filter.
///
/// # References
/// Williams L. 1983, "Pyramidal parametrics", SIGGRAPH (mip-mapping); Dupuy & Bruneton 2012
/// (mip-mapped FFT statistics); Olano M., Baker D. 2010, "LEAN mapping", I3D (mip-mapped
/// moments of slopes).
#[derive(Debug, Clone, PartialEq)]
pub struct FftPyramid<const C: usize> {
    spacing: f64,
    /// `(n, texels)` per level, texels row by row.
    levels: Vec<(usize, Vec<[f64; C]>)>,
}

impl<const C: usize> FftPyramid<C> {
    /// Builds the pyramid of a grid.
    ///
    /// # Arguments
    /// - `n`: grid resolution, a power of two (the resolution of an [`crate::FftCascade`]).
    /// - `spacing`: grid spacing `Δ` (m), `> 0`.
    /// - `base`: `n²` values, `[j·n + i]` at `(iΔ, jΔ)`.
    ///
    /// # Panics
    /// If `n` is not a power of two or `base` does not hold `n²` values (programming errors).
    pub fn new(n: usize, spacing: f64, base: Vec<[f64; C]>) -> Self {
        assert!(n.is_power_of_two() && base.len() == n * n, "FftPyramid: n = {n}, {} values", base.len());
        debug_assert!(spacing > 0.0);
        let mut levels = vec![(n, base)];
        while let Some((m, prev)) = levels.last().filter(|l| l.0 > 1) {
            let (m, half) = (*m, *m / 2);
            let mut texels = Vec::with_capacity(half * half);
            for j in 0..half {
                for i in 0..half {
                    let mut v = [0.0; C];
                    for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let t = prev[(2 * j + dj) * m + 2 * i + di];
                        for (a, b) in v.iter_mut().zip(t) {
                            *a += 0.25 * b;
                        }
                    }
                    texels.push(v);
                }
            }
            levels.push((half, texels));
        }
        Self { spacing, levels }
    }

    /// Grid spacing `Δ` of level 0 (m).
    pub fn spacing(&self) -> f64 {
        self.spacing
    }

    /// Grid resolution `N` of level 0.
    pub fn resolution(&self) -> usize {
        self.levels[0].0
    }

    /// The mean of every channel over the whole grid (the `1 × 1` level).
    pub fn mean(&self) -> [f64; C] {
        self.levels.last().expect("a pyramid has a 1×1 level").1[0]
    }

    /// Bilinear value of level `l` at `(x, z)`, periodic.
    fn sample(&self, l: usize, x: f64, z: f64) -> [f64; C] {
        let (n, texels) = &self.levels[l];
        let n = *n;
        if n == 1 {
            return texels[0];
        }
        let scale = (1usize << l) as f64;
        let offset = 0.5 * (scale - 1.0);
        let (u, v) = ((x / self.spacing - offset) / scale, (z / self.spacing - offset) / scale);
        let (fu, fv) = (u.floor(), v.floor());
        let (s, t) = (u - fu, v - fv);
        let mask = n as i64 - 1;
        let (i0, j0) = (fu as i64 & mask, fv as i64 & mask);
        let (i1, j1) = ((i0 + 1) & mask, (j0 + 1) & mask);
        let at = |i: i64, j: i64| texels[(j * n as i64 + i) as usize];
        let (a, b, c, d) = (at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1));
        let mut out = [0.0; C];
        for k in 0..C {
            let top = a[k] + (b[k] - a[k]) * s;
            let bottom = c[k] + (d[k] - c[k]) * s;
            out[k] = top + (bottom - top) * t;
        }
        out
    }

    /// The channels' means over a box of width `width_m` (m) centred at `(x, z)`: the level
    /// `log₂(w/Δ)` (clamped to `[0, log₂ N]`), trilinearly.
    ///
    /// # Arguments
    /// - `x`, `z`: centre (m), finite; `width_m`: box width (m), `≥ 0` (`0` reads level 0, the
    ///   bilinear interpolant of the grid).
    pub fn box_mean(&self, x: f64, z: f64, width_m: f64) -> [f64; C] {
        let top = (self.levels.len() - 1) as f64;
        let level = if width_m > self.spacing { (width_m / self.spacing).log2().min(top) } else { 0.0 };
        let l0 = level.floor();
        let f = level - l0;
        let a = self.sample(l0 as usize, x, z);
        if f <= 0.0 {
            return a;
        }
        let b = self.sample(l0 as usize + 1, x, z);
        let mut out = a;
        for k in 0..C {
            out[k] += (b[k] - a[k]) * f;
        }
        out
    }

    /// The channels' means over a Gaussian footprint of standard deviation `footprint_m` (m):
    /// [`FftPyramid::box_mean`] with the box width `√12 s`.
    pub fn footprint_mean(&self, x: f64, z: f64, footprint_m: f64) -> [f64; C] {
        self.box_mean(x, z, BOX_WIDTH_PER_SIGMA * footprint_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Block means summed in another order than the reference: rounding of a few hundred terms
    /// of order 1.
    const MEAN_ROUND_ABS: f64 = 1e-12;

    #[test]
    fn levels_are_block_means_and_the_top_is_the_grid_mean() {
        let n = 16;
        let base: Vec<[f64; 1]> = (0..n * n).map(|i| [((i * 37) % 11) as f64]).collect();
        let p = FftPyramid::new(n, 0.5, base.clone());
        let mean = base.iter().map(|v| v[0]).sum::<f64>() / (n * n) as f64;
        assert!((p.mean()[0] - mean).abs() < MEAN_ROUND_ABS);
        // Level 2 texel (1, 2): block i ∈ [4, 8), j ∈ [8, 12), centred at ((4 + 1.5)Δ, (8 + 1.5)Δ).
        let b = &base;
        let block: f64 = (8..12).flat_map(|j| (4..8).map(move |i| b[j * n + i][0])).sum::<f64>() / 16.0;
        let got = p.box_mean(5.5 * 0.5, 9.5 * 0.5, 4.0 * 0.5);
        assert!((got[0] - block).abs() < MEAN_ROUND_ABS, "{} vs {block}", got[0]);
        // Level 0 at a grid point is the grid value; beyond the tile, the mean.
        assert_eq!(p.box_mean(3.0 * 0.5, 7.0 * 0.5, 0.0)[0].to_bits(), base[7 * n + 3][0].to_bits());
        assert!((p.box_mean(1.0, 2.0, 1e6)[0] - mean).abs() < MEAN_ROUND_ABS);
    }
}
