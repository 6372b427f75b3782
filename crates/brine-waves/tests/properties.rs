//! Property tests: bounds never exceeded on random points, Lipschitz constants hold on random
//! pairs and directions, derivatives match finite differences, the Gerstner inversion returns the
//! point the forward map came from, nothing is NaN over the documented domain.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use brine_testkit::strategies::{point_and_time, trochoid_set};
use brine_trace::LipschitzSum;
use brine_waves::{
    CosineSquared, CosineTwoS, Dispersion, DonelanBanner, Elfouhaily, FitOptions, G, GerstnerSurface, Jonswap,
    Phillips, PiersonMoskowitz, SineSet, Spectrum, Spreading, Tma, Trochoid, TrochoidSet, TrochoidSum, WaveSurface,
    fit_trochoids,
};
use glam::{DVec2, DVec3};
use proptest::prelude::*;

/// Cases per property: keeps the whole file under ~20 s in the dev profile.
const CASES: u32 = 64;

/// Rounding slack of a Lipschitz comparison: `|Δn| ≤ L|Δp| (1 + REL) + ABS`. Heights are sums of
/// at most 12 terms below 2 m (rounding ~10⁻¹⁵); the Gerstner inversion stops at a residual of
/// 10⁻¹² m, which moves a height by at most `L·10⁻¹²`.
const SLACK_REL: f64 = 1e-9;
const SLACK_ABS: f64 = 1e-9;

/// Rounding of a height (a sum of at most 12 terms below 2 m: ~10⁻¹⁵ m) or of a unit vector's
/// length, with margin.
const ROUND_ABS: f64 = 1e-12;

/// SIMD lanes against the scalar sums, relative to `1 + ΣA`: the same terms summed in another
/// order, each within a few ulp (`lanes.rs`, `gerstner_lanes.rs`).
const LANES_ABS: f64 = 1e-13;

/// Central-difference step (m, s) of the derivative checks, and their tolerance relative to
/// `1 + L` (truncation `h²|h'''|/6` stays below 10⁻⁶ of the slope scale even at `Q = 0.95`,
/// where `|h'''|/|h'| ≲ k²/(1 − Q)⁴ ≈ 10⁷ m⁻²`; rounding `~10⁻¹⁶ ΣA/h ≈ 10⁻⁹`).
const FD_STEP: f64 = 1e-6;
const FD_REL: f64 = 1e-5;

/// The Gerstner inversion's miss `|forward(inverse(x)) − x|`: its stopping rule
/// `10⁻¹² m + 10⁻¹⁴(|x| + ΣA)` is at most 5.5×10⁻¹² m on this domain (`|x| ≤ 425` m).
const INVERSION_MISS_M: f64 = 1e-11;

/// `inverse(forward(u))` against `u`: the inversion's residual over the smallest singular value
/// `1 − ΣQ` of the map, with the rounding of `forward`; divided by `1 − ΣQ` in the test.
const ROUND_TRIP_M: f64 = 1e-10;

/// Jacobian against the determinant of the central-difference derivative of the forward map
/// (step [`FD_STEP`]: truncation `h²k²ΣQ ≈ 10⁻¹¹`, rounding `10⁻¹⁶·400 m/h ≈ 4×10⁻⁸` per entry).
const JACOBIAN_FD_ABS: f64 = 1e-6;

/// One trochoid's Jacobian against the central difference of the particle map `dx/du`
/// (rounding `10⁻¹⁶·100 m/10⁻⁶ m = 10⁻⁸`), and its displacement against `x(u) − u` (rounding of
/// coordinates up to 100 m).
const ONE_WAVE_J_ABS: f64 = 1e-7;
const ONE_WAVE_D_ABS: f64 = 1e-9;

/// A directional Lipschitz constant may not exceed the full one beyond rounding.
const DIRECTIONAL_REL: f64 = 1e-12;
const DIRECTIONAL_ABS: f64 = 1e-15;

