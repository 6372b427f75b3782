//! `brine query`, `brine mesh`, `brine bake`: the rendered sea handed to other tools.

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

use glam::DVec2;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::CliError;
use crate::export::{BakeOptions, MeshFormat, MeshGrid, UpAxis};
use crate::{Scene, World};

/// Loads `path` (or the default scene) and sets the sea's time when `time` is given.
fn load(path: Option<&PathBuf>, time: Option<f64>) -> Result<Scene, CliError> {
    let mut scene = match path {
        Some(p) => Scene::load(p).map_err(|e| CliError::Input(e.to_string()))?,
        None => Scene::default_scene(),
    };
    if let Some(t) = time {
        scene.sea.time_s = t;
    }
    Ok(scene)
}

fn world_of(scene: &Scene, lattice: Option<&brine_waves::TileLattice>) -> Result<World, CliError> {
    World::on_lattice(scene, lattice).map_err(|e| CliError::Input(e.to_string()))
}

/// Output format of `brine query`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum QueryFormat {
    /// One JSON array of objects.
    #[default]
    Json,
    /// Comma-separated values with a header line.
    Csv,
}

/// Arguments of `brine query`.
#[derive(Debug, Clone, clap::Args)]
pub struct QueryArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Points `x,z[,t];…` (m, s); a point without `t` is at the scene's `sea.time_s`.
    #[arg(long, conflicts_with = "stdin", required_unless_present = "stdin", allow_hyphen_values = true)]
    pub points: Option<String>,
    /// Read the points from standard input, one `x,z[,t]` a line (`#` starts a comment).
    #[arg(long)]
    pub stdin: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t)]
    pub format: QueryFormat,
    /// Time of the points that give none (s, [-1e9, 1e9], as a point's own); overrides `sea.time_s`.
    #[arg(long, allow_hyphen_values = true, value_parser = super::within(-1e9, 1e9))]
    pub time: Option<f64>,
}

/// Runs `brine query`.
///
/// # Errors
/// [`CliError::Input`] for a bad scene or point.
pub fn run_query(args: &QueryArgs) -> Result<(), CliError> {
    let scene = load(args.scene.as_ref(), args.time)?;
    let points = match (&args.points, args.stdin) {
        (Some(text), _) => crate::export::parse_points(text, scene.sea.time_s, "--points"),
        (None, _) => {
            let mut text = String::new();
            for line in std::io::stdin().lock().lines() {
                let line = line.map_err(|e| CliError::Failure(format!("cannot read standard input: {e}")))?;
                text.push_str(&line);
                text.push('\n');
            }
            crate::export::parse_points(&text, scene.sea.time_s, "stdin")
        }
    }
    .map_err(CliError::Input)?;
    let world = world_of(&scene, None)?;
    let results = crate::export::query_points(&scene, &world, &points).map_err(|e| CliError::Input(e.to_string()))?;
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = match args.format {
        QueryFormat::Json => serde_json::to_writer_pretty(&mut out, &results)
            .map_err(std::io::Error::other)
            .and_then(|()| writeln!(out)),
        QueryFormat::Csv => (|| {
            writeln!(
                out,
                "x,z,t,height_m,normal_x,normal_y,normal_z,displacement_x_m,displacement_z_m,velocity_x_m_s,velocity_y_m_s,velocity_z_m_s,vertical_acceleration_m_s2,jacobian,foam,whitecap"
            )?;
            for r in &results {
                writeln!(
                    out,
                    "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                    r.x,
                    r.z,
                    r.t,
                    r.height_m,
                    r.normal[0],
                    r.normal[1],
                    r.normal[2],
                    r.displacement_m[0],
                    r.displacement_m[1],
                    r.velocity_m_s[0],
                    r.velocity_m_s[1],
                    r.velocity_m_s[2],
                    r.vertical_acceleration_m_s2,
                    r.jacobian,
                    r.foam,
                    r.whitecap
                )?;
            }
            Ok(())
        })(),
    }
    .and_then(|()| out.flush());
    match written {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(CliError::Failure(format!("cannot write to standard output: {e}"))),
        Ok(()) => Ok(()),
    }
}

