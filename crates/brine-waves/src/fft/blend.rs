//! Tile and blend: a periodic cascade read at random offsets on a lattice and blended with
//! variance-preserving weights, so that the sea does not repeat with the cascade's tile.

/// Lattice spacing of the blend in tiles: `S = L/2`, so that two points one tile apart (or any
/// whole number of tiles) never share a lattice corner, and their values are independent reads.
pub const BLEND_SPACING_PER_TILE: f64 = 0.5;

/// Fraction of a lattice cell (per axis) over which one corner's weight hands over to the next:
/// elsewhere one corner alone is read. A narrower transition reads fewer corners and has larger
/// weight derivatives.
pub const BLEND_TRANSITION: f64 = 0.4;

/// Samples per unit of the cell coordinate over which the weights' derivative bounds are taken
/// (their suprema are inflated by [`BLEND_BOUND_MARGIN`]).
const BOUND_SAMPLES: usize = 1 << 14;

/// Relative margin on the sampled suprema of the weights' derivatives: between samples
/// `1/16384` apart a smooth function with the third derivative of these weights (below 10⁴ per
/// unit³ for `f = 0.4`) moves its second derivative by less than 1 % of its supremum.
const BLEND_BOUND_MARGIN: f64 = 1.02;

/// The quintic smoothstep `σ(t) = 6t⁵ − 15t⁴ + 10t³` and its first two derivatives, `t ∈ [0, 1]`.
#[inline]
fn smoothstep5(t: f64) -> (f64, f64, f64) {
    let t2 = t * t;
    (t2 * t * (t * (6.0 * t - 15.0) + 10.0), 30.0 * t2 * (t - 1.0) * (t - 1.0), 60.0 * t * (t - 1.0) * (2.0 * t - 1.0))
}

/// The two variance-preserving weights of one axis at the cell coordinate `u ∈ [0, 1)`, with
/// their derivatives in `u`: `a₀ = (1 − σ)/√p`, `a₁ = σ/√p`, `p = σ² + (1 − σ)²`, so that
/// `a₀² + a₁² = 1`; `σ = σ₅((u − ½)/f + ½)` clamped to `[0, 1]` (`f` = [`BLEND_TRANSITION`]).
///
/// Returns `([a₀, a₁], [a₀′, a₁′], [a₀″, a₁″])`.
#[inline]
pub(crate) fn axis_weights(u: f64) -> ([f64; 2], [f64; 2], [f64; 2]) {
    let f = BLEND_TRANSITION;
    let t = ((u - 0.5) / f + 0.5).clamp(0.0, 1.0);
    let (s, s1, s2) = smoothstep5(t);
    let (s1, s2) = (s1 / f, s2 / (f * f));
    let p = s * s + (1.0 - s) * (1.0 - s);
    let rp = 1.0 / p.sqrt();
    // a₁ = σ p^{−1/2}: a₁′ = σ′(1 − σ) p^{−3/2}; a₀′ = −σ′σ p^{−3/2}.
    let rp3 = rp * rp * rp;
    let (d1, d0) = (s1 * (1.0 - s) * rp3, -s1 * s * rp3);
    // p′ = 2σ′(2σ − 1); differentiating a₁′ and a₀′ once more.
    let dp = 2.0 * s1 * (2.0 * s - 1.0);
    let rp5 = rp3 * rp * rp;
    let e1 = (s2 * (1.0 - s) - s1 * s1) * rp3 - 1.5 * s1 * (1.0 - s) * dp * rp5;
    let e0 = (-s2 * s - s1 * s1) * rp3 + 1.5 * s1 * s * dp * rp5;
    ([(1.0 - s) * rp, s * rp], [d0, d1], [e0, e1])
}

/// Suprema over the cell of `a₀ + a₁`, `|a₀′| + |a₁′|` and `|a₀″| + |a₁″|` (per unit `u`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct AxisBounds {
    sum: f64,
    slope: f64,
    curvature: f64,
}

