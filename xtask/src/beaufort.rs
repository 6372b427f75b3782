//! The Beaufort sheet: the same view of the sea at six winds on the trochoid and FFT surfaces,
//! rendered and measured, written to `docs/beaufort.md` with its images in `docs/beaufort/`.
//!
//! Each image is measured from its own output variables:
//! - **detail**: the variance of the shading normals' slopes `(−nₓ/n_y, −n_z/n_y)` over the sea
//!   between 10 and 30 m from the eye, as a share of Cox & Munk's clean-surface total at the
//!   scene's wind (12.5 m above the sea, the neutral log profile);
//! - **peaks**: on a top-down view of the same sea (256² normals, `50 (U₁₀/8)²` m up, so that the
//!   view scales with the sea's waves), the share of the slope power held by the 20 strongest wave vectors of its 2-D spectrum; a handful of crossing waves
//!   (a lattice of glints) puts most of the power there, a sea of many waves very little; also
//!   of the wave vectors the view resolves (four cycles across it or more, Hann-tapered);
//! - **glitter** (2, 5 and 12 m/s): the total slope variance that the sun's glitter implies,
//!   inverted as Cox & Munk (1954) did from their photographs, over that of a Gaussian sea of
//!   Cox & Munk's total seen through the same image.

use std::fmt::Write as _;
use std::path::Path;

use brine_render::{Frame, RenderOptions, Scene};
use brine_testkit::lattice::{PeakShare, peak_share as peak_share_of};

/// Winds of the sheet (m s⁻¹, 10 m above the sea): Beaufort 2, 3, 5, 6, 7 and 9.
const WINDS: [f64; 6] = [2.0, 5.0, 8.0, 12.0, 16.0, 22.0];

/// Surfaces of the sheet, as `[sea] surface` names.
const SURFACES: [&str; 2] = ["trochoids", "fft"];

/// Near field of the detail figure (m from the eye).
const NEAR_FIELD_M: (f32, f32) = (10.0, 30.0);

/// Side of the top-down normal map (pixels) and how many of its strongest wave vectors count as peaks.
const TOP_DOWN_SIZE: u32 = 256;
const PEAKS: usize = 20;

/// The scene of one image: a camera 10 m up looking 8° down, the sun 30° high and 90° to the side
/// (or straight ahead, `toward_sun`).
fn scene_text(surface: &str, wind: f64, top_down: bool, spp: u32) -> String {
    scene_text_facing(surface, wind, top_down, spp, false)
}

fn scene_text_facing(surface: &str, wind: f64, top_down: bool, spp: u32, toward_sun: bool) -> String {
    let height = if top_down { Some(TOP_DOWN_HEIGHT_M) } else { None };
    view_text(surface, wind, height, spp, toward_sun)
}

/// Height of the top-down view of the tile lags (m).
const TOP_DOWN_HEIGHT_M: f64 = 50.0;

/// Wind at which the peaks' top-down view is [`TOP_DOWN_HEIGHT_M`] up (m s⁻¹).
const PEAKS_REFERENCE_WIND: f64 = 8.0;

/// Height of the peaks' top-down view at wind `U₁₀` (m): `50 (U₁₀ / 8)²`, so that the view holds the
/// same drawn waves and normals, in units of the peak wavelength, at every wind. The sea's wave lengths scale as `U₁₀²/g`: its waves are fitted over a
/// band set in units of the peak frequency `ω_p ∝ g/U₁₀` (from 5 m/s; at lighter winds the band
/// ends sooner, where the spectrum reaches Cox & Munk's total), and the pixel, which sets where the
/// drawn waves end and the detail normals and the BRDF take over, grows with the height. On this
/// view the peak wave spans the same share of the image: 58 m across at 8 m/s (about one peak
/// wavelength), 231 m at 16 m/s. On a fixed view the longer waves of a higher wind show as a tilt
/// of the image and put their slope in its few lowest bins whatever the sea.
fn peaks_height_m(wind: f64) -> f64 {
    TOP_DOWN_HEIGHT_M * (wind / PEAKS_REFERENCE_WIND).powi(2)
}

/// The scene of one image, or of a top-down view `height` metres up.
fn view_text(surface: &str, wind: f64, height: Option<f64>, spp: u32, toward_sun: bool) -> String {
    // Toward the sun the sky is clear, so that no cloud hides the sun and its glitter.
    let (yaw, clouds) = if toward_sun { (90.0, "") } else { (0.0, "\n[sky.clouds]\ncover = 0.35\n") };
    let camera = if let Some(height) = height {
        format!(
            "position = [0.0, {height}, 0.0]\npitch_deg = -90.0\nyaw_deg = 0.0\nwidth = {TOP_DOWN_SIZE}\nheight = {TOP_DOWN_SIZE}\nfov_deg = 60.0\n"
        )
    } else {
        format!(
            "position = [0.0, 10.0, 0.0]\npitch_deg = -8.0\nyaw_deg = {yaw}\nwidth = 640\nheight = 360\nspp = {spp}\n"
        )
    };
    format!(
        "[camera]\n{camera}\n[sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = 20.0\nseed = 3\n\n\
         [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 90.0\n{clouds}"
    )
}