/// Parses `x,z`, each in [-1e9, 1e9] m (as a queried point's).
fn parse_xz(s: &str) -> Result<DVec2, String> {
    let (a, b) = s.split_once(',').ok_or_else(|| format!("expected x,z (metres), got {s:?}"))?;
    let within = super::within(-1e9, 1e9);
    Ok(DVec2::new(within(a.trim())?, within(b.trim())?))
}

/// Arguments of `brine mesh`.
#[derive(Debug, Clone, clap::Args)]
pub struct MeshArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Output mesh: `.glb`, `.gltf` (with a `.bin` beside it), `.obj` or `.ply`.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Side of the square grid (m).
    #[arg(long, default_value_t = 100.0, value_parser = super::finite, conflicts_with = "camera")]
    pub size_m: f64,
    /// Distance between the grid's rest positions (m).
    #[arg(long, default_value_t = 0.5, value_parser = super::finite, conflicts_with = "camera")]
    pub spacing_m: f64,
    /// Centre of the grid `x,z` (m).
    #[arg(long, value_parser = parse_xz, default_value = "0,0", allow_hyphen_values = true, conflicts_with = "camera")]
    pub center: DVec2,
    /// A camera-adaptive mesh instead: spacing following the pixel footprint of the scene's
    /// camera, over its field of view out to the trace distance.
    #[arg(long)]
    pub camera: bool,
    /// With `--camera`: pixel footprints per edge.
    #[arg(long, default_value_t = 2.0, value_parser = super::within(0.125, 64.0), requires = "camera")]
    pub pixels: f64,
    /// With `--camera`: the surface as the camera's rays draw it, the far waves (or the FFT
    /// sea's cascades) faded with the pixel footprint; without, every wave everywhere.
    #[arg(long, requires = "camera")]
    pub faded: bool,
    /// With the regular grid: leave out the waves shorter than two spacings, which the grid would
    /// show as other, longer waves, and fade those up to three (the trochoid, Gerstner and FFT seas);
    /// the slope covariance left out is printed, for a roughness on the mesh's material. Without,
    /// every vertex lies on the rendered surface, short waves included.
    #[arg(long, conflicts_with = "camera")]
    pub band_limit: bool,
    /// Time of the surface (s, [-1e9, 1e9]); overrides `sea.time_s`.
    #[arg(long, allow_hyphen_values = true, value_parser = super::within(-1e9, 1e9))]
    pub time: Option<f64>,
    /// A mesh sequence: frames `A..B` (B excluded) or a count `N` (= `0..N`), frame `f` at
    /// `sea.time_s + f/fps` (`--time` for `sea.time_s`); the output path must hold a run of `#`
    /// replaced by the zero-padded frame number.
    #[arg(long, value_parser = super::render::parse_frames)]
    pub frames: Option<(u32, u32)>,
    /// With `--frames`: keep the frames already written in full by an interrupted run of the same
    /// command (a file cut short is made again; temporaries left by a killed run are removed)
    #[arg(long, requires = "frames")]
    pub resume: bool,
    /// No summary.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Runs `brine mesh`.
