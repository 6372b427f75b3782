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
