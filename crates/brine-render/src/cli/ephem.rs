//! `brine sun | moon`: not implemented yet (issue #4).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine sun` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct SunArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine sun`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #4 lands.
pub fn run_sun(_args: &SunArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "sun", issue: 4 })
}

/// Arguments of `brine moon` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct MoonArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine moon`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #4 lands.
pub fn run_moon(_args: &MoonArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "moon", issue: 4 })
}
