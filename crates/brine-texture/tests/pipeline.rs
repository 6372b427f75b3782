//! The pipeline on the shipped example photos: seams, determinism, reachability, the walk, shape
//! from shading, bad inputs.

use std::path::{Path, PathBuf};

use brine_texture::{
    HeightField, OceanParams, PhotoOcean, Pinhole, ProjectionOptions, ProjectionView, RelightRule, SynthesisParams,
    Texture, TextureError, border_differences, frame_distance, relight_intensity, render_projection, seam_differences,
    seam_z_score, synthesize_tileable, walk_links, wrap_border_test,
};
use glam::DVec3;

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples").join(name)
}

/// A 96 × 96 crop of an example photo (keeps the tests fast in the dev profile).
fn crop(name: &str) -> Texture {
    Texture::load(&example(name), name).unwrap().window(40, 70, 96, 96)
}

/// Small sizes: patches of 24 texels with 4-texel boundary zones (cells of 16), 64-texel tiles.
fn params() -> OceanParams {
    OceanParams {
        synthesis: SynthesisParams { patch_size: 24, boundary_width: 4, ..SynthesisParams::default() },
        small_size: 64,
        main_size: 64,
        bed_size: 64,
        frames: 5,
        links_per_frame: 2,
        morph_steps: 3,
        mesh_spacing: 16,
        ..OceanParams::default()
    }
}

fn ocean(seed: u64) -> PhotoOcean {
    PhotoOcean::new(&crop("small-waves.png"), &crop("main-structure.png"), None, &params(), seed, &|_| {}).unwrap()
}

/// Standard deviations from the mean of the interior lines within which each wrap line must lie:
/// a seamless wrap is one more line of the texture. Three standard deviations leave a 0.3 %
/// chance per line of a false alarm for Gaussian line means.
const SEAM_SIGMAS: f64 = 3.0;

/// A seamless tile's wrap is one more cell border: the construction is invariant under
/// translations by whole cells, so the wrap's cell-long segments are draws from the population of
/// the interior border segments (`wrap_border_test`; 12 wrap and 60 interior segments here). The
/// Mann–Whitney rank statistic `z_U` of the wrap segments is then standard normal whatever the
/// segments' distribution (sun glitter makes it heavy-tailed, so no Gaussian test), and
/// `|z_U| ≤ 3.29` is the two-sided test at significance 10⁻³. Calibrated on 100 seeds per
/// example photo: the tiles' `z_U` have standard deviations 0.86 and 1.03 and `|z_U| ≤ 2.7`; the
/// photos score 5.4 (the largest value possible: every wrap segment above every interior one)
/// and 4.6.
///
/// The wrap is *not* compared with the mean over all neighbours: cell borders lie in the
/// feathered zones, where two patches blend with weights ≈ ½ and the neighbour differences of a
/// blend of two independent patches shrink to √(½² + ½²) ≈ 0.71 of one patch's (1 for identical
/// patches); with only 12 wrap segments that ratio is noisy (0.50–1.73 over the seeds, mean 0.89).
const WRAP_Z: f64 = 3.29;

fn wrap_sigmas(t: &Texture) -> f64 {
    seam_z_score(t)
}

fn assert_seamless(t: &Texture, what: &str) {
    let z = wrap_sigmas(t);
    assert!(z <= SEAM_SIGMAS, "{what}: the wrap lines are {z:.1} standard deviations from the interior lines");
}

#[test]
fn tileable_synthesis_has_no_seam_and_the_photo_has_one() {
    for name in ["main-structure.png", "small-waves.png"] {
        let photo = crop(name);
        let tile = synthesize_tileable(&photo, 96, 96, &params().synthesis, 5).unwrap();
        assert_seamless(&tile, name);
        let step = params().synthesis.step();
        let t = wrap_border_test(&tile, step).unwrap();
        assert_eq!(t.segments, (12, 60));
        assert!(
            t.rank_z.abs() <= WRAP_Z,
            "{name}: across the wrap {:.2}, interior cell borders {:.2} ± {:.2} (z_U = {:.2})",
            t.wrap,
            t.borders,
            t.standard_error,
            t.rank_z
        );
        // `border_differences` is the interior borders' mean by another route.
        assert!((border_differences(&tile, step) - t.borders).abs() <= ROUTE_LEVELS);
        // The test can fail: the photo itself does not tile.
        let p = wrap_border_test(&photo, step).unwrap();
        assert!(
            p.rank_z > WRAP_Z,
            "{name}: photo wrap {:.2} vs borders {:.2}, z_U = {:.1}",
            p.wrap,
            p.borders,
            p.rank_z
        );
        let (wrap, inside) = seam_differences(&photo);
        assert!(wrap > inside, "{name}: photo wrap {wrap:.2} vs inside {inside:.2}");
        assert!(wrap_sigmas(&photo) > SEAM_SIGMAS, "{name}: the photo's wrap is {:.1} σ", wrap_sigmas(&photo));
    }
}

