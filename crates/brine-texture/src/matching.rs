//! Patch matching: the masked sum of squared differences between a template and every window of
//! an exemplar image, computed for all windows at once with FFT correlations.
//!
//! `D(q) = Σ_u M(u) Σ_c (I_c(q + u) − T_c(u))² = Σ_u M(u) Σ_c I_c(q + u)² − 2 Σ_c (M T_c ⋆ I_c)(q) + Σ_u M(u) Σ_c T_c(u)²`.
//! The first term comes from a summed-area table (the masks are boxes and rings), the
//! correlation from one complex FFT product: packing two channels as `R + iG`, the real part of
//! `Σ_u conj(T_R + iT_G)(u) (I_R + iI_G)(q + u)` is `T_R ⋆ I_R + T_G ⋆ I_G`.

use std::sync::Arc;

use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

use crate::Texture;

/// Which texels of a `p × p` window a distance counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mask {
    /// Every texel.
    Full,
    /// The O-shaped zone: the ring of the given width along the window's four sides.
    Ring(usize),
}

impl Mask {
    /// Whether texel `(i, j)` of a `p × p` window counts.
    #[inline]
    pub(crate) fn contains(self, i: usize, j: usize, p: usize) -> bool {
        match self {
            Mask::Full => true,
            Mask::Ring(r) => i < r || j < r || i + r >= p || j + r >= p,
        }
    }

    /// Number of texels counted in a `p × p` window.
    pub(crate) fn area(self, p: usize) -> usize {
        match self {
            Mask::Full => p * p,
            Mask::Ring(r) => p * p - p.saturating_sub(2 * r).pow(2),
        }
    }
}

/// An exemplar prepared for matching: its spectra and a summed-area table of `Σ_c I_c²`.
pub(crate) struct Exemplar {
    texture: Texture,
    width: usize,
    height: usize,
    /// Spectrum of `I_R + i I_G`, transposed layout (`width` rows of `height`).
    rg_hat: Vec<Complex64>,
    /// Spectrum of `I_B`, transposed layout.
    b_hat: Vec<Complex64>,
    /// Summed-area table of `Σ_c I_c²`, `(width + 1) × (height + 1)`.
    sat: Vec<f64>,
    rows: Arc<dyn Fft<f64>>,
    cols: Arc<dyn Fft<f64>>,
    rows_inv: Arc<dyn Fft<f64>>,
    cols_inv: Arc<dyn Fft<f64>>,
}

/// Transposes the `h × w` row-major `src` into the `w × h` row-major `dst`.
fn transpose(src: &[Complex64], dst: &mut [Complex64], w: usize, h: usize) {
    const B: usize = 32;
    for jb in (0..h).step_by(B) {
        for ib in (0..w).step_by(B) {
            for j in jb..(jb + B).min(h) {
                for i in ib..(ib + B).min(w) {
                    dst[i * h + j] = src[j * w + i];
                }
            }
        }
    }
}

impl Exemplar {
    /// Prepares `texture` (any size ≥ 1×1).
    pub(crate) fn new(texture: &Texture) -> Self {
        let (w, h) = (texture.width(), texture.height());
        let mut planner = FftPlanner::<f64>::new();
        let rows = planner.plan_fft_forward(w);
        let cols = planner.plan_fft_forward(h);
        let rows_inv = planner.plan_fft_inverse(w);
        let cols_inv = planner.plan_fft_inverse(h);
        let mut sat = vec![0.0f64; (w + 1) * (h + 1)];
        for j in 0..h {
            let mut row = 0.0;
            for i in 0..w {
                let t = texture.get(i, j);
                row += t.iter().map(|&v| f64::from(v) * f64::from(v)).sum::<f64>();
                sat[(j + 1) * (w + 1) + i + 1] = sat[j * (w + 1) + i + 1] + row;
            }
        }
        let mut ex = Self {
            texture: texture.clone(),
            width: w,
            height: h,
            rg_hat: Vec::new(),
            b_hat: Vec::new(),
            sat,
            rows,
            cols,
            rows_inv,
            cols_inv,
        };
        let rg: Vec<Complex64> =
            texture.texels().iter().map(|t| Complex64::new(f64::from(t[0]), f64::from(t[1]))).collect();
        let b: Vec<Complex64> = texture.texels().iter().map(|t| Complex64::new(f64::from(t[2]), 0.0)).collect();
        ex.rg_hat = ex.forward(rg, h);
        ex.b_hat = ex.forward(b, h);
        ex
    }

