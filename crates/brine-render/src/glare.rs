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
/// digital images", SIGGRAPH 325–334, Eq. 5–8 (photopic); equation sheet §15.
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

/// An energy-preserving glare filter for images of one size and pixel angle; reusable across
/// frames (the kernel's transform is computed once).
pub struct Glare {
    width: usize,
    height: usize,
    pw: usize,
    ph: usize,
    kernel_hat: Vec<Complex<f64>>,
    row_fwd: Arc<dyn Fft<f64>>,
    row_inv: Arc<dyn Fft<f64>>,
    col_fwd: Arc<dyn Fft<f64>>,
    col_inv: Arc<dyn Fft<f64>>,
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
        let mut kernel = vec![Complex::new(0.0, 0.0); pw * ph];
        let mut spread = 0.0;
        for dy in -(height as i64 - 1)..=(height as i64 - 1) {
            for dx in -(width as i64 - 1)..=(width as i64 - 1) {
                if dx == 0 && dy == 0 {
                    continue;
                }
                let theta = ((dx * dx + dy * dy) as f64).sqrt() * pix_deg;
                let w = spencer_photopic_psf(theta) * pix_deg * pix_deg / energy;
                spread += w;
                let (ix, iy) = (dx.rem_euclid(pw as i64) as usize, dy.rem_euclid(ph as i64) as usize);
                kernel[iy * pw + ix] = Complex::new(w, 0.0);
            }
        }
        kernel[0] = Complex::new((1.0 - spread).max(0.0), 0.0);
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
        };
        g.fft2(&mut kernel, false);
        g.kernel_hat = kernel;
        g
    }

    /// In-place 2-D transform of a `pw × ph` row-major buffer (rows, then columns).
    fn fft2(&self, data: &mut [Complex<f64>], inverse: bool) {
        let (row, col) = if inverse { (&self.row_inv, &self.col_inv) } else { (&self.row_fwd, &self.col_fwd) };
        data.par_chunks_mut(self.pw).for_each(|r| row.process(r));
        let mut cols = vec![Complex::new(0.0, 0.0); self.pw * self.ph];
        for y in 0..self.ph {
            for x in 0..self.pw {
                cols[x * self.ph + y] = data[y * self.pw + x];
            }
        }
        cols.par_chunks_mut(self.ph).for_each(|c| col.process(c));
        for x in 0..self.pw {
            for y in 0..self.ph {
                data[y * self.pw + x] = cols[x * self.ph + y];
            }
        }
    }

    /// Convolves `pixels` (row-major, `width × height`, linear radiance) with the PSF, spreading
    /// each pixel's radiance only up to `clip` (per channel; `f64::INFINITY` spreads everything):
    /// the part above stays in its pixel. Two channels share one complex transform (the kernel
    /// is real), so three channels cost two.
    pub fn apply(&self, pixels: &mut [DVec3], clip: f64) {
        assert_eq!(pixels.len(), self.width * self.height, "glare: image size mismatch");
        let excess: Vec<DVec3> = pixels.iter().map(|p| (*p - DVec3::splat(clip)).max(DVec3::ZERO)).collect();
        for (p, e) in pixels.iter_mut().zip(&excess) {
            *p -= *e;
        }
        let n = (self.pw * self.ph) as f64;
        let mut rg = vec![Complex::new(0.0, 0.0); self.pw * self.ph];
        let mut b = vec![Complex::new(0.0, 0.0); self.pw * self.ph];
        for y in 0..self.height {
            for x in 0..self.width {
                let p = pixels[y * self.width + x];
                rg[y * self.pw + x] = Complex::new(p.x, p.y);
                b[y * self.pw + x] = Complex::new(p.z, 0.0);
            }
        }
        for buf in [&mut rg, &mut b] {
            self.fft2(buf, false);
            for (v, k) in buf.iter_mut().zip(&self.kernel_hat) {
                *v *= *k;
            }
            self.fft2(buf, true);
        }
        for y in 0..self.height {
            for x in 0..self.width {
                let (c, d) = (rg[y * self.pw + x] / n, b[y * self.pw + x] / n);
                let i = y * self.width + x;
                pixels[i] = DVec3::new(c.re.max(0.0), c.im.max(0.0), d.re.max(0.0)) + excess[i];
            }
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
        // Equation sheet "Test oracles": P(0, 0.1°, 1°, 10°) = 2.2766e6, 6.4777e3, 19.018, 0.10941.
        assert_relative_eq!(spencer_photopic_psf(0.0), 2.2766e6, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(0.1), 6.4777e3, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(1.0), 19.018, max_relative = ORACLE);
        assert_relative_eq!(spencer_photopic_psf(10.0), 0.10941, max_relative = ORACLE);
    }

    #[test]
    fn glare_preserves_energy_inside_a_large_margin_and_spreads_a_point() {
        let (w, h) = (40, 30);
        let mut img = vec![DVec3::ZERO; w * h];
        img[15 * w + 20] = DVec3::new(1000.0, 500.0, 250.0);
        let g = Glare::new(w, h, 0.05f64.to_radians());
        g.apply(&mut img, f64::INFINITY);
        let total: DVec3 = img.iter().copied().sum();
        // The kernel sums to 1 (its transform at frequency 0); energy spread beyond the 2° × 1.5°
        // image is lost, a few per cent of the f₂ tail.
        assert_relative_eq!(g.kernel_hat[0].re, 1.0, max_relative = 1e-12);
        assert!(total.x <= 1000.0 * (1.0 + 1e-9) && total.x > 900.0, "{total:?}");
        assert_relative_eq!(total.y / total.x, 0.5, max_relative = 1e-9);
        // The halo falls off with distance.
        let at = |x: usize| img[15 * w + x].x;
        assert!(at(20) > at(21) && at(21) > at(23) && at(23) > at(27) && at(27) > 0.0);
    }
}
