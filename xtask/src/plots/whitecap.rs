//! Plots of brine-whitecap: W(α) curves, the lower tail of J against the Gaussian law, erf errors,
//! the calibration against Monahan, and top-down maps of J, the whitecap mask and the footprint
//! coverage.

use std::path::Path;

use brine_foam::{CoverageParams, DARLES_ONSET_WIND_M_S, WhitecapLaw, whitecap_coverage as monahan};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TrochoidSet, fit_trochoids};
use brine_whitecap::{
    Calibration, CalibrationOptions, ErfMethod, FootprintFilter, JacobianStatistics, Moments, WINITZKI_A,
    WINITZKI_A_DEMO, erf_abramowitz_stegun, erf_winitzki, whitecap_coverage,
};
use glam::DVec2;
use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;

use super::{LineChart, Scale};

fn e(err: impl std::fmt::Display) -> String {
    err.to_string()
}

/// The sea of `brine whitecap`'s defaults at `u10`: PM, Hasselmann spreading, 50 waves, choppiness 2.5, seed 1.
pub(super) fn default_sea(u10: f64) -> Result<TrochoidSet, String> {
    let pm = PiersonMoskowitz::from_u10(u10).map_err(e)?;
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).map_err(e)?;
    fit_trochoids(&pm, &spreading, 50, 1, &FitOptions { choppiness: 2.5, ..FitOptions::default() }).map_err(e)
}

/// Deterministic low-discrepancy points (R2 sequence) over a `side`² square.
fn surface_points(n: usize, side: f64) -> impl Iterator<Item = DVec2> {
    const G: f64 = 1.324_717_957_244_746; // plastic number
    (0..n).map(move |i| {
        let i = i as f64 + 0.5;
        DVec2::new((i / G).fract() * side, (i / (G * G)).fract() * side)
    })
}

/// Writes the brine-whitecap figures.
pub fn plot(dir: &Path) -> Result<(), String> {
    w_alpha(dir)?;
    tail(dir)?;
    erf_errors(dir)?;
    calibration(dir)?;
    maps(dir)
}

fn w_alpha(dir: &Path) -> Result<(), String> {
    let series = [0.05, 0.1, 0.2]
        .iter()
        .map(|&sd| {
            let pts = (0..=300)
                .map(|i| {
                    let a = 0.2 + 1.6 * i as f64 / 300.0;
                    (a, whitecap_coverage(Moments { mu: 1.0, sigma2: sd * sd }, a, ErfMethod::Libm))
                })
                .collect();
            (format!("μ = 1, σ = {sd}"), pts)
        })
        .collect();
    LineChart {
        title: "Whitecap coverage W(α) = ½(1 + erf((α − μ)/√(2σ²)))",
        x_label: "threshold α",
        y_label: "W",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("whitecap-w-alpha.svg"))
}

fn tail(dir: &Path) -> Result<(), String> {
    let set = default_sea(10.0)?;
    let st = JacobianStatistics::new(&set).map_err(e)?;
    let n = 400_000;
    let mut js: Vec<f64> = surface_points(n, 2.0e4).map(|u| st.jacobian_at(u, 0.0)).collect();
    js.sort_by(f64::total_cmp);
    let alphas: Vec<f64> = (0..=120).map(|i| 0.55 + 0.45 * i as f64 / 120.0).collect();
    let empirical =
        alphas.iter().map(|&a| (a, js.partition_point(|&j| j < a) as f64 / n as f64)).filter(|p| p.1 > 0.0).collect();
    let m = Moments { mu: st.mean(), sigma2: st.variance() };
    let gaussian = alphas.iter().map(|&a| (a, whitecap_coverage(m, a, ErfMethod::Libm))).collect();
    let target = monahan(&CoverageParams::new(10.0, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).map_err(e)?);
    LineChart {
        title: "Lower tail of J, 50-wave sea at U10 = 10 m/s: surface vs Gaussian law",
        x_label: "threshold α",
        y_label: "fraction of the sea with J < α",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: vec![
            ("surface, 4·10⁵ points (what the calibration uses)".into(), empirical),
            (format!("Gaussian, μ = 1, σ² = {:.5}", st.variance()), gaussian),
            ("Monahan 1980 at 10 m/s".into(), vec![(0.55, target), (1.0, target)]),
        ],
    }
    .write(&dir.join("whitecap-tail.svg"))
}

