//! Per-pixel composition and the parallel frame loop.

use brine_foam::{FRESH_FOAM_REFLECTANCE, SprayLighting, SprayRay, SprayScattering};
use brine_optics::{
    SlopeVariance, SunDisc, WATER_IOR, fresnel_dielectric, reflect, reflected_source_radiance, refract,
};
use brine_trace::{Hit, Method};
use brine_trace::{Lowered, Ray, TraceOptions, TraceStats, trace};
use brine_waves::{RayTile, TracedSea};
use brine_whitecap::WHITECAP_REFLECTANCE;
use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::scene::Scene;
use crate::world::{World, WorldError};

mod energy;
pub use energy::{ENERGY_BANDS, energy_bands};
mod sea_field;
mod shade;

use sea_field::*;
use shade::*;

/// Options of a render that are not part of the scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RenderOptions {
    /// Worker threads; `None` uses all cores. The image does not depend on it.
    pub threads: Option<usize>,
    /// Measure the time spent in each stage ([`Frame::stages`]); costs a few percent.
    pub profile: bool,
    /// The reference rendering ([`World::reference`]): nothing faded or filtered with the pixel
    /// footprint; meant for many samples per pixel.
    pub reference: bool,
}

/// Stages of the per-pixel work, as in Darles et al.'s Table 3.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Primary ray–surface intersection.
    Trace,
    /// Fresnel, sky reflection, sun and moon through the BRDF.
    Surface,
    /// The water column under the surface (Darles Eq. 8–11) with the floor.
    Water,
    /// Light through thin crests (dipole, with its trace inside the water).
    Subsurface,
    /// Foam and whitecaps.
    WhiteWater,
    /// Aerial perspective and spray along the camera ray.
    Atmosphere,
    /// Sky seen directly (rays that miss the sea).
    Sky,
}

/// Seconds of thread time spent per stage, summed over all threads.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StageTimes {
    /// Seconds per [`Stage`], in declaration order.
    pub seconds: [f64; 7],
    /// Glare and exposure after the pixels (wall-clock seconds).
    pub post_s: f64,
}

impl StageTimes {
    /// The stages with their names, in order.
    pub fn named(&self) -> [(&'static str, f64); 8] {
        let s = &self.seconds;
        [
            ("ray-surface intersection", s[0]),
            ("surface (Fresnel, sky, sun glint)", s[1]),
            ("water column and floor", s[2]),
            ("sub-surface (crests)", s[3]),
            ("foam and whitecaps", s[4]),
            ("aerial perspective and spray", s[5]),
            ("sky", s[6]),
            ("glare and exposure", self.post_s),
        ]
    }
}

/// Per-row counters: tracer statistics of primary and secondary rays, and stage times.
pub(crate) struct Counters {
    primary: TraceStats,
    secondary: TraceStats,
    times: Option<StageTimes>,
}

impl Counters {
    fn new(profile: bool) -> Self {
        Self {
            primary: TraceStats::default(),
            secondary: TraceStats::default(),
            times: profile.then(StageTimes::default),
        }
    }

    /// Starts a timer when profiling.
    #[inline]
    fn clock(&self) -> Option<std::time::Instant> {
        self.times.map(|_| std::time::Instant::now())
    }

    /// Adds the time since `started` to `stage`.
    #[inline]
    fn lap(&mut self, stage: Stage, started: Option<std::time::Instant>) {
        if let (Some(t), Some(s)) = (self.times.as_mut(), started) {
            t.seconds[stage as usize] += s.elapsed().as_secs_f64();
        }
    }
}

/// Arbitrary output variables of a pixel, taken from its first sample.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Aov {
    /// Distance from the eye to the sea surface along the ray (m); infinite for the sky.
    pub depth: f32,
    /// Unit normal of the sea surface at the hit (zero for the sky).
    pub normal: [f32; 3],
    /// Foam coverage at the hit, `[0, 1]`.
    pub foam: f32,
    /// Whitecap coverage at the hit, `[0, 1]`.
    pub whitecap: f32,
    /// The sun's glint at the hit per unit of its irradiance: the luminance the sea reflects from
    /// the sun over the sun's illuminance on a plane facing it (sr⁻¹), before cloud shadow, white
    /// water and the atmosphere. Cox & Munk's photographs measured this quantity.
    pub glint: f32,
    /// Evaluations of the implicit function `F` spent on the primary ray (those of the image
    /// coherence's cones shared equally among the rays below each cone).
    pub evaluations: f32,
}

