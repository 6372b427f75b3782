//! Patch-based "chessboard filling" synthesis of tileable textures (Lai & Wu, their ref. [12];
//! patch-based sampling after Liang et al. 2001), spatial and spatio-temporal.
//!
//! The output torus is cut into an even number of square cells of side `s = p − 2w_E` per
//! direction and coloured like a chessboard. Each cell receives a patch of side `p` centred on it,
//! which overlaps its four neighbours by `w_E`. Pass 1 fills the black cells; as no two black
//! cells share an edge, their patches only meet in the `2w_E × 2w_E` squares around shared
//! corners, where they are feathered. Pass 2 fills the white cells: every texel of a white
//! window's O-shaped boundary zone (the ring of width `2w_E` along its four sides) is then known,
//! and the patch is chosen among the exemplar's windows whose ring matches it, then feathered
//! across the ring. Window coordinates wrap around, so the result tiles without a seam.
//!
//! For a frame of a temporal sequence, the candidates are further ranked by their similarity to
//! the window at the same place in the previous frame (Lai & Wu §III.A, Fig. 2).

use rand::Rng;
use rayon::prelude::*;

use crate::error::check;
use crate::matching::{Exemplar, Mask};
use crate::rng::{FrameStreams, Purpose};
use crate::{Texture, TextureError};

/// Parameters of the patch-based synthesis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SynthesisParams {
    /// Patch side `p` (texels): a cell and its boundary zones, `[8, 512]`, `> 4 w_E`.
    pub patch_size: usize,
    /// Boundary-zone width `w_E` (texels), `≥ 1`: neighbouring patches overlap by `2 w_E`.
    pub boundary_width: usize,
    /// Relative tolerance `ε` of the candidate set `{q : d(q) ≤ (1 + ε) d_min}`, `[0, 10]`.
    pub tolerance: f64,
    /// Smallest number of spatial candidates handed to the temporal choice, `[1, 4096]`.
    pub min_candidates: usize,
}

impl Default for SynthesisParams {
    fn default() -> Self {
        Self { patch_size: 48, boundary_width: 8, tolerance: 0.1, min_candidates: 12 }
    }
}

impl SynthesisParams {
    /// The cell side `s = p − 2 w_E` (texels).
    pub fn step(&self) -> usize {
        self.patch_size - 2 * self.boundary_width
    }

    /// Checks every field.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] naming the first bad field.
    pub fn validate(&self) -> Result<(), TextureError> {
        let p = self.patch_size;
        check("patch_size", p as f64, (8..=512).contains(&p), "[8, 512] texels")?;
        check(
            "boundary_width",
            self.boundary_width as f64,
            self.boundary_width >= 1 && 4 * self.boundary_width < p,
            "[1, patch_size/4) texels",
        )?;
        check("tolerance", self.tolerance, (0.0..=10.0).contains(&self.tolerance), "[0, 10]")?;
        check("min_candidates", self.min_candidates as f64, (1..=4096).contains(&self.min_candidates), "[1, 4096]")?;
        Ok(())
    }

    /// Checks that an output of `width × height` texels is a whole even number of cells per side.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] if not.
    pub fn check_output(&self, name: &'static str, width: usize, height: usize) -> Result<(), TextureError> {
        let two_s = 2 * self.step();
        for v in [width, height] {
            check(
                name,
                v as f64,
                v >= two_s && v % two_s == 0 && v <= 8192,
                "a multiple of 2(patch − 2·boundary), ≤ 8192 texels",
            )?;
        }
        Ok(())
    }

    /// Checks that an exemplar is at least one patch in both directions.
    ///
    /// # Errors
    /// [`TextureError::TooSmall`] if not.
    pub fn check_exemplar(&self, what: &str, exemplar: &Texture) -> Result<(), TextureError> {
        if exemplar.width() < self.patch_size || exemplar.height() < self.patch_size {
            return Err(TextureError::TooSmall {
                what: what.to_owned(),
                width: exemplar.width(),
                height: exemplar.height(),
                patch: self.patch_size,
            });
        }
        Ok(())
    }
}

/// The chessboard of cells over a `width × height` torus.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Chessboard {
    pub(crate) width: usize,
    pub(crate) height: usize,
    pub(crate) step: usize,
    pub(crate) boundary: usize,
    pub(crate) patch: usize,
}

