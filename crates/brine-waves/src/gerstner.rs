//! The true sum of Gerstner waves as a height field, by inverting the horizontal displacement.

use glam::{DVec2, DVec3};

use crate::error::WaveError;
use crate::{TrochoidSet, WaveSurface};

/// Absolute part of the inversion tolerance (m): the residual `|u + D(u) − x|` the Newton solve
/// of [`GerstnerField::solve`] reaches. The relative part `10⁻¹⁴ (|x| + Σ Aᵢ)` covers rounding
/// in far-away coordinates.
pub const GERSTNER_TOLERANCE_M: f64 = 1e-12;

/// Iteration cap of the inversion (2–3 iterations are usual; the property tests never reach it).
pub const GERSTNER_MAX_ITERATIONS: usize = 64;

/// The sum of Gerstner waves with all horizontal displacements composed, as Bruneton et al. 2010,
/// Crest and Blender draw it (equation sheet §1(b)):
///
/// `P(u, t) = (u − Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ, Σ Aᵢ cos φᵢ)`, `φᵢ = kᵢ d̂ᵢ·u − ωᵢt + φ₀ᵢ`.
///
/// The height at a world point `x` needs the rest position `u` with `u + D(u) = x`, found by a
/// damped Newton solve in `u` ([`GerstnerField::solve`]: tolerance [`GERSTNER_TOLERANCE_M`],
/// at most [`GERSTNER_MAX_ITERATIONS`] iterations). The map `u ↦ x` has the symmetric Jacobian
/// `J = I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos φᵢ`, whose eigenvalues lie in `[1 − ΣQ, 1 + ΣQ]`: while
/// `Σ Qᵢ < 1` it is a diffeomorphism and the height field exists. Then
/// `∇ₓh = J⁻¹ ∇ᵤh`, `|∇ₓh| ≤ Σ kᵢAᵢ/(1 − Σ Qᵢ)` (the conservative bound of the equation sheet, `Q_Σ/(1 − Q_Σ)`
/// when `Qᵢ = kᵢAᵢ`; for one wave it exceeds the exact `Q/√(1 − Q²)`).
///
/// # References
/// Gerstner F. 1802; Tessendorf 2001, §3.2; Bruneton E., Neyret F., Holzschuch N. 2010,
/// "Real-time realistic ocean lighting using seamless transitions from geometry to BRDF", CGF
/// 29(2); equation sheet §1(b) and §10.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GerstnerSurface {
    kx: Vec<f64>,
    kz: Vec<f64>,
    omega: Vec<f64>,
    phase: Vec<f64>,
    amplitude: Vec<f64>,
    /// `Qᵢ/kᵢ²`: times `(kx, kz)` gives the horizontal radius vector `(Qᵢ/kᵢ) d̂ᵢ`.
    q_over_k2: Vec<f64>,
    total_amplitude: f64,
    total_steepness: f64,
    total_ka: f64,
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
            s.total_ka += k * w.amplitude();
        }
        Ok(s)
    }

    /// Number of waves.
    pub fn len(&self) -> usize {
        self.kx.len()
    }

    /// `true` for a flat sea.
    pub fn is_empty(&self) -> bool {
        self.kx.is_empty()
    }

    /// `Σ Qᵢ` (dimensionless), below 0.99.
    pub fn total_steepness(&self) -> f64 {
        self.total_steepness
    }

    /// `Σ Aᵢ` (m).
    pub fn total_amplitude(&self) -> f64 {
        self.total_amplitude
    }

    /// The Lipschitz constant of the height field, `Σ kᵢAᵢ/(1 − Σ Qᵢ)` (dimensionless).
    ///
    /// # References
    /// Equation sheet §1(b) (derived: `|∇ᵤh| ≤ Σ kA`, `‖J⁻¹‖ ≤ 1/(1 − ΣQ)`).
    pub fn slope_bound(&self) -> f64 {
        self.total_ka / (1.0 - self.total_steepness)
    }

    /// The surface frozen at time `t` (s).
    pub fn at_time(&self, t: f64) -> GerstnerField<'_> {
        let offset = self.omega.iter().zip(&self.phase).map(|(w, p)| p - w * t).collect();
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

impl State {
    fn det(&self) -> f64 {
        self.jxx * self.jzz - self.jxz * self.jxz
    }

    /// `J⁻¹ v`.
    fn solve(&self, v: DVec2) -> DVec2 {
        let det = self.det();
        DVec2::new(self.jzz * v.x - self.jxz * v.y, self.jxx * v.y - self.jxz * v.x) / det
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
        let s = self.surface;
        let mut d = DVec2::ZERO;
        for i in 0..s.len() {
            let sn = (s.kx[i] * u.x + s.kz[i] * u.y + self.offset[i]).sin();
            d -= s.q_over_k2[i] * sn * DVec2::new(s.kx[i], s.kz[i]);
        }
        d
    }

