//! Plots of brine-foam: coverage laws, spray size distribution, optical depth, the spume and the
//! visibility in the spray, a map of the local foam amount, and the foam history at one water
//! particle.

use std::path::Path;

use brine_foam::{
    CoverageParams, DARLES_ONSET_WIND_M_S, ExtinctionEfficiency, FoamExtension, FoamExtensionParams, FoamHistory,
    FoamHistoryParams, FoamPoint, KoepkeFoam, SprayMedium, SprayParams, SpumeLayer, SpumeParams, SurfaceStatistics,
    WhitecapLaw, f94_spume_flux, msd86_flux, whitecap_coverage,
};
use brine_waves::{Elfouhaily, PiersonMoskowitz, TrochoidSum, WaveSurface};
use glam::DVec2;
use plotters::style::RGBColor;

use super::whitecap::{HeatMap, default_sea};
use super::{LineChart, Scale};

fn e(err: impl std::fmt::Display) -> String {
    err.to_string()
}

/// Writes the brine-foam figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    coverage(dir)?;
    spray(dir)?;
    spume(dir)?;
    foam_map(dir)?;
    history(dir)
}

fn coverage(dir: &Path) -> Result<(), String> {
    let laws = [
        ("Monahan 1980, 3.84e-6 U^3.41".to_owned(), WhitecapLaw::Monahan1980),
        ("Monahan 1986, 2.95e-6 U^3.52".to_owned(), WhitecapLaw::Monahan1986Wind),
        ("Monahan 1986 stability, ΔT = 0".to_owned(), WhitecapLaw::Monahan1986Stability { delta_t_c: 0.0 }),
        (
            "Monahan 1986 stability, ΔT = −8 °C (Darles fig. 6)".to_owned(),
            WhitecapLaw::Monahan1986Stability { delta_t_c: -8.0 },
        ),
        ("Monahan 1986 stability, ΔT = +4 °C".to_owned(), WhitecapLaw::Monahan1986Stability { delta_t_c: 4.0 }),
        ("Darles Eq. 3 as printed, ΔT = 0".to_owned(), WhitecapLaw::Darles2007AsPrinted { delta_t_c: 0.0 }),
    ];
    let mut series = Vec::new();
    for (name, law) in laws {
        let pts = (0..=250)
            .map(|i| {
                let u = 0.1 * i as f64;
                Ok((u, whitecap_coverage(&CoverageParams::new(u, law, DARLES_ONSET_WIND_M_S).map_err(e)?)))
            })
            .collect::<Result<Vec<_>, String>>()?;
        series.push((name, pts));
    }
    LineChart {
        title: "Whitecap coverage vs wind (zero below the 13 km/h onset)",
        x_label: "U10 (m/s)",
        y_label: "coverage W",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("foam-coverage.svg"))
}

/// The spume layer of a fully developed sea at `u`: Elfouhaily's `u*`, half the
/// Pierson–Moskowitz `H_s`.
fn spume_layer(u: f64) -> Result<SpumeLayer, String> {
    let u_star = Elfouhaily::new(u, 0.84).map_err(e)?.u_star();
    let z_s = 0.5 * PiersonMoskowitz::from_u10(u).map_err(e)?.significant_wave_height();
    SpumeLayer::new(&SpumeParams { u10: u, friction_velocity_m_s: u_star, source_height_m: z_s }).map_err(e)
}

fn spume(dir: &Path) -> Result<(), String> {
    let mut series = Vec::new();
    for u in [10.0, 16.0, 22.0] {
        let pts = (0..=300).map(|i| 0.8 * 300f64.powf(i as f64 / 300.0));
        series.push((
            format!("bubble drops (MSD86), U10 = {u} m/s"),
            pts.clone().filter(|&r| r < 15.0).map(|r| (r, msd86_flux(r, u))).collect(),
        ));
        series.push((
            format!("spume (Fairall et al. 1994), U10 = {u} m/s"),
            pts.filter(|&r| (15.0..250.0).contains(&r)).map(|r| (r, f94_spume_flux(r, u))).collect(),
        ));
    }
    LineChart {
        title: "Source functions of the spray: bubble drops below 15 µm, spume above",
        x_label: "r80 (µm)",
        y_label: "dF/dr80 (drops m⁻² s⁻¹ µm⁻¹)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("foam-spume-dfdr.svg"))?;
    let mut at_sea = Vec::new();
    let mut at_10 = Vec::new();
    let mut spume_only = Vec::new();
    for i in 8..=60 {
        let u = 0.5 * i as f64;
        let bubbles = SprayMedium::new(&SprayParams { u10: u, ..SprayParams::default() }).map_err(e)?;
        let spume = spume_layer(u)?;
        let v = |k: f64| 50f64.ln() / k / 1000.0;
        at_sea.push((u, v(bubbles.extinction(0.0, 1.0) + spume.extinction(0.0))));
        at_10.push((u, v(bubbles.extinction(10.0, 1.0) + spume.extinction(10.0))));
        spume_only.push((u, v(spume.extinction(0.0))));
    }
    LineChart {
        title: "Visibility ln 50 / k in the spray over a fully developed sea",
        x_label: "U10 (m/s)",
        y_label: "visibility (km)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: vec![
            ("at the sea, bubble drops and spume".to_owned(), at_sea),
            ("10 m above the sea".to_owned(), at_10),
            ("at the sea, spume alone".to_owned(), spume_only),
        ],
    }
    .write(&dir.join("foam-spray-visibility.svg"))
}

