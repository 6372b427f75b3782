//! The displaced sea surface as a triangle mesh: `brine mesh` (glTF 2.0, OBJ, PLY).

use std::io::Write;
use std::path::Path;

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use super::GridLimit;
use crate::World;

/// A triangle mesh of the sea: positions (m, y up), unit normals, foam and whitecap cover per
/// vertex, counter-clockwise triangles seen from above.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions `(x, y, z)` (m).
    pub positions: Vec<[f32; 3]>,
    /// Unit upward normals.
    pub normals: Vec<[f32; 3]>,
    /// Foam cover `[0, 1]`.
    pub foam: Vec<f32>,
    /// Active whitecap cover `[0, 1]`.
    pub whitecap: Vec<f32>,
    /// Triangles, three vertex indices each.
    pub indices: Vec<u32>,
}

/// Bytes per vertex of a [`Mesh`] in memory and in its file (position, normal, foam, whitecap)
/// plus its share of the indices (two triangles per vertex), twice over (the mesh and the
/// encoded file): what [`MeshGrid::memory_estimate`] counts.
const BYTES_PER_VERTEX: u64 = 2 * (12 + 12 + 4 + 4 + 24);

/// A regular grid of rest positions: `count × count` points `spacing_m` apart around `center`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshGrid {
    /// Centre of the grid `(x, z)` (m).
    pub center: DVec2,
    /// Side of the square (m), `> 0`.
    pub size_m: f64,
    /// Distance between neighbouring rest positions (m), `> 0`.
    pub spacing_m: f64,
}

/// Most vertices a mesh may have: 32-bit indices.
pub const MAX_MESH_VERTICES: u64 = u32::MAX as u64;

impl MeshGrid {
    /// Vertices along a side, `round(size/spacing) + 1`.
    pub fn count(&self) -> u64 {
        (self.size_m / self.spacing_m).round() as u64 + 1
    }

    /// Estimated peak memory of the mesh and its encoding (bytes).
    pub fn memory_estimate(&self) -> u64 {
        self.count().saturating_mul(self.count()).saturating_mul(BYTES_PER_VERTEX)
    }

    /// Checks the grid: positive sizes, at least 2 × 2 vertices, indices that fit 32 bits, and
    /// memory the machine has.
    ///
    /// # Errors
    /// A message naming the flag and its range, or the memory estimate.
    pub fn check(&self) -> Result<(), String> {
        if !(self.size_m > 0.0 && self.size_m <= 1e6) {
            return Err(format!("--size-m = {} is out of range: expected (0, 1e6] m", self.size_m));
        }
        if !(self.spacing_m > 0.0 && self.spacing_m <= self.size_m) {
            return Err(format!("--spacing-m = {} is out of range: expected (0, --size-m] m", self.spacing_m));
        }
        let n = self.count().saturating_mul(self.count());
        if n > MAX_MESH_VERTICES {
            return Err(format!(
                "a {0} × {0} grid has {n} vertices, more than a mesh with 32-bit indices holds ({MAX_MESH_VERTICES}): raise --spacing-m",
                self.count()
            ));
        }
        super::check_memory(&format!("a mesh of {n} vertices"), self.memory_estimate())
    }
}

/// One vertex of the surface: the point of rest position `u` (see brine-waves
/// `SeaFrame::rest_displacement`) with its normal and cover.
fn vertex(world: &World, frame: &brine_waves::SeaFrame, x: DVec2, footprint_m: f64) -> ([f32; 3], [f32; 3], f32, f32) {
    vertex_of(world, frame, x, &frame.sample(x.x, x.y), footprint_m)
}

/// [`vertex`] of a sample already taken at `x`.
fn vertex_of(
    world: &World,
    frame: &brine_waves::SeaFrame,
    x: DVec2,
    s: &brine_waves::SurfaceSample,
    footprint_m: f64,
) -> ([f32; 3], [f32; 3], f32, f32) {
    let p = DVec3::new(x.x, s.height, x.y);
    let c = world.cover_at_time(p, s.normal, frame.time(), footprint_m);
    (p.as_vec3().to_array(), s.normal.as_vec3().to_array(), c.foam as f32, c.whitecap as f32)
}

