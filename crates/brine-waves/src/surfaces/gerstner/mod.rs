//! The true sum of Gerstner waves as a height field, by inverting the horizontal displacement.

use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

use crate::error::WaveError;
use crate::tracing::gerstner_lanes::{self, LaneState, LaneWaves};
use crate::{TrochoidSet, WaveSurface};

mod fading;

pub use fading::FadedWaves;
#[cfg(feature = "tracing")]
pub(crate) use fading::WarmStart;

/// Absolute part of the inversion tolerance (m): the residual `|u + D(u) − x|` the Newton solve
/// of [`GerstnerField::solve`] reaches. The relative part `10⁻¹⁴ (|x| + Σ Aᵢ)` covers rounding
/// in far-away coordinates.
pub const GERSTNER_TOLERANCE_M: f64 = 1e-12;

/// Relative part of the inversion tolerance: the stopping rule is
/// `|u + D(u) − x| ≤ GERSTNER_TOLERANCE_M + GERSTNER_TOLERANCE_REL (|x| + Σ Aᵢ)`.
pub const GERSTNER_TOLERANCE_REL: f64 = 1e-14;

/// Iteration cap of the inversion (2–3 iterations are usual; the property tests never reach it).
pub const GERSTNER_MAX_ITERATIONS: usize = 64;

/// The sum of Gerstner waves with all horizontal displacements composed, as Bruneton et al. 2010,
/// Crest and Blender draw it (docs/equations.md §1(b)):
///
/// `P(u, t) = (u − Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ, Σ Aᵢ cos φᵢ)`, `φᵢ = kᵢ d̂ᵢ·u − ωᵢt + φ₀ᵢ`.
///
/// The height at a world point `x` needs the rest position `u` with `u + D(u) = x`, found by a
/// damped Newton solve in `u` ([`GerstnerField::solve`]: tolerance [`GERSTNER_TOLERANCE_M`],
/// at most [`GERSTNER_MAX_ITERATIONS`] iterations). The map `u ↦ x` has the symmetric Jacobian
/// `J = I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos φᵢ`, whose eigenvalues lie in `[1 − ΣQ, 1 + ΣQ]`: while
/// `Σ Qᵢ < 1` it is a diffeomorphism and the height field exists. Then
/// `∇ₓh = J⁻¹ ∇ᵤh`, `|∇ₓh| ≤ ρ*` ([`GerstnerSurface::slope_bound`], docs/equations.md §1(b):
/// the exact `kA/√(1 − Q²)` for one wave, below the simpler `Σ kᵢAᵢ/(1 − Σ Qᵢ)`).
///
/// [`GerstnerField::height`] runs the inversion's passes over the waves one at a time;
/// [`GerstnerField::height_lanes`] (and [`WaveSurface::heights`]) four at a time in
/// `wide::f64x4` lanes, with the same Newton iteration and stopping rule.
///
/// # References
/// Gerstner F. 1802; Tessendorf 2001, §3.2; Bruneton E., Neyret F., Holzschuch N. 2010,
/// "Real-time realistic ocean lighting using seamless transitions from geometry to BRDF", CGF
/// 29(2); docs/equations.md §1(b) and §10.
///
/// The wave arrays are padded to a multiple of four with inert waves (`A = Q = 0`, `k = 0`) for
/// the SIMD passes; the scalar passes stop at the real count.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GerstnerSurface {
    n: usize,
    kx: Vec<f64>,
    kz: Vec<f64>,
    omega: Vec<f64>,
    phase: Vec<f64>,
    amplitude: Vec<f64>,
    /// `Qᵢ/kᵢ²`: times `(kx, kz)` gives the horizontal radius vector `(Qᵢ/kᵢ) d̂ᵢ`.
    q_over_k2: Vec<f64>,
    total_amplitude: f64,
    total_steepness: f64,
    slope_bound: f64,
}

impl GerstnerSurface {
    /// The Gerstner surface of `set`.
    ///
    /// # Errors
    /// [`WaveError::TooSteep`] if `Σ Qᵢ > 0.99`: the surface may fold and no height field exists.
    pub fn new(set: &TrochoidSet) -> Result<Self, WaveError> {
        let total_steepness = set.total_steepness();
        if !(total_steepness <= crate::MAX_STEEPNESS) {
            return Err(WaveError::TooSteep { total_steepness, limit: crate::MAX_STEEPNESS });
        }
        let mut s = Self { total_steepness, ..Self::default() };
        for w in set.waves() {
            let d = w.direction_vector();
            let k = w.wavenumber();
            s.kx.push(k * d.x);
            s.kz.push(k * d.y);
            s.omega.push(w.omega());
            s.phase.push(w.phase());
            s.amplitude.push(w.amplitude());
            s.q_over_k2.push(w.steepness() / (k * k));
            s.total_amplitude += w.amplitude();
        }
        s.n = s.kx.len();
        s.slope_bound = slope_bound_of(set.waves().iter().map(|w| (w.wavenumber() * w.amplitude(), w.steepness())), 3);
        while !s.kx.len().is_multiple_of(4) {
            for v in [&mut s.kx, &mut s.kz, &mut s.omega, &mut s.phase, &mut s.amplitude, &mut s.q_over_k2] {
                v.push(0.0);
            }
        }
        Ok(s)
    }

