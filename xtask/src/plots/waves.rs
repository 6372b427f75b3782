//! Plots of brine-waves.

use std::path::Path;

use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, fit_trochoids};

use super::{LineChart, Scale};

/// Writes the brine-waves figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    let mut spectra = Vec::new();
    for u in [5.0, 10.0, 20.0] {
        let pm = PiersonMoskowitz::from_u10(u).map_err(|e| e.to_string())?;
        let pts = (0..400).map(|i| {
            let w = 0.1 * 10f64.powf(i as f64 / 200.0);
            (w, pm.s_omega(w))
        });
        spectra.push((format!("Pierson–Moskowitz, U10 = {u} m/s"), pts.filter(|p| p.1 > 1e-8).collect()));
    }
    LineChart {
        title: "Pierson–Moskowitz spectra",
        x_label: "ω (rad/s)",
        y_label: "S(ω) (m² s/rad)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: spectra,
    }
    .write(&dir.join("waves-pm-spectra.svg"))?;

    let pm = PiersonMoskowitz::from_u10(10.0).map_err(|e| e.to_string())?;
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).map_err(|e| e.to_string())?;
    let set = fit_trochoids(&pm, &spreading, 50, 1, &FitOptions::default()).map_err(|e| e.to_string())?;
    let amps: Vec<(f64, f64)> = set.waves().iter().map(|w| (w.omega(), w.amplitude())).collect();
    LineChart {
        title: "Fitted amplitudes, 50 waves, PM U10 = 10 m/s, log partition",
        x_label: "ω (rad/s)",
        y_label: "A (m)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: vec![("Aᵢ = √(2∫S dω over bin i)".into(), amps)],
    }
    .write(&dir.join("waves-fit-amplitudes.svg"))
}
