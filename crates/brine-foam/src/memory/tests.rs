use super::*;

/// Standard error of a share measured on 40 000 points whose patch variable is correlated
/// over ~1 first-octave cell (a few thousand independent cells): ≈ 0.01; three of them.
const AREA_TOL: f64 = 0.03;

fn memory() -> FoamMemory {
    FoamMemory::new(&FoamMemoryParams::default(), 0.4).unwrap()
}

/// The documented threshold `θ(a) = A₀ e^{−a/τ} min(1, (T − a)/Δt)`.
fn theta(mem: &FoamMemory, age: f64) -> f64 {
    FOAM_DENSITY * (-age / mem.decay_time()).exp() * ((mem.length() - age) / mem.step()).clamp(0.0, 1.0)
}

/// Points spread over many patch cells.
fn points() -> impl Iterator<Item = [f64; 2]> {
    (0..200).flat_map(|i| (0..200).map(move |j| [f64::from(i) * 1.37 + 0.11, f64::from(j) * 1.41 - 0.23]))
}

#[test]
fn the_patch_variable_is_uniform() {
    let mem = memory();
    let n = 40_000.0;
    for q in [0.1, 0.25, 0.5, 0.75, 0.9] {
        let share = points().filter(|p| mem.patches.at(p[0], p[1], 0.0) < q).count() as f64 / n;
        assert!((share - q).abs() < AREA_TOL, "P(m < {q}) = {share}");
    }
}

/// One breaking event covering everything at one instant leaves foam whose area decays as
/// `e^{−a/τ}` (Monahan 1971): the area law is exact in the mean, whatever the patches' shape.
#[test]
fn foam_area_decays_with_monahans_time_constant() {
    let mem = memory();
    let t0 = 10.0;
    for age in [0.5, 1.0, 2.0, 4.0, 5.9] {
        let t = t0 + age;
        let mean: f64 = points()
            .map(|p| mem.compose(p, t, 0.0, 0.0, |s| if (s.time_s - t0).abs() < 1e-9 { 1.0 } else { 0.0 }).white)
            .sum::<f64>()
            / 40_000.0;
        let expected = theta(&mem, age);
        assert!((mean - expected).abs() < AREA_TOL, "age {age}: area {mean}, e^(-a/τ) {expected}");
    }
}

/// A far pixel, whose footprint hides every patch, sees the mean survival exactly.
#[test]
fn an_unresolved_pixel_sees_the_mean_survival() {
    let mem = memory();
    let w = mem.compose([3.0, 4.0], 11.1, 1e3, 0.0, |s| if s.index == 2 { 1.0 } else { 0.0 });
    let age = mem.instant(11.1, 2).1;
    assert!((w.white - theta(&mem, age)).abs() < 1e-12);
}

/// Points of the midpoint rule over the patch variable `m ∈ [0, 1]`: the step is smooth, so the
/// rule's error is `O(n⁻²)` of its curvature, `≪ 10⁻⁶` here.
const STEP_QUADRATURE_POINTS: usize = 20_000;

/// `∫₀¹ S(θ, m) dm` by the midpoint rule.
fn survival_area(theta: f64) -> f64 {
    let n = STEP_QUADRATURE_POINTS as f64;
    (0..STEP_QUADRATURE_POINTS).map(|i| survival_step(theta, (i as f64 + 0.5) / n)).sum::<f64>() / n
}

proptest::proptest! {
    /// The fringe keeps the area law: over a uniform patch variable the survival's mean is `θ`
    /// (the step is symmetric about `θ` and stays inside `[0, 1]`), except within
    /// `MIN_EDGE_SOFTNESS` of 0 or 1, where the smallest step spills over the end by at most half
    /// its width.
    #[test]
    fn the_fringe_keeps_the_area_law(theta in 0.0..=1.0f64) {
        let area = survival_area(theta);
        let tol = if theta.min(1.0 - theta) * PATCH_FRINGE < MIN_EDGE_SOFTNESS { MIN_EDGE_SOFTNESS } else { 1e-6 };
        proptest::prop_assert!((area - theta).abs() <= tol, "θ = {}: area {}", theta, area);
    }
}

