//! The sea as one surface: built once from a scene's waves ([`Ocean`]), frozen at any instant
//! ([`SeaFrame`]), and sampled there ([`SurfaceSample`]) — the one surface that is traced,
//! queried, baked and meshed.

use std::sync::{Arc, OnceLock};

use glam::{DVec2, DVec3};

use crate::{FftFrame, FftKinematics, FftOcean, GerstnerSurface, SineSet, TracedTrochoids, TrochoidSet, WaveError};

/// Waves shorter than this are not drawn as geometry by the sine surface of Chen et al.: they only
/// perturb its normals (m).
pub const SINE_DETAIL_WAVELENGTH_M: f64 = 4.0;

/// The sea of a scene as a model of time: its waves, ready to be frozen at any instant.
///
/// One of the four surfaces Brine draws: Darles et al.'s trochoid sum (the default), the true
/// Gerstner sum, Chen et al.'s sine waves (with normal-only detail waves), or Tessendorf's FFT
/// cascades.
///
/// # Example
///
/// ```
/// use brine_waves::{FitOptions, Ocean, PiersonMoskowitz, CosineTwoS, Spectrum, fit_trochoids};
///
/// let pm = PiersonMoskowitz::from_u10(8.0)?;
/// let spreading = CosineTwoS::hasselmann(pm.peak_omega())?;
/// let set = fit_trochoids(&pm, &spreading, 60, 7, &FitOptions::default())?;
/// let ocean = Ocean::trochoids(set);
/// let frame = ocean.at_time(12.0);
/// let p = frame.sample(3.0, -4.0);
/// assert!((p.height - frame.height(3.0, -4.0)).abs() < 1e-12);
/// assert!(p.normal.y > 0.0);
/// # Ok::<(), brine_waves::WaveError>(())
/// ```
#[derive(Debug, Clone)]
pub enum Ocean {
    /// Darles et al.'s sum of trochoid height fields.
    Trochoids {
        /// The waves.
        set: TrochoidSet,
    },
    /// The Gerstner sum of the same waves.
    Gerstner {
        /// The waves.
        set: TrochoidSet,
        /// The checked surface.
        surface: GerstnerSurface,
    },
    /// Chen et al.'s sine waves: those of at least [`SINE_DETAIL_WAVELENGTH_M`] as geometry, the
    /// shorter ones in the normals only.
    Sine {
        /// The geometric waves.
        geometry: TrochoidSet,
        /// The surface (geometry and detail).
        surface: SineSet,
    },
    /// Tessendorf's FFT cascades.
    Fft {
        /// The random amplitudes of every cascade.
        ocean: Arc<FftOcean>,
    },
}

impl Ocean {
    /// The trochoid sum of `set`.
    pub fn trochoids(set: TrochoidSet) -> Self {
        Ocean::Trochoids { set }
    }

    /// The Gerstner sum of `set`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] if `Σ Qᵢ ≥ 1` (the sum would fold; see [`GerstnerSurface::new`]).
    pub fn gerstner(set: TrochoidSet) -> Result<Self, WaveError> {
        let surface = GerstnerSurface::new(&set)?;
        Ok(Ocean::Gerstner { set, surface })
    }

    /// Chen et al.'s sine waves of `set`, split at [`SINE_DETAIL_WAVELENGTH_M`].
    pub fn sine(set: &TrochoidSet) -> Self {
        let geometry = TrochoidSet::new(
            set.waves().iter().copied().filter(|w| w.wavelength() >= SINE_DETAIL_WAVELENGTH_M).collect(),
        );
        Ocean::Sine { geometry, surface: SineSet::split_at_wavelength(set, SINE_DETAIL_WAVELENGTH_M) }
    }

    /// The FFT sea of `ocean`.
    pub fn fft(ocean: FftOcean) -> Self {
        Ocean::Fft { ocean: Arc::new(ocean) }
    }

