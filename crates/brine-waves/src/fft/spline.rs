//! A periodic interpolating cubic B-spline on a square grid, with certified bounds of its value,
//! slope and curvature: the traced surface of one FFT cascade.

/// Pole of the cubic B-spline prefilter, `z₁ = √3 − 2` (Unser 1999).
const POLE: f64 = -0.267_949_192_431_122_7;

/// Terms of the periodic initialisation sums: `|z₁|⁴⁰ ≈ 10⁻²³`, below the rounding of any sample.
const INIT_TERMS: usize = 40;

/// Relative inflation of the certified bounds, for the rounding of the f64 evaluation (a few ulps
/// of the 16 coefficients and of the cell coordinates).
const BOUND_INFLATION: f64 = 1.0 + 1e-12;

/// The periodic cubic B-spline `s(x, z) = Σᵢⱼ cᵢⱼ β₃(x/Δ − i) β₃(z/Δ − j)` whose coefficients are
/// prefiltered so that it interpolates the grid samples, `s(iΔ, jΔ) = Hᵢⱼ`.
///
/// **Bounds**: see [`crate::FftCascade`] for the proof; `a`, `b`, `C` are the largest magnitudes of
/// the line-wise quadratic splines of the differences (exact per line), `A`, `B` the largest second
/// differences, all from the stored (f32) coefficients, the ones evaluated.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SplineGrid {
    n: usize,
    mask: i64,
    inv_spacing: f64,
    coef: Vec<f32>,
    pub(crate) min: f64,
    pub(crate) max: f64,
    /// `a`, `b`: bounds of `|∂s/∂x|`, `|∂s/∂z|`.
    pub(crate) slope: (f64, f64),
    /// `A`, `B`, `C`: bounds of `|∂²s/∂x²|`, `|∂²s/∂z²|`, `|∂²s/∂x∂z|`.
    pub(crate) curvature: (f64, f64, f64),
}

/// The cubic B-spline weights of the four taps `i₀ − 1 … i₀ + 2` at fraction `t ∈ [0, 1)`, and
/// their derivatives.
#[inline]
fn weights(t: f64) -> ([f64; 4], [f64; 4]) {
    let t2 = t * t;
    let t3 = t2 * t;
    let u = 1.0 - t;
    (
        [u * u * u / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0],
        [-0.5 * u * u, 1.5 * t2 - 2.0 * t, -1.5 * t2 + t + 0.5, 0.5 * t2],
    )
}

/// Periodic prefilter of one line in place: `c = 6 (z + 4 + z⁻¹)⁻¹ f`, the coefficients whose
/// spline interpolates `f` (causal and anti-causal first-order recursions with periodic
/// initialisation).
fn prefilter_line(f: &mut [f64]) {
    let n = f.len();
    let terms = INIT_TERMS.min(n);
    let norm = 1.0 / (1.0 - POLE.powi(n as i32));
    // c⁺(0) = Σ_{k≥0} z₁ᵏ f(−k), periodic.
    let mut zk = 1.0;
    let mut acc = 0.0;
    for k in 0..terms {
        acc += zk * f[(n - k) % n];
        zk *= POLE;
    }
    let mut plus = vec![0.0; n];
    plus[0] = acc * norm;
    for k in 1..n {
        plus[k] = f[k] + POLE * plus[k - 1];
    }
    // c⁻(N − 1) = −Σ_{j≥0} z₁^{j+1} c⁺(N − 1 + j), periodic.
    let mut zj = POLE;
    let mut acc = 0.0;
    for j in 0..terms {
        acc -= zj * plus[(n - 1 + j) % n];
        zj *= POLE;
    }
    f[n - 1] = 6.0 * acc * norm;
    let mut minus = acc * norm;
    for k in (0..n - 1).rev() {
        minus = POLE * (minus - plus[k]);
        f[k] = 6.0 * minus;
    }
}

