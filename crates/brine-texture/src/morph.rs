//! Morphing interpolation along a transition link (Lai & Wu §III.A, Fig. 3, their ref. [12]):
//! an automatic mesh correspondence between two frames, an affine map per mesh triangle, and a
//! warp of both frames to the in-between mesh blended by the morph parameter.

use rayon::prelude::*;

use crate::{Grid, Texture};

/// Largest vertex displacement of a correspondence, as a fraction of the mesh spacing `g`.
///
/// No triangle of the mesh folds over for any displacement below `g(√2 − 1)/2 ≈ 0.207 g`: for
/// the right-angled vertex `A` of a half cell with legs `g`, moving each vertex by at most `ε`
/// changes `2·Area = (B − A) × (C − A) = g²` by at most `2·g·2ε + 4ε²`, which stays below `g²`
/// while `ε < g(√2 − 1)/2`; the other two vertices see the same triangle.
pub const MAX_DISPLACEMENT: f64 = 0.2;

/// Correspondence between two frames `a` and `b` of the same size: the mesh vertex `V` of `a` (a
/// regular grid of spacing `g`, toroidal) corresponds to `V + δ_V` in `b`.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshCorrespondence {
    spacing: usize,
    cols: usize,
    rows: usize,
    displacement: Vec<[f64; 2]>,
}

impl MeshCorrespondence {
    /// The identity correspondence (all displacements zero).
    ///
    /// # Panics
    /// If `spacing` is zero or does not divide both sizes.
    pub fn identity(width: usize, height: usize, spacing: usize) -> Self {
        assert!(
            spacing > 0 && width.is_multiple_of(spacing) && height.is_multiple_of(spacing),
            "mesh spacing {spacing} must divide {width}×{height}"
        );
        let (cols, rows) = (width / spacing, height / spacing);
        Self { spacing, cols, rows, displacement: vec![[0.0; 2]; cols * rows] }
    }

    /// Estimates the correspondence automatically: for each vertex, the integer displacement
    /// `δ` with `|δ| ≤ 0.2 g` ([`MAX_DISPLACEMENT`]) that minimises the sum of squared intensity
    /// differences over a `g × g` block centred on the vertex (every other texel, toroidal),
    /// ties to the shortest `δ`; then one smoothing pass (each `δ` averaged with its four
    /// neighbours, which keeps `|δ| ≤ 0.2 g`).
    ///
    /// # Panics
    /// If the frames' sizes differ or `spacing` does not divide them.
    pub fn estimate(a: &Texture, b: &Texture, spacing: usize) -> Self {
        assert!(a.width() == b.width() && a.height() == b.height(), "morph frames differ in size");
        let mut m = Self::identity(a.width(), a.height(), spacing);
        let (ia, ib) = (a.intensity(), b.intensity());
        let g = spacing as isize;
        let radius = MAX_DISPLACEMENT * spacing as f64;
        let r = radius.floor() as isize;
        let mut shifts: Vec<(isize, isize)> = (-r..=r)
            .flat_map(|dy| (-r..=r).map(move |dx| (dx, dy)))
            .filter(|&(dx, dy)| ((dx * dx + dy * dy) as f64) <= radius * radius)
            .collect();
        shifts.sort_by_key(|&(dx, dy)| (dx * dx + dy * dy, dy, dx));
        let ssd = |vx: isize, vy: isize, dx: isize, dy: isize, ia: &Grid, ib: &Grid| -> f64 {
            let mut s = 0.0f64;
            for j in (-g / 2..g / 2).step_by(2) {
                for i in (-g / 2..g / 2).step_by(2) {
                    let e = ia.get_wrapped(vx + i, vy + j) - ib.get_wrapped(vx + i + dx, vy + j + dy);
                    s += f64::from(e * e);
                }
            }
            s
        };
        let raw: Vec<[f64; 2]> = (0..m.cols * m.rows)
            .into_par_iter()
            .map(|k| {
                let (vx, vy) = ((k % m.cols) as isize * g, (k / m.cols) as isize * g);
                let mut best = (f64::INFINITY, (0, 0));
                for &(dx, dy) in &shifts {
                    let s = ssd(vx, vy, dx, dy, &ia, &ib);
                    if s < best.0 {
                        best = (s, (dx, dy));
                    }
                }
                [best.1.0 as f64, best.1.1 as f64]
            })
            .collect();
        let (c, r) = (m.cols, m.rows);
        for k in 0..c * r {
            let (x, y) = (k % c, k / c);
            let n = [
                raw[k],
                raw[y * c + (x + 1) % c],
                raw[y * c + (x + c - 1) % c],
                raw[((y + 1) % r) * c + x],
                raw[((y + r - 1) % r) * c + x],
            ];
            m.displacement[k] = [n.iter().map(|d| d[0]).sum::<f64>() / 5.0, n.iter().map(|d| d[1]).sum::<f64>() / 5.0];
        }
        m
    }

