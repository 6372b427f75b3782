//! Frame-to-frame similarity and the transition links of the temporal texture (Lai & Wu §III.A,
//! their ref. [12]): every frame links to its most similar frames and to its successor in the
//! basis sequence, with probabilities that favour similar frames; the graph is made strongly
//! connected so that every frame can reach every other.

use crate::Texture;

/// RMS difference of two frames of the same size over all texels and channels,
/// `D(a, b) = √(Σ_texels Σ_c (a_c − b_c)² / 3N)`: the frame similarity on which the transition
/// links and their probabilities are built.
///
/// # Arguments
/// - `a`, `b`: two frames of the same size (levels `[0, 255]`).
///
/// # Returns
/// `D` in levels, `[0, 255]`; `0` for identical frames.
///
/// # References
/// Lai & Wu §III.A ("the similarity between frames"); Schödl et al. 2000, "Video textures" (the
/// L2 distance between frames).
///
/// # Panics
/// If the sizes differ.
pub fn frame_distance(a: &Texture, b: &Texture) -> f64 {
    assert!(a.width() == b.width() && a.height() == b.height(), "frame_distance: sizes differ");
    let s: f64 = a
        .texels()
        .iter()
        .zip(b.texels())
        .map(|(x, y)| (0..3).map(|k| f64::from(x[k] - y[k]).powi(2)).sum::<f64>())
        .sum();
    (s / (3 * a.texels().len()) as f64).sqrt()
}

/// One transition link `from → to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Link {
    /// Frame left.
    pub from: usize,
    /// Frame reached.
    pub to: usize,
    /// Frame distance `D(from, to)` (levels).
    pub distance: f64,
    /// Probability of taking this link from `from`: `exp(−D/σ)` normalised over the links
    /// leaving `from`, `σ` the mean distance over all links.
    pub probability: f64,
}

/// The transition graph over the frames of a basis sequence.
#[derive(Debug, Clone, PartialEq)]
pub struct TransitionGraph {
    frames: usize,
    links: Vec<Link>,
    first: Vec<usize>,
}

impl TransitionGraph {
    /// Builds the links of `n` frames from their distance matrix `d` (row-major, `n × n`).
    ///
    /// Frame `i` links to its `links_per_frame` nearest frames `j ≠ i` (ties to the lower index)
    /// and to its successor `i + 1`; if some frames could then not come back to frame 0, the last
    /// frame gets a link to its nearest frame among those that can. The successor chain reaches
    /// every frame from frame 0, so the graph is strongly connected. Probabilities:
    /// `P(i → j) = exp(−D(i, j)/σ) / Σ_{links of i} exp(−D/σ)`, `σ` the mean link distance (the
    /// exponential weighting of Schödl et al. 2000's video textures).
    ///
    /// # Arguments
    /// - `n`: number of frames, `≥ 2`.
    /// - `d`: distances (levels), finite and `≥ 0`.
    /// - `links_per_frame`: `[1, n − 1]`.
    ///
    /// # References
    /// Lai & Wu 2007 (CAVW 18(4–5)) as described in Lai & Wu §III.A ("transition links with
    /// probabilities of similarity", "each frame may have the path to another frame"); Schödl A.,
    /// Szeliski R., Salesin D., Essa I. 2000, "Video textures", SIGGRAPH 489–498.
    ///
    /// # Returns
    /// The strongly connected graph, links grouped by the frame they leave, each frame's
    /// probabilities summing to 1.
    ///
    /// # Panics
    /// If `n < 2` or `d.len() != n²` (callers validate).
    pub fn new(n: usize, d: &[f64], links_per_frame: usize) -> Self {
        assert!(n >= 2 && d.len() == n * n, "TransitionGraph::new: {n} frames, {} distances", d.len());
        let k = links_per_frame.clamp(1, n - 1);
        let mut targets: Vec<Vec<usize>> = (0..n)
            .map(|i| {
                let mut js: Vec<usize> = (0..n).filter(|&j| j != i).collect();
                js.sort_by(|&a, &b| d[i * n + a].total_cmp(&d[i * n + b]).then(a.cmp(&b)));
                js.truncate(k);
                if i + 1 < n && !js.contains(&(i + 1)) {
                    js.push(i + 1);
                }
                js
            })
            .collect();
        // Frames that can come back to frame 0.
        let back = |targets: &Vec<Vec<usize>>| -> Vec<bool> {
            let mut reach = vec![false; n];
            reach[0] = true;
            let mut changed = true;
            while changed {
                changed = false;
                for i in 0..n {
                    if !reach[i] && targets[i].iter().any(|&j| reach[j]) {
                        reach[i] = true;
                        changed = true;
                    }
                }
            }
            reach
        };
        let reach = back(&targets);
        if reach.iter().any(|r| !r) {
            let last = n - 1;
            let j = (0..n)
                .filter(|&j| reach[j] && j != last)
                .min_by(|&a, &b| d[last * n + a].total_cmp(&d[last * n + b]).then(a.cmp(&b)))
                .expect("frame 0 can reach itself");
            targets[last].push(j);
        }
        debug_assert!(back(&targets).iter().all(|&r| r));
        let mut links = Vec::new();
        let mut first = Vec::with_capacity(n + 1);
        let all: Vec<f64> =
            targets.iter().enumerate().flat_map(|(i, js)| js.iter().map(move |&j| d[i * n + j])).collect();
        let sigma = all.iter().sum::<f64>() / all.len() as f64;
        for (i, js) in targets.iter().enumerate() {
            first.push(links.len());
            let weights: Vec<f64> =
                js.iter().map(|&j| if sigma > 0.0 { (-d[i * n + j] / sigma).exp() } else { 1.0 }).collect();
            let total: f64 = weights.iter().sum();
            for (&j, w) in js.iter().zip(&weights) {
                links.push(Link { from: i, to: j, distance: d[i * n + j], probability: w / total });
            }
        }
        first.push(links.len());
        Self { frames: n, links, first }
    }

