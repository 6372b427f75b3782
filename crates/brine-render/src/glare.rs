//! Glare: the point-spread function of the human eye applied to the HDR image.
//!
//! Darles et al. (2007, §5.1) splat a "glare texture" at the most specular pixels, an artistic
//! heuristic with no equation. Brine uses the physically based alternative of Spencer, Shirley,
//! Zimmerman & Greenberg (1995): the photopic point-spread function `P(θ)` of the eye, convolved
//! with the linear image. The convolution is energy-preserving: each pixel keeps the share of its
//! energy that lands inside it and spreads the rest over the image. The renderer spreads radiance
//! only up to [`GLARE_CLIP_WHITES`] times the exposure's white: a sun disc 10⁵ times brighter
//! than the sky would otherwise veil the whole frame (as it does the eye looking at it); the
//! clip keeps the veil to what a camera lens shows. A stated rendering choice.

/// Radiance spread by the glare filter, in multiples of the exposure's white.
pub const GLARE_CLIP_WHITES: f64 = 64.0;

use std::sync::Arc;

use glam::DVec3;
use rayon::prelude::*;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

/// Photopic point-spread function of the eye (unnormalised, per square degree),
/// `P(θ) = 0.384 f₀ + 0.478 f₁ + 0.138 f₂` with `f₀ = 2.61×10⁶ exp(−(θ/0.02)²)`,
/// `f₁ = 20.91/(θ + 0.02)³`, `f₂ = 72.37/(θ + 0.02)²`.
///
/// # Arguments
/// - `theta_deg`: visual angle from the source (°), `[0, 180]`.
///
/// # Returns
/// The relative intensity (per deg²; only ratios matter after normalisation).
///
/// # References
/// Spencer G., Shirley P., Zimmerman K., Greenberg D. 1995, "Physically-based glare effects for
/// digital images", SIGGRAPH 325–334, Eq. 5–8 (photopic); docs/equations.md §15.
pub fn spencer_photopic_psf(theta_deg: f64) -> f64 {
    let t = theta_deg.max(0.0);
    let f0 = 2.61e6 * (-(t / 0.02).powi(2)).exp();
    let f1 = 20.91 / (t + 0.02).powi(3);
    let f2 = 72.37 / (t + 0.02).powi(2);
    0.384 * f0 + 0.478 * f1 + 0.138 * f2
}

/// `∫₀^{θmax} P(θ) 2πθ dθ` (deg²-weighted), the energy of the PSF within `θmax` degrees,
/// by Simpson's rule in `ln(θ + 0.02)` (the PSF's natural scale).
fn psf_energy(theta_max_deg: f64) -> f64 {
    let (a, b) = ((0.02f64).ln(), (theta_max_deg + 0.02).ln());
    let n = 4000;
    let h = (b - a) / n as f64;
    let f = |u: f64| {
        let s = u.exp();
        let t = s - 0.02;
        spencer_photopic_psf(t) * std::f64::consts::TAU * t * s
    };
    let mut sum = f(a) + f(b);
    for j in 1..n {
        sum += if j % 2 == 1 { 4.0 } else { 2.0 } * f(a + j as f64 * h);
    }
    sum * h / 3.0
}

/// One complex sample of the transforms: `f32` (the PSF's smallest weights are ~10⁻⁹ of the
/// centre's; the filtered radiance is rounded to ~10⁻⁷ of the frame's brightest spread value,
/// far below any output format's step), at half the memory traffic of `f64`.
type C32 = Complex<f32>;

/// `n` zeros, written in parallel (`vec!` writes a non-primitive element one by one, on one
/// thread).
fn zeros(n: usize) -> Vec<C32> {
    (0..n).into_par_iter().map(|_| C32::new(0.0, 0.0)).collect()
}