/// Cox & Munk's clean-surface mean-square slope `σ_u² + σ_c² = 0.003 + 5.12×10⁻³ U₁₂.₅`, with
/// `U₁₂.₅ = U₁₀ ln(12.5/z₀)/ln(10/z₀)`, `z₀ = 2×10⁻⁴ m` (as the renderer's BRDF).
fn cox_munk_total(u10: f64) -> f64 {
    let z0: f64 = 2e-4;
    let u = u10 * (12.5 / z0).ln() / (10.0 / z0).ln();
    0.003 + 5.12e-3 * u
}

fn render(text: &str, name: &str) -> Result<Frame, String> {
    let scene = Scene::from_toml_str(text, name).map_err(|e| e.to_string())?;
    brine_render::render(&scene, &RenderOptions::default(), &|| {}).map_err(|e| e.to_string())
}

/// The slopes `(−nₓ/n_y, −n_z/n_y)` of the sea pixels whose depth is in `range`.
fn slopes(frame: &Frame, range: (f32, f32)) -> Vec<(f64, f64)> {
    frame
        .aovs
        .iter()
        .filter(|a| a.depth >= range.0 && a.depth <= range.1 && a.normal[1] > 0.05)
        .map(|a| (-f64::from(a.normal[0] / a.normal[1]), -f64::from(a.normal[2] / a.normal[1])))
        .collect()
}

/// Variance of the slopes about their mean, `var(sₓ) + var(s_z)`.
fn slope_variance(s: &[(f64, f64)]) -> f64 {
    let n = s.len().max(1) as f64;
    let (mx, mz) = s.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    s.iter().map(|p| (p.0 - mx).powi(2) + (p.1 - mz).powi(2)).sum::<f64>() / n
}

/// Fewest cycles across the top-down view a wave vector needs to count in the resolved peak
/// share: a wave longer than a quarter of the view shows as a tilt or a bend of it, not as a
/// wave vector the view can tell from its neighbours.
const RESOLVED_CYCLES: f64 = 4.0;

/// Share of the slope power (mean removed) in the [`PEAKS`] strongest wave vectors of the slopes'
/// 2-D spectrum of a top-down frame (brine-testkit `lattice::peak_share`): `(plain, resolved)`.
/// The plain share is of the image as it is; the resolved one tapers it with a Hann window and
/// keeps the wave vectors of at least [`RESOLVED_CYCLES`] cycles across the view, where a lattice
/// of crossing short waves shows. Waves longer than the view put their slope in the few lowest
/// bins whatever the sea, which the plain share counts as peaks.
fn peak_share(frame: &Frame) -> (f64, f64) {
    let normals: Vec<[f32; 3]> = frame.aovs.iter().map(|a| a.normal).collect();
    let n = frame.width as usize;
    let share = |resolved_cycles| peak_share_of(&normals, n, &PeakShare { peaks: PEAKS, resolved_cycles });
    (share(None), share(Some(RESOLVED_CYCLES)))
}

/// Winds up to which the sparkle figure is measured (m s⁻¹), and its reference sample count.
const SPARKLE_MAX_WIND: f64 = 5.0;
const SPARKLE_SPP: u32 = 16;

/// Far field of the sparkle figure (m from the eye).
const FAR_FIELD_M: (f32, f32) = (150.0, 2500.0);

/// RMS high-pass noise of the displayed image over the far field, in 8-bit grey levels: the
/// luminance `0.2126 R + 0.7152 G + 0.0722 B` of the PNG (tone-mapped, sRGB) minus the mean of its
/// eight neighbours, at pixels whose 3 × 3 neighbourhood is all far-field sea. The frame is
/// written to `png` and read back, so the figure is of the image as a user sees it.
fn far_noise(frame: &Frame, png: &Path) -> Result<f64, String> {
    brine_render::write_frame(png, frame, frame.exposure_ev, false).map_err(|e| e.to_string())?;
    let img = image::open(png).map_err(|e| format!("cannot read {}: {e}", png.display()))?.to_rgb8();
    let (w, h) = (frame.width as usize, frame.height as usize);
    let y: Vec<f64> =
        img.pixels().map(|p| 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2])).collect();
    let far = |i: usize| (FAR_FIELD_M.0..=FAR_FIELD_M.1).contains(&frame.aovs[i].depth);
    let (mut sum, mut n) = (0.0, 0.0);
    for r in 1..h - 1 {
        for c in 1..w - 1 {
            let around = [
                (r - 1, c - 1),
                (r - 1, c),
                (r - 1, c + 1),
                (r, c - 1),
                (r, c + 1),
                (r + 1, c - 1),
                (r + 1, c),
                (r + 1, c + 1),
            ];
            if !far(r * w + c) || !around.iter().all(|&(a, b)| far(a * w + b)) {
                continue;
            }
            let mean = around.iter().map(|&(a, b)| y[a * w + b]).sum::<f64>() / 8.0;
            sum += (y[r * w + c] - mean).powi(2);
            n += 1.0;
        }
    }
    if n < 100.0 {
        return Err(format!("too few far-field sea pixels ({n}) for the sparkle figure"));
    }
    Ok((sum / n).sqrt())
}

/// Seeds over which the glitter figure is also averaged: one realisation of the sea scatters it by
/// about ±0.1 (at 12 m/s, seeds 1–6: FFT 0.83–1.08, trochoids 0.93–1.15).
const GLITTER_SEEDS: u32 = 6;