/// Fills a mesh from vertex rows (row-major, `cols` per row) and triangulates the grid.
fn grid_of(rows: usize, cols: usize, vertices: Vec<([f32; 3], [f32; 3], f32, f32)>) -> Mesh {
    let mut m = Mesh {
        positions: Vec::with_capacity(vertices.len()),
        normals: Vec::with_capacity(vertices.len()),
        foam: Vec::with_capacity(vertices.len()),
        whitecap: Vec::with_capacity(vertices.len()),
        indices: Vec::with_capacity(6 * rows.saturating_sub(1) * cols.saturating_sub(1)),
    };
    for (p, n, f, w) in vertices {
        m.positions.push(p);
        m.normals.push(n);
        m.foam.push(f);
        m.whitecap.push(w);
    }
    for j in 0..rows.saturating_sub(1) {
        for i in 0..cols.saturating_sub(1) {
            let a = (j * cols + i) as u32;
            let (b, c, d) = (a + 1, a + cols as u32, a + cols as u32 + 1);
            // Counter-clockwise seen from +y: x east, z south (right-handed, y up).
            m.indices.extend_from_slice(&[a, c, b, b, c, d]);
        }
    }
    m
}

/// The sea of `world` at time `t` (s) on a regular grid of rest positions: each grid point `u`
/// goes to `x = u + D(u)` (the water's own displacement, so that vertices crowd toward the
/// crests) and then onto the traced surface `(x, h(x))`.
///
/// # Arguments
/// - `world`: the scene's world; `t`: time (s), finite; `grid`: a checked [`MeshGrid`].
///
/// # Returns
/// The [`Mesh`].
pub fn grid_mesh(world: &World, t: f64, grid: &MeshGrid) -> Mesh {
    world.with_sea_at(t, |frame| grid_mesh_of(world, frame, grid))
}

/// The sea a grid can carry: [`grid_mesh`] of the waves at least two spacings long, those up to
/// three faded (brine-waves `grid_band`, the band a bake keeps). A grid samples a wave shorter
/// than two spacings as another, longer wave in another direction; the vertices of this mesh
/// hold none, and the slope covariance left out is returned for a roughness on its material.
/// Every vertex lies on the band-limited surface, not on the rendered one (which differs from
/// it by the short waves' heights, millimetres to centimetres).
///
/// # Arguments
/// - `world`, `t`, `grid`: as [`grid_mesh`].
///
/// # Returns
/// The [`Mesh`] and what the grid left out ([`GridLimit`]); a sea whose waves all fit gives the
/// mesh of [`grid_mesh`], byte for byte.
///
/// The FFT sea leaves out its modes the same way (brine-waves `FftOcean::at_time_on_grid`), and
/// the slope covariance it returns is that of the modes removed, on the undisplaced sea.
///
/// # Errors
/// A message for the sine sea, whose short waves are normals, not a sum a grid can leave out.
pub fn grid_mesh_band_limited(world: &World, t: f64, grid: &MeshGrid) -> Result<(Mesh, GridLimit), String> {
    if world.ocean().fft_ocean().is_some_and(|o| o.modes_faded_on_grid(grid.spacing_m) == 0) {
        // Every mode fits: the plain mesh, byte for byte (no second synthesis).
        let limit =
            GridLimit { shortest_wave_m: 2.0 * grid.spacing_m, faded_waves: Some(0), lost_slope_covariance: [0.0; 3] };
        return Ok((grid_mesh(world, t, grid), limit));
    }
    if let Some((frame, band)) = world.ocean().fft_frame_on_grid(t, grid.spacing_m) {
        let limit = GridLimit {
            shortest_wave_m: 2.0 * grid.spacing_m,
            faded_waves: Some(band.faded),
            lost_slope_covariance: band.lost_slope_covariance.to_array(),
        };
        return Ok((grid_mesh_of(world, &frame, grid), limit));
    }
    let unsupported = || {
        "--band-limit: the sine sea (sea.surface = \"sine\") draws its short waves as normals, not as a sum of waves a grid can leave out; use the trochoid, Gerstner or FFT sea".to_owned()
    };
    // A valid sea's faded Gerstner sum always builds (fading only lowers ΣQ).
    let (ocean, band) = world.ocean().grid_band(grid.spacing_m).map_err(|e| e.to_string())?.ok_or_else(unsupported)?;
    let limit = GridLimit {
        shortest_wave_m: 2.0 * grid.spacing_m,
        faded_waves: Some(band.faded),
        lost_slope_covariance: band.lost_slope_covariance.to_array(),
    };
    let mesh = if band.faded == 0 { grid_mesh(world, t, grid) } else { grid_mesh_of(world, &ocean.at_time(t), grid) };
    Ok((mesh, limit))
}

