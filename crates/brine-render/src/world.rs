//! A scene turned into models: the fitted sea, the sky and sun, the slope statistics.

use brine_optics::{
    DarlesWater, JerlovType, RgbBands, SlopeVariance, WATER_IOR, WaterBody, WaterRgb, fresnel_dielectric,
    hemispherical_fresnel_reflectance,
};
use brine_sky::{PreethamSky, Sun};
use brine_trace::{LipschitzSum, Method, TraceOptions};
use brine_waves::{
    CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, Trochoid, TrochoidSet, TrochoidSum, fit_trochoids,
};
use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::camera::{Camera, direction_from_bearing};
use crate::scene::{FloorConfig, Scene, SpectrumKind};

/// Why a scene could not be turned into models.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    /// A model rejected a parameter.
    #[error("{0}")]
    Model(String),
}

/// Everything the per-pixel shading needs, built once per frame.
pub struct World {
    /// The fitted wave set.
    pub set: TrochoidSet,
    /// The traced surface.
    pub sea: TrochoidSum,
    /// Time of the frame (s).
    pub time: f64,
    /// The daylight sky.
    pub sky: PreethamSky,
    /// The sun.
    pub sun: Sun,
    /// Unit horizontal wind direction (the BRDF's x axis).
    pub wind: DVec3,
    /// Slope variances of the waves not drawn as geometry (Cox–Munk total minus the fitted set).
    pub variance_unresolved: SlopeVariance,
    /// Slope variances of the whole sea (Cox–Munk), used beyond the trace distance.
    pub variance_total: SlopeVariance,
    /// Optical properties of the water per channel.
    pub water: WaterRgb,
    /// Downwelling irradiance just below a flat surface, `E_d(0⁻)` (klx per channel).
    pub e_below: DVec3,
    /// The sea floor, if the water is not deep.
    pub floor: Option<Floor>,
    /// `true` when the camera is below the sea surface.
    pub underwater: bool,
    /// Options of the tracer.
    pub trace: TraceOptions,
    /// The camera.
    pub camera: Camera,
    /// Exposure of the frame (EV₁₀₀), from the scene or automatic.
    pub exposure_ev: f64,
}

/// Automatic exposure from the horizontal illuminance `E` (lx): `EV₁₀₀ = log₂(E/2.5)`, the
/// exposure an incident-light meter with calibration constant `C = 250 lx·s` sets at ISO 100.
///
/// # References
/// ISO 2720:1974 (incident-light meter calibration); Ray S. 2000, *The Manual of Photography*, §21.
pub fn auto_exposure_ev(illuminance_lx: f64) -> f64 {
    (illuminance_lx.max(1e-6) / 2.5).log2()
}

/// A Lambertian sea floor `y = −depth + h(x, z)` shaped by a static trochoid set.
pub struct Floor {
    /// The floor's undulations (static: `ω = 0`).
    pub shape: TrochoidSum,
    /// Mean depth below sea level (m).
    pub depth: f64,
    /// Diffuse reflectance per channel.
    pub albedo: DVec3,
}

impl Floor {
    /// The floor of a (validated) `[water.floor]` section: `waves` trochoids with wavelengths
    /// log-spaced over the range, amplitudes proportional to wavelength (equal slopes) summing to
    /// `amplitude_m`, steepness `kA`, directions and phases from the seed.
    fn new(c: &FloorConfig) -> Result<Self, WorldError> {
        let mut rng = ChaCha8Rng::seed_from_u64(c.seed);
        let n = c.waves as usize;
        let [lo, hi] = c.wavelength_range_m;
        let lambdas: Vec<f64> =
            (0..n).map(|i| lo * (hi / lo).powf(if n > 1 { i as f64 / (n - 1) as f64 } else { 0.0 })).collect();
        let total: f64 = lambdas.iter().sum();
        let mut waves = Vec::with_capacity(n);
        for lambda in lambdas {
            let amplitude = c.amplitude_m * lambda / total;
            let k = std::f64::consts::TAU / lambda;
            let (dir, phase): (f64, f64) =
                (rng.random::<f64>() * std::f64::consts::TAU, rng.random::<f64>() * std::f64::consts::TAU);
            let q = (k * amplitude).min(0.5);
            waves.push(Trochoid::new(amplitude, k, dir, 0.0, phase, q).map_err(|e| WorldError::Model(e.to_string()))?);
        }
        Ok(Self {
            shape: TrochoidSum::new(&TrochoidSet::new(waves)),
            depth: c.depth_m,
            albedo: DVec3::from_array(c.albedo),
        })
    }
}

