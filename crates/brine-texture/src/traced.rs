//! Beyond the paper (its stated future work): the composed height field ray traced with
//! brine-trace and shaded with the renderer's sky, sun specular and refraction onto a bed.

use brine_optics::{
    JerlovType, RgbBands, SlopeVariance, WATER_IOR, WaterBody, WaterRgb, fresnel_dielectric,
    hemispherical_fresnel_reflectance, radiance_out_of_water, reflect, reflected_sun_radiance, refract,
};
use brine_sky::{Sky, SkyParams};
use brine_trace::{Aabb, LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace};
use glam::{DVec2, DVec3};
use palette::{LinSrgb, Srgb};
use rayon::prelude::*;

use crate::error::check;
use crate::{HeightField, OceanFrame, PhotoOcean, Pinhole, TextureError};

/// The composed height field of one frame as an implicit function for brine-trace:
/// `F(p) = y − [(P_h(u, v) − P̄_h) + (M_h(u_m, v_m) − M̄_h)]`, three components:
/// `n₀ = y` (`L₀ = 1`), `n₁ = −(P_h − P̄_h)` and `n₂ = −(M_h − M̄_h)`, each bilinear in its texels.
///
/// The Lipschitz constant of a bilinear height field is its largest gradient norm
/// ([`HeightField::max_gradient`], per texel) divided by the texel size in metres; along a
/// direction `d̂` it is at most `(A_max |d_x| + B_max |d_z|)/texel`, `A_max`, `B_max` the largest
/// neighbour differences along x and z.
#[derive(Debug, Clone, Copy)]
pub struct ComposedSurface<'a> {
    small: &'a HeightField,
    main: &'a HeightField,
    inv_texel: f64,
    inv_main_texel: f64,
    small_offset: DVec2,
    main_offset: DVec2,
}

impl<'a> ComposedSurface<'a> {
    /// The surface of a frame.
    pub fn of(frame: &'a OceanFrame<'_>) -> Self {
        let s0 = frame.small_uv(0.0, 0.0);
        let m0 = frame.main_uv(0.0, 0.0);
        let p = frame.ocean().params();
        Self {
            small: frame.small.height(),
            main: frame.ocean().main_height(),
            inv_texel: 1.0 / p.texel_m,
            inv_main_texel: 1.0 / (p.texel_m * p.scale),
            small_offset: s0,
            main_offset: m0,
        }
    }

    /// A surface from two height fields (m) with texel sizes `texel_m` and `main_texel_m` (m), no
    /// shift (for tests and other uses).
    pub fn new(small: &'a HeightField, main: &'a HeightField, texel_m: f64, main_texel_m: f64) -> Self {
        Self {
            small,
            main,
            inv_texel: 1.0 / texel_m,
            inv_main_texel: 1.0 / main_texel_m,
            small_offset: DVec2::ZERO,
            main_offset: DVec2::ZERO,
        }
    }

    /// Height of the surface above `(x, z)` relative to the mean level (m).
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        -self.component(1, DVec3::new(x, 0.0, z)) - self.component(2, DVec3::new(x, 0.0, z))
    }

    /// Lowest and highest possible height (m).
    pub fn height_range(&self) -> (f64, f64) {
        let (s, m) = (self.small, self.main);
        (s.min() - s.mean() + m.min() - m.mean(), s.max() - s.mean() + m.max() - m.mean())
    }

    #[inline]
    fn field(&self, i: usize) -> (&HeightField, f64, DVec2) {
        if i == 1 {
            (self.small, self.inv_texel, self.small_offset)
        } else {
            (self.main, self.inv_main_texel, self.main_offset)
        }
    }
}

impl LipschitzSum for ComposedSurface<'_> {
    fn component_count(&self) -> usize {
        3
    }

    #[inline]
    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 {
            return p.y;
        }
        let (f, inv, off) = self.field(i);
        -(f.sample(p.x * inv + off.x, p.z * inv + off.y) - f.mean())
    }

    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 {
            return 1.0;
        }
        let (f, inv, _) = self.field(i);
        f.max_gradient() * inv
    }

    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 {
            return d.y.abs();
        }
        let (f, inv, _) = self.field(i);
        ((f.max_du() * d.x.abs() + f.max_dv() * d.z.abs()) * inv).min(f.max_gradient() * inv)
    }

    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 {
            return a.y.min(b.y);
        }
        let (f, _, _) = self.field(i);
        -(f.max() - f.mean())
    }

    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 {
            return a.y.max(b.y);
        }
        let (f, _, _) = self.field(i);
        -(f.min() - f.mean())
    }

    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { 1.0 / self.field(i).1 }
    }

    #[inline]
    fn value(&self, p: DVec3) -> f64 {
        p.y + self.component(1, p) + self.component(2, p)
    }

    fn zero_set_bounds(&self) -> Aabb {
        let (lo, hi) = self.height_range();
        Aabb::slab_y(lo, hi)
    }
}

