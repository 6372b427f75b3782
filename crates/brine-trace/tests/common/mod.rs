//! Shared helpers of the integration tests: a non-ocean implementor, random wave sets, and the
//! dense f64 reference of the first crossing.

#![allow(dead_code)]

use brine_trace::{Aabb, LipschitzSum, Ray, Step, StepKind, TraceOptions};
use brine_waves::{Trochoid, TrochoidSet};
use glam::DVec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// `F(p) = Σ sᵢ (‖p − cᵢ‖ − rᵢ)`: a weighted sum of sphere distance functions (weights of both
/// signs make the zero set non-convex). Each component is `|sᵢ|`-Lipschitz in every direction.
pub struct SphereSum {
    pub centres: Vec<DVec3>,
    pub radii: Vec<f64>,
    pub weights: Vec<f64>,
}

impl SphereSum {
    /// `n` spheres in the cube `[−2, 2]³` with radii in `[0.3, 1.2]`, 70 % of weight 1 and 30 % of
    /// weight −0.5 (the zero set is bounded unless `Σ sᵢ = 0`).
    pub fn random(n: usize, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut s = Self { centres: vec![], radii: vec![], weights: vec![] };
        for _ in 0..n {
            s.centres.push(DVec3::new(
                rng.random_range(-2.0..2.0),
                rng.random_range(-2.0..2.0),
                rng.random_range(-2.0..2.0),
            ));
            s.radii.push(rng.random_range(0.3..1.2));
            s.weights.push(if rng.random::<f64>() < 0.7 { 1.0 } else { -0.5 });
        }
        s
    }

    fn distance_range(&self, i: usize, a: DVec3, b: DVec3) -> (f64, f64) {
        let c = self.centres[i];
        let ab = b - a;
        let u = if ab.length_squared() > 0.0 { ((c - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0) } else { 0.0 };
        let near = (a + u * ab - c).length();
        let far = (a - c).length().max((b - c).length());
        (near - self.radii[i], far - self.radii[i])
    }
}

impl LipschitzSum for SphereSum {
    fn component_count(&self) -> usize {
        self.centres.len()
    }
    fn component(&self, i: usize, p: DVec3) -> f64 {
        self.weights[i] * ((p - self.centres[i]).length() - self.radii[i])
    }
    fn component_lipschitz(&self, i: usize) -> f64 {
        self.weights[i].abs()
    }
    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        let (lo, hi) = self.distance_range(i, a, b);
        if self.weights[i] > 0.0 { self.weights[i] * lo } else { self.weights[i] * hi }
    }
    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        let (lo, hi) = self.distance_range(i, a, b);
        if self.weights[i] > 0.0 { self.weights[i] * hi } else { self.weights[i] * lo }
    }
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        let r = p - self.centres[i];
        let len = r.length();
        (len > 0.0).then(|| self.weights[i] * d.dot(r) / len)
    }
    fn component_feature_size(&self, i: usize) -> f64 {
        self.radii[i]
    }
    fn zero_set_bounds(&self) -> Aabb {
        // sᵢ‖p − cᵢ‖ lies within sᵢ‖p‖ ± |sᵢ|‖cᵢ‖, so F = Σ sᵢ(‖p − cᵢ‖ − rᵢ) has the sign of
        // S = Σ sᵢ beyond the radius Σ|sᵢ|(‖cᵢ‖ + rᵢ)/|S| (F > 0 there if S > 0, F < 0 if S < 0:
        // a single sphere of weight −0.5; S = 0 gives an infinite radius, no clipping).
        let total: f64 = self.weights.iter().sum::<f64>().abs();
        let reach: f64 = self
            .weights
            .iter()
            .zip(&self.centres)
            .zip(&self.radii)
            .map(|((w, c), r)| w.abs() * (c.length() + r))
            .sum::<f64>()
            / total;
        Aabb { min: DVec3::splat(-reach), max: DVec3::splat(reach) }
    }
}

/// A random trochoid set: `n` waves, wavelengths log-uniform in `[lambda_min, 100]` m, directions
/// in a half-plane, steepness `Q` uniform in `[0, q_max]` (up to the no-loop limit 0.99), and
/// amplitudes scaled so that `Σ kᵢAᵢ = slope_sum`.
pub fn random_set(n: usize, lambda_min: f64, q_max: f64, slope_sum: f64, seed: u64) -> TrochoidSet {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut raw = Vec::with_capacity(n);
    for _ in 0..n {
        let lambda = lambda_min * (100.0 / lambda_min).powf(rng.random::<f64>());
        let k = std::f64::consts::TAU / lambda;
        let weight: f64 = rng.random_range(0.2..1.0);
        raw.push((
            k,
            weight,
            rng.random_range(-1.5..1.5),
            rng.random_range(0.0..std::f64::consts::TAU),
            rng.random_range(0.0..=q_max),
        ));
    }
    let total: f64 = raw.iter().map(|w| w.1).sum();
    let waves = raw
        .into_iter()
        .map(|(k, weight, dir, phase, q)| {
            let a = slope_sum * weight / total / k;
            Trochoid::new(a, k, dir, (9.81 * k).sqrt(), phase, q).unwrap()
        })
        .collect();
    TrochoidSet::new(waves)
}

