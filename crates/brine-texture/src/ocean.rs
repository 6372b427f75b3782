//! The whole system: preprocessing (synthesis, transitions, morph meshes, heights) and the
//! composed, relit, animated surface of one frame (Lai & Wu Eq. 2–3, 8–11).

use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use crate::error::check;
use crate::matching::Exemplar;
use crate::rng::{FrameStreams, Purpose};
use crate::synthesis::{Chessboard, chessboard_fill};
use crate::temporal::basis_sequence;
use crate::{
    BasisSequence, Grid, HeightField, MeshCorrespondence, RelightRule, Relighting, SynthesisParams, Texture,
    TextureError, TransitionGraph, WalkPosition, walk_position,
};

/// Every parameter of the photo-based ocean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OceanParams {
    /// Patch-based synthesis (patch size, boundary width, tolerance).
    pub synthesis: SynthesisParams,
    /// Side of the small-wave frames (texels), a multiple of `2(p − 2w_E)`.
    pub small_size: usize,
    /// Side of the main-structure texture (texels), a multiple of `2(p − 2w_E)`.
    pub main_size: usize,
    /// Side of the bed texture (texels), a multiple of `2(p − 2w_E)`.
    pub bed_size: usize,
    /// Frames of the basis sequence, `[2, 256]`.
    pub frames: usize,
    /// Smallest source displacement between consecutive basis frames (texels), `[0, 64]`.
    pub min_shift: usize,
    /// Nearest-frame links per basis frame, `[1, frames − 1]`.
    pub links_per_frame: usize,
    /// Animation frames per link (the in-betweens of the morph plus its start), `[1, 1000]`.
    pub morph_steps: usize,
    /// Spacing of the morph mesh (texels), `[4, small_size/2]`, dividing `small_size`.
    pub mesh_spacing: usize,
    /// Height factor `hf` of the small waves (m), `(0, 100]`.
    pub height_factor_small_m: f64,
    /// Height factor `hf` of the main structure (m), `(0, 100]`.
    pub height_factor_main_m: f64,
    /// The `scale` of Eq. 3: one main-structure texel spans `scale` small-wave texels, `[1, 1000]`.
    pub scale: f64,
    /// Size of a small-wave texel on the sea (m), `(0, 100]`.
    pub texel_m: f64,
    /// Size of a bed texel (m), `(0, 100]`.
    pub bed_texel_m: f64,
    /// Velocity of the small-wave pattern, `[east, south]` (m/s), each `[−100, 100]`.
    pub small_velocity_m_s: [f64; 2],
    /// Velocity of the main structure, `[east, south]` (m/s), each `[−100, 100]`.
    pub main_velocity_m_s: [f64; 2],
    /// Animation frames per second, `(0, 1000]`.
    pub fps: f64,
    /// Form of the relighting factor (Eq. 9).
    pub relight: RelightRule,
}

impl Default for OceanParams {
    fn default() -> Self {
        // Waves moving toward the south-west, as in Lai & Wu's Fig. 6.
        let sw = std::f64::consts::FRAC_1_SQRT_2;
        Self {
            synthesis: SynthesisParams::default(),
            small_size: 256,
            main_size: 256,
            bed_size: 256,
            frames: 12,
            min_shift: 1,
            links_per_frame: 3,
            morph_steps: 8,
            mesh_spacing: 32,
            height_factor_small_m: 0.25,
            height_factor_main_m: 2.0,
            scale: 8.0,
            texel_m: 0.08,
            bed_texel_m: 0.02,
            small_velocity_m_s: [-0.6 * sw, 0.6 * sw],
            main_velocity_m_s: [-2.5 * sw, 2.5 * sw],
            fps: 24.0,
            relight: RelightRule::Paper,
        }
    }
}

