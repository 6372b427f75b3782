//! `brine view`: the scene in a window, rendered progressively while it is edited.
//!
//! The window never waits for the renderer: a render thread ([`worker`]) renders the passes a
//! schedule ([`schedule`]) asks for — a coarse image at once, finer pixels and then more samples
//! while the view stays still — and the window shows the newest. A camera move swaps the
//! world's camera, a new hour builds the world at that instant on the parts that do not change
//! with time, and only a new sea builds those again.

pub mod app;
pub mod schedule;
pub mod script;
pub mod worker;

use std::path::PathBuf;
use std::time::Instant;

use crate::cli::CliError;

/// Arguments of `brine view`.
#[derive(Debug, Clone, clap::Args)]
pub struct ViewArgs {
    /// Scene file (TOML); the embedded default scene when omitted.
    pub scene: Option<PathBuf>,
    /// Width of the preview's box (pixels); the image keeps the output's aspect inside it.
    #[arg(long, default_value_t = 320, value_parser = clap::value_parser!(u32).range(16..=4096))]
    pub width: u32,
    /// Height of the preview's box (pixels).
    #[arg(long, default_value_t = 240, value_parser = clap::value_parser!(u32).range(16..=4096))]
    pub height: u32,
    /// Print the time to the first image and the frames shown per second (standard error).
    #[arg(long)]
    pub stats: bool,
    /// Play scripted input (wait, settle, drag, scroll, screenshot, save, quit; see the docs).
    #[arg(long)]
    pub script: Option<PathBuf>,
}

/// Whether a display is there to open a window on.
fn has_display() -> bool {
    ["DISPLAY", "WAYLAND_DISPLAY", "WAYLAND_SOCKET"].iter().any(|k| std::env::var_os(k).is_some_and(|v| !v.is_empty()))
}

/// Runs `brine view`.
///
/// # Errors
/// [`CliError::Input`] for a bad scene or script, or without a display; [`CliError::Failure`]
/// if the window cannot be opened or the script fails.
pub fn run(args: &ViewArgs) -> Result<(), CliError> {
    let opened = Instant::now();
    let scene = match &args.scene {
        Some(p) => crate::Scene::load(p).map_err(|e| CliError::Input(e.to_string()))?,
        None => crate::Scene::default_scene(),
    };
    let script = match &args.script {
        Some(p) => {
            let text = std::fs::read_to_string(p)
                .map_err(|e| CliError::Input(format!("{}: cannot read the script: {e}", p.display())))?;
            Some(script::parse(&text).map_err(|e| CliError::Input(format!("{}: {e}", p.display())))?)
        }
        None => None,
    };
    if !has_display() {
        return Err(CliError::Input(
            "brine view needs a display, and neither DISPLAY nor WAYLAND_DISPLAY is set: run it on a desktop, \
             or under a virtual display (xvfb-run brine view); `brine render` makes images without one"
                .into(),
        ));
    }
    // The render thread starts on the scene before the window is up: the first image is ready
    // sooner.
    let ctx_slot: std::sync::Arc<std::sync::OnceLock<eframe::egui::Context>> = Default::default();
    let slot = ctx_slot.clone();
    let (shared, handle) = worker::spawn(move || {
        if let Some(c) = slot.get() {
            c.request_repaint();
        }
    })
    .map_err(|e| CliError::Failure(format!("cannot start the render thread: {e}")))?;
    let app = app::ViewApp::new(scene, (args.width, args.height), shared.clone(), args.stats, script, opened);
    let script_error = app.script_error.clone();
    let render_thread = app.render_thread.clone();
    // Ctrl-C or SIGTERM removes the temporary of an image being written.
    let _ = crate::output::remove_temporaries_on_signal();
    let options = eframe::NativeOptions {
        viewport: eframe::egui::ViewportBuilder::default()
            .with_title("Brine")
            .with_inner_size([2.0 * args.width as f32 + 340.0, (2.0 * args.height as f32 + 40.0).max(620.0)]),
        ..Default::default()
    };
    let result = eframe::run_native(
        "brine view",
        options,
        Box::new(move |cc| {
            let _ = ctx_slot.set(cc.egui_ctx.clone());
            Ok(Box::new(app))
        }),
    );
    shared.stop();
    let _ = handle.join();
    // A render started with the button is finished, not lost, when the window closes.
    let running = render_thread.lock().unwrap_or_else(std::sync::PoisonError::into_inner).take();
    if let Some((path, thread)) = running {
        if !thread.is_finished() {
            eprintln!("brine view: finishing the render of {} (Ctrl-C stops it)", path.display());
        }
        let _ = thread.join();
    }
    result.map_err(|e| CliError::Failure(format!("cannot open the window: {e}")))?;
    match script_error.lock().unwrap_or_else(std::sync::PoisonError::into_inner).take() {
        Some(e) => Err(CliError::Failure(e)),
        None => Ok(()),
    }
}