/// Parameters of the traced mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TracedParams {
    /// Atmospheric turbidity `T`, `[1.7, 10]`.
    pub turbidity: f64,
    /// Unit direction toward the sun (y up).
    pub sun_direction: DVec3,
    /// Wind speed 10 m above the sea (m/s), `[0, 60]`: the Cox–Munk slope variance of the waves
    /// smaller than a texel (minus the texture's resolved slopes) shapes the sun's highlight.
    pub wind_speed_m_s: f64,
    /// The water body (its colour, attenuation and reflectance).
    pub water: WaterBody,
    /// Depth of the bed plane below sea level (m), `(0, 1000]`; used when the ocean has a bed.
    pub bed_depth_m: f64,
    /// Distance up to which the surface is traced (m), `[1, 10⁶]`; beyond it, its mean plane.
    pub max_distance_m: f64,
    /// Aerial perspective between the eye and the sea (Hoffman & Preetham 2002, brine-sky).
    pub aerial_perspective: bool,
}

impl Default for TracedParams {
    fn default() -> Self {
        Self {
            turbidity: 3.0,
            sun_direction: DVec3::new(0.3, 0.45, -0.84).normalize(),
            wind_speed_m_s: 6.0,
            water: WaterBody::jerlov(JerlovType::IB),
            bed_depth_m: 2.0,
            max_distance_m: 2000.0,
            aerial_perspective: true,
        }
    }
}

/// Everything the traced shading needs, built once per ocean and sky.
#[derive(Debug, Clone)]
pub struct TracedScene {
    /// The sky and sun.
    pub sky: Sky,
    /// Water optics per channel.
    pub water: WaterRgb,
    /// Downwelling irradiance just below a flat surface (klx per channel).
    pub e_below: DVec3,
    /// Slope variance of the waves smaller than a texel (the BRDF's).
    pub variance: SlopeVariance,
    /// Slope variance of the whole sea (for the mean plane beyond the traced distance).
    pub variance_total: SlopeVariance,
    /// Unit horizontal direction of the BRDF's x axis (the main structure's motion).
    pub wind: DVec3,
    /// Mean linear colour of the small-wave texture (the body-colour modulation's unit).
    pub mean_linear: DVec3,
    /// The parameters.
    pub params: TracedParams,
}

/// Linear value of an 8-bit sRGB level in `[0, 255]`.
#[inline]
fn linear(level: f32) -> f64 {
    let s = Srgb::new(level / 255.0, 0.0, 0.0);
    let l: LinSrgb = s.into_linear();
    f64::from(l.red)
}

/// Linear colour of a texel.
#[inline]
fn linear_rgb(c: [f32; 3]) -> DVec3 {
    DVec3::new(linear(c[0]), linear(c[1]), linear(c[2]))
}

