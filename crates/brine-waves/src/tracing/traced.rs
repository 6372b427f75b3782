//! A trochoid sum frozen at one instant and laid out for fast tracing: waves sorted by length
//! scale in lane groups of 8 f32 lanes (SIMD), about five tiers of groups along a ray, each with
//! its bounds.

// Lane loops index several parallel arrays of one tier at once.
#![allow(clippy::needless_range_loop)]

use std::cell::RefCell;
use std::f64::consts::TAU;

use brine_trace::{
    Aabb, FADE_CURVATURE, FADE_SLOPE, Hit, LipschitzSum, Ray, RayTiers, Step, TierBounds, TierSample, TierScratch,
    TraceOptions, TraceStats, certify_cone_with, footprint_weight, trace_tiers_with,
};
use glam::{DVec2, DVec3};
use wide::{f32x8, f64x4};

use crate::fit::trochoid::trough_curvature_factor;
use crate::tracing::fast_profile::{
    PROFILE_ERROR, ProfileMode, SERIES_ROWS, profile1, profile8, reduce_phases, series_polynomials,
};
use crate::{Trochoid, TrochoidSet};

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
    /// Real waves in this tier.
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
/// It implements [`LipschitzSum`] (every method can trace it; the components are evaluated by
/// the same f32 kernel) and overrides [`LipschitzSum::trace_tiered`] with the fast path.
///
/// # References
/// Darles et al. 2007 §3.2; docs/equations.md §1 (trochoid profile, per-wave bounds, antialiasing).
#[derive(Debug, Clone)]
pub struct TracedTrochoids {
    tiers: Vec<Tier>,
    /// Lane groups per tier of the tracer ([`tier_group`]).
    group: usize,
    /// `(tier, lane)` of wave `i` (original order).
    lane_of_wave: Vec<(usize, usize)>,
    /// Wave `i` (original order): `(Trochoid, offset φᵢ − ωᵢt)`.
    waves: Vec<(Trochoid, f64)>,
    /// Wave `i`'s slope covariance `⟨sᵢ²⟩ (k̂x², k̂x k̂z, k̂z²)`.
    slope_covariance: Vec<DVec3>,
    total_amplitude: f64,
    error: f64,
}

thread_local! {
    static SCRATCH: RefCell<(TierScratch, RayState)> = RefCell::new((TierScratch::default(), RayState::default()));
}

