//! Plots of brine-waves: the five spectra, a fitted set over its spectrum, trochoid profiles,
//! spreading functions, dispersion curves, Elfouhaily's curvature spectra and its mean-square
//! slope against Cox & Munk, and the FFT ocean (its cascades' spectra, choppy profiles, the
//! distribution of its Jacobian, a cascade's correlation with itself, periodic and blended).

use std::f64::consts::PI;
use std::path::Path;

use brine_waves::{
    CosineSquared, CosineTwoS, Directions, Dispersion, DonelanBanner, Elfouhaily, FftOcean, FftOptions, FitOptions,
    FrequencyPartition, Jonswap, Phillips, PiersonMoskowitz, SEA_WATER_DENSITY, SEA_WATER_SURFACE_TENSION, Spectrum,
    Spreading, Tma, Trochoid, fit_trochoids, frequency_bins,
};

use super::{LineChart, Scale};

/// Winds of the spectrum plots (m/s).
const WINDS: [f64; 3] = [5.0, 10.0, 20.0];
/// Fetch of the JONSWAP and TMA plots (m).
const FETCH_M: f64 = 100_000.0;
/// Depth of the TMA plot (m).
const DEPTH_M: f64 = 20.0;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// `n` log-spaced values from `a` to `b`.
fn logspace(a: f64, b: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |i| a * (b / a).powf(i as f64 / (n - 1) as f64))
}

/// `S(ω)` on 0.1–30 rad/s, down to 10⁻⁴ m² s/rad (four decades below the peaks: the tails'
/// `ω⁻⁵` slope stays visible and the log axis keeps readable ticks).
fn spectrum_series(s: &dyn Spectrum) -> Vec<(f64, f64)> {
    logspace(0.1, 30.0, 800).map(|w| (w, s.s_omega(w))).filter(|p| p.1 > 1e-4).collect()
}

fn spectrum_for(model: &str, u: f64) -> Result<Box<dyn Spectrum>, String> {
    Ok(match model {
        "pm" => Box::new(PiersonMoskowitz::from_u10(u).map_err(err)?),
        "jonswap" => Box::new(Jonswap::from_fetch(u, FETCH_M).map_err(err)?),
        "tma" => Box::new(Tma::from_fetch(u, FETCH_M, DEPTH_M).map_err(err)?),
        "phillips" => Box::new(Phillips::from_wind(u).map_err(err)?),
        _ => Box::new(Elfouhaily::fully_developed(u).map_err(err)?),
    })
}

/// Writes the brine-waves figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    spectra(dir)?;
    fit(dir)?;
    profiles(dir)?;
    spreading(dir)?;
    dispersion(dir)?;
    elfouhaily(dir)?;
    fft(dir)
}

