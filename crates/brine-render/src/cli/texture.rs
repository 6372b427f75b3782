//! `brine texture`: not implemented yet (issue #8).
//!
//! Replace the placeholder argument types and `run_*` functions with the real command.

use super::CliError;

/// Arguments of `brine texture` (placeholder: accepts anything).
#[derive(Debug, clap::Args)]
pub struct TextureArgs {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}

/// Runs `brine texture`.
///
/// # Errors
/// [`CliError::NotYet`] until issue #8 lands.
pub fn run_texture(_args: &TextureArgs) -> Result<(), CliError> {
    Err(CliError::NotYet { command: "texture", issue: 8 })
}