#[test]
fn basis_frames_and_their_morphs_tile() {
    let o = ocean(11);
    for (k, f) in o.sequence().frames.iter().enumerate() {
        assert_seamless(f, &format!("basis frame {k}"));
    }
    for n in [1, 4, 7] {
        let f = o.frame(n);
        assert!(f.position.alpha > 0.0);
        assert_seamless(&f.small.colour, &format!("in-between at frame {n}"));
    }
    assert_seamless(o.main_texture(), "main structure");
}

#[test]
fn the_same_seed_gives_the_same_frames() {
    let camera = Pinhole::from_angles(DVec3::new(0.0, 4.0, 0.0), 225.0, -25.0, 55.0, 48, 40).unwrap();
    let view = ProjectionView::with_background(&camera, [180, 190, 210]);
    let render = |o: &PhotoOcean, n| render_projection(&o.frame(n), &view, &ProjectionOptions::default()).into_raw();
    let (a, b, c) = (ocean(3), ocean(3), ocean(4));
    for n in [0, 5, 13] {
        assert_eq!(render(&a, n), render(&b, n), "frame {n}");
    }
    assert_eq!(a.sequence(), b.sequence());
    assert_ne!(a.sequence().frames[1], c.sequence().frames[1], "another seed gives another sequence");
}

#[test]
fn every_frame_reaches_every_other() {
    let o = ocean(2);
    let g = o.graph();
    assert_eq!(g.frames(), params().frames);
    for i in 0..g.frames() {
        assert!(g.reachable_from(i).iter().all(|&r| r), "frame {i} cannot reach every frame");
    }
    assert!(g.outgoing(0).len() >= 2, "a walk needs a choice to be non-repeating");
}

#[test]
fn the_walk_is_seamless_and_does_not_repeat() {
    let o = ocean(8);
    let g = o.graph();
    let longest_link = g.links().iter().map(|l| l.distance).fold(0.0, f64::max);
    // Seamless: no displayed frame jumps further from the previous one than a whole link.
    let frames: Vec<Texture> = (0..40).map(|n| o.frame(n).small.colour).collect();
    for n in 1..frames.len() {
        let step = frame_distance(&frames[n - 1], &frames[n]);
        assert!(step <= longest_link, "frame {n}: step {step:.2} > longest link {longest_link:.2}");
    }
    // Frames at link ends are the basis frames themselves.
    let steps = params().morph_steps as u64;
    for n in (0..40).step_by(steps as usize) {
        let f = o.frame(n);
        assert_eq!(f.small.colour, o.sequence().frames[f.position.from]);
    }
    // Non-repeating: the link sequence has no period up to 300 over 3000 links.
    let links = walk_links(g, o.seed(), 3000);
    for p in 1..=300 {
        assert!((1000..3000).any(|i| links[i] != links[i - p]), "the walk repeats with period {p}");
    }
}

/// A height field and its "photo": intensity affine in height (the model Eq. 1 inverts), 8-bit.
fn synthetic(w: usize, h: usize) -> (Vec<f64>, Texture) {
    let height: Vec<f64> = (0..w * h)
        .map(|k| {
            let (x, y) = ((k % w) as f64, (k / w) as f64);
            0.8 * (0.2 * x).sin() * (0.13 * y).cos() + 0.3 * (0.05 * x + 0.31 * y).sin()
        })
        .collect();
    let (lo, hi) = height.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let tex = Texture::from_fn(w, h, |i, j| {
        let v = (30.0 + 180.0 * (height[j * w + i] - lo) / (hi - lo)).round() as f32;
        [v, v, v]
    });
    (height, tex)
}

/// Least-squares fit `r ≈ a h + b`; returns `(a, b, largest residual)`.
fn affine_fit(h: &[f64], r: &[f64]) -> (f64, f64, f64) {
    let n = h.len() as f64;
    let (mh, mr) = (h.iter().sum::<f64>() / n, r.iter().sum::<f64>() / n);
    let cov: f64 = h.iter().zip(r).map(|(a, b)| (a - mh) * (b - mr)).sum();
    let var: f64 = h.iter().map(|a| (a - mh).powi(2)).sum();
    let a = cov / var;
    let b = mr - a * mh;
    let worst = h.iter().zip(r).map(|(x, y)| (y - a * x - b).abs()).fold(0.0, f64::max);
    (a, b, worst)
}