impl Chessboard {
    pub(crate) fn new(width: usize, height: usize, params: &SynthesisParams) -> Self {
        Self { width, height, step: params.step(), boundary: params.boundary_width, patch: params.patch_size }
    }

    /// Cells per row and per column.
    pub(crate) fn cells(&self) -> (usize, usize) {
        (self.width / self.step, self.height / self.step)
    }

    /// Cell indices (row-major) of one colour: black `(i + j)` even, white odd.
    pub(crate) fn cells_of(&self, black: bool) -> Vec<usize> {
        let (nx, ny) = self.cells();
        (0..nx * ny).filter(|c| ((c % nx + c / nx) % 2 == 0) == black).collect()
    }

    /// Top-left corner of a cell's window (may be negative: it wraps).
    pub(crate) fn window_origin(&self, cell: usize) -> (isize, isize) {
        let nx = self.cells().0;
        let (ci, cj) = (cell % nx, cell / nx);
        ((ci * self.step) as isize - self.boundary as isize, (cj * self.step) as isize - self.boundary as isize)
    }

    /// Feathering weight of texel `(i, j)` of a window: rises from near 0 at the window's edge to
    /// 1 at depth `2 w_E` (the inner edge of the O-shaped zone).
    #[inline]
    pub(crate) fn feather(&self, i: usize, j: usize) -> f32 {
        let p = self.patch;
        let d = i.min(j).min(p - 1 - i).min(p - 1 - j);
        ((d as f32 + 0.5) / (2 * self.boundary) as f32).min(1.0)
    }

    /// Wrapped texel index of texel `(i, j)` of the window at `origin`.
    #[inline]
    pub(crate) fn index(&self, origin: (isize, isize), i: usize, j: usize) -> usize {
        let x = (origin.0 + i as isize).rem_euclid(self.width as isize) as usize;
        let y = (origin.1 + j as isize).rem_euclid(self.height as isize) as usize;
        y * self.width + x
    }

    /// The `p × p` window of `texels` at a cell.
    pub(crate) fn window(&self, texels: &[[f32; 3]], cell: usize) -> Vec<[f32; 3]> {
        let o = self.window_origin(cell);
        let p = self.patch;
        (0..p).flat_map(|j| (0..p).map(move |i| (i, j))).map(|(i, j)| texels[self.index(o, i, j)]).collect()
    }
}

/// Where each cell's patch came from in the exemplar (window top-left corner).
pub type Sources = Vec<(usize, usize)>;

/// A uniformly random element of the candidate set `{q : d(q) ≤ (1 + ε) d_min}` over the
/// positions `allowed` (indices into `d`); `None` if `allowed` is empty.
fn choose_within_tolerance(
    d: &[f64],
    allowed: impl Iterator<Item = usize> + Clone,
    tolerance: f64,
    rng: &mut impl Rng,
) -> Option<usize> {
    let d_min = allowed.clone().map(|q| d[q]).fold(f64::INFINITY, f64::min);
    if !d_min.is_finite() {
        return None;
    }
    let limit = d_min * (1.0 + tolerance);
    let candidates: Vec<usize> = allowed.filter(|&q| d[q] <= limit).collect();
    Some(candidates[rng.random_range(0..candidates.len())])
}

/// Whether the source `q` (index into positions with `nx` columns) is at least `min_shift` from
/// `previous` in the max norm.
#[inline]
fn far_enough(q: usize, nx: usize, previous: (usize, usize), min_shift: usize) -> bool {
    let (qx, qy) = (q % nx, q / nx);
    qx.abs_diff(previous.0).max(qy.abs_diff(previous.1)) >= min_shift
}

/// The previous frame of a temporal sequence: the sources of its cells.
#[derive(Clone, Copy)]
pub(crate) struct Previous<'a> {
    pub(crate) sources: &'a [(usize, usize)],
    pub(crate) min_shift: usize,
}

/// The cell whose source [`pick_source`] picks: its index, its colour on the chessboard and the
/// canvas filled so far (empty for the black cells).
#[derive(Clone, Copy)]
struct Target<'a> {
    canvas: &'a [[f32; 3]],
    cell: usize,
    black: bool,
}

