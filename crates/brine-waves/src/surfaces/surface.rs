//! Wave surfaces as height fields, and the sum-of-trochoids surface of Darles et al.

use glam::{DVec2, DVec3};

use crate::tracing::lanes;
use crate::{TrochoidSet, solve_trochoid_phase};

/// A sea surface seen as a height field `y = h(x, z, t)` over the horizontal plane, with the
/// motion of the water particles on it.
///
/// Implemented by [`TrochoidSum`] (the surface Darles et al. trace, the default for rendering),
/// [`crate::GerstnerSurface`] (the true Gerstner sum) and [`crate::SineSet`] (Chen et al.'s sine
/// waves); docs/equations.md §1 explains why the first two differ.
///
/// Common arguments: `x`, `z` horizontal position (m, any finite value; y is up, see
/// `docs/conventions.md`), `t` time (s, any finite value).
///
/// # References
/// Darles et al. 2007, §3 (trochoid sum); Bruneton et al. 2010 (Gerstner sum); Chen et al. 2007,
/// §3.3 (sine set); docs/equations.md §1 and §10.
pub trait WaveSurface {
    /// Surface elevation `h(x, z, t)` above the mean sea level `y = 0`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `h` (m), within [`WaveSurface::height_bounds`].
    ///
    /// # References
    /// docs/equations.md §1 (each implementation cites its own equation).
    fn height(&self, x: f64, z: f64, t: f64) -> f64;

    /// Gradient of the height field, `∇h = (∂h/∂x, ∂h/∂z)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `∇h` (dimensionless), `|∇h| ≤` [`WaveSurface::max_slope`].
    ///
    /// # References
    /// docs/equations.md §1.
    fn gradient(&self, x: f64, z: f64, t: f64) -> DVec2;

