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

use brine_trace::simd::f32x8;

/// Relative error bound of the f32 profile: `|A τ̃ − A τ| ≤ A · PROFILE_ERROR · (1 + 1/√(1 − Q²))`.
///
/// Sources: iteration error ≤ 3×10⁻⁷ (the table of [`ProfileMode::for_steepness`]); f32 rounding
/// of `s_hi` and of the residual, ~2×10⁻⁷ in `θ`, amplified by `|dτ/ds| ≤ 1/√(1 − Q²)`; rounding
/// of the products, a few ulps. `profile_error_is_within_bound` checks it on dense grids of `s`
/// for steepnesses up to 0.99 with a margin of at least 2.
pub const PROFILE_ERROR: f64 = 5.0e-7;

/// How the profile of a group of waves is solved: Newton steps and polynomial degree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ProfileMode {
    /// Newton steps after the start.
    pub iterations: u8,
    /// 0: `|δ| ≤ 0.2` (sin to δ⁵, cos to δ⁶); 1: `|δ| ≤ 0.6` (δ⁹, δ¹⁰); 2: `|δ| ≤ 1` (δ¹³, δ¹⁴).
    pub poly: u8,
    /// Start from the cubic (high steepness).
    pub cubic: bool,
}

impl ProfileMode {
    /// The mode for waves of steepness at most `q_max`.
    ///
    /// Worst iteration error in `cos θ` over `s ∈ [−π, π]` (4001 points, f64), from the start
    /// `δ₀ = Q sin s/(1 − Q cos s)`: `Q = 0.005`, 0 steps: 6.2×10⁻⁸; `Q = 0.15`, 1 step: 2.1×10⁻⁷;
    /// `Q = 0.5`, 2 steps: 2.3×10⁻⁷; `Q = 0.8`, 3 steps: 1.5×10⁻⁷; from the cubic start, `Q = 0.99`,
    /// 3 steps: 9×10⁻¹¹.
    pub fn for_steepness(q_max: f64) -> Self {
        if q_max <= 0.005 {
            Self { iterations: 0, poly: 0, cubic: false }
        } else if q_max <= 0.15 {
            Self { iterations: 1, poly: 0, cubic: false }
        } else if q_max <= 0.5 {
            Self { iterations: 2, poly: 1, cubic: false }
        } else if q_max <= 0.8 {
            Self { iterations: 3, poly: 2, cubic: false }
        } else {
            Self { iterations: 3, poly: 2, cubic: true }
        }
    }
}

/// `(cos δ, sin δ)` by Taylor polynomials (Horner in `δ²`).
macro_rules! cos_sin_small {
    ($d:expr, $poly:expr, $one:expr, $c:ident) => {{
        let d = $d;
        let d2 = d * d;
        match $poly {
            0 => {
                let s = d * (d2 * (d2 * $c(1.0 / 120.0) + $c(-1.0 / 6.0)) + $one);
                let c = d2 * (d2 * (d2 * $c(-1.0 / 720.0) + $c(1.0 / 24.0)) + $c(-0.5)) + $one;
                (c, s)
            }
            1 => {
                let s = d
                    * (d2 * (d2 * (d2 * (d2 * $c(1.0 / 362_880.0) + $c(-1.0 / 5040.0)) + $c(1.0 / 120.0))
                        + $c(-1.0 / 6.0))
                        + $one);
                let c = d2
                    * (d2 * (d2 * (d2 * (d2 * $c(-1.0 / 3_628_800.0) + $c(1.0 / 40320.0)) + $c(-1.0 / 720.0))
                        + $c(1.0 / 24.0))
                        + $c(-0.5))
                    + $one;
                (c, s)
            }
            _ => {
                let s = d
                    * (d2
                        * (d2
                            * (d2
                                * (d2
                                    * (d2 * (d2 * $c(1.0 / 6_227_020_800.0) + $c(-1.0 / 39_916_800.0))
                                        + $c(1.0 / 362_880.0))
                                    + $c(-1.0 / 5040.0))
                                + $c(1.0 / 120.0))
                            + $c(-1.0 / 6.0))
                        + $one);
                let c = d2
                    * (d2
                        * (d2
                            * (d2
                                * (d2
                                    * (d2
                                        * (d2 * $c(1.0 / 87_178_291_200.0) + $c(-1.0 / 479_001_600.0))
                                        + $c(1.0 / 3_628_800.0))
                                    + $c(-1.0 / 40320.0))
                                + $c(1.0 / 720.0))
                            + $c(-1.0 / 24.0))
                        + $c(0.5))
                    * $c(-1.0)
                    + $one;
                (c, s)
            }
        }
    }};
}

