//! `brine.Scene`: a scene from TOML text or a dict, rendered to arrays, queried at points, meshed
//! and baked to maps — the same code as `brine render`, `brine query`, `brine mesh` and
//! `brine bake`.

use std::sync::OnceLock;

use brine_render::export::{
    BakeOptions, MeshGrid, QueryPoint, UpAxis, bake_frame, camera_mesh, check_camera_mesh, grid_mesh,
    grid_mesh_band_limited, query_points,
};
use brine_render::{RenderOptions, World};
use numpy::{IntoPyArray, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::bad;

/// A checked scene (the TOML keys of docs/scene.md), with its sea built on first use.
#[pyclass(frozen, module = "brine._brine")]
pub(crate) struct Scene {
    scene: brine_render::Scene,
    toml: String,
    world: OnceLock<World>,
    /// What does not change between the frames of an animation, built on the first frame.
    timeless: OnceLock<brine_render::Timeless>,
}

/// A scene error as a Python exception: file, line and key, as the command line prints it.
fn scene_err(e: impl std::fmt::Display) -> PyErr {
    bad(e.to_string())
}

impl Scene {
    fn new(scene: brine_render::Scene, toml: String) -> Self {
        Self { scene, toml, world: OnceLock::new(), timeless: OnceLock::new() }
    }

    /// The world of the scene at its own time, built once.
    fn world(&self, py: Python<'_>) -> PyResult<&World> {
        if let Some(w) = self.world.get() {
            return Ok(w);
        }
        let built = py.detach(|| World::new(&self.scene)).map_err(scene_err)?;
        Ok(self.world.get_or_init(|| built))
    }
}

/// A Python `UserWarning` when the FFT sea's `sea.fft.loop_period_s` moves much of the sea off its
/// dispersion relation: the warning `brine render` prints (brine-render
/// [`brine_render::cli::loop_warning`]).
fn warn_of_loop(py: Python<'_>, world: &World, scene: &brine_render::Scene) -> PyResult<()> {
    match (world.loop_distortion(), scene.sea.fft.loop_period_s) {
        (Some(d), Some(period)) => warn_of_distortion(py, d, period, "sea.fft.loop_period_s"),
        _ => Ok(()),
    }
}

/// A Python `UserWarning` when a loop of `period_s` set by `setting` moves much of the sea off its
/// dispersion relation ([`brine_render::cli::loop_warning`]); nothing otherwise.
fn warn_of_distortion(py: Python<'_>, d: &brine_waves::LoopDistortion, period_s: f64, setting: &str) -> PyResult<()> {
    let Some(message) = brine_render::cli::loop_warning(d, period_s, setting) else { return Ok(()) };
    let message = message.strip_prefix("warning: ").unwrap_or(&message);
    let text = std::ffi::CString::new(message).map_err(|e| bad(e.to_string()))?;
    // Level 2: the line of the caller of the package's method, not the method's own.
    PyErr::warn(py, &py.get_type::<pyo3::exceptions::PyUserWarning>(), &text, 2)
}

/// Rows of `n` values per pixel as an array of shape `(height, width, n)` (or `(height, width)`).
fn image<'py>(py: Python<'py>, flat: Vec<f32>, h: usize, w: usize, n: usize) -> PyResult<Bound<'py, PyAny>> {
    let a = flat.into_pyarray(py);
    Ok(if n == 1 { a.reshape([h, w])?.into_any() } else { a.reshape([h, w, n])?.into_any() })
}

#[pymethods]
impl Scene {
    /// A scene from TOML text (the format of `brine render SCENE`); without text, the embedded
    /// default scene. `name` names the text in error messages.
    #[new]
    #[pyo3(signature = (toml = None, name = "<string>"))]
    fn py_new(toml: Option<&str>, name: &str) -> PyResult<Self> {
        match toml {
            None => Ok(Self::new(brine_render::Scene::default_scene(), String::new())),
            Some(text) => {
                let scene = brine_render::Scene::from_toml_str(text, name).map_err(scene_err)?;
                Ok(Self::new(scene, text.to_owned()))
            }
        }
    }

