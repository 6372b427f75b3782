//! The preview's render thread: it keeps the world of the scene on screen, renders the passes
//! the schedule asks for, and hands each finished image to the window.
//!
//! What a change costs depends on what changed. A camera move only swaps the world's camera
//! ([`World::set_camera`]); with clouds, a move over the sea builds the world again before the
//! refining passes, so that the clouds are seen from the camera. A new hour or date builds the world at that instant on the parts
//! that do not change with time ([`World::at_instant`]). A new sea (wind, surface, spectrum,
//! phenomena) builds those parts again ([`Timeless::new`]).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use std::time::Instant;

use crate::scene::{CameraConfig, Scene};
use crate::world::{Timeless, World};
use crate::{RenderError, RenderOptions, render_world_cancellable};

use super::schedule::{FRAME_BUDGET_S, Pass, Schedule};

/// What the window asks the render thread to show.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The scene as edited (its camera's size and samples are the output's, not the preview's).
    pub scene: Scene,
    /// The preview's size (pixels).
    pub preview: (u32, u32),
    /// Increases with every request.
    pub generation: u64,
}

/// A finished pass, tone-mapped for the screen.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    /// The request it shows.
    pub generation: u64,
    /// The pass.
    pub pass: Pass,
    /// Image size (pixels).
    pub size: (u32, u32),
    /// 8-bit sRGB, RGBA, row-major, top row first.
    pub rgba: Vec<u8>,
    /// Seconds the pass took to render (the world's construction not included).
    pub render_s: f64,
    /// Seconds spent building the world for it (0 when only the camera moved).
    pub build_s: f64,
}

/// What the window and the render thread share.
#[derive(Default)]
pub struct Shared {
    request: Mutex<Option<Request>>,
    wake: Condvar,
    shown: Mutex<Option<Shown>>,
    error: Mutex<Option<String>>,
    cancel: AtomicBool,
    stop: AtomicBool,
    /// Set while the thread renders or builds; cleared when the view is fully refined.
    busy: AtomicBool,
}

impl Shared {
    /// Asks for `request`: the pass in progress, unless it is the first of its view, is given up.
    pub fn ask(&self, request: Request) {
        *self.request.lock().unwrap_or_else(PoisonError::into_inner) = Some(request);
        self.busy.store(true, Ordering::SeqCst);
        self.cancel.store(true, Ordering::SeqCst);
        self.wake.notify_all();
    }

    /// The newest finished pass not yet taken.
    pub fn take_shown(&self) -> Option<Shown> {
        self.shown.lock().unwrap_or_else(PoisonError::into_inner).take()
    }

    /// Why the last request could not be rendered (a model refused the scene), if it could not.
    pub fn error(&self) -> Option<String> {
        self.error.lock().unwrap_or_else(PoisonError::into_inner).clone()
    }

    /// Whether the thread still has work for the view on screen.
    pub fn busy(&self) -> bool {
        self.busy.load(Ordering::SeqCst)
    }

    /// Ends the render thread.
    pub fn stop(&self) {
        self.stop.store(true, Ordering::SeqCst);
        self.cancel.store(true, Ordering::SeqCst);
        self.wake.notify_all();
    }
}

/// The scene without its camera: what decides whether the world must be built again.
fn without_camera(scene: &Scene) -> Scene {
    Scene { camera: CameraConfig::default(), ..scene.clone() }
}