/// An energy-preserving glare filter for images of one size and pixel angle; reusable across
/// frames (the kernel's transform is computed once).
pub struct Glare {
    width: usize,
    height: usize,
    pw: usize,
    ph: usize,
    /// The kernel's transform, column-major (`x·ph + y`). The kernel is real and even in both
    /// axes, so its transform is real: only the real part is kept.
    kernel_hat: Vec<f32>,
    row_fwd: Arc<dyn Fft<f32>>,
    row_inv: Arc<dyn Fft<f32>>,
    col_fwd: Arc<dyn Fft<f32>>,
    col_inv: Arc<dyn Fft<f32>>,
    /// The image-sized and the transform-sized buffers of [`Self::apply`], kept for the next call
    /// (allocating and zeroing ~15 MB per frame cost more than the transforms).
    scratch: std::sync::Mutex<(Vec<C32>, Vec<C32>)>,
}

impl Glare {
    /// The filter for `width × height` images whose pixels subtend `pixel_angle_rad` radians.
    ///
    /// The weight of an offset `(dx, dy) ≠ 0` is `P(θ) Ω_pixel / E`, `θ = |(dx, dy)|·pixel angle`,
    /// `E` the PSF energy within 90°; the centre keeps `1 − Σ` of the others (the energy that
    /// falls inside the pixel or beyond the image).
    pub fn new(width: usize, height: usize, pixel_angle_rad: f64) -> Self {
        let (pw, ph) = (2 * width, 2 * height);
        let pix_deg = pixel_angle_rad.to_degrees();
        let energy = psf_energy(90.0);
        // The PSF is radial: weights of the quadrant dx, dy ≥ 0, one row per task, summed in a
        // fixed order (the same bits at any thread count).
        let weight = |dx: usize, dy: usize| {
            let theta = ((dx * dx + dy * dy) as f64).sqrt() * pix_deg;
            spencer_photopic_psf(theta) * pix_deg * pix_deg / energy
        };
        let quadrant: Vec<Vec<f64>> =
            (0..height).into_par_iter().map(|dy| (0..width).map(|dx| weight(dx, dy)).collect()).collect();
        let mut kernel = zeros(pw * ph);
        let mut spread = 0.0;
        for (dy, row) in quadrant.iter().enumerate() {
            for (dx, &w) in row.iter().enumerate() {
                if dx == 0 && dy == 0 {
                    continue;
                }
                // The offsets (±dx, ±dy), each once.
                let xs: &[usize] = if dx == 0 { &[0] } else { &[dx, pw - dx] };
                let ys: &[usize] = if dy == 0 { &[0] } else { &[dy, ph - dy] };
                for &iy in ys {
                    for &ix in xs {
                        kernel[iy * pw + ix] = C32::new(w as f32, 0.0);
                        spread += w;
                    }
                }
            }
        }
        kernel[0] = C32::new((1.0 - spread).max(0.0) as f32, 0.0);
        let mut planner = FftPlanner::new();
        let mut g = Self {
            width,
            height,
            pw,
            ph,
            kernel_hat: Vec::new(),
            row_fwd: planner.plan_fft_forward(pw),
            row_inv: planner.plan_fft_inverse(pw),
            col_fwd: planner.plan_fft_forward(ph),
            col_inv: planner.plan_fft_inverse(ph),
            scratch: std::sync::Mutex::new((Vec::new(), Vec::new())),
        };
        let mut cols = zeros(pw * ph);
        g.forward(&mut kernel, ph, &mut cols);
        g.kernel_hat = cols.iter().map(|c| c.re).collect();
        g
    }

    /// Forward 2-D transform of the first `rows` rows of a row-major buffer `pw` wide (the rows
    /// beyond, up to `ph`, are taken as zero), into `cols`, transposed (column-major:
    /// `x·ph + y`), the layout [`Self::inverse`] takes.
    fn forward(&self, data: &mut [C32], rows: usize, cols: &mut [C32]) {
        data[..rows * self.pw].par_chunks_mut(self.pw).for_each(|r| self.row_fwd.process(r));
        let data = &*data;
        cols.par_chunks_mut(self.ph).enumerate().for_each(|(x, c)| {
            for (y, v) in c.iter_mut().enumerate() {
                *v = if y < rows { data[y * self.pw + x] } else { C32::new(0.0, 0.0) };
            }
            self.col_fwd.process(c);
        });
    }

