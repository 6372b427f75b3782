//! The basis sequence of the temporal texture synthesis (Lai & Wu §III.A, Fig. 2, their ref. [12]):
//! frame 0 by chessboard filling; every later frame patch by patch under the spatial constraint
//! (the O-shaped boundary zone) and the temporal one (similarity to the window at the same place
//! in the previous frame), toroidal.

use crate::error::check;
use crate::matching::Exemplar;
use crate::rng::{FrameStreams, Purpose};
use crate::synthesis::{Chessboard, Previous, Sources, chessboard_fill};
use crate::{SynthesisParams, Texture, TextureError};

/// A basis sequence: tileable frames that change a little from one to the next.
#[derive(Debug, Clone, PartialEq)]
pub struct BasisSequence {
    /// The frames, all of the same size.
    pub frames: Vec<Texture>,
    /// Where each frame's cells came from in the exemplar.
    pub sources: Vec<Sources>,
}

/// Synthesises a basis sequence of `frames` tileable frames of `width × height` texels.
///
/// Frame 0 is a chessboard filling. In frame `k ≥ 1`, a black cell takes a window among those
/// within `(1 + ε)` of the best temporal distance to the patch at the same place in the previous
/// frame (the exemplar window the cell took then), and a white cell first keeps the windows that match its O-shaped zone (the
/// `min_candidates` best and all within tolerance), then chooses among them by the temporal
/// distance. In both cases windows closer than `min_shift` texels (max norm) to the cell's
/// previous source are excluded, so that the frame changes (without it the previous patch itself
/// would always be the best temporal match and the sequence would freeze): a patch typically
/// drifts by a texel or two from frame to frame.
///
/// # Arguments
/// - `exemplar`: the small-wave image, at least one patch in both directions.
/// - `width`, `height`: frame size (texels), multiples of `2(p − 2 w_E)`.
/// - `frames`: number of frames, `[1, 4096]`.
/// - `params`: synthesis parameters.
/// - `min_shift`: smallest source displacement between consecutive frames (texels), `[0, 64]`.
/// - `seed`: random seed.
///
/// # Returns
/// The frames and the exemplar window of every cell of every frame; the same inputs and seed give
/// the same sequence.
///
/// # Errors
/// [`TextureError`] for a parameter out of range or an exemplar smaller than a patch.
///
/// # References
/// Lai & Wu 2007 (CAVW 18(4–5), basis sequence generation) as described in Lai & Wu, "Ocean
/// surface rendering using temporal texture synthesis", §III.A and Fig. 2.
pub fn synthesize_sequence(
    exemplar: &Texture,
    width: usize,
    height: usize,
    frames: usize,
    params: &SynthesisParams,
    min_shift: usize,
    seed: u64,
) -> Result<BasisSequence, TextureError> {
    params.validate()?;
    params.check_output("frame size", width, height)?;
    params.check_exemplar("exemplar", exemplar)?;
    check("frames", frames as f64, (1..=4096).contains(&frames), "[1, 4096]")?;
    check("min_shift", min_shift as f64, min_shift <= 64, "[0, 64] texels")?;
    let ex = Exemplar::new(exemplar);
    Ok(basis_sequence(&ex, (width, height), frames, params, min_shift, seed, &|| {}))
}

/// [`synthesize_sequence`] on a prepared exemplar, with a tick per cell; `size` is the frames'
/// `(width, height)` in texels.
pub(crate) fn basis_sequence(
    ex: &Exemplar,
    (width, height): (usize, usize),
    frames: usize,
    params: &SynthesisParams,
    min_shift: usize,
    seed: u64,
    tick: &(dyn Fn() + Sync),
) -> BasisSequence {
    let board = Chessboard::new(width, height, params);
    let mut out = BasisSequence { frames: Vec::with_capacity(frames), sources: Vec::with_capacity(frames) };
    for k in 0..frames {
        let previous = (k > 0).then(|| Previous { sources: &out.sources[k - 1], min_shift });
        let (frame, sources) = chessboard_fill(
            ex,
            &board,
            params,
            FrameStreams { seed, purpose: Purpose::Small, frame: k as u64 },
            previous,
            tick,
        );
        out.frames.push(frame);
        out.sources.push(sources);
    }
    out
}