/// Picks the source of one cell.
///
/// - Black cell, no previous frame: uniformly random window.
/// - Black cell of a temporal frame: the candidates of the temporal distance to the patch placed
///   at the same place in the previous frame (the exemplar window at the cell's previous
///   source), excluding sources closer than `min_shift` to the previous one.
/// - White cell: the spatial candidates of the O-shaped zone; with a previous frame, the
///   `min_candidates` best (or all within tolerance) are re-ranked by the temporal distance.
fn pick_source(
    ex: &Exemplar,
    board: &Chessboard,
    target: Target<'_>,
    params: &SynthesisParams,
    previous: Option<Previous<'_>>,
    rng: &mut impl Rng,
) -> (usize, usize) {
    let Target { canvas, cell, black } = target;
    let p = board.patch;
    let (nx, ny) = ex.positions(p);
    let n = nx * ny;
    let at = |q: usize| (q % nx, q / nx);
    match (black, previous) {
        (true, None) => (rng.random_range(0..nx), rng.random_range(0..ny)),
        (true, Some(prev)) => {
            let q_prev = prev.sources[cell];
            let template = ex.patch(q_prev.0, q_prev.1, p);
            let d = ex.distances(&template, p, Mask::Full);
            let q = choose_within_tolerance(
                &d,
                (0..n).filter(|&q| far_enough(q, nx, q_prev, prev.min_shift)),
                params.tolerance,
                rng,
            )
            .or_else(|| choose_within_tolerance(&d, 0..n, params.tolerance, rng))
            .expect("at least one window");
            at(q)
        }
        (false, _) => {
            let template = board.window(canvas, cell);
            let d = ex.distances(&template, p, Mask::Ring(2 * board.boundary));
            let Some(prev) = previous else {
                return at(choose_within_tolerance(&d, 0..n, params.tolerance, rng).expect("at least one window"));
            };
            // The spatially matched set: the `min_candidates` best, and every window within tolerance.
            let q_prev = prev.sources[cell];
            let mut order: Vec<usize> = (0..n).filter(|&q| far_enough(q, nx, q_prev, prev.min_shift)).collect();
            if order.is_empty() {
                order = (0..n).collect();
            }
            order.sort_unstable_by(|&a, &b| d[a].total_cmp(&d[b]).then(a.cmp(&b)));
            let limit = d[order[0]] * (1.0 + params.tolerance);
            let keep = order.iter().take_while(|&&q| d[q] <= limit).count().max(params.min_candidates).min(order.len());
            let spatial = &order[..keep];
            // Temporal similarity to the patch at the same place in the previous frame.
            let before = ex.patch(q_prev.0, q_prev.1, p);
            let mut dt = vec![f64::INFINITY; n];
            for &q in spatial {
                let (qx, qy) = at(q);
                dt[q] = ex.distance_at(qx, qy, &before, p, Mask::Full);
            }
            at(choose_within_tolerance(&dt, spatial.iter().copied(), params.tolerance, rng).expect("non-empty"))
        }
    }
}

/// Records each pick's source in `sources` and calls `paste(k, a, t)` for every texel of its
/// window: the canvas index `k`, the feather weight `a` there and the exemplar's texel `t`.
fn paste_picks(
    ex: &Exemplar,
    board: &Chessboard,
    picks: &[(usize, (usize, usize))],
    sources: &mut [(usize, usize)],
    mut paste: impl FnMut(usize, f32, [f32; 3]),
) {
    let p = board.patch;
    for &(cell, (qx, qy)) in picks {
        sources[cell] = (qx, qy);
        let o = board.window_origin(cell);
        for j in 0..p {
            for i in 0..p {
                paste(board.index(o, i, j), board.feather(i, j), ex.texture().get(qx + i, qy + j));
            }
        }
    }
}