    /// The waves of a trochoid, Gerstner or sine sea (the geometric ones for the sine sea);
    /// `None` for the FFT sea.
    pub fn waves(&self) -> Option<&TrochoidSet> {
        match self {
            Ocean::Trochoids { set } | Ocean::Gerstner { set, .. } => Some(set),
            Ocean::Sine { geometry, .. } => Some(geometry),
            Ocean::Fft { .. } => None,
        }
    }

    /// The sea a square grid of spacing `spacing_m` (m, `> 0`) samples without aliasing: the
    /// trochoid and Gerstner sums of [`crate::grid_band`]'s waves (the waves shorter than two
    /// spacings left out, those up to three faded), for baked maps and meshes. `None` for the
    /// sine sea (its detail waves are normals of their own) and the FFT sea (its cascades are
    /// grids of their own).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] if the faded Gerstner sum cannot be built (it can whenever the
    /// sea's own could: fading only lowers `Σ Qᵢ`).
    pub fn grid_band(&self, spacing_m: f64) -> Result<Option<(Ocean, crate::GridBand)>, WaveError> {
        let band = |set: &TrochoidSet| crate::grid_band(set, spacing_m);
        Ok(match self {
            Ocean::Trochoids { set } => {
                let b = band(set);
                Some((Ocean::trochoids(b.waves.clone()), b))
            }
            Ocean::Gerstner { set, .. } => {
                let b = band(set);
                Some((Ocean::gerstner(b.waves.clone())?, b))
            }
            Ocean::Sine { .. } | Ocean::Fft { .. } => None,
        })
    }

    /// The FFT sea's ocean (its cascades' spectra), `None` for the other seas.
    pub fn fft_ocean(&self) -> Option<&FftOcean> {
        match self {
            Ocean::Fft { ocean } => Some(ocean),
            _ => None,
        }
    }

    /// The FFT sea at time `t` as a square grid of spacing `spacing_m` (m, `> 0`) samples it
    /// without aliasing (brine-waves `FftOcean::at_time_on_grid` and
    /// `FftOcean::kinematics_on_grid`: its modes shorter than two spacings left out, those up to
    /// three faded, from the surface and from the particles' motion alike), for baked maps and
    /// meshes; `None` for the other seas (see [`Self::grid_band`]).
    ///
    /// # Returns
    /// The frame and what was left out.
    pub fn fft_frame_on_grid(&self, t: f64, spacing_m: f64) -> Option<(SeaFrame, crate::FftGridBand)> {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        let Ocean::Fft { ocean } = self else { return None };
        let (frame, band) = ocean.at_time_on_grid(t, spacing_m);
        let surface = FrameSurface::Fft(Box::new(frame));
        // The particles move with the same modes as the surface (the displacement read at a rest
        // position, the velocities): their kinematics weighted alike, not the whole sea's.
        let kinematics = OnceLock::new();
        let _ = kinematics.set(ocean.kinematics_on_grid(t, spacing_m));
        let frame = SeaFrame { time: t, surface, waves: None, fft: Some(Arc::clone(ocean)), kinematics };
        Some((frame, band))
    }

    /// The sea frozen at time `t`.
    ///
    /// # Arguments
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// The [`SeaFrame`]; for the FFT sea this synthesises the cascades (four inverse FFTs each).
    pub fn at_time(&self, t: f64) -> SeaFrame {
        debug_assert!(t.is_finite(), "time {t} must be finite");
        let surface = match self {
            Ocean::Trochoids { set } => FrameSurface::Trochoids(TracedTrochoids::new(set, t)),
            Ocean::Gerstner { surface, .. } => FrameSurface::Gerstner(surface.clone()),
            Ocean::Sine { surface, .. } => FrameSurface::Sine(surface.clone()),
            Ocean::Fft { ocean } => FrameSurface::Fft(Box::new(ocean.at_time(t))),
        };
        let fft = match self {
            Ocean::Fft { ocean } => Some(Arc::clone(ocean)),
            _ => None,
        };
        SeaFrame { time: t, surface, waves: self.waves().cloned(), fft, kinematics: OnceLock::new() }
    }
}