/// `k(ω(k)) = k` through the safeguarded Newton inversion (it stops at 10⁻¹⁴ relative; the
/// `tanh` of `kh` rounds the rest).
const DISPERSION_REL: f64 = 1e-11;

/// The acceptance bound on a fitted set's variance against `∫ S dω` over the band.
const VARIANCE_REL: f64 = 0.01;

fn surfaces(set: &TrochoidSet) -> Vec<(&'static str, Box<dyn WaveSurface>)> {
    vec![
        ("trochoid sum", Box::new(TrochoidSum::new(set))),
        ("Gerstner", Box::new(GerstnerSurface::new(set).unwrap())),
        ("sine set", Box::new(SineSet::new(set))),
    ]
}

/// A displacement of random direction and a length spread over five decades (1 mm – 100 m).
fn offset() -> impl Strategy<Value = DVec2> {
    (-PI..PI, -3.0f64..2.0).prop_map(|(a, e)| 10f64.powf(e) * DVec2::new(a.cos(), a.sin()))
}

fn unit3() -> impl Strategy<Value = DVec3> {
    (-PI..PI, -1.0f64..1.0).prop_map(|(a, y)| {
        let r = (1.0 - y * y).sqrt();
        DVec3::new(r * a.cos(), y, r * a.sin())
    })
}