/// The profile of 8 waves: `(cos θ, sin θ, 1/(1 − Q cos θ))` per lane.
///
/// # Arguments
/// - `s_hi`, `s_lo`: the horizontal phase `s = s_hi + s_lo` (rad), `s_hi ∈ [−π, π]`,
///   `|s_lo| ≤ 10⁻⁶`.
/// - `q`: steepness per lane, `[0, 0.99]`, at most what `mode` was chosen for.
/// - `mode`: iterations and polynomial degree.
///
/// # Returns
/// `cos θ`, `sin θ` and `1/(1 − Q cos θ)` (the stretch `ds/dθ` inverted), with the error of
/// [`PROFILE_ERROR`].
///
/// # References
/// Equation sheet §1 (`τ_Q(s) = cos θ` with `θ − Q sin θ = s`; Newton step); Thon & Ghazanfarpour 2002.
#[inline]
pub(crate) fn profile8(s_hi: f32x8, s_lo: f32x8, q: f32x8, mode: ProfileMode) -> (f32x8, f32x8, f32x8) {
    let one = f32x8::splat(1.0);
    let c = f32x8::splat;
    let (ss, cs) = s_hi.sin_cos();
    let mut delta = if mode.cubic {
        // θ³ + pθ − r = 0 with p = 6(1 − Q)/Q, r = 6s/Q: Cardano's real root.
        let inv_q = one / q.max(c(1e-3));
        let p = c(6.0) * (one - q) * inv_q;
        let r = c(6.0) * s_hi * inv_q;
        let disc = (c(0.25) * r * r + p * p * p * c(1.0 / 27.0)).sqrt();
        let theta = (c(0.5) * r + disc).cbrt() + (c(0.5) * r - disc).cbrt();
        theta - s_hi
    } else {
        q * ss / (one - q * cs)
    };
    delta = delta.max(-q).min(q);
    let rot = |delta: f32x8| {
        let (cd, sd) = cos_sin_small!(delta, mode.poly, one, c);
        (cs * cd - ss * sd, ss * cd + cs * sd)
    };
    for _ in 0..mode.iterations {
        let (ct, st) = rot(delta);
        let residual = delta - q * st - s_lo;
        delta -= residual / (one - q * ct);
    }
    let (ct, st) = rot(delta);
    (ct, st, one / (one - q * ct))
}

/// The scalar twin of [`profile8`] (same algorithm in f32), for single components.
///
/// # Arguments
/// As [`profile8`], one lane.
///
/// # Returns
/// As [`profile8`].
#[inline]
pub(crate) fn profile1(s_hi: f32, s_lo: f32, q: f32, mode: ProfileMode) -> (f32, f32, f32) {
    let one = 1.0f32;
    let c = |x: f32| x;
    let (ss, cs) = s_hi.sin_cos();
    let mut delta = if mode.cubic {
        let inv_q = 1.0 / q.max(1e-3);
        let p = 6.0 * (1.0 - q) * inv_q;
        let r = 6.0 * s_hi * inv_q;
        let disc = (0.25 * r * r + p * p * p / 27.0).sqrt();
        let theta = (0.5 * r + disc).cbrt() + (0.5 * r - disc).cbrt();
        theta - s_hi
    } else {
        q * ss / (1.0 - q * cs)
    };
    delta = delta.clamp(-q, q);
    let rot = |delta: f32| {
        let (cd, sd) = cos_sin_small!(delta, mode.poly, one, c);
        (cs * cd - ss * sd, ss * cd + cs * sd)
    };
    for _ in 0..mode.iterations {
        let (ct, st) = rot(delta);
        let residual = delta - q * st - s_lo;
        delta -= residual / (1.0 - q * ct);
    }
    let (ct, st) = rot(delta);
    (ct, st, 1.0 / (1.0 - q * ct))
}

/// Splits a phase (rad, any finite value) into `(s_hi, s_lo)`: reduced to `[−π, π]` in f64, then
/// the nearest f32 and the f32 of the remainder.
#[inline]
pub(crate) fn split_phase(s: f64) -> (f32, f32) {
    use std::f64::consts::TAU;
    let r = s - TAU * (s * (1.0 / TAU)).round();
    let hi = r as f32;
    (hi, (r - f64::from(hi)) as f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve_trochoid_phase;

    /// Largest steepness of each mode's range, and a few inside.
    const STEEPNESSES: [f64; 12] = [0.0, 0.003, 0.005, 0.05, 0.15, 0.3, 0.5, 0.65, 0.8, 0.9, 0.95, 0.99];

    #[test]
    fn profile_error_is_within_bound() {
        for &q in &STEEPNESSES {
            let mode = ProfileMode::for_steepness(q);
            let bound = PROFILE_ERROR * (1.0 + 1.0 / (1.0 - q * q).sqrt());
            let (mut worst, mut worst_inv) = (0.0f64, 0.0f64);
            for j in 0..20_000 {
                // Phases far from the origin too: the f64 reduction must keep them exact.
                let s = -3.2 + 6.4 * j as f64 / 20_000.0 + 2.0e3 * std::f64::consts::TAU;
                let (hi, lo) = split_phase(s);
                let (_, c_ref, s_ref) = solve_trochoid_phase(s, q);
                let lanes = f32x8::splat(hi);
                let (c8, s8, i8) = profile8(lanes, f32x8::splat(lo), f32x8::splat(q as f32), mode);
                let (c1, s1, i1) = profile1(hi, lo, q as f32, mode);
                for (c, sn, inv) in [(c8.to_array()[3], s8.to_array()[3], i8.to_array()[3]), (c1, s1, i1)] {
                    worst = worst.max((f64::from(c) - c_ref).abs()).max((f64::from(sn) - s_ref).abs());
                    let inv_ref = 1.0 / (1.0 - q * c_ref);
                    worst_inv = worst_inv.max((f64::from(inv) - inv_ref).abs() / inv_ref);
                }
            }
            eprintln!("Q = {q}: worst {worst:.2e}, stretch {worst_inv:.2e}, bound {bound:.2e}");
            assert!(worst <= 0.5 * bound, "Q = {q}: error {worst:e} vs bound {bound:e}");
            assert!(worst_inv <= 0.5 * bound / (1.0 - q), "Q = {q}: stretch error {worst_inv:e}");
        }
    }

    #[test]
    fn split_phase_is_exact_to_f64_rounding() {
        for &s in &[0.0, 1.0, -3.14, 1.0e4, -7.77e5] {
            let (hi, lo) = split_phase(s);
            let back = f64::from(hi) + f64::from(lo);
            let r = s - std::f64::consts::TAU * (s / std::f64::consts::TAU).round();
            assert!((back - r).abs() < 1e-13, "{s}");
        }
    }
}
