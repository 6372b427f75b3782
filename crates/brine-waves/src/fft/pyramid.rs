//! Mip pyramids of periodic grid quantities, read with trilinear filtering over a footprint,
//! round or elliptical.

use brine_core::footprint::{BOX_WIDTH_PER_SIGMA, EllipticalFootprint};
use brine_core::lattice_floor;

/// The level `log₂(w/Δ)` of a box of width `w` (m) in a pyramid of `count` levels over a grid of
/// spacing `Δ` (m), clamped to `[0, count − 1]`, as its whole part and fraction.
fn mip_level(spacing: f64, count: usize, width_m: f64) -> (usize, f64) {
    let top = (count - 1) as f64;
    let level = if width_m > spacing { (width_m / spacing).log2().min(top) } else { 0.0 };
    let l0 = level.floor();
    (l0 as usize, level - l0)
}

/// The four texels around a point on level `l` of a periodic pyramid (row by row, texel `i`
/// centred at `(i 2ˡ + (2ˡ − 1)/2)Δ`) and the point's bilinear coordinates `(s, t)` among them.
struct TexelCell {
    /// `(i₀, j₀)`, `(i₁, j₀)`, `(i₀, j₁)`, `(i₁, j₁)`.
    index: [usize; 4],
    s: f64,
    t: f64,
}

impl TexelCell {
    /// The cell of `(x, z)` (m) on level `l` of `n × n` texels (`n ≥ 2` a power of two) over a
    /// grid of spacing `spacing` (m).
    #[inline]
    fn at(spacing: f64, n: usize, l: usize, x: f64, z: f64) -> Self {
        let scale = (1usize << l) as f64;
        let offset = 0.5 * (scale - 1.0);
        let (u, v) = ((x / spacing - offset) / scale, (z / spacing - offset) / scale);
        // `lattice_floor`: `floor` without the `libm` call of the SSE2 baseline.
        let (fu, fv) = (lattice_floor(u), lattice_floor(v));
        let mask = n as i64 - 1;
        let (i0, j0) = (fu as i64 & mask, fv as i64 & mask);
        let (i1, j1) = ((i0 + 1) & mask, (j0 + 1) & mask);
        let at = |i: i64, j: i64| (j * n as i64 + i) as usize;
        Self { index: [at(i0, j0), at(i1, j0), at(i0, j1), at(i1, j1)], s: u - fu, t: v - fv }
    }
}

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
        if *n == 1 {
            return texels[0];
        }
        let TexelCell { index, s, t } = TexelCell::at(self.spacing, *n, l, x, z);
        let (a, b, c, d) = (texels[index[0]], texels[index[1]], texels[index[2]], texels[index[3]]);
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
        self.trilinear(self.level(width_m), x, z)
    }

    /// The level `log₂(w/Δ)` of a box of width `w` (m), clamped to `[0, log₂ N]`, as its whole
    /// part and fraction.
    fn level(&self, width_m: f64) -> (usize, f64) {
        mip_level(self.spacing, self.levels.len(), width_m)
    }

    /// The trilinear read at `(x, z)` between level `l0` and the next, a fraction `f` of the way.
    fn trilinear(&self, (l0, f): (usize, f64), x: f64, z: f64) -> [f64; C] {
        let a = self.sample(l0, x, z);
        if f <= 0.0 {
            return a;
        }
        let b = self.sample(l0 + 1, x, z);
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

    /// The channels' means over an elliptical footprint: the mean of its probes' round reads
    /// ([`EllipticalFootprint`]). One read where the probes could not differ: the footprint is
    /// round, or the round reads reach the `1 × 1` level (all the grid mean), or the major
    /// axis's box is within one texel of level 0 (the probes would all read one bilinear patch,
    /// linear along the axis, whose mean over the row is its centre's value).
    ///
    /// # Arguments
    /// - `x`, `z`: centre (m), finite; `footprint`: the ellipse.
    pub fn ellipse_mean(&self, x: f64, z: f64, footprint: &EllipticalFootprint) -> [f64; C] {
        let width = BOX_WIDTH_PER_SIGMA * footprint.minor_m();
        let whole = self.spacing * self.resolution() as f64;
        if footprint.probes() == 1 || width >= whole || BOX_WIDTH_PER_SIGMA * footprint.major_m() <= self.spacing {
            return self.box_mean(x, z, width);
        }
        let level = self.level(width);
        let mut out = [0.0; C];
        for o in footprint.offsets() {
            for (a, b) in out.iter_mut().zip(self.trilinear(level, x + o.x, z + o.y)) {
                *a += b;
            }
        }
        let inv = 1.0 / footprint.probes() as f64;
        out.map(|v| v * inv)
    }
}

/// A mip pyramid like [`FftPyramid`] whose texels hold a run of `channels` values chosen at run
/// time (f32), read together: one texel address and one set of trilinear weights serve every
/// channel. Made for a stack of co-registered fields, e.g. one quantity at many instants.
#[derive(Debug, Clone, PartialEq)]
pub struct FftStackPyramid {
    spacing: f64,
    channels: usize,
    /// `(n, texels)` per level, `channels` values per texel, texels row by row.
    levels: Vec<(usize, Vec<f32>)>,
}