    /// A scene from a dict of tables (`{"sea": {"wind_speed_m_s": 16}, "camera": {...}}`): the
    /// keys not given take their defaults, as in a TOML file.
    #[staticmethod]
    fn from_dict(d: &Bound<'_, PyDict>) -> PyResult<Self> {
        let table: toml::Table = pythonize::depythonize(d.as_any())
            .map_err(|e| bad(format!("the scene dict is not a table of TOML values: {e}")))?;
        let text =
            toml::to_string(&table).map_err(|e| bad(format!("the scene dict cannot be written as TOML: {e}")))?;
        let scene = brine_render::Scene::from_toml_str(&text, "<dict>").map_err(scene_err)?;
        Ok(Self::new(scene, text))
    }

    /// A scene read from a TOML file.
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Self> {
        let scene = brine_render::Scene::load(&path).map_err(scene_err)?;
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        Ok(Self::new(scene, text))
    }

    /// The TOML text the scene was made from (empty for the default scene).
    #[getter]
    fn toml(&self) -> &str {
        &self.toml
    }

    /// `(width, height)` of the camera's image (pixels).
    #[getter]
    fn size(&self) -> (u32, u32) {
        (self.scene.camera.width, self.scene.camera.height)
    }

    /// The scene's time (s), where queries and bakes default.
    #[getter]
    fn time_s(&self) -> f64 {
        self.scene.sea.time_s
    }