/// Winds at which the glitter is inverted for the slope variance (m s⁻¹).
const GLITTER_WINDS: [f64; 3] = [2.0, 5.0, 12.0];
/// Width of the slope bins of the glitter inversion (1).
const GLITTER_BIN: f64 = 0.02;
/// Fewest pixels a slope bin needs to enter the moments.
const GLITTER_MIN_PIXELS: usize = 8;

/// The scene the glitter is measured on: the sun 30° high straight ahead in a clear sky, a camera
/// 10 m up pitched 30° down with a 90° vertical field, so that the glitter's centre (the flat
/// sea's mirror point, 30° below the horizon) is in the middle of the image.
/// `surface = "brdf"` draws no waves (`waves = 0`): the whole slope variance is in the BRDF, where
/// the inversion must return Cox & Munk's total — the check of the method.
fn glitter_scene(surface: &str, wind: f64, seed: u32) -> String {
    let (surface, waves) = if surface == "brdf" { ("trochoids", "waves = 0\n") } else { (surface, "") };
    format!(
        "[camera]\nposition = [0.0, 10.0, 0.0]\npitch_deg = -30.0\nyaw_deg = 90.0\nfov_deg = 90.0\nwidth = 640\nheight = 360\n\n\
         [sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = 20.0\nseed = {seed}\n{waves}\n\
         [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 90.0\n"
    )
}

/// The slope variance the sun's glitter implies: Cox & Munk's inversion of their photographs.
///
/// For each sea pixel, the glint per unit of the sun's irradiance (the `glint` output variable)
/// gives the density of the slope that mirrors the sun toward the eye (brine-optics
/// `glitter_slope_density`, Cox & Munk's glitter equation inverted). Averaged over the pixels of each `ζ`
/// bin, `p` gives the slope distribution over the slopes the image sees; its central second
/// moment (the trace of the covariance) is returned. The image sees slopes out to about ±0.4
/// along the sun's direction: wider distributions are truncated, which the caller corrects by
/// the same measurement on a Gaussian sea of Cox & Munk's variance.
fn glitter_variance(surface: &str, wind: f64, seed: u32) -> Result<f64, String> {
    let text = glitter_scene(surface, wind, seed);
    let scene = Scene::from_toml_str(&text, "glitter.toml").map_err(|e| e.to_string())?;
    let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
    let frame = brine_render::render(&scene, &RenderOptions::default(), &|| {}).map_err(|e| e.to_string())?;
    let l = world.sky().sun().direction;
    let n = (2.0 / GLITTER_BIN) as usize;
    let mut bins = vec![(0.0f64, 0usize); n * n];
    for j in 0..frame.height {
        for i in 0..frame.width {
            let a = &frame.aovs[(j * frame.width + i) as usize];
            if !a.depth.is_finite() {
                continue;
            }
            let v = -world.camera().direction(f64::from(i) + 0.5, f64::from(j) + 0.5);
            if v.y <= 0.0 {
                continue;
            }
            // The world is y up; the glitter equation takes z up.
            let z_up = |d: glam::DVec3| glam::DVec3::new(d.x, d.z, d.y);
            let (zx, zz, p) =
                brine_optics::glitter_slope_density(z_up(v), z_up(l), f64::from(a.glint), brine_optics::WATER_IOR);
            let (bx, bz) = (((zx + 1.0) / GLITTER_BIN).floor(), ((zz + 1.0) / GLITTER_BIN).floor());
            if !(0.0..n as f64).contains(&bx) || !(0.0..n as f64).contains(&bz) {
                continue;
            }
            let b = &mut bins[bz as usize * n + bx as usize];
            b.0 += p;
            b.1 += 1;
        }
    }
    let centre = |k: usize| -1.0 + (k as f64 + 0.5) * GLITTER_BIN;
    let (mut m0, mut mx, mut mz, mut mxx, mut mzz) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (k, &(sum, count)) in bins.iter().enumerate() {
        if count < GLITTER_MIN_PIXELS {
            continue;
        }
        let p = sum / count as f64;
        let (x, z) = (centre(k % n), centre(k / n));
        (m0, mx, mz, mxx, mzz) = (m0 + p, mx + p * x, mz + p * z, mxx + p * x * x, mzz + p * z * z);
    }
    if !(m0 > 0.0) {
        return Err(format!("glitter of {surface} at {wind} m/s: no glint in view"));
    }
    let (cx, cz) = (mx / m0, mz / m0);
    Ok(mxx / m0 - cx * cx + mzz / m0 - cz * cz)
}

/// Winds at which the reflected sky is compared with the mirror and the lobe-blurred sky (m s⁻¹).
const SKY_WINDS: [f64; 1] = [16.0];