impl TracedScene {
    /// Builds the sky (brine-sky, `Sky::new(&SkyParams::new(T, sun))`), the water optics and the
    /// slope variances for `ocean`.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] for a parameter out of range (the sky's and the BRDF's
    /// messages are passed through).
    pub fn new(params: &TracedParams, ocean: &PhotoOcean) -> Result<Self, TextureError> {
        let bad = |name, value, range| TextureError::OutOfRange(brine_core::OutOfRange { name, value, range });
        check(
            "bed_depth_m",
            params.bed_depth_m,
            params.bed_depth_m > 0.0 && params.bed_depth_m <= 1000.0,
            "(0, 1000] m",
        )?;
        check("max_distance_m", params.max_distance_m, (1.0..=1e6).contains(&params.max_distance_m), "[1, 10⁶] m")?;
        let sky = Sky::new(&SkyParams::new(params.turbidity, params.sun_direction))
            .map_err(|_| bad("turbidity", params.turbidity, "[1.7, 10], with a finite non-zero sun direction"))?;
        let variance_total = SlopeVariance::cox_munk_clean(params.wind_speed_m_s)
            .map_err(|_| bad("wind_speed_m_s", params.wind_speed_m_s, "[0, 60] m/s"))?;
        let p = ocean.params();
        let v = DVec2::from_array(p.main_velocity_m_s);
        let w2 = if v.length() > 0.0 { v.normalize() } else { DVec2::X };
        let wind = DVec3::new(w2.x, 0.0, w2.y);
        // Resolved slope variances of the texture's heights along and across the wind.
        let f0 = &ocean.basis_frames()[0];
        let (mgu, mgv) = ocean.main_height().grid().central_gradients();
        let (mut rx, mut ry) = (0.0, 0.0);
        let n = f0.grad_u().values().len();
        for k in 0..n {
            let g = DVec2::new(f64::from(f0.grad_u().values()[k]), f64::from(f0.grad_v().values()[k])) / p.texel_m;
            rx += g.dot(w2).powi(2);
            ry += g.perp_dot(w2).powi(2);
        }
        let (mut mx, mut my) = (0.0, 0.0);
        let nm = mgu.values().len();
        for k in 0..nm {
            let g = DVec2::new(f64::from(mgu.values()[k]), f64::from(mgv.values()[k])) / (p.texel_m * p.scale);
            mx += g.dot(w2).powi(2);
            my += g.perp_dot(w2).powi(2);
        }
        let variance = variance_total.minus(rx / n as f64 + mx / nm as f64, ry / n as f64 + my / nm as f64);
        let water = WaterRgb::new(&params.water, RgbBands::SrgbAverage);
        let sun = sky.sun();
        let c = sun.direction.y.max(0.0);
        let e_below = sun.irradiance_rgb * c * (1.0 - fresnel_dielectric(c, 1.0, WATER_IOR))
            + sky.horizontal_irradiance_rgb() * (1.0 - hemispherical_fresnel_reflectance(1.0, WATER_IOR));
        let mean = f0.colour.texels().iter().fold(DVec3::ZERO, |a, t| a + linear_rgb(*t)) / n as f64;
        Ok(Self {
            sky,
            water,
            e_below,
            variance,
            variance_total,
            wind,
            mean_linear: mean.max(DVec3::splat(1e-6)),
            params: *params,
        })
    }

    /// Sun radiance reflected toward `v` by a facet of normal `n` (Bruneton et al. 2010 BRDF of
    /// the unresolved slopes), per channel.
    fn sun_specular(&self, v: DVec3, n: DVec3, variance: &SlopeVariance) -> DVec3 {
        let sun = self.sky.sun();
        if sun.irradiance_rgb == DVec3::ZERO {
            return DVec3::ZERO;
        }
        let x = (self.wind - n * self.wind.dot(n)).normalize_or(n.any_orthonormal_vector());
        let y = n.cross(x);
        let local = |a: DVec3| DVec3::new(a.dot(x), a.dot(y), a.dot(n));
        sun.irradiance_rgb * reflected_sun_radiance(local(v), local(sun.direction), variance, 1.0)
    }
}

/// A traced frame: linear sRGB radiance (kcd m⁻²), row-major, top row first.
#[derive(Debug, Clone, PartialEq)]
pub struct TracedImage {
    /// Width (pixels).
    pub width: u32,
    /// Height (pixels).
    pub height: u32,
    /// Radiance per pixel.
    pub pixels: Vec<DVec3>,
    /// Tracer counters.
    pub stats: TraceStats,
}