#[test]
fn shape_from_shading_recovers_a_known_height_field_up_to_an_affine_map() {
    let (w, h) = (64, 48);
    let (truth, photo) = synthetic(w, h);
    let hf = 2.0;
    let field = HeightField::from_texture(&photo, hf, "synthetic").unwrap();
    let recovered: Vec<f64> = field.grid().values().iter().map(|&v| f64::from(v)).collect();
    let (a, _, worst) = affine_fit(&truth, &recovered);
    assert!(a > 0.0, "dark is deep: heights increase with intensity");
    // 8-bit rounding moves an intensity by at most ½ level of the 180-level range, i.e. a height
    // by δ = hf·0.5/180 from the exact affine map; the least-squares line lies within δ of that
    // map, so residuals stay below 2δ (plus f32 storage of heights ≤ 2 m: 2⁻²⁴ · 2 m ≈ 10⁻⁷ m).
    const F32_HEIGHT_M: f64 = 1e-5;
    let quantisation = 2.0 * hf * 0.5 / 180.0 + F32_HEIGHT_M;
    assert!(worst <= quantisation, "largest residual {worst} > {quantisation}");
    // Eq. 1 spans [0, hf], up to the f32 storage.
    assert!(field.min().abs() < F32_HEIGHT_M && (field.max() - hf).abs() < F32_HEIGHT_M);
}

#[test]
fn shape_from_shading_of_beer_lambert_darkening_is_nearly_affine() {
    // Deeper water is darker: I = 230 exp(−2 K_d (h_max − h)), K_d = 0.1 m⁻¹ over 2 m of relief.
    let (w, h) = (64, 48);
    let (unit, _) = synthetic(w, h);
    let (lo, hi) = unit.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let truth: Vec<f64> = unit.iter().map(|v| 2.0 * (v - lo) / (hi - lo)).collect();
    let photo = Texture::from_fn(w, h, |i, j| {
        let v = (230.0 * (-0.2 * (2.0 - truth[j * w + i])).exp()).round() as f32;
        [v, v, v]
    });
    let field = HeightField::from_texture(&photo, 2.0, "beer-lambert").unwrap();
    let recovered: Vec<f64> = field.grid().values().iter().map(|&v| f64::from(v)).collect();
    let (_, _, worst) = affine_fit(&truth, &recovered);
    // exp(−x) over x ∈ [0, Δ], Δ = 0.4, departs from its chord by at most Δ²/8 = 0.02, which is
    // 0.02/(1 − e^{−Δ}) = 6.1 % of its range; the least-squares line does no worse than the
    // chord. Plus the 8-bit rounding, 0.5 level of the 76-level range (0.7 %).
    const NEARLY_AFFINE: f64 = (0.061 + 0.007) * 2.0;
    assert!(worst <= NEARLY_AFFINE, "largest residual {worst} m");
}

#[test]
fn bad_inputs_are_clear_errors() {
    let dir = tempfile::tempdir().unwrap();
    // Missing file.
    let missing = dir.path().join("nope.png");
    let e = Texture::load(&missing, "--small").unwrap_err();
    assert!(matches!(e, TextureError::Io { .. }) && e.to_string().contains("nope.png"), "{e}");
    // Not an image.
    let text = dir.path().join("notes.txt");
    std::fs::write(&text, "not an image").unwrap();
    let e = Texture::load(&text, "--main").unwrap_err();
    assert!(matches!(e, TextureError::Decode { .. }) && e.to_string().contains("notes.txt"), "{e}");
    // An image format that is not supported (GIF).
    let gif = dir.path().join("anim.gif");
    std::fs::write(&gif, b"GIF89a\x01\x00\x01\x00\x00\x00\x00;").unwrap();
    let e = Texture::load(&gif, "--main").unwrap_err();
    assert!(matches!(e, TextureError::Decode { .. }), "{e}");
    // A corrupt PNG.
    let bad_png = dir.path().join("broken.png");
    std::fs::write(&bad_png, b"\x89PNG\r\n\x1a\nbroken").unwrap();
    let e = Texture::load(&bad_png, "--small").unwrap_err();
    assert!(matches!(e, TextureError::Decode { .. }) && e.to_string().contains("broken.png"), "{e}");
    // Smaller than a patch.
    let tiny = Texture::from_fn(20, 30, |i, j| [(i * 9) as f32, (j * 7) as f32, 100.0]);
    let e = PhotoOcean::new(&tiny, &crop("main-structure.png"), None, &params(), 1, &|_| {}).unwrap_err();
    assert!(matches!(e, TextureError::TooSmall { width: 20, height: 30, patch: 24, .. }), "{e}");
    // Uniform grey: Eq. 1 divides by I_max − I_min.
    let grey = Texture::from_fn(96, 96, |_, _| [128.0; 3]);
    let e = PhotoOcean::new(&crop("small-waves.png"), &grey, None, &params(), 1, &|_| {}).unwrap_err();
    assert!(matches!(e, TextureError::Flat { .. }) && e.to_string().contains("main-structure"), "{e}");
    // A parameter out of range names itself.
    let p = OceanParams { scale: 0.0, ..params() };
    let e = PhotoOcean::new(&crop("small-waves.png"), &crop("main-structure.png"), None, &p, 1, &|_| {}).unwrap_err();
    assert!(e.to_string().contains("scale"), "{e}");
}