/// A crossing of the dense reference: `[t_before, t_after]` bracket and the depth of the
/// excursion that follows it (the largest `|F|` before the sign changes back).
#[derive(Debug, Clone, Copy)]
pub struct Crossing {
    pub t: f64,
    pub depth: f64,
    /// `true` if `F` leaves the sign it had at `t0` (only those can be a ray's first hit).
    pub leaving: bool,
}

/// Dense f64 reference along a ray: samples `f` every `delta` on `[t0, t1]`, returns every sign
/// change (refined by 60 bisections) with the depth of the excursion after it.
pub fn dense_crossings(f: &dyn Fn(f64) -> f64, t0: f64, t1: f64, delta: f64) -> Vec<Crossing> {
    let n = ((t1 - t0) / delta).ceil().max(1.0) as usize;
    let samples: Vec<(f64, f64)> = (0..=n)
        .map(|j| {
            let t = if j == n { t1 } else { t0 + j as f64 * delta };
            (t, f(t))
        })
        .collect();
    let mut out = Vec::new();
    let start_sign = samples[0].1 > 0.0;
    let mut j = 1;
    let mut side = start_sign;
    while j < samples.len() {
        let (ta, fa) = samples[j - 1];
        let (tb, fb) = samples[j];
        if (fb > 0.0) != side {
            let (mut lo, mut hi) = (ta, tb);
            for _ in 0..60 {
                let m = 0.5 * (lo + hi);
                if (f(m) > 0.0) == (fa > 0.0) { lo = m } else { hi = m }
            }
            // Depth: the largest |F| of the new sign until the sign returns.
            let new_side = fb > 0.0;
            let mut depth = 0.0f64;
            let mut k = j;
            while k < samples.len() && (samples[k].1 > 0.0) == new_side {
                depth = depth.max(samples[k].1.abs());
                k += 1;
            }
            out.push(Crossing { t: 0.5 * (lo + hi), depth, leaving: new_side != start_sign });
            side = new_side;
        }
        j += 1;
    }
    out
}

/// Checks one traced result against the dense reference.
///
/// - A hit must lie on the surface: `|F(t_hit)| ≤ on_surface`.
/// - Every reference crossing that leaves the starting sign before the hit must be a skim: the
///   excursion of `F` after it, up to the hit (or up to where the sign returns), stays within
///   `skim`. A deeper one is a missed root (`t_hit` a later root).
/// - A miss is allowed only if every such crossing is a skim over its whole excursion.
pub fn check_first_crossing(
    f: &dyn Fn(f64) -> f64,
    crossings: &[Crossing],
    hit: Option<f64>,
    on_surface: f64,
    skim: f64,
) -> Result<(), String> {
    match hit {
        Some(t) => {
            let v = f(t);
            if v.abs() > on_surface {
                return Err(format!("hit at t = {t} is off the surface: F = {v:e} > {on_surface:e}"));
            }
            for c in crossings.iter().filter(|c| c.leaving && c.t < t && c.depth > skim) {
                // Depth of the excursion between the crossing and the hit only.
                let depth = (0..=400)
                    .map(|j| f(c.t + (t - c.t) * j as f64 / 400.0))
                    .map(|v| v.abs())
                    .fold(0.0, f64::max)
                    .min(c.depth);
                if depth > skim + on_surface {
                    return Err(format!(
                        "missed an earlier crossing at t = {} (depth {depth:e} > {skim:e} before the hit at {t})",
                        c.t
                    ));
                }
            }
        }
        None => {
            if let Some(c) = crossings.iter().find(|c| c.leaving && c.depth > skim) {
                return Err(format!("missed the crossing at t = {} (depth {:e} > {skim:e})", c.t, c.depth));
            }
        }
    }
    Ok(())
}

/// Checks the step log: certified steps contain no reference crossing deeper than `skim`, probe
/// steps of the sphere-tracing methods are no longer than `h(t)`, and only the last step brackets.
pub fn check_steps(
    f: &dyn Fn(f64) -> f64,
    log: &[Step],
    options: &TraceOptions,
    skim: f64,
    probe_limit: bool,
) -> Result<(), String> {
    for (i, s) in log.iter().enumerate() {
        match s.kind {
            StepKind::Certified => {
                let n = 64;
                let f0 = f(s.t_from);
                for j in 1..=n {
                    let t = s.t_from + (s.t_to - s.t_from) * j as f64 / n as f64;
                    let v = f(t);
                    if (v > 0.0) != (f0 > 0.0) && v.abs() > skim {
                        return Err(format!(
                            "certified step {i} [{}, {}] crosses the surface at {t} (F = {v:e})",
                            s.t_from, s.t_to
                        ));
                    }
                }
            }
            StepKind::Probe => {
                let h = options.min_step_at(s.t_from);
                if probe_limit && s.t_to - s.t_from > h * (1.0 + 1e-9) {
                    return Err(format!("probe step {i} of length {} exceeds h = {h}", s.t_to - s.t_from));
                }
            }
            StepKind::Bracket => {
                if i + 1 != log.len() {
                    return Err(format!("bracket at step {i} is not the last step"));
                }
            }
            StepKind::Rejected => {}
        }
    }
    Ok(())
}

