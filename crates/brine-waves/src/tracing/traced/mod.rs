//! A trochoid sum frozen at one instant and laid out for fast tracing: waves sorted by length
//! scale in lane groups of 8 f32 lanes (SIMD), about five tiers of groups along a ray, each with
//! its bounds.

// Lane loops index several parallel arrays of one tier at once.
#![allow(clippy::needless_range_loop)]

use std::f64::consts::TAU;

use brine_core::footprint::footprint_weight;
#[cfg(feature = "tracing")]
use brine_trace::{RayTiers, TierBounds, TierSample};
use glam::{DVec2, DVec3};
use wide::{f32x8, f64x4};

use crate::fit::trochoid::trough_curvature_factor;
use crate::tracing::fast_profile::{
    PROFILE_ERROR, ProfileMode, SERIES_ROWS, profile1, profile8, reduce_phases, series_polynomials,
};
use crate::{Trochoid, TrochoidSet};

#[cfg(feature = "tracing")]
mod adapter;
#[cfg(feature = "tracing")]
pub(crate) mod tiers;

#[cfg(feature = "tracing")]
pub(crate) use adapter::cone_span;

/// Waves per lane group: one f32x8 vector.
pub const LANES: usize = 8;

/// Tiers of waves the tracer sees (besides `y`), whatever `N`: each holds [`tier_group`] lane
/// groups of 8 waves.
///
/// The tracer's bookkeeping per tier (bounds, the certified step's assignment of each tier) costs
/// about as much as sampling 8 lanes, while frequency pruning rarely drops more than a few lane
/// groups of a fitted sea near the surface. Whole 640×480 frames of the default scene (2 threads,
/// s, best of two) with 1, 2, 3, 5 groups per tier: N = 30: 0.57, 0.53, 0.56, 0.56; N = 50: 0.74,
/// 0.71, 0.71, 0.73; N = 200: 2.36, 2.08, 1.93, 1.95; N = 100, one thread, 1, 2, 3, 4, 6 groups:
/// 3.04, 2.74, 2.63, 2.66, 2.65. About five tiers is at or near the fastest everywhere.
const WAVE_TIERS: usize = 5;

/// Lane groups per tracer tier for a sea of `groups` lane groups: `⌈groups/5⌉` ([`WAVE_TIERS`]).
fn tier_group(groups: usize) -> usize {
    groups.div_ceil(WAVE_TIERS).max(1)
}

/// One tier of 8 lanes (padding lanes have `A = 0`, `k = 0`).
#[derive(Debug, Clone)]
struct Tier {
    kx: [f64; LANES],
    kz: [f64; LANES],
    offset: [f64; LANES],
    wavenumber: [f64; LANES],
    amplitude: [f32; LANES],
    steepness: [f32; LANES],
    /// `Aᵢ/√(1 − Qᵢ²)` (the max slope per unit wavenumber along `d̂`).
    slope_factor: [f64; LANES],
    /// `Aᵢ/(1 − Qᵢ)²` (the curvature bound per unit wavenumber² along `d̂`: the crest's).
    curvature_factor: [f64; LANES],
    /// `Aᵢ c(Qᵢ)` (the trough's, [`Trochoid::max_trough_curvature`]): how concave `nᵢ = −hᵢ` can
    /// be, per unit wavenumber² along `d̂`.
    concavity_factor: [f64; LANES],
    /// `Aᵢ·PROFILE_ERROR/(1 − Qᵢ)²` (derivative error per unit `|σᵢ|`).
    slope_error_factor: [f64; LANES],
    /// Slope covariance `⟨sᵢ²⟩ (k̂x², k̂x k̂z, k̂z²)` per lane, one array per entry (0 for padding
    /// lanes).
    slope_covariance: [[f64; LANES]; 3],
    mode: ProfileMode,
    /// Series polynomial coefficients per lane, `[row][lane]` (series mode; empty otherwise).
    series: Vec<[f32; LANES]>,
    /// `kᵢ` in f32 (the fade distances are computed in f32 lanes).
    wavenumber_f32: [f32; LANES],
    /// `ωᵢ` (rad s⁻¹), for the particle kinematics.
    omega: [f32; LANES],
    /// `(Qᵢ/kᵢ²) kᵢ`, x and z (m): the particle displacement per unit `sin θᵢ`.
    displacement_factor: [[f32; LANES]; 2],
    /// `kᵢ` (x, z) and `1/kᵢ²` in f32, for the particle kinematics.
    kinematic_k: [[f32; LANES]; 3],
    /// Real waves in this tier.
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    count: u32,
    /// `Σ Aᵢ` of the f32 amplitudes the kernel uses (m).
    amplitude_sum: f64,
    /// `Σ Aᵢkᵢ/√(1 − Qᵢ²)`: the tier's 3-D Lipschitz constant (cones).
    spread: f64,
    /// Bound of the evaluation error of the tier's sum (m).
    error: f64,
}