    /// Number of waves.
    pub fn len(&self) -> usize {
        self.n
    }

    /// `true` for a flat sea.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// `Σ Qᵢ` (dimensionless), below 0.99.
    pub fn total_steepness(&self) -> f64 {
        self.total_steepness
    }

    /// `Σ Aᵢ` (m).
    pub fn total_amplitude(&self) -> f64 {
        self.total_amplitude
    }

    /// The Lipschitz constant of the height field: `L = ρ*`, the root of
    /// `Σ √((kᵢAᵢ)² + ρ²Qᵢ²) = ρ` (the bound of `slope_bound_of`); `Q/√(1 − Q²)` for one wave with
    /// `Q = kA`, where it is attained, and at most the cruder `Σ kᵢAᵢ/(1 − Σ Qᵢ)`.
    ///
    /// # Returns
    /// `L` (dimensionless), `≥ |∇ₓh|` everywhere.
    ///
    /// # References
    /// docs/equations.md §1(b) (derived: `∇ₓh = J⁻¹∇ᵤh`, `|∇ᵤh| ≤ Σ kᵢAᵢ|sin φᵢ|`,
    /// `λ_min(J) ≥ 1 − Σ Qᵢ max(cos φᵢ, 0)`).
    pub fn slope_bound(&self) -> f64 {
        self.slope_bound
    }

    /// The surface frozen at time `t` (s).
    ///
    /// Each wave's phase offset `φ₀ − ωt` is reduced to `[0, 2π]` once here: unreduced, at
    /// `t = 10⁶ s` it is 10⁷ rad, and every sine of the sum pays a slow argument reduction (a
    /// frame took 7 times as long as at `t = 0`).
    pub fn at_time(&self, t: f64) -> GerstnerField<'_> {
        let offset = self.omega.iter().zip(&self.phase).map(|(w, p)| (p - w * t).rem_euclid(TAU)).collect();
        GerstnerField { surface: self, offset }
    }
}

/// The result of inverting the horizontal displacement at one world point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inversion {
    /// Rest position `u` (m) with `u + D(u) = x`.
    pub rest: DVec2,
    /// Residual `|u + D(u) − x|` (m).
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
}

/// Everything [`GerstnerField::point`] gives at one world point, from a single inversion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GerstnerPoint {
    /// The rest position `u` of the particle above the point (m).
    pub rest: DVec2,
    /// `h` (m), as [`GerstnerField::height_lanes`].
    pub height: f64,
    /// `∇ₓh` (dimensionless), as [`GerstnerField::gradient`].
    pub gradient: DVec2,
    /// `D(u)` (m), as [`GerstnerField::displacement`].
    pub displacement: DVec2,
    /// The particle's velocity (m s⁻¹), as [`GerstnerField::velocity`].
    pub velocity: DVec3,
    /// `det J(u)` (dimensionless), as [`GerstnerField::jacobian`].
    pub jacobian: f64,
}

/// Everything the waves give at one rest position.
struct State {
    displacement: DVec2,
    height: f64,
    grad_u: DVec2,
    jxx: f64,
    jxz: f64,
    jzz: f64,
    velocity: DVec3,
}

/// The part of a rest-position state the Newton solve uses.
trait RestState {
    /// `D(u)` (m).
    fn displacement(&self) -> DVec2;
    /// `(jxx, jxz, jzz)` of the symmetric Jacobian of `u ↦ u + D(u)`.
    fn jacobian(&self) -> (f64, f64, f64);

    /// `det J`.
    fn det(&self) -> f64 {
        let (xx, xz, zz) = self.jacobian();
        xx * zz - xz * xz
    }

    /// `J⁻¹ v`.
    fn solve(&self, v: DVec2) -> DVec2 {
        let (xx, xz, zz) = self.jacobian();
        DVec2::new(zz * v.x - xz * v.y, xx * v.y - xz * v.x) / self.det()
    }
}

impl RestState for State {
    fn displacement(&self) -> DVec2 {
        self.displacement
    }
    fn jacobian(&self) -> (f64, f64, f64) {
        (self.jxx, self.jxz, self.jzz)
    }
}

impl RestState for LaneState {
    fn displacement(&self) -> DVec2 {
        self.displacement
    }
    fn jacobian(&self) -> (f64, f64, f64) {
        (self.jxx, self.jxz, self.jzz)
    }
}

/// A [`GerstnerSurface`] frozen at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct GerstnerField<'a> {
    surface: &'a GerstnerSurface,
    offset: Vec<f64>,
}