/// A random ray toward a slab `|y| ≤ half_height`: origin above it, inside it or below the mean
/// level, directions from straight down to grazing (`|d_y|` down to 10⁻³) and a few upward.
pub fn random_ray(half_height: f64, rng: &mut ChaCha8Rng) -> Ray {
    let kind = rng.random_range(0..4);
    let y = match kind {
        0 => half_height * rng.random_range(1.0..3.0),
        1 => half_height * rng.random_range(-1.0..1.0),
        _ => half_height * rng.random_range(0.2..1.5),
    };
    let origin = DVec3::new(rng.random_range(-50.0..50.0), y, rng.random_range(-50.0..50.0));
    let azimuth: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    let dy = match kind {
        3 => -10f64.powf(rng.random_range(-3.0..-1.0)), // grazing
        1 => rng.random_range(-0.3..0.1),
        _ => -rng.random_range(0.02..1.0),
    };
    let horizontal = (1.0 - dy * dy).max(0.0).sqrt();
    Ray::new(origin, DVec3::new(horizontal * azimuth.cos(), dy, horizontal * azimuth.sin())).unwrap()
}

/// `F(p) = y − Σᵢ aᵢ sin(kᵢ·(x, z) + φᵢ)`: a sum of sine waves with exact derivatives along a ray
/// (`−aᵢ σᵢ cos(·)`, `σᵢ = kᵢ·d̂_xz`) and curvature bounds (`aᵢ σᵢ²`), in f64: a second
/// implementor whose tiers carry every bound the tiered and segment methods use.
pub struct SineSum {
    pub amplitudes: Vec<f64>,
    pub wavevectors: Vec<(f64, f64)>,
    pub phases: Vec<f64>,
}

impl SineSum {
    /// `n` waves, wavelengths log-uniform in `[1, 60]` m, slopes `aᵢ|kᵢ|` summing to 0.5.
    pub fn random(n: usize, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut s = Self { amplitudes: vec![], wavevectors: vec![], phases: vec![] };
        for _ in 0..n {
            let k = std::f64::consts::TAU / 60f64.powf(rng.random::<f64>());
            let dir: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            s.wavevectors.push((k * dir.cos(), k * dir.sin()));
            s.amplitudes.push(0.5 / n as f64 / k);
            s.phases.push(rng.random_range(0.0..std::f64::consts::TAU));
        }
        s
    }

    fn wavenumber(&self, j: usize) -> f64 {
        let (kx, kz) = self.wavevectors[j];
        kx.hypot(kz)
    }

    fn sigma(&self, j: usize, d: DVec3) -> f64 {
        let (kx, kz) = self.wavevectors[j];
        kx * d.x + kz * d.z
    }

    fn phase(&self, j: usize, p: DVec3) -> f64 {
        let (kx, kz) = self.wavevectors[j];
        kx * p.x + kz * p.z + self.phases[j]
    }
}

impl LipschitzSum for SineSum {
    fn component_count(&self) -> usize {
        self.amplitudes.len() + 1
    }
    fn component(&self, i: usize, p: DVec3) -> f64 {
        if i == 0 { p.y } else { -self.amplitudes[i - 1] * self.phase(i - 1, p).sin() }
    }
    fn component_lipschitz(&self, i: usize) -> f64 {
        if i == 0 { 1.0 } else { self.amplitudes[i - 1] * self.wavenumber(i - 1) }
    }
    fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 { d.y.abs() } else { self.amplitudes[i - 1] * self.sigma(i - 1, d).abs() }
    }
    fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.min(b.y) } else { -self.amplitudes[i - 1] }
    }
    fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
        if i == 0 { a.y.max(b.y) } else { self.amplitudes[i - 1] }
    }
    fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
        Some(if i == 0 { d.y } else { -self.amplitudes[i - 1] * self.sigma(i - 1, d) * self.phase(i - 1, p).cos() })
    }
    fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
        if i == 0 { 0.0 } else { self.amplitudes[i - 1] * self.sigma(i - 1, d).powi(2) }
    }
    fn component_feature_size(&self, i: usize) -> f64 {
        if i == 0 { f64::INFINITY } else { std::f64::consts::TAU / self.wavenumber(i - 1) }
    }
    fn zero_set_bounds(&self) -> Aabb {
        let a: f64 = self.amplitudes.iter().sum();
        Aabb::slab_y(-a, a)
    }
}
