//! `brine render [SCENE.toml]`.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::CliError;
use crate::output::OutputFormat;
use crate::world::{Timeless, World, WorldError};
use crate::{RenderError, RenderOptions, Scene, render_world, write_frame};

/// Arguments of `brine render`.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct RenderArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Output image (.png or .exr); overrides `output.path`.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Image width in pixels; overrides `camera.width`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub width: Option<u32>,
    /// Image height in pixels; overrides `camera.height`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub height: Option<u32>,
    /// Samples per pixel; overrides `camera.spp`.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub spp: Option<u32>,
    /// Worker threads (default: all cores). The image does not depend on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
    /// Render an animation: frames `A..B` (B excluded) or a count `N` (= `0..N`), frame `f` at
    /// `sea.time_s + f/fps`; the output path must hold a run of `#` replaced by the zero-padded
    /// frame number.
    #[arg(long, value_parser = parse_frames)]
    pub frames: Option<(u32, u32)>,
    /// A time-lapse `START..END` (UTC, e.g. `2024-06-21T04:00Z..2024-06-21T23:00Z`): the scene's
    /// `[place]` time runs from START (frame 0) to END (last frame) while the waves move at the
    /// normal rate; needs `--frames` and a `[place]`.
    #[arg(long, value_parser = parse_time_lapse, requires = "frames")]
    pub time_lapse: Option<(brine_ephem::Timestamp, brine_ephem::Timestamp)>,
    /// With `--frames`: skip the frames already written in full (a frame that does not decode
    /// completely is made again; temporaries left by a killed run are removed).
    #[arg(long, requires = "frames")]
    pub resume: bool,
    /// The reference rendering: no wave faded and no normal filtered with the pixel footprint,
    /// with 64 samples per pixel unless `--spp` says otherwise; what the filtering of
    /// the normal rendering is meant to preserve.
    #[arg(long)]
    pub reference: bool,
}

/// Samples per pixel of `brine render --reference` when `--spp` is not given.
pub const REFERENCE_SPP: u32 = 64;

/// Parses `A..B` with `A < B`, or a count `N ≥ 1` as `0..N`.
pub(crate) fn parse_frames(s: &str) -> Result<(u32, u32), String> {
    let Some((a, b)) = s.split_once("..") else {
        let n: u32 =
            s.trim().parse().map_err(|_| format!("expected A..B (e.g. 0..240) or a frame count, got {s:?}"))?;
        return if n == 0 { Err("the frame count must be at least 1".into()) } else { Ok((0, n)) };
    };
    let a: u32 = a.trim().parse().map_err(|_| format!("expected a frame number before .., got {a:?}"))?;
    let b: u32 = b.trim().parse().map_err(|_| format!("expected a frame number after .., got {b:?}"))?;
    if a >= b {
        return Err(format!("the range {a}..{b} is empty (the end is excluded)"));
    }
    Ok((a, b))
}

/// Parses `START..END`, two UTC instants (RFC 3339; `2024-06-21T04:00Z` is accepted too), with
/// `START < END`.
fn parse_time_lapse(s: &str) -> Result<(brine_ephem::Timestamp, brine_ephem::Timestamp), String> {
    let (a, b) = s.split_once("..").ok_or_else(|| format!("expected START..END (UTC instants), got {s:?}"))?;
    let parse = |t: &str| {
        let t = t.trim();
        // Accept minutes without seconds (`04:00Z`), which RFC 3339 requires.
        let full = if t.len() == 17 && t.ends_with('Z') { format!("{}:00Z", &t[..16]) } else { t.to_owned() };
        brine_ephem::parse_utc(&full).and_then(brine_ephem::check_range).map_err(|e| e.to_string())
    };
    let (a, b) = (parse(a)?, parse(b)?);
    if a >= b {
        return Err(format!("the time-lapse {a}..{b} is empty: START must be before END"));
    }
    Ok((a, b))
}

/// The output path of frame `f`: the last run of `#` in the file name replaced by `f`, padded with
/// zeros to the run's length.
///
/// # Errors
/// A message if the file name has no `#`.
pub fn frame_path(pattern: &std::path::Path, frame: u32) -> Result<PathBuf, String> {
    let name = pattern.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let end = name.rfind('#').ok_or_else(|| {
        format!(
            "{}: an animation needs a run of # in the file name for the frame number (e.g. frame_####.png)",
            pattern.display()
        )
    })?;
    let start = name[..=end].trim_end_matches('#').len();
    let width = end + 1 - start;
    let file = format!("{}{:0width$}{}", &name[..start], frame, &name[end + 1..]);
    Ok(pattern.with_file_name(file))
}

