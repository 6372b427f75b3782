//! The `brine` command line: `brine [render] [SCENE.toml]` and the model queries.
//!
//! Each subcommand lives in its own module. Exit codes: 0 success, 2 bad input (usage, scene,
//! parameter out of range), 1 failure while working (I/O).

use std::io::Write;
use std::process::ExitCode;

/// Writes one line to standard output. A closed pipe (`brine fit … | head`) ends the program
/// quietly with success, as command-line tools do; another write error ends it with code 1.
pub(crate) fn write_stdout_line(args: std::fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args).and_then(|()| out.write_all(b"\n")) {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("error: cannot write to standard output: {e}");
        std::process::exit(1);
    }
}

/// `println!` that does not panic on a closed pipe (see [`write_stdout_line`]).
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cli::write_stdout_line(format_args!($($arg)*))
    };
}
pub(crate) use outln;

use clap::{CommandFactory, Parser, Subcommand};

/// Parses a flag's number, refusing NaN and infinities (clap names the flag in its message).
pub(crate) fn finite(s: &str) -> Result<f64, String> {
    let x: f64 = s.trim().parse().map_err(|_| format!("expected a number, got {s:?}"))?;
    if x.is_finite() { Ok(x) } else { Err(format!("expected a finite number, got {s}")) }
}

/// A parser of a flag's number in `[lo, hi]` (NaN and infinities refused).
pub(crate) fn within(lo: f64, hi: f64) -> impl Fn(&str) -> Result<f64, String> + Clone + Send + Sync + 'static {
    move |s: &str| {
        let x = finite(s)?;
        if (lo..=hi).contains(&x) {
            Ok(x)
        } else {
            Err(format!("{} is out of range: expected [{}, {}]", s.trim(), num(lo), num(hi)))
        }
    }
}

/// A number for a message: as Rust writes it, with an exponent from a million up and below a
/// thousandth (`1e9`, not `1000000000`; `1e-100`, not a hundred zeros).
pub(crate) fn num(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-3..1e6).contains(&x.abs()) { format!("{x:e}") } else { format!("{x}") }
}

/// The warning for a loop period that moves much of the sea off its dispersion relation: more
/// than 5 % of its height variance in waves whose frequency (and phase speed) the loop moved by
/// more than 5 % (brine-waves [`brine_waves::LoopDistortion`]); `None` below that. `setting` names
/// where the period came from (`--loop-s`, `sea.fft.loop_period_s`).
pub fn loop_warning(d: &brine_waves::LoopDistortion, period_s: f64, setting: &str) -> Option<String> {
    let tolerance = brine_waves::LOOP_TOLERANCE;
    (d.share_moved() > tolerance).then(|| {
        format!(
            "warning: {setting} = {} s moves {:.0} % of the sea's height variance by more than {:.0} % in \
             frequency and speed (RMS {:.0} %): the loop moves a wave of period P by up to P/(2T), and \
             turns one longer than 2T once per loop. A period of at least {:.0} s keeps 95 % of it within \
             {:.0} %.",
            num(period_s),
            100.0 * d.share_moved(),
            100.0 * tolerance,
            100.0 * d.rms(),
            d.suggested_period_s().ceil(),
            100.0 * tolerance,
        )
    })
}

/// Rewrites a model's message so that it names the flags the user typed: a parameter name that
/// is also an argument of `subcommand` (`t_water_c`) becomes its flag (`--t-water-c`).
fn name_flags(subcommand: &str, message: &str) -> String {
    let cli = Cli::command();
    let Some(sub) = cli.find_subcommand(subcommand) else { return message.to_owned() };
    let mut out = message.to_owned();
    // The subcommand's arguments and those of its own subcommands (`brine optics fresnel`).
    let mut args: Vec<(String, String)> = std::iter::once(sub)
        .chain(sub.get_subcommands())
        .flat_map(|c| c.get_arguments())
        .filter_map(|a| a.get_long().map(|l| (a.get_id().as_str().to_owned(), format!("--{l}"))))
        .collect();
    // The models' names of parameters whose flag is spelt otherwise (same unit).
    for (model, id) in [("u10_m_s", "u10"), ("latitude_deg", "lat"), ("longitude_deg", "lon"), ("n_waves", "waves")] {
        if let Some(flag) = args.iter().find(|(a, _)| a == id).map(|(_, f)| f.clone()) {
            args.push((model.to_owned(), flag));
        }
    }
    // Longer names first, so that `t_water_c` is not taken for a `t` inside it.
    args.sort_by_key(|(id, _)| std::cmp::Reverse(id.len()));
    for (id, flag) in args {
        out = replace_word(&out, &id, &flag);
    }
    out
}

