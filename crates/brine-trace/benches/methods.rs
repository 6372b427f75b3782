//! `cargo xtask bench trace`: every tracing method on identical primary rays, side by side.
//!
//! Seas: Pierson–Moskowitz at U10 = 10 m/s, wind toward 20°, fitted with N ∈ {30, 50, 100, 200}
//! trochoids (choppiness 2.5, Σ Q ≤ 0.9, the renderer's defaults), at three steepness levels:
//! the fitted steepness, and every wave's Q set to 0.5 and to 0.9 (sharper crests, larger slope
//! and curvature bounds). Cameras: 2 m grazing, 10 m toward the horizon (the default scene),
//! 50 m looking down; 640×480 pixels, 50° vertical field of view, trace distance 3000 m, the
//! renderer's step and tolerance options.
//!
//! All methods run on the same subsampled grid of the image (every `STRIDE`-th pixel in x and y);
//! the tiered variants also run on the whole 640×480 image. Evaluations count every point where
//! `F` (or, for Darles and the tiered method, part of it) is evaluated, refinement included;
//! cones of the image-coherent variant are shared equally among their rays.
//!
//! Environment: `BRINE_BENCH_QUICK=1` runs N = 50 and the default camera only.

use std::time::Instant;

use brine_texture::Pinhole;
use brine_trace::{
    Hit, LipschitzSum, Method, Ray, RayTile, TraceOptions, TraceStats, trace, trace_temporal, trace_tile,
};
use brine_waves::{
    CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TracedTrochoids, TrochoidSet, TrochoidSum, fit_trochoids,
    solve_trochoid_phase,
};
use glam::DVec3;

/// Subsampling of the image for the all-method comparison.
const STRIDE: usize = 8;
const WIDTH: usize = 640;
const HEIGHT: usize = 480;
const FOV_DEG: f64 = 50.0;
/// Tile of the image-coherent variant (its quadtree root).
const TILE: usize = 16;
/// One frame at 25 frames per second, for temporal coherence.
const FRAME_S: f64 = 0.04;

/// A benchmark camera: the renderer's pinhole (brine-texture `Pinhole`), named.
struct Camera {
    name: &'static str,
    pinhole: Pinhole,
    position: DVec3,
}

impl Camera {
    fn new(name: &'static str, height: f64, bearing_deg: f64, pitch_deg: f64) -> Self {
        let position = DVec3::new(0.0, height, 0.0);
        let pinhole = Pinhole::from_angles(position, bearing_deg, pitch_deg, FOV_DEG, WIDTH as u32, HEIGHT as u32)
            .expect("a valid camera");
        Self { name, pinhole, position }
    }

    /// The direction through the centre of pixel `(x, y)`.
    fn direction(&self, x: usize, y: usize) -> DVec3 {
        self.pinhole.direction(x as f64 + 0.5, y as f64 + 0.5)
    }

    fn pixel_angle(&self) -> f64 {
        self.pinhole.pixel_angle()
    }
}

/// The fitted set with every steepness replaced by `q` (or kept when `None`).
fn sea(n: usize, q: Option<f64>) -> TrochoidSet {
    let pm = PiersonMoskowitz::from_u10(10.0).expect("valid wind");
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).expect("valid spreading");
    let options = FitOptions { wind_direction: 20f64.to_radians(), choppiness: 2.5, ..FitOptions::default() };
    let set = fit_trochoids(&pm, &spreading, n, 1, &options).expect("valid fit");
    match q {
        None => set,
        Some(q) => TrochoidSet::new(set.waves().iter().map(|w| w.with_steepness(q).unwrap()).collect()),
    }
}

/// One method's result on one set of rays.
struct Row {
    name: String,
    hits: usize,
    /// Evaluations of each hitting ray.
    per_hit: Vec<f64>,
    terms_per_ray: f64,
    seconds: f64,
    rays: usize,
    t_hit: Vec<Option<f64>>,
}

impl Row {
    fn from_runs(name: String, costs: Vec<(Option<Hit>, f64)>, stats: &TraceStats, seconds: f64) -> Self {
        let rays = costs.len();
        let mut per_hit: Vec<f64> = costs.iter().filter(|c| c.0.is_some()).map(|c| c.1).collect();
        per_hit.sort_by(f64::total_cmp);
        Self {
            name,
            hits: per_hit.len(),
            per_hit,
            terms_per_ray: stats.component_evaluations as f64 / rays.max(1) as f64,
            seconds,
            rays,
            t_hit: costs.iter().map(|c| c.0.map(|h| h.t)).collect(),
        }
    }
    fn mean(&self) -> f64 {
        if self.per_hit.is_empty() { 0.0 } else { self.per_hit.iter().sum::<f64>() / self.per_hit.len() as f64 }
    }
    fn quantile(&self, q: f64) -> f64 {
        if self.per_hit.is_empty() {
            return 0.0;
        }
        self.per_hit[((self.per_hit.len() - 1) as f64 * q).round() as usize]
    }
    fn rays_per_second(&self) -> f64 {
        self.rays as f64 / self.seconds
    }
}

