//! `cargo xtask bench`: the registry of benchmarks.
//!
//! Each entry names a benchmark and the cargo command that runs it. Criterion benches print their
//! medians; custom harnesses (`harness = false`) print their own side-by-side tables with ratios.
//! Add an entry here when a crate adds a benchmark.

/// `(name, what it measures, cargo arguments)`.
const BENCHES: &[(&str, &str, &[&str])] = &[(
    "trace",
    "brine-trace: every tracing method on identical 640×480 primary rays (tables of docs/benchmarks.md)",
    &["bench", "-p", "brine-trace", "--bench", "methods"],
)];

/// Runs the named benchmarks (all when `names` is empty) or lists them.
pub fn run(names: &[String], list: bool) -> Result<(), String> {
    if list || BENCHES.is_empty() {
        if BENCHES.is_empty() {
            eprintln!("no benchmark is registered yet");
        }
        for (name, what, _) in BENCHES {
            println!("{name:12} {what}");
        }
        return Ok(());
    }
    for n in names {
        if !BENCHES.iter().any(|(name, _, _)| name == n) {
            return Err(format!("unknown benchmark {n} (try --list)"));
        }
    }
    for (name, _, args) in BENCHES {
        if names.is_empty() || names.iter().any(|n| n == name) {
            super::cargo(args, &[])?;
        }
    }
    Ok(())
}
