//! The scene file: TOML, every key optional, unknown keys rejected, every value range-checked.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

mod check;
pub mod keys;

/// The scene embedded in the binary, rendered by `brine` with no arguments.
pub const DEFAULT_SCENE_TOML: &str = include_str!("../../scenes/default.toml");

/// Name used in messages for the embedded default scene.
pub const DEFAULT_SCENE_NAME: &str = "<default scene>";

/// A scene-file error: the file, the line when known, and what was expected.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{file}{}: {message}", line.map(|l| format!(" line {l}")).unwrap_or_default())]
pub struct SceneError {
    /// File name as given by the user.
    pub file: String,
    /// 1-based line of the offending key or value, when known.
    pub line: Option<usize>,
    /// What is wrong and what was expected.
    pub message: String,
}

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Scene {
    /// Place and time: the sun and the moon from brine-ephem.
    pub place: Option<PlaceConfig>,
    /// The camera.
    pub camera: CameraConfig,
    /// The sea.
    pub sea: SeaConfig,
    /// Sky and sun.
    pub sky: SkyConfig,
    /// The output image.
    pub output: OutputConfig,
    /// The water body and the sea floor.
    pub water: WaterConfig,
    /// Phenomena switched on or off.
    pub phenomena: PhenomenaConfig,
    /// Animation timing.
    pub animation: AnimationConfig,
    /// Seconds elapsed since `place.time_utc` (set per frame by animations, not in files).
    #[serde(skip)]
    pub elapsed_s: f64,
}

/// `[place]`: where and when; the sun and the moon follow from them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaceConfig {
    /// Geodetic latitude (°, `[−90, 90]`, north positive).
    pub latitude_deg: f64,
    /// Longitude (°, `[−180, 180]`, east positive).
    pub longitude_deg: f64,
    /// UTC instant (RFC 3339, e.g. `2024-06-21T09:30:00Z`), 1800–2200.
    pub time_utc: String,
    /// Sun model: `spa` (NREL SPA, ±0.0003°) or `schlyter` (Schlyter's elements, ~0.01°).
    #[serde(default)]
    pub sun_model: SunModelKind,
    /// Atmospheric refraction of the sun and moon near the horizon (standard air).
    #[serde(default = "yes")]
    pub refraction: bool,
}

fn yes() -> bool {
    true
}

/// Which sun-position model `[place]` uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SunModelKind {
    /// NREL's Solar Position Algorithm.
    #[default]
    Spa,
    /// Schlyter's simplified model (the one of Li Ying et al. 2018).
    Schlyter,
}

/// `[water]`: the optical water type and the sea floor.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WaterConfig {
    /// Jerlov water type (`I`, `IA`, `IB`, `II`, `III`, `1C`, `3C`, `5C`, `7C`, `9C`) or Darles et
    /// al.'s `clear`, `turbid`, `very-turbid`; excludes `chlorophyll_mg_m3`. Jerlov IB when
    /// neither is given.
    #[serde(rename = "type")]
    pub water_type: Option<String>,
    /// Chlorophyll concentration of Case-1 water (mg m⁻³, `[0, 30]`); excludes `type`.
    pub chlorophyll_mg_m3: Option<f64>,
    /// The sea floor; deep water when absent.
    pub floor: Option<FloorConfig>,
    /// Sea-surface temperature (°C, `[−2, 40]`); with `air_temperature_c`, whitecap coverage
    /// follows Monahan & Ó Muircheartaigh's 1986 stability law, else their 1980 wind law.
    pub temperature_c: Option<f64>,
    /// Air temperature 10 m above the sea (°C, `[−40, 50]`).
    pub air_temperature_c: Option<f64>,
}

/// `[water.floor]`: a Lambertian sea floor shaped by its own static trochoid set (Darles et al.
/// 2007 §4.3), traced by the same sphere tracer as the surface.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FloorConfig {
    /// Mean depth of the floor below sea level (m, `[0.5, 1000]`).
    pub depth_m: f64,
    /// Diffuse reflectance (linear sRGB, each `[0, 1]`); sand is about `[0.45, 0.40, 0.30]`.
    pub albedo: [f64; 3],
    /// Number of trochoids shaping the floor (`[0, 64]`).
    pub waves: u32,
    /// Sum of the floor trochoids' amplitudes (m, `[0, depth_m/2]`).
    pub amplitude_m: f64,
    /// Shortest and longest floor wavelengths (m, `0.05 ≤ min ≤ max ≤ 10⁴`).
    pub wavelength_range_m: [f64; 2],
    /// Seed of the floor's directions and phases.
    pub seed: u64,
}

