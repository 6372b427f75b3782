//! Plots of brine-sky: sky domes (PNG), the sky through the day and night, the sun's spectrum,
//! aerial perspective.

use std::path::Path;

use brine_sky::{
    MoonParams, RGB_WAVELENGTHS_NM, Scattering, Sky, SkyParams, fisheye_pixel_direction, linear_srgb_to_xyz,
    sun_spectral_radiance,
};
use glam::DVec3;

use super::{LineChart, Scale};

/// Unit vector of an elevation and a compass bearing (degrees).
fn dir(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
    DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos())
}

/// Draws the domes of `skies` side by side in rows of `per_row`, each `n` pixels, each scaled so
/// that its zenith luminance is 1 kcd m⁻² (exposed for its own zenith), and writes a PNG.
fn dome_grid(path: &Path, skies: &[Sky], per_row: usize, n: u32) -> Result<(), String> {
    let rows = skies.len().div_ceil(per_row);
    let (w, h) = (n * per_row as u32, n * rows as u32);
    let mut pixels = vec![DVec3::ZERO; (w * h) as usize];
    for (k, sky) in skies.iter().enumerate() {
        let scale = 1.0 / linear_srgb_to_xyz(sky.radiance_rgb(DVec3::Y)).y.max(1e-30);
        let (ox, oy) = ((k % per_row) as u32 * n, (k / per_row) as u32 * n);
        for j in 0..n {
            for i in 0..n {
                if let Some(v) = fisheye_pixel_direction(i, j, n) {
                    pixels[((oy + j) * w + ox + i) as usize] = sky.background_rgb(v) * scale;
                }
            }
        }
    }
    // 1 kcd/m² at the zenith maps to 0.5 before the tone curve: 1.2·2^EV = 2000 cd/m².
    let ev = (2000.0f64 / 1.2).log2();
    brine_render::write_image(path, w, h, &pixels, ev).map_err(|e| e.to_string())
}