fn erf_errors(dir: &Path) -> Result<(), String> {
    let curve = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        (1..=600)
            .map(|i| {
                let x = 4.0 * i as f64 / 600.0;
                (x, (f(x) - ErfMethod::Libm.erf(x)).abs())
            })
            .filter(|p| p.1 > 1e-12)
            .collect()
    };
    LineChart {
        title: "Absolute error of the erf approximations (odd functions: x ≥ 0 shown)",
        x_label: "x",
        y_label: "|approx(x) − erf(x)|",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: vec![
            ("Winitzki a = 0.147 (slides), max 1.24e-4".into(), curve(&|x| erf_winitzki(x, WINITZKI_A))),
            ("Winitzki a = 0.140012 (demo code), max 3.29e-4".into(), curve(&|x| erf_winitzki(x, WINITZKI_A_DEMO))),
            ("Abramowitz–Stegun 7.1.26, max 1.39e-7".into(), curve(&erf_abramowitz_stegun)),
        ],
    }
    .write(&dir.join("whitecap-erf-error.svg"))
}

fn calibration(dir: &Path) -> Result<(), String> {
    let (mut target, mut calibrated, mut gaussian, mut alpha, mut alpha_g) = (vec![], vec![], vec![], vec![], vec![]);
    for i in 0..=10 {
        let u = 5.0 + 2.0 * i as f64;
        let set = default_sea(u)?;
        let st = JacobianStatistics::new(&set).map_err(e)?;
        let w = monahan(&CoverageParams::new(u, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).map_err(e)?);
        let cal = Calibration::new(&st, w, &CalibrationOptions::default()).map_err(e)?;
        let n = 1_000_000;
        let (mut c, mut g) = (0usize, 0usize);
        for p in surface_points(n, 2.0e4) {
            let j = st.jacobian_at(p, 0.0);
            c += usize::from(j < cal.alpha());
            g += usize::from(j < cal.alpha_unresolved());
        }
        target.push((u, w));
        calibrated.push((u, c as f64 / n as f64));
        gaussian.push((u, (g as f64 / n as f64).max(1e-6)));
        alpha.push((u, cal.alpha()));
        alpha_g.push((u, cal.alpha_unresolved()));
    }
    LineChart {
        title: "Calibrated whitecap coverage of a 50-wave sea vs Monahan 1980",
        x_label: "U10 (m/s)",
        y_label: "whitecap coverage",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: vec![
            ("Monahan 1980 (target)".into(), target),
            ("surface fraction J < α, calibrated α".into(), calibrated),
            ("surface fraction J < α, Gaussian-quantile α".into(), gaussian),
        ],
    }
    .write(&dir.join("whitecap-calibration.svg"))?;
    LineChart {
        title: "Calibrated threshold α of the default sea",
        x_label: "U10 (m/s)",
        y_label: "α",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![
            ("α (resolved footprints: P(J < α) = W)".into(), alpha),
            ("α (unresolved footprints: Gaussian quantile)".into(), alpha_g),
        ],
    }
    .write(&dir.join("whitecap-alpha.svg"))
}

/// A top-down map of scalar values on a grid, as SVG rectangles (runs of equal colour merged).
pub(super) struct HeatMap<'a> {
    /// Title.
    pub title: &'a str,
    /// Side of the square patch (m); the grid covers `[0, side]²` in (x, z).
    pub side: f64,
    /// `values[row][col]`, row along z, col along x.
    pub values: Vec<Vec<f64>>,
    /// Value range mapped to the colour map.
    pub range: (f64, f64),
    /// Number of colour levels.
    pub levels: usize,
    /// Colour of a normalised value in `[0, 1]`.
    pub colour: &'a dyn Fn(f64) -> RGBColor,
}