/// The particle kinematics of a trochoid sum at one point ([`TracedTrochoids::kinematics`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Kinematics {
    pub(crate) height: f64,
    pub(crate) gradient: DVec2,
    pub(crate) height_rate: f64,
    pub(crate) velocity: DVec2,
    pub(crate) displacement: DVec2,
    pub(crate) deformation: DVec3,
    pub(crate) vertical_acceleration: f64,
}

/// The trochoid-sum surface of Darles et al. (`F = y − Σ Aᵢ τ_{Qᵢ}(kᵢ d̂ᵢ·(x, z) − ωᵢt + φᵢ)`,
/// [`crate::TrochoidField`]) at one instant, prepared for [`brine_trace::Method::Tiered`]:
///
/// - waves sorted by decreasing `2Aᵢ/Lᵢ = 2√(1 − Qᵢ²)/kᵢ` (Darles' key at its largest, ∝ the
///   wavelength), in tiers of [`LANES`]; component 0 is `y`, then the waves in their original order;
/// - each tier evaluated in f32 SIMD lanes ([`wide::f32x8`]) after an f64 reduction of the phase,
///   within `Aᵢ·5×10⁻⁷·(1 + 1/√(1 − Qᵢ²))` of the f64 surface (test `profile_error_is_within_bound`);
/// - along a ray, each tier knows its value, derivative, range, Lipschitz and curvature bounds
///   (`Σ Aᵢ σᵢ²/(1 − Qᵢ)²`, `σᵢ = kᵢ d̂ᵢ·d̂_xz`), and fades with the pixel footprint.
///
/// With the feature `tracing` it implements `brine_trace::LipschitzSum` (every method can trace
/// it; the components are evaluated by the same f32 kernel) and overrides its `trace_tiered`
/// with the fast path.
///
/// # References
/// Darles et al. 2007 §3.2; docs/equations.md §1 (trochoid profile, per-wave bounds, antialiasing).
#[derive(Debug, Clone)]
pub struct TracedTrochoids {
    tiers: Vec<Tier>,
    /// Lane groups per tier of the tracer ([`tier_group`]).
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    group: usize,
    /// `(tier, lane)` of wave `i` (original order).
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    lane_of_wave: Vec<(usize, usize)>,
    /// Wave `i` (original order): `(Trochoid, offset φᵢ − ωᵢt)`.
    waves: Vec<(Trochoid, f64)>,
    /// Wave `i`'s slope covariance `⟨sᵢ²⟩ (k̂x², k̂x k̂z, k̂z²)`.
    slope_covariance: Vec<DVec3>,
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    pub(crate) total_amplitude: f64,
    error: f64,
}