impl GerstnerField<'_> {
    /// The underlying surface.
    pub fn surface(&self) -> &GerstnerSurface {
        self.surface
    }

    /// Horizontal displacement `D(u) = −Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ` (m) at rest position `u`.
    fn displacement_at_rest(&self, u: DVec2) -> DVec2 {
        self.displacement_scaled(u, |_| 1.0)
    }

    /// [`Self::displacement_at_rest`] with the steepnesses scaled by `w(i)`.
    #[inline]
    fn displacement_scaled(&self, u: DVec2, w: impl Fn(usize) -> f64) -> DVec2 {
        let s = self.surface;
        let mut d = DVec2::ZERO;
        for i in 0..s.len() {
            let wi = w(i);
            if wi == 0.0 {
                continue;
            }
            let sn = (s.kx[i] * u.x + s.kz[i] * u.y + self.offset[i]).sin();
            d -= s.q_over_k2[i] * wi * sn * DVec2::new(s.kx[i], s.kz[i]);
        }
        d
    }

    /// `(Aᵢ, kᵢAᵢ, Qᵢ, Qᵢ/kᵢ)` of wave `i`: amplitude (m), slope, steepness and horizontal radius (m).
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    pub(crate) fn wave_terms(&self, i: usize) -> (f64, f64, f64, f64) {
        let s = self.surface;
        let k = (s.kx[i] * s.kx[i] + s.kz[i] * s.kz[i]).sqrt();
        let q = s.q_over_k2[i] * k * k;
        (s.amplitude[i], k * s.amplitude[i], q, if k > 0.0 { q / k } else { 0.0 })
    }

    fn state(&self, u: DVec2) -> State {
        self.state_scaled(u, |_| 1.0)
    }

    /// [`Self::state`] of the waves with amplitudes and steepnesses scaled by `w(i)`.
    #[inline]
    fn state_scaled(&self, u: DVec2, w: impl Fn(usize) -> f64) -> State {
        let s = self.surface;
        let mut st = State {
            displacement: DVec2::ZERO,
            height: 0.0,
            grad_u: DVec2::ZERO,
            jxx: 1.0,
            jxz: 0.0,
            jzz: 1.0,
            velocity: DVec3::ZERO,
        };
        for i in 0..s.len() {
            let wi = w(i);
            if wi == 0.0 {
                continue;
            }
            let (sn, c) = (s.kx[i] * u.x + s.kz[i] * u.y + self.offset[i]).sin_cos();
            let k = DVec2::new(s.kx[i], s.kz[i]);
            let a = s.amplitude[i] * wi;
            let q = s.q_over_k2[i] * wi;
            st.displacement -= q * sn * k;
            st.height += a * c;
            st.grad_u -= a * sn * k;
            let qc = q * c;
            st.jxx -= qc * k.x * k.x;
            st.jxz -= qc * k.x * k.y;
            st.jzz -= qc * k.y * k.y;
            let h = qc * s.omega[i];
            st.velocity += DVec3::new(h * k.x, a * s.omega[i] * sn, h * k.y);
        }
        st
    }

    /// The surface point of the particle at rest position `u`, `P(u) = (u + D(u), Σ Aᵢ cos φᵢ)`.
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    ///
    /// # Returns
    /// `(x, y, z)` (m).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn forward(&self, u: DVec2) -> DVec3 {
        let st = self.state(u);
        let x = u + st.displacement;
        DVec3::new(x.x, st.height, x.y)
    }

    /// Inverts the horizontal displacement: the rest position `u` with `u + D(u) = x`, whose particle
    /// is above `(x, z)`.
    ///
    /// Damped Newton on `G(u) = u + D(u) − x` from `u₀ = x − D(x)`: each step `J⁻¹G` is halved until
    /// `|G|` decreases (at most 30 halvings; if none decreases, a fixed-point step `u ← x − D(u)`, a
    /// contraction of rate `Σ Qᵢ`, is taken instead). Stops when
    /// `|G| ≤ GERSTNER_TOLERANCE_M + GERSTNER_TOLERANCE_REL (|x| + Σ Aᵢ)` or after
    /// [`GERSTNER_MAX_ITERATIONS`] (2–3 iterations are usual for fitted sets with `Σ Q` up to 0.99).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The rest position (m), the residual `|G|` (m) and the iteration count.
    ///
    /// # References
    /// docs/equations.md §1(b); Nocedal & Wright 2006, *Numerical Optimization*, ch. 11 (Newton with a
    /// line search).
    pub fn solve(&self, x: f64, z: f64) -> Inversion {
        self.solve_state(x, z).0
    }

    /// [`GerstnerField::solve`], also returning the waves' state at the rest position.
    fn solve_state(&self, x: f64, z: f64) -> (Inversion, State) {
        self.invert(x, z, |u| self.displacement_at_rest(u), |u| self.state(u))
    }

    /// The padded wave arrays for the SIMD passes.
    fn lanes(&self) -> LaneWaves<'_> {
        let s = self.surface;
        LaneWaves { kx: &s.kx, kz: &s.kz, offset: &self.offset, amplitude: &s.amplitude, q_over_k2: &s.q_over_k2 }
    }

    /// The damped Newton inversion of [`GerstnerField::solve`], over any evaluation of the waves:
    /// `first(u)` is `D(u)` (for the first guess), `state(u)` everything a step needs.
    fn invert<S: RestState>(
        &self,
        x: f64,
        z: f64,
        first: impl FnOnce(DVec2) -> DVec2,
        state: impl Fn(DVec2) -> S,
    ) -> (Inversion, S) {
        let target = DVec2::new(x, z);
        let tol = GERSTNER_TOLERANCE_M + GERSTNER_TOLERANCE_REL * (target.length() + self.surface.total_amplitude);
        let mut u = target - first(target);
        let mut st = state(u);
        let mut g = u + st.displacement() - target;
        let mut residual = g.length();
        for it in 0..GERSTNER_MAX_ITERATIONS {
            if residual <= tol {
                return (Inversion { rest: u, residual, iterations: it }, st);
            }
            let step = st.solve(g);
            let mut lambda = 1.0;
            let mut accepted = false;
            for _ in 0..30 {
                let cand = u - lambda * step;
                let cand_st = state(cand);
                let cand_g = cand + cand_st.displacement() - target;
                if cand_g.length() < residual {
                    (u, st, g, residual) = (cand, cand_st, cand_g, cand_g.length());
                    accepted = true;
                    break;
                }
                lambda *= 0.5;
            }
            if !accepted {
                u = target - st.displacement();
                st = state(u);
                g = u + st.displacement() - target;
                residual = g.length();
            }
        }
        (Inversion { rest: u, residual, iterations: GERSTNER_MAX_ITERATIONS }, st)
    }

    /// [`GerstnerField::solve`] with the passes over the waves four at a time in SIMD lanes: the same
    /// iteration and stopping rule, the sums rounded in another order.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// As [`GerstnerField::solve`].
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn solve_lanes(&self, x: f64, z: f64) -> Inversion {
        let w = self.lanes();
        self.invert(x, z, |u| gerstner_lanes::displacement(w, u), |u| gerstner_lanes::state(w, u)).0
    }

    /// Height `h(x, z)` (m) with the inversion's passes four waves at a time (`wide::f64x4`):
    /// the same Newton iteration as [`GerstnerField::height`], its sums rounded in another order.
    ///
    /// Both rest positions meet the stopping rule `|u + D(u) − x| ≤ τ`
    /// (`τ = GERSTNER_TOLERANCE_M + 10⁻¹⁴(|x| + ΣA)`): each is the exact rest position of a
    /// world point within `τ` of `x`, so the heights differ by at most `2τ L`, `L` the slope bound
    /// ([`GerstnerSurface::slope_bound`]), plus rounding.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m).
    ///
    /// # Returns
    /// `h` (m).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn height_lanes(&self, x: f64, z: f64) -> f64 {
        let w = self.lanes();
        self.invert(x, z, |u| gerstner_lanes::displacement(w, u), |u| gerstner_lanes::state(w, u)).1.height
    }

    /// Height, gradient, displacement, velocity and Jacobian of the particle above `(x, z)`, from
    /// one inversion: [`GerstnerField::height_lanes`]'s (the height is its, bit for bit), then one
    /// pass over the waves at its rest position for the rest. Each of [`GerstnerField::gradient`],
    /// [`GerstnerField::displacement`], [`GerstnerField::velocity`] and
    /// [`GerstnerField::jacobian`] inverts on its own; this costs about as much as one of them.
    ///
    /// Both inversions meet the stopping rule `|u + D(u) − x| ≤ τ`, so their rest positions are
    /// within `2τ/(1 − ΣQ)` of each other (`‖J⁻¹‖ ≤ 1/(1 − ΣQ)`), and each field differs from the
    /// single function's by at most its derivative with respect to `x` times `2τ`, plus rounding.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The [`GerstnerPoint`].
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn point(&self, x: f64, z: f64) -> GerstnerPoint {
        let w = self.lanes();
        let (inversion, lanes) =
            self.invert(x, z, |u| gerstner_lanes::displacement(w, u), |u| gerstner_lanes::state(w, u));
        let st = self.state(inversion.rest);
        GerstnerPoint {
            rest: inversion.rest,
            height: lanes.height,
            gradient: st.solve(st.grad_u),
            displacement: st.displacement,
            velocity: st.velocity,
            jacobian: st.det(),
        }
    }

    /// [`GerstnerField::point`] of the particle at rest position `u` (m), which needs no
    /// inversion: one pass over the waves at `u`. The point is `u + D(u)`; its fields are those
    /// [`GerstnerField::point`] gives there, within the inversion's tolerance (the height in
    /// the scalar pass's rounding, not the lanes').
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    ///
    /// # Returns
    /// The [`GerstnerPoint`] (its `rest` is `u`).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn point_at_rest(&self, u: DVec2) -> GerstnerPoint {
        let st = self.state(u);
        GerstnerPoint {
            rest: u,
            height: st.height,
            gradient: st.solve(st.grad_u),
            displacement: st.displacement,
            velocity: st.velocity,
            jacobian: st.det(),
        }
    }

    /// Heights at many points, each by [`GerstnerField::height_lanes`].
    ///
    /// # Arguments
    /// - `xs`, `zs`: horizontal positions (m), equal lengths.
    /// - `out`: receives the heights (m), same length.
    ///
    /// # Panics
    /// If the three slices differ in length.
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn heights(&self, xs: &[f64], zs: &[f64], out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = self.height_lanes(x, z);
        }
    }

    /// Rest position `u` of the particle above `(x, z)`, `u + D(u) = (x, z)` ([`GerstnerField::solve`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `u` (m).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn rest_position(&self, x: f64, z: f64) -> DVec2 {
        self.solve(x, z).rest
    }

    fn state_at(&self, x: f64, z: f64) -> State {
        self.solve_state(x, z).1
    }

    /// Height of the Gerstner sum, `h(x) = Σ Aᵢ cos φᵢ(u)` at the rest position `u` of `x`, the passes
    /// over the waves one at a time (the reference for [`GerstnerField::height_lanes`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `h` (m), in `[−ΣAᵢ, ΣAᵢ]`.
    ///
    /// # References
    /// docs/equations.md §1(b); Bruneton et al. 2010.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.state_at(x, z).height
    }

    /// Gradient of the height field, `∇ₓh = J⁻¹ ∇ᵤh` with `∇ᵤh = −Σ Aᵢ kᵢ d̂ᵢ sin φᵢ`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `∇h` (dimensionless), `|∇h| ≤` [`GerstnerSurface::slope_bound`].
    ///
    /// # References
    /// docs/equations.md §1(b) (chain rule through the inversion).
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        let st = self.state_at(x, z);
        st.solve(st.grad_u)
    }

    /// Horizontal displacement `D(u) = −Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ` of the particle above `(x, z)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `D` (m).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn displacement(&self, x: f64, z: f64) -> DVec2 {
        self.state_at(x, z).displacement
    }

    /// Jacobian determinant `det J(u)`, `J = I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos φᵢ`, at the particle above `(x, z)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `det J` (dimensionless), `≥ (1 − Σ Qᵢ)²`.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        self.state_at(x, z).det()
    }

    /// Velocity of the particle above `(x, z)`, `Σ ((Qᵢωᵢ/kᵢ) d̂ᵢ cos φᵢ, Aᵢωᵢ sin φᵢ)` (`∂P/∂t` at fixed
    /// `u`; it satisfies the kinematic condition exactly).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `(v_x, v_y, v_z)` (m s⁻¹).
    ///
    /// # References
    /// docs/equations.md §1(b).
    pub fn velocity(&self, x: f64, z: f64) -> DVec3 {
        self.state_at(x, z).velocity
    }
}