fn axis_bounds() -> AxisBounds {
    let mut b = AxisBounds { sum: 0.0, slope: 0.0, curvature: 0.0 };
    for i in 0..=BOUND_SAMPLES {
        let (a, d, e) = axis_weights(i as f64 / BOUND_SAMPLES as f64);
        b.sum = b.sum.max(a[0] + a[1]);
        b.slope = b.slope.max(d[0].abs() + d[1].abs());
        b.curvature = b.curvature.max(e[0].abs() + e[1].abs());
    }
    // `a₀ + a₁ = 1/√p ≤ √2` exactly (at σ = ½).
    AxisBounds {
        sum: std::f64::consts::SQRT_2,
        slope: b.slope * BLEND_BOUND_MARGIN,
        curvature: b.curvature * BLEND_BOUND_MARGIN,
    }
}

/// One corner of the blend at a point: the offset its read is taken at and its weight, with
/// the weight's gradient and Hessian (per metre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlendCorner {
    /// Offset `o` (m) added to the point before the periodic read.
    pub offset: [f64; 2],
    /// `ŵ`.
    pub weight: f64,
    /// `(∂ŵ/∂x, ∂ŵ/∂z)` (m⁻¹).
    pub gradient: [f64; 2],
    /// `(∂²ŵ/∂x², ∂²ŵ/∂x∂z, ∂²ŵ/∂z²)` (m⁻²).
    pub hessian: [f64; 3],
}

/// The tile-and-blend of one periodic cascade (Heitz & Neyret 2018, with separable,
/// variance-preserving weights): `H(x) = Σ_k ŵ_k(x) s(x + o_k)` over the four corners of the
/// square lattice cell of `x` (spacing `S = L/2`), each corner with its own random offset `o_k`
/// in the tile. `ŵ_{ij} = a_i(u) a_j(v)` (`axis_weights`) with `Σ ŵ² = 1`, so a blend of
/// independent reads keeps the cascade's variance; the weights are `C²`.
///
/// **Bounds.** With `|s| ≤ M`, `|∇s·d| ≤ λ(d)` and `|d²s/dt²| ≤ κ(d)` along a horizontal direction
/// `d = (dₓ, d_z)`, and the per-axis suprema `B = sup(a₀ + a₁) = √2`, `G₁ = sup(|a₀′| + |a₁′|)`,
/// `G₂ = sup(|a₀″| + |a₁″|)` (per unit cell coordinate):
/// - `|H| ≤ B² M = 2M`;
/// - `|∇H·d| ≤ B² λ(d) + (B G₁/S)(|dₓ| + |d_z|) M`;
/// - `|d²H/dt²| ≤ B² κ(d) + 2 (B G₁/S)(|dₓ| + |d_z|) λ(d) + (B G₂ (dₓ² + d_z²) + 2 G₁² |dₓd_z|) M/S²`.
///
/// `G₁` and `G₂` are the maxima of the weights' derivatives over 2¹⁴ + 1 points of the cell,
/// raised by `BLEND_BOUND_MARGIN` (2 %); a test checks them against 16 times as many points.
///
/// **Brine's variant.** Heitz & Neyret blend three reads on a triangle grid with weights
/// `w_k/√(Σ w²)` (variance-preserving blending, exact for Gaussian inputs) and then restore the histogram; here the
/// grid is square and the weights separable, so that each axis is one `C²` hand-over and the
/// bounds above factor per axis, and no histogram is restored: the cascades are Gaussian fields,
/// and a variance-preserving blend of independent Gaussian reads is Gaussian with the same
/// variance.
///
/// # References
/// - Heitz E., Neyret F. 2018, "High-performance by-example noise using a histogram-preserving
///   blending operator", Proc. ACM Comput. Graph. Interact. Tech. 1(2) (HPG 2018), doi:10.1145/3233304
///   (tiling and blending; for Gaussian inputs, blending that preserves mean and variance).
/// - Steele G.L., Lea D., Flood C.H. 2014, "Fast splittable pseudorandom number generators",
///   OOPSLA (the SplitMix64 finaliser of the offsets' hash).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TileBlend {
    inv_spacing: f64,
    tile: f64,
    key: u64,
    bounds: AxisBounds,
}

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): a well-mixed 64-bit hash.
#[inline]
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

