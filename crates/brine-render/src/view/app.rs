//! The preview window: the controls on the left, the progressive image on the right, the mouse
//! on the image for the camera.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Instant;

use eframe::egui;
use glam::DVec3;

use crate::scene::{CloudConfig, PlaceConfig, Scene, SpectrumKind, SurfaceKind};

use super::script::Step;
use super::worker::{Request, Shared, Shown};

/// Degrees of yaw or pitch per point of drag, at a 50° field of view (scaled with it).
const ORBIT_DEG_PER_POINT: f64 = 0.25;
/// Metres of pan per point of drag, per metre of camera height.
const PAN_PER_POINT_PER_M: f64 = 0.01;
/// The field of view's factor per point of scroll: `exp(−k Δ)`.
const ZOOM_PER_POINT: f64 = 0.002;
/// How long `settle` waits before the script fails (s).
const SETTLE_TIMEOUT_S: f64 = 300.0;

/// A full render started with the "render" button.
#[derive(Default)]
struct Job {
    rows: AtomicU32,
    total_rows: u32,
    done: Mutex<Option<Result<PathBuf, String>>>,
}

/// The state of a scripted run.
struct Playback {
    steps: Vec<Step>,
    /// The step in progress and when it started.
    at: usize,
    started: Instant,
    /// Events of the step in progress already sent (a drag: pressed).
    pressed: bool,
    /// A screenshot asked and not yet written.
    shooting: Arc<AtomicBool>,
    /// Why the script failed, if it did.
    failed: Arc<Mutex<Option<String>>>,
}

/// The window's state.
pub struct ViewApp {
    scene: Scene,
    /// The preview's box (pixels): the image has the output's aspect inside it.
    preview_box: (u32, u32),
    shared: Arc<Shared>,
    generation: u64,
    /// The scene of the last request.
    sent: Option<Scene>,
    texture: Option<egui::TextureHandle>,
    last: Option<(u64, super::schedule::Pass, f64)>,
    /// Where the image was drawn last frame (for the script's pointer).
    image_rect: Option<egui::Rect>,
    /// Date (`YYYY-MM-DD`) and hour (UTC) being edited.
    date: String,
    message: Option<String>,
    save_path: String,
    job: Option<Arc<Job>>,
    /// Frames per second while the image changes.
    stats: bool,
    opened: Instant,
    /// When the window drew its first frame (s after the command started).
    first_frame: Option<f64>,
    first_image: Option<f64>,
    shown_since: (Instant, u32),
    fps: f64,
    script: Option<Playback>,
    /// Set when the script failed; read by [`super::run`] after the window closes.
    pub script_error: Arc<Mutex<Option<String>>>,
    /// The full render in progress; read by [`super::run`] after the window closes.
    pub render_thread: RenderThread,
}

/// The view direction of a camera as yaw and pitch (°), `look_at` turned into angles.
fn yaw_pitch(scene: &Scene) -> (f64, f64) {
    let c = &scene.camera;
    match c.look_at {
        Some(t) => {
            let f = (DVec3::from_array(t) - DVec3::from_array(c.position)).normalize_or(DVec3::NEG_Z);
            (f.x.atan2(-f.z).to_degrees().rem_euclid(360.0), f.y.clamp(-1.0, 1.0).asin().to_degrees())
        }
        None => (c.yaw_deg.unwrap_or(Scene::DEFAULT_YAW_DEG), c.pitch_deg.unwrap_or(Scene::DEFAULT_PITCH_DEG)),
    }
}

/// The date (`YYYY-MM-DD`) and hour (UTC, fractional) of an RFC 3339 instant.
fn date_and_hour(time_utc: &str) -> Option<(String, f64)> {
    let t: jiff::Timestamp = time_utc.parse().ok()?;
    let z = t.to_zoned(jiff::tz::TimeZone::UTC);
    let hour = f64::from(z.hour()) + f64::from(z.minute()) / 60.0 + f64::from(z.second()) / 3600.0;
    Some((z.date().to_string(), hour))
}

