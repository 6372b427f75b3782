//! Procedural cloud layers: Chen et al.'s (2007, §3.1) texture perturbation, done with tileable
//! noise instead of textures.
//!
//! Chen et al. scroll two tileable textures past each other in opposite directions: a
//! perturbation texture whose two channels offset the coordinates at which a cloud texture is
//! read, and several cloud layers scrolled at different speeds for parallax. Here each texture is
//! a periodic value-noise fBm (period 256 lattice cells, so it tiles), seeded by ChaCha8: two
//! cloud layers at the same altitude (the first moving with the wind, the second at half the
//! feature size moving 1.6 times faster) read through one perturbation field (twice the
//! feature size) that scrolls against the wind at the wind's speed. The sky-dome
//! mapping is the intersection of the view ray with a spherical shell at the cloud altitude, so
//! the clouds crowd toward the horizon. The `cover` parameter is the fraction of the dome's
//! texture area that is cloud (opacity ≥ ½): the density threshold is the matching quantile of
//! the noise, measured once in the constructor.

use brine_core::lattice_floor;
use glam::{DVec2, DVec3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{SkyError, check};
use crate::twilight::EARTH_RADIUS_M;

/// Lattice period of the noise (cells): the textures tile every 256 cells.
const PERIOD: usize = 256;
/// Octaves of the cloud fBm and of the perturbation fBm.
const CLOUD_OCTAVES: usize = 5;
const PERTURB_OCTAVES: usize = 3;
/// Amplitude of the perturbation (texture units, i.e. fractions of the feature size).
const PERTURB_AMPLITUDE: f64 = 0.35;
/// Speeds of the two cloud layers relative to the wind: the second (half the feature size)
/// moves faster, for parallax. The perturbation map moves at −1 (against the wind).
const LAYER_SPEEDS: [f64; 2] = [1.0, 1.6];
/// Half-width of the opacity ramp around the threshold (noise units).
const EDGE: f64 = 0.06;
/// Distance over which the clouds fade into the haze toward the horizon (m).
const FADE_DISTANCE_M: f64 = 80_000.0;

/// The cloud settings of a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CloudParams {
    /// Fraction of the sky covered, `[0, 1]`.
    pub cover: f64,
    /// Altitude of the cloud base (m), `(0, 20 000]`.
    pub altitude_m: f64,
    /// Size of the largest cloud features (m), `[10, 10⁶]`.
    pub scale_m: f64,
    /// Wind carrying the clouds (m s⁻¹), `(east, south)` components, each `[−100, 100]`.
    pub wind_m_s: DVec2,
    /// Seed of the noise.
    pub seed: u64,
    /// Where the sky is seen from: the horizontal position `(x, z)` of the eye in the sea's frame
    /// (m), finite. The layers are fixed over the sea; the clouds toward a view are those above
    /// `origin + (v_x, v_z) t`, and a sea point's shadow is read at its own position, so the
    /// clouds seen and their shadows agree wherever the camera stands.
    pub origin_m: DVec2,
}

impl Default for CloudParams {
    fn default() -> Self {
        Self {
            cover: 0.4,
            altitude_m: 2000.0,
            scale_m: 4000.0,
            wind_m_s: DVec2::new(8.0, 0.0),
            seed: 1,
            origin_m: DVec2::ZERO,
        }
    }
}

/// Seeded, tileable cloud layers.
#[derive(Debug, Clone, PartialEq)]
pub struct CloudLayers {
    params: CloudParams,
    perm: Vec<u8>,
    values: Vec<f64>,
    threshold: f64,
}

