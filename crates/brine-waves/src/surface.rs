//! Wave surfaces as height fields, and the sum-of-trochoids surface of Darles et al.

use glam::{DVec2, DVec3};

use crate::{TrochoidSet, solve_trochoid_phase};

/// A sea surface seen as a height field `y = h(x, z, t)` over the horizontal plane.
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
}

/// The surface Darles et al. (2007, Eq. 2) trace: a sum of per-wave trochoid height fields,
/// `h(x, z, t) = Σᵢ Aᵢ cos θᵢ` with `θᵢ − Qᵢ sin θᵢ = kᵢ d̂ᵢ·(x, z) − ωᵢ t + φᵢ`.
///
/// Each term is the exact profile of its trochoid, but the horizontal displacements of different
/// waves do not compose: this is *not* the Gerstner sum (equation sheet §1(a)); it is a valid,
/// self-consistent surface whose height lies in `[−Σ Aᵢ, Σ Aᵢ]` and whose slope is at most
/// `Σ kᵢAᵢ/√(1 − Qᵢ²)`.
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

    /// Height of wave `i` alone at `(x, z)` (m): `Aᵢ cos θᵢ`.
    #[inline]
    pub fn wave_height(&self, i: usize, x: f64, z: f64) -> f64 {
        let s = &self.sum;
        let arg = s.kx[i] * x + s.kz[i] * z + self.offset[i];
        let (_, c, _) = solve_trochoid_phase(arg, s.steepness[i]);
        s.amplitude[i] * c
    }

    /// Height `h(x, z)` (m).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        (0..self.sum.len()).map(|i| self.wave_height(i, x, z)).sum()
    }

    /// Gradient `(∂h/∂x, ∂h/∂z)`: `∂(A cos θ)/∂s = −A sin θ/(1 − Q cos θ)` times `k d̂`.
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        let s = &self.sum;
        let mut g = DVec2::ZERO;
        for i in 0..s.len() {
            let arg = s.kx[i] * x + s.kz[i] * z + self.offset[i];
            let (_, c, sn) = solve_trochoid_phase(arg, s.steepness[i]);
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
}
