//! A square tile (and a loop period) to which a wave set is snapped, so that the sea repeats
//! exactly: the lattice of baked, tileable maps.

use std::f64::consts::TAU;

use glam::DVec3;

use crate::looping::{LoopDistortion, looped_omega};
use crate::{Trochoid, TrochoidSet, WaveError};

/// A square tile of side `L` and, optionally, a loop period `T`, to which a wave set is snapped
/// so that the sea repeats exactly in space (and in time).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TileLattice {
    tile_m: f64,
    loop_period_s: Option<f64>,
}

impl TileLattice {
    /// A tile of side `tile_m` (m, `[10⁻³, 10⁶]`) and an optional loop period (s, `(0, 10⁶]`).
    ///
    /// A tile shorter than a millimetre would pull every wave onto lattice vectors whose slopes
    /// overflow (a wave of amplitude `A` snapped to `k = 2π/L`); no sea has waves that short.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the parameter out of its range.
    pub fn new(tile_m: f64, loop_period_s: Option<f64>) -> Result<Self, WaveError> {
        let tile = crate::error::check("tile_m", tile_m, (1e-3..=1e6).contains(&tile_m), "[1e-3, 1e6]")?;
        let period = |v: f64| crate::error::check("loop_s", v, v > 0.0 && v <= 1e6, "(0, 1e6]");
        Ok(Self { tile_m: tile, loop_period_s: loop_period_s.map(period).transpose()? })
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
    /// wave repeats after `T` ([`looped_omega`]: a wave of period `P` moves by up to `P/(2T)`;
    /// [`Self::loop_distortion`] says how far the set's waves move). Amplitudes, steepnesses and
    /// phases are kept.
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
        let waves = set.waves().iter().map(|w| {
            let (kx, kz, omega) = self.snapped_vector(w);
            let omega = self.loop_period_s.map_or(omega, |period| looped_omega(omega, period));
            Trochoid::new(w.amplitude(), kx.hypot(kz), kz.atan2(kx), omega, w.phase(), w.steepness())
        });
        Ok(TrochoidSet::new(waves.collect::<Result<Vec<_>, _>>()?))
    }

    /// How far the loop period moves the waves of `set` snapped to the tile ([`Self::snap`]) from
    /// their dispersion relation, each wave weighted by its linear height variance `Aᵢ²/2` (the spectrum's share it was fitted
    /// to)
    /// (brine-waves [`LoopDistortion`]); `None` without a loop period.
    ///
    /// # Arguments
    /// - `set`: the set before snapping (what [`Self::snap`] is given).
    ///
    /// # Returns
    /// The distortion of the frequencies (and phase speeds) by the loop's rounding alone: the
    /// tile's own move of each wave vector is not counted.
    pub fn loop_distortion(&self, set: &TrochoidSet) -> Option<LoopDistortion> {
        let period = self.loop_period_s?;
        let mut d = LoopDistortion::default();
        for w in set.waves() {
            let omega = self.snapped_vector(w).2;
            d.add(omega, looped_omega(omega, period), 0.5 * w.amplitude() * w.amplitude());
        }
        Some(d)
    }

    /// Wave `w` moved to the nearest point `(kx, kz)` of the lattice (rad m⁻¹), and its frequency
    /// there by the deep-water dispersion, `ω′ = ω √(k′/k)` (rad s⁻¹), before any loop.
    fn snapped_vector(&self, w: &Trochoid) -> (f64, f64, f64) {
        let dk = TAU / self.tile_m;
        let kv = w.wavenumber() * w.direction_vector();
        let (mut m, mut n) = ((kv.x / dk).round(), (kv.y / dk).round());
        if m == 0.0 && n == 0.0 {
            // Longer than the tile: the shortest lattice vector nearest in direction.
            m = if kv.x.abs() >= kv.y.abs() { kv.x.signum() } else { 0.0 };
            n = if m == 0.0 { kv.y.signum() } else { 0.0 };
        }
        let (kx, kz) = (m * dk, n * dk);
        (kx, kz, w.omega() * (kx.hypot(kz) / w.wavenumber()).sqrt())
    }
}