impl FftStackPyramid {
    /// Builds the pyramid of a stack of grids.
    ///
    /// # Arguments
    /// - `n`: grid resolution, a power of two; `spacing`: grid spacing `Δ` (m), `> 0`.
    /// - `channels`: values per grid point, `≥ 1`.
    /// - `base`: `n² · channels` values, `[(j·n + i)·channels + c]` channel `c` at `(iΔ, jΔ)`.
    ///
    /// # Panics
    /// If `n` is not a power of two, `channels` is 0 or `base` has another length (programming
    /// errors).
    pub fn new(n: usize, spacing: f64, channels: usize, base: Vec<f32>) -> Self {
        assert!(
            n.is_power_of_two() && channels > 0 && base.len() == n * n * channels,
            "FftStackPyramid: n = {n}, {channels} channels, {} values",
            base.len()
        );
        debug_assert!(spacing > 0.0);
        let mut levels = vec![(n, base)];
        while let Some((m, prev)) = levels.last().filter(|l| l.0 > 1) {
            let (m, half) = (*m, *m / 2);
            let mut texels = vec![0.0f32; half * half * channels];
            for j in 0..half {
                for i in 0..half {
                    let out = &mut texels[(j * half + i) * channels..][..channels];
                    for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let src = &prev[((2 * j + dj) * m + 2 * i + di) * channels..][..channels];
                        for (a, b) in out.iter_mut().zip(src) {
                            *a += 0.25 * b;
                        }
                    }
                }
            }
            levels.push((half, texels));
        }
        Self { spacing, channels, levels }
    }

    /// Number of channels.
    pub fn channels(&self) -> usize {
        self.channels
    }

    /// Adds `weight` times the bilinear values of level `l` at `(x, z)` of channels
    /// `first..first + out.len()` to `out`.
    fn add_sample(&self, l: usize, x: f64, z: f64, weight: f64, first: usize, out: &mut [f64]) {
        let (n, texels) = &self.levels[l];
        let (ch, len) = (self.channels, out.len());
        let run = |texel: usize| &texels[texel * ch + first..][..len];
        if *n == 1 {
            for (o, &v) in out.iter_mut().zip(run(0)) {
                *o += weight * f64::from(v);
            }
            return;
        }
        let TexelCell { index, s, t } = TexelCell::at(self.spacing, *n, l, x, z);
        let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), (1.0 - s) * t, s * t].map(|v| v * weight);
        let (a, b, c, d) = (run(index[0]), run(index[1]), run(index[2]), run(index[3]));
        for (k, o) in out.iter_mut().enumerate() {
            *o += w[0] * f64::from(a[k]) + w[1] * f64::from(b[k]) + w[2] * f64::from(c[k]) + w[3] * f64::from(d[k]);
        }
    }

    /// Adds the means of channels `first..first + out.len()` over a Gaussian footprint of
    /// standard deviation `footprint_m` (m, `≥ 0`) centred at `(x, z)` (m, finite) to `out`: the
    /// level of box width `√12 s`, trilinearly (as [`FftPyramid::footprint_mean`]).
    ///
    /// # Panics
    /// If `first + out.len()` exceeds the channels (a programming error).
    pub fn add_footprint_mean(&self, x: f64, z: f64, footprint_m: f64, first: usize, out: &mut [f64]) {
        assert!(
            first + out.len() <= self.channels,
            "FftStackPyramid: channels {first}..{} of {}",
            first + out.len(),
            self.channels
        );
        let (l0, f) = mip_level(self.spacing, self.levels.len(), BOX_WIDTH_PER_SIGMA * footprint_m);
        if f <= 0.0 {
            self.add_sample(l0, x, z, 1.0, first, out);
        } else {
            self.add_sample(l0, x, z, 1.0 - f, first, out);
            self.add_sample(l0 + 1, x, z, f, first, out);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

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

    /// A pyramid of a plane wave `cos(2πx/λ)` (channel 0) and its square (channel 1) on a
    /// `256²` grid of 0.1 m, `λ` = 0.8 m (8 texels, a whole number of periods per tile).
    fn wave_pyramid() -> FftPyramid<2> {
        let (n, dx, lambda) = (256, 0.1, 0.8);
        let base = (0..n * n)
            .map(|k| {
                let c = (std::f64::consts::TAU * (k % n) as f64 * dx / lambda).cos();
                [c, c * c]
            })
            .collect();
        FftPyramid::new(n, dx, base)
    }

    /// The largest `|value|` of channel 0 read at 64 points along x.
    fn amplitude(read: impl Fn(f64) -> f64) -> f64 {
        (0..64).map(|i| read(0.0137 + 0.0125 * f64::from(i)).abs()).fold(0.0, f64::max)
    }

    proptest::proptest! {
        /// Each probe is a mean over the grid, so the ellipse's mean of `x²` stays above the square
        /// of its mean of `x` (a covariance stays a covariance).
        #[test]
        fn an_elliptical_mean_keeps_jensens_inequality(
            x in -20.0f64..20.0, z in -20.0f64..20.0, minor in 0.0f64..2.0, ratio in 1.0f64..30.0,
            angle in 0.0f64..std::f64::consts::TAU,
        ) {
            let p = wave_pyramid();
            let m = p.ellipse_mean(x, z, &EllipticalFootprint::new(minor, minor * ratio, DVec2::from_angle(angle)));
            proptest::prop_assert!(m[1] - m[0] * m[0] >= -MEAN_ROUND_ABS, "{m:?}");
        }
    }

    /// A round ellipse reads exactly as the round footprint.
    #[test]
    fn a_round_ellipse_is_the_round_read() {
        let p = wave_pyramid();
        for (x, s) in [(0.31, 0.0), (1.7, 0.05), (-3.2, 0.4), (5.5, 30.0)] {
            let round = p.footprint_mean(x, 0.7, s);
            for e in [
                EllipticalFootprint::round(s),
                EllipticalFootprint::new(s, s, DVec2::X),
                EllipticalFootprint::new(s, s, DVec2::ZERO),
            ] {
                let m = p.ellipse_mean(x, 0.7, &e);
                assert_eq!(m.map(f64::to_bits), round.map(f64::to_bits), "x = {x}, s = {s}");
            }
        }
    }

    /// An ellipse 8 times longer than wide averages away a wave along its major axis and keeps
    /// one across it as the round read of its width does. Along x, the 14 probes 0.123 m apart
    /// over the 0.8 m wave respond by `|sin(nkh/2)/(n sin(kh/2))| ≈ 0.07`; across, every probe
    /// reads the same column of the wave.
    #[test]
    fn an_ellipse_averages_the_waves_along_its_axis_only() {
        /// The comb's response (0.07) with room for the trilinear reads' own blur.
        const ALONG_RESPONSE: f64 = 0.1;
        /// Probes on one column of a wave constant along z: the same values summed 14 times.
        const ACROSS_ROUNDING: f64 = 1e-12;
        let p = wave_pyramid();
        let (minor, major) = (0.0625, 0.5);
        let round = amplitude(|x| p.footprint_mean(x, 0.3, minor)[0]);
        assert!(round > 0.5, "the round read keeps the wave: {round}");
        let along = amplitude(|x| p.ellipse_mean(x, 0.3, &EllipticalFootprint::new(minor, major, DVec2::X))[0]);
        assert!(along < ALONG_RESPONSE * round, "along the axis: {along} vs {round}");
        for i in 0..32 {
            let x = 0.011 + 0.05 * f64::from(i);
            let across = p.ellipse_mean(x, 0.3, &EllipticalFootprint::new(minor, major, DVec2::Y))[0];
            let r = p.footprint_mean(x, 0.3, minor)[0];
            assert!((across - r).abs() <= ACROSS_ROUNDING, "x = {x}: {across} vs {r}");
        }
    }

    /// Every channel of a stack reads what a one-channel pyramid of that channel alone reads, at
    /// any point and footprint (level 0 to beyond the tile), for any run of channels.
    #[test]
    fn a_stack_reads_each_channel_as_its_own_pyramid() {
        /// The stack stores f32 (values of order 1: `2⁻²⁴` relative each) and sums its levels
        /// in f32 (8 levels of 4-term means) and weights differently: a few 10⁻⁷.
        const STACK_F32: f64 = 2e-6;
        let (n, dx, channels) = (64, 0.25, 5);
        let value = |k: usize, c: usize| (((k * 37 + c * 101) % 23) as f64 / 11.0 - 1.0) * (1.0 + 0.1 * c as f64);
        let singles: Vec<FftPyramid<1>> =
            (0..channels).map(|c| FftPyramid::new(n, dx, (0..n * n).map(|k| [value(k, c)]).collect())).collect();
        let base = (0..n * n).flat_map(|k| (0..channels).map(move |c| value(k, c) as f32)).collect();
        let stack = FftStackPyramid::new(n, dx, channels, base);
        for (x, z, sigma) in [(0.0, 0.0, 0.0), (1.37, -2.9, 0.03), (7.7, 3.1, 0.4), (-3.3, 15.2, 2.0), (4.0, 4.0, 50.0)]
        {
            for first in [0, 2] {
                let mut out = vec![0.0; channels - first];
                stack.add_footprint_mean(x, z, sigma, first, &mut out);
                for (k, got) in out.iter().enumerate() {
                    let want = singles[first + k].footprint_mean(x, z, sigma)[0];
                    assert!(
                        (got - want).abs() < STACK_F32,
                        "({x}, {z}), s = {sigma}, channel {}: {got} vs {want}",
                        first + k
                    );
                }
            }
        }
    }
}
