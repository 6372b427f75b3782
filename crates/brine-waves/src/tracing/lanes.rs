//! Wave sums evaluated four waves at a time (`wide::f64x4`), over structure-of-arrays data.
//!
//! The tracer's inner loop is a sum over waves at one point; these kernels load four consecutive
//! waves into SIMD lanes, so the work vectorises over waves. With SSE2 (the baseline `x86_64`
//! target) `f64x4` runs as two 2-lane halves; built with AVX2 it is one 4-lane operation. The
//! trigonometric functions are `wide`'s Cephes-style polynomials (about 1 ulp on the reduced
//! range), so results agree with the scalar path to `~10⁻¹⁵` relative per wave (tested).

use std::f64::consts::TAU;

use wide::f64x4;

use crate::solve_trochoid_phase;

/// Loads `xs[i..i + 4]`.
#[inline(always)]
fn load(xs: &[f64], i: usize) -> f64x4 {
    f64x4::from([xs[i], xs[i + 1], xs[i + 2], xs[i + 3]])
}

/// Reduces `s` to `[−π, π]`: `s − 2π round(s/2π)`.
#[inline(always)]
fn reduce(s: f64x4) -> f64x4 {
    s - f64x4::splat(TAU) * (s * f64x4::splat(1.0 / TAU)).round()
}

/// Halley steps on Kepler's equation `θ − Q sin θ = s`, kept inside the bracket `[s − Q, s + Q]`,
/// until every lane's step is below `10⁻¹³` (at most 8; 5 suffice at `Q = 0.99` from this start).
/// Returns `(cos θ, sin θ)`; the last step `δ` is applied to them to first order
/// (`cos(θ − δ) = cos θ + δ sin θ + O(δ²)`, `δ² < 10⁻²⁶`), which saves one `sin_cos`.
#[inline(always)]
fn kepler(s: f64x4, q: f64x4) -> (f64x4, f64x4) {
    let one = f64x4::ONE;
    let (lo, hi) = (s - q, s + q);
    let (sn, cs) = s.sin_cos();
    let mut theta = (s + q * sn / (one - q * cs)).max(lo).min(hi);
    for _ in 0..8 {
        let (sn, cs) = theta.sin_cos();
        let f = theta - q * sn - s;
        let fp = one - q * cs;
        let step = f / (fp - f64x4::splat(0.5) * f * q * sn / fp);
        if step.abs().simd_lt(f64x4::splat(1e-13)).all() {
            return (cs + step * sn, sn - step * cs);
        }
        theta = (theta - step).max(lo).min(hi);
    }
    let (sn, cs) = theta.sin_cos();
    (cs, sn)
}

/// `Σᵢ Aᵢ profile(sᵢ, i)` with the phase `sᵢ = kxᵢ x + kzᵢ z + offᵢ`: four waves per vector by
/// `lane(s reduced to [−π, π], first index)`, the remainder one by one by `single(sᵢ, i)`.
#[inline(always)]
fn wave_sum(
    (kx, kz, off, amp): (&[f64], &[f64], &[f64], &[f64]),
    x: f64,
    z: f64,
    lane: impl Fn(f64x4, usize) -> f64x4,
    single: impl Fn(f64, usize) -> f64,
) -> f64 {
    let n = kx.len();
    let full = n - n % 4;
    let (xv, zv) = (f64x4::splat(x), f64x4::splat(z));
    let mut acc = f64x4::ZERO;
    let mut i = 0;
    while i < full {
        let s = reduce(load(kx, i) * xv + load(kz, i) * zv + load(off, i));
        acc += load(amp, i) * lane(s, i);
        i += 4;
    }
    let mut h = acc.reduce_add();
    for j in full..n {
        h += amp[j] * single(kx[j] * x + kz[j] * z + off[j], j);
    }
    h
}