/// Synthesises one tileable frame by chessboard filling.
///
/// Sources are picked in parallel within each pass (each cell from its own random stream) and
/// pasted in cell order, so the result does not depend on the thread count.
pub(crate) fn chessboard_fill(
    ex: &Exemplar,
    board: &Chessboard,
    params: &SynthesisParams,
    streams: FrameStreams,
    previous: Option<Previous<'_>>,
    tick: &(dyn Fn() + Sync),
) -> (Texture, Sources) {
    let (w, h) = (board.width, board.height);
    let (ncx, ncy) = board.cells();
    let mut sources = vec![(0usize, 0usize); ncx * ncy];
    // The sources of the cells of one colour, each from its own random stream.
    let pick = |canvas: &[[f32; 3]], black: bool| -> Vec<(usize, (usize, usize))> {
        board
            .cells_of(black)
            .par_iter()
            .map(|&cell| {
                let mut rng = streams.cell(cell as u64);
                let q = pick_source(ex, board, Target { canvas, cell, black }, params, previous, &mut rng);
                tick();
                (cell, q)
            })
            .collect()
    };
    // Pass 1: black cells, feathered where their windows meet at corners.
    let picks = pick(&[], true);
    let mut acc = vec![[0.0f32; 3]; w * h];
    let mut weight = vec![0.0f32; w * h];
    paste_picks(ex, board, &picks, &mut sources, |k, f, t| {
        for c in 0..3 {
            acc[k][c] += f * t[c];
        }
        weight[k] += f;
    });
    let mut canvas: Vec<[f32; 3]> = acc
        .iter()
        .zip(&weight)
        .map(|(a, &wt)| if wt > 0.0 { a.map(|v| (v / wt).clamp(0.0, 255.0)) } else { [0.0; 3] })
        .collect();
    // Pass 2: white cells, matched on their O-shaped zone, feathered across it.
    let picks = pick(&canvas, false);
    paste_picks(ex, board, &picks, &mut sources, |k, a, t| {
        let old = canvas[k];
        canvas[k] = std::array::from_fn(|c| (old[c] + a * (t[c] - old[c])).clamp(0.0, 255.0));
    });
    (Texture::from_texels_unchecked(w, h, canvas), sources)
}

/// Synthesises a tileable texture of `width × height` texels from an exemplar by chessboard
/// filling (Lai & Wu §III.A, their ref. \[12\]): black cells random, white cells matched on their
/// O-shaped boundary zone, a random choice among the windows within `(1 + ε)` of the best
/// distance (Liang et al. 2001 choose at random below a threshold), windows wrapping around.
///
/// # Arguments
/// - `exemplar`: the input image, at least `patch_size` in both directions.
/// - `width`, `height`: output size (texels), each a multiple of `2(p − 2 w_E)`.
/// - `params`: patch size, boundary width, tolerance.
/// - `seed`: random seed; the same inputs and seed give the same texture.
///
/// # Returns
/// The tileable texture.
///
/// # Errors
/// [`TextureError`] if a parameter is out of range or the exemplar is smaller than a patch.
///
/// # References
/// Lai C.-H., Wu J.-L. 2007, "Temporal texture synthesis by patch-based sampling and morphing
/// interpolation", CAVW 18(4–5):415–428 (chessboard filling), as summarised in Lai & Wu, "Ocean
/// surface rendering using temporal texture synthesis", §III.A; Liang L., Liu C., Xu Y.-Q., Guo
/// B., Shum H.-Y. 2001, "Real-time texture synthesis by patch-based sampling", ACM TOG 20(3).
pub fn synthesize_tileable(
    exemplar: &Texture,
    width: usize,
    height: usize,
    params: &SynthesisParams,
    seed: u64,
) -> Result<Texture, TextureError> {
    params.validate()?;
    params.check_output("output size", width, height)?;
    params.check_exemplar("exemplar", exemplar)?;
    let ex = Exemplar::new(exemplar);
    let board = Chessboard::new(width, height, params);
    Ok(chessboard_fill(&ex, &board, params, FrameStreams { seed, purpose: Purpose::Main, frame: 0 }, None, &|| {}).0)
}