/// How well the near field's radiance follows the sky reflected at the mirror direction of each
/// pixel's shading normal, and the same sky blurred by the reflection lobe of the waves not
/// drawn (a Gaussian of twice their slope deviation, as the renderer's `FilteredSky` lookup):
/// the squared correlation `R²` of the pixels' luminance with each, over the sea 10–30 m away,
/// pixels less than a tenth covered by foam or whitecap (Darles' foam is a thin veil everywhere).
fn sky_r2(scene_text: &str, frame: &Frame) -> Result<(f64, f64), String> {
    let scene = Scene::from_toml_str(scene_text, "sky.toml").map_err(|e| e.to_string())?;
    let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
    let y = |c: glam::DVec3| c.dot(glam::DVec3::new(0.2126, 0.7152, 0.0722));
    let v = world.variance_unresolved();
    let lobe = 2.0 * (0.5 * (v.sigma_x2() + v.sigma_y2())).sqrt();
    let (mut lum, mut mirror, mut blurred) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..frame.height {
        for i in 0..frame.width {
            let k = (j * frame.width + i) as usize;
            let a = &frame.aovs[k];
            if !(NEAR_FIELD_M.0..=NEAR_FIELD_M.1).contains(&a.depth) || a.foam > 0.1 || a.whitecap > 0.1 {
                continue;
            }
            let d = world.camera().direction(f64::from(i) + 0.5, f64::from(j) + 0.5);
            let n = glam::DVec3::from_array(a.normal.map(f64::from));
            let mut r = brine_optics::reflect(d, n);
            if r.y < 1e-3 {
                r = glam::DVec3::new(r.x, 1e-3, r.z).normalize();
            }
            lum.push(y(frame.pixels[k]));
            mirror.push(y(world.sky().radiance_rgb(r)));
            blurred.push(y(world.filtered_sky().radiance(r, lobe, |r| world.sky().radiance_rgb(r))));
        }
    }
    let r2 = |x: &[f64], z: &[f64]| {
        let m = x.len() as f64;
        let (mx, mz) = (x.iter().sum::<f64>() / m, z.iter().sum::<f64>() / m);
        let (mut sxz, mut sxx, mut szz) = (0.0, 0.0, 0.0);
        for (a, b) in x.iter().zip(z) {
            (sxz, sxx, szz) = (sxz + (a - mx) * (b - mz), sxx + (a - mx).powi(2), szz + (b - mz).powi(2));
        }
        sxz * sxz / (sxx * szz)
    };
    if lum.len() < 100 {
        return Err(format!("sky R²: only {} near-field pixels", lum.len()));
    }
    Ok((r2(&lum, &blurred), r2(&lum, &mirror)))
}

/// Points of the tile-lag correlation, spread by the `R₂` sequence over a square of this side (m).
const LAG_POINTS: usize = 20_000;
const LAG_SQUARE_M: f64 = 2_000.0;

/// Side of a pixel of the tile lags' top-down view on the sea (m): [`TOP_DOWN_HEIGHT_M`] up, a 60° field over [`TOP_DOWN_SIZE`] pixels.
fn top_down_pixel_m() -> f64 {
    2.0 * TOP_DOWN_HEIGHT_M * 30f64.to_radians().tan() / f64::from(TOP_DOWN_SIZE)
}

/// How much the FFT sea repeats: what its cascades' repetition adds to the correlation of the
/// sea's slopes with themselves one tile `L_c` away. At that lag only cascade `c` can repeat
/// (the tiles are incommensurate), and it adds its share of the slope variance times its own
/// slopes' correlation with themselves there, `ρ_c` (1 for a periodic cascade; a cascade read
/// through its blend, brine-waves `TileBlend`, does not repeat), along x, z and the diagonal.
/// What any sea of the spectrum correlates at that distance is not counted. Returns the
/// largest over the cascades: of the slopes a pixel of the top-down view shows (each cascade's
/// gradient averaged over the pixel's footprint and blended, as brine-waves `FftSlopeFilter`
/// reads it), over [`LAG_POINTS`] points, and of the drawn surface (the traced gradient).
fn tile_lag_correlation(text: &str) -> Result<(f64, f64), String> {
    let scene = Scene::from_toml_str(text, "lags.toml").map_err(|e| e.to_string())?;
    let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
    let brine_waves::FrameSurface::Fft(frame) = world.sea().surface() else {
        return Err("tile lags: not an FFT sea".into());
    };
    let sigma = top_down_pixel_m() / brine_waves::BOX_WIDTH_PER_SIGMA;
    // The R₂ low-discrepancy sequence (Roberts 2018): an even cover, no seed.
    let (a1, a2) = (0.754_877_666_246_692_7, 0.569_840_290_998_053_3);
    let points: Vec<(f64, f64)> = (0..LAG_POINTS)
        .map(|i| {
            let i = i as f64 + 1.0;
            (LAG_SQUARE_M * (0.5 + a1 * i).fract(), LAG_SQUARE_M * (0.5 + a2 * i).fract())
        })
        .collect();
    // Variance of a slope field (both components) and its largest correlation with itself at
    // the cascade's tile lags (the components pooled).
    let stats = |slope: &dyn Fn(f64, f64) -> (f64, f64), l: f64| {
        let values: Vec<(f64, f64)> = points.iter().map(|&(x, z)| slope(x, z)).collect();
        let n = values.len() as f64;
        let mean = values.iter().fold((0.0, 0.0), |m, v| (m.0 + v.0 / n, m.1 + v.1 / n));
        let var = values.iter().map(|v| (v.0 - mean.0).powi(2) + (v.1 - mean.1).powi(2)).sum::<f64>() / n;
        let mut rho = f64::NEG_INFINITY;
        for lag in [(l, 0.0), (0.0, l), (l, l)] {
            let cov = points
                .iter()
                .zip(&values)
                .map(|(&(x, z), v)| {
                    let w = slope(x + lag.0, z + lag.1);
                    (v.0 - mean.0) * (w.0 - mean.0) + (v.1 - mean.1) * (w.1 - mean.1)
                })
                .sum::<f64>()
                / n;
            rho = rho.max(cov / var.max(f64::MIN_POSITIVE));
        }
        (var, rho)
    };
    let (mut seen, mut drawn) = (Vec::new(), Vec::new());
    for c in frame.cascades() {
        let base = c
            .gradients()
            .iter()
            .zip(c.heights())
            .map(|(g, &h)| [f64::from(g[0]), f64::from(g[1]), f64::from(h)])
            .collect();
        let pyramid = brine_waves::FftPyramid::<3>::new(c.resolution(), c.spacing(), base);
        let filtered = |x: f64, z: f64| match c.blend() {
            None => {
                let m = pyramid.footprint_mean(x, z, sigma);
                (m[0], m[1])
            }
            Some(b) => b.corners(x, z).iter().filter(|k| k.weight > 0.0).fold((0.0, 0.0), |g, k| {
                let m = pyramid.footprint_mean(x + k.offset[0], z + k.offset[1], sigma);
                (g.0 + k.weight * m[0] + m[2] * k.gradient[0], g.1 + k.weight * m[1] + m[2] * k.gradient[1])
            }),
        };
        let traced = |x: f64, z: f64| {
            let g = c.traced_gradient(x, z);
            (g.x, g.y)
        };
        seen.push(stats(&filtered, c.tile_size()));
        drawn.push(stats(&traced, c.tile_size()));
    }
    let largest_excess = |v: &[(f64, f64)]| {
        let total: f64 = v.iter().map(|s| s.0).sum();
        v.iter().map(|&(var, rho)| var / total * rho).fold(0.0, f64::max)
    };
    Ok((largest_excess(&seen), largest_excess(&drawn)))
}