/// Writes the brine-sky figures.
pub fn plot(dir_out: &Path) -> Result<(), String> {
    let sky = |t: f64, e: f64| Sky::new(&SkyParams::new(t, dir(e, 180.0))).map_err(|e| e.to_string());

    // Sky domes: four sun elevations × two turbidities (sun due south, at the bottom).
    let mut domes = Vec::new();
    for t in [2.0, 6.0] {
        for e in [5.0, 20.0, 45.0, 80.0] {
            domes.push(sky(t, e)?);
        }
    }
    dome_grid(&dir_out.join("sky-domes.png"), &domes, 4, 256)?;

    // Dusk to night: the sun at 0°, −3°, −6°, −9°, and a moonlit night.
    let mut dusk: Vec<Sky> = [0.0, -3.0, -6.0, -9.0].iter().map(|&e| sky(3.0, e)).collect::<Result<_, _>>()?;
    let moon = MoonParams { direction: dir(30.0, 160.0), phase_angle: 0.1, distance_km: 384_400.0 };
    dusk.push(
        Sky::new(&SkyParams { moon: Some(moon), ..SkyParams::new(3.0, dir(-35.0, 0.0)) }).map_err(|e| e.to_string())?,
    );
    dome_grid(&dir_out.join("sky-dusk-to-night.png"), &dusk, 5, 256)?;

    // The twilight along the horizon: the sky's chromaticity x over the view's elevation toward
    // the set sun, to its side and away from it, with the sun 3.6° down (the dusk of the gallery).
    let twilight = Sky::new(&SkyParams::new(3.0, dir(-3.6, 180.0))).map_err(|e| e.to_string())?;
    let mut horizon = Vec::new();
    for (label, bearing) in [("toward the set sun", 180.0), ("90° from it", 90.0), ("away from it", 0.0)] {
        let points = (0..=60)
            .filter_map(|k| {
                let e = 0.6 + 0.5 * k as f64;
                brine_sky::chromaticity(twilight.radiance_xyz(dir(e, bearing))).map(|(x, _)| (e, x))
            })
            .collect();
        horizon.push((label.to_owned(), points));
    }
    horizon.push(("D65 white (x = 0.3127)".to_owned(), vec![(0.6, 0.3127), (30.6, 0.3127)]));
    LineChart {
        title: "Twilight along the horizon, sun 3.6° down, T = 3: chromaticity x",
        x_label: "view elevation (°)",
        y_label: "x (CIE 1931)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: horizon,
    }
    .write(&dir_out.join("sky-twilight-horizon.svg"))?;

    // Zenith luminance and horizontal illuminance from −20° to 90°.
    let mut zenith = Vec::new();
    let mut illuminance = Vec::new();
    for t in [2.0, 3.0, 6.0] {
        let (mut zs, mut es) = (Vec::new(), Vec::new());
        for k in 0..=110 {
            let e = -20.0 + k as f64;
            let s = sky(t, e)?;
            let lum = |rgb: DVec3| linear_srgb_to_xyz(rgb).y;
            zs.push((e, lum(s.radiance_rgb(DVec3::Y)) * 1000.0));
            let direct = lum(s.sun().irradiance_rgb) * dir(e, 180.0).y.max(0.0);
            es.push((e, (lum(s.horizontal_irradiance_rgb()) + direct) * 1000.0));
        }
        zenith.push((format!("T = {t}"), zs));
        illuminance.push((format!("T = {t}, sun + sky"), es));
    }
    LineChart {
        title: "Zenith luminance through the day (Preetham; twilight ratio; night glow)",
        x_label: "sun elevation (°)",
        y_label: "zenith luminance (cd/m²)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: zenith,
    }
    .write(&dir_out.join("sky-zenith-luminance.svg"))?;
    illuminance.push((
        "measured twilight (Wikipedia lux table / US Navy): 400 lx, 3.4 lx, 0.008 lx".into(),
        vec![(0.0, 400.0), (-6.0, 3.4), (-12.0, 0.008)],
    ));
    LineChart {
        title: "Horizontal illuminance at sea level",
        x_label: "sun elevation (°)",
        y_label: "E_h (lx)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: illuminance,
    }
    .write(&dir_out.join("sky-horizontal-illuminance.svg"))?;

    // The sun's spectral radiance through the atmosphere.
    let mut spectra = Vec::new();
    for (m, label) in [(0.0, "top of atmosphere"), (1.0, "m = 1"), (2.0, "m = 2"), (5.0, "m = 5"), (20.0, "m = 20")] {
        let pts = (0..=74).map(|i| {
            let l = 380.0 + 5.0 * i as f64;
            (l, sun_spectral_radiance(l, 3.0, m))
        });
        spectra.push((label.to_string(), pts.collect()));
    }
    LineChart {
        title: "Sun spectral radiance, T = 3 (Preetham Appendix A.1)",
        x_label: "λ (nm)",
        y_label: "L (W m⁻² sr⁻¹ nm⁻¹)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: spectra,
    }
    .write(&dir_out.join("sky-sun-spectrum.svg"))?;

    // Aerial perspective: extinction along a horizontal ray at 2 m, T = 2 and 6.
    let mut fex = Vec::new();
    for t in [2.0, 6.0] {
        let sc = Scattering::new(t).map_err(|e| e.to_string())?;
        for (c, l) in RGB_WAVELENGTHS_NM.iter().enumerate() {
            let pts = (0..=100).map(|i| {
                let s = 500.0 * i as f64;
                (s / 1000.0, sc.aerial_perspective(2.0, DVec3::X, s, &[], DVec3::ZERO).extinction[c])
            });
            fex.push((format!("T = {t}, {l} nm"), pts.collect()));
        }
    }
    LineChart {
        title: "Aerial perspective: extinction F_ex of a horizontal path",
        x_label: "distance (km)",
        y_label: "F_ex",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: fex,
    }
    .write(&dir_out.join("sky-extinction.svg"))?;
    Ok(())
}
