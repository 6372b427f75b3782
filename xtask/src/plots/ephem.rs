//! Plots of brine-ephem: the sun's path over a day at two latitudes, the moon's phase over a
//! month, and the Schlyter Sun and Moon against SPA over a century.

use std::path::Path;

use brine_ephem::{Observer, Options, SunModel, Timestamp, moon_position, parse_utc, sun_position};

use super::{LineChart, Scale};

fn at(t: Timestamp, seconds: i64) -> Result<Timestamp, String> {
    Timestamp::from_second(t.as_second() + seconds).map_err(|e| e.to_string())
}

/// Writes the brine-ephem figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    let err = |e: brine_ephem::EphemError| e.to_string();
    let opts = Options::default();

    // The sun's path (altitude against azimuth) on the solstices, Toulouse and Tromsø.
    let mut paths = Vec::new();
    for (name, lat, lon) in [("Toulouse 43.6° N", 43.6, 1.44), ("Tromsø 69.65° N", 69.65, 18.96)] {
        let o = Observer::from_degrees(lat, lon, 0.0).map_err(err)?;
        for day in ["2024-06-21", "2024-12-21"] {
            let start = parse_utc(&format!("{day}T00:00:00Z")).map_err(err)?;
            let mut pts = Vec::new();
            for k in 0..=288 {
                let p = sun_position(at(start, 300 * k)?, &o, SunModel::Spa, &opts).map_err(err)?;
                pts.push((p.azimuth.to_degrees(), p.altitude.to_degrees()));
            }
            paths.push((format!("{name}, {day}"), pts));
        }
    }
    LineChart {
        title: "Sun path over a day (SPA, airless altitude)",
        x_label: "azimuth from north (°)",
        y_label: "altitude (°)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: paths,
    }
    .write(&dir.join("ephem-sun-path.svg"))?;

    // The Moon's illuminated fraction and phase angle over a month.
    let o = Observer::from_degrees(43.6, 1.44, 0.0).map_err(err)?;
    let start = parse_utc("2024-06-01T00:00:00Z").map_err(err)?;
    let (mut k, mut i) = (Vec::new(), Vec::new());
    for h in 0..=(31 * 24) {
        let m = moon_position(at(start, 3600 * h)?, &o, &opts).map_err(err)?;
        k.push((h as f64 / 24.0, m.illuminated_fraction));
        i.push((h as f64 / 24.0, m.phase_angle.to_degrees() / 180.0));
    }
    LineChart {
        title: "The Moon over June 2024 (full 22 June 01:08 UT, new 6 June 12:38 UT)",
        x_label: "days from 2024-06-01 0h UT",
        y_label: "fraction",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![("illuminated fraction k".into(), k), ("phase angle / 180°".into(), i)],
    }
    .write(&dir.join("ephem-moon-phase.svg"))?;

    // Schlyter's Sun against SPA every 73 days over 1950–2050 at 43.6° N (angular separation).
    let start = parse_utc("1950-01-01T12:00:00Z").map_err(err)?;
    let mut pts = Vec::new();
    for k in 0..500 {
        let t = at(start, k * 73 * 86_400 + (k % 24) * 3600)?;
        let a = sun_position(t, &o, SunModel::Spa, &opts).map_err(err)?;
        let b = sun_position(t, &o, SunModel::Schlyter, &opts).map_err(err)?;
        let (u, v) = (a.horizontal().direction(), b.horizontal().direction());
        let c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]).clamp(-1.0, 1.0);
        pts.push((1950.0 + k as f64 * 73.0 / 365.25, c.acos().to_degrees() * 3600.0));
    }
    LineChart {
        title: "Schlyter's Sun against NREL SPA, 43.6° N",
        x_label: "year",
        y_label: "angular difference (arcsec)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![("|Schlyter − SPA|".into(), pts)],
    }
    .write(&dir.join("ephem-schlyter-vs-spa.svg"))?;
    Ok(())
}