impl CloudLayers {
    /// Checks the parameters, draws the lattice values (ChaCha8 from `seed`) and measures the
    /// cover threshold: the `(1 − cover)` quantile of the density over 4096 points of one period.
    ///
    /// # Arguments
    /// - `params`: the [`CloudParams`] (ranges in their field docs).
    ///
    /// # Returns
    /// The seeded [`CloudLayers`].
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming the parameter outside its range.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (cloud layers and the perturbation texture).
    pub fn new(params: &CloudParams) -> Result<Self, SkyError> {
        check("clouds.cover", params.cover, (0.0..=1.0).contains(&params.cover), "[0, 1]")?;
        check(
            "clouds.altitude_m",
            params.altitude_m,
            params.altitude_m > 0.0 && params.altitude_m <= 20_000.0,
            "(0, 20000] m",
        )?;
        check("clouds.scale_m", params.scale_m, (10.0..=1e6).contains(&params.scale_m), "[10, 1e6] m")?;
        for w in params.wind_m_s.to_array() {
            check("clouds.wind_m_s", w, (-100.0..=100.0).contains(&w), "[-100, 100] m/s per component")?;
        }
        for o in params.origin_m.to_array() {
            check("clouds.origin_m", o, o.is_finite(), "finite m")?;
        }
        let mut rng = ChaCha8Rng::seed_from_u64(params.seed);
        let mut perm: Vec<u8> = (0..=255u8).collect();
        for i in (1..PERIOD).rev() {
            perm.swap(i, rng.random_range(0..=i));
        }
        let values = (0..PERIOD).map(|_| rng.random::<f64>()).collect();
        let mut layers = Self { params: *params, perm, values, threshold: 0.0 };
        // The noise's distribution: 4096 samples on a fixed grid over one period.
        let mut samples: Vec<f64> = (0..4096)
            .map(|k| layers.density(DVec2::new((k % 64) as f64 * 3.97, (k / 64) as f64 * 3.97), 0.0))
            .collect();
        samples.sort_by(f64::total_cmp);
        let q = ((1.0 - params.cover) * (samples.len() - 1) as f64).round() as usize;
        layers.threshold = samples[q.min(samples.len() - 1)];
        if params.cover <= 0.0 {
            layers.threshold = f64::INFINITY;
        } else if params.cover >= 1.0 {
            layers.threshold = f64::NEG_INFINITY;
        }
        Ok(layers)
    }

    /// The settings.
    pub fn params(&self) -> &CloudParams {
        &self.params
    }

    fn hash(&self, i: i64, j: i64) -> f64 {
        let p = |k: i64| self.perm[k.rem_euclid(PERIOD as i64) as usize] as usize;
        self.values[p(i + p(j) as i64)]
    }

    /// Periodic value noise in `[0, 1]` with smoothstep interpolation.
    fn value_noise(&self, x: DVec2) -> f64 {
        let (fx, fy) = (lattice_floor(x.x), lattice_floor(x.y));
        let (i, j) = (fx as i64, fy as i64);
        let (u, v) = (x.x - fx, x.y - fy);
        let s = |t: f64| t * t * (3.0 - 2.0 * t);
        let (su, sv) = (s(u), s(v));
        let a = self.hash(i, j) + su * (self.hash(i + 1, j) - self.hash(i, j));
        let b = self.hash(i, j + 1) + su * (self.hash(i + 1, j + 1) - self.hash(i, j + 1));
        a + sv * (b - a)
    }

    /// Fractal sum of `octaves` octaves (gain ½, lacunarity 2, which keeps the period), in `[0, 1]`.
    fn fbm(&self, x: DVec2, octaves: usize, offset: f64) -> f64 {
        let (mut sum, mut amp, mut norm, mut p) = (0.0, 0.5, 0.0, x);
        for k in 0..octaves {
            sum += amp * self.value_noise(p + DVec2::splat(offset + 17.0 * k as f64));
            norm += amp;
            amp *= 0.5;
            p *= 2.0;
        }
        sum / norm
    }

    /// The wind in texture units per second, `w/ℓ` (`ℓ` the feature size).
    fn wind_uv(&self) -> DVec2 {
        self.params.wind_m_s / self.params.scale_m
    }

    /// Chen's perturbation map: a two-channel fBm at twice the feature size whose pattern
    /// scrolls *against* the wind, `p(uv, t) = fBm(uv/2 + (w/ℓ) t/2)` (it moves at `−w/ℓ`),
    /// mapped to an offset in `[−A, A]²`, `A` = [`PERTURB_AMPLITUDE`].
    fn perturbation(&self, uv: DVec2, time_s: f64) -> DVec2 {
        let at = uv * 0.5 + self.wind_uv() * (0.5 * time_s);
        let p = DVec2::new(self.fbm(at, PERTURB_OCTAVES, 101.0), self.fbm(at, PERTURB_OCTAVES, 211.0));
        (p - DVec2::splat(0.5)) * (2.0 * PERTURB_AMPLITUDE)
    }

