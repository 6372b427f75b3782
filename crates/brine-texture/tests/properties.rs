//! Property tests: bounds and invariants of brine-texture on random inputs.

use brine_texture::{
    ComposedSurface, Grid, HeightField, RelightRule, Texture, TransitionGraph, height_from_intensity,
    intensity_from_height, relight_intensity,
};
use brine_trace::{LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace};
use glam::DVec3;
use proptest::prelude::*;

/// Relative slack on the Lipschitz inequality for the f64 rounding of the bilinear interpolation
/// (a few ulps of heights of order 1 m).
const LIPSCHITZ_SLACK: f64 = 1e-9;

/// Relative rounding of a closed form or a short sum evaluated in `f64` (a few ulps).
const F64_REL: f64 = 1e-12;

/// Eq. 4 inverting Eq. 1: `I_min + (I − I_min)/span · span` with spans down to 0.5 level and
/// intensities up to 255 amplifies one ulp by at most ~10³: 10⁻⁹ relative is ample.
const INVERSE_REL: f64 = 1e-9;

/// Heights of the composed surface against its reported range (m): f64 round-off of bilinear
/// sums of heights ≤ 7 m.
const RANGE_SLACK_M: f64 = 1e-9;

/// Slack on the bounded relighting's monotonicity (levels): `f64` round-off of `I ± I·x^{3/4}`.
const MONOTONIC_SLACK: f64 = 1e-9;

/// `f32` bilinear samples of levels ≤ 255 (a few roundings of 2⁻²⁴ relative, ~10⁻⁵ level).
const F32_LEVELS: f32 = 1e-3;

