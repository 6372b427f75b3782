//! One instant of the FFT ocean: each cascade's surface on its grid, interpolated by a cubic
//! B-spline — the surface the tracer draws — with shading gradients, Jacobians and certified
//! bounds.

use std::f64::consts::TAU;

use brine_core::footprint::footprint_weight;
use glam::{DVec2, DVec3};
use rayon::prelude::*;

use crate::fft::blend::TileBlend;
use crate::fft::resample::resample;
use crate::fft::spline::SplineGrid;
use crate::{FftOcean, FftRestFields};

/// Smallest `|d_y|` used to stretch a pixel footprint along a grazing view (the floor of the
/// trochoid fades and the renderer's footprint, whose stretch stops at `1/0.05`; the FFT sea's
/// fade stretches by `1/√|d_y|`, so beyond 87° from the vertical its stretch stops at `1/√0.05`).
const MIN_GRAZING: f64 = brine_core::footprint::MIN_FOOTPRINT_GRAZING;

/// One cascade of an [`FftFrame`]: an `N × N` periodic grid of spacing `Δ = L/N` over its tile;
/// the traced height is the interpolating cubic B-spline of its grid heights, the shading
/// gradient and the Jacobian are bilinear interpolants of their grids.
///
/// **The traced height** `s(x, z) = Σᵢⱼ cᵢⱼ β₃(x/Δ − i) β₃(z/Δ − j)` (`β₃` the cubic B-spline), with
/// coefficients prefiltered so that `s(iΔ, jΔ) = Hᵢⱼ`, the grid heights (the cascade's displaced
/// surface resampled on the grid, see [`FftFrame`]); periodic. It is `C²`, and for a smooth field
/// its interpolation error is `O(Δ⁴)`. (Bilinear interpolation would be `O(Δ²)`, with slopes that
/// jump at cell edges: no curvature bound, hence no second-order step for the tracer, which then
/// crawls near grazing hits.)
///
/// **Certified bounds** (proof). The derivative of a cubic B-spline is a difference of quadratic
/// ones, `β₃'(u) = β₂(u + ½) − β₂(u − ½)`, so
/// `∂s/∂x = (1/Δ) Σⱼ β₃(z/Δ − j) qⱼ(x/Δ)` with `qⱼ(u) = Σᵢ (cᵢ₊₁,ⱼ − cᵢⱼ) β₂(u − i − ½)`, the
/// quadratic spline of row `j`'s differences. B-splines are non-negative and sum to 1, so
/// `∂s/∂x` is a convex combination of the `qⱼ` at the same `u`, and `|∂s/∂x| ≤ a = maxⱼ max |qⱼ|/Δ`,
/// each `max |qⱼ|` exact (on a unit segment `qⱼ` is a quadratic in the fraction: its largest
/// magnitude is at an end or at its vertex); `a ≤ max|Δₓc|/Δ`. Likewise `|∂s/∂z| ≤ b` over the
/// columns. Hence along a horizontal unit direction `|∇s·d| ≤ a|dₓ| + b|d_z|`, and
/// `|∇s| ≤ L = √(a² + b²)` (Cauchy–Schwarz), so `|s(p) − s(q)| ≤ L|p − q|`. Differentiating once
/// more, `∂²s/∂x² = (1/Δ²) Σ (cᵢ₊₁ − 2cᵢ + cᵢ₋₁) β₁ β₃` is a convex combination of second differences
/// (`|·| ≤ A = max|Δₓ²c|/Δ²`, likewise `B`), and `∂²s/∂x∂z = (1/Δ²) Σⱼ β₂(z/Δ − j − ½) rⱼ(x/Δ)` with
/// `rⱼ` the quadratic spline of the mixed differences `ΔₓΔ_z c` of row `j` (`|·| ≤ C = maxⱼ max|rⱼ|/Δ²`):
/// along a ray of horizontal direction `(dₓ, d_z)`, `|d²s/dt²| ≤ A dₓ² + 2C|dₓd_z| + B d_z²`. And
/// `min c ≤ s ≤ max c`. The bounds are computed from the stored (f32) coefficients, those evaluated
/// (in f64), and inflated by `10⁻¹²` for the evaluation's rounding. For a field resolved by the
/// grid they are close to the true maxima (the sampled slopes reach 72–93 % of `a`, `b` in the
/// tests, on bands reaching 85 % of the Nyquist frequency); near the Nyquist frequency
/// the prefilter amplifies the coefficients (up to 3×) and the bounds loosen.
#[derive(Debug, Clone, PartialEq)]
pub struct FftCascade {
    tile: f64,
    n: usize,
    mask: i64,
    inv_spacing: f64,
    height: Vec<f32>,
    spline: SplineGrid,
    gradient: Vec<[f32; 2]>,
    jacobian: Vec<f32>,
    band: (f64, f64),
    k_longest: f64,
    variance: f64,
    slope_covariance: DVec3,
    uncovered: usize,
    /// The tile-and-blend that keeps the cascade from repeating (`None` for a tiled sea).
    blend: Option<TileBlend>,
}