impl OceanParams {
    /// Checks that a small-wave or main-structure photo can be used: at least one patch in both
    /// directions, and not uniform (Eq. 1 divides by `I_max − I_min`).
    ///
    /// # Arguments
    /// - `what`: how the photo is named in the error (e.g. its flag and path).
    /// - `photo`: the photo.
    ///
    /// # Errors
    /// [`TextureError::TooSmall`] or [`TextureError::Flat`] naming `what`.
    pub fn check_photo(&self, what: &str, photo: &Texture) -> Result<(), TextureError> {
        self.synthesis.check_exemplar(what, photo)?;
        let (lo, hi) = photo.intensity_range();
        if !(f64::from(hi) - f64::from(lo) > crate::height::MIN_INTENSITY_RANGE) {
            return Err(TextureError::Flat { what: what.to_owned(), level: f64::from(lo) });
        }
        Ok(())
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] naming the first bad field.
    pub fn validate(&self) -> Result<(), TextureError> {
        self.synthesis.validate()?;
        self.synthesis.check_output("small_size", self.small_size, self.small_size)?;
        self.synthesis.check_output("main_size", self.main_size, self.main_size)?;
        self.synthesis.check_output("bed_size", self.bed_size, self.bed_size)?;
        check("frames", self.frames as f64, (2..=256).contains(&self.frames), "[2, 256]")?;
        check("min_shift", self.min_shift as f64, self.min_shift <= 64, "[0, 64] texels")?;
        check(
            "links_per_frame",
            self.links_per_frame as f64,
            self.links_per_frame >= 1 && self.links_per_frame < self.frames,
            "[1, frames − 1]",
        )?;
        check("morph_steps", self.morph_steps as f64, (1..=1000).contains(&self.morph_steps), "[1, 1000]")?;
        let g = self.mesh_spacing;
        check(
            "mesh_spacing",
            g as f64,
            g >= 4 && 2 * g <= self.small_size && self.small_size.is_multiple_of(g),
            "[4, small_size/2] texels, dividing small_size",
        )?;
        let metres = |name, v: f64| check(name, v, v > 0.0 && v <= 100.0, "(0, 100] m");
        metres("height_factor_small_m", self.height_factor_small_m)?;
        metres("height_factor_main_m", self.height_factor_main_m)?;
        metres("texel_m", self.texel_m)?;
        metres("bed_texel_m", self.bed_texel_m)?;
        check("scale", self.scale, (1.0..=1000.0).contains(&self.scale), "[1, 1000]")?;
        for v in self.small_velocity_m_s.iter().chain(&self.main_velocity_m_s) {
            check("velocity_m_s", *v, (-100.0..=100.0).contains(v), "[-100, 100] m/s")?;
        }
        check("fps", self.fps, self.fps > 0.0 && self.fps <= 1000.0, "(0, 1000] frames/s")?;
        Ok(())
    }
}

/// Progress of the preprocessing: units of work done out of the total (one unit per synthesised
/// cell, per morph mesh and per height field).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Units done.
    pub done: u64,
    /// Units in all.
    pub total: u64,
}

/// A frame of the small waves as the renderer uses it: colour and mip levels, and (computed on
/// first use, as only the bed and the traced mode need them) its height field by Eq. 1 and the
/// height gradients.
#[derive(Debug, Clone)]
pub struct SmallFrame {
    /// The colour `P_c` (levels).
    pub colour: Texture,
    /// Box-filtered levels `1, 2, …` of `colour` (halving down to 1 texel).
    pub mips: Vec<Texture>,
    hf: f64,
    heights: OnceLock<Heights>,
}

/// The height field of a frame and its central-difference gradients.
#[derive(Debug, Clone)]
struct Heights {
    height: HeightField,
    grad_u: Grid,
    grad_v: Grid,
}

impl SmallFrame {
    /// A frame of colour `colour` whose heights (Eq. 1) use the height factor `hf` (m). A uniform
    /// frame (impossible from a non-uniform input, which preprocessing checks) gets zero heights.
    pub fn new(colour: Texture, hf: f64) -> Self {
        let mut mips = Vec::new();
        let mut level = colour.clone();
        while level.width() > 1 || level.height() > 1 {
            level = level.half();
            mips.push(level.clone());
        }
        Self { colour, mips, hf, heights: OnceLock::new() }
    }

    fn heights(&self) -> &Heights {
        self.heights.get_or_init(|| {
            let c = &self.colour;
            let height = HeightField::from_texture(c, self.hf, "small-wave frame")
                .unwrap_or_else(|_| HeightField::from_heights(Grid::from_fn(c.width(), c.height(), |_, _| 0.0)));
            let (grad_u, grad_v) = height.grid().central_gradients();
            Heights { height, grad_u, grad_v }
        })
    }

    /// The height field `P_h` of Eq. 1 (m).
    pub fn height(&self) -> &HeightField {
        &self.heights().height
    }

