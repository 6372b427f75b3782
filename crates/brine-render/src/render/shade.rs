//! The per-pixel composition: what arrives at the camera along one ray — sea surface, white water, water column, floor, crests, atmosphere, spray and sky.

use super::*;

/// Radiance (linear sRGB, kcd m⁻²) arriving at the camera along the unit direction `d` whose
/// primary ray found `hit`, and the sample's output variables.
pub(super) fn radiance(world: &World, field: &SeaField<'_>, d: DVec3, hit: Option<Hit>, cx: &mut Counters) -> Sample {
    let origin = world.camera.position;
    if world.underwater {
        return underwater_radiance(world, field, d, hit.map(|h| (h.t, h.point)), cx);
    }
    let faded;
    let mut weight = 1.0;
    let (t, p, n, facet, variance) = match hit {
        Some(hit) => {
            let (n, v, facet) = field.hit_geometry(hit.point, d, hit.t, world);
            faded = v;
            if world.reference && world.detail.is_some() {
                // The detail normals are not displaced geometry: a sample of the traced surface
                // stands for a facet of area dA/(n·n_g) seen at v·n, against dA seen at v·n_g.
                weight = projected_area_weight(-d, n, field.normal(hit.point, d, 0.0, world));
            }
            (hit.t, hit.point, n, facet, &faded)
        }
        // Beyond the trace distance: the Earth's curved mean sea (brine-core), with every wave's
        // slopes in the BRDF about its tilted normal; the point is on the sea (height 0).
        None if let Some(t) = brine_core::mean_sea_distance(origin.y, d.y) => {
            let p = origin + t * d;
            let n = DVec3::from_array(brine_core::mean_sea_normal(origin.y, d.to_array(), t));
            (t, DVec3::new(p.x, 0.0, p.z), n, n, &world.variance_total)
        }
        None => {
            // The sky's own aerosol is Preetham's turbidity: only the spume layer over the sea is
            // added to sky rays.
            let started = cx.clock();
            let l = spray(world, d, None, sky_radiance(world, d));
            cx.lap(Stage::Sky, started);
            return Sample { radiance: l, aov: Aov { depth: f32::INFINITY, ..Aov::default() }, weight: 1.0 };
        }
    };
    let shade = shade_surface(world, field, &SeenPoint { p, d, t, normal: n, facet }, variance, cx);
    let aov = Aov {
        depth: t as f32,
        normal: n.as_vec3().to_array(),
        foam: shade.foam as f32,
        whitecap: shade.whitecap as f32,
        glint: shade.glint as f32,
        ..Aov::default()
    };
    let started = cx.clock();
    let l = spray(world, d, Some(t), aerial(world, d, t, shade.radiance));
    cx.lap(Stage::Atmosphere, started);
    Sample { radiance: l, aov, weight }
}

/// Sea spray between the eye and the sea `t` metres along `d`, or, for `t = None`, along a ray
/// that leaves the sea behind: Beer–Lambert transmittance and single scattering of sun and sky
/// light by the drops (brine-foam `SprayRay`, Darles et al. 2007 §4.2 corrected). Toward the sea
/// both the bubble drops and the spume count; toward the sky only the spume, a layer a few wave
/// heights deep that the sky model does not hold (its own aerosol is Preetham's turbidity). Drops
/// are much larger than the wavelength, so the extinction is grey; the in-scattered light is the
/// sun's through the phase function and the sky and sea around the drop through the same lobe
/// (brine-foam `PhaseLobeTable`).
pub(super) fn spray(world: &World, d: DVec3, t: Option<f64>, l0: DVec3) -> DVec3 {
    let Some(spray) = &world.spray else { return l0 };
    let y0 = world.camera.position.y.max(0.0);
    let sun = world.sky.sun();
    let scattering = SprayScattering::default();
    // One ray lit by a unit sun and a unit sky; the two parts are coloured below.
    let lighting = SprayLighting {
        sun_irradiance: if sun.direction.y > 0.0 { 1.0 } else { 0.0 },
        sin_sun_elevation: sun.direction.y.clamp(0.01, 1.0),
        cos_view_sun: d.dot(sun.direction),
        sky_radiance: 1.0,
    };
    let ray = match t {
        Some(t) => {
            let top = spray.medium.params().max_height_m;
            let mut ray = SprayRay::new(&spray.medium, &scattering, &lighting).with_spume(&spray.spume);
            ray.step(y0, (y0 + d.y * t).clamp(0.0, top), t, 1.0);
            ray
        }
        None => {
            let mut ray = SprayRay::spume_only(&spray.spume, &scattering, &lighting);
            ray.step_to_space(y0, d.y.max(0.0));
            ray
        }
    };
    let (transmittance, (in_sun, in_sky)) = (ray.transmittance(), ray.in_scattered_parts());
    // The ray's sky term counts ½ L̄ for `sky_radiance = 1`; the drops' source is J(d).
    let around = 2.0 * DVec3::from_array(spray.light.lookup(d.to_array()));
    l0 * transmittance + sun.irradiance_rgb * in_sun + around * in_sky
}