/// Bilinear weights of a point: the four grid indices and `(s, t)`.
#[derive(Debug, Clone, Copy)]
struct Cell {
    i00: usize,
    i10: usize,
    i01: usize,
    i11: usize,
    s: f64,
    t: f64,
}

impl FftCascade {
    /// The cell of `(x, z)` and its bilinear coordinates.
    #[inline]
    fn cell(&self, x: f64, z: f64) -> Cell {
        let (u, v) = (x * self.inv_spacing, z * self.inv_spacing);
        let (fu, fv) = (u.floor(), v.floor());
        let (i0, j0) = (fu as i64 & self.mask, fv as i64 & self.mask);
        let (i1, j1) = ((i0 + 1) & self.mask, (j0 + 1) & self.mask);
        let n = self.mask + 1;
        Cell {
            i00: (j0 * n + i0) as usize,
            i10: (j0 * n + i1) as usize,
            i01: (j1 * n + i0) as usize,
            i11: (j1 * n + i1) as usize,
            s: u - fu,
            t: v - fv,
        }
    }

    #[inline]
    fn lerp2(c: &Cell, v00: f64, v10: f64, v01: f64, v11: f64) -> f64 {
        let a = v00 + (v10 - v00) * c.s;
        let b = v01 + (v11 - v01) * c.s;
        a + (b - a) * c.t
    }