impl TracedTrochoids {
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
        let mut k = Kinematics::default();
        for t in &self.tiers {
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
            let mut kx = [0f32; LANES];
            let mut kz = [0f32; LANES];
            let mut inv_k2 = [0f32; LANES];
            for l in 0..LANES {
                kx[l] = t.kx[l] as f32;
                kz[l] = t.kz[l] as f32;
                inv_k2[l] =
                    if t.wavenumber[l] > 0.0 { (1.0 / (t.wavenumber[l] * t.wavenumber[l])) as f32 } else { 0.0 };
            }
            let (kx, kz, inv_k2) = (f32x8::new(kx), f32x8::new(kz), f32x8::new(inv_k2));
            let qc = q * c * inv_k2;
            let v = qc * w;
            let d = q * sn * inv_k2;
            let r = |v: f32x8| f64::from(v.reduce_add());
            k.height += r(ac);
            k.gradient -= DVec2::new(r(ag * kx), r(ag * kz));
            k.height_rate += r(ag * w);
            k.velocity += DVec2::new(r(v * kx), r(v * kz));
            k.displacement -= DVec2::new(r(d * kx), r(d * kz));
            k.deformation -= DVec3::new(r(qc * kx * kx), r(qc * kx * kz), r(qc * kz * kz));
            k.vertical_acceleration -= r(ac * w * w);
        }
        k.deformation += DVec3::new(1.0, 0.0, 1.0);
        k
    }

    /// `−Σ (Qᵢ/kᵢ) d̂ᵢ sin(kᵢ·u + offᵢ)`: each wave's particle displacement at rest phase
    /// `kᵢ·u + offᵢ` (f32 lanes, the phase reduced in f64).
    pub(crate) fn rest_displacement(&self, u: DVec2) -> DVec2 {
        let mut d = DVec2::ZERO;
        for t in &self.tiers {
            let mut s = [0f32; LANES];
            let mut fx = [0f32; LANES];
            let mut fz = [0f32; LANES];
            for l in 0..LANES {
                let p = t.kx[l] * u.x + t.kz[l] * u.y + t.offset[l];
                s[l] = (p - TAU * (p / TAU).round()) as f32;
                let k2 = t.wavenumber[l] * t.wavenumber[l];
                let f = if k2 > 0.0 { f64::from(t.steepness[l]) / k2 } else { 0.0 };
                fx[l] = (f * t.kx[l]) as f32;
                fz[l] = (f * t.kz[l]) as f32;
            }
            let sn = f32x8::new(s).sin();
            d -= DVec2::new(
                f64::from((sn * f32x8::new(fx)).reduce_add()),
                f64::from((sn * f32x8::new(fz)).reduce_add()),
            );
        }
        d
    }

    /// Height of wave `i` alone by the scalar twin of the kernel.
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
            footprint_weight(self.component_fade_distance(i + 1, direction, footprint_angle), t)
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
        // Fade weights by halves of 4 f64 lanes: wᵢ = smoothstep(1, 1.5, Tᵢ/t) with
        // Tᵢ/t = (2π/(α t))/√(kᵢ² + σᵢ²/d_y²) (`footprint_weight`, `component_fade_distance`);
        // padding lanes (k = 0) get Tᵢ = ∞, w = 1 and no covariance.
        let fading = footprint_angle > 0.0 && t > 0.0;
        let inv_dy2 = f64x4::splat(1.0 / (direction.y * direction.y).max(1e-300));
        let reach = f64x4::splat(if fading { TAU / (footprint_angle * t) } else { 0.0 });
        let (dx, dz) = (f64x4::splat(direction.x), f64x4::splat(direction.z));
        let (one, zero) = (f64x4::splat(1.0), f64x4::splat(0.0));
        let (mut gx, mut gz) = (0.0, 0.0);
        let mut lost = [f64x4::splat(0.0); 3];
        for tier in &self.tiers {
            let mut s = [0.0; LANES];
            let (mut weight, mut kx, mut kz) = ([1.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
            for l in 0..LANES {
                s[l] = tier.kx[l] * x + tier.kz[l] * z + tier.offset[l];
                kx[l] = tier.kx[l] as f32;
                kz[l] = tier.kz[l] as f32;
            }
            if fading {
                for half in 0..2 {
                    let lanes = half * 4..half * 4 + 4;
                    let v = |a: &[f64; LANES]| f64x4::new(a[lanes.clone()].try_into().expect("4 lanes"));
                    let (tkx, tkz, k) = (v(&tier.kx), v(&tier.kz), v(&tier.wavenumber));
                    let sigma = tkx * dx + tkz * dz;
                    let resolution = k * k + sigma * sigma * inv_dy2;
                    // Tᵢ/t ≥ 1.5 on every lane, i.e. (2π/(αt))² ≥ 2.25 (kᵢ² + σᵢ²/d_y²): no wave of
                    // these four has begun to fade (w = 1, nothing lost), without the square root
                    // and division, which cost as much as the profile itself.
                    if (reach * reach).simd_ge(f64x4::splat(2.25) * resolution).all() {
                        continue;
                    }
                    let ratio = reach / resolution.sqrt();
                    let u = ((ratio - one) * f64x4::splat(2.0)).max(zero).min(one);
                    let w = u * u * (f64x4::splat(3.0) - f64x4::splat(2.0) * u);
                    let gone = one - w;
                    for (o, c) in lost.iter_mut().zip(&tier.slope_covariance) {
                        *o += gone * v(c);
                    }
                    for (dst, wl) in weight[lanes].iter_mut().zip(w.to_array()) {
                        *dst = wl as f32;
                    }
                }
            }
            let (_, g) = profile8(reduce_phases(&s), f32x8::new(tier.steepness), &tier.series, tier.mode);
            let dh = -(f32x8::new(tier.amplitude) * g * f32x8::new(weight));
            gx += f64::from((dh * f32x8::new(kx)).reduce_add());
            gz += f64::from((dh * f32x8::new(kz)).reduce_add());
        }
        let lost = lost.map(|v| v.reduce_add());
        (DVec2::new(gx, gz), DVec3::from_array(lost))
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

/// Per-tier quantities along one ray.
#[derive(Debug, Default, Clone, Copy)]
struct TierOnRay {
    /// `Σ wᵢ(t₀) Aᵢ|σᵢ|/√(1 − Qᵢ²)` over the lanes in use.
    lipschitz: f64,
    /// `Σ Aᵢσᵢ²/(1 − Qᵢ)²` over the lanes in use.
    curvature: f64,
    /// `Σ Aᵢσᵢ² c(Qᵢ)` over the lanes in use (`nᵢ'' ≥ −Aᵢσᵢ² c(Qᵢ)`).
    concavity: f64,
    /// Bound of the derivative error.
    slope_error: f64,
    /// Smallest and largest fade distance of the tier's waves (m).
    fade_min: f64,
    fade_max: f64,
    /// Amplitude of the lanes in use, and of the lanes a cone cannot follow (held at `−A`).
    amplitude: f64,
    held: f64,
    /// `Σ Aᵢkᵢ/√(1 − Qᵢ²)` over the lanes in use: the 3D Lipschitz constant (cones).
    spread: f64,
    /// Some lane is held (cone mode).
    masked: bool,
}

/// Per-ray state of the fast tiers (reused between rays).
#[derive(Debug, Default, Clone)]
struct RayState {
    /// Phase at the ray origin, per lane (f64).
    s0: Vec<[f64; LANES]>,
    /// Phase rate along the ray `σ = k·d̂_xz` (rad m⁻¹), per lane.
    sigma: Vec<[f64; LANES]>,
    /// `Aᵢ σᵢ` in f32 times the lane's mask (m rad m⁻¹): the factor of the sampled derivative.
    amp_sigma: Vec<[f32; LANES]>,
    /// Fade distance per lane (m; `+∞` without fading).
    fade: Vec<[f32; LANES]>,
    /// 1 for a lane in use, 0 for a lane held at its minimum (cone mode).
    mask: Vec<[f32; LANES]>,
    /// `Aᵢ |σᵢ|/√(1 − Qᵢ²)`, `Aᵢ σᵢ²/(1 − Qᵢ)²` and `Aᵢ σᵢ² c(Qᵢ)` per lane (derivative,
    /// curvature and concavity bounds).
    lane_bounds: Vec<[(f64, f64, f64); LANES]>,
    tier: Vec<TierOnRay>,
}

/// [`RayTiers`] of a [`TracedTrochoids`] along one ray (or the cone around it): tier 0 is `y`,
/// tier `j ≥ 1` the `j`-th run of [`tier_group`] lane groups of 8 waves.
struct SeaTiers<'a> {
    sea: &'a TracedTrochoids,
    state: &'a mut RayState,
    origin: DVec3,
    direction: DVec3,
    t_exit: f64,
    slope_error: f64,
}

impl<'a> SeaTiers<'a> {
    /// The tiers along `ray` up to `t_exit`, faded for a pixel of `footprint_angle` rad; with
    /// `cone > 0`, tiers that bound every ray within `cone` rad of `ray`: a wave that would fade
    /// for some ray of the cone before `t_exit` is held at its minimum `−A` (the faded term
    /// `−wA cos θ ≥ −A` for any weight), the others are used whole.
    fn new(
        sea: &'a TracedTrochoids,
        state: &'a mut RayState,
        ray: &Ray,
        t_exit: f64,
        footprint_angle: f64,
        cone: f64,
    ) -> Self {
        let (o, d) = (ray.origin(), ray.direction());
        let n = sea.tiers.len();
        state.s0.resize(n, [0.0; LANES]);
        state.sigma.resize(n, [0.0; LANES]);
        state.fade.resize(n, [f32::INFINITY; LANES]);
        state.mask.resize(n, [1.0; LANES]);
        state.lane_bounds.resize(n, [(0.0, 0.0, 0.0); LANES]);
        state.tier.resize(n, TierOnRay::default());
        state.amp_sigma.resize(n, [0.0; LANES]);
        let slope_error = if cone == 0.0 {
            Self::fill_ray(sea, state, o, d, footprint_angle)
        } else {
            Self::fill_cone(sea, state, o, d, t_exit, footprint_angle, cone)
        };
        Self { sea, state, origin: o, direction: d, t_exit, slope_error }
    }

    /// The per-lane and per-group quantities of one ray (origin `o`, unit direction `d`), faded
    /// for a pixel of `footprint_angle` rad (0: no fading); returns the bound of the derivative
    /// error. Lanes in f64 for the phases and bounds, in f32 for the fade distances (stored in
    /// f32 and used as such by both the bounds and the samples).
    fn fill_ray(sea: &TracedTrochoids, state: &mut RayState, o: DVec3, d: DVec3, footprint_angle: f64) -> f64 {
        let fading = footprint_angle > 0.0;
        // Tᵢ = 2π/(α √(kᵢ² + σᵢ²/d_y²)): the footprint stretched by 1/|d_y| along the view.
        let reach = f32x8::splat(if fading { (TAU / footprint_angle) as f32 } else { 0.0 });
        let inv_dy2 = f32x8::splat(((1.0 / (d.y * d.y).max(1e-300)) as f32).min(f32::MAX));
        let mut slope_error = 0.0;
        for (j, t) in sea.tiers.iter().enumerate() {
            let (s0, sigma, lanes) = (&mut state.s0[j], &mut state.sigma[j], &mut state.lane_bounds[j]);
            let mut info = TierOnRay {
                fade_min: f64::INFINITY,
                fade_max: f64::INFINITY,
                amplitude: t.amplitude_sum,
                spread: t.spread,
                ..TierOnRay::default()
            };
            // Two halves of 4 f64 lanes: phases at the origin, phase rates, and the per-lane
            // derivative, curvature and derivative-error bounds with their sums.
            let mut sigma32 = [0.0f32; LANES];
            let (mut lip, mut curv, mut conc, mut err) = (f64x4::ZERO, f64x4::ZERO, f64x4::ZERO, f64x4::ZERO);
            for half in 0..2 {
                let at = half * 4..half * 4 + 4;
                let v = |a: &[f64; LANES]| f64x4::new(a[at.clone()].try_into().expect("4 lanes"));
                let (kx, kz) = (v(&t.kx), v(&t.kz));
                let phase = kx * f64x4::splat(o.x) + kz * f64x4::splat(o.z) + v(&t.offset);
                let sg = kx * f64x4::splat(d.x) + kz * f64x4::splat(d.z);
                let (l1, k1) = (v(&t.slope_factor) * sg.abs(), v(&t.curvature_factor) * sg * sg);
                let c1 = v(&t.concavity_factor) * sg * sg;
                lip += l1;
                curv += k1;
                conc += c1;
                err += v(&t.slope_error_factor) * sg.abs();
                let (l1, k1, c1, sg) = (l1.to_array(), k1.to_array(), c1.to_array(), sg.to_array());
                s0[at.clone()].copy_from_slice(&phase.to_array());
                sigma[at.clone()].copy_from_slice(&sg);
                for (i, l) in at.enumerate() {
                    sigma32[l] = sg[i] as f32;
                    lanes[l] = (l1[i], k1[i], c1[i]);
                }
            }
            (info.lipschitz, info.curvature, info.concavity, info.slope_error) =
                (lip.reduce_add(), curv.reduce_add(), conc.reduce_add(), err.reduce_add());
            state.amp_sigma[j] = (f32x8::new(t.amplitude) * f32x8::new(sigma32)).to_array();
            state.mask[j] = [1.0; LANES];
            if fading {
                let k = f32x8::new(t.wavenumber_f32);
                let sg = f32x8::new(sigma32);
                let mut fade = (reach / (k * k + sg * sg * inv_dy2).sqrt()).to_array();
                let real = t.count as usize;
                // Padding lanes (A = 0) count as faded out, so that no weight is NaN.
                fade[real..].fill(0.0);
                // Plain comparisons (the fades are never NaN): `f32::min`'s NaN rule costs a blend.
                let (lo, hi) = fade[..real].iter().fold((f32::INFINITY, 0.0f32), |(lo, hi), &f| {
                    (if f < lo { f } else { lo }, if f > hi { f } else { hi })
                });
                (info.fade_min, info.fade_max) = (f64::from(lo), f64::from(hi));
                if info.fade_max == 0.0 {
                    info.fade_max = f64::INFINITY; // an empty tier never fades
                }
                state.fade[j] = fade;
            } else {
                state.fade[j] = [f32::INFINITY; LANES];
            }
            slope_error += info.slope_error;
            state.tier[j] = info;
        }
        slope_error
    }

    /// [`Self::fill_ray`] for every ray within `cone` rad of the ray: waves that would fade for
    /// some ray of the cone before `t_exit` are held at `−A` (mask 0), the others are used whole.
    fn fill_cone(
        sea: &TracedTrochoids,
        state: &mut RayState,
        o: DVec3,
        d: DVec3,
        t_exit: f64,
        footprint_angle: f64,
        cone: f64,
    ) -> f64 {
        // In a cone, |σ/d_y| ≤ (|σ_axis| + kθ)/(|d_y| − θ).
        let dy_cone = (d.y.abs() - cone).max(1e-12);
        let mut slope_error = 0.0;
        for (j, t) in sea.tiers.iter().enumerate() {
            let mut info = TierOnRay { fade_min: f64::INFINITY, fade_max: f64::INFINITY, ..TierOnRay::default() };
            let (s0, sigma, lanes) = (&mut state.s0[j], &mut state.sigma[j], &mut state.lane_bounds[j]);
            let (fade, mask, amp_sigma) = (&mut state.fade[j], &mut state.mask[j], &mut state.amp_sigma[j]);
            for l in 0..LANES {
                s0[l] = t.kx[l] * o.x + t.kz[l] * o.z + t.offset[l];
                let sg = t.kx[l] * d.x + t.kz[l] * d.z;
                sigma[l] = sg;
                lanes[l] =
                    (t.slope_factor[l] * sg.abs(), t.curvature_factor[l] * sg * sg, t.concavity_factor[l] * sg * sg);
                fade[l] = f32::INFINITY;
                mask[l] = 1.0;
                amp_sigma[l] = t.amplitude[l] * sg as f32;
                let a = f64::from(t.amplitude[l]);
                if footprint_angle > 0.0 && l < t.count as usize {
                    // Tᵢ = 2π/(α √(kᵢ² + σᵢ²/d_y²)) at its smallest over the cone.
                    let k = t.wavenumber[l];
                    let ratio = (sg.abs() + k * cone) / dy_cone;
                    let big_t = TAU / (footprint_angle * (k * k + ratio * ratio).sqrt());
                    if big_t < 1.5 * t_exit {
                        mask[l] = 0.0;
                        amp_sigma[l] = 0.0;
                        info.held += a;
                        info.masked = true;
                        continue;
                    }
                }
                info.lipschitz += lanes[l].0;
                info.curvature += lanes[l].1;
                info.concavity += lanes[l].2;
                info.slope_error += t.slope_error_factor[l] * sg.abs();
                info.amplitude += a;
                info.spread += t.slope_factor[l] * t.wavenumber[l];
            }
            slope_error += info.slope_error;
            state.tier[j] = info;
        }
        slope_error
    }
}

impl SeaTiers<'_> {
    /// The sea's lane groups summed into tracer tier `tier ≥ 1`: `group` consecutive ones.
    fn group(&self, tier: usize) -> std::ops::Range<usize> {
        let g = self.sea.group;
        let first = (tier - 1) * g;
        first..(first + g).min(self.sea.tiers.len())
    }

    /// Bounds of the sea's lane group `j` (8 waves) for every `t' ∈ [t, t_exit]`.
    fn lane_bounds(&self, j: usize, t: f64) -> TierBounds {
        let info = self.state.tier[j];
        if t >= info.fade_max {
            return TierBounds::ZERO;
        }
        if info.fade_min >= 1.5 * self.t_exit {
            // Unfaded (held lanes, if any, sit at −A: the tier is Σ nᵢ − A_held).
            return TierBounds {
                min: -info.amplitude - info.held,
                max: info.amplitude - info.held,
                lipschitz: info.lipschitz,
                curvature: info.curvature,
                concavity: info.concavity,
            };
        }
        // Faded products wᵢ·nᵢ with wᵢ non-increasing in t (footprint.rs): |wᵢnᵢ| ≤ wᵢ(t)Aᵢ,
        // |(wᵢnᵢ)'| ≤ wᵢ(t)Lᵢ + |wᵢ'|Aᵢ, |(wᵢnᵢ)''| ≤ wᵢ(t)Kᵢ + 2|wᵢ'|Lᵢ + |wᵢ''|Aᵢ, with
        // |wᵢ'| ≤ 4.5/t and |wᵢ''| ≤ 63/t² while fading (t ∈ [Tᵢ/1.5, Tᵢ]), 0 after. One-sided:
        // (wᵢnᵢ)'' ≥ −wᵢCᵢ − 2|wᵢ'|Lᵢ − |wᵢ''|Aᵢ with nᵢ'' ≥ −Cᵢ (wᵢ ≥ 0).
        let tier = &self.sea.tiers[j];
        let (mut amp, mut lip, mut curv, mut conc) = (0.0, 0.0, 0.0, 0.0);
        for l in 0..tier.count as usize {
            let big_t = f64::from(self.state.fade[j][l]);
            if big_t <= t {
                continue;
            }
            let (a_i, (l_i, k_i, c_i)) = (f64::from(tier.amplitude[l]), self.state.lane_bounds[j][l]);
            let w = footprint_weight(big_t, t);
            amp += w * a_i;
            lip += w * l_i;
            curv += w * k_i;
            conc += w * c_i;
            if big_t < 1.5 * self.t_exit {
                let tt = t.max(big_t / 1.5);
                lip += FADE_SLOPE * a_i / tt;
                let fade = 2.0 * FADE_SLOPE * l_i / tt + FADE_CURVATURE * a_i / (tt * tt);
                curv += fade;
                conc += fade;
            }
        }
        TierBounds { min: -amp, max: amp, lipschitz: lip, curvature: curv, concavity: conc }
    }

    /// The sea's lane group `j` (8 waves) at `t`.
    fn lane_sample(&self, j: usize, t: f64) -> TierSample {
        let info = self.state.tier[j];
        if t >= info.fade_max {
            return TierSample { value: 0.0, slope: 0.0, terms: 0 };
        }
        let w = &self.sea.tiers[j];
        let (s0, sigma) = (&self.state.s0[j], &self.state.sigma[j]);
        let mut s = [0.0; LANES];
        for l in 0..LANES {
            s[l] = s0[l] + sigma[l] * t;
        }
        let (c, g) = profile8(reduce_phases(&s), f32x8::new(w.steepness), &w.series, w.mode);
        let mut amp = f32x8::new(w.amplitude);
        if info.masked {
            amp *= f32x8::new(self.state.mask[j]);
        }
        // n = −w·A cos θ;  dn/dt = −w'·A cos θ + w·A sin θ σ/(1 − Q cos θ).
        let h = amp * c;
        let dh = g * f32x8::new(self.state.amp_sigma[j]);
        let (value, slope, terms) = if t * 1.5 <= info.fade_min {
            (-h.reduce_add(), dh.reduce_add(), w.count)
        } else {
            let tf = f32x8::splat(t as f32);
            let x = f32x8::new(self.state.fade[j]) / tf;
            let u = ((x - f32x8::splat(1.0)) * f32x8::splat(2.0)).max(f32x8::splat(0.0)).min(f32x8::splat(1.0));
            let weight = u * u * (f32x8::splat(3.0) - f32x8::splat(2.0) * u);
            let dweight = f32x8::splat(-12.0) * u * (f32x8::splat(1.0) - u) * x / tf;
            let live = self.state.fade[j].iter().take(w.count as usize).filter(|&&f| f64::from(f) > t).count();
            (-(weight * h).reduce_add(), (weight * dh - dweight * h).reduce_add(), live as u32)
        };
        TierSample { value: f64::from(value) - info.held, slope: f64::from(slope), terms }
    }
}

