//! The reusable buffers of the tiered tracer: each tier's bounds along the ray, refreshed as the ray advances.

use super::*;

/// Reusable buffers of [`trace_tiers_with`] (one per thread avoids an allocation per ray).
#[derive(Debug, Clone, Default)]
pub struct TierScratch {
    pub(super) bounds: Vec<TierBounds>,
    /// Oriented lower bound of each tier.
    pub(super) lo: Vec<f64>,
    /// `Σ_{j≥k} lo[j]`, length `n + 1`.
    pub(super) lo_suffix: Vec<f64>,
    /// `(max − min)/L`: the largest step at which evaluating the tier can help.
    pub(super) key: Vec<f64>,
    /// Oriented value of each sampled tier at the current point.
    pub(super) value: Vec<f64>,
    /// Oriented derivative (a lower bound of it) of each sampled tier.
    pub(super) slope: Vec<f64>,
    /// Bound of how concave the oriented tier can be, used with `slope` (0 when the slope is the
    /// Lipschitz lower bound).
    pub(super) curvature: Vec<f64>,
    /// 3D Lipschitz constant of each tier (cone mode).
    pub(super) spread: Vec<f64>,
    /// Unoriented derivative of the first samples (while the side is unknown).
    pub(super) raw_slope: Vec<f64>,
    /// Whether the stored slope of each tier is its sampled derivative with a finite curvature
    /// bound (`false`: the slope is the Lipschitz lower bound `−L`).
    pub(super) exact: Vec<bool>,
    /// Segment tracing ([`crate::trace_segments`]): the tiers' bounds and derivatives.
    pub(crate) segment_bounds: Vec<TierBounds>,
    pub(crate) segment_slopes: Vec<f64>,
}

impl TierScratch {
    pub(super) fn reset(&mut self, n: usize) {
        for v in [
            &mut self.lo,
            &mut self.key,
            &mut self.value,
            &mut self.slope,
            &mut self.curvature,
            &mut self.spread,
            &mut self.raw_slope,
        ] {
            v.clear();
            v.resize(n, 0.0);
        }
        self.exact.clear();
        self.exact.resize(n, false);
        self.lo_suffix.clear();
        self.lo_suffix.resize(n + 1, 0.0);
        self.bounds.clear();
        self.bounds.resize(n, TierBounds::ZERO);
    }

    /// Reads the bounds of every tier at `t` and orients them by `sign`.
    pub(super) fn refresh<R: RayTiers + ?Sized>(&mut self, tiers: &mut R, t: f64, sign: f64, cone: bool) {
        let n = self.bounds.len();
        for j in 0..n {
            let b = tiers.bounds(j, t);
            if cone {
                self.spread[j] = tiers.spread_lipschitz(j);
            }
            self.bounds[j] = b;
            self.lo[j] = if sign > 0.0 { b.min } else { -b.max };
            let range = b.max - b.min;
            self.key[j] = if b.lipschitz > 0.0 {
                range / b.lipschitz
            } else if range > 0.0 {
                f64::INFINITY
            } else {
                0.0
            };
        }
        self.lo_suffix[n] = 0.0;
        for j in (0..n).rev() {
            self.lo_suffix[j] = self.lo_suffix[j + 1] + self.lo[j];
        }
    }

    /// Stores the sample of tier `j`, oriented.
    pub(super) fn store(&mut self, j: usize, value: f64, slope: f64, sign: f64) {
        self.value[j] = sign * value;
        let b = self.bounds[j];
        // The oriented tier `sign·T` has `(sign·T)'' ≥ −concavity` on the positive side and
        // `≥ −curvature` on the negative side (the one-sided bound of `T'' ≤ curvature`).
        let curvature = if sign > 0.0 { b.concavity.min(b.curvature) } else { b.curvature };
        if slope.is_finite() && curvature.is_finite() {
            self.slope[j] = (sign * slope).max(-b.lipschitz);
            self.curvature[j] = curvature;
            self.exact[j] = true;
        } else {
            self.exact[j] = false;
            // Unknown derivative or curvature: the tier can only fall at its Lipschitz rate.
            self.slope[j] = -b.lipschitz;
            self.curvature[j] = 0.0;
        }
    }