/// [`grid_mesh`] on the sea `frame`.
fn grid_mesh_of(world: &World, frame: &brine_waves::SeaFrame, grid: &MeshGrid) -> Mesh {
    let n = grid.count() as usize;
    let origin = grid.center - DVec2::splat(0.5 * (n - 1) as f64 * grid.spacing_m);
    let vertices: Vec<_> = (0..n * n)
        .into_par_iter()
        .with_min_len(1024)
        .map(|k| {
            let u = origin + DVec2::new((k % n) as f64, (k / n) as f64) * grid.spacing_m;
            let (d, s) = frame.sample_at_rest(u);
            vertex_of(world, frame, u + d, &s, grid.spacing_m)
        })
        .collect();
    grid_of(n, n, vertices)
}

/// The sea of `world` at time `t` as the camera sees it: a polar grid around the camera's foot,
/// over its horizontal field of view (and a margin of a tenth of it each side), from where the
/// view meets the sea out to the trace distance, with vertices `pixels` pixel footprints apart —
/// across, `r α`; along the view, `r α/max(sin γ, 0.05)` (`α` the pixel angle, `γ` the grazing
/// angle; the renderer's footprint, stretched along the view by at most 20).
///
/// With `faded`, each vertex is on the surface the renderer draws along the ray from the eye
/// to it: the waves (or the FFT sea's cascades) weighted by their fade at that distance
/// (brine-waves `TracedSea::faded_height`, the primary rays' weights), so the far sea is the
/// smoother one of the image.
///
/// # Arguments
/// - `world`, `t`: as [`grid_mesh`]; `pixels`: pixel footprints per edge, `≥ 0.125`;
///   `faded`: the waves faded as the camera's primary rays fade them.
///
/// # Returns
/// The [`Mesh`] (Eulerian vertices: each on the traced surface above its grid point).
pub fn camera_mesh(world: &World, t: f64, pixels: f64, faded: bool) -> Mesh {
    let (rings, angles, _) = camera_layout(world, pixels);
    world.with_traced_sea_at(t, |frame, traced| {
        let c = world.camera.position;
        let alpha = world.camera.pixel_angle();
        let fade = world.filtering_angle();
        let cols = angles.len();
        let vertices: Vec<_> = (0..rings.len() * cols)
            .into_par_iter()
            .with_min_len(1024)
            .map(|k| {
                let (r, a) = (rings[k / cols], angles[k % cols]);
                let x = DVec2::new(c.x + r * a.cos(), c.z + r * a.sin());
                if faded {
                    faded_vertex(world, frame, traced, x, pixels * alpha * r, fade)
                } else {
                    vertex(world, frame, x, pixels * alpha * r)
                }
            })
            .collect();
        let mut mesh = grid_of(rings.len(), cols, vertices);
        // `grid_of` winds its triangles for columns along +x and rows along +z; here columns run
        // in azimuth from +x toward +z and rows outward, a mirrored layout (radial × tangential
        // points down), so each triangle is turned over to face up.
        for triangle in mesh.indices.chunks_exact_mut(3) {
            triangle.swap(1, 2);
        }
        mesh
    })
}

/// A file name as a relative URI (RFC 3986 path segment): every byte but the unreserved
/// `A–Z a–z 0–9 - . _ ~` percent-encoded, so that `%`, `#`, `?` or a space in the name reach the
/// reader as the name (glTF buffers are addressed by URI).
fn uri_path_segment(name: &str) -> String {
    name.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' => (b as char).to_string(),
            _ => format!("%{b:02X}"),
        })
        .collect()
}