/// `max |q|` of the periodic quadratic spline `q(u) = Σₖ dₖ β₂(u − k − ½)` of coefficients `dₖ`:
/// on the unit segment `[m, m + 1]`, `q = ½(1−t)² d_{m−1} + ½(1 + 2t − 2t²) d_m + ½t² d_{m+1}`, a
/// quadratic in `t` whose largest magnitude is at an end or at its vertex.
fn quadratic_spline_max(d: &[f64]) -> f64 {
    let n = d.len();
    let mut best = 0.0f64;
    for m in 0..n {
        let (p, q, r) = (d[(m + n - 1) % n], d[m], d[(m + 1) % n]);
        let (alpha, beta, gamma) = (0.5 * (p - 2.0 * q + r), q - p, 0.5 * (p + q));
        best = best.max(gamma.abs()).max((alpha + beta + gamma).abs());
        if alpha != 0.0 {
            let t = -beta / (2.0 * alpha);
            if t > 0.0 && t < 1.0 {
                best = best.max(((alpha * t + beta) * t + gamma).abs());
            }
        }
    }
    best
}

impl SplineGrid {
    /// The spline interpolating `samples` (`n × n`, row by row, `[j·n + i]` at `(iΔ, jΔ)`).
    pub(crate) fn new(samples: &[f32], n: usize, spacing: f64) -> Self {
        let mut c: Vec<f64> = samples.iter().map(|&v| f64::from(v)).collect();
        for row in c.chunks_mut(n) {
            prefilter_line(row);
        }
        let mut column = vec![0.0; n];
        for i in 0..n {
            for j in 0..n {
                column[j] = c[j * n + i];
            }
            prefilter_line(&mut column);
            for j in 0..n {
                c[j * n + i] = column[j];
            }
        }
        let coef: Vec<f32> = c.iter().map(|&v| v as f32).collect();
        let at = |i: usize, j: usize| f64::from(coef[(j % n) * n + i % n]);
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut aa, mut bb) = (0.0f64, 0.0f64);
        for j in 0..n {
            for i in 0..n {
                let v = at(i + 1, j + 1);
                min = min.min(v);
                max = max.max(v);
                aa = aa.max((at(i + 2, j + 1) - 2.0 * v + at(i, j + 1)).abs());
                bb = bb.max((at(i + 1, j + 2) - 2.0 * v + at(i + 1, j)).abs());
            }
        }
        // First derivatives and the mixed one: quadratic splines of the differences, line by line.
        let (mut a, mut b, mut cc) = (0.0f64, 0.0f64, 0.0f64);
        let mut line = vec![0.0; n];
        for j in 0..n {
            for (i, d) in line.iter_mut().enumerate() {
                *d = at(i + 1, j) - at(i, j);
            }
            a = a.max(quadratic_spline_max(&line));
            for (i, d) in line.iter_mut().enumerate() {
                *d = at(j, i + 1) - at(j, i);
            }
            b = b.max(quadratic_spline_max(&line));
            for (i, d) in line.iter_mut().enumerate() {
                *d = at(i + 1, j + 1) - at(i, j + 1) - at(i + 1, j) + at(i, j);
            }
            cc = cc.max(quadratic_spline_max(&line));
        }
        let inv = 1.0 / spacing;
        let k = BOUND_INFLATION;
        Self {
            n,
            mask: n as i64 - 1,
            inv_spacing: inv,
            coef,
            min: min - 1e-12 * max.abs().max(min.abs()),
            max: max + 1e-12 * max.abs().max(min.abs()),
            slope: (a * inv * k, b * inv * k),
            curvature: (aa * inv * inv * k, bb * inv * inv * k, cc * inv * inv * k),
        }
    }

    /// `(s, ∂s/∂x, ∂s/∂z)` at `(x, z)` (m, dimensionless).
    #[inline]
    pub(crate) fn value_and_gradient(&self, x: f64, z: f64) -> (f64, f64, f64) {
        let (u, v) = (x * self.inv_spacing, z * self.inv_spacing);
        let (fu, fv) = (u.floor(), v.floor());
        let (wx, dwx) = weights(u - fu);
        let (wz, dwz) = weights(v - fv);
        let (i0, j0) = (fu as i64 - 1, fv as i64 - 1);
        let n = self.n as i64;
        let (mut s, mut sx, mut sz) = (0.0, 0.0, 0.0);
        for b in 0..4 {
            let row = (((j0 + b as i64) & self.mask) * n) as usize;
            let (mut r, mut rx) = (0.0, 0.0);
            for a in 0..4 {
                let c = f64::from(self.coef[row + ((i0 + a as i64) & self.mask) as usize]);
                r += wx[a] * c;
                rx += dwx[a] * c;
            }
            s += wz[b] * r;
            sx += wz[b] * rx;
            sz += dwz[b] * r;
        }
        (s, sx * self.inv_spacing, sz * self.inv_spacing)
    }

    /// `s(x, z)` (m).
    #[inline]
    pub(crate) fn value(&self, x: f64, z: f64) -> f64 {
        let (u, v) = (x * self.inv_spacing, z * self.inv_spacing);
        let (fu, fv) = (u.floor(), v.floor());
        let (wx, _) = weights(u - fu);
        let (wz, _) = weights(v - fv);
        let (i0, j0) = (fu as i64 - 1, fv as i64 - 1);
        let n = self.n as i64;
        let mut s = 0.0;
        for (b, wzb) in wz.iter().enumerate() {
            let row = (((j0 + b as i64) & self.mask) * n) as usize;
            let mut r = 0.0;
            for (a, wxa) in wx.iter().enumerate() {
                r += wxa * f64::from(self.coef[row + ((i0 + a as i64) & self.mask) as usize]);
            }
            s += wzb * r;
        }
        s
    }

    /// Bound of `|∇s·d|` along the horizontal direction `(dₓ, d_z)`: `a|dₓ| + b|d_z|`.
    #[inline]
    pub(crate) fn directional_slope(&self, dx: f64, dz: f64) -> f64 {
        self.slope.0 * dx.abs() + self.slope.1 * dz.abs()
    }

    /// Bound of `|∇s|`: `√(a² + b²)`.
    pub(crate) fn max_slope(&self) -> f64 {
        self.slope.0.hypot(self.slope.1)
    }

    /// Bound of `|d²s/dt²|` along the horizontal direction `(dₓ, d_z)`:
    /// `A dₓ² + 2C|dₓd_z| + B d_z²`.
    #[inline]
    pub(crate) fn directional_curvature(&self, dx: f64, dz: f64) -> f64 {
        let (aa, bb, cc) = self.curvature;
        aa * dx * dx + 2.0 * cc * (dx * dz).abs() + bb * dz * dz
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coefficients are stored in f32: the interpolant meets the samples to ~10⁻⁷ of their
    /// range (order 1 here); 10⁻⁶ with the prefilter's amplification.
    const F32_COEFFICIENTS_ABS: f64 = 1e-6;

    /// The cubic spline's interpolation error of a unit cosine at `kΔ = 0.59`:
    /// `(kΔ)⁴/384 ≈ 3×10⁻⁴`.
    const SPLINE_INTERPOLATION_ABS: f64 = 1e-3;

    /// Four weights summing to 1 (or derivatives to 0): rounding.
    const ROUND_ABS: f64 = 1e-15;

    #[test]
    fn the_spline_interpolates_the_samples_and_reproduces_a_low_sinusoid() {
        let n = 32;
        let dx = 0.5;
        let k = std::f64::consts::TAU * 3.0 / (n as f64 * dx);
        let samples: Vec<f32> =
            (0..n * n).map(|idx| ((k * (idx % n) as f64 * dx).cos() + 0.3 * (idx / n) as f64 % 1.7) as f32).collect();
        let s = SplineGrid::new(&samples, n, dx);
        for idx in (0..n * n).step_by(37) {
            let (i, j) = (idx % n, idx / n);
            assert!((s.value(i as f64 * dx, j as f64 * dx) - f64::from(samples[idx])).abs() < F32_COEFFICIENTS_ABS);
        }
        // A pure cosine of 10.7 samples per wavelength is reproduced to O((kΔ)⁴) between samples.
        let wave: Vec<f32> = (0..n * n).map(|idx| (k * (idx % n) as f64 * dx).cos() as f32).collect();
        let s = SplineGrid::new(&wave, n, dx);
        for q in 0..100 {
            let x = q as f64 * 0.137;
            assert!((s.value(x, 1.3) - (k * x).cos()).abs() < SPLINE_INTERPOLATION_ABS, "x = {x}");
        }
    }

    #[test]
    fn weights_sum_to_one_and_derivatives_to_zero() {
        for t in [0.0, 0.13, 0.5, 0.99] {
            let (w, d) = weights(t);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < ROUND_ABS && d.iter().sum::<f64>().abs() < ROUND_ABS);
        }
    }
}
