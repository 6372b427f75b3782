//! # brine-render — the thin renderer and the `brine` command
//!
//! Composes the model crates into an image of a sea at a place and an hour. A scene file (TOML,
//! [`Scene`]) sets place and UTC time (the sun and the moon from brine-ephem), wind, spectrum and
//! swell, water, sky, clouds, camera and output. [`World::new`] builds the models once per frame;
//! each pixel's primary ray is traced against the fitted trochoid sea (or the FFT, Gerstner or
//! sine sea) by brine-trace with footprint fading, and shaded by the models of every paper:
//!
//! | term | model | crate |
//! |---|---|---|
//! | `F·R(θ, σ)/R(θ, 0) · L_sky(r)` | exact Fresnel at the resolved facet, the rough-surface factor of the unresolved slopes, the sky with clouds | brine-optics, brine-sky |
//! | `L_glint` | Bruneton et al. 2010 BRDF of the unresolved and faded slopes, sun and moon (discs integrated on calm water) | brine-optics |
//! | `(1 − F) L_w / n²` | Darles et al. 2007 Eq. 8–11 (Premoze–Ashikhmin water), the floor traced by the same tracer | brine-optics, brine-trace |
//! | `L_crest` | Jensen et al. 2001 dipole through thin crests (thickness traced along the refracted sun ray) | brine-optics |
//! | foam `s′`, whitecaps `W` | Darles Eq. 4 (corrected) with Koepke's reflectance; Dupuy & Bruneton 2012, α calibrated to Monahan | brine-foam, brine-whitecap |
//! | `L₀ F_ex + L_in` | Hoffman & Preetham 2002 aerial perspective, then Monahan et al. 1986 spray | brine-sky, brine-foam |
//!
//! then glare (Spencer et al. 1995), exposure (ISO 2720 meter) and the ACES filmic curve, written
//! as PNG or EXR with AOVs. How a pixel is made: `docs/renderer.md`; every scene key with its unit
//! and range: `docs/scene.md`.
//!
//! ## Notation
//!
//! | symbol | Rust | unit |
//! |---|---|---|
//! | radiance `L` | [`Frame::pixels`] | kcd m⁻² (linear sRGB, Y in kcd m⁻²) |
//! | exposure | [`Frame::exposure_ev`] | EV₁₀₀ |
//! | hit distance `t` | [`Aov::depth`] | m |
//! | `U₁₀` | `scene.sea.wind_speed_m_s` | m s⁻¹ |
//!
//! ## Validity
//!
//! Every scene value has a checked range ([`Scene::load`] rejects the others with the file, line
//! and key): wind `[0, 60]` m/s, up to 10 000 waves, any sun elevation (night and twilight), a
//! camera above or under water. The image depends only on the scene, not on the thread count.
//!
//! ## Example
//!
//! ```
//! use brine_render::{RenderOptions, Scene, render, write_image};
//! let mut scene = Scene::default_scene();
//! scene.camera.width = 80;
//! scene.camera.height = 45;
//! let frame = render(&scene, &RenderOptions::default(), &|| {})?;
//! assert!(frame.pixels.iter().all(|p| p.is_finite()));
//! let path = std::env::temp_dir().join("brine-doc-example.png");
//! write_image(&path, frame.width, frame.height, &frame.pixels, frame.exposure_ev)?;
//! # std::fs::remove_file(&path)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod camera;
pub mod cli;
pub mod export;
pub mod glare;
pub mod output;
mod render;
pub mod scene;
pub mod tonemap;
#[cfg(feature = "view")]
pub mod view;
mod world;

pub use output::{OutputError, OutputFormat, write_frame, write_image};
pub use render::{
    Aov, ENERGY_BANDS, Frame, RenderError, RenderOptions, Stage, StageTimes, energy_bands, render, render_world,
    render_world_cancellable,
};
pub use scene::{Scene, SceneError};
pub use world::{Cover, NIGHT_ADAPTATION_LX, Timeless, WhiteWaterSea, World, WorldError, auto_exposure_ev};