/// A vertex of the faded surface above `x`: the fade of the ray from the eye to the point of the
/// full surface there (the weights change by far less than a wave between the two points).
fn faded_vertex(
    world: &World,
    frame: &brine_waves::SeaFrame,
    traced: &brine_waves::TracedSea<'_>,
    x: DVec2,
    footprint_m: f64,
    angle: f64,
) -> ([f32; 3], [f32; 3], f32, f32) {
    let c = world.camera.position;
    let ray = DVec3::new(x.x, frame.height(x.x, x.y), x.y) - c;
    let (t, d) = (ray.length(), ray.normalize_or_zero());
    let h = traced.faded_height(x.x, x.y, d, angle, t);
    // The shading gradient of the drawn waves (the sine sea's bump-mapped detail waves included,
    // faded as its geometric ones), as the unfaded mesh's normals carry them.
    let g = traced.faded_gradient_and_covariance(x.x, x.y, d, angle, t).0;
    let n = DVec3::new(-g.x, 1.0, -g.y).normalize();
    let p = DVec3::new(x.x, h, x.y);
    let cover = world.cover_at_time(p, n, frame.time(), footprint_m);
    (p.as_vec3().to_array(), n.as_vec3().to_array(), cover.foam as f32, cover.whitecap as f32)
}

/// Checks a [`camera_mesh`] request before any work: `pixels` in `[0.125, 64]`, a camera that
/// sees the sea, and memory the machine has.
///
/// # Errors
/// A message naming the flag and its range, the camera that sees no sea, or the memory
/// estimate.
pub fn check_camera_mesh(world: &World, pixels: f64) -> Result<(), String> {
    if !(0.125..=64.0).contains(&pixels) {
        return Err(format!("--pixels = {pixels} is out of range: expected [0.125, 64]"));
    }
    let (_, _, n) = camera_layout(world, pixels);
    if n == 0 {
        return Err("--camera: the camera sees no sea (every ray of its image points above the horizon)".to_owned());
    }
    super::check_memory(&format!("a camera mesh of {n} vertices"), n.saturating_mul(112))?;
    Ok(())
}

/// The radii and azimuths (atan2 in the x–z plane) of [`camera_mesh`] and its vertex count; no
/// ring when the camera sees no sea (every ray of its image above the horizon).
///
/// The azimuths span the image's (its horizontal field of view and a tenth each side, or the
/// azimuths of its border rays and a tenth more, for a view steep enough that its lower corners
/// reach wider), the whole circle when the image holds the nadir (a view straight down, whose
/// polar grid then starts one pixel footprint from the camera's foot). The radii end at the trace
/// distance, or nearer for an image wholly below the horizon, a fifth beyond where its farthest
/// border ray meets the troughs.
pub fn camera_layout(world: &World, pixels: f64) -> (Vec<f64>, Vec<f64>, u64) {
    let cam = &world.camera;
    let alpha = cam.pixel_angle() * pixels.max(0.125);
    let h = (cam.position.y - world.sea.height_bounds().1).max(0.5);
    let aspect = f64::from(cam.width) / f64::from(cam.height);
    let half_h = (cam.tan_half_fov * aspect).atan();
    let yaw = cam.forward.z.atan2(cam.forward.x);
    // The image's border rays, and whether the nadir is inside the image.
    let (w, hgt) = (f64::from(cam.width), f64::from(cam.height));
    let border: Vec<DVec3> = (0..=32)
        .flat_map(|i| {
            let u = f64::from(i) / 32.0;
            [
                cam.direction(u * w, 0.0),
                cam.direction(u * w, hgt),
                cam.direction(0.0, u * hgt),
                cam.direction(w, u * hgt),
            ]
        })
        .collect();
    let down = DVec3::NEG_Y;
    let (f, x, y) = (down.dot(cam.forward), down.dot(cam.right), down.dot(cam.up));
    let nadir_inside = f > 0.0 && x.abs() <= f * cam.tan_half_fov * aspect && y.abs() <= f * cam.tan_half_fov;
    // A camera above the crests sees no sea when every ray of its image points above the
    // horizon (one under the surface sees its underside whichever way it looks).
    let above = cam.position.y > world.sea.height_bounds().1;
    if above && !nadir_inside && border.iter().all(|d| d.y >= 0.0) {
        return (Vec::new(), Vec::new(), 0);
    }
    let half = if nadir_inside {
        std::f64::consts::PI
    } else {
        // The azimuths of the border rays that meet the sea (those above the horizon do not).
        let spread =
            border.iter().filter(|d| d.y < 0.0).map(|d| wrap_angle(d.z.atan2(d.x) - yaw).abs()).fold(0.0, f64::max);
        (1.2 * half_h).max(1.1 * spread).min(std::f64::consts::PI)
    };
    let count = (2.0 * half / alpha).ceil().max(1.0) as usize;
    let angles: Vec<f64> = (0..=count).map(|i| yaw - half + 2.0 * half * i as f64 / count as f64).collect();
    // From where the lowest ray meets the crests (and a fifth nearer), one footprint from the
    // foot when the image holds the nadir.
    let pitch = cam.forward.y.asin();
    let lowest = pitch - cam.tan_half_fov.atan();
    let r_min = if nadir_inside {
        alpha * h
    } else if lowest < -1e-3 {
        0.8 * h / (-lowest).tan()
    } else {
        0.5 * h * 0.8
    };
    // To the trace distance; for an image wholly below the horizon, to where its farthest border
    // ray meets the troughs (and a fifth more).
    let h_trough = (cam.position.y - world.sea.height_bounds().0).max(h);
    let farthest = border.iter().map(|d| if d.y < 0.0 { h_trough * d.x.hypot(d.z) / -d.y } else { f64::INFINITY });
    let r_max = world.trace.t_max.min(1.2 * farthest.fold(0.0, f64::max)).max(r_min * 1.01);
    let mut rings = vec![r_min];
    while let Some(&r) = rings.last() {
        if r >= r_max || rings.len() > 1 << 22 {
            break;
        }
        // A footprint along the view, `α r/sin γ`, no finer than at a third of the eye's height
        // (near the foot of a view straight down, `α r` would crowd the rings far below a pixel),
        // and stretched by at most `1/0.05` as the renderer's footprint (brine-core
        // `MIN_FOOTPRINT_GRAZING`), which keeps the waves down to that length in the faded mesh.
        let sin_grazing = (h / r.hypot(h)).max(brine_core::footprint::MIN_FOOTPRINT_GRAZING);
        rings.push((r + alpha * r.max(h / 3.0) / sin_grazing).min(r_max));
    }
    let n = (rings.len() * angles.len()) as u64;
    (rings, angles, n)
}