    /// Traced height of the cascade, `s(x, z) = Σᵢⱼ cᵢⱼ β₃(x/Δ − i) β₃(z/Δ − j)`: the interpolating cubic
    /// B-spline of the grid heights.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `s` (m), within [`FftCascade::height_bounds`].
    ///
    /// # References
    /// Unser 1999, "Splines: a perfect fit for signal and image processing", IEEE SPM 16(6) (cubic
    /// B-spline interpolation); Tessendorf 2001 (the field).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        match &self.blend {
            None => self.spline.value(x, z),
            Some(b) => b
                .corners(x, z)
                .iter()
                .filter(|c| c.weight > 0.0)
                .map(|c| c.weight * self.spline.value(x + c.offset[0], z + c.offset[1]))
                .sum(),
        }
    }

    /// The traced height and its exact gradient, `(s, ∂s/∂x, ∂s/∂z)`: the spline's, or the
    /// blend of the corners' reads, `H = Σ ŵ_k s_k`, `∇H = Σ (ŵ_k ∇s_k + s_k ∇ŵ_k)`.
    #[inline]
    fn value_and_gradient(&self, x: f64, z: f64) -> (f64, f64, f64) {
        match &self.blend {
            None => self.spline.value_and_gradient(x, z),
            Some(b) => {
                let (mut h, mut gx, mut gz) = (0.0, 0.0, 0.0);
                for c in b.corners(x, z) {
                    if c.weight > 0.0 {
                        let (s, sx, sz) = self.spline.value_and_gradient(x + c.offset[0], z + c.offset[1]);
                        h += c.weight * s;
                        gx += c.weight * sx + s * c.gradient[0];
                        gz += c.weight * sz + s * c.gradient[1];
                    }
                }
                (h, gx, gz)
            }
        }
    }

    /// Gradient of the traced height, `∇s` (the spline's exact derivative).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `(∂s/∂x, ∂s/∂z)` (dimensionless), `|∂s/∂x| ≤ a`, `|∂s/∂z| ≤ b` ([`FftCascade::max_axis_slopes`]).
    ///
    /// # References
    /// Unser 1999 (derivative of a B-spline).
    #[inline]
    pub fn traced_gradient(&self, x: f64, z: f64) -> DVec2 {
        let (_, gx, gz) = self.value_and_gradient(x, z);
        DVec2::new(gx, gz)
    }

    /// The traced height and its derivative along a horizontal direction, `(s, ∇s·(dₓ, d_z))`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    /// - `dx`, `dz`: horizontal direction components (any length; the derivative scales with it).
    ///
    /// # Returns
    /// `(s (m), ∇s·d (dimensionless per unit of d))`.
    ///
    /// # References
    /// Unser 1999.
    #[inline]
    pub fn height_and_derivative(&self, x: f64, z: f64, dx: f64, dz: f64) -> (f64, f64) {
        let (s, gx, gz) = self.value_and_gradient(x, z);
        (s, gx * dx + gz * dz)
    }

    /// Shading gradient: the bilinear interpolant of the displaced surface's exact slopes `M⁻¹∇h` at
    /// the grid points (clamped to [`crate::FFT_MAX_SHADING_SLOPE`] near folds). It agrees with
    /// [`FftCascade::traced_gradient`] to the interpolation error of the grid.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `(∂h/∂x, ∂h/∂z)` (dimensionless).
    ///
    /// # References
    /// Tessendorf 2001 (the slope and choppy-displacement sums); docs/equations.md §1.
    #[inline]
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        match &self.blend {
            None => self.tile_gradient(x, z),
            Some(b) => {
                let mut g = DVec2::ZERO;
                for c in b.corners(x, z) {
                    if c.weight > 0.0 {
                        let (px, pz) = (x + c.offset[0], z + c.offset[1]);
                        let h = self.tile_height(px, pz);
                        g += c.weight * self.tile_gradient(px, pz) + h * DVec2::new(c.gradient[0], c.gradient[1]);
                    }
                }
                g
            }
        }
    }

    /// The bilinear interpolant of the grid heights (the shading's height, without the blend).
    #[inline]
    fn tile_height(&self, x: f64, z: f64) -> f64 {
        let c = self.cell(x, z);
        let h = &self.height;
        Self::lerp2(&c, f64::from(h[c.i00]), f64::from(h[c.i10]), f64::from(h[c.i01]), f64::from(h[c.i11]))
    }

    /// The bilinear interpolant of the grid's shading gradients (without the blend).
    #[inline]
    fn tile_gradient(&self, x: f64, z: f64) -> DVec2 {
        let c = self.cell(x, z);
        let g = &self.gradient;
        let comp = |k: usize| {
            Self::lerp2(
                &c,
                f64::from(g[c.i00][k]),
                f64::from(g[c.i10][k]),
                f64::from(g[c.i01][k]),
                f64::from(g[c.i11][k]),
            )
        };
        DVec2::new(comp(0), comp(1))
    }

    /// Jacobian of the cascade's horizontal map `x = u + λD(u)`, bilinear between its grid values
    /// `(1 + λDₓₓ)(1 + λD_zz) − λ²Dₓ_z²`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `J` (dimensionless): `< 1` compressed, `< 0` folded.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; Tessendorf 2001 (choppy waves); docs/equations.md §10.
    #[inline]
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        match &self.blend {
            None => self.tile_jacobian(x, z),
            // J − 1 blends as the height does.
            Some(b) => {
                1.0 + b
                    .corners(x, z)
                    .iter()
                    .filter(|c| c.weight > 0.0)
                    .map(|c| c.weight * (self.tile_jacobian(x + c.offset[0], z + c.offset[1]) - 1.0))
                    .sum::<f64>()
            }
        }
    }

    #[inline]
    fn tile_jacobian(&self, x: f64, z: f64) -> f64 {
        let c = self.cell(x, z);
        let j = &self.jacobian;
        Self::lerp2(&c, f64::from(j[c.i00]), f64::from(j[c.i10]), f64::from(j[c.i01]), f64::from(j[c.i11]))
    }

    /// Whether the cascade is read through a tile-and-blend (an untiled sea's cascades are).
    pub fn blended(&self) -> bool {
        self.blend.is_some()
    }

    /// The cascade's tile-and-blend, if any.
    pub fn blend(&self) -> Option<&TileBlend> {
        self.blend.as_ref()
    }

    /// `max(|min c|, |max c|)`: the bound of the tile's own spline.
    fn tile_magnitude(&self) -> f64 {
        self.spline.min.abs().max(self.spline.max.abs())
    }

    /// Tile size `L` (m).
    pub fn tile_size(&self) -> f64 {
        self.tile
    }

    /// Grid resolution `N`.
    pub fn resolution(&self) -> usize {
        self.n
    }

    /// Grid spacing `Δ = L/N` (m).
    pub fn spacing(&self) -> f64 {
        1.0 / self.inv_spacing
    }

    /// Grid heights `Hᵢⱼ` (m), `[j·N + i]` at `(iΔ, jΔ)` (the traced spline interpolates them).
    pub fn heights(&self) -> &[f32] {
        &self.height
    }

    /// Grid shading gradients `(∂h/∂x, ∂h/∂z)`, `[j·N + i]`.
    pub fn gradients(&self) -> &[[f32; 2]] {
        &self.gradient
    }

    /// Grid Jacobians `J` of the displacement (dimensionless), `[j·N + i]`, on the displaced
    /// (Eulerian) grid: the Jacobian of the sheet seen from above each grid point.
    pub fn jacobians(&self) -> &[f32] {
        &self.jacobian
    }

    /// `(min c, max c)` (m): bounds of the traced height.
    pub fn height_bounds(&self) -> (f64, f64) {
        match &self.blend {
            None => (self.spline.min, self.spline.max),
            // ŵ ≥ 0 and 1 ≤ Σ ŵ ≤ 2.
            Some(b) => {
                (b.weight_sum_bound() * self.spline.min.min(0.0), b.weight_sum_bound() * self.spline.max.max(0.0))
            }
        }
    }

    /// Certified bound `L = √(a² + b²)` of `|∇s|` (see the type's documentation).
    pub fn max_slope(&self) -> f64 {
        match &self.blend {
            None => self.spline.max_slope(),
            Some(b) => b.gradient_bound(self.tile_magnitude(), self.spline.max_slope()),
        }
    }

    /// Certified bounds `(a, b)` of `|∂s/∂x|` and `|∂s/∂z|`.
    pub fn max_axis_slopes(&self) -> (f64, f64) {
        match &self.blend {
            None => self.spline.slope,
            Some(_) => (self.directional_max_slope(1.0, 0.0), self.directional_max_slope(0.0, 1.0)),
        }
    }

    /// Certified bound of `|∇s·d|` along the horizontal part `(dₓ, d_z)` of a direction:
    /// `a|dₓ| + b|d_z|`.
    #[inline]
    pub fn directional_max_slope(&self, dx: f64, dz: f64) -> f64 {
        let lambda = self.spline.directional_slope(dx, dz);
        match &self.blend {
            None => lambda,
            Some(b) => b.slope_bound(self.tile_magnitude(), lambda, dx, dz),
        }
    }

    /// Certified bound of `|d²s/dt²|` along the horizontal part `(dₓ, d_z)` of a direction:
    /// `A dₓ² + 2C|dₓd_z| + B d_z²`.
    #[inline]
    pub fn directional_curvature(&self, dx: f64, dz: f64) -> f64 {
        let kappa = self.spline.directional_curvature(dx, dz);
        match &self.blend {
            None => kappa,
            Some(b) => {
                let lambda = self.spline.directional_slope(dx, dz);
                b.curvature_bound(self.tile_magnitude(), lambda, kappa, dx, dz)
            }
        }
    }

    /// The band `[k_lo, k_hi)` of `|k|_∞` (rad m⁻¹) the cascade holds.
    pub fn band(&self) -> (f64, f64) {
        self.band
    }

    /// Wavelength of the cascade's longest wave (m), `2π/k_lo` (the tile for cascade 0): its
    /// feature size for footprint fading.
    pub fn longest_wavelength(&self) -> f64 {
        TAU / self.k_longest
    }

    /// Expected height variance of the (un-displaced) cascade, `∫_band Ψ d²k` (m²).
    pub fn expected_variance(&self) -> f64 {
        self.variance
    }

    /// Expected slope covariance `(⟨ζₓ²⟩, ⟨ζₓζ_z⟩, ⟨ζ_z²⟩)` of the un-displaced cascade.
    pub fn expected_slope_covariance(&self) -> DVec3 {
        self.slope_covariance
    }

    /// Grid points that no displaced triangle covered (filled from the rest grid; 0 unless the
    /// rasterisation met a degenerate configuration).
    pub fn uncovered_points(&self) -> usize {
        self.uncovered
    }

    /// Distance along a ray at which a pixel footprint covers the cascade's longest wavelength `λ`:
    /// `T = λ √max(|d_y|, 0.05)/α` (the footprint `αt` stretched by `1/√|d_y|`, the geometric mean of its
    /// two axes on the sea, as the renderer's footprint).
    ///
    /// # Arguments
    /// - `direction`: unit ray direction `d̂`.
    /// - `footprint_angle`: pixel angular width `α` (rad), `> 0`.
    ///
    /// # Returns
    /// `T` (m).
    ///
    /// # References
    /// Darles et al. 2007 (pixel-footprint antialiasing); Bruneton et al. 2010 (fading).
    #[inline]
    pub fn fade_distance(&self, direction: DVec3, footprint_angle: f64) -> f64 {
        self.longest_wavelength() * direction.y.abs().max(MIN_GRAZING).sqrt() / footprint_angle
    }
}

