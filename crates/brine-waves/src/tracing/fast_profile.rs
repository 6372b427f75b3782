//! The trochoid profile `τ_Q(s) = cos θ`, `θ − Q sin θ = s`, in f32 lanes (SIMD) with a stated error.
//!
//! The phase `s` is reduced to `(−π, π]` in f64 by the caller and split into `s_hi + s_lo` (two
//! f32). The kernel writes `θ = s_hi + δ` and solves `δ − Q sin(s_hi + δ) = s_lo` by Newton's
//! method in `δ` (`|δ| ≤ Q`), with `sin(s_hi + δ) = S cos δ + C sin δ` from one `sin_cos(s_hi)` and
//! Taylor polynomials of `cos δ`, `sin δ`: no cancellation between `θ` and `s`, one trigonometric
//! call per lane. The start is one Newton step from `θ = s`, `δ₀ = Q sin s/(1 − Q cos s)`
//! (or, for `Q > 0.8`, the root of the cubic `s = (1 − Q)θ + Qθ³/6`), clamped to `[−Q, Q]`; the
//! number of further steps is chosen per steepness so that the iteration error in `cos θ` is below
//! `3×10⁻⁷` (see [`ProfileMode::for_steepness`]).

// Lane loops index several parallel arrays of one tier at once.
#![allow(clippy::needless_range_loop)]

use wide::f32x8;

/// Relative error bound of the f32 profile: `|A τ̃ − A τ| ≤ A · PROFILE_ERROR · (1 + 1/√(1 − Q²))`.
///
/// Sources: iteration error ≤ 3×10⁻⁷ (the table of [`ProfileMode::for_steepness`]); f32 rounding
/// of `s_hi` and of the residual, ~2×10⁻⁷ in `θ`, amplified by `|dτ/ds| ≤ 1/√(1 − Q²)`; rounding
/// of the products, a few ulps. `profile_error_is_within_bound` checks it on dense grids of `s`
/// for steepnesses up to 0.99 with a margin of at least 2.
pub const PROFILE_ERROR: f64 = 5.0e-7;

/// How the profile of a group of waves is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ProfileMode {
    /// Harmonics of the Fourier–Bessel series (0: Newton's method instead).
    pub harmonics: u8,
    /// Newton steps after the start.
    pub iterations: u8,
    /// 0: `|δ| ≤ 0.2` (sin to δ⁵, cos to δ⁶); 1: `|δ| ≤ 0.6` (δ⁹, δ¹⁰); 2: `|δ| ≤ 1` (δ¹³, δ¹⁴).
    pub poly: u8,
    /// Start from the cubic (high steepness).
    pub cubic: bool,
}

/// Largest steepness evaluated by the series (its harmonics then number at most 9).
pub(crate) const SERIES_MAX_STEEPNESS: f64 = 0.1;

/// The series is cut where the neglected `Σ_{n>m} (1 + n)|aₙ|` falls below this.
const SERIES_TAIL: f64 = 1e-7;

impl ProfileMode {
    /// The mode for waves of steepness at most `q_max`.
    ///
    /// Up to [`SERIES_MAX_STEEPNESS`], the Fourier–Bessel series of [`series_coefficients`] with
    /// as many harmonics as its tail needs. Beyond, Newton's method; worst iteration error in
    /// `cos θ` over `s ∈ [−π, π]` (4001 points, f64), from the start
    /// `δ₀ = Q sin s/(1 − Q cos s)`: `Q = 0.15`, 1 step: 2.1×10⁻⁷; `Q = 0.5`, 2 steps: 2.3×10⁻⁷;
    /// `Q = 0.8`, 3 steps: 1.5×10⁻⁷; from the cubic start, `Q = 0.99`, 3 steps: 9×10⁻¹¹.
    pub fn for_steepness(q_max: f64) -> Self {
        if q_max <= SERIES_MAX_STEEPNESS {
            let a = series_coefficients(q_max, 24);
            let mut m = a.len() - 1;
            let mut tail = 0.0;
            while m > 1 {
                tail += (1.0 + m as f64) * a[m].abs();
                if tail > SERIES_TAIL {
                    break;
                }
                m -= 1;
            }
            if m <= SERIES_MAX_HARMONICS {
                return Self { harmonics: m as u8, iterations: 0, poly: 0, cubic: false };
            }
            Self { harmonics: 0, iterations: 1, poly: 0, cubic: false }
        } else if q_max <= 0.5 {
            Self {
                harmonics: 0,
                iterations: if q_max <= 0.15 { 1 } else { 2 },
                poly: if q_max <= 0.15 { 0 } else { 1 },
                cubic: false,
            }
        } else if q_max <= 0.8 {
            Self { harmonics: 0, iterations: 3, poly: 2, cubic: false }
        } else {
            Self { harmonics: 0, iterations: 3, poly: 2, cubic: true }
        }
    }
}