///
/// # Errors
/// [`CliError::Input`] for bad input (nothing is written), [`CliError::Failure`] for I/O.
pub fn run_mesh(args: &MeshArgs) -> Result<(), CliError> {
    MeshFormat::from_path(&args.output).map_err(CliError::Input)?;
    let (first, last) = args.frames.unwrap_or((0, 1));
    let path_of = |f: u32| match args.frames {
        Some(_) => super::render::frame_path(&args.output, f),
        None => Ok(args.output.clone()),
    };
    crate::output::check_writable(&path_of(first).map_err(CliError::Input)?).map_err(CliError::Input)?;
    let scene = load(args.scene.as_ref(), args.time)?;
    let grid = MeshGrid { center: args.center, size_m: args.size_m, spacing_m: args.spacing_m };
    if !args.camera {
        grid.check().map_err(CliError::Input)?;
    }
    crate::output::remove_temporaries_on_signal().map_err(CliError::Failure)?;
    let started = std::time::Instant::now();
    let world = world_of(&scene, None)?;
    if args.camera {
        crate::export::check_camera_mesh(&world, args.pixels).map_err(CliError::Input)?;
    }
    let time_of =
        |f: u32| if f == 0 { scene.sea.time_s } else { scene.sea.time_s + f64::from(f) / scene.animation.fps };
    check_last_frame(last - 1, time_of(last - 1))?;
    // Each frame of a sequence has the world `brine mesh --time` builds for it alone (the white
    // water's state belongs to its instant), from the parts that do not change built once.
    let timeless = match args.frames {
        Some(_) => Some(crate::world::Timeless::new(&scene, None).map_err(|e| CliError::Input(e.to_string()))?),
        None => None,
    };
    let bar = if args.quiet || args.frames.is_none() || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        let b = ProgressBar::with_draw_target(Some(u64::from(last - first)), ProgressDrawTarget::stderr());
        b.set_style(
            ProgressStyle::with_template("meshing {bar:40} {pos}/{len} frames, {eta} left")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        b
    };
    let mut limit = None;
    let mut last_mesh = (0, 0);
    let mut resumed = 0u32;
    for f in first..last {
        let path = path_of(f).map_err(CliError::Input)?;
        if args.resume {
            crate::output::remove_stale_temporaries(&path);
            if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("gltf")) {
                crate::output::remove_stale_temporaries(&path.with_extension("bin"));
            }
            if crate::export::mesh_is_complete(&path) {
                resumed += 1;
                bar.set_length(bar.length().unwrap_or(0).saturating_sub(1));
                continue;
            }
        }
        let t = time_of(f);
        let own;
        let world = match &timeless {
            Some(timeless) => {
                let mut s = scene.clone();
                s.sea.time_s = t;
                own = World::at_instant(&s, timeless).map_err(|e| CliError::Input(e.to_string()))?;
                &own
            }
            None => &world,
        };
        let mesh = if args.camera {
            crate::export::camera_mesh(world, t, args.pixels, args.faded)
        } else if args.band_limit {
            let (mesh, l) = crate::export::grid_mesh_band_limited(world, t, &grid).map_err(CliError::Input)?;
            limit = Some(l);
            mesh
        } else {
            crate::export::grid_mesh(world, t, &grid)
        };
        crate::export::write_mesh(&path, &mesh).map_err(CliError::Failure)?;
        last_mesh = (mesh.positions.len(), mesh.indices.len() / 3);
        bar.inc(1);
    }
    bar.finish_and_clear();
    if !args.quiet {
        let (vertices, triangles) = last_mesh;
        let seconds = started.elapsed().as_secs_f64();
        match args.frames {
            None => {
                eprintln!("{}: {vertices} vertices, {triangles} triangles in {seconds:.2} s", args.output.display())
            }
            Some(_) if resumed == last - first => {
                eprintln!("{}: every frame ({resumed}) kept from an earlier run", args.output.display())
            }
            Some(_) => {
                let n = last - first - resumed;
                let kept =
                    if resumed > 0 { format!(" ({resumed} more kept from an earlier run)") } else { String::new() };
                eprintln!(
                    "{}: {n} frames of {vertices} vertices, {triangles} triangles{kept}, {:.2} s a frame",
                    args.output.display(),
                    seconds / f64::from(n.max(1))
                )
            }
        }
        // Of the meshes made here (none when every frame was kept).
        if resumed < last - first {
            for line in mesh_band_summary(&world, &grid, args.camera, limit.as_ref()) {
                eprintln!("{line}");
            }
        }
    }
    Ok(())
}

/// The least range (m) of a 16-bit displacement map of a sea whose heights lie in `[lo, hi]` (m):
/// half again the larger bound, at least a millimetre (the maps' own largest displacement widens
/// it where needed).
fn displacement_range(lo: f64, hi: f64) -> f64 {
    (lo.abs().max(hi.abs()) * 1.5).max(1e-3)
}

/// Refuses a run whose last (latest) frame, at `t` (s), is beyond the times the models hold, as
/// `brine render` does, before anything is written.
fn check_last_frame(frame: u32, t: f64) -> Result<(), CliError> {
    let limit = super::render::MAX_FRAME_TIME_S;
    if t.abs() <= limit {
        return Ok(());
    }
    Err(CliError::Input(format!(
        "frame {frame} would be at t = {} s, beyond the {} s the models are accurate to",
        super::num(t),
        super::num(limit)
    )))
}