/// Measures how well a texture tiles: the mean absolute channel difference between texels that
/// are neighbours across the wrap (last column/first column, last row/first row) and the same
/// mean over all neighbouring pairs inside the texture,
/// `d̄ = (1/N) Σ_pairs (1/3) Σ_c |t_c(p) − t_c(q)|`.
///
/// # Arguments
/// - `texture`: any texture (levels).
///
/// # Returns
/// `(across the wrap, inside)`, in channel levels `[0, 255]`. A seamless tile has similar values
/// (the wrap of a chessboard filling is a feathered cell border, smoother than the average: see
/// [`wrap_border_test`] for a test with a stated significance).
///
/// # References
/// The seam measure ("the mean colour difference across the wrap equals that inside the
/// texture"); Lai & Wu §III.A (toroidal synthesis).
pub fn seam_differences(texture: &Texture) -> (f64, f64) {
    let (w, h) = (texture.width(), texture.height());
    let diff = |a: [f32; 3], b: [f32; 3]| -> f64 { (0..3).map(|k| f64::from((a[k] - b[k]).abs())).sum::<f64>() / 3.0 };
    let (mut wrap, mut nw) = (0.0, 0usize);
    let (mut inside, mut ni) = (0.0, 0usize);
    for j in 0..h {
        for i in 0..w {
            let t = texture.get(i, j);
            let right = texture.get((i + 1) % w, j);
            let down = texture.get(i, (j + 1) % h);
            if i + 1 == w {
                wrap += diff(t, right);
                nw += 1;
            } else {
                inside += diff(t, right);
                ni += 1;
            }
            if j + 1 == h {
                wrap += diff(t, down);
                nw += 1;
            } else {
                inside += diff(t, down);
                ni += 1;
            }
        }
    }
    (wrap / nw as f64, inside / ni as f64)
}

/// The mean absolute channel difference across the interior cell borders of a chessboard-filled
/// texture: between texels `k·step − 1` and `k·step` for `k = 1, 2, …` in both directions. The
/// wrap of a seamless tile is one more such border (see [`seam_differences`]).
///
/// # Arguments
/// - `texture`: a chessboard-filled texture (levels).
/// - `step`: the cell side `p − 2w_E` (texels), `≥ 1`.
///
/// # Returns
/// The mean difference (levels), `0` if the texture has no interior border.
///
/// # References
/// The cells of chessboard filling (Lai & Wu 2007, as summarised in Lai & Wu §III.A).
pub fn border_differences(texture: &Texture, step: usize) -> f64 {
    let (w, h) = (texture.width(), texture.height());
    let diff = |a: [f32; 3], b: [f32; 3]| -> f64 { (0..3).map(|k| f64::from((a[k] - b[k]).abs())).sum::<f64>() / 3.0 };
    let (mut sum, mut n) = (0.0, 0usize);
    for x in (step..w).step_by(step.max(1)) {
        for j in 0..h {
            sum += diff(texture.get(x - 1, j), texture.get(x, j));
            n += 1;
        }
    }
    for y in (step..h).step_by(step.max(1)) {
        for i in 0..w {
            sum += diff(texture.get(i, y - 1), texture.get(i, y));
            n += 1;
        }
    }
    if n == 0 { 0.0 } else { sum / n as f64 }
}

/// The wrap of a chessboard-filled tile compared with its interior cell borders, segment by
/// segment (see [`wrap_border_test`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WrapBorderTest {
    /// Mean absolute channel difference across the wrap (levels).
    pub wrap: f64,
    /// Mean absolute channel difference across the interior cell borders (levels).
    pub borders: f64,
    /// Standard deviation of the interior segments' means (levels).
    pub segment_sd: f64,
    /// Standard error of `wrap − borders`, `s √(1/n_w + 1/n_b)` (levels).
    pub standard_error: f64,
    /// `z = (wrap − borders)/standard_error` (dimensionless).
    pub z: f64,
    /// The Mann–Whitney rank-sum statistic of the wrap segments among all segments, standardised:
    /// `(U − n_w n_b/2)/√(n_w n_b (n_w + n_b + 1)/12)` (dimensionless).
    pub rank_z: f64,
    /// Segments across the wrap `n_w` and across the interior borders `n_b`.
    pub segments: (usize, usize),
}