/// The RFC 3339 instant of a date and an hour (UTC).
fn instant_of(date: &str, hour: f64) -> Option<String> {
    let d: jiff::civil::Date = date.trim().parse().ok()?;
    let seconds = (hour.clamp(0.0, 24.0) * 3600.0).round().min(86_399.0) as i64;
    let t = d.at((seconds / 3600) as i8, ((seconds / 60) % 60) as i8, (seconds % 60) as i8, 0);
    Some(t.to_zoned(jiff::tz::TimeZone::UTC).ok()?.timestamp().to_string())
}

impl ViewApp {
    /// A window on `scene` with a preview inside `preview_box` pixels.
    pub fn new(
        scene: Scene,
        preview_box: (u32, u32),
        shared: Arc<Shared>,
        stats: bool,
        script: Option<Vec<Step>>,
        opened: Instant,
    ) -> Self {
        let mut scene = scene;
        // The mouse turns the camera by its angles.
        let (yaw, pitch) = yaw_pitch(&scene);
        scene.camera.look_at = None;
        scene.camera.yaw_deg = Some(yaw);
        scene.camera.pitch_deg = Some(pitch);
        let date = scene.place.as_ref().and_then(|p| date_and_hour(&p.time_utc)).map_or_else(String::new, |(d, _)| d);
        let failed = Arc::new(Mutex::new(None));
        let mut app = Self {
            scene,
            preview_box,
            shared,
            generation: 0,
            sent: None,
            texture: None,
            last: None,
            image_rect: None,
            date,
            message: None,
            save_path: "view.toml".into(),
            job: None,
            stats,
            opened,
            first_frame: None,
            first_image: None,
            shown_since: (Instant::now(), 0),
            fps: 0.0,
            script: script.map(|steps| Playback {
                steps,
                at: 0,
                started: Instant::now(),
                pressed: false,
                shooting: Arc::new(AtomicBool::new(false)),
                failed: failed.clone(),
            }),
            script_error: failed,
            render_thread: RenderThread::default(),
        };
        // The first view is asked at once: its world is built while the window opens.
        app.send();
        app
    }

    /// The preview's size: the output's aspect inside the box.
    fn preview_size(&self) -> (u32, u32) {
        let (bw, bh) = (f64::from(self.preview_box.0), f64::from(self.preview_box.1));
        let aspect = f64::from(self.scene.camera.width) / f64::from(self.scene.camera.height);
        let (w, h) = if bw / bh > aspect { (bh * aspect, bh) } else { (bw, bw / aspect) };
        ((w.round() as u32).max(1), (h.round() as u32).max(1))
    }

    /// Sends the scene to the render thread if it changed and is valid.
    fn send(&mut self) {
        if self.sent.as_ref() == Some(&self.scene) {
            return;
        }
        match self.scene.to_toml("the edited scene") {
            Ok(_) => {
                self.generation += 1;
                self.sent = Some(self.scene.clone());
                self.shared.ask(Request {
                    scene: self.scene.clone(),
                    preview: self.preview_size(),
                    generation: self.generation,
                });
                if self.message.as_deref().is_some_and(|m| m.starts_with("scene: ")) {
                    self.message = None;
                }
            }
            Err(e) => self.message = Some(format!("scene: {e}")),
        }
    }

    /// Takes a finished pass into the texture.
    fn receive(&mut self, ctx: &egui::Context) {
        let Some(Shown { generation, pass, size, rgba, render_s, build_s }) = self.shared.take_shown() else { return };
        let image = egui::ColorImage::from_rgba_unmultiplied([size.0 as usize, size.1 as usize], &rgba);
        match &mut self.texture {
            Some(t) => t.set(image, egui::TextureOptions::LINEAR),
            None => self.texture = Some(ctx.load_texture("preview", image, egui::TextureOptions::LINEAR)),
        }
        self.last = Some((generation, pass, render_s));
        if self.first_image.is_none() {
            let t = self.opened.elapsed().as_secs_f64();
            self.first_image = Some(t);
            if self.stats {
                let window = self.first_frame.unwrap_or(t);
                eprintln!(
                    "brine view: first image {}×{} after {t:.3} s, {:.3} s after the window's first frame (the world built in {build_s:.3} s, the pass rendered in {render_s:.3} s)",
                    size.0,
                    size.1,
                    t - window
                );
            }
        }
        self.shown_since.1 += 1;
    }