    /// Central-difference `∂P_h/∂u` (m per texel).
    pub fn grad_u(&self) -> &Grid {
        &self.heights().grad_u
    }

    /// Central-difference `∂P_h/∂v` (m per texel).
    pub fn grad_v(&self) -> &Grid {
        &self.heights().grad_v
    }

    /// Colour at `(u, v)` (texels) filtered for a footprint of `footprint` texels: trilinear
    /// between the mip levels around `log₂ footprint` (level 0 below one texel).
    #[inline]
    pub fn filtered(&self, u: f64, v: f64, footprint: f64) -> [f32; 3] {
        if !(footprint > 1.0) || self.mips.is_empty() {
            return self.colour.sample(u, v);
        }
        // Levels beyond 2⁶² texels would overflow the shift below; the last level is uniform anyway.
        let lod = mip_level(footprint).min(self.mips.len() as f64);
        let l0 = lod.floor() as usize;
        let f = (lod - l0 as f64) as f32;
        let at = |l: usize| -> [f32; 3] {
            if l == 0 {
                return self.colour.sample(u, v);
            }
            let s = (1u64 << l) as f64;
            let off = 0.5 * (s - 1.0);
            self.mips[l - 1].sample((u - off) / s, (v - off) / s)
        };
        let a = at(l0);
        if f <= 0.0 || l0 >= self.mips.len() {
            return a;
        }
        let b = at(l0 + 1);
        std::array::from_fn(|k| a[k] + (b[k] - a[k]) * f)
    }
}