/// Shortest wave the detail figure can count, in near-field footprints: a box of side `w`
/// averages a wave of length `2w` to `2/π` of its slope (`sinc(π w/λ)`), so 0.41 of its slope
/// variance; shorter waves keep less.
const VISIBLE_WAVE_FOOTPRINTS: f64 = 2.0;

/// What the detail figure can reach: the share of Cox & Munk's total that Elfouhaily et al.
/// (1997)'s spectrum, the one published model of the short wind waves (whose total slope
/// variance follows Cox & Munk's), holds in waves longer than [`VISIBLE_WAVE_FOOTPRINTS`] times
/// the median pixel footprint `α t/√|d_y|` of the near field. Returns the share and that footprint (m).
fn detail_reach(text: &str, frame: &Frame, wind: f64) -> Result<(f64, f64), String> {
    let scene = Scene::from_toml_str(text, "reach.toml").map_err(|e| e.to_string())?;
    let world = brine_render::World::new(&scene).map_err(|e| e.to_string())?;
    let angle = world.filtering_angle();
    let mut footprints = Vec::new();
    for j in 0..frame.height {
        for i in 0..frame.width {
            let a = &frame.aovs[(j * frame.width + i) as usize];
            if (NEAR_FIELD_M.0..=NEAR_FIELD_M.1).contains(&a.depth) {
                let d = world.camera().direction(f64::from(i) + 0.5, f64::from(j) + 0.5);
                footprints.push(angle * f64::from(a.depth) / d.y.abs().sqrt());
            }
        }
    }
    if footprints.is_empty() {
        return Err("detail reach: no near-field pixel".into());
    }
    footprints.sort_by(f64::total_cmp);
    let w = footprints[footprints.len() / 2];
    let spectrum = brine_waves::Elfouhaily::fully_developed(wind).map_err(|e| e.to_string())?;
    let (up, cross) = spectrum.slope_variances(std::f64::consts::TAU / (VISIBLE_WAVE_FOOTPRINTS * w));
    Ok(((up + cross) / cox_munk_total(wind), w))
}

/// Winds of the energy comparison (m s⁻¹).
const ENERGY_WINDS: [f64; 3] = [3.0, 10.0, 18.0];
/// Image of the energy comparison (pixels) and the reference's samples per pixel.
const ENERGY_SIZE: (u32, u32, u32) = (256, 144, 16);

/// The mean luminance of each tenth of the rows of the frame at one sample per pixel, over that of
/// the reference rendering (nothing faded or filtered with the footprint, [`ENERGY_SIZE`] samples
/// per pixel), for the sea tenths (the fourth to the tenth; the first three are sky). The
/// default scene's view with the sun behind the camera (so that no glitter, sampled once per
/// pixel, adds noise), white water, spray and glare off.
fn energy_bands(surface: &str, wind: f64) -> Result<Vec<f64>, String> {
    let (w, h, spp) = ENERGY_SIZE;
    let text = format!(
        "[camera]\nposition = [0.0, 10.0, 0.0]\nyaw_deg = 100.0\npitch_deg = -9.0\nwidth = {w}\nheight = {h}\n\n\
         [sea]\nsurface = \"{surface}\"\nwind_speed_m_s = {wind}\nwind_direction_deg = 20.0\n\n\
         [sky]\nsun_elevation_deg = 30.0\nsun_azimuth_deg = 280.0\n\n\
         [phenomena]\nfoam = false\nwhitecaps = false\nspray = false\nglare = false\n"
    );
    let scene = Scene::from_toml_str(&text, "energy.toml").map_err(|e| e.to_string())?;
    let bands = brine_render::energy_bands(&scene, spp).map_err(|e| e.to_string())?;
    Ok(bands[3..].to_vec())
}

