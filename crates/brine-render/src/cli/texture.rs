//! `brine texture`: the photo-based ocean of Lai & Wu (brine-texture).
//!
//! `brine texture --small small.png --main main.png [--bed rock.png] -o out.png
//! [--frames 0..120 -o out/frame_####.png] [--seed S] [--mode project|trace] [--dump DIR]`
//! preprocesses the two photos (tileable and temporal synthesis, transitions, morph meshes,
//! heights; a progress bar on stderr), then renders each frame by the paper's perspective
//! projection (8-bit PNG) or by ray tracing the composed height field (PNG or EXR, linear
//! radiance exposed like `brine render`).

use std::io::{BufWriter, IsTerminal};
use std::path::{Path, PathBuf};
use std::time::Instant;

use brine_sky::{Sky, SkyParams};
use brine_texture::{
    OceanParams, PhotoOcean, Pinhole, ProjectionOptions, ProjectionView, RelightRule, SynthesisParams, Texture,
    TextureError, TracedParams, TracedScene, render_projection, render_traced,
};
use glam::DVec3;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::CliError;
use super::render::frame_path;
use crate::camera::direction_from_bearing;
use crate::output::OutputFormat;

/// How frames are rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum TextureMode {
    /// The paper's perspective projection of the plane y = 0 (Lai & Wu §III.C); 8-bit PNG.
    #[default]
    Project,
    /// Sphere tracing of the composed height field with sky, sun specular and refraction (brine-trace,
    /// brine-sky, brine-optics); PNG or EXR.
    Trace,
}

/// Form of the relighting factor of Eq. 9.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum RelightArg {
    /// Eq. 7–9 as printed, clamped to [0, 255].
    #[default]
    Paper,
    /// The docs/equations.md's bounded form, in range by construction.
    Bounded,
}

