//! `cargo xtask bench fft`: FFT synthesis time per frame (256² and 512² tiles, all cascades), and
//! the trace cost per ray of the FFT ocean against the trochoid sum of the same spectrum, side by
//! side in one process.
//!
//! Sea: Elfouhaily et al. 1997 at U10 = 10 m/s, fetch 100 km (`Ω = 1.20`, peak wavelength
//! 44.5 m), down-wind spreading, wind toward 20°.
//!
//! - Synthesis: 4 cascades (354, 51.6, 7.53, 1.10 m, the default tiles for this spectrum),
//!   choppiness 1; medians of 9 frames at successive times, with 1 and 2 rayon threads. "FFT
//!   only" is `rest_fields` (sincos per wave vector and 4 complex inverse FFTs per cascade);
//!   "frame" is `at_time` (the same, then the choppy resampling and the certified bounds).
//! - Shading lookups: the traced height (4 splines), the shading gradient (4 bilinear lookups),
//!   and the mip-mapped slope moments over a footprint, per call, one thread.
//! - Tracing: cameras at 2 m (grazing), 10 m toward the horizon and 50 m looking down 50°,
//!   640×480 pixels of 50° vertical field, every 4th pixel in x and y (19 200 rays), one thread,
//!   the renderer's trace options. Matched detail: the trochoid fit covers `0.5–12 ω_p`
//!   (wavelengths 178 m to 0.31 m) and the FFT's first two cascades at 256² hold 354 m to 0.40 m;
//!   the full four cascades go down to 8.6 mm.
//!
//! Environment: `BRINE_BENCH_QUICK=1` runs 256² and the 10 m camera only.

use std::time::Instant;

use brine_texture::Pinhole;
use brine_trace::{LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace};
use brine_waves::{
    Directions, Elfouhaily, FftFrame, FftOcean, FftOptions, FftSlopeFilter, FitOptions, Spectrum, TracedTrochoids,
    fit_trochoids,
};
use glam::DVec3;

const WIDTH: usize = 640;
const HEIGHT: usize = 480;
const STRIDE: usize = 4;
const FOV_DEG: f64 = 50.0;
const FRAMES: usize = 9;
const WIND_DEG: f64 = 20.0;

use brine_testkit::timing::median;

fn ms(s: f64) -> String {
    format!("{:.1} ms", 1e3 * s)
}

/// A named view of the bench: brine-texture's pinhole camera (the renderer's) at a height,
/// bearing and pitch.
struct Camera {
    name: &'static str,
    pinhole: Pinhole,
}

impl Camera {
    fn new(name: &'static str, height: f64, bearing_deg: f64, pitch_deg: f64) -> Self {
        let position = DVec3::new(0.0, height, 0.0);
        let pinhole = Pinhole::from_angles(position, bearing_deg, pitch_deg, FOV_DEG, WIDTH as u32, HEIGHT as u32)
            .expect("a valid bench camera");
        Self { name, pinhole }
    }

    /// The rays through the centres of every `STRIDE`-th pixel.
    fn rays(&self) -> Vec<Ray> {
        let mut out = Vec::new();
        for y in (0..HEIGHT).step_by(STRIDE) {
            for x in (0..WIDTH).step_by(STRIDE) {
                let d = self.pinhole.direction(x as f64 + 0.5, y as f64 + 0.5);
                out.push(Ray::new(self.pinhole.position, d).expect("finite camera ray"));
            }
        }
        out
    }

    fn pixel_angle(&self) -> f64 {
        self.pinhole.pixel_angle()
    }
}

/// `(hits, evaluations per hitting ray, µs per ray)` over `rays`, one thread.
fn run<S: LipschitzSum + ?Sized>(surface: &S, rays: &[Ray], options: &TraceOptions) -> (u64, f64, f64) {
    let mut stats = TraceStats::default();
    let mut hit_evals = 0u64;
    let start = Instant::now();
    for ray in rays {
        let before = stats.evaluations;
        if trace(surface, ray, options, &mut stats).is_some() {
            hit_evals += stats.evaluations - before;
        }
    }
    let seconds = start.elapsed().as_secs_f64();
    let per_hit = if stats.hits > 0 { hit_evals as f64 / stats.hits as f64 } else { 0.0 };
    (stats.hits, per_hit, 1e6 * seconds / rays.len() as f64)
}

