//! The choppy (horizontally displaced) surface of one cascade resampled on its regular grid.

use crate::FftRestFields;

/// Largest shading slope `|∇h|` kept on the displaced surface (dimensionless, 87° of tilt): near a
/// fold (`J → 0`) the slope `M⁻¹∇h` of the displaced sheet diverges; shading normals are clamped
/// there. The traced heights are not affected.
pub const FFT_MAX_SHADING_SLOPE: f64 = 20.0;

/// Tolerance of the inside test in barycentric coordinates: points on a shared edge belong to
/// both triangles (the upper envelope takes either, they agree there).
const INSIDE_TOLERANCE: f64 = 1e-9;

/// Triangles whose doubled area (in grid cells²) is below this are skipped: they carry no area
/// of the torus (zero-area slivers at a fold's edge).
const MIN_DOUBLE_AREA: f64 = 1e-12;

/// One cascade's surface on its Eulerian grid `x = (iΔ, jΔ)`, row by row.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct EulerianGrid {
    pub(crate) height: Vec<f32>,
    pub(crate) gradient: Vec<[f32; 2]>,
    pub(crate) jacobian: Vec<f32>,
    /// Grid points no displaced triangle covered (filled from the rest grid; 0 in practice).
    pub(crate) uncovered: usize,
}

/// Per-vertex data of the displaced mesh: position (grid units), height, gradient, Jacobian.
#[derive(Debug, Clone, Copy)]
struct Vertex {
    x: f64,
    z: f64,
    h: f64,
    gx: f64,
    gz: f64,
    j: f64,
}

/// The slope `∇ₓh = M⁻¹ ∇ᵤh` of the displaced sheet, `M = I + λ∇D` (symmetric), clamped to
/// [`FFT_MAX_SHADING_SLOPE`].
fn displaced_gradient(f: &FftRestFields, idx: usize, lambda: f64, jac: f64) -> (f64, f64) {
    let (hx, hz) = (f.slope_x[idx], f.slope_z[idx]);
    let (a, b, d) = (1.0 + lambda * f.dxx[idx], lambda * f.dxz[idx], 1.0 + lambda * f.dzz[idx]);
    // adj(M) ∇h = (d hx − b hz, −b hx + a hz); divided by J.
    let (px, pz) = (d * hx - b * hz, a * hz - b * hx);
    let norm = px.hypot(pz);
    if norm == 0.0 {
        return (0.0, 0.0);
    }
    let slope = norm / jac.abs();
    let scale =
        if slope.is_finite() && slope <= FFT_MAX_SHADING_SLOPE { 1.0 / jac } else { FFT_MAX_SHADING_SLOPE / norm };
    (px * scale, pz * scale)
}

