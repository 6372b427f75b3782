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

/// A facet the view sees from behind weighs as the shading shades it, seen at the least cosine
/// `c₀`: small but not zero, so that a reference pixel whose every sample lands on such facets
/// has their mean radiance rather than none, while beside the facets the view does see it
/// counts for little.
#[test]
fn facets_turned_away_weigh_as_seen_at_grazing() {
    let g = DVec3::Y;
    let v = DVec3::new(0.0, 0.1, 1.0).normalize();
    // Leaning away from the viewer by more than the view's elevation: seen from behind.
    let away = DVec3::new(0.0, 1.0, -0.5).normalize();
    assert!(v.dot(away) < 0.0);
    let w = projected_area_weight(v, away, g);
    assert!(w > 0.0, "{w}");
    // Any facet turned away weighs the same: the pixel's mean of such samples is theirs.
    let further = DVec3::new(0.0, 1.0, -0.5 - 0.3).normalize();
    let ratio = projected_area_weight(v, further, g) / w;
    assert!((ratio - away.dot(g) / further.dot(g)).abs() < 1e-12, "{ratio}");
    // Against the facet leaning toward the viewer as much: under 1 %.
    let toward = DVec3::new(0.0, 1.0, 0.5).normalize();
    assert!(w / projected_area_weight(v, toward, g) < 0.01, "{w}");
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
/// FFT seas do: their primary rays (toward the horizon, where a pixel covers metres) cost fewer
/// evaluations of the sea than the same rays traced with every wave, and the slopes the
/// geometry lost reach the BRDF.
#[test]
fn gerstner_and_sine_primary_rays_fade_with_the_footprint() {
    // Faded over whole evaluations: 1 without fading; measured 0.61 (Gerstner: 13 110 / 21 559,
    // whose whole trace the sharp slope bound made 3.3 times cheaper, against 0.50 with the
    // simpler bound) and 0.15 (sine).
    const FADED_COST: f64 = 0.75;
    for surface in [crate::scene::SurfaceKind::Gerstner, crate::scene::SurfaceKind::Sine] {
        let mut scene = Scene::default_scene();
        (scene.camera.width, scene.camera.height) = (160, 90);
        scene.sea.surface = surface;
        scene.sea.waves = Some(120);
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
            (faded.evaluations as f64) < FADED_COST * whole.evaluations as f64,
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
            let (n1, v1, _) = field.hit_geometry(h.point, d, h.t, &with);
            let (n0, v0, _) = field.hit_geometry(h.point, d, h.t, &without);
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

/// The drawn waves' share of a reflection's escape is brine-optics `drawn_escape` for the view's
/// elevation, the drawn facet's slope toward the eye and the sea's slope deviations along the
/// view's azimuth (computed here from the world's variances in the wind frame): 1 where nothing
/// is drawn or the eye looks straight down; at a grazing view over drawn waves, a facet that
/// faces the eye steeply sends its reflection high and it escapes more often than a level one's.
#[test]
fn reflections_escape_the_drawn_waves_as_the_two_scale_sea_says() {
    const ROUNDING: f64 = 1e-12;
    let world = World::new(&Scene::default_scene()).expect("the default scene is valid");
    let total = world.variance_total;
    let level = DVec3::Y;
    // Everything in the BRDF, or a view from straight above: nothing drawn masks the ray.
    let v = DVec3::new(-0.05f64.cos(), 0.05f64.sin(), 0.0);
    assert!((reflection_escape(&world, &total, v, level) - 1.0).abs() < ROUNDING);
    let brdf = SlopeVariance::new(0.2 * total.sigma_x2(), 0.2 * total.sigma_y2()).expect("valid");
    assert!((reflection_escape(&world, &brdf, DVec3::Y, level) - 1.0).abs() < ROUNDING);
    for (e, azimuth) in [(0.01f64, 0.0f64), (0.05, 1.0), (0.2, 2.5), (0.6, -1.0)] {
        // The eye at elevation `e` in the direction of `azimuth` from +x (`v` points to it).
        let toward = DVec3::new(azimuth.cos(), 0.0, azimuth.sin());
        let v = (toward * e.cos() + DVec3::Y * e.sin()).normalize();
        let along = DVec3::new(v.dot(world.wind), v.dot(DVec3::Y.cross(world.wind)), v.y);
        let (sigma_t, sigma_b) = (total.along(along).sqrt(), brdf.along(along).sqrt());
        let escape = |zeta: f64| {
            // Height rising by `ζ` per metre toward the eye: `∇h = ζ·toward`, `n ∝ (−∇h, 1)`.
            let n = DVec3::new(-zeta * toward.x, 1.0, -zeta * toward.z).normalize();
            let got = reflection_escape(&world, &brdf, v, n);
            let facet = brine_optics::TwoScaleFacet::new(e.tan(), zeta, sigma_t, sigma_b).expect("valid");
            let expected = brine_optics::drawn_escape(&facet);
            assert!((got - expected).abs() < ROUNDING, "elevation {e}, ζ {zeta}: {got} vs {expected}");
            got
        };
        let (flat, steep) = (escape(0.0), escape(-2.0 * sigma_t));
        if e < 0.1 {
            assert!(steep > flat, "elevation {e}: steep {steep}, level {flat}");
        }
    }
    // Nearly every slope drawn: the whole sea's escape at the drawn facet's slope, by hand from
    // Smith's `Λ` and the measured `e` (brine-optics' own test bounds the quadrature's
    // departure from it by 0.5 %).
    const NEAR: f64 = 5e-3;
    let thin = SlopeVariance::new(1e-6 * total.sigma_x2(), 1e-6 * total.sigma_y2()).expect("valid");
    let e = 0.03f64;
    let v = DVec3::new(-e.cos(), e.sin(), 0.0);
    let along = DVec3::new(v.dot(world.wind), v.dot(DVec3::Y.cross(world.wind)), v.y);
    let sigma = total.along(along).sqrt();
    let zeta = -1.5 * sigma;
    // `v` points to −x: height rising by `ζ` toward the eye is `∇h = (−ζ, 0)`, `n ∝ (ζ, 1, 0)`.
    let n = DVec3::new(zeta, 1.0, 0.0).normalize();
    let (nu, s) = (e.tan() / sigma, (e.tan() - zeta) / sigma);
    let up = |t: f64| brine_optics::smith_lambda(t / (1.0 + t * t).sqrt(), 1.0);
    let hand =
        brine_optics::SlopeVisibility::stored().escape(nu, s) * (1.0 + up(nu)) / (1.0 + up(nu) + up(2.0 * s - nu));
    let got = reflection_escape(&world, &thin, v, n);
    assert!((got - hand).abs() < NEAR * hand, "{got} vs {hand}");
}

/// The sky the seen facets reflect: calm water keeps the mirror direction exactly; a rough
/// surface seen at a grazing view turns the mirror direction toward the normal by exactly the
/// rise of the mean mirror cosine (brine-optics `mirror_cosine`), in the same azimuth; a steep
/// view moves little.
#[test]
fn the_sky_is_looked_up_where_the_seen_facets_reflect() {
    let n = DVec3::Y;
    let d = DVec3::new(0.0, -0.02, 1.0).normalize();
    let mirror = brine_optics::reflect(d, n);
    let cos_v = -d.dot(n);
    assert_eq!(seen_sky_direction(mirror, n, cos_v, 0.0), mirror);
    let raised = seen_sky_direction(mirror, n, cos_v, 0.16);
    assert!((raised.length() - 1.0).abs() < 1e-12);
    // Turned toward `n` by the table's rise of the mean mirror cosine over the calm surface's.
    let table = crate::world::rough_reflectance();
    let rise = table.mirror_cosine(cos_v, 0.16) - table.mirror_cosine(cos_v, 0.0);
    assert!(rise > 0.0);
    assert!((raised.dot(n) - (mirror.dot(n) + rise)).abs() < 1e-12, "{raised} against {mirror}, rise {rise}");
    assert!(raised.x.abs() < 1e-12 && raised.z > 0.0, "azimuth kept: {raised}");
    let steep = DVec3::new(0.0, -1.0, 0.3).normalize();
    let mirror = brine_optics::reflect(steep, n);
    let moved = seen_sky_direction(mirror, n, -steep.dot(n), 0.05);
    assert!(moved.angle_between(mirror) < 0.01, "{moved} against {mirror}");
}

/// Crests do not mirror the horizon: on a 12 m/s trochoid sea seen from 10 m (foam and light
/// through the crests off), almost no pixel of the middle distance is 1.5 times brighter than the
/// pixels above and below it. Taking the horizon sky for every reflection pointing into the sea
/// drew 1.6 % of them so: horizontal threads along the backs of crests seen edge-on.
#[test]
fn crests_do_not_mirror_the_horizon() {
    const THREADS: f64 = 2e-3;
    let text = "[camera]\nposition = [0.0, 10.0, 0.0]\npitch_deg = -8.0\nyaw_deg = 0.0\nwidth = 640\nheight = 360\n\n\
                [sea]\nwind_speed_m_s = 12.0\nwind_direction_deg = 20.0\nseed = 3\n\n\
                [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 90.0\n\n\
                [phenomena]\nfoam = false\nwhitecaps = false\nsubsurface = false\n";
    let scene = Scene::from_toml_str(text, "threads.toml").expect("a valid scene");
    let frame = render(&scene, &RenderOptions::default(), &|| {}).expect("renders");
    let w = frame.width as usize;
    let y = |i: usize| frame.pixels[i].dot(DVec3::new(0.2126, 0.7152, 0.0722));
    let (mut bright, mut all) = (0.0, 0.0);
    for r in 140..200 {
        for c in 1..w - 1 {
            let i = r * w + c;
            all += 1.0;
            if y(i) > 1.5 * (y(i - w) + y(i + w)) / 2.0 {
                bright += 1.0;
            }
        }
    }
    assert!(bright / all < THREADS, "{bright} of {all} pixels are threads");
}

/// `balanced` is `plain` through the white balance `m`: the same exposure, every pixel `m` times
/// the unbalanced one (one 3 × 3 product of values of order 1: 10⁻¹² relative).
fn assert_balanced(plain: &Frame, balanced: &Frame, m: glam::DMat3) {
    const ROUNDING: f64 = 1e-12;
    assert_eq!(plain.exposure_ev.to_bits(), balanced.exposure_ev.to_bits());
    for (p, q) in plain.pixels.iter().zip(&balanced.pixels) {
        let expected = m * *p;
        assert!(
            (*q - expected).abs().max_element() <= ROUNDING * expected.abs().max_element().max(1.0),
            "{q} vs {expected}"
        );
    }
}

/// `[output] white_balance = "scene"` balances the frame to the scene's light: each pixel is the
/// unbalanced frame's through one matrix, the one that shows the light of sun and sky on a level
/// surface as neutral (brine-sky `white_balance_linear_srgb`); `"image"`, to the frame's mean
/// colour (clipped at the exposure's white); the exposure is metered on the unbalanced frame,
/// so it does not move.
#[test]
fn the_scene_white_balance_shows_the_scenes_light_as_white() {
    // One 3 × 3 product of values of order 1, against pixels of order 10⁻²…10 kcd m⁻².
    const ROUNDING: f64 = 1e-12;
    // The share of the sun's direct light an overcast lets through, at most (measured 0: a
    // cover of 1 is opaque; 1 if the shadow were not applied).
    const OVERCAST_SUN: f64 = 0.2;
    let mut scene = Scene::default_scene();
    (scene.camera.width, scene.camera.height) = (96, 54);
    scene.sky.sun_elevation_deg = Some(8.0);
    // A clear sky: the sun's light reaches the whole sea (clouds are below).
    scene.sky.clouds = None;
    // The glare clips whites before it spreads them: not a linear map of the pixels.
    scene.phenomena.glare = false;
    let plain = render(&scene, &RenderOptions::default(), &|| {}).expect("a valid scene");
    assert!(World::new(&scene).expect("a valid scene").white_balance.is_none());
    scene.output.white_balance = crate::scene::WhiteBalance::Scene;
    let world = World::new(&scene).expect("a valid scene");
    let m = world.white_balance.expect("daylight is a white to adapt to");
    let balanced = render(&scene, &RenderOptions::default(), &|| {}).expect("a valid scene");
    assert_balanced(&plain, &balanced, m);
    // The light: the sky's irradiance on a level surface plus the sun's and the moon's.
    let disc = |d: &brine_sky::Disc| d.irradiance_rgb * d.direction.y.max(0.0);
    let light =
        world.sky.horizontal_irradiance_rgb() + disc(world.sky.sun()) + world.sky.moon().map_or(DVec3::ZERO, disc);
    let (x, y) = brine_sky::chromaticity(brine_sky::linear_srgb_to_xyz(light)).expect("daylight");
    assert!((x - 0.3127).abs().max((y - 0.3290).abs()) > 3e-3, "the light is not D65 already: ({x}, {y})");
    let seen = m * light;
    assert!((seen - DVec3::splat(seen.y)).abs().max_element() < ROUNDING * seen.y, "{seen}");
    // "image": the frame balanced to its own mean colour, each pixel clipped at the exposure's
    // white (a grey world; summed here in order, in the renderer in runs: rounding).
    scene.output.white_balance = crate::scene::WhiteBalance::Image;
    let grey_world = render(&scene, &RenderOptions::default(), &|| {}).expect("a valid scene");
    let white = 1.0 / crate::tonemap::exposure_scale(plain.exposure_ev);
    let mean = plain.pixels.iter().fold(DVec3::ZERO, |a, p| a + p.clamp(DVec3::ZERO, DVec3::splat(white)))
        / plain.pixels.len() as f64;
    let m = brine_sky::white_balance_linear_srgb(mean).expect("a daylit frame's mean is a white to adapt to");
    assert_balanced(&plain, &grey_world, m);
    // The clip is reached (the sun's glitter), and moves the mean the balance takes.
    let unclipped = plain.pixels.iter().fold(DVec3::ZERO, |a, p| a + *p) / plain.pixels.len() as f64;
    assert!(plain.pixels.iter().any(|p| p.max_element() > white), "no pixel above the exposure's white");
    assert!((unclipped - mean).abs().max_element() > 1e-3 * mean.y, "{unclipped} against {mean}");
    // Under an overcast sky the sun's direct light is the clouds' to take; under a broken cover,
    // the share of the sea the clouds leave in the sun (a cloud scale of 4 km, a 16 km square).
    let sun_share = |cover: f64, position: [f64; 3], yaw_deg: f64| {
        let mut s = scene.clone();
        s.output.white_balance = crate::scene::WhiteBalance::Scene;
        s.sky.clouds = Some(crate::scene::CloudConfig { cover, ..crate::scene::CloudConfig::default() });
        (s.camera.position, s.camera.yaw_deg) = (position, Some(yaw_deg));
        let world = World::new(&s).expect("a valid scene");
        let sun = world.sky.sun();
        let direct = sun.irradiance_rgb * sun.direction.y;
        // The square ahead of the camera: its foot the middle of the near edge.
        let forward = world.camera.forward;
        let ahead = DVec2::new(forward.x, forward.z).normalize() * 0.5 * world.white_balance_span_m;
        let centre = DVec2::new(position[0], position[2]) + ahead;
        let light = crate::world::scene_light(&world.sky, centre, world.white_balance_span_m);
        let m = world.white_balance.expect("daylight");
        let seen = m * light;
        assert!((seen - DVec3::splat(seen.y)).abs().max_element() < ROUNDING * seen.y, "{seen}");
        (light.y - world.sky.horizontal_irradiance_rgb().y) / direct.y
    };
    let overcast = sun_share(1.0, [0.0, 10.0, 0.0], 0.0);
    assert!(overcast < OVERCAST_SUN, "the sun through an overcast: {overcast}");
    let broken = sun_share(0.5, [3000.0, 10.0, -2000.0], 70.0);
    assert!((0.05..0.95).contains(&broken), "the sun through a broken cover: {broken}");
}
