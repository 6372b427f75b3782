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
    let post = std::time::Instant::now();
    let exposure_ev = world.exposure_ev.unwrap_or_else(|| {
        let l = crate::world::log_average_luminance_cd_m2(&pixels);
        (crate::world::auto_exposure_ev(l, world.illuminance_lx) - world.exposure_compensation_ev).clamp(-10.0, 30.0)
    });
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
/// unit of that surface's projected area: `max(v·n, 0) / ((n·g)(v·g))`. Its mean over facets
/// whose slopes relative to the surface average zero is 1 (the surface's area is conserved).
fn projected_area_weight(v: DVec3, n: DVec3, g: DVec3) -> f64 {
    v.dot(n).max(0.0) / (n.dot(g).max(1e-3) * v.dot(g).max(1e-3))
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

/// Radiance (linear sRGB, kcd m⁻²) arriving at the camera along the unit direction `d` whose
/// primary ray found `hit`, and the sample's output variables.
fn radiance(world: &World, field: &SeaField<'_>, d: DVec3, hit: Option<Hit>, cx: &mut Counters) -> Sample {
    let origin = world.camera.position;
    if world.underwater {
        return underwater_radiance(world, field, d, hit.map(|h| (h.t, h.point)), cx);
    }
    let faded;
    let mut weight = 1.0;
    let (t, p, n, variance) = match hit {
        Some(hit) => {
            let (n, v) = field.hit_geometry(hit.point, d, hit.t, world);
            faded = v;
            if world.reference && world.detail.is_some() {
                // The detail normals are not displaced geometry: a sample of the traced surface
                // stands for a facet of area dA/(n·n_g) seen at v·n, against dA seen at v·n_g.
                weight = projected_area_weight(-d, n, field.normal(hit.point, d, 0.0, world));
            }
            (hit.t, hit.point, n, &faded)
        }
        // Beyond the trace distance: the mean plane, with every wave's slopes in the BRDF.
        None if d.y < 0.0 && world.camera.position.y / -d.y < horizon_distance(world.camera.position.y) => {
            let t = world.camera.position.y / -d.y;
            (t, origin + t * d, DVec3::Y, &world.variance_total)
        }
        None => {
            // The sky's own aerosol is Preetham's turbidity: spray is not added to sky rays.
            let started = cx.clock();
            let l = sky_radiance(world, d);
            cx.lap(Stage::Sky, started);
            return Sample { radiance: l, aov: Aov { depth: f32::INFINITY, ..Aov::default() }, weight: 1.0 };
        }
    };
    let shade = shade_surface(world, field, p, d, t, n, variance, cx);
    let aov = Aov {
        depth: t as f32,
        normal: n.as_vec3().to_array(),
        foam: shade.foam as f32,
        whitecap: shade.whitecap as f32,
        glint: shade.glint as f32,
        ..Aov::default()
    };
    let started = cx.clock();
    let l = spray(world, d, t, aerial(world, d, t, shade.radiance));
    cx.lap(Stage::Atmosphere, started);
    Sample { radiance: l, aov, weight }
}

/// Mean radius of the Earth (m).
const EARTH_RADIUS_M: f64 = 6.371e6;

/// Distance to the sea horizon from a height `h` above the sea, `√(2Rh + h²)` (m): the Earth's
/// curvature hides the sea beyond it, so rays that would meet the mean plane farther away see the
/// sky just above the horizon.
fn horizon_distance(h: f64) -> f64 {
    let h = h.max(0.01);
    (2.0 * EARTH_RADIUS_M * h + h * h).sqrt()
}

/// Sea spray between the eye and the sea `t` metres along `d`:
/// Beer–Lambert transmittance and single scattering of sun and sky light by the drops
/// (brine-foam `SprayRay`, Darles et al. 2007 §4.2 corrected). Drops are much larger than the
/// wavelength, so the extinction is grey; the in-scattered light takes the sun's and sky's colour.
fn spray(world: &World, d: DVec3, t: f64, l0: DVec3) -> DVec3 {
    let Some(medium) = &world.spray else { return l0 };
    let y0 = world.camera.position.y.max(0.0);
    let top = medium.params().max_height_m;
    let (len, y1) = (t, (y0 + d.y * t).clamp(0.0, top));
    let sun = world.sky.sun();
    let scattering = SprayScattering::default();
    let lit = |sun_irradiance: f64, sky_radiance: f64| {
        let mut ray = SprayRay::new(
            medium,
            &scattering,
            &SprayLighting {
                sun_irradiance,
                sin_sun_elevation: sun.direction.y.clamp(0.01, 1.0),
                cos_view_sun: d.dot(sun.direction),
                sky_radiance,
            },
        );
        ray.step(y0, y1, len, 1.0);
        (ray.radiance(1.0) - ray.radiance(0.0), ray.radiance(0.0))
    };
    let (transmittance, in_sun) = lit(if sun.direction.y > 0.0 { 1.0 } else { 0.0 }, 0.0);
    let (_, in_sky) = lit(0.0, 1.0);
    let sky_mean = world.sky.horizontal_irradiance_rgb() / std::f64::consts::PI;
    l0 * transmittance + sun.irradiance_rgb * in_sun + sky_mean * in_sky
}

/// The share of the sun's and the moon's direct light that reaches a sea point through the
/// clouds (cloud shadows; brine-sky `Sky::cloud_transmittance`), each in `[0, 1]`.
#[derive(Debug, Clone, Copy)]
struct DirectLight {
    sun: f64,
    moon: f64,
}

impl DirectLight {
    fn at(world: &World, p: DVec3) -> Self {
        let sky = &world.sky;
        Self {
            sun: sky.cloud_transmittance(p, sky.sun().direction),
            moon: sky.moon().map_or(1.0, |m| sky.cloud_transmittance(p, m.direction)),
        }
    }

    /// `E_d(0⁻)` and its direct part under this light: the discs' shares scaled.
    fn e_below(&self, world: &World) -> (DVec3, DVec3) {
        let moon = world.e_below_direct - world.e_below_sun;
        let direct = world.e_below_sun * self.sun + moon * self.moon;
        (world.e_below - world.e_below_direct + direct, direct)
    }
}

/// The shading of a surface point.
struct SurfaceShade {
    radiance: DVec3,
    foam: f64,
    whitecap: f64,
    /// The sun's glint per unit of its irradiance (sr⁻¹, luminance), for the `glint` AOV.
    glint: f64,
}

/// Aerial perspective of the segment from the eye along `d` over `t` metres:
/// `L = L₀ F_ex + L_in` (Hoffman & Preetham 2002, brine-sky).
fn aerial(world: &World, d: DVec3, t: f64, l0: DVec3) -> DVec3 {
    if !world.aerial_perspective {
        return l0;
    }
    let ap = world.sky.aerial_perspective(world.camera.position.y.max(0.0), d, t);
    l0 * ap.extinction + ap.inscatter
}

/// Everything seen along `d` above the sea: sky, clouds, sun and moon discs.
fn sky_radiance(world: &World, d: DVec3) -> DVec3 {
    world.sky.background_rgb(d)
}

/// Where a ray through the water from `p` along the unit `d` meets the floor: `(distance, point)`.
fn floor_hit(world: &World, p: DVec3, d: DVec3, cx: &mut Counters) -> Option<(f64, DVec3)> {
    let floor = world.floor.as_ref()?;
    let field = floor.shape.at_time(0.0);
    let lowered = Lowered::new(&field, floor.depth);
    let ray = Ray::new(p, d).ok()?;
    let options = TraceOptions { t_max: 50.0 * floor.depth + 100.0, ..world.trace };
    trace(&lowered, &ray, &options, &mut cx.secondary).map(|h| (h.t, h.point))
}

/// Radiance leaving the floor at `point`: Lambertian, lit by the diffuse part of `E_d` and by the
/// refracted sun on the floor's own slope (`n_f·(−t)/(−t_y)` times its horizontal irradiance),
/// both attenuated by `e^{−K_d z}` down to its depth (brine-optics `lambertian_floor_radiance`).
fn floor_radiance(world: &World, point: DVec3, light: DirectLight) -> DVec3 {
    let floor = world.floor.as_ref().expect("floor_radiance needs a floor");
    let depth = (-point.y).max(0.0);
    let n = floor.shape.at_time(0.0).normal(point.x, point.z);
    let t = world.sun_below;
    let slope_gain = (n.dot(-t)).max(0.0) / (-t.y).max(1e-3);
    let (e_below, direct) = light.e_below(world);
    let diffuse = e_below - direct;
    world.water.lambertian_floor_radiance(floor.albedo, direct * slope_gain + diffuse, depth)
}

/// Upwelling radiance just below the surface along the downward refracted ray `t` from the
/// surface point `p`: Darles et al. 2007 Eq. 8–11 (corrected, docs/equations.md §7) with the floor
/// traced by the same sphere tracer.
fn water_column_radiance(world: &World, p: DVec3, t: DVec3, light: DirectLight, cx: &mut Counters) -> DVec3 {
    let cos_theta = (-t.y).clamp(0.0, 1.0);
    let (e_below, _) = light.e_below(world);
    match floor_hit(world, p, t, cx) {
        Some((s, q)) => world.water.refracted_ray_radiance(e_below, cos_theta, s, floor_radiance(world, q, light)),
        None => world.water.refracted_ray_radiance(e_below, cos_theta, f64::INFINITY, DVec3::ZERO),
    }
}

/// Radiance leaving the sea surface toward the camera at `p`: Fresnel-weighted sky reflection, the
/// sun through the ocean BRDF of the unresolved slopes, and the water column through `1 − F` and
/// the `n²` radiance law (Chen et al. 2007 §3.4; Bruneton et al. 2010 §5; Darles et al. 2007 §4.3).
#[allow(clippy::too_many_arguments)]
fn shade_surface(
    world: &World,
    field: &SeaField<'_>,
    p: DVec3,
    d: DVec3,
    t: f64,
    normal: DVec3,
    variance: &SlopeVariance,
    cx: &mut Counters,
) -> SurfaceShade {
    let started = cx.clock();
    let v = -d;
    // Grazing views can see a facet from behind; tilt its normal toward the viewer just enough.
    let mut n = normal;
    let cos_v = v.dot(n);
    if cos_v < 1e-3 {
        n = (n + (1e-3 - cos_v) * v).normalize();
    }
    let cos_v = v.dot(n).max(1e-3);
    // Local wind frame: z along the normal, x downwind.
    let x = (world.wind - world.wind.dot(n) * n).normalize_or(n.any_orthonormal_vector());
    let y = n.cross(x);
    let to_local = |a: DVec3| DVec3::new(a.dot(x), a.dot(y), a.dot(n));
    // The sky is looked up once, at the mirror direction of the resolved facet, through the
    // reflection lobe of the unresolved waves (brine-sky `FilteredSky`, a Gaussian of twice their
    // slope deviation: reflection doubles the facets' tilt), and weighted by the reflectance of
    // the rough surface they make: the exact Fresnel factor times R(θ_v, σ_v)/R(θ_v, 0) of
    // Bruneton et al.'s integral (brine-optics `RoughReflectance`), so that the distant, rough sea
    // is no mirror at grazing views. The filter is normalised: a uniform sky reflects as before.
    let sigma_v = variance.along(to_local(v)).sqrt();
    let f = (fresnel_dielectric(cos_v, 1.0, WATER_IOR)
        * crate::world::rough_reflectance().roughness_factor(cos_v, sigma_v))
    .clamp(0.0, 1.0);
    let mut r = reflect(d, n);
    if r.y < 1e-3 {
        // A reflection pointing into the sea would hit another wave; take the horizon sky.
        r = DVec3::new(r.x, 1e-3, r.z).normalize();
    }
    let lobe = 2.0 * (0.5 * (variance.sigma_x2() + variance.sigma_y2())).sqrt();
    let sky = world.filtered_sky.radiance(r, lobe, |r| world.sky.radiance_rgb(r));
    // Sun glint and moon glitter through the BRDF of the unresolved slopes (brine-optics
    // `reflected_source_radiance`: a point source or the disc's integral, as the disc's image needs).
    let glint = |disc: &brine_sky::Disc, rules: &SunDisc| {
        let l = disc.direction;
        if l.dot(n) > 0.0 && disc.irradiance_rgb != DVec3::ZERO {
            let r = reflected_source_radiance(to_local(v), to_local(l), variance, 1.0, rules);
            disc.irradiance_rgb * r
        } else {
            DVec3::ZERO
        }
    };
    let light = DirectLight::at(world, p);
    let sun_glint = glint(world.sky.sun(), &world.discs.0);
    let luminance = |c: DVec3| c.dot(DVec3::new(0.2126, 0.7152, 0.0722));
    let sun_irradiance = luminance(world.sky.sun().irradiance_rgb);
    let glint_aov = if sun_irradiance > 0.0 { luminance(sun_glint) / sun_irradiance } else { 0.0 };
    let sun = sun_glint * light.sun
        + world.sky.moon().zip(world.discs.1.as_ref()).map_or(DVec3::ZERO, |(m, d)| glint(m, d)) * light.moon;
    cx.lap(Stage::Surface, started);
    let started = cx.clock();
    let below = match refract(d, n, 1.0, WATER_IOR) {
        Some(t) => water_column_radiance(world, p, t, light, cx),
        None => DVec3::ZERO,
    };
    cx.lap(Stage::Water, started);
    let started = cx.clock();
    let crest = crest_radiance(world, field, p, v, n, cx) * light.sun;
    cx.lap(Stage::Subsurface, started);
    let sea = f * sky + sun + (1.0 - f) * below / (WATER_IOR * WATER_IOR) + crest;
    let started = cx.clock();
    let shade = white_water(world, p, d, t, normal, sea, light);
    cx.lap(Stage::WhiteWater, started);
    SurfaceShade { glint: glint_aov, ..shade }
}

/// Foam (Darles et al. 2007 §4.1, Koepke 1984) and active whitecaps (Dupuy & Bruneton 2012) over
/// the sea radiance at `p`, seen along `d` from `t` metres.
fn white_water(world: &World, p: DVec3, d: DVec3, t: f64, n: DVec3, sea: DVec3, light: DirectLight) -> SurfaceShade {
    let mut shade = SurfaceShade { radiance: sea, foam: 0.0, whitecap: 0.0, glint: 0.0 };
    if world.foam.is_none() && world.whitecaps.is_none() && world.white_water.is_none() {
        return shade;
    }
    // Pixel footprint on the sea: the pixel's angle at distance t, stretched by the grazing view
    // (geometric mean of the two axes); a Gaussian footprint of the same area has σ = ℓ/√12.
    let footprint = t * world.camera.pixel_angle() / d.y.abs().max(0.05).sqrt();
    let sun = world.sky.sun();
    let cos_sun = n.dot(sun.direction);
    let e_sky = world.sky.horizontal_irradiance_rgb();
    let e_moon = world.sky.moon().map_or(DVec3::ZERO, |m| m.irradiance_rgb * n.dot(m.direction).max(0.0)) * light.moon;
    let e_sun = sun.irradiance_rgb * light.sun;
    let lambert = |r: f64| -> DVec3 {
        let f = |c: usize| brine_foam::foam_radiance(r, e_sun[c], cos_sun, e_sky[c] + e_moon[c]);
        DVec3::new(f(0), f(1), f(2))
    };
    let cover = world.cover_at(p, n, footprint);
    if let Some((white, brightness)) = cover.memory {
        // Fresh foam (Koepke's R_f) where the crest breaks, dimming with the foam's age; ageing
        // foam thins (Koepke's falling reflectance): the water shows through it. Thick foam in
        // a lace is brighter than the mean (brightness above 1): opaque, and more reflective.
        let c = white * brightness;
        if c > 0.0 {
            shade.radiance = shade.radiance * (1.0 - c.min(white)) + lambert(FRESH_FOAM_REFLECTANCE) * c;
        }
    }
    if let Some(foam) = &world.foam {
        shade.radiance = shade.radiance * (1.0 - cover.foam) + lambert(foam.reflectance) * cover.foam;
    }
    if world.whitecaps.is_some() {
        shade.radiance = shade.radiance * (1.0 - cover.whitecap) + lambert(WHITECAP_REFLECTANCE) * cover.whitecap;
    }
    shade.foam = cover.foam;
    shade.whitecap = cover.whitecap;
    shade
}

/// Longest path through a crest followed for the dipole (m): beyond it the light is gone.
const MAX_CREST_THICKNESS_M: f64 = 8.0;

/// Sun light through a thin crest (Jensen et al. 2001 dipole, brine-optics `crest_radiance`):
/// the crest's thickness is the distance from `p` back along the sun's ray refracted by a level
/// surface to where it entered the water, found by tracing inside the water with the same tracer.
fn crest_radiance(world: &World, field: &SeaField<'_>, p: DVec3, v: DVec3, n: DVec3, cx: &mut Counters) -> DVec3 {
    let Some(materials) = &world.crest else { return DVec3::ZERO };
    let sun = world.sky.sun();
    let l = sun.direction;
    if sun.irradiance_rgb == DVec3::ZERO || l.dot(n) > 0.2 {
        return DVec3::ZERO;
    }
    let Some(t_sun) = refract(-l, DVec3::Y, 1.0, WATER_IOR) else { return DVec3::ZERO };
    let Ok(ray) = Ray::new(p - 1e-3 * n, -t_sun) else { return DVec3::ZERO };
    let Some(exit) = field.trace_within(&ray, MAX_CREST_THICKNESS_M, world, &mut cx.secondary) else {
        return DVec3::ZERO;
    };
    let n_entry = field.normal(exit.point, -t_sun, 0.0, world);
    let cos_i = l.dot(n_entry);
    if cos_i <= 0.0 {
        return DVec3::ZERO;
    }
    let cos_o = v.dot(n).clamp(0.0, 1.0);
    let e = sun.irradiance_rgb;
    DVec3::new(
        materials[0].crest_radiance(e.x, cos_i, cos_o, exit.t),
        materials[1].crest_radiance(e.y, cos_i, cos_o, exit.t),
        materials[2].crest_radiance(e.z, cos_i, cos_o, exit.t),
    )
}

/// Diffuse radiance of the water body at depth `z` (m), `L_df(0) e^{−K_d z}`, toward a camera
/// under water: the in-water "background" (docs/equations.md §7, isotropic approximation).
fn water_background(world: &World, z: f64) -> DVec3 {
    let l0 = world.water.diffuse_upwelling_radiance(world.e_below);
    l0 * (-world.water.k_d * z.max(0.0)).exp()
}

/// Radiance reaching a camera under water along `d`: the underside of the surface (Snell's window:
/// the sky refracted through the surface inside the critical angle, total internal reflection of
/// the water outside it) or the floor, attenuated by `e^{−c s}` over the path and filled in by the
/// background radiance at the camera's depth (single-scattering equilibrium approximation).
fn underwater_radiance(
    world: &World,
    field: &SeaField<'_>,
    d: DVec3,
    surface: Option<(f64, DVec3)>,
    cx: &mut Counters,
) -> Sample {
    let origin = world.camera.position;
    let z_cam = -origin.y;
    let background = water_background(world, z_cam);
    let (s, source, aov) = if let Some((t, p)) = surface {
        let n = field.normal(p, d, t, world);
        let window = brine_optics::SnellWindow::new(d, n);
        let above = match window.refracted {
            Some(tr) => sky_radiance(world, if tr.y > 1e-3 { tr } else { DVec3::new(tr.x, 1e-3, tr.z).normalize() }),
            None => DVec3::ZERO,
        };
        let l = window.radiance(above, water_background(world, 0.0));
        (t, l, Aov { depth: t as f32, normal: (-n).as_vec3().to_array(), ..Aov::default() })
    } else if let Some((t, q)) = floor_hit(world, origin, d, cx) {
        (
            t,
            floor_radiance(world, q, DirectLight::at(world, q)),
            Aov { depth: t as f32, normal: [0.0, 1.0, 0.0], ..Aov::default() },
        )
    } else {
        return Sample { radiance: background, aov: Aov { depth: f32::INFINITY, ..Aov::default() }, weight: 1.0 };
    };
    let transmittance = (-world.water.c * s).exp();
    Sample { radiance: source * transmittance + background * (DVec3::ONE - transmittance), aov, weight: 1.0 }
}

/// Smallest `|d_y|` of the pixel footprint's stretch `1/√|d_y|` on the sea (the FFT fading's).
const MIN_FOOTPRINT_GRAZING: f64 = 0.05;

/// The sea of a frame ready to trace (brine-waves `TracedSea`), with the renderer's choices of
/// options: primary rays by the tiered method with the waves fading with the pixel footprint,
/// secondary rays with every wave.
pub(crate) struct SeaField<'a> {
    sea: TracedSea<'a>,
}

