//! A square tile (and a loop period) to which a wave set is snapped, so that the sea repeats
//! exactly: the lattice of baked, tileable maps.

use std::f64::consts::TAU;

use crate::{Trochoid, TrochoidSet, WaveError};

/// A square tile of side `L` and, optionally, a loop period `T`, to which a wave set is snapped
/// so that the sea repeats exactly in space (and in time).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TileLattice {
    tile_m: f64,
    loop_period_s: Option<f64>,
}

impl TileLattice {
    /// A tile of side `tile_m` (m, `(0, 10⁶]`) and an optional loop period (s, `(0, 10⁶]`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the parameter out of its range.
    pub fn new(tile_m: f64, loop_period_s: Option<f64>) -> Result<Self, WaveError> {
        let range = |name, v: f64| crate::error::check(name, v, v > 0.0 && v <= 1e6, "(0, 1e6]");
        Ok(Self {
            tile_m: range("tile_m", tile_m)?,
            loop_period_s: loop_period_s.map(|t| range("loop_s", t)).transpose()?,
        })
    }

    /// The tile's side (m).
    pub fn tile_m(&self) -> f64 {
        self.tile_m
    }

    /// The loop period (s), if any.
    pub fn loop_period_s(&self) -> Option<f64> {
        self.loop_period_s
    }

    /// FFT cascade tiles made whole fractions of the lattice's tile, `L/m_c` with
    /// `m_c = max(1, round(L/L_c), ⌈1.5 m_{c−1}⌉)`, so that every cascade repeats over it (the first
    /// cascade's tile is usually `L` itself) and each stays at least 1.5 times shorter than the one
    /// before.
    ///
    /// # Arguments
    /// - `tiles`: the cascades' tile sizes `L_c` (m, positive).
    ///
    /// # Returns
    /// The snapped tile sizes (m), one per cascade.
    pub fn commensurate_tiles(&self, tiles: &[f64]) -> Vec<f64> {
        // Whole fractions, each cascade at least 1.5 times shorter than the one before (as the
        // FFT sea asks of its cascades).
        let mut m_prev = 0.0f64;
        tiles
            .iter()
            .map(|&l| {
                let m = (self.tile_m / l).round().max(1.0).max((1.5 * m_prev).ceil());
                m_prev = m;
                self.tile_m / m
            })
            .collect()
    }

    /// `set` with every wave vector moved to the nearest point of the tile's lattice
    /// `(2π/L)(m, n)` (`m, n` integers, not both 0), so that the sea repeats every `L` along x
    /// and z. The frequency follows the deep-water dispersion, `ω′ = ω √(k′/k)`; with a loop
    /// period `T` it is then rounded to a multiple `(2π/T) max(1, round(ω′T/2π))` so that every
    /// wave repeats after `T`. Amplitudes, steepnesses and phases are kept.
    ///
    /// The change in the spectrum: each wave vector moves by at most `(π/L)√2`, a relative change
    /// of wavenumber up to `√2 λ/(2L)` (0.7 % for a wave of `λ = L/100`) and of direction up to
    /// `√2 λ/(2L)` rad; waves longer than about `2L` are pulled to the lattice's shortest
    /// vectors. Waves whose snapped vectors coincide are kept as separate waves (their heights
    /// add).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] if a snapped wave cannot be built (it cannot for a valid set).
    pub fn snap(&self, set: &TrochoidSet) -> Result<TrochoidSet, WaveError> {
        let dk = TAU / self.tile_m;
        let mut waves = Vec::with_capacity(set.len());
        for w in set.waves() {
            let kv = w.wavenumber() * w.direction_vector();
            let (mut m, n) = ((kv.x / dk).round(), (kv.y / dk).round());
            if m == 0.0 && n == 0.0 {
                // Longer than the tile: the shortest lattice vector nearest in direction.
                m = if kv.x.abs() >= kv.y.abs() { kv.x.signum() } else { 0.0 };
                let n1 = if m == 0.0 { kv.y.signum() } else { 0.0 };
                waves.push(snapped(w, m * dk, n1 * dk, self.loop_period_s)?);
                continue;
            }
            waves.push(snapped(w, m * dk, n * dk, self.loop_period_s)?);
        }
        Ok(TrochoidSet::new(waves))
    }
}

/// Wave `w` moved to the wave vector `(kx, kz)` (see [`TileLattice::snap`]).
fn snapped(w: &Trochoid, kx: f64, kz: f64, loop_period_s: Option<f64>) -> Result<Trochoid, WaveError> {
    let k = kx.hypot(kz);
    let mut omega = w.omega() * (k / w.wavenumber()).sqrt();
    if let Some(period) = loop_period_s {
        let base = TAU / period;
        omega = base * (omega / base).round().max(1.0);
    }
    Trochoid::new(w.amplitude(), k, kz.atan2(kx), omega, w.phase(), w.steepness())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ocean;
    use crate::sea::tests::set;

    /// A snapped set repeats over its tile (and its loop), to rounding.
    #[test]
    fn snapped_seas_tile_and_loop() {
        let lattice = TileLattice::new(96.0, Some(20.0)).unwrap();
        let set = lattice.snap(&set(12.0)).unwrap();
        let ocean = Ocean::trochoids(set);
        let (a, b) = (ocean.at_time(3.0), ocean.at_time(23.0));
        for (x, z) in [(1.0, 2.0), (40.0, -7.0)] {
            let h = a.sample(x, z).height;
            for (dx, dz) in [(96.0, 0.0), (0.0, -96.0), (192.0, 96.0)] {
                assert!((a.sample(x + dx, z + dz).height - h).abs() < 1e-5, "tile");
            }
            assert!((b.sample(x, z).height - h).abs() < 1e-5, "loop");
        }
        assert!(TileLattice::new(0.0, None).is_err() && TileLattice::new(10.0, Some(-1.0)).is_err());
    }
}