/// The water body of `[water]`: a Jerlov type, one of Darles et al.'s classes, or Case-1 water of
/// a chlorophyll concentration (Jerlov IB when neither is given).
///
/// # Errors
/// A message naming the unknown type.
pub fn water_body_of(water_type: Option<&str>, chlorophyll_mg_m3: Option<f64>) -> Result<WaterBody, String> {
    if let Some(c) = chlorophyll_mg_m3 {
        return WaterBody::case1(c).map_err(|e| e.to_string());
    }
    let name = water_type.unwrap_or("IB");
    Ok(match name.to_ascii_lowercase().as_str() {
        "clear" => WaterBody::darles(DarlesWater::Clear),
        "turbid" => WaterBody::darles(DarlesWater::Turbid),
        "very-turbid" => WaterBody::darles(DarlesWater::VeryTurbid),
        _ => WaterBody::jerlov(name.parse::<JerlovType>().map_err(|_| {
            format!("water.type = {name:?} is unknown: expected I, IA, IB, II, III, 1C, 3C, 5C, 7C, 9C, clear, turbid or very-turbid")
        })?),
    })
}

/// Wind speed 12.5 m above the sea from `U₁₀` by the neutral logarithmic profile with roughness
/// length `z₀ = 2×10⁻⁴ m`: `U₁₂.₅ = U₁₀ ln(12.5/z₀)/ln(10/z₀)` (factor 1.0206).
fn u12_5_from_u10(u10: f64) -> f64 {
    let z0: f64 = 2e-4;
    u10 * (12.5 / z0).ln() / (10.0 / z0).ln()
}

impl World {
    /// Builds the models of a validated scene.
    ///
    /// # Errors
    /// [`WorldError`] if a model rejects a parameter.
    pub fn new(scene: &Scene) -> Result<Self, WorldError> {
        let model = |e: &dyn std::fmt::Display| WorldError::Model(e.to_string());
        let s = &scene.sea;
        let wind_angle = s.wind_direction_deg.to_radians();
        let wind = DVec3::new(wind_angle.cos(), 0.0, wind_angle.sin());
        let set = if s.wind_speed_m_s <= 0.0 || s.waves == 0 {
            TrochoidSet::default()
        } else {
            let spectrum = match s.spectrum {
                SpectrumKind::PiersonMoskowitz => {
                    PiersonMoskowitz::from_u10(s.wind_speed_m_s).map_err(|e| model(&e))?
                }
            };
            let spreading = CosineTwoS::hasselmann(spectrum.peak_omega()).map_err(|e| model(&e))?;
            let options = FitOptions { wind_direction: wind_angle, choppiness: s.choppiness, ..FitOptions::default() };
            fit_trochoids(&spectrum, &spreading, s.waves as usize, s.seed, &options).map_err(|e| model(&e))?
        };
        let sea = TrochoidSum::new(&set);

        let k = &scene.sky;
        let sun_dir = direction_from_bearing(k.sun_azimuth_deg, k.sun_elevation_deg);
        let sky = PreethamSky::new(k.turbidity, sun_dir).map_err(|e| model(&e))?;
        let sun = Sun::through_atmosphere(k.turbidity, sun_dir).map_err(|e| model(&e))?;

        let variance_total =
            SlopeVariance::cox_munk_clean(u12_5_from_u10(s.wind_speed_m_s).min(60.0)).map_err(|e| model(&e))?;
        let (mut rx, mut ry) = (0.0, 0.0);
        for w in set.waves() {
            let c = (w.direction() - wind_angle).cos();
            let msq = w.mean_square_slope();
            rx += msq * c * c;
            ry += msq * (1.0 - c * c);
        }
        let variance_unresolved = variance_total.minus(rx, ry);

        // Downwelling irradiance just below a flat surface: the sun's share through Fresnel, the
        // sky's through the hemispherical Fresnel reflectance of a uniform sky (0.066).
        let sky_e = sky.horizontal_irradiance_rgb();
        let cos_sun = sun_dir.y.max(0.0);
        let e_below = sun.irradiance_rgb() * cos_sun * (1.0 - fresnel_dielectric(cos_sun, 1.0, WATER_IOR))
            + sky_e * (1.0 - hemispherical_fresnel_reflectance(1.0, WATER_IOR));
        let body = water_body_of(scene.water.water_type.as_deref(), scene.water.chlorophyll_mg_m3)
            .map_err(WorldError::Model)?;
        let water = WaterRgb::new(&body, RgbBands::SrgbAverage);
        let floor = scene.water.floor.as_ref().map(Floor::new).transpose()?;

        let camera = Camera::from_config(&scene.camera);
        let exposure_ev = if scene.output.auto_exposure {
            let e_klx = sun.irradiance_rgb().y * cos_sun + sky_e.y;
            (auto_exposure_ev(e_klx * 1000.0) + scene.output.exposure_ev).clamp(-10.0, 30.0)
        } else {
            scene.output.exposure_ev
        };
        let trace = TraceOptions {
            method: Method::Directional,
            t_max: s.trace_distance_m,
            max_steps: 20_000,
            min_step: 1e-3,
            min_step_relative: 1e-4,
            tolerance: 1e-4,
            tolerance_relative: 1e-6,
            ..TraceOptions::default()
        };
        let world = Self {
            set,
            sea,
            time: s.time_s,
            sky,
            sun,
            wind,
            variance_unresolved,
            variance_total,
            water,
            e_below,
            floor,
            underwater: false,
            trace,
            camera,
            exposure_ev,
        };
        let mut world = world;
        world.underwater = world.sea.at_time(world.time).value(camera.position) < 0.0;
        Ok(world)
    }
}