/// The surface of a [`SeaFrame`], as the tracer sees it.
#[derive(Debug, Clone)]
pub enum FrameSurface {
    /// Darles et al.'s trochoid sum, laid out for the tiered tracer.
    Trochoids(TracedTrochoids),
    /// The true Gerstner sum (time-independent; traced at the frame's time).
    Gerstner(GerstnerSurface),
    /// Chen et al.'s sine waves with normal-perturbing detail waves (traced at the frame's time).
    Sine(SineSet),
    /// Tessendorf's FFT cascades at the frame's time (traced as certified cubic B-splines).
    Fft(Box<FftFrame>),
}

/// The sea at one instant: the surface the renderer traces, and its values at any point.
#[derive(Debug)]
pub struct SeaFrame {
    pub(crate) time: f64,
    pub(crate) surface: FrameSurface,
    waves: Option<TrochoidSet>,
    fft: Option<Arc<FftOcean>>,
    kinematics: OnceLock<FftKinematics>,
}

/// What the sea does at one point of a [`SeaFrame`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceSample {
    /// Height `h(x, z)` of the surface as traced (m).
    pub height: f64,
    /// Upward unit shading normal (the detail waves of the sine sea included).
    pub normal: DVec3,
    /// Horizontal displacement `D` of the water particle at the surface there (m): its rest
    /// position is `(x, z) − D`.
    pub displacement: DVec2,
    /// Velocity of that particle `(v_x, v_y, v_z)` (m s⁻¹).
    pub velocity: DVec3,
    /// Its vertical acceleration (m s⁻²).
    pub vertical_acceleration: f64,
    /// Jacobian determinant of the horizontal map from rest positions (dimensionless): `< 1`
    /// compressed, `≤ 0` folded (whitecaps).
    pub jacobian: f64,
    /// The deformation `M = ∂x/∂u` of the horizontal map, symmetric, as `(M_xx, M_xz, M_zz)`.
    pub deformation: DVec3,
}

impl SurfaceSample {
    /// The smaller eigenvalue of the deformation `M` and its unit eigenvector: the direction in
    /// which the surface is compressed most (Blender's "spray" direction where it folds).
    ///
    /// # Returns
    /// `(μ₋, e₋)`: `μ₋ = (a + c)/2 − √(((a − c)/2)² + b²)` for `M = [[a, b], [b, c]]`, and `e₋`
    /// (unit; `(1, 0)` when `M` is a multiple of `I`).
    pub fn minor_eigen(&self) -> (f64, DVec2) {
        let (a, b, c) = (self.deformation.x, self.deformation.y, self.deformation.z);
        let half = 0.5 * (a - c);
        let r = half.hypot(b);
        let mu = 0.5 * (a + c) - r;
        // (M − μI) e = 0: e ∥ (b, μ − a) or (μ − c, b), whichever is longer.
        let e1 = DVec2::new(b, mu - a);
        let e2 = DVec2::new(mu - c, b);
        let e = if e1.length_squared() >= e2.length_squared() { e1 } else { e2 };
        let len = e.length();
        (mu, if len > 1e-300 { e / len } else { DVec2::X })
    }
}

impl SeaFrame {
    /// The time of the frame (s).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The surface the tracer draws.
    pub fn surface(&self) -> &FrameSurface {
        &self.surface
    }