/// Residual foam thins toward its edges: one breaking event that covered everything leaves, at
/// age `a`, foam whose cover is partial (between 5 % and 95 %) on the share of the foam that the
/// definition gives — the patch variable within the fringe's middle, where
/// `smoothstep(x) ∈ (0.05, 0.95)`, i.e. `x ∈ (0.1296, 0.8704)` of the fringe `θ ± ε`,
/// `ε = 0.6 min(θ, 1 − θ)` — measured on the water (so through the noise's own uniformity).
#[test]
fn residual_foam_frays_at_its_edges() {
    // Roots of 3x² − 2x³ = 0.05 and 0.95.
    let (lo, hi) = (0.129_62, 0.870_38);
    let mem = memory();
    let t0 = 10.0;
    for age in [0.5, 2.0, 4.0] {
        let (th, t) = (theta(&mem, age), t0 + age);
        let eps = 0.6 * th.min(1.0 - th);
        let partial = 2.0 * eps * (hi - lo);
        let foamed = th - eps + 2.0 * eps * hi;
        let covers: Vec<f64> = points()
            .map(|p| mem.compose(p, t, 0.0, 0.0, |s| if (s.time_s - t0).abs() < 1e-9 { 1.0 } else { 0.0 }).white)
            .collect();
        let n = covers.len() as f64;
        let got_partial = covers.iter().filter(|&&c| c > 0.05 && c < 0.95).count() as f64 / n;
        let got_foamed = covers.iter().filter(|&&c| c > 0.05).count() as f64 / n;
        assert!((got_partial - partial).abs() < AREA_TOL, "age {age}: partial {got_partial} against {partial}");
        assert!((got_foamed - foamed).abs() < AREA_TOL, "age {age}: foamed {got_foamed} against {foamed}");
        assert!(
            got_partial / got_foamed > 0.25,
            "age {age}: the fringe holds {} of the foam",
            got_partial / got_foamed
        );
    }
}

#[test]
fn streaks_are_longer_along_the_wind() {
    let p = FoamMemoryParams { streak_stretch: 6.0, wind_direction_rad: 0.0, ..FoamMemoryParams::default() };
    let mem = FoamMemory::new(&p, 0.4).unwrap();
    // Mean absolute change of the patch noise over 1 m along x (the wind) and along z.
    let diff = |dx: f64, dz: f64| -> f64 {
        points().map(|q| (mem.patches.raw(q[0] + dx, q[1] + dz, 0.0) - mem.patches.raw(q[0], q[1], 0.0)).abs()).sum()
    };
    let (along, across) = (diff(1.0, 0.0), diff(0.0, 1.0));
    assert!(along < 0.5 * across, "along {along}, across {across}");
}

/// A clock made once for a time gives, bit for bit, the survivals and white water each point
/// computes alone, at that time; a time whose newest instant is another age is not its.
#[test]
fn the_clock_gives_what_each_point_computes() {
    let mem = memory();
    let t = 7.3;
    let clock = mem.clock(t);
    assert!(clock.holds(&mem, t) && !clock.holds(&mem, t + 0.1));
    for (i, p) in points().step_by(97).enumerate() {
        let footprint = [0.0, 0.05, 0.4, 3.0][i % 4];
        let (mut a, mut b) = ([0.0; MAX_MEMORY_INSTANTS], [0.0; MAX_MEMORY_INSTANTS]);
        let n = mem.survivals(p, t, footprint, &mut a);
        assert_eq!(mem.survivals_at(&clock, p, footprint, &mut b), n);
        assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits), "{p:?}");
        let sources: Vec<f64> = (0..n).map(|j| ((j as f64 + p[0]) * 0.37).sin().abs()).collect();
        assert_eq!(mem.combine(t, 0.1, &a[..n], &sources), mem.combine_at(&clock, 0.1, &a[..n], &sources));
    }
}

