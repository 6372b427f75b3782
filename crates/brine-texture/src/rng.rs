//! Seeded random streams: one ChaCha8 stream per purpose, frame and cell, so that results do not
//! depend on the order in which parallel work is done.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// What a random stream is used for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Purpose {
    /// The tileable main-structure texture.
    Main = 1,
    /// The basis sequence of small-wave frames.
    Small = 2,
    /// The tileable bed texture.
    Bed = 3,
    /// The transition walk.
    Walk = 4,
}

/// The ChaCha8 stream of `seed` for `purpose`, frame `frame` and cell `cell`.
pub(crate) fn stream(seed: u64, purpose: Purpose, frame: u64, cell: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    debug_assert!(frame < 1 << 24 && cell < 1 << 24);
    rng.set_stream(((purpose as u64) << 48) | (frame << 24) | cell);
    rng
}

/// The streams of one synthesised frame: `seed`, `purpose` and `frame` of [`stream`].
#[derive(Debug, Clone, Copy)]
pub(crate) struct FrameStreams {
    /// The user's seed.
    pub seed: u64,
    /// What the frame is.
    pub purpose: Purpose,
    /// Frame number within the purpose.
    pub frame: u64,
}

impl FrameStreams {
    /// The stream of cell `cell`.
    pub fn cell(self, cell: u64) -> ChaCha8Rng {
        stream(self.seed, self.purpose, self.frame, cell)
    }
}