impl TracedTrochoids {
    /// `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²))`: the pixel footprint on the sea is `αt` across the view and
    /// `αt/max(|d_y|, 0.05)` along it; its extent along `k̂ᵢ` is `αt √(1 + (k̂ᵢ·d̂_xz)²/max(|d_y|, 0.05)²)`.
    ///
    /// Component 0 is `y` (never fades, `∞`); component `i + 1` is wave `i`: the distance (m)
    /// along a ray of unit direction `d` at which wave `i` is faded out by a footprint of
    /// `footprint_angle` (rad, `> 0`).
    pub fn fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 {
            return f64::INFINITY;
        }
        let w = &self.waves[i - 1].0;
        let k = w.wavenumber();
        let sigma = k * (w.direction_vector().x * d.x + w.direction_vector().y * d.z);
        TAU / (footprint_angle * (k * k + sigma * sigma * brine_core::footprint::footprint_stretch_squared(d.y)).sqrt())
    }

    /// The surface of `set` at time `time` (s, finite: the scene's validated time).
    pub fn new(set: &TrochoidSet, time: f64) -> Self {
        debug_assert!(time.is_finite(), "time {time} must be finite");
        let n = set.len();
        let mut order: Vec<usize> = (0..n).collect();
        let key = |w: &Trochoid| (1.0 - w.steepness() * w.steepness()).sqrt() / w.wavenumber();
        order.sort_by(|&a, &b| key(&set.waves()[b]).total_cmp(&key(&set.waves()[a])));
        let mut tiers = Vec::with_capacity(n.div_ceil(LANES));
        let mut lane_of_wave = vec![(0, 0); n];
        for chunk in order.chunks(LANES) {
            let mut t = Tier {
                kx: [0.0; LANES],
                kz: [0.0; LANES],
                offset: [0.0; LANES],
                wavenumber: [0.0; LANES],
                amplitude: [0.0; LANES],
                steepness: [0.0; LANES],
                slope_factor: [0.0; LANES],
                curvature_factor: [0.0; LANES],
                concavity_factor: [0.0; LANES],
                slope_error_factor: [0.0; LANES],
                slope_covariance: [[0.0; LANES]; 3],
                mode: ProfileMode::for_steepness(0.0),
                series: Vec::new(),
                wavenumber_f32: [0.0; LANES],
                omega: [0.0; LANES],
                displacement_factor: [[0.0; LANES]; 2],
                kinematic_k: [[0.0; LANES]; 3],
                count: chunk.len() as u32,
                amplitude_sum: 0.0,
                spread: 0.0,
                error: 0.0,
            };
            let mut q_max = 0.0f64;
            for (l, &i) in chunk.iter().enumerate() {
                let w = &set.waves()[i];
                let d = w.direction_vector();
                let (a, q) = (w.amplitude(), w.steepness());
                t.kx[l] = w.wavenumber() * d.x;
                t.kz[l] = w.wavenumber() * d.y;
                t.offset[l] = w.phase() - w.omega() * time;
                t.omega[l] = w.omega() as f32;
                t.wavenumber[l] = w.wavenumber();
                t.amplitude[l] = a as f32;
                t.steepness[l] = q as f32;
                t.slope_factor[l] = a / (1.0 - q * q).sqrt();
                t.curvature_factor[l] = a / ((1.0 - q) * (1.0 - q));
                t.concavity_factor[l] = a * trough_curvature_factor(q);
                t.slope_error_factor[l] = a * PROFILE_ERROR * (1.0 + 1.0 / ((1.0 - q) * (1.0 - q)));
                let mss = w.mean_square_slope();
                t.slope_covariance[0][l] = mss * d.x * d.x;
                t.slope_covariance[1][l] = mss * d.x * d.y;
                t.slope_covariance[2][l] = mss * d.y * d.y;
                t.wavenumber_f32[l] = w.wavenumber() as f32;
                let k2 = t.wavenumber[l] * t.wavenumber[l];
                t.kinematic_k[0][l] = t.kx[l] as f32;
                t.kinematic_k[1][l] = t.kz[l] as f32;
                t.kinematic_k[2][l] = if t.wavenumber[l] > 0.0 { (1.0 / k2) as f32 } else { 0.0 };
                let f = if k2 > 0.0 { f64::from(t.steepness[l]) / k2 } else { 0.0 };
                t.displacement_factor = [0, 1].map(|c| {
                    let mut row = t.displacement_factor[c];
                    row[l] = (f * [t.kx[l], t.kz[l]][c]) as f32;
                    row
                });
                // f32 amplitude rounding (6×10⁻⁸ relative) and the 8-lane f32 sum are inside the
                // factor 2 of PROFILE_ERROR's margin; the bound adds them explicitly anyway.
                t.error += a * PROFILE_ERROR * (1.0 + 1.0 / (1.0 - q * q).sqrt()) + a * 1e-6;
                q_max = q_max.max(q);
                lane_of_wave[i] = (tiers.len(), l);
            }
            for l in 0..LANES {
                t.amplitude_sum += f64::from(t.amplitude[l]);
                t.spread += t.slope_factor[l] * t.wavenumber[l];
            }
            t.mode = ProfileMode::for_steepness(q_max);
            let m = usize::from(t.mode.harmonics);
            if m > 0 {
                t.series = vec![[0.0; LANES]; SERIES_ROWS];
                for l in 0..chunk.len() {
                    for (row, a) in series_polynomials(f64::from(t.steepness[l]), m).into_iter().enumerate() {
                        t.series[row][l] = a as f32;
                    }
                }
            }
            tiers.push(t);
        }
        let waves = set.waves().iter().map(|w| (*w, w.phase() - w.omega() * time)).collect();
        let error = tiers.iter().map(|t| t.error).sum();
        let slope_covariance = set
            .waves()
            .iter()
            .map(|w| {
                let d = w.direction_vector();
                w.mean_square_slope() * DVec3::new(d.x * d.x, d.x * d.y, d.y * d.y)
            })
            .collect();
        let group = tier_group(tiers.len());
        Self { tiers, group, lane_of_wave, waves, slope_covariance, total_amplitude: set.total_amplitude(), error }
    }

    /// Number of waves.
    pub fn len(&self) -> usize {
        self.waves.len()
    }

    /// `true` for a flat sea.
    pub fn is_empty(&self) -> bool {
        self.waves.is_empty()
    }

    /// Bound of `|h̃ − h|` (m) between this f32 evaluation and the f64 height of
    /// [`crate::TrochoidField`], everywhere.
    pub fn error_bound(&self) -> f64 {
        self.error
    }

    /// Height `h̃(x, z)` (m) by the f32 SIMD kernel.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        let mut sum = 0.0;
        for t in &self.tiers {
            let mut s = [0.0; LANES];
            for l in 0..LANES {
                s[l] = t.kx[l] * x + t.kz[l] * z + t.offset[l];
            }
            let (c, _) = profile8(reduce_phases(&s), f32x8::new(t.steepness), &t.series, t.mode);
            sum += f64::from((f32x8::new(t.amplitude) * c).reduce_add());
        }
        sum
    }

    /// The particle kinematics of the trochoid sum at `(x, z)` by the f32 kernel (each wave's
    /// particle at its own phase `θᵢ`, as [`crate::TrochoidField`]'s): height `Σ Aᵢ cos θᵢ`,
    /// gradient `−Σ Aᵢ kᵢ sin θᵢ/(1 − Qᵢ cos θᵢ)`, `∂h/∂t = Σ Aᵢωᵢ sin θᵢ/(1 − Qᵢ cos θᵢ)`,
    /// horizontal velocity `Σ (Qᵢωᵢ/kᵢ) d̂ᵢ cos θᵢ`, displacement `−Σ (Qᵢ/kᵢ) d̂ᵢ sin θᵢ`,
    /// deformation `I − Σ Qᵢ d̂ᵢd̂ᵢᵀ cos θᵢ` and vertical acceleration `−Σ Aᵢωᵢ² cos θᵢ`, within
    /// the kernel's f32 error of the f64 sums.
    pub(crate) fn kinematics(&self, x: f64, z: f64) -> Kinematics {
        kinematics_of(&self.tiers, x, z)
    }

    /// `−Σ (Qᵢ/kᵢ) d̂ᵢ sin(kᵢ·u + offᵢ)`: each wave's particle displacement at rest phase
    /// `kᵢ·u + offᵢ` (f32 lanes, the phase reduced in f64).
    pub(crate) fn rest_displacement(&self, u: DVec2) -> DVec2 {
        rest_displacement_of(&self.tiers, u)
    }

    /// Height of wave `i` alone by the scalar twin of the kernel.
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    fn wave_height_fast(&self, i: usize, x: f64, z: f64) -> f64 {
        let (tier, lane) = self.lane_of_wave[i];
        let t = &self.tiers[tier];
        let (c, _) =
            profile1(t.kx[lane] * x + t.kz[lane] * z + t.offset[lane], t.steepness[lane], &t.series, lane, t.mode);
        f64::from(t.amplitude[lane]) * f64::from(c)
    }

    /// The fade weight of wave `i` (original order) at distance `t` along a ray of direction `d̂`
    /// traced with a pixel footprint of `footprint_angle` rad (1 when the angle is 0).
    pub fn fade_weight(&self, i: usize, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        if footprint_angle > 0.0 {
            footprint_weight(self.fade_distance(i + 1, direction, footprint_angle), t)
        } else {
            1.0
        }
    }

    /// The gradient `(∂h/∂x, ∂h/∂z)` of the surface the tracer drew at a hit `t` along a ray of
    /// direction `d̂`: `Σ wᵢ(t) ∂hᵢ/∂s · kᵢ d̂ᵢ` with `∂hᵢ/∂s = −Aᵢ sin θ/(1 − Qᵢ cos θ)`, every wave
    /// weighted by its fade weight, by the f32 SIMD kernel (relative error about 10⁻⁶).
    ///
    /// # Arguments
    /// - `x`, `z`: the hit's horizontal position (m).
    /// - `direction`: unit ray direction; `footprint_angle` (rad, 0: no fading) and `t` (m) as
    ///   traced.
    ///
    /// # Returns
    /// The gradient (dimensionless); the upward normal is `(−gx, 1, −gz)/‖·‖`.
    pub fn faded_gradient(&self, x: f64, z: f64, direction: DVec3, footprint_angle: f64, t: f64) -> DVec2 {
        self.faded_gradient_and_covariance(x, z, direction, footprint_angle, t).0
    }

    /// [`Self::faded_gradient`] and [`Self::faded_slope_covariance`] in one pass over the waves
    /// (each wave's fade weight computed once): what a renderer needs at a hit.
    ///
    /// # Arguments
    /// As [`Self::faded_gradient`].
    ///
    /// # Returns
    /// `(gradient, covariance)`: the gradient (dimensionless) of the drawn surface and the slope
    /// covariance `(xx, xz, zz)` (dimensionless) of the waves faded at `t`.
    ///
    /// # References
    /// docs/equations.md §1 (trochoid slope) and §11 (`σ²_BRDF = σ²_total − σ²_resolved`).
    pub fn faded_gradient_and_covariance(
        &self,
        x: f64,
        z: f64,
        direction: DVec3,
        footprint_angle: f64,
        t: f64,
    ) -> (DVec2, DVec3) {
        let fade = Fade::new(direction, footprint_angle, t);
        let (mut gx, mut gz) = (0.0, 0.0);
        let mut lost = [f64x4::splat(0.0); 3];
        for tier in &self.tiers {
            let mut s = [0.0; LANES];
            let (mut kx, mut kz) = ([0.0f32; LANES], [0.0f32; LANES]);
            for l in 0..LANES {
                s[l] = tier.kx[l] * x + tier.kz[l] * z + tier.offset[l];
                kx[l] = tier.kx[l] as f32;
                kz[l] = tier.kz[l] as f32;
            }
            let weight = fade.weights(tier, Some(&mut lost));
            let (_, g) = profile8(reduce_phases(&s), f32x8::new(tier.steepness), &tier.series, tier.mode);
            let dh = -(f32x8::new(tier.amplitude) * g * f32x8::new(weight));
            gx += f64::from((dh * f32x8::new(kx)).reduce_add());
            gz += f64::from((dh * f32x8::new(kz)).reduce_add());
        }
        let lost = lost.map(|v| v.reduce_add());
        (DVec2::new(gx, gz), DVec3::from_array(lost))
    }

    /// Height of the surface as a primary ray draws it at `(x, z)`: each wave weighted by its
    /// fade `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` along the ray (the weights of
    /// [`Self::faded_gradient`]), `h = Σ wᵢ Aᵢ cos θᵢ` in the kernel's f32 lanes; every wave
    /// (the traced height) when `footprint_angle` is 0.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m).
    /// - `direction`: unit direction of the ray from the eye to the point; `footprint_angle`
    ///   (rad, `≥ 0`) and `t` (m, the distance along the ray) as traced.
    ///
    /// # Returns
    /// The height (m).
    ///
    /// # References
    /// Darles et al. 2007, Eq. 2 (trochoid sum); docs/equations.md §11 (fade weights).
    pub fn faded_height(&self, x: f64, z: f64, direction: DVec3, footprint_angle: f64, t: f64) -> f64 {
        let fade = Fade::new(direction, footprint_angle, t);
        let mut h = 0.0;
        for tier in &self.tiers {
            let mut s = [0.0; LANES];
            for l in 0..LANES {
                s[l] = tier.kx[l] * x + tier.kz[l] * z + tier.offset[l];
            }
            let weight = fade.weights(tier, None);
            let (c, _) = profile8(reduce_phases(&s), f32x8::new(tier.steepness), &tier.series, tier.mode);
            h += f64::from((f32x8::new(tier.amplitude) * c * f32x8::new(weight)).reduce_add());
        }
        h
    }

    /// The slope covariance `(⟨ζx²⟩, ⟨ζx ζz⟩, ⟨ζz²⟩)` of the waves the tracer faded at `t`:
    /// `Σ (1 − wᵢ) ⟨sᵢ²⟩ (k̂x², k̂x k̂z, k̂z²)` in world axes, to be added to the BRDF's unresolved
    /// slope variance (Bruneton et al. 2010 seamless transition).
    ///
    /// # Arguments
    /// - `direction`, `footprint_angle`, `t`: as traced.
    ///
    /// # Returns
    /// The covariance (dimensionless) as `DVec3(xx, xz, zz)`.
    ///
    /// # References
    /// docs/equations.md §11 (`σ²_BRDF = σ²_total − σ²_resolved`, weights `smoothstep(1, 1.5, λ/ℓ)`).
    pub fn faded_slope_covariance(&self, direction: DVec3, footprint_angle: f64, t: f64) -> DVec3 {
        let mut out = DVec3::ZERO;
        if footprint_angle <= 0.0 {
            return out;
        }
        for (i, cov) in self.slope_covariance.iter().enumerate() {
            let lost = 1.0 - self.fade_weight(i, direction, footprint_angle, t);
            if lost > 0.0 {
                out += lost * *cov;
            }
        }
        out
    }
}

