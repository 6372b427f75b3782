//! `brine render [SCENE.toml]`.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::CliError;
use crate::output::OutputFormat;
use crate::{RenderError, RenderOptions, Scene, render, write_image};

/// Arguments of `brine render`.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct RenderArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Output image (.png or .exr); overrides `output.path`.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Image width in pixels; overrides `camera.width`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub width: Option<u32>,
    /// Image height in pixels; overrides `camera.height`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub height: Option<u32>,
    /// Samples per pixel; overrides `camera.spp`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub spp: Option<u32>,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

/// Loads the scene named by `args` (or the default) and applies the command-line overrides.
///
/// # Errors
/// [`CliError::Input`] for a bad scene or output path.
pub fn scene_of(args: &RenderArgs) -> Result<Scene, CliError> {
    let mut scene = match &args.scene {
        Some(path) => Scene::load(path).map_err(|e| CliError::Input(e.to_string()))?,
        None => Scene::default_scene(),
    };
    if let Some(o) = &args.output {
        OutputFormat::from_path(o).map_err(|m| CliError::Input(m.replacen("output.path", "--output", 1)))?;
        scene.output.path = o.clone();
    }
    if let Some(w) = args.width {
        scene.camera.width = w;
    }
    if let Some(h) = args.height {
        scene.camera.height = h;
    }
    if let Some(s) = args.spp {
        scene.camera.spp = s;
    }
    Ok(scene)
}

/// Runs `brine render`.
///
/// # Errors
/// [`CliError::Input`] for bad input (nothing is written), [`CliError::Failure`] for I/O errors.
pub fn run(args: &RenderArgs) -> Result<(), CliError> {
    let scene = scene_of(args)?;
    let out = scene.output.path.clone();
    // Fail before a long render if the destination folder is missing.
    if let Some(dir) = out.parent().filter(|p| !p.as_os_str().is_empty())
        && !dir.is_dir()
    {
        return Err(CliError::Input(format!(
            "cannot write {}: folder {} does not exist",
            out.display(),
            dir.display()
        )));
    }
    let (w, h, spp) = (scene.camera.width, scene.camera.height, scene.camera.spp);
    let show = !args.quiet && std::io::stderr().is_terminal();
    let bar = ProgressBar::with_draw_target(
        Some(u64::from(h)),
        if show { ProgressDrawTarget::stderr() } else { ProgressDrawTarget::hidden() },
    );
    bar.set_style(
        ProgressStyle::with_template("{spinner} rendering {bar:40.cyan/blue} {pos}/{len} rows  {msg}  ETA {eta}")
            .expect("valid template"),
    );
    let start = Instant::now();
    let rays_per_row = f64::from(w) * f64::from(spp);
    let on_row = || {
        bar.inc(1);
        let secs = start.elapsed().as_secs_f64();
        if secs > 0.0 {
            bar.set_message(format!("{:.2} Mrays/s", bar.position() as f64 * rays_per_row / secs / 1e6));
        }
    };
    let options = RenderOptions { threads: args.threads.map(usize::from) };
    let frame = render(&scene, &options, &on_row).map_err(|e| match e {
        RenderError::World(w) => CliError::Input(w.to_string()),
        other => CliError::Failure(other.to_string()),
    })?;
    bar.finish_and_clear();
    write_image(&out, frame.width, frame.height, &frame.pixels, scene.output.exposure_ev)
        .map_err(|e| CliError::Failure(e.to_string()))?;
    if !args.quiet {
        let secs = start.elapsed().as_secs_f64();
        eprintln!(
            "wrote {} ({w}×{h}, {spp} spp) in {secs:.2} s: {:.2} Mrays/s, {:.1} evaluations per ray",
            out.display(),
            rays_per_row * f64::from(h) / secs / 1e6,
            frame.stats.evaluations_per_ray()
        );
    }
    Ok(())
}
