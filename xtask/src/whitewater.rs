//! `cargo xtask whitewater`: white water measured as Monahan measured it, from above.
//!
//! Monahan & Ó Muircheartaigh's whitecap coverage `W` is the share of photographed sea that is
//! white: the renderer's white water is therefore measured top-down (50 m up, 60° field), over
//! several seeds, as the share of sea pixels more than half white, `1 − (1 − foam)(1 − whitecap)`
//! from the output variables, beside the mean of that white fraction. The sheet adds the shape of
//! the foam (its correlation lengths along and across the wind at 18 m/s) and the constancy of the
//! sea's coverage over a 5 s animation (the same sea seen from 400 m), and how much the spray
//! lowers the contrast of the horizon. The tables go to `docs/whitewater.md`, the images to
//! `docs/whitewater/`.

use std::fmt::Write as _;
use std::path::Path;

use brine_foam::{CoverageParams, DARLES_ONSET_WIND_M_S, WhitecapLaw};
use brine_render::{Frame, RenderOptions, Scene};
use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;

/// Winds of the coverage table (m s⁻¹): Beaufort 5, 6, 7 and 9.
const WINDS: [f64; 4] = [8.0, 12.0, 16.0, 22.0];
/// Wind of the streak figure (m s⁻¹), Beaufort 8.
const STREAK_WIND: f64 = 18.0;
/// Surfaces, as `[sea] surface` names.
const SURFACES: [&str; 2] = ["trochoids", "fft"];
/// Seeds of the coverage table.
const SEEDS: [u64; 6] = [1, 2, 3, 4, 5, 6];
/// Side of the top-down images (pixels).
const SIZE: u32 = 384;
/// Height of the top-down camera (m).
const HEIGHT_M: f64 = 100.0;
/// Wind direction of every scene (degrees from +x toward +z).
const WIND_DIRECTION_DEG: f64 = 20.0;
/// Points of the whole-sea coverage in time.
const TIME_POINTS: usize = 160_000;
/// Half-white threshold of the visible coverage.
const HALF_WHITE: f64 = 0.5;

/// Winds of the spray-haze table (m s⁻¹): Beaufort 6, 7, 8 and 9.
const HAZE_WINDS: [f64; 4] = [12.0, 16.0, 20.0, 22.0];
/// Wind of the horizon images kept for the sheet (m s⁻¹), one of [`HAZE_WINDS`].
const HAZE_IMAGE_WIND: f64 = 20.0;
/// Vertical field of the horizon view (degrees): 0.125° a row at [`HAZE_HEIGHT`] rows.
const HAZE_FOV_DEG: f64 = 20.0;
/// Image of the horizon view (pixels).
const HAZE_WIDTH: u32 = 320;
const HAZE_HEIGHT: u32 = 160;
/// Rows of the horizon bands, counted from the horizon line: 2 to 8 rows (0.25°–1°) above it for
/// the sky, below it for the sea (from 10 m, 1.6 km to 570 m away).
const HAZE_BAND: (usize, usize) = (2, 8);

/// A view of the horizon from 10 m, the sun 30° high and 90° to the right, glare off.
fn horizon_scene(surface: &str, wind: f64, spray: bool) -> String {
    format!(
        "[camera]\nposition = [0.0, 10.0, 0.0]\npitch_deg = 0.0\nyaw_deg = 0.0\nwidth = {HAZE_WIDTH}\nheight = {HAZE_HEIGHT}\n\
         fov_deg = {HAZE_FOV_DEG}\n\n[sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = {WIND_DIRECTION_DEG}\n\
         seed = 1\n\n[sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 90.0\n\n[phenomena]\nglare = false\nspray = {spray}\n"
    )
}

