//! Wave surfaces as height fields, and the sum-of-trochoids surface of Darles et al.

use glam::{DVec2, DVec3};

use crate::{TrochoidSet, lanes, solve_trochoid_phase};

/// A sea surface seen as a height field `y = h(x, z, t)` over the horizontal plane, with the
/// motion of the water particles on it.
///
/// Implemented by [`TrochoidSum`] (the surface Darles et al. trace, the default for rendering),
/// [`crate::GerstnerSurface`] (the true Gerstner sum) and [`crate::SineSet`] (Chen et al.'s sine
/// waves); equation sheet §1 explains why the first two differ.
pub trait WaveSurface {
    /// Height `h` (m) above the mean level at horizontal position `(x, z)` (m) and time `t` (s).
    fn height(&self, x: f64, z: f64, t: f64) -> f64;

    /// Gradient `(∂h/∂x, ∂h/∂z)` (dimensionless) at `(x, z, t)`.
    fn gradient(&self, x: f64, z: f64, t: f64) -> DVec2;

    /// Upward unit normal `(−∂h/∂x, 1, −∂h/∂z)/‖·‖`.
    fn normal(&self, x: f64, z: f64, t: f64) -> DVec3 {
        let g = self.gradient(x, z, t);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// `(h_min, h_max)` (m): bounds of the height over all positions and times.
    fn height_bounds(&self) -> (f64, f64);

    /// A bound of `|∇h|` over all positions and times (the height field's Lipschitz constant).
    fn max_slope(&self) -> f64;

    /// Horizontal displacement `D` (m) of the water particle now at the surface above `(x, z)`:
    /// its rest position is `(x, z) − D`.
    fn displacement(&self, x: f64, z: f64, t: f64) -> DVec2;

    /// Jacobian determinant `J = det(∂x/∂u)` (dimensionless) of the horizontal map from rest
    /// positions `u` to positions `x = u + D(u)`, at the particle now above `(x, z)`: `J < 1`
    /// where the surface is compressed, `J ≤ 0` where it folds (whitecaps, equation sheet §10).
    fn jacobian(&self, x: f64, z: f64, t: f64) -> f64;

    /// Velocity `(v_x, v_y, v_z)` (m s⁻¹) of the water particle at the surface above `(x, z)`.
    fn velocity(&self, x: f64, z: f64, t: f64) -> DVec3;

    /// Heights (m) at many points `(xs[j], zs[j])` at time `t`, written to `out[j]`.
    ///
    /// The default loops over [`WaveSurface::height`]; the wave sets override it with a kernel
    /// that evaluates four waves at a time in SIMD lanes.
    ///
    /// # Panics
    /// If the three slices differ in length (a programming error, not user input).
    fn heights(&self, xs: &[f64], zs: &[f64], t: f64, out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = self.height(x, z, t);
        }
    }
}

/// The surface Darles et al. (2007, Eq. 2) trace: a sum of per-wave trochoid height fields,
/// `h(x, z, t) = Σᵢ Aᵢ cos θᵢ` with `θᵢ − Qᵢ sin θᵢ = kᵢ d̂ᵢ·(x, z) − ωᵢ t + φᵢ`.
///
/// Each term is the exact profile of its trochoid, but the horizontal displacements of different
/// waves do not compose: this is *not* the Gerstner sum (equation sheet §1(a),
/// [`crate::GerstnerSurface`] is); it is a valid, self-consistent surface whose height lies in
/// `[−Σ Aᵢ, Σ Aᵢ]` and whose slope is at most `Σ kᵢAᵢ/√(1 − Qᵢ²)`.
///
/// Its particle quantities are summed wave by wave, each wave's particle taken at its own phase
/// `θᵢ`: displacement `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ`, velocity
/// `Σ ((Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ, Aᵢωᵢ sin θᵢ)`, and Jacobian `J = det(I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ)` (the
/// Gerstner form of equation sheet §10 at these phases: exact for one wave, and the same
/// statistics as the Gerstner sum for many).
///
/// Stored as structure-of-arrays for the tracer's inner loop.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrochoidSum {
    pub(crate) kx: Vec<f64>,
    pub(crate) kz: Vec<f64>,
    pub(crate) omega: Vec<f64>,
    pub(crate) phase: Vec<f64>,
    pub(crate) amplitude: Vec<f64>,
    pub(crate) steepness: Vec<f64>,
    pub(crate) max_slope: Vec<f64>,
    pub(crate) wavenumber: Vec<f64>,
    pub(crate) total_amplitude: f64,
}

impl TrochoidSum {
    /// The surface of `set`.
    pub fn new(set: &TrochoidSet) -> Self {
        let mut s = Self::default();
        for w in set.waves() {
            let d = w.direction_vector();
            s.kx.push(w.wavenumber() * d.x);
            s.kz.push(w.wavenumber() * d.y);
            s.omega.push(w.omega());
            s.phase.push(w.phase());
            s.amplitude.push(w.amplitude());
            s.steepness.push(w.steepness());
            s.max_slope.push(w.max_slope());
            s.wavenumber.push(w.wavenumber());
        }
        s.total_amplitude = s.amplitude.iter().sum();
        s
    }

    /// Number of waves.
    pub fn len(&self) -> usize {
        self.kx.len()
    }

