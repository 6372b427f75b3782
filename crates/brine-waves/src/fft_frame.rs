//! One instant of the FFT ocean: each cascade's surface on its grid, bilinearly interpolated —
//! the surface the tracer draws — with shading gradients, Jacobians and certified bounds.

use std::f64::consts::TAU;

use brine_trace::footprint_weight;
use glam::{DVec2, DVec3};
use rayon::prelude::*;

use crate::fft_resample::resample;
use crate::{FftOcean, FftRestFields};

/// Relative inflation of the certified slope bounds, for the rounding of the f64 bilinear
/// evaluation (a few ulps of the corner values and of the cell coordinates).
const BOUND_INFLATION: f64 = 1.0 + 1e-12;

/// Smallest `|d_y|` used to stretch a pixel footprint along a grazing view (as the renderer's
/// footprint, `brine-render`): beyond 87° from the vertical the stretch stops at `1/√0.05`.
const MIN_GRAZING: f64 = 0.05;

/// One cascade of an [`FftFrame`]: an `N × N` periodic grid of spacing `Δ = L/N` over its tile, and
/// the bilinear interpolants of its height, shading gradient and Jacobian.
///
/// **The traced height** `h̄(x, z)` is the bilinear interpolant of the grid heights `Hᵢⱼ` (the
/// cascade's displaced surface resampled on the grid, see [`FftFrame`]), extended periodically.
///
/// **Certified slope bound** (proof). On a cell `[0, Δ]²`, with `s = x/Δ`, `t = z/Δ`,
/// `h̄ = (1−s)(1−t)H₀₀ + s(1−t)H₁₀ + (1−s)t H₀₁ + st H₁₁`, so
/// `∂h̄/∂x = [(1−t)(H₁₀ − H₀₀) + t(H₁₁ − H₀₁)]/Δ` is an affine function `g(t)` of `t` alone and
/// `∂h̄/∂z = [(1−s)(H₀₁ − H₀₀) + s(H₁₁ − H₁₀)]/Δ` an affine function `f(s)` of `s` alone. Then
/// `|∇h̄|² = g(t)² + f(s)²` is maximal at a corner, where it equals `aᶜ² + bᶜ²` with
/// `aᶜ = max(|H₁₀ − H₀₀|, |H₁₁ − H₀₁|)/Δ`, `bᶜ = max(|H₀₁ − H₀₀|, |H₁₁ − H₁₀|)/Δ`: the bound is
/// exact on the cell. `h̄` is continuous across cells (both neighbours are linear along a shared
/// edge, with the same end values), hence absolutely continuous along any segment, whose
/// derivative is bounded cell by cell: `|h̄(p) − h̄(q)| ≤ L |p − q|` with
/// `L = maxᶜ √(aᶜ² + bᶜ²)`, attained. Along a horizontal unit direction `(dₓ, d_z)`,
/// `|∇h̄·d| ≤ a|dₓ| + b|d_z|` with `a = maxᶜ aᶜ`, `b = maxᶜ bᶜ`, the largest horizontal and vertical
/// differences of the grid. And `min H ≤ h̄ ≤ max H` (convex combinations). The second derivative
/// of `h̄` along a ray is not bounded (the slope jumps across cell edges): the tracer steps on
/// these bounds alone for the cascades.
#[derive(Debug, Clone, PartialEq)]
pub struct FftCascade {
    tile: f64,
    n: usize,
    mask: i64,
    inv_spacing: f64,
    height: Vec<f32>,
    gradient: Vec<[f32; 2]>,
    jacobian: Vec<f32>,
    min: f64,
    max: f64,
    lipschitz: f64,
    lipschitz_x: f64,
    lipschitz_z: f64,
    band: (f64, f64),
    k_longest: f64,
    variance: f64,
    slope_covariance: DVec3,
    uncovered: usize,
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