/// The share of the sun's and the moon's direct light that reaches a sea point through the
/// clouds (cloud shadows; brine-sky `Sky::cloud_transmittance`), each in `[0, 1]`.
#[derive(Debug, Clone, Copy)]
pub(super) struct DirectLight {
    sun: f64,
    moon: f64,
}

impl DirectLight {
    pub(super) fn at(world: &World, p: DVec3) -> Self {
        let sky = &world.sky;
        Self {
            sun: sky.cloud_transmittance(p, sky.sun().direction),
            moon: sky.moon().map_or(1.0, |m| sky.cloud_transmittance(p, m.direction)),
        }
    }

    /// `E_d(0⁻)` and its direct part under this light: the discs' shares scaled.
    pub(super) fn e_below(&self, world: &World) -> (DVec3, DVec3) {
        let moon = world.e_below_direct - world.e_below_sun;
        let direct = world.e_below_sun * self.sun + moon * self.moon;
        (world.e_below - world.e_below_direct + direct, direct)
    }
}

/// The shading of a surface point.
pub(super) struct SurfaceShade {
    radiance: DVec3,
    foam: f64,
    whitecap: f64,
    /// The sun's glint per unit of its irradiance (sr⁻¹, luminance), for the `glint` AOV.
    glint: f64,
}

/// Aerial perspective of the segment from the eye along `d` over `t` metres:
/// `L = L₀ F_ex + L_in` (Hoffman & Preetham 2002, brine-sky).
pub(super) fn aerial(world: &World, d: DVec3, t: f64, l0: DVec3) -> DVec3 {
    if !world.aerial_perspective {
        return l0;
    }
    let ap = world.sky.aerial_perspective(world.camera.position.y.max(0.0), d, t);
    l0 * ap.extinction + ap.inscatter
}

/// Everything seen along `d` above the sea: sky, clouds, sun and moon discs.
pub(super) fn sky_radiance(world: &World, d: DVec3) -> DVec3 {
    world.sky.background_rgb(d)
}