    /// Frames per second over the last second, printed with `--stats`.
    fn count(&mut self) {
        let elapsed = self.shown_since.0.elapsed().as_secs_f64();
        if elapsed >= 1.0 {
            self.fps = f64::from(self.shown_since.1) / elapsed;
            if self.stats && self.shown_since.1 > 0 {
                let pass = self.last.map_or(String::new(), |(_, p, s)| {
                    let (w, h) = p.size(self.preview_size().0, self.preview_size().1);
                    format!("; last pass {w}×{h}, {} spp, rendered in {s:.3} s", p.spp)
                });
                eprintln!("brine view: {:.1} frames/s{pass}", self.fps);
            }
            self.shown_since = (Instant::now(), 0);
        }
    }

    /// The controls.
    fn controls(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.scene;
        ui.heading("Sea");
        ui.add(egui::Slider::new(&mut s.sea.wind_speed_m_s, 0.0..=40.0).text("wind (m/s)"));
        ui.add(egui::Slider::new(&mut s.sea.wind_direction_deg, 0.0..=360.0).text("wind toward (°)"));
        egui::ComboBox::from_label("surface").selected_text(format!("{:?}", s.sea.surface)).show_ui(ui, |ui| {
            for k in [SurfaceKind::Trochoids, SurfaceKind::Gerstner, SurfaceKind::Sine, SurfaceKind::Fft] {
                ui.selectable_value(&mut s.sea.surface, k, format!("{k:?}"));
            }
        });
        egui::ComboBox::from_label("spectrum").selected_text(format!("{:?}", s.sea.spectrum)).show_ui(ui, |ui| {
            for k in [
                SpectrumKind::PiersonMoskowitz,
                SpectrumKind::Jonswap,
                SpectrumKind::Phillips,
                SpectrumKind::Tma,
                SpectrumKind::Elfouhaily,
            ] {
                ui.selectable_value(&mut s.sea.spectrum, k, format!("{k:?}"));
            }
        });
        if s.sea.surface != SurfaceKind::Fft {
            let mut waves = s.sea.wave_count();
            if ui.add(egui::Slider::new(&mut waves, 1..=400).text("waves")).changed() {
                s.sea.waves = Some(waves);
            }
        }

        ui.separator();
        ui.heading("Sun and moon");
        match s.place.as_mut() {
            Some(place) => {
                let (_, mut hour) = date_and_hour(&place.time_utc).unwrap_or((String::new(), 12.0));
                ui.horizontal(|ui| {
                    ui.label("date");
                    ui.text_edit_singleline(&mut self.date);
                });
                ui.add(egui::Slider::new(&mut hour, 0.0..=23.99).text("hour (UTC)"));
                match instant_of(&self.date, hour) {
                    Some(t) => place.time_utc = t,
                    None => {
                        ui.colored_label(egui::Color32::LIGHT_RED, "date: expected YYYY-MM-DD");
                    }
                }
                ui.add(egui::Slider::new(&mut place.latitude_deg, -90.0..=90.0).text("latitude (°)"));
                ui.add(egui::Slider::new(&mut place.longitude_deg, -180.0..=180.0).text("longitude (°)"));
            }
            None => {
                ui.label("The scene has no [place]: the sun stands where [sky] puts it.");
                if ui.button("Add a place and a time").clicked() {
                    s.place = Some(PlaceConfig {
                        latitude_deg: 43.3,
                        longitude_deg: 5.37,
                        time_utc: "2024-06-21T10:00:00Z".into(),
                        sun_model: Default::default(),
                        refraction: true,
                    });
                    self.date = "2024-06-21".into();
                }
            }
        }

        ui.separator();
        ui.heading("Camera");
        ui.label("Drag: orbit. Shift+drag: look around. Right drag: move. Wheel: zoom.");
        ui.add(egui::Slider::new(&mut s.camera.position[1], -5.0..=200.0).text("height (m)"));
        ui.add(egui::Slider::new(&mut s.camera.fov_deg, 5.0..=120.0).text("field of view (°)"));

        ui.separator();
        ui.heading("Phenomena");
        let p = &mut s.phenomena;
        ui.checkbox(&mut p.foam, "foam");
        ui.checkbox(&mut p.whitecaps, "whitecaps");
        ui.checkbox(&mut p.spray, "spray");
        ui.checkbox(&mut p.subsurface, "light through crests");
        ui.checkbox(&mut p.aerial_perspective, "aerial perspective");
        ui.checkbox(&mut p.glare, "glare");
        // Clouds are drawn when the scene has a cloud layer and they are on.
        let mut clouds = p.clouds && s.sky.clouds.is_some();
        if ui.checkbox(&mut clouds, "clouds").changed() {
            p.clouds = clouds;
            if clouds && s.sky.clouds.is_none() {
                s.sky.clouds = Some(CloudConfig::default());
            }
        }

        ui.separator();
        ui.heading("Output");
        ui.horizontal(|ui| {
            ui.label("scene file");
            ui.text_edit_singleline(&mut self.save_path);
        });
        let mut image = s.output.path.display().to_string();
        ui.horizontal(|ui| {
            ui.label("image");
            if ui.text_edit_singleline(&mut image).changed() {
                s.output.path = PathBuf::from(&image);
            }
        });
        ui.label(format!("{} × {} pixels, {} spp", s.camera.width, s.camera.height, s.camera.spp));
        ui.horizontal(|ui| {
            if ui
                .button("Save")
                .on_hover_text("Write the scene as TOML: `brine render FILE` renders this view")
                .clicked()
            {
                let path = PathBuf::from(&self.save_path);
                self.message = Some(match save_scene(&self.scene, &path) {
                    Ok(()) => format!("saved {}", path.display()),
                    Err(e) => e,
                });
            }
            let busy =
                self.job.as_ref().is_some_and(|j| j.done.lock().unwrap_or_else(PoisonError::into_inner).is_none());
            if ui
                .add_enabled(!busy, egui::Button::new("Render"))
                .on_hover_text("Render the image at the output's size")
                .clicked()
            {
                self.job = Some(start_render(self.scene.clone(), ui.ctx().clone(), &self.render_thread));
            }
        });
        if let Some(job) = &self.job {
            match &*job.done.lock().unwrap_or_else(PoisonError::into_inner) {
                None => {
                    let f = job.rows.load(Ordering::Relaxed) as f32 / job.total_rows.max(1) as f32;
                    ui.add(egui::ProgressBar::new(f).show_percentage().text("rendering"));
                }
                Some(Ok(p)) => {
                    ui.label(format!("wrote {}", p.display()));
                }
                Some(Err(e)) => {
                    ui.colored_label(egui::Color32::LIGHT_RED, e);
                }
            }
        }
        if let Some(m) = &self.message {
            ui.separator();
            ui.label(m);
        }
        if let Some(e) = self.shared.error() {
            ui.colored_label(egui::Color32::LIGHT_RED, e);
        }
        ui.separator();
        let pass = self.last.map_or("—".to_owned(), |(_, p, _)| {
            let (w, h) = p.size(self.preview_size().0, self.preview_size().1);
            format!("{w}×{h}, {} spp", p.spp)
        });
        ui.label(format!("preview {pass}; {:.1} frames/s", self.fps));
    }