/// Bessel function `Jₙ(x)` by its power series (accurate for the small `x ≤ 3` used here).
fn bessel_j(n: usize, x: f64) -> f64 {
    let half = 0.5 * x;
    let mut term = half.powi(n as i32) / (1..=n).map(|k| k as f64).product::<f64>();
    let mut sum = term;
    for k in 1..60 {
        term *= -half * half / (k as f64 * (k + n) as f64);
        sum += term;
        if term.abs() < 1e-18 * sum.abs().max(1e-300) {
            break;
        }
    }
    sum
}

/// The Fourier–Bessel series of the trochoid profile (Kepler's equation with eccentricity `Q`):
/// `τ_Q(s) = cos θ = Σₙ aₙ cos(n s)`, `a₀ = −Q/2`, `aₙ = (Jₙ₋₁(nQ) − Jₙ₊₁(nQ))/n`
/// (`= (2/n²) d Jₙ(nQ)/dQ`).
///
/// # Arguments
/// - `q`: steepness `Q`, `[0, 0.5]` (the series converges for `Q < 1`; its coefficients are
///   computed here for small `Q`).
/// - `harmonics`: the largest `n`.
///
/// # Returns
/// `[a₀, a₁, …, a_harmonics]`.
///
/// # References
/// Watson G.N. 1944, *A Treatise on the Theory of Bessel Functions*, §17.2 (Kepler's equation:
/// `cos E = −e/2 + Σ (2/n²) (d/de) Jₙ(ne) cos nM`); docs/equations.md §1 (the profile `τ_Q`).
pub(crate) fn series_coefficients(q: f64, harmonics: usize) -> Vec<f64> {
    let mut a = vec![-0.5 * q];
    for n in 1..=harmonics {
        let x = n as f64 * q;
        a.push((bessel_j(n - 1, x) - bessel_j(n + 1, x)) / n as f64);
    }
    a
}

/// The series of [`series_coefficients`] as the monomial coefficients the kernel evaluates:
/// `[p₀ … p₈, r₀ … r₇]` with `Σ aₙ Tₙ(C) = Σ p_k Cᵏ` and `Σ n aₙ Uₙ₋₁(C) = Σ r_k Cᵏ` (Chebyshev
/// polynomials of the first and second kinds, by their recurrences in f64).
///
/// # Arguments
/// - `q`: steepness, `[0, SERIES_MAX_STEEPNESS]`; `harmonics`: `[1, 8]`.
///
/// # Returns
/// The [`SERIES_ROWS`] coefficients (zeros above the degree).
pub(crate) fn series_polynomials(q: f64, harmonics: usize) -> [f64; SERIES_ROWS] {
    debug_assert!((1..=SERIES_MAX_HARMONICS).contains(&harmonics));
    let a = series_coefficients(q, harmonics);
    let mut out = [0.0; SERIES_ROWS];
    // Tₙ and Uₙ as coefficient vectors (degree ≤ 8).
    let (mut t_prev, mut t_cur) = ([0.0f64; 9], [0.0f64; 9]);
    t_prev[0] = 1.0; // T₀
    t_cur[1] = 1.0; // T₁
    let (mut u_prev, mut u_cur) = ([0.0f64; 9], [0.0f64; 9]);
    u_prev[0] = 1.0; // U₀
    u_cur[1] = 2.0; // U₁
    out[0] += a[0];
    for (n, &an) in a.iter().enumerate().skip(1) {
        // aₙ Tₙ into P (t_cur = Tₙ); n aₙ Uₙ₋₁ into R (u_prev = Uₙ₋₁).
        for k in 0..9 {
            out[k] += an * t_cur[k];
            if k < 8 {
                out[9 + k] += n as f64 * an * u_prev[k];
            }
        }
        // Advance: T_{n+1} = 2C Tₙ − Tₙ₋₁, Uₙ = 2C Uₙ₋₁ − Uₙ₋₂.
        let mut t_next = [0.0; 9];
        let mut u_next = [0.0; 9];
        for k in 0..9 {
            t_next[k] = -t_prev[k] + if k > 0 { 2.0 * t_cur[k - 1] } else { 0.0 };
            u_next[k] = -u_prev[k] + if k > 0 { 2.0 * u_cur[k - 1] } else { 0.0 };
        }
        t_prev = t_cur;
        t_cur = t_next;
        u_prev = u_cur;
        u_cur = u_next;
    }
    out
}

