//! Brine from Python: the native module `brine._brine` behind the `brine` package.
//!
//! Every model function takes its scalar parameters as keyword arguments named as the
//! command-line flags (`u10`, `fetch_m`, `sun_elevation_deg`, …) and parses them with the
//! command line's own parser, so that defaults, ranges and error messages are those of the
//! `brine` command; the arrays (frequencies, instants, directions, points) are evaluated in Rust
//! on the Rust threads with Python's lock released. The Python wrappers in `brine/__init__.py`
//! broadcast and reshape the arrays and turn instants into seconds.

use clap::Parser as _;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

mod models;
mod scene;

pyo3::create_exception!(
    _brine,
    BrineError,
    pyo3::exceptions::PyValueError,
    "Bad input to a Brine model or scene: the message names the parameter and its range, as the `brine` command does."
);

/// A command-line error as a Python exception: bad input is [`BrineError`] (a `ValueError`),
/// a failure while working a `RuntimeError`.
pub(crate) fn py_err(e: brine_render::cli::CliError) -> PyErr {
    match e {
        brine_render::cli::CliError::Input(m) => BrineError::new_err(m),
        other => pyo3::exceptions::PyRuntimeError::new_err(other.to_string()),
    }
}

/// A bad-input exception with `message`.
pub(crate) fn bad(message: impl Into<String>) -> PyErr {
    BrineError::new_err(message.into())
}

/// Parses `brine SUB… --key value …` built from the keyword arguments (`fixed` first: values the
/// binding sets itself), with the command line's parser.
///
/// A keyword `fetch_m=5e4` becomes `--fetch-m 50000.0` (Python's `str` of a float reads back as
/// the same float); `True` becomes the bare flag, `False` and `None` are left out.
///
/// # Errors
/// [`BrineError`] with the parser's message for an unknown keyword or a value out of range.
pub(crate) fn parse_cli(
    sub: &[&str],
    fixed: &[(&str, String)],
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<brine_render::cli::Command> {
    let mut argv: Vec<String> = std::iter::once("brine").chain(sub.iter().copied()).map(str::to_owned).collect();
    for (k, v) in fixed {
        argv.push(format!("--{}", k.replace('_', "-")));
        argv.push(v.clone());
    }
    if let Some(kw) = kwargs {
        for (key, value) in kw.iter() {
            let key: String = key.extract()?;
            if fixed.iter().any(|(k, _)| *k == key) {
                return Err(bad(format!("{key} is given by the array argument, not as a keyword")));
            }
            let flag = format!("--{}", key.replace('_', "-"));
            if value.is_none() {
                continue;
            }
            if value.is_instance_of::<PyBool>() {
                if value.extract::<bool>()? {
                    argv.push(flag);
                }
                continue;
            }
            argv.push(flag);
            argv.push(value.str()?.to_string());
        }
    }
    let cli = brine_render::cli::Cli::try_parse_from(&argv).map_err(|e| {
        // The parser's first paragraph, without the usage lines meant for a terminal.
        let text = e.render().to_string();
        let first = text.split("\n\n").next().unwrap_or(&text).trim();
        bad(as_keywords(first.strip_prefix("error: ").unwrap_or(first)))
    })?;
    cli.command.ok_or_else(|| bad("no model named"))
}

/// The parser's words for flags turned into Python's for keywords: `'--fetch-m <FETCH_M>'`
/// becomes `'fetch_m'`, "argument" becomes "keyword argument".
fn as_keywords(message: &str) -> String {
    let mut out = String::new();
    let mut rest = message;
    while let Some(at) = rest.find("'--") {
        out.push_str(&rest[..at + 1]);
        let tail = &rest[at + 3..];
        let end = tail.find(['\'', ' ']).unwrap_or(tail.len());
        out.push_str(&tail[..end].replace('-', "_"));
        rest = &tail[end..];
        if let Some(close) = rest.find('\'') {
            // Drop the value placeholder (` <FETCH_M>`) between the name and the quote.
            if rest[..close].trim_start().starts_with('<') {
                rest = &rest[close..];
            }
        }
    }
    out.push_str(rest);
    out.replace("unexpected argument", "unexpected keyword argument")
}

/// The native module.
#[pymodule]
fn _brine(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("BrineError", m.py().get_type::<BrineError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    models::register(m)?;
    m.add_class::<scene::Scene>()?;
    Ok(())
}
