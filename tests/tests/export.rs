//! The sea handed to other tools is the sea that is rendered: queries against the depth AOV,
//! baked maps that tile and loop, meshes that the Khronos validator accepts.

use brine_render::export::{
    BakeOptions, MeshGrid, QueryPoint, UpAxis, bake_frame, camera_mesh, check_camera_mesh, grid_mesh,
    grid_mesh_band_limited, query_points, write_mesh,
};
use brine_render::{RenderOptions, Scene, World, render_world};
use glam::{DVec2, DVec3};

/// Hit points against the queried height: 1 mm, what a buoyancy user asks of the near field. The
/// tracer stops within its tolerance of the crossing (the world's `TraceOptions`: 1 mm, or
/// `10⁻⁵` of the distance beyond 100 m, [`TRACE_RELATIVE`]); the f32 depth AOV rounds the distance
/// by `2⁻²⁴` of it (6 µm at 100 m).
const ON_THE_SURFACE_M: f64 = 1e-3;

/// The world's relative trace tolerance (`tolerance_relative` of its `TraceOptions`).
const TRACE_RELATIVE: f64 = 1e-5;

/// Near field: hits closer than this (m), where no wave is faded by the pixel footprint.
const NEAR_FIELD_M: f64 = 40.0;

/// The hits of `scene`'s camera rays closer than `near_m`, and the worst distance between a hit
/// and the queried surface in units of `max(1 mm, 10⁻⁵ × distance)`.
fn hits_and_queries(scene: &Scene, world: &World, near_m: f64) -> (usize, f64) {
    let frame = render_world(scene, world, &RenderOptions::default(), &|| {}).unwrap();
    let mut points = Vec::new();
    let mut hits = Vec::new();
    for y in 0..scene.camera.height {
        for x in 0..scene.camera.width {
            let a = frame.aovs[(y * scene.camera.width + x) as usize];
            let depth = f64::from(a.depth);
            if depth.is_finite() && depth < near_m {
                let d = world.camera().direction(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let p: DVec3 = world.camera().position + depth * d;
                points.push(QueryPoint { x: p.x, z: p.z, t: scene.sea.time_s });
                hits.push(p);
            }
        }
    }
    let results = query_points(scene, world, &points).unwrap();
    let worst = hits
        .iter()
        .zip(&results)
        .map(|(p, r)| {
            let depth = (*p - world.camera().position).length();
            (p.y - r.height_m).abs() / ON_THE_SURFACE_M.max(TRACE_RELATIVE * depth)
        })
        .fold(0.0, f64::max);
    (hits.len(), worst)
}

/// In the near field of the default 640×360 view, where the pixel footprint fades no wave, the
/// depth AOV's hit points lie on the queried surface; and in the reference rendering (nothing
/// faded) they do at any distance.
#[test]
fn queried_heights_are_the_rendered_surface() {
    for surface in [brine_render::scene::SurfaceKind::Trochoids, brine_render::scene::SurfaceKind::Fft] {
        let mut scene = Scene::default_scene();
        scene.sea.surface = surface;
        scene.sea.fft.resolution = 128;
        scene.camera.width = 640;
        scene.camera.height = 360;
        scene.camera.spp = 1;
        scene.phenomena.glare = false;
        let world = World::new(&scene).unwrap();
        let (n, worst) = hits_and_queries(&scene, &world, NEAR_FIELD_M);
        eprintln!("{surface:?}: {n} near hits, worst {:.2e} m", worst * ON_THE_SURFACE_M);
        assert!(n > 1000, "{surface:?}: {n} near hits");
        assert!(worst < 1.0, "{surface:?}: a near hit {} m off the queried surface", worst * ON_THE_SURFACE_M);
        scene.camera.width = 96;
        scene.camera.height = 54;
        let mut world = World::new(&scene).unwrap();
        world.set_reference(true);
        let (n, worst) = hits_and_queries(&scene, &world, 1000.0);
        assert!(n > 1000, "{surface:?}: {n} hits");
        assert!(worst < 1.0, "{surface:?}: a reference hit {worst} tolerances off the queried surface");
    }
}

/// Texels on opposite edges of a bake continue each other: the maps are periodic with the tile.
#[test]
fn baked_maps_tile_and_loop() {
    for surface in [brine_render::scene::SurfaceKind::Trochoids, brine_render::scene::SurfaceKind::Fft] {
        let mut scene = Scene::default_scene();
        scene.sea.surface = surface;
        scene.sea.fft.resolution = 64;
        // Enough wind for foam and whitecaps to tile.
        scene.sea.wind_speed_m_s = 14.0;
        let tile = 64.0;
        let lattice = brine_waves_lattice(tile, Some(8.0));
        let world = World::on_lattice(&scene, Some(&lattice)).unwrap();
        let n = 32;
        // The surface one tile away is the same surface.
        let frame = world.ocean().at_time(1.25);
        for u in [DVec2::new(3.0, 7.0), DVec2::new(-11.0, 40.0)] {
            let a = frame.sample(u.x, u.y);
            for shift in [DVec2::new(tile, 0.0), DVec2::new(0.0, -tile), DVec2::new(2.0 * tile, tile)] {
                let b = frame.sample(u.x + shift.x, u.y + shift.y);
                assert!((a.height - b.height).abs() < 1e-4, "{surface:?}: height");
                assert!((a.normal - b.normal).length() < 1e-3, "{surface:?}: normal");
                let d = frame.rest_displacement(u) - frame.rest_displacement(u + shift);
                assert!(d.length() < 1e-4, "{surface:?}: displacement");
            }
        }
        // The white water repeats too: the same cover one tile away, over a grid with foam on it.
        let (mut white, mut worst) = (0.0, 0.0f64);
        for i in 0..40 {
            for j in 0..40 {
                let u = DVec2::new(f64::from(i) * 1.6, f64::from(j) * 1.6);
                let s = frame.sample(u.x, u.y);
                let p = DVec3::new(u.x, s.height, u.y);
                let a = world.cover_at_time(p, s.normal, 1.25, 0.0);
                let b = world.cover_at_time(p + DVec3::new(tile, 0.0, -tile), s.normal, 1.25, 0.0);
                white += a.foam + a.whitecap;
                worst = worst.max((a.foam - b.foam).abs()).max((a.whitecap - b.whitecap).abs());
            }
        }
        assert!(white > 1.0, "{surface:?}: no white water to compare ({white})");
        assert!(worst < 1e-6, "{surface:?}: the white water differs by {worst} one tile away");
        // And one loop later, the same maps.
        let options = BakeOptions { size: n, tile_m: tile, up: UpAxis::Y };
        let (a, b) = (bake_frame(&world, 1.25, &options), bake_frame(&world, 9.25, &options));
        let worst = a
            .maps
            .displacement
            .iter()
            .zip(&b.maps.displacement)
            .map(|(p, q)| (0..3).map(|k| (p[k] - q[k]).abs()).fold(0.0f32, f32::max))
            .fold(0.0f32, f32::max);
        assert!(worst < 1e-3, "{surface:?}: the loop differs by {worst} m");
    }
}

/// Mean-square slope `⟨ζx²⟩ + ⟨ζz²⟩` of a baked normal map.
fn map_mean_square_slope(normals: &[[f32; 3]]) -> f64 {
    let n = normals.len() as f64;
    let (mut sx, mut sz, mut sxx, mut szz) = (0.0, 0.0, 0.0, 0.0);
    for v in normals {
        let (x, z) = (-f64::from(v[0]) / f64::from(v[1]), -f64::from(v[2]) / f64::from(v[1]));
        (sx, sz, sxx, szz) = (sx + x, sz + z, sxx + x * x, szz + z * z);
    }
    (sxx / n - (sx / n).powi(2)) + (szz / n - (sz / n).powi(2))
}

/// The coarse grid's slopes plus the lost ones against the fine grid's: on the tile's lattice
/// the waves' cross terms average out over the grid, save for waves snapped onto the same
/// lattice vector (they add coherently) and the trochoid profiles' harmonics; 5 % covers both
/// for the default sea (measured 0.9 %; 1.8 % on a 50-wave sea).
const GRID_SLOPE_BUDGET_REL: f64 = 0.05;

/// The FFT sea's budget: the lost slopes are those of the undisplaced (linear) sea, the mesh's
/// normals those of the choppy one, and each cascade is read through its spline, which softens
/// the modes near its grid's Nyquist (at 64² cascades the sum fell 14 % short; at 256², the
/// test's, measured 2.3 %).
const FFT_GRID_SLOPE_BUDGET_REL: f64 = 0.05;

/// The tile of the band-limit tests (m).
const GRID_TILE_M: f64 = 64.0;

/// The default scene's sea snapped to a [`GRID_TILE_M`] tile.
fn default_sea_on_a_tile() -> World {
    World::on_lattice(&Scene::default_scene(), Some(&brine_waves_lattice(GRID_TILE_M, None))).unwrap()
}

/// Band limit of the maps: a grid of texels `Δ` cannot hold a wave shorter than `2Δ` (it would
/// show as another, longer wave), so a coarse bake leaves such waves out and says what slopes it
/// lost: the coarse map's slopes plus the lost ones are the fine map's, where no wave is left
/// out. Point-sampled, the coarse map held the fine map's whole slope variance in 32² texels,
/// half of it as waves that are not in the sea.
#[test]
fn baked_maps_hold_no_wave_the_grid_cannot_carry() {
    let (tile, world) = (GRID_TILE_M, default_sea_on_a_tile());
    let bake = |size| bake_frame(&world, 0.0, &BakeOptions { size, tile_m: tile, up: UpAxis::Y });
    let (fine, coarse) = (bake(512), bake(32));
    let (fl, cl) = (fine.limit.unwrap(), coarse.limit.unwrap());
    // At 12.5 cm texels every wave fits (the fit's shortest is over half a metre): nothing lost.
    assert_eq!((fl.faded_waves, fl.lost_slope_covariance), (Some(0), [0.0; 3]));
    assert!(cl.faded_waves.unwrap() > 10 && (cl.shortest_wave_m - 4.0).abs() < 1e-12, "{cl:?}");
    let (f, c) = (map_mean_square_slope(&fine.maps.normal), map_mean_square_slope(&coarse.maps.normal));
    let lost = cl.lost_slope_covariance[0] + cl.lost_slope_covariance[2];
    eprintln!("fine {f:.5}, coarse {c:.5} + lost {lost:.5} = {:.5}", c + lost);
    assert!(lost > 0.2 * f, "the coarse grid lost only {lost} of {f}");
    assert!(((c + lost) / f - 1.0).abs() < GRID_SLOPE_BUDGET_REL, "coarse {c} + lost {lost} against fine {f}");
}

/// Variance of a map's values about their mean.
fn variance(v: &[f64]) -> f64 {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n
}

/// Excess of the coarse FFT bake's Jacobian variance over that of the fine bake averaged over
/// the coarse texels: 1.5 covers the difference between the band limit's smooth cut and the
/// box (measured 0.97; 1.91 with the coarse texels point-sampling every cascade).
const FFT_JACOBIAN_ALIASING: f64 = 1.5;

/// The FFT sea's cascades are grids of their own, most finer than a coarse bake's texels: baked
/// on a grid of texels `Δ`, the sea leaves out its modes shorter than `2Δ`, so that the
/// displacement and Jacobian maps hold no cascade as the aliases of finer ones. The coarse
/// Jacobian map then varies as the fine map averaged over the coarse texels, not more.
#[test]
fn an_fft_bake_holds_no_mode_the_grid_cannot_carry() {
    let mut scene = Scene::default_scene();
    scene.sea.surface = brine_render::scene::SurfaceKind::Fft;
    scene.sea.fft.resolution = 64;
    scene.sea.wind_speed_m_s = 14.0;
    let tile = 64.0;
    let world = World::on_lattice(&scene, Some(&brine_waves_lattice(tile, None))).unwrap();
    let bake = |size| bake_frame(&world, 0.0, &BakeOptions { size, tile_m: tile, up: UpAxis::Y });
    let (coarse, fine) = (bake(32), bake(256));
    let faded = coarse.limit.as_ref().and_then(|l| l.faded_waves).unwrap_or(0);
    assert!(faded > 100, "modes left out of the coarse bake: {faded}");
    let r = 256 / 32;
    let box_mean: Vec<f64> = (0..32 * 32)
        .map(|c| {
            let (ci, cj) = (c % 32, c / 32);
            let mut sum = 0.0;
            for j in 0..r {
                for i in 0..r {
                    sum += f64::from(fine.maps.jacobian[(cj * r + j) * 256 + ci * r + i]);
                }
            }
            sum / (r * r) as f64
        })
        .collect();
    let coarse_j: Vec<f64> = coarse.maps.jacobian.iter().map(|&j| f64::from(j)).collect();
    let (vc, vb) = (variance(&coarse_j), variance(&box_mean));
    eprintln!("Jacobian variance: coarse {vc:.5}, fine averaged {vb:.5}, ratio {:.3}", vc / vb);
    assert!(vc <= FFT_JACOBIAN_ALIASING * vb, "coarse {vc} against the fine map averaged {vb}");
}

/// Every seventh vertex of `mesh` lies on the band-limited sea `band` (to the f32 vertices'
/// rounding), and the short waves are really gone: somewhere the mesh is over 1 mm off the
/// world's full sea.
fn assert_vertices_on_the_band_sea(mesh: &brine_render::export::Mesh, band: &brine_waves::SeaFrame, world: &World) {
    let mut off_full = 0.0_f64;
    for p in mesh.positions.iter().step_by(7) {
        let (x, y, z) = (f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
        assert!((band.height(x, z) - y).abs() < 1e-5, "vertex off the band-limited surface");
        off_full = off_full.max((world.sea().height(x, z) - y).abs());
    }
    assert!(off_full > 1e-3, "the coarse mesh is the full surface (off by at most {off_full} m)");
}

/// The normals of the vertices of one tile of a square grid mesh `spacing` apart over `tile`
/// (its far row and column left out: the points a bake samples).
fn one_tile_normals(m: &brine_render::export::Mesh, tile: f64, spacing: f64) -> Vec<[f32; 3]> {
    let n = (tile / spacing) as usize + 1;
    (0..(n - 1) * (n - 1)).map(|k| m.normals[(k / (n - 1)) * n + k % (n - 1)]).collect()
}

/// `brine mesh --band-limit`: a grid of vertices `Δ` apart leaves out the waves shorter than
/// `2Δ` (which its vertices would show as other, longer waves), like a bake. Its vertices lie on
/// the band-limited sea, not on the full one; its normals' slopes plus the ones it says it left
/// out are the slopes of a grid fine enough for every wave; and on such a grid it is the plain
/// mesh, byte for byte.
#[test]
fn a_band_limited_mesh_holds_no_wave_its_grid_cannot_carry() {
    // The vertices of one tile of the lattice sea, its far row and column left out: the points
    // the bake samples.
    let (tile, world) = (GRID_TILE_M, default_sea_on_a_tile());
    let t = Scene::default_scene().sea.time_s;
    let grid = |spacing_m| MeshGrid { center: DVec2::splat(0.5 * tile), size_m: tile, spacing_m };
    let one_tile = |m: &brine_render::export::Mesh, spacing: f64| one_tile_normals(m, tile, spacing);
    let (fine, fine_limit) = grid_mesh_band_limited(&world, t, &grid(0.125)).unwrap();
    assert_eq!(fine_limit.faded_waves, Some(0));
    assert!(fine == grid_mesh(&world, t, &grid(0.125)), "a grid that carries every wave changed the mesh");
    let (coarse, limit) = grid_mesh_band_limited(&world, t, &grid(2.0)).unwrap();
    assert!(limit.faded_waves.unwrap() > 10, "{limit:?}");
    let (band_sea, _) = world.ocean().grid_band(2.0).unwrap().unwrap();
    let band_frame = band_sea.at_time(t);
    assert_vertices_on_the_band_sea(&coarse, &band_frame, &world);
    let f = map_mean_square_slope(&one_tile(&fine, 0.125));
    let c = map_mean_square_slope(&one_tile(&coarse, 2.0));
    let lost = limit.lost_slope_covariance[0] + limit.lost_slope_covariance[2];
    eprintln!("fine {f:.5}, coarse {c:.5} + lost {lost:.5} = {:.5}", c + lost);
    assert!(((c + lost) / f - 1.0).abs() < GRID_SLOPE_BUDGET_REL, "coarse {c} + lost {lost} against fine {f}");
}

/// The FFT sea's band-limited mesh: its vertices on the sea of the modes a grid of that
/// spacing carries (brine-waves `FftOcean::at_time_on_grid`), off the full sea, and its normals'
/// slopes plus the slopes it says it left out are those of a fine mesh.
#[test]
fn a_band_limited_fft_mesh_holds_no_mode_its_grid_cannot_carry() {
    let mut scene = Scene::default_scene();
    scene.sea.surface = brine_render::scene::SurfaceKind::Fft;
    scene.sea.fft.resolution = 256;
    let tile = GRID_TILE_M;
    let world = World::on_lattice(&scene, Some(&brine_waves_lattice(tile, None))).unwrap();
    let t = scene.sea.time_s;
    let grid = |spacing_m| MeshGrid { center: DVec2::splat(0.5 * tile), size_m: tile, spacing_m };
    let one_tile = |m: &brine_render::export::Mesh, spacing: f64| one_tile_normals(m, tile, spacing);
    let (coarse, limit) = grid_mesh_band_limited(&world, t, &grid(2.0)).unwrap();
    assert!(limit.faded_waves.unwrap() > 100, "{limit:?}");
    let (band_frame, _) = world.ocean().fft_frame_on_grid(t, 2.0).unwrap();
    assert_vertices_on_the_band_sea(&coarse, &band_frame, &world);
    // The vertices moved with the band-limited water (each rest point `u` to `u + D(u)`), not
    // with the whole sea's, whose short modes move them by more than a millimetre somewhere.
    let (spacing, n) = (2.0, (tile / 2.0) as usize + 1);
    let origin = DVec2::splat(0.5 * tile) - DVec2::splat(0.5 * (n - 1) as f64 * spacing);
    let mut moved = 0.0_f64;
    for (k, p) in coarse.positions.iter().enumerate().step_by(7) {
        let u = origin + DVec2::new((k % n) as f64, (k / n) as f64) * spacing;
        let x = u + band_frame.rest_displacement(u);
        let at = DVec2::new(f64::from(p[0]), f64::from(p[2]));
        assert!((at - x).length() < 1e-4, "vertex {k} at {at}, the band-limited water at {x}");
        moved = moved.max((world.sea().rest_displacement(u) - band_frame.rest_displacement(u)).length());
    }
    assert!(moved > 1e-3, "the band-limited water moves as the whole sea (by at most {moved} m)");
    // At 12.5 cm the mesh still leaves out the shortest modes: the totals are compared.
    let (fine, fine_limit) = grid_mesh_band_limited(&world, t, &grid(0.125)).unwrap();
    let fine_limit_lost = fine_limit.lost_slope_covariance[0] + fine_limit.lost_slope_covariance[2];
    let f = map_mean_square_slope(&one_tile(&fine, 0.125));
    let c = map_mean_square_slope(&one_tile(&coarse, 2.0));
    let lost = limit.lost_slope_covariance[0] + limit.lost_slope_covariance[2];
    eprintln!("FFT: fine {f:.5} + lost {fine_limit_lost:.5}, coarse {c:.5} + lost {lost:.5} = {:.5}", c + lost);
    assert!(
        ((c + lost) / (f + fine_limit_lost) - 1.0).abs() < FFT_GRID_SLOPE_BUDGET_REL,
        "coarse {c} + lost {lost} against fine {f} + {fine_limit_lost}"
    );
}

/// A camera mesh covers the sea its camera sees, however steep the view: every point where one
/// of the image's rays meets the mean sea has a vertex within two edges (looking 60° down,
/// where the lower corners reach wider than the field of view and the nearest sea is under half
/// the eye's height away, and straight down, where the image holds the camera's foot); a camera
/// that sees no sea is refused.
#[test]
fn a_camera_mesh_covers_what_the_camera_sees() {
    for pitch in [-60.0, -90.0] {
        let mut scene = Scene::default_scene();
        (scene.camera.width, scene.camera.height, scene.camera.pitch_deg) = (64, 36, Some(pitch));
        let world = World::new(&scene).unwrap();
        check_camera_mesh(&world, 2.0).unwrap();
        let mesh = camera_mesh(&world, scene.sea.time_s, 2.0, false);
        let cam = world.camera();
        let footprint = cam.pixel_angle() * 2.0;
        for j in 0..=12 {
            for i in 0..=12 {
                let d = cam.direction(f64::from(i) / 12.0 * 64.0, f64::from(j) / 12.0 * 36.0);
                let g = cam.position + d * (cam.position.y / -d.y);
                let gap = mesh
                    .positions
                    .iter()
                    .map(|p| (f64::from(p[0]) - g.x).hypot(f64::from(p[2]) - g.z))
                    .fold(f64::INFINITY, f64::min);
                // A vertex within two edges: the vertices stand above their grid points (no
                // horizontal displacement), whose edges are 2 footprints long across the view
                // and 2/sin γ along it (γ the grazing angle, `−d_y`).
                let reach = 2.0 * footprint * (g - cam.position).length() / -d.y;
                assert!(gap < reach, "pitch {pitch}: the sea at ({:.1}, {:.1}) is {gap:.2} m from the mesh", g.x, g.z);
            }
        }
    }
    let mut scene = Scene::default_scene();
    scene.camera.pitch_deg = Some(90.0);
    let world = World::new(&scene).unwrap();
    let e = check_camera_mesh(&world, 2.0).unwrap_err();
    assert!(e.contains("sees no sea"), "{e}");
}

fn brine_waves_lattice(tile: f64, period: Option<f64>) -> brine_waves::TileLattice {
    brine_waves::TileLattice::new(tile, period).unwrap()
}

/// The meshes are valid glTF 2.0 under the Khronos validator (the npm `gltf-validator`, run when
/// `BRINE_GLTF_VALIDATOR` names its script, as `.ci/run` does), and OBJ and PLY files parse.
#[test]
fn meshes_are_valid() {
    let scene = Scene::default_scene();
    let world = World::new(&scene).unwrap();
    let grid = MeshGrid { center: DVec2::new(5.0, -3.0), size_m: 20.0, spacing_m: 0.5 };
    let mesh = grid_mesh(&world, scene.sea.time_s, &grid);
    assert_eq!(mesh.positions.len(), 41 * 41);
    // Every vertex lies on the rendered surface.
    for p in mesh.positions.iter().step_by(97) {
        let h = world.sea().height(f64::from(p[0]), f64::from(p[2]));
        assert!((h - f64::from(p[1])).abs() < 1e-5, "vertex off the surface by {}", h - f64::from(p[1]));
    }
    let dir = tempfile::tempdir().unwrap();
    for name in ["sea.glb", "sea.gltf", "sea.obj", "sea.ply"] {
        write_mesh(&dir.path().join(name), &mesh).unwrap();
    }
    let obj = std::fs::read_to_string(dir.path().join("sea.obj")).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), mesh.positions.len());
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), mesh.indices.len() / 3);
    let ply = std::fs::read(dir.path().join("sea.ply")).unwrap();
    let header_end = ply.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    assert_eq!(ply.len() - header_end, mesh.positions.len() * 32 + mesh.indices.len() / 3 * 13);
    // No temporary is left beside the outputs.
    assert!(
        std::fs::read_dir(dir.path()).unwrap().all(|e| !e.unwrap().file_name().to_string_lossy().ends_with(".tmp"))
    );
    match std::env::var_os("BRINE_GLTF_VALIDATOR") {
        Some(script) => {
            for name in ["sea.glb", "sea.gltf"] {
                let out = std::process::Command::new("node").arg(&script).arg(dir.path().join(name)).output().unwrap();
                assert!(
                    out.status.success(),
                    "{name}: {}{}",
                    String::from_utf8_lossy(&out.stdout),
                    String::from_utf8_lossy(&out.stderr)
                );
            }
        }
        None => eprintln!("BRINE_GLTF_VALIDATOR is not set: the Khronos validator was not run (.ci/run runs it)"),
    }
}

