//! # brine-texture — the photo-based ocean of Lai & Wu
//!
//! An ocean built from two photographs instead of a wave model (Lai & Wu, "Ocean surface
//! rendering using temporal texture synthesis"): a small-wave photo becomes an endless, seamless
//! animation of tileable frames, a main-structure photo a tileable low-frequency height field;
//! heights come from intensities (Eq. 1), the two are composed (Eq. 2–3), the small waves are
//! relit by the large ones (Eq. 6–9) and both move (Eq. 10–11).
//!
//! 1. **Tileable synthesis** ([`synthesize_tileable`]): patch-based "chessboard filling" with
//!    toroidal windows (Lai & Wu 2007, their ref. \[12\]; Liang et al. 2001).
//! 2. **Temporal synthesis** ([`synthesize_sequence`], [`TransitionGraph`],
//!    [`MeshCorrespondence`], [`walk_position`]): a basis sequence synthesised under the spatial
//!    O-shaped-zone constraint and the temporal one, frame-to-frame transition links with
//!    probabilities, and affine-mesh morphing along each link, walked at random.
//! 3. **Heights** ([`height_from_intensity`], [`HeightField`]): Eq. 1 for the main texture and
//!    every small-wave frame.
//! 4. **Composition, relighting, animation** ([`OceanFrame`], [`relight_intensity`]).
//! 5. **Rendering**: the paper's perspective projection of the plane ([`render_projection`]),
//!    and beyond the paper a sphere-traced height field ([`ComposedSurface`] is a
//!    [`brine_trace::LipschitzSum`]) shaded with brine-sky's sky, brine-optics' Fresnel, ocean
//!    BRDF and water, and refraction onto a bed ([`render_traced`]).
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `I(x, y)` | [`intensity`] | levels `[0, 255]` | intensity of a texel (Rec. 601 luma) |
//! | `I_min`, `I_max` | `i_min`, `i_max` | levels | intensity range of an image |
//! | `hf` | `hf`, [`OceanParams::height_factor_small_m`], [`OceanParams::height_factor_main_m`] | m | height factor of Eq. 1 |
//! | `P_c`, `P_h` | [`SmallFrame::colour`], [`SmallFrame::height`] | levels, m | small-wave frame and its heights |
//! | `M_h` | [`PhotoOcean::main_height`] | m | main-structure heights |
//! | `scale` | [`OceanParams::scale`] | 1 | main texels per small texel |
//! | `S_c`, `S_h` | [`OceanFrame::colour`], [`OceanFrame::height`] | levels, m | composed colour and height |
//! | `Δheight`, `Δheight_max` | `delta_height`, `delta_height_max` | m | Eq. 8, its largest magnitude |
//! | `dhfac` | inside [`relight_intensity`] | levels m⁻¹ | Eq. 9 factor |
//! | `(m_x, m_y)`, `(s_x, s_y)` | [`OceanParams::main_velocity_m_s`], [`OceanParams::small_velocity_m_s`] | m s⁻¹ | shifting vectors of Eq. 10–11 |
//! | `t` | [`OceanFrame::time_s`] | s | time |
//! | `p`, `w_E` | [`SynthesisParams::patch_size`], [`SynthesisParams::boundary_width`] | texels | patch side, boundary zone width |
//! | `ε` | [`SynthesisParams::tolerance`] | 1 | relative tolerance of the candidate set |
//! | `D(i, j)` | [`frame_distance`] | levels | RMS frame difference |
//! | `P(i → j)` | [`Link::probability`] | 1 | transition probability |
//! | `δ_V`, `α` | [`MeshCorrespondence::displacements`], `alpha` | texels, 1 | morph mesh displacement, morph parameter |
//! | `L_i` | [`brine_trace::LipschitzSum::component_lipschitz`] | 1 | Lipschitz constant of a height field (max slope) |
//!
//! World coordinates follow Brine's conventions: y up, x east, z south; the small-wave texel
//! `(u, v)` of the sea point `(x, z)` is `(x, z)/texel_m` shifted by the animation.
//!
//! ## Validity
//!
//! Any PNG or JPEG photo of water at least one patch in size and not uniform. Eq. 1 is the
//! "dark is deep" heuristic, not true shape from shading: it recovers a height field that is an
//! affine function of the intensity, right up to that affine ambiguity when the photo's shading
//! is itself affine in height, and only qualitatively otherwise. The relit colour stays in
//! `[0, 255]` for every input (clamped as the paper requires). The traced mode needs the camera
//! above the highest wave.
//!
//! ## Example
//!
//! ```
//! use brine_texture::{OceanParams, PhotoOcean, Pinhole, ProjectionOptions, ProjectionView, SynthesisParams, Texture, render_projection};
//! use glam::DVec3;
//! // Two small synthetic "photos" (any PNG/JPEG works: `Texture::load`).
//! let small = Texture::from_fn(40, 40, |i, j| [40.0 + ((i * 7 + j * 3) % 23) as f32 * 5.0, 90.0, 160.0]);
//! let main = Texture::from_fn(40, 40, |i, j| [60.0, 80.0 + ((i + 2 * j) % 31) as f32 * 3.0, 150.0]);
//! let params = OceanParams {
//!     synthesis: SynthesisParams { patch_size: 16, boundary_width: 2, ..SynthesisParams::default() },
//!     small_size: 48, main_size: 48, bed_size: 48, frames: 3, links_per_frame: 1, mesh_spacing: 12,
//!     ..OceanParams::default()
//! };
//! let ocean = PhotoOcean::new(&small, &main, None, &params, 7, &|_| {})?;
//! let camera = Pinhole::from_angles(DVec3::new(0.0, 6.0, 0.0), 180.0, -30.0, 50.0, 64, 48)?;
//! let view = ProjectionView::with_background(&camera, [200; 3]);
//! let image = render_projection(&ocean.frame(5), &view, &ProjectionOptions::default());
//! assert_eq!(image.dimensions(), (64, 48));
//! # Ok::<(), brine_texture::TextureError>(())
//! ```
//!
//! ## References
//!
//! - Lai C.-H., Wu J.-L., "Ocean surface rendering using temporal texture synthesis technique"
//!   (National Chung Hsing University), Eq. 1–11, Fig. 1–9.
//! - Lai C.-H., Wu J.-L. 2007, "Temporal texture synthesis by patch-based sampling and morphing
//!   interpolation", Computer Animation and Virtual Worlds 18(4–5):415–428 (their ref. \[12\]; not
//!   available to us: implemented from the description in §III.A, see `docs/models/brine-texture.md`).
//! - Liang L., Liu C., Xu Y.-Q., Guo B., Shum H.-Y. 2001, "Real-time texture synthesis by
//!   patch-based sampling", ACM TOG 20(3):127–150.
//! - Fang H., Hart J.C. 2004, "Textureshop: texture synthesis as a photograph editing tool",
//!   ACM TOG 23(3):354–359 (Eq. 1's heuristic).
//! - Schödl A., Szeliski R., Salesin D., Essa I. 2000, "Video textures", SIGGRAPH 489–498.
//! - docs/equations.md §14 (errata: the stray "+," of Eq. 10, "relighting(x, y)" of Eq. 11 is ΔI of
//!   Eq. 7–9, the sign of the shift, the range of Eq. 9).