/// [`TracedTrochoids::kinematics`] over `tiers`: compiled for the widest vectors the processor
/// has and chosen at run time (the phases' `f64` lanes then run four at a time); the operations
/// and their order, so the roundings, are the same on every route.
#[multiversion::multiversion(targets("x86_64+avx"))]
fn kinematics_of(tiers: &[Tier], x: f64, z: f64) -> Kinematics {
    let mut k = Kinematics::default();
    // Every sum but the height's is kept in lanes over the tiers and reduced once (the height
    // is reduced per tier, as `Self::height`, so that the two agree bit for bit).
    let mut lanes = [f32x8::ZERO; 11];
    for t in tiers {
        let mut s = [0.0; LANES];
        for l in 0..LANES {
            s[l] = t.kx[l] * x + t.kz[l] * z + t.offset[l];
        }
        let q = f32x8::new(t.steepness);
        let (c, g) = profile8(reduce_phases(&s), q, &t.series, t.mode);
        let a = f32x8::new(t.amplitude);
        let w = f32x8::new(t.omega);
        let (ac, ag) = (a * c, a * g);
        let sn = g * (f32x8::ONE - q * c);
        let [kx, kz, inv_k2] = t.kinematic_k.map(f32x8::new);
        let qc = q * c * inv_k2;
        let v = qc * w;
        let d = q * sn * inv_k2;
        k.height += f64::from(ac.reduce_add());
        for (sum, term) in lanes.iter_mut().zip([
            ag * kx,
            ag * kz,
            ag * w,
            v * kx,
            v * kz,
            d * kx,
            d * kz,
            qc * kx * kx,
            qc * kx * kz,
            qc * kz * kz,
            ac * w * w,
        ]) {
            *sum += term;
        }
    }
    let [gx, gz, rate, vx, vz, dx, dz, mxx, mxz, mzz, acc] = lanes.map(|v| f64::from(v.reduce_add()));
    k.gradient = -DVec2::new(gx, gz);
    k.height_rate = rate;
    k.velocity = DVec2::new(vx, vz);
    k.displacement = -DVec2::new(dx, dz);
    k.deformation = DVec3::new(1.0 - mxx, -mxz, 1.0 - mzz);
    k.vertical_acceleration = -acc;
    k
}

