//! The endless walk over the transition links (Lai & Wu §III.D: "the pointer P will keep pointing
//! to the next appropriate node according to the current node and the associated similarity
//! probability").

use rand::Rng;

use crate::TransitionGraph;
use crate::rng::{Purpose, stream};

/// Where the walk is at one animation frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WalkPosition {
    /// Index of the link being played (into [`TransitionGraph::links`]).
    pub link: usize,
    /// Basis frame the link leaves.
    pub from: usize,
    /// Basis frame the link reaches.
    pub to: usize,
    /// Morph parameter along the link, `[0, 1)`: `0` is the frame `from` itself.
    pub alpha: f64,
}

/// The first `count` links of the seeded walk that starts at basis frame 0: from each frame `i`, a
/// link `i → j` drawn with probability `P(i → j)` ([`TransitionGraph::choose`] of a uniform draw
/// from a ChaCha8 stream of the seed), the next frame being `j` — a Markov chain on the basis
/// frames.
///
/// # Arguments
/// - `graph`: the transition graph.
/// - `seed`: the walk's seed; the same graph and seed give the same links.
/// - `count`: number of links, `≥ 0`.
///
/// # Returns
/// Indices into [`TransitionGraph::links`], in playing order; each link leaves the frame the
/// previous one reached.
///
/// # References
/// Lai & Wu §III.D ("the pointer P will keep pointing to the next appropriate node according to
/// the current node and the associated similarity probability"); Schödl et al. 2000 (random
/// play of video textures).
pub fn walk_links(graph: &TransitionGraph, seed: u64, count: usize) -> Vec<usize> {
    let mut rng = stream(seed, Purpose::Walk, 0, 0);
    let mut at = 0;
    let mut out = Vec::with_capacity(count);
    for _ in 0..count {
        let k = graph.choose(at, rng.random::<f64>());
        out.push(k);
        at = graph.links()[k].to;
    }
    out
}

/// The walk's position at animation frame `n`: each link is played over `morph_steps` frames,
/// `alpha = s/morph_steps` at step `s`, so the last in-between of a link is followed by the frame
/// it reaches, which is the first frame of the next link (the walk is seamless).
///
/// # Arguments
/// - `graph`: the transition graph.
/// - `seed`: the walk's seed.
/// - `morph_steps`: frames per link, `≥ 1`.
/// - `n`: animation frame number.
///
/// # Returns
/// The link, its ends and the morph parameter.
///
/// # References
/// Lai & Wu §III.A and §III.D (morphing interpolation along the links, the pointer's walk).
pub fn walk_position(graph: &TransitionGraph, seed: u64, morph_steps: usize, n: u64) -> WalkPosition {
    let m = morph_steps.max(1) as u64;
    let (k, s) = ((n / m) as usize, n % m);
    let links = walk_links(graph, seed, k + 1);
    let l = graph.links()[links[k]];
    WalkPosition { link: links[k], from: l.from, to: l.to, alpha: s as f64 / m as f64 }
}
