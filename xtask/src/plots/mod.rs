//! `cargo xtask plots`: figures for `docs/models/`, one module per crate.
//!
//! Each module exposes `plot(dir: &Path) -> Result<(), String>` writing SVG (or PNG) files into
//! `docs/models/plots/`; register it in [`PLOTTERS`].

use std::path::Path;

use plotters::prelude::*;

mod ephem;
mod foam;
mod optics;
mod sky;
mod texture;
mod trace;
mod waves;
mod whitecap;

type Plotter = fn(&Path) -> Result<(), String>;

/// `(crate, plotting function)`.
const PLOTTERS: &[(&str, Plotter)] = &[
    ("brine-waves", waves::plot),
    ("brine-trace", trace::plot),
    ("brine-optics", optics::plot),
    ("brine-sky", sky::plot),
    ("brine-ephem", ephem::plot),
    ("brine-foam", foam::plot),
    ("brine-whitecap", whitecap::plot),
    ("brine-texture", texture::plot),
];

/// Runs the plotters of the named crates (all when empty).
pub fn run(root: &Path, crates: &[String]) -> Result<(), String> {
    let dir = root.join("docs/models/plots");
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    for c in crates {
        if !PLOTTERS.iter().any(|(name, _)| name == c) {
            let known: Vec<_> = PLOTTERS.iter().map(|p| p.0).collect();
            return Err(format!("no plots for {c} (known: {})", known.join(", ")));
        }
    }
    for (name, plot) in PLOTTERS {
        if crates.is_empty() || crates.iter().any(|c| c == name) {
            eprintln!("plotting {name}");
            plot(&dir)?;
        }
    }
    Ok(())
}

/// Axis scale of a [`LineChart`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear axis.
    Linear,
    /// Logarithmic axis (all values must be positive).
    Log,
}

/// A simple multi-series line chart written as SVG.
pub struct LineChart<'a> {
    /// Title above the plot.
    pub title: &'a str,
    /// X axis label, with unit.
    pub x_label: &'a str,
    /// Y axis label, with unit.
    pub y_label: &'a str,
    /// X axis scale.
    pub x_scale: Scale,
    /// Y axis scale.
    pub y_scale: Scale,
    /// `(legend, points)` per series.
    pub series: Vec<(String, Vec<(f64, f64)>)>,
}

fn range_of(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && (scale == Scale::Linear || *v > 0.0)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !(lo < hi) {
        (lo - 1.0, hi + 1.0)
    } else if scale == Scale::Log {
        (lo, hi)
    } else {
        let pad = 0.05 * (hi - lo);
        (lo - pad, hi + pad)
    }
}

/// Tick label with at most four significant digits: plain for moderate magnitudes, scientific
/// otherwise (log axes otherwise print values like `9.999999999e-5`). Below 10⁻¹⁵ in magnitude a
/// tick is the zero of a linear axis missed by rounding (`-5.55e-17`), and prints as `0`.
pub fn tick(v: &f64) -> String {
    let a = v.abs();
    if a < 1e-15 {
        "0".into()
    } else if (1e-3..1e5).contains(&a) {
        format!("{v:.4}").trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        let s = format!("{v:.2e}");
        s.replace(".00e", "e")
    }
}

impl LineChart<'_> {
    /// Writes the chart to `path` (SVG, 720 × 450).
    pub fn write(&self, path: &Path) -> Result<(), String> {
        let err = |e: &dyn std::fmt::Display| format!("plot {}: {e}", path.display());
        let root = SVGBackend::new(path, (720, 450)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let xs = range_of(self.series.iter().flat_map(|s| s.1.iter().map(|p| p.0)), self.x_scale);
        let ys = range_of(self.series.iter().flat_map(|s| s.1.iter().map(|p| p.1)), self.y_scale);
        let mut builder = ChartBuilder::on(&root);
        builder.caption(self.title, ("sans-serif", 18)).margin(12).x_label_area_size(40).y_label_area_size(70);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart.map_err(|e| err(&e))?;
                chart
                    .configure_mesh()
                    .x_desc(self.x_label)
                    .y_desc(self.y_label)
                    .x_label_formatter(&tick)
                    .y_label_formatter(&tick)
                    .draw()
                    .map_err(|e| err(&e))?;
                for (i, (label, pts)) in self.series.iter().enumerate() {
                    let colour = Palette99::pick(i).to_rgba();
                    chart
                        .draw_series(LineSeries::new(pts.iter().copied(), colour.stroke_width(2)))
                        .map_err(|e| err(&e))?
                        .label(label.as_str())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
                }
                chart
                    .configure_series_labels()
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .draw()
                    .map_err(|e| err(&e))?;
            }};
        }
        match (self.x_scale, self.y_scale) {
            (Scale::Linear, Scale::Linear) => draw!(builder.build_cartesian_2d(xs.0..xs.1, ys.0..ys.1)),
            (Scale::Log, Scale::Linear) => draw!(builder.build_cartesian_2d((xs.0..xs.1).log_scale(), ys.0..ys.1)),
            (Scale::Linear, Scale::Log) => draw!(builder.build_cartesian_2d(xs.0..xs.1, (ys.0..ys.1).log_scale())),
            (Scale::Log, Scale::Log) => {
                draw!(builder.build_cartesian_2d((xs.0..xs.1).log_scale(), (ys.0..ys.1).log_scale()))
            }
        }
        root.present().map_err(|e| err(&e))
    }
}