/// Arithmetic of one f32 lane or of eight (the kernel is written once for both).
pub(crate) trait Lane:
    Copy
    + std::ops::Add<Output = Self>
    + std::ops::Sub<Output = Self>
    + std::ops::Mul<Output = Self>
    + std::ops::Div<Output = Self>
    + std::ops::Neg<Output = Self>
{
    fn splat(x: f32) -> Self;
    fn max(self, o: Self) -> Self;
    fn min(self, o: Self) -> Self;
    fn sqrt(self) -> Self;
    fn cbrt(self) -> Self;
}

impl Lane for f32 {
    #[inline(always)]
    fn splat(x: f32) -> Self {
        x
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        f32::max(self, o)
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        f32::min(self, o)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f32::sqrt(self)
    }
    #[inline(always)]
    fn cbrt(self) -> Self {
        f32::cbrt(self)
    }
}

impl Lane for f32x8 {
    #[inline(always)]
    fn splat(x: f32) -> Self {
        f32x8::splat(x)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        f32x8::max(self, o)
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        f32x8::min(self, o)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f32x8::sqrt(self)
    }
    #[inline(always)]
    fn cbrt(self) -> Self {
        f32x8::cbrt(self)
    }
}

/// `(sin r, cos r)` for `|r| ≤ π/4` by Taylor polynomials to `r⁹` and `r¹⁰` (errors below
/// `r¹¹/11! ≤ 1.7×10⁻⁹` and `r¹²/12! ≤ 1.1×10⁻¹⁰`).
#[inline(always)]
fn sin_cos_quarter<T: Lane>(r: T) -> (T, T) {
    // Estrin's scheme in x = r² (short dependency chains): sin r/r = (1 − x/6) + x²(1/120 − x/5040)
    // + x⁴/9!, cos r = (1 − x/2) + x²(1/24 − x/720) + x⁴(1/8! − x/10!).
    let c = T::splat;
    let x = r * r;
    let x2 = x * x;
    let x4 = x2 * x2;
    let s = r * ((c(1.0) - x * c(1.0 / 6.0)) + x2 * (c(1.0 / 120.0) - x * c(1.0 / 5040.0)) + x4 * c(1.0 / 362_880.0));
    let co = (c(1.0) - x * c(0.5))
        + x2 * (c(1.0 / 24.0) - x * c(1.0 / 720.0))
        + x4 * (c(1.0 / 40320.0) - x * c(1.0 / 3_628_800.0));
    (s, co)
}

/// `(cos δ, sin δ)` by Taylor polynomials (Horner in `δ²`): `POLY` 0 for `|δ| ≤ 0.2` (to δ⁵,
/// δ⁶), 1 for `|δ| ≤ 0.6` (δ⁹, δ¹⁰), 2 for `|δ| ≤ 1` (δ¹³, δ¹⁴); errors below 3×10⁻¹⁰.
#[inline(always)]
fn cos_sin_small<T: Lane, const POLY: u8>(d: T) -> (T, T) {
    let c = T::splat;
    let x = d * d;
    match POLY {
        0 => (
            x * (x * (x * c(-1.0 / 720.0) + c(1.0 / 24.0)) + c(-0.5)) + c(1.0),
            d * (x * (x * c(1.0 / 120.0) + c(-1.0 / 6.0)) + c(1.0)),
        ),
        1 => (
            x * (x * (x * (x * (x * c(-1.0 / 3_628_800.0) + c(1.0 / 40320.0)) + c(-1.0 / 720.0)) + c(1.0 / 24.0))
                + c(-0.5))
                + c(1.0),
            d * (x * (x * (x * (x * c(1.0 / 362_880.0) + c(-1.0 / 5040.0)) + c(1.0 / 120.0)) + c(-1.0 / 6.0)) + c(1.0)),
        ),
        _ => {
            let cos = x
                * (x * (x
                    * (x * (x
                        * (x * (x * c(-1.0 / 87_178_291_200.0) + c(1.0 / 479_001_600.0)) + c(-1.0 / 3_628_800.0))
                        + c(1.0 / 40320.0))
                        + c(-1.0 / 720.0))
                    + c(1.0 / 24.0))
                    + c(-0.5))
                + c(1.0);
            let sin = d
                * (x * (x
                    * (x * (x * (x * (x * c(1.0 / 6_227_020_800.0) + c(-1.0 / 39_916_800.0)) + c(1.0 / 362_880.0))
                        + c(-1.0 / 5040.0))
                        + c(1.0 / 120.0))
                    + c(-1.0 / 6.0))
                    + c(1.0));
            (cos, sin)
        }
    }
}