/// A rendered frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// Width (pixels).
    pub width: u32,
    /// Height (pixels).
    pub height: u32,
    /// Linear sRGB radiance (kcd m⁻²), row-major, top row first.
    pub pixels: Vec<DVec3>,
    /// Per-pixel output variables, same layout as `pixels`.
    pub aovs: Vec<Aov>,
    /// Tracer counters over all primary rays.
    pub stats: TraceStats,
    /// Tracer counters of the secondary rays (floor, crests).
    pub secondary_stats: TraceStats,
    /// Time per stage, when profiled.
    pub stages: Option<StageTimes>,
    /// Exposure to display the frame with (EV₁₀₀).
    pub exposure_ev: f64,
}

/// Why a frame could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The scene could not be turned into models.
    #[error(transparent)]
    World(#[from] WorldError),
    /// The thread pool could not be built.
    #[error("cannot start {threads} worker threads: {message}")]
    Threads {
        /// Requested count.
        threads: usize,
        /// Cause.
        message: String,
    },
    /// The render was cancelled before its end ([`render_world_cancellable`]).
    #[error("the render was cancelled")]
    Cancelled,
}

/// Mixes the scene seed and a pixel index into a generator seed (SplitMix64 finaliser), so that
/// each pixel has its own stream, independent of the order pixels are rendered in.
fn pixel_seed(seed: u64, index: u64) -> u64 {
    let mut z = seed ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Renders `scene`; `on_row` is called once per finished row (from any thread, in bursts of a
/// band of 16 rows).
///
/// # Errors
/// [`RenderError`] if a model rejects the scene or the thread pool cannot start.
pub fn render(scene: &Scene, options: &RenderOptions, on_row: &(dyn Fn() + Sync)) -> Result<Frame, RenderError> {
    let mut world = World::new(scene)?;
    world.reference = options.reference;
    render_world(scene, &world, options, on_row)
}

/// Renders a scene whose models are already built (animations rebuild only what changes).
///
/// # Errors
/// [`RenderError::Threads`] if the thread pool cannot start.
pub fn render_world(
    scene: &Scene,
    world: &World,
    options: &RenderOptions,
    on_row: &(dyn Fn() + Sync),
) -> Result<Frame, RenderError> {
    render_world_cancellable(scene, world, options, on_row, None)
}

/// [`render_world`], given up as soon as `cancel` is set: the bands of rows not yet started are
/// skipped and the call returns [`RenderError::Cancelled`] (what an interactive preview does when
/// the view changes under it). A render that is not cancelled is the same image.
///
/// # Errors
/// [`RenderError::Threads`] if the thread pool cannot start; [`RenderError::Cancelled`].
pub fn render_world_cancellable(
    scene: &Scene,
    world: &World,
    options: &RenderOptions,
    on_row: &(dyn Fn() + Sync),
    cancel: Option<&std::sync::atomic::AtomicBool>,
) -> Result<Frame, RenderError> {
    let cancelled = || cancel.is_some_and(|c| c.load(std::sync::atomic::Ordering::Relaxed));
    let (w, h) = (scene.camera.width, scene.camera.height);
    let spp = scene.camera.spp;
    let seed = scene.sea.seed;
    let field = SeaField::new(world);
    // The frame buffers (16 MB at 640×480) are first written by the workers, not by one thread.
    let n = w as usize * h as usize;
    let mut pixels: Vec<DVec3> = (0..n).into_par_iter().map(|_| DVec3::ZERO).collect();
    let mut aovs: Vec<Aov> = (0..n).into_par_iter().map(|_| Aov::default()).collect();
    let work = |pixels: &mut [DVec3], aovs: &mut [Aov]| -> Counters {
        let width = w as usize;
        pixels
            .par_chunks_mut(width * TILE)
            .zip(aovs.par_chunks_mut(width * TILE))
            .enumerate()
            .map(|(band, (rows, aov_rows))| {
                let mut cx = Counters::new(options.profile);
                if cancelled() {
                    return cx;
                }
                let (y0, band_h) = (band * TILE, rows.len() / width);
                // Each pixel's jitters, drawn from its own generator in sample order.
                let jitter: Vec<(f64, f64)> = (0..rows.len())
                    .flat_map(|i| {
                        let index = (y0 + i / width) as u64 * u64::from(w) + (i % width) as u64;
                        let mut rng = ChaCha8Rng::seed_from_u64(pixel_seed(seed, index));
                        (0..spp).map(
                            move |_| {
                                if spp == 1 { (0.5, 0.5) } else { (rng.random::<f64>(), rng.random::<f64>()) }
                            },
                        )
                    })
                    .collect();
                rows.iter_mut().for_each(|p| *p = DVec3::ZERO);
                let mut weights = vec![0.0f64; rows.len()];
                let mut tile = TileRays::default();
                for s in 0..spp as usize {
                    for x0 in (0..width).step_by(TILE) {
                        let tile_w = TILE.min(width - x0);
                        tile.directions.clear();
                        for y in 0..band_h {
                            for x in x0..x0 + tile_w {
                                let (jx, jy) = jitter[(y * width + x) * spp as usize + s];
                                tile.directions.push(world.camera.direction(x as f64 + jx, (y0 + y) as f64 + jy));
                            }
                        }
                        let started = cx.clock();
                        field.trace_tile(world, &mut tile, tile_w, &mut cx.primary);
                        cx.lap(Stage::Trace, started);
                        for y in 0..band_h {
                            for x in x0..x0 + tile_w {
                                let k = y * tile_w + x - x0;
                                let sample = radiance(world, &field, tile.directions[k], tile.hits[k], &mut cx);
                                if s == 0 {
                                    aov_rows[y * width + x] = Aov { evaluations: tile.costs[k] as f32, ..sample.aov };
                                }
                                rows[y * width + x] += sample.radiance * sample.weight;
                                weights[y * width + x] += sample.weight;
                            }
                        }
                    }
                }
                // A sum of unit weights is exact: the mean of the usual rendering is unchanged.
                for (p, w) in rows.iter_mut().zip(&weights) {
                    *p = if *w > 0.0 { *p / *w } else { DVec3::ZERO };
                }
                for _ in 0..band_h {
                    on_row();
                }
                cx
            })
            .reduce(
                || Counters::new(options.profile),
                |mut a, b| {
                    a.primary.merge(&b.primary);
                    a.secondary.merge(&b.secondary);
                    if let (Some(x), Some(y)) = (a.times.as_mut(), b.times) {
                        for (u, v) in x.seconds.iter_mut().zip(y.seconds) {
                            *u += v;
                        }
                    }
                    a
                },
            )
    };
    let counters = match options.threads {
        None => work(&mut pixels, &mut aovs),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map_err(|e| RenderError::Threads { threads: n, message: e.to_string() })?
            .install(|| work(&mut pixels, &mut aovs)),
    };
    if cancelled() {
        return Err(RenderError::Cancelled);
    }
    let post = std::time::Instant::now();
    let exposure_ev = world.exposure_ev.unwrap_or_else(|| {
        let l = crate::world::log_average_luminance_cd_m2(&pixels);
        (crate::world::auto_exposure_ev(l, world.illuminance_lx) - world.exposure_compensation_ev).clamp(-10.0, 30.0)
    });
    let balance = world.white_balance.or_else(|| {
        let white = 1.0 / crate::tonemap::exposure_scale(exposure_ev);
        (world.white_balance_mode == crate::scene::WhiteBalance::Image)
            .then(|| brine_sky::white_balance_linear_srgb(crate::world::clipped_mean_rgb(&pixels, white)))
            .flatten()
    });
    if let Some(m) = balance {
        for p in &mut pixels {
            *p = m * *p;
        }
    }
    if scene.phenomena.glare {
        let white = 1.0 / crate::tonemap::exposure_scale(exposure_ev);
        glare_filter(w as usize, h as usize, world.camera.pixel_angle())
            .apply(&mut pixels, crate::glare::GLARE_CLIP_WHITES * white);
    }
    let stages = counters.times.map(|mut t| {
        t.post_s = post.elapsed().as_secs_f64();
        t
    });
    Ok(Frame {
        width: w,
        height: h,
        pixels,
        aovs,
        stats: counters.primary,
        secondary_stats: counters.secondary,
        stages,
        exposure_ev,
    })
}

/// The glare filter for `width × height` images of pixels `pixel_angle` rad wide: built once and
/// kept for the following frames of that size and angle (an animation's), since the kernel's
/// transform is a quarter of the filter's cost.
fn glare_filter(width: usize, height: usize, pixel_angle: f64) -> std::sync::Arc<crate::glare::Glare> {
    type Cached = Option<((usize, usize, u64), std::sync::Arc<crate::glare::Glare>)>;
    static LAST: std::sync::Mutex<Cached> = std::sync::Mutex::new(None);
    let key = (width, height, pixel_angle.to_bits());
    // A poisoned lock only means another render panicked while holding it; the cache stays valid.
    let mut last = LAST.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    match &*last {
        Some((k, g)) if *k == key => g.clone(),
        _ => {
            let g = std::sync::Arc::new(crate::glare::Glare::new(width, height, pixel_angle));
            *last = Some((key, g.clone()));
            g
        }
    }
}

/// What one camera sample returns.
struct Sample {
    radiance: DVec3,
    aov: Aov,
    /// Weight of the sample in its pixel's mean: 1, but in the reference rendering of a sea with
    /// detail normals their facet's projected area over that of the surface traced ([`World::reference`]).
    weight: f64,
}

/// The projected area toward `v` of a facet of normal `n` laid on a surface of normal `g`, per
/// unit of that surface's projected area: `max(v·n, c₀) / ((n·g)(v·g))`. Its mean over facets
/// whose slopes relative to the surface average zero is 1 (the surface's area is conserved)
/// where the view sees every facet above `c₀`.
///
/// A facet turned away from the viewer, or more grazing than `c₀` ([`shade::MIN_SEEN_COSINE`]),
/// counts as the shading shades it: seen at `c₀`. Its weight is then small but not zero, so a
/// pixel whose every sample lands on such facets (a lee face seen edge-on under detail normals
/// that all lean away) takes their mean radiance rather than none (a black pixel).
fn projected_area_weight(v: DVec3, n: DVec3, g: DVec3) -> f64 {
    v.dot(n).max(shade::MIN_SEEN_COSINE) / (n.dot(g).max(1e-3) * v.dot(g).max(1e-3))
}

/// Rows per band of the frame loop and columns per tile: the primary rays of a tile are traced
/// together by brine-trace's cone quadtree ([`brine_trace::trace_tile`], image coherence).
const TILE: usize = 16;

/// The primary rays of one tile (row-major) and what tracing them found; reused between tiles.
#[derive(Default)]
struct TileRays {
    directions: Vec<DVec3>,
    hits: Vec<Option<Hit>>,
    /// Evaluations of `F` per ray, the cones' shared equally among the rays below them.
    costs: Vec<f64>,
}

#[cfg(test)]
mod tests;