impl HeatMap<'_> {
    /// Writes the map (SVG, 620 × 600).
    pub(super) fn write(&self, path: &Path) -> Result<(), String> {
        let err = |x: &dyn std::fmt::Display| format!("plot {}: {x}", path.display());
        let root = SVGBackend::new(path, (620, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|x| err(&x))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(self.title, ("sans-serif", 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(0.0..self.side, 0.0..self.side)
            .map_err(|x| err(&x))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x (m, east)")
            .y_desc("z (m, south)")
            .draw()
            .map_err(|x| err(&x))?;
        let rows = self.values.len();
        let (lo, hi) = self.range;
        let mut rects = Vec::new();
        for (r, row) in self.values.iter().enumerate() {
            let cols = row.len();
            let (cw, rh) = (self.side / cols as f64, self.side / rows as f64);
            let level = |v: f64| (((v - lo) / (hi - lo)).clamp(0.0, 1.0) * (self.levels - 1) as f64).round() as usize;
            let mut start = 0;
            while start < cols {
                let l = level(row[start]);
                let mut end = start + 1;
                while end < cols && level(row[end]) == l {
                    end += 1;
                }
                let c = (self.colour)(l as f64 / (self.levels - 1) as f64);
                rects.push(Rectangle::new(
                    [(start as f64 * cw, r as f64 * rh), (end as f64 * cw, (r + 1) as f64 * rh)],
                    c.filled(),
                ));
                start = end;
            }
        }
        chart.draw_series(rects).map_err(|x| err(&x))?;
        root.present().map_err(|x| err(&x))
    }
}

fn maps(dir: &Path) -> Result<(), String> {
    let u10 = 15.0;
    let set = default_sea(u10)?;
    let st = JacobianStatistics::new(&set).map_err(e)?;
    let w = monahan(&CoverageParams::new(u10, WhitecapLaw::Monahan1980, DARLES_ONSET_WIND_M_S).map_err(e)?);
    let cal = Calibration::new(&st, w, &CalibrationOptions::default()).map_err(e)?;
    let (side, n) = (32.0, 100);
    let grid = |f: &dyn Fn(DVec2) -> f64| -> Vec<Vec<f64>> {
        (0..n)
            .map(|r| {
                (0..n)
                    .map(|c| f(DVec2::new((c as f64 + 0.5) * side / n as f64, (r as f64 + 0.5) * side / n as f64)))
                    .collect()
            })
            .collect()
    };
    let j = grid(&|u| st.jacobian_at(u, 0.0));
    let viridis = |t: f64| ViridisRGB::get_color(t);
    HeatMap {
        title: &format!("Jacobian J of the default sea, U10 = {u10} m/s (range 0.6 to 1.4)"),
        side,
        values: j.clone(),
        range: (0.6, 1.4),
        levels: 16,
        colour: &viridis,
    }
    .write(&dir.join("whitecap-jacobian-map.svg"))?;
    let mask: Vec<Vec<f64>> =
        j.iter().map(|row| row.iter().map(|&v| f64::from(u8::from(v < cal.alpha()))).collect()).collect();
    let two = |t: f64| if t > 0.5 { RGBColor(250, 250, 250) } else { RGBColor(20, 45, 80) };
    HeatMap {
        title: &format!("Whitecaps J < α = {:.3} (calibrated to W = {:.2} %)", cal.alpha(), 100.0 * w),
        side,
        values: mask,
        range: (0.0, 1.0),
        levels: 2,
        colour: &two,
    }
    .write(&dir.join("whitecap-mask.svg"))?;
    let s = 0.5;
    let cover =
        grid(&|u| cal.coverage(st.moments_at(u, 0.0, s, FootprintFilter::Gaussian), s, ErfMethod::AbramowitzStegun));
    let grey = |t: f64| {
        let v = (20.0 + 230.0 * t) as u8;
        RGBColor(v, v, v)
    };
    HeatMap {
        title: &format!("Footprint coverage W, Gaussian footprint s = {s} m (black 0, white ≥ 0.5)"),
        side,
        values: cover,
        range: (0.0, 0.5),
        levels: 16,
        colour: &grey,
    }
    .write(&dir.join("whitecap-coverage-map.svg"))
}