/// The render thread's loop; `repaint` is called after each finished pass.
pub fn run(shared: &Shared, repaint: &(dyn Fn() + Sync)) {
    let mut timeless: Option<Timeless> = None;
    let mut world: Option<(Scene, World)> = None;
    let mut current: Option<Request> = None;
    let mut schedule = Schedule::new(1, 1, FRAME_BUDGET_S);
    loop {
        {
            let mut pending = shared.request.lock().unwrap_or_else(PoisonError::into_inner);
            loop {
                if shared.stop.load(Ordering::SeqCst) {
                    return;
                }
                if let Some(r) = pending.take() {
                    schedule.restart(r.preview.0, r.preview.1);
                    current = Some(r);
                    break;
                }
                if current.is_some() && schedule.next().is_some() {
                    break;
                }
                shared.busy.store(false, Ordering::SeqCst);
                pending = shared.wake.wait(pending).unwrap_or_else(PoisonError::into_inner);
            }
            shared.cancel.store(false, Ordering::SeqCst);
        }
        let Some(request) = current.as_ref() else { continue };
        let Some(pass) = schedule.next() else { continue };

        // The world of the request: rebuilt only as far as what changed requires. A move over the
        // sea with clouds keeps the clouds seen from where the world was built for the view's
        // first pass, which follows the mouse; the refining passes see them from the camera.
        let started = Instant::now();
        let key = without_camera(&request.scene);
        let clouds_from_elsewhere = |w: &World| {
            let p = request.scene.camera.position;
            w.cloud_origin().is_some_and(|o| o != glam::DVec2::new(p[0], p[2]))
        };
        if world.as_ref().is_none_or(|(k, w)| *k != key || (!schedule.is_first() && clouds_from_elsewhere(w))) {
            world = None;
            if !timeless.as_ref().is_some_and(|t| t.fits(&request.scene)) {
                timeless = None;
                match Timeless::new(&request.scene, None) {
                    Ok(t) => timeless = Some(t),
                    Err(e) => {
                        *shared.error.lock().unwrap_or_else(PoisonError::into_inner) = Some(e.to_string());
                        current = None;
                        continue;
                    }
                }
            }
            let Some(parts) = timeless.as_ref() else { continue };
            match World::at_instant(&request.scene, parts) {
                Ok(w) => world = Some((key, w)),
                Err(e) => {
                    *shared.error.lock().unwrap_or_else(PoisonError::into_inner) = Some(e.to_string());
                    current = None;
                    continue;
                }
            }
        }
        *shared.error.lock().unwrap_or_else(PoisonError::into_inner) = None;
        let build_s = started.elapsed().as_secs_f64();
        let Some((_, w)) = world.as_mut() else { continue };

        // The pass: the scene at the pass's size and samples.
        let (pw, ph) = request.preview;
        let (width, height) = pass.size(pw, ph);
        let mut scene = request.scene.clone();
        scene.camera.width = width;
        scene.camera.height = height;
        scene.camera.spp = pass.spp;
        w.set_camera(&scene.camera);
        // The first pass of a view is always finished: a view that keeps moving is still drawn.
        let cancel = (!schedule.is_first()).then_some(&shared.cancel);
        let t = Instant::now();
        match render_world_cancellable(&scene, w, &RenderOptions::default(), &|| {}, cancel) {
            Ok(frame) => {
                let render_s = t.elapsed().as_secs_f64();
                schedule.done(pass, render_s);
                let rgba = rgba8(&frame);
                let shown =
                    Shown { generation: request.generation, pass, size: (width, height), rgba, render_s, build_s };
                *shared.shown.lock().unwrap_or_else(PoisonError::into_inner) = Some(shown);
                repaint();
            }
            Err(RenderError::Cancelled) => {}
            Err(e) => {
                *shared.error.lock().unwrap_or_else(PoisonError::into_inner) = Some(e.to_string());
                current = None;
            }
        }
    }
}

/// A frame exposed and tone-mapped as `brine render` writes it to PNG: 8-bit sRGB, RGBA.
pub fn rgba8(frame: &crate::Frame) -> Vec<u8> {
    let scale = crate::tonemap::exposure_scale(frame.exposure_ev);
    frame
        .pixels
        .iter()
        .flat_map(|&p| {
            let [r, g, b] = crate::tonemap::to_srgb8(p, scale);
            [r, g, b, 255]
        })
        .collect()
}