#[test]
fn relit_frames_stay_in_range_even_with_tall_main_waves() {
    // Δheight_max = 50 m ≫ 255 − I: the printed Eq. 9 needs its clamp.
    let p = OceanParams { height_factor_main_m: 100.0, ..params() };
    let o = PhotoOcean::new(&crop("small-waves.png"), &crop("main-structure.png"), None, &p, 1, &|_| {}).unwrap();
    let f = o.frame(2);
    let top = f.top_down(-3.0, 5.0, 0.05, 64, 64, true);
    assert!(top.texels().iter().flatten().all(|v| (0.0..=255.0).contains(v)));
    // Relighting changes the texture (it is not a no-op).
    let plain = f.top_down(-3.0, 5.0, 0.05, 64, 64, false);
    assert!(frame_distance(&top, &plain) > 1.0);
}

#[test]
fn traced_frames_are_finite_show_the_bed_and_refuse_a_camera_under_the_waves() {
    use brine_texture::{TracedParams, TracedScene, render_traced};
    let bed = Texture::from_fn(96, 96, |i, j| {
        let v = if (i / 8 + j / 8) % 2 == 0 { 200.0 } else { 40.0 };
        [v, v * 0.9, v * 0.7]
    });
    let o = PhotoOcean::new(&crop("small-waves.png"), &crop("main-structure.png"), Some(&bed), &params(), 5, &|_| {})
        .unwrap();
    let scene = TracedScene::new(&TracedParams::default(), &o).unwrap();
    let camera = Pinhole::from_angles(DVec3::new(0.0, 3.0, 0.0), 200.0, -50.0, 50.0, 32, 24).unwrap();
    let frame = o.frame(2);
    let img = render_traced(&frame, &camera, &scene).unwrap();
    assert!(img.pixels.iter().all(|p| p.is_finite() && p.min_element() >= 0.0));
    assert_eq!(img.stats.hits, 32 * 24, "every pixel looks down at the sea");
    assert_eq!(img, render_traced(&frame, &camera, &scene).unwrap(), "deterministic");
    // The bed shows through: a uniform bed gives another image.
    let flat_bed = Texture::from_fn(96, 96, |i, _| [120.0, 110.0, 90.0 + (i % 2) as f32]);
    let o2 =
        PhotoOcean::new(&crop("small-waves.png"), &crop("main-structure.png"), Some(&flat_bed), &params(), 5, &|_| {})
            .unwrap();
    let img2 = render_traced(&o2.frame(2), &camera, &TracedScene::new(&TracedParams::default(), &o2).unwrap()).unwrap();
    // A real change: 0.1 % of a pixel's radiance, far above the f64 noise of two identical
    // renders (they are bit-identical, tested above).
    const BED_CHANGE: f64 = 1e-3;
    assert!(img.pixels.iter().zip(&img2.pixels).any(|(a, b)| (*a - *b).length() > BED_CHANGE * a.length()));
    // A camera below the crests is refused.
    let low = Pinhole::from_angles(DVec3::new(0.0, 0.0, 0.0), 200.0, -10.0, 50.0, 8, 8).unwrap();
    let e = render_traced(&frame, &low, &scene).unwrap_err();
    assert!(e.to_string().contains("camera.position.y"), "{e}");
}

