//! A scene turned into models: the fitted sea, the sky and sun, the slope statistics.

use brine_optics::{SlopeVariance, WATER_IOR, fresnel_dielectric};
use brine_sky::{PreethamSky, Sun};
use brine_trace::{LipschitzSum, Method, TraceOptions};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TrochoidSet, TrochoidSum, fit_trochoids};
use glam::DVec3;

use crate::camera::{Camera, direction_from_bearing};
use crate::scene::{Scene, SpectrumKind};

/// Why a scene could not be turned into models.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    /// A model rejected a parameter.
    #[error("{0}")]
    Model(String),
    /// The camera is below the sea surface (underwater views arrive with issue #7).
    #[error(
        "the camera at y = {camera_y:.3} m is below the sea surface there (surface at {surface_y:.3} m); \
         raise camera.position[1] (underwater cameras arrive with issue #7)"
    )]
    CameraUnderwater {
        /// Camera height (m).
        camera_y: f64,
        /// Surface height under the camera (m).
        surface_y: f64,
    },
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
    /// Radiance leaving the water body just above the surface, before the `(1 − F)` weight
    /// (linear sRGB, kcd m⁻²).
    pub water_radiance: DVec3,
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

/// Wind speed 12.5 m above the sea from `U₁₀` by the neutral logarithmic profile with roughness
/// length `z₀ = 2×10⁻⁴ m`: `U₁₂.₅ = U₁₀ ln(12.5/z₀)/ln(10/z₀)` (factor 1.0206).
fn u12_5_from_u10(u10: f64) -> f64 {
    let z0: f64 = 2e-4;
    u10 * (12.5 / z0).ln() / (10.0 / z0).ln()
}

/// **Provisional** deep-water diffuse reflectance just below the surface, `R(0⁻) = 0.33 b_b/a`
/// (Morel & Prieur 1977) for pure sea water at 650, 550 and 450 nm (one wavelength per sRGB
/// channel): `a` from Pope & Fry 1997 (0.340, 0.0565, 0.0092 m⁻¹), `b_b = ½ b_w`,
/// `b_w = 0.00758 (400/λ)^{4.32}` m⁻¹. Replaced by the brine-optics water model with issue #5.
fn pure_water_reflectance_rgb() -> DVec3 {
    let r = |lambda: f64, a: f64| 0.33 * 0.5 * 0.00758 * (400.0 / lambda).powf(4.32) / a;
    DVec3::new(r(650.0, 0.340), r(550.0, 0.0565), r(450.0, 0.0092))
}

impl World {
    /// Builds the models of a validated scene.
    ///
    /// # Errors
    /// [`WorldError`] if a model rejects a parameter or the camera is under the surface.
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
        // sky's through its hemispherical mean transmittance 1 − 0.066 (uniform sky).
        let sky_e = sky.horizontal_irradiance_rgb();
        let cos_sun = sun_dir.y.max(0.0);
        let e_below = sun.irradiance_rgb() * cos_sun * (1.0 - fresnel_dielectric(cos_sun, 1.0, WATER_IOR))
            + sky_e * (1.0 - 0.066);
        // Upwelling radiance below, L_u = R E_d/π, carried through the surface with the n²
        // radiance law (the (1 − F) factor is applied per pixel).
        let water_radiance = pure_water_reflectance_rgb() * e_below / std::f64::consts::PI / (WATER_IOR * WATER_IOR);

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
            water_radiance,
            trace,
            camera,
            exposure_ev,
        };
        let field = world.sea.at_time(world.time);
        let f = field.value(camera.position);
        if f <= 0.0 {
            return Err(WorldError::CameraUnderwater { camera_y: camera.position.y, surface_y: camera.position.y - f });
        }
        Ok(world)
    }
}