impl Default for FloorConfig {
    fn default() -> Self {
        Self {
            depth_m: 6.0,
            albedo: [0.45, 0.40, 0.30],
            waves: 8,
            amplitude_m: 0.4,
            wavelength_range_m: [0.8, 25.0],
            seed: 7,
        }
    }
}

/// `[phenomena]`: what the image shows beyond sea, sky and sun.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PhenomenaConfig {
    /// Glare of the eye (Spencer et al. 1995 point-spread function).
    pub glare: bool,
    /// Aerial perspective between the eye and the sea (Hoffman & Preetham 2002).
    pub aerial_perspective: bool,
    /// The cloud layers of `[sky.clouds]`.
    pub clouds: bool,
    /// Sun light through thin wave crests (Jensen et al. 2001 dipole, Li Ying et al. 2018 §3.3).
    pub subsurface: bool,
    /// Decaying foam on crests (Darles et al. 2007 §4.1: Monahan coverage, height/slope/noise
    /// extension, Koepke reflectance).
    pub foam: bool,
    /// Active whitecaps from the displacement Jacobian (Dupuy & Bruneton 2012).
    pub whitecaps: bool,
    /// Sea spray above the surface (Monahan et al. 1986, Darles et al. 2007 §4.2).
    pub spray: bool,
    /// Raw whitecap threshold `α` of Dupuy & Bruneton (`[−2, 2]`); when absent, `α` is calibrated
    /// so that the sea's mean coverage is Monahan's.
    pub whitecap_alpha: Option<f64>,
    /// With foam and whitecaps both on: the foam is left by the breaking crests and remembered
    /// (brine-foam `FoamMemory`); `false` draws the two separately (Darles' extension and the
    /// Jacobian whitecaps, a faint veil).
    pub foam_memory: bool,
}

impl Default for PhenomenaConfig {
    fn default() -> Self {
        Self {
            glare: true,
            aerial_perspective: true,
            clouds: true,
            subsurface: true,
            foam: true,
            whitecaps: true,
            spray: true,
            whitecap_alpha: None,
            foam_memory: true,
        }
    }
}

/// `[animation]`: frame timing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct AnimationConfig {
    /// Frames per second (`(0, 1000]`); frame `f` is at `sea.time_s + f/fps`.
    pub fps: f64,
}

impl Default for AnimationConfig {
    fn default() -> Self {
        Self { fps: 24.0 }
    }
}

/// `[camera]`: a pinhole camera.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CameraConfig {
    /// Position (m), y up, sea level at y = 0.
    pub position: [f64; 3],
    /// A point to look at (m); excludes `yaw_deg`/`pitch_deg`.
    pub look_at: Option<[f64; 3]>,
    /// Compass bearing of the view (°, 0 north = −z, 90 east = +x); 100° when neither it nor
    /// `look_at` is given ([`Scene::DEFAULT_YAW_DEG`]).
    pub yaw_deg: Option<f64>,
    /// Elevation of the view (°, `[−90, 90]`, negative looks down); −9° when neither it nor
    /// `look_at` is given ([`Scene::DEFAULT_PITCH_DEG`]).
    pub pitch_deg: Option<f64>,
    /// Vertical field of view (°, `(0, 180)`).
    pub fov_deg: f64,
    /// Image width (pixels, `[1, 16384]`).
    pub width: u32,
    /// Image height (pixels, `[1, 16384]`).
    pub height: u32,
    /// Samples per pixel (`[1, 4096]`); 1 samples the pixel centre.
    pub spp: u32,
}

impl Default for CameraConfig {
    fn default() -> Self {
        Self {
            position: [0.0, 10.0, 0.0],
            look_at: None,
            yaw_deg: None,
            pitch_deg: None,
            fov_deg: 50.0,
            width: 1280,
            height: 720,
            spp: 1,
        }
    }
}

/// Ocean spectrum of the fitted wave set.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SpectrumKind {
    /// Pierson–Moskowitz 1964, fully developed sea (Darles et al. 2007).
    #[default]
    PiersonMoskowitz,
    /// JONSWAP (Hasselmann et al. 1973), fetch-limited; uses `fetch_km` and `gamma`.
    Jonswap,
    /// Phillips (Tessendorf 2001).
    Phillips,
    /// TMA (Bouws et al. 1985): JONSWAP in water of depth `depth_m`.
    Tma,
    /// Elfouhaily et al. 1997 unified spectrum (Li Ying et al. 2018); uses `fetch_km`.
    Elfouhaily,
}