/// An upper bound of the slope of a Gerstner sum of waves with slopes `aᵢ = kᵢAᵢ` and
/// steepnesses `Qᵢ` (`Σ Qᵢ < 1`): the root `ρ*` of `g(ρ) = Σ √(aᵢ² + ρ²Qᵢ²) − ρ`, rounded up.
///
/// Why: `∇ₓh = J⁻¹∇ᵤh` with `|∇ᵤh| ≤ Σ aᵢ|sin φᵢ|` and, `J = I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos φᵢ` being
/// symmetric, `λ_min(J) ≥ 1 − Σ Qᵢ max(cos φᵢ, 0)`. The ratio of the two is at least `ρ` only
/// where `Σ (aᵢ|sin φᵢ| + ρQᵢ max(cos φᵢ, 0)) ≥ ρ`, whose left side is at most
/// `Σ √(aᵢ² + ρ²Qᵢ²)` over all phases: so `|∇ₓh| ≤ ρ*`. The cruder `Σ aᵢ/(1 − Σ Qᵢ)` takes the
/// largest gradient and the smallest Jacobian at once, which no phase gives (the Jacobian is
/// smallest at the crests, where the gradient vanishes). For one wave `ρ* = a/√(1 − Q²)`, the
/// exact largest slope; for fitted sets (every `Qᵢ/aᵢ` the same) `ρ* = Σa/√(1 − (ΣQ)²)`, about
/// a quarter of the cruder bound at `ΣQ = 0.9`.
///
/// Computed without iteration up to `newton_steps = 0`: `g` is convex with `g′ ≤ ΣQ − 1`, and
/// `ρ₀ = Σa/√(1 − (ΣQ)²)` is below the root (Minkowski: `g(ρ₀) ≥ 0`), so
/// `ρ₀ + g(ρ₀)/(1 − ΣQ) ≥ ρ*`. Newton steps from `ρ₀` stay below the root (convexity) and bring
/// that bound down to it. With no step it exceeded the root by 11 % at most over 3 000 random
/// sets whose ratios `Qᵢ/aᵢ` lie within a factor 4 of one another (`ΣQ` 0.3–0.97), but two
/// waves with ratios exactly 4 apart at `ΣQ = 0.97` reach 20.5 %, as does the unit test's set,
/// whose ratios are 55 apart (21 %).
///
/// # Arguments
/// - `terms`: `(aᵢ, Qᵢ)` per wave, each `≥ 0`, with `Σ Qᵢ < 1`.
/// - `newton_steps`: Newton steps before the bound is taken.
///
/// # Returns
/// `L ≥ ρ*` (dimensionless), `0` for no waves, at most `Σ aᵢ/(1 − Σ Qᵢ)` but for rounding.
///
/// # References
/// docs/equations.md §1(b); Gerstner F. 1802 (the map); derived here.
pub(crate) fn slope_bound_of(terms: impl Iterator<Item = (f64, f64)> + Clone, newton_steps: usize) -> f64 {
    let (mut sum_a, mut sum_q, mut n) = (0.0, 0.0, 0usize);
    for (a, q) in terms.clone() {
        sum_a += a;
        sum_q += q;
        n += 1;
    }
    if sum_a <= 0.0 {
        return 0.0;
    }
    debug_assert!(sum_q < 1.0, "ΣQ = {sum_q}");
    let g = |rho: f64| -> (f64, f64) {
        let (mut value, mut slope) = (-rho, -1.0);
        for (a, q) in terms.clone() {
            let r = (a * a + rho * rho * q * q).sqrt();
            value += r;
            if r > 0.0 {
                slope += rho * q * q / r;
            }
        }
        (value, slope)
    };
    let mut rho = sum_a / (1.0 - sum_q * sum_q).sqrt();
    let (mut value, mut slope) = g(rho);
    for _ in 0..newton_steps {
        if !(value > 0.0 && slope < 0.0) {
            break;
        }
        rho -= value / slope;
        (value, slope) = g(rho);
    }
    // The sums' rounding (`n + 2` terms of size ≤ ρ), through the division by `1 − ΣQ`.
    let rounding = 4.0 * (n as f64 + 2.0) * f64::EPSILON / (1.0 - sum_q);
    (rho + value.max(0.0) / (1.0 - sum_q)) * (1.0 + rounding)
}