/// What `brine mesh` says about the waves its regular grid cannot carry: with `--band-limit`,
/// what it left out; without, how many waves alias into the vertices (the trochoid and Gerstner
/// seas; nothing for a camera mesh, whose spacing follows the pixels).
fn mesh_band_summary(
    world: &World,
    grid: &MeshGrid,
    camera: bool,
    limit: Option<&crate::export::GridLimit>,
) -> Vec<String> {
    if let Some(l) = limit {
        let c = l.lost_slope_covariance;
        return match l.faded_waves {
            Some(0) | None => vec!["every wave is at least three spacings long: nothing left out".to_owned()],
            Some(n) => vec![format!(
                "{n} waves shorter than {:.3} m (three spacings) faded, those under {:.3} m left out; slope covariance left out (⟨ζx²⟩, ⟨ζxζz⟩, ⟨ζz²⟩) = ({:.5}, {:.5}, {:.5}), mean-square slope {:.5}",
                1.5 * l.shortest_wave_m,
                l.shortest_wave_m,
                c[0],
                c[1],
                c[2],
                c[0] + c[2]
            )],
        };
    }
    if camera {
        return Vec::new();
    }
    if let Some(ocean) = world.ocean().fft_ocean() {
        let short = ocean.modes_shorter_than(2.0 * grid.spacing_m);
        return if short == 0 {
            Vec::new()
        } else {
            vec![format!(
                "note: {short} of the FFT sea's {} modes are shorter than two spacings ({:.3} m): the grid aliases them (its vertices show them as longer waves in other directions); --band-limit leaves them out",
                ocean.mode_count(),
                2.0 * grid.spacing_m
            )]
        };
    }
    match world.ocean().grid_band(grid.spacing_m) {
        Ok(Some((_, band))) => {
            let all = world.ocean().waves().map_or(0, brine_waves::TrochoidSet::len);
            if band.waves.len() == all {
                return Vec::new();
            }
            vec![format!(
                "note: {} of the sea's {all} waves are shorter than two spacings ({:.3} m): the grid aliases them (its vertices show them as longer waves in other directions); --band-limit leaves them out",
                all - band.waves.len(),
                2.0 * grid.spacing_m
            )]
        }
        _ => Vec::new(),
    }
}

/// Arguments of `brine bake`.
#[derive(Debug, Clone, clap::Args)]
pub struct BakeArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Output folder (made if missing).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Texels per side.
    #[arg(long, default_value_t = 512)]
    pub size: usize,
    /// Side of the tile (m); by default the FFT sea's largest cascade, or the
    /// longest wave of a trochoid sea (about four peak wavelengths).
    #[arg(long, value_parser = super::finite)]
    pub tile_m: Option<f64>,
    /// Frames `A..B` (B excluded) or a count `N`; frame `f` at `sea.time_s + f/fps`.
    #[arg(long, value_parser = super::render::parse_frames)]
    pub frames: Option<(u32, u32)>,
    /// Loop period (s): the waves' frequencies are snapped so that the maps repeat exactly after it.
    #[arg(long, value_parser = super::finite)]
    pub loop_s: Option<f64>,
    /// Write 16-bit PNG maps instead of OpenEXR (the encodings are in `bake.json`).
    #[arg(long)]
    pub png16: bool,
    /// Up axis of the vector maps: `y` (Brine, glTF, Houdini, Unity) or `z` (Blender).
    #[arg(long, value_enum, default_value_t)]
    pub up: UpAxis,
    /// Keep the frames whose six maps are already in the folder in full, from an interrupted
    /// run of the same command (a map that does not decode completely makes its frame again;
    /// temporaries left by a killed run are removed). `--png16` still measures every frame for
    /// the maps' common range
    #[arg(long)]
    pub resume: bool,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

/// The tile of a bake when none is given (m): the FFT sea's largest cascade, else the longest
/// wave rounded up to a metre (at least 10 m).
///
/// # Errors
/// [`CliError::Input`] if the scene's world cannot be built.
pub fn default_tile_m(scene: &Scene) -> Result<f64, CliError> {
    let plain = world_of(scene, None)?;
    Ok(match &plain.ocean {
        brine_waves::Ocean::Fft { ocean } => ocean.options().tile_sizes[0],
        o => {
            let longest = o.waves().map_or(0.0, |s| s.waves().iter().map(|w| w.wavelength()).fold(0.0, f64::max));
            longest.max(10.0).ceil()
        }
    })
}