/// The horizon's contrast `(L_sky − L_sea)/L_sky`: the mean luminance of the sky rows
/// [`HAZE_BAND`] above the horizon line (the last sky pixel of each column) against the sea rows
/// as far below it.
fn horizon_contrast(frame: &Frame) -> f64 {
    let (w, h) = (frame.width as usize, frame.height as usize);
    let y = |c: glam::DVec3| c.dot(glam::DVec3::new(0.2126, 0.7152, 0.0722));
    let (mut sky, mut sea, mut n) = (0.0, 0.0, 0usize);
    for x in 0..w {
        let Some(line) = (0..h).find(|&r| frame.aovs[r * w + x].depth.is_finite()) else { continue };
        if line < HAZE_BAND.1 || line + HAZE_BAND.1 >= h {
            continue;
        }
        for k in HAZE_BAND.0..=HAZE_BAND.1 {
            sky += y(frame.pixels[(line - k) * w + x]);
            sea += y(frame.pixels[(line - 1 + k) * w + x]);
            n += 1;
        }
    }
    if n == 0 || sky <= 0.0 { f64::NAN } else { (sky - sea) / sky }
}

/// A top-down scene `height_m` up.
fn scene_text(surface: &str, wind: f64, seed: u64, height_m: f64, time_s: f64) -> String {
    format!(
        "[camera]\nposition = [0.0, {height_m}, 0.0]\npitch_deg = -90.0\nyaw_deg = 0.0\nwidth = {SIZE}\nheight = {SIZE}\n\
         fov_deg = 60.0\n\n[sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = {WIND_DIRECTION_DEG}\n\
         seed = {seed}\ntime_s = {time_s}\n\n[sky]\nsun_elevation_deg = 40.0\nsun_azimuth_deg = 90.0\n"
    )
}

/// The meteorological visibility at the sea, `ln 50 / k(0)` (m), of the spray the renderer
/// builds at `wind` (bubble drops and spume).
fn haze_visibility(wind: f64) -> Result<f64, String> {
    let scene = Scene::from_toml_str(&horizon_scene("trochoids", wind, true), "horizon").map_err(|e| e.to_string())?;
    let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
    world.spray_visibility_m(0.0).ok_or_else(|| "no spray".to_string())
}

fn render(text: &str, name: &str) -> Result<Frame, String> {
    let scene = Scene::from_toml_str(text, name).map_err(|e| e.to_string())?;
    brine_render::render(&scene, &RenderOptions::default(), &|| {}).map_err(|e| e.to_string())
}

/// Monahan & Ó Muircheartaigh 1980 at `u10`, as the renderer computes it.
fn monahan(u10: f64) -> f64 {
    let p = CoverageParams::new(u10, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).expect("winds in range");
    brine_foam::whitecap_coverage(&p)
}

/// White fraction of every sea pixel (`None` for sky).
fn white(frame: &Frame) -> Vec<Option<f64>> {
    frame
        .aovs
        .iter()
        .map(|a| a.depth.is_finite().then(|| 1.0 - (1.0 - f64::from(a.foam)) * (1.0 - f64::from(a.whitecap))))
        .collect()
}

/// `(visible share, mean)` of the white fraction over the sea pixels.
fn coverage(w: &[Option<f64>]) -> (f64, f64) {
    let sea: Vec<f64> = w.iter().flatten().copied().collect();
    let n = sea.len().max(1) as f64;
    (sea.iter().filter(|&&x| x > HALF_WHITE).count() as f64 / n, sea.iter().sum::<f64>() / n)
}