fn main() {
    let quick = std::env::var("BRINE_BENCH_QUICK").is_ok_and(|v| v == "1");
    let elf = Elfouhaily::from_fetch(10.0, 1e5).expect("valid sea");
    let spreading = elf.spreading(Directions::Downwind);
    let wind = WIND_DEG.to_radians();
    let base = FftOptions { wind_direction: wind, ..FftOptions::for_spectrum(&elf, 4) };
    println!("# FFT ocean (brine-waves): synthesis and tracing");
    println!();
    println!(
        "Elfouhaily U10 = 10 m/s, fetch 100 km (Ω = {:.2}, λ_p = {:.1} m); tiles {:?} m",
        elf.inverse_wave_age(),
        std::f64::consts::TAU / elf.k_p(),
        base.tile_sizes.iter().map(|l| (l * 100.0).round() / 100.0).collect::<Vec<_>>()
    );
    println!();

    // ---------------------------------------------------------------- synthesis
    println!("## Synthesis per frame (4 cascades, medians of {FRAMES} frames)");
    println!();
    println!("| N | threads | construction | FFT only (`rest_fields`) | frame λ = 0 | frame λ = 1 (`at_time`) |");
    println!("|---|---|---|---|---|---|");
    let sizes: &[usize] = if quick { &[256] } else { &[256, 512] };
    for &n in sizes {
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
            pool.install(|| {
                let start = Instant::now();
                let o = FftOptions { resolution: n, ..base.clone() };
                let ocean = FftOcean::new(&elf, &spreading, &o).expect("valid ocean");
                let build = start.elapsed().as_secs_f64();
                let flat =
                    FftOcean::new(&elf, &spreading, &FftOptions { choppiness: 0.0, ..o.clone() }).expect("ocean");
                let time = |f: &dyn Fn(f64)| {
                    median(
                        (0..FRAMES)
                            .map(|i| {
                                let s = Instant::now();
                                f(0.5 * i as f64);
                                s.elapsed().as_secs_f64()
                            })
                            .collect(),
                    )
                };
                let fft = time(&|t| {
                    std::hint::black_box(ocean.rest_fields(t));
                });
                let frame0 = time(&|t| {
                    std::hint::black_box(flat.at_time(t));
                });
                let frame1 = time(&|t| {
                    std::hint::black_box(ocean.at_time(t));
                });
                println!("| {n}² | {threads} | {} | {} | {} | {} |", ms(build), ms(fft), ms(frame0), ms(frame1));
            });
        }
    }
    println!();

    // ---------------------------------------------------------------- shading lookups
    println!("## Shading lookups (one thread)");
    println!();
    println!("| N | `FftSlopeFilter::new` (per frame) | `height` | `gradient` | `filtered`, s = 0 | s = 1 m |");
    println!("|---|---|---|---|---|---|");
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("thread pool");
    for &n in sizes {
        pool.install(|| {
            let o = FftOptions { resolution: n, ..base.clone() };
            let frame = FftOcean::new(&elf, &spreading, &o).expect("valid ocean").at_time(1.0);
            let build = median(
                (0..FRAMES)
                    .map(|_| {
                        let s = Instant::now();
                        std::hint::black_box(FftSlopeFilter::new(&frame));
                        s.elapsed().as_secs_f64()
                    })
                    .collect(),
            );
            let filter = FftSlopeFilter::new(&frame);
            let points: Vec<(f64, f64)> =
                (0..4096).map(|i| (i as f64 * 0.731 - 500.0, i as f64 * -0.377 + 80.0)).collect();
            let per_call = |f: &dyn Fn(f64, f64)| {
                1e9 * median(
                    (0..FRAMES)
                        .map(|_| {
                            let s = Instant::now();
                            for &(x, z) in &points {
                                f(x, z);
                            }
                            s.elapsed().as_secs_f64()
                        })
                        .collect(),
                ) / points.len() as f64
            };
            let h = per_call(&|x, z| {
                std::hint::black_box(frame.height(x, z));
            });
            let g = per_call(&|x, z| {
                std::hint::black_box(frame.gradient(x, z));
            });
            let f0 = per_call(&|x, z| {
                std::hint::black_box(filter.filtered(x, z, 0.0));
            });
            let f1 = per_call(&|x, z| {
                std::hint::black_box(filter.filtered(x, z, 1.0));
            });
            println!("| {n}² | {} | {h:.0} ns | {g:.0} ns | {f0:.0} ns | {f1:.0} ns |", ms(build));
        });
    }
    println!();

    // ---------------------------------------------------------------- tracing
    let fft_full = pool.install(|| {
        FftOcean::new(&elf, &spreading, &FftOptions { resolution: 256, ..base.clone() }).expect("ocean").at_time(10.0)
    });
    let matched_options = FftOptions { resolution: 256, tile_sizes: base.tile_sizes[..2].to_vec(), ..base.clone() };
    let fft_matched: FftFrame =
        pool.install(|| FftOcean::new(&elf, &spreading, &matched_options).expect("ocean").at_time(10.0));
    let fit = FitOptions { wind_direction: wind, choppiness: 2.5, ..FitOptions::default() };
    let counts: &[usize] = if quick { &[50] } else { &[50, 100, 200] };
    let trochoids: Vec<(usize, TracedTrochoids)> = counts
        .iter()
        .map(|&n| (n, TracedTrochoids::new(&fit_trochoids(&elf, &spreading, n, 1, &fit).expect("fit"), 10.0)))
        .collect();
    println!(
        "## Trace cost per ray (one thread, {}×{} rays: every {STRIDE}th pixel of {WIDTH}×{HEIGHT})",
        WIDTH / STRIDE,
        HEIGHT / STRIDE
    );
    println!();
    println!(
        "Trochoids: fit over 0.5–12 ω_p ({:.0} m to {:.2} m), choppiness 2.5, Σ Q ≤ 0.9. FFT matched: cascades 0–1 at \
         256² ({:.0} m to {:.2} m); FFT full: cascades 0–3 ({:.3} m shortest). Slope bounds Σ L: FFT matched {:.2}, \
         full {:.2}.",
        std::f64::consts::TAU / elf.dispersion().wavenumber(0.5 * elf.peak_omega()),
        std::f64::consts::TAU / elf.dispersion().wavenumber(12.0 * elf.peak_omega()),
        base.tile_sizes[0],
        2.0 * base.tile_sizes[1] / 256.0,
        2.0 * base.tile_sizes[3] / 256.0,
        fft_matched.max_slope(),
        fft_full.max_slope()
    );
    println!();
    println!("| camera | surface | method | hits | eval/hit | µs/ray | vs trochoids N=50 (same method) |");
    println!("|---|---|---|---|---|---|---|");
    let cameras = if quick {
        vec![Camera::new("10 m toward the horizon", 10.0, 110.0, -8.0)]
    } else {
        vec![
            Camera::new("2 m grazing", 2.0, 110.0, -3.0),
            Camera::new("10 m toward the horizon", 10.0, 110.0, -8.0),
            Camera::new("50 m looking down", 50.0, 110.0, -50.0),
        ]
    };
    for camera in &cameras {
        let rays = camera.rays();
        for (method, footprint, label) in [
            (Method::Tiered, camera.pixel_angle(), "tiered + footprint"),
            (Method::Tiered, 0.0, "tiered"),
            (Method::Directional, 0.0, "directional L"),
        ] {
            let o = TraceOptions::comparison(method, footprint);
            let reference = run(&trochoids[0].1, &rays, &o);
            let mut rows: Vec<(String, (u64, f64, f64))> = Vec::new();
            for (n, t) in &trochoids {
                let r = if *n == trochoids[0].0 { reference } else { run(t, &rays, &o) };
                rows.push((format!("trochoids N = {n}"), r));
            }
            rows.push(("FFT matched (2 × 256²)".into(), run(&fft_matched, &rays, &o)));
            rows.push(("FFT full (4 × 256²)".into(), run(&fft_full, &rays, &o)));
            for (name, (hits, per_hit, us)) in rows {
                println!(
                    "| {} | {name} | {label} | {hits} | {per_hit:.1} | {us:.2} | {:.2}× |",
                    camera.name,
                    reference.2 / us
                );
            }
        }
    }
}
