//! A scene turned into models: the fitted sea, the sky and sun, the slope statistics.

use brine_ephem::{Atmosphere, Observer, Options as EphemOptions, SunModel, moon_position, parse_utc, sun_position};
use brine_foam::{
    CoverageParams, DARLES_ONSET_WIND_M_S, FoamExtension, FoamExtensionParams, FoamPoint, KoepkeFoam, SprayMedium,
    SprayParams, SurfaceStatistics, WhiteWater, WhitecapLaw,
};
use brine_optics::{
    DipoleMaterial, RgbBands, RoughReflectance, SlopeVariance, SunDisc, WATER_IOR, WaterBody, WaterRgb,
    fresnel_dielectric, hemispherical_fresnel_reflectance,
};
use brine_sky::{CloudParams, DaylightModel, FilteredSky, MoonParams, Sky, SkyParams};
use brine_trace::{Method, TraceOptions};
use brine_waves::{
    BOX_WIDTH_PER_SIGMA, BandLimited, BandedTrochoids, CosineSquared, CosineTwoS, DetailOptions, DetailSlopes,
    DetailWaves, Directions, DonelanBanner, Elfouhaily, EllipticalFootprint, FftOcean, FftOptions, FftSlopeFilter,
    FitOptions, FrameSurface, GriddedTrochoids, Jonswap, LoopDistortion, Ocean, Phillips, PiersonMoskowitz,
    SeaComponent, SeaFrame, SeabedRelief, Spectrum, Spreading, SteepnessLimit, SummedSpectrum, TileLattice, Tma,
    TracedSea, TrochoidSet, TrochoidSum, fit_sea_state, seabed_relief,
};
use brine_whitecap::{
    Calibration, CalibrationOptions, ErfMethod, FftBreaking, FftCalibration, FftJacobianStatistics, FootprintFilter,
    JacobianStatistics, TrochoidBreaking, WhiteWaterModel, whitecap_coverage,
};
use glam::{DVec2, DVec3};

use crate::camera::{Camera, direction_from_bearing};

mod sea;
mod spray;
mod timeless;
mod white_water;

use crate::scene::{
    FloorConfig, GridMode, Scene, SeaConfig, SkyConfig, SkyModelKind, SpectrumKind, SpreadingKind, SunModelKind,
    SwellConfig,
};
use sea::{SeaSpectra, sea_spectra, sea_statistics};
pub use timeless::Timeless;
pub(crate) use white_water::EDGE_SHARE;
use white_water::monahan_coverage;
pub use white_water::{ACTIVE_WHITECAP_SHARE, Foam, WhiteWaterSea, Whitecaps};