/// A phase reduced in f64 for the f32 kernel: `s = n π/2 + r_hi + r_lo` with `|r_hi| ≤ π/4`,
/// `(cq, sq) = (cos nπ/2, sin nπ/2)`, and `s_full = s − 2π·round(s/2π)` in f32 (cubic start).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Phase<T> {
    pub r_hi: T,
    pub r_lo: T,
    pub cq: T,
    pub sq: T,
    pub s_full: T,
}

/// Reduces one phase (rad, `|s| < 2⁵⁰`) for the kernel; exact to f64 rounding. Branch-free and
/// table-free so that the loop of [`reduce_phases`] vectorises: `n = round(2s/π)`,
/// `m = n − 4 round(n/4) ∈ {−2, …, 2}`, `cos(mπ/2) = 1 − 7m²/6 + m⁴/6`, `sin(mπ/2) = m(4 − m²)/3`.
#[inline(always)]
pub(crate) fn reduce_phase(s: f64) -> (f32, f32, f32, f32, f32) {
    use std::f64::consts::{FRAC_2_PI, FRAC_PI_2};
    const MAGIC: f64 = 6_755_399_441_055_744.0; // 1.5·2⁵²: x + MAGIC − MAGIC rounds to an integer
    let n = (s * FRAC_2_PI + MAGIC) - MAGIC;
    let r = s - n * FRAC_PI_2;
    let m = n - 4.0 * ((0.25 * n + MAGIC) - MAGIC);
    let m2 = m * m;
    let cq = 1.0 + m2 * (m2 - 7.0) * (1.0 / 6.0);
    let sq = m * (4.0 - m2) * (1.0 / 3.0);
    let hi = r as f32;
    let lo = (r - f64::from(hi)) as f32;
    (hi, lo, cq as f32, sq as f32, (r + m * FRAC_PI_2) as f32)
}

/// The profile by Newton's method: `(cos θ, sin θ/(1 − Q cos θ))` with `θ − Q sin θ = s`, for
/// one lane or eight.
///
/// `ITER` Newton steps after the start, Taylor degree `POLY` for the rotations by `δ`, `CUBIC`
/// start for high steepness (see [`ProfileMode`]). The first step of the `POLY = 2` modes rotates
/// by the full polynomial; the others by `θ → θ − Δ` with `cos Δ ≈ 1 − Δ²/2 + Δ⁴/24`,
/// `sin Δ ≈ Δ − Δ³/6 + Δ⁵/120` (error `Δ⁶/720`, `Δ ≤ 0.1` there).
#[inline(always)]
fn kernel<T: Lane, const ITER: u8, const POLY: u8, const CUBIC: bool>(p: Phase<T>, q: T) -> (T, T) {
    let c = T::splat;
    let one = c(1.0);
    let (sr, cr) = sin_cos_quarter(p.r_hi);
    let ss = sr * p.cq + cr * p.sq;
    let cs = cr * p.cq - sr * p.sq;
    let mut delta = if CUBIC {
        // θ³ + pθ − r = 0 with p = 6(1 − Q)/Q, r = 6s/Q: Cardano's real root.
        let inv_q = one / q.max(c(1e-3));
        let pp = c(6.0) * (one - q) * inv_q;
        let r = c(6.0) * p.s_full * inv_q;
        let disc = (c(0.25) * r * r + pp * pp * pp * c(1.0 / 27.0)).sqrt();
        let theta = (c(0.5) * r + disc).cbrt() + (c(0.5) * r - disc).cbrt();
        theta - p.s_full
    } else {
        q * ss / (one - q * cs)
    };
    delta = delta.max(-q).min(q);
    let rotate = |delta: T| {
        let (cd, sd) = cos_sin_small::<T, POLY>(delta);
        (cs * cd - ss * sd, ss * cd + cs * sd)
    };
    let (mut ct, mut st) = rotate(delta);
    for i in 0..ITER {
        let residual = delta - q * st - p.r_lo;
        let step = residual / (one - q * ct);
        delta = delta - step;
        if POLY == 2 && i == 0 {
            (ct, st) = rotate(delta);
        } else {
            let x = step * step;
            let cd = one - x * (c(0.5) - x * c(1.0 / 24.0));
            let sd = step * (one - x * (c(1.0 / 6.0) - x * c(1.0 / 120.0)));
            (ct, st) = (ct * cd + st * sd, st * cd - ct * sd);
        }
    }
    (ct, st / (one - q * ct))
}