    /// Mesh spacing `g` (texels).
    pub fn spacing(&self) -> usize {
        self.spacing
    }

    /// The displacement `δ` of every vertex (texels), row-major over the vertex grid.
    pub fn displacements(&self) -> &[[f64; 2]] {
        &self.displacement
    }

    /// Largest `|δ|` (texels).
    pub fn max_displacement(&self) -> f64 {
        self.displacement.iter().map(|d| d[0].hypot(d[1])).fold(0.0, f64::max)
    }

    /// The morph of `a` into `b` at `alpha`: the in-between mesh `V + α δ_V`; for each of its
    /// triangles the affine maps to the triangle `V` in `a` and `V + δ_V` in `b`; every texel
    /// takes `(1 − α) a(A⁻¹x) + α b(B⁻¹x)` (bilinear samples, toroidal).
    ///
    /// `alpha = 0` returns `a` and `alpha = 1` returns `b` (both maps are then the identity).
    ///
    /// # Arguments
    /// - `a`, `b`: the two frames (the sizes of this correspondence).
    /// - `alpha`: morph parameter, `[0, 1]` (clamped).
    ///
    /// # Returns
    /// The in-between frame (levels), the size of `a`.
    ///
    /// # References
    /// Lai & Wu §III.A and Fig. 3 ("frame `F_i` and `F_j` are warped to each other by computing the
    /// affine mesh mapping and both are blended together"); Wolberg G. 1990, *Digital Image
    /// Warping* (triangle-mesh warping).
    pub fn morph(&self, a: &Texture, b: &Texture, alpha: f64) -> Texture {
        let alpha = alpha.clamp(0.0, 1.0);
        let (w, h) = (a.width(), a.height());
        let g = self.spacing as f64;
        let (c, r) = (self.cols, self.rows);
        let vertex = |x: usize, y: usize| -> ([f64; 2], [f64; 2]) {
            let d = self.displacement[(y % r) * c + x % c];
            ([x as f64 * g, y as f64 * g], d)
        };
        // Every triangle: its in-between vertices, its vertices in `a` and in `b`.
        let mut triangles = Vec::with_capacity(2 * c * r);
        for cy in 0..r {
            for cx in 0..c {
                let quad = [vertex(cx, cy), vertex(cx + 1, cy), vertex(cx + 1, cy + 1), vertex(cx, cy + 1)];
                for tri in [[0, 1, 2], [0, 2, 3]] {
                    let v = tri.map(|t| quad[t]);
                    let at = |s: f64| v.map(|(base, d)| [base[0] + s * d[0], base[1] + s * d[1]]);
                    let (p, pa, pb) = (at(alpha), at(0.0), at(1.0));
                    let area = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
                    if area.abs() > 1e-12 {
                        triangles.push((p, pa, pb, area));
                    }
                }
            }
        }
        const BAND: usize = 16;
        let (af, bf) = (1.0 - alpha as f32, alpha as f32);
        let mut out = vec![[0.0f32; 3]; w * h];
        out.par_chunks_mut(BAND * w).enumerate().for_each(|(band, rows)| {
            let (lo, hi) = (band * BAND, (band * BAND + rows.len() / w) as isize);
            for (p, pa, pb, area) in &triangles {
                let ys = p.iter().map(|q| q[1]);
                let y0 = ys.clone().fold(f64::INFINITY, f64::min).floor() as isize;
                let y1 = ys.fold(f64::NEG_INFINITY, f64::max).ceil() as isize;
                let x0 = p.iter().map(|q| q[0]).fold(f64::INFINITY, f64::min).floor() as isize;
                let x1 = p.iter().map(|q| q[0]).fold(f64::NEG_INFINITY, f64::max).ceil() as isize;
                for y in y0..=y1 {
                    let row = y.rem_euclid(h as isize);
                    if row < lo as isize || row >= hi {
                        continue;
                    }
                    let fy = y as f64;
                    for x in x0..=x1 {
                        let fx = x as f64;
                        let edge = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (fy - a[1]) - (b[1] - a[1]) * (fx - a[0]);
                        let l0 = edge(p[1], p[2]) / area;
                        let l1 = edge(p[2], p[0]) / area;
                        let l2 = 1.0 - l0 - l1;
                        const INSIDE: f64 = -1e-9;
                        if l0 < INSIDE || l1 < INSIDE || l2 < INSIDE {
                            continue;
                        }
                        let bary = |q: &[[f64; 2]; 3], k: usize| l0 * q[0][k] + l1 * q[1][k] + l2 * q[2][k];
                        let ta = a.sample(bary(pa, 0), bary(pa, 1));
                        let tb = b.sample(bary(pb, 0), bary(pb, 1));
                        let k = (row as usize - lo) * w + x.rem_euclid(w as isize) as usize;
                        rows[k] = std::array::from_fn(|ch| (af * ta[ch] + bf * tb[ch]).clamp(0.0, 255.0));
                    }
                }
            }
        });
        Texture::from_texels_unchecked(w, h, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pattern(shift: f64) -> Texture {
        Texture::from_fn(64, 64, |i, j| {
            let x = std::f64::consts::TAU * (i as f64 - shift) / 64.0;
            let y = std::f64::consts::TAU * j as f64 / 64.0;
            let v = 128.0 + 60.0 * x.sin() * (2.0 * y).cos() + 30.0 * (3.0 * x + y).cos();
            [v as f32, (v * 0.8) as f32, 200.0]
        })
    }

    /// Bilinear resampling at lattice points is exact up to f32 rounding.
    const EXACT: f32 = 1e-3;

    #[test]
    fn ends_of_the_morph_are_the_frames() {
        let (a, b) = (pattern(0.0), pattern(3.0));
        let m = MeshCorrespondence::estimate(&a, &b, 16);
        for (alpha, f) in [(0.0, &a), (1.0, &b)] {
            let out = m.morph(&a, &b, alpha);
            let err = out
                .texels()
                .iter()
                .zip(f.texels())
                .flat_map(|(x, y)| (0..3).map(move |k| (x[k] - y[k]).abs()))
                .fold(0.0, f32::max);
            assert!(err < EXACT, "alpha = {alpha}: max error {err}");
        }
    }

    /// Block matching tries integer shifts, so a translation by 3 texels is found exactly, and
    /// smoothing a constant field keeps it: only the `f64` averaging's round-off remains.
    const SHIFT_TEXELS: f64 = 1e-9;

    #[test]
    fn a_translation_is_recovered_and_the_midpoint_is_sharp() {
        let (a, b) = (pattern(0.0), pattern(3.0));
        let m = MeshCorrespondence::estimate(&a, &b, 16);
        for d in m.displacements() {
            assert!((d[0] - 3.0).abs() < SHIFT_TEXELS && d[1].abs() < SHIFT_TEXELS, "{d:?}");
        }
        // The morph at ½ is the pattern shifted by 1.5, not a blurred cross-fade.
        let mid = m.morph(&a, &b, 0.5);
        let truth = pattern(1.5);
        let err = crate::frame_distance(&mid, &truth);
        let fade = crate::frame_distance(&mid, &a).min(crate::frame_distance(&mid, &b));
        // A cross-fade would be about as far from the half-way shift as from the ends (ratio ~1);
        // the warp differs from it only by the bilinear resampling of a smooth pattern.
        const SHARP_MIDPOINT: f64 = 0.05;
        assert!(err < SHARP_MIDPOINT * fade, "morph error {err} vs distance to the ends {fade}");
    }
}