/// Why a scene could not be turned into models: the model that refused, with its message.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    /// The waves (spectra, fit, surfaces, FFT sea).
    #[error(transparent)]
    Waves(#[from] brine_waves::WaveError),
    /// Foam, spray and the foam memory.
    #[error(transparent)]
    Foam(#[from] brine_foam::FoamError),
    /// Whitecaps and white water.
    #[error(transparent)]
    Whitecap(#[from] brine_whitecap::WhitecapError),
    /// Water optics, the BRDF and the crest dipole.
    #[error(transparent)]
    Optics(#[from] brine_optics::OpticsError),
    /// The sky, sun and clouds.
    #[error(transparent)]
    Sky(#[from] brine_sky::SkyError),
    /// The sun's and moon's positions.
    #[error(transparent)]
    Ephem(#[from] brine_ephem::EphemError),
    /// A scene value the models accept but cannot use here (with the key it came from).
    #[error("{0}")]
    Scene(String),
}

/// Everything the per-pixel shading needs, built once per frame.
pub struct World {
    /// The fitted wave set.
    pub(crate) set: TrochoidSet,
    /// How far the tile lattice's loop period moved the waves from their dispersion relation
    /// (a world built on a lattice with a loop period only).
    loop_distortion: Option<LoopDistortion>,
    /// The sea of the scene as a model of time (brine-waves `Ocean`): what bakes, meshes and
    /// queries freeze at other instants.
    pub(crate) ocean: Ocean,
    /// The traced surface at the frame's time (brine-waves `SeaFrame`).
    pub(crate) sea: SeaFrame,
    /// The trochoid sea with its shorter waves on grids at the frame's time, if `sea.grid` puts
    /// them there (brine-waves `GriddedTrochoids`): what the rays meet; `sea` holds the snapped
    /// waves it stands for.
    pub(crate) gridded: Option<GriddedTrochoids>,
    /// The split those grids are filled from, for other instants ([`World::with_traced_sea_at`]).
    banded: Option<BandedTrochoids>,
    /// Time of the frame (s).
    pub(crate) time: f64,
    /// Sky, sun, moon, clouds and aerial perspective, for any sun elevation.
    pub(crate) sky: Sky,
    /// The sky with its clouds prefiltered by angular Gaussians: what the rough sea reflects
    /// (brine-sky `FilteredSky`).
    pub(crate) filtered_sky: FilteredSky,
    /// Aerial perspective between the eye and the sea is on.
    pub(crate) aerial_perspective: bool,
    /// Unit horizontal wind direction (the BRDF's x axis).
    pub(crate) wind: DVec3,
    /// Slope variances of the waves drawn neither as geometry nor as detail normals (Cox–Munk
    /// total minus the fitted set and the detail band).
    pub(crate) variance_unresolved: SlopeVariance,
    /// The detail normals of a trochoid, Gerstner or sine sea: the spectrum's waves between the
    /// traced band and the 1 cm wave, read at the hit through the pixel footprint (brine-waves
    /// `DetailWaves`); `None` for the FFT sea (its cascades already reach that far) and a calm.
    pub(crate) detail: Option<DetailSlopes>,
    /// The FFT sea's slopes mip-mapped for footprint reads (LEAN mapping): the mean shading
    /// gradient over each pixel and the slopes the pixel hides, for the BRDF.
    pub(crate) fft_slopes: Option<FftSlopeFilter>,
    /// Slope variances of the whole sea (Cox–Munk), used beyond the trace distance.
    pub(crate) variance_total: SlopeVariance,
    /// Optical properties of the water per channel.
    pub(crate) water: WaterRgb,
    /// Downwelling irradiance just below a flat surface, `E_d(0⁻)` (klx per channel).
    pub(crate) e_below: DVec3,
    /// The sun's (and moon's) share of `e_below` (klx per channel), arriving along
    /// [`World::sun_below`].
    pub(crate) e_below_direct: DVec3,
    /// The sun's share of `e_below_direct` (the rest is the moon's).
    pub(crate) e_below_sun: DVec3,
    /// Unit direction of the sun's light refracted into the water (pointing down); straight down
    /// when the sun has set.
    pub(crate) sun_below: DVec3,
    /// The sea floor, if the water is not deep.
    pub(crate) floor: Option<Floor>,
    /// `true` when the camera is below the sea surface.
    pub(crate) underwater: bool,
    /// Foam on crests, when on and the wind makes any.
    pub(crate) foam: Option<Foam>,
    /// Active whitecaps, when on alone (or with a raw threshold) and the wind makes any.
    pub(crate) whitecaps: Option<Whitecaps>,
    /// Active whitecaps with the foam they leave, when foam and whitecaps are both on.
    pub(crate) white_water: Option<WhiteWaterSea>,
    /// The spray (bubble drops, spume and the light they scatter), when on.
    pub(crate) spray: Option<spray::Spray>,
    /// Dipole materials of the water per channel (R, G, B) for light through thin crests, when
    /// sub-surface scattering is on.
    pub(crate) crest: Option<[DipoleMaterial; 3]>,
    /// Quadrature rules over the sun's and the moon's discs, for glints on calm water
    /// (brine-optics `reflected_disc_radiance`).
    pub(crate) discs: (SunDisc, Option<SunDisc>),
    /// Options of the tracer.
    pub(crate) trace: TraceOptions,
    /// The camera.
    pub(crate) camera: Camera,
    /// Manual exposure (EV₁₀₀), or `None` for automatic.
    pub(crate) exposure_ev: Option<f64>,
    /// Compensation of the automatic exposure (EV, positive is brighter).
    pub(crate) exposure_compensation_ev: f64,
    /// Horizontal illuminance of sun, moon and sky at sea level (lx).
    pub(crate) illuminance_lx: f64,
    /// The white balance applied to the frame (linear sRGB to linear sRGB) for
    /// `[output] white_balance = "scene"`, when the light is one it can adapt to.
    pub(crate) white_balance: Option<glam::DMat3>,
    /// `[output] white_balance`.
    pub(crate) white_balance_mode: crate::scene::WhiteBalance,
    /// Side of the square of sea over which the scene light averages the clouds' shadow (m).
    pub(crate) white_balance_span_m: f64,
    /// The reference rendering: no wave faded with the pixel footprint, no normal read through
    /// it (the slopes a footprint would hide stay in the normals, for many samples per pixel to
    /// average), so that a supersampled frame shows what the filtering is meant to preserve.
    pub(crate) reference: bool,
    /// The share of the pixel's angle one sample's footprint covers,
    /// `max(1/8, 1/√spp)` ([`sample_footprint_scale`]).
    pub(crate) sample_scale: f64,
}

/// What a caller outside the renderer reads of a world; the rest is the renderer's own.
impl World {
    /// The trochoid set fitted to the sea's spectrum (empty for the FFT sea, whose waves are its
    /// cascades).
    pub fn fitted_set(&self) -> &TrochoidSet {
        &self.set
    }

    /// How far a loop period (the FFT sea's `sea.fft.loop_period_s`, or the tile lattice's of a
    /// bake) moved the sea's waves from their dispersion relation; `None` without a loop.
    pub fn loop_distortion(&self) -> Option<&LoopDistortion> {
        self.loop_distortion.as_ref()
    }

    /// The sea as a model of time (bakes and animations take frames from it).
    pub fn ocean(&self) -> &Ocean {
        &self.ocean
    }

    /// The sea frozen at the world's time: the surface that is traced and queried.
    pub fn sea(&self) -> &SeaFrame {
        &self.sea
    }

    /// The sea at the world's time ready to trace: through its grids where the shorter waves are
    /// on grids (brine-waves `TracedSea::Gridded`), else the frame itself.
    ///
    /// # Returns
    /// What the renderer traces its rays through (and shades at their hits).
    pub fn traced_sea(&self) -> TracedSea<'_> {
        match &self.gridded {
            Some(grid) => self.sea.traced_through(grid),
            None => self.sea.traced(),
        }
    }

    /// Runs `f` on the sea at time `t` (s) and on it ready to trace ([`World::traced_sea`]): the
    /// world's own at its time, else the ocean frozen at `t` (its grids filled at `t` where the
    /// shorter waves are on grids), made for the call.
    pub fn with_traced_sea_at<R>(&self, t: f64, f: impl FnOnce(&SeaFrame, &TracedSea<'_>) -> R) -> R {
        if t.to_bits() == self.time.to_bits() {
            return f(&self.sea, &self.traced_sea());
        }
        let frame = self.ocean.at_time(t);
        match &self.banded {
            Some(b) => {
                let grid = GriddedTrochoids::at_time(b, t);
                f(&frame, &frame.traced_through(&grid))
            }
            None => f(&frame, &frame.traced()),
        }
    }

    /// Runs `f` on the sea at time `t` (s): the world's own frame at its time, else the ocean
    /// frozen at `t` (`Ocean::at_time`), made for the call.
    pub fn with_sea_at<R>(&self, t: f64, f: impl FnOnce(&SeaFrame) -> R) -> R {
        if t.to_bits() == self.time.to_bits() { f(&self.sea) } else { f(&self.ocean.at_time(t)) }
    }

    /// The world's time (s, on the scene's clock).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The sky model (sun, moon, sky radiance).
    pub fn sky(&self) -> &Sky {
        &self.sky
    }

    /// The sky dome prefiltered for reflections through the sea's roughness.
    pub fn filtered_sky(&self) -> &FilteredSky {
        &self.filtered_sky
    }

    /// Where the sky's clouds are seen from: the horizontal position `(x, z)` (m) of the camera
    /// the world was built for; `None` without clouds (or with a cover of 0, which draws none).
    pub fn cloud_origin(&self) -> Option<DVec2> {
        self.sky.clouds().filter(|c| c.params().cover > 0.0).map(|c| c.params().origin_m)
    }

    /// The camera.
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The slope variance (wind frame) of the waves not drawn, which the BRDF carries.
    pub fn variance_unresolved(&self) -> &SlopeVariance {
        &self.variance_unresolved
    }

    /// The meteorological visibility through the spray at height `z` above the sea,
    /// `ln 50 / k(z)` (m; Koschmieder), bubble drops and spume together, when the scene has spray.
    pub fn spray_visibility_m(&self, z: f64) -> Option<f64> {
        self.spray.as_ref().map(|s| {
            let k = s.medium.extinction(z, 1.0) + s.spume.extinction(z);
            if k > 0.0 { 50f64.ln() / k } else { f64::INFINITY }
        })
    }

    /// The white water (foam memory and whitecaps), when the scene has it.
    pub fn white_water(&self) -> Option<&WhiteWaterSea> {
        self.white_water.as_ref()
    }

    /// Whether this world renders as the reference (nothing faded or filtered with the pixel
    /// footprint; `brine render --reference`).
    pub fn reference(&self) -> bool {
        self.reference
    }

    /// Renders this world as the reference (`true`) or as the filtered frame (`false`).
    pub fn set_reference(&mut self, reference: bool) {
        self.reference = reference;
    }

    /// The same world seen through another camera: what a camera move changes (the camera,
    /// whether it is under the sea, the samples' footprint for its samples per pixel); the sea,
    /// the sky and the white water stay. The world is then the one [`World::new`] builds for the
    /// scene with that camera, but for the clouds: the sky keeps them as seen from where the
    /// world was built ([`World::cloud_origin`]; their shadows on the sea do not move). After a
    /// move over the sea with clouds, build the world again for the exact sky.
    pub fn set_camera(&mut self, camera: &crate::scene::CameraConfig) {
        self.camera = crate::camera::from_config(camera);
        self.sample_scale = sample_footprint_scale(camera.spp);
        let c = self.camera.position;
        self.underwater = c.y < self.sea.height(c.x, c.z);
        self.white_balance = self.scene_white_balance();
    }

    /// The white balance of `[output] white_balance = "scene"` for this world's camera: the
    /// [`scene_light`] over the square of [`SCENE_LIGHT_SPAN_CLOUD_SCALES`] cloud scales ahead
    /// of the camera ([`Self::scene_light_centre`]); `None` in the other modes or for a light
    /// it cannot adapt to.
    pub(crate) fn scene_white_balance(&self) -> Option<glam::DMat3> {
        if self.white_balance_mode != crate::scene::WhiteBalance::Scene {
            return None;
        }
        let light = scene_light(&self.sky, self.scene_light_centre(), self.white_balance_span_m);
        brine_sky::white_balance_linear_srgb(light)
    }

    /// The centre of the square of sea whose clouds' shadow the scene light averages (x, z; m):
    /// half its side ahead of the camera's foot along the view's bearing, so that the camera's
    /// foot is the middle of its near edge (the foot itself for a view straight down).
    pub(crate) fn scene_light_centre(&self) -> DVec2 {
        let c = self.camera.position;
        let ahead = DVec2::new(self.camera.forward.x, self.camera.forward.z);
        let ahead =
            if ahead.length() > 0.1 { ahead.normalize() * 0.5 * self.white_balance_span_m } else { DVec2::ZERO };
        DVec2::new(c.x, c.z) + ahead
    }
}

/// White water at one point of the surface, as the renderer draws it there.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Cover {
    /// Share of the area under foam in `[0, 1]`: the foam that breaking crests left (white water
    /// with memory) or Darles et al.'s foam amount.
    pub foam: f64,
    /// Share of the area under active whitecaps in `[0, 1]`.
    pub whitecap: f64,
    /// With the white water with memory: its white share and its brightness (Koepke's ageing),
    /// both in `[0, 1]`.
    pub memory: Option<(f64, f64)>,
}

impl World {
    /// The white water at surface point `p` of upward normal `n` (unit), seen along `d` (unit)
    /// through a pixel of side `across_m` across the view (m, `≥ 0`; 0 for a point): the pixel's
    /// footprint on the facet of normal `facet` (unit; the drawn surface's, brine-core
    /// `EllipticalFootprint::on_facet`), longer along the view the more the facet turns away
    /// from the eye.
    pub fn cover_seen(&self, p: DVec3, n: DVec3, facet: DVec3, across_m: f64, d: DVec3) -> Cover {
        // A Gaussian footprint of a box's spread has σ = ℓ/√12 on each axis.
        let footprint = EllipticalFootprint::on_facet(across_m / BOX_WIDTH_PER_SIGMA, d, facet);
        self.cover_over(p, n, self.time, &footprint)
    }

    /// The white water at surface point `p` of upward normal `n` (unit) at time `t` (s), seen
    /// through a square pixel footprint of side `footprint_m` (m, `≥ 0`; 0 for a point):
    /// trochoid, Gerstner and sine seas' white water is a function of time; the FFT sea's
    /// whitecap statistics are those of the world's frame whatever `t` (build a world at `t` for
    /// it).
    pub fn cover_at_time(&self, p: DVec3, n: DVec3, t: f64, footprint_m: f64) -> Cover {
        self.cover_over(p, n, t, &EllipticalFootprint::round(footprint_m / BOX_WIDTH_PER_SIGMA))
    }

    /// [`World::cover_at_time`] through a Gaussian footprint.
    fn cover_over(&self, p: DVec3, n: DVec3, t: f64, footprint: &EllipticalFootprint) -> Cover {
        let mut cover = Cover::default();
        let sigma = footprint.area_sigma_m();
        let footprint_m = sigma * BOX_WIDTH_PER_SIGMA;
        if let Some(ww) = &self.white_water {
            let w = ww.at_over(DVec2::new(p.x, p.z), t, footprint);
            cover.foam = w.residual;
            cover.whitecap = w.active;
            cover.memory = Some((w.white, w.brightness));
        }
        if let Some(foam) = &self.foam {
            let (gx, gz) = (-n.x / n.y.max(1e-3), -n.z / n.y.max(1e-3));
            let point = FoamPoint { height: p.y, slope: [gx, gz], rest: [p.x, p.z], footprint_m };
            cover.foam = foam.extension.foam_amount(foam.coverage, &point);
        }
        if let Some(wc) = &self.whitecaps {
            cover.whitecap = wc.coverage(DVec2::new(p.x, p.z), t, sigma);
        }
        cover
    }
}

impl World {
    /// The angle (rad) the waves fade with and the normals are filtered by: one sample's
    /// ([`Self::sample_angle`]), or 0 in the reference rendering.
    pub fn filtering_angle(&self) -> f64 {
        if self.reference { 0.0 } else { self.sample_angle() }
    }

    /// The angle (rad) one sample's footprint spans: the pixel's, shrunk as the samples of the
    /// pixel share it ([`sample_footprint_scale`]).
    pub fn sample_angle(&self) -> f64 {
        self.camera.pixel_angle() * self.sample_scale
    }
}

/// The share of a pixel's footprint one of its `spp` samples filters over, `max(1/8, 1/√spp)`:
/// at one sample per pixel the sample stands for the whole pixel; with more, the samples spread
/// over the pixel cover part of it by their number (each one the `1/√spp`-wide cell of a
/// stratified pattern), and the filter covers the rest. Without it a supersampled frame would
/// be blurred by the filter and by the samples' spread both; the floor of `1/8` keeps the
/// tracer's fading from vanishing at thousands of samples.
///
/// # Arguments
/// - `spp`: samples per pixel, `≥ 1`.
///
/// # Returns
/// The scale (1), `[1/8, 1]`.
///
/// # References
/// Pharr, Jakob & Humphreys, *Physically Based Rendering* (4th ed.), §5.2 (camera ray
/// differentials scaled by `max(1/8, 1/√spp)`).
pub fn sample_footprint_scale(spp: u32) -> f64 {
    (1.0 / f64::from(spp.max(1)).sqrt()).max(0.125)
}

/// Side of the square of sea over which [`scene_light`] averages the clouds' shadow on the sun
/// and the moon, in cloud scales (`[sky.clouds] scale_m`, the size of the layers' largest
/// features): a few features, so that the mean is the cover's share of shadow rather than
/// whether one cloud shades the camera.
pub(crate) const SCENE_LIGHT_SPAN_CLOUD_SCALES: f64 = 4.0;

/// Samples per side of [`scene_light`]'s square.
const SCENE_LIGHT_SHADOW_SAMPLES: usize = 16;

/// The light of the scene for its white balance (linear sRGB, klx): the irradiance on a level
/// surface of the sky (clouds included) plus the sun's and the moon's, each times the sine of
/// its elevation and the mean of the clouds' transmittance toward it over a square of sea of
/// side `span_m` (m) centred on `centre` (x, z; m), on a 16 × 16 grid: under a broken cover,
/// the share of the sea in the clouds' shadow.
pub(crate) fn scene_light(sky: &Sky, centre: DVec2, span_m: f64) -> DVec3 {
    let n = SCENE_LIGHT_SHADOW_SAMPLES;
    let step = span_m / n as f64;
    let offset = |k: usize| (k as f64 + 0.5 - 0.5 * n as f64) * step;
    let shadow = |toward: DVec3| {
        let mut sum = 0.0;
        for j in 0..n {
            for i in 0..n {
                sum += sky.cloud_transmittance(DVec3::new(centre.x + offset(i), 0.0, centre.y + offset(j)), toward);
            }
        }
        sum / (n * n) as f64
    };
    let disc = |d: &brine_sky::Disc| {
        let c = d.direction.y.max(0.0);
        if c > 0.0 { d.irradiance_rgb * c * shadow(d.direction) } else { DVec3::ZERO }
    };
    sky.horizontal_irradiance_rgb() + disc(sky.sun()) + sky.moon().map_or(DVec3::ZERO, disc)
}

/// Illuminance below which the automatic exposure stops following the light fully (lx), about
/// the end of civil twilight's brightest part.
pub const NIGHT_ADAPTATION_LX: f64 = 1000.0;

/// Reflected-light meter calibration constant `K` (cd s m⁻²) of ISO 2720.
pub const METER_K: f64 = 12.5;

/// Automatic exposure of a frame from the log-average luminance `L̄` of its pixels (cd m⁻²) and
/// the horizontal illuminance `E` of sun, moon and sky (lx).
///
/// `EV₁₀₀ = log₂(L̄ · 100/K) + ⅓ log₂(E₀/E)⁺`: a reflected-light meter (ISO 2720, `K = 12.5`)
/// reading the frame, so that the scene's mean maps to middle grey whether the view faces the sun
/// or not; below [`NIGHT_ADAPTATION_LX`] (`E₀`) the exposure follows the light with a third of the
/// slope, so that twilight and night stay dark as the eye sees them (a full-moon sea is about
/// 4 EV darker than a fully compensated exposure) — a stated rendering choice, not a model of the
/// eye's adaptation.
///
/// # References
/// ISO 2720:1974 (exposure-meter calibration); Reinhard et al. 2002 (log-average luminance as the
/// scene key).
pub fn auto_exposure_ev(log_average_luminance_cd_m2: f64, illuminance_lx: f64) -> f64 {
    let l = log_average_luminance_cd_m2.max(1e-9);
    let e = illuminance_lx.max(1e-9);
    (l * 100.0 / METER_K).log2() + (NIGHT_ADAPTATION_LX / e).log2().max(0.0) / 3.0
}

/// Mean of linear sRGB pixels (kcd m⁻²), each channel clipped at `white` (the exposure's
/// saturation, kcd m⁻²) as a camera's sensor clips it: the colour an automatic white balance
/// takes for grey. Summed in runs of 4096 pixels in parallel, then over the runs in pixel order
/// (the same bits at any thread count).
pub fn clipped_mean_rgb(pixels: &[DVec3], white: f64) -> DVec3 {
    use rayon::prelude::*;
    if pixels.is_empty() {
        return DVec3::ZERO;
    }
    let runs: Vec<DVec3> = pixels
        .par_chunks(4096)
        .map(|run| run.iter().fold(DVec3::ZERO, |a, p| a + p.clamp(DVec3::ZERO, DVec3::splat(white))))
        .collect();
    runs.iter().fold(DVec3::ZERO, |a, r| a + *r) / pixels.len() as f64
}

/// Log-average luminance `exp(mean ln(Y + 10⁻⁶))` of linear sRGB pixels in kcd m⁻², returned in
/// cd m⁻²; summed in runs of 4096 pixels in parallel, then over the runs in pixel order (the same
/// bits at any thread count).
pub fn log_average_luminance_cd_m2(pixels: &[DVec3]) -> f64 {
    use rayon::prelude::*;
    if pixels.is_empty() {
        return 0.0;
    }
    let runs: Vec<f64> = pixels
        .par_chunks(4096)
        .map(|run| {
            run.iter()
                .map(|p| {
                    // Rec. 709 luminance of linear sRGB.
                    let y = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
                    (y.max(0.0) * 1000.0 + 1e-6).ln()
                })
                .sum::<f64>()
        })
        .collect();
    (runs.iter().sum::<f64>() / pixels.len() as f64).exp()
}

/// Level-0 grid of the prefiltered sky (azimuth × elevation texels): 1.4° texels, under the 1°
/// Gaussian of its finest level plus bilinear lookup; 256 × 64 = 16 384 texels from 64 770 sky
/// evaluations per frame.
pub const FILTERED_SKY_WIDTH: usize = 256;
/// See [`FILTERED_SKY_WIDTH`].
pub const FILTERED_SKY_HEIGHT: usize = 64;

/// The rough-surface reflectance table of sea water (brine-optics `RoughReflectance`), built
/// once per process (it depends only on the index of water).
pub fn rough_reflectance() -> &'static RoughReflectance {
    static TABLE: std::sync::OnceLock<RoughReflectance> = std::sync::OnceLock::new();
    TABLE.get_or_init(RoughReflectance::water)
}

/// Mean cosine `g` of the scattering phase function of sea water used by the crest dipole: the
/// particle phase function's 0.92 (Petzold; docs/equations.md §12 "physically based defaults").
pub const CREST_PHASE_G: f64 = 0.92;

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
    /// The floor of a (validated) `[water.floor]` section: brine-waves `seabed_relief`.
    fn new(c: &FloorConfig) -> Result<Self, WorldError> {
        let relief = SeabedRelief {
            amplitude_m: c.amplitude_m,
            wavelength_range_m: c.wavelength_range_m,
            waves: c.waves,
            seed: c.seed,
        };
        let waves = seabed_relief(&relief)?;
        Ok(Self { shape: TrochoidSum::new(&waves), depth: c.depth_m, albedo: DVec3::from_array(c.albedo) })
    }
}

/// The water body of `[water]`: a Jerlov type, one of Darles et al.'s classes, or Case-1 water of
/// a chlorophyll concentration (Jerlov IB when neither is given).
///
/// # Errors
/// A message naming the unknown type.
pub fn water_body_of(water_type: Option<&str>, chlorophyll_mg_m3: Option<f64>) -> Result<WaterBody, String> {
    match chlorophyll_mg_m3 {
        Some(c) => WaterBody::case1(c),
        None => water_type.unwrap_or("IB").parse::<WaterBody>(),
    }
    .map_err(|e| e.to_string().replacen("water_type", "water.type", 1))
}

/// The sun's direction and distance (AU) and the moon of a scene: from brine-ephem for `[place]`
/// (the moon included), else from `[sky]`'s angles (no moon).
fn sun_and_moon(scene: &Scene) -> Result<(DVec3, f64, Option<MoonParams>), WorldError> {
    let Some(p) = &scene.place else {
        let k = &scene.sky;
        let dir = direction_from_bearing(
            k.sun_azimuth_deg.unwrap_or(SkyConfig::DEFAULT_SUN_AZIMUTH_DEG),
            k.sun_elevation_deg.unwrap_or(SkyConfig::DEFAULT_SUN_ELEVATION_DEG),
        );
        return Ok((dir, 1.0, None));
    };
    let t0 = parse_utc(&p.time_utc)?;
    let t = t0
        .checked_add(jiff::SignedDuration::from_secs_f64(scene.elapsed_s))
        .map_err(|e| WorldError::Scene(format!("place.time_utc + {} s: {e}", scene.elapsed_s)))?;
    let observer = Observer::from_degrees(p.latitude_deg, p.longitude_deg, 0.0)?;
    let options = EphemOptions { refraction: p.refraction.then(Atmosphere::standard), delta_t_s: None };
    let model = match p.sun_model {
        SunModelKind::Spa => SunModel::Spa,
        SunModelKind::Schlyter => SunModel::Schlyter,
    };
    let sun = sun_position(t, &observer, model, &options)?;
    let moon = moon_position(t, &observer, &options)?;
    let moon = MoonParams {
        direction: DVec3::from_array(moon.horizontal().direction()),
        phase_angle: moon.phase_angle,
        distance_km: moon.topocentric_distance_km,
    };
    Ok((DVec3::from_array(sun.horizontal().direction()), sun.distance_au, Some(moon)))
}

impl World {
    /// Builds the models of a validated scene.
    ///
    /// # Errors
    /// [`WorldError`] if a model rejects a parameter.
    pub fn new(scene: &Scene) -> Result<Self, WorldError> {
        Self::on_lattice(scene, None)
    }

    /// Builds the models of a validated scene with its waves snapped to a tile's lattice (and
    /// loop), so that the sea repeats over the tile: the trochoid, Gerstner and sine waves by
    /// brine-waves `TileLattice::snap`, the FFT cascades' tiles made whole fractions of the tile
    /// (`TileLattice::commensurate_tiles`); what `brine bake` draws.
    ///
    /// # Errors
    /// [`WorldError`] if a model rejects a parameter.
    pub fn on_lattice(scene: &Scene, lattice: Option<&TileLattice>) -> Result<Self, WorldError> {
        Self::at_instant(scene, &Timeless::new(scene, lattice)?)
    }

    /// Builds the world of a scene from the parts of it that do not change with time, built
    /// once ([`Timeless::new`]) for every frame of an animation: the same world, bit for bit,
    /// as [`World::on_lattice`] builds for the frame alone.
    ///
    /// # Errors
    /// [`WorldError::Scene`] if `timeless` was built from another scene (other than by its
    /// instants) or lattice; [`WorldError`] if a model rejects a parameter.
    pub fn at_instant(scene: &Scene, timeless: &Timeless) -> Result<Self, WorldError> {
        if !timeless.fits(scene) {
            return Err(WorldError::Scene(
                "the precomputed parts of the world belong to another scene (they may differ by its instants only)"
                    .into(),
            ));
        }
        let s = &scene.sea;
        let wind_angle = s.wind_direction_deg.to_radians();
        let wind = DVec3::new(wind_angle.cos(), 0.0, wind_angle.sin());
        let set = timeless.set.clone();
        let ocean = timeless.ocean.clone();
        let sea = ocean.at_time(s.time_s);
        let gridded = timeless.banded.as_ref().map(|b| GriddedTrochoids::at_time(b, s.time_s));
        let stats = sea_statistics(&set, &sea, wind_angle);

        let k = &scene.sky;
        let (sun_dir, sun_distance_au, moon) = sun_and_moon(scene)?;
        let clouds = match (&k.clouds, scene.phenomena.clouds) {
            (Some(c), true) => Some(CloudParams {
                cover: c.cover,
                altitude_m: c.altitude_m,
                scale_m: c.scale_m,
                wind_m_s: DVec2::from_array(c.wind_m_s),
                seed: c.seed,
                // The layers are fixed over the sea and seen from the camera.
                origin_m: DVec2::new(scene.camera.position[0], scene.camera.position[2]),
            }),
            _ => None,
        };
        let sky = Sky::new(&SkyParams {
            turbidity: k.turbidity,
            sun_direction: sun_dir,
            sun_distance_au,
            moon,
            clouds,
            time_s: s.time_s,
            model: match k.model {
                SkyModelKind::Preetham => DaylightModel::Preetham,
                SkyModelKind::HosekWilkie => DaylightModel::HosekWilkie,
            },
        })?;

        let filtered_sky = FilteredSky::new(FILTERED_SKY_WIDTH, FILTERED_SKY_HEIGHT, |d| sky.radiance_rgb(d));

        let variance_total = SlopeVariance::cox_munk_clean_from_u10(s.wind_speed_m_s.min(60.0))?;
        let detail = timeless.detail.as_ref().map(|d| d.at_time(s.time_s));
        let (detail_along, detail_across) = detail.as_ref().map_or((0.0, 0.0), |d| {
            let c = d.expected_slope_covariance();
            let (wx, wz) = (wind.x, wind.z);
            (c.x * wx * wx + 2.0 * c.y * wx * wz + c.z * wz * wz, c.x * wz * wz - 2.0 * c.y * wx * wz + c.z * wx * wx)
        });
        let variance_unresolved =
            variance_total.minus(stats.slope_along + detail_along, stats.slope_across + detail_across);

        // Downwelling irradiance just below a flat surface: the sun's and the moon's share
        // through Fresnel, the sky's through the hemispherical Fresnel reflectance of a uniform
        // sky (0.066).
        let sky_e = sky.horizontal_irradiance_rgb();
        let disc_e = |d: &brine_sky::Disc| {
            let c = d.direction.y.max(0.0);
            d.irradiance_rgb * c * (1.0 - fresnel_dielectric(c, 1.0, WATER_IOR))
        };
        let e_below_sun = disc_e(sky.sun());
        let discs_e = e_below_sun + sky.moon().map_or(DVec3::ZERO, disc_e);
        let e_below = discs_e + sky_e * (1.0 - hemispherical_fresnel_reflectance(1.0, WATER_IOR));
        let e_horizontal = sky_e.y
            + sky.sun().irradiance_rgb.y * sky.sun().direction.y.max(0.0)
            + sky.moon().map_or(0.0, |m| m.irradiance_rgb.y * m.direction.y.max(0.0));
        let white_balance_span_m = SCENE_LIGHT_SPAN_CLOUD_SCALES
            * scene.sky.clouds.as_ref().map_or(crate::scene::CloudConfig::default().scale_m, |c| c.scale_m);
        let sun_below = brine_optics::refract(-sky.sun().direction, DVec3::Y, 1.0, WATER_IOR)
            .filter(|_| sky.sun().direction.y > 0.0)
            .unwrap_or(DVec3::NEG_Y);
        let body = water_body_of(scene.water.water_type.as_deref(), scene.water.chlorophyll_mg_m3)
            .map_err(WorldError::Scene)?;
        let water = WaterRgb::new(&body, RgbBands::SrgbAverage);
        let floor = scene.water.floor.as_ref().map(Floor::new).transpose()?;
        let ph = &scene.phenomena;
        let monahan = monahan_coverage(scene)?;
        let (foam_share, whitecap_share) = match (ph.foam, ph.whitecaps) {
            (true, true) => (1.0 - ACTIVE_WHITECAP_SHARE, ACTIVE_WHITECAP_SHARE),
            (f, w) => (f64::from(u8::from(f)), f64::from(u8::from(w))),
        };
        // Foam and whitecaps together (calibrated once, [`Timeless`]); either alone, or a raw
        // threshold, keeps the separate models.
        let together = ph.foam && ph.whitecaps && ph.foam_memory && ph.whitecap_alpha.is_none();
        let white_water =
            if together && monahan > 0.0 && !stats.flat { timeless.white_water_at(s.time_s) } else { None };
        let foam = if ph.foam && !together && monahan > 0.0 && !stats.flat {
            let extension = FoamExtension::new(
                &FoamExtensionParams { seed: s.seed, ..FoamExtensionParams::default() },
                &stats.surface,
            )?;
            Some(Foam {
                extension,
                coverage: monahan * foam_share,
                reflectance: KoepkeFoam::default().effective_reflectance(),
            })
        } else {
            None
        };
        let whitecaps = if ph.whitecaps && !together && !stats.flat && (ph.whitecap_alpha.is_some() || monahan > 0.0) {
            let alpha = ph.whitecap_alpha.unwrap_or(0.0);
            let target = monahan * whitecap_share;
            let calibrate = ph.whitecap_alpha.is_none();
            Some(match sea.surface() {
                FrameSurface::Fft(frame) => {
                    let stats = Box::new(FftJacobianStatistics::new(frame));
                    let calibration = calibrate
                        .then(|| FftCalibration::new(&stats, target, &CalibrationOptions::default()))
                        .transpose()?;
                    Whitecaps::Fft { stats, calibration, alpha }
                }
                _ => {
                    let stats = JacobianStatistics::new(&set)?;
                    let calibration = calibrate
                        .then(|| Calibration::new(&stats, target, &CalibrationOptions::default()))
                        .transpose()?;
                    Whitecaps::Trochoids { stats, calibration, alpha }
                }
            })
        } else {
            None
        };
        let spray = if ph.spray && s.wind_speed_m_s > sea::CALM_WIND_M_S {
            Some(spray::spray(s, &sky, &variance_total)?)
        } else {
            None
        };
        let crest = if scene.phenomena.subsurface {
            let m = |i: usize| DipoleMaterial::new(water.a[i], water.b[i], CREST_PHASE_G, WATER_IOR);
            Some([m(0)?, m(1)?, m(2)?])
        } else {
            None
        };

        let discs =
            (SunDisc::new(sky.sun().angular_radius)?, sky.moon().map(|m| SunDisc::new(m.angular_radius)).transpose()?);
        let camera = crate::camera::from_config(&scene.camera);
        let exposure_ev = scene.output.exposure_ev;
        let trace = TraceOptions {
            method: Method::Directional,
            t_max: s.trace_distance_m,
            max_steps: 20_000,
            min_step: 1e-3,
            min_step_relative: 1e-4,
            tolerance: 1e-3,
            tolerance_relative: 1e-5,
            ..TraceOptions::default()
        };
        let fft_slopes = match sea.surface() {
            FrameSurface::Fft(frame) => Some(FftSlopeFilter::new(frame)),
            _ => None,
        };
        let world = Self {
            set,
            loop_distortion: timeless.loop_distortion.clone(),
            ocean,
            sea,
            gridded,
            banded: timeless.banded.clone(),
            time: s.time_s,
            sky,
            filtered_sky,
            aerial_perspective: scene.phenomena.aerial_perspective,
            wind,
            variance_unresolved,
            detail,
            fft_slopes,
            variance_total,
            water,
            e_below,
            e_below_direct: discs_e,
            e_below_sun,
            sun_below,
            floor,
            underwater: false,
            crest,
            discs,
            foam,
            whitecaps,
            white_water,
            spray,
            trace,
            camera,
            exposure_ev,
            exposure_compensation_ev: scene.output.exposure_compensation_ev,
            illuminance_lx: e_horizontal * 1000.0,
            white_balance: None,
            white_balance_mode: scene.output.white_balance,
            white_balance_span_m,
            reference: false,
            sample_scale: sample_footprint_scale(scene.camera.spp),
        };
        let mut world = world;
        let c = camera.position;
        world.underwater = c.y < world.sea.height(c.x, c.z);
        world.white_balance = world.scene_white_balance();
        Ok(world)
    }
}

#[cfg(test)]
mod tests;