/// `a` wrapped to `(−π, π]` (rad).
fn wrap_angle(a: f64) -> f64 {
    let t = std::f64::consts::TAU;
    let w = a - t * (a / t).round();
    if w <= -std::f64::consts::PI { w + t } else { w }
}

/// Mesh file formats, chosen by the extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// Binary glTF 2.0 (`.glb`).
    Glb,
    /// glTF 2.0 JSON with its buffer in a `.bin` beside it (`.gltf`).
    Gltf,
    /// Wavefront OBJ with vertex normals and the white-water cover as a vertex colour.
    Obj,
    /// Binary little-endian PLY with `foam` and `whitecap` vertex properties.
    Ply,
}

impl MeshFormat {
    /// The format of `path`'s extension.
    ///
    /// # Errors
    /// A message naming the extension if it is not one of `.glb`, `.gltf`, `.obj`, `.ply`.
    pub fn from_path(path: &Path) -> Result<Self, String> {
        match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("glb") => Ok(Self::Glb),
            Some("gltf") => Ok(Self::Gltf),
            Some("obj") => Ok(Self::Obj),
            Some("ply") => Ok(Self::Ply),
            other => Err(format!(
                "--output {}: {} (expected .glb, .gltf, .obj or .ply)",
                path.display(),
                other.map_or("no extension".to_owned(), |e| format!("unsupported extension .{e}"))
            )),
        }
    }
}