    fn state(&self, u: DVec2) -> State {
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
            let (sn, c) = (s.kx[i] * u.x + s.kz[i] * u.y + self.offset[i]).sin_cos();
            let k = DVec2::new(s.kx[i], s.kz[i]);
            let a = s.amplitude[i];
            st.displacement -= s.q_over_k2[i] * sn * k;
            st.height += a * c;
            st.grad_u -= a * sn * k;
            let qc = s.q_over_k2[i] * c;
            st.jxx -= qc * k.x * k.x;
            st.jxz -= qc * k.x * k.y;
            st.jzz -= qc * k.y * k.y;
            let h = qc * s.omega[i];
            st.velocity += DVec3::new(h * k.x, a * s.omega[i] * sn, h * k.y);
        }
        st
    }

    /// The surface point of the particle at rest position `u` (m): `(u + D(u), h(u))` as
    /// `(x, y, z)`.
    pub fn forward(&self, u: DVec2) -> DVec3 {
        let st = self.state(u);
        let x = u + st.displacement;
        DVec3::new(x.x, st.height, x.y)
    }

    /// Inverts the horizontal displacement: the rest position `u` whose particle is above `(x, z)`.
    ///
    /// Damped Newton on `G(u) = u + D(u) − x` from `u₀ = x − D(x)`: each step `J⁻¹G` is halved
    /// until `|G|` decreases (at most 30 halvings; if none decreases, a fixed-point step
    /// `u ← x − D(u)`, a contraction of rate `Σ Qᵢ`, is taken instead). Stops when
    /// `|G| ≤ GERSTNER_TOLERANCE_M + 10⁻¹⁴ (|x| + Σ Aᵢ)` or after [`GERSTNER_MAX_ITERATIONS`]
    /// (2–3 iterations are usual for fitted sets with `Σ Q` up to 0.99).
    pub fn solve(&self, x: f64, z: f64) -> Inversion {
        self.solve_state(x, z).0
    }

    /// [`GerstnerField::solve`], also returning the waves' state at the rest position.
    fn solve_state(&self, x: f64, z: f64) -> (Inversion, State) {
        let target = DVec2::new(x, z);
        let tol = GERSTNER_TOLERANCE_M + 1e-14 * (target.length() + self.surface.total_amplitude);
        let mut u = target - self.displacement_at_rest(target);
        let mut st = self.state(u);
        let mut g = u + st.displacement - target;
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
                let cand_st = self.state(cand);
                let cand_g = cand + cand_st.displacement - target;
                if cand_g.length() < residual {
                    (u, st, g, residual) = (cand, cand_st, cand_g, cand_g.length());
                    accepted = true;
                    break;
                }
                lambda *= 0.5;
            }
            if !accepted {
                u = target - st.displacement;
                st = self.state(u);
                g = u + st.displacement - target;
                residual = g.length();
            }
        }
        (Inversion { rest: u, residual, iterations: GERSTNER_MAX_ITERATIONS }, st)
    }

    /// Rest position `u` (m) of the particle above `(x, z)` (see [`GerstnerField::solve`]).
    pub fn rest_position(&self, x: f64, z: f64) -> DVec2 {
        self.solve(x, z).rest
    }

    fn state_at(&self, x: f64, z: f64) -> State {
        self.solve_state(x, z).1
    }

    /// Height `h(x, z) = Σ Aᵢ cos φᵢ(u)` (m).
    pub fn height(&self, x: f64, z: f64) -> f64 {
        self.state_at(x, z).height
    }

    /// Gradient `∇ₓh = J⁻¹ ∇ᵤh`, `∇ᵤh = −Σ Aᵢ kᵢ d̂ᵢ sin φᵢ` (dimensionless).
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        let st = self.state_at(x, z);
        st.solve(st.grad_u)
    }

    /// Horizontal displacement `D(u)` (m) of the particle above `(x, z)`.
    pub fn displacement(&self, x: f64, z: f64) -> DVec2 {
        self.state_at(x, z).displacement
    }

    /// Jacobian `det J(u)` (dimensionless) at the particle above `(x, z)`.
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        self.state_at(x, z).det()
    }

    /// Velocity `Σ ((Qᵢωᵢ/kᵢ) d̂ᵢ cos φᵢ, Aᵢωᵢ sin φᵢ)` (m s⁻¹) of the particle above `(x, z)`.
    pub fn velocity(&self, x: f64, z: f64) -> DVec3 {
        self.state_at(x, z).velocity
    }
}

impl WaveSurface for GerstnerSurface {
    fn height(&self, x: f64, z: f64, t: f64) -> f64 {
        self.at_time(t).height(x, z)
    }

    fn gradient(&self, x: f64, z: f64, t: f64) -> DVec2 {
        self.at_time(t).gradient(x, z)
    }

    fn height_bounds(&self) -> (f64, f64) {
        (-self.total_amplitude, self.total_amplitude)
    }

    fn max_slope(&self) -> f64 {
        self.slope_bound()
    }

    fn displacement(&self, x: f64, z: f64, t: f64) -> DVec2 {
        self.at_time(t).displacement(x, z)
    }

    fn jacobian(&self, x: f64, z: f64, t: f64) -> f64 {
        self.at_time(t).jacobian(x, z)
    }

    fn velocity(&self, x: f64, z: f64, t: f64) -> DVec3 {
        self.at_time(t).velocity(x, z)
    }

    fn heights(&self, xs: &[f64], zs: &[f64], t: f64, out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        let field = self.at_time(t);
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = field.height(x, z);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Trochoid, TrochoidSum};

    #[test]
    fn one_wave_is_the_exact_trochoid() {
        // A single Gerstner wave and the single-trochoid height field are the same surface.
        let w = Trochoid::new(0.4, 1.5, 0.7, 3.0, 0.2, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w]);
        let g = GerstnerSurface::new(&set).unwrap();
        let t = TrochoidSum::new(&set);
        for j in 0..50 {
            let (x, z) = (j as f64 * 0.37 - 9.0, j as f64 * 0.11);
            assert!((g.height(x, z, 0.4) - t.height(x, z, 0.4)).abs() < 1e-10);
            assert!((g.gradient(x, z, 0.4) - t.gradient(x, z, 0.4)).length() < 1e-9);
            assert!((g.jacobian(x, z, 0.4) - t.jacobian(x, z, 0.4)).abs() < 1e-9);
        }
    }

    #[test]
    fn folding_sets_are_refused() {
        let w = Trochoid::new(0.5, 1.0, 0.0, 1.0, 0.0, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w, w]);
        assert!(matches!(GerstnerSurface::new(&set), Err(WaveError::TooSteep { .. })));
    }
}