    /// Renders the scene as `brine render` does, with Python's lock released.
    ///
    /// `threads`: worker threads (`None`: every core; the image does not depend on it);
    /// `reference`: the reference rendering (nothing filtered by the pixel footprint); `frame`:
    /// frame `f ≥ 0` of the scene's animation, as `brine render --frames` renders it (the waves
    /// at `sea.time_s + f/fps`, the sun and moon at `place.time_utc + f/fps`), the parts that do
    /// not change between frames built once for the scene; `None`: the still.
    ///
    /// Returns a dict: `rgb` (float32, `(height, width, 3)`, linear sRGB radiance in kcd m⁻²),
    /// `depth` (m, infinite for the sky), `normal` (`(height, width, 3)`), `foam`, `whitecap`,
    /// `glint` (sr⁻¹), and `exposure_ev`, the exposure the command line would display it with.
    #[pyo3(signature = (threads = None, reference = false, frame = None))]
    fn render<'py>(
        &self,
        py: Python<'py>,
        threads: Option<usize>,
        reference: bool,
        frame: Option<u32>,
    ) -> PyResult<Bound<'py, PyDict>> {
        if threads == Some(0) {
            return Err(bad("threads = 0 is out of range: expected at least 1 (or None for every core)"));
        }
        let options = RenderOptions { threads, profile: false, reference };
        // A scene the models refuse is bad input (`BrineError`); a failure to run is not.
        let failed = |e: brine_render::RenderError| match e {
            brine_render::RenderError::World(w) => scene_err(w),
            other => pyo3::exceptions::PyRuntimeError::new_err(other.to_string()),
        };
        let frame = match frame {
            // The scene's own world, built once and shared with queries and meshes.
            None if !reference => {
                let world = self.world(py)?;
                warn_of_loop(py, world, &self.scene)?;
                py.detach(|| brine_render::render_world(&self.scene, world, &options, &|| {})).map_err(failed)?
            }
            None => {
                let mut world = py.detach(|| World::new(&self.scene)).map_err(scene_err)?;
                world.set_reference(true);
                warn_of_loop(py, &world, &self.scene)?;
                py.detach(|| brine_render::render_world(&self.scene, &world, &options, &|| {})).map_err(failed)?
            }
            Some(f) => {
                let s = brine_render::cli::render::scene_at_frame(&self.scene, f, (0, f.saturating_add(1)), None)
                    .map_err(crate::py_err)?;
                let timeless = match self.timeless.get() {
                    Some(t) => t,
                    None => {
                        let built = py.detach(|| brine_render::Timeless::new(&self.scene, None)).map_err(scene_err)?;
                        self.timeless.get_or_init(|| built)
                    }
                };
                let mut world = py.detach(|| World::at_instant(&s, timeless)).map_err(scene_err)?;
                world.set_reference(reference);
                warn_of_loop(py, &world, &self.scene)?;
                py.detach(|| brine_render::render_world(&s, &world, &options, &|| {})).map_err(failed)?
            }
        };
        let (w, h) = (frame.width as usize, frame.height as usize);
        let d = PyDict::new(py);
        let rgb: Vec<f32> = frame.pixels.iter().flat_map(|p| p.as_vec3().to_array()).collect();
        d.set_item("rgb", image(py, rgb, h, w, 3)?)?;
        let a = &frame.aovs;
        d.set_item("depth", image(py, a.iter().map(|v| v.depth).collect(), h, w, 1)?)?;
        d.set_item("normal", image(py, a.iter().flat_map(|v| v.normal).collect(), h, w, 3)?)?;
        d.set_item("foam", image(py, a.iter().map(|v| v.foam).collect(), h, w, 1)?)?;
        d.set_item("whitecap", image(py, a.iter().map(|v| v.whitecap).collect(), h, w, 1)?)?;
        d.set_item("glint", image(py, a.iter().map(|v| v.glint).collect(), h, w, 1)?)?;
        d.set_item("exposure_ev", frame.exposure_ev)?;
        Ok(d)
    }

    /// The rendered surface at points `(x, z)` (m, east and south) and times `t` (s, the scene's
    /// clock; `None`: the scene's time), as `brine query`: arrays of one length.
    ///
    /// Returns a dict of arrays: `height_m`, `normal` (`(n, 3)`), `displacement_m` (`(n, 2)`),
    /// `velocity_m_s` (`(n, 3)`), `vertical_acceleration_m_s2`, `jacobian`, `foam`, `whitecap`.
    #[pyo3(signature = (x, z, t = None))]
    fn query<'py>(
        &self,
        py: Python<'py>,
        x: PyReadonlyArray1<'py, f64>,
        z: PyReadonlyArray1<'py, f64>,
        t: Option<PyReadonlyArray1<'py, f64>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (xs, zs) = (x.as_slice()?, z.as_slice()?);
        let ts: Option<&[f64]> = match &t {
            Some(a) => Some(a.as_slice()?),
            None => None,
        };
        if xs.len() != zs.len() || ts.is_some_and(|t| t.len() != xs.len()) {
            return Err(bad("x, z and t must have one length"));
        }
        let t0 = self.scene.sea.time_s;
        let mut points = Vec::with_capacity(xs.len());
        for i in 0..xs.len() {
            let p = QueryPoint { x: xs[i], z: zs[i], t: ts.map_or(t0, |t| t[i]) };
            let ok = |v: f64| v.is_finite() && v.abs() <= 1e9;
            if !(ok(p.x) && ok(p.z) && ok(p.t)) {
                return Err(bad(format!(
                    "point {i} = ({}, {}, {}): expected x, z (m) and t (s) finite, in [-1e9, 1e9]",
                    p.x, p.z, p.t
                )));
            }
            points.push(p);
        }
        let world = self.world(py)?;
        let r = py.detach(|| query_points(&self.scene, world, &points)).map_err(scene_err)?;
        let d = PyDict::new(py);
        let n = r.len();
        let col = |f: &dyn Fn(&brine_render::export::QueryResult) -> f64| -> Vec<f64> { r.iter().map(f).collect() };
        let rows = |v: Vec<f64>, k: usize| -> PyResult<Bound<'py, PyAny>> {
            Ok(v.into_pyarray(py).reshape([n, k])?.into_any())
        };
        d.set_item("height_m", col(&|q| q.height_m).into_pyarray(py))?;
        d.set_item("normal", rows(r.iter().flat_map(|q| q.normal).collect(), 3)?)?;
        d.set_item("displacement_m", rows(r.iter().flat_map(|q| q.displacement_m).collect(), 2)?)?;
        d.set_item("velocity_m_s", rows(r.iter().flat_map(|q| q.velocity_m_s).collect(), 3)?)?;
        d.set_item("vertical_acceleration_m_s2", col(&|q| q.vertical_acceleration_m_s2).into_pyarray(py))?;
        d.set_item("jacobian", col(&|q| q.jacobian).into_pyarray(py))?;
        d.set_item("foam", col(&|q| q.foam).into_pyarray(py))?;
        d.set_item("whitecap", col(&|q| q.whitecap).into_pyarray(py))?;
        Ok(d)
    }

    /// Tileable maps of the sea over a square tile at time `t`, as `brine bake` writes them.
    ///
    /// `size`: texels per side, [2, 16384]; `tile_m`: side of the tile (m; `None`: the sea's
    /// own, as `brine bake`); `t`: time (s; `None`: the scene's); `up`: `"y"` (Brine, glTF,
    /// Houdini, Unity) or `"z"` (Blender) for the vector maps; `loop_s`: a loop period (s), as
    /// `brine bake --loop-s`: the waves' frequencies snapped so that the maps repeat after it
    /// (a `UserWarning` when that moves much of the sea off its dispersion relation).
    ///
    /// Returns a dict of float32 arrays, row `j` at `z = j·tile/size`: `displacement`
    /// (`(size, size, 3)`, m), `normal`, `foam`, `whitecap`, `jacobian`, `spray` (the minor
    /// eigenvector and its eigenvalue); and `tile_m`, `time_s`, `grid_limit`, `loop_period_s`
    /// (`loop_s`, or the FFT sea's own `loop_period_s`, or `None`) and `loop_distortion` (as in
    /// `bake.json`, or `None`).
    #[pyo3(signature = (size = 512, tile_m = None, t = None, up = "y", loop_s = None))]
    fn bake<'py>(
        &self,
        py: Python<'py>,
        size: usize,
        tile_m: Option<f64>,
        t: Option<f64>,
        up: &str,
        loop_s: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let up = match up {
            "y" | "Y" => UpAxis::Y,
            "z" | "Z" => UpAxis::Z,
            other => return Err(bad(format!("up = {other:?}: expected \"y\" or \"z\""))),
        };
        let tile_m = match tile_m {
            Some(v) => v,
            None => brine_render::cli::export::default_tile_m(&self.scene).map_err(crate::py_err)?,
        };
        let options = BakeOptions { size, tile_m, up };
        options.check().map_err(|m| bad(m.replace("--size", "size").replace("--tile-m", "tile_m")))?;
        let t = t.unwrap_or(self.scene.sea.time_s);
        if !(t.is_finite() && t.abs() <= 1e9) {
            return Err(bad(format!("t = {t}: expected a finite time in [-1e9, 1e9] s")));
        }
        let lattice = brine_waves::TileLattice::new(tile_m, loop_s).map_err(scene_err)?;
        let mut scene = self.scene.clone();
        let fft = matches!(scene.sea.surface, brine_render::scene::SurfaceKind::Fft);
        if fft {
            // The FFT sea's white water belongs to its frame: the world is built at `t`.
            scene.sea.time_s = t;
        }
        let (frame, distortion) = py
            .detach(|| {
                World::on_lattice(&scene, Some(&lattice))
                    .map(|w| (bake_frame(&w, t, &options), w.loop_distortion().cloned()))
            })
            .map_err(scene_err)?;
        // The loop the maps repeat after, as `brine bake` tells it.
        let (loop_period, setting) = match (loop_s, fft.then_some(self.scene.sea.fft.loop_period_s).flatten()) {
            (Some(p), _) => (Some(p), "loop_s"),
            (None, own) => (own, "sea.fft.loop_period_s"),
        };
        if let (Some(d), Some(period)) = (&distortion, loop_period) {
            warn_of_distortion(py, d, period, setting)?;
        }
        let loop_distortion = distortion.map(|d| {
            let m = PyDict::new(py);
            m.set_item("frequency_change_rms", d.rms())?;
            m.set_item("variance_share_moved_over_5_percent", d.share_moved())?;
            m.set_item("suggested_period_s", d.suggested_period_s())?;
            Ok::<_, PyErr>(m)
        });
        let n = frame.size;
        let limit = frame.limit.map(|l| brine_render::cli::export::grid_limit_json(&l, up));
        let m = frame.maps;
        let grid3 = |v: Vec<[f32; 3]>| -> PyResult<Bound<'py, PyAny>> {
            Ok(v.into_iter().flatten().collect::<Vec<f32>>().into_pyarray(py).reshape([n, n, 3])?.into_any())
        };
        let grid1 = |v: Vec<f32>| -> PyResult<Bound<'py, PyAny>> { Ok(v.into_pyarray(py).reshape([n, n])?.into_any()) };
        let d = PyDict::new(py);
        d.set_item("displacement", grid3(m.displacement)?)?;
        d.set_item("normal", grid3(m.normal)?)?;
        d.set_item("foam", grid1(m.foam)?)?;
        d.set_item("whitecap", grid1(m.whitecap)?)?;
        d.set_item("jacobian", grid1(m.jacobian)?)?;
        d.set_item("spray", grid3(m.spray)?)?;
        d.set_item("tile_m", tile_m)?;
        d.set_item("time_s", frame.time)?;
        d.set_item("grid_limit", pythonize::pythonize(py, &limit)?)?;
        d.set_item("loop_period_s", loop_period)?;
        d.set_item("loop_distortion", loop_distortion.transpose()?)?;
        Ok(d)
    }

    /// The rendered sea as a triangle mesh, as `brine mesh`, from the command's own keywords
    /// (`size_m`, `spacing_m`, `center` as `"x,z"`, `time`, `band_limit`, `camera`, `pixels`,
    /// `faded`), checked by its parser.
    ///
    /// Returns a dict: `positions` (float32 `(n, 3)`, m, y up), `normals` (`(n, 3)`), `foam`,
    /// `whitecap` (`(n,)`), `indices` (uint32 `(m, 3)`, counter-clockwise seen from above),
    /// `time_s`, and `grid_limit` (as `brine bake`'s, with `band_limit`; else `None`).
    #[pyo3(signature = (**kwargs))]
    fn mesh<'py>(&self, py: Python<'py>, kwargs: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyDict>> {
        // The output is the command's, not written: the parser wants one.
        let args = match crate::parse_cli(&["mesh"], &[("output", "mesh.ply".to_owned())], kwargs)? {
            brine_render::cli::Command::Mesh(args) => args,
            _ => return Err(bad("the mesh command's parser returned another command")),
        };
        let renamed = |m: String| {
            bad(m
                .replace("--size-m", "size_m")
                .replace("--spacing-m", "spacing_m")
                .replace("--pixels", "pixels")
                .replace("--faded", "faded")
                .replace("--band-limit", "band_limit"))
        };
        let grid = MeshGrid { center: args.center, size_m: args.size_m, spacing_m: args.spacing_m };
        if !args.camera {
            grid.check().map_err(renamed)?;
        }
        let (camera, pixels, faded, band_limit) = (args.camera, args.pixels, args.faded, args.band_limit);
        let t0 = self.scene.sea.time_s;
        let t = args.time.unwrap_or(t0);
        // As `brine mesh --time`: the world of the scene at `t` (the FFT sea's white water
        // belongs to its frame), the scene's own world when `t` is its time.
        let other;
        let world = if t.to_bits() == t0.to_bits() {
            self.world(py)?
        } else {
            let mut scene = self.scene.clone();
            scene.sea.time_s = t;
            other = py.detach(|| World::new(&scene)).map_err(scene_err)?;
            &other
        };
        let (mesh, limit) = if camera {
            check_camera_mesh(world, pixels).map_err(renamed)?;
            (py.detach(|| camera_mesh(world, t, pixels, faded)), None)
        } else if band_limit {
            let (m, l) = py.detach(|| grid_mesh_band_limited(world, t, &grid)).map_err(renamed)?;
            (m, Some(l))
        } else {
            (py.detach(|| grid_mesh(world, t, &grid)), None)
        };
        let n = mesh.positions.len();
        let rows3 = |v: Vec<[f32; 3]>| -> PyResult<Bound<'py, PyAny>> {
            Ok(v.into_iter().flatten().collect::<Vec<f32>>().into_pyarray(py).reshape([n, 3])?.into_any())
        };
        let triangles = mesh.indices.len() / 3;
        let d = PyDict::new(py);
        d.set_item("positions", rows3(mesh.positions)?)?;
        d.set_item("normals", rows3(mesh.normals)?)?;
        d.set_item("foam", mesh.foam.into_pyarray(py))?;
        d.set_item("whitecap", mesh.whitecap.into_pyarray(py))?;
        d.set_item("indices", mesh.indices.into_pyarray(py).reshape([triangles, 3])?)?;
        d.set_item("time_s", t)?;
        let limit = limit.map(|l| brine_render::cli::export::grid_limit_json(&l, UpAxis::Y));
        d.set_item("grid_limit", pythonize::pythonize(py, &limit)?)?;
        Ok(d)
    }
}