/// A random height field of `w × h` texels with values in `[0, amplitude]` (m), from a seed.
fn random_field(seed: u64, w: usize, h: usize, amplitude: f32, smooth: bool) -> HeightField {
    let mut state = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
    let mut next = move || {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) as f32) / (1u64 << 31) as f32
    };
    let raw: Vec<f32> = (0..w * h).map(|_| next()).collect();
    let g = Grid::from_fn(w, h, |i, j| {
        if smooth {
            // A 3×3 box blur of the noise: gentler slopes, like a photo's heights.
            let mut s = 0.0;
            for dj in [h - 1, 0, 1] {
                for di in [w - 1, 0, 1] {
                    s += raw[((j + dj) % h) * w + (i + di) % w];
                }
            }
            amplitude * s / 9.0
        } else {
            amplitude * raw[j * w + i]
        }
    });
    HeightField::from_heights(g)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Eq. 6–9 keep every intensity in [0, 255], for both forms, any height change and any
    /// largest height change (the printed form needs its clamp; the bounded form does not).
    #[test]
    fn relighting_keeps_intensities_in_range(
        i in 0.0f64..=255.0, dh in -50.0f64..50.0, dh_max in 0.0f64..50.0,
    ) {
        for rule in [RelightRule::Paper, RelightRule::Bounded] {
            let out = relight_intensity(i, dh, dh_max, rule);
            prop_assert!((0.0..=255.0).contains(&out), "{rule:?}: I = {i}, Δh = {dh}, Δh_max = {dh_max} → {out}");
        }
        // In its domain |Δh| ≤ Δh_max the bounded form needs no clamp and is monotonic in Δh.
        if dh.abs() <= dh_max && dh_max > 0.0 {
            let a = relight_intensity(i, dh, dh_max, RelightRule::Bounded);
            let b = relight_intensity(i, (dh + 0.1 * dh_max).min(dh_max), dh_max, RelightRule::Bounded);
            // Monotonic up to the round-off of the ¾ power of levels ≤ 255 (~10⁻¹³).
            prop_assert!(b >= a - MONOTONIC_SLACK);
        }
    }

    /// Eq. 1 maps into [0, hf], and Eq. 4 inverts it.
    #[test]
    fn eq1_is_in_range_and_eq4_inverts_it(
        i_min in 0.0f64..200.0, span in 0.5f64..55.0, f in 0.0f64..=1.0, hf in 0.01f64..50.0,
    ) {
        let i_max = i_min + span;
        let i = i_min + f * span;
        let h = height_from_intensity(i, i_min, i_max, hf);
        prop_assert!((-F64_REL..=hf * (1.0 + F64_REL)).contains(&h));
        prop_assert!((intensity_from_height(h, i_min, i_max, hf) - i).abs() <= INVERSE_REL * (1.0 + i));
    }

    /// The composed height field honours every bound it reports to brine-trace on random points:
    /// |nᵢ(p) − nᵢ(q)| ≤ Lᵢ|p − q| and ≤ Lᵢ(d̂)|p − q| along d̂, Lᵢ(d̂) ≤ Lᵢ, mᵢ ≤ nᵢ ≤ Mᵢ, F is
    /// the sum of its components, and the zero set lies in the reported slab.
    #[test]
    fn composed_surface_bounds_hold_on_random_points(
        seed in 0u64..10_000, smooth in any::<bool>(), amp_small in 0.01f32..2.0, amp_main in 0.01f32..5.0,
        texel in 0.01f64..0.5, scale in 1.0f64..16.0,
        px in -200.0f64..200.0, pz in -200.0f64..200.0, py in -5.0f64..5.0,
        dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0, step in 1e-4f64..3.0,
    ) {
        let small = random_field(seed, 12, 10, amp_small, smooth);
        let main = random_field(seed + 1, 9, 14, amp_main, smooth);
        let s = ComposedSurface::new(&small, &main, texel, texel * scale);
        let d = DVec3::new(dx, dy, dz).normalize_or(DVec3::X);
        let p = DVec3::new(px, py, pz);
        let q = p + step * d;
        let mut sum = 0.0;
        for i in 0..s.component_count() {
            let (np, nq) = (s.component(i, p), s.component(i, q));
            sum += np;
            let l = s.component_lipschitz(i);
            let ld = s.component_directional_lipschitz(i, d);
            let tol = LIPSCHITZ_SLACK * (1.0 + np.abs() + nq.abs());
            prop_assert!((np - nq).abs() <= l * step + tol, "component {i}: |Δn| = {} > L|Δp| = {}", (np - nq).abs(), l * step);
            prop_assert!((np - nq).abs() <= ld * step + tol, "component {i}: directional");
            prop_assert!(np >= s.component_min(i, p, q) - tol && np <= s.component_max(i, p, q) + tol, "component {i}: range");
        }
        prop_assert!((s.value(p) - sum).abs() <= F64_REL * (1.0 + sum.abs()));
        let h = s.height(px, pz);
        let (lo, hi) = s.height_range();
        prop_assert!(h >= lo - RANGE_SLACK_M && h <= hi + RANGE_SLACK_M);
    }

    /// The first crossing is found: sphere tracing the composed surface stops where a fine march
    /// first changes sign (the march step is far below a texel, so it sees every crossing the
    /// tracer must see), up to skims thinner than the minimum step (seed 1862: a dip of the
    /// surface at t = 59.68 shallower than L(d̂)·h = 0.56 mm, the crossing at 59.84).
    #[test]
    fn the_first_crossing_is_found(
        seed in 0u64..10_000, height in 0.5f64..6.0, pitch_deg in -60.0f64..-3.0, yaw in 0.0f64..std::f64::consts::TAU,
    ) {
        let small = random_field(seed, 16, 16, 0.3, true);
        let main = random_field(seed + 7, 16, 16, 1.0, true);
        let s = ComposedSurface::new(&small, &main, 0.1, 0.8);
        let (_, hi) = s.height_range();
        let o = DVec3::new(0.3, hi + height, -0.2);
        let e = pitch_deg.to_radians();
        let d = DVec3::new(yaw.cos() * e.cos(), e.sin(), yaw.sin() * e.cos());
        let ray = Ray::new(o, d).unwrap();
        let options = TraceOptions { method: Method::Directional, t_max: 400.0, ..TraceOptions::default() };
        let hit = trace(&s, &ray, &options, &mut TraceStats::default());
        // Reference: march with a step of 10⁻³ texels of the small field.
        let step = 1e-4;
        let mut t = 0.0;
        let mut reference = None;
        while t < options.t_max {
            let t1 = t + step;
            if s.value(ray.at(t1)) <= 0.0 {
                reference = Some(t1);
                break;
            }
            t = t1;
        }
        // A hit is a sign change seen by the tracer's probes: a dip below zero thinner than the
        // minimum step h(t) (depth under L(d̂)·h, a skim over a crest) may be passed over. The
        // traced hit is the marched crossing, or lies beyond crossings that are all such skims.
        let skim = |from: f64, to: f64| {
            let depth = s.directional_lipschitz(d) * options.min_step_at(to);
            let mut u = from;
            while u < to - 2.0 * step {
                if s.value(ray.at(u)) < -depth {
                    return false;
                }
                u += step;
            }
            true
        };
        match (hit, reference) {
            (Some(h), Some(r)) => prop_assert!(
                (h.t - r).abs() <= 2.0 * step || (h.t > r && skim(r, h.t)),
                "traced {} vs marched {r}", h.t
            ),
            (None, None) => {}
            (None, Some(r)) => prop_assert!(skim(r, options.t_max), "traced nothing vs marched {r}"),
            (h, r) => prop_assert!(false, "traced {h:?} vs marched {r:?}"),
        }
    }

    /// Every distance matrix gives a strongly connected transition graph whose probabilities
    /// leaving each frame are positive and sum to 1.
    #[test]
    fn transition_graphs_are_strongly_connected(
        n in 2usize..24, k in 1usize..6, seed in 0u64..10_000, clustered in any::<bool>(),
    ) {
        let mut state = seed + 1;
        let mut next = move || { state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1); (state >> 40) as f64 / (1u64 << 24) as f64 };
        let mut d = vec![0.0; n * n];
        for i in 0..n {
            for j in i + 1..n {
                let base = if clustered && (i % 3 == 0) != (j % 3 == 0) { 1000.0 } else { 0.0 };
                let v = base + 50.0 * next();
                d[i * n + j] = v;
                d[j * n + i] = v;
            }
        }
        let g = TransitionGraph::new(n, &d, k.min(n - 1));
        prop_assert!(g.is_strongly_connected());
        for i in 0..n {
            let out = g.outgoing(i);
            prop_assert!(!out.is_empty());
            let p: f64 = out.iter().map(|l| l.probability).sum();
            prop_assert!((p - 1.0).abs() < F64_REL);
            prop_assert!(out.iter().all(|l| l.probability > 0.0 && l.to != i));
        }
    }

    /// Bilinear samples of a texture stay within the range of its texels.
    #[test]
    fn bilinear_samples_stay_in_range(u in -1e4f64..1e4, v in -1e4f64..1e4) {
        let t = Texture::from_fn(7, 5, |i, j| [(i * 30) as f32, (j * 50) as f32, 255.0]);
        let c = t.sample(u, v);
        prop_assert!(c[0] >= 0.0 && c[0] <= 180.0 + F32_LEVELS && c[1] >= 0.0 && c[1] <= 200.0 + F32_LEVELS);
        prop_assert!((c[2] - 255.0).abs() < F32_LEVELS);
    }
}
