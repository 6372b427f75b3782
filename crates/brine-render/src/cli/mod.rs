//! The `brine` command line: `brine [render] [SCENE.toml]` and the model queries.
//!
//! Each subcommand lives in its own module. Exit codes: 0 success, 2 bad input (usage, scene,
//! parameter out of range), 1 failure while working (I/O).

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod render;
mod stubs;

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
    /// Print an ocean spectrum S(ω) as JSON (issue #3).
    Spectrum(stubs::Rest),
    /// Fit a trochoid wave set to a spectrum and print it as JSON (issue #3).
    Fit(stubs::Rest),
    /// Sun position for a place and a UTC time (issue #4).
    Sun(stubs::Rest),
    /// Moon position and phase for a place and a UTC time (issue #4).
    Moon(stubs::Rest),
    /// Sky radiance or a fisheye sky dome (issue #4).
    Sky(stubs::Rest),
    /// Fresnel and water optics queries (issue #5).
    Optics(stubs::Rest),
    /// Whitecap coverage of Monahan's laws (issue #6).
    Foam(stubs::Rest),
    /// Sea-spray size distribution and extinction (issue #6).
    Spray(stubs::Rest),
    /// Whitecap coverage from the Jacobian statistics (issue #6).
    Whitecap(stubs::Rest),
    /// The photo-based ocean of Lai & Wu (issue #8).
    Texture(stubs::Rest),
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
        Some(Command::Spectrum(_)) => Err(CliError::NotYet { command: "spectrum", issue: 3 }),
        Some(Command::Fit(_)) => Err(CliError::NotYet { command: "fit", issue: 3 }),
        Some(Command::Sun(_)) => Err(CliError::NotYet { command: "sun", issue: 4 }),
        Some(Command::Moon(_)) => Err(CliError::NotYet { command: "moon", issue: 4 }),
        Some(Command::Sky(_)) => Err(CliError::NotYet { command: "sky", issue: 4 }),
        Some(Command::Optics(_)) => Err(CliError::NotYet { command: "optics", issue: 5 }),
        Some(Command::Foam(_)) => Err(CliError::NotYet { command: "foam", issue: 6 }),
        Some(Command::Spray(_)) => Err(CliError::NotYet { command: "spray", issue: 6 }),
        Some(Command::Whitecap(_)) => Err(CliError::NotYet { command: "whitecap", issue: 6 }),
        Some(Command::Texture(_)) => Err(CliError::NotYet { command: "texture", issue: 8 }),
    }
}