/// The mesh's binary buffer (positions, normals, foam, whitecap, indices) and the glTF JSON
/// describing it; `uri` names the external buffer of a `.gltf`.
fn gltf_parts(mesh: &Mesh, uri: Option<String>) -> Result<(Vec<u8>, Vec<u8>), String> {
    use gltf::json;
    use gltf::json::validation::Checked::Valid;
    use gltf::json::validation::USize64;
    let mut bin = Vec::new();
    let n = mesh.positions.len();
    let mut put = |bytes: &[u8]| {
        let offset = bin.len();
        bin.extend_from_slice(bytes);
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        (offset, bytes.len())
    };
    let flat3 = |v: &[[f32; 3]]| v.iter().flat_map(|p| p.iter().flat_map(|c| c.to_le_bytes())).collect::<Vec<u8>>();
    let flat1 = |v: &[f32]| v.iter().flat_map(|c| c.to_le_bytes()).collect::<Vec<u8>>();
    let parts = [
        put(&flat3(&mesh.positions)),
        put(&flat3(&mesh.normals)),
        put(&flat1(&mesh.foam)),
        put(&flat1(&mesh.whitecap)),
        put(&mesh.indices.iter().flat_map(|i| i.to_le_bytes()).collect::<Vec<u8>>()),
    ];
    let mut root = json::Root::default();
    root.asset.generator = Some(format!("brine {}", env!("CARGO_PKG_VERSION")));
    let buffer = root.push(json::Buffer {
        byte_length: USize64::from(bin.len()),
        name: None,
        uri,
        extensions: Option::default(),
        extras: Default::default(),
    });
    let mut view = |(offset, len): (usize, usize), target| {
        root.push(json::buffer::View {
            buffer,
            byte_length: USize64::from(len),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            name: None,
            target: Some(Valid(target)),
            extensions: Option::default(),
            extras: Default::default(),
        })
    };
    let array = json::buffer::Target::ArrayBuffer;
    let views = [
        view(parts[0], array),
        view(parts[1], array),
        view(parts[2], array),
        view(parts[3], array),
        view(parts[4], json::buffer::Target::ElementArrayBuffer),
    ];
    let (mut lo, mut hi) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for p in &mesh.positions {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let mut accessor = |view, count: usize, component, type_, bounds: Option<(Vec<f32>, Vec<f32>)>| {
        root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: Some(USize64(0)),
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(component)),
            extensions: Option::default(),
            extras: Default::default(),
            type_: Valid(type_),
            min: bounds.as_ref().map(|b| json::Value::from(b.0.clone())),
            max: bounds.map(|b| json::Value::from(b.1)),
            name: None,
            normalized: false,
            sparse: None,
        })
    };
    use json::accessor::{ComponentType, Type};
    let position = accessor(views[0], n, ComponentType::F32, Type::Vec3, Some((lo.to_vec(), hi.to_vec())));
    let normal = accessor(views[1], n, ComponentType::F32, Type::Vec3, None);
    let foam = accessor(views[2], n, ComponentType::F32, Type::Scalar, None);
    let whitecap = accessor(views[3], n, ComponentType::F32, Type::Scalar, None);
    let indices = accessor(views[4], mesh.indices.len(), ComponentType::U32, Type::Scalar, None);
    let mut attributes = std::collections::BTreeMap::new();
    attributes.insert(Valid(json::mesh::Semantic::Positions), position);
    attributes.insert(Valid(json::mesh::Semantic::Normals), normal);
    attributes.insert(Valid(json::mesh::Semantic::Extras("FOAM".into())), foam);
    attributes.insert(Valid(json::mesh::Semantic::Extras("WHITECAP".into())), whitecap);
    let primitive = json::mesh::Primitive {
        attributes,
        extensions: Option::default(),
        extras: Default::default(),
        indices: Some(indices),
        material: None,
        mode: Valid(json::mesh::Mode::Triangles),
        targets: None,
    };
    let mesh_index = root.push(json::Mesh {
        extensions: Option::default(),
        extras: Default::default(),
        name: Some("sea".into()),
        primitives: vec![primitive],
        weights: None,
    });
    let node = root.push(json::Node { mesh: Some(mesh_index), name: Some("sea".into()), ..Default::default() });
    let scene = root.push(json::Scene {
        extensions: Option::default(),
        extras: Default::default(),
        name: Some("brine".into()),
        nodes: vec![node],
    });
    root.scene = Some(scene);
    let text = json::serialize::to_vec(&root).map_err(|e| e.to_string())?;
    Ok((text, bin))
}