/// The mip level of a footprint of `x` texels: `log₂ x` for `x ≥ 1` (0 below), linear in the
/// mantissa between powers of two (error below 0.09 level).
#[inline]
pub(crate) fn mip_level(x: f64) -> f64 {
    if !(x > 1.0) {
        return 0.0;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let mantissa = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    exponent as f64 + (mantissa - 1.0)
}

/// The photo-based ocean after preprocessing: the tileable main structure and its heights, the
/// basis sequence of small waves, its transition graph and morph meshes, the optional bed.
#[derive(Debug, Clone)]
pub struct PhotoOcean {
    params: OceanParams,
    seed: u64,
    main: Texture,
    main_height: HeightField,
    main_grad: (Grid, Grid),
    relighting: Relighting,
    sequence: BasisSequence,
    small_frames: Vec<SmallFrame>,
    graph: TransitionGraph,
    morphs: Vec<MeshCorrespondence>,
    bed: Option<Texture>,
}

impl PhotoOcean {
    /// Preprocesses two photos (and an optional bed photo) into the ocean (Lai & Wu §III.A–B, §IV
    /// "preprocessing stage").
    ///
    /// 1. The main-structure texture: tileable chessboard filling of `main`.
    /// 2. The small waves: a basis sequence of `frames` tileable frames of `small`, the
    ///    transition graph over them, and a morph mesh along every link.
    /// 3. Heights by Eq. 1 for the main texture and every basis frame (and every displayed
    ///    in-between, at render time).
    /// 4. The bed, if any: a tileable texture of `bed`.
    ///
    /// # Arguments
    /// - `small`, `main`, `bed`: the photos; each at least one patch in both directions; `small`
    ///   and `main` not uniform (Eq. 1).
    /// - `params`: parameters, validated here.
    /// - `seed`: seed of every random choice (synthesis and walk).
    /// - `progress`: called after every unit of work, from any thread.
    ///
    /// # Errors
    /// [`TextureError`] naming the bad parameter or input.
    pub fn new(
        small: &Texture,
        main: &Texture,
        bed: Option<&Texture>,
        params: &OceanParams,
        seed: u64,
        progress: &(dyn Fn(Progress) + Sync),
    ) -> Result<Self, TextureError> {
        params.validate()?;
        let sp = &params.synthesis;
        params.check_photo("small-wave image", small)?;
        params.check_photo("main-structure image", main)?;
        if let Some(b) = bed {
            sp.check_exemplar("bed image", b)?;
        }
        let cells = |size: usize| ((size / sp.step()) * (size / sp.step())) as u64;
        let n_links_max = (params.frames * (params.links_per_frame + 2)) as u64;
        let total = cells(params.main_size)
            + cells(params.small_size) * params.frames as u64
            + bed.map_or(0, |_| cells(params.bed_size))
            + n_links_max
            + params.frames as u64
            + 1;
        let done = AtomicU64::new(0);
        let tick = || {
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress(Progress { done: d.min(total), total });
        };

        // Main structure.
        let main_ex = Exemplar::new(main);
        let board = Chessboard::new(params.main_size, params.main_size, sp);
        let (main_tex, _) =
            chessboard_fill(&main_ex, &board, sp, FrameStreams { seed, purpose: Purpose::Main, frame: 0 }, None, &tick);
        let main_height =
            HeightField::from_texture(&main_tex, params.height_factor_main_m, "synthesised main-structure texture")?;
        tick();
        let main_grad = main_height.grid().central_gradients();
        let delta_height_max = (main_height.max() - main_height.mean()).max(main_height.mean() - main_height.min());

        // Small waves: basis sequence, heights, transitions, morph meshes.
        let small_ex = Exemplar::new(small);
        let sequence = basis_sequence(
            &small_ex,
            (params.small_size, params.small_size),
            params.frames,
            sp,
            params.min_shift,
            seed,
            &tick,
        );
        let small_frames: Vec<SmallFrame> = sequence
            .frames
            .par_iter()
            .map(|f| {
                let s = SmallFrame::new(f.clone(), params.height_factor_small_m);
                s.height();
                tick();
                s
            })
            .collect();
        let graph = TransitionGraph::from_frames(&sequence.frames, params.links_per_frame);
        let morphs: Vec<MeshCorrespondence> = graph
            .links()
            .par_iter()
            .map(|l| {
                let m =
                    MeshCorrespondence::estimate(&sequence.frames[l.from], &sequence.frames[l.to], params.mesh_spacing);
                tick();
                m
            })
            .collect();

        // Bed.
        let bed = bed.map(|b| {
            let ex = Exemplar::new(b);
            let board = Chessboard::new(params.bed_size, params.bed_size, sp);
            chessboard_fill(&ex, &board, sp, FrameStreams { seed, purpose: Purpose::Bed, frame: 0 }, None, &tick).0
        });
        progress(Progress { done: total, total });

        Ok(Self {
            params: *params,
            seed,
            main: main_tex,
            main_height,
            main_grad,
            relighting: Relighting { delta_height_max, rule: params.relight },
            sequence,
            small_frames,
            graph,
            morphs,
            bed,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &OceanParams {
        &self.params
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The tileable main-structure texture `M_c`.
    pub fn main_texture(&self) -> &Texture {
        &self.main
    }

    /// The main-structure height field `M_h` (Eq. 1).
    pub fn main_height(&self) -> &HeightField {
        &self.main_height
    }

    /// The relighting (Eq. 7–9) with `Δheight_max` of the main structure.
    pub fn relighting(&self) -> &Relighting {
        &self.relighting
    }

    /// The basis sequence of small-wave frames.
    pub fn sequence(&self) -> &BasisSequence {
        &self.sequence
    }

    /// The basis frames with their heights.
    pub fn basis_frames(&self) -> &[SmallFrame] {
        &self.small_frames
    }

    /// The transition graph.
    pub fn graph(&self) -> &TransitionGraph {
        &self.graph
    }

    /// The morph mesh of every link (same order as [`TransitionGraph::links`]).
    pub fn morphs(&self) -> &[MeshCorrespondence] {
        &self.morphs
    }

    /// The tileable bed texture, if a bed photo was given.
    pub fn bed(&self) -> Option<&Texture> {
        self.bed.as_ref()
    }

    /// The small-wave frame shown at walk position `at`: the basis frame itself at `alpha = 0`,
    /// else the morph along the link.
    pub fn small_frame_at(&self, at: &WalkPosition) -> SmallFrame {
        if at.alpha <= 0.0 {
            return self.small_frames[at.from].clone();
        }
        let f = &self.sequence.frames;
        let colour = self.morphs[at.link].morph(&f[at.from], &f[at.to], at.alpha);
        SmallFrame::new(colour, self.params.height_factor_small_m)
    }

    /// The composed surface of animation frame `n` (time `n/fps`): the walk's small-wave frame
    /// and the shifted main structure (Eq. 10–11).
    pub fn frame(&self, n: u64) -> OceanFrame<'_> {
        let at = walk_position(&self.graph, self.seed, self.params.morph_steps, n);
        let small = self.small_frame_at(&at);
        let t = n as f64 / self.params.fps;
        OceanFrame::new(self, small, at, n, t)
    }
}

/// The ocean surface of one animation frame (Lai & Wu Eq. 10–11 with the reference's (docs/equations.md) sign:
/// sampling at `x − t·v` moves a pattern along `v`). World `(x, z)` in metres maps to small-wave
/// texels `u = x/texel_m`, `v = z/texel_m` (x east along a row, z south down the columns).
#[derive(Debug, Clone)]
pub struct OceanFrame<'a> {
    ocean: &'a PhotoOcean,
    /// Animation frame number.
    pub index: u64,
    /// Time (s).
    pub time_s: f64,
    /// The walk's position.
    pub position: WalkPosition,
    /// The small-wave frame `P`.
    pub small: SmallFrame,
    small_offset: DVec2,
    main_offset: DVec2,
    inv_texel: f64,
    inv_main_texel: f64,
}

impl<'a> OceanFrame<'a> {
    fn new(ocean: &'a PhotoOcean, small: SmallFrame, position: WalkPosition, index: u64, time_s: f64) -> Self {
        let p = &ocean.params;
        let inv_texel = 1.0 / p.texel_m;
        let inv_main_texel = inv_texel / p.scale;
        let small_offset = -time_s * DVec2::from_array(p.small_velocity_m_s) * inv_texel;
        let main_offset = -time_s * DVec2::from_array(p.main_velocity_m_s) * inv_main_texel;
        Self { ocean, index, time_s, position, small, small_offset, main_offset, inv_texel, inv_main_texel }
    }

    /// The ocean this frame belongs to.
    pub fn ocean(&self) -> &'a PhotoOcean {
        self.ocean
    }

    /// Small-wave texel coordinates of the sea point `(x, z)` (m) at this frame's time,
    /// `(u, v) = ((x, z) − t s)/texel_m` (the shift of Eq. 10–11, sampled at `x − t s` so that the
    /// pattern moves along `s`).
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m, east and south).
    ///
    /// # Returns
    /// Texel coordinates (texels; the frame wraps).
    ///
    /// # References
    /// Lai & Wu Eq. 10–11; docs/equations.md §14 (the sign of the shift).
    #[inline]
    pub fn small_uv(&self, x: f64, z: f64) -> DVec2 {
        DVec2::new(x, z) * self.inv_texel + self.small_offset
    }

    /// Main-structure texel coordinates of `(x, z)`: `((x − t m)/texel_m)/scale`.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m, east and south).
    ///
    /// # Returns
    /// Texel coordinates of the main structure (texels; it wraps).
    ///
    /// # References
    /// Lai & Wu Eq. 3 (`M_h(x/scale, y/scale)`) and Eq. 10 (the shift `t m`).
    #[inline]
    pub fn main_uv(&self, x: f64, z: f64) -> DVec2 {
        DVec2::new(x, z) * self.inv_main_texel + self.main_offset
    }

    /// `Δheight = M_h(x/scale, y/scale) − mean(M_h)` at `(x, z)` (Eq. 8, shifted as Eq. 10), m.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// `Δheight` (m), in `[−Δheight_max, Δheight_max]`.
    ///
    /// # References
    /// Lai & Wu Eq. 8 and 10.
    #[inline]
    pub fn delta_height(&self, x: f64, z: f64) -> f64 {
        let m = self.main_uv(x, z);
        self.ocean.main_height.sample(m.x, m.y) - self.ocean.main_height.mean()
    }

    /// The composed height `S_h = M_h + P_h` (Eq. 3 and 10) relative to its mean, so that the mean
    /// sea level is `y = 0`:
    /// `S_h − S̄_h = (P_h(u, v) − P̄_h) + (M_h(u_m, v_m) − M̄_h)`.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// The height above the mean sea level (m).
    ///
    /// # References
    /// Lai & Wu Eq. 3 and 10.
    #[inline]
    pub fn height(&self, x: f64, z: f64) -> f64 {
        let s = self.small_uv(x, z);
        let m = self.main_uv(x, z);
        let (p, main) = (self.small.height(), &self.ocean.main_height);
        p.sample(s.x, s.y) - p.mean() + main.sample(m.x, m.y) - main.mean()
    }

    /// The gradient `(∂y/∂x, ∂y/∂z)` of the composed surface, from the central-difference
    /// gradients of both height fields interpolated bilinearly:
    /// `∇S_h = ∇P_h/texel_m + ∇M_h/(texel_m · scale)`, `∇` per texel.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// The slope vector (dimensionless).
    ///
    /// # References
    /// Lai & Wu Eq. 3 (the composed surface; the paper draws it flat and uses no normal — the bed
    /// refraction of Fig. 9 and the traced mode need one).
    #[inline]
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        let s = self.small_uv(x, z);
        let m = self.main_uv(x, z);
        let (gu, gv) = &self.ocean.main_grad;
        DVec2::new(self.small.grad_u().sample(s.x, s.y), self.small.grad_v().sample(s.x, s.y)) * self.inv_texel
            + DVec2::new(gu.sample(m.x, m.y), gv.sample(m.x, m.y)) * self.inv_main_texel
    }

    /// Unit upward normal of the composed surface at `(x, z)`, `n = (−∂y/∂x, 1, −∂y/∂z)/‖·‖`.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// The unit normal (`n_y > 0`).
    ///
    /// # References
    /// The normal of a height field `y = S_h(x, z)`; [`OceanFrame::gradient`].
    #[inline]
    pub fn normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// The colour before relighting, `S_c = P_c(x − t s)` (Eq. 2 shifted as Eq. 11; the reference's
    /// sign), levels.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// The bilinear colour of the small-wave frame (levels `[0, 255]`).
    ///
    /// # References
    /// Lai & Wu Eq. 2 and 11.
    #[inline]
    pub fn unrelit_colour(&self, x: f64, z: f64) -> [f32; 3] {
        let s = self.small_uv(x, z);
        self.small.colour.sample(s.x, s.y)
    }

    /// The relit colour `S_c = P_c(x − t s) + ΔI` (Eq. 11 with ΔI of Eq. 7–9 at the shifted
    /// `Δheight`), per channel.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    ///
    /// # Returns
    /// The colour (levels), every channel in `[0, 255]`.
    ///
    /// # References
    /// Lai & Wu Eq. 6–9 and 11; docs/equations.md §14 (errata of Eq. 11, range of Eq. 9).
    #[inline]
    pub fn colour(&self, x: f64, z: f64) -> [f32; 3] {
        self.ocean.relighting.apply(self.unrelit_colour(x, z), self.delta_height(x, z))
    }

    /// [`OceanFrame::colour`] filtered over a footprint of `footprint_m` metres (mip levels,
    /// trilinear), then relit.
    ///
    /// # Arguments
    /// - `x`, `z`: sea point (m).
    /// - `footprint_m`: the pixel's footprint on the sea (m), `≥ 0`; `0` is the bilinear colour.
    ///
    /// # Returns
    /// The colour (levels), every channel in `[0, 255]`.
    ///
    /// # References
    /// Lai & Wu Eq. 11; Williams L. 1983, "Pyramidal parametrics", SIGGRAPH (mip-mapping).
    #[inline]
    pub fn colour_filtered(&self, x: f64, z: f64, footprint_m: f64) -> [f32; 3] {
        let s = self.small_uv(x, z);
        let c = self.small.filtered(s.x, s.y, footprint_m * self.inv_texel);
        self.ocean.relighting.apply(c, self.delta_height(x, z))
    }

    /// Bed colour at `(x, z)` (levels), if the ocean has a bed.
    #[inline]
    pub fn bed_colour(&self, x: f64, z: f64) -> Option<[f32; 3]> {
        let b = self.ocean.bed.as_ref()?;
        let inv = 1.0 / self.ocean.params.bed_texel_m;
        Some(b.sample(x * inv, z * inv))
    }

    /// A top-down view of `width × height` texels of the composed colour with its origin at
    /// `(x0, z0)` and `texel_m` metres per texel: relit (Eq. 11) or not (Eq. 2).
    pub fn top_down(&self, x0: f64, z0: f64, texel_m: f64, width: usize, height: usize, relit: bool) -> Texture {
        Texture::from_fn(width, height, |i, j| {
            let (x, z) = (x0 + i as f64 * texel_m, z0 + j as f64 * texel_m);
            if relit { self.colour(x, z) } else { self.unrelit_colour(x, z) }
        })
    }
}