impl TileBlend {
    /// The blend of a cascade of tile `tile` (m, `> 0`), keyed by the sea's seed and the
    /// cascade's index.
    pub(crate) fn new(tile: f64, seed: u64, cascade: usize) -> Self {
        debug_assert!(tile > 0.0);
        Self {
            inv_spacing: 1.0 / (BLEND_SPACING_PER_TILE * tile),
            tile,
            key: mix(seed ^ mix(0x7b1e_b1e0 + cascade as u64)),
            bounds: axis_bounds(),
        }
    }

    /// The random offset of lattice vertex `(i, j)` (m), uniform in the tile.
    #[inline]
    fn offset(&self, i: i64, j: i64) -> [f64; 2] {
        let h = mix(self.key ^ mix((i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ (j as u64)));
        let unit = |bits: u64| (bits >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        [self.tile * unit(h), self.tile * unit(mix(h ^ 0x5851_f42d_4c95_7f2d))]
    }

    /// The four corners of the cell of `(x, z)`, weights 0 included (a read may be skipped
    /// where the weight is 0).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The corners `(o_k, ŵ_k, ∇ŵ_k, ∇²ŵ_k)`, `Σ ŵ_k² = 1`.
    #[inline]
    pub fn corners(&self, x: f64, z: f64) -> [BlendCorner; 4] {
        let (u, v) = (x * self.inv_spacing, z * self.inv_spacing);
        let (fu, fv) = (u.floor(), v.floor());
        let (i, j) = (fu as i64, fv as i64);
        let (a, da, ea) = axis_weights(u - fu);
        let (b, db, eb) = axis_weights(v - fv);
        let s = self.inv_spacing;
        let corner = |ci: usize, cj: usize| BlendCorner {
            offset: self.offset(i + ci as i64, j + cj as i64),
            weight: a[ci] * b[cj],
            gradient: [da[ci] * b[cj] * s, a[ci] * db[cj] * s],
            hessian: [ea[ci] * b[cj] * s * s, da[ci] * db[cj] * s * s, a[ci] * eb[cj] * s * s],
        };
        [corner(0, 0), corner(1, 0), corner(0, 1), corner(1, 1)]
    }

    /// `sup Σ ŵ = B² = 2`.
    pub(crate) fn weight_sum_bound(&self) -> f64 {
        self.bounds.sum * self.bounds.sum
    }

    /// Bound of `|∇H·d|` for `|s| ≤ m`, `|∇s·d| ≤ lambda` along `d = (dx, dz)`.
    pub(crate) fn slope_bound(&self, m: f64, lambda: f64, dx: f64, dz: f64) -> f64 {
        let b = &self.bounds;
        self.weight_sum_bound() * lambda + b.sum * b.slope * self.inv_spacing * (dx.abs() + dz.abs()) * m
    }

    /// Bound of `|d²H/dt²|` for `|s| ≤ m`, `|∇s·d| ≤ lambda`, `|d²s/dt²| ≤ kappa` along `d`.
    pub(crate) fn curvature_bound(&self, m: f64, lambda: f64, kappa: f64, dx: f64, dz: f64) -> f64 {
        let b = &self.bounds;
        let s = self.inv_spacing;
        self.weight_sum_bound() * kappa
            + 2.0 * b.sum * b.slope * s * (dx.abs() + dz.abs()) * lambda
            + (b.sum * b.curvature * (dx * dx + dz * dz) + 2.0 * b.slope * b.slope * (dx * dz).abs()) * s * s * m
    }

    /// Bound of `|∇H|` for `|s| ≤ m`, `|∇s| ≤ lipschitz`.
    pub(crate) fn gradient_bound(&self, m: f64, lipschitz: f64) -> f64 {
        let b = &self.bounds;
        // |Σ s_k ∇ŵ_k| ≤ m Σ|∇ŵ_k| ≤ m √2 · B G₁/S (both axes at their worst).
        self.weight_sum_bound() * lipschitz + std::f64::consts::SQRT_2 * b.sum * b.slope * self.inv_spacing * m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Finite differences of the weights (central, step 10⁻⁵ of a cell): their error is
    /// `O(h²)` times the third derivative, below 10⁻⁴ relative here.
    const FD: f64 = 1e-4;

    // Outside the transition the weights are exactly 0 and 1 (σ clamps to 0 or 1, `p = 1`).
    #[allow(clippy::float_cmp)]
    #[test]
    fn the_weights_preserve_variance_and_their_derivatives_are_right() {
        for i in 0..=1000 {
            let u = i as f64 / 1000.0 * 0.999_98 + 0.000_01;
            let (a, d, e) = axis_weights(u);
            assert!((a[0] * a[0] + a[1] * a[1] - 1.0).abs() < 1e-12, "u = {u}");
            assert!(a[0] >= 0.0 && a[1] >= 0.0);
            let h = 1e-5;
            let (ap, dp, _) = axis_weights(u + h);
            let (am, dm, _) = axis_weights(u - h);
            for k in 0..2 {
                let fd1 = (ap[k] - am[k]) / (2.0 * h);
                let fd2 = (dp[k] - dm[k]) / (2.0 * h);
                assert!((fd1 - d[k]).abs() < FD * (1.0 + d[k].abs()), "u = {u}, a{k}′ {} vs {fd1}", d[k]);
                assert!((fd2 - e[k]).abs() < 20.0 * FD * (1.0 + e[k].abs()), "u = {u}, a{k}″ {} vs {fd2}", e[k]);
            }
        }
        // Outside the transition one corner alone: weights exactly 0 and 1.
        assert_eq!(axis_weights(0.1).0, [1.0, 0.0]);
        assert_eq!(axis_weights(0.9).0, [0.0, 1.0]);
    }

    /// The weights' derivative bounds `G₁`, `G₂` (maxima over 2¹⁴ + 1 points, raised by 2 %) hold
    /// over 16 times as many points, and `a₀ + a₁ ≤ √2` everywhere.
    #[test]
    fn the_sampled_suprema_bound_a_finer_sampling() {
        let b = axis_bounds();
        let n = 16 * BOUND_SAMPLES;
        let (mut slope, mut curvature) = (0.0_f64, 0.0_f64);
        for i in 0..=n {
            let (a, d, e) = axis_weights(i as f64 / n as f64);
            assert!(a[0] + a[1] <= b.sum * (1.0 + 1e-15), "u = {}", i as f64 / n as f64);
            slope = slope.max(d[0].abs() + d[1].abs());
            curvature = curvature.max(e[0].abs() + e[1].abs());
        }
        assert!(slope <= b.slope && curvature <= b.curvature, "{slope} > {} or {curvature} > {}", b.slope, b.curvature);
        // The margin is not idle: the finer maxima are within it, not far below the bounds.
        assert!(slope > b.slope / BLEND_BOUND_MARGIN / 1.001 && curvature > b.curvature / BLEND_BOUND_MARGIN / 1.001);
    }

    // Neighbouring vertices' offsets differ (exact comparison of two hashes' outputs).
    #[allow(clippy::float_cmp)]
    #[test]
    fn corners_are_continuous_across_cells_and_offsets_are_in_the_tile() {
        let blend = TileBlend::new(10.0, 3, 1);
        // The field of a corner's weight times a function of its offset is continuous where
        // the cell changes: just either side of x = S.
        let s = 0.5 * 10.0;
        let value = |x: f64, z: f64| {
            blend.corners(x, z).iter().map(|c| c.weight * (c.offset[0] * 0.37 + c.offset[1] * 0.11).sin()).sum::<f64>()
        };
        for z in [0.3, 2.6, 4.99] {
            assert!((value(s - 1e-9, z) - value(s + 1e-9, z)).abs() < 1e-6);
            assert!((value(z, s - 1e-9) - value(z, s + 1e-9)).abs() < 1e-6);
        }
        for c in blend.corners(-123.4, 987.6) {
            assert!((0.0..10.0).contains(&c.offset[0]) && (0.0..10.0).contains(&c.offset[1]));
        }
        assert_ne!(blend.corners(0.1, 0.1)[0].offset, blend.corners(5.1, 0.1)[0].offset);
    }
}