    /// Traced height `h̄(x, z)` (m): the bilinear interpolant of the grid heights.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite (periodic with the tile).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        let c = self.cell(x, z);
        let h = &self.height;
        Self::lerp2(&c, f64::from(h[c.i00]), f64::from(h[c.i10]), f64::from(h[c.i01]), f64::from(h[c.i11]))
    }

    /// The derivative of the traced height along the horizontal direction `(dx, dz)` at `(x, z)`
    /// (the cell containing the point; one-sided on a cell edge).
    #[inline]
    pub fn directional_derivative(&self, x: f64, z: f64, dx: f64, dz: f64) -> f64 {
        let c = self.cell(x, z);
        let h = |i: usize| f64::from(self.height[i]);
        let gx = ((1.0 - c.t) * (h(c.i10) - h(c.i00)) + c.t * (h(c.i11) - h(c.i01))) * self.inv_spacing;
        let gz = ((1.0 - c.s) * (h(c.i01) - h(c.i00)) + c.s * (h(c.i11) - h(c.i10))) * self.inv_spacing;
        gx * dx + gz * dz
    }

    /// Shading gradient `(∂h/∂x, ∂h/∂z)` at `(x, z)`: the bilinear interpolant of the displaced
    /// surface's exact slopes `M⁻¹∇h` at the grid points (smooth across cells, unlike the traced
    /// interpolant's own facets; clamped to [`crate::FFT_MAX_SHADING_SLOPE`] near folds).
    #[inline]
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
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

    /// Jacobian `J` of the cascade's horizontal map at `(x, z)` (bilinear, dimensionless).
    #[inline]
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        let c = self.cell(x, z);
        let j = &self.jacobian;
        Self::lerp2(&c, f64::from(j[c.i00]), f64::from(j[c.i10]), f64::from(j[c.i01]), f64::from(j[c.i11]))
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

    /// Grid heights `Hᵢⱼ` (m), `[j·N + i]` at `(iΔ, jΔ)`.
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

    /// `(min H, max H)` (m): bounds of the traced height.
    pub fn height_bounds(&self) -> (f64, f64) {
        (self.min, self.max)
    }

    /// Certified bound `L` of `|∇h̄|` (see the type's documentation).
    pub fn max_slope(&self) -> f64 {
        self.lipschitz
    }

    /// Certified bounds `(a, b)` of `|∂h̄/∂x|` and `|∂h̄/∂z|`.
    pub fn max_axis_slopes(&self) -> (f64, f64) {
        (self.lipschitz_x, self.lipschitz_z)
    }

    /// Certified bound of `|∇h̄·d|` along the horizontal part `(dₓ, d_z)` of a direction:
    /// `min(L |d_xz|, a|dₓ| + b|d_z|)`.
    #[inline]
    pub fn directional_max_slope(&self, dx: f64, dz: f64) -> f64 {
        (self.lipschitz * dx.hypot(dz)).min(self.lipschitz_x * dx.abs() + self.lipschitz_z * dz.abs())
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

    /// Distance `T` (m) along a ray of direction `d̂` at which a pixel of angular width
    /// `footprint_angle` (rad) covers the cascade's longest wavelength `λ`:
    /// `T = λ √max(|d_y|, 0.05)/α` (the footprint `αt` stretched by `1/√|d_y|`, the geometric mean
    /// of its two axes on the sea, as the renderer's footprint).
    #[inline]
    pub fn fade_distance(&self, direction: DVec3, footprint_angle: f64) -> f64 {
        self.longest_wavelength() * direction.y.abs().max(MIN_GRAZING).sqrt() / footprint_angle
    }
}

/// The FFT ocean at one instant ([`FftOcean::at_time`]): the sum of its cascades' surfaces,
/// `y = h̄(x, z) = Σ_c h̄_c(x, z)`, each cascade's bilinear interpolant of its grid.
///
/// **Which surface is traced.** With choppiness `λ > 0` each cascade's surface is the displaced
/// sheet `{(u + λD_c(u), h_c(u))}`, which is a height field only where its Jacobian `J_c > 0`.
/// Brine resamples it on the cascade's own grid: the displaced grid points form a periodic mesh
/// of triangles, and each grid point takes the height of the highest triangle above it (the upper
/// envelope where the sheet folds, what a camera above the sea sees); the traced surface is the
/// bilinear interpolant of these heights. So each cascade is a true height field with a certified
/// slope bound ([`FftCascade`]), and the sea is their sum. As with the trochoid sum of Darles et
/// al. (equation sheet §1(a)), the displacements of different cascades do not compose: the sum
/// of displaced cascades is not the displaced sum (a valid, self-consistent surface; the two
/// agree to first order in `λ`). With `λ = 0` it is Tessendorf's height field itself, sampled
/// exactly at the grid points. The resampling is linear on the displaced mesh: its error is
/// `O(Δ²)` times the curvature of the displaced sheet, largest at near-folds.
///
/// **Shading** uses the bilinear interpolant of the displaced sheets' exact slopes at the grid
/// points ([`FftFrame::gradient`]), not the facets of the traced interpolant; **whitecaps** use
/// the grid Jacobians (`brine-whitecap`'s mip-mapped statistics).
///
/// It implements [`brine_trace::LipschitzSum`]: component 0 is `y`, component `c + 1` is
/// `−h̄_c(x, z)`, with the certified bounds of [`FftCascade`].
#[derive(Debug, Clone, PartialEq)]
pub struct FftFrame {
    time: f64,
    choppiness: f64,
    cascades: Vec<FftCascade>,
}