/// Replaces the whole-word occurrences of `word` (not inside another identifier, not after a `.`
/// or a `-`) that name a parameter by `by`.
fn replace_word(text: &str, word: &str, by: &str) -> String {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(word) {
        let before = rest[..at].chars().next_back();
        let after = rest[at + word.len()..].chars().next();
        // Only a name, not an English word that happens to be a flag ("patch size"): a word
        // with an underscore, or one followed by ` = ` as the models write `name = value`.
        let named = word.contains('_') || rest[at + word.len()..].starts_with(" = ");
        let whole =
            named && before.is_none_or(|c| !ident(c) && c != '.' && c != '-') && after.is_none_or(|c| !ident(c));
        out += &rest[..at];
        out += if whole { by } else { word };
        rest = &rest[at + word.len()..];
    }
    out + rest
}

// The subcommands' arguments and builders are public: the Python bindings parse their keyword
// arguments with them, so that defaults, ranges and messages are the command line's.
pub mod ephem;
pub mod export;
pub mod foam;
pub mod optics;
pub mod render;
pub mod sky;
pub mod texture;
pub mod waves;
pub mod whitecap;

/// A command-line failure, with the exit code it maps to.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// Bad input: a scene or parameter error (exit code 2).
    #[error("{0}")]
    Input(String),
    /// A failure while working, such as I/O (exit code 1).
    #[error("{0}")]
    Failure(String),
}

impl CliError {
    /// The process exit code of this error.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Failure(_) => 1,
            CliError::Input(_) => 2,
        }
    }
}

/// Brine renders realistic ocean scenes and answers questions about the physical models behind
/// them. With no subcommand it renders (the embedded default scene if no file is given).
#[derive(Debug, Parser)]
#[command(name = "brine", version, about, args_conflicts_with_subcommands = true)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Arguments of `render` when no subcommand is given.
    #[command(flatten)]
    pub render: render::RenderArgs,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene file (or the embedded default scene) to PNG or EXR.
    Render(render::RenderArgs),
    /// Print an ocean spectrum S(ω) as JSON.
    Spectrum(waves::SpectrumArgs),
    /// Fit a trochoid wave set to a spectrum and print it as JSON.
    Fit(waves::FitArgs),
    /// Sun position for a place and a UTC time.
    Sun(ephem::SunArgs),
    /// Moon position and phase for a place and a UTC time.
    Moon(ephem::MoonArgs),
    /// Sky radiance for a view direction, or a fisheye sky dome image.
    Sky(sky::SkyArgs),
    /// Fresnel and water-optics queries.
    Optics(optics::OpticsArgs),
    /// Whitecap coverage of Monahan's laws.
    Foam(foam::FoamArgs),
    /// Sea-spray size distribution and extinction.
    Spray(foam::SprayArgs),
    /// Whitecap coverage from the displacement-Jacobian statistics.
    Whitecap(whitecap::WhitecapArgs),
    /// The photo-based ocean of Lai & Wu.
    Texture(texture::TextureArgs),
    /// Height, normal, motion and white water of the rendered sea at points and times.
    Query(export::QueryArgs),
    /// The rendered sea as a mesh (glTF 2.0, OBJ, PLY): a regular grid or camera-adaptive.
    Mesh(export::MeshArgs),
    /// Tileable maps of the rendered sea (displacement, normal, foam, whitecap, Jacobian, spray).
    Bake(export::BakeArgs),
    /// The scene in a window, rendered progressively while you set wind, hour and camera.
    #[cfg(feature = "view")]
    View(crate::view::ViewArgs),
}