/// [`TracedTrochoids::rest_displacement`] over `tiers`, multiversioned as [`kinematics_of`].
#[multiversion::multiversion(targets("x86_64+avx"))]
fn rest_displacement_of(tiers: &[Tier], u: DVec2) -> DVec2 {
    let mut d = DVec2::ZERO;
    for t in tiers {
        let mut s = [0f32; LANES];
        for l in 0..LANES {
            let p = t.kx[l] * u.x + t.kz[l] * u.y + t.offset[l];
            // Whole turns off by the 1.5·2⁵² rounding trick (`f64::round` is a library call on
            // the SSE2 baseline); ties go to even, which changes no phase's sine.
            const MAGIC: f64 = 6_755_399_441_055_744.0;
            s[l] = (p - TAU * ((p * (1.0 / TAU) + MAGIC) - MAGIC)) as f32;
        }
        let sn = f32x8::new(s).sin();
        let [fx, fz] = t.displacement_factor;
        d -= DVec2::new(f64::from((sn * f32x8::new(fx)).reduce_add()), f64::from((sn * f32x8::new(fz)).reduce_add()));
    }
    d
}

/// The fade of the waves along one ray: `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` with
/// `Tᵢ/t = (2π/(α t))/√(kᵢ² + σᵢ²/max(|d_y|, 0.05)²)` (`footprint_weight`, `component_fade_distance`), computed
/// by halves of 4 f64 lanes; padding lanes (k = 0) get `Tᵢ = ∞`, `w = 1` and no covariance.
struct Fade {
    fading: bool,
    inv_dy2: f64x4,
    reach: f64x4,
    dx: f64x4,
    dz: f64x4,
}