    /// Height of the surface as traced above `(x, z)` (m).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        match &self.surface {
            FrameSurface::Trochoids(s) => s.height(x, z),
            FrameSurface::Gerstner(s) => s.at_time(self.time).height_lanes(x, z),
            FrameSurface::Sine(s) => s.at_time(self.time).height_lanes(x, z),
            FrameSurface::Fft(f) => f.height(x, z),
        }
    }

    /// `(h_min, h_max)` (m): bounds of the height over all positions.
    pub fn height_bounds(&self) -> (f64, f64) {
        match &self.surface {
            FrameSurface::Trochoids(_) | FrameSurface::Gerstner(_) | FrameSurface::Sine(_) => {
                let a = self.waves.as_ref().map_or(0.0, TrochoidSet::total_amplitude);
                let b = match &self.surface {
                    FrameSurface::Trochoids(s) => s.error_bound(),
                    _ => 0.0,
                };
                (-a - b, a + b)
            }
            FrameSurface::Fft(f) => f.height_bounds(),
        }
    }

    /// The FFT sea's particle kinematics at the frame's time (synthesised on first use).
    fn kinematics(&self) -> Option<&FftKinematics> {
        let ocean = self.fft.as_ref()?;
        Some(self.kinematics.get_or_init(|| ocean.kinematics(self.time)))
    }

    /// Everything the sea does above `(x, z)` at the frame's time.
    ///
    /// The height is the traced one (for the trochoid sum its f32 kernel, within
    /// [`TracedTrochoids::error_bound`] of the f64 sum); the other values are evaluated in f64:
    ///
    /// - trochoid sum (by the tracer's f32 kernel, within `10⁻⁶` of the f64 sums): each wave's
    ///   particle at its own phase `θᵢ` (Kepler's equation `θ − Q sin θ = k·x − ωt + φ`), `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ`, `v_xz = Σ (Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ`,
    ///   `v_y = ∂h/∂t + ∇h·v_xz` (kinematic condition), `a_y = −Σ Aᵢωᵢ² cos θᵢ`,
    ///   `M = I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ`;
    /// - Gerstner sum: the particle of rest position `u` (the sum inverted), exactly;
    /// - sine waves: the Eulerian linear values (`D = 0`, `M = I`, `a_y = ∂²h/∂t²`);
    /// - FFT: per cascade, the particle found by Newton's method on `u + λD(u) = x` on its rest
    ///   grid, summed over the cascades; `J` is the frame's (`1 + Σ (J_c − 1)`, as the whitecaps
    ///   read it).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The [`SurfaceSample`].
    ///
    /// # References
    /// Darles et al. 2007, Eq. 2 (trochoid sum); Tessendorf 2001, Eq. 36, 44 (FFT); Chen et al.
    /// 2007, §3.3 (sine); Dupuy & Bruneton 2012 (Jacobian); Lamb 1932, §9 (kinematic condition).
    pub fn sample(&self, x: f64, z: f64) -> SurfaceSample {
        debug_assert!(x.is_finite() && z.is_finite());
        let t = self.time;
        match &self.surface {
            FrameSurface::Trochoids(traced) => {
                let k = traced.kinematics(x, z);
                let g = k.gradient;
                SurfaceSample {
                    // The kinematics' height is `TracedTrochoids::height`'s sum, bit for bit.
                    height: k.height,
                    normal: DVec3::new(-g.x, 1.0, -g.y).normalize(),
                    displacement: k.displacement,
                    velocity: DVec3::new(k.velocity.x, k.height_rate + g.dot(k.velocity), k.velocity.y),
                    vertical_acceleration: k.vertical_acceleration,
                    jacobian: k.deformation.x * k.deformation.z - k.deformation.y * k.deformation.y,
                    deformation: k.deformation,
                }
            }
            FrameSurface::Gerstner(surface) => self.gerstner_sample(&surface.at_time(t).point(x, z)),
            FrameSurface::Sine(surface) => {
                let f = surface.at_time(t);
                let a = self.waves.as_ref().map_or(0.0, |s| {
                    s.waves()
                        .iter()
                        .map(|w| {
                            let d = w.direction_vector();
                            let phi = w.wavenumber() * d.dot(DVec2::new(x, z)) - w.omega() * t + w.phase();
                            -w.amplitude() * w.omega() * w.omega() * phi.cos()
                        })
                        .sum()
                });
                SurfaceSample {
                    height: f.height_lanes(x, z),
                    normal: f.shading_normal(x, z),
                    displacement: DVec2::ZERO,
                    velocity: f.velocity(x, z),
                    vertical_acceleration: a,
                    jacobian: 1.0,
                    deformation: DVec3::new(1.0, 0.0, 1.0),
                }
            }
            FrameSurface::Fft(frame) => {
                let mut p = SurfaceSample {
                    height: frame.height(x, z),
                    normal: frame.normal(x, z),
                    displacement: DVec2::ZERO,
                    velocity: DVec3::ZERO,
                    vertical_acceleration: 0.0,
                    jacobian: frame.jacobian(x, z),
                    deformation: DVec3::new(1.0, 0.0, 1.0),
                };
                if let Some(k) = self.kinematics() {
                    for c in 0..k.cascade_count() {
                        let (_, s) = k.rest_position(c, DVec2::new(x, z));
                        p.displacement += s.displacement;
                        p.velocity += s.velocity;
                        p.vertical_acceleration += s.vertical_acceleration;
                        p.deformation += s.deformation - DVec3::new(1.0, 0.0, 1.0);
                    }
                }
                p
            }
        }
    }

    /// The particle at rest position `u` (m): its displacement `D(u)` (m,
    /// [`SeaFrame::rest_displacement`]) and the [`SurfaceSample`] where it is, at `x = u + D(u)`,
    /// as `(D, sample)`. The Gerstner sea knows the rest position here and samples it without
    /// inverting (one pass over the waves, where [`SeaFrame::sample`] at `x` would invert back to
    /// `u` within its tolerance `τ`: the heights agree within `2τL`); the other seas sample at
    /// `x` with [`SeaFrame::sample`].
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    ///
    /// # Returns
    /// `(D, sample)`: the displacement (m) and the surface at `u + D`.
    ///
    /// # References
    /// docs/equations.md §1(b) (the Gerstner map).
    pub fn sample_at_rest(&self, u: DVec2) -> (DVec2, SurfaceSample) {
        debug_assert!(u.is_finite());
        if let FrameSurface::Gerstner(surface) = &self.surface {
            let p = surface.at_time(self.time).point_at_rest(u);
            return (p.displacement, self.gerstner_sample(&p));
        }
        let d = self.rest_displacement(u);
        let x = u + d;
        (d, self.sample(x.x, x.y))
    }

    /// The [`SurfaceSample`] of a Gerstner point: its fields, and the deformation `M` and the
    /// vertical acceleration of its particle.
    fn gerstner_sample(&self, p: &crate::GerstnerPoint) -> SurfaceSample {
        let (t, u) = (self.time, p.rest);
        let mut m = DVec3::new(1.0, 0.0, 1.0);
        let mut a = 0.0;
        for w in self.waves.as_ref().map_or(&[][..], |s| s.waves()) {
            let d = w.direction_vector();
            let phi = w.wavenumber() * d.dot(u) - w.omega() * t + w.phase();
            let c = phi.cos();
            m -= w.steepness() * c * DVec3::new(d.x * d.x, d.x * d.y, d.y * d.y);
            a -= w.amplitude() * w.omega() * w.omega() * c;
        }
        let g = p.gradient;
        SurfaceSample {
            height: p.height,
            normal: DVec3::new(-g.x, 1.0, -g.y).normalize(),
            displacement: p.displacement,
            velocity: p.velocity,
            vertical_acceleration: a,
            jacobian: m.x * m.z - m.y * m.y,
            deformation: m,
        }
    }

    /// A smooth periodic parametrisation of the surface for meshes and baked maps: the
    /// horizontal displacement `D(u)` of the particle of rest position `u`, so that the grid
    /// point `u` goes to `x = u + D(u)` and then to the surface point `(x, h(x))` — the vertices
    /// crowd toward the crests as the water does, and every vertex lies on the traced surface.
    ///
    /// - trochoid sum: each wave's particle of rest phase `kᵢ·u − ωᵢt + φᵢ`,
    ///   `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin(kᵢ·u − ωᵢt + φᵢ)` (exact for one wave);
    /// - Gerstner sum: its own displacement `D(u)`, exact;
    /// - sine waves: `0`;
    /// - FFT: `Σ_c λD_c(u)`, the cascades' displacements on their rest grids (bilinear).
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    ///
    /// # Returns
    /// `D(u)` (m).
    ///
    /// # References
    /// docs/equations.md §1 (trochoid and Gerstner orbits); Tessendorf 2001, Eq. 44.
    pub fn rest_displacement(&self, u: DVec2) -> DVec2 {
        let t = self.time;
        match &self.surface {
            FrameSurface::Trochoids(traced) => traced.rest_displacement(u),
            FrameSurface::Gerstner(_) => {
                let mut d = DVec2::ZERO;
                for w in self.waves.as_ref().map_or(&[][..], |s| s.waves()) {
                    let dir = w.direction_vector();
                    let phi = w.wavenumber() * dir.dot(u) - w.omega() * t + w.phase();
                    d -= w.horizontal_radius() * phi.sin() * dir;
                }
                d
            }
            FrameSurface::Sine(_) => DVec2::ZERO,
            FrameSurface::Fft(_) => self
                .kinematics()
                .map_or(DVec2::ZERO, |k| (0..k.cascade_count()).map(|c| k.at_rest(c, u).displacement).sum()),
        }
    }
}