fn run_method(surface: &dyn LipschitzSum, rays: &[Ray], method: Method, footprint: f64, name: &str) -> Row {
    let o = TraceOptions::comparison(method, footprint);
    let mut stats = TraceStats::default();
    let start = Instant::now();
    let costs: Vec<(Option<Hit>, f64)> = rays
        .iter()
        .map(|r| {
            let before = stats.evaluations;
            let hit = trace(surface, r, &o, &mut stats);
            (hit, (stats.evaluations - before) as f64)
        })
        .collect();
    Row::from_runs(name.to_string(), costs, &stats, start.elapsed().as_secs_f64())
}

/// The tiered method with footprint fading and the cone quadtree over `TILE`×`TILE` tiles of the
/// `(xs, ys)` pixel grid.
fn run_coherent(surface: &TracedTrochoids, camera: &Camera, xs: &[usize], ys: &[usize], footprint: f64) -> Row {
    let o = TraceOptions::comparison(Method::Tiered, footprint);
    let mut stats = TraceStats::default();
    let (w, h) = (xs.len(), ys.len());
    let mut results = vec![(None, 0.0); w * h];
    let start = Instant::now();
    for ty in (0..h).step_by(TILE) {
        for tx in (0..w).step_by(TILE) {
            let (tw, th) = (TILE.min(w - tx), TILE.min(h - ty));
            let dirs: Vec<DVec3> = (0..th)
                .flat_map(|j| (0..tw).map(move |i| (i, j)))
                .map(|(i, j)| camera.direction(xs[tx + i], ys[ty + j]))
                .collect();
            let mut hits = vec![None; dirs.len()];
            let mut costs = vec![0.0; dirs.len()];
            let tile = RayTile { origin: camera.position, directions: &dirs, width: tw };
            trace_tile(surface, &tile, &o, &mut stats, &mut hits, Some(&mut costs));
            for j in 0..th {
                for i in 0..tw {
                    results[(ty + j) * w + tx + i] = (hits[j * tw + i], costs[j * tw + i]);
                }
            }
        }
    }
    Row::from_runs("tiered + fp + image coh.".into(), results, &stats, start.elapsed().as_secs_f64())
}

/// Frame t + 1/25 s with temporal coherence from the hits of frame t.
fn run_temporal(next: &TracedTrochoids, rays: &[Ray], previous: &[Option<f64>], footprint: f64) -> Row {
    let o = TraceOptions::comparison(Method::Tiered, footprint);
    let mut stats = TraceStats::default();
    let start = Instant::now();
    let costs: Vec<(Option<Hit>, f64)> = rays
        .iter()
        .zip(previous)
        .map(|(r, p)| {
            let before = stats.evaluations;
            let hit = trace_temporal(next, r, *p, &o, &mut stats);
            (hit, (stats.evaluations - before) as f64)
        })
        .collect();
    Row::from_runs("tiered + temporal coh., frame t + 1/25 s".into(), costs, &stats, start.elapsed().as_secs_f64())
}

fn print_table(title: &str, rows: &[Row], brute: Option<f64>, global: Option<f64>) {
    println!("\n{title}");
    println!(
        "| method | hitting rays | eval/hit mean | median | p99 | wave terms/ray | rays/s/thread | vs brute force | vs global L |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let ratio = |base: Option<f64>| match base {
            Some(b) if r.mean() > 0.0 => format!("{:.1}×", b / r.mean()),
            _ => "–".into(),
        };
        println!(
            "| {} | {} | {:.1} | {:.0} | {:.0} | {:.0} | {:.0} | {} | {} |",
            r.name,
            r.hits,
            r.mean(),
            r.quantile(0.5),
            r.quantile(0.99),
            r.terms_per_ray,
            r.rays_per_second(),
            ratio(brute),
            ratio(global)
        );
    }
}