/// Rows of the series mode per lane: the value polynomial `P(C) = Σ_{k≤8} p_k Cᵏ` then the
/// derivative polynomial `R(C) = Σ_{k≤7} r_k Cᵏ` (see [`series_polynomials`]).
pub(crate) const SERIES_ROWS: usize = 17;

/// Largest number of harmonics of the series mode (`P` of degree 8).
pub(crate) const SERIES_MAX_HARMONICS: usize = 8;

/// The series mode: `cos θ = Σ aₙ cos(n s) = P(cos s)` and
/// `sin θ/(1 − Q cos θ) = Σ n aₙ sin(n s) = sin s · R(cos s)` (`cos ns = Tₙ(C)`,
/// `sin ns = sin s Uₙ₋₁(C)`), both polynomials evaluated by Estrin's scheme: no division, short
/// dependency chains.
#[inline(always)]
fn series<T: Lane>(p: Phase<T>, coefficient: impl Fn(usize) -> T) -> (T, T) {
    let (sr, cr) = sin_cos_quarter(p.r_hi);
    let ss = sr * p.cq + cr * p.sq;
    let cs = sr * -p.sq + cr * p.cq;
    let c2 = cs * cs;
    let c4 = c2 * c2;
    let k = |i: usize| coefficient(i);
    let value = ((k(0) + k(1) * cs) + (k(2) + k(3) * cs) * c2)
        + ((k(4) + k(5) * cs) + (k(6) + k(7) * cs) * c2) * c4
        + k(8) * (c4 * c4);
    let slope =
        ((k(9) + k(10) * cs) + (k(11) + k(12) * cs) * c2) + ((k(13) + k(14) * cs) + (k(15) + k(16) * cs) * c2) * c4;
    (value, ss * slope)
}

/// Dispatches on the mode (one monomorphised body per Newton mode).
#[inline(always)]
fn kernel_for<T: Lane>(p: Phase<T>, q: T, mode: ProfileMode, coefficient: impl Fn(usize) -> T) -> (T, T) {
    if mode.harmonics > 0 {
        return series(p, coefficient);
    }
    match (mode.iterations, mode.poly, mode.cubic) {
        (0, _, _) => kernel::<T, 0, 0, false>(p, q),
        (1, _, _) => kernel::<T, 1, 0, false>(p, q),
        (2, _, _) => kernel::<T, 2, 1, false>(p, q),
        (_, _, false) => kernel::<T, 3, 2, false>(p, q),
        (_, _, true) => kernel::<T, 3, 2, true>(p, q),
    }
}

/// The profile of 8 waves: `(cos θ, sin θ/(1 − Q cos θ))` per lane, the height `τ_Q(s)` and
/// minus its derivative `dτ_Q/ds`.
///
/// # Arguments
/// - `phase`: the reduced horizontal phases ([`reduce_phases`]).
/// - `q`: steepness per lane, `[0, 0.99]`, at most what `mode` was chosen for.
/// - `series`: per lane, the [`series_polynomials`] (series mode), indexed `[row][lane]`.
/// - `mode`: series or Newton, see [`ProfileMode`].
///
/// # Returns
/// `cos θ` and `sin θ/(1 − Q cos θ)` with the error of [`PROFILE_ERROR`].
///
/// # References
/// docs/equations.md §1 (`τ_Q(s) = cos θ` with `θ − Q sin θ = s`; Newton step); Thon & Ghazanfarpour
/// 2002; Watson 1944 §17.2 (the series).
#[inline(always)]
pub(crate) fn profile8(phase: Phase<f32x8>, q: f32x8, series: &[[f32; 8]], mode: ProfileMode) -> (f32x8, f32x8) {
    kernel_for(phase, q, mode, |n| f32x8::new(series[n]))
}