    /// Upward unit normal of the height field, `n = (−∂h/∂x, 1, −∂h/∂z)/√(1 + |∇h|²)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `n` (unit vector, `n_y > 0`).
    ///
    /// # References
    /// docs/equations.md §1 (normal of a height field).
    fn normal(&self, x: f64, z: f64, t: f64) -> DVec3 {
        let g = self.gradient(x, z, t);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// Bounds of the height over all positions and times, `h_min ≤ h ≤ h_max`.
    ///
    /// # Returns
    /// `(h_min, h_max)` (m); `±Σ Aᵢ` for the wave sets here.
    ///
    /// # References
    /// docs/equations.md §1 (`|Aᵢ cos θᵢ| ≤ Aᵢ`).
    fn height_bounds(&self) -> (f64, f64);

    /// Lipschitz constant of the height field: a bound `L ≥ |∇h|` over all positions and times.
    ///
    /// # Returns
    /// `L` (dimensionless): `Σ kᵢAᵢ/√(1 − Qᵢ²)` (trochoid sum), the root `ρ*` of
    /// `Σ √((kᵢAᵢ)² + ρ²Qᵢ²) = ρ` (Gerstner sum, at most `Σ kᵢAᵢ/(1 − Σ Qᵢ)`), `Σ kᵢAᵢ` (sine set).
    ///
    /// # References
    /// docs/equations.md §1 ("max |slope|"; the Gerstner bound is derived there).
    fn max_slope(&self) -> f64;

    /// Horizontal displacement `D` of the water particle now at the surface above `(x, z)`: its
    /// rest position is `(x, z) − D`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `D = (D_x, D_z)` (m): `−Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ` for the trochoid and Gerstner sums, `0` for the
    /// sine set.
    ///
    /// # References
    /// docs/equations.md §1 (particle orbits) and §10.
    fn displacement(&self, x: f64, z: f64, t: f64) -> DVec2;

    /// Jacobian determinant `J = det(∂x/∂u)` of the horizontal map from rest positions `u` to
    /// positions `x = u + D(u)`, at the particle now above `(x, z)`: `J < 1` where the surface is
    /// compressed, `J ≤ 0` where it folds (whitecaps).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `J` (dimensionless): `det(I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ)` for the trochoid and Gerstner sums
    /// (at least `(1 − Σ Qᵢ)² > 0` while `Σ Qᵢ < 1`), `1` for the sine set.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
    fn jacobian(&self, x: f64, z: f64, t: f64) -> f64;

    /// Velocity of the surface point above `(x, z)`: horizontally as the waves' particles move,
    /// vertically as the kinematic condition `v_y = ∂h/∂t + ∇h·v_xz` requires for the trochoid
    /// and Gerstner sums (a point carried by `v` stays on the surface), the linear
    /// `v_y = ∂h/∂t` for the sine set.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `t`: time (s).
    ///
    /// # Returns
    /// `(v_x, v_y, v_z)` (m s⁻¹). Each implementation documents its horizontal part.
    ///
    /// # References
    /// docs/equations.md §1 (particle orbits); Lamb 1932, *Hydrodynamics*, §9 (kinematic surface
    /// condition).
    fn velocity(&self, x: f64, z: f64, t: f64) -> DVec3;

    /// Heights at many points `(xs[j], zs[j])` at time `t`, written to `out[j]`: the same values
    /// as [`WaveSurface::height`] (to rounding, `~10⁻¹³ Σ Aᵢ`).
    ///
    /// The default loops over [`WaveSurface::height`]. The three wave sets here override it with
    /// kernels that evaluate four waves at a time in `wide::f64x4` SIMD lanes
    /// ([`TrochoidField::height_lanes`], [`crate::SineField::height_lanes`],
    /// [`crate::GerstnerField::height_lanes`]).
    ///
    /// # Arguments
    /// - `xs`, `zs`: horizontal positions (m), equal lengths; `t`: time (s).
    /// - `out`: receives the heights (m), same length.
    ///
    /// # Panics
    /// If the three slices differ in length (a programming error, not user input).
    ///
    /// # References
    /// docs/equations.md §1.
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
/// waves do not compose: this is *not* the Gerstner sum (docs/equations.md §1(a),
/// [`crate::GerstnerSurface`] is); it is a valid, self-consistent surface whose height lies in
/// `[−Σ Aᵢ, Σ Aᵢ]` and whose slope is at most `Σ kᵢAᵢ/√(1 − Qᵢ²)`.
///
/// Its particle quantities are summed wave by wave, each wave's particle taken at its own phase
/// `θᵢ`: displacement `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ`, horizontal velocity
/// `v_xz = Σ (Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ` (the time derivative of each `Dᵢ` with that wave's rest
/// coordinate `d̂ᵢ·x + (Qᵢ/kᵢ) sin θᵢ` held fixed), and Jacobian
/// `J = det(I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ)` (the Gerstner form of docs/equations.md §10 at these phases:
/// exact for one wave, and the same statistics as the Gerstner sum for many). The vertical
/// velocity is the kinematic condition `v_y = ∂h/∂t + ∇h·v_xz`, so that a point carried by
/// `v` stays on the surface; for one wave it is the particle's `Aω sin θ`, for many it differs
/// from `Σ Aᵢωᵢ sin θᵢ` by the cross terms `Σ_{i≠j} ∇hᵢ·v_{xz,j}` (the summed height field is not
/// a material surface of the summed particles).
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
    by_frozen_field!(height -> f64, gradient -> DVec2, displacement -> DVec2, jacobian -> f64, velocity -> DVec3);

    fn height_bounds(&self) -> (f64, f64) {
        (-self.total_amplitude, self.total_amplitude)
    }

    fn max_slope(&self) -> f64 {
        self.max_slope.iter().sum()
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

    /// Height of wave `i` alone, `hᵢ = Aᵢ cos θᵢ` with `θᵢ − Qᵢ sin θᵢ = kᵢ·x + offᵢ`.
    ///
    /// # Arguments
    /// - `i`: wave index, `< len()`.
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `hᵢ` (m), in `[−Aᵢ, Aᵢ]`.
    ///
    /// # References
    /// Darles et al. 2007, Eq. 2; docs/equations.md §1(a).
    #[inline]
    pub fn wave_height(&self, i: usize, x: f64, z: f64) -> f64 {
        let (_, c, _) = self.wave_phase(i, x, z);
        self.sum.amplitude[i] * c
    }

    /// Height of the trochoid sum, `h = Σᵢ Aᵢ cos θᵢ`, one wave at a time (safeguarded Newton on each
    /// wave's Kepler equation).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `h` (m), in `[−ΣAᵢ, ΣAᵢ]`.
    ///
    /// # References
    /// Darles et al. 2007, Eq. 2; docs/equations.md §1(a).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        (0..self.sum.len()).map(|i| self.wave_height(i, x, z)).sum()
    }

    /// Height `h = Σᵢ Aᵢ cos θᵢ`, four waves at a time in SIMD lanes (`wide::f64x4`, Halley iterations
    /// on Kepler's equation); equal to [`TrochoidField::height`] to `~10⁻¹⁴ Σ Aᵢ`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `h` (m).
    ///
    /// # References
    /// docs/equations.md §1(a).
    #[inline]
    pub fn height_lanes(&self, x: f64, z: f64) -> f64 {
        let s = self.sum;
        lanes::trochoid_height(&s.kx, &s.kz, &self.offset, &s.amplitude, &s.steepness, x, z)
    }

    /// Heights at many points, each by [`TrochoidField::height_lanes`].
    ///
    /// # Arguments
    /// - `xs`, `zs`: horizontal positions (m), equal lengths.
    /// - `out`: receives the heights (m), same length.
    ///
    /// # Panics
    /// If the three slices differ in length.
    ///
    /// # References
    /// docs/equations.md §1.
    pub fn heights(&self, xs: &[f64], zs: &[f64], out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = self.height_lanes(x, z);
        }
    }