/// Writes `mesh` to `path` in the format of its extension, atomically (a `.gltf` writes its
/// buffer to the `.bin` of the same name first).
///
/// # Errors
/// A message naming the path and the cause.
pub fn write_mesh(path: &Path, mesh: &Mesh) -> Result<(), String> {
    let format = MeshFormat::from_path(path)?;
    let atomic =
        |p: &Path, bytes: &[u8]| crate::output::write_atomic(p, |w| w.write_all(bytes)).map_err(|e| e.to_string());
    match format {
        MeshFormat::Glb => {
            let (json, bin) = gltf_parts(mesh, None)?;
            let pad = |n: usize| n.div_ceil(4) * 4;
            let length = 12 + 8 + pad(json.len()) + 8 + pad(bin.len());
            let glb = gltf::binary::Glb {
                header: gltf::binary::Header {
                    magic: *b"glTF",
                    version: 2,
                    length: u32::try_from(length).map_err(|_| "the mesh is larger than a GLB file holds (4 GiB): use .gltf, .obj or .ply".to_owned())?,
                },
                json: std::borrow::Cow::Owned(json),
                bin: Some(std::borrow::Cow::Owned(bin)),
            };
            let bytes = glb.to_vec().map_err(|e| e.to_string())?;
            atomic(path, &bytes)
        }
        MeshFormat::Gltf => {
            let bin_path = path.with_extension("bin");
            let uri = uri_path_segment(bin_path.file_name().and_then(|n| n.to_str()).unwrap_or("sea.bin"));
            let (json, bin) = gltf_parts(mesh, Some(uri))?;
            atomic(&bin_path, &bin)?;
            atomic(path, &json)
        }
        MeshFormat::Obj => crate::output::write_atomic(path, |w| {
            writeln!(
                w,
                "# brine {}: the sea surface; vertex colour = (foam, whitecap, 0); {} vertices, {} triangles",
                env!("CARGO_PKG_VERSION"),
                mesh.positions.len(),
                mesh.indices.len() / 3
            )?;
            for (k, p) in mesh.positions.iter().enumerate() {
                writeln!(w, "v {} {} {} {} {} 0", p[0], p[1], p[2], mesh.foam[k], mesh.whitecap[k])?;
            }
            for n in &mesh.normals {
                writeln!(w, "vn {} {} {}", n[0], n[1], n[2])?;
            }
            for t in mesh.indices.chunks_exact(3) {
                let (a, b, c) = (t[0] + 1, t[1] + 1, t[2] + 1);
                writeln!(w, "f {a}//{a} {b}//{b} {c}//{c}")?;
            }
            Ok(())
        })
        .map_err(|e| e.to_string()),
        MeshFormat::Ply => crate::output::write_atomic(path, |w| {
            write!(
                w,
                "ply\nformat binary_little_endian 1.0\ncomment brine {}: the sea surface, y up\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float foam\nproperty float whitecap\nelement face {}\nproperty list uchar uint vertex_indices\nend_header\n",
                env!("CARGO_PKG_VERSION"),
                mesh.positions.len(),
                mesh.indices.len() / 3
            )?;
            for k in 0..mesh.positions.len() {
                for c in mesh.positions[k].iter().chain(&mesh.normals[k]).chain([&mesh.foam[k], &mesh.whitecap[k]]) {
                    w.write_all(&c.to_le_bytes())?;
                }
            }
            for t in mesh.indices.chunks_exact(3) {
                w.write_all(&[3u8])?;
                for i in t {
                    w.write_all(&i.to_le_bytes())?;
                }
            }
            Ok(())
        })
        .map_err(|e| e.to_string()),
    }
}