/// The FFT ocean at one instant ([`FftOcean::at_time`]): the sum of its cascades' surfaces,
/// `y = h̄(x, z) = Σ_c s_c(x, z)`, each cascade's cubic B-spline through its grid heights.
///
/// **Which surface is traced.** With choppiness `λ > 0` each cascade's surface is the displaced
/// sheet `{(u + λD_c(u), h_c(u))}`, which is a height field only where its Jacobian `J_c > 0`.
/// Brine resamples it on the cascade's own grid: the displaced grid points form a periodic mesh
/// of triangles, and each grid point takes the height of the highest triangle above it (the upper
/// envelope where the sheet folds, what a camera above the sea sees); the traced surface is the
/// cubic B-spline through these heights. So each cascade is a true height field with certified
/// slope and curvature bounds ([`FftCascade`]), and the sea is their sum. As with the trochoid sum of Darles et
/// al. (docs/equations.md §1(a)), the displacements of different cascades do not compose: the sum
/// of displaced cascades is not the displaced sum (a valid, self-consistent surface; the two
/// agree to first order in `λ`). With `λ = 0` it is Tessendorf's height field itself, exact at the
/// grid points and within `O(Δ⁴)` between them. The resampling is linear on the displaced mesh:
/// its error is `O(Δ²)` times the curvature of the displaced sheet, largest at near-folds.
///
/// **Shading** uses the bilinear interpolant of the displaced sheets' exact slopes at the grid
/// points ([`FftFrame::gradient`]; the traced spline's own gradient is
/// [`FftCascade::traced_gradient`]); **whitecaps** use
/// the grid Jacobians (`brine-whitecap`'s mip-mapped statistics).
///
/// It implements [`brine_trace::LipschitzSum`]: component 0 is `y`, component `c + 1` is
/// `−s_c(x, z)`, with the certified bounds of [`FftCascade`].
#[derive(Debug, Clone, PartialEq)]
pub struct FftFrame {
    time: f64,
    choppiness: f64,
    cascades: Vec<FftCascade>,
}