/// Arguments of `brine texture`.
#[derive(Debug, Clone, clap::Args)]
pub struct TextureArgs {
    /// Photo of the small waves (PNG or JPEG), e.g. crates/brine-texture/examples/small-waves.png.
    #[arg(long)]
    pub small: PathBuf,
    /// Photo of the main wave structure (PNG or JPEG), e.g. crates/brine-texture/examples/main-structure.png.
    #[arg(long)]
    pub main: PathBuf,
    /// Photo of a sea bed seen through the water by refraction (PNG or JPEG).
    #[arg(long)]
    pub bed: Option<PathBuf>,
    /// Output image; with --frames, a path with a run of # for the frame number.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Render an animation: frames A..B (B excluded) or a count N (= 0..N), frame f at time f/fps.
    #[arg(long, value_parser = super::render::parse_frames)]
    pub frames: Option<(u32, u32)>,
    /// Seed of every random choice (synthesis and the transition walk).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Renderer.
    #[arg(long, value_enum, default_value = "project")]
    pub mode: TextureMode,
    /// Write the synthesised textures, height fields (16-bit PNG) and transition links into DIR.
    #[arg(long)]
    pub dump: Option<PathBuf>,
    /// Camera position "x,y,z" (m), y up, above the sea.
    #[arg(long, value_parser = parse_vec3, default_value = "0,8,0", allow_hyphen_values = true)]
    pub position: DVec3,
    /// Compass bearing of the view (degrees, 0 north, 90 east).
    #[arg(long, default_value_t = 225.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub yaw_deg: f64,
    /// Elevation of the view (degrees, negative looks down), [-90, 90].
    #[arg(long, default_value_t = -20.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub pitch_deg: f64,
    /// Vertical field of view (degrees), (0, 180).
    #[arg(long, default_value_t = 60.0, value_parser = super::finite)]
    pub fov_deg: f64,
    /// Image width (pixels).
    #[arg(long, default_value_t = 384, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub width: u32,
    /// Image height (pixels).
    #[arg(long, default_value_t = 384, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub height: u32,
    /// Sun elevation (degrees), [-90, 90].
    #[arg(long, default_value_t = 35.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub sun_elevation_deg: f64,
    /// Sun azimuth, compass bearing (degrees).
    #[arg(long, default_value_t = 200.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub sun_azimuth_deg: f64,
    /// Atmospheric turbidity, [1.7, 10].
    #[arg(long, default_value_t = 3.0, value_parser = super::finite)]
    pub turbidity: f64,
    /// Synthesis, height and animation parameters.
    #[command(flatten)]
    pub tuning: Box<TextureTuning>,
    /// Depth of the bed below sea level (m).
    #[arg(long, default_value_t = 2.0, value_parser = super::finite)]
    pub bed_depth_m: f64,
    /// No mip-mapping in projection mode (the paper's plain bilinear lookup).
    #[arg(long)]
    pub no_mipmaps: bool,
    /// Wind speed for the sun's highlight in trace mode (m/s), [0, 60].
    #[arg(long, default_value_t = 6.0, value_parser = super::finite)]
    pub wind_m_s: f64,
    /// Exposure EV100 in trace mode, [-10, 30]; automatic (metered on the first frame) when absent.
    #[arg(long, allow_hyphen_values = true, value_parser = super::within(-10.0, 30.0))]
    pub exposure_ev: Option<f64>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Synthesis, height and animation parameters of `brine texture` (boxed in [`TextureArgs`] to keep
/// the command enum small).
#[derive(Debug, Clone, clap::Args)]
pub struct TextureTuning {
    /// Size of a small-wave texel on the sea (m).
    #[arg(long, default_value_t = OceanParams::default().texel_m, value_parser = super::finite)]
    pub texel_m: f64,
    /// Size of a bed texel (m).
    #[arg(long, default_value_t = OceanParams::default().bed_texel_m, value_parser = super::finite)]
    pub bed_texel_m: f64,
    /// Main-structure texels per small-wave texel (the `scale` of Eq. 3).
    #[arg(long, default_value_t = OceanParams::default().scale, value_parser = super::finite)]
    pub scale: f64,
    /// Height factor hf of the small waves (m), Eq. 1.
    #[arg(long, default_value_t = OceanParams::default().height_factor_small_m, value_parser = super::finite)]
    pub hf_small_m: f64,
    /// Height factor hf of the main structure (m), Eq. 1.
    #[arg(long, default_value_t = OceanParams::default().height_factor_main_m, value_parser = super::finite)]
    pub hf_main_m: f64,
    /// Velocity of the small-wave pattern "east,south" (m/s).
    #[arg(long, value_parser = parse_vec2, allow_hyphen_values = true)]
    pub small_velocity_m_s: Option<[f64; 2]>,
    /// Velocity of the main structure "east,south" (m/s).
    #[arg(long, value_parser = parse_vec2, allow_hyphen_values = true)]
    pub main_velocity_m_s: Option<[f64; 2]>,
    /// Side of the synthesised small-wave frames (texels).
    #[arg(long, default_value_t = OceanParams::default().small_size)]
    pub small_size: usize,
    /// Side of the synthesised main-structure texture (texels).
    #[arg(long, default_value_t = OceanParams::default().main_size)]
    pub main_size: usize,
    /// Patch side of the synthesis (texels).
    #[arg(long, default_value_t = SynthesisParams::default().patch_size)]
    pub patch: usize,
    /// Boundary-zone width of the synthesis (texels).
    #[arg(long, default_value_t = SynthesisParams::default().boundary_width)]
    pub boundary: usize,
    /// Frames of the basis sequence.
    #[arg(long, default_value_t = OceanParams::default().frames)]
    pub basis_frames: usize,
    /// Animation frames per transition link (morph in-betweens).
    #[arg(long, default_value_t = OceanParams::default().morph_steps)]
    pub morph_steps: usize,
    /// Nearest-frame transition links per basis frame.
    #[arg(long, default_value_t = OceanParams::default().links_per_frame)]
    pub links: usize,
    /// Animation frames per second.
    #[arg(long, default_value_t = OceanParams::default().fps, value_parser = super::finite)]
    pub fps: f64,
    /// Form of the relighting factor (Eq. 9).
    #[arg(long, value_enum, default_value = "paper")]
    pub relight: RelightArg,
}

/// Parses `n` comma-separated finite numbers.
fn parse_numbers(s: &str, n: usize) -> Result<Vec<f64>, String> {
    let v: Vec<f64> = s
        .split(',')
        .map(|t| t.trim().parse::<f64>().map_err(|_| format!("expected a number, got {t:?}")))
        .collect::<Result<_, _>>()?;
    if v.len() != n || v.iter().any(|x| !x.is_finite()) {
        return Err(format!("expected {n} finite comma-separated numbers, got {s:?}"));
    }
    Ok(v)
}

fn parse_vec3(s: &str) -> Result<DVec3, String> {
    parse_numbers(s, 3).map(|v| DVec3::new(v[0], v[1], v[2]))
}

fn parse_vec2(s: &str) -> Result<[f64; 2], String> {
    parse_numbers(s, 2).map(|v| [v[0], v[1]])
}

/// A bad input: the message of a brine-texture error, naming the flag of the parameter it names
/// (`links_per_frame = 9` is `--links = 9`).
fn input(e: TextureError) -> CliError {
    let m = e.to_string();
    for (param, flag) in PARAMETER_FLAGS {
        if let Some(rest) = m.strip_prefix(param).filter(|r| r.starts_with(" =")) {
            return CliError::Input(format!("{flag}{rest}"));
        }
    }
    CliError::Input(m)
}

/// brine-texture's parameter names and the flags that set them.
const PARAMETER_FLAGS: [(&str, &str); 17] = [
    ("links_per_frame", "--links"),
    ("boundary_width", "--boundary"),
    ("patch_size", "--patch"),
    ("height_factor_small_m", "--hf-small-m"),
    ("height_factor_main_m", "--hf-main-m"),
    ("small_velocity_m_s", "--small-velocity-m-s"),
    ("main_velocity_m_s", "--main-velocity-m-s"),
    ("velocity_m_s", "--small-velocity-m-s or --main-velocity-m-s"),
    ("wind_speed_m_s", "--wind-m-s"),
    ("frames", "--basis-frames"),
    ("morph_steps", "--morph-steps"),
    ("small_size", "--small-size"),
    ("main_size", "--main-size"),
    ("texel_m", "--texel-m"),
    ("bed_texel_m", "--bed-texel-m"),
    ("bed_depth_m", "--bed-depth-m"),
    ("fps", "--fps"),
];

/// Writes a file atomically ([`crate::output::write_atomic`]: a temporary file in the destination
/// folder, renamed over it once complete, removed on a signal).
fn write_atomic(
    path: &Path,
    encode: impl FnOnce(&mut BufWriter<&mut std::fs::File>) -> Result<(), String>,
) -> Result<(), CliError> {
    crate::output::write_atomic(path, |w| encode(w).map_err(std::io::Error::other))
        .map_err(|e| CliError::Failure(e.to_string()))
}

/// Writes an 8-bit sRGB colour image (a frame, a synthesised texture) as a PNG tagged sRGB, as the
/// renderer's images are ([`crate::output::encode_srgb_png`]), atomically.
fn write_colour_png(path: &Path, img: &image::RgbImage) -> Result<(), CliError> {
    write_atomic(path, |w| {
        crate::output::encode_srgb_png(w, img.width(), img.height(), img.as_raw()).map_err(|e| e.to_string())
    })
}

/// Writes a 16-bit grey height field as PNG, atomically: data, so untagged.
fn write_height_png(path: &Path, img: &image::ImageBuffer<image::Luma<u16>, Vec<u16>>) -> Result<(), CliError> {
    use image::{EncodableLayout, ImageEncoder};
    write_atomic(path, |w| {
        image::codecs::png::PngEncoder::new(w)
            .write_image(img.as_raw().as_bytes(), img.width(), img.height(), image::ExtendedColorType::L16)
            .map_err(|e| e.to_string())
    })
}

/// Loads a photo and checks it (`photo`: a small-wave or main-structure photo, at least one patch
/// in size and not uniform; otherwise a bed, at least one patch in size), naming its flag and
/// path in errors.
fn load(path: &Path, flag: &str, params: &OceanParams, photo: bool) -> Result<Texture, CliError> {
    let texture = Texture::load(path, flag).map_err(input)?;
    let what = format!("{flag} {}", path.display());
    if photo { params.check_photo(&what, &texture) } else { params.synthesis.check_exemplar(&what, &texture) }
        .map_err(input)?;
    Ok(texture)
}

/// The ocean parameters of the arguments.
fn params_of(a: &TextureArgs) -> OceanParams {
    let d = OceanParams::default();
    let t = &a.tuning;
    OceanParams {
        synthesis: SynthesisParams { patch_size: t.patch, boundary_width: t.boundary, ..SynthesisParams::default() },
        small_size: t.small_size,
        main_size: t.main_size,
        bed_size: t.small_size,
        frames: t.basis_frames,
        links_per_frame: t.links,
        morph_steps: t.morph_steps,
        height_factor_small_m: t.hf_small_m,
        height_factor_main_m: t.hf_main_m,
        scale: t.scale,
        texel_m: t.texel_m,
        bed_texel_m: t.bed_texel_m,
        small_velocity_m_s: t.small_velocity_m_s.unwrap_or(d.small_velocity_m_s),
        main_velocity_m_s: t.main_velocity_m_s.unwrap_or(d.main_velocity_m_s),
        fps: t.fps,
        relight: match t.relight {
            RelightArg::Paper => RelightRule::Paper,
            RelightArg::Bounded => RelightRule::Bounded,
        },
        ..d
    }
}

/// Writes the synthesised textures, height fields and transitions into `dir`.
fn dump(ocean: &PhotoOcean, dir: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir).map_err(|e| CliError::Failure(format!("cannot create {}: {e}", dir.display())))?;
    let p = ocean.params();
    write_colour_png(&dir.join("main-texture.png"), &ocean.main_texture().to_image())?;
    let m = ocean.main_height();
    write_height_png(&dir.join("main-height.png"), &m.grid().to_grey16(0.0, p.height_factor_main_m))?;
    for (k, f) in ocean.basis_frames().iter().enumerate() {
        write_colour_png(&dir.join(format!("small-frame-{k:02}.png")), &f.colour.to_image())?;
        write_height_png(
            &dir.join(format!("small-height-{k:02}.png")),
            &f.height().grid().to_grey16(0.0, p.height_factor_small_m),
        )?;
    }
    if let Some(b) = ocean.bed() {
        write_colour_png(&dir.join("bed-texture.png"), &b.to_image())?;
    }
    let links: Vec<_> = ocean
        .graph()
        .links()
        .iter()
        .map(|l| serde_json::json!({"from": l.from, "to": l.to, "distance": l.distance, "probability": l.probability}))
        .collect();
    let json = serde_json::json!({
        "seed": ocean.seed(),
        "basis_frames": ocean.graph().frames(),
        "morph_steps": p.morph_steps,
        "delta_height_max_m": ocean.relighting().delta_height_max,
        "links": links,
    });
    write_atomic(&dir.join("transitions.json"), |w| serde_json::to_writer_pretty(w, &json).map_err(|e| e.to_string()))
}

/// Runs `brine texture`.
///
/// # Errors
/// [`CliError::Input`] for a missing or unreadable photo, an unsupported format, an image smaller
/// than a patch, a uniform image, a parameter out of range or a bad output path (nothing is
/// written); [`CliError::Failure`] for I/O errors while writing.
pub fn run_texture(args: &TextureArgs) -> Result<(), CliError> {
    // Check everything cheap before the preprocessing.
    let pattern = &args.output;
    let format =
        OutputFormat::from_path(pattern).map_err(|m| CliError::Input(m.replacen("output.path", "--output", 1)))?;
    if args.mode == TextureMode::Project && format != OutputFormat::Png {
        return Err(CliError::Input(format!(
            "--output {}: projection mode writes 8-bit PNG (use --mode trace for EXR)",
            pattern.display()
        )));
    }
    // Frame paths are made one at a time (a run of 10⁸ frames holds no list of them); the
    // first is checked now: a `#` for the frame number, a folder where a file can be written.
    let (first, last) = args.frames.unwrap_or((0, 1));
    let count = last - first;
    let path_of = |f: u32| match args.frames {
        Some(_) => frame_path(pattern, f).map_err(CliError::Input),
        None => Ok(pattern.clone()),
    };
    crate::output::check_writable(&path_of(first)?).map_err(CliError::Input)?;
    // An interrupted run leaves no temporary file behind.
    crate::output::remove_temporaries_on_signal().map_err(CliError::Failure)?;
    let camera =
        Pinhole::from_angles(args.position, args.yaw_deg, args.pitch_deg, args.fov_deg, args.width, args.height)
            .map_err(input)?;
    if !(args.position.y > 0.0) {
        return Err(CliError::Input(format!(
            "--position: the camera must be above the sea (y > 0), got y = {}",
            args.position.y
        )));
    }
    if !(-90.0..=90.0).contains(&args.sun_elevation_deg) {
        return Err(CliError::Input(format!(
            "--sun-elevation-deg = {} is out of range: expected [-90, 90]°",
            args.sun_elevation_deg
        )));
    }
    let params = params_of(args);
    params.validate().map_err(input)?;
    let sun = direction_from_bearing(args.sun_azimuth_deg, args.sun_elevation_deg);
    let sky = Sky::new(&SkyParams::new(args.turbidity, sun)).map_err(|e| CliError::Input(e.to_string()))?;
    let projection =
        ProjectionOptions { mipmaps: !args.no_mipmaps, bed_depth_m: args.bed_depth_m, ..ProjectionOptions::default() };
    projection.validate().map_err(input)?;
    let small = load(&args.small, "--small", &params, true)?;
    let main = load(&args.main, "--main", &params, true)?;
    let bed = args.bed.as_deref().map(|b| load(b, "--bed", &params, false)).transpose()?;

    // Preprocessing, with a progress bar.
    let show = !args.quiet && std::io::stderr().is_terminal();
    let bar = ProgressBar::with_draw_target(
        None,
        if show { ProgressDrawTarget::stderr() } else { ProgressDrawTarget::hidden() },
    );
    bar.set_style(
        ProgressStyle::with_template("{spinner} preprocessing {bar:40.cyan/blue} {percent}%  ETA {eta}")
            .expect("valid template"),
    );
    let start = Instant::now();
    let ocean = PhotoOcean::new(&small, &main, bed.as_ref(), &params, args.seed, &|p| {
        bar.set_length(p.total);
        bar.set_position(p.done);
    })
    .map_err(input)?;
    bar.finish_and_clear();
    let preprocess_s = start.elapsed().as_secs_f64();
    if let Some(dir) = &args.dump {
        dump(&ocean, dir)?;
    }

    // Frames.
    let bar = ProgressBar::with_draw_target(
        Some(u64::from(count)),
        if show && count > 1 { ProgressDrawTarget::stderr() } else { ProgressDrawTarget::hidden() },
    );
    bar.set_style(
        ProgressStyle::with_template("{spinner} frames {bar:40.cyan/blue} {pos}/{len}  ETA {eta}")
            .expect("valid template"),
    );
    let render_start = Instant::now();
    match args.mode {
        TextureMode::Project => {
            let view = ProjectionView::new(&camera, &sky);
            for f in first..last {
                let img = render_projection(&ocean.frame(u64::from(f)), &view, &projection);
                write_colour_png(&path_of(f)?, &img)?;
                bar.inc(1);
            }
        }
        TextureMode::Trace => {
            let traced = TracedParams {
                turbidity: args.turbidity,
                sun_direction: sun,
                wind_speed_m_s: args.wind_m_s,
                bed_depth_m: args.bed_depth_m,
                ..TracedParams::default()
            };
            let scene = TracedScene::new(&traced, &ocean).map_err(input)?;
            let s = scene.sky.sun();
            let illuminance_lx =
                (scene.sky.horizontal_irradiance_rgb().y + s.irradiance_rgb.y * s.direction.y.max(0.0)) * 1000.0;
            let mut exposure = args.exposure_ev;
            for f in first..last {
                let path = path_of(f)?;
                let img = render_traced(&ocean.frame(u64::from(f)), &camera, &scene).map_err(input)?;
                let ev = *exposure.get_or_insert_with(|| {
                    crate::auto_exposure_ev(crate::world::log_average_luminance_cd_m2(&img.pixels), illuminance_lx)
                });
                crate::write_image(&path, img.width, img.height, &img.pixels, ev)
                    .map_err(|e| CliError::Failure(e.to_string()))?;
                bar.inc(1);
            }
        }
    }
    bar.finish_and_clear();
    if !args.quiet {
        let n = f64::from(count);
        let target = if args.frames.is_some() { format!("{count} frames") } else { pattern.display().to_string() };
        eprintln!(
            "wrote {target} ({}×{}, {:?} mode): preprocessing {preprocess_s:.2} s, {:.1} ms per frame",
            args.width,
            args.height,
            args.mode,
            render_start.elapsed().as_secs_f64() / n * 1e3
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    use super::*;
    use crate::cli::{Cli, Command};

    fn examples() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../brine-texture/examples")
    }

    fn args(extra: &[&str]) -> TextureArgs {
        let small = examples().join("small-waves.png");
        let main = examples().join("main-structure.png");
        let mut v = vec!["brine", "texture", "--small", small.to_str().unwrap(), "--main", main.to_str().unwrap()];
        // Small sizes keep the test quick in the dev profile.
        v.extend([
            "--small-size",
            "64",
            "--main-size",
            "64",
            "--patch",
            "24",
            "--boundary",
            "4",
            "--basis-frames",
            "3",
        ]);
        v.extend(["--links", "1", "--width", "40", "--height", "30", "-q"]);
        v.extend(extra);
        match Cli::try_parse_from(v).unwrap().command {
            Some(Command::Texture(a)) => a,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn renders_the_examples_in_both_modes_and_dumps() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("p.png");
        let dump_dir = dir.path().join("dump");
        let a = args(&["-o", out.to_str().unwrap(), "--dump", dump_dir.to_str().unwrap()]);
        run_texture(&TextureArgs { mode: TextureMode::Project, ..a.clone() }).unwrap();
        let img = image::open(&out).unwrap();
        assert_eq!((img.width(), img.height()), (40, 30));
        assert!(dump_dir.join("main-height.png").exists() && dump_dir.join("small-frame-02.png").exists());
        assert!(dump_dir.join("transitions.json").exists());
        let traced = dir.path().join("t.exr");
        run_texture(&TextureArgs { mode: TextureMode::Trace, output: traced.clone(), dump: None, ..a }).unwrap();
        assert!(traced.exists());
        let frames = dir.path().join("f_##.png");
        run_texture(&args(&["-o", frames.to_str().unwrap(), "--frames", "3..5"])).unwrap();
        assert!(dir.path().join("f_03.png").exists() && dir.path().join("f_04.png").exists());
        assert_eq!(
            std::fs::read_dir(dir.path())
                .unwrap()
                .filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().ends_with(".tmp"))
                .count(),
            0
        );
    }

    #[test]
    fn bad_inputs_are_input_errors_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("x.png");
        let missing = dir.path().join("missing.png");
        let a = args(&["-o", out.to_str().unwrap()]);
        let e = run_texture(&TextureArgs { small: missing.clone(), ..a.clone() }).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert!(e.to_string().contains("missing.png") && e.to_string().contains("--small"), "{e}");
        let grey = dir.path().join("grey.png");
        image::RgbImage::from_pixel(80, 80, image::Rgb([90, 90, 90])).save(&grey).unwrap();
        let e = run_texture(&TextureArgs { main: grey.clone(), ..a.clone() }).unwrap_err();
        assert!(e.to_string().contains("uniform"), "{e}");
        let tiny = dir.path().join("tiny.png");
        image::RgbImage::from_fn(10, 10, |i, j| image::Rgb([(i * 20) as u8, (j * 20) as u8, 9])).save(&tiny).unwrap();
        let e = run_texture(&TextureArgs { small: tiny, ..a.clone() }).unwrap_err();
        assert!(e.to_string().contains("smaller than the patch"), "{e}");
        let e = run_texture(&TextureArgs { output: dir.path().join("x.exr"), ..a.clone() }).unwrap_err();
        assert!(e.to_string().contains("PNG"), "{e}");
        let e = run_texture(&TextureArgs { position: DVec3::new(0.0, -1.0, 0.0), ..a }).unwrap_err();
        assert!(e.to_string().contains("above the sea"), "{e}");
        // The model's parameters are named by the flags that set them.
        let mut many_links = args(&["-o", out.to_str().unwrap()]);
        many_links.tuning.links = 99;
        let e = run_texture(&many_links).unwrap_err();
        assert!(e.to_string().starts_with("--links = 99 is out of range"), "{e}");
        // A folder given as the output is refused before the synthesis.
        let folder = dir.path().join("d.png");
        std::fs::create_dir(&folder).unwrap();
        let e = run_texture(&args(&["-o", folder.to_str().unwrap()])).unwrap_err();
        assert!(e.to_string().contains("it is a folder"), "{e}");
        assert!(!out.exists());
    }
}