/// Every primary hit of a rendered frame within the trace distance lies on the faded height
/// (brine-waves `TracedSea::faded_height` with the ray's direction and distance: the surface
/// `brine mesh --camera --faded` is made of), near and far, within the tracer's tolerance, on
/// each of the four seas and on the trochoid sea of 200 waves with its shorter waves on grids;
/// and the faded camera mesh's vertices are that surface.
#[test]
fn the_faded_height_is_what_the_primary_rays_hit() {
    use brine_render::scene::SurfaceKind;
    let seas = [
        (SurfaceKind::Trochoids, 50),
        (SurfaceKind::Trochoids, 200),
        (SurfaceKind::Gerstner, 50),
        (SurfaceKind::Sine, 50),
        (SurfaceKind::Fft, 50),
    ];
    for (surface, waves) in seas {
        let mut scene = Scene::default_scene();
        scene.sea.waves = Some(waves);
        scene.camera.width = 200;
        scene.camera.height = 112;
        scene.camera.spp = 1;
        scene.phenomena.glare = false;
        scene.sea.surface = surface;
        let world = World::new(&scene).unwrap();
        let frame = render_world(&scene, &world, &RenderOptions::default(), &|| {}).unwrap();
        let traced = world.traced_sea();
        assert_eq!(matches!(traced, brine_waves::TracedSea::Gridded { .. }), waves >= 150);
        let cam = world.camera();
        let (mut n, mut far, mut worst) = (0, 0, 0.0f64);
        for y in 0..scene.camera.height {
            for x in 0..scene.camera.width {
                let depth = f64::from(frame.aovs[(y * scene.camera.width + x) as usize].depth);
                // Beyond the trace distance a ray meets the curved mean sea, not the waves.
                if !(depth < scene.sea.trace_distance_m) {
                    continue;
                }
                let d = cam.direction(f64::from(x) + 0.5, f64::from(y) + 0.5);
                let p = cam.position + depth * d;
                let h = traced.faded_height(p.x, p.z, d, world.filtering_angle(), depth);
                worst = worst.max((p.y - h).abs() / ON_THE_SURFACE_M.max(TRACE_RELATIVE * depth));
                n += 1;
                far += usize::from(depth > 200.0);
            }
        }
        assert!(n > 10_000 && far > 1000, "{surface:?}: {n} hits, {far} beyond 200 m");
        assert!(worst < 1.0, "{surface:?}: a hit {worst} tolerances off the faded height");
        let mesh = brine_render::export::camera_mesh(&world, scene.sea.time_s, 2.0, true);
        for v in mesh.positions.iter().step_by(101) {
            let p = DVec3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]));
            let s = world.sea().sample(p.x, p.z);
            let ray = DVec3::new(p.x, s.height, p.z) - cam.position;
            let h = traced.faded_height(p.x, p.z, ray.normalize(), world.filtering_angle(), ray.length());
            // The vertex is stored in f32: 2⁻²⁴ of its coordinates.
            assert!((h - p.y).abs() < 1e-5 * (1.0 + h.abs()), "{surface:?}: vertex {p} against {h}");
        }
    }
}