/// The waves a square grid can carry, and the slopes it cannot: what [`grid_band`] returns.
#[derive(Debug, Clone, PartialEq)]
pub struct GridBand {
    /// The waves faded by their grid weights (the waves of weight 0 left out).
    pub waves: TrochoidSet,
    /// Slope covariance `(⟨ζx²⟩, ⟨ζx ζz⟩, ⟨ζz²⟩)` (dimensionless, world axes) of what the fade
    /// removed: `Σ (⟨sᵢ²⟩ − ⟨s′ᵢ²⟩) (d̂x², d̂x d̂z, d̂z²)`, each wave's mean-square slope
    /// ([`Trochoid::mean_square_slope`]) before and after.
    pub lost_slope_covariance: DVec3,
    /// Number of waves faded (weight below 1), of which some may be left out.
    pub faded: usize,
}

/// The waves of `set` that a square grid of spacing `Δ` samples without aliasing: each wave of
/// wavelength `λ` is kept with the weight
///
/// ```text
/// w(λ) = smoothstep(0, 1, 2 (λ/(2Δ) − 1))
/// ```
///
/// (0 for `λ ≤ 2Δ`, 1 for `λ ≥ 3Δ`; the footprint fade of the renderer's primary rays, brine-core
/// `footprint_weight`, with a footprint of two grid spacings), its amplitude and its steepness
/// both multiplied by `w` (a smaller trochoid of the same wave vector, its particles on circles of
/// `w` times the radius). A wave of `λ ≤ 2Δ` has a wave-vector component at or beyond the grid's
/// Nyquist wavenumber `π/Δ`; sampled on the grid, it would read as another, longer wave (a
/// grid of `N` points over a tile `L` = `NΔ` sees the lattice vector `(2π/L)(m, n)` as
/// `(m mod N, n mod N)`). The fade leaves such waves out and eases the ones just above.
///
/// # Arguments
/// - `set`: the waves.
/// - `spacing_m`: grid spacing `Δ` (m), `> 0` and finite.
///
/// # Returns
/// The [`GridBand`]: the kept waves (the same set when every wave is at least `3Δ` long) and the
/// slopes the fade removed.
///
/// # References
/// Shannon 1949 (sampling); Bruneton, Neyret & Holzschuch 2010, §4 (what the geometry cannot
/// resolve goes to the shading: here, the lost covariance for the map's user).
pub fn grid_band(set: &TrochoidSet, spacing_m: f64) -> GridBand {
    debug_assert!(spacing_m > 0.0 && spacing_m.is_finite(), "spacing {spacing_m} m");
    let mut waves = Vec::with_capacity(set.len());
    let mut lost = DVec3::ZERO;
    let mut faded = 0;
    for w in set.waves() {
        let weight = brine_core::footprint::footprint_weight(w.wavelength(), 2.0 * spacing_m);
        if weight >= 1.0 {
            waves.push(*w);
            continue;
        }
        faded += 1;
        let kept = (weight > 0.0)
            .then(|| {
                Trochoid::new(
                    weight * w.amplitude(),
                    w.wavenumber(),
                    w.direction(),
                    w.omega(),
                    w.phase(),
                    weight * w.steepness(),
                )
            })
            .transpose()
            .ok()
            .flatten();
        let d = w.direction_vector();
        let removed = w.mean_square_slope() - kept.as_ref().map_or(0.0, Trochoid::mean_square_slope);
        lost += removed * DVec3::new(d.x * d.x, d.x * d.y, d.y * d.y);
        waves.extend(kept);
    }
    GridBand { waves: TrochoidSet::new(waves), lost_slope_covariance: lost, faded }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ocean;
    use crate::sea::tests::set;

    /// The loop's distortion is that of the snapped set's frequencies, the loop against none:
    /// the variance-weighted RMS of `ω_loop/ω − 1` recomputed from the two snaps.
    #[test]
    fn the_loop_distortion_is_the_snaps_frequency_change() {
        let set = set(12.0);
        let free = TileLattice::new(96.0, None).unwrap();
        assert!(free.loop_distortion(&set).is_none());
        for period in [2.0, 20.0, 600.0] {
            let looped = TileLattice::new(96.0, Some(period)).unwrap();
            let (a, b) = (free.snap(&set).unwrap(), looped.snap(&set).unwrap());
            let (mut w, mut sq) = (0.0, 0.0);
            for (x, y) in a.waves().iter().zip(b.waves()) {
                let v = 0.5 * x.amplitude() * x.amplitude();
                w += v;
                sq += v * (y.omega() / x.omega() - 1.0).powi(2);
            }
            let d = looped.loop_distortion(&set).unwrap();
            // The same sums in the same order.
            assert!(
                (d.rms() - (sq / w).sqrt()).abs() <= 1e-14,
                "T = {period}: {} against {}",
                d.rms(),
                (sq / w).sqrt()
            );
        }
    }

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
        assert!(TileLattice::new(1e-100, None).is_err() && TileLattice::new(1e-3, None).is_ok());
    }

    /// Sampled on a grid of `N` points over the tile, a snapped wave of `m` cycles along x reads
    /// as one of `m − N` cycles once `m > N/2`: the grid band leaves such waves out, keeps the
    /// waves of at least three spacings whole, and its lost covariance is what it took.
    #[test]
    fn the_grid_band_leaves_out_what_the_grid_would_alias() {
        let (tile, n) = (64.0, 32usize);
        let spacing = tile / n as f64;
        let dk = TAU / tile;
        // Waves of 24, 20, 17, 12 and 6 cycles over the tile along x: λ = 1.33, 1.6, 1.88, 2.67
        // and 5.33 grid spacings.
        let wave = |m: f64, a: f64| Trochoid::new(a, m * dk, 0.0, 1.0, 0.3, 0.2).unwrap();
        let set = TrochoidSet::new(vec![
            wave(24.0, 0.01),
            wave(20.0, 0.01),
            wave(17.0, 0.01),
            wave(12.0, 0.02),
            wave(6.0, 0.05),
        ]);
        // The aliasing itself: on the grid, 24 cycles are −8 cycles, a different wave.
        let alias = Ocean::trochoids(TrochoidSet::new(vec![wave(24.0, 0.01)])).at_time(0.0);
        let seen = Ocean::trochoids(TrochoidSet::new(vec![
            Trochoid::new(0.01, 8.0 * dk, std::f64::consts::PI, 1.0, 0.3, 0.2).unwrap(),
        ]))
        .at_time(0.0);
        for i in 0..n {
            let x = i as f64 * spacing;
            assert!((alias.height(x, 0.0) - seen.height(x, 0.0)).abs() < 1e-5, "texel {i}");
        }
        let band = grid_band(&set, spacing);
        // λ ≤ 2Δ (24, 20 and 17 cycles: 1.33Δ, 1.6Δ, 1.88Δ) out; 12 cycles (2.67Δ) faded; 6 whole.
        let kept: Vec<f64> = band.waves.waves().iter().map(|w| w.wavenumber() / dk).collect();
        assert_eq!(kept.len(), 2, "{kept:?}");
        assert!((kept[0] - 12.0).abs() < 1e-9 && (kept[1] - 6.0).abs() < 1e-9);
        assert_eq!(band.faded, 4);
        // 12 cycles: λ/(2Δ) = (64/12)/4 = 4/3, u = 2(4/3 − 1) = 2/3, w = u²(3 − 2u) = 20/27.
        let w12 = 20.0 / 27.0;
        assert!((band.waves.waves()[0].amplitude() - w12 * 0.02).abs() < 1e-15, "{:?}", band.waves.waves()[0]);
        assert!((band.waves.waves()[0].steepness() - w12 * 0.2).abs() < 1e-15);
        assert_eq!(band.waves.waves()[1], set.waves()[4]);
        // Lost: three whole waves and part of a fourth, all along x.
        let whole: f64 = set.waves()[..3].iter().map(Trochoid::mean_square_slope).sum();
        let part = set.waves()[3].mean_square_slope() - band.waves.waves()[0].mean_square_slope();
        assert!((band.lost_slope_covariance.x - (whole + part)).abs() < 1e-15 * whole);
        assert!(band.lost_slope_covariance.y.abs() < 1e-18 && band.lost_slope_covariance.z.abs() < 1e-18);
        // A grid fine enough for every wave keeps the set as it is.
        let fine = grid_band(&set, spacing / 4.0);
        assert_eq!(fine.waves, set);
        assert_eq!((fine.faded, fine.lost_slope_covariance), (0, DVec3::ZERO));
    }
}