impl RayTiers for SeaTiers<'_> {
    fn tier_count(&self) -> usize {
        self.sea.tiers.len().div_ceil(self.sea.group) + 1
    }

    fn bounds(&mut self, tier: usize, t: f64) -> TierBounds {
        if tier == 0 {
            let (y0, y1) = (self.origin.y + self.direction.y * t, self.origin.y + self.direction.y * self.t_exit);
            return TierBounds::symmetric(y0.min(y1), y0.max(y1), self.direction.y.abs(), 0.0);
        }
        // The bounds of a sum: the sums of the bounds.
        let mut b = TierBounds::ZERO;
        for j in self.group(tier) {
            let g = self.lane_bounds(j, t);
            b.min += g.min;
            b.max += g.max;
            b.lipschitz += g.lipschitz;
            b.curvature += g.curvature;
            b.concavity += g.concavity;
        }
        b
    }

    fn spread_lipschitz(&self, tier: usize) -> f64 {
        if tier == 0 { 1.0 } else { self.group(tier).map(|j| self.state.tier[j].spread).sum() }
    }

    fn sample(&mut self, tier: usize, t: f64) -> TierSample {
        if tier == 0 {
            return TierSample { value: self.origin.y + self.direction.y * t, slope: self.direction.y, terms: 0 };
        }
        let mut out = TierSample { value: 0.0, slope: 0.0, terms: 0 };
        for j in self.group(tier) {
            let g = self.lane_sample(j, t);
            out.value += g.value;
            out.slope += g.slope;
            out.terms += g.terms;
        }
        out
    }

    fn error_bound(&self) -> f64 {
        self.sea.error
    }

    fn slope_error_bound(&self) -> f64 {
        self.slope_error
    }
}