/// The f64 sample of a trochoid sum (height included) at `(x, z)`, time `t`: the reference of
/// the f32 kernel's.
#[cfg(test)]
fn trochoid_sample(waves: &[crate::Trochoid], x: f64, z: f64, t: f64) -> SurfaceSample {
    let (mut h, mut dh_dt, mut a) = (0.0, 0.0, 0.0);
    let (mut grad, mut v, mut d) = (DVec2::ZERO, DVec2::ZERO, DVec2::ZERO);
    let mut m = DVec3::new(1.0, 0.0, 1.0);
    for w in waves {
        let dir = w.direction_vector();
        let (k, q, amp, omega) = (w.wavenumber(), w.steepness(), w.amplitude(), w.omega());
        let kv = k * dir;
        let s = kv.dot(DVec2::new(x, z)) - omega * t + w.phase();
        let (_, c, sn) = crate::solve_trochoid_phase(s, q);
        // dθ/ds = 1/(1 − Q cos θ); ∂s/∂t = −ω, ∇s = k.
        let a_sn_over = amp * sn / (1.0 - q * c);
        h += amp * c;
        dh_dt += omega * a_sn_over;
        grad -= a_sn_over * kv;
        v += q * omega * c / k * dir;
        d -= q * sn / k * dir;
        m -= q * c * DVec3::new(dir.x * dir.x, dir.x * dir.y, dir.y * dir.y);
        a -= amp * omega * omega * c;
    }
    SurfaceSample {
        height: h,
        normal: DVec3::new(-grad.x, 1.0, -grad.y).normalize(),
        displacement: d,
        velocity: DVec3::new(v.x, dh_dt + grad.dot(v), v.y),
        vertical_acceleration: a,
        jacobian: m.x * m.z - m.y * m.y,
        deformation: m,
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::{CosineTwoS, FftOptions, FitOptions, PiersonMoskowitz, Spectrum, Trochoid, WaveSurface, fit_trochoids};

    /// A 60-wave Pierson–Moskowitz set fitted at `u10` (m s⁻¹), for the surface's tests.
    pub(crate) fn set(u10: f64) -> TrochoidSet {
        let pm = PiersonMoskowitz::from_u10(u10).unwrap();
        let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        fit_trochoids(&pm, &spreading, 60, 7, &FitOptions::default()).unwrap()
    }

    /// The f32 kernel against f64 sums of ~60 terms of size ≤ 1: `60 × 2⁻²³ × (a few)`, with the
    /// kernel's own profile error (`5 × 10⁻⁷` relative).
    const F32_KERNEL: f64 = 1e-4;

    /// Central differences of step `h` in time: error `O(h²)` times the third derivative,
    /// `~ a ω² h²/6 ≈ 10⁻⁵` relative for the waves here at `h = 10⁻³ s`; the tolerance leaves room
    /// for the Newton solves' rounding amplified by `1/h`.
    const DIFFERENCE: f64 = 1e-4;

    /// A point carried by the sample's velocity stays on the surface (kinematic condition) and
    /// its vertical velocity changes at the sample's acceleration, for one trochoid (exact there).
    #[test]
    fn one_trochoid_particle_moves_with_the_sample() {
        let w = Trochoid::new(0.8, 0.3, 0.4, (9.81f64 * 0.3).sqrt(), 0.2, 0.6).unwrap();
        let set = TrochoidSet::new(vec![w]);
        let ocean = Ocean::trochoids(set.clone());
        let (t0, h) = (5.0, 1e-3);
        let frame = ocean.at_time(t0);
        let x0 = DVec2::new(2.0, -1.0);
        let p = trochoid_sample(set.waves(), x0.x, x0.y, t0);
        // The particle's position a step later, and the surface there.
        let x1 = x0 + h * DVec2::new(p.velocity.x, p.velocity.z);
        let later = trochoid_sample(set.waves(), x1.x, x1.y, t0 + h);
        let earlier = {
            let xm = x0 - h * DVec2::new(p.velocity.x, p.velocity.z);
            trochoid_sample(set.waves(), xm.x, xm.y, t0 - h)
        };
        let dy = (later.height - earlier.height) / (2.0 * h);
        assert!((dy - p.velocity.y).abs() < DIFFERENCE * p.velocity.y.abs().max(1.0), "{dy} {}", p.velocity.y);
        let ay = (later.velocity.y - earlier.velocity.y) / (2.0 * h);
        assert!((ay - p.vertical_acceleration).abs() < 1e-2 * p.vertical_acceleration.abs().max(0.1));
        // The traced height is the f64 one within the kernel's bound.
        let q = frame.sample(x0.x, x0.y);
        assert!((q.height - p.height).abs() <= frame.height_bounds().1 - set.total_amplitude() + 1e-12);
    }

    #[test]
    fn the_sample_agrees_with_the_wave_surfaces() {
        let set = set(10.0);
        let sum = crate::TrochoidSum::new(&set);
        let frame = Ocean::trochoids(set.clone()).at_time(7.0);
        for (x, z) in [(0.0, 0.0), (13.0, -4.5), (-80.0, 33.0)] {
            let p = frame.sample(x, z);
            let f = sum.at_time(7.0);
            let r = trochoid_sample(set.waves(), x, z, 7.0);
            assert!((p.displacement - f.displacement(x, z)).length() < F32_KERNEL);
            assert!((p.velocity - f.velocity(x, z)).length() < F32_KERNEL);
            assert!((p.jacobian - f.jacobian(x, z)).abs() < F32_KERNEL);
            assert!((p.normal - f.normal(x, z)).length() < F32_KERNEL);
            assert!((p.vertical_acceleration - r.vertical_acceleration).abs() < F32_KERNEL);
            // The f64 reference agrees with the wave surfaces to rounding.
            assert!((r.velocity - f.velocity(x, z)).length() < 1e-12 && (r.normal - f.normal(x, z)).length() < 1e-12);
            let u = DVec2::new(x, z);
            let rest: DVec2 = set
                .waves()
                .iter()
                .map(|w| {
                    let phi = w.wavenumber() * w.direction_vector().dot(u) - w.omega() * 7.0 + w.phase();
                    -w.horizontal_radius() * phi.sin() * w.direction_vector()
                })
                .sum();
            assert!((frame.rest_displacement(u) - rest).length() < F32_KERNEL);
        }
        let g = Ocean::gerstner(set.clone()).unwrap().at_time(7.0);
        let surface = GerstnerSurface::new(&set).unwrap();
        for (x, z) in [(0.0, 0.0), (13.0, -4.5)] {
            let p = g.sample(x, z);
            assert!((p.jacobian - surface.jacobian(x, z, 7.0)).abs() < 1e-9);
            assert!((p.height - surface.height(x, z, 7.0)).abs() < 1e-9);
        }
    }

    /// The sample of a particle at its rest position is the sample where it is. On the trochoid
    /// sea it is `sample` at `u + D(u)`, bit for bit. On the Gerstner sea it is taken at `u`
    /// without inverting, and `sample` inverts back to a rest position within `2τ/(1 − ΣQ)` of it
    /// (`τ` ≈ 10⁻¹² m, `ΣQ` = 0.9: 2×10⁻¹¹ m); the fastest field, the gradient, moves by at most
    /// `Σk²A/(1 − ΣQ)³` per metre of it (about 10³ m⁻¹ for this 10 m/s set): 2×10⁻⁸, so 10⁻⁷.
    #[test]
    fn the_sample_at_rest_is_the_sample_where_the_particle_is() {
        const REST_SAMPLE_ABS: f64 = 1e-7;
        let set = set(10.0);
        for gerstner in [true, false] {
            let ocean = if gerstner { Ocean::gerstner(set.clone()).unwrap() } else { Ocean::trochoids(set.clone()) };
            let frame = ocean.at_time(7.0);
            for (x, z) in [(0.0, 0.0), (13.0, -4.5), (-80.0, 33.0)] {
                let u = DVec2::new(x, z);
                let (d, a) = frame.sample_at_rest(u);
                let p = u + d;
                let b = frame.sample(p.x, p.y);
                if !gerstner {
                    assert_eq!(d, frame.rest_displacement(u));
                    assert_eq!(a, b);
                    continue;
                }
                assert!((d - frame.rest_displacement(u)).length() < 1e-12, "{u}");
                assert!((a.height - b.height).abs() < REST_SAMPLE_ABS, "{u}");
                assert!((a.normal - b.normal).length() < REST_SAMPLE_ABS, "{u}");
                assert!((a.velocity - b.velocity).length() < REST_SAMPLE_ABS, "{u}");
                assert!((a.jacobian - b.jacobian).abs() < REST_SAMPLE_ABS, "{u}");
                assert!((a.displacement - b.displacement).length() < REST_SAMPLE_ABS, "{u}");
            }
        }
    }

    /// The minor eigenvector satisfies `M e = μ e` with `μ` the smaller eigenvalue.
    #[test]
    fn minor_eigen_is_an_eigenpair() {
        for m in [DVec3::new(0.3, 0.4, 1.2), DVec3::new(1.0, 0.0, 1.0), DVec3::new(-0.2, -0.7, 0.9)] {
            let s = SurfaceSample {
                height: 0.0,
                normal: DVec3::Y,
                displacement: DVec2::ZERO,
                velocity: DVec3::ZERO,
                vertical_acceleration: 0.0,
                jacobian: m.x * m.z - m.y * m.y,
                deformation: m,
            };
            let (mu, e) = s.minor_eigen();
            let me = DVec2::new(m.x * e.x + m.y * e.y, m.y * e.x + m.z * e.y);
            assert!((me - mu * e).length() < 1e-12, "{m}");
            let trace = m.x + m.z;
            assert!(mu <= 0.5 * trace + 1e-15 && (mu * (trace - mu) - s.jacobian).abs() < 1e-12);
        }
    }

    /// The FFT sea's particle found under a point is carried there by its displacement, and its
    /// vertical velocity is the rate of its height.
    #[test]
    fn fft_particles_sit_under_their_points() {
        let pm = PiersonMoskowitz::from_u10(12.0).unwrap();
        let spreading = CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let options = FftOptions { resolution: 64, ..FftOptions::for_spectrum(&pm, 2) };
        let fft = FftOcean::new(&pm, &spreading, &options).unwrap();
        let k = fft.kinematics(4.0);
        for c in 0..k.cascade_count() {
            for x in [DVec2::new(3.0, 4.0), DVec2::new(-20.0, 11.0)] {
                let (u, s) = k.rest_position(c, x);
                assert!((u + s.displacement - x).length() < 1e-4, "{c} {x}");
            }
        }
        let ocean = Ocean::fft(fft);
        let frame = ocean.at_time(4.0);
        let p = frame.sample(3.0, 4.0);
        assert!(p.normal.y > 0.0 && p.jacobian.is_finite() && p.velocity.is_finite());
    }
}
