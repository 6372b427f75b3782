//! # brine-render — the thin renderer and the `brine` command
//!
//! Composes the model crates into an image: a scene file (TOML) describes the sea, sky and camera;
//! each pixel's primary ray is sphere traced against the fitted trochoid sea (brine-waves,
//! brine-trace), and shaded with exact Fresnel reflection of the Preetham sky (brine-optics,
//! brine-sky), the sun through the Bruneton ocean BRDF of the waves too small to draw, and the
//! light leaving the water body. The image is exposed, tone-mapped and written as PNG or EXR.
//!
//! ## Example
//!
//! ```no_run
//! use brine_render::{RenderOptions, Scene, render, write_image};
//! let mut scene = Scene::default_scene();
//! scene.camera.width = 160;
//! scene.camera.height = 90;
//! let frame = render(&scene, &RenderOptions::default(), &|| {})?;
//! write_image("small.png".as_ref(), frame.width, frame.height, &frame.pixels, frame.exposure_ev)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod camera;
pub mod cli;
pub mod glare;
pub mod output;
mod render;
pub mod scene;
pub mod tonemap;
mod world;

pub use output::{OutputError, OutputFormat, write_frame, write_image};
pub use render::{Aov, Frame, RenderError, RenderOptions, Stage, StageTimes, render, render_world};
pub use scene::{Scene, SceneError};
pub use world::{World, WorldError, auto_exposure_ev};