    /// The image, and the mouse on it.
    fn image(&mut self, ui: &mut egui::Ui) {
        let (w, h) = self.preview_size();
        let avail = ui.available_size();
        let scale = (avail.x / w as f32).min(avail.y / h as f32).max(0.1);
        let size = egui::vec2(w as f32 * scale, h as f32 * scale);
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click_and_drag());
        self.image_rect = Some(rect);
        match &self.texture {
            Some(t) => {
                ui.painter().image(
                    t.id(),
                    rect,
                    egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)),
                    egui::Color32::WHITE,
                );
            }
            None => {
                ui.painter().rect_filled(rect, 0.0, egui::Color32::from_gray(20));
            }
        }
        let c = &mut self.scene.camera;
        let d = response.drag_delta();
        if response.dragged_by(egui::PointerButton::Primary) && d != egui::Vec2::ZERO {
            let k = ORBIT_DEG_PER_POINT * c.fov_deg / 50.0;
            let (dx, dy) = (f64::from(d.x) * k, f64::from(d.y) * k);
            if ui.input(|i| i.modifiers.shift) {
                // Look around from where the camera stands.
                let (yaw, pitch) = (c.yaw_deg.unwrap_or(0.0), c.pitch_deg.unwrap_or(0.0));
                c.yaw_deg = Some((yaw - dx).rem_euclid(360.0));
                c.pitch_deg = Some((pitch + dy).clamp(-89.0, 89.0));
            } else {
                orbit(c, -dx, -dy);
            }
        }
        if (response.dragged_by(egui::PointerButton::Secondary) || response.dragged_by(egui::PointerButton::Middle))
            && d != egui::Vec2::ZERO
        {
            let yaw = c.yaw_deg.unwrap_or(0.0).to_radians();
            let (forward, right) = (DVec3::new(yaw.sin(), 0.0, -yaw.cos()), DVec3::new(yaw.cos(), 0.0, yaw.sin()));
            let k = PAN_PER_POINT_PER_M * c.position[1].abs().max(1.0);
            let p = DVec3::from_array(c.position) - right * f64::from(d.x) * k + forward * f64::from(d.y) * k;
            c.position = p.to_array();
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                c.fov_deg = (c.fov_deg * (-ZOOM_PER_POINT * f64::from(scroll)).exp()).clamp(5.0, 120.0);
            }
        }
    }

    /// Plays the script's step in progress into this frame's input.
    fn play(&mut self, ctx: &egui::Context, raw: &mut egui::RawInput) {
        let settled = !self.shared.busy() && self.last.is_some_and(|(g, _, _)| g == self.generation);
        let rect = self.image_rect;
        let scene = self.scene.clone();
        let Some(p) = self.script.as_mut() else { return };
        let Some(step) = p.steps.get(p.at).cloned() else { return };
        let elapsed = p.started.elapsed().as_secs_f64();
        let mut next = false;
        match step {
            Step::Wait(s) => next = elapsed >= s,
            Step::Settle => {
                next = settled;
                if elapsed > SETTLE_TIMEOUT_S {
                    *p.failed.lock().unwrap_or_else(PoisonError::into_inner) =
                        Some(format!("script: the view did not settle in {SETTLE_TIMEOUT_S} s"));
                    ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                }
            }
            Step::Drag { dx, dy, seconds, pan } => {
                let Some(rect) = rect else { return };
                let button = if pan { egui::PointerButton::Secondary } else { egui::PointerButton::Primary };
                let start = rect.center();
                let f = if seconds > 0.0 { (elapsed / seconds).min(1.0) as f32 } else { 1.0 };
                let at = start + egui::vec2(dx, dy) * f;
                let modifiers = egui::Modifiers::default();
                if !p.pressed {
                    raw.events.push(egui::Event::PointerMoved(start));
                    raw.events.push(egui::Event::PointerButton { pos: start, button, pressed: true, modifiers });
                    p.pressed = true;
                } else {
                    raw.events.push(egui::Event::PointerMoved(at));
                    if f >= 1.0 {
                        raw.events.push(egui::Event::PointerButton { pos: at, button, pressed: false, modifiers });
                        next = true;
                    }
                }
            }
            Step::Scroll(dy) => {
                if let Some(rect) = rect {
                    raw.events.push(egui::Event::PointerMoved(rect.center()));
                    raw.events.push(egui::Event::MouseWheel {
                        unit: egui::MouseWheelUnit::Point,
                        delta: egui::vec2(0.0, dy),
                        phase: egui::TouchPhase::Move,
                        source: egui::MouseWheelSource::Unknown,
                        modifiers: egui::Modifiers::default(),
                    });
                    next = elapsed > 0.5;
                }
            }
            Step::Screenshot(path) => {
                if !p.pressed {
                    p.pressed = true;
                    p.shooting.store(true, Ordering::SeqCst);
                    let (shooting, failed) = (p.shooting.clone(), p.failed.clone());
                    ctx.request_screenshot(move |image| {
                        if let Err(e) = write_screenshot(&path, &image) {
                            *failed.lock().unwrap_or_else(PoisonError::into_inner) = Some(e);
                        }
                        shooting.store(false, Ordering::SeqCst);
                    });
                } else {
                    next = !p.shooting.load(Ordering::SeqCst);
                }
            }
            Step::Save(path) => {
                if let Err(e) = save_scene(&scene, &path) {
                    *p.failed.lock().unwrap_or_else(PoisonError::into_inner) = Some(e);
                }
                next = true;
            }
            Step::Render => {
                if !p.pressed {
                    p.pressed = true;
                    self.job = Some(start_render(scene, ctx.clone(), &self.render_thread));
                } else if let Some(job) = &self.job {
                    match &*job.done.lock().unwrap_or_else(PoisonError::into_inner) {
                        None => {}
                        Some(Ok(_)) => next = true,
                        Some(Err(e)) => {
                            *p.failed.lock().unwrap_or_else(PoisonError::into_inner) = Some(format!("render: {e}"));
                            next = true;
                        }
                    }
                }
            }
            Step::Quit => {
                ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            }
        }
        if next {
            p.at += 1;
            p.started = Instant::now();
            p.pressed = false;
        }
    }
}