    /// Gradient of the trochoid sum, `∇h = −Σ Aᵢ kᵢ sin θᵢ/(1 − Qᵢ cos θᵢ)` (with `dθ/ds = 1/(1 − Q cos θ)`).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `(∂h/∂x, ∂h/∂z)` (dimensionless), `|∇h| ≤ Σ kᵢAᵢ/√(1 − Qᵢ²)`.
    ///
    /// # References
    /// docs/equations.md §1(a) (slope of a trochoid).
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

    /// Upward unit normal `(−∂h/∂x, 1, −∂h/∂z)/√(1 + |∇h|²)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The normal (unit, `n_y > 0`).
    ///
    /// # References
    /// docs/equations.md §1.
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// Horizontal displacement of the waves' particles at `(x, z)`, `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `D` (m), `|D| ≤ Σ Qᵢ/kᵢ`.
    ///
    /// # References
    /// docs/equations.md §1 (trochoid orbits).
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

    /// Jacobian of the horizontal map at the waves' phases, `J = det(I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `J` (dimensionless); `1 − Q cos θ` for one wave.
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
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

    /// Velocity of the surface point above `(x, z)`: `v_xz = Σ (Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ`, and the kinematic
    /// condition `v_y = ∂h/∂t + ∇h·v_xz` with `∂h/∂t = Σ Aᵢωᵢ sin θᵢ/(1 − Qᵢ cos θᵢ)` (see
    /// [`TrochoidSum`] for what this means with many waves).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `(v_x, v_y, v_z)` (m s⁻¹); for one wave the particle's velocity `((Qω/k) d̂ cos θ, Aω sin θ)`.
    ///
    /// # References
    /// docs/equations.md §1; Lamb 1932, *Hydrodynamics*, §9 (kinematic condition).
    pub fn velocity(&self, x: f64, z: f64) -> DVec3 {
        let s = &self.sum;
        let (mut dh_dt, mut grad, mut v) = (0.0, DVec2::ZERO, DVec2::ZERO);
        for i in 0..s.len() {
            let (_, c, sn) = self.wave_phase(i, x, z);
            let k = DVec2::new(s.kx[i], s.kz[i]);
            // ∂θ/∂s = 1/(1 − Q cos θ); ∂s/∂t = −ω, ∇s = k.
            let a_sn_over = s.amplitude[i] * sn / (1.0 - s.steepness[i] * c);
            dh_dt += s.omega[i] * a_sn_over;
            grad -= a_sn_over * k;
            v += s.steepness[i] * s.omega[i] * c / (s.wavenumber[i] * s.wavenumber[i]) * k;
        }
        DVec3::new(v.x, dh_dt + grad.dot(v), v.y)
    }
}