    /// The exemplar texture.
    pub(crate) fn texture(&self) -> &Texture {
        &self.texture
    }

    /// 2D forward FFT of an `h × w` row-major buffer whose rows at and beyond `nonzero_rows` are
    /// zero; returns the spectrum in transposed layout.
    fn forward(&self, mut data: Vec<Complex64>, nonzero_rows: usize) -> Vec<Complex64> {
        let (w, h) = (self.width, self.height);
        self.rows.process(&mut data[..nonzero_rows * w]);
        let mut t = vec![Complex64::new(0.0, 0.0); w * h];
        transpose(&data, &mut t, w, h);
        self.cols.process(&mut t);
        t
    }

    /// 2D inverse FFT of a transposed-layout spectrum; returns the real part, row-major, scaled.
    fn inverse_real(&self, mut spectrum: Vec<Complex64>) -> Vec<f64> {
        let (w, h) = (self.width, self.height);
        self.cols_inv.process(&mut spectrum);
        let mut data = vec![Complex64::new(0.0, 0.0); w * h];
        transpose(&spectrum, &mut data, h, w);
        self.rows_inv.process(&mut data);
        let scale = 1.0 / (w * h) as f64;
        data.iter().map(|c| c.re * scale).collect()
    }

    /// `Σ` of `Σ_c I_c²` over the box `[x, x + bw) × [y, y + bh)`.
    #[inline]
    fn box_sum(&self, x: usize, y: usize, bw: usize, bh: usize) -> f64 {
        let s = |i: usize, j: usize| self.sat[j * (self.width + 1) + i];
        s(x + bw, y + bh) - s(x, y + bh) - s(x + bw, y) + s(x, y)
    }

    /// Number of window positions along x and y for `p × p` windows.
    pub(crate) fn positions(&self, p: usize) -> (usize, usize) {
        (self.width + 1 - p, self.height + 1 - p)
    }

    /// The RMS distance `√(D(q)/(3A))` between `template` (`p × p`, row-major) and every window of
    /// the exemplar, over the texels of `mask` (`A` of them). Row-major over the positions of
    /// [`Exemplar::positions`].
    pub(crate) fn distances(&self, template: &[[f32; 3]], p: usize, mask: Mask) -> Vec<f64> {
        debug_assert_eq!(template.len(), p * p);
        let (w, h) = (self.width, self.height);
        let (nx, ny) = self.positions(p);
        let zero = Complex64::new(0.0, 0.0);
        let mut rg = vec![zero; w * h];
        let mut b = vec![zero; w * h];
        let mut t_sq = 0.0;
        for j in 0..p {
            for i in 0..p {
                if mask.contains(i, j, p) {
                    let t = template[j * p + i];
                    let (r, g, bb) = (f64::from(t[0]), f64::from(t[1]), f64::from(t[2]));
                    rg[j * w + i] = Complex64::new(r, g);
                    b[j * w + i] = Complex64::new(bb, 0.0);
                    t_sq += r * r + g * g + bb * bb;
                }
            }
        }
        let rg_hat = self.forward(rg, p);
        let b_hat = self.forward(b, p);
        let product: Vec<Complex64> =
            (0..w * h).map(|k| rg_hat[k].conj() * self.rg_hat[k] + b_hat[k].conj() * self.b_hat[k]).collect();
        let corr = self.inverse_real(product);
        let area = mask.area(p) as f64 * 3.0;
        let mut out = Vec::with_capacity(nx * ny);
        for qy in 0..ny {
            for qx in 0..nx {
                let i_sq = match mask {
                    Mask::Full => self.box_sum(qx, qy, p, p),
                    Mask::Ring(r) => {
                        let inner = p.saturating_sub(2 * r);
                        self.box_sum(qx, qy, p, p) - self.box_sum(qx + r, qy + r, inner, inner)
                    }
                };
                let d = (i_sq - 2.0 * corr[qy * w + qx] + t_sq).max(0.0);
                out.push((d / area).sqrt());
            }
        }
        out
    }