fn spray(dir: &Path) -> Result<(), String> {
    let series = [5.0, 10.0, 20.0]
        .iter()
        .map(|&u| {
            let pts = (0..=200).map(|i| {
                let r = 0.5 * 60f64.powf(i as f64 / 200.0);
                (r, msd86_flux(r, u))
            });
            (format!("U10 = {u} m/s (law fitted on 0.8–15 µm)"), pts.collect())
        })
        .collect();
    LineChart {
        title: "Spray source function dF/dr80 of Monahan, Spiel & Davidson 1986",
        x_label: "r80 (µm)",
        y_label: "dF/dr80 (drops m⁻² s⁻¹ µm⁻¹)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("foam-spray-dfdr.svg"))?;
    let efficiencies = [
        ("Q_e = 2 (Darles)".to_owned(), ExtinctionEfficiency::Constant(2.0)),
        (
            "anomalous diffraction, 450 nm".to_owned(),
            ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm: 450.0, refractive_index: 1.34 },
        ),
        (
            "anomalous diffraction, 650 nm".to_owned(),
            ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm: 650.0, refractive_index: 1.34 },
        ),
    ];
    let mut series = Vec::new();
    for (name, efficiency) in efficiencies {
        let pts = (1..=60)
            .map(|i| {
                let u = 0.5 * i as f64;
                let m = SprayMedium::new(&SprayParams { u10: u, efficiency, ..SprayParams::default() }).map_err(e)?;
                Ok((u, m.optical_depth()))
            })
            .collect::<Result<Vec<_>, String>>()?;
        series.push((name, pts));
    }
    LineChart {
        title: "Vertical optical depth τ of the spray (H = 1 km, z_max = 2 km, r80 0.8–15 µm)",
        x_label: "U10 (m/s)",
        y_label: "τ",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("foam-spray-optical-depth.svg"))
}

/// Height and slope statistics of a set for the foam extension.
fn surface_statistics(set: &brine_waves::TrochoidSet) -> SurfaceStatistics {
    let sum = TrochoidSum::new(set);
    let (y_min, y_max) = sum.height_bounds();
    let (mut sx, mut sz) = (0.0, 0.0);
    for w in set.waves() {
        let d = w.direction_vector();
        sx += w.mean_square_slope() * d.x * d.x;
        sz += w.mean_square_slope() * d.y * d.y;
    }
    SurfaceStatistics { y_min, y_max, height_std: set.variance().sqrt(), slope_variance_x: sx, slope_variance_z: sz }
}

fn foam_map(dir: &Path) -> Result<(), String> {
    let u10 = 12.0;
    let set = default_sea(u10)?;
    let sum = TrochoidSum::new(&set);
    let ext = FoamExtension::new(&FoamExtensionParams::default(), &surface_statistics(&set)).map_err(e)?;
    let w = whitecap_coverage(&CoverageParams::new(u10, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).map_err(e)?);
    let (side, n) = (150.0, 90);
    let values: Vec<Vec<f64>> = (0..n)
        .map(|r| {
            (0..n)
                .map(|c| {
                    let p = DVec2::new((c as f64 + 0.5) * side / n as f64, (r as f64 + 0.5) * side / n as f64);
                    let g = sum.gradient(p.x, p.y, 0.0);
                    ext.foam_amount(
                        w,
                        &FoamPoint {
                            height: sum.height(p.x, p.y, 0.0),
                            slope: [g.x, g.y],
                            rest: [p.x, p.y],
                            footprint_m: side / n as f64,
                        },
                    )
                })
                .collect()
        })
        .collect();
    let mean = values.iter().flatten().sum::<f64>() / (n * n) as f64;
    let blue_white = |t: f64| {
        let lerp = |a: f64, b: f64| (a + (b - a) * t) as u8;
        RGBColor(lerp(15.0, 255.0), lerp(40.0, 255.0), lerp(75.0, 255.0))
    };
    HeatMap {
        title: &format!("Foam amount s′ (Darles Eq. 4 corrected), U10 = {u10} m/s: W = {:.3}, map mean {mean:.3}", w),
        side,
        values,
        range: (0.0, 0.1),
        levels: 12,
        colour: &blue_white,
    }
    .write(&dir.join("foam-extension-map.svg"))
}

fn history(dir: &Path) -> Result<(), String> {
    let h = FoamHistory::new(&FoamHistoryParams::default(), &KoepkeFoam::default()).map_err(e)?;
    // A water particle under a sea of three waves: the source peaks each time a crest passes.
    let source = |t: f64| {
        let y = 0.6 * (0.9 * t).cos() + 0.3 * (1.7 * t + 1.0).cos() + 0.2 * (2.9 * t + 2.0).cos();
        (0.03 * ((y + 1.1) / 2.2).clamp(0.0, 1.0).powi(8) / 0.04).min(1.0)
    };
    let (mut src, mut cover, mut bright) = (vec![], vec![], vec![]);
    for i in 0..=1200 {
        let t = 0.05 * i as f64;
        let s = h.accumulate(t, |smp| source(smp.time_s));
        src.push((t, source(t)));
        cover.push((t, s.cover));
        bright.push((t, s.brightness * s.cover));
    }
    LineChart {
        title: "Foam at one water particle: source s′, cover after ageing (τ = 4 s), cover × brightness",
        x_label: "time (s)",
        y_label: "fraction",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![
            ("instantaneous s′ (Eq. 4)".into(), src),
            ("foam cover (history)".into(), cover),
            ("cover × brightness ρ(age)".into(), bright),
        ],
    }
    .write(&dir.join("foam-history.svg"))
}
