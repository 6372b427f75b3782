//! `cargo xtask bench`: the registry of benchmarks.
//!
//! Each entry names a benchmark and the cargo command that runs it. Criterion benches print their
//! medians; custom harnesses (`harness = false`) print their own side-by-side tables with ratios.
//! Add an entry here when a crate adds a benchmark.

/// `(name, what it measures, cargo arguments)`.
const BENCHES: &[(&str, &str, &[&str])] = &[
    (
        "frame",
        "one 640×480 frame, 100 waves (and the FFT sea), every phenomenon, 1 spp: median of 5 (brine-render)",
        &["bench", "-p", "brine-render", "--bench", "frame"],
    ),
    (
        "wave-count",
        "the reference frame at N = 50, 100, 200, 400 waves, as sea.grid = \"auto\" draws them and the other way: whole-frame medians, t(N)/t(50), thread time per stage (brine-render)",
        &["bench", "-p", "brine-render", "--bench", "wave_count"],
    ),
    (
        "grid-band",
        "study: the primary rays at N = 50 and 400 with every wave traced or the shorter ones gathered into one to three grids (brine-waves GriddedTrochoids)",
        &["bench", "-p", "brine-waves", "--bench", "grid_band"],
    ),
    (
        "animation",
        "a 24-frame animation of the reference frame against a still of it, per frame, both surfaces; frames checked equal to stills (brine-render)",
        &["bench", "-p", "brine-render", "--bench", "animation"],
    ),
    (
        "export",
        "the default sea handed to other tools: a 1024² bake frame, a 1 M-vertex mesh, 10⁶ point queries (brine-render)",
        &["bench", "-p", "brine-render", "--bench", "export"],
    ),
    (
        "peers",
        "Brine against the mesh route: the same sea as a camera-adaptive mesh traced by Mitsuba 3 (venv made in target/peers), accuracy matched on Brine's depth",
        &["bench", "-p", "brine-render", "--bench", "peers"],
    ),
    (
        "optics",
        "brine-optics per-pixel and per-scene costs (criterion)",
        &["bench", "-p", "brine-optics", "--bench", "optics"],
    ),
    ("sky", "brine-sky per-call and constructor costs", &["bench", "-p", "brine-sky", "--bench", "sky"]),
    ("ephem", "SPA vs Schlyter sun and moon positions", &["bench", "-p", "brine-ephem", "--bench", "ephem"]),
    (
        "waves",
        "brine-waves: height at one point × N waves, scalar loop vs SIMD lanes (trochoid, sine), Gerstner inversion",
        &["bench", "-p", "brine-waves", "--bench", "surface_eval"],
    ),
    (
        "fft",
        "brine-waves FFT ocean: synthesis per frame at 256² and 512², trace cost per ray against trochoids (custom)",
        &["bench", "-p", "brine-waves", "--bench", "fft"],
    ),
    (
        "whitecap-erf",
        "erf side by side: the slides' Winitzki (a = 0.147) vs Abramowitz–Stegun 7.1.26 vs libm::erf (criterion)",
        &["bench", "-p", "brine-whitecap", "--bench", "whitecap", "--", "erf/"],
    ),
    (
        "whitecap",
        "per-pixel footprint moments of J and the calibration of α, 50 and 100 waves (criterion)",
        &["bench", "-p", "brine-whitecap", "--bench", "whitecap", "--", "whitecap/"],
    ),
    (
        "whitecap-fft",
        "FFT ocean whitecaps: mip pyramids per frame, footprint moments per pixel, calibration of α (example)",
        &["run", "--release", "-p", "brine-whitecap", "--example", "fft_whitecap_cost"],
    ),
    (
        "foam",
        "per-pixel foam amount, foam history, spray ray segments, spray medium construction (criterion)",
        &["bench", "-p", "brine-foam", "--bench", "foam"],
    ),
    (
        "texture",
        "brine-texture: preprocessing and per-frame time at 384×384 (projection, bed, traced), 1 thread vs all",
        &["bench", "-p", "brine-texture", "--bench", "texture"],
    ),
    (
        "trace",
        "brine-trace: every tracing method on identical 640×480 primary rays (tables of docs/benchmarks.md)",
        &["bench", "-p", "brine-trace", "--bench", "methods"],
    ),
];

/// Runs the named benchmarks (all when `names` is empty) or lists them.
pub fn run(names: &[String], list: bool) -> Result<(), String> {
    if list || BENCHES.is_empty() {
        if BENCHES.is_empty() {
            eprintln!("no benchmark is registered yet");
        }
        for (name, what, _) in BENCHES {
            println!("{name:12} {what}");
        }
        return Ok(());
    }
    for n in names {
        if !BENCHES.iter().any(|(name, _, _)| name == n) {
            return Err(format!("unknown benchmark {n} (try --list)"));
        }
    }
    for (name, _, args) in BENCHES {
        if names.is_empty() || names.iter().any(|n| n == name) {
            super::cargo(args, &[])?;
        }
    }
    Ok(())
}
