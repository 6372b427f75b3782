//! A loop period: every frequency rounded so that the sea repeats in time, and how far that moves
//! the waves from their dispersion relation.

use std::f64::consts::TAU;

/// The frequency a wave takes so that it repeats after the loop period `T`:
/// `ω′ = (2π/T) max(1, round(ωT/2π))`, the multiple of `2π/T` nearest `ω`, at least one turn per
/// loop.
///
/// The rounding moves `ω` by at most `π/T`, a relative change `|ω′/ω − 1| ≤ P/(2T)` for a wave of
/// period `P = 2π/ω ≤ 2T`; a wave of period above `2T` is sped up to one turn per loop,
/// `ω′/ω = P/T`. The wavenumber is kept, so the phase speed `ω/k` moves by the same ratio.
///
/// # Arguments
/// - `omega`: the wave's angular frequency `ω` (rad s⁻¹), `> 0`.
/// - `period_s`: the loop period `T` (s), `> 0`.
///
/// # Returns
/// `ω′` (rad s⁻¹), a whole multiple (at least 1) of `2π/T`.
///
/// # References
/// Tessendorf 2001, "Simulating Ocean Water", the dispersion relation's "repeat time" (§4.2:
/// `ω` quantised to multiples of `ω₀ = 2π/T`).
pub fn looped_omega(omega: f64, period_s: f64) -> f64 {
    debug_assert!(omega > 0.0 && period_s > 0.0, "ω = {omega}, T = {period_s}");
    let base = TAU / period_s;
    base * libm::round(omega / base).max(1.0)
}

/// Relative change of frequency beyond which [`LoopDistortion::share_moved`] counts a wave as
/// moved: 5 %, about what an eye tells apart in the speed of a crest.
pub const LOOP_TOLERANCE: f64 = 0.05;

/// How far a loop period moves a sea's waves from their dispersion relation: the relative change
/// `εᵢ = ω′ᵢ/ωᵢ − 1` of each wave's frequency (and phase speed) by [`looped_omega`], weighted by
/// the height variance the wave holds (its spectral share: `Aᵢ²/2` of a fitted wave, a mode's
/// cell energy for the FFT sea).
///
/// A loop of period `T` keeps a wave of period `P` within `P/(2T)`: ten times the longest period
/// that holds much of the sea's height keeps it within 5 % ([`Self::suggested_period_s`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LoopDistortion {
    /// `Σ wᵢ` (m²): the height variance of the waves counted.
    weight: f64,
    /// `Σ wᵢ εᵢ²` (m²).
    squares: f64,
    /// `Σ wᵢ` over the waves with `|εᵢ| > LOOP_TOLERANCE` (m²).
    moved: f64,
    /// `Σ wᵢ` by period, in bins [`PERIOD_BIN_RATIO`] wide from [`PERIOD_BINS_FROM_S`] (the
    /// first bin also holds every shorter period, the last every longer one), for the suggested
    /// period.
    by_period: Vec<f64>,
}

/// The shortest period binned apart (s): a capillary wave of 1 mm has 3 ms.
const PERIOD_BINS_FROM_S: f64 = 1e-3;
/// The ratio of two bins' periods: the suggested period is rounded up by at most 2 %.
const PERIOD_BIN_RATIO: f64 = 1.02;
/// Bins from 1 ms to about 10⁵ s (`1.02⁹²⁹ ≈ 10⁸`); a wave of a 10⁶ m tile has a period of
/// 800 s, so the last bin, which would also hold longer periods, holds none.
const PERIOD_BIN_COUNT: usize = 930;

impl Default for LoopDistortion {
    fn default() -> Self {
        Self { weight: 0.0, squares: 0.0, moved: 0.0, by_period: vec![0.0; PERIOD_BIN_COUNT] }
    }
}

impl LoopDistortion {
    /// Counts a wave of frequency `omega` (rad s⁻¹, `> 0`), looped to `looped`
    /// (rad s⁻¹, [`looped_omega`]), holding the height variance `variance` (m², `≥ 0`).
    pub fn add(&mut self, omega: f64, looped: f64, variance: f64) {
        debug_assert!(omega > 0.0 && variance >= 0.0);
        let e = looped / omega - 1.0;
        self.weight += variance;
        self.squares += variance * e * e;
        if e.abs() > LOOP_TOLERANCE {
            self.moved += variance;
        }
        let bin = ((TAU / omega / PERIOD_BINS_FROM_S).ln() / PERIOD_BIN_RATIO.ln()).ceil();
        self.by_period[(bin.max(0.0) as usize).min(PERIOD_BIN_COUNT - 1)] += variance;
    }

    /// Adds the waves counted by `other`.
    pub fn merge(&mut self, other: &Self) {
        self.weight += other.weight;
        self.squares += other.squares;
        self.moved += other.moved;
        for (a, b) in self.by_period.iter_mut().zip(&other.by_period) {
            *a += b;
        }
    }