    /// Cloud layer `k` (0 or 1) read through the perturbation offset: layer 0 at the feature
    /// size moving with the wind, `fBm(uv − (w/ℓ) t + o)`; layer 1 at half the feature size
    /// moving [`LAYER_SPEEDS`]`[1]` times faster, `fBm(2(uv − 1.6 (w/ℓ) t + o))`.
    #[cfg(test)]
    fn layer(&self, k: usize, uv: DVec2, time_s: f64) -> f64 {
        self.layer_with(k, uv, time_s, self.perturbation(uv, time_s))
    }

    /// [`Self::layer`] read through a perturbation `offset` computed once for both layers.
    fn layer_with(&self, k: usize, uv: DVec2, time_s: f64, offset: DVec2) -> f64 {
        let at = uv - self.wind_uv() * (LAYER_SPEEDS[k] * time_s) + offset;
        match k {
            0 => self.fbm(at, CLOUD_OCTAVES, 0.0),
            _ => self.fbm(at * 2.0, CLOUD_OCTAVES - 1, 53.0),
        }
    }

    /// Cloud density at texture coordinates `uv` (units of the feature size) and time `t` (s):
    /// Chen's perturbed read of two scrolled layers, `0.65 d₀ + 0.35 d₁`, in `[0, 1]`.
    fn density(&self, uv: DVec2, time_s: f64) -> f64 {
        // Both layers are read through the same perturbation map: computed once.
        let offset = self.perturbation(uv, time_s);
        0.65 * self.layer_with(0, uv, time_s, offset) + 0.35 * self.layer_with(1, uv, time_s, offset)
    }

    /// Distance along a unit view direction to the cloud shell at the cloud altitude (spherical
    /// Earth of radius 6371 km), `t = √(R² v_y² + 2RH + H²) − R v_y`.
    ///
    /// # Arguments
    /// - `view`: unit view direction (y up), any.
    ///
    /// # Returns
    /// `t` (m): the cloud altitude `H` at the zenith, `√(2RH + H²)` (160 km at 2 km) on the
    /// horizon.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (the clouds on a sky sphere); ray–sphere intersection.
    pub fn distance(&self, view: DVec3) -> f64 {
        let (r, h) = (EARTH_RADIUS_M, self.params.altitude_m);
        let vy = view.y;
        (r * r * vy * vy + 2.0 * r * h + h * h).sqrt() - r * vy
    }