impl<'a> SeaField<'a> {
    fn new(world: &'a World) -> Self {
        Self { sea: world.sea.traced() }
    }

    /// The options of a primary ray: the tiered method, the waves faded by the pixel's angle.
    fn primary_options(world: &World) -> TraceOptions {
        TraceOptions { method: Method::Tiered, footprint_angle: world.filtering_angle(), ..world.trace }
    }

    /// Traces a primary ray (the waves fade with the pixel footprint).
    #[cfg(test)]
    fn trace_primary(&self, ray: &Ray, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &Self::primary_options(world), stats)
    }

    /// Traces a secondary ray (every wave).
    #[cfg(test)]
    fn trace_secondary(&self, ray: &Ray, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &world.trace, stats)
    }

    /// Traces the primary rays of a tile (`width` per row) from the camera, with footprint fading;
    /// the trochoid and FFT seas share cones among the rays (image coherence), the others trace
    /// ray by ray.
    fn trace_tile(&self, world: &World, tile: &mut TileRays, width: usize, stats: &mut TraceStats) {
        let n = tile.directions.len();
        tile.hits.clear();
        tile.hits.resize(n, None);
        tile.costs.clear();
        tile.costs.resize(n, 0.0);
        let options = Self::primary_options(world);
        let rays = RayTile { origin: world.camera.position, directions: &tile.directions, width };
        self.sea.trace_tile(&rays, &options, stats, &mut tile.hits, &mut tile.costs);
    }

    /// Traces a secondary ray up to `t_max` metres.
    fn trace_within(&self, ray: &Ray, t_max: f64, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &TraceOptions { t_max, ..world.trace }, stats)
    }

    /// Upward unit normal of the surface as drawn at `p`, hit `t` metres along `d` (the faded
    /// waves of a primary ray are left out; `t = 0` keeps every wave).
    fn normal(&self, p: DVec3, d: DVec3, t: f64, world: &World) -> DVec3 {
        let angle = if t > 0.0 { world.filtering_angle() } else { 0.0 };
        let g = self.sea.faded_gradient(p.x, p.z, d, angle, t);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// The shading normal and the BRDF slope variances (the unresolved waves' plus those the
    /// tracer faded, Bruneton et al. 2010's seamless transition, in the wind frame) at a
    /// primary hit `t` along `d`, in one pass over the waves where the surface allows it.
    ///
    /// The detail normals (the waves between the traced band and the pixel) add their gradient,
    /// read through the pixel's footprint, and the slopes the footprint hides join the BRDF's.
    fn hit_geometry(&self, p: DVec3, d: DVec3, t: f64, world: &World) -> (DVec3, SlopeVariance) {
        let angle = world.filtering_angle();
        // The pixel's side on the sea, the geometric mean of its two axes (as the fading's).
        let footprint = angle * t / d.y.abs().max(MIN_FOOTPRINT_GRAZING).sqrt();
        let (mut g, mut c) = match (&self.sea, &world.fft_slopes) {
            // The FFT cascades read through the footprint (LEAN mapping) rather than faded whole.
            (TracedSea::Fft(_), Some(lean)) => {
                let l = lean.filtered(p.x, p.z, footprint / brine_waves::BOX_WIDTH_PER_SIGMA);
                (l.gradient, l.covariance)
            }
            _ => self.sea.faded_gradient_and_covariance(p.x, p.z, d, angle, t),
        };
        if let Some(detail) = &world.detail {
            let f = detail.filtered(p.x, p.z, footprint / brine_waves::BOX_WIDTH_PER_SIGMA);
            g += f.gradient;
            c += f.covariance;
        }
        (DVec3::new(-g.x, 1.0, -g.y).normalize(), Self::variance_with(world, c))
    }

    /// The unresolved variances plus a faded world-axes covariance `c = (xx, xz, zz)`, in the wind
    /// frame.
    fn variance_with(world: &World, c: DVec3) -> SlopeVariance {
        if c == DVec3::ZERO {
            return world.variance_unresolved;
        }
        let (wx, wz) = (world.wind.x, world.wind.z);
        let along = c.x * wx * wx + 2.0 * c.y * wx * wz + c.z * wz * wz;
        let across = c.x * wz * wz - 2.0 * c.y * wx * wz + c.z * wx * wx;
        let v = &world.variance_unresolved;
        SlopeVariance::new(v.sigma_x2() + along.max(0.0), v.sigma_y2() + across.max(0.0)).unwrap_or(*v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    /// f32 depth AOVs and the f64 hit differ by rounding only; the hit itself is within the trace
    /// tolerance of the first crossing for either start, so two hits are within twice it.
    const HITS_AGREE_TOLERANCES: f64 = 2.0;

    /// Facets of zero-mean slopes on a tilted surface keep its projected area on average: the
    /// weights of the reference's detail normals average to 1 (here over a symmetric grid of
    /// slopes small enough that no facet turns away from the viewer, where the mean is exact).
    #[test]
    fn detail_facets_keep_the_projected_area() {
        const ROUNDING: f64 = 1e-12;
        let g = DVec3::new(0.2, 1.0, -0.1).normalize();
        let (t1, t2) = (g.any_orthonormal_vector(), g.cross(g.any_orthonormal_vector()));
        for v in [DVec3::new(0.0, 0.3, 1.0).normalize(), DVec3::new(0.5, 0.8, -0.3).normalize()] {
            let (mut sum, mut n) = (0.0, 0);
            for i in -10..=10 {
                for j in -10..=10 {
                    let (a, b) = (0.01 * f64::from(i), 0.01 * f64::from(j));
                    let facet = (g - a * t1 - b * t2).normalize();
                    sum += projected_area_weight(v, facet, g);
                    n += 1;
                }
            }
            assert!((sum / f64::from(n) - 1.0).abs() < ROUNDING, "{v}: mean weight {}", sum / f64::from(n));
        }
    }

    /// Image coherence changes only where each primary ray starts tracing: a tile's hits are the
    /// hits of its rays traced one by one (the same first crossing, each refined to the trace
    /// tolerance), and its misses are theirs.
    #[test]
    fn tiled_primary_hits_are_the_hits_of_each_ray_alone() {
        for surface in [crate::scene::SurfaceKind::Trochoids, crate::scene::SurfaceKind::Fft] {
            tiles_match_single_rays(surface);
        }
    }

    fn tiles_match_single_rays(surface: crate::scene::SurfaceKind) {
        let mut scene = Scene::default_scene();
        scene.camera.width = 640;
        scene.camera.height = 480;
        scene.sea.surface = surface;
        let world = World::new(&scene).expect("the default scene is valid");
        let field = SeaField::new(&world);
        let (mut hits, mut misses) = (0, 0);
        // Tiles across the image: the sky, the horizon, mid-distance and the foreground.
        for (x0, y0) in [(0, 0), (312, 150), (600, 156), (100, 170), (400, 300), (200, 460)] {
            let mut tile = TileRays::default();
            for y in 0..TILE {
                for x in 0..TILE {
                    tile.directions.push(world.camera.direction((x0 + x) as f64 + 0.5, (y0 + y) as f64 + 0.5));
                }
            }
            field.trace_tile(&world, &mut tile, TILE, &mut TraceStats::default());
            for (d, tiled) in tile.directions.iter().zip(&tile.hits) {
                let ray = Ray::new(world.camera.position, *d).expect("unit direction");
                let alone = field.trace_primary(&ray, &world, &mut TraceStats::default());
                match (tiled, alone) {
                    (Some(a), Some(b)) => {
                        let tol = HITS_AGREE_TOLERANCES * world.trace.tolerance_at(b.t);
                        assert!((a.t - b.t).abs() <= tol, "tile ({x0}, {y0}): {} vs {} alone", a.t, b.t);
                        hits += 1;
                    }
                    (None, None) => misses += 1,
                    (a, b) => panic!("tile ({x0}, {y0}), direction {d}: tiled {a:?}, alone {b:?}"),
                }
            }
        }
        assert!(hits > 800 && misses > 100, "{hits} hits, {misses} misses: the tiles should see sea and sky");
    }

    /// Gerstner and sine seas fade their short waves with the pixel footprint, as the trochoid and
    /// FFT seas do: their primary rays (toward the horizon, where a pixel covers metres) cost far
    /// fewer evaluations of the sea than the same rays traced with every wave, and the slopes the
    /// geometry lost reach the BRDF.
    #[test]
    fn gerstner_and_sine_primary_rays_fade_with_the_footprint() {
        for surface in [crate::scene::SurfaceKind::Gerstner, crate::scene::SurfaceKind::Sine] {
            let mut scene = Scene::default_scene();
            (scene.camera.width, scene.camera.height) = (160, 90);
            scene.sea.surface = surface;
            scene.sea.waves = 120;
            let mut world = World::new(&scene).expect("a valid scene");
            // Without the detail normals, whose hidden slopes would reach the BRDF as well.
            world.detail = None;
            let field = SeaField::new(&world);
            let (mut faded, mut whole) = (TraceStats::default(), TraceStats::default());
            let mut lost = 0.0;
            // The rows from just below the horizon down to mid-image.
            for y in (46..70).step_by(3) {
                for x in (0..160).step_by(8) {
                    let d = world.camera.direction(f64::from(x) + 0.5, f64::from(y) + 0.5);
                    let ray = Ray::new(world.camera.position, d).expect("unit direction");
                    if let Some(h) = field.trace_primary(&ray, &world, &mut faded) {
                        let v = field.hit_geometry(h.point, d, h.t, &world).1;
                        lost += v.sigma_x2() + v.sigma_y2()
                            - world.variance_unresolved.sigma_x2()
                            - world.variance_unresolved.sigma_y2();
                    }
                    field.trace_secondary(&ray, &world, &mut whole);
                }
            }
            assert!(
                (faded.evaluations as f64) < 0.5 * whole.evaluations as f64,
                "{surface:?}: {} evaluations faded, {} whole",
                faded.evaluations,
                whole.evaluations
            );
            assert!(lost > 0.0, "{surface:?}: the faded slopes reach the BRDF");
        }
    }

    /// The detail normals reach the picture: over the near field the shading normals' slope
    /// variance grows by a tenth of the detail band's or more (at 12 m/s the band runs from 85 cm
    /// to 1 cm waves; a 5 cm pixel, read through a mip pyramid, shows the waves above about
    /// 15 cm: 17 % of the band measured), and what each pixel draws plus what it hands to the BRDF
    /// is the whole band (one random draw of the waves over a few hundred pixels: 25 %).
    #[test]
    fn detail_normals_shade_the_near_field_and_keep_their_slopes() {
        const DRAW_REL: f64 = 0.25;
        let mut scene = Scene::default_scene();
        (scene.camera.width, scene.camera.height) = (320, 180);
        scene.camera.pitch_deg = Some(-30.0);
        scene.sea.wind_speed_m_s = 12.0;
        let with = World::new(&scene).expect("a valid scene");
        let mut without = World::new(&scene).expect("a valid scene");
        without.detail = None;
        let expected = with.detail.as_ref().expect("a detail band").expected_slope_covariance();
        let field = SeaField::new(&with);
        let mut slopes = (Vec::new(), Vec::new());
        let mut kept = 0.0;
        for y in (120..180).step_by(4) {
            for x in (0..320).step_by(8) {
                let d = with.camera.direction(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let ray = Ray::new(with.camera.position, d).expect("unit direction");
                let Some(h) = field.trace_primary(&ray, &with, &mut TraceStats::default()) else { continue };
                let slope = |n: DVec3| DVec2::new(-n.x / n.y, -n.z / n.y);
                let (n1, v1) = field.hit_geometry(h.point, d, h.t, &with);
                let (n0, v0) = field.hit_geometry(h.point, d, h.t, &without);
                let drawn = slope(n1) - slope(n0);
                kept += drawn.length_squared() + (v1.sigma_x2() + v1.sigma_y2()) - (v0.sigma_x2() + v0.sigma_y2());
                slopes.0.push(slope(n1));
                slopes.1.push(slope(n0));
            }
        }
        let variance = |s: &[DVec2]| {
            let m = s.iter().copied().sum::<DVec2>() / s.len() as f64;
            s.iter().map(|v| (*v - m).length_squared()).sum::<f64>() / s.len() as f64
        };
        let n = slopes.0.len() as f64;
        assert!(n > 200.0, "{n} near-field hits");
        let gain = variance(&slopes.0) - variance(&slopes.1);
        // The unresolved variance of the world without detail is not raised here, so `kept`
        // counts the detail band once: drawn slopes plus the hidden covariance.
        approx::assert_relative_eq!(kept / n, expected.x + expected.z, max_relative = DRAW_REL);
        assert!(gain > 0.1 * (expected.x + expected.z), "drawn {gain}, band {}", expected.x + expected.z);
    }
}