/// Correlation lengths (pixels) of a square field along and across the wind: where its
/// normalised autocorrelation (by FFT, periodic) first falls below `1/e`.
fn correlation_lengths(w: &[Option<f64>], n: usize) -> (f64, f64) {
    let vals: Vec<f64> = w.iter().map(|x| x.unwrap_or(0.0)).collect();
    let mean = vals.iter().sum::<f64>() / vals.len() as f64;
    let mut data: Vec<Complex64> = vals.iter().map(|&v| Complex64::new(v - mean, 0.0)).collect();
    let mut planner = FftPlanner::new();
    let fwd = planner.plan_fft_forward(n);
    let inv = planner.plan_fft_inverse(n);
    let transform = |data: &mut Vec<Complex64>, f: &std::sync::Arc<dyn rustfft::Fft<f64>>| {
        for row in data.chunks_mut(n) {
            f.process(row);
        }
        let mut col = vec![Complex64::default(); n];
        for i in 0..n {
            for j in 0..n {
                col[j] = data[j * n + i];
            }
            f.process(&mut col);
            for j in 0..n {
                data[j * n + i] = col[j];
            }
        }
    };
    transform(&mut data, &fwd);
    for c in &mut data {
        *c = Complex64::new(c.norm_sqr(), 0.0);
    }
    transform(&mut data, &inv);
    let c0 = data[0].re;
    if c0 <= 0.0 {
        return (0.0, 0.0);
    }
    let at = |x: f64, y: f64| -> f64 {
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let idx = |i: f64, j: f64| {
            let (i, j) = ((i as i64).rem_euclid(n as i64) as usize, (j as i64).rem_euclid(n as i64) as usize);
            data[j * n + i].re
        };
        let v = idx(x0, y0) * (1.0 - fx) * (1.0 - fy)
            + idx(x0 + 1.0, y0) * fx * (1.0 - fy)
            + idx(x0, y0 + 1.0) * (1.0 - fx) * fy
            + idx(x0 + 1.0, y0 + 1.0) * fx * fy;
        v / c0
    };
    // Image axes of a top-down camera with yaw 0: north (−z) is the image's up, so world +x is
    // to the right and world +z down the rows. The wind's image direction follows.
    let th = WIND_DIRECTION_DEG.to_radians();
    let along = (th.cos(), th.sin());
    let across = (-th.sin(), th.cos());
    let length = |d: (f64, f64)| -> f64 {
        let mut prev = 1.0;
        for step in 1..(n / 2) {
            let r = step as f64;
            let c = at(d.0 * r, d.1 * r);
            if c < (-1f64).exp() {
                // Linear interpolation between the two steps.
                return r - 1.0 + (prev - (-1f64).exp()) / (prev - c);
            }
            prev = c;
        }
        (n / 2) as f64
    };
    (length(along), length(across))
}

fn save_png(frame: &Frame, path: &Path) -> Result<(), String> {
    brine_render::write_frame(path, frame, frame.exposure_ev, false).map_err(|e| e.to_string())
}

/// The top-down view of one sea at time 0; the first seed's image is kept in `dir`.
fn render_top_down(surface: &str, wind: f64, seed: u64, dir: &Path) -> Result<Frame, String> {
    let frame = render(&scene_text(surface, wind, seed, HEIGHT_M, 0.0), "whitewater")?;
    if seed == SEEDS[0] {
        save_png(&frame, &dir.join(format!("{surface}-{wind:02}.png")))?;
    }
    Ok(frame)
}

/// The foam's correlation lengths along and across the wind at [`STREAK_WIND`] (m, mean over the
/// seeds) for each surface; the first seed's image is kept in `dir` when given.
fn streak_lengths(dir: Option<&Path>) -> Result<Vec<(&'static str, f64, f64)>, String> {
    let metres_per_pixel = 2.0 * HEIGHT_M * 30f64.to_radians().tan() / f64::from(SIZE);
    let mut out = Vec::new();
    for surface in SURFACES {
        let (mut along, mut across) = (0.0, 0.0);
        for &seed in &SEEDS {
            let frame = render(&scene_text(surface, STREAK_WIND, seed, HEIGHT_M, 0.0), "whitewater")?;
            if let Some(dir) = dir.filter(|_| seed == SEEDS[0]) {
                save_png(&frame, &dir.join(format!("{surface}-{STREAK_WIND:02}.png")))?;
            }
            let foam: Vec<Option<f64>> =
                frame.aovs.iter().map(|a| a.depth.is_finite().then(|| f64::from(a.foam))).collect();
            let (a, c) = correlation_lengths(&foam, SIZE as usize);
            along += a * metres_per_pixel / SEEDS.len() as f64;
            across += c * metres_per_pixel / SEEDS.len() as f64;
        }
        eprintln!("streaks {surface}: along {along:.2} m, across {across:.2} m, ratio {:.2}", along / across.max(1e-9));
        out.push((surface, along, across));
    }
    Ok(out)
}