impl FftFrame {
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
                let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
                let (mut l, mut a, mut b) = (0.0f64, 0.0f64, 0.0f64);
                let h = |i: usize, j: usize| f64::from(grid.height[(j % n) * n + i % n]);
                for j in 0..n {
                    for i in 0..n {
                        let h00 = h(i, j);
                        min = min.min(h00);
                        max = max.max(h00);
                        let (h10, h01, h11) = (h(i + 1, j), h(i, j + 1), h(i + 1, j + 1));
                        let ac = (h10 - h00).abs().max((h11 - h01).abs());
                        let bc = (h01 - h00).abs().max((h11 - h10).abs());
                        l = l.max(ac.hypot(bc));
                        a = a.max(ac);
                        b = b.max(bc);
                    }
                }
                let cov = spec.slope_covariance;
                FftCascade {
                    tile: f.tile_size,
                    n,
                    mask: n as i64 - 1,
                    inv_spacing: 1.0 / dx,
                    height: grid.height,
                    gradient: grid.gradient,
                    jacobian: grid.jacobian,
                    min,
                    max,
                    lipschitz: l / dx * BOUND_INFLATION,
                    lipschitz_x: a / dx * BOUND_INFLATION,
                    lipschitz_z: b / dx * BOUND_INFLATION,
                    band: (spec.band.lo, spec.band.hi),
                    k_longest: spec.k_longest,
                    variance: spec.variance,
                    slope_covariance: DVec3::new(cov[0], cov[1], cov[2]),
                    uncovered: grid.uncovered,
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

    /// Traced height `h̄(x, z) = Σ_c h̄_c(x, z)` (m) at horizontal position `(x, z)` (m).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.cascades.iter().map(|c| c.height(x, z)).sum()
    }

    /// Shading gradient `(∂h/∂x, ∂h/∂z)` at `(x, z)`: the sum of the cascades' (see
    /// [`FftCascade::gradient`]).
    #[inline]
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        self.cascades.iter().map(|c| c.gradient(x, z)).sum()
    }

    /// Upward unit shading normal `(−∂h/∂x, 1, −∂h/∂z)/‖·‖` at `(x, z)`.
    #[inline]
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// Jacobian of the sea's horizontal map at `(x, z)`, `J ≈ 1 + Σ_c (J_c − 1)` (dimensionless):
    /// the cascades' products are neglected, as in Dupuy & Bruneton's whitecap statistics.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; equation sheet §10 (`μ = Σ⟨kᵢ⟩`, cross-cascade products neglected).
    #[inline]
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        1.0 + self.cascades.iter().map(|c| c.jacobian(x, z) - 1.0).sum::<f64>()
    }

    /// `(h_min, h_max)` (m): bounds of the traced height, `Σ_c min H_c` and `Σ_c max H_c`.
    pub fn height_bounds(&self) -> (f64, f64) {
        self.cascades.iter().fold((0.0, 0.0), |(lo, hi), c| (lo + c.min, hi + c.max))
    }

    /// Certified bound of `|∇h̄|` over the whole sea, `Σ_c L_c`.
    pub fn max_slope(&self) -> f64 {
        self.cascades.iter().map(|c| c.lipschitz).sum()
    }

    /// The fade weight `smoothstep(1, 1.5, T_c/t)` of cascade `c` at distance `t` (m) along a ray
    /// of direction `d̂` traced with a pixel footprint of `footprint_angle` rad (1 when the angle is
    /// 0), `T_c` its [`FftCascade::fade_distance`].
    ///
    /// # Panics
    /// If `c ≥ cascade_count()`.
    pub fn fade_weight(&self, c: usize, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        if footprint_angle > 0.0 {
            footprint_weight(self.cascades[c].fade_distance(direction, footprint_angle), t)
        } else {
            1.0
        }
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
    /// Bruneton, Neyret & Holzschuch 2010 (seamless transition); equation sheet §11.
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