    /// The graph of a basis sequence: [`TransitionGraph::new`] on the [`frame_distance`] matrix.
    ///
    /// # Panics
    /// If there are fewer than two frames or their sizes differ.
    pub fn from_frames(frames: &[Texture], links_per_frame: usize) -> Self {
        let n = frames.len();
        let mut d = vec![0.0; n * n];
        for i in 0..n {
            for j in i + 1..n {
                let v = frame_distance(&frames[i], &frames[j]);
                d[i * n + j] = v;
                d[j * n + i] = v;
            }
        }
        Self::new(n, &d, links_per_frame)
    }

    /// Number of frames.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// Every link, grouped by `from`.
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// Index range in [`TransitionGraph::links`] of the links leaving frame `i`.
    pub fn outgoing_range(&self, i: usize) -> std::ops::Range<usize> {
        self.first[i]..self.first[i + 1]
    }

    /// The links leaving frame `i`.
    pub fn outgoing(&self, i: usize) -> &[Link] {
        &self.links[self.outgoing_range(i)]
    }

    /// The link (index into [`TransitionGraph::links`]) taken from frame `i` for a uniform draw
    /// `u ∈ [0, 1)`: the first link `k` with `Σ_{l ≤ k} P(i → l) > u` (inverse-CDF sampling of the
    /// links' probabilities).
    ///
    /// # Arguments
    /// - `i`: the current frame, `[0, frames)`.
    /// - `u`: a uniform draw, `[0, 1)`.
    ///
    /// # Returns
    /// The index of the link; the last link of `i` if rounding leaves the cumulative sum below `u`.
    ///
    /// # References
    /// Lai & Wu §III.D (the pointer moves "according to the associated similarity probability").
    pub fn choose(&self, i: usize, u: f64) -> usize {
        let r = self.outgoing_range(i);
        let mut acc = 0.0;
        for k in r.clone() {
            acc += self.links[k].probability;
            if u < acc {
                return k;
            }
        }
        r.end - 1
    }

    /// Which frames can be reached from frame `i` by following links (`i` itself included).
    pub fn reachable_from(&self, i: usize) -> Vec<bool> {
        let mut seen = vec![false; self.frames];
        let mut stack = vec![i];
        seen[i] = true;
        while let Some(a) = stack.pop() {
            for l in self.outgoing(a) {
                if !seen[l.to] {
                    seen[l.to] = true;
                    stack.push(l.to);
                }
            }
        }
        seen
    }

    /// Whether every frame can reach every other.
    pub fn is_strongly_connected(&self) -> bool {
        (0..self.frames).all(|i| self.reachable_from(i).iter().all(|&r| r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Probabilities normalised by their own sum add up to 1 within a few ulps.
    const SUM_ROUNDING: f64 = 1e-12;

    #[test]
    fn two_clusters_are_joined() {
        // Frames 0–2 alike, frames 3–5 alike, the clusters far apart: nearest neighbours alone
        // would split the graph.
        let n = 6;
        let d: Vec<f64> = (0..n * n)
            .map(|k| {
                let (i, j) = (k / n, k % n);
                if i == j {
                    0.0
                } else if (i < 3) == (j < 3) {
                    1.0 + (i + j) as f64 * 0.01
                } else {
                    100.0
                }
            })
            .collect();
        let g = TransitionGraph::new(n, &d, 2);
        assert!(g.is_strongly_connected());
        for i in 0..n {
            let p: f64 = g.outgoing(i).iter().map(|l| l.probability).sum();
            assert!((p - 1.0).abs() < SUM_ROUNDING);
        }
    }

    #[test]
    fn similar_frames_are_more_likely() {
        let d = [0.0, 1.0, 5.0, 1.0, 0.0, 2.0, 5.0, 2.0, 0.0];
        let g = TransitionGraph::new(3, &d, 2);
        let out = g.outgoing(0);
        let p1 = out.iter().find(|l| l.to == 1).unwrap().probability;
        let p2 = out.iter().find(|l| l.to == 2).unwrap().probability;
        assert!(p1 > p2);
    }
}