/// Checks every bound `LipschitzSum` promises on random points `p`, `q`, a direction `d`.
fn check_lipschitz_sum(f: &dyn LipschitzSum, p: DVec3, q: DVec3, d: DVec3, t: f64) -> Result<(), TestCaseError> {
    let bounds = f.zero_set_bounds();
    let mut sum = 0.0;
    for i in 0..f.component_count() {
        let (np, nq) = (f.component(i, p), f.component(i, q));
        sum += np;
        let l = f.component_lipschitz(i);
        prop_assert!(np.is_finite() && l.is_finite());
        prop_assert!((np - nq).abs() <= l * (p - q).length() * (1.0 + SLACK_REL) + SLACK_ABS, "component {i}: L");
        let ld = f.component_directional_lipschitz(i, d);
        prop_assert!(ld <= l * (1.0 + DIRECTIONAL_REL) + DIRECTIONAL_ABS, "component {i}: L(d) = {ld} > L = {l}");
        let nt = f.component(i, p + t * d);
        prop_assert!((nt - np).abs() <= ld * t.abs() * (1.0 + SLACK_REL) + SLACK_ABS, "component {i}: L(d)");
        let m = f.component_min(i, p, q);
        for s in [0.0, 0.25, 0.5, 0.75, 1.0] {
            let on = f.component(i, p + s * (q - p));
            prop_assert!(on >= m - SLACK_ABS, "component {i}: {on} below its minimum {m}");
        }
    }
    let v = f.value(p);
    prop_assert!((v - sum).abs() <= ROUND_ABS * (1.0 + v.abs()) + SLACK_ABS, "value {v} ≠ Σ components {sum}");
    // Above the box F > 0, below it F < 0: no zero outside.
    // A micrometre outside the slab, far beyond the rounding of the height.
    let (top, bottom) = (DVec3::new(p.x, bounds.max.y + FD_STEP, p.z), DVec3::new(p.x, bounds.min.y - FD_STEP, p.z));
    prop_assert!(f.value(top) > 0.0 && f.value(bottom) < 0.0);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn heights_stay_within_bounds_and_are_finite(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        for (name, s) in surfaces(&set) {
            let (lo, hi) = s.height_bounds();
            let h = s.height(x, z, t);
            prop_assert!(h.is_finite() && lo - ROUND_ABS <= h && h <= hi + ROUND_ABS, "{name}: {h} ∉ [{lo}, {hi}]");
            prop_assert!(s.gradient(x, z, t).is_finite() && s.velocity(x, z, t).is_finite());
            prop_assert!(s.displacement(x, z, t).is_finite() && s.jacobian(x, z, t).is_finite());
            let n = s.normal(x, z, t);
            prop_assert!((n.length() - 1.0).abs() < ROUND_ABS && n.y > 0.0);
        }
    }

    #[test]
    fn heights_are_lipschitz_with_the_stated_constant(set in trochoid_set(12), (x, z, t) in point_and_time(), d in offset()) {
        for (name, s) in surfaces(&set) {
            let l = s.max_slope();
            let (hp, hq) = (s.height(x, z, t), s.height(x + d.x, z + d.y, t));
            let (dh, bound) = ((hp - hq).abs(), l * d.length());
            prop_assert!(dh <= bound * (1.0 + SLACK_REL) + SLACK_ABS, "{name}: |Δh| = {dh} > L|Δp| = {bound}");
            prop_assert!(s.gradient(x, z, t).length() <= l * (1.0 + SLACK_REL) + SLACK_ABS, "{name}: |∇h| > L");
        }
    }

    #[test]
    fn gradients_match_central_differences(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        let h = FD_STEP;
        for (name, s) in surfaces(&set) {
            let g = s.gradient(x, z, t);
            let fd = DVec2::new(
                (s.height(x + h, z, t) - s.height(x - h, z, t)) / (2.0 * h),
                (s.height(x, z + h, t) - s.height(x, z - h, t)) / (2.0 * h),
            );
            let scale = 1.0 + s.max_slope();
            prop_assert!((g - fd).length() <= FD_REL * scale, "{name}: ∇h = {g}, FD {fd}");
        }
    }

    /// The Gerstner slope bound holds where it is hardest to hold: a few long-crested waves of
    /// high steepness (`ΣQ` up to 0.97), their `kA` and `Q` drawn apart, the gradient searched
    /// for its largest value over rest positions (a lattice over the longest wave, then a local
    /// climb). The gradient is `J⁻¹∇ᵤh` at `x = forward(u)`, read through the inversion.
    #[test]
    fn gerstner_slopes_stay_below_the_slope_bound(
        waves in prop::collection::vec((0.2f64..3.0, -0.4f64..0.4, 0.0..TAU, 0.05f64..1.0, 0.3f64..3.0), 1..5),
        total_q in 0.3f64..0.97,
    ) {
        let weight: f64 = waves.iter().map(|w| w.3).sum();
        let set = TrochoidSet::new(
            waves
                .iter()
                .map(|&(k, dir, ph, share, ratio)| {
                    let q = total_q * share / weight;
                    // kA = ratio·Q (ratio 0.3–3), so that Qᵢ/kᵢAᵢ differs between waves.
                    Trochoid::new(q * ratio / k, k, dir, (G * k).sqrt(), ph, q).unwrap()
                })
                .collect(),
        );
        let g = GerstnerSurface::new(&set).unwrap();
        let f = g.at_time(0.0);
        let bound = g.slope_bound();
        let crude: f64 = set.waves().iter().map(|w| w.wavenumber() * w.amplitude()).sum::<f64>() / (1.0 - g.total_steepness());
        prop_assert!(bound <= crude * (1.0 + 1e-12), "ρ* = {bound} above the crude bound {crude}");
        let slope = |u: DVec2| {
            let p = f.forward(u);
            f.gradient(p.x, p.z).length()
        };
        let longest = set.waves().iter().map(|w| TAU / w.wavenumber()).fold(0.0, f64::max);
        let (mut best, mut at) = (0.0, DVec2::ZERO);
        for i in 0..40 {
            for j in 0..40 {
                let u = DVec2::new(i as f64, j as f64) * (longest / 40.0);
                let s = slope(u);
                if s > best {
                    (best, at) = (s, u);
                }
            }
        }
        let mut h = longest / 80.0;
        while h > 1e-6 * longest {
            let mut moved = false;
            for d in [DVec2::X, -DVec2::X, DVec2::Y, -DVec2::Y] {
                let s = slope(at + h * d);
                if s > best {
                    (best, at, moved) = (s, at + h * d, true);
                }
            }
            if !moved {
                h *= 0.5;
            }
        }
        prop_assert!(best <= bound * (1.0 + SLACK_REL) + SLACK_ABS, "slope {best} at {at} above the bound {bound}");
    }

    #[test]
    fn gerstner_jacobian_and_inversion_match_the_forward_map(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        let g = GerstnerSurface::new(&set).unwrap();
        let f = g.at_time(t);
        // Inversion: the rest position maps forward onto the query point.
        let inv = f.solve(x, z);
        prop_assert!(inv.iterations < brine_waves::GERSTNER_MAX_ITERATIONS);
        let p = f.forward(inv.rest);
        let miss = DVec2::new(p.x - x, p.z - z).length();
        prop_assert!(miss <= INVERSION_MISS_M, "forward(inverse) off by {miss}");
        prop_assert!((p.y - f.height(x, z)).abs() < ROUND_ABS);
        // …and the forward map of a rest position inverts back to it (the map is one-to-one).
        let u = DVec2::new(z * 0.7 + 3.0, x * 0.3 - 5.0);
        let fu = f.forward(u);
        let back = f.rest_position(fu.x, fu.z);
        let off = (back - u).length();
        prop_assert!(off <= ROUND_TRIP_M / (1.0 - g.total_steepness()), "round trip off by {off}");
        // Jacobian: det of the central-difference derivative of u ↦ x at the rest position.
        let h = FD_STEP;
        let dx = (f.forward(inv.rest + DVec2::X * h) - f.forward(inv.rest - DVec2::X * h)) / (2.0 * h);
        let dz = (f.forward(inv.rest + DVec2::Y * h) - f.forward(inv.rest - DVec2::Y * h)) / (2.0 * h);
        let det = dx.x * dz.z - dx.z * dz.x;
        prop_assert!((det - f.jacobian(x, z)).abs() < JACOBIAN_FD_ABS, "J = {}, FD {det}", f.jacobian(x, z));
        prop_assert!(f.jacobian(x, z) >= 1.0 - g.total_steepness() - ROUND_ABS);
    }

    #[test]
    fn one_trochoid_jacobian_is_the_particle_map_derivative(
        (a, k, dir, ph, q) in (0.01f64..1.5, 0.05f64..3.0, -PI..PI, 0.0..TAU, 0.0f64..0.99),
        u in -100.0f64..100.0,
    ) {
        // x(u) = u − (Q/k) sin φ(u) along d̂: dx/du = 1 − Q cos φ; the trochoid sum's Jacobian at
        // x(u) must equal it (central difference, step 10⁻⁶).
        let w = Trochoid::new(a, k, dir, (G * k).sqrt(), ph, q).unwrap();
        let sum = TrochoidSum::new(&TrochoidSet::new(vec![w]));
        let along = |s: f64| s - q / k * (k * s + ph).sin();
        let h = FD_STEP;
        let fd = (along(u + h) - along(u - h)) / (2.0 * h);
        let d = w.direction_vector();
        let x = along(u) * d;
        prop_assert!((sum.jacobian(x.x, x.y, 0.0) - fd).abs() < ONE_WAVE_J_ABS);
        let disp = sum.displacement(x.x, x.y, 0.0);
        prop_assert!((disp - (along(u) - u) * d).length() < ONE_WAVE_D_ABS);
    }

    #[test]
    fn particle_velocity_satisfies_the_kinematic_condition(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        // A surface particle stays on the surface: v_y = ∂h/∂t + ∇h·v_xz (exact for the Gerstner
        // sum; for a sine set v_y = ∂h/∂t, its points moving only vertically). The trochoid sum
        // has its own tests (tests/kinematics.rs).
        let dt = FD_STEP;
        let g = GerstnerSurface::new(&set).unwrap();
        let v = g.velocity(x, z, t);
        let dhdt = (g.height(x, z, t + dt) - g.height(x, z, t - dt)) / (2.0 * dt);
        let rhs = dhdt + g.gradient(x, z, t).dot(DVec2::new(v.x, v.z));
        let scale: f64 = set.waves().iter().map(|w| w.amplitude() * w.omega()).sum::<f64>() * (1.0 + g.slope_bound());
        prop_assert!((v.y - rhs).abs() < FD_REL * scale, "Gerstner: v_y = {}, ∂h/∂t + ∇h·v = {rhs}", v.y);
        let s = SineSet::new(&set);
        let dhdt = (s.height(x, z, t + dt) - s.height(x, z, t - dt)) / (2.0 * dt);
        prop_assert!((s.velocity(x, z, t).y - dhdt).abs() < FD_REL * scale);
    }

    #[test]
    fn lipschitz_sums_keep_their_bounds(
        set in trochoid_set(12),
        (x, z, t) in point_and_time(),
        y in -4.0f64..4.0,
        d in unit3(),
        (e, q_dir) in (-3.0f64..1.5, unit3()),
        (step_e, step_sign) in (-3.0f64..1.7, any::<bool>()),
    ) {
        // Separations and steps over four decades (1 mm – 30/50 m): short ones test the slope
        // bound, long ones the value bounds.
        let p = DVec3::new(x, y, z);
        let q = p + 10f64.powf(e) * q_dir;
        let step = if step_sign { 10f64.powf(step_e) } else { -(10f64.powf(step_e)) };
        let sum = TrochoidSum::new(&set);
        check_lipschitz_sum(&sum.at_time(t), p, q, d, step)?;
        let sine = SineSet::new(&set);
        check_lipschitz_sum(&sine.at_time(t), p, q, d, step)?;
        let gerstner = GerstnerSurface::new(&set).unwrap();
        check_lipschitz_sum(&gerstner.at_time(t), p, q, d, step)?;
    }

    #[test]
    fn simd_lanes_match_the_scalar_sums(set in trochoid_set(12), (x, z, t) in point_and_time()) {
        let scale = set.total_amplitude();
        let sum = TrochoidSum::new(&set);
        let f = sum.at_time(t);
        prop_assert!((f.height_lanes(x, z) - f.height(x, z)).abs() <= LANES_ABS * (1.0 + scale));
        let sine = SineSet::new(&set);
        let g = sine.at_time(t);
        prop_assert!((g.height_lanes(x, z) - g.height(x, z)).abs() <= LANES_ABS * (1.0 + scale));
        // Gerstner: two inversions that both stop at |u + D(u) − x| ≤ τ give heights within 2τL
        // (GerstnerField::height_lanes), plus the rounding of the sums.
        let gerstner = GerstnerSurface::new(&set).unwrap();
        let h = gerstner.at_time(t);
        let tau = brine_waves::GERSTNER_TOLERANCE_M
            + brine_waves::GERSTNER_TOLERANCE_REL * (DVec2::new(x, z).length() + scale);
        let bound = 2.0 * tau * gerstner.slope_bound() + LANES_ABS * (1.0 + scale);
        prop_assert!((h.height_lanes(x, z) - h.height(x, z)).abs() <= bound);
        let (xs, zs) = ([x, x + 1.0, x - 7.5], [z, z * 0.5, -z]);
        let mut out = [0.0; 3];
        let list: [(&dyn WaveSurface, f64); 3] =
            [(&sum, LANES_ABS * (1.0 + scale)), (&sine, LANES_ABS * (1.0 + scale)), (&gerstner, 2.0 * bound)];
        for (s, tol) in list {
            s.heights(&xs, &zs, t, &mut out);
            for j in 0..3 {
                prop_assert!((out[j] - s.height(xs[j], zs[j], t)).abs() <= tol);
            }
        }
    }

    #[test]
    fn spectra_are_finite_and_non_negative(
        u10 in 0.5f64..60.0,
        fetch in 100.0f64..1e7,
        depth in 0.5f64..1e4,
        omega in 0.01f64..200.0,
    ) {
        let list: Vec<Box<dyn Spectrum>> = vec![
            Box::new(PiersonMoskowitz::from_u10(u10).unwrap()),
            Box::new(Jonswap::from_fetch(u10, fetch).unwrap()),
            Box::new(Tma::from_fetch(u10, fetch, depth).unwrap()),
            Box::new(Phillips::from_wind(u10).unwrap()),
            Box::new(Elfouhaily::from_fetch(u10, fetch).unwrap()),
        ];
        for s in &list {
            let v = s.s_omega(omega);
            prop_assert!(v.is_finite() && v >= 0.0, "S({omega}) = {v}");
            let k = s.dispersion().wavenumber(omega);
            prop_assert!(k.is_finite() && k > 0.0 && s.s_k(k).is_finite() && s.s_k(k) >= 0.0);
            prop_assert!(s.peak_omega().is_finite() && s.peak_omega() > 0.0);
        }
    }

    #[test]
    fn spreadings_sample_inside_their_support(omega in 0.05f64..30.0, u in 0.0f64..1.0, u10 in 1.0f64..40.0) {
        let e = Elfouhaily::fully_developed(u10).unwrap();
        let list: Vec<(Box<dyn Spreading>, f64)> = vec![
            (Box::new(CosineTwoS::hasselmann(0.8).unwrap()), PI),
            (Box::new(CosineTwoS::mitsuyasu(0.8, u10).unwrap()), PI),
            (Box::new(DonelanBanner::new(0.8).unwrap()), PI),
            (Box::new(CosineSquared::downwind()), FRAC_PI_2),
            (Box::new(e.spreading(brine_waves::Directions::Downwind)), FRAC_PI_2),
            (Box::new(e.spreading(brine_waves::Directions::BothWays)), PI),
        ];
        for (d, half) in &list {
            let th = d.sample(omega, u);
            prop_assert!(th.is_finite() && th.abs() <= half + ROUND_ABS, "θ = {th}");
            let dens = d.density(th, omega);
            prop_assert!(dens.is_finite() && dens >= 0.0);
        }
    }

    #[test]
    fn dispersion_inverts_for_any_depth(depth in 0.1f64..1e4, k in 1e-4f64..1e4, capillary in any::<bool>()) {
        let d = if capillary {
            Dispersion::capillary_gravity(depth, 0.074, 1025.0).unwrap()
        } else {
            Dispersion::finite_depth(depth).unwrap()
        };
        let w = d.omega(k);
        prop_assert!(w.is_finite() && w > 0.0);
        prop_assert!((d.wavenumber(w) / k - 1.0).abs() < DISPERSION_REL);
        prop_assert!(d.group_velocity(k) > 0.0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn fits_respect_the_cap_and_the_variance(
        kind in 0usize..5,
        u10 in 2.0f64..40.0,
        n in 30usize..120,
        seed in any::<u64>(),
        choppiness in 0.0f64..20.0,
        wind_direction in -PI..PI,
    ) {
        let s: Box<dyn Spectrum> = match kind {
            0 => Box::new(PiersonMoskowitz::from_u10(u10).unwrap()),
            1 => Box::new(Jonswap::from_fetch(u10, 5e4).unwrap()),
            2 => Box::new(Tma::from_fetch(u10, 5e4, 15.0).unwrap()),
            3 => Box::new(Phillips::from_wind(u10).unwrap()),
            _ => Box::new(Elfouhaily::from_fetch(u10, 5e4).unwrap()),
        };
        let d = DonelanBanner::new(s.peak_omega()).unwrap();
        let o = FitOptions { choppiness, wind_direction, ..FitOptions::default() };
        let set = fit_trochoids(s.as_ref(), &d, n, seed, &o).unwrap();
        prop_assert_eq!(set.len(), n);
        prop_assert!(set.total_steepness() <= o.max_total_steepness + ROUND_ABS);
        for w in set.waves() {
            prop_assert!(w.amplitude().is_finite() && w.wavenumber() > 0.0 && w.phase() >= 0.0 && w.phase() < TAU);
            prop_assert!((w.direction() - wind_direction).abs() <= PI + ROUND_ABS);
        }
        let wp = s.peak_omega();
        let band = s.variance_between(0.5 * wp, 12.0 * wp);
        prop_assert!((set.variance() / band - 1.0).abs() < VARIANCE_REL);
        prop_assert!(GerstnerSurface::new(&set).is_ok());
    }
}