/// Resamples the displaced surface `(u + λD(u), h(u))` of one cascade onto the regular grid.
///
/// The displaced grid points form a periodic mesh of triangles (each rest cell split along its
/// diagonal). Every output grid point takes the linear interpolation of the triangle above it;
/// where the surface folds (`J < 0`) and several sheets lie above a point, the highest wins (the
/// upper envelope, what a camera above the sea sees). The map `u ↦ u + λD(u)` of the torus to
/// itself is homotopic to the identity, so its degree is 1 and every point is covered by at least
/// one triangle of positive orientation. The height gradient (clamped near folds) and the
/// Jacobian are interpolated with the same weights. With `λ = 0` the grid is the rest grid.
pub(crate) fn resample(f: &FftRestFields, lambda: f64) -> EulerianGrid {
    let n = f.resolution;
    let nn = n * n;
    if lambda == 0.0 {
        return EulerianGrid {
            height: f.height.iter().map(|&h| h as f32).collect(),
            gradient: f.slope_x.iter().zip(&f.slope_z).map(|(&x, &z)| [x as f32, z as f32]).collect(),
            jacobian: vec![1.0; nn],
            uncovered: 0,
        };
    }
    let inv_dx = n as f64 / f.tile_size;
    let vertices: Vec<Vertex> = (0..nn)
        .map(|idx| {
            let (i, j) = (idx % n, idx / n);
            let jac = f.jacobian(idx, lambda);
            let (gx, gz) = displaced_gradient(f, idx, lambda, jac);
            Vertex {
                x: i as f64 + lambda * f.displacement_x[idx] * inv_dx,
                z: j as f64 + lambda * f.displacement_z[idx] * inv_dx,
                h: f.height[idx],
                gx,
                gz,
                j: jac,
            }
        })
        .collect();
    let mut best = vec![f64::NEG_INFINITY; nn];
    let mut gradient = vec![[0.0f32; 2]; nn];
    let mut jacobian = vec![0.0f32; nn];
    // Vertex (i, j) of the unwrapped mesh, i, j ∈ [0, n].
    let vertex = |i: usize, j: usize| {
        let mut v = vertices[(j % n) * n + i % n];
        if i == n {
            v.x += n as f64;
        }
        if j == n {
            v.z += n as f64;
        }
        v
    };
    for j in 0..n {
        for i in 0..n {
            let (v00, v10, v01, v11) = (vertex(i, j), vertex(i + 1, j), vertex(i, j + 1), vertex(i + 1, j + 1));
            for tri in [[v00, v10, v11], [v00, v11, v01]] {
                rasterise(&tri, n, &mut best, &mut gradient, &mut jacobian);
            }
        }
    }
    let mut uncovered = 0;
    let height = best
        .iter()
        .enumerate()
        .map(|(idx, &h)| {
            if h == f64::NEG_INFINITY {
                uncovered += 1;
                gradient[idx] = [f.slope_x[idx] as f32, f.slope_z[idx] as f32];
                jacobian[idx] = f.jacobian(idx, lambda) as f32;
                f.height[idx] as f32
            } else {
                h as f32
            }
        })
        .collect();
    EulerianGrid { height, gradient, jacobian, uncovered }
}

/// `(v − u) × (p − u)`, twice the signed area of the triangle `u, v, p`.
#[inline]
fn edge(ux: f64, uz: f64, vx: f64, vz: f64, px: f64, pz: f64) -> f64 {
    (vx - ux) * (pz - uz) - (vz - uz) * (px - ux)
}

/// Writes the triangle's interpolated values to the grid points it covers where it is higher than
/// what they hold.
fn rasterise(t: &[Vertex; 3], n: usize, best: &mut [f64], gradient: &mut [[f32; 2]], jacobian: &mut [f32]) {
    let [a, b, c] = *t;
    let area = edge(a.x, a.z, b.x, b.z, c.x, c.z);
    if area.abs() < MIN_DOUBLE_AREA {
        return;
    }
    let inv = 1.0 / area;
    let (x0, x1) = (a.x.min(b.x).min(c.x), a.x.max(b.x).max(c.x));
    let (z0, z1) = (a.z.min(b.z).min(c.z), a.z.max(b.z).max(c.z));
    let mask = n as i64 - 1;
    for iz in (z0.ceil() as i64)..=(z1.floor() as i64) {
        let pz = iz as f64;
        for ix in (x0.ceil() as i64)..=(x1.floor() as i64) {
            let px = ix as f64;
            let wa = edge(b.x, b.z, c.x, c.z, px, pz) * inv;
            let wb = edge(c.x, c.z, a.x, a.z, px, pz) * inv;
            let wc = 1.0 - wa - wb;
            if wa < -INSIDE_TOLERANCE || wb < -INSIDE_TOLERANCE || wc < -INSIDE_TOLERANCE {
                continue;
            }
            let h = wa * a.h + wb * b.h + wc * c.h;
            // n is a power of two: `& mask` is the Euclidean remainder, negative indices included.
            let o = ((iz & mask) * (mask + 1) + (ix & mask)) as usize;
            if h > best[o] {
                best[o] = h;
                gradient[o] = [(wa * a.gx + wb * b.gx + wc * c.gx) as f32, (wa * a.gz + wb * b.gz + wc * c.gz) as f32];
                jacobian[o] = (wa * a.j + wb * b.j + wc * c.j) as f32;
            }
        }
    }
}