#[test]
fn white_water_is_a_pure_function_of_place_and_time() {
    let mem = memory();
    let src = |s: &MemorySample| (0.5 + 0.5 * (s.time_s * 1.3).sin()).max(0.0);
    let a = mem.compose([1.0, 2.0], 7.3, 0.1, 0.2, src);
    let b = memory().compose([1.0, 2.0], 7.3, 0.1, 0.2, src);
    assert_eq!(a, b);
    assert!((0.0..=1.0).contains(&a.white) && a.white >= a.active && a.white >= a.residual);
}

/// On a tile, the foam repeats: the same survivals one tile away, and the patch variable still
/// uniform.
#[test]
fn tiled_foam_repeats_over_its_tile() {
    for (u10, dir) in [(8.0, 0.3), (18.0, 1.1)] {
        let tile = 150.0;
        let params = FoamMemoryParams { tile_m: Some(tile), ..FoamMemoryParams::for_wind(u10, dir, 5) };
        let mem = FoamMemory::new(&params, 0.4).unwrap();
        let (mut a, mut b) = ([0.0; MAX_MEMORY_INSTANTS], [0.0; MAX_MEMORY_INSTANTS]);
        for u in [[1.0, 2.0], [-40.0, 77.0]] {
            for shift in [[tile, 0.0], [0.0, tile], [-tile, 2.0 * tile]] {
                let na = mem.survivals(u, 3.3, 0.0, &mut a);
                let nb = mem.survivals([u[0] + shift[0], u[1] + shift[1]], 3.3, 0.0, &mut b);
                assert_eq!(na, nb);
                assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-9));
                let (ea, eb) =
                    (mem.edge_noise(u[0], u[1], 0.0).0, mem.edge_noise(u[0] + shift[0], u[1] + shift[1], 0.0).0);
                assert!((ea - eb).abs() < 1e-9);
            }
        }
        // The stretch and direction stay near the wind's.
        let p = periodic_patches(tile, params.patch_wavelength_m, params.streak_stretch, dir);
        let turn = (p.n as f64).atan2(p.m as f64) - dir;
        assert!(turn.abs() < 0.1, "{p:?}");
        let s = p.g as f64 / p.stretch_divisor as f64;
        assert!((s / params.streak_stretch).ln().abs() < 0.25, "{p:?}");
        let in_range = points()
            .filter(|u| {
                let m = mem.patches.at(u[0], u[1], 0.0);
                m < 0.3
            })
            .count();
        let share = in_range as f64 / points().count() as f64;
        assert!((share - 0.3).abs() < 0.03, "{share}");
    }
}

#[test]
fn the_bisection_finds_the_threshold() {
    let alpha = calibrate_threshold(0.3, (-1.0, 1.0), 1e-10, |a| 0.5 * (1.0 + a));
    assert!((alpha - (-0.4)).abs() < 1e-9);
}

proptest::proptest! {
    #[test]
    fn the_bisection_meets_any_monotone_cover(
        root in -3.0..3.0f64, width in 1e-3..2.0f64, target in 0.01..0.99f64, tol in 1e-8..1e-2f64,
    ) {
        // A logistic cover through `target` at `root`.
        let shift = width * (target / (1.0 - target)).ln();
        let cover = |a: f64| 1.0 / (1.0 + (-(a - root + shift) / width).exp());
        let alpha = calibrate_threshold(target, (-5.0, 5.0), tol, cover);
        proptest::prop_assert!((alpha - root).abs() <= tol, "{} against {}", alpha, root);
    }
}

#[test]
fn bad_parameters_are_named() {
    let e = FoamMemory::new(&FoamMemoryParams { streak_stretch: 0.5, ..FoamMemoryParams::default() }, 0.4);
    assert!(matches!(e, Err(FoamError::OutOfRange(brine_core::OutOfRange { name: "streak_stretch", .. }))));
    let e = FoamMemory::new(&FoamMemoryParams { step_s: 10.0, ..FoamMemoryParams::default() }, 0.4);
    assert!(matches!(e, Err(FoamError::OutOfRange(brine_core::OutOfRange { name: "step_s", .. }))));
}

