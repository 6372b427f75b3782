//! `brine whitecap`: not implemented yet (issue #6).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine whitecap` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct WhitecapArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine whitecap`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #6 lands.
pub fn run_whitecap(_args: &WhitecapArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "whitecap", issue: 6 })
}