    /// The variance-weighted root-mean-square relative change of frequency,
    /// `√(Σ wᵢεᵢ² / Σ wᵢ)` (dimensionless; 0 for no wave).
    pub fn rms(&self) -> f64 {
        if self.weight > 0.0 { (self.squares / self.weight).sqrt() } else { 0.0 }
    }

    /// The share of the height variance in waves whose frequency moved by more than
    /// [`LOOP_TOLERANCE`] (`[0, 1]`).
    pub fn share_moved(&self) -> f64 {
        if self.weight > 0.0 { self.moved / self.weight } else { 0.0 }
    }

    /// A loop period that keeps the waves holding 95 % of the height variance within
    /// [`LOOP_TOLERANCE`]: `P₉₅/(2 · 0.05) = 10 P₉₅`, with `P₉₅` the period below which 95 % of
    /// the variance lies, rounded up by at most 2 % (s; 0 for no wave).
    pub fn suggested_period_s(&self) -> f64 {
        if !(self.weight > 0.0) {
            return 0.0;
        }
        let mut below = 0.0;
        for (i, &w) in self.by_period.iter().enumerate() {
            below += w;
            if below >= 0.95 * self.weight {
                // The bin's upper edge.
                return PERIOD_BINS_FROM_S * PERIOD_BIN_RATIO.powi(i as i32) / (2.0 * LOOP_TOLERANCE);
            }
        }
        // Not reached (the bins hold the whole weight, to rounding): the last bin's edge.
        PERIOD_BINS_FROM_S * PERIOD_BIN_RATIO.powi(PERIOD_BIN_COUNT as i32 - 1) / (2.0 * LOOP_TOLERANCE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A wave 10 % above a multiple of `2π/T` comes back to it; one longer than `2T` is sped up to
    /// one turn per loop.
    #[test]
    fn looping_rounds_to_the_nearest_turn_count() {
        let t = 10.0;
        let base = TAU / t;
        // The same products, so the same bits.
        let bits = |x: f64| x.to_bits();
        assert_eq!(bits(looped_omega(3.1 * base, t)), bits(3.0 * base));
        assert_eq!(bits(looped_omega(2.6 * base, t)), bits(3.0 * base));
        assert_eq!(bits(looped_omega(0.2 * base, t)), bits(base));
        let mut d = LoopDistortion::default();
        d.add(1.1 * base, base, 1.0);
        assert!((d.rms() - (1.0 / 1.1 - 1.0f64).abs()).abs() < 1e-15);
        assert_eq!(d.share_moved().to_bits(), 1f64.to_bits());
        // Its period is 10/1.1 s: ten times that keeps it within 5 % (up to the bins' 2 %).
        let p = d.suggested_period_s();
        assert!((100.0 / 1.1..=1.02 * 100.0 / 1.1).contains(&p), "{p}");
    }

    /// The weights: a wave that did not move dilutes the RMS by its share of the variance, and the
    /// suggested period is set by the waves holding 95 % of it.
    #[test]
    fn the_distortion_is_weighted_by_variance() {
        let mut d = LoopDistortion::default();
        d.add(1.0, 1.0, 3.0);
        d.add(1.0, 1.2, 1.0);
        assert!((d.rms() - (0.04f64 / 4.0).sqrt()).abs() < 1e-15);
        assert!((d.share_moved() - 0.25).abs() < 1e-15);
        let p = d.suggested_period_s();
        assert!((10.0 * TAU..=1.02 * 10.0 * TAU).contains(&p), "{p}");
        let mut e = LoopDistortion::default();
        e.add(1.0, 1.2, 1.0);
        e.merge(&{
            let mut f = LoopDistortion::default();
            f.add(1.0, 1.0, 3.0);
            f
        });
        assert_eq!(e, d);
        assert_eq!(LoopDistortion::default().rms().to_bits(), 0f64.to_bits());
        assert_eq!(LoopDistortion::default().suggested_period_s().to_bits(), 0f64.to_bits());
    }

    proptest! {
        /// The looped wave repeats after `T` (a whole number of turns), and moves by at most
        /// `P/(2T)` when its period `P` is at most `2T`, else by `P/T − 1` exactly.
        #[test]
        fn looped_waves_repeat_and_stay_within_the_rounding(omega in 1e-3f64..1e3, period in 1e-2f64..1e4) {
            let looped = looped_omega(omega, period);
            let turns = looped * period / TAU;
            prop_assert!((turns - turns.round()).abs() < 1e-9 * turns.max(1.0) && turns.round() >= 1.0);
            let p = TAU / omega;
            let e = looped / omega - 1.0;
            // Rounding of the quotient and the products: a few ulps of the ratio.
            const ROUNDING: f64 = 1e-12;
            if p <= 2.0 * period {
                prop_assert!(e.abs() <= p / (2.0 * period) + ROUNDING, "ε = {e}, P/(2T) = {}", p / (2.0 * period));
            } else {
                prop_assert!((e - (p / period - 1.0)).abs() <= ROUNDING * p / period);
            }
        }
    }
}