impl Fade {
    fn new(direction: DVec3, footprint_angle: f64, t: f64) -> Self {
        let fading = footprint_angle > 0.0 && t > 0.0;
        Self {
            fading,
            inv_dy2: f64x4::splat(brine_core::footprint::footprint_stretch_squared(direction.y)),
            reach: f64x4::splat(if fading { TAU / (footprint_angle * t) } else { 0.0 }),
            dx: f64x4::splat(direction.x),
            dz: f64x4::splat(direction.z),
        }
    }

    /// The weights of `tier`'s lanes; the slope covariance of what they remove is added to
    /// `lost` when given.
    #[inline]
    fn weights(&self, tier: &Tier, mut lost: Option<&mut [f64x4; 3]>) -> [f32; LANES] {
        let mut weight = [1.0f32; LANES];
        if !self.fading {
            return weight;
        }
        let (one, zero) = (f64x4::splat(1.0), f64x4::splat(0.0));
        for half in 0..2 {
            let lanes = half * 4..half * 4 + 4;
            let v = |a: &[f64; LANES]| f64x4::new(a[lanes.clone()].try_into().expect("4 lanes"));
            let (tkx, tkz, k) = (v(&tier.kx), v(&tier.kz), v(&tier.wavenumber));
            let sigma = tkx * self.dx + tkz * self.dz;
            let resolution = k * k + sigma * sigma * self.inv_dy2;
            // Tᵢ/t ≥ 1.5 on every lane, i.e. (2π/(αt))² ≥ 2.25 (kᵢ² + σᵢ²/max(|d_y|, 0.05)²): no wave of
            // these four has begun to fade (w = 1, nothing lost), without the square root
            // and division, which cost as much as the profile itself.
            if (self.reach * self.reach).simd_ge(f64x4::splat(2.25) * resolution).all() {
                continue;
            }
            let ratio = self.reach / resolution.sqrt();
            let u = ((ratio - one) * f64x4::splat(2.0)).max(zero).min(one);
            let w = u * u * (f64x4::splat(3.0) - f64x4::splat(2.0) * u);
            if let Some(lost) = lost.as_deref_mut() {
                let gone = one - w;
                for (o, c) in lost.iter_mut().zip(&tier.slope_covariance) {
                    *o += gone * v(c);
                }
            }
            for (dst, wl) in weight[lanes].iter_mut().zip(w.to_array()) {
                *dst = wl as f32;
            }
        }
        weight
    }
}

#[cfg(all(test, feature = "tracing"))]
mod tests;
