//! `brine sky`: not implemented yet (issue #4).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine sky` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct SkyArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine sky`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #4 lands.
pub fn run_sky(_args: &SkyArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "sky", issue: 4 })
}