/// `cargo xtask whitewater --streaks`: the streak figures only, printed.
pub fn streaks() -> Result<Vec<(&'static str, f64, f64)>, String> {
    streak_lengths(None)
}

/// Runs the measurements and writes `docs/whitewater.md`.
pub fn run(root: &Path) -> Result<(), String> {
    let dir = root.join("docs/whitewater");
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let mut md = String::new();
    let _ = writeln!(md, "# White water measured from above\n");
    let _ = writeln!(
        md,
        "Generated by `cargo xtask whitewater`. Each figure is measured on the renderer's own output \
         variables (foam and whitecap coverage per pixel), seen straight down from {HEIGHT_M} m ({SIZE}² pixels, \
         60° field, about {:.2} m a pixel, 115 m across), over {} seeds. *Visible* is the share of sea pixels more than \
         half white, `1 − (1 − foam)(1 − whitecap) > 0.5`, the quantity Monahan & Ó Muircheartaigh \
         (1980) measured by thresholding photographs; *mean* is the mean white fraction. Both are given \
         as multiples of their `W` at the same wind.\n",
        2.0 * HEIGHT_M * 30f64.to_radians().tan() / f64::from(SIZE),
        SEEDS.len()
    );
    let _ = writeln!(md, "| wind (m/s) | W (Monahan 1980) | surface | visible / W | mean / W |");
    let _ = writeln!(md, "|---|---|---|---|---|");
    for &wind in &WINDS {
        let w_m = monahan(wind);
        for surface in SURFACES {
            let (mut vis, mut mean) = (0.0, 0.0);
            for &seed in &SEEDS {
                let frame = render_top_down(surface, wind, seed, &dir)?;
                let (v, m) = coverage(&white(&frame));
                vis += v / SEEDS.len() as f64;
                mean += m / SEEDS.len() as f64;
            }
            eprintln!("{wind:>4} m/s {surface:<9}: visible {:.3} W, mean {:.3} W", vis / w_m, mean / w_m);
            let _ =
                writeln!(md, "| {wind} | {:.2} % | {surface} | {:.2} | {:.2} |", 100.0 * w_m, vis / w_m, mean / w_m);
        }
    }
    let _ = writeln!(md, "\nSeed 1 of each, as rendered (sun 40° high, from the right):\n");
    let _ = writeln!(md, "| wind (m/s) | trochoids | FFT |");
    let _ = writeln!(md, "|---|---|---|");
    for &wind in &WINDS {
        let _ = writeln!(
            md,
            "| {wind} | ![trochoids {wind} m/s](whitewater/trochoids-{wind:02}.png) | ![FFT {wind} m/s](whitewater/fft-{wind:02}.png) |"
        );
    }
    let _ = writeln!(
        md,
        "\n## Streaks\n\nAt {STREAK_WIND} m/s (Beaufort 8), the correlation length of the foam output variable \
         (the foam left behind by breaking crests, with the wind streaks) along the wind and across it: where the field's autocorrelation first falls below 1/e, in metres \
         (mean over the seeds).\n"
    );
    let _ = writeln!(md, "| surface | along the wind (m) | across (m) | ratio |");
    let _ = writeln!(md, "|---|---|---|---|");
    for (surface, along, across) in streak_lengths(Some(&dir))? {
        let _ = writeln!(md, "| {surface} | {along:.2} | {across:.2} | {:.2} |", along / across.max(1e-9));
    }
    let _ = writeln!(
        md,
        "\n## Coverage in time\n\nThe mean white fraction of the whole sea at 16 m/s, every 0.5 s over 5 s of an \
         animation: the renderer's white-water model read at {TIME_POINTS} fixed points (a 2 km square for \
         the trochoids, the largest tile for the FFT sea), each frame's world built as `brine render` builds \
         it; its range over the mean.\n"
    );
    let _ = writeln!(md, "| surface | min / mean | max / mean |");
    let _ = writeln!(md, "|---|---|---|");
    for surface in SURFACES {
        let mut series = Vec::new();
        for i in 0..=10 {
            let text = scene_text(surface, 16.0, 1, HEIGHT_M, 0.5 * f64::from(i));
            let scene = Scene::from_toml_str(&text, "whitewater").map_err(|e| e.to_string())?;
            let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
            let Some(ww) = world.white_water() else { return Err("no white water at 16 m/s".into()) };
            let side = match ww {
                brine_render::WhiteWaterSea::Fft(m) => m.source().now().largest_tile(),
                brine_render::WhiteWaterSea::Trochoids(_) => 2000.0,
            };
            let n = (TIME_POINTS as f64).sqrt() as usize;
            let mut sum = 0.0;
            for a in 0..n {
                for b in 0..n {
                    let u = glam::DVec2::new((a as f64 + 0.5) / n as f64, (b as f64 + 0.5) / n as f64) * side;
                    sum += ww.at(u, world.time(), 0.0).white;
                }
            }
            series.push(sum / (n * n) as f64);
        }
        let mean = series.iter().sum::<f64>() / series.len() as f64;
        let (lo, hi) = series.iter().fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
        eprintln!("time {surface}: {:.3}..{:.3} of the mean {mean:.4}", lo / mean, hi / mean);
        let _ = writeln!(md, "| {surface} | {:.3} | {:.3} |", lo / mean, hi / mean);
    }
    let _ = writeln!(
        md,
        "\n## Spray over the horizon\n\nThe horizon seen from 10 m (sun 30° high, 90° to the right, glare off, \
         {HAZE_WIDTH} × {HAZE_HEIGHT} pixels over {HAZE_FOV_DEG}°), with the spray on and off: the contrast of the \
         horizon, `(L_sky − L_sea)/L_sky`, from the mean luminance of the sky 0.25°–1° above the horizon line and of \
         the sea as far below it (1.6 km to 570 m away), and how much the spray lowers it. The spray is the bubble drops \
         of Monahan et al. (1986) and the spume of Fairall et al. (1994); the visibility is `ln 50 / k` at the sea \
         (`brine spray`).\n"
    );
    let _ =
        writeln!(md, "| wind (m/s) | visibility at the sea | surface | contrast, no spray | with spray | lowered by |");
    let _ = writeln!(md, "|---|---|---|---|---|---|");
    for (w, &wind) in HAZE_WINDS.iter().enumerate() {
        let vis = haze_visibility(wind)?;
        let keep = w == HAZE_WINDS.iter().position(|&x| x >= HAZE_IMAGE_WIND).unwrap_or(0);
        for surface in SURFACES {
            let mut c = [0.0; 2];
            for (i, spray) in [false, true].into_iter().enumerate() {
                let frame = render(&horizon_scene(surface, wind, spray), "horizon")?;
                if keep {
                    let on = if spray { "spray" } else { "clear" };
                    save_png(&frame, &dir.join(format!("horizon-{surface}-{wind:02}-{on}.png")))?;
                }
                c[i] = horizon_contrast(&frame);
            }
            eprintln!("horizon {wind:>4} m/s {surface:<9}: contrast {:.3} → {:.3}", c[0], c[1]);
            let _ = writeln!(
                md,
                "| {wind} | {:.1} km | {surface} | {:.3} | {:.3} | {:.0} % |",
                vis / 1000.0,
                c[0],
                c[1],
                100.0 * (1.0 - c[1] / c[0])
            );
        }
    }
    let _ = writeln!(md, "\nAt {HAZE_IMAGE_WIND} m/s, without and with the spray:\n");
    let _ = writeln!(md, "| surface | no spray | spray |");
    let _ = writeln!(md, "|---|---|---|");
    for surface in SURFACES {
        let _ = writeln!(
            md,
            "| {surface} | ![{surface}, no spray](whitewater/horizon-{surface}-20-clear.png) | ![{surface}, spray](whitewater/horizon-{surface}-20-spray.png) |"
        );
    }
    let path = root.join("docs/whitewater.md");
    std::fs::write(&path, md).map_err(|e| format!("cannot write {}: {e}", path.display()))
}