impl WaveSurface for GerstnerSurface {
    by_frozen_field!(height -> f64, gradient -> DVec2, displacement -> DVec2, jacobian -> f64, velocity -> DVec3);

    fn height_bounds(&self) -> (f64, f64) {
        (-self.total_amplitude, self.total_amplitude)
    }

    fn max_slope(&self) -> f64 {
        self.slope_bound()
    }

    fn heights(&self, xs: &[f64], zs: &[f64], t: f64, out: &mut [f64]) {
        self.at_time(t).heights(xs, zs, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Trochoid, TrochoidSum};

    /// One wave two ways: the inversion's residual (≤ 10⁻¹² m) times the slope (`Q/√(1 − Q²)` =
    /// 0.75), plus Kepler's 10⁻¹³ in `θ` times `A`: ~10⁻¹² m; 10⁻¹⁰ is loose.
    const ONE_WAVE_HEIGHT_ABS: f64 = 1e-10;

    /// The gradient and Jacobian move with the rest position by the curvature `k²A/(1 − Q)³`
    /// (≈ 14 m⁻¹) times its error (~10⁻¹² m): ~10⁻¹¹.
    const ONE_WAVE_DERIVATIVE_ABS: f64 = 1e-9;

    /// Two sums of the same ≤ 52 terms in different orders: `~52 ε` of `ΣA`, with margin.
    const SUM_ORDER_REL: f64 = 1e-13;

    #[test]
    fn one_wave_is_the_exact_trochoid() {
        // A single Gerstner wave and the single-trochoid height field are the same surface.
        let w = Trochoid::new(0.4, 1.5, 0.7, 3.0, 0.2, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w]);
        let g = GerstnerSurface::new(&set).unwrap();
        let t = TrochoidSum::new(&set);
        for j in 0..50 {
            let (x, z) = (j as f64 * 0.37 - 9.0, j as f64 * 0.11);
            assert!((g.height(x, z, 0.4) - t.height(x, z, 0.4)).abs() < ONE_WAVE_HEIGHT_ABS);
            assert!((g.gradient(x, z, 0.4) - t.gradient(x, z, 0.4)).length() < ONE_WAVE_DERIVATIVE_ABS);
            assert!((g.jacobian(x, z, 0.4) - t.jacobian(x, z, 0.4)).abs() < ONE_WAVE_DERIVATIVE_ABS);
        }
    }

