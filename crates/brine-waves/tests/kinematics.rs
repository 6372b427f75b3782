//! Kinematics of the trochoid sum: what `TrochoidSum::velocity` means, checked by two
//! finite-difference routes that use neither the velocity nor the gradient code.
//!
//! - **Eulerian**: the kinematic condition `v_y = ∂h/∂t + ∇h·v_xz`, with `∂h/∂t` and `∇h` from
//!   central differences of the height field alone (a point carried by `v` stays on the surface).
//! - **Lagrangian**: the particle of one wave at `x` has the rest position `u = x − D(x, t)` (the
//!   crate's displacement). Holding `u` fixed, its position at `t ± δ` is the root `X` of
//!   `X − D(X, t ± δ) = u` (found here by bisection along the wave's direction, where
//!   `η ↦ η − D(u + η d̂)·d̂` is increasing: its derivative is `1/(1 − Q cos θ) > 0`), and its
//!   velocity is `(X(t + δ) − X(t − δ))/2δ`, its vertical speed the central difference of
//!   `h(X(t), t)` along the path.
//!
//! For one wave the crate's velocity is that particle's. For many waves its horizontal part is
//! the sum of the waves' own particle velocities (each wave's `Dᵢ` differentiated at that wave's
//! fixed rest coordinate; the per-wave particles come from one-wave surfaces, whose displacements
//! add up to the sum's), and its vertical part differs from the sum of the particles' vertical
//! speeds by exactly the cross terms `Σ_{i≠j} ∇hᵢ·v_{xz,j}`.

use std::f64::consts::{PI, TAU};

use brine_testkit::strategies::{point_and_time, trochoid_set};
use brine_waves::{G, Trochoid, TrochoidSet, TrochoidSum, WaveSurface};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

/// Cases per property.
const CASES: u32 = 64;

/// Eulerian central differences: step in space (m) and time (s). At `Q = 0.95` the profile's third
/// derivative grows like `A k³/(1 − Q)⁵`, so the truncation `h²|h'''|/6` stays below 10⁻⁵ of the
/// velocity scale; rounding `~10⁻¹⁶ ΣA/h` is ~10⁻⁹ m/s.
const EULER_STEP: f64 = 1e-6;

/// Tolerance of the Eulerian route, relative to the scale `Σ(Aᵢ + Qᵢ/kᵢ)ωᵢ (1 + L)` (the size of
/// `∂h/∂t` and `∇h·v`): the truncation bound above.
const EULER_REL: f64 = 1e-5;

/// Lagrangian time step (s): along a particle path the motion is a circle of frequency `ω ≤ 5.5`
/// rad/s, so the truncation `δ²ω³r/6` is ~3×10⁻⁷ of the orbit radius `r`, and the bisection's last
/// ulp (`~7×10⁻¹⁴` m at 300 m) costs `7×10⁻¹⁰ (1 + L)` m/s.
const LAGRANGE_STEP: f64 = 1e-4;

/// Tolerance of the Lagrangian route relative to the same velocity scale: the truncation above.
const LAGRANGE_REL: f64 = 1e-6;

/// Margin (m) of the bisection bracket `[−r, r]` of the particle's offset along `d̂`: the root lies
/// inside it, and the margin keeps the sign change strict at `|η| = r`.
const BRACKET_MARGIN_M: f64 = 1e-9;

/// The per-wave displacements add up to the sum's: rounding of at most 12 terms below 20 m.
const ADDITIVE_ABS: f64 = 1e-12;

/// `Σ (Aᵢ + Qᵢ/kᵢ) ωᵢ (1 + L)`: the scale of every velocity term (m/s).
fn velocity_scale(set: &TrochoidSet) -> f64 {
    let sum = TrochoidSum::new(set);
    let orbit: f64 = set.waves().iter().map(|w| (w.amplitude() + w.horizontal_radius()) * w.omega()).sum();
    orbit * (1.0 + sum.max_slope())
}

/// `(∂h/∂t, ∇h)` by central differences of the height alone.
fn eulerian_derivatives(s: &dyn WaveSurface, x: f64, z: f64, t: f64) -> (f64, DVec2) {
    let e = EULER_STEP;
    let dh_dt = (s.height(x, z, t + e) - s.height(x, z, t - e)) / (2.0 * e);
    let grad = DVec2::new(s.height(x + e, z, t) - s.height(x - e, z, t), s.height(x, z + e, t) - s.height(x, z - e, t))
        / (2.0 * e);
    (dh_dt, grad)
}

/// Position at time `t` of the particle of the one-wave surface `s` (direction `d`) whose rest
/// position is `u`: the root of `X − D(X, t) = u`, by bisection on `X = u + η d̂`,
/// `|η| ≤ Q/k = r`.
fn particle_position(s: &TrochoidSum, d: DVec2, r: f64, u: DVec2, t: f64) -> DVec2 {
    let g = |eta: f64| {
        let x = u + eta * d;
        eta - s.displacement(x.x, x.y, t).dot(d)
    };
    let (mut lo, mut hi) = (-r - BRACKET_MARGIN_M, r + BRACKET_MARGIN_M);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) < 0.0 { lo = mid } else { hi = mid }
    }
    u + 0.5 * (lo + hi) * d
}