fn spectra(dir: &Path) -> Result<(), String> {
    let models = [
        ("pm", "Pierson–Moskowitz"),
        ("jonswap", "JONSWAP, fetch 100 km"),
        ("tma", "TMA, fetch 100 km, depth 20 m"),
        ("phillips", "Phillips (Tessendorf), A = α/2π, ℓ = L/1000"),
        ("elfouhaily", "Elfouhaily et al. 1997, fully developed (Ω = 0.84)"),
    ];
    for (key, title) in models {
        let mut series = Vec::new();
        for u in WINDS {
            let s = spectrum_for(key, u)?;
            series.push((format!("U10 = {u} m/s"), spectrum_series(s.as_ref())));
        }
        LineChart {
            title,
            x_label: "ω (rad/s)",
            y_label: "S(ω) (m² s/rad)",
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series,
        }
        .write(&dir.join(format!("waves-spectrum-{key}.svg")))?;
    }
    let mut series = Vec::new();
    for (key, title) in models {
        let s = spectrum_for(key, 10.0)?;
        series.push((title.split(',').next().unwrap_or(title).to_string(), spectrum_series(s.as_ref())));
    }
    LineChart {
        title: "The five spectra at U10 = 10 m/s",
        x_label: "ω (rad/s)",
        y_label: "S(ω) (m² s/rad)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("waves-spectra-10ms.svg"))
}

fn fit(dir: &Path) -> Result<(), String> {
    let s = Jonswap::from_fetch(10.0, FETCH_M).map_err(err)?;
    let wp = s.peak_omega();
    let d = CosineTwoS::hasselmann(wp).map_err(err)?;
    for (partition, key, name) in [
        (FrequencyPartition::Logarithmic, "log", "log-spaced"),
        (FrequencyPartition::EqualEnergy, "equal-energy", "equal-energy"),
    ] {
        let n = 40;
        let o = FitOptions { partition, ..FitOptions::default() };
        let set = fit_trochoids(&s, &d, n, 1, &o).map_err(err)?;
        let bins = frequency_bins(&s, partition, o.omega_min_factor * wp, o.omega_max_factor * wp, n);
        // Each wave drawn as the constant density Aᵢ²/(2Δωᵢ) over its bin: a staircase whose area
        // is the wave's variance.
        let mut stairs = Vec::new();
        for (b, w) in bins.iter().zip(set.waves()) {
            let density = w.amplitude() * w.amplitude() / (2.0 * (b.omega_hi - b.omega_lo));
            stairs.push((b.omega_lo, density));
            stairs.push((b.omega_hi, density));
        }
        let curve: Vec<(f64, f64)> =
            logspace(0.45 * wp, 13.0 * wp, 400).map(|w| (w, s.s_omega(w))).filter(|p| p.1 > 1e-6).collect();
        let title = format!("{n} waves fitted to JONSWAP (U10 = 10 m/s), {name} bins: Aᵢ²/(2Δωᵢ) over S(ω)");
        LineChart {
            title: &title,
            x_label: "ω (rad/s)",
            y_label: "S(ω), Aᵢ²/(2Δωᵢ) (m² s/rad)",
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series: vec![("S(ω)".into(), curve), ("fitted waves".into(), stairs)],
        }
        .write(&dir.join(format!("waves-fit-{key}.svg")))?;
        if partition == FrequencyPartition::Logarithmic {
            let amps: Vec<(f64, f64)> = set.waves().iter().map(|w| (w.omega(), w.amplitude())).collect();
            LineChart {
                title: "Fitted amplitudes Aᵢ, 40 waves, JONSWAP U10 = 10 m/s, log partition",
                x_label: "ω (rad/s)",
                y_label: "A (m)",
                x_scale: Scale::Log,
                y_scale: Scale::Log,
                series: vec![("Aᵢ = √(2∫S dω over bin i)".into(), amps)],
            }
            .write(&dir.join("waves-fit-amplitudes.svg"))?;
        }
    }
    Ok(())
}

fn profiles(dir: &Path) -> Result<(), String> {
    let mut series = Vec::new();
    for q in [0.0, 0.5, 0.8, 0.95] {
        // Exact trochoids (Q = kA) of wavelength 1: x/λ against y/λ over two wavelengths.
        let k = 2.0 * PI;
        let a = if q > 0.0 { q / k } else { 0.8 / k };
        let w = Trochoid::new(a, k, 0.0, 0.0, 0.0, q).map_err(err)?;
        let pts = (0..=800).map(|i| w.profile_point(-2.0 * PI + 4.0 * PI * i as f64 / 800.0)).collect();
        let label = if q > 0.0 { format!("trochoid Q = kA = {q}") } else { "sinusoid kA = 0.8 (Q = 0)".into() };
        series.push((label, pts));
    }
    LineChart {
        title: "Trochoid profiles (λ = 1): crests sharpen as Q → 1; the steepest slope Q/√(1 − Q²) is at y = QA",
        x_label: "x/λ",
        y_label: "y/λ",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("waves-trochoid-profile.svg"))
}

fn spreading(dir: &Path) -> Result<(), String> {
    let u = 10.0;
    let pm = PiersonMoskowitz::from_u10(u).map_err(err)?;
    let wp = pm.peak_omega();
    let e = Elfouhaily::fully_developed(u).map_err(err)?;
    let ewp = e.peak_omega();
    for (ratio, key) in [(1.0, "peak"), (3.0, "3peak")] {
        let list: Vec<(String, Box<dyn Spreading>, f64)> = vec![
            ("cos-2s, Hasselmann 1980".into(), Box::new(CosineTwoS::hasselmann(wp).map_err(err)?), wp),
            ("cos-2s, Mitsuyasu 1975".into(), Box::new(CosineTwoS::mitsuyasu(wp, u).map_err(err)?), wp),
            ("sech², Donelan–Banner".into(), Box::new(DonelanBanner::new(wp).map_err(err)?), wp),
            ("Elfouhaily Δ(k), down-wind".into(), Box::new(e.spreading(Directions::Downwind)), ewp),
            ("Elfouhaily Δ(k), both ways".into(), Box::new(e.spreading(Directions::BothWays)), ewp),
            ("(2/π) cos²θ".into(), Box::new(CosineSquared::downwind()), wp),
        ];
        let series = list
            .into_iter()
            .map(|(name, d, peak)| {
                let pts = (0..=720).map(|i| {
                    let th = -PI + 2.0 * PI * i as f64 / 720.0;
                    (th.to_degrees(), d.density(th, ratio * peak))
                });
                (name, pts.collect())
            })
            .collect();
        let title = format!("Directional spreading D(θ; ω) at ω = {ratio} ω_p, U10 = 10 m/s");
        LineChart {
            title: &title,
            x_label: "θ from the wind (degrees)",
            y_label: "D (1/rad)",
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series,
        }
        .write(&dir.join(format!("waves-spreading-{key}.svg")))?;
    }
    Ok(())
}

fn dispersion(dir: &Path) -> Result<(), String> {
    let list = [
        ("deep water, ω² = gk".to_string(), Dispersion::DEEP_WATER),
        ("depth 10 m".to_string(), Dispersion::finite_depth(10.0).map_err(err)?),
        ("depth 1 m".to_string(), Dispersion::finite_depth(1.0).map_err(err)?),
        (
            "capillary–gravity, deep (σ = 0.074 N/m)".to_string(),
            Dispersion::capillary_gravity(f64::INFINITY, SEA_WATER_SURFACE_TENSION, SEA_WATER_DENSITY).map_err(err)?,
        ),
        (
            "capillary–gravity, depth 1 m".to_string(),
            Dispersion::capillary_gravity(1.0, SEA_WATER_SURFACE_TENSION, SEA_WATER_DENSITY).map_err(err)?,
        ),
    ];
    let mut speeds = Vec::new();
    for (name, d) in &list {
        speeds.push((name.clone(), logspace(1e-3, 1e4, 400).map(|k| (k, d.phase_speed(k))).collect()));
    }
    LineChart {
        title: "Phase speed c = ω/k of the dispersion relations (minimum 0.23 m/s at λ = 1.7 cm)",
        x_label: "k (rad/m)",
        y_label: "c (m/s)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: speeds,
    }
    .write(&dir.join("waves-dispersion.svg"))
}

fn elfouhaily(dir: &Path) -> Result<(), String> {
    let mut series = Vec::new();
    for u in WINDS {
        let e = Elfouhaily::fully_developed(u).map_err(err)?;
        let ks = || logspace(1e-3, 1e4, 600);
        series.push((
            format!("B_l + B_h, U10 = {u} m/s"),
            ks().map(|k| (k, e.curvature_long(k) + e.curvature_short(k))).filter(|p| p.1 > 1e-4).collect(),
        ));
        series.push((
            format!("B_h, U10 = {u} m/s"),
            ks().map(|k| (k, e.curvature_short(k))).filter(|p| p.1 > 1e-4).collect(),
        ));
    }
    LineChart {
        title: "Elfouhaily et al. 1997: curvature spectrum B(k) = k³S(k), long + short waves",
        x_label: "k (rad/m)",
        y_label: "B (1)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("waves-elfouhaily-curvature.svg"))?;

    // Mean-square slope against Cox & Munk 1954 (clean surface, U at 12.5 m, ±0.004).
    let winds: Vec<f64> = (2..=30).map(|i| i as f64 * 0.5 + 1.0).collect();
    let u12_5 = |u: f64| u * (12.5f64 / 2e-4).ln() / (10.0f64 / 2e-4).ln();
    let cm = |u: f64| 0.003 + 5.12e-3 * u12_5(u);
    let mut model = Vec::new();
    for &u in &winds {
        model.push((u, Elfouhaily::fully_developed(u).map_err(err)?.mean_square_slope(1e4)));
    }
    LineChart {
        title: "Mean-square slope: Elfouhaily spectrum (Ω = 0.84, k ≤ 10⁴ rad/m) vs Cox & Munk 1954 clean sea",
        x_label: "U10 (m/s)",
        y_label: "mean-square slope",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![
            ("Elfouhaily ∫k²S(k)dk".into(), model),
            ("Cox & Munk 0.003 + 5.12e-3 U12.5".into(), winds.iter().map(|&u| (u, cm(u))).collect()),
            ("Cox & Munk + 0.004".into(), winds.iter().map(|&u| (u, cm(u) + 0.004)).collect()),
            ("Cox & Munk − 0.004".into(), winds.iter().map(|&u| (u, cm(u) - 0.004)).collect()),
        ],
    }
    .write(&dir.join("waves-mss-cox-munk.svg"))
}

/// The FFT ocean: one realisation's spectrum per cascade against `S(k)`, transects of the traced
/// surface at three choppinesses, and the distribution of the Jacobian.
fn fft(dir: &Path) -> Result<(), String> {
    let elf = Elfouhaily::from_fetch(10.0, 1e5).map_err(err)?;
    let spreading = elf.spreading(Directions::Downwind);
    let base = FftOptions::for_spectrum(&elf, 4);
    let ocean = FftOcean::new(&elf, &spreading, &base).map_err(err)?;

    // Radially binned |h̃(k)|² per unit k, 10 bins per decade.
    let (k_lo, k_hi): (f64, f64) = (1e-3, 2e3);
    let bins = (10.0 * (k_hi / k_lo).log10()).round() as usize;
    let bin_of = |k: f64| ((k / k_lo).log10() * 10.0).floor() as usize;
    let centre = |b: usize| k_lo * 10f64.powf((b as f64 + 0.5) / 10.0);
    let width = |b: usize| k_lo * (10f64.powf((b as f64 + 1.0) / 10.0) - 10f64.powf(b as f64 / 10.0));
    let mut series = vec![(
        "S(k), Elfouhaily U10 = 10 m/s, fetch 100 km".to_string(),
        logspace(0.02, k_hi, 400).map(|k| (k, elf.s_k(k))).filter(|p| p.1 > 1e-14).collect::<Vec<_>>(),
    )];
    let mut total = vec![0.0; bins];
    for c in 0..ocean.cascade_count() {
        let mut acc = vec![0.0; bins];
        for ((kx, kz), (re, im)) in ocean.amplitudes_at(c, 0.0) {
            let b = bin_of(kx.hypot(kz));
            if b < bins {
                acc[b] += re * re + im * im;
            }
        }
        for (t, a) in total.iter_mut().zip(&acc) {
            *t += a;
        }
        let pts = (0..bins).filter(|&b| acc[b] > 0.0).map(|b| (centre(b), acc[b] / width(b))).collect();
        series.push((format!("cascade {c}, L = {:.3} m, one seed", base.tile_sizes[c]), pts));
    }
    series.push((
        "sum of the cascades".into(),
        (0..bins).filter(|&b| total[b] > 0.0).map(|b| (centre(b), total[b] / width(b))).collect(),
    ));
    LineChart {
        title: "FFT ocean, 4 cascades of 256²: Σ|h̃|² per unit k (binned) against S(k)",
        x_label: "k (rad/m)",
        y_label: "S(k) (m³/rad)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("waves-fft-spectrum.svg"))?;

    // Transects along the wind at three choppinesses (same seed).
    let mut transects = Vec::new();
    let mut jacobians = Vec::new();
    for lambda in [0.0, 1.0, 2.0] {
        let frame = FftOcean::new(&elf, &spreading, &FftOptions { choppiness: lambda, ..base.clone() })
            .map_err(err)?
            .at_time(0.0);
        transects.push((
            format!("choppiness λ = {lambda}"),
            (0..1200).map(|i| i as f64 * 0.1).map(|x| (x, frame.height(x, 7.0))).collect(),
        ));
        if lambda > 0.0 {
            // Density of J = 1 + Σ(Jᵢ − 1) on a 512² grid over the largest tile, 80 bins.
            let (j_lo, j_hi, nb) = (-0.5, 2.5, 80usize);
            let mut hist = vec![0.0; nb];
            let m = 512;
            let l = base.tile_sizes[0];
            for a in 0..m {
                for b in 0..m {
                    let j = frame.jacobian(a as f64 * l / m as f64, b as f64 * l / m as f64);
                    let bin = ((j - j_lo) / (j_hi - j_lo) * nb as f64).floor();
                    if bin >= 0.0 && (bin as usize) < nb {
                        hist[bin as usize] += 1.0;
                    }
                }
            }
            let scale = nb as f64 / ((j_hi - j_lo) * (m * m) as f64);
            jacobians.push((
                format!("λ = {lambda}"),
                (0..nb).map(|b| (j_lo + (b as f64 + 0.5) * (j_hi - j_lo) / nb as f64, hist[b] * scale)).collect(),
            ));
        }
    }
    LineChart {
        title: "FFT ocean: traced height along the wind (x from 0 to 120 m, z = 7 m), t = 0",
        x_label: "x (m)",
        y_label: "height (m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: transects,
    }
    .write(&dir.join("waves-fft-profile.svg"))?;
    LineChart {
        title: "FFT ocean: distribution of the Jacobian J = 1 + Σ(Jᵢ − 1) over the sea",
        x_label: "J",
        y_label: "probability density",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: jacobians,
    }
    .write(&dir.join("waves-fft-jacobian.svg"))?;
    blend(&elf, &spreading, &base, dir)
}

/// The tile and blend: the along-wind slope autocorrelation of each cascade, periodic and
/// blended, against the lag in tiles (quasi-random points over 40 tiles, 4000 per lag).
fn blend(elf: &Elfouhaily, spreading: &dyn Spreading, base: &FftOptions, dir: &Path) -> Result<(), String> {
    let tiled = FftOcean::new(elf, spreading, &FftOptions { tiled: true, ..base.clone() }).map_err(err)?.at_time(0.0);
    let blended =
        FftOcean::new(elf, spreading, &FftOptions { tiled: false, ..base.clone() }).map_err(err)?.at_time(0.0);
    let (a1, a2) = (0.754_877_666_246_692_7, 0.569_840_290_998_053_3);
    let correlation = |c: &brine_waves::FftCascade, lag: f64| {
        let side = 40.0 * c.tile_size();
        let (mut sxy, mut sxx, mut syy, mut sx, mut sy, mut n) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        for i in 1..=4000 {
            let (x, z) = (side * (0.5 + a1 * f64::from(i)).fract(), side * (0.5 + a2 * f64::from(i)).fract());
            let p = c.traced_gradient(x, z).x;
            let q = c.traced_gradient(x + lag, z).x;
            (sxy, sxx, syy, sx, sy, n) = (sxy + p * q, sxx + p * p, syy + q * q, sx + p, sy + q, n + 1.0);
        }
        let cov = sxy / n - sx * sy / n / n;
        cov / ((sxx / n - (sx / n).powi(2)) * (syy / n - (sy / n).powi(2))).sqrt()
    };
    let mut series = Vec::new();
    for (name, frame) in [("periodic", &tiled), ("blended", &blended)] {
        for (c, cascade) in frame.cascades().iter().enumerate().take(2) {
            let l = cascade.tile_size();
            series.push((
                format!("{name}, cascade {c} (L = {l:.1} m)"),
                (0..=240).map(|i| f64::from(i) / 80.0).map(|u| (u, correlation(cascade, u * l))).collect(),
            ));
        }
    }
    LineChart {
        title: "FFT ocean: along-wind slope correlation of a cascade with itself, periodic and blended",
        x_label: "lag (tiles of the cascade)",
        y_label: "correlation",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("waves-fft-blend.svg"))
}