/// Where a ray through the water from `p` along the unit `d` meets the floor: `(distance, point)`.
pub(super) fn floor_hit(world: &World, p: DVec3, d: DVec3, cx: &mut Counters) -> Option<(f64, DVec3)> {
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
pub(super) fn floor_radiance(world: &World, point: DVec3, light: DirectLight) -> DVec3 {
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
pub(super) fn water_column_radiance(world: &World, p: DVec3, t: DVec3, light: DirectLight, cx: &mut Counters) -> DVec3 {
    let cos_theta = (-t.y).clamp(0.0, 1.0);
    let (e_below, _) = light.e_below(world);
    match floor_hit(world, p, t, cx) {
        Some((s, q)) => world.water.refracted_ray_radiance(e_below, cos_theta, s, floor_radiance(world, q, light)),
        None => world.water.refracted_ray_radiance(e_below, cos_theta, f64::INFINITY, DVec3::ZERO),
    }
}

/// The least cosine between the view and a shading normal (dimensionless): a normal the view sees
/// from behind, or more grazing, is tilted toward the viewer until it is seen at this cosine (a
/// facet turned away stands for the grazing faces of the waves around it, which the pixel does
/// see). `10⁻³`, 89.94° from the normal, where water's Fresnel factor is 0.994.
pub(super) const MIN_SEEN_COSINE: f64 = 1e-3;

/// A point of the sea seen by the camera: `p` (m), reached `t` metres along the unit view
/// direction `d`, of upward unit normal `normal` (the drawn waves').
#[derive(Debug, Clone, Copy)]
pub(super) struct SeenPoint {
    pub(super) p: DVec3,
    pub(super) d: DVec3,
    pub(super) t: f64,
    pub(super) normal: DVec3,
    /// The drawn surface's normal there, without the detail normals: the facet on which the
    /// pixel's footprint is taken for the textures laid on the surface.
    pub(super) facet: DVec3,
}

/// Radiance leaving the sea surface toward the camera at `p`: Fresnel-weighted sky reflection, the
/// sun through the ocean BRDF of the unresolved slopes, and the water column through `1 − F` and
/// the `n²` radiance law (Chen et al. 2007 §3.4; Bruneton et al. 2010 §5; Darles et al. 2007 §4.3).
pub(super) fn shade_surface(
    world: &World,
    field: &SeaField<'_>,
    seen: &SeenPoint,
    variance: &SlopeVariance,
    cx: &mut Counters,
) -> SurfaceShade {
    let SeenPoint { p, d, normal, .. } = *seen;
    let started = cx.clock();
    let v = -d;
    // Grazing views can see a facet from behind; tilt its normal toward the viewer just enough.
    let mut n = normal;
    let cos_v = v.dot(n);
    if cos_v < MIN_SEEN_COSINE {
        n = (n + (MIN_SEEN_COSINE - cos_v) * v).normalize();
    }
    let cos_v = v.dot(n).max(MIN_SEEN_COSINE);
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
    // What the unresolved facets reflect below the horizon or into a neighbour, (R_seen − R) of
    // the same integral, is light from the waves met, not transmitted light.
    let sigma_v = variance.along(to_local(v)).sqrt();
    let fresnel = fresnel_dielectric(cos_v, 1.0, WATER_IOR);
    let table = crate::world::rough_reflectance();
    let f = (fresnel * table.roughness_factor(cos_v, sigma_v)).clamp(0.0, 1.0);
    let f_met = (fresnel * table.met_factor(cos_v, sigma_v)).clamp(0.0, 1.0 - f);
    // The sky the seen facets reflect lies above the mirror direction of the resolved normal
    // (they lean toward the viewer): the lobe is centred at their mean mirror direction.
    let r = seen_sky_direction(reflect(d, n), n, cos_v, sigma_v);
    let escape = reflection_escape(world, variance, v, n);
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
    // The reflected light leaves over the waves drawn around the point: the drawn waves' share
    // of its escape ([`reflection_escape`]) moves it between the sky and the waves met, within
    // the light the facets seen reflect (`R_seen`).
    let started = cx.clock();
    let f_sky = (f * escape).min(f + f_met);
    let f_met = f + f_met - f_sky;
    let lobe = 2.0 * (0.5 * (variance.sigma_x2() + variance.sigma_y2())).sqrt();
    let sky =
        if f_sky > 0.0 { world.filtered_sky.radiance(r, lobe, |r| world.sky.radiance_rgb(r)) } else { DVec3::ZERO };
    let met = if f_met > 0.0 { met_wave_radiance(world, r, below, &light) } else { DVec3::ZERO };
    cx.lap(Stage::Surface, started);
    let sea = f_sky * sky + f_met * met + sun + (1.0 - f_sky - f_met) * below / (WATER_IOR * WATER_IOR) + crest;
    let started = cx.clock();
    let shade = white_water(world, seen, sea, light);
    cx.lap(Stage::WhiteWater, started);
    SurfaceShade { glint: glint_aov, ..shade }
}

/// Where the facets seen about a resolved normal reflect, on average: the unit mirror direction
/// `r` about the unit normal `n`, turned toward `n` in its own vertical plane, keeping its
/// azimuth, by the rise of the mean cosine `μ_r` of the mirror directions of the facets seen on a
/// rough surface of slope deviation `sigma` at `cos θ_v` (brine-optics
/// `RoughReflectance::mirror_cosine`) over the calm surface's, so that calm water keeps the
/// mirror direction exactly. At grazing views the facets seen lean toward the viewer and reflect
/// the sky well above the mirror direction of the mean normal (at 89° and σ = 0.2, 22°
/// higher); the filtered sky is looked up there.
///
/// # References
/// Bruneton E., Neyret F., Holzschuch N. 2010, CGF 29(2), §5.2 (the sky reflected by the rough
/// sea, looked up once per pixel); Heitz E. 2014, JCGT 3(2) (the visible normals).
pub(super) fn seen_sky_direction(r: DVec3, n: DVec3, cos_v: f64, sigma: f64) -> DVec3 {
    let table = crate::world::rough_reflectance();
    let raise = table.mirror_cosine(cos_v, sigma) - table.mirror_cosine(cos_v, 0.0);
    let along = r.dot(n);
    let tangent = r - along * n;
    let length = tangent.length();
    if raise <= 0.0 || length < 1e-9 {
        return r;
    }
    let mu = (along + raise).min(1.0);
    (tangent / length * (1.0 - mu * mu).max(0.0).sqrt() + mu * n).normalize()
}

/// Slopes below this variance (dimensionless) mask no reflected ray.
const MIN_MASKING_VARIANCE: f64 = 1e-6;

/// `r` in the mean sea's wind frame: `(downwind, crosswind, up)`, for [`SlopeVariance::along`].
fn in_wind_frame(world: &World, r: DVec3) -> DVec3 {
    DVec3::new(r.dot(world.wind), r.dot(DVec3::Y.cross(world.wind)), r.y)
}

/// The drawn waves' share of the escape of the light reflected toward the viewer at a point of
/// upward unit normal `n` (the drawn waves' and the detail normals') seen from the unit direction
/// `v` (toward the eye): how much more or less of it than the BRDF's rough reflectance sends to
/// the sky reaches the sky past the waves drawn around the point (brine-optics `drawn_escape`:
/// the whole sea's masking, Smith's height-correlated form with the measured escape of the
/// facets seen, over the BRDF's own), for the slope deviations of every wave and of the BRDF's
/// `variance` along the view's azimuth. 1 where nothing is drawn, for a view from straight above
/// and for a facet that faces away; `≥ 0`, above 1 where the BRDF's own integral, taken in the
/// drawn facet's frame, masks more than the whole sea does.
///
/// # References
/// Smith B.G. 1967, IEEE Trans. Antennas Propag. 15(5); Heitz E. 2014, "Understanding the
/// masking-shadowing function in microfacet-based BRDFs", JCGT 3(2), §6; Bruneton E., Neyret F.,
/// Holzschuch N. 2010, CGF 29(2), §4.
pub(super) fn reflection_escape(world: &World, variance: &SlopeVariance, v: DVec3, n: DVec3) -> f64 {
    let wv = in_wind_frame(world, v);
    let (total, brdf) = (world.variance_total.along(wv), variance.along(wv));
    let horizontal = DVec3::new(v.x, 0.0, v.z).length();
    if !(total - brdf > MIN_MASKING_VARIANCE) || horizontal < 1e-9 || v.y <= 0.0 || n.y <= 0.0 {
        return 1.0;
    }
    let zeta = -(n.x * v.x + n.z * v.z) / (n.y * horizontal);
    brine_optics::TwoScaleFacet::new(v.y / horizontal, zeta, total.sqrt(), brdf.clamp(0.0, total).sqrt())
        .map_or(1.0, |facet| brine_optics::drawn_escape(&facet))
}

/// Radiance of the wave a reflected ray along the unit `r` meets, on average: the mean sea seen
/// at the ray's grazing angle `μ = max(|r_y|, 10⁻³)` with every slope in its BRDF — the sky at
/// `(r_x, μ, r_z)` through their lobe times Fresnel and the rough factor of the sea's total slopes,
/// the sun's glint and the moon's glitter through the BRDF of those slopes (under the hit's cloud
/// shadow `light`) — and the water below it, taken as the hit's own `below`. Radiances in linear
/// sRGB (kcd m⁻²). An approximation of the renderer's, not of a paper: the wave met is shaded
/// statistically, not traced; where a pixel resolves it, it is the mean of the seas it could be.
///
/// # References
/// Bruneton E., Neyret F., Holzschuch N. 2010, CGF 29(2), Eq. 5–6 and §5.2 (the rough sea's
/// reflectance, its BRDF and the filtered sky).
pub(super) fn met_wave_radiance(world: &World, r: DVec3, below: DVec3, light: &DirectLight) -> DVec3 {
    let up = DVec3::new(r.x, r.y.abs().max(1e-3), r.z).normalize();
    let total = &world.variance_total;
    let sigma = total.along(in_wind_frame(world, up)).sqrt();
    let f = (fresnel_dielectric(up.y, 1.0, WATER_IOR)
        * crate::world::rough_reflectance().roughness_factor(up.y, sigma))
    .clamp(0.0, 1.0);
    let lobe = 2.0 * (0.5 * total.total()).sqrt();
    let seen = seen_sky_direction(up, DVec3::Y, up.y, sigma);
    let sky = world.filtered_sky.radiance(seen, lobe, |r| world.sky.radiance_rgb(r));
    // Seen from the meeting point, the viewer is up the ray: `v = (−r_x, μ, −r_z)`.
    let v = in_wind_frame(world, DVec3::new(-up.x, up.y, -up.z));
    let glint = |disc: &brine_sky::Disc, rules: &SunDisc| {
        if disc.direction.y > 0.0 && disc.irradiance_rgb != DVec3::ZERO {
            disc.irradiance_rgb * reflected_source_radiance(v, in_wind_frame(world, disc.direction), total, 1.0, rules)
        } else {
            DVec3::ZERO
        }
    };
    let discs = glint(world.sky.sun(), &world.discs.0) * light.sun
        + world.sky.moon().zip(world.discs.1.as_ref()).map_or(DVec3::ZERO, |(m, d)| glint(m, d)) * light.moon;
    f * sky + discs + (1.0 - f) * below / (WATER_IOR * WATER_IOR)
}

/// Foam (Darles et al. 2007 §4.1, Koepke 1984) and active whitecaps (Dupuy & Bruneton 2012) over
/// the sea radiance `sea` at the point `seen`, lit through `light`.
pub(super) fn white_water(world: &World, seen: &SeenPoint, sea: DVec3, light: DirectLight) -> SurfaceShade {
    let SeenPoint { p, d, t, normal: n, facet } = *seen;
    let mut shade = SurfaceShade { radiance: sea, foam: 0.0, whitecap: 0.0, glint: 0.0 };
    if world.foam.is_none() && world.whitecaps.is_none() && world.white_water.is_none() {
        return shade;
    }
    // Sample footprint on the sea: the sample's angle at distance t across the view, stretched
    // along it by the grazing view of the facet met.
    let across = t * world.sample_angle();
    let sun = world.sky.sun();
    let cos_sun = n.dot(sun.direction);
    let e_sky = world.sky.horizontal_irradiance_rgb();
    let e_moon = world.sky.moon().map_or(DVec3::ZERO, |m| m.irradiance_rgb * n.dot(m.direction).max(0.0)) * light.moon;
    let e_sun = sun.irradiance_rgb * light.sun;
    let lambert = |r: f64| -> DVec3 {
        let f = |c: usize| brine_foam::foam_radiance(r, e_sun[c], cos_sun, e_sky[c] + e_moon[c]);
        DVec3::new(f(0), f(1), f(2))
    };
    let cover = world.cover_seen(p, n, facet, across, d);
    if let Some((white, brightness)) = cover.memory {
        // Fresh foam (Koepke's R_f) where the crest breaks; ageing foam thins (Koepke's falling
        // reflectance): the water shows through it, through holes where the pixel resolves its
        // lace (brightness 0 there). Thick foam in a lace is brighter than the mean (brightness
        // above 1): opaque, and more reflective.
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
pub(super) const MAX_CREST_THICKNESS_M: f64 = 8.0;

/// Sun light through a thin crest (Jensen et al. 2001 dipole, brine-optics `crest_radiance`):
/// the crest's thickness is the distance from `p` back along the sun's ray refracted by a level
/// surface to where it entered the water, found by tracing inside the water with the same tracer.
pub(super) fn crest_radiance(
    world: &World,
    field: &SeaField<'_>,
    p: DVec3,
    v: DVec3,
    n: DVec3,
    cx: &mut Counters,
) -> DVec3 {
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
pub(super) fn water_background(world: &World, z: f64) -> DVec3 {
    let l0 = world.water.diffuse_upwelling_radiance(world.e_below);
    l0 * (-world.water.k_d * z.max(0.0)).exp()
}

/// Radiance reaching a camera under water along `d`: the underside of the surface (Snell's window:
/// the sky refracted through the surface inside the critical angle, total internal reflection of
/// the water outside it) or the floor, attenuated by `e^{−c s}` over the path and filled in by the
/// background radiance at the camera's depth (single-scattering equilibrium approximation).
pub(super) fn underwater_radiance(
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