/// Nanoseconds per wave term of the three evaluators.
fn kernel_timings() {
    let set = sea(200, None);
    let sum = TrochoidSum::new(&set);
    let exact = sum.at_time(0.0);
    let fast = TracedTrochoids::new(&set, 0.0);
    let points: Vec<DVec3> = (0..2000).map(|i| DVec3::new(i as f64 * 0.37, 0.0, i as f64 * -0.21)).collect();
    let n_terms = (points.len() * set.len()) as f64;
    let time = |f: &dyn Fn(DVec3) -> f64| {
        let start = Instant::now();
        let mut acc = 0.0;
        for _ in 0..5 {
            for p in &points {
                acc += f(*p);
            }
        }
        std::hint::black_box(acc);
        start.elapsed().as_secs_f64() * 1e9 / (5.0 * n_terms)
    };
    let f64_ns = time(&|p| exact.height(p.x, p.z));
    let scalar_ns = time(&|p| (1..=set.len()).map(|i| fast.component(i, p)).sum());
    let simd_ns = time(&|p| fast.height(p.x, p.z));
    let newton_ns = time(&|p| {
        set.waves().iter().map(|w| solve_trochoid_phase(w.wavenumber() * (p.x - p.z), w.steepness()).1).sum::<f64>()
    });
    println!("\nWave-term evaluation (N = 200, ns per term, one thread)");
    println!("| evaluator | ns/term |");
    println!("|---|---|");
    println!("| f64 safeguarded Newton (`TrochoidField`, the reference) | {f64_ns:.1} |");
    println!("| f64 `solve_trochoid_phase` alone | {newton_ns:.1} |");
    println!("| f32 scalar kernel (`TracedTrochoids::component`) | {scalar_ns:.1} |");
    println!("| f32×8 SIMD kernel (`TracedTrochoids::height`) | {simd_ns:.2} |");
}

fn machine() {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    let compiled = if cfg!(target_feature = "avx2") && cfg!(target_feature = "fma") {
        "AVX2+FMA"
    } else if cfg!(target_feature = "avx") {
        "AVX"
    } else if cfg!(target_feature = "sse4.1") {
        "SSE4.1"
    } else {
        "SSE2"
    };
    #[cfg(target_arch = "x86_64")]
    let available = if std::is_x86_feature_detected!("avx512f") {
        "AVX-512"
    } else if std::is_x86_feature_detected!("avx2") {
        "AVX2"
    } else {
        "SSE2/AVX"
    };
    #[cfg(not(target_arch = "x86_64"))]
    let available = "n/a";
    println!("CPU: {cpu}; SIMD compiled for: {compiled} (f32x8 = wide crate); CPU supports: {available}");
    println!(
        "(the workspace forbids unsafe code and `wide` picks its instruction set at compile time, so \
         there is no run-time dispatch; build with RUSTFLAGS=\"-C target-cpu=x86-64-v3\" for AVX2)"
    );
}