/// `Σᵢ Aᵢ cos θᵢ` with `θᵢ − Qᵢ sin θᵢ = kxᵢ x + kzᵢ z + offᵢ`: the trochoid-sum height.
#[inline]
pub(crate) fn trochoid_height(kx: &[f64], kz: &[f64], off: &[f64], amp: &[f64], q: &[f64], x: f64, z: f64) -> f64 {
    wave_sum((kx, kz, off, amp), x, z, |s, i| kepler(s, load(q, i)).0, |s, j| solve_trochoid_phase(s, q[j]).1)
}

/// `cos x` for `x ∈ [−π, π]`: with `y = |x|` folded onto `z ∈ [0, π/2]` (`cos y = −cos(π − y)`),
/// the Taylor series of `cos z` to `z²⁰` (remainder below `(π/2)²²/22! = 1.8×10⁻¹⁷`), in Horner
/// form. Cheaper than a full `sin_cos` when only the cosine is needed.
#[inline(always)]
fn cos_reduced(x: f64x4) -> f64x4 {
    const PI_F: f64 = std::f64::consts::PI;
    let y = x.abs();
    let flip = y.simd_gt(f64x4::splat(0.5 * PI_F));
    let z = flip.select(f64x4::splat(PI_F) - y, y);
    let z2 = z * z;
    // (−1)ⁿ/(2n)! for n = 10 … 1.
    let mut c = f64x4::splat(1.0 / 2_432_902_008_176_640_000.0);
    for coef in [
        -1.0 / 6_402_373_705_728_000.0,
        1.0 / 20_922_789_888_000.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 479_001_600.0,
        -1.0 / 3_628_800.0,
        1.0 / 40_320.0,
        -1.0 / 720.0,
        1.0 / 24.0,
        -0.5,
        1.0,
    ] {
        c = c * z2 + f64x4::splat(coef);
    }
    flip.select(-c, c)
}

/// `Σᵢ Aᵢ cos(kxᵢ x + kzᵢ z + offᵢ)`: the sine-set height.
#[inline]
pub(crate) fn sine_height(kx: &[f64], kz: &[f64], off: &[f64], amp: &[f64], x: f64, z: f64) -> f64 {
    wave_sum((kx, kz, off, amp), x, z, |s, _| cos_reduced(s), |s, _| s.cos())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `cos_reduced` against `f64::cos` on `[−π, π]`: the series remainder 1.8×10⁻¹⁷ plus a few
    /// roundings of terms below 1 (4×10⁻¹⁶ is under 2 ulps of 1).
    const COS_REDUCED_ABS: f64 = 4e-16;

    #[test]
    fn cos_reduced_is_accurate_on_the_reduced_range() {
        for j in -5000..=5000 {
            let x = j as f64 * std::f64::consts::PI / 5000.0;
            let got = cos_reduced(f64x4::splat(x)).to_array()[0];
            assert!((got - x.cos()).abs() < COS_REDUCED_ABS, "x = {x}: {got} vs {}", x.cos());
        }
    }

    /// The lanes' Halley solver against the scalar Newton one: both stop once their step is
    /// below 10⁻¹³ rad and apply it (the lanes to first order, error `δ²` < 10⁻²⁶), so each `θ`
    /// is converged well within that step. The tolerance is that stopping threshold, a wide
    /// margin over what remains (the two reductions of `s` and rounding).
    const KEPLER_LANES_ABS: f64 = 1e-13;

    #[test]
    fn kepler_lanes_agree_with_the_scalar_solver() {
        for q in [0.0, 0.2, 0.6, 0.9, 0.99] {
            for j in -200..200 {
                let s0 = j as f64 * 0.0157 + 0.003;
                let s = f64x4::from([s0, s0 + 1.0, s0 - 2.0, s0 + 3.0]);
                let (c, sn) = kepler(reduce(s), f64x4::splat(q));
                for (lane, &sv) in s.to_array().iter().enumerate() {
                    let (_, cs, ss) = solve_trochoid_phase(sv, q);
                    assert!((c.to_array()[lane] - cs).abs() < KEPLER_LANES_ABS, "q = {q}, s = {sv}");
                    assert!((sn.to_array()[lane] - ss).abs() < KEPLER_LANES_ABS, "q = {q}, s = {sv}");
                }
            }
        }
    }
}