mod camera;
mod error;
mod height;
mod matching;
mod morph;
mod ocean;
mod project;
mod relight;
mod rng;
mod synthesis;
mod temporal;
mod texture;
mod traced;
mod transitions;
mod walk;

pub use camera::Pinhole;
pub use error::TextureError;
pub use height::{HeightField, MIN_INTENSITY_RANGE, height_from_intensity, intensity_change, intensity_from_height};
pub use morph::{MAX_DISPLACEMENT, MeshCorrespondence};
pub use ocean::{OceanFrame, OceanParams, PhotoOcean, Progress, SmallFrame};
pub use project::{ProjectionOptions, ProjectionView, render_projection};
pub use relight::{RelightRule, Relighting, pow_three_quarters, relight_intensity};
pub use synthesis::{
    Sources, SynthesisParams, WrapBorderTest, border_differences, seam_differences, seam_z_score, synthesize_tileable,
    wrap_border_test,
};
pub use temporal::{BasisSequence, synthesize_sequence};
pub use texture::{Grid, LUMA_WEIGHTS, Texture, intensity};
pub use traced::{ComposedSurface, TracedImage, TracedParams, TracedScene, render_traced};
pub use transitions::{Link, TransitionGraph, frame_distance};
pub use walk::{WalkPosition, walk_links, walk_position};