/// Directional spreading of the fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SpreadingKind {
    /// The spectrum's natural choice: Elfouhaily's own `Δ(k)` for `elfouhaily`, the cos-2s law of
    /// Hasselmann et al. 1980 otherwise.
    #[default]
    Auto,
    /// cos-2s, Hasselmann et al. 1980.
    Cos2s,
    /// cos-2s, Mitsuyasu et al. 1975 (wind-dependent).
    Mitsuyasu,
    /// Donelan, Hamilton & Hui 1985 sech² with Banner's extension.
    DonelanBanner,
    /// `(2/π) cos²θ`.
    CosSquared,
    /// Elfouhaily et al. 1997 `Δ(k)`.
    Elfouhaily,
}

/// Which surface is traced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SurfaceKind {
    /// Sum of per-wave trochoid height fields (Darles et al. 2007; the default).
    #[default]
    Trochoids,
    /// The true Gerstner sum (horizontal displacements composed).
    Gerstner,
    /// Chen et al. 2007 sine waves with normal-perturbing detail waves.
    Sine,
    /// Tessendorf's inverse-FFT height field (Li Ying et al. 2018 §2.2, Dupuy & Bruneton 2012):
    /// periodic cascades of the spectrum, traced as certified cubic B-splines (`[sea.fft]`).
    Fft,
}

/// `[sea]`: the wind sea.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SeaConfig {
    /// Ocean spectrum.
    pub spectrum: SpectrumKind,
    /// Directional spreading.
    pub spreading: SpreadingKind,
    /// Surface model traced.
    pub surface: SurfaceKind,
    /// Wind speed 10 m above the sea, `U₁₀` (m s⁻¹, `[0, 60]`; 0 is a flat calm).
    pub wind_speed_m_s: f64,
    /// Direction the wind blows toward (°, from +x (east) toward +z (south)).
    pub wind_direction_deg: f64,
    /// Fetch (km, `[0.1, 10⁵]`) of `jonswap`, `tma`, `elfouhaily`; fully developed when absent
    /// (JONSWAP and TMA then use 100 km).
    pub fetch_km: Option<f64>,
    /// Peak enhancement `γ` of `jonswap`/`tma` (`[1, 10]`, default 3.3).
    pub gamma: Option<f64>,
    /// Water depth of `tma` (m, `[0.5, 10⁴]`).
    pub depth_m: Option<f64>,
    /// Number of trochoid waves of the wind sea (`[0, 10000]`).
    pub waves: u32,
    /// Choppiness of the fit (`[0, 100]`): each wave's steepness is `c·kA` before the cap.
    pub choppiness: f64,
    /// Random seed of wave directions and phases.
    pub seed: u64,
    /// Time of the frame (s, `[0, 10⁶]`).
    pub time_s: f64,
    /// Distance up to which waves are traced as geometry (m, `[10, 10⁶]`); beyond it the sea is
    /// its mean plane shaded with the slope statistics of all waves.
    pub trace_distance_m: f64,
    /// A swell from a distant storm, added to the wind sea.
    pub swell: Option<SwellConfig>,
    /// Grid and cascades of `surface = "fft"`.
    pub fft: FftConfig,
}

/// `[sea.fft]`: the FFT ocean of `surface = "fft"` (brine-waves `FftOcean`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct FftConfig {
    /// Grid resolution `N` of every cascade (a power of two in `[64, 2048]`, default 256; below 64
    /// the default tile ratio leaves a cascade too few grid points per wavelength).
    pub resolution: u32,
    /// Number of cascades (`[1, 8]`, default 4): tiles from 8 peak wavelengths down by a
    /// non-commensurate ratio.
    pub cascades: u32,
    /// Choppiness `λ` of the horizontal displacement (`[0, 4]`, default 1; 0 is the plain height
    /// field).
    pub choppiness: f64,
    /// Loop period (s, `(0, 10⁶]`): when given, the sea repeats exactly after it.
    pub loop_period_s: Option<f64>,
}

impl Default for FftConfig {
    fn default() -> Self {
        Self { resolution: 256, cascades: 4, choppiness: 1.0, loop_period_s: None }
    }
}

impl Default for SeaConfig {
    fn default() -> Self {
        Self {
            spectrum: SpectrumKind::PiersonMoskowitz,
            spreading: SpreadingKind::Auto,
            surface: SurfaceKind::Trochoids,
            wind_speed_m_s: 10.0,
            wind_direction_deg: 20.0,
            fetch_km: None,
            gamma: None,
            depth_m: None,
            waves: 50,
            choppiness: 2.5,
            seed: 1,
            time_s: 0.0,
            trace_distance_m: 3000.0,
            swell: None,
            fft: FftConfig::default(),
        }
    }
}