impl FftCascade {
    /// A periodic cascade from heights already on its grid (`n × n` row by row, `[j·n + i]` at
    /// `(iΔ, jΔ)`, `Δ = tile/n`): the traced surface is their cubic B-spline (read through
    /// `blend` if any), its shading gradient the bilinear interpolant of the spline's gradient at
    /// the grid points, its Jacobian 1 (no displacement of its own). The grids the trochoid
    /// sea's shorter waves are traced on (brine-waves `GriddedTrochoids`).
    ///
    /// # Arguments
    /// - `tile`: the tile's side (m), `> 0`; `n`: its resolution, a power of two `≥ 4`.
    /// - `heights`: the grid heights (m).
    /// - `band`: the band `[k_lo, k_hi)` of `|k|_∞` (rad m⁻¹) the heights hold; `k_longest` its longest wave's
    ///   wavenumber (rad m⁻¹), `> 0`: the cascade's feature size for footprint fading.
    /// - `variance` (m²), `slope_covariance`: what the heights hold, for the statistics.
    /// - `blend`: the tile-and-blend that keeps it from repeating, or `None` (periodic).
    #[cfg(feature = "tracing")]
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_heights(
        tile: f64,
        n: usize,
        heights: Vec<f32>,
        band: (f64, f64),
        k_longest: f64,
        variance: f64,
        slope_covariance: DVec3,
        blend: Option<TileBlend>,
    ) -> Self {
        debug_assert!(n.is_power_of_two() && n >= 4 && heights.len() == n * n && tile > 0.0 && k_longest > 0.0);
        let dx = tile / n as f64;
        let spline = SplineGrid::new(&heights, n, dx);
        let gradient = (0..n * n)
            .map(|idx| {
                let (_, gx, gz) = spline.value_and_gradient((idx % n) as f64 * dx, (idx / n) as f64 * dx);
                [gx as f32, gz as f32]
            })
            .collect();
        FftCascade {
            tile,
            n,
            mask: n as i64 - 1,
            inv_spacing: 1.0 / dx,
            height: heights,
            spline,
            gradient,
            jacobian: vec![1.0; n * n],
            band,
            k_longest,
            variance,
            slope_covariance,
            uncovered: 0,
            blend,
        }
    }
}

