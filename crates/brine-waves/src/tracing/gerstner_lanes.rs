//! The passes of the Gerstner inversion four waves at a time (`wide::f64x4`), over the
//! structure-of-arrays of [`crate::GerstnerSurface`], padded to a multiple of four waves with
//! waves of zero amplitude, zero steepness and zero wave vector (which add exactly nothing).
//!
//! Two passes: the displacement `D(u) = −Σ (Qᵢ/kᵢ²) kᵢ sin φᵢ` (the Newton solve's first guess),
//! and at each Newton step the displacement, the height `Σ Aᵢ cos φᵢ` and the Jacobian
//! `I − Σ (Qᵢ/kᵢ²) kᵢkᵢᵀ cos φᵢ` together, `φᵢ = kᵢ·u + offᵢ`. The sines and cosines are
//! `wide`'s vector `sin_cos` (Cody–Waite reduction by `π/2` in three parts, then minimax
//! polynomials: about 1 ulp for the phases here), so the sums agree with the scalar passes to
//! rounding (`~10⁻¹⁶` relative per term; the test bound is derived in `surfaces/gerstner/mod.rs`). With SSE2
//! (the baseline `x86_64` target) `f64x4` runs as two 2-lane halves.

use glam::DVec2;
use wide::f64x4;

/// Loads `xs[i..i + 4]`.
#[inline(always)]
fn load(xs: &[f64], i: usize) -> f64x4 {
    f64x4::from([xs[i], xs[i + 1], xs[i + 2], xs[i + 3]])
}

/// The padded wave arrays of a Gerstner field at one instant (all of the same length, a multiple
/// of 4): wave vector `(kx, kz)` (rad m⁻¹), phase offset `φ₀ − ωt` (rad), amplitude `A` (m),
/// `Q/k²` (m rad⁻²).
#[derive(Clone, Copy)]
pub(crate) struct LaneWaves<'a> {
    pub kx: &'a [f64],
    pub kz: &'a [f64],
    pub offset: &'a [f64],
    pub amplitude: &'a [f64],
    pub q_over_k2: &'a [f64],
}

/// What one Newton step needs at a rest position: the displacement, the height and the
/// symmetric Jacobian `[[jxx, jxz], [jxz, jzz]]` of `u ↦ u + D(u)`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LaneState {
    pub displacement: DVec2,
    pub height: f64,
    pub jxx: f64,
    pub jxz: f64,
    pub jzz: f64,
}

/// `D(u) = −Σ (Qᵢ/kᵢ²) kᵢ sin(kᵢ·u + offᵢ)` (m).
#[inline]
pub(crate) fn displacement(w: LaneWaves<'_>, u: DVec2) -> DVec2 {
    debug_assert!(w.kx.len().is_multiple_of(4));
    let (ux, uz) = (f64x4::splat(u.x), f64x4::splat(u.y));
    let (mut dx, mut dz) = (f64x4::ZERO, f64x4::ZERO);
    let mut i = 0;
    while i < w.kx.len() {
        let (kx, kz) = (load(w.kx, i), load(w.kz, i));
        let (sn, _) = (kx * ux + kz * uz + load(w.offset, i)).sin_cos();
        let r = load(w.q_over_k2, i) * sn;
        dx -= r * kx;
        dz -= r * kz;
        i += 4;
    }
    DVec2::new(dx.reduce_add(), dz.reduce_add())
}

/// Displacement, height and Jacobian at rest position `u` in one pass over the waves.
#[inline]
pub(crate) fn state(w: LaneWaves<'_>, u: DVec2) -> LaneState {
    debug_assert!(w.kx.len().is_multiple_of(4));
    let (ux, uz) = (f64x4::splat(u.x), f64x4::splat(u.y));
    let (mut dx, mut dz, mut h) = (f64x4::ZERO, f64x4::ZERO, f64x4::ZERO);
    let (mut jxx, mut jxz, mut jzz) = (f64x4::ZERO, f64x4::ZERO, f64x4::ZERO);
    let mut i = 0;
    while i < w.kx.len() {
        let (kx, kz) = (load(w.kx, i), load(w.kz, i));
        let (sn, c) = (kx * ux + kz * uz + load(w.offset, i)).sin_cos();
        let q = load(w.q_over_k2, i);
        let r = q * sn;
        dx -= r * kx;
        dz -= r * kz;
        h += load(w.amplitude, i) * c;
        let qc = q * c;
        jxx -= qc * kx * kx;
        jxz -= qc * kx * kz;
        jzz -= qc * kz * kz;
        i += 4;
    }
    LaneState {
        displacement: DVec2::new(dx.reduce_add(), dz.reduce_add()),
        height: h.reduce_add(),
        jxx: 1.0 + jxx.reduce_add(),
        jxz: jxz.reduce_add(),
        jzz: 1.0 + jzz.reduce_add(),
    }
}
