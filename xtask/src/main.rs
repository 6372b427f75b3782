//! Project automation for Brine: `cargo xtask ci | bench | plots | gallery | golden | beaufort`.
//!
//! Everything here shells out to `cargo` (so the usual profiles apply) except `plots`, which calls
//! the model crates directly and writes SVG files under `docs/models/plots/`.

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use clap::{Parser, Subcommand};

mod beaufort;
mod bench;
mod plots;
mod whitewater;

/// Brine's project automation.
#[derive(Debug, Parser)]
#[command(name = "cargo xtask")]
struct Cli {
    #[command(subcommand)]
    command: Task,
}

#[derive(Debug, Subcommand)]
enum Task {
    /// fmt --check, clippy -D warnings, and the test suite: what CI runs.
    Ci,
    /// Run benchmarks side by side and print ratios (`cargo xtask bench --list` for names).
    Bench {
        /// Benchmarks to run (all when empty).
        names: Vec<String>,
        /// List the benchmarks.
        #[arg(long)]
        list: bool,
    },
    /// Regenerate the plots of docs/models/ (all crates when none is named).
    Plots {
        /// Crates to plot, e.g. `brine-waves`.
        crates: Vec<String>,
    },
    /// Render the scenes of docs/gallery/*.toml to docs/gallery/*.png with the release build, then
    /// the Beaufort sheet (docs/beaufort.md) when no scene is named.
    Gallery {
        /// Scene names (file stems) to render; all when empty.
        names: Vec<String>,
    },
    /// Run the golden-image tests; with --bless, rewrite the golden images from this build.
    Golden {
        /// Replace the stored golden images.
        #[arg(long)]
        bless: bool,
    },
    /// Render and measure the Beaufort sheet only (docs/beaufort.md, docs/beaufort/*.png).
    Beaufort {
        /// Only measure the far-field sparkle (2 and 5 m/s, both surfaces) and print it; write
        /// nothing in docs/.
        #[arg(long)]
        sparkle: bool,
        /// Only measure the energy bands (filtered frame against the reference) and print them;
        /// write nothing in docs/.
        #[arg(long)]
        energy: bool,
        /// Only measure the near-field detail for 8 seeds (each and pooled) and print it; write
        /// nothing in docs/.
        #[arg(long)]
        detail: bool,
    },
    /// Measure white water from above (docs/whitewater.md, docs/whitewater/*.png).
    Whitewater {
        /// Only measure the streaks (correlation lengths at 18 m/s) and print them; write nothing.
        #[arg(long)]
        streaks: bool,
    },
}

/// The workspace root (the parent of this crate's folder).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask lives in the workspace").to_path_buf()
}

/// Runs `cargo` with `args` in the workspace root; `Err` with a message if it fails.
fn cargo(args: &[&str], envs: &[(&str, &str)]) -> Result<(), String> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    eprintln!("$ cargo {}", args.join(" "));
    let status = Command::new(cargo)
        .args(args)
        .envs(envs.iter().copied())
        .current_dir(root())
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if status.success() { Ok(()) } else { Err(format!("`cargo {}` failed ({status})", args.join(" "))) }
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Task::Ci => {
            cargo(&["fmt", "--all", "--", "--check"], &[])?;
            cargo(&["clippy", "--workspace", "--all-targets", "--locked", "--", "-D", "warnings"], &[])?;
            // brine-waves as brine-whitecap takes it: without the tracer adapters.
            cargo(&["clippy", "-p", "brine-waves", "--no-default-features", "--locked", "--", "-D", "warnings"], &[])?;
            cargo(&["test", "--workspace"], &[])
        }
        Task::Bench { names, list } => bench::run(&names, list),
        Task::Plots { crates } => plots::run(&root(), &crates),
        Task::Gallery { names } => {
            gallery(&names)?;
            if names.is_empty() { beaufort::run(&root()) } else { Ok(()) }
        }
        Task::Beaufort { sparkle, energy, detail } => {
            if detail {
                beaufort::detail()
            } else if sparkle {
                beaufort::sparkle(&root())
            } else if energy {
                beaufort::energy()
            } else {
                beaufort::run(&root())
            }
        }
        Task::Whitewater { streaks } => {
            if streaks {
                whitewater::streaks().map(|_| ())
            } else {
                whitewater::run(&root())
            }
        }
        Task::Golden { bless } => {
            let envs: &[(&str, &str)] = if bless { &[("BRINE_BLESS", "1")] } else { &[] };
            cargo(&["test", "-p", "brine-tests", "--test", "golden"], envs)
        }
    }
}

/// Renders every `docs/gallery/*.toml` (or the named ones) next to itself as PNG.
fn gallery(names: &[String]) -> Result<(), String> {
    let dir = root().join("docs/gallery");
    let mut scenes: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map_err(|e| format!("cannot list {}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .filter(|p| names.is_empty() || names.iter().any(|n| p.file_stem().is_some_and(|s| s == n.as_str())))
        .collect();
    scenes.sort();
    if scenes.is_empty() {
        return Err(format!("no gallery scene found in {}", dir.display()));
    }
    cargo(&["build", "--release", "-p", "brine-render"], &[])?;
    let brine = root().join("target/release/brine");
    for scene in scenes {
        let out = scene.with_extension("png");
        eprintln!("rendering {} -> {}", scene.display(), out.display());
        let status = Command::new(&brine)
            .arg("render")
            .arg(&scene)
            .arg("-o")
            .arg(&out)
            .status()
            .map_err(|e| format!("cannot run {}: {e}", brine.display()))?;
        if !status.success() {
            return Err(format!("rendering {} failed ({status})", scene.display()));
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    match run(Cli::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