/// Distance (m) to the point a camera orbits when its view does not meet the sea within it.
const ORBIT_FAR_M: f64 = 100.0;
/// The lowest elevation (°) of an orbiting camera above its pivot: it stays above the sea.
const ORBIT_MIN_ELEVATION_DEG: f64 = 2.0;

/// Orbits the camera by `d_azimuth` and `d_elevation` (°) around the point it looks at: where
/// its view meets the sea, or [`ORBIT_FAR_M`] ahead when that is farther or above the horizon.
/// The camera keeps its distance to that point and looks at it.
fn orbit(c: &mut crate::scene::CameraConfig, d_azimuth: f64, d_elevation: f64) {
    let p = DVec3::from_array(c.position);
    let f = crate::camera::direction_from_bearing(c.yaw_deg.unwrap_or(0.0), c.pitch_deg.unwrap_or(0.0));
    let distance = if f.y < 0.0 && p.y > 0.0 { (-p.y / f.y).clamp(1.0, ORBIT_FAR_M) } else { ORBIT_FAR_M };
    let pivot = p + f * distance;
    let offset = p - pivot;
    let r = offset.length();
    let azimuth = offset.z.atan2(offset.x) + d_azimuth.to_radians();
    let elevation = ((offset.y / r).clamp(-1.0, 1.0).asin().to_degrees() + d_elevation)
        .clamp(ORBIT_MIN_ELEVATION_DEG, 89.0)
        .to_radians();
    let offset = DVec3::new(elevation.cos() * azimuth.cos(), elevation.sin(), elevation.cos() * azimuth.sin()) * r;
    let position = pivot + offset;
    let forward = (pivot - position) / r;
    c.position = position.to_array();
    c.yaw_deg = Some(forward.x.atan2(-forward.z).to_degrees().rem_euclid(360.0));
    c.pitch_deg = Some(forward.y.clamp(-1.0, 1.0).asin().to_degrees());
}