/// How far a downward cone of primary rays with footprint fading certifies, as a multiple of where
/// it starts (or enters the slab `|y| ≤ ΣA`, or 1 m): waves that fade for some ray of the cone
/// before `1.5×` that end are held at `−A`, so the shorter the cone's reach the fewer are held.
/// Measured on the bench frame (640×480, N = 100, every phenomenon, 16 × 16 tiles):
/// evaluations per frame 1.446 M without a limit, 1.581 M at 1.1, 1.307 M at 1.25, 1.141 M at
/// 1.4, **1.136 M at 1.5**, 1.137 M at 1.75, 1.139 M at 2, 1.157 M at 4, 1.193 M at 8.
pub(crate) const CONE_REACH: f64 = 1.5;

impl LipschitzSum for TracedTrochoids {
    fn component_count(&self) -> usize {
        self.waves.len() + 1
    }

    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.wave_height_fast(i - 1, p.x, p.z) }
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.waves[i - 1].0.max_slope() }
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.waves[i - 1].0.amplitude() }
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { self.waves[i - 1].0.amplitude() }
    }

    /// `Lᵢ |k̂ᵢ·d̂_xz|` for a wave, `|d_y|` for `y`.
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return d.y.abs();
        }
        let w = &self.waves[i - 1].0;
        let k = w.direction_vector();
        w.max_slope() * (k.x * d.x + k.y * d.z).abs()
    }

    /// `d(−A cos θ)/dt = A sin θ/(1 − Q cos θ) · σ`, `σ = k d̂ᵢ·d̂_xz` (f32 kernel).
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        if i == 0 {
            return Some(d.y);
        }
        let (tier, lane) = self.lane_of_wave[i - 1];
        let t = &self.tiers[tier];
        let (_, g) =
            profile1(t.kx[lane] * p.x + t.kz[lane] * p.z + t.offset[lane], t.steepness[lane], &t.series, lane, t.mode);
        let sigma = t.kx[lane] * d.x + t.kz[lane] * d.z;
        Some(f64::from(t.amplitude[lane]) * f64::from(g) * sigma)
    }

    /// `A σ²/(1 − Q)²`: `|τ''_Q| = |Q − cos θ|/(1 − Q cos θ)³ ≤ 1/(1 − Q)²` (at the crest).
    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return 0.0;
        }
        let w = &self.waves[i - 1].0;
        let sigma = w.wavenumber() * (w.direction_vector().x * d.x + w.direction_vector().y * d.z);
        w.amplitude() * sigma * sigma / ((1.0 - w.steepness()).powi(2))
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { self.waves[i - 1].0.wavelength() }
    }

    /// `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/d_y²))`: the pixel footprint on the sea is `αt` across the view and
    /// `αt/|d_y|` along it; its extent along `k̂ᵢ` is `αt √(1 + (k̂ᵢ·d̂_xz)²/d_y²)`.
    fn component_fade_distance(&self, i: usize, d: DVec3, footprint_angle: f64) -> f64 {
        if i == 0 {
            return f64::INFINITY;
        }
        let w = &self.waves[i - 1].0;
        let k = w.wavenumber();
        let sigma = k * (w.direction_vector().x * d.x + w.direction_vector().y * d.z);
        TAU / (footprint_angle * (k * k + sigma * sigma / (d.y * d.y).max(1e-300)).sqrt())
    }

    fn value(&self, p: DVec3) -> f64 {
        p.y - self.height(p.x, p.z)
    }

    fn zero_set_bounds(&self) -> Aabb {
        Aabb::slab_y(-self.total_amplitude, self.total_amplitude)
    }

    fn trace_tiered(
        &self,
        ray: &Ray,
        t_enter: f64,
        t_exit: f64,
        options: &TraceOptions,
        stats: &mut TraceStats,
        log: Option<&mut Vec<Step>>,
    ) -> Option<Hit> {
        SCRATCH.with(|cell| {
            let mut guard = cell.borrow_mut();
            let (scratch, state) = &mut *guard;
            let mut tiers = SeaTiers::new(self, state, ray, t_exit, options.footprint_angle, 0.0);
            trace_tiers_with(scratch, &mut tiers, ray, t_enter, t_exit, options, stats, log)
        })
    }

    fn certify_cone(
        &self,
        ray: &Ray,
        half_angle: f64,
        t_enter: f64,
        t_exit: f64,
        options: &TraceOptions,
        stats: &mut TraceStats,
    ) -> f64 {
        // With fading, a wave that fades for some ray of the cone before the cone's end is held at
        // −A: a downward cone certifies only up to CONE_REACH times where it starts or meets the
        // slab, so that the waves fading beyond are used whole; its children go on from there.
        let (o, d) = (ray.origin(), ray.direction());
        let t_exit = if options.footprint_angle > 0.0 && d.y < 0.0 {
            let slab = if o.y > self.total_amplitude { (o.y - self.total_amplitude) / -d.y } else { 0.0 };
            t_exit.min(CONE_REACH * t_enter.max(slab).max(1.0))
        } else {
            t_exit
        };
        SCRATCH.with(|cell| {
            let mut guard = cell.borrow_mut();
            let (scratch, state) = &mut *guard;
            let mut tiers = SeaTiers::new(self, state, ray, t_exit, options.footprint_angle, half_angle);
            certify_cone_with(scratch, &mut tiers, ray, half_angle, t_enter, t_exit, options, stats)
        })
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::{FitOptions, PiersonMoskowitz, Spectrum, TrochoidSum, fit_trochoids, solve_trochoid_phase};

    /// A set with mixed steepness (series and Newton modes) from the fit, `Q` overridden per wave.
    fn set(n: usize, q_max: f64, seed: u64) -> TrochoidSet {
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let spreading = crate::CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
        let fit = fit_trochoids(&pm, &spreading, n, seed, &FitOptions::default()).unwrap();
        let waves = fit
            .waves()
            .iter()
            .enumerate()
            .map(|(i, w)| {
                let q = q_max * ((i * 37 + seed as usize) % 11) as f64 / 10.0;
                Trochoid::new(w.amplitude(), w.wavenumber(), w.direction(), w.omega(), w.phase(), q).unwrap()
            })
            .collect();
        TrochoidSet::new(waves)
    }

    #[test]
    fn the_kinematics_height_is_the_traced_height_bit_for_bit() {
        // `SeaFrame::sample` reads the height from the kinematics: it must be the traced sum.
        for (n, q) in [(50, 0.6), (150, 0.9)] {
            let sea = TracedTrochoids::new(&set(n, q, 3), 2.7);
            for i in 0..2000 {
                let f = f64::from(i);
                let (x, z) = (400.0 * (f * 0.618_034).fract() - 200.0, 400.0 * (f * 0.754_878).fract() - 200.0);
                assert_eq!(sea.kinematics(x, z).height.to_bits(), sea.height(x, z).to_bits(), "({x}, {z})");
            }
        }
    }

    /// The exact f64 value of tier `tier` along the ray at `t` (faded like the lanes).
    fn exact_tier(sea: &TracedTrochoids, state: &RayState, ray: &Ray, tier: usize, t: f64) -> f64 {
        if tier == 0 {
            return ray.at(t).y;
        }
        // Tracer tier `tier` holds the lane groups `(tier − 1)·group ..` (`SeaTiers::group`).
        let groups = (tier - 1) * sea.group..tier * sea.group;
        let p = ray.at(t);
        let mut sum = 0.0;
        let mut held = 0.0;
        for j in groups.clone().filter(|&j| j < sea.tiers.len()) {
            held += state.tier[j].held;
        }
        for (i, (w, offset)) in sea.waves.iter().enumerate() {
            let (j, l) = sea.lane_of_wave[i];
            if !groups.contains(&j) {
                continue;
            }
            let k = w.wavenumber() * w.direction_vector();
            let (_, c, _) = solve_trochoid_phase(k.x * p.x + k.y * p.z + offset, w.steepness());
            let weight = footprint_weight(f64::from(state.fade[j][l]), t);
            sum -= weight * state.mask[j][l] as f64 * w.amplitude() * c;
        }
        sum - held
    }

    /// Rounding of a second difference of f64 tier values (|T| ≲ 10 m) at a spacing of 1 cm:
    /// about 4·10 m·2⁻⁵² / (10⁻² m)² ≈ 10⁻¹⁰ m⁻¹, with margin.
    const SECOND_DIFFERENCE_ROUNDING: f64 = 1e-8;

    /// Relative slack of `|ΔT| ≤ L Δt` between two samples: the f64 rounding of `L Δt` and of the
    /// sums that form `L`, a few ulps; 10⁻¹² is a wide margin.
    const LIPSCHITZ_ROUNDING_REL: f64 = 1e-12;

    /// Relative slack of the curvature and concavity checks (`|ΔT′|/dt ≤ K`, second difference
    /// `≥ −C`), which hold exactly by the mean value theorem once the f32 errors are added: the
    /// bounds' fade terms use the f32-rounded amplitudes (6×10⁻⁸ relative) and f64 sums. 10⁻⁶ is
    /// a margin over these, not a measured error.
    const BOUND_ROUNDING_REL: f64 = 1e-6;

    /// Absolute slack of `|ΔT′|/dt` (m⁻¹) for the f64 rounding of the slope difference over
    /// `dt` = 10⁻³ m: about ulp(`L`)/`dt` ≈ 2×10⁻¹³ `L`; 10⁻⁹ covers it for any `L` below 10³.
    const SLOPE_DIFFERENCE_ROUNDING: f64 = 1e-9;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

        /// Along random rays, every tier's samples stay within its bounds, its derivative within
        /// its Lipschitz bound, the change of the derivative within the curvature bound (and above
        /// the one-sided concavity bound), and the f32 sample within the error bound of the exact
        /// f64 tier.
        #[test]
        fn tier_samples_respect_their_bounds(
            n in 1usize..120,
            q_max in prop_oneof![Just(0.05), Just(0.6), Just(0.99)],
            seed in 0u64..1000,
            dy in -0.9f64..-0.01,
            azimuth in 0.0f64..std::f64::consts::TAU,
            fade in prop_oneof![Just(0.0), Just(0.002), Just(0.02)],
        ) {
            let set = set(n, q_max, seed);
            let sea = TracedTrochoids::new(&set, 1.3);
            let h = (1.0 - dy * dy).sqrt();
            let ray = Ray::new(DVec3::new(3.0, 2.0, -7.0), DVec3::new(h * azimuth.cos(), dy, h * azimuth.sin())).unwrap();
            let t_exit = 80.0;
            let mut state = RayState::default();
            let mut tiers = SeaTiers::new(&sea, &mut state, &ray, t_exit, fade, 0.0);
            let eps = tiers.error_bound();
            let eta = tiers.slope_error_bound();
            for j in 0..tiers.tier_count() {
                for &t0 in &[0.5, 5.0, 30.0] {
                    let b = tiers.bounds(j, t0);
                    let dt = 1e-3;
                    let mut previous: Option<(f64, f64)> = None;
                    for i in 0..200 {
                        let t = t0 + (t_exit - t0) * i as f64 / 200.0;
                        let s = tiers.sample(j, t);
                        prop_assert!(s.value >= b.min - eps && s.value <= b.max + eps, "tier {j} t {t}: {} ∉ [{}, {}]", s.value, b.min, b.max);
                        prop_assert!(s.slope.abs() <= b.lipschitz + eta, "tier {j} t {t}: slope {} > {}", s.slope, b.lipschitz);
                        // The value itself between samples, not only the reported slope: each f32
                        // sample is within ε of the exact tier, which is L-Lipschitz on [t0, t_exit].
                        if let Some((tp, vp)) = previous {
                            prop_assert!((s.value - vp).abs() <= b.lipschitz * (t - tp) * (1.0 + LIPSCHITZ_ROUNDING_REL) + 2.0 * eps, "tier {j} t {t}: |Δvalue| {} > L Δt {}", (s.value - vp).abs(), b.lipschitz * (t - tp));
                        }
                        let s2 = tiers.sample(j, t + dt);
                        // Finite difference of the slope, with the f32 slope error over dt.
                        let second = (s2.slope - s.slope) / dt;
                        prop_assert!(second.abs() <= b.curvature * (1.0 + BOUND_ROUNDING_REL) + 2.0 * eta / dt + SLOPE_DIFFERENCE_ROUNDING, "tier {j} t {t}: curvature {second} > {}", b.curvature);
                        let exact = exact_tier(&sea, tiers.state, &ray, j, t);
                        prop_assert!((s.value - exact).abs() <= eps, "tier {j} t {t}: f32 {} vs f64 {exact} (ε = {eps:e})", s.value);
                        // One-sided: the second difference of the exact tier (a weighted mean of
                        // T'' over [t, t + 2h]) never falls below −concavity.
                        let h2 = 1e-2;
                        let (e1, e2) = (exact_tier(&sea, tiers.state, &ray, j, t + h2), exact_tier(&sea, tiers.state, &ray, j, t + 2.0 * h2));
                        let second_exact = (e2 - 2.0 * e1 + exact) / (h2 * h2);
                        prop_assert!(b.concavity <= b.curvature, "tier {j}: concavity {} > curvature {}", b.concavity, b.curvature);
                        prop_assert!(second_exact >= -b.concavity * (1.0 + BOUND_ROUNDING_REL) - SECOND_DIFFERENCE_ROUNDING, "tier {j} t {t}: T'' {second_exact} < −{}", b.concavity);
                        previous = Some((t, s.value));
                    }
                }
            }
        }
    }

    /// The f32 gradient against the f64 one, relative to the slope sum `Σ Lᵢ` (at most the
    /// largest possible slope): per wave the f32 slope error `PROFILE_ERROR·(1 + 1/(1 − Q)²)` in
    /// units of `kA` is at most 2.9×10⁻⁶ of its `Lᵢ = kA/√(1 − Q²)` for `Q ≤ 0.6` (this set);
    /// 10⁻⁵ leaves room for the f32 amplitudes and sums.
    const F32_GRADIENT_REL: f64 = 1e-5;

    /// At 1 m a footprint of 2 mrad is far below every wave, so no wave should have faded and the
    /// lost covariance should be exactly 0; 10⁻¹² accepts rounding residue only.
    const NOTHING_FADED: f64 = 1e-12;

    /// At 1000 km every wave has faded: the lost covariance's trace is `Σ mssᵢ (d_x² + d_z²)` with
    /// unit `d` in f64, against `Σ mssᵢ`: rounding of 80 terms, ~10⁻¹⁴ relative; 10⁻⁹ is loose.
    const ALL_FADED_REL: f64 = 1e-9;

    #[test]
    fn faded_gradient_matches_the_f64_gradient_and_fades() {
        let set = set(80, 0.6, 5);
        let sea = TracedTrochoids::new(&set, 0.4);
        let sum = TrochoidSum::new(&set);
        let exact = sum.at_time(0.4);
        let d = DVec3::new(0.9, -0.1, 0.3).normalize();
        for i in 0..200 {
            let (x, z) = (i as f64 * 2.37 - 200.0, i as f64 * -0.71 + 40.0);
            let (fast, reference) = (sea.faded_gradient(x, z, d, 0.0, 10.0), exact.gradient(x, z));
            let scale: f64 = set.waves().iter().map(Trochoid::max_slope).sum();
            assert!((fast - reference).length() <= F32_GRADIENT_REL * scale, "{fast} vs {reference}");
        }
        // Far away every short wave has faded: the gradient loses them and the covariance gains them.
        let near = sea.faded_slope_covariance(d, 0.002, 1.0);
        let far = sea.faded_slope_covariance(d, 0.002, 1e6);
        assert!(near.x.abs() < NOTHING_FADED && far.x > 0.0 && far.z > 0.0);
        let total: f64 = set.waves().iter().map(Trochoid::mean_square_slope).sum();
        assert!(((far.x + far.z) - total).abs() < ALL_FADED_REL * total, "all waves faded at 1000 km");
    }

    /// The one-pass covariance against the wave-by-wave one: the same terms summed in another
    /// order, rounding of a sum of ≤ 80 positive terms.
    const ORDER_ROUNDING: f64 = 1e-13;

    /// The one-pass covariance equals the wave-by-wave one of `faded_slope_covariance` (set
    /// order, weights from `fade_weight`) at distances where the waves fade one after the other;
    /// the gradient of the one pass is tested against the f64 surface above.
    #[test]
    fn fused_covariance_equals_the_wave_by_wave_one() {
        let set = set(80, 0.6, 9);
        let sea = TracedTrochoids::new(&set, 0.7);
        let d = DVec3::new(0.6, -0.08, -0.8).normalize();
        let mut faded_some = 0;
        for (i, t) in [0.5, 3.0, 20.0, 150.0, 900.0, 5e3].into_iter().enumerate() {
            let (x, z) = (i as f64 * 13.1 - 7.0, 2.0 - i as f64 * 5.3);
            let (_, c) = sea.faded_gradient_and_covariance(x, z, d, 0.0015, t);
            let reference = sea.faded_slope_covariance(d, 0.0015, t);
            let scale = reference.abs().max_element();
            assert!((c - reference).abs().max_element() <= ORDER_ROUNDING * scale, "t = {t}: {c} vs {reference}");
            faded_some += usize::from(scale > 0.0);
        }
        assert!(faded_some >= 3, "the distances must fade some waves");
    }

    #[test]
    fn fast_height_matches_the_f64_surface_within_its_error_bound() {
        for (q_max, seed) in [(0.05, 1), (0.5, 2), (0.99, 3)] {
            let set = set(150, q_max, seed);
            let sea = TracedTrochoids::new(&set, 0.4);
            let sum = TrochoidSum::new(&set);
            let exact = sum.at_time(0.4);
            for i in 0..500 {
                let (x, z) = (i as f64 * 1.37 - 300.0, i as f64 * -0.61 + 40.0);
                let (fast, reference) = (sea.height(x, z), exact.height(x, z));
                assert!((fast - reference).abs() <= sea.error_bound(), "{fast} vs {reference}");
                let component = (1..=set.len()).map(|c| -sea.component(c, DVec3::new(x, 0.0, z))).sum::<f64>();
                assert!((component - reference).abs() <= sea.error_bound(), "{component} vs {reference}");
            }
        }
    }
}
