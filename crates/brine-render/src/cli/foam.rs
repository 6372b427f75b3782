//! `brine foam | spray`: not implemented yet (issue #6).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine foam` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct FoamArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine foam`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #6 lands.
pub fn run_foam(_args: &FoamArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "foam", issue: 6 })
}

/// Arguments of `brine spray` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct SprayArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine spray`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #6 lands.
pub fn run_spray(_args: &SprayArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "spray", issue: 6 })
}