/// Writes the scene as TOML, atomically.
fn save_scene(scene: &Scene, path: &Path) -> Result<(), String> {
    let name = path.display().to_string();
    let text = scene.to_toml(&name).map_err(|e| e.to_string())?;
    crate::output::write_atomic(path, |w| std::io::Write::write_all(w, text.as_bytes())).map_err(|e| e.to_string())
}

/// Writes a window screenshot as PNG.
fn write_screenshot(path: &Path, image: &egui::ColorImage) -> Result<(), String> {
    let [w, h] = image.size;
    let rgba: Vec<u8> = image.pixels.iter().flat_map(|c| c.to_array()).collect();
    let png = image::RgbaImage::from_raw(w as u32, h as u32, rgba).ok_or("screenshot: bad image size")?;
    crate::output::write_atomic(path, |out| png.write_to(out, image::ImageFormat::Png).map_err(std::io::Error::other))
        .map_err(|e| e.to_string())
}

/// Starts the full render of `scene` on another thread.
fn start_render(scene: Scene, ctx: egui::Context, running: &RenderThread) -> Arc<Job> {
    let job = Arc::new(Job { total_rows: scene.camera.height, ..Job::default() });
    let j = job.clone();
    let path = scene.output.path.clone();
    let handle = std::thread::spawn(move || {
        let on_row = || {
            j.rows.fetch_add(1, Ordering::Relaxed);
            ctx.request_repaint();
        };
        let result = crate::render(&scene, &crate::RenderOptions::default(), &on_row)
            .map_err(|e| e.to_string())
            .and_then(|frame| {
                let path = scene.output.path.clone();
                crate::write_frame(&path, &frame, frame.exposure_ev, scene.output.aovs)
                    .map(|()| path)
                    .map_err(|e| e.to_string())
            });
        *j.done.lock().unwrap_or_else(PoisonError::into_inner) = Some(result);
        ctx.request_repaint();
    });
    *running.lock().unwrap_or_else(PoisonError::into_inner) = Some((path, handle));
    job
}