/// Parses the process arguments and runs; prints `error: …` on failure.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let sub = cli.command.as_ref().map(subcommand_name);
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let message = match (&e, sub) {
                // Scene keys are named as in the scene file; model parameters as the flags.
                (CliError::Input(m), Some(s)) if s != "render" && s != "view" => name_flags(s, m),
                _ => e.to_string(),
            };
            eprintln!("error: {message}");
            ExitCode::from(e.exit_code())
        }
    }
}

/// The name of a subcommand as typed.
fn subcommand_name(c: &Command) -> &'static str {
    match c {
        Command::Render(_) => "render",
        Command::Spectrum(_) => "spectrum",
        Command::Fit(_) => "fit",
        Command::Sun(_) => "sun",
        Command::Moon(_) => "moon",
        Command::Sky(_) => "sky",
        Command::Optics(_) => "optics",
        Command::Foam(_) => "foam",
        Command::Spray(_) => "spray",
        Command::Whitecap(_) => "whitecap",
        Command::Texture(_) => "texture",
        Command::Query(_) => "query",
        Command::Mesh(_) => "mesh",
        Command::Bake(_) => "bake",
        #[cfg(feature = "view")]
        Command::View(_) => "view",
    }
}

/// Runs a parsed command line.
///
/// # Errors
/// [`CliError`] describing what went wrong.
pub fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        None => render::run(&cli.render),
        Some(Command::Render(args)) => render::run(&args),
        Some(Command::Spectrum(args)) => waves::run_spectrum(&args),
        Some(Command::Fit(args)) => waves::run_fit(&args),
        Some(Command::Sun(args)) => ephem::run_sun(&args),
        Some(Command::Moon(args)) => ephem::run_moon(&args),
        Some(Command::Sky(args)) => sky::run_sky(&args),
        Some(Command::Optics(args)) => optics::run_optics(&args),
        Some(Command::Foam(args)) => foam::run_foam(&args),
        Some(Command::Spray(args)) => foam::run_spray(&args),
        Some(Command::Whitecap(args)) => whitecap::run_whitecap(&args),
        Some(Command::Texture(args)) => texture::run_texture(&args),
        Some(Command::Query(args)) => export::run_query(&args),
        Some(Command::Mesh(args)) => export::run_mesh(&args),
        Some(Command::Bake(args)) => export::run_bake(&args),
        #[cfg(feature = "view")]
        Some(Command::View(args)) => crate::view::run(&args),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn model_parameters_are_named_as_the_flags_typed() {
        let m = name_flags("foam", "t_water_c = 50 is out of range: expected [-2, 40] °C (t_water_c − t_air_c)");
        assert_eq!(m, "--t-water-c = 50 is out of range: expected [-2, 40] °C (--t-water-c − --t-air-c)");
        // Not inside another name, not after a dot (scene keys), not in another subcommand.
        assert_eq!(replace_word("x_t_water_c sea.t_water_c", "t_water_c", "--t-water-c"), "x_t_water_c sea.t_water_c");
        assert_eq!(name_flags("nope", "t_water_c"), "t_water_c");
        // Words of the message that are also flags stay words.
        assert_eq!(name_flags("texture", "smaller than the patch size 24 px"), "smaller than the patch size 24 px");
        assert_eq!(name_flags("foam", "u10 = 70 is out of range"), "--u10 = 70 is out of range");
    }

    #[test]
    fn numbers_of_flags_are_finite_and_in_range() {
        assert_eq!(finite("1.5"), Ok(1.5));
        for bad in ["nan", "NaN", "inf", "-inf", "1e309", "x"] {
            assert!(finite(bad).is_err(), "{bad}");
        }
        let clouds = within(0.0, 1.0);
        assert_eq!(clouds("1"), Ok(1.0));
        assert!(clouds("-0.1").is_err() && clouds("1.0001").is_err() && clouds("nan").is_err());
    }
}