/// Tolerance for comparing two evaluations of the same composed quantity by different routes:
/// the heights are stored in `f32` (relative 6·10⁻⁸ of a few metres) and the colours are `f32`
/// levels; 10⁻⁴ m and 10⁻³ level are far above those roundings and far below any real error (a
/// wrong texel or shift changes a height by ~10⁻² m and a colour by levels).
const ROUTE_M: f64 = 1e-4;
const ROUTE_LEVELS: f64 = 1e-3;
/// `t = n/fps` by the test and by the frame: one division each, a few ulps of seconds.
const TIME_ROUNDING_S: f64 = 1e-12;

#[test]
fn composition_and_animation_follow_eq_2_3_10_11() {
    let o = ocean(6);
    let p = o.params();
    let main = o.main_height();
    let f0 = o.frame(0);
    for n in [0u64, 5, 11] {
        let f = o.frame(n);
        let t = n as f64 / p.fps;
        assert!((f.time_s - t).abs() < TIME_ROUNDING_S);
        let [sx, sz] = p.small_velocity_m_s;
        let [mx, mz] = p.main_velocity_m_s;
        // P_h of Eq. 1 recomputed from the displayed small-wave colour.
        let small_h = HeightField::from_texture(&f.small.colour, p.height_factor_small_m, "frame").unwrap();
        for (x, z) in [(0.3, -1.7), (2.45, 3.05), (-4.0, 0.77)] {
            // Eq. 10 (sampling at x − t·v): small-wave texels ((x − t s)/Δ), main texels at 1/scale of those.
            let (us, vs) = ((x - t * sx) / p.texel_m, (z - t * sz) / p.texel_m);
            let (um, vm) = ((x - t * mx) / p.texel_m / p.scale, (z - t * mz) / p.texel_m / p.scale);
            let expected = small_h.sample(us, vs) - small_h.mean() + main.sample(um, vm) - main.mean();
            assert!((f.height(x, z) - expected).abs() < ROUTE_M, "Eq. 3/10 at frame {n}, ({x}, {z})");
            // Eq. 8 shifted: Δheight = M_h − mean(M_h) at the shifted main texel.
            let dh = main.sample(um, vm) - main.mean();
            assert!((f.delta_height(x, z) - dh).abs() < ROUTE_M);
            // The main structure travels along m: Δheight at x + t·m now is Δheight at x at t = 0.
            assert!((f.delta_height(x + t * mx, z + t * mz) - f0.delta_height(x, z)).abs() < ROUTE_M);
            // Eq. 2: S_c is the small-wave colour at the shifted texel; Eq. 11 adds ΔI of Eq. 7–9.
            let pc = f.small.colour.sample(us, vs);
            let unrelit = f.unrelit_colour(x, z);
            let relit = f.colour(x, z);
            let dh_max = o.relighting().delta_height_max;
            for c in 0..3 {
                assert!(f64::from((unrelit[c] - pc[c]).abs()) < ROUTE_LEVELS, "Eq. 2");
                let i = relight_intensity(f64::from(pc[c]), dh, dh_max, RelightRule::Paper);
                assert!((f64::from(relit[c]) - i).abs() < ROUTE_LEVELS, "Eq. 11");
            }
        }
    }
    // Δheight_max of Eq. 9 is the largest |M_h − mean(M_h)|.
    let g = main.grid().values();
    let largest = g.iter().map(|&v| (f64::from(v) - main.mean()).abs()).fold(0.0, f64::max);
    assert!((o.relighting().delta_height_max - largest).abs() < ROUTE_M);
}

#[test]
fn the_temporal_constraint_makes_consecutive_frames_closest() {
    // Under the temporal constraint each frame stays close to the previous one: consecutive basis
    // frames are nearer than frames two or more apart (without it, every pair would be as far as
    // two independent syntheses).
    let o = ocean(9);
    let frames = &o.sequence().frames;
    let n = frames.len();
    let mean = |gap: usize| {
        let d: Vec<f64> = (0..n - gap).map(|i| frame_distance(&frames[i], &frames[i + gap])).collect();
        d.iter().sum::<f64>() / d.len() as f64
    };
    let (near, far) = (mean(1), mean(n - 1));
    assert!(near < far, "consecutive frames {near:.2}, first to last {far:.2}");
    // Consecutive frames are not identical either: the waves move.
    assert!(near > 0.5, "consecutive frames differ by {near:.2} levels only");
    // And two independent tileable syntheses are further apart than consecutive frames.
    let ex = crop("small-waves.png");
    let a = synthesize_tileable(&ex, 64, 64, &params().synthesis, 1).unwrap();
    let b = synthesize_tileable(&ex, 64, 64, &params().synthesis, 2).unwrap();
    assert!(near < frame_distance(&a, &b), "consecutive {near:.2} vs independent {:.2}", frame_distance(&a, &b));
}
