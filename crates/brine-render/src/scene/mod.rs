//! The scene file: TOML, every key optional, unknown keys rejected, every value range-checked.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

mod check;
pub mod keys;
mod load;

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

/// Whether the trochoid sea's shorter waves are traced on grids (brine-waves
/// `GriddedTrochoids`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum GridMode {
    /// On grids from [`GRID_AUTO_WAVES`] waves up, where they pay (the default).
    #[default]
    Auto,
    /// On grids whatever the number of waves (an error if the set cannot be split).
    On,
    /// Every wave traced as a trochoid.
    Off,
}

/// The wave count from which `grid = "auto"` traces the trochoid sea's shorter waves on grids:
/// below it, the grids' fixed cost is not repaid (`cargo xtask bench wave-count`).
pub const GRID_AUTO_WAVES: u32 = 150;

/// The trochoid sea's wave count when `sea.waves` is not given. With 50 waves a handful of short
/// waves crossing at the spreading angles holds most of the glitter's slopes, a lattice of glints:
/// on a top-down view at 8 m/s the 20 strongest wave vectors hold 0.37–0.42 of the slope power
/// (five seeds), against 0.25–0.31 with 150. From
/// 150 waves the shorter ones are traced on grids ([`GRID_AUTO_WAVES`]), so the frame costs about
/// 1.4 times the 50-wave one (the default scene, `docs/benchmarks.md`).
pub const DEFAULT_TROCHOID_WAVES: u32 = 150;
const _: () = assert!(DEFAULT_TROCHOID_WAVES >= GRID_AUTO_WAVES, "the default sea is traced on grids");

/// The Gerstner and sine seas' wave count when `sea.waves` is not given: they are traced wave by
/// wave (a Gerstner frame of 150 waves takes about four times one of 50).
pub const DEFAULT_WAVES: u32 = 50;

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
    /// Wind speed 10 m above the sea, `U₁₀` (m s⁻¹, `[0, 60]`; 0 is a flat calm, as is a wind too light
    /// to raise waves a millimetre long, under about 0.02 m/s).
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
    /// Number of waves of the wind sea (`[0, 10000]`); `None`: the surface's default
    /// ([`SeaConfig::wave_count`]).
    pub waves: Option<u32>,
    /// Choppiness of the fit (`[0, 100]`): each wave's steepness is `c·kA` before the cap.
    pub choppiness: f64,
    /// Whether the trochoid sea's shorter waves are snapped to tiles and traced on grids.
    pub grid: GridMode,
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
    /// Read every cascade through a tile and blend (brine-waves `TileBlend`, default `true`), so
    /// that the sea does not repeat with the cascades' tiles; `false` reads the periodic tiles,
    /// about 2.3× faster and visibly repeating in aerial views.
    pub blend: bool,
}

impl Default for FftConfig {
    fn default() -> Self {
        Self { resolution: 256, cascades: 4, choppiness: 1.0, loop_period_s: None, blend: true }
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
            waves: None,
            choppiness: 2.5,
            grid: GridMode::Auto,
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

impl SeaConfig {
    /// The number of waves of the wind sea: `sea.waves`, or the surface's default,
    /// [`DEFAULT_TROCHOID_WAVES`] for trochoids and [`DEFAULT_WAVES`] for the Gerstner and sine
    /// seas (the FFT sea does not use it).
    pub fn wave_count(&self) -> u32 {
        self.waves.unwrap_or(match self.surface {
            SurfaceKind::Trochoids => DEFAULT_TROCHOID_WAVES,
            _ => DEFAULT_WAVES,
        })
    }
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
    /// The white the image is balanced to.
    pub white_balance: WhiteBalance,
}

/// The white balance of `[output] white_balance`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum WhiteBalance {
    /// None: the scene's radiance shown as it is on a D65 display, a warm low sun warm.
    #[default]
    None,
    /// The scene's light shown as white: the image adapted (Bradford) from the colour of the
    /// irradiance of sun, moon and sky on a level surface (the sun and moon through the clouds'
    /// mean shadow) to D65, as a white card lying on the sea would show it.
    Scene,
    /// The image's mean colour shown as grey ("grey world"), as a camera's automatic white
    /// balance does: the frame adapted (Bradford) from the mean of its pixels, each clipped at
    /// the exposure's white, to D65.
    Image,
}

impl Default for OutputConfig {
    fn default() -> Self {
        Self {
            path: PathBuf::from("ocean.png"),
            exposure_ev: None,
            exposure_compensation_ev: 0.0,
            aovs: false,
            white_balance: WhiteBalance::None,
        }
    }
}

#[cfg(test)]
mod tests;