/// Starts the render thread.
///
/// # Errors
/// The system's error if the thread cannot be started.
pub fn spawn(
    repaint: impl Fn() + Send + Sync + 'static,
) -> std::io::Result<(Arc<Shared>, std::thread::JoinHandle<()>)> {
    let shared = Arc::new(Shared::default());
    let s = shared.clone();
    let handle = std::thread::Builder::new().name("brine-view-render".into()).spawn(move || run(&s, &repaint))?;
    Ok((shared, handle))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    /// Waits for the thread to finish the view on screen and returns the last pass shown.
    fn settle(shared: &Shared) -> Shown {
        let mut last = None;
        let t = Instant::now();
        while t.elapsed() < Duration::from_secs(120) {
            if let Some(s) = shared.take_shown() {
                last = Some(s);
            }
            if !shared.busy() {
                if let Some(s) = shared.take_shown() {
                    last = Some(s);
                }
                break;
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        last.expect("a pass was shown")
    }

    /// The render thread refines a view to its final pass, which is `brine render`'s image of
    /// the scene at the preview's size and that pass's samples; a camera move, a new hour, a
    /// new wind and a move over the sea under clouds are drawn the same way on what it keeps of
    /// the world.
    #[test]
    fn the_preview_ends_on_the_still_of_the_scene() {
        let (shared, handle) = spawn(|| {}).expect("the render thread starts");
        let mut scene = Scene::default_scene();
        scene.sea.waves = Some(12);
        let preview = (24, 16);
        let check = |scene: &Scene, generation: u64| {
            shared.ask(Request { scene: scene.clone(), preview, generation });
            let shown = settle(&shared);
            assert_eq!(shown.generation, generation);
            assert_eq!(shown.pass, Pass { block: 1, spp: 16 });
            let mut still = scene.clone();
            (still.camera.width, still.camera.height, still.camera.spp) = (24, 16, 16);
            let frame = crate::render(&still, &RenderOptions::default(), &|| {}).expect("renders");
            assert!(rgba8(&frame) == shown.rgba, "generation {generation}");
        };
        check(&scene, 1);
        scene.camera.yaw_deg = Some(140.0);
        check(&scene, 2);
        if let Some(place) = scene.place.as_mut() {
            place.time_utc = "2024-09-20T15:10:00Z".into();
        }
        check(&scene, 3);
        // A new sea builds the instant-free parts again.
        scene.sea.wind_speed_m_s = 14.0;
        check(&scene, 4);
        // With clouds, a move over the sea ends on the clouds seen from where the camera stands
        // (the world is built again before the refining passes).
        scene.sky.clouds =
            Some(crate::scene::CloudConfig { cover: 0.5, scale_m: 300.0, ..crate::scene::CloudConfig::default() });
        check(&scene, 5);
        scene.camera.position = [700.0, 10.0, -400.0];
        check(&scene, 6);
        shared.stop();
        handle.join().expect("the thread ends");
    }

    /// A scene a model refuses is reported, and the thread goes on with the next request.
    #[test]
    fn a_refused_scene_is_reported() {
        let (shared, handle) = spawn(|| {}).expect("the render thread starts");
        let mut scene = Scene::default_scene();
        scene.sea.waves = Some(12);
        scene.water.water_type = Some("not-a-type".into());
        shared.ask(Request { scene: scene.clone(), preview: (8, 6), generation: 1 });
        let t = Instant::now();
        while shared.error().is_none() && t.elapsed() < Duration::from_secs(60) {
            std::thread::sleep(Duration::from_millis(5));
        }
        assert!(shared.error().is_some_and(|e| e.contains("not-a-type")), "{:?}", shared.error());
        scene.water.water_type = None;
        shared.ask(Request { scene, preview: (8, 6), generation: 2 });
        assert_eq!(settle(&shared).generation, 2);
        assert!(shared.error().is_none());
        shared.stop();
        handle.join().expect("the thread ends");
    }
}