/// The full render in progress, if any: its output path and thread, which [`super::run`] waits
/// for when the window closes (the image is not lost half made).
pub type RenderThread = Arc<Mutex<Option<(PathBuf, std::thread::JoinHandle<()>)>>>;

impl eframe::App for ViewApp {
    fn raw_input_hook(&mut self, ctx: &egui::Context, raw_input: &mut egui::RawInput) {
        self.play(ctx, raw_input);
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        if self.first_frame.is_none() {
            self.first_frame = Some(self.opened.elapsed().as_secs_f64());
        }
        self.receive(&ctx);
        self.count();
        egui::Panel::left("controls").resizable(false).default_size(300.0).show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| self.controls(ui));
        });
        egui::CentralPanel::default().show(ui, |ui| {
            ui.centered_and_justified(|ui| self.image(ui));
        });
        self.send();
        if self.script.is_some() {
            // A script plays on the window's frames: one every 20 ms (not as fast as a display
            // without vertical sync allows, which would take the renderer's processor time).
            ctx.request_repaint_after(std::time::Duration::from_millis(20));
        }
    }

    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        self.shared.stop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `atan2` and `asin` of a unit vector made of sines and cosines of round angles: a few
    /// ulps of the angle; 10⁻⁹° is a wide margin.
    const ANGLE_ROUNDING_DEG: f64 = 1e-9;

    #[test]
    fn a_look_at_camera_keeps_its_view_as_angles() {
        let mut scene = Scene::default_scene();
        scene.camera.yaw_deg = None;
        scene.camera.pitch_deg = None;
        let p = DVec3::from_array(scene.camera.position);
        for (yaw, pitch) in [(0.0, -10.0), (90.0, 5.0), (200.0, -45.0)] {
            scene.camera.look_at = Some((p + crate::camera::direction_from_bearing(yaw, pitch) * 30.0).to_array());
            let (y, q) = yaw_pitch(&scene);
            assert!(
                (y - yaw).abs() < ANGLE_ROUNDING_DEG && (q - pitch).abs() < ANGLE_ROUNDING_DEG,
                "{yaw} {pitch}: {y} {q}"
            );
        }
    }

    /// Orbiting keeps the camera's distance to the point it looks at on the sea and keeps looking
    /// at it; a full turn comes back to the start; the camera stays above the sea.
    #[test]
    fn the_camera_orbits_the_point_it_looks_at() {
        const ORBIT_ROUNDING_M: f64 = 1e-9;
        let mut c = Scene::default_scene().camera;
        let p0 = DVec3::from_array(c.position);
        let f0 = crate::camera::direction_from_bearing(c.yaw_deg.unwrap(), c.pitch_deg.unwrap());
        let pivot = p0 + f0 * (-p0.y / f0.y);
        let start = c.clone();
        for _ in 0..8 {
            orbit(&mut c, 45.0, 0.0);
            let p = DVec3::from_array(c.position);
            let f = crate::camera::direction_from_bearing(c.yaw_deg.unwrap(), c.pitch_deg.unwrap());
            assert!(((p - pivot).length() - (p0 - pivot).length()).abs() < ORBIT_ROUNDING_M);
            assert!((p + f * (p - pivot).length() - pivot).length() < ORBIT_ROUNDING_M);
        }
        for (a, b) in c.position.iter().zip(start.position) {
            assert!((a - b).abs() < ORBIT_ROUNDING_M);
        }
        orbit(&mut c, 0.0, -80.0);
        assert!(c.position[1] > 0.0 && c.pitch_deg.unwrap() < 0.0);
    }

    #[test]
    fn dates_and_hours_make_instants() {
        assert_eq!(instant_of("2024-09-20", 7.75).as_deref(), Some("2024-09-20T07:45:00Z"));
        assert_eq!(date_and_hour("2024-09-20T07:45:00Z"), Some(("2024-09-20".into(), 7.75)));
        assert_eq!(instant_of("2024-13-01", 1.0), None);
        assert_eq!(instant_of("2024-09-20", 24.0).as_deref(), Some("2024-09-20T23:59:59Z"));
    }
}