    /// `point` inverts once and gives each field of the single functions: the height bit for bit
    /// (the same lane inversion, an identity of the code), the others from a rest position that
    /// meets the same stopping rule. Derived bound: the two rest positions lie within
    /// `2τ/(1 − ΣQ)` (τ about 3×10⁻¹² m at these points, ΣQ = 0.9), and the fastest field, the
    /// gradient, moves by at most `Σ kᵢ²Aᵢ/(1 − ΣQ)³` per metre of it; the test computes that
    /// product for its set and checks it is within this tolerance. A point taken at another rest
    /// position (a wrong root, a stale state) differs by the fields' own size, 10⁻³ and more.
    const POINT_FIELDS_ABS: f64 = 1e-7;

    #[test]
    fn one_inversion_gives_every_field() {
        use crate::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
        let pm = PiersonMoskowitz::from_u10(12.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let o = FitOptions { choppiness: 2.5, ..FitOptions::default() };
        let set = fit_trochoids(&pm, &d, 40, 3, &o).unwrap();
        let g = GerstnerSurface::new(&set).unwrap();
        // The derived bound of the gradient's difference (the fastest field), for this set.
        let sum_q: f64 = set.waves().iter().map(|w| w.steepness()).sum();
        let sum_k2a: f64 = set.waves().iter().map(|w| w.wavenumber().powi(2) * w.amplitude()).sum();
        let tau = GERSTNER_TOLERANCE_M + GERSTNER_TOLERANCE_REL * (200.0 + g.total_amplitude()); // |(x, z)| < 200 m below
        let derived = 2.0 * tau / (1.0 - sum_q) * sum_k2a / (1.0 - sum_q).powi(3);
        assert!(derived <= POINT_FIELDS_ABS, "derived bound {derived:e}");
        let f = g.at_time(7.5);
        for j in 0..200 {
            let (x, z) = (j as f64 * 1.37 - 90.0, (j * 7 % 31) as f64 * 2.9 - 40.0);
            let p = f.point(x, z);
            assert_eq!(p.height.to_bits(), f.height_lanes(x, z).to_bits(), "{x} {z}");
            assert!((p.rest - f.rest_position(x, z)).length() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((p.gradient - f.gradient(x, z)).length() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((p.displacement - f.displacement(x, z)).length() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((p.velocity - f.velocity(x, z)).length() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((p.jacobian - f.jacobian(x, z)).abs() < POINT_FIELDS_ABS, "{x} {z}");
            // The particle at that rest position, with no inversion: the same point and fields.
            let q = f.point_at_rest(p.rest);
            assert!((p.rest + q.displacement - DVec2::new(x, z)).length() <= 2.0 * tau, "{x} {z}");
            assert!((q.height - p.height).abs() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((q.gradient - p.gradient).length() < POINT_FIELDS_ABS, "{x} {z}");
            assert!((q.velocity - p.velocity).length() < POINT_FIELDS_ABS, "{x} {z}");
        }
    }

    #[test]
    fn lanes_agree_with_the_scalar_passes_within_the_derived_bound() {
        // Fitted sets (ΣQ = 0.9, with 50 and 7 waves: padded to 52 and 8) at 400 points and
        // several instants. Bound: both inversions meet |u + D(u) − x| ≤ τ, so the heights are
        // within 2τL (see `height_lanes`), plus the rounding of two sums in different orders,
        // 10⁻¹³ ΣA.
        use crate::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
        let pm = PiersonMoskowitz::from_u10(12.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let o = FitOptions { choppiness: 4.0, ..FitOptions::default() };
        for n in [50, 7] {
            let set = fit_trochoids(&pm, &d, n, 17, &o).unwrap();
            let g = GerstnerSurface::new(&set).unwrap();
            assert_eq!(g.len(), n);
            for t in [0.0, 3.7, 1000.0] {
                let f = g.at_time(t);
                for j in 0..400 {
                    let (x, z) = (j as f64 * 1.37 - 250.0, (j as f64 * 0.71).sin() * 90.0);
                    let tau = GERSTNER_TOLERANCE_M
                        + GERSTNER_TOLERANCE_REL * (DVec2::new(x, z).length() + g.total_amplitude());
                    let bound = 2.0 * tau * g.slope_bound() + SUM_ORDER_REL * g.total_amplitude();
                    let (a, b) = (f.height(x, z), f.height_lanes(x, z));
                    assert!((a - b).abs() <= bound, "n = {n}, t = {t}, ({x}, {z}): {a} vs {b}");
                    let inv = f.solve_lanes(x, z);
                    assert!(inv.residual <= tau && inv.iterations < GERSTNER_MAX_ITERATIONS);
                }
            }
        }
    }

    /// A solve started from the solution at another point (the tracer's previous sample) finds
    /// the same rest position as one started from `x − D(x)`: the inversion is unique, so the
    /// heights differ only within the bound of `lanes_agree_with_the_scalar_passes_within_the_derived_bound`
    /// (both solves stop within `τ` of it), for nearby and far starts and weights that change
    /// from point to point as a ray's do. Started 0.9 m away, the warm solves take fewer Newton
    /// iterations in all than the cold ones (a wrong `J′⁻¹` or a stale solution would not).
    #[test]
    fn warm_started_solves_find_the_same_surface() {
        use crate::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};
        let pm = PiersonMoskowitz::from_u10(12.0).unwrap();
        let d = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let o = FitOptions { choppiness: 4.0, ..FitOptions::default() };
        let set = fit_trochoids(&pm, &d, 50, 17, &o).unwrap();
        let g = GerstnerSurface::new(&set).unwrap();
        let f = g.at_time(3.7);
        let mut scratch = FadedWaves::default();
        let mut warm: Option<fading::WarmStart> = None;
        let (mut warm_iterations, mut cold_iterations) = (0, 0);
        for j in 0..400 {
            // Steps of 0.2 m (a fifth of the shortest wave, 0.93 m: a ray's near the surface),
            // with a jump of 60 m every 50 points; a third of the waves fading.
            let (x, z) = (j as f64 * 0.2 - 150.0 + 60.0 * (j / 50) as f64, (j as f64 * 0.05).sin() * 2.0);
            let fade = 1.0 - j as f64 / 400.0;
            let weights: Vec<f64> = (0..g.len()).map(|i| if i % 3 == 0 { fade } else { 1.0 }).collect();
            let tau = GERSTNER_TOLERANCE_M + GERSTNER_TOLERANCE_REL * (DVec2::new(x, z).length() + g.total_amplitude());
            let bound = 2.0 * tau * g.slope_bound() + SUM_ORDER_REL * g.total_amplitude();
            let (cold, from_cold) = f.faded_height_lanes_from(x, z, &weights, &mut scratch, None);
            let (h, solved) = f.faded_height_lanes_from(x, z, &weights, &mut scratch, warm.as_ref());
            assert!((h - cold).abs() <= bound, "({x}, {z}): {h} vs {cold}");
            if j % 50 != 0 {
                warm_iterations += solved.iterations;
                cold_iterations += from_cold.iterations;
            }
            warm = Some(solved);
        }
        assert!(warm_iterations < cold_iterations, "{warm_iterations} warm against {cold_iterations} cold");
        // One Newton step from a solution 2 cm and 1 cm away starts `O(Δx²)` from the rest
        // position (a quarter as far at half the distance; a start that kept the displacement,
        // `u′ + (x − x′)`, would be `O(Δx)`, half as far).
        let weights = vec![1.0; g.len()];
        let (x0, dir) = (DVec2::new(3.0, -1.0), DVec2::new(0.8, 0.6));
        let (_, at) = f.faded_height_lanes_from(x0.x, x0.y, &weights, &mut scratch, None);
        let error = |d: f64| {
            let x = x0 + d * dir;
            (at.start(x) - f.solve(x.x, x.y).rest).length()
        };
        let (e2, e1) = (error(0.02), error(0.01));
        assert!((3.0..5.0).contains(&(e2 / e1)), "start errors {e2} and {e1} m");
    }

    /// Eleven days (10⁶ s) later: the phase offsets are reduced to `[0, 2π]` (unreduced, every sine
    /// paid a slow argument reduction), and the surface is still the single trochoid's, whose
    /// phase `ωt` is taken whole (10⁷ rad: its f64 rounding, ~10⁻⁹ rad, times `A` and the
    /// slope, is the tolerance's scale).
    #[test]
    fn late_frames_keep_their_phases_reduced_and_their_surface() {
        const LATE_HEIGHT_ABS: f64 = 1e-8;
        let w = Trochoid::new(0.4, 1.5, 0.7, 3.0, 0.2, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w]);
        let g = GerstnerSurface::new(&set).unwrap();
        let t = TrochoidSum::new(&set);
        let late = 1.0e6 + 0.37;
        assert!(g.at_time(late).offset.iter().all(|o| (0.0..=std::f64::consts::TAU).contains(o)));
        for j in 0..50 {
            let (x, z) = (j as f64 * 0.37 - 9.0, j as f64 * 0.11);
            assert!((g.height(x, z, late) - t.height(x, z, late)).abs() < LATE_HEIGHT_ABS);
        }
    }

    /// The slope bound is exact for one wave (`a/√(1 − Q²)`, here `kA = 0.6`, `Q = 0.8`: 1.0),
    /// and that slope is reached (the largest over 20 000 rest positions of one period, 10⁻⁴
    /// from it: the lattice's step near the maximum, where the slope is flat to second order).
    #[test]
    fn the_slope_bound_of_one_wave_is_its_largest_slope() {
        let w = Trochoid::new(0.4, 1.5, 0.7, 3.0, 0.2, 0.8).unwrap();
        let g = GerstnerSurface::new(&TrochoidSet::new(vec![w])).unwrap();
        let exact = 0.6 / (1.0 - 0.8f64 * 0.8).sqrt();
        assert!((g.slope_bound() - exact).abs() <= 1e-12 * exact, "{} vs {exact}", g.slope_bound());
        let f = g.at_time(0.0);
        let d = DVec2::new(0.7f64.cos(), 0.7f64.sin());
        let largest = (0..20_000)
            .map(|i| {
                let p = f.forward(d * (i as f64 * TAU / 1.5 / 20_000.0));
                f.gradient(p.x, p.z).length()
            })
            .fold(0.0, f64::max);
        assert!(largest <= g.slope_bound() && largest >= g.slope_bound() * (1.0 - 1e-4), "{largest}");
    }

    /// Sets whose `Qᵢ/kᵢAᵢ` are all equal (fitted sets) have `ρ* = Σa/√(1 − (ΣQ)²)` with no
    /// iteration; mixed sets (here ratios 55 apart) are bounded from above, within 25 % of the
    /// root with no Newton step (21 %) and within 10⁻⁸ with three (9×10⁻¹⁰ measured; the root
    /// found here by bisection).
    #[test]
    fn the_slope_bound_is_the_root_from_above() {
        let proportional = [(0.3, 0.2), (0.15, 0.1), (0.6, 0.4), (0.3, 0.2)];
        let closed = 1.35 / (1.0 - 0.9f64 * 0.9).sqrt();
        let got = slope_bound_of(proportional.iter().copied(), 0);
        assert!(got >= closed && got <= closed * (1.0 + 1e-13), "{got} vs {closed}");
        let mixed = [(0.05, 0.3), (0.9, 0.1), (0.2, 0.25), (0.4, 0.2)];
        let g = |r: f64| mixed.iter().map(|&(a, q): &(f64, f64)| (a * a + r * r * q * q).sqrt()).sum::<f64>() - r;
        let (mut lo, mut hi) = (0.0, 1.55 / (1.0 - 0.85));
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if g(m) > 0.0 { lo = m } else { hi = m }
        }
        let (rough, fine) = (slope_bound_of(mixed.iter().copied(), 0), slope_bound_of(mixed.iter().copied(), 3));
        assert!(rough >= hi && rough <= 1.25 * hi, "{rough} vs {hi}");
        assert!(fine >= hi && fine <= hi * (1.0 + 1e-8), "{fine} vs {hi}");
    }

    #[test]
    fn folding_sets_are_refused() {
        let w = Trochoid::new(0.5, 1.0, 0.0, 1.0, 0.0, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w, w]);
        assert!(matches!(GerstnerSurface::new(&set), Err(WaveError::TooSteep { .. })));
    }
}