/// Whether the mesh file `path` (as [`write_mesh`] writes it) is there in full: a valid glTF
/// whose binary buffer (the `.glb`'s chunk, or the `.gltf`'s `.bin`) holds its declared length; a
/// PLY file of the length its header's vertex and face counts give; an OBJ file of the vertices,
/// normals and faces its first line counts, its last line ended. What `--resume` keeps.
pub fn mesh_is_complete(path: &Path) -> bool {
    let Ok(bytes) = std::fs::read(path) else { return false };
    let Ok(format) = MeshFormat::from_path(path) else { return false };
    match format {
        MeshFormat::Glb => gltf::Gltf::from_slice(&bytes).is_ok_and(|g| {
            let declared: u64 = g.buffers().map(|b| b.length() as u64).sum();
            g.blob.as_ref().is_some_and(|b| b.len() as u64 >= declared)
        }),
        MeshFormat::Gltf => gltf::Gltf::from_slice(&bytes).is_ok_and(|g| {
            g.buffers().all(|b| match b.source() {
                gltf::buffer::Source::Uri(_) => {
                    std::fs::metadata(path.with_extension("bin")).is_ok_and(|m| m.len() == b.length() as u64)
                }
                gltf::buffer::Source::Bin => false,
            })
        }),
        MeshFormat::Ply => {
            let Some(end) = bytes.windows(11).position(|w| w == b"end_header\n").map(|i| i + 11) else { return false };
            let header = String::from_utf8_lossy(&bytes[..end]);
            let count = |element: &str| {
                header.lines().find_map(|l| l.strip_prefix(&format!("element {element} "))?.trim().parse::<u64>().ok())
            };
            match (count("vertex"), count("face")) {
                // Eight floats a vertex; a count byte and three indices a triangle.
                (Some(v), Some(f)) => bytes.len() as u64 == end as u64 + 32 * v + 13 * f,
                _ => false,
            }
        }
        MeshFormat::Obj => {
            // The counts the first line declares, against the lines that follow.
            let text = String::from_utf8_lossy(&bytes);
            let declared = text.lines().next().and_then(|l| {
                let (_, counts) = l.rsplit_once("; ")?;
                let mut words = counts.split(' ');
                let v = words.next()?.parse::<usize>().ok()?;
                let f = words.nth(1)?.parse::<usize>().ok()?;
                Some((v, f))
            });
            let lines = |prefix: &str| text.lines().filter(|l| l.starts_with(prefix)).count();
            declared == Some((lines("v "), lines("f "))) && lines("vn ") == lines("v ") && text.ends_with('\n')
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_are_checked_and_huge_ones_refused_up_front() {
        let g = MeshGrid { center: DVec2::ZERO, size_m: 10.0, spacing_m: 1.0 };
        assert_eq!(g.count(), 11);
        assert!(g.check().is_ok());
        let huge = MeshGrid { spacing_m: 1e-3, size_m: 100.0, ..g };
        let e = huge.check().unwrap_err();
        assert!(e.contains("vertices"), "{e}");
        // A billion vertices fit 32-bit indices but not this machine's memory.
        let billion = MeshGrid { spacing_m: 1e-2, size_m: 316.0, ..g };
        if let Some(avail) = super::super::available_memory_bytes()
            && billion.memory_estimate() > avail / 10 * 8
        {
            let e = billion.check().unwrap_err();
            assert!(e.contains("GiB"), "{e}");
        }
        assert!(MeshGrid { spacing_m: 0.0, ..g }.check().unwrap_err().contains("--spacing-m"));
        assert!(MeshGrid { size_m: f64::NAN, ..g }.check().unwrap_err().contains("--size-m"));
    }

    #[test]
    fn grid_triangles_face_up() {
        let verts = (0..9).map(|k| ([(k % 3) as f32, 0.0, (k / 3) as f32], [0.0, 1.0, 0.0], 0.0, 0.0)).collect();
        let m = grid_of(3, 3, verts);
        assert_eq!(m.indices.len(), 2 * 2 * 6);
        for t in m.indices.chunks_exact(3) {
            let p = |i: u32| glam::Vec3::from_array(m.positions[i as usize]);
            let n = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
            assert!(n.y > 0.0, "{t:?}");
        }
    }

    /// A `.gltf`'s buffer is named by a relative URI: reserved characters and non-ASCII bytes are
    /// percent-encoded (UTF-8), the unreserved kept (RFC 3986 §2.3).
    #[test]
    fn buffer_names_are_uri_segments() {
        assert_eq!(uri_path_segment("sea_0001.bin"), "sea_0001.bin");
        assert_eq!(uri_path_segment("p%41 #1?.bin"), "p%2541%20%231%3F.bin");
        assert_eq!(uri_path_segment("mer-é~.bin"), "mer-%C3%A9~.bin");
    }

    /// The camera mesh's triangles face up too (counter-clockwise seen from above, as the docs
    /// say and single-sided viewers need), and agree with its vertex normals, on an oblique and a
    /// nadir view. (Its polar layout is the grid's mirrored: it was once wound face down.)
    #[test]
    fn camera_mesh_triangles_face_up() {
        for pitch in [-8.0, -90.0] {
            let mut scene = crate::Scene::default_scene();
            scene.camera.pitch_deg = Some(pitch);
            scene.camera.width = 64;
            scene.camera.height = 36;
            let world = crate::World::new(&scene).expect("a valid scene");
            let m = camera_mesh(&world, 0.0, 16.0, false);
            assert!(!m.indices.is_empty());
            for t in m.indices.chunks_exact(3) {
                let p = |i: u32| glam::Vec3::from_array(m.positions[i as usize]);
                let face = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
                let normal = glam::Vec3::from_array(m.normals[t[0] as usize]);
                assert!(face.y > 0.0 && face.dot(normal) > 0.0, "pitch {pitch}: {t:?} faces {face}");
            }
        }
    }
}