    /// `true` for a flat sea.
    pub fn is_empty(&self) -> bool {
        self.kx.is_empty()
    }

    /// The surface frozen at time `t` (s), with the phase offsets `φᵢ − ωᵢ t` precomputed: the
    /// form the tracer evaluates.
    pub fn at_time(&self, t: f64) -> TrochoidField<'_> {
        let offset = self.omega.iter().zip(&self.phase).map(|(w, p)| p - w * t).collect();
        TrochoidField { sum: self, offset }
    }
}

impl WaveSurface for TrochoidSum {
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
        self.max_slope.iter().sum()
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
        self.at_time(t).heights(xs, zs, out);
    }
}

/// A [`TrochoidSum`] frozen at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct TrochoidField<'a> {
    pub(crate) sum: &'a TrochoidSum,
    pub(crate) offset: Vec<f64>,
}

impl TrochoidField<'_> {
    /// The underlying surface.
    pub fn surface(&self) -> &TrochoidSum {
        self.sum
    }

    /// Particle phase `θᵢ` of wave `i` at `(x, z)`, as `(θ, cos θ, sin θ)`.
    #[inline]
    fn wave_phase(&self, i: usize, x: f64, z: f64) -> (f64, f64, f64) {
        let s = &self.sum;
        solve_trochoid_phase(s.kx[i] * x + s.kz[i] * z + self.offset[i], s.steepness[i])
    }

    /// Height of wave `i` alone at `(x, z)` (m): `Aᵢ cos θᵢ`.
    #[inline]
    pub fn wave_height(&self, i: usize, x: f64, z: f64) -> f64 {
        let (_, c, _) = self.wave_phase(i, x, z);
        self.sum.amplitude[i] * c
    }

    /// Height `h(x, z)` (m), one wave at a time.
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        (0..self.sum.len()).map(|i| self.wave_height(i, x, z)).sum()
    }

    /// Height `h(x, z)` (m), four waves at a time in SIMD lanes (`wide::f64x4`); equal to
    /// [`TrochoidField::height`] to `~10⁻¹⁴ Σ Aᵢ`.
    #[inline]
    pub fn height_lanes(&self, x: f64, z: f64) -> f64 {
        let s = self.sum;
        lanes::trochoid_height(&s.kx, &s.kz, &self.offset, &s.amplitude, &s.steepness, x, z)
    }

    /// Heights at many points (m), each by [`TrochoidField::height_lanes`].
    ///
    /// # Panics
    /// If the three slices differ in length.
    pub fn heights(&self, xs: &[f64], zs: &[f64], out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = self.height_lanes(x, z);
        }
    }

    /// Gradient `(∂h/∂x, ∂h/∂z)`: `∂(A cos θ)/∂s = −A sin θ/(1 − Q cos θ)` times `k d̂`.
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        let s = &self.sum;
        let mut g = DVec2::ZERO;
        for i in 0..s.len() {
            let (_, c, sn) = self.wave_phase(i, x, z);
            let dh_ds = -s.amplitude[i] * sn / (1.0 - s.steepness[i] * c);
            g += dh_ds * DVec2::new(s.kx[i], s.kz[i]);
        }
        g
    }

    /// Upward unit normal at `(x, z)`.
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// Horizontal displacement `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ` (m) of the waves' particles at `(x, z)`.
    pub fn displacement(&self, x: f64, z: f64) -> DVec2 {
        let s = &self.sum;
        let mut d = DVec2::ZERO;
        for i in 0..s.len() {
            let (_, _, sn) = self.wave_phase(i, x, z);
            // (Q/k) d̂ = Q k_vec / k².
            let k2 = s.wavenumber[i] * s.wavenumber[i];
            d -= s.steepness[i] * sn / k2 * DVec2::new(s.kx[i], s.kz[i]);
        }
        d
    }

    /// Jacobian `J = det(I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ)` at `(x, z)` (dimensionless).
    pub fn jacobian(&self, x: f64, z: f64) -> f64 {
        let s = &self.sum;
        let (mut jxx, mut jxz, mut jzz) = (1.0, 0.0, 1.0);
        for i in 0..s.len() {
            let (_, c, _) = self.wave_phase(i, x, z);
            let qc = s.steepness[i] * c / (s.wavenumber[i] * s.wavenumber[i]);
            jxx -= qc * s.kx[i] * s.kx[i];
            jxz -= qc * s.kx[i] * s.kz[i];
            jzz -= qc * s.kz[i] * s.kz[i];
        }
        jxx * jzz - jxz * jxz
    }

    /// Particle velocity `Σ ((Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ, Aᵢωᵢ sin θᵢ)` (m s⁻¹) at `(x, z)`.
    pub fn velocity(&self, x: f64, z: f64) -> DVec3 {
        let s = &self.sum;
        let mut v = DVec3::ZERO;
        for i in 0..s.len() {
            let (_, c, sn) = self.wave_phase(i, x, z);
            let k2 = s.wavenumber[i] * s.wavenumber[i];
            let h = s.steepness[i] * s.omega[i] * c / k2;
            v += DVec3::new(h * s.kx[i], s.amplitude[i] * s.omega[i] * sn, h * s.kz[i]);
        }
        v
    }
}
