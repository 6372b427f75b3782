//! Plots of brine-trace: evaluations per ray over the image for each method, their growth with the
//! number of waves, and the steps along one grazing ray.

use std::path::Path;

use brine_texture::Pinhole;
use brine_trace::{LipschitzSum, Method, Ray, RayTile, TraceOptions, TraceStats, trace, trace_logged, trace_tile};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TracedTrochoids, TrochoidSet, fit_trochoids};
use glam::DVec3;
use plotters::prelude::*;

use super::{LineChart, Scale};

/// Heat-map resolution: every `STRIDE`-th pixel of a 640×480 image.
const STRIDE: usize = 16;
const WIDTH: usize = 640;
const HEIGHT: usize = 480;

/// The default scene's view: brine-texture's pinhole camera (the renderer's), 10 m up, bearing
/// 100°, pitch −9°, 50° field of view.
struct Camera(Pinhole);

impl Camera {
    fn default_scene() -> Self {
        let position = DVec3::new(0.0, 10.0, 0.0);
        Self(Pinhole::from_angles(position, 100.0, -9.0, 50.0, WIDTH as u32, HEIGHT as u32).expect("a valid camera"))
    }

    /// The direction through the centre of pixel `(x, y)`.
    fn direction(&self, x: usize, y: usize) -> DVec3 {
        self.0.direction(x as f64 + 0.5, y as f64 + 0.5)
    }

    fn pixel_angle(&self) -> f64 {
        self.0.pixel_angle()
    }
}

fn sea(n: usize) -> Result<TrochoidSet, String> {
    let pm = PiersonMoskowitz::from_u10(10.0).map_err(|e| e.to_string())?;
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).map_err(|e| e.to_string())?;
    let options = FitOptions { wind_direction: 20f64.to_radians(), choppiness: 2.5, ..FitOptions::default() };
    fit_trochoids(&pm, &spreading, n, 1, &options).map_err(|e| e.to_string())
}

/// A variant of the tracer: name, method, footprint fading, image coherence.
type Variant = (&'static str, Method, bool, bool);

const VARIANTS: [Variant; 8] = [
    ("brute force", Method::BruteForce, false, false),
    ("global L (Hart)", Method::GlobalLipschitz, false, false),
    ("directional L", Method::Directional, false, false),
    ("relaxed (Keinert)", Method::Relaxed, false, false),
    ("Darles Alg. 1", Method::Darles, false, false),
    ("tiered", Method::Tiered, false, false),
    ("tiered + footprint", Method::Tiered, true, false),
    ("tiered + fp + cones", Method::Tiered, true, true),
];

/// Evaluations of every ray of the `w × h` grid (`None`: no hit), for one variant.
fn evaluations(sea: &TracedTrochoids, camera: &Camera, variant: &Variant) -> (Vec<f64>, Vec<bool>) {
    let (w, h) = (WIDTH / STRIDE, HEIGHT / STRIDE);
    let dirs: Vec<DVec3> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| camera.direction(x * STRIDE + STRIDE / 2, y * STRIDE + STRIDE / 2))
        .collect();
    let o = TraceOptions::comparison(variant.1, if variant.2 { camera.pixel_angle() } else { 0.0 });
    let mut stats = TraceStats::default();
    if variant.3 {
        let mut hits = vec![None; dirs.len()];
        let mut costs = vec![0.0; dirs.len()];
        let tile = RayTile { origin: camera.0.position, directions: &dirs, width: w };
        trace_tile(sea, &tile, &o, &mut stats, &mut hits, Some(&mut costs));
        return (costs, hits.iter().map(Option::is_some).collect());
    }
    dirs.iter()
        .map(|d| {
            let before = stats.evaluations;
            let hit = Ray::new(camera.0.position, *d).ok().and_then(|r| trace(sea, &r, &o, &mut stats));
            ((stats.evaluations - before) as f64, hit.is_some())
        })
        .unzip()
}

fn mean_per_hit(costs: &[f64], hits: &[bool]) -> f64 {
    let (sum, n) = costs.iter().zip(hits).filter(|(_, h)| **h).fold((0.0, 0usize), |(s, n), (c, _)| (s + c, n + 1));
    sum / n.max(1) as f64
}

/// Writes the brine-trace figures into `dir`.
pub fn plot(dir: &Path) -> Result<(), String> {
    let camera = Camera::default_scene();
    let set = sea(50)?;
    let fast = TracedTrochoids::new(&set, 0.0);
    heat_maps(dir, &fast, &camera)?;
    growth_with_n(dir, &camera)?;
    steps_along_a_ray(dir, &fast, &camera)
}