fn main() {
    if std::env::args().any(|a| a == "--list") {
        return; // cargo bench -- --list
    }
    let quick = std::env::var("BRINE_BENCH_QUICK").is_ok();
    machine();
    kernel_timings();
    let cameras = [
        Camera::new("2 m grazing", 2.0, 100.0, -2.0),
        Camera::new("10 m toward the horizon", 10.0, 100.0, -9.0),
        Camera::new("50 m looking down", 50.0, 100.0, -50.0),
    ];
    let sizes: &[usize] = if quick { &[50] } else { &[30, 50, 100, 200] };
    let levels: [(Option<f64>, &str); 3] =
        [(None, "fitted Q (Σ Q ≤ 0.9)"), (Some(0.5), "Q = 0.5"), (Some(0.9), "Q = 0.9")];
    let xs: Vec<usize> = (0..WIDTH).step_by(STRIDE).map(|x| x + STRIDE / 2).collect();
    let ys: Vec<usize> = (0..HEIGHT).step_by(STRIDE).map(|y| y + STRIDE / 2).collect();
    let mut summary = Vec::new();
    for camera in &cameras {
        if quick && (camera.position.y - 10.0).abs() > 1e-9 {
            continue;
        }
        let footprint = camera.pixel_angle();
        let rays: Vec<Ray> = ys
            .iter()
            .flat_map(|&y| xs.iter().map(move |&x| (x, y)))
            .map(|(x, y)| Ray::new(camera.position, camera.direction(x, y)).unwrap())
            .collect();
        let all_x: Vec<usize> = (0..WIDTH).collect();
        let all_y: Vec<usize> = (0..HEIGHT).collect();
        let full: Vec<Ray> = all_y
            .iter()
            .flat_map(|&y| all_x.iter().map(move |&x| (x, y)))
            .map(|(x, y)| Ray::new(camera.position, camera.direction(x, y)).unwrap())
            .collect();
        for (q, level) in levels {
            for &n in sizes {
                let set = sea(n, q);
                let fast = TracedTrochoids::new(&set, 0.0);
                let next = TracedTrochoids::new(&set, FRAME_S);
                let mut rows = Vec::new();
                for method in Method::ALL {
                    rows.push(run_method(&fast, &rays, method, 0.0, method.name()));
                }
                rows.push(run_method(&fast, &rays, Method::Tiered, footprint, "tiered + footprint"));
                rows.push(run_coherent(&fast, camera, &xs, &ys, footprint));
                let brute = rows[0].mean();
                let global = rows[1].mean();
                debug_assert!(
                    rows[0].name == Method::BruteForce.name() && rows[1].name == Method::GlobalLipschitz.name()
                );
                print_table(
                    &format!(
                        "{} — {level} — N = {n} — {}×{} rays (every {STRIDE}th pixel)",
                        camera.name,
                        xs.len(),
                        ys.len()
                    ),
                    &rows,
                    Some(brute),
                    Some(global),
                );
                // Whole image (fitted steepness only, the renderer's case): the tiered variants,
                // and the next frame with temporal coherence.
                let full_rows = if q.is_none() {
                    let whole_tiered = run_method(&fast, &full, Method::Tiered, footprint, "tiered + footprint");
                    let whole_coherent = run_coherent(&fast, camera, &all_x, &all_y, footprint);
                    // Temporal coherence needs the unfaded surface (see `trace_temporal`).
                    let frame = run_method(&fast, &full, Method::Tiered, 0.0, "tiered, frame t");
                    let whole_next = run_method(&next, &full, Method::Tiered, 0.0, "tiered, frame t + 1/25 s");
                    let whole_temporal = run_temporal(&next, &full, &frame.t_hit, 0.0);
                    let rows = vec![whole_tiered, whole_coherent, whole_next, whole_temporal];
                    print_table(&format!("{} — {level} — N = {n} — 640×480 rays", camera.name), &rows, None, None);
                    rows
                } else {
                    Vec::new()
                };
                summary.push((camera.name, level, n, brute, global, rows, full_rows));
            }
        }
    }
    let find = |rows: &[Row], name: &str| -> usize {
        rows.iter().position(|r| r.name == name).unwrap_or_else(|| panic!("no row {name}"))
    };
    println!("\nSummary (Darles et al. Tables 1–2 style): mean evaluations per hitting ray, ratios on identical rays");
    println!(
        "(×brute, ×global: tiered without footprint on the same unfaded surface as the baselines; \
         \"fp\" ratios: tiered + footprint, a faded per-ray surface, against the unfaded baselines)"
    );
    println!(
        "| camera | steepness | N | brute force | global L | directional | Darles | segment | tiered | tiered+fp | ×brute | ×global | fp ×brute | fp ×global | image coh. (SC) | temporal coh. (TC) | µs/ray 640×480 (tiered+fp) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for (camera, level, n, brute, global, rows, full) in &summary {
        let tiered = rows[find(rows, Method::Tiered.name())].mean();
        let faded = rows[find(rows, "tiered + footprint")].mean();
        let (sc, tc, us) = if full.is_empty() {
            ("–".to_string(), "–".to_string(), "–".to_string())
        } else {
            (
                format!("{:.2}×", full[0].mean() / full[1].mean().max(1e-9)),
                format!("{:.2}×", full[2].mean() / full[3].mean().max(1e-9)),
                format!("{:.2}", 1e6 / full[0].rays_per_second()),
            )
        };
        println!(
            "| {camera} | {level} | {n} | {brute:.0} | {global:.1} | {:.1} | {:.1} | {:.1} | {tiered:.1} | {faded:.1} | {:.1}× | {:.1}× | {:.1}× | {:.1}× | {sc} | {tc} | {us} |",
            rows[find(rows, Method::Directional.name())].mean(),
            rows[find(rows, Method::Darles.name())].mean(),
            rows[find(rows, Method::Segment.name())].mean(),
            brute / tiered,
            global / tiered,
            brute / faded,
            global / faded,
        );
    }
    println!(
        "\nBest methods per configuration: evaluations per hitting ray (mean / median / p99) and wave terms per ray"
    );
    println!("| camera | steepness | N | tiered | terms/ray | tiered + footprint | terms/ray | segment | terms/ray |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for (camera, level, n, _, _, rows, _) in &summary {
        let cell = |name: &str| {
            let r = &rows[find(rows, name)];
            (
                format!("{:.1} / {:.0} / {:.0}", r.mean(), r.quantile(0.5), r.quantile(0.99)),
                format!("{:.0}", r.terms_per_ray),
            )
        };
        let (t, tt) = cell(Method::Tiered.name());
        let (f, ft) = cell("tiered + footprint");
        let (g, gt) = cell(Method::Segment.name());
        println!("| {camera} | {level} | {n} | {t} | {tt} | {f} | {ft} | {g} | {gt} |");
    }
}