/// `[sea.swell]`: a narrow JONSWAP swell of given height and period.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SwellConfig {
    /// Significant wave height `H_s = 4√m₀` (m, `(0, 20]`).
    pub significant_height_m: f64,
    /// Peak period (s, `[4, 30]`).
    pub peak_period_s: f64,
    /// Direction the swell travels toward (°, from +x toward +z).
    pub direction_deg: f64,
    /// Number of waves (`[1, 1000]`).
    pub waves: u32,
    /// Exponent `s` of its cos-2s spreading (`[1, 200]`; larger is narrower).
    pub spreading_s: f64,
    /// Peak enhancement `γ` (`[1, 10]`).
    pub gamma: f64,
}

impl Default for SwellConfig {
    fn default() -> Self {
        Self {
            significant_height_m: 1.0,
            peak_period_s: 12.0,
            direction_deg: 0.0,
            waves: 12,
            spreading_s: 40.0,
            gamma: 3.3,
        }
    }
}

/// `[sky]`: atmosphere, sun (when there is no `[place]`) and clouds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SkyConfig {
    /// Atmospheric turbidity `T` (`[1.7, 10]`).
    pub turbidity: f64,
    /// Sun elevation (°, `[−90, 90]`); only without `[place]` (default 24°).
    pub sun_elevation_deg: Option<f64>,
    /// Sun azimuth as a compass bearing (°, 0 north, 90 east); only without `[place]` (default 115°).
    pub sun_azimuth_deg: Option<f64>,
    /// Cloud layers; a clear sky when absent.
    pub clouds: Option<CloudConfig>,
    /// The clear daylight sky's model.
    pub model: SkyModelKind,
}

impl Default for SkyConfig {
    fn default() -> Self {
        Self {
            turbidity: 3.0,
            sun_elevation_deg: None,
            sun_azimuth_deg: None,
            clouds: None,
            model: SkyModelKind::Preetham,
        }
    }
}

/// The analytic clear-sky model of `[sky] model`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum SkyModelKind {
    /// Preetham, Shirley & Smits 1999 (the papers' sky).
    #[default]
    Preetham,
    /// Hosek & Wilkie 2012.
    HosekWilkie,
}

impl SkyConfig {
    /// Sun elevation used without `[place]` (°).
    pub const DEFAULT_SUN_ELEVATION_DEG: f64 = 24.0;
    /// Sun azimuth used without `[place]` (°).
    pub const DEFAULT_SUN_AZIMUTH_DEG: f64 = 115.0;
}

/// `[sky.clouds]`: procedural cloud layers after Chen et al. 2007 (brine-sky).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CloudConfig {
    /// Fraction of the sky covered (`[0, 1]`).
    pub cover: f64,
    /// Altitude of the cloud base (m, `(0, 20000]`).
    pub altitude_m: f64,
    /// Size of the largest cloud features (m, `[10, 10⁶]`).
    pub scale_m: f64,
    /// Wind carrying the clouds, `[east, south]` (m/s, each `[−100, 100]`).
    pub wind_m_s: [f64; 2],
    /// Seed of the cloud noise.
    pub seed: u64,
}

impl Default for CloudConfig {
    fn default() -> Self {
        Self { cover: 0.4, altitude_m: 2000.0, scale_m: 4000.0, wind_m_s: [8.0, 0.0], seed: 1 }
    }
}

/// `[output]`: where and how the image is written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct OutputConfig {
    /// Output file; `.png` (8-bit sRGB, tone-mapped) or `.exr` (linear f32 radiance).
    pub path: PathBuf,
    /// Manual exposure as EV₁₀₀ (`[−10, 30]`): the luminance mapped to white before the tone
    /// curve is `1.2 · 2^EV` cd m⁻² (saturation-based exposure, ISO 12232). Automatic when absent.
    pub exposure_ev: Option<f64>,
    /// Exposure compensation of the automatic exposure (EV, `[−10, 10]`; positive is brighter).
    /// The automatic exposure meters the frame's log-average luminance (ISO 2720 reflected-light
    /// calibration) and darkens twilight and night (see `auto_exposure_ev`).
    pub exposure_compensation_ev: f64,
    /// Write the output variables (depth, normal, foam, whitecap, evaluations) as extra EXR
    /// channels (`.exr` only).
    pub aovs: bool,
}