/// The scene's name in messages: its path, or the default scene's name.
fn scene_name(args: &RenderArgs) -> String {
    args.scene.as_ref().map_or_else(|| crate::scene::DEFAULT_SCENE_NAME.to_owned(), |p| p.display().to_string())
}

/// Loads the scene named by `args` (or the default) and applies the command-line overrides.
///
/// # Errors
/// [`CliError::Input`] for a bad scene or output path.
pub fn scene_of(args: &RenderArgs) -> Result<Scene, CliError> {
    let mut scene = match &args.scene {
        Some(path) => Scene::load(path).map_err(|e| CliError::Input(e.to_string()))?,
        None => Scene::default_scene(),
    };
    if let Some(o) = &args.output {
        OutputFormat::from_path(o).map_err(|m| CliError::Input(m.replacen("output.path", "--output", 1)))?;
        scene.output.path = o.clone();
    }
    // The output's constraints are checked once `-o` has set the path (a scene asking for AOVs
    // with the default `ocean.png` is fine with `-o x.exr`).
    scene.check_output().map_err(|m| {
        let file = scene_name(args);
        let line = match &args.scene {
            Some(p) => std::fs::read_to_string(p).ok().and_then(|t| Scene::line_of_key(&t, "output.aovs")),
            None => Scene::line_of_key(crate::scene::DEFAULT_SCENE_TOML, "output.aovs"),
        };
        let at = line.map(|l| format!(" line {l}")).unwrap_or_default();
        let how = if args.output.is_some() { " (given by --output)" } else { "" };
        CliError::Input(format!("{file}{at}: {m}{how}"))
    })?;
    if let Some(w) = args.width {
        scene.camera.width = w;
    }
    if let Some(h) = args.height {
        scene.camera.height = h;
    }
    if args.reference && args.spp.is_none() {
        scene.camera.spp = REFERENCE_SPP;
    }
    if let Some(s) = args.spp {
        scene.camera.spp = s;
    }
    Ok(scene)
}

/// Largest time of an animation frame, after `sea.time_s` or the sky's clock (s): the models'
/// phases hold their precision to about here.
pub const MAX_FRAME_TIME_S: f64 = 1e9;

/// The scene of animation frame `frame` of the run `first..last`: the waves at
/// `sea.time_s + frame/fps`; the sun and moon at `place.time_utc + frame/fps`, or, in a time-lapse
/// `START..END`, at START for frame 0 and END for frame `last − 1`, linearly between (whatever
/// `first` is).
///
/// # Errors
/// [`CliError::Input`] if the frame's time passes [`MAX_FRAME_TIME_S`] or the time-lapse
/// instant cannot be represented.
pub fn scene_at_frame(
    scene: &Scene,
    frame: u32,
    (_first, last): (u32, u32),
    time_lapse: Option<(brine_ephem::Timestamp, brine_ephem::Timestamp)>,
) -> Result<Scene, CliError> {
    let mut s = scene.clone();
    let elapsed = f64::from(frame) / scene.animation.fps;
    s.sea.time_s += elapsed;
    // The models hold their precision for times within 10⁹ s (32 years); a frame beyond (a
    // huge frame number at a tiny `fps`) would render NaN.
    if !(s.sea.time_s.abs() <= MAX_FRAME_TIME_S && (scene.elapsed_s + elapsed).abs() <= MAX_FRAME_TIME_S) {
        return Err(CliError::Input(format!(
            "frame {frame} is {} s after frame 0 (animation.fps = {}): the waves' time would be {} s, beyond the {} s the models are accurate to",
            super::num(elapsed),
            super::num(scene.animation.fps),
            super::num(s.sea.time_s),
            super::num(MAX_FRAME_TIME_S)
        )));
    }
    match (time_lapse, s.place.as_mut()) {
        (Some((start, end)), Some(place)) => {
            let span = (end.as_nanosecond() - start.as_nanosecond()) as f64 * 1e-9;
            // Frame 0 at START and the run's last frame at END, whatever frame the run starts
            // at: the tail of a run (`--frames 100..240` after a crash) is the same frames.
            let share = if last > 1 { f64::from(frame) / f64::from(last - 1) } else { 0.0 };
            let at = start
                .checked_add(jiff::SignedDuration::from_secs_f64(span * share))
                .map_err(|e| CliError::Input(format!("--time-lapse: {e}")))?;
            place.time_utc = at.to_string();
        }
        _ => s.elapsed_s = scene.elapsed_s + elapsed,
    }
    Ok(s)
}