impl FftFrame {
    /// A frame of the given cascades at time `time` (s), without displacement of its own
    /// (choppiness 0): the gridded-band study's band.
    #[cfg(feature = "tracing")]
    pub(crate) fn from_cascades(time: f64, cascades: Vec<FftCascade>) -> Self {
        Self { time, choppiness: 0.0, cascades }
    }

    /// Builds the frame from the rest fields of `ocean` at time `time` (s).
    pub(crate) fn from_rest_fields(ocean: &FftOcean, rest: &[FftRestFields], time: f64) -> Self {
        let lambda = ocean.options().choppiness;
        let cascades = rest
            .par_iter()
            .enumerate()
            .map(|(c, f)| {
                let spec = ocean.cascade_spectrum(c);
                let grid = resample(f, lambda);
                let n = f.resolution;
                let dx = f.tile_size / n as f64;
                let spline = SplineGrid::new(&grid.height, n, dx);
                let cov = spec.slope_covariance;
                FftCascade {
                    tile: f.tile_size,
                    n,
                    mask: n as i64 - 1,
                    inv_spacing: 1.0 / dx,
                    height: grid.height,
                    spline,
                    gradient: grid.gradient,
                    jacobian: grid.jacobian,
                    band: (spec.band.lo, spec.band.hi),
                    k_longest: spec.k_longest,
                    variance: spec.variance,
                    slope_covariance: DVec3::new(cov[0], cov[1], cov[2]),
                    uncovered: grid.uncovered,
                    blend: ocean.tile_blend(c),
                }
            })
            .collect();
        Self { time, choppiness: lambda, cascades }
    }

    /// The time of the frame (s).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The choppiness `λ` the frame was built with.
    pub fn choppiness(&self) -> f64 {
        self.choppiness
    }

    /// Number of cascades.
    pub fn cascade_count(&self) -> usize {
        self.cascades.len()
    }

    /// The cascades.
    pub fn cascades(&self) -> &[FftCascade] {
        &self.cascades
    }

    /// Cascade `c`.
    ///
    /// # Panics
    /// If `c ≥ cascade_count()` (a programming error).
    pub fn cascade(&self, c: usize) -> &FftCascade {
        &self.cascades[c]
    }