/// `bake.json`'s `grid_limit`: the waves the grid left out and their slope covariance in the
/// maps' horizontal axes (`x, z` for `--up y`; `X = x, Y = −z` for `--up z`).
pub fn grid_limit_json(l: &crate::export::GridLimit, up: UpAxis) -> serde_json::Value {
    let [xx, xz, zz] = l.lost_slope_covariance;
    let (axes, cross) = match up {
        UpAxis::Y => ("x z", xz),
        UpAxis::Z => ("X Y", -xz),
    };
    serde_json::json!({
        "shortest_wave_m": l.shortest_wave_m,
        "faded_waves": l.faded_waves,
        "lost_slope_covariance": { "axes": axes, "xx": xx, "xy": cross, "yy": zz },
        "lost_mean_square_slope": xx + zz,
    })
}

/// The keys in which two scene files differ, as `baked → now: key old → new` (the `[sea]` keys
/// first, then the others but the camera's and the output's, which do not enter the maps; at
/// most four, then how many more), or `None` if either is not TOML
/// (a scene recorded in its Rust form) or they hold the same keys and values. A table on one
/// side only is listed key by key.
fn scene_differences(before: &str, now: &str) -> Option<String> {
    fn walk(prefix: &str, a: Option<&toml::Value>, b: Option<&toml::Value>, out: &mut Vec<String>) {
        let empty = toml::Value::Table(toml::Table::new());
        match (a, b) {
            (Some(toml::Value::Table(_)), None) => walk(prefix, a, Some(&empty), out),
            (None, Some(toml::Value::Table(_))) => walk(prefix, Some(&empty), b, out),
            (Some(toml::Value::Table(x)), Some(toml::Value::Table(y))) => {
                let mut keys: Vec<&String> = x.keys().chain(y.keys()).collect();
                keys.sort();
                keys.dedup();
                for k in keys {
                    let path = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                    walk(&path, x.get(k), y.get(k), out);
                }
            }
            (a, b) if a != b => {
                let show = |v: Option<&toml::Value>| v.map_or_else(|| "absent".to_owned(), |v| v.to_string());
                out.push(format!("{prefix} {} → {}", show(a), show(b)));
            }
            _ => {}
        }
    }
    let a: toml::Value = toml::from_str(before).ok()?;
    let b: toml::Value = toml::from_str(now).ok()?;
    let mut out = Vec::new();
    walk("", Some(&a), Some(&b), &mut out);
    // The camera and the output do not enter the maps.
    out.retain(|line| !line.starts_with("camera.") && !line.starts_with("output."));
    if out.is_empty() {
        return None;
    }
    // The waves' keys first: the maps are made of them (stable: each group stays sorted).
    out.sort_by_key(|line| !line.starts_with("sea."));
    let more = out.len().saturating_sub(4);
    out.truncate(4);
    if more > 0 {
        out.push(format!("and {more} more"));
    }
    Some(format!("baked → now: {}", out.join("; ")))
}

/// The file beside a bake's maps that records what they were baked with (the scene, the
/// arguments, the 16-bit range), so that `--resume` keeps only maps of the same bake.
const BAKE_SETTINGS: &str = ".bake-settings.json";

