//! `brine optics`: not implemented yet (issue #5).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine optics` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct OpticsArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine optics`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #5 lands.
pub fn run_optics(_args: &OpticsArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "optics", issue: 5 })
}