    /// The certified step from the first `k` sampled tiers (the others at their bounds).
    ///
    /// Each sampled tier is assigned to the quadratic part (derivative + curvature) or to the
    /// reserve part (how far it can fall, at its Lipschitz rate), whichever costs less at the
    /// expected step; two passes refine the guess. Every assignment gives a valid bound, so the
    /// largest root is kept.
    pub(super) fn step(&self, k: usize, eps: f64, eta: f64, guess: f64, spread: (f64, f64)) -> f64 {
        // Cone mode: every ray within `θ` of the axis is within `θ(t + s)` of the axis point, so
        // the evaluated tiers lose at most `θ(t + s) Σ Lⱼ³ᴰ`.
        let (margin, margin_rate) = if spread.0 > 0.0 {
            let l3: f64 = self.spread[..k].iter().sum();
            (spread.0 * spread.1 * l3, spread.0 * l3)
        } else {
            (0.0, 0.0)
        };
        let value: f64 = self.value[..k].iter().sum::<f64>() + self.lo_suffix[k] - eps - margin;
        if !(value > 0.0) {
            return 0.0;
        }
        let mut guess = if guess.is_finite() && guess > 0.0 {
            guess
        } else {
            let l: f64 = self.bounds[..k].iter().map(|b| b.lipschitz).sum();
            if l > 0.0 { value / l } else { f64::INFINITY }
        };
        let mut best = 0.0f64;
        for _ in 0..2 {
            let mut b = StepBound {
                value,
                slope: -eta - margin_rate,
                curvature: 0.0,
                lipschitz: eta + margin_rate,
                reserve: 0.0,
                reserve_lipschitz: 0.0,
            };
            for j in 0..k {
                let (d, kk, l) = (self.slope[j], self.curvature[j], self.bounds[j].lipschitz);
                let a = (self.value[j] - self.lo[j]).max(0.0);
                let fall_q = quadratic_fall(d, kk, l, guess);
                let fall_p = a.min(l * guess);
                if fall_q <= fall_p {
                    b.slope += d;
                    b.curvature += kk;
                    b.lipschitz += l;
                } else {
                    b.reserve += a;
                    b.reserve_lipschitz += l;
                }
            }
            let s = b.first_root();
            best = best.max(s);
            if !s.is_finite() {
                break;
            }
            guess = s;
        }
        best
    }

    /// The certified step *backward* (toward the ray origin) from the stored samples of the first
    /// `k` tiers: [`step`](Self::step) with every sampled derivative reversed. The bounds hold
    /// there too: they were read at or before the start of the step. A tier without a usable
    /// derivative keeps its slope `−L`: that is a lower bound of its rate of change in either
    /// direction (reversing it to `+L` would claim that the tier grows, and certify steps across
    /// crossings: found by the sphere-sum property test, seed 308).
    pub(super) fn backward_step(&mut self, k: usize, eps: f64, eta: f64, guess: f64) -> f64 {
        for (d, &exact) in self.slope[..k].iter_mut().zip(&self.exact[..k]) {
            if exact {
                *d = -*d;
            }
        }
        let s = self.step(k, eps, eta, guess, (0.0, 0.0));
        for (d, &exact) in self.slope[..k].iter_mut().zip(&self.exact[..k]) {
            if exact {
                *d = -*d;
            }
        }
        s
    }

    /// Tiers to evaluate at the next point after a step `s`: those whose key is at least
    /// `DEPTH_KEEP·s`, stopping at the first that is not (at least one).
    pub(super) fn next_depth(&self, s: f64) -> usize {
        let n = self.key.len();
        let mut k = 1;
        while k < n && self.key[k] >= DEPTH_KEEP * s {
            k += 1;
        }
        k
    }
}