/// The scalar twin of [`profile8`] (the same code on one lane), for single components.
///
/// # Arguments
/// - `s`: the horizontal phase (rad, any finite value).
/// - `q`, `mode`: as [`profile8`]; `series`, `lane`: the coefficients `series[row][lane]`.
///
/// # Returns
/// As [`profile8`].
#[inline]
#[cfg_attr(not(feature = "tracing"), allow(dead_code))]
pub(crate) fn profile1(s: f64, q: f32, series: &[[f32; 8]], lane: usize, mode: ProfileMode) -> (f32, f32) {
    let (r_hi, r_lo, cq, sq, s_full) = reduce_phase(s);
    kernel_for(Phase { r_hi, r_lo, cq, sq, s_full }, q, mode, |n| series[n][lane])
}

/// Reduces 8 phases into the lanes of a [`Phase`] (the loop vectorises).
#[inline(always)]
pub(crate) fn reduce_phases(s: &[f64; 8]) -> Phase<f32x8> {
    let (mut hi, mut lo, mut cq, mut sq, mut full) = ([0f32; 8], [0f32; 8], [0f32; 8], [0f32; 8], [0f32; 8]);
    for l in 0..8 {
        (hi[l], lo[l], cq[l], sq[l], full[l]) = reduce_phase(s[l]);
    }
    Phase {
        r_hi: f32x8::new(hi),
        r_lo: f32x8::new(lo),
        cq: f32x8::new(cq),
        sq: f32x8::new(sq),
        s_full: f32x8::new(full),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve_trochoid_phase;

    /// Steepnesses at the edges of each mode's range, and a few inside.
    const STEEPNESSES: [f64; 16] =
        [0.0, 0.003, 0.01, 0.023, 0.05, 0.07, 0.1, 0.101, 0.15, 0.3, 0.5, 0.65, 0.8, 0.9, 0.95, 0.99];

    #[test]
    fn profile_error_is_within_bound() {
        for &q in &STEEPNESSES {
            let mode = ProfileMode::for_steepness(q);
            let coefficients: Vec<[f32; 8]> = if mode.harmonics > 0 {
                series_polynomials(q, usize::from(mode.harmonics)).iter().map(|&a| [a as f32; 8]).collect()
            } else {
                Vec::new()
            };
            let bound = PROFILE_ERROR * (1.0 + 1.0 / (1.0 - q * q).sqrt());
            let slope_bound = PROFILE_ERROR * (1.0 + 1.0 / ((1.0 - q) * (1.0 - q)));
            let (mut worst, mut worst_slope) = (0.0f64, 0.0f64);
            for j in 0..20_000 {
                // Phases far from the origin too: the f64 reduction must keep them exact.
                let s = -3.2 + 6.4 * j as f64 / 20_000.0 + 2.0e3 * std::f64::consts::TAU;
                let (_, c_ref, s_ref) = solve_trochoid_phase(s, q);
                let g_ref = s_ref / (1.0 - q * c_ref);
                let (c8, g8) = profile8(reduce_phases(&[s; 8]), f32x8::splat(q as f32), &coefficients, mode);
                let (c1, g1) = profile1(s, q as f32, &coefficients, 5, mode);
                for (c, g) in [(c8.to_array()[3], g8.to_array()[3]), (c1, g1)] {
                    worst = worst.max((f64::from(c) - c_ref).abs());
                    worst_slope = worst_slope.max((f64::from(g) - g_ref).abs());
                }
            }
            eprintln!(
                "Q = {q} ({mode:?}): height {worst:.2e} / {bound:.2e}, slope {worst_slope:.2e} / {slope_bound:.2e}"
            );
            assert!(worst <= 0.5 * bound, "Q = {q}: error {worst:e} vs bound {bound:e}");
            assert!(worst_slope <= 0.5 * slope_bound, "Q = {q}: slope error {worst_slope:e} vs {slope_bound:e}");
        }
    }

    /// The same nine-term series in f64, as cosines of multiples of `s` and as monomials of
    /// `cos s`: rounding only, on values of order 1 (the large monomial coefficients, up to 256 in
    /// `T₈`, multiply `a₈` ~ 10⁻⁸); 10⁻¹² (about 4500 ulps of 1) is a wide margin.
    const SERIES_FORMS_ABS: f64 = 1e-12;

    #[test]
    fn series_polynomials_equal_the_cosine_series() {
        let (q, m) = (0.08, 8);
        let a = series_coefficients(q, m);
        let p = series_polynomials(q, m);
        for j in 0..50 {
            let s = -3.0 + 0.12 * j as f64;
            let (sn, c) = s.sin_cos();
            let direct: f64 = a.iter().enumerate().map(|(n, an)| an * (n as f64 * s).cos()).sum();
            let slope: f64 = a.iter().enumerate().map(|(n, an)| n as f64 * an * (n as f64 * s).sin()).sum();
            let poly: f64 = (0..9).map(|k| p[k] * c.powi(k as i32)).sum();
            let poly_slope: f64 = sn * (0..8).map(|k| p[9 + k] * c.powi(k as i32)).sum::<f64>();
            assert!(
                (direct - poly).abs() < SERIES_FORMS_ABS && (slope - poly_slope).abs() < SERIES_FORMS_ABS,
                "s = {s}"
            );
        }
    }

    /// The expansion's `O(Q³)` remainder at `Q = 10⁻³`: 10⁻⁹ = `Q³`; the largest term it
    /// drops is `−Q³/3` in `a₂` (`a₂ = Q/2 − Q³/3 + …`), 3.3×10⁻¹⁰.
    const EXPANSION_REMAINDER: f64 = 1e-9;

    #[test]
    fn series_matches_its_small_steepness_expansion() {
        // cos θ = −Q/2 + (1 − 3Q²/8) cos s + (Q/2) cos 2s + (3Q²/8) cos 3s + O(Q³).
        let q = 1e-3;
        let a = series_coefficients(q, 3);
        let expected = [-q / 2.0, 1.0 - 3.0 * q * q / 8.0, q / 2.0, 3.0 * q * q / 8.0];
        for (x, e) in a.iter().zip(expected) {
            assert!((x - e).abs() < EXPANSION_REMAINDER, "{a:?}");
        }
    }

    /// Slack of `|r| ≤ π/4` (rad) for the rounding of `n = round(2s/π)` at a tie. None of the
    /// phases tested is near one (the nearest, 2.4, is 0.028 of a quarter turn from it), so the
    /// bound holds with room; at a tie with `|s|` ~ 10⁵ the rounding of `2s/π` could exceed it.
    const QUADRANT_EDGE: f64 = 1e-12;

    /// `(sin, cos)` of `n π/2 + r_hi + r_lo` against those of `s`: at `|s|` ≤ 7.77×10⁵ the f64
    /// `r = s − n·FRAC_PI_2` is off by at most half an ulp of `n π/2` (5.8×10⁻¹¹) plus `n` times
    /// the error of `FRAC_PI_2` (3.0×10⁻¹¹), 8.8×10⁻¹¹ in all (2.7×10⁻¹¹ for −7.77×10⁵); the
    /// `r_hi + r_lo` split adds ~10⁻¹⁵.
    const REDUCTION_ABS: f64 = 1e-10;

    /// `sin(s_full)` against `sin s`: `s_full` (`|s_full|` ≤ 5π/4) is stored in f32, half an ulp
    /// of which is 1.2×10⁻⁷ between 2 and 4; 10⁻⁶ is a margin of 8.
    const FULL_PHASE_F32: f64 = 1e-6;

    #[test]
    fn phase_reduction_is_exact_to_f64_rounding() {
        for &s in &[0.0, 1.0, -3.1, 0.7, 2.4, 1.0e4, -7.77e5] {
            let (hi, lo, cq, sq, full) = reduce_phase(s);
            let r = f64::from(hi) + f64::from(lo);
            let (ss, cs) = s.sin_cos();
            // (cos, sin) of n π/2 + r must be those of s.
            let (sr, cr) = r.sin_cos();
            let back_s = sr * f64::from(cq) + cr * f64::from(sq);
            let back_c = cr * f64::from(cq) - sr * f64::from(sq);
            assert!(r.abs() <= std::f64::consts::FRAC_PI_4 + QUADRANT_EDGE, "{s}");
            assert!((back_s - ss).abs() < REDUCTION_ABS && (back_c - cs).abs() < REDUCTION_ABS, "{s}");
            assert!(
                (f64::from(full).sin() - ss).abs() < FULL_PHASE_F32
                    && f64::from(full).abs() <= 1.25 * std::f64::consts::PI,
                "{s}"
            );
        }
    }
}
