//! `proptest` strategies of random trochoid seas.

use std::f64::consts::{PI, TAU};

use brine_waves::{G, Trochoid, TrochoidSet};
use proptest::prelude::*;

/// A random wave set of 1 to `max_waves − 1` waves: amplitudes 0.01–1.5 m, wavenumbers
/// 0.05–3 rad/m (wavelengths 2–125 m), any direction and phase, deep-water frequencies
/// `ω = √(gk)`, steepnesses sharing a random total `Σ Q ∈ [0, 0.95]` (so `Qᵢ` and `kᵢAᵢ` are
/// unrelated, as with choppiness ≠ 1).
pub fn trochoid_set(max_waves: usize) -> impl Strategy<Value = TrochoidSet> {
    (prop::collection::vec((0.01f64..1.5, 0.05f64..3.0, -PI..PI, 0.0..TAU, 0.01f64..1.0), 1..max_waves), 0.0f64..0.95)
        .prop_map(|(raw, total)| {
            let q_sum: f64 = raw.iter().map(|w| w.4).sum();
            TrochoidSet::new(
                raw.iter()
                    .map(|&(a, k, dir, ph, q)| {
                        Trochoid::new(a, k, dir, (G * k).sqrt(), ph, total * q / q_sum).expect("parameters in range")
                    })
                    .collect(),
            )
        })
}

/// A point `(x, z, t)`: ±300 m, 0–100 s.
pub fn point_and_time() -> impl Strategy<Value = (f64, f64, f64)> {
    (-300.0f64..300.0, -300.0f64..300.0, 0.0f64..100.0)
}