    /// The same distance as [`Exemplar::distances`] for one window position, computed directly.
    pub(crate) fn distance_at(&self, qx: usize, qy: usize, template: &[[f32; 3]], p: usize, mask: Mask) -> f64 {
        let mut d = 0.0;
        for j in 0..p {
            for i in 0..p {
                if mask.contains(i, j, p) {
                    let a = self.texture.get(qx + i, qy + j);
                    let t = template[j * p + i];
                    for k in 0..3 {
                        let e = f64::from(a[k]) - f64::from(t[k]);
                        d += e * e;
                    }
                }
            }
        }
        (d / (mask.area(p) as f64 * 3.0)).sqrt()
    }

    /// The `p × p` window of the exemplar at `(qx, qy)` (no wrap).
    pub(crate) fn patch(&self, qx: usize, qy: usize, p: usize) -> Vec<[f32; 3]> {
        (0..p).flat_map(|j| (0..p).map(move |i| (i, j))).map(|(i, j)| self.texture.get(qx + i, qy + j)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noise_texture(w: usize, h: usize) -> Texture {
        Texture::from_fn(w, h, |i, j| {
            let x = ((i * 7919 + j * 104_729) % 251) as f32;
            [x, (x * 3.0) % 255.0, ((i * j) % 255) as f32]
        })
    }

    /// FFT round-off on sums of ~10⁸ (255² × 3 × 1000 texels) in f64: about 10⁻⁸ relative.
    const FFT_TOLERANCE: f64 = 1e-6;

    #[test]
    fn fft_distances_match_direct_sums() {
        let tex = noise_texture(40, 33);
        let ex = Exemplar::new(&tex);
        let p = 12;
        let template: Vec<[f32; 3]> = (0..p * p).map(|k| [(k % 200) as f32, 10.0, (k * 3 % 255) as f32]).collect();
        for mask in [Mask::Full, Mask::Ring(3)] {
            let d = ex.distances(&template, p, mask);
            let (nx, ny) = ex.positions(p);
            assert_eq!(d.len(), nx * ny);
            for (qx, qy) in [(0, 0), (nx - 1, ny - 1), (5, 17), (28, 3)] {
                let direct = ex.distance_at(qx, qy, &template, p, mask);
                assert!((d[qy * nx + qx] - direct).abs() <= FFT_TOLERANCE * (1.0 + direct), "{mask:?} at ({qx}, {qy})");
            }
        }
    }

    /// The exemplar's own window by the FFT route: the distance is zero up to the correlation's
    /// round-off (the direct-sum test bounds the FFT route at 10⁻⁶ relative); any other window of
    /// the noise texture is levels away.
    const SELF_DISTANCE: f64 = 1e-6;

    #[test]
    fn a_patch_of_the_exemplar_is_found_at_distance_zero() {
        let tex = noise_texture(32, 32);
        let ex = Exemplar::new(&tex);
        let p = 8;
        let template = ex.patch(11, 6, p);
        let d = ex.distances(&template, p, Mask::Ring(2));
        let (nx, _) = ex.positions(p);
        let best = d.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).unwrap().0;
        assert_eq!((best % nx, best / nx), (11, 6));
        assert!(d[best] < SELF_DISTANCE);
    }
}