/// The far-field sparkle of one surface at one wind: [`far_noise`] at one sample per pixel over
/// that at [`SPARKLE_SPP`]; the two frames are written to `target/`.
fn sparkle_of(root: &Path, surface: &str, wind: f64) -> Result<f64, String> {
    let name = format!("{surface}-{wind:02}");
    let frame = render(&scene_text(surface, wind, false, 1), &format!("{name}.toml"))?;
    let fine = render(&scene_text(surface, wind, false, SPARKLE_SPP), &format!("{name}-spp.toml"))?;
    let target = root.join("target");
    let coarse = target.join(format!("beaufort-{name}-spp1.png"));
    let reference = target.join(format!("beaufort-{name}-spp{SPARKLE_SPP}.png"));
    Ok(far_noise(&frame, &coarse)? / far_noise(&fine, &reference)?)
}

/// `cargo xtask beaufort --energy`: the sheet's energy bands alone, printed.
pub fn energy() -> Result<(), String> {
    for surface in SURFACES {
        for wind in ENERGY_WINDS {
            let bands = energy_bands(surface, wind)?;
            let cells: Vec<String> = bands.iter().map(|b| format!("{:+.1} %", 100.0 * (b - 1.0))).collect();
            println!("energy {surface} {wind} m/s: {}", cells.join(" "));
        }
    }
    Ok(())
}

/// Seeds of `cargo xtask beaufort --detail`.
const DETAIL_SEEDS: u32 = 8;

/// The detail figure of the sheet's view for seeds 1 to [`DETAIL_SEEDS`]: each seed's (those with a
/// near field in view) and the pooled one, of every seed's near-field slopes about their common
/// mean.
fn seeds_detail(surface: &str, wind: f64) -> Result<(Vec<f64>, f64), String> {
    let mut pooled = Vec::new();
    let mut each = Vec::new();
    for seed in 1..=DETAIL_SEEDS {
        let text = scene_text(surface, wind, false, 1).replace("seed = 3", &format!("seed = {seed}"));
        let frame = render(&text, "detail.toml")?;
        let s = slopes(&frame, NEAR_FIELD_M);
        if !s.is_empty() {
            each.push(slope_variance(&s) / cox_munk_total(wind));
        }
        pooled.extend(s);
    }
    Ok((each, slope_variance(&pooled) / cox_munk_total(wind)))
}

/// `cargo xtask beaufort --detail`: the detail figure of the sheet's view for [`DETAIL_SEEDS`]
/// seeds at 8–22 m/s, each and pooled (the slopes of every seed's near field about their common
/// mean), and the share of Cox & Munk's total that Elfouhaily et al.'s spectrum holds in waves
/// longer than 20 m, which one view's 20 m deep near field sees as a tilt.
pub fn detail() -> Result<(), String> {
    for surface in SURFACES {
        for wind in [8.0, 12.0, 16.0, 22.0] {
            let (each, pooled) = seeds_detail(surface, wind)?;
            let each: Vec<String> = each.iter().map(|d| format!("{d:.2}")).collect();
            let spectrum = brine_waves::Elfouhaily::fully_developed(wind).map_err(|e| e.to_string())?;
            let (up, cross) = spectrum.slope_variances(std::f64::consts::TAU / 20.0);
            println!(
                "detail {surface} {wind} m/s: seeds {} · pooled {pooled:.2} · in waves over 20 m {:.2}",
                each.join(" "),
                (up + cross) / cox_munk_total(wind)
            );
        }
    }
    Ok(())
}

/// `cargo xtask beaufort --sparkle`: the sheet's sparkle figures alone, printed.
pub fn sparkle(root: &Path) -> Result<(), String> {
    for wind in WINDS.into_iter().filter(|&w| w <= SPARKLE_MAX_WIND) {
        for surface in SURFACES {
            println!("sparkle {surface} {wind} m/s: {:.2}", sparkle_of(root, surface, wind)?);
        }
    }
    Ok(())
}

