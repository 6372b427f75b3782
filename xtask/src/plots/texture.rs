//! Figures of brine-texture: the pipeline's intermediate images (PNG) on the shipped example
//! photos, and the frame-to-frame distances of the basis sequence (SVG).

use std::path::Path;

use brine_sky::{Sky, SkyParams};
use brine_texture::{
    Grid, OceanParams, PhotoOcean, Pinhole, ProjectionOptions, ProjectionView, Texture, TracedParams, TracedScene,
    border_differences, frame_distance, render_projection, render_traced, seam_differences, seam_z_score,
    wrap_border_test,
};
use glam::DVec3;

use super::{LineChart, Scale};

/// Seed of every figure.
const SEED: u64 = 1;

/// Saves an 8-bit image.
fn save(img: &image::RgbImage, path: &Path) -> Result<(), String> {
    img.save(path).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// Pastes `tiles` side by side (same height), separated by `gap` white pixels.
fn strip(tiles: &[image::RgbImage], gap: u32) -> image::RgbImage {
    let h = tiles.iter().map(|t| t.height()).max().unwrap_or(1);
    let w = tiles.iter().map(|t| t.width()).sum::<u32>() + gap * tiles.len().saturating_sub(1) as u32;
    let mut out = image::RgbImage::from_pixel(w, h, image::Rgb([255, 255, 255]));
    let mut x = 0;
    for t in tiles {
        image::imageops::overlay(&mut out, t, i64::from(x), 0);
        x += t.width() + gap;
    }
    out
}

/// A texture tiled `n × n` times.
fn tiled(t: &Texture, n: usize) -> image::RgbImage {
    Texture::from_fn(t.width() * n, t.height() * n, |i, j| t.get(i % t.width(), j % t.height())).to_image()
}

/// A height grid as 8-bit grey, `[lo, hi]` to `[0, 255]`.
fn grey(g: &Grid, lo: f64, hi: f64) -> image::RgbImage {
    let t = Texture::from_fn(g.width(), g.height(), |i, j| {
        let v = (255.0 * (f64::from(g.get(i, j)) - lo) / (hi - lo)) as f32;
        [v, v, v]
    });
    t.to_image()
}

/// Scales an image to `w × h` (bilinear).
fn resized(img: &image::RgbImage, w: u32, h: u32) -> image::RgbImage {
    image::imageops::resize(img, w, h, image::imageops::FilterType::Triangle)
}

/// A procedural pebble bed for the refraction figures (Worley cells; the paper uses a rock photo).
fn pebbles(n: usize) -> Texture {
    let cells = 10usize;
    let size = n as f64 / cells as f64;
    let hash = |a: usize, b: usize, k: u64| -> f64 {
        let mut x = (a as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (b as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F) ^ k;
        x ^= x >> 31;
        x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        x ^= x >> 29;
        (x % 10_000) as f64 / 10_000.0
    };
    Texture::from_fn(n, n, |i, j| {
        let (x, y) = (i as f64 / size, j as f64 / size);
        let (mut d1, mut d2, mut id) = (f64::INFINITY, f64::INFINITY, (0, 0));
        for dj in -1i64..=1 {
            for di in -1i64..=1 {
                let (cx, cy) = (
                    (x.floor() as i64 + di).rem_euclid(cells as i64) as usize,
                    (y.floor() as i64 + dj).rem_euclid(cells as i64) as usize,
                );
                let px = x.floor() + di as f64 + hash(cx, cy, 1);
                let py = y.floor() + dj as f64 + hash(cx, cy, 2);
                let d = (x - px).hypot(y - py);
                if d < d1 {
                    d2 = d1;
                    d1 = d;
                    id = (cx, cy);
                } else if d < d2 {
                    d2 = d;
                }
            }
        }
        let edge = ((d2 - d1) * 6.0).min(1.0);
        let tone = 0.55 + 0.45 * hash(id.0, id.1, 3);
        let v = (200.0 * tone * edge) as f32;
        [v, 0.92 * v, 0.75 * v]
    })
}

/// Writes the brine-texture figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    let examples = super::super::root().join("crates/brine-texture/examples");
    let load = |name: &str| Texture::load(&examples.join(name), name).map_err(|e| e.to_string());
    let (small, main) = (load("small-waves.png")?, load("main-structure.png")?);
    let bed = pebbles(256);
    let params = OceanParams::default();
    let ocean = PhotoOcean::new(&small, &main, Some(&bed), &params, SEED, &|_| {}).map_err(|e| e.to_string())?;

    // 1. Inputs and the tileable main structure (2×2 tiles: the photo shows its seams).
    save(&strip(&[small.to_image(), main.to_image()], 8), &dir.join("texture-inputs.png"))?;
    let photo_tiles = resized(&tiled(&main, 2), 384, 384);
    let synth_tiles = resized(&tiled(ocean.main_texture(), 2), 384, 384);
    save(&strip(&[photo_tiles, synth_tiles], 8), &dir.join("texture-main-tiling.png"))?;

    // 2. The basis sequence (every other frame) and its heights.
    let frames: Vec<image::RgbImage> =
        ocean.sequence().frames.iter().step_by(2).take(6).map(|f| resized(&f.to_image(), 160, 160)).collect();
    save(&strip(&frames, 4), &dir.join("texture-basis-frames.png"))?;
    let f0 = &ocean.basis_frames()[0];
    let heights = [
        resized(&f0.colour.to_image(), 256, 256),
        grey(f0.height().grid(), 0.0, params.height_factor_small_m),
        resized(&ocean.main_texture().to_image(), 256, 256),
        grey(ocean.main_height().grid(), 0.0, params.height_factor_main_m),
    ];
    save(&strip(&heights, 8), &dir.join("texture-heights.png"))?;

    // 3. Morphing along one link.
    let link = ocean.graph().links().iter().position(|l| l.to != l.from + 1).unwrap_or(0);
    let l = ocean.graph().links()[link];
    let f = &ocean.sequence().frames;
    let morphs: Vec<image::RgbImage> = [0.0, 0.25, 0.5, 0.75, 1.0]
        .iter()
        .map(|&a| {
            resized(&ocean.morphs()[link].morph(&f[l.from], &f[l.to], a).window(0, 0, 128, 128).to_image(), 192, 192)
        })
        .collect();
    save(&strip(&morphs, 4), &dir.join("texture-morph.png"))?;

    // 4. Relighting (Lai & Wu Fig. 4): the composed colour seen from above, before and after.
    let frame = ocean.frame(0);
    let before = frame.top_down(0.0, 0.0, 0.16, 384, 384, false).to_image();
    let after = frame.top_down(0.0, 0.0, 0.16, 384, 384, true).to_image();
    save(&strip(&[before, after], 8), &dir.join("texture-relighting.png"))?;

    // 5. Rendering: the paper's projection, with the bed (Fig. 9), and traced.
    let sun = DVec3::new(-0.28, 0.57, 0.77).normalize();
    let sky = Sky::new(&SkyParams::new(3.0, sun)).map_err(|e| e.to_string())?;
    let camera =
        Pinhole::from_angles(DVec3::new(0.0, 8.0, 0.0), 225.0, -20.0, 60.0, 384, 384).map_err(|e| e.to_string())?;
    let plain = PhotoOcean::new(&small, &main, None, &params, SEED, &|_| {}).map_err(|e| e.to_string())?;
    let view = ProjectionView::new(&camera, &sky);
    let projected: Vec<image::RgbImage> =
        [0, 12].iter().map(|&n| render_projection(&plain.frame(n), &view, &ProjectionOptions::default())).collect();
    save(&strip(&projected, 8), &dir.join("texture-projection.png"))?;
    let down =
        Pinhole::from_angles(DVec3::new(0.0, 4.0, 0.0), 225.0, -55.0, 60.0, 384, 384).map_err(|e| e.to_string())?;
    let bed_view = ProjectionView::new(&down, &sky);
    let shallow = ProjectionOptions { bed_depth_m: 3.0, ..ProjectionOptions::default() };
    let with_bed = render_projection(&ocean.frame(0), &bed_view, &shallow);
    let without = render_projection(&plain.frame(0), &bed_view, &shallow);
    save(&strip(&[without, with_bed], 8), &dir.join("texture-bed.png"))?;
    let scene = TracedScene::new(&TracedParams { sun_direction: sun, ..TracedParams::default() }, &ocean)
        .map_err(|e| e.to_string())?;
    let traced = render_traced(&ocean.frame(0), &camera, &scene).map_err(|e| e.to_string())?;
    eprintln!(
        "brine-texture traced view: {:.1} evaluations of F per ray",
        traced.stats.evaluations as f64 / traced.stats.rays.max(1) as f64
    );
    let ev = brine_render::auto_exposure_ev(
        {
            let n = traced.pixels.len() as f64;
            (traced
                .pixels
                .iter()
                .map(|p| ((0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z).max(0.0) * 1000.0 + 1e-6).ln())
                .sum::<f64>()
                / n)
                .exp()
        },
        (scene.sky.horizontal_irradiance_rgb().y + scene.sky.sun().irradiance_rgb.y * sun.y) * 1000.0,
    );
    brine_render::write_image(&dir.join("texture-traced.png"), traced.width, traced.height, &traced.pixels, ev)
        .map_err(|e| e.to_string())?;

    // 6. Frame-to-frame distances of the basis sequence, and the seams.
    let n = ocean.sequence().frames.len();
    let mut series = Vec::new();
    for i in [0, n / 2] {
        let pts = (0..n).filter(|&j| j != i).map(|j| ((j as f64 - i as f64), frame_distance(&f[i], &f[j]))).collect();
        series.push((format!("from basis frame {i}"), pts));
    }
    LineChart {
        title: "RMS distance between basis frames (levels) against their separation in the sequence",
        x_label: "j − i (frames)",
        y_label: "D(i, j) (levels)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("texture-frame-distances.svg"))?;
    let step = params.synthesis.step();
    // The photos are cut to whole cells (their 256² already are for the default 32-texel cells).
    let segment_z = |t: &Texture| {
        let (w, h) = (t.width() / step * step, t.height() / step * step);
        wrap_border_test(&t.window(0, 0, w, h), step).map_or(f64::NAN, |r| r.rank_z)
    };
    let (wrap, inside) = seam_differences(ocean.main_texture());
    let borders = border_differences(ocean.main_texture(), step);
    let (pw, pi) = seam_differences(&main);
    let (sw, si) = seam_differences(&f[0]);
    let sb = border_differences(&f[0], step);
    eprintln!(
        "brine-texture seams (levels): main tile wrap {wrap:.2}, inside {inside:.2}, cell borders {borders:.2}; \
         small frame 0 wrap {sw:.2}, inside {si:.2}, borders {sb:.2}; main photo wrap {pw:.2}, inside {pi:.2}; \
         z-scores of the wrap: main tile {:.2}, small frame 0 {:.2}, main photo {:.1}, small photo {:.1}; \
         wrap vs cell-border segments (Mann–Whitney z_U): main tile {:.2}, small frame 0 {:.2}, main photo {:.1}, small photo {:.1}; \
         Δh_max = {:.3} m",
        seam_z_score(ocean.main_texture()),
        seam_z_score(&f[0]),
        seam_z_score(&main),
        seam_z_score(&small),
        segment_z(ocean.main_texture()),
        segment_z(&f[0]),
        segment_z(&main),
        segment_z(&small),
        ocean.relighting().delta_height_max
    );
    Ok(())
}
