//! Procedural cloud layers: Chen et al.'s (2007, §3.1) texture perturbation, done with tileable
//! noise instead of textures.
//!
//! Chen et al. scroll two tileable textures past each other in opposite directions: a
//! perturbation texture whose two channels offset the coordinates at which a cloud texture is
//! read, and several cloud layers scrolled at different speeds for parallax. Here each texture is
//! a periodic value-noise fBm (period 256 lattice cells, so it tiles), seeded by ChaCha8: two
//! cloud layers at the same altitude (the second at half the feature size, moving 1.6 times
//! faster) read through one perturbation field that drifts against the wind. The sky-dome
//! mapping is the intersection of the view ray with a spherical shell at the cloud altitude, so
//! the clouds crowd toward the horizon. The `cover` parameter is the fraction of the dome's
//! texture area that is cloud (opacity ≥ ½): the density threshold is the matching quantile of
//! the noise, measured once in the constructor.

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
}

impl Default for CloudParams {
    fn default() -> Self {
        Self { cover: 0.4, altitude_m: 2000.0, scale_m: 4000.0, wind_m_s: DVec2::new(8.0, 0.0), seed: 1 }
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
    /// Checks the parameters, draws the lattice values and measures the cover threshold.
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming the parameter outside its range.
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
        let (fx, fy) = (x.x.floor(), x.y.floor());
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

    /// Cloud density at texture coordinates `uv` (units of the feature size) and time `t` (s):
    /// Chen's perturbed read of two scrolled layers.
    fn density(&self, uv: DVec2, time_s: f64) -> f64 {
        let wind = self.params.wind_m_s / self.params.scale_m;
        let perturb_at = uv * 0.5 - wind * (0.5 * time_s);
        let perturb =
            DVec2::new(self.fbm(perturb_at, PERTURB_OCTAVES, 101.0), self.fbm(perturb_at, PERTURB_OCTAVES, 211.0));
        let offset = (perturb - DVec2::splat(0.5)) * (2.0 * PERTURB_AMPLITUDE);
        let d1 = self.fbm(uv - wind * time_s + offset, CLOUD_OCTAVES, 0.0);
        let d2 = self.fbm(uv * 2.0 - wind * (2.0 * 1.6 * time_s) + offset * 2.0, CLOUD_OCTAVES - 1, 53.0);
        0.65 * d1 + 0.35 * d2
    }

    /// Distance along a unit view direction to the cloud shell at the cloud altitude (spherical
    /// Earth of radius 6371 km), `t = √(R² v_y² + 2RH + H²) − R v_y`.
    pub fn distance(&self, view: DVec3) -> f64 {
        let (r, h) = (EARTH_RADIUS_M, self.params.altitude_m);
        let vy = view.y;
        (r * r * vy * vy + 2.0 * r * h + h * h).sqrt() - r * vy
    }

    /// Opacity of the clouds toward `view` at time `time_s`: 0 below the horizon, a smooth ramp
    /// around the cover threshold, faded with distance toward the horizon.
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
        let p = DVec2::new(view.x, view.z) * t;
        let d = self.density(p / self.params.scale_m, time_s);
        let x = ((d - self.threshold + EDGE) / (2.0 * EDGE)).clamp(0.0, 1.0);
        x * x * (3.0 - 2.0 * x) * (-t / FADE_DISTANCE_M).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn textures_tile_and_are_seeded() {
        let c = CloudLayers::new(&CloudParams::default()).unwrap();
        let p = DVec2::new(12.3, 45.6);
        let shifted = p + DVec2::new(PERIOD as f64, -(PERIOD as f64));
        assert!((c.value_noise(p) - c.value_noise(shifted)).abs() < 1e-9);
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
            assert!((f - cover).abs() < 0.05, "cover {cover}: {f}");
        }
        let clear = CloudLayers::new(&CloudParams { cover: 0.0, ..CloudParams::default() }).unwrap();
        assert!(clear.opacity(DVec3::Y, 0.0).abs() < 1e-300);
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = CloudLayers::new(&CloudParams { cover: 1.5, ..CloudParams::default() }).unwrap_err();
        assert!(e.to_string().contains("clouds.cover"));
    }
}