/// Ray traces a frame: each pixel's ray is sphere traced against the composed height field
/// ([`ComposedSurface`], `Method::Directional` of brine-trace) and shaded with
///
/// `L = F(θ) L_sky(r) + L_sun + (1 − F) L_w/n²`,
///
/// `F` exact Fresnel at the traced normal, `r` the mirror direction (brine-sky's sky),
/// `L_sun` the sun through the Bruneton ocean BRDF of the slopes finer than a texel, and `L_w`
/// the water leaving radiance below the surface along the refracted ray (brine-optics): the
/// diffuse upwelling radiance `R E_d/π` modulated by the texture's colour
/// (`linear(S_c)/mean(linear(P_c))`, the photo as the spatial pattern of the water's colour),
/// and with a bed the Lambertian bed texture at the refracted ray's end attenuated by `e^{−c s}`
/// (their Fig. 9). Aerial perspective between the eye and the sea when enabled.
///
/// # Arguments
/// - `frame`: the frame (its composed surface, colour and bed).
/// - `camera`: the camera, above the highest wave of the composed surface.
/// - `scene`: sky, water and slope variances ([`TracedScene::new`]).
///
/// # Returns
/// Linear sRGB radiance per pixel (kcd m⁻², finite, `≥ 0`) and the tracer's counters.
///
/// # Errors
/// [`TextureError::OutOfRange`] if the camera is not above the highest wave.
///
/// # References
/// Lai & Wu §V (ray marching and specular named as future work), Fig. 9; Hart 1996 (sphere
/// tracing); Bruneton, Neyret & Holzschuch 2010 (BRDF); Premoze & Ashikhmin 2001 (water).
pub fn render_traced(
    frame: &OceanFrame<'_>,
    camera: &Pinhole,
    scene: &TracedScene,
) -> Result<TracedImage, TextureError> {
    let surface = ComposedSurface::of(frame);
    let (_, hi) = surface.height_range();
    let o = camera.position;
    check("camera.position.y", o.y, o.y > hi, "above the highest wave of the composed surface")?;
    let options = TraceOptions {
        method: Method::Directional,
        t_max: scene.params.max_distance_m,
        min_step: 1e-3,
        min_step_relative: 1e-4,
        tolerance: 1e-4,
        tolerance_relative: 1e-6,
        ..TraceOptions::default()
    };
    let (w, h) = (camera.width, camera.height);
    let alpha = camera.pixel_angle();
    let rows: Vec<(Vec<DVec3>, TraceStats)> = (0..h)
        .into_par_iter()
        .map(|j| {
            let mut stats = TraceStats::default();
            let row = (0..w)
                .map(|i| {
                    let d = camera.direction(f64::from(i) + 0.5, f64::from(j) + 0.5);
                    shade(frame, &surface, scene, &options, (o, d, alpha), &mut stats)
                })
                .collect();
            (row, stats)
        })
        .collect();
    let mut stats = TraceStats::default();
    let mut pixels = Vec::with_capacity((w * h) as usize);
    for (row, s) in rows {
        pixels.extend(row);
        stats.merge(&s);
    }
    Ok(TracedImage { width: w, height: h, pixels, stats })
}

/// Radiance toward the eye along one primary ray.
fn shade(
    frame: &OceanFrame<'_>,
    surface: &ComposedSurface<'_>,
    scene: &TracedScene,
    options: &TraceOptions,
    (o, d, alpha): (DVec3, DVec3, f64),
    stats: &mut TraceStats,
) -> DVec3 {
    let sky = &scene.sky;
    let ray = Ray::new(o, d).expect("unit camera direction");
    let (point, normal, variance, dist) = match trace(surface, &ray, options, stats) {
        Some(hit) => (hit.point, frame.normal(hit.point.x, hit.point.z), scene.variance, hit.t),
        None if d.y < -1e-9 => {
            // Beyond the traced distance: the mean plane with the slopes of the whole sea.
            let t = -o.y / d.y;
            (o + t * d, DVec3::Y, scene.variance_total, t)
        }
        None => return sky.background_rgb(d),
    };
    let v = -d;
    let cos_i = v.dot(normal).clamp(1e-4, 1.0);
    let f = fresnel_dielectric(cos_i, 1.0, WATER_IOR);
    let mut r = reflect(d, normal);
    if r.y < 0.01 {
        r = DVec3::new(r.x, 0.01, r.z).normalize();
    }
    let reflected = sky.radiance_rgb(r) * f;
    let sun = scene.sun_specular(v, normal, &variance);
    // Light from below: the water's diffuse radiance modulated by the texture, and the bed.
    let colour = linear_rgb(frame.colour_filtered(point.x, point.z, dist * alpha / cos_i.sqrt())) / scene.mean_linear;
    let e = scene.e_below;
    let below = match (refract(d, normal, 1.0, WATER_IOR), frame.ocean().bed().is_some()) {
        (Some(t), true) if t.y < -1e-6 => {
            let depth = (point.y + scene.params.bed_depth_m).max(0.0);
            let s = depth / -t.y;
            let bed = frame.bed_colour(point.x + s * t.x, point.z + s * t.z).map_or(DVec3::ZERO, linear_rgb);
            let floor = scene.water.lambertian_floor_radiance(bed, e, scene.params.bed_depth_m);
            scene.water.refracted_ray_radiance(e * colour, -t.y, s, floor)
        }
        _ => scene.water.diffuse_upwelling_radiance(e) * colour,
    };
    let cos_t = refract(d, normal, 1.0, WATER_IOR).map_or(1.0, |t| -t.dot(normal)).clamp(0.0, 1.0);
    let out = DVec3::new(
        radiance_out_of_water(below.x, cos_t, WATER_IOR),
        radiance_out_of_water(below.y, cos_t, WATER_IOR),
        radiance_out_of_water(below.z, cos_t, WATER_IOR),
    );
    let l = reflected + sun + out;
    if scene.params.aerial_perspective {
        let ap = sky.aerial_perspective(o.y.max(0.0), d, dist);
        l * ap.extinction + ap.inscatter
    } else {
        l
    }
}