/// `trace-evaluations.svg`: evaluations per ray over the image, one panel per method.
fn heat_maps(dir: &Path, sea: &TracedTrochoids, camera: &Camera) -> Result<(), String> {
    let path = dir.join("trace-evaluations.svg");
    let err = |e: &dyn std::fmt::Display| format!("plot {}: {e}", path.display());
    let root = SVGBackend::new(&path, (1280, 620)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let (title, body) = root.split_vertically(50);
    title
        .titled(
            "Evaluations of F per ray, default scene (N = 50, 10 m camera), every 16th pixel; \
             colour: log₁₀ evaluations, 1 (purple) to 1000 (yellow); grey: sky (under one evaluation)",
            ("sans-serif", 15),
        )
        .map_err(|e| err(&e))?;
    let (w, h) = (WIDTH / STRIDE, HEIGHT / STRIDE);
    for (panel, variant) in body.split_evenly((2, 4)).iter().zip(VARIANTS.iter()) {
        let (costs, hits) = evaluations(sea, camera, variant);
        let caption = format!("{}: {:.1} per hit", variant.0, mean_per_hit(&costs, &hits));
        let area = panel.margin(4, 4, 4, 4).titled(&caption, ("sans-serif", 14)).map_err(|e| err(&e))?;
        let (pw, ph) = area.dim_in_pixel();
        let (cw, ch) = (pw as f64 / w as f64, ph as f64 / h as f64);
        for y in 0..h {
            for x in 0..w {
                let c = costs[y * w + x];
                // Below one evaluation: a culled ray, or a sky ray whose share of its cones is small.
                let colour = if c < 1.0 {
                    RGBColor(200, 200, 200)
                } else {
                    ViridisRGB::get_color((c.log10() / 3.0).clamp(0.0, 1.0))
                };
                let (x0, y0) = ((x as f64 * cw) as i32, (y as f64 * ch) as i32);
                let (x1, y1) = (((x + 1) as f64 * cw).ceil() as i32, ((y + 1) as f64 * ch).ceil() as i32);
                area.draw(&Rectangle::new([(x0, y0), (x1, y1)], colour.filled())).map_err(|e| err(&e))?;
            }
        }
    }
    root.present().map_err(|e| err(&e))
}

/// `trace-evaluations-vs-n.svg` and `trace-terms-vs-n.svg`: mean evaluations and wave terms per
/// hitting ray against the number of waves.
fn growth_with_n(dir: &Path, camera: &Camera) -> Result<(), String> {
    let sizes = [10, 20, 30, 50, 100, 200];
    let chosen = [VARIANTS[0], VARIANTS[1], VARIANTS[2], VARIANTS[4], VARIANTS[5], VARIANTS[6]];
    let mut evals: Vec<(String, Vec<(f64, f64)>)> = chosen.iter().map(|v| (v.0.to_string(), vec![])).collect();
    let mut terms: Vec<(String, Vec<(f64, f64)>)> = chosen.iter().map(|v| (v.0.to_string(), vec![])).collect();
    let dirs: Vec<DVec3> = (0..HEIGHT / STRIDE)
        .flat_map(|y| (0..WIDTH / STRIDE).map(move |x| (x, y)))
        .map(|(x, y)| camera.direction(x * STRIDE + STRIDE / 2, y * STRIDE + STRIDE / 2))
        .collect();
    for n in sizes {
        let fast = TracedTrochoids::new(&sea(n)?, 0.0);
        for (k, v) in chosen.iter().enumerate() {
            let o = TraceOptions::comparison(v.1, if v.2 { camera.pixel_angle() } else { 0.0 });
            let mut stats = TraceStats::default();
            for d in &dirs {
                if let Ok(r) = Ray::new(camera.0.position, *d) {
                    trace(&fast, &r, &o, &mut stats);
                }
            }
            let hits = stats.hits.max(1) as f64;
            evals[k].1.push((n as f64, stats.evaluations as f64 / hits));
            terms[k].1.push((n as f64, stats.component_evaluations as f64 / hits));
        }
    }
    LineChart {
        title: "Mean evaluations of F per hitting ray (default camera, PM 10 m/s fits)",
        x_label: "number of waves N",
        y_label: "evaluations per hitting ray",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: evals,
    }
    .write(&dir.join("trace-evaluations-vs-n.svg"))?;
    LineChart {
        title: "Wave terms evaluated per hitting ray",
        x_label: "number of waves N",
        y_label: "wave terms per hitting ray",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: terms,
    }
    .write(&dir.join("trace-terms-vs-n.svg"))
}

/// `trace-steps.svg`: `F` along one grazing ray and the points where each method evaluates it.
fn steps_along_a_ray(dir: &Path, sea: &TracedTrochoids, camera: &Camera) -> Result<(), String> {
    let ray = Ray::new(camera.0.position, camera.direction(WIDTH / 2, 250)).map_err(|e| e.to_string())?;
    let mut series = Vec::new();
    let mut t_hit = 0.0;
    let mut t_start = f64::INFINITY;
    for v in [VARIANTS[2], VARIANTS[4], VARIANTS[5]] {
        let mut log = Vec::new();
        let hit = trace_logged(sea, &ray, &TraceOptions::comparison(v.1, 0.0), &mut TraceStats::default(), &mut log);
        t_hit = hit.map_or(t_hit, |h| h.t);
        t_start = t_start.min(log.first().map_or(t_start, |s| s.t_from));
        let pts: Vec<(f64, f64)> = log.iter().map(|s| (s.t_from, sea.value(ray.at(s.t_from)))).collect();
        series.push((format!("{} ({} points)", v.0, pts.len()), pts));
    }
    let curve: Vec<(f64, f64)> = (0..=600)
        .map(|i| t_start + (t_hit + 2.0 - t_start) * i as f64 / 600.0)
        .map(|t| (t, sea.value(ray.at(t))))
        .collect();
    series.insert(0, ("F along the ray".to_string(), curve));
    LineChart {
        title: "F along a ray of the default view, and the points each method visits",
        x_label: "t along the ray (m)",
        y_label: "F = y − h (m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("trace-steps.svg"))
}