/// Renders and measures the sheet, writing `docs/beaufort.md` and `docs/beaufort/*.png`.
pub fn run(root: &Path) -> Result<(), String> {
    let dir = root.join("docs/beaufort");
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let mut rows = String::new();
    for wind in WINDS {
        let mut cells = Vec::new();
        for surface in SURFACES {
            let name = format!("{surface}-{wind:02}");
            eprintln!("beaufort: {name}");
            let text = scene_text(surface, wind, false, 1);
            let frame = render(&text, &format!("{name}.toml"))?;
            let png = dir.join(format!("{name}.png"));
            brine_render::write_frame(&png, &frame, frame.exposure_ev, false).map_err(|e| e.to_string())?;
            let detail = slope_variance(&slopes(&frame, NEAR_FIELD_M)) / cox_munk_total(wind);
            let (reach, _) = detail_reach(&text, &frame, wind)?;
            let (_, pooled) = seeds_detail(surface, wind)?;
            let lags = if surface == "fft" {
                let (seen, drawn) = tile_lag_correlation(&scene_text(surface, wind, true, 1))?;
                format!(" · tile lags {seen:.2} (drawn {drawn:.2})")
            } else {
                String::new()
            };
            let top =
                render(&view_text(surface, wind, Some(peaks_height_m(wind)), 1, false), &format!("{name}-top.toml"))?;
            let (peaks, resolved_peaks) = peak_share(&top);
            let sparkle = if wind <= SPARKLE_MAX_WIND {
                format!(" · sparkle {:.2}", sparkle_of(root, surface, wind)?)
            } else {
                String::new()
            };
            let sky = if SKY_WINDS.contains(&wind) {
                let (lobe, mirror) = sky_r2(&text, &frame)?;
                format!(" · sky R² {lobe:.2} (mirror {mirror:.2})")
            } else {
                String::new()
            };
            cells.push(format!(
                "![{surface} at {wind} m/s](beaufort/{name}.png)<br>detail {detail:.2} ({DETAIL_SEEDS} seeds {pooled:.2}; reach {reach:.2}) · peaks {peaks:.2} (resolved {resolved_peaks:.2}){lags}{sparkle}{sky}"
            ));
            let sun_name = format!("{name}-sun");
            let facing = render(&scene_text_facing(surface, wind, false, 1, true), &format!("{sun_name}.toml"))?;
            let sun_png = dir.join(format!("{sun_name}.png"));
            brine_render::write_frame(&sun_png, &facing, facing.exposure_ev, false).map_err(|e| e.to_string())?;
            let glitter = if GLITTER_WINDS.contains(&wind) {
                // With no waves drawn the seed changes nothing: one reference serves every seed.
                let reference = glitter_variance("brdf", wind, 3)?;
                let mut each = Vec::new();
                for seed in 1..=GLITTER_SEEDS {
                    each.push(glitter_variance(surface, wind, seed)? / reference);
                }
                let mean = each.iter().sum::<f64>() / each.len() as f64;
                format!("<br>glitter {:.2} ({GLITTER_SEEDS} seeds {mean:.2})", each[2])
            } else {
                String::new()
            };
            cells.push(format!("![{surface} at {wind} m/s, toward the sun](beaufort/{sun_name}.png){glitter}"));
        }
        let _ = writeln!(rows, "| {wind} | {} |", cells.join(" | "));
    }
    let mut check = Vec::new();
    for wind in GLITTER_WINDS {
        eprintln!("beaufort: glitter check at {wind} m/s");
        check.push(format!("{:.2} at {wind} m/s", glitter_variance("brdf", wind, 3)? / cox_munk_total(wind)));
    }
    let check = check.join(", ");
    let mut energy = String::new();
    for surface in SURFACES {
        for wind in ENERGY_WINDS {
            eprintln!("beaufort: energy, {surface} at {wind} m/s");
            let bands = energy_bands(surface, wind)?;
            let cells: Vec<String> = bands.iter().map(|r| format!("{:+.1} %", 100.0 * (r - 1.0))).collect();
            let _ = writeln!(energy, "| {surface} | {wind} | {} |", cells.join(" | "));
        }
    }
    let page = format!(
        "# The sea at six winds\n\n\
         The same view — a camera 10 m above the sea looking 8° down, the sun 30° high and 90° to the\n\
         right, a third of the sky clouded (and, in the second column of each surface, the sun straight ahead\n\
         in a clear sky), a vertical field of view of 50° — at 2, 5, 8, 12, 16 and 22 m/s (Beaufort 2 to 9), on the\n\
         trochoid sea (the default) and the FFT sea. Every other key is the default scene's.\n\
         Regenerate with `cargo xtask gallery` (which also renders `docs/gallery/`).\n\n\
         Under each image, measured from the render's own output variables:\n\n\
         - **detail**: the slope variance of the shading normals 10–30 m from the eye, as a share of\n\
           Cox & Munk's clean-surface total at that wind. The rest of the slopes are in the BRDF:\n\
           the pixel, 5–13 cm wide there, cannot show them. In brackets, what the figure can reach:\n\
           the share of Cox & Munk's total that Elfouhaily et al. (1997)'s spectrum — the published\n\
           model of the short wind waves, whose total follows Cox & Munk's — holds in waves longer than\n\
           {VISIBLE_WAVE_FOOTPRINTS} median footprints of the near field (a pixel keeps 0.41 of the slope\n\
           variance of a wave two footprints long, less of shorter ones). From 12 m/s most of Cox &\n\
           Munk's total is in waves shorter than that: no sea filtered with its pixels shows half of it\n\
           there, and one that showed more would sparkle. Also in brackets, the figure of the slopes of\n\
           {DETAIL_SEEDS} seeds' near fields pooled: one view's near field is a small patch of sea, and the\n\
           figure moves with the seed (on the trochoid sea at 8 m/s from 0.41 to 0.56).\n\
         - **peaks**: on a top-down view of the same sea (256 × 256 normals), the share of the slope\n\
           power in its {PEAKS} strongest wave vectors. A handful of crossing waves — a lattice of\n\
           glints — puts most of the power there; a sea of many waves little. The view scales with the\n\
           sea: it looks down from `50 (U₁₀/8)²` m (58 m across at 8 m/s, about one peak wavelength; 231 m\n\
           at 16 m/s), because the sea's wave lengths grow as `U₁₀²/g` (its waves are fitted over a band\n\
           set in units of the peak frequency, and the pixel, which sets where the drawn waves end and\n\
           the detail normals and the BRDF take over, grows with the view). From 5 m/s each view thus\n\
           holds the same drawn waves and normals in units of the peak wavelength, and the figure is the\n\
           same; at 2 m/s the drawn band ends sooner, where the spectrum reaches Cox & Munk's total. On one fixed 58 m view, the waves longer than a quarter of\n\
           it would show as a tilt and put their slope in its few lowest bins, whatever the sea (of the\n\
           trochoid set's slope variance, 22 % at 8 m/s and 51 % at 16): there, at 16 m/s over seeds 1–5,\n\
           the share is 0.45–0.50 on the trochoid sea and 0.32–0.43 on the FFT sea, whose continuous\n\
           spectrum has no lattice. In brackets, the same share of the wave vectors the view resolves (at least\n\
           {RESOLVED_CYCLES} cycles across it, the image tapered by a Hann window, which spreads each wave\n\
           vector over a few of the bins counted).\n\
         - **tile lags** (FFT): how much the sea repeats. One tile of a cascade away, its repetition\n\
           adds to the correlation of the sea's slopes its share of their variance times its own\n\
           correlation there: 1 for a periodic cascade, about 0 for one read through its blend of\n\
           randomly offset reads (the sea's cascades are). The figure is the largest over the\n\
           cascades (along x, z and the diagonal): of the slopes a pixel of a top-down view 50 m up shows\n\
           (averaged over its {px:.2} m footprint, {LAG_POINTS} points), and (in brackets) of the drawn\n\
           surface, down to its millimetre waves. What any sea of the spectrum correlates at that\n\
           distance is not counted.\n\
         - **sparkle** (2 and 5 m/s): the high-pass noise of the far field (150 m to 2.5 km) at 1\n\
           sample per pixel over that at {SPARKLE_SPP} (whose samples each filter over a quarter of the\n\
           pixel's width, the rest covered by their spread): near 1 when each pixel is filtered over\n\
           its footprint, large when sub-pixel glints alias.\n\
         - **sky R²** (16 m/s): over the sea 10–30 m away (under a tenth foam), the squared correlation of the\n\
           pixels' luminance with the sky reflected at each pixel's mirror direction blurred by the\n\
           reflection lobe of the waves not drawn, and (in brackets) with the unblurred mirror sky.\n\
         - **glitter** (2, 5 and 12 m/s, under the sun-facing image): the total slope variance the sun's\n\
           glitter implies, over that of a Gaussian sea of Cox & Munk's variance seen the same way.\n\
           Measured on its own render (the sun 30° high straight ahead, the camera pitched 30° down\n\
           with a 90° field, so the glitter is centred): each sea pixel's glint per unit of sun\n\
           irradiance (the `glint` output variable) gives the slope density of the facet that mirrors\n\
           the sun, `p = 4 (L/E) cos θ_v cos⁴β / ρ(ω)` (Cox & Munk 1954); the central second moment of\n\
           its average over slope bins is the variance. The image sees slopes to about ±0.4 along the\n\
           sun, so wide distributions are truncated; the reference — the same measurement on a sea\n\
           with no waves drawn, every slope in the BRDF with Cox & Munk's variance — is truncated the\n\
           same way and returns {check} of Cox & Munk's total. In brackets, the mean of the figure over\n\
           seeds 1 to {GLITTER_SEEDS} (the image's is seed 3): one realisation scatters it by about ±0.1.\n\n\
         | U₁₀ (m/s) | trochoids | trochoids, toward the sun | FFT | FFT, toward the sun |\n|---|---|---|---|---|\n{rows}\n\
         ## Energy: the filtered frame against the reference\n\n\
         The mean luminance of each tenth of the rows (from the fourth, the first sea rows near the\n\
         horizon, to the tenth, the foreground) of a {ew}×{eh} frame at one sample per pixel, against\n\
         `brine render --reference` of the same scene at {espp} samples per pixel: nothing faded or\n\
         filtered with the pixel footprint. The default view with the sun behind the camera (no\n\
         glitter to sample), white water, spray and glare off. The reference traces the fitted waves\n\
         (or the FFT cascades) as geometry; the detail normals it reads unfiltered are normals, not\n\
         geometry, each sample weighted by its facet's projected area. See `docs/renderer.md`.\n\n\
         | surface | U₁₀ (m/s) | 4th | 5th | 6th | 7th | 8th | 9th | 10th |\n|---|---|---|---|---|---|---|---|---|\n{energy}",
        ew = ENERGY_SIZE.0,
        eh = ENERGY_SIZE.1,
        espp = ENERGY_SIZE.2,
        px = top_down_pixel_m()
    );
    let path = root.join("docs/beaufort.md");
    std::fs::write(&path, page).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    eprintln!("wrote {}", path.display());
    Ok(())
}