/// Runs `brine render`.
///
/// # Errors
/// [`CliError::Input`] for bad input (nothing is written), [`CliError::Failure`] for I/O errors.
pub fn run(args: &RenderArgs) -> Result<(), CliError> {
    let scene = scene_of(args)?;
    let pattern = scene.output.path.clone();
    // An interrupted render leaves no temporary file behind.
    let _ = crate::output::remove_temporaries_on_signal();
    // Frame paths are made one at a time (a run of 10⁸ frames holds no list of them); the first
    // is checked now.
    let (first, last) = args.frames.unwrap_or((0, 1));
    let path_of = |f: u32| match args.frames {
        Some(_) => frame_path(&pattern, f).map_err(CliError::Input),
        None => Ok(pattern.clone()),
    };
    // Fail before a long render if the destination cannot be written (a missing folder, a folder
    // given as the file, a read-only place such as /proc).
    crate::output::check_writable(&path_of(first)?).map_err(CliError::Input)?;
    let count = u64::from(last - first);
    let (w, h, spp) = (scene.camera.width, scene.camera.height, scene.camera.spp);
    let show = !args.quiet && std::io::stderr().is_terminal();
    let bar = ProgressBar::with_draw_target(
        Some(u64::from(h) * count),
        if show { ProgressDrawTarget::stderr() } else { ProgressDrawTarget::hidden() },
    );
    let what = if args.frames.is_some() { format!("{count} frames") } else { "rendering".to_owned() };
    bar.set_style(
        ProgressStyle::with_template(&format!(
            "{{spinner}} {what} {{bar:40.cyan/blue}} {{percent}}%  {{msg}}  ETA {{eta}}"
        ))
        .expect("valid template"),
    );
    let start = Instant::now();
    let rays_per_row = f64::from(w) * f64::from(spp);
    let on_row = || {
        bar.inc(1);
        let secs = start.elapsed().as_secs_f64();
        if secs > 0.0 {
            bar.set_message(format!("{:.2} Mrays/s", bar.position() as f64 * rays_per_row / secs / 1e6));
        }
    };
    let options = RenderOptions { threads: args.threads.map(usize::from), profile: false, reference: args.reference };
    if args.time_lapse.is_some() && scene.place.is_none() {
        return Err(CliError::Input(
            "--time-lapse needs a [place] in the scene (the sun and moon follow its time)".into(),
        ));
    }
    let (first, last) = args.frames.unwrap_or((0, 1));
    // The last frame is the latest: if its time is within the models', every frame's is, and a
    // run that cannot end is refused before it writes anything.
    scene_at_frame(&scene, last - 1, (first, last), args.time_lapse)?;
    let mut evaluations = 0.0;
    let input = |w: WorldError| CliError::Input(format!("{}: {w}", scene_name(args)));
    // What does not change between frames (the fit, the ocean's amplitudes, the detail band,
    // the white water's calibration) is built once for the run.
    let mut timeless: Option<Timeless> = None;
    let (mut done, mut skipped) = (0u64, 0u64);
    // A loop period far from the waves' own periods is told once.
    let mut warned = false;
    for frame in first..last {
        let path = &path_of(frame)?;
        // `--resume` skips the frames already written in full (after removing what a killed
        // run left); a truncated or empty frame is made again.
        if args.resume {
            crate::output::remove_stale_temporaries(path);
            if crate::output::decodes_completely(path) {
                // Out of the bar's length, not counted as progress: the rate and the time left
                // are those of the frames rendered.
                skipped += 1;
                bar.set_length(bar.length().unwrap_or(0).saturating_sub(u64::from(h)));
                continue;
            }
        }
        let s = scene_at_frame(&scene, frame, (first, last), args.time_lapse)?;
        let parts = match timeless.take() {
            Some(t) if t.fits(&s) => t,
            _ => Timeless::new(&s, None).map_err(input)?,
        };
        let mut world = World::at_instant(&s, &parts).map_err(input)?;
        timeless = Some(parts);
        if let (Some(d), Some(period), false) = (world.loop_distortion(), s.sea.fft.loop_period_s, warned) {
            if let Some(w) = super::loop_warning(d, period, "sea.fft.loop_period_s") {
                bar.suspend(|| eprintln!("{w}"));
            }
            warned = true;
        }
        world.set_reference(options.reference);
        let frame = render_world(&s, &world, &options, &on_row).map_err(|e| match e {
            RenderError::World(w) => input(w),
            other => CliError::Failure(other.to_string()),
        })?;
        write_frame(path, &frame, frame.exposure_ev, scene.output.aovs)
            .map_err(|e| CliError::Failure(e.to_string()))?;
        evaluations += frame.stats.evaluations_per_ray();
        done += 1;
        if !show && !args.quiet && args.frames.is_some() {
            eprintln!("wrote {}", path.display());
        }
    }
    bar.finish_and_clear();
    if !args.quiet {
        let secs = start.elapsed().as_secs_f64();
        let n = done.max(1) as f64;
        let target = if args.frames.is_some() {
            format!("{done} frames ({skipped} skipped)")
        } else {
            pattern.display().to_string()
        };
        eprintln!(
            "wrote {target} ({w}×{h}, {spp} spp) in {secs:.2} s: {:.2} Mrays/s, {:.1} evaluations per ray",
            rays_per_row * f64::from(h) * done as f64 / secs / 1e6,
            evaluations / n
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_numbers_replace_the_last_run_of_hashes() {
        let p = frame_path(std::path::Path::new("out/f_####.png"), 42).unwrap();
        assert_eq!(p, PathBuf::from("out/f_0042.png"));
        let p = frame_path(std::path::Path::new("a#b_##.exr"), 7).unwrap();
        assert_eq!(p, PathBuf::from("a#b_07.exr"));
        assert!(frame_path(std::path::Path::new("x.png"), 1).is_err());
    }

    #[test]
    fn each_frame_moves_the_waves_and_the_sun_by_frame_over_fps() {
        let mut scene = Scene::default_scene();
        scene.animation.fps = 25.0;
        scene.sea.time_s = 2.0;
        let s = scene_at_frame(&scene, 50, (0, 100), None).unwrap();
        // 50 frames at 25 fps: 2 s later for the waves and for the sky's clock.
        assert_eq!((s.sea.time_s, s.elapsed_s), (4.0, 2.0));
        assert_eq!(s.place, scene.place);
        let lapse = parse_time_lapse("2024-06-21T04:00Z..2024-06-21T22:00Z").unwrap();
        let s = scene_at_frame(&scene, 0, (0, 19), Some(lapse)).unwrap();
        assert_eq!((s.place.as_ref().unwrap().time_utc.as_str(), s.elapsed_s), ("2024-06-21T04:00:00Z", 0.0));
        let s = scene_at_frame(&scene, 18, (10, 19), Some(lapse)).unwrap();
        assert_eq!(s.place.unwrap().time_utc, "2024-06-21T22:00:00Z");
        // Frame 9 of 18 intervals is half-way, 13:00, in the whole run and in its tail alike.
        for range in [(0, 19), (9, 19)] {
            let s = scene_at_frame(&scene, 9, range, Some(lapse)).unwrap();
            assert_eq!(s.place.unwrap().time_utc, "2024-06-21T13:00:00Z", "{range:?}");
        }
    }

    #[test]
    fn frames_are_a_range_or_a_count_and_time_lapses_are_ordered() {
        assert_eq!(parse_frames("3..7"), Ok((3, 7)));
        assert_eq!(parse_frames("240"), Ok((0, 240)));
        assert!(parse_frames("0").is_err() && parse_frames("5..5").is_err() && parse_frames("x").is_err());
        let (a, b) = parse_time_lapse("2024-06-21T04:00Z..2024-06-21T23:00:00Z").unwrap();
        assert_eq!(b.as_second() - a.as_second(), 19 * 3600);
        assert!(parse_time_lapse("2024-06-21T23:00Z..2024-06-21T04:00Z").is_err());
        assert!(parse_time_lapse("yesterday..today").is_err());
    }
}