    /// Opacity of the clouds toward `view` at time `time_s`: 0 below the horizon, a smooth ramp
    /// around the cover threshold, faded with distance toward the horizon,
    /// `α = S((d − d_c + ε)/(2ε)) e^{−t/80 km}`, `S(x) = x²(3 − 2x)` on `[0, 1]`, `d` the
    /// density at the point `(o + (v_x, v_z) t)/ℓ` of the shell, `o` the eye's horizontal position
    /// ([`CloudParams::origin_m`]), `d_c` the cover threshold, `ε = 0.06`.
    ///
    /// # Arguments
    /// - `view`: unit view direction (y up).
    /// - `time_s`: time (s); the layers scroll with the wind.
    ///
    /// # Returns
    /// Opacity `α ∈ [0, 1]`.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (texture perturbation, layers scrolled at different speeds).
    pub fn opacity(&self, view: DVec3, time_s: f64) -> f64 {
        if view.y <= 0.0 || self.threshold == f64::INFINITY {
            return 0.0;
        }
        let t = self.distance(view);
        let p = self.params.origin_m + DVec2::new(view.x, view.z) * t;
        let d = self.density(p / self.params.scale_m, time_s);
        let x = ((d - self.threshold + EDGE) / (2.0 * EDGE)).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x) * (-t / FADE_DISTANCE_M).exp()
    }

    /// Opacity of the clouds crossed by the ray from the sea point `(x, z)` toward the unit
    /// direction `toward` (the sun's): the cloud's shadow. The same ramp as [`Self::opacity`] at
    /// the point `(x, z) + (l_x, l_z) t(l)` of the shell, without the view's distance fade (a
    /// shadow is cast by the cloud itself, however far the ray runs to it).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position of the sea point (m) in the sea's frame, the frame of
    ///   [`CloudParams::origin_m`].
    /// - `toward`: unit direction of the light (y up); 0 for directions at or below the horizon.
    /// - `time_s`: time (s).
    ///
    /// # Returns
    /// Opacity `α ∈ [0, 1]`; the light reaching the point is `1 − α` of the clear-sky light.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (the cloud layer); the shadow is a straight ray through the shell.
    pub fn shadow(&self, x: f64, z: f64, toward: DVec3, time_s: f64) -> f64 {
        if toward.y <= 0.0 || self.threshold == f64::INFINITY {
            return 0.0;
        }
        let t = self.distance(toward);
        let p = DVec2::new(x, z) + DVec2::new(toward.x, toward.z) * t;
        let d = self.density(p / self.params.scale_m, time_s);
        let u = ((d - self.threshold + EDGE) / (2.0 * EDGE)).clamp(0.0, 1.0);
        u * u * (3.0 - 2.0 * u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Periodic noise: equal at points one period apart up to the rounding of the coordinates.
    const TILING_ROUNDING: f64 = 1e-9;
    /// Cover measured on 120 × 120 samples of a correlated field: 0.05.
    const COVER_SAMPLING: f64 = 0.05;
    /// Exact expressions evaluated in double precision.
    const ROUNDING: f64 = 1e-12;
    /// Over two hours of 8 m/s wind (58 km, 14 feature sizes) a half-covered sky must pass both
    /// cloud and gap at a fixed direction: the opacity must swing by more than 0.5.
    const MIN_SWING: f64 = 0.5;

    #[test]
    fn textures_tile_and_are_seeded() {
        let c = CloudLayers::new(&CloudParams::default()).unwrap();
        let p = DVec2::new(12.3, 45.6);
        let shifted = p + DVec2::new(PERIOD as f64, -(PERIOD as f64));
        assert!((c.value_noise(p) - c.value_noise(shifted)).abs() < TILING_ROUNDING);
        let same = CloudLayers::new(&CloudParams::default()).unwrap();
        assert_eq!(c, same);
        let other = CloudLayers::new(&CloudParams { seed: 2, ..CloudParams::default() }).unwrap();
        assert!((c.value_noise(p) - other.value_noise(p)).abs() > 0.0);
    }

    #[test]
    fn cover_is_the_cloudy_fraction() {
        // Over a large patch of texture (not the samples used for the threshold) the fraction with
        // α ≥ ½ before the distance fade matches `cover` to 0.05 (sampling of a correlated field).
        for cover in [0.2, 0.5, 0.8] {
            let c = CloudLayers::new(&CloudParams { cover, ..CloudParams::default() }).unwrap();
            let n = 120;
            let mut cloudy = 0;
            for i in 0..n {
                for j in 0..n {
                    let uv = DVec2::new(i as f64 * 1.31 + 0.17, j as f64 * 1.29 + 0.43);
                    if c.density(uv, 0.0) >= c.threshold {
                        cloudy += 1;
                    }
                }
            }
            let f = cloudy as f64 / (n * n) as f64;
            assert!((f - cover).abs() < COVER_SAMPLING, "cover {cover}: {f}");
        }
        let clear = CloudLayers::new(&CloudParams { cover: 0.0, ..CloudParams::default() }).unwrap();
        assert!(clear.opacity(DVec3::Y, 0.0).abs() < f64::MIN_POSITIVE);
    }

    /// A cloud's shadow on the sea is the cloud seen from that point: at the origin, straight up,
    /// the shadow equals the opacity before the distance fade, and the shadow of a point moved by
    /// `Δ` is the shadow of the origin looking through the shell point moved by `Δ`.
    #[test]
    fn shadows_are_the_clouds_seen_from_the_sea_point() {
        // Rounding of the fade factor e^{−t/80 km} at t = 2 km, divided out.
        const ROUNDING: f64 = 1e-12;
        let c = CloudLayers::new(&CloudParams { cover: 0.5, ..CloudParams::default() }).unwrap();
        let fade = (-c.distance(DVec3::Y) / FADE_DISTANCE_M).exp();
        assert!((c.shadow(0.0, 0.0, DVec3::Y, 30.0) * fade - c.opacity(DVec3::Y, 30.0)).abs() < ROUNDING);
        let (mut lit, mut shaded) = (0, 0);
        for i in 0..400 {
            let (x, z) = (i as f64 * 173.0, i as f64 * -97.0);
            let a = c.shadow(x, z, DVec3::Y, 0.0);
            assert!((0.0..=1.0).contains(&a));
            lit += usize::from(a <= 0.0);
            shaded += usize::from(a >= 1.0);
        }
        // Half the sky is covered: both fully lit and fully shaded points occur.
        assert!(lit > 50 && shaded > 50, "lit {lit}, shaded {shaded}");
        assert!(c.shadow(10.0, 5.0, DVec3::new(1.0, 0.0, 0.0), 0.0) <= 0.0, "no shadow from the horizon");
    }

    /// The layers are fixed over the sea: from an eye away from the origin, the cloud seen straight
    /// up is the one whose shadow a zenith sun casts at the eye's foot, and a view toward `v` sees
    /// the cloud above `o + (v_x, v_z) t`, the shadow's at that point. (Before the origin was a
    /// parameter the sky was drawn as seen from the origin wherever the camera stood: measured,
    /// 12 of these 40 eyes then saw a cloud straight up that did not shade their foot, or the
    /// reverse; 17 differed by more than 0.1 in opacity.)
    #[test]
    fn the_clouds_seen_from_anywhere_are_those_over_the_sea() {
        // Rounding of the fade factor e^{−t/80 km}, divided out.
        const ROUNDING: f64 = 1e-12;
        let v = DVec3::new(0.3, 0.5, -0.2).normalize();
        for i in 0..40 {
            let origin = DVec2::new(i as f64 * 911.0 - 15_000.0, i as f64 * -523.0 + 4_000.0);
            let c = CloudLayers::new(&CloudParams { cover: 0.5, origin_m: origin, ..CloudParams::default() }).unwrap();
            for (view, time) in [(DVec3::Y, 30.0), (v, 400.0)] {
                let t = c.distance(view);
                let under = origin + DVec2::new(view.x, view.z) * t;
                let fade = (-t / FADE_DISTANCE_M).exp();
                let seen = c.opacity(view, time);
                let shade = c.shadow(under.x, under.y, DVec3::Y, time);
                assert!((shade * fade - seen).abs() < ROUNDING, "eye at {origin}, view {view}: {seen} against {shade}");
            }
        }
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = CloudLayers::new(&CloudParams { cover: 1.5, ..CloudParams::default() }).unwrap_err();
        assert!(e.to_string().contains("clouds.cover"));
        let far = DVec2::new(f64::NAN, 0.0);
        let e = CloudLayers::new(&CloudParams { origin_m: far, ..CloudParams::default() }).unwrap_err();
        assert!(e.to_string().contains("clouds.origin_m"), "{e}");
    }

    /// Where along `x` (texture units, step `STEP` from 0 to `MAX_SHIFT`) the pattern `f(·, t₁)`
    /// best matches `f(·, t₀)` shifted: the lag of the largest normalised cross-correlation over
    /// a 2-D patch of 24 × 200 samples.
    fn best_shift(f: &dyn Fn(DVec2, f64) -> f64, t0: f64, t1: f64, wind_sign: f64) -> f64 {
        const STEP: f64 = 0.05;
        const MAX_SHIFT: f64 = 5.0;
        let patch: Vec<DVec2> =
            (0..24).flat_map(|j| (0..200).map(move |i| DVec2::new(i as f64 * STEP, j as f64 * 0.37))).collect();
        let centred = |v: Vec<f64>| {
            let m = v.iter().sum::<f64>() / v.len() as f64;
            let n = v.iter().map(|x| (x - m).powi(2)).sum::<f64>().sqrt();
            v.into_iter().map(|x| (x - m) / n).collect::<Vec<_>>()
        };
        let a = centred(patch.iter().map(|&p| f(p, t0)).collect());
        let (mut best, mut lag) = (f64::NEG_INFINITY, 0.0);
        for k in 0..=(MAX_SHIFT / STEP) as usize {
            let s = wind_sign * k as f64 * STEP;
            let b = centred(patch.iter().map(|&p| f(p + DVec2::new(s, 0.0), t1)).collect());
            let c: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
            if c > best {
                (best, lag) = (c, s);
            }
        }
        lag
    }

    /// The lag is found on a 0.05-unit grid, and the perturbation (±0.35 units, itself moving)
    /// warps a layer's pattern while it moves: 0.15 units.
    const SHIFT_TOLERANCE: f64 = 0.15;

    #[test]
    fn layers_and_perturbation_move_at_their_own_speeds() {
        // Wind 8 m/s east, features 4 km: 2 texture units in 1000 s. Layer 0 moves +2.0, layer 1
        // +3.2, the perturbation map −2.0 (against the wind).
        let c = CloudLayers::new(&CloudParams::default()).unwrap();
        let dt = 1000.0;
        let expected = c.wind_uv().x * dt;
        assert!((expected - 2.0).abs() < ROUNDING);
        let l0 = best_shift(&|p, t| c.layer(0, p, t), 0.0, dt, 1.0);
        let l1 = best_shift(&|p, t| c.layer(1, p, t), 0.0, dt, 1.0);
        let pert = best_shift(&|p, t| c.perturbation(p, t).x, 0.0, dt, -1.0);
        assert!((l0 - LAYER_SPEEDS[0] * expected).abs() < SHIFT_TOLERANCE, "layer 0 moved {l0}");
        assert!((l1 - LAYER_SPEEDS[1] * expected).abs() < SHIFT_TOLERANCE, "layer 1 moved {l1}");
        assert!((pert + expected).abs() < SHIFT_TOLERANCE, "perturbation moved {pert}");
    }

    #[test]
    fn opacity_changes_over_time_at_a_fixed_direction() {
        // 30° up toward the south-east, every 2 minutes for 2 hours: the clouds drift across.
        let c = CloudLayers::new(&CloudParams { cover: 0.5, ..CloudParams::default() }).unwrap();
        let v = DVec3::new(0.6, 0.5, 0.6).normalize();
        let a: Vec<f64> = (0..60).map(|i| c.opacity(v, i as f64 * 120.0)).collect();
        let (lo, hi) = a.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| (l.min(x), h.max(x)));
        assert!(hi - lo > MIN_SWING, "opacity range {lo}..{hi}");
        // No wind, no motion.
        let still = CloudLayers::new(&CloudParams { wind_m_s: DVec2::ZERO, ..CloudParams::default() }).unwrap();
        assert!((still.opacity(v, 0.0) - still.opacity(v, 7200.0)).abs() < f64::EPSILON);
    }

    #[test]
    fn no_cover_is_clear_and_full_cover_is_overcast() {
        // cover 0: no cloud anywhere; cover 1: every direction above the horizon at its largest
        // opacity, the haze fade e^{−t/80 km} (0.975 at the zenith for a 2 km base).
        let clear = CloudLayers::new(&CloudParams { cover: 0.0, ..CloudParams::default() }).unwrap();
        let full = CloudLayers::new(&CloudParams { cover: 1.0, ..CloudParams::default() }).unwrap();
        for i in 0..200 {
            let (e, a) = ((i % 20) as f64 * 4.5 + 0.5, (i / 20) as f64 * 36.0);
            let (e, a) = (e.to_radians(), a.to_radians());
            let v = DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos());
            for t in [0.0, 500.0, 3600.0] {
                assert!(clear.opacity(v, t).abs() < f64::EPSILON);
                let fade = (-full.distance(v) / FADE_DISTANCE_M).exp();
                assert!((full.opacity(v, t) - fade).abs() < ROUNDING, "{v:?}");
            }
        }
        assert!((full.opacity(DVec3::Y, 0.0) - (-2000.0f64 / FADE_DISTANCE_M).exp()).abs() < ROUNDING);
        assert!(full.opacity(DVec3::new(1.0, -0.01, 0.0).normalize(), 0.0).abs() < f64::EPSILON);
    }
}
