//! Placeholder arguments of subcommands whose models have not landed: they accept anything and
//! report which issue brings them.

/// Any arguments.
#[derive(Debug, clap::Args)]
pub struct Rest {
    /// Ignored until the subcommand is implemented.
    #[arg(trailing_var_arg = true, allow_hyphen_values = true, hide = true)]
    pub rest: Vec<String>,
}
