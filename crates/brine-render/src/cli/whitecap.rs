//! `brine whitecap`: whitecap coverage from the displacement-Jacobian statistics, for given
//! moments, or for the fitted sea at a wind with a raw or calibrated threshold.

use brine_foam::{
    CoverageParams, DARLES_ONSET_WIND_M_S, FoamMemory, FoamMemoryParams, KOEPKE_EFFICIENCY, WhitecapLaw,
    whitecap_coverage as monahan_coverage,
};
use brine_waves::{CosineTwoS, FitOptions, PiersonMoskowitz, Spectrum, TrochoidSet, fit_trochoids};
use brine_whitecap::{
    Calibration, CalibrationOptions, ErfMethod, JacobianStatistics, Moments, TrochoidBreaking, WhiteWaterModel,
    WhiteWaterOptions, surface_coverage, whitecap_coverage,
};
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::{Value, json};

use super::CliError;

/// The error function on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ErfArg {
    /// The slides' approximation (Winitzki, a = 0.147), error ≤ 1.25e-4.
    Fast,
    /// Abramowitz & Stegun 7.1.26, error ≤ 1.5e-7.
    #[value(name = "abramowitz-stegun")]
    AbramowitzStegun,
    /// libm's erf (full precision).
    Libm,
}

impl From<ErfArg> for ErfMethod {
    fn from(e: ErfArg) -> Self {
        match e {
            ErfArg::Fast => ErfMethod::Fast,
            ErfArg::AbramowitzStegun => ErfMethod::AbramowitzStegun,
            ErfArg::Libm => ErfMethod::Libm,
        }
    }
}