/// Runs `brine bake`.
///
/// # Errors
/// [`CliError::Input`] for bad input (nothing is written), [`CliError::Failure`] for I/O.
pub fn run_bake(args: &BakeArgs) -> Result<(), CliError> {
    let scene = load(args.scene.as_ref(), None)?;
    // The tile: given, or from the sea itself.
    let tile_m = match args.tile_m {
        Some(t) => t,
        None => default_tile_m(&scene)?,
    };
    let options = BakeOptions { size: args.size, tile_m, up: args.up };
    options.check().map_err(CliError::Input)?;
    let lattice = brine_waves::TileLattice::new(tile_m, args.loop_s)
        .map_err(|e| CliError::Input(e.to_string().replace("tile_m", "--tile-m").replace("loop_s", "--loop-s")))?;
    if let Some((_, last)) = args.frames {
        check_last_frame(last - 1, scene.sea.time_s + f64::from(last - 1) / scene.animation.fps)?;
    }
    if args.output.exists() && !args.output.is_dir() {
        return Err(CliError::Input(format!("--output {}: not a folder", args.output.display())));
    }
    std::fs::create_dir_all(&args.output)
        .map_err(|e| CliError::Input(format!("cannot make the folder {}: {e}", args.output.display())))?;
    crate::output::check_writable(&args.output.join("bake.json")).map_err(CliError::Input)?;
    crate::output::remove_temporaries_on_signal().map_err(CliError::Failure)?;
    let (first, last) = args.frames.unwrap_or((0, 1));
    let fps = scene.animation.fps;
    let time_of = |f: u32| scene.sea.time_s + f64::from(f) / fps;
    let fft = scene.sea.surface == crate::scene::SurfaceKind::Fft;
    // Trochoid, Gerstner and sine seas answer at any time from one world; the FFT sea's white
    // water belongs to its frame.
    let shared = if fft { None } else { Some(world_of(&scene, Some(&lattice))?) };
    // How far the loop moves the waves: from the shared world, or from the FFT sea's first frame.
    let distortion = std::cell::OnceCell::new();
    if let Some(w) = &shared {
        let _ = distortion.set(w.loop_distortion().cloned());
    }
    let bar = |verb: &str| {
        if args.quiet || !std::io::stderr().is_terminal() {
            ProgressBar::hidden()
        } else {
            let b = ProgressBar::with_draw_target(Some(u64::from(last - first)), ProgressDrawTarget::stderr());
            b.set_style(
                ProgressStyle::with_template(&format!("{verb} {{bar:40}} {{pos}}/{{len}} frames, {{eta}} left"))
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            b
        }
    };
    // Frame `f`'s maps and the sea's height bounds then.
    let bake_at = |f: u32| -> Result<(crate::export::BakedFrame, (f64, f64)), CliError> {
        let t = time_of(f);
        let own;
        let world = match &shared {
            Some(w) => w,
            None => {
                let mut s = scene.clone();
                s.sea.time_s = t;
                own = world_of(&s, Some(&lattice))?;
                distortion.get_or_init(|| own.loop_distortion().cloned());
                &own
            }
        };
        Ok((crate::export::bake_frame(world, t, &options), world.sea.height_bounds()))
    };
    // The loop the maps repeat after: `--loop-s`, else the FFT sea's own `loop_period_s`.
    let (loop_period, loop_setting) = match (args.loop_s, fft.then_some(scene.sea.fft.loop_period_s).flatten()) {
        (Some(t), _) => (Some(t), "--loop-s"),
        (None, own) => (own, "sea.fft.loop_period_s"),
    };
    let warn_once = std::cell::Cell::new(false);
    let warn = || {
        if let (Some(Some(d)), Some(period), false) = (distortion.get(), loop_period, warn_once.get()) {
            if let Some(w) = super::loop_warning(d, period, loop_setting) {
                eprintln!("{w}");
            }
            warn_once.set(true);
        }
    };
    warn();
    let started = std::time::Instant::now();
    // A 16-bit PNG bake encodes every frame's displacement on one range, which must hold every
    // frame's largest displacement, horizontal included (a few trochoids move 2.5 times as far
    // sideways as up and down; the FFT sea's reach changes from frame to frame). A sequence is
    // therefore baked twice: once to find that range and to check that every other value fits
    // its fixed encoding, before any file is written; once to write (a single frame is kept).
    let mut range_m = 0.0f64;
    let mut kept = None;
    let mut first_limit = None;
    if args.png16 {
        let measuring = bar("measuring");
        for f in first..last {
            let (frame, (lo, hi)) = bake_at(f)?;
            measuring.suspend(warn);
            if f == first {
                first_limit = Some(frame.limit);
            }
            let largest = frame.maps.displacement.iter().flatten().fold(0.0f64, |m, v| m.max(f64::from(v.abs())));
            range_m = range_m.max(displacement_range(lo, hi)).max(largest);
            if let Some(e) = crate::export::bake::png_unencodable(&frame, None) {
                return Err(CliError::Input(format!("frame {f}: {e}; bake EXR maps (without --png16)")));
            }
            if last - first == 1 {
                kept = Some(frame);
            }
            measuring.inc(1);
        }
        measuring.finish_and_clear();
    }
    // What the maps are baked with, kept beside them so that `--resume` keeps only maps of the
    // same bake (a 16-bit PNG's encoding depends on the run's frames through `range_m`).
    let settings = serde_json::json!({
        // The scene as a scene file (its Rust form where TOML cannot hold it): only compared.
        "scene": scene.to_toml("scene").unwrap_or_else(|_| format!("{scene:?}")),
        "size": args.size,
        "tile_m": tile_m,
        "loop_s": args.loop_s,
        "up": format!("{:?}", args.up),
        "format": if args.png16 { "png16" } else { "exr" },
        "png16_range_m": args.png16.then_some(range_m),
    });
    let settings_path = args.output.join(BAKE_SETTINGS);
    if args.resume {
        crate::output::remove_stale_temporaries(&args.output.join("bake.json"));
        crate::output::remove_stale_temporaries(&settings_path);
        // The scenes are compared as TOML tables: the same keys written another way are the same.
        // The camera and the output do not enter the maps and are left out.
        let baked = |text: &str| {
            toml::from_str::<toml::Table>(text).map(|mut t| {
                t.remove("camera");
                t.remove("output");
                t
            })
        };
        let same = |before: &serde_json::Value, k: &str| match (before.get(k), settings.get(k)) {
            (Some(serde_json::Value::String(a)), Some(serde_json::Value::String(b))) if k == "scene" => {
                match (baked(a), baked(b)) {
                    (Ok(x), Ok(y)) => x == y,
                    _ => a == b,
                }
            }
            (a, b) => a == b,
        };
        const KEYS: [&str; 7] = ["scene", "size", "tile_m", "loop_s", "up", "format", "png16_range_m"];
        if let Some(before) =
            std::fs::read(&settings_path).ok().and_then(|b| serde_json::from_slice::<serde_json::Value>(&b).ok())
            && !KEYS.iter().all(|k| same(&before, k))
        {
            let differs: Vec<&str> = KEYS.into_iter().filter(|k| !same(&before, k)).collect();
            let mut named = differs.join(", ").replace("tile_m", "--tile-m").replace("loop_s", "--loop-s").replace(
                "png16_range_m",
                "16-bit displacement range (that of the frames asked for, which needs another)",
            );
            if let (Some(a), Some(b)) = (before.get("scene").and_then(|v| v.as_str()), settings["scene"].as_str())
                && let Some(keys) = scene_differences(a, b)
            {
                named = named.replacen("scene", &format!("scene ({keys})"), 1);
            }
            return Err(CliError::Input(format!(
                "--resume: the maps in {} were baked with another {named}; bake without --resume (every frame again), \
                 or into another folder",
                args.output.display(),
            )));
        }
    }
    let text = serde_json::to_string_pretty(&settings).map_err(|e| CliError::Failure(e.to_string()))?;
    crate::output::write_atomic(&settings_path, |w| w.write_all(text.as_bytes()))
        .map_err(|e| CliError::Failure(e.to_string()))?;
    let baking = bar("baking");
    let mut frames = Vec::new();
    // The grid's limit is frame `first`'s (the FFT sea's changes with time).
    let mut limit = None;
    let mut resumed = 0u32;
    for f in first..last {
        // `--resume` keeps a frame whose maps are all there in full at the bake's size (after
        // removing what a killed run left beside them).
        if args.resume {
            let paths = crate::export::bake_frame_paths(&args.output, f, args.png16);
            paths.iter().for_each(|p| {
                crate::output::remove_stale_temporaries(p);
            });
            if paths.iter().all(|p| crate::output::decoded_size(p) == Some((args.size, args.size))) {
                frames.push(serde_json::json!({ "index": f, "time_s": time_of(f) }));
                resumed += 1;
                baking.set_length(baking.length().unwrap_or(0).saturating_sub(1));
                continue;
            }
        }
        let frame = match kept.take() {
            Some(frame) => frame,
            None => bake_at(f)?.0,
        };
        baking.suspend(warn);
        if f == first {
            limit = Some(frame.limit);
        }
        let png = args.png16.then_some(range_m);
        crate::export::write_bake_frame(&args.output, f, &frame, png).map_err(CliError::Failure)?;
        frames.push(serde_json::json!({ "index": f, "time_s": time_of(f) }));
        baking.inc(1);
    }
    baking.finish_and_clear();
    // Frame `first` was kept: its grid limit from the measuring pass, or from the frame baked
    // again in memory.
    let limit = match limit.or(first_limit) {
        Some(l) => l,
        None => {
            let l = bake_at(first)?.0.limit;
            warn();
            l
        }
    };
    let meta = serde_json::json!({
        "generator": format!("brine {}", env!("CARGO_PKG_VERSION")),
        "surface": format!("{:?}", scene.sea.surface).to_lowercase(),
        "tile_m": tile_m,
        "size": args.size,
        "texel_m": tile_m / args.size as f64,
        "loop_period_s": loop_period,
        "loop_distortion": distortion.get().cloned().flatten().map(|d| serde_json::json!({
            "frequency_change_rms": d.rms(),
            "variance_share_moved_over_5_percent": d.share_moved(),
            "suggested_period_s": d.suggested_period_s(),
        })),
        "up": match args.up { UpAxis::Y => "y (x east, y up, z south)", UpAxis::Z => "z (X east, Y north, Z up)" },
        "maps": crate::export::MAP_NAMES,
        "format": if args.png16 { "png16" } else { "exr" },
        "png16_encodings": args.png16.then(|| {
            crate::export::bake::png_scales(range_m).iter().map(|(k, s)| (k.to_string(), serde_json::json!(s))).collect::<serde_json::Map<_, _>>()
        }),
        "frames": frames,
        "grid_limit": limit.map(|l| grid_limit_json(&l, args.up)),
    });
    let text = serde_json::to_string_pretty(&meta).map_err(|e| CliError::Failure(e.to_string()))?;
    crate::output::write_atomic(&args.output.join("bake.json"), |w| w.write_all(text.as_bytes()))
        .map_err(|e| CliError::Failure(e.to_string()))?;
    if !args.quiet && resumed == last - first {
        eprintln!("{}: every frame ({resumed}) kept from an earlier run", args.output.display());
    } else if !args.quiet {
        let n = last - first - resumed;
        let kept = if resumed > 0 { format!(" ({resumed} more kept from an earlier run)") } else { String::new() };
        eprintln!(
            "{}: {n} frame(s) of 6 maps{kept}, {}×{} texels over {tile_m} m, {:.2} s a frame",
            args.output.display(),
            args.size,
            args.size,
            started.elapsed().as_secs_f64() / f64::from(n.max(1))
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::scene_differences;

    /// The keys that differ are named with both values, the `[sea]` keys first and each group
    /// sorted, nested tables by their dotted path, a key set on one side only as absent on the
    /// other and a table on one side only key by key; the camera's and the output's keys are not
    /// named (the maps do not depend on them); the same scene, or one that is not TOML, names none.
    #[test]
    fn a_resumed_bake_names_the_scene_keys_that_changed() {
        let before = "[camera]\nwidth = 8\n[sea]\nwaves = 5\n[sea.fft]\nresolution = 64\n";
        let now = "[camera]\nwidth = 9\n[sea]\nwaves = 5\nseed = 2\n[sea.fft]\nresolution = 128\n[sea.swell]\nwaves = 3\n\
                   [water]\ntype = \"II\"\n[output]\npath = \"o.png\"\n";
        assert_eq!(
            scene_differences(before, now).as_deref(),
            Some(
                "baked → now: sea.fft.resolution 64 → 128; sea.seed absent → 2; sea.swell.waves absent → 3; \
                 water.type absent → \"II\""
            )
        );
        assert_eq!(scene_differences(before, before), None);
        assert_eq!(
            scene_differences(before, "[camera]\nwidth = 9\n[sea]\nwaves = 5\n[sea.fft]\nresolution = 64\n"),
            None
        );
        assert_eq!(
            scene_differences(before, "camera = { width = 8 }\nsea = { waves = 5, fft = { resolution = 64 } }"),
            None
        );
        assert_eq!(scene_differences("Scene { camera: .. }", now), None);
        let many: String = (0..6).map(|i| format!("k{i} = {i}\n")).collect();
        let listed = scene_differences("", &many).unwrap();
        assert!(listed.ends_with("; and 2 more") && listed.starts_with("baked → now: k0 absent → 0"), "{listed}");
    }
}