/// Tests whether the wrap of a tile made by chessboard filling with cells of side `step` is one
/// more cell border. Every border line (vertical lines `x = k·step`, horizontal `y = k·step`,
/// `k = 0` the wrap between the last and the first texel) is cut into cell-long segments, each
/// separating two cells; the segment's value is the mean absolute channel difference across it.
/// Windows wrap and every cell's patch is drawn from its own random stream, so the construction is
/// invariant under translations by whole cells: the wrap segments are draws from the same
/// population as the interior ones. With `m_w`, `m_b` the means of the `n_w` wrap and `n_b`
/// interior segments and `s` the standard deviation of the interior ones,
///
/// `z = (m_w − m_b) / (s √(1/n_w + 1/n_b))`
///
/// is approximately standard normal for a seamless tile if the segment values are near Gaussian,
/// and large for a texture whose wrap is a seam. Sun glitter makes them heavy-tailed, so the
/// distribution-free form is also given: the Mann–Whitney count `U` of (wrap, interior) pairs in
/// which the wrap segment is the larger (ties ½), standardised,
///
/// `z_U = (U − n_w n_b/2) / √(n_w n_b (n_w + n_b + 1)/12)`,
///
/// standard normal under exchangeable segments whatever their distribution; its largest possible
/// value (every wrap segment above every interior one) is `√(3 n_w n_b/(n_w + n_b + 1))`.
///
/// # Arguments
/// - `texture`: the tile, each side a whole number (`≥ 3`) of cells.
/// - `step`: the cell side `p − 2w_E` (texels), `≥ 1`.
///
/// # Returns
/// The comparison; `None` if a side is not a whole number of at least 3 cells (fewer than 2
/// interior borders per direction leave no spread to compare with).
///
/// # References
/// Two-sample comparison of means with the reference population's variance (e.g. Wasserman 2004,
/// *All of Statistics*, §10.1, the Wald test); Mann H.B., Whitney D.R. 1947, "On a test of
/// whether one of two random variables is stochastically larger than the other", Ann. Math.
/// Statist. 18(1):50–60 (the rank-sum test and its normal approximation); the cell borders of
/// chessboard filling as in [`border_differences`].
pub fn wrap_border_test(texture: &Texture, step: usize) -> Option<WrapBorderTest> {
    let (w, h) = (texture.width(), texture.height());
    if step == 0 || !w.is_multiple_of(step) || !h.is_multiple_of(step) || w / step < 3 || h / step < 3 {
        return None;
    }
    let d = |a: [f32; 3], b: [f32; 3]| (0..3).map(|k| f64::from((a[k] - b[k]).abs())).sum::<f64>() / 3.0;
    let (mut wrap, mut inner) = (Vec::new(), Vec::new());
    // Vertical lines x = k·step (texels x − 1 | x), segments of rows [c·step, (c + 1)·step).
    for k in 0..w / step {
        let x = k * step;
        for c in 0..h / step {
            let m =
                (c * step..(c + 1) * step).map(|j| d(texture.get((x + w - 1) % w, j), texture.get(x, j))).sum::<f64>()
                    / step as f64;
            if k == 0 { wrap.push(m) } else { inner.push(m) }
        }
    }
    for k in 0..h / step {
        let y = k * step;
        for c in 0..w / step {
            let m =
                (c * step..(c + 1) * step).map(|i| d(texture.get(i, (y + h - 1) % h), texture.get(i, y))).sum::<f64>()
                    / step as f64;
            if k == 0 { wrap.push(m) } else { inner.push(m) }
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (m_w, m_b) = (mean(&wrap), mean(&inner));
    let (n_w, n_b) = (wrap.len(), inner.len());
    let sd = (inner.iter().map(|v| (v - m_b).powi(2)).sum::<f64>() / (n_b - 1) as f64).sqrt();
    let se = sd * (1.0 / n_w as f64 + 1.0 / n_b as f64).sqrt();
    let gap = m_w - m_b;
    let z = if se > 0.0 {
        gap / se
    } else if gap == 0.0 {
        0.0
    } else {
        gap.signum() * f64::INFINITY
    };
    // U = number of (wrap, interior) pairs in which the wrap segment is larger (ties count ½).
    let u: f64 = wrap
        .iter()
        .map(|&a| {
            inner
                .iter()
                .map(|&b| match a.total_cmp(&b) {
                    std::cmp::Ordering::Greater => 1.0,
                    std::cmp::Ordering::Equal => 0.5,
                    std::cmp::Ordering::Less => 0.0,
                })
                .sum::<f64>()
        })
        .sum();
    let (nw, nb) = (n_w as f64, n_b as f64);
    let rank_z = (u - 0.5 * nw * nb) / (nw * nb * (nw + nb + 1.0) / 12.0).sqrt();
    Some(WrapBorderTest {
        wrap: m_w,
        borders: m_b,
        segment_sd: sd,
        standard_error: se,
        z,
        rank_z,
        segments: (n_w, n_b),
    })
}

/// How far a texture's wrap lines stand out from its other lines: for the vertical lines `x`
/// (texels `x − 1` and `x`, line 0 the wrap) and likewise the horizontal ones, the mean absolute
/// channel difference across each line; returns the larger over the two directions of
/// `|wrap − mean(interior)|/sd(interior)`. A seamless tile scores like any of its lines (below
/// about 3); a photo's wrap is typically far beyond.
///
/// `z = |d̄_wrap − mean(d̄_interior)| / sd(d̄_interior)`, `d̄` the mean difference across a line.
///
/// # Arguments
/// - `texture`: any texture (levels).
///
/// # Returns
/// The z-score (dimensionless); `0` for textures narrower than 3 texels.
///
/// # References
/// The standard score of one observation against a sample (e.g. Wasserman 2004, *All of
/// Statistics*, §3); 3 σ is a 0.3 % two-sided false-alarm rate for Gaussian line means.
pub fn seam_z_score(texture: &Texture) -> f64 {
    let (w, h) = (texture.width(), texture.height());
    if w < 3 || h < 3 {
        return 0.0;
    }
    let d = |a: [f32; 3], b: [f32; 3]| (0..3).map(|k| f64::from((a[k] - b[k]).abs())).sum::<f64>() / 3.0;
    let vertical: Vec<f64> = (0..w)
        .map(|x| (0..h).map(|j| d(texture.get((x + w - 1) % w, j), texture.get(x, j))).sum::<f64>() / h as f64)
        .collect();
    let horizontal: Vec<f64> = (0..h)
        .map(|y| (0..w).map(|i| d(texture.get(i, (y + h - 1) % h), texture.get(i, y))).sum::<f64>() / w as f64)
        .collect();
    [vertical, horizontal]
        .iter()
        .map(|lines| {
            let inner = &lines[1..];
            let n = inner.len() as f64;
            let mean = inner.iter().sum::<f64>() / n;
            let sd = (inner.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
            let gap = (lines[0] - mean).abs();
            // Identical lines (sd = 0): no seam if the wrap line is identical too.
            if sd > 0.0 {
                gap / sd
            } else if gap > 0.0 {
                f64::INFINITY
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `f64` arithmetic on small integers and one square root: a few ulps.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn wrap_border_test_by_hand() {
        // 6 × 6 texels in cells of 2: every column holds one level a_i, so horizontal lines
        // differ by 0, and the vertical lines x = 0 (the wrap, |a₅ − a₀| = 9), 2 (|a₁ − a₂| = 3)
        // and 4 (|a₃ − a₄| = 3) each give 3 equal segments. Wrap: three 9s and three 0s, mean
        // 4.5; interior: six 3s and six 0s, mean 1.5, s² = 12 · 1.5²/11 = 27/11;
        // SE = s √(1/6 + 1/12) = s/2, z = 3/(s/2) = 6 √(11/27).
        let a = [0.0, 0.0, 3.0, 3.0, 6.0, 9.0];
        let t = Texture::from_fn(6, 6, |i, _| [a[i]; 3]);
        let r = wrap_border_test(&t, 2).unwrap();
        assert_eq!(r.segments, (6, 12));
        assert!((r.wrap - 4.5).abs() < ROUNDING && (r.borders - 1.5).abs() < ROUNDING);
        assert!((r.segment_sd - (27.0f64 / 11.0).sqrt()).abs() < ROUNDING);
        assert!((r.z - 6.0 * (11.0f64 / 27.0).sqrt()).abs() < ROUNDING);
        assert!((r.borders - border_differences(&t, 2)).abs() < ROUNDING);
        // U: each 9 beats the six 3s and six 0s (12 each), each wrap 0 ties the six 0s (3 each):
        // U = 3·12 + 3·3 = 45 of 6·12 = 72; z_U = (45 − 36)/√(72 · 19/12) = 9/√114.
        assert!((r.rank_z - 9.0 / 114.0f64.sqrt()).abs() < ROUNDING);
        // Not a whole number of at least 3 cells: no test.
        assert!(wrap_border_test(&t, 4).is_none() && wrap_border_test(&t, 3).is_none());
        assert!(wrap_border_test(&Texture::from_fn(4, 6, |_, _| [1.0; 3]), 2).is_none());
        // A uniform texture: no difference anywhere, z = 0.
        let flat = wrap_border_test(&Texture::from_fn(6, 6, |_, _| [7.0; 3]), 2).unwrap();
        assert!(flat.z.abs() < ROUNDING && flat.rank_z.abs() < ROUNDING, "{flat:?}");
    }
}
