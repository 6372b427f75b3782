//! `brine spectrum | fit`: not implemented yet (issue #3).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine spectrum` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct SpectrumArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine spectrum`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #3 lands.
pub fn run_spectrum(_args: &SpectrumArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "spectrum", issue: 3 })
}

/// Arguments of `brine fit` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct FitArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine fit`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #3 lands.
pub fn run_fit(_args: &FitArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "fit", issue: 3 })
}