    /// Traced height of the sea, `h̄(x, z) = Σ_c s_c(x, z)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `h̄` (m), within [`FftFrame::height_bounds`].
    ///
    /// # References
    /// Tessendorf 2001; Li Ying et al. 2018, §2.2.
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.cascades.iter().map(|c| c.height(x, z)).sum()
    }

    /// Shading gradient of the sea, `Σ_c ∇h_c` (each cascade's [`FftCascade::gradient`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `(∂h/∂x, ∂h/∂z)` (dimensionless).
    ///
    /// # References
    /// Tessendorf 2001 (the slope sum).
    #[inline]
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        self.cascades.iter().map(|c| c.gradient(x, z)).sum()
    }

    /// Upward unit shading normal `(−∂h/∂x, 1, −∂h/∂z)/√(1 + |∇h|²)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// The normal (unit, `n_y > 0`).
    ///
    /// # References
    /// docs/equations.md §1 (normal of a height field).
    #[inline]
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// Jacobian of the sea's horizontal map, `J ≈ 1 + Σ_c (J_c − 1)`: the cascades' cross products are
    /// neglected, as in Dupuy & Bruneton's whitecap statistics.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    ///
    /// # Returns
    /// `J` (dimensionless).
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10 (`μ = Σ⟨kᵢ⟩`, cross-cascade products neglected).
    #[inline]
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        1.0 + self.cascades.iter().map(|c| c.jacobian(x, z) - 1.0).sum::<f64>()
    }

    /// `(h_min, h_max)` (m): bounds of the traced height, `Σ_c min H_c` and `Σ_c max H_c`.
    pub fn height_bounds(&self) -> (f64, f64) {
        self.cascades.iter().map(FftCascade::height_bounds).fold((0.0, 0.0), |(lo, hi), (a, b)| (lo + a, hi + b))
    }

    /// Certified bound of `|∇h̄|` over the whole sea, `Σ_c L_c`.
    pub fn max_slope(&self) -> f64 {
        self.cascades.iter().map(FftCascade::max_slope).sum()
    }

    /// The fade weight `w_c = smoothstep(1, 1.5, T_c/t)` of cascade `c`, `T_c` its
    /// [`FftCascade::fade_distance`] (1 when the footprint angle is 0).
    ///
    /// # Arguments
    /// - `c`: cascade index, `< cascade_count()`.
    /// - `direction`: unit ray direction; `footprint_angle`: pixel angular width (rad, `≥ 0`).
    /// - `t`: distance along the ray (m), `≥ 0`.
    ///
    /// # Returns
    /// `w_c` (dimensionless, in `[0, 1]`).
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    ///
    /// # References
    /// Bruneton et al. 2010 (seamless transition); docs/equations.md §1.
    pub fn fade_weight(&self, c: usize, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        if footprint_angle > 0.0 {
            footprint_weight(self.cascades[c].fade_distance(direction, footprint_angle), t)
        } else {
            1.0
        }
    }

    /// The height of the surface the tracer draws at `t` (m) along a ray of direction `d̂`
    /// traced with footprint fading: `Σ_c w_c(t) s_c(x, z)` (the traced cascades, each weighted
    /// by its fade).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m).
    /// - `direction`: unit ray direction; `footprint_angle` (rad, 0: no fading) and `t` as traced.
    ///
    /// # Returns
    /// The height (m), within [`FftFrame::height_bounds`].
    ///
    /// # References
    /// Bruneton et al. 2010 (seamless transition); docs/equations.md §1.
    pub fn faded_height(&self, x: f64, z: f64, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        let mut h = 0.0;
        for (c, cascade) in self.cascades.iter().enumerate() {
            let w = self.fade_weight(c, direction, footprint_angle, t);
            if w > 0.0 {
                h += w * cascade.height(x, z);
            }
        }
        h
    }

    /// The shading gradient of the surface the tracer drew at a hit `t` (m) along a ray of
    /// direction `d̂` traced with footprint fading: `Σ_c w_c(t) ∇h_c`.
    ///
    /// # Arguments
    /// - `x`, `z`: the hit's horizontal position (m).
    /// - `direction`: unit ray direction; `footprint_angle` (rad, 0: no fading) and `t` as traced.
    ///
    /// # Returns
    /// The gradient (dimensionless).
    pub fn faded_gradient(&self, x: f64, z: f64, direction: DVec3, footprint_angle: f64, t: f64) -> DVec2 {
        let mut g = DVec2::ZERO;
        for (c, cascade) in self.cascades.iter().enumerate() {
            let w = self.fade_weight(c, direction, footprint_angle, t);
            if w > 0.0 {
                g += w * cascade.gradient(x, z);
            }
        }
        g
    }

    /// The slope covariance `(⟨ζₓ²⟩, ⟨ζₓζ_z⟩, ⟨ζ_z²⟩)` of the cascades the tracer faded at `t`:
    /// `Σ_c (1 − w_c) ⟨ζζᵀ⟩_c` in world axes (the expected covariance of the un-displaced
    /// cascades), to add to the BRDF's unresolved slope variance.
    ///
    /// # Arguments
    /// - `direction`, `footprint_angle`, `t`: as traced.
    ///
    /// # Returns
    /// `DVec3(xx, xz, zz)` (dimensionless).
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 (seamless transition); docs/equations.md §11.
    pub fn faded_slope_covariance(&self, direction: DVec3, footprint_angle: f64, t: f64) -> DVec3 {
        let mut out = DVec3::ZERO;
        if footprint_angle <= 0.0 {
            return out;
        }
        for (c, cascade) in self.cascades.iter().enumerate() {
            let lost = 1.0 - self.fade_weight(c, direction, footprint_angle, t);
            if lost > 0.0 {
                out += lost * cascade.slope_covariance;
            }
        }
        out
    }
}
