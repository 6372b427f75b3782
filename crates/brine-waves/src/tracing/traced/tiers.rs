//! The trochoid sea as the tiered tracer sees it: its waves in tiers of falling wavelength, each tier's bounds along a ray, and the state a ray carries from step to step.

use super::*;
use brine_core::footprint::{FADE_CURVATURE, FADE_SLOPE};
use brine_trace::Ray;

/// Per-tier quantities along one ray.
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct TierOnRay {
    /// `Σ wᵢ(t₀) Aᵢ|σᵢ|/√(1 − Qᵢ²)` over the lanes in use.
    pub(super) lipschitz: f64,
    /// `Σ Aᵢσᵢ²/(1 − Qᵢ)²` over the lanes in use.
    pub(super) curvature: f64,
    /// `Σ Aᵢσᵢ² c(Qᵢ)` over the lanes in use (`nᵢ'' ≥ −Aᵢσᵢ² c(Qᵢ)`).
    pub(super) concavity: f64,
    /// Bound of the derivative error.
    pub(super) slope_error: f64,
    /// Smallest and largest fade distance of the tier's waves (m).
    pub(super) fade_min: f64,
    pub(super) fade_max: f64,
    /// Amplitude of the lanes in use, and of the lanes a cone cannot follow (held at `−A`).
    pub(super) amplitude: f64,
    pub(super) held: f64,
    /// `Σ Aᵢkᵢ/√(1 − Qᵢ²)` over the lanes in use: the 3D Lipschitz constant (cones).
    pub(super) spread: f64,
    /// Some lane is held (cone mode).
    pub(super) masked: bool,
}

/// Per-ray state of the fast tiers (reused between rays).
#[derive(Debug, Default, Clone)]
pub(crate) struct RayState {
    /// Phase at the ray origin, per lane (f64).
    pub(super) s0: Vec<[f64; LANES]>,
    /// Phase rate along the ray `σ = k·d̂_xz` (rad m⁻¹), per lane.
    pub(super) sigma: Vec<[f64; LANES]>,
    /// `Aᵢ σᵢ` in f32 times the lane's mask (m rad m⁻¹): the factor of the sampled derivative.
    pub(super) amp_sigma: Vec<[f32; LANES]>,
    /// Fade distance per lane (m; `+∞` without fading).
    pub(super) fade: Vec<[f32; LANES]>,
    /// 1 for a lane in use, 0 for a lane held at its minimum (cone mode).
    pub(super) mask: Vec<[f32; LANES]>,
    /// `Aᵢ |σᵢ|/√(1 − Qᵢ²)`, `Aᵢ σᵢ²/(1 − Qᵢ)²` and `Aᵢ σᵢ² c(Qᵢ)` per lane (derivative,
    /// curvature and concavity bounds).
    pub(super) lane_bounds: Vec<[(f64, f64, f64); LANES]>,
    pub(super) tier: Vec<TierOnRay>,
}

/// [`RayTiers`] of a [`TracedTrochoids`] along one ray (or the cone around it): tier 0 is `y`,
/// tier `j ≥ 1` the `j`-th run of [`tier_group`] lane groups of 8 waves.
pub(crate) struct SeaTiers<'a> {
    pub(super) sea: &'a TracedTrochoids,
    pub(super) state: &'a mut RayState,
    pub(super) origin: DVec3,
    pub(super) direction: DVec3,
    pub(super) t_exit: f64,
    pub(super) slope_error: f64,
}

impl<'a> SeaTiers<'a> {
    /// The tiers along `ray` up to `t_exit`, faded for a pixel of `footprint_angle` rad; with
    /// `cone > 0`, tiers that bound every ray within `cone` rad of `ray`: a wave that would fade
    /// for some ray of the cone before `t_exit` is held at its minimum `−A` (the faded term
    /// `−wA cos θ ≥ −A` for any weight), the others are used whole.
    pub(crate) fn new(
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
    pub(super) fn fill_ray(
        sea: &TracedTrochoids,
        state: &mut RayState,
        o: DVec3,
        d: DVec3,
        footprint_angle: f64,
    ) -> f64 {
        let fading = footprint_angle > 0.0;
        // Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²)): the footprint stretched by 1/max(|d_y|, 0.05) along the view.
        let reach = f32x8::splat(if fading { (TAU / footprint_angle) as f32 } else { 0.0 });
        let inv_dy2 = f32x8::splat(brine_core::footprint::footprint_stretch_squared(d.y) as f32);
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
    pub(super) fn fill_cone(
        sea: &TracedTrochoids,
        state: &mut RayState,
        o: DVec3,
        d: DVec3,
        t_exit: f64,
        footprint_angle: f64,
        cone: f64,
    ) -> f64 {
        // In a cone, |σ|/max(|d_y|, g) ≤ (|σ_axis| + kθ)/max(|d_y| − θ, g), g the smallest grazing.
        let dy_cone = (d.y.abs() - cone).max(brine_core::footprint::MIN_FOOTPRINT_GRAZING);
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
                    // Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²)) at its smallest over the cone.
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
    pub(super) fn group(&self, tier: usize) -> std::ops::Range<usize> {
        let g = self.sea.group;
        let first = (tier - 1) * g;
        first..(first + g).min(self.sea.tiers.len())
    }

    /// Bounds of the sea's lane group `j` (8 waves) for every `t' ∈ [t, t_exit]`.
    pub(super) fn lane_bounds(&self, j: usize, t: f64) -> TierBounds {
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
    pub(super) fn lane_sample(&self, j: usize, t: f64) -> TierSample {
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