    /// Inverse of [`Self::forward`] (unnormalised), writing the first `rows` rows of the result
    /// into `data` (row-major, `pw` wide).
    fn inverse(&self, cols: &mut [C32], data: &mut [C32], rows: usize) {
        cols.par_chunks_mut(self.ph).for_each(|c| self.col_inv.process(c));
        let cols = &*cols;
        data[..rows * self.pw].par_chunks_mut(self.pw).enumerate().for_each(|(y, r)| {
            for (x, v) in r.iter_mut().enumerate() {
                *v = cols[x * self.ph + y];
            }
            self.row_inv.process(r);
        });
    }

    /// Convolves `pixels` (row-major, `width × height`, linear radiance) with the PSF, spreading
    /// each pixel's radiance only up to `clip` (per channel; `f64::INFINITY` spreads everything):
    /// the part above stays in its pixel. Two channels share one complex transform (the kernel
    /// is real), so three channels cost two.
    pub fn apply(&self, pixels: &mut [DVec3], clip: f64) {
        assert_eq!(pixels.len(), self.width * self.height, "glare: image size mismatch");
        let (w, pw) = (self.width, self.pw);
        let clip = DVec3::splat(clip);
        let n = 1.0 / (self.pw * self.ph) as f64;
        // Only the image's rows are stored; the padding rows of the transform are zeros. One
        // buffer serves both transforms: red and green (real and imaginary parts) first, blue
        // after; each result goes back into `pixels` before the next transform.
        // A poisoned lock only means a panic elsewhere while applying: every element read here
        // is written first (the padding columns and rows included), so the buffers stay usable.
        let mut scratch = self.scratch.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let (buf, spectrum) = &mut *scratch;
        if buf.len() != pw * self.height {
            *buf = zeros(pw * self.height);
            *spectrum = zeros(pw * self.ph);
        }
        for pass in 0..2 {
            buf.par_chunks_mut(pw).zip(pixels.par_chunks(w)).for_each(|(b, row)| {
                for (x, p) in row.iter().enumerate() {
                    let p = p.min(clip);
                    b[x] = if pass == 0 { C32::new(p.x as f32, p.y as f32) } else { C32::new(p.z as f32, 0.0) };
                }
                b[row.len()..].fill(C32::new(0.0, 0.0)); // the padding columns (the last pass's output)
            });
            self.forward(buf, self.height, spectrum);
            spectrum.par_iter_mut().zip(self.kernel_hat.par_iter()).for_each(|(v, k)| *v *= *k);
            self.inverse(spectrum, buf, self.height);
            // The part of each channel above `clip` stays in its pixel: `max(L − clip, 0)`.
            pixels.par_chunks_mut(w).zip(buf.par_chunks(pw)).for_each(|(row, b)| {
                for (p, c) in row.iter_mut().zip(b) {
                    let excess = (*p - clip).max(DVec3::ZERO);
                    let (re, im) = (f64::from(c.re) * n, f64::from(c.im) * n);
                    if pass == 0 {
                        p.x = re.max(0.0) + excess.x;
                        p.y = im.max(0.0) + excess.y;
                    } else {
                        p.z = re.max(0.0) + excess.z;
                    }
                }
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The sheet prints the oracle values to 5 significant digits.
    const ORACLE: f64 = 1e-4;

    #[test]
    fn psf_oracles() {
        // docs/equations.md "Test oracles": P(0, 0.1°, 1°, 10°) = 2.2766e6, 6.4777e3, 19.018, 0.10941.
        assert_relative_eq!(spencer_photopic_psf(0.0), 2.2766e6, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(0.1), 6.4777e3, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(1.0), 19.018, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(10.0), 0.10941, max_relative = ORACLE);
    }

    /// The FFT convolution equals the direct sum `Σ_q w(p − q) L(q)` with the weights of the
    /// definition (PSF per pixel solid angle, centre keeping the rest), on a small random image.
    #[test]
    fn fft_convolution_equals_the_direct_sum() {
        // Two f32 2-D FFTs of a 24 × 18 buffer: each of the log₂(432) ≈ 9 stages rounds by
        // ε₃₂ = 6×10⁻⁸ relative to the spectrum's largest magnitude, the image sum (≈ 160 per
        // channel here); after the 1/432 normalisation that is ~2×10⁻⁷ per pixel, and the f32
        // kernel adds ε₃₂ of each weight. 10⁻⁵ leaves a margin of about 50 (measured: 1.6×10⁻⁷).
        const FFT_ROUNDING: f64 = 1e-5;
        let (w, h) = (12usize, 9usize);
        let pixel = 0.3f64.to_radians();
        let img: Vec<DVec3> = (0..w * h)
            .map(|i| {
                let f = |k: u64| ((i as u64 * 2654435761 + k * 40503) % 1000) as f64 / 1000.0;
                DVec3::new(f(1), f(2), f(3))
            })
            .collect();
        let mut out = img.clone();
        Glare::new(w, h, pixel).apply(&mut out, f64::INFINITY);
        let pix_deg = pixel.to_degrees();
        let energy = psf_energy(90.0);
        let weight = |dx: i64, dy: i64| {
            let theta = ((dx * dx + dy * dy) as f64).sqrt() * pix_deg;
            spencer_photopic_psf(theta) * pix_deg * pix_deg / energy
        };
        let mut spread = 0.0;
        for dy in -(h as i64 - 1)..h as i64 {
            for dx in -(w as i64 - 1)..w as i64 {
                if (dx, dy) != (0, 0) {
                    spread += weight(dx, dy);
                }
            }
        }
        for y in 0..h as i64 {
            for x in 0..w as i64 {
                let mut sum = DVec3::ZERO;
                for qy in 0..h as i64 {
                    for qx in 0..w as i64 {
                        let k = if (qx, qy) == (x, y) { 1.0 - spread } else { weight(x - qx, y - qy) };
                        sum += k * img[(qy * w as i64 + qx) as usize];
                    }
                }
                let got = out[(y * w as i64 + x) as usize];
                assert!((got - sum).abs().max_element() < FFT_ROUNDING, "({x}, {y}): {got} vs {sum}");
            }
        }
    }

    /// A filter reused for a second image (its buffers hold the first one's transforms) gives
    /// the same bits as a fresh filter.
    #[test]
    fn a_reused_filter_gives_the_fresh_filters_result() {
        let (w, h) = (20usize, 14usize);
        let image = |k: u64| -> Vec<DVec3> {
            (0..w * h)
                .map(|i| {
                    let f = |c: u64| ((i as u64 * 2654435761 + c * 40503 + k * 977) % 1000) as f64 / 100.0;
                    DVec3::new(f(1), f(2), f(3))
                })
                .collect()
        };
        let reused = Glare::new(w, h, 0.2f64.to_radians());
        let (mut first, mut second) = (image(1), image(2));
        reused.apply(&mut first, 5.0);
        reused.apply(&mut second, 5.0);
        let mut fresh = image(2);
        Glare::new(w, h, 0.2f64.to_radians()).apply(&mut fresh, 5.0);
        assert_eq!(second, fresh);
        assert_ne!(first, second);
    }

    #[test]
    fn glare_preserves_energy_inside_a_large_margin_and_spreads_a_point() {
        // f32 transforms: ~10 stages of ε₃₂ = 6×10⁻⁸ relative rounding of each output.
        const F32_TRANSFORM: f64 = 1e-6;
        let (w, h) = (40, 30);
        let mut img = vec![DVec3::ZERO; w * h];
        img[15 * w + 20] = DVec3::new(1000.0, 500.0, 250.0);
        let g = Glare::new(w, h, 0.05f64.to_radians());
        g.apply(&mut img, f64::INFINITY);
        let total: DVec3 = img.iter().copied().sum();
        // The kernel sums to 1 (its transform at frequency 0); energy spread beyond the 2° × 1.5°
        // image is lost, a few per cent of the f₂ tail.
        assert_relative_eq!(f64::from(g.kernel_hat[0]), 1.0, max_relative = F32_TRANSFORM);
        assert!(total.x <= 1000.0 * (1.0 + F32_TRANSFORM) && total.x > 900.0, "{total:?}");
        assert_relative_eq!(total.y / total.x, 0.5, max_relative = F32_TRANSFORM);
        // The halo falls off with distance.
        let at = |x: usize| img[15 * w + x].x;
        assert!(at(20) > at(21) && at(21) > at(23) && at(23) > at(27) && at(27) > 0.0);
    }
}