impl Default for OutputConfig {
    fn default() -> Self {
        Self { path: PathBuf::from("ocean.png"), exposure_ev: None, exposure_compensation_ev: 0.0, aovs: false }
    }
}

impl Scene {
    /// The embedded default scene.
    pub fn default_scene() -> Self {
        Self::from_toml_str(DEFAULT_SCENE_TOML, DEFAULT_SCENE_NAME).expect("the embedded default scene is valid")
    }

    /// Reads and checks a scene file.
    ///
    /// # Errors
    /// [`SceneError`] if the file cannot be read, is not UTF-8 (with the line of the first bad
    /// byte), is not valid TOML, has an unknown key or a value of the wrong type, or a value out of
    /// range.
    pub fn load(path: &Path) -> Result<Self, SceneError> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| SceneError {
            file: name.clone(),
            line: None,
            message: format!("cannot read the scene file: {e}"),
        })?;
        let text = match String::from_utf8(bytes) {
            Ok(t) => t,
            Err(e) => {
                let at = e.utf8_error().valid_up_to();
                let bytes = e.as_bytes();
                let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
                return Err(SceneError {
                    file: name,
                    line: Some(line),
                    message: format!(
                        "the scene file is not UTF-8 text: byte {at} (0x{:02x}) is not valid UTF-8 (save the file as UTF-8)",
                        bytes[at]
                    ),
                });
            }
        };
        Self::from_toml_str(&text, &name)
    }

    /// Parses and checks a scene from TOML text; `file` names it in messages.
    ///
    /// Every key is checked against the key table ([`keys::KEYS`]: type, range, array length)
    /// on the parsed document, then the keys that constrain each other. Messages carry the line
    /// of the key, whether it is written under a header, dotted, quoted or in an inline table.
    ///
    /// # Errors
    /// See [`Scene::load`].
    pub fn from_toml_str(text: &str, file: &str) -> Result<Self, SceneError> {
        // A UTF-8 byte-order mark (some Windows editors write one) is not part of the TOML.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let error = |at: Option<usize>, message: String| SceneError {
            file: file.to_owned(),
            line: at.map(|a| line_of(text, a)),
            message,
        };
        let doc = check::Located::parse(text).map_err(|(at, m)| error(at, m))?;
        doc.check().map_err(|(at, m)| error(at, m))?;
        let de = toml::de::Deserializer::parse(text)
            .map_err(|e| error(e.span().map(|s| s.start), format!("invalid TOML: {}", e.message().trim())))?;
        let scene: Scene = serde_path_to_error::deserialize(de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            error(inner.span().map(|s| s.start), explain(&path, inner.message()))
        })?;
        scene.validate().map_err(|(path, message)| error(doc.offset_of(path), message))?;
        Ok(scene)
    }

    /// The 1-based line of the key `path` (dotted, `output.aovs`) in the scene text `text`, when
    /// the text sets it: for messages about a scene once it is loaded.
    pub fn line_of_key(text: &str, path: &str) -> Option<usize> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        check::Located::parse(text).ok()?.offset_of(path).map(|at| line_of(text, at))
    }

    /// The camera's view when neither `look_at` nor the angles are given: yaw 100°, pitch −9°.
    pub const DEFAULT_YAW_DEG: f64 = 100.0;
    /// See [`Scene::DEFAULT_YAW_DEG`].
    pub const DEFAULT_PITCH_DEG: f64 = -9.0;

    /// Checks the output against the scene once the command line has set its path: AOVs need an
    /// EXR file.
    ///
    /// # Errors
    /// A message naming `output.aovs` and the path.
    pub fn check_output(&self) -> Result<(), String> {
        let format = crate::output::OutputFormat::from_path(&self.output.path)?;
        if self.output.aovs && format != crate::output::OutputFormat::Exr {
            return Err(format!(
                "output.aovs = true needs an .exr output, but the output is {} (PNG has no extra channels)",
                self.output.path.display()
            ));
        }
        Ok(())
    }

    /// Checks the constraints between keys (each key's own type and range are the key table's,
    /// checked before); the error names the key (dotted path) whose line is shown.
    fn validate(&self) -> Result<(), (&'static str, String)> {
        let c = &self.camera;
        if c.look_at.is_some() && (c.yaw_deg.is_some() || c.pitch_deg.is_some()) {
            return Err((
                "camera.look_at",
                "camera.look_at cannot be combined with yaw_deg/pitch_deg: give one or the other".into(),
            ));
        }
        if let Some(t) = c.look_at {
            let d = [t[0] - c.position[0], t[1] - c.position[1], t[2] - c.position[2]];
            let len2: f64 = d.iter().map(|x| x * x).sum();
            if !(len2 > 1e-12) || !len2.is_finite() {
                return Err(("camera.look_at", "camera.look_at must differ from camera.position".into()));
            }
        }
        let s = &self.sea;
        if s.spectrum == SpectrumKind::Tma && s.depth_m.is_none() {
            return Err(("sea.spectrum", "sea.spectrum = \"tma\" needs sea.depth_m (the water depth, m)".into()));
        }
        if let Some(w) = &s.swell {
            // A deep-water swell steeper than H_s/L = 1/7 (Michell's limit of a single wave, with
            // L = g T²/2π) cannot exist.
            let (h, t) = (w.significant_height_m, w.peak_period_s);
            let limit = brine_waves::G * t * t / std::f64::consts::TAU / 7.0;
            if h > limit {
                return Err((
                    "sea.swell.significant_height_m",
                    format!(
                        "sea.swell.significant_height_m = {h} is out of range: expected at most {limit:.2} m for a {t} s swell (H/L ≤ 1/7)"
                    ),
                ));
            }
        }
        let k = &self.sky;
        if self.place.is_some() && (k.sun_elevation_deg.is_some() || k.sun_azimuth_deg.is_some()) {
            let key = if k.sun_elevation_deg.is_some() { "sun_elevation_deg" } else { "sun_azimuth_deg" };
            let path = if k.sun_elevation_deg.is_some() { "sky.sun_elevation_deg" } else { "sky.sun_azimuth_deg" };
            return Err((
                path,
                format!("sky.{key} cannot be combined with [place], which sets the sun: give one or the other"),
            ));
        }
        let w = &self.water;
        if w.water_type.is_some() && w.chlorophyll_mg_m3.is_some() {
            return Err((
                "water.chlorophyll_mg_m3",
                "water.type and water.chlorophyll_mg_m3 exclude each other: give one".into(),
            ));
        }
        if let (Some(tw), Some(ta)) = (w.temperature_c, w.air_temperature_c) {
            // Monahan & Ó Muircheartaigh 1986's stability fit covers ΔT = T_w − T_a in [−30, 30] °C.
            // The difference of two decimal inputs carries their rounding (12.7 − 42.7 is
            // −30.000000000000004): it is compared with that much room.
            let dt = tw - ta;
            if dt.abs() > MAX_STABILITY_DIFFERENCE_C + DECIMAL_ROUNDING_C {
                return Err((
                    "water.air_temperature_c",
                    format!(
                        "water.air_temperature_c = {ta} is out of range: expected a water–air difference within ±30 °C (Monahan 1986's fit), got {:.3} °C",
                        dt
                    ),
                ));
            }
        }
        if let Some(f) = &w.floor {
            if f.amplitude_m > 0.5 * f.depth_m {
                return Err((
                    "water.floor.amplitude_m",
                    format!(
                        "water.floor.amplitude_m = {} is out of range: expected [0, depth_m/2] = [0, {}] m",
                        f.amplitude_m,
                        0.5 * f.depth_m
                    ),
                ));
            }
            let [lo, hi] = f.wavelength_range_m;
            if lo > hi {
                return Err((
                    "water.floor.wavelength_range_m",
                    format!(
                        "water.floor.wavelength_range_m = [{lo}, {hi}]: the shortest wavelength must come first (min ≤ max)"
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// Widest water–air temperature difference of Monahan & Ó Muircheartaigh 1986's stability fit (°C).
const MAX_STABILITY_DIFFERENCE_C: f64 = 30.0;

/// Room for the rounding of a difference of two temperatures written with a few decimals (°C):
/// far below any physical meaning, far above f64 rounding of values within ±50 °C (10⁻¹⁴).
const DECIMAL_ROUNDING_C: f64 = 1e-9;

/// 1-based line of byte offset `at` in `text`.
fn line_of(text: &str, at: usize) -> usize {
    text.as_bytes()[..at.min(text.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// Rewrites serde's messages into what the user should have written, naming the key.
fn explain(path: &str, message: &str) -> String {
    let message = message.trim();
    let found = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
        .and_then(|m| m.split_once(", expected "));
    if let Some((found, expected)) = found {
        let what = match expected {
            "f64" | "f32" => "a number".to_owned(),
            "u8" | "u16" | "u32" | "u64" | "usize" => "a non-negative whole number".to_owned(),
            "i32" | "i64" => "a whole number".to_owned(),
            "a boolean" => "true or false".to_owned(),
            e if e.starts_with("an array of length") || e.starts_with("a sequence") || e.starts_with("a tuple") => {
                format!("an array ({e})")
            }
            e => e.to_owned(),
        };
        return format!("expected {what} for {path}, found {found}");
    }
    if let Some(rest) = message.strip_prefix("unknown field ") {
        let (name, expected) = rest.split_once(", expected ").unwrap_or((rest, ""));
        let name = name.trim_matches('`');
        let key = if path.is_empty() || path == "." {
            name.to_owned()
        } else if path == name || path.ends_with(&format!(".{name}")) {
            path.to_owned()
        } else {
            format!("{path}.{name}")
        };
        return format!("unknown key {key} (expected {})", expected.replace('`', ""));
    }
    if let Some(rest) = message.strip_prefix("unknown variant ") {
        return format!("unknown value {} for {path}", rest.replace('`', ""));
    }
    format!("{path}: {message}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_embedded_scene_sets_a_place_and_the_rest_is_default() {
        let mut s = Scene::default_scene();
        assert!(s.place.is_some());
        s.place = None;
        // The file writes out the view and the water type that are also the defaults when absent.
        assert_eq!(
            (s.camera.yaw_deg, s.camera.pitch_deg, s.water.water_type.as_deref()),
            (Some(Scene::DEFAULT_YAW_DEG), Some(Scene::DEFAULT_PITCH_DEG), Some("IB"))
        );
        (s.camera.yaw_deg, s.camera.pitch_deg, s.water.water_type) = (None, None, None);
        assert_eq!(s, Scene::default());
    }

    #[test]
    fn sun_angles_and_place_exclude_each_other() {
        let e = Scene::from_toml_str(
            "[place]\nlatitude_deg = 43.0\nlongitude_deg = 5.0\ntime_utc = \"2024-06-21T12:00:00Z\"\n[sky]\nsun_elevation_deg = 20.0\n",
            "s.toml",
        )
        .unwrap_err();
        assert!(e.message.contains("cannot be combined with [place]"), "{e}");
        assert_eq!(e.line, Some(6));
        let e = Scene::from_toml_str(
            "[place]\nlatitude_deg = 43.0\nlongitude_deg = 5.0\ntime_utc = \"yesterday\"\n",
            "s.toml",
        )
        .unwrap_err();
        assert!(e.message.starts_with("place.time_utc:"), "{e}");
        assert_eq!(e.line, Some(4));
    }

    #[test]
    fn wrong_type_names_the_key_and_line() {
        let e = Scene::from_toml_str("[camera]\nwidth = 100\nfov_deg = \"wide\"\n", "s.toml").unwrap_err();
        assert_eq!(e.line, Some(3));
        assert!(e.message.contains("expected a number for camera.fov_deg"), "{e}");
        assert!(e.to_string().starts_with("s.toml line 3: "), "{e}");
    }

    #[test]
    fn unknown_key_is_an_error() {
        let e = Scene::from_toml_str("[sea]\nwind = 3.0\n", "s.toml").unwrap_err();
        assert!(e.message.starts_with("unknown key sea.wind (expected one of"), "{e}");
        assert_eq!(e.line, Some(2));
    }

    #[test]
    fn out_of_range_values_are_errors_with_lines() {
        let e = Scene::from_toml_str("[sea]\n\nwind_speed_m_s = -1.0\n", "s.toml").unwrap_err();
        assert_eq!(e.line, Some(3));
        assert!(e.message.contains("sea.wind_speed_m_s = -1 is out of range"), "{e}");
        let e = Scene::from_toml_str("[camera]\nfov_deg = 180.0\n", "s.toml").unwrap_err();
        assert!(e.message.contains("camera.fov_deg"), "{e}");
        let e = Scene::from_toml_str("[camera]\nwidth = 0\n", "s.toml").unwrap_err();
        assert!(e.message.contains("camera.width"), "{e}");
    }

    fn parse(text: &str) -> Result<Scene, SceneError> {
        Scene::from_toml_str(text, "s.toml")
    }

    #[test]
    fn look_at_alone_is_accepted_and_with_an_angle_refused() {
        let s = parse("[camera]\nlook_at = [100.0, 0.0, 0.0]\n").unwrap();
        assert_eq!((s.camera.look_at, s.camera.yaw_deg, s.camera.pitch_deg), (Some([100.0, 0.0, 0.0]), None, None));
        let e = parse("[camera]\nlook_at = [100.0, 0.0, 0.0]\npitch_deg = -3.0\n").unwrap_err();
        assert!(e.message.contains("cannot be combined"), "{e}");
        assert_eq!(e.line, Some(2));
        // Without look_at and angles the default view is unchanged.
        let cam = crate::camera::from_config(&Scene::default().camera);
        let want = crate::camera::direction_from_bearing(Scene::DEFAULT_YAW_DEG, Scene::DEFAULT_PITCH_DEG);
        assert!((cam.forward - want).length() < 1e-12);
    }

    #[test]
    fn chlorophyll_alone_is_accepted_and_with_a_type_refused() {
        let s = parse("[water]\nchlorophyll_mg_m3 = 1.0\n").unwrap();
        assert_eq!((s.water.water_type.as_deref(), s.water.chlorophyll_mg_m3), (None, Some(1.0)));
        let e = parse("[water]\ntype = \"II\"\nchlorophyll_mg_m3 = 1.0\n").unwrap_err();
        assert!(e.message.contains("exclude each other"), "{e}");
        assert_eq!(e.line, Some(3));
    }

    #[test]
    fn the_documented_ends_of_ranges_are_accepted() {
        // Fetches up to 10⁵ km, the year 2200, 30 °C between water and air written in decimals.
        parse("[sea]\nspectrum = \"jonswap\"\nfetch_km = 100000.0\n").unwrap();
        parse("[place]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\ntime_utc = \"2200-12-31T23:59:59Z\"\n").unwrap();
        parse("[water]\ntemperature_c = 12.7\nair_temperature_c = 42.7\n").unwrap();
        let e = parse("[water]\ntemperature_c = 12.7\nair_temperature_c = 42.8\n").unwrap_err();
        assert!(e.message.contains("water.air_temperature_c"), "{e}");
        let e = parse("[place]\nlatitude_deg = 0.0\nlongitude_deg = 0.0\ntime_utc = \"2201-01-01T00:00:00Z\"\n")
            .unwrap_err();
        assert!(e.message.contains("1800–2200") && e.line == Some(4), "{e}");
    }

    #[test]
    fn arrays_must_have_their_length() {
        let e = parse("[camera]\nposition = [0.0, 10.0, 0.0, 1.0]\n").unwrap_err();
        assert!(e.message.contains("camera.position has 4 elements"), "{e}");
        assert_eq!(e.line, Some(2));
        let e = parse("[sky.clouds]\nwind_m_s = [1.0, 2.0, 3.0]\n").unwrap_err();
        assert!(e.message.contains("sky.clouds.wind_m_s has 3 elements"), "{e}");
        let e = parse("[water.floor]\nalbedo = [0.5, 0.5]\n").unwrap_err();
        assert!(e.message.contains("water.floor.albedo has 2 elements"), "{e}");
    }

    #[test]
    fn range_errors_keep_their_line_in_every_form_of_key() {
        let forms = [
            ("sea.wind_speed_m_s = 70.0\n", 1),
            ("sea = { wind_speed_m_s = 70.0 }\n", 1),
            ("[sea]\n\"wind_speed_m_s\" = 70.0\n", 2),
            ("[sea] # the sea\nwind_speed_m_s = 70.0\n", 2),
            ("\u{feff}[sea]\nwind_speed_m_s = 70.0\n", 2),
            ("[camera]\nwidth = 10\n[sea]\nseed = 3\n\n  wind_speed_m_s   =   70.0 # gale\n", 6),
        ];
        for (text, line) in forms {
            let e = parse(text).unwrap_err();
            assert!(e.message.contains("sea.wind_speed_m_s = 70 is out of range"), "{text:?}: {e}");
            assert_eq!(e.line, Some(line), "{text:?}: {e}");
        }
        let e = parse("[[sea]]\nwind_speed_m_s = 7.0\n").unwrap_err();
        assert!(e.message.contains("not as an array of tables [[sea]]"), "{e}");
        assert_eq!(e.line, Some(1));
    }

    #[test]
    fn a_file_that_is_not_utf8_gets_the_line_of_its_first_bad_byte() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("latin1.toml");
        std::fs::write(&path, b"[sea]\n# caf\xe9\nwind_speed_m_s = 7.0\n").unwrap();
        let e = Scene::load(&path).unwrap_err();
        assert_eq!(e.line, Some(2), "{e}");
        assert!(e.message.contains("not UTF-8"), "{e}");
    }

    #[test]
    fn aovs_are_checked_against_the_final_output_path() {
        let mut s = parse("[output]\naovs = true\n").unwrap();
        assert!(s.check_output().unwrap_err().contains("output.aovs"));
        s.output.path = "x.exr".into();
        s.check_output().unwrap();
    }
}
