//! The `brine` command line: `brine [render] [SCENE.toml]` and the model queries.
//!
//! Each subcommand lives in its own module. Exit codes: 0 success, 2 bad input (usage, scene,
//! parameter out of range), 1 failure while working (I/O).

use std::io::Write;
use std::process::ExitCode;

/// Writes one line to standard output. A closed pipe (`brine fit … | head`) ends the program
/// quietly with success, as command-line tools do; another write error ends it with code 1.
pub(crate) fn write_stdout_line(args: std::fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args).and_then(|()| out.write_all(b"\n")) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: cannot write to standard output: {e}");
        std::process::exit(1);
    }
}

/// `println!` that does not panic on a closed pipe (see [`write_stdout_line`]).
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cli::write_stdout_line(format_args!($($arg)*))
    };
}
pub(crate) use outln;

use clap::{Parser, Subcommand};

mod ephem;
mod foam;
mod optics;
mod render;
mod sky;
mod texture;
mod waves;
mod whitecap;

/// A command-line failure, with the exit code it maps to.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input: a scene or parameter error (exit code 2).
    #[error("{0}")]
    Input(String),
    /// A failure while working, such as I/O (exit code 1).
    #[error("{0}")]
    Failure(String),
    /// A subcommand whose model has not landed yet (exit code 2).
    #[error("`brine {command}` is not implemented yet (issue #{issue})")]
    NotYet {
        /// The subcommand.
        command: &'static str,
        /// The issue that brings it.
        issue: u32,
    },
}

impl CliError {
    /// The process exit code of this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Failure(_) => 1,
            CliError::Input(_) | CliError::NotYet { .. } => 2,
        }
    }
}

/// Brine renders realistic ocean scenes and answers questions about the physical models behind
/// them. With no subcommand it renders (the embedded default scene if no file is given).
#[derive(Debug, Parser)]
#[command(name = "brine", version, about, args_conflicts_with_subcommands = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Arguments of `render` when no subcommand is given.
    #[command(flatten)]
    pub render: render::RenderArgs,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene file (or the embedded default scene) to PNG or EXR.
    Render(render::RenderArgs),
    /// Print an ocean spectrum S(ω) as JSON.
    Spectrum(waves::SpectrumArgs),
    /// Fit a trochoid wave set to a spectrum and print it as JSON.
    Fit(waves::FitArgs),
    /// Sun position for a place and a UTC time.
    Sun(ephem::SunArgs),
    /// Moon position and phase for a place and a UTC time.
    Moon(ephem::MoonArgs),
    /// Sky radiance for a view direction, or a fisheye sky dome image.
    Sky(sky::SkyArgs),
    /// Fresnel and water-optics queries.
    Optics(optics::OpticsArgs),
    /// Whitecap coverage of Monahan's laws.
    Foam(foam::FoamArgs),
    /// Sea-spray size distribution and extinction.
    Spray(foam::SprayArgs),
    /// Whitecap coverage from the displacement-Jacobian statistics.
    Whitecap(whitecap::WhitecapArgs),
    /// The photo-based ocean of Lai & Wu.
    Texture(texture::TextureArgs),
}

/// Parses the process arguments and runs; prints `error: …` on failure.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}

/// Runs a parsed command line.
///
/// # Errors
/// [`CliError`] describing what went wrong.
pub fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        None => render::run(&cli.render),
        Some(Command::Render(args)) => render::run(&args),
        Some(Command::Spectrum(args)) => waves::run_spectrum(&args),
        Some(Command::Fit(args)) => waves::run_fit(&args),
        Some(Command::Sun(args)) => ephem::run_sun(&args),
        Some(Command::Moon(args)) => ephem::run_moon(&args),
        Some(Command::Sky(args)) => sky::run_sky(&args),
        Some(Command::Optics(args)) => optics::run_optics(&args),
        Some(Command::Foam(args)) => foam::run_foam(&args),
        Some(Command::Spray(args)) => foam::run_spray(&args),
        Some(Command::Whitecap(args)) => whitecap::run_whitecap(&args),
        Some(Command::Texture(args)) => texture::run_texture(&args),
    }
}