/// Ageing foam is drawn as holes, not as a dimming: over the sea the drawn reflectance
/// `white × brightness` keeps its mean `w b` at every footprint (from a point to one that hides
/// the lace), and where a pixel resolves the lace a point of old, dim foam is either bright foam
/// (its brightness within the thickness shading of 1) or open water, but in the lace's softened
/// edges: a band of `±0.3 min(b, 1 − b)` of its uniform variable, so at most `0.6 min(b, 1 − b)`
/// of the area.
#[test]
fn ageing_foam_opens_holes_of_the_same_mean() {
    let mem = memory();
    let n = 40_000.0;
    for (white, brightness, solid) in [(1.0, 0.3, true), (1.0, 0.6, true), (0.5, 0.4, false)] {
        let ww = WhiteWater { active: 0.0, residual: white, white, brightness };
        // Round footprints, and long ones (a pixel seen 6° and 3° above the sea) read at probes.
        let footprints = [0.0, 0.04, 0.12, 1.0].map(EllipticalFootprint::round).into_iter().chain(
            [(0.005, 0.05), (0.01, 0.2)].map(|(a, b)| EllipticalFootprint::new(a, b, glam::DVec2::new(0.8, 0.6))),
        );
        for fp in footprints {
            let laced: Vec<WhiteWater> = points().map(|p| mem.laced(ww, p[0], p[1], &fp)).collect();
            let mean = laced.iter().map(|l| l.white * l.brightness).sum::<f64>() / n;
            assert!(
                (mean - white * brightness).abs() < AREA_TOL,
                "w {white}, b {brightness}, {fp:?}: mean {mean}, expected {}",
                white * brightness
            );
            let cover = laced.iter().map(|l| l.white).sum::<f64>() / n;
            assert!((cover - white).abs() < AREA_TOL, "w {white}, {fp:?}: mean cover {cover}");
        }
        if solid {
            // Thickness shading of both laces: 1 ± 0.2 each.
            let (lo, hi) = (0.8 * 0.8, 1.2 * 1.2);
            let in_between = points()
                .map(|p| mem.laced(ww, p[0], p[1], &EllipticalFootprint::round(0.0)).brightness)
                .filter(|&b| b > 0.05 && b < lo)
                .count() as f64
                / n;
            let edges = 0.6 * brightness.min(1.0 - brightness);
            assert!(in_between < edges + AREA_TOL, "b {brightness}: {in_between} of the points dim but not open");
            assert!(
                points().all(|p| mem.laced(ww, p[0], p[1], &EllipticalFootprint::round(0.0)).brightness <= hi + 1e-12)
            );
        }
    }
}

/// Where the lace leaves open water, no white water of any kind is left there (the active and
/// residual covers follow the white one to 0), and the brightness is the mean's; where it does
/// not, the union of active and residual is the laced cover.
#[test]
fn open_water_in_the_lace_holds_no_white_water() {
    let mem = memory();
    let ww = WhiteWater { active: 0.03, residual: 0.12, white: 1.0 - 0.97 * 0.88, brightness: 0.7 };
    let (mut open, mut foam) = (0, 0);
    for p in points() {
        let l = mem.laced(ww, p[0], p[1], &EllipticalFootprint::round(0.0));
        if l.white <= 0.0 {
            open += 1;
            assert!(l.active <= 0.0 && l.residual <= 0.0, "{l:?}");
            assert_eq!(l.brightness.to_bits(), ww.brightness.to_bits());
        } else {
            foam += 1;
            let union = 1.0 - (1.0 - l.active) * (1.0 - l.residual);
            assert!((union - l.white).abs() < 1e-12, "{l:?}");
        }
    }
    // A cover of 0.15 drawn as lace: most of the sea open, some of it foam.
    assert!(open > 20_000 && foam > 2_000, "open {open}, foam {foam}");
}