/// The velocity of the particle of wave `w` that is at `(x, z)` at time `t`, by the Lagrangian
/// route (central differences along its path at fixed rest position).
fn lagrangian_velocity(w: &Trochoid, x: f64, z: f64, t: f64) -> DVec3 {
    let s = TrochoidSum::new(&TrochoidSet::new(vec![*w]));
    let (d, r) = (w.direction_vector(), w.horizontal_radius());
    let u = DVec2::new(x, z) - s.displacement(x, z, t);
    let dt = LAGRANGE_STEP;
    let (a, b) = (particle_position(&s, d, r, u, t - dt), particle_position(&s, d, r, u, t + dt));
    let v = (b - a) / (2.0 * dt);
    let vy = (s.height(b.x, b.y, t + dt) - s.height(a.x, a.y, t - dt)) / (2.0 * dt);
    DVec3::new(v.x, vy, v.y)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn one_wave_velocity_is_its_particle_velocity(
        (a, k, dir, ph, q) in (0.01f64..1.5, 0.05f64..3.0, -PI..PI, 0.0..TAU, 0.0f64..0.95),
        (x, z, t) in point_and_time(),
    ) {
        let w = Trochoid::new(a, k, dir, (G * k).sqrt(), ph, q).unwrap();
        let set = TrochoidSet::new(vec![w]);
        let s = TrochoidSum::new(&set);
        let scale = velocity_scale(&set);
        let v = s.velocity(x, z, t);
        // Lagrangian: the particle at rest position x − D moves with v (both components).
        let fd = lagrangian_velocity(&w, x, z, t);
        prop_assert!((v - fd).length() <= LAGRANGE_REL * scale, "v = {v}, particle FD {fd}");
        // Eulerian: it stays on the surface.
        let (dh_dt, grad) = eulerian_derivatives(&s, x, z, t);
        let rhs = dh_dt + grad.dot(DVec2::new(v.x, v.z));
        prop_assert!((v.y - rhs).abs() <= EULER_REL * scale, "v_y = {}, ∂h/∂t + ∇h·v = {rhs}", v.y);
    }

    #[test]
    fn many_wave_velocity_keeps_the_point_on_the_surface(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        let s = TrochoidSum::new(&set);
        let v = s.velocity(x, z, t);
        let (dh_dt, grad) = eulerian_derivatives(&s, x, z, t);
        let rhs = dh_dt + grad.dot(DVec2::new(v.x, v.z));
        prop_assert!((v.y - rhs).abs() <= EULER_REL * velocity_scale(&set), "v_y = {}, ∂h/∂t + ∇h·v = {rhs}", v.y);
    }

    #[test]
    fn many_wave_velocity_is_the_sum_of_the_waves_particles_plus_cross_terms(
        set in trochoid_set(8),
        (x, z, t) in point_and_time(),
    ) {
        let s = TrochoidSum::new(&set);
        let scale = velocity_scale(&set);
        // The sum's displacement is the sum of the one-wave displacements: the one-wave surfaces
        // hold the sum's per-wave particles.
        let singles: Vec<TrochoidSum> = set.waves().iter().map(|w| TrochoidSum::new(&TrochoidSet::new(vec![*w]))).collect();
        let d_sum: DVec2 = singles.iter().map(|one| one.displacement(x, z, t)).sum();
        prop_assert!((s.displacement(x, z, t) - d_sum).length() <= ADDITIVE_ABS);
        // Horizontal: Σ of the waves' particle velocities (Lagrangian FD, one wave at a time).
        let particles: Vec<DVec3> = set.waves().iter().map(|w| lagrangian_velocity(w, x, z, t)).collect();
        let v = s.velocity(x, z, t);
        let v_xz: DVec2 = particles.iter().map(|p| DVec2::new(p.x, p.z)).sum();
        prop_assert!((DVec2::new(v.x, v.z) - v_xz).length() <= LAGRANGE_REL * scale, "v_xz = {v}, Σ particles {v_xz}");
        // Vertical: Σ particle speeds + Σ_{i≠j} ∇hᵢ·v_xz,j, the ∇hᵢ by central differences of the
        // one-wave heights.
        let grads: Vec<DVec2> = singles.iter().map(|one| eulerian_derivatives(one, x, z, t).1).collect();
        let mut expected: f64 = particles.iter().map(|p| p.y).sum();
        for (i, g) in grads.iter().enumerate() {
            for (j, p) in particles.iter().enumerate() {
                if i != j {
                    expected += g.dot(DVec2::new(p.x, p.z));
                }
            }
        }
        prop_assert!((v.y - expected).abs() <= EULER_REL * scale, "v_y = {}, expected {expected}", v.y);
    }
}