/// Arguments of `brine whitecap`.
///
/// Either `--mu M --sigma S --alpha A` (the coverage law alone), or `--u10 U` with `--calibrate`
/// (the threshold that gives Monahan's coverage on the fitted sea) or with `--alpha A` (the
/// coverage of a raw threshold on the fitted sea).
#[derive(Debug, Clone, clap::Args)]
pub struct WhitecapArgs {
    /// Mean μ of the Jacobian over the footprint.
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub mu: Option<f64>,
    /// Standard deviation σ of the Jacobian over the footprint (≥ 0).
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub sigma: Option<f64>,
    /// Breaking threshold α: whitecaps where J < α.
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub alpha: Option<f64>,
    /// Wind speed 10 m above the sea U10 (m/s, (0, 60]) of the fitted sea.
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub u10: Option<f64>,
    /// Calibrate α so that the fitted sea's coverage equals Monahan's.
    #[arg(long, requires = "u10", conflicts_with = "alpha")]
    pub calibrate: bool,
    /// With --u10: the renderer's white water (active whitecaps and the foam they leave,
    /// calibrated together on Monahan's W), measured at --mc-samples points (at most 10⁶).
    #[arg(long, requires = "u10", conflicts_with_all = ["alpha", "calibrate"])]
    pub white_water: bool,
    /// Number of waves of the fitted sea ([1, 10000]; 50, the Gerstner and sine seas' default).
    #[arg(long, default_value_t = 50)]
    pub waves: usize,
    /// Choppiness of the fit ([0, 100]; the default scene's 2.5).
    #[arg(long, default_value_t = 2.5, value_parser = super::finite)]
    pub choppiness: f64,
    /// Seed of the fitted sea's directions and phases.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Water temperature (°C): with --t-air-c, the target is Monahan's 1986 stability law.
    #[arg(long, allow_negative_numbers = true, requires = "t_air_c", value_parser = super::finite)]
    pub t_water_c: Option<f64>,
    /// Air temperature (°C).
    #[arg(long, allow_negative_numbers = true, requires = "t_water_c", value_parser = super::finite)]
    pub t_air_c: Option<f64>,
    /// Surface points of the Monte Carlo check over the sea ([1000, 10⁸]).
    #[arg(long, default_value_t = 1 << 19)]
    pub mc_samples: usize,
    /// Error function for the coverage law.
    #[arg(long, value_enum, default_value = "libm")]
    pub erf: ErfArg,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

fn input<E: std::fmt::Display>(e: E) -> CliError {
    CliError::Input(e.to_string())
}

/// The fitted sea of the command's arguments at `u10` (by default 50 waves, seed 1, choppiness 2.5).
fn fitted_sea(args: &WhitecapArgs, u10: f64) -> Result<TrochoidSet, CliError> {
    if !(0.0..=100.0).contains(&args.choppiness) {
        return Err(CliError::Input(format!("--choppiness {} is out of range: expected [0, 100]", args.choppiness)));
    }
    let pm = PiersonMoskowitz::from_u10(u10).map_err(input)?;
    let spreading = CosineTwoS::hasselmann(pm.peak_omega()).map_err(input)?;
    let options = FitOptions { choppiness: args.choppiness, ..FitOptions::default() };
    fit_trochoids(&pm, &spreading, args.waves, args.seed, &options).map_err(input)
}

/// Fraction of `n` uniform points of a 20 km square (ChaCha8, seed 1) where `J < α`, and its
/// standard error.
fn monte_carlo(stats: &JacobianStatistics, alpha: f64, n: usize) -> (f64, f64) {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let below = (0..n)
        .filter(|_| {
            let u = DVec2::new(rng.random::<f64>() * 2e4, rng.random::<f64>() * 2e4);
            stats.jacobian_at(u, 0.0) < alpha
        })
        .count();
    let p = below as f64 / n as f64;
    (p, (p * (1.0 - p) / n as f64).sqrt())
}

/// Largest number of points of the white-water measurement.
const MAX_WHITE_WATER_POINTS: usize = 1_000_000;

/// `brine whitecap --u10 U --white-water`: the renderer's white-water model on the fitted sea,
/// measured on fresh points (a 20 km square, times over an hour) at the point footprint.
fn white_water_json(
    args: &WhitecapArgs,
    u10: f64,
    stats: JacobianStatistics,
    set: &TrochoidSet,
    target: f64,
    law: &str,
) -> Result<Value, CliError> {
    let pm = PiersonMoskowitz::from_u10(u10).map_err(input)?;
    let s_b = brine_whitecap::breaking_footprint(brine_waves::G / pm.peak_omega());
    let params = FoamMemoryParams {
        edge_wavelength_m: (std::f64::consts::PI * s_b).clamp(0.5, 20.0),
        ..FoamMemoryParams::for_wind(u10, 0.0, args.seed)
    };
    let memory = FoamMemory::new(&params, KOEPKE_EFFICIENCY).map_err(input)?;
    let source = TrochoidBreaking::new(stats, memory.step(), DVec2::from_array(memory.drift()));
    let options = WhiteWaterOptions { seed: args.seed, ..WhiteWaterOptions::default() };
    let model = WhiteWaterModel::new(source, memory, s_b, crate::world::EDGE_SHARE, target, &options).map_err(input)?;
    let n = args.mc_samples.min(MAX_WHITE_WATER_POINTS);
    let mut rng = ChaCha8Rng::seed_from_u64(args.seed ^ 0xf00d);
    let (mut white, mut visible, mut active, mut residual) = (0.0, 0.0, 0.0, 0.0);
    for _ in 0..n {
        let u = DVec2::new(rng.random::<f64>() * 2e4, rng.random::<f64>() * 2e4);
        let w = model.at(u, rng.random::<f64>() * 3600.0, 0.0);
        white += w.white;
        visible += f64::from(u8::from(w.white > 0.5));
        active += w.active;
        residual += w.residual;
    }
    let m = n as f64;
    Ok(json!({
        "u10_m_s": u10,
        "waves": set.len(),
        "seed": args.seed,
        "monahan_law": law,
        "monahan_coverage": target,
        "alpha": model.alpha_for_footprint(0.0),
        "breaking_footprint_m": s_b,
        "edge_std": model.edge_std(),
        "decay_time_s": model.memory().decay_time(),
        "brightness_decay_time_s": model.memory().brightness_decay_time(),
        "points": n,
        "mean_white": white / m,
        "visible_coverage": visible / m,
        "active_coverage": active / m,
        "residual_coverage": residual / m,
        "windrow_coverage": model.windrow_cover(),
    }))
}

/// The JSON answer of `brine whitecap`.
///
/// # Errors
/// [`CliError::Input`] for a missing or out-of-range parameter.
pub fn whitecap_json(args: &WhitecapArgs) -> Result<Value, CliError> {
    let erf: ErfMethod = args.erf.into();
    if let Some(u10) = args.u10 {
        if args.mu.is_some() || args.sigma.is_some() {
            return Err(CliError::Input("--mu/--sigma and --u10 are two different modes: give one".into()));
        }
        if !(1000..=100_000_000).contains(&args.mc_samples) {
            return Err(CliError::Input(format!(
                "--mc-samples {} is out of range: expected [1000, 1e8]",
                args.mc_samples
            )));
        }
        let set = fitted_sea(args, u10)?;
        let stats = JacobianStatistics::new(&set).map_err(input)?;
        let law = match (args.t_water_c, args.t_air_c) {
            (Some(tw), Some(ta)) => WhitecapLaw::monahan_1986_from_temperatures(tw, ta).map_err(input)?,
            _ => WhitecapLaw::Monahan1980,
        };
        let target = monahan_coverage(&CoverageParams::new(u10, law, DARLES_ONSET_WIND_M_S).map_err(input)?);
        if args.white_water {
            return white_water_json(args, u10, stats, &set, target, law.name());
        }
        let options = CalibrationOptions::default();
        let mut v = json!({
            "u10_m_s": u10,
            "waves": args.waves,
            "choppiness": args.choppiness,
            "seed": args.seed,
            "jacobian_mean": stats.mean(),
            "jacobian_variance": stats.variance(),
            "monahan_law": law.name(),
            "monahan_coverage": target,
        });
        let alpha = if args.calibrate {
            let cal = Calibration::new(&stats, target, &options).map_err(input)?;
            v["alpha"] = json!(cal.alpha());
            v["alpha_unresolved"] = json!(cal.alpha_unresolved());
            v["calibration_relative_std_error"] = json!(cal.relative_std_error());
            v["footprint_table"] = cal.table().map(|(s, a)| json!({ "footprint_m": s, "alpha": a })).collect();
            cal.alpha()
        } else {
            let alpha = args.alpha.ok_or_else(|| CliError::Input("with --u10, give --calibrate or --alpha".into()))?;
            if !alpha.is_finite() {
                return Err(CliError::Input(format!("--alpha {alpha} is not finite")));
            }
            let est = surface_coverage(&stats, alpha, &options).map_err(input)?;
            v["alpha"] = json!(alpha);
            v["coverage_importance_sampled"] = json!(est.coverage);
            v["coverage_gaussian"] =
                json!(whitecap_coverage(Moments { mu: stats.mean(), sigma2: stats.variance() }, alpha, erf));
            alpha
        };
        let (p, se) = monte_carlo(&stats, alpha, args.mc_samples);
        v["coverage"] = json!(p);
        v["coverage_std_error"] = json!(se);
        return Ok(v);
    }
    match (args.mu, args.sigma, args.alpha) {
        (Some(mu), Some(sigma), Some(alpha)) => {
            if !mu.is_finite() || !alpha.is_finite() {
                return Err(CliError::Input("--mu and --alpha must be finite".into()));
            }
            if !(sigma >= 0.0 && sigma.is_finite()) {
                return Err(CliError::Input(format!("--sigma {sigma} is out of range: expected [0, ∞)")));
            }
            let w = whitecap_coverage(Moments { mu, sigma2: sigma * sigma }, alpha, erf);
            Ok(
                json!({ "mu": mu, "sigma": sigma, "alpha": alpha, "erf": clap::ValueEnum::to_possible_value(&args.erf).map(|v| v.get_name().to_owned()), "coverage": w }),
            )
        }
        _ => Err(CliError::Input("give --mu M --sigma S --alpha A, or --u10 U with --calibrate or --alpha A".into())),
    }
}

/// The threshold `α` as text: a number, or what an infinite threshold means (JSON has `null`,
/// for a target coverage of 0 or 1).
fn alpha_text(v: &Value, target: f64) -> String {
    match v["alpha"].as_f64() {
        Some(a) => format!("{a:.5}"),
        None if target <= 0.0 => "−∞ (no whitecaps: Monahan's W is 0)".into(),
        None => "+∞ (white everywhere: Monahan's W is 1)".into(),
    }
}

/// The text answer of `brine whitecap` for its JSON answer `v`.
fn whitecap_text(v: &Value) -> String {
    let f = |key: &str| v[key].as_f64().unwrap_or(f64::NAN);
    if v.get("u10_m_s").is_none() {
        return format!("W = {:.8}", f("coverage"));
    }
    let target = f("monahan_coverage");
    let head = format!("U10 = {} m/s, {} waves: α = {}", v["u10_m_s"], v["waves"], alpha_text(v, target));
    if v.get("mean_white").is_some() {
        // --white-water: the memory's white water at the point footprint.
        return format!(
            "{head} at the point footprint\n\
             white {:.5} (active whitecaps {:.5}, foam left behind {:.5}, wind streaks' share {:.5}), \
             more than half white {:.5}, Monahan {target:.5} ({}); {} points",
            f("mean_white"),
            f("active_coverage"),
            f("residual_coverage"),
            f("windrow_coverage"),
            f("visible_coverage"),
            v["monahan_law"].as_str().unwrap_or("?"),
            v["points"],
        );
    }
    format!("{head}, surface coverage {:.5} ± {:.5}, Monahan {target:.5}", f("coverage"), f("coverage_std_error"))
}

/// Runs `brine whitecap`.
///
/// # Errors
/// [`CliError::Input`] for a missing or out-of-range parameter.
pub fn run_whitecap(args: &WhitecapArgs) -> Result<(), CliError> {
    let v = whitecap_json(args)?;
    if args.json {
        super::outln!("{v}");
    } else {
        super::outln!("{}", whitecap_text(&v));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    use super::*;

    #[derive(Parser)]
    struct Whitecap {
        #[command(flatten)]
        args: WhitecapArgs,
    }

    fn run(line: &str) -> Result<Value, CliError> {
        whitecap_json(
            &Whitecap::try_parse_from(std::iter::once("whitecap").chain(line.split_whitespace())).unwrap().args,
        )
    }

    #[test]
    fn coverage_of_given_moments() {
        // α one σ below μ: Φ(−1) = 0.158655253931457.
        let v = run("--mu 1 --sigma 0.2 --alpha 0.8 --json").unwrap();
        assert!((v["coverage"].as_f64().unwrap() - 0.158_655_253_931_457).abs() < 1e-12);
        let v = run("--mu 1 --sigma 0.2 --alpha 0.8 --erf fast").unwrap();
        assert!((v["coverage"].as_f64().unwrap() - 0.158_655_253_931_457).abs() < 1e-4);
    }

    #[test]
    fn calibrated_sea_matches_monahan() {
        let v = run("--u10 10 --calibrate --mc-samples 200000 --json").unwrap();
        let (c, m) = (v["coverage"].as_f64().unwrap(), v["monahan_coverage"].as_f64().unwrap());
        assert!((m - 9.870e-3).abs() < 1e-5);
        // The 10 % acceptance tolerance.
        assert!((c / m - 1.0).abs() < 0.1, "{v}");
        assert!(v["alpha"].as_f64().unwrap() > 0.0 && v["footprint_table"].as_array().unwrap().len() == 8);
    }

    /// Binomial error of a share `W ≈ 0.05` on 100 000 points plus the calibration's on 32 768,
    /// relative: `√((1 − W)/(W M))` ≈ 0.014 and 0.025; 0.1 is over three of both together.
    const WHITE_WATER_REL_TOL: f64 = 0.1;

    #[test]
    fn white_water_is_monahans_and_reads_as_white() {
        let v = run("--u10 16 --white-water --mc-samples 100000 --json").unwrap();
        let m = v["monahan_coverage"].as_f64().unwrap();
        // Monahan & Ó Muircheartaigh 1980 at 16 m/s: 3.84e-6 · 16^3.41.
        assert!((m - 3.84e-6 * 16f64.powf(3.41)).abs() < 1e-9);
        for key in ["mean_white", "visible_coverage"] {
            let c = v[key].as_f64().unwrap();
            assert!((c / m - 1.0).abs() < WHITE_WATER_REL_TOL, "{key}: {v}");
        }
        // Stage B outlasts stage A: most white water is foam left behind.
        assert!(v["active_coverage"].as_f64().unwrap() < 0.5 * v["mean_white"].as_f64().unwrap(), "{v}");
        assert!((v["decay_time_s"].as_f64().unwrap() - 3.85).abs() < 1e-12);
    }

    /// Every text answer names its figures with numbers: no NaN from a key the mode does not
    /// have, and an infinite threshold (a target of 0 or 1) said in words.
    #[test]
    fn text_answers_hold_no_nan() {
        for line in [
            "--mu 1 --sigma 0.2 --alpha 0.8",
            "--u10 10 --calibrate --mc-samples 2000",
            "--u10 10 --alpha 0.5 --mc-samples 2000",
            "--u10 16 --white-water --mc-samples 2000",
            "--u10 1 --white-water --mc-samples 2000",
            "--u10 40 --white-water --mc-samples 2000",
        ] {
            let text = whitecap_text(&run(line).unwrap());
            assert!(!text.contains("NaN"), "{line}: {text}");
        }
        let v = run("--u10 16 --white-water --mc-samples 2000").unwrap();
        let text = whitecap_text(&v);
        let white = format!("white {:.5}", v["mean_white"].as_f64().unwrap());
        assert!(text.contains(&white) && text.contains("active whitecaps"), "{text}");
        assert!(whitecap_text(&run("--u10 1 --white-water --mc-samples 2000").unwrap()).contains("α = −∞"));
        assert!(whitecap_text(&run("--u10 40 --white-water --mc-samples 2000").unwrap()).contains("α = +∞"));
    }

    #[test]
    fn bad_input() {
        for line in [
            "--mu 1 --sigma -0.2 --alpha 0.8",
            "--mu 1 --alpha 0.8",
            "--u10 0 --calibrate",
            "--u10 70 --calibrate",
            "--u10 10",
            "--u10 10 --calibrate --waves 0",
            "--u10 10 --calibrate --waves 20000",
            "--u10 10 --calibrate --mc-samples 5",
            "--u10 10 --alpha 0.5 --mu 1",
        ] {
            match run(line) {
                Err(CliError::Input(m)) => assert!(!m.is_empty()),
                other => panic!("{line}: {other:?}"),
            }
        }
    }
}
