//! `brine spectrum | fit`: ocean spectra and the spectrum-to-trochoid fit of brine-waves.
//!
//! `brine spectrum --model pm|jonswap|phillips|tma|elfouhaily --u10 10 [--fetch-m F] [--depth-m D]
//! [--gamma G] --omega-min a --omega-max b --samples n --json` prints
//! `{"omega": [...], "s": [...], ...}` (rad/s, m²·s/rad); `brine fit … --json` prints the fitted
//! wave set.

use brine_waves::{
    AmplitudeRule, CosineSquared, CosineTwoS, Directions, DonelanBanner, Elfouhaily, FitOptions, FrequencyPartition,
    Jonswap, Phillips, PiersonMoskowitz, Spectrum, Spreading, Tma, TrochoidSet, fit_trochoids,
};
use serde_json::json;

use super::CliError;

/// Default fetch of JONSWAP and TMA when `--fetch-m` is not given (m).
const DEFAULT_FETCH_M: f64 = 100_000.0;

/// A spectrum model of brine-waves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SpectrumModel {
    /// Pierson–Moskowitz 1964, fully developed sea.
    Pm,
    /// JONSWAP (Hasselmann et al. 1973), fetch-limited sea.
    Jonswap,
    /// Phillips as in Tessendorf 2001, with its small-wave cutoff.
    Phillips,
    /// TMA (Bouws et al. 1985): JONSWAP in finite depth.
    Tma,
    /// Elfouhaily et al. 1997 unified spectrum (long and short waves).
    Elfouhaily,
}

/// Which spectrum, and its parameters (shared by `brine spectrum` and `brine fit`).
#[derive(Debug, Clone, clap::Args)]
pub struct SpectrumParams {
    /// Spectrum model.
    #[arg(long, value_enum, default_value = "pm")]
    pub model: SpectrumModel,
    /// Wind speed 10 m above the sea (m/s), (0, 60]; Phillips' wind speed V.
    #[arg(long = "u10", default_value_t = 10.0, value_parser = super::finite)]
    pub u10: f64,
    /// Fetch (m): JONSWAP and TMA (default 100 km), Elfouhaily (default: fully developed sea).
    #[arg(long, value_parser = super::finite)]
    pub fetch_m: Option<f64>,
    /// Water depth (m): TMA only, required there.
    #[arg(long, value_parser = super::finite)]
    pub depth_m: Option<f64>,
    /// Peak enhancement γ (JONSWAP and TMA, default 3.3), [1, 20].
    #[arg(long, value_parser = super::finite)]
    pub gamma: Option<f64>,
}

impl SpectrumParams {
    /// Builds the spectrum, rejecting options that do not apply to the model.
    ///
    /// # Errors
    /// [`CliError::Input`] for a parameter out of range or an option that does not apply.
    pub fn build(&self) -> Result<Box<dyn Spectrum>, CliError> {
        let input = |e: brine_waves::WaveError| CliError::Input(e.to_string());
        let only = |flag: &str, models: &str| CliError::Input(format!("--{flag} applies to {models} only"));
        use SpectrumModel as M;
        if self.gamma.is_some() && !matches!(self.model, M::Jonswap | M::Tma) {
            return Err(only("gamma", "jonswap and tma"));
        }
        if self.depth_m.is_some() && self.model != M::Tma {
            return Err(only("depth-m", "tma"));
        }
        if self.fetch_m.is_some() && !matches!(self.model, M::Jonswap | M::Tma | M::Elfouhaily) {
            return Err(only("fetch-m", "jonswap, tma and elfouhaily"));
        }
        // A parameter the fetch laws derive out of its range (the Phillips constant α of a very
        // short fetch under a strong wind) is said with the fetch and wind that gave it.
        let fetch = self.fetch_m.unwrap_or(DEFAULT_FETCH_M);
        let from_fetch = |e: brine_waves::WaveError| {
            let m = e.to_string();
            if m.starts_with("u10") || m.starts_with("fetch") {
                CliError::Input(m)
            } else {
                CliError::Input(format!(
                    "--fetch-m = {} with --u10 = {}: the fetch laws give {m}; a longer fetch or a lighter wind is within the model",
                    super::num(fetch),
                    super::num(self.u10)
                ))
            }
        };
        let jonswap = || -> Result<Jonswap, CliError> {
            let j = Jonswap::from_fetch(self.u10, fetch).map_err(from_fetch)?;
            match self.gamma {
                Some(g) => j.with_peak_shape(g, Jonswap::SIGMA_A, Jonswap::SIGMA_B).map_err(input),
                None => Ok(j),
            }
        };
        Ok(match self.model {
            M::Pm => Box::new(PiersonMoskowitz::from_u10(self.u10).map_err(input)?),
            M::Jonswap => Box::new(jonswap()?),
            M::Phillips => Box::new(Phillips::from_wind(self.u10).map_err(input)?),
            M::Tma => {
                let depth = self.depth_m.ok_or_else(|| CliError::Input("--model tma needs --depth-m".into()))?;
                Box::new(Tma::new(jonswap()?, depth).map_err(input)?)
            }
            M::Elfouhaily => Box::new(match self.fetch_m {
                Some(x) => Elfouhaily::from_fetch(self.u10, x).map_err(from_fetch)?,
                None => Elfouhaily::fully_developed(self.u10).map_err(input)?,
            }),
        })
    }

    /// The model's name as typed.
    pub fn model_name(&self) -> &'static str {
        match self.model {
            SpectrumModel::Pm => "pm",
            SpectrumModel::Jonswap => "jonswap",
            SpectrumModel::Phillips => "phillips",
            SpectrumModel::Tma => "tma",
            SpectrumModel::Elfouhaily => "elfouhaily",
        }
    }
}

/// Arguments of `brine spectrum`.
#[derive(Debug, clap::Args)]
pub struct SpectrumArgs {
    /// The spectrum.
    #[command(flatten)]
    pub spectrum: SpectrumParams,
    /// Lowest angular frequency (rad/s), [1e-4, 1e4) (default 0.3 ωₚ).
    #[arg(long, value_parser = super::finite)]
    pub omega_min: Option<f64>,
    /// Highest angular frequency (rad/s), (omega-min, 1e4] (default 10 ωₚ).
    #[arg(long, value_parser = super::finite)]
    pub omega_max: Option<f64>,
    /// Number of samples, [2, 100000].
    #[arg(long, default_value_t = 200)]
    pub samples: usize,
    /// Space the samples logarithmically instead of evenly.
    #[arg(long)]
    pub log: bool,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// The JSON document of `brine spectrum`.
fn spectrum_json(args: &SpectrumArgs) -> Result<serde_json::Value, CliError> {
    let s = args.spectrum.build()?;
    let wp = s.peak_omega();
    let lo = args.omega_min.unwrap_or(0.3 * wp);
    let hi = args.omega_max.unwrap_or(10.0 * wp);
    // Ocean waves, from swell of hours to capillary ripples (a millimetre: 2×10³ rad/s), with room.
    let default_out =
        (args.omega_min.is_none() && !(1e-4..1e4).contains(&lo)) || (args.omega_max.is_none() && hi > 1e4);
    if default_out {
        return Err(CliError::Input(format!(
            "the default band 0.3–10 ωₚ (ωₚ = {} rad/s for --u10 = {}) leaves [1e-4, 1e4] rad/s: give --omega-min and --omega-max",
            super::num(wp),
            super::num(args.spectrum.u10)
        )));
    }
    if !(1e-4..1e4).contains(&lo) {
        return Err(CliError::Input(format!(
            "--omega-min = {} is out of range: expected [1e-4, 1e4) rad/s",
            super::num(lo)
        )));
    }
    if !(hi > lo && hi <= 1e4) {
        return Err(CliError::Input(format!(
            "--omega-max = {} is out of range: expected (omega-min, 1e4] rad/s",
            super::num(hi)
        )));
    }
    if !(2..=100_000).contains(&args.samples) {
        return Err(CliError::Input(format!("--samples = {} is out of range: expected [2, 100000]", args.samples)));
    }
    let n = args.samples;
    let omega: Vec<f64> = (0..n)
        .map(|i| {
            let f = i as f64 / (n - 1) as f64;
            if args.log { lo * (hi / lo).powf(f) } else { lo + f * (hi - lo) }
        })
        .collect();
    let values: Vec<f64> = omega.iter().map(|&w| s.s_omega(w)).collect();
    Ok(json!({
        "model": args.spectrum.model_name(),
        "u10_m_s": args.spectrum.u10,
        "peak_omega_rad_s": wp,
        "significant_wave_height_m": s.significant_wave_height(),
        "omega": omega,
        "s": values,
    }))
}

/// Runs `brine spectrum`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range or an option that does not apply.
pub fn run_spectrum(args: &SpectrumArgs) -> Result<(), CliError> {
    let doc = spectrum_json(args)?;
    if args.json {
        super::outln!("{doc}");
    } else {
        super::outln!(
            "# {} spectrum, U10 = {} m/s: ωₚ = {:.5} rad/s, Hs = {:.4} m",
            doc["model"].as_str().unwrap_or(""),
            args.spectrum.u10,
            doc["peak_omega_rad_s"].as_f64().unwrap_or(f64::NAN),
            doc["significant_wave_height_m"].as_f64().unwrap_or(f64::NAN)
        );
        super::outln!("{:>14} {:>14}", "omega_rad_s", "s_m2_s_rad");
        let (w, s) = (doc["omega"].as_array(), doc["s"].as_array());
        for (w, s) in w.into_iter().flatten().zip(s.into_iter().flatten()) {
            super::outln!("{:>14.6} {:>14.6e}", w.as_f64().unwrap_or(f64::NAN), s.as_f64().unwrap_or(f64::NAN));
        }
    }
    Ok(())
}

/// A directional spreading function of brine-waves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SpreadingModel {
    /// cos-2s with Hasselmann et al. 1980 exponents.
    Hasselmann,
    /// cos-2s with Mitsuyasu et al. 1975 exponents (uses --u10).
    Mitsuyasu,
    /// sech² of Donelan et al. 1985 with Banner's 1990 extension.
    DonelanBanner,
    /// Elfouhaily et al. 1997 Δ(k), folded down-wind (uses --u10 and --fetch-m).
    Elfouhaily,
    /// (2/π) cos²θ down-wind.
    Cos2,
}

/// Frequency partition of the fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PartitionArg {
    /// Equal steps in ln ω.
    Log,
    /// Equal shares of the variance.
    EqualEnergy,
    /// Equal steps in ω.
    EqualSpacing,
}

/// Amplitude rule of the fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum AmplitudeArg {
    /// A = √(2 ∫_bin S dω).
    BinVariance,
    /// A = √(2 S(ω) Δω).
    Midpoint,
}

/// Arguments of `brine fit`.
#[derive(Debug, clap::Args)]
pub struct FitArgs {
    /// The spectrum.
    #[command(flatten)]
    pub spectrum: SpectrumParams,
    /// Number of waves, [1, 10000].
    #[arg(long, default_value_t = 50)]
    pub waves: usize,
    /// Random seed of directions and phases.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Directional spreading.
    #[arg(long, value_enum, default_value = "hasselmann")]
    pub spreading: SpreadingModel,
    /// Frequency partition.
    #[arg(long, value_enum, default_value = "log")]
    pub partition: PartitionArg,
    /// Amplitude rule.
    #[arg(long, value_enum, default_value = "bin-variance")]
    pub amplitudes: AmplitudeArg,
    /// Wind direction (degrees from +x/east toward +z/south, the direction the wind blows toward).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub wind_direction_deg: f64,
    /// Choppiness c ≥ 0: steepness Q = c·k·A before the cap.
    #[arg(long, default_value_t = 1.0, value_parser = super::finite)]
    pub choppiness: f64,
    /// Cap on Σ Q, (0, 0.99]; steeper sets are scaled down together.
    #[arg(long, default_value_t = 0.9, value_parser = super::finite)]
    pub max_total_steepness: f64,
    /// Lower band edge as a multiple of ωₚ, (0, omega-max-factor).
    #[arg(long, default_value_t = 0.5, value_parser = super::finite)]
    pub omega_min_factor: f64,
    /// Upper band edge as a multiple of ωₚ, (0, 1000].
    #[arg(long, default_value_t = 12.0, value_parser = super::finite)]
    pub omega_max_factor: f64,
    /// Amplification of the high-frequency waves (Darles et al.'s capillary waves), [1, 100].
    #[arg(long, default_value_t = 1.0, value_parser = super::finite)]
    pub high_frequency_gain: f64,
    /// Start of the amplified range as a multiple of ωₚ.
    #[arg(long, default_value_t = 6.0, value_parser = super::finite)]
    pub high_frequency_start_factor: f64,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// The directional spreading `args` name, for a spectrum of peak `wp` (rad/s).
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn spreading_of(args: &FitArgs, wp: f64) -> Result<Box<dyn Spreading>, CliError> {
    let input = |e: brine_waves::WaveError| CliError::Input(e.to_string());
    Ok(match args.spreading {
        SpreadingModel::Hasselmann => Box::new(CosineTwoS::hasselmann(wp).map_err(input)?),
        SpreadingModel::Mitsuyasu => Box::new(CosineTwoS::mitsuyasu(wp, args.spectrum.u10).map_err(input)?),
        SpreadingModel::DonelanBanner => Box::new(DonelanBanner::new(wp).map_err(input)?),
        SpreadingModel::Cos2 => Box::new(CosineSquared::downwind()),
        SpreadingModel::Elfouhaily => {
            let e = match args.spectrum.fetch_m {
                Some(x) => Elfouhaily::from_fetch(args.spectrum.u10, x),
                None => Elfouhaily::fully_developed(args.spectrum.u10),
            }
            .map_err(input)?;
            Box::new(e.spreading(Directions::Downwind))
        }
    })
}

/// Widest band of a fit, in multiples of the peak frequency.
const MAX_OMEGA_FACTOR: f64 = 1000.0;

/// Fits the set described by `args`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range or an option that does not apply.
pub fn fit_set(args: &FitArgs) -> Result<(Box<dyn Spectrum>, TrochoidSet), CliError> {
    let input = |e: brine_waves::WaveError| CliError::Input(e.to_string());
    let s = args.spectrum.build()?;
    let spreading = spreading_of(args, s.peak_omega())?;
    if !args.wind_direction_deg.is_finite() {
        return Err(CliError::Input(format!(
            "--wind-direction-deg = {} is out of range: expected a finite angle in degrees",
            args.wind_direction_deg
        )));
    }
    if !(1..=10_000).contains(&args.waves) {
        return Err(CliError::Input(format!("--waves = {} is out of range: expected [1, 10000]", args.waves)));
    }
    // The band in multiples of ωₚ: a wave at 1000 ωₚ is a millimetre long for the lightest wind.
    if !(args.omega_max_factor > 0.0 && args.omega_max_factor <= MAX_OMEGA_FACTOR) {
        return Err(CliError::Input(format!(
            "--omega-max-factor = {} is out of range: expected (0, {MAX_OMEGA_FACTOR}]",
            super::num(args.omega_max_factor)
        )));
    }
    if !(args.omega_min_factor > 0.0 && args.omega_min_factor < args.omega_max_factor) {
        return Err(CliError::Input(format!(
            "--omega-min-factor = {} is out of range: expected (0, --omega-max-factor)",
            super::num(args.omega_min_factor)
        )));
    }
    let options = FitOptions {
        partition: match args.partition {
            PartitionArg::Log => FrequencyPartition::Logarithmic,
            PartitionArg::EqualEnergy => FrequencyPartition::EqualEnergy,
            PartitionArg::EqualSpacing => FrequencyPartition::EqualSpacing,
        },
        amplitude_rule: match args.amplitudes {
            AmplitudeArg::BinVariance => AmplitudeRule::BinVariance,
            AmplitudeArg::Midpoint => AmplitudeRule::Midpoint,
        },
        omega_min_factor: args.omega_min_factor,
        omega_max_factor: args.omega_max_factor,
        wind_direction: args.wind_direction_deg.to_radians(),
        choppiness: args.choppiness,
        max_total_steepness: args.max_total_steepness,
        high_frequency_gain: args.high_frequency_gain,
        high_frequency_start_factor: args.high_frequency_start_factor,
        ..FitOptions::default()
    };
    let set = fit_trochoids(s.as_ref(), spreading.as_ref(), args.waves, args.seed, &options).map_err(input)?;
    Ok((s, set))
}

/// The JSON document of `brine fit`.
fn fit_json(args: &FitArgs) -> Result<serde_json::Value, CliError> {
    let (s, set) = fit_set(args)?;
    let wp = s.peak_omega();
    let waves: Vec<serde_json::Value> = set
        .waves()
        .iter()
        .map(|w| {
            json!({
                "amplitude_m": w.amplitude(),
                "wavelength_m": w.wavelength(),
                "direction_rad": w.direction(),
                "omega_rad_s": w.omega(),
                "phase_rad": w.phase(),
                "steepness": w.steepness(),
            })
        })
        .collect();
    Ok(json!({
        "model": args.spectrum.model_name(),
        "seed": args.seed,
        "peak_omega_rad_s": wp,
        "variance_m2": set.variance(),
        "band_variance_m2": s.variance_between(args.omega_min_factor * wp, args.omega_max_factor * wp),
        "total_amplitude_m": set.total_amplitude(),
        "total_steepness": set.total_steepness(),
        "waves": waves,
    }))
}

/// Runs `brine fit`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range or an option that does not apply.
pub fn run_fit(args: &FitArgs) -> Result<(), CliError> {
    let doc = fit_json(args)?;
    if args.json {
        super::outln!("{doc}");
        return Ok(());
    }
    super::outln!(
        "# {} waves fitted to {} (seed {}): Σ A²/2 = {:.5} m² (band ∫S dω = {:.5} m²), Σ Q = {:.4}",
        args.waves,
        doc["model"].as_str().unwrap_or(""),
        args.seed,
        doc["variance_m2"].as_f64().unwrap_or(f64::NAN),
        doc["band_variance_m2"].as_f64().unwrap_or(f64::NAN),
        doc["total_steepness"].as_f64().unwrap_or(f64::NAN)
    );
    let cols = ["amplitude_m", "wavelength_m", "direction_rad", "omega_rad_s", "phase_rad", "steepness"];
    super::outln!("{}", cols.map(|c| format!("{c:>14}")).join(" "));
    for w in doc["waves"].as_array().into_iter().flatten() {
        super::outln!("{}", cols.map(|c| format!("{:>14.6}", w[c].as_f64().unwrap_or(f64::NAN))).join(" "));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    use super::super::{Cli, Command};
    use super::*;

    fn spectrum_args(argv: &[&str]) -> SpectrumArgs {
        let mut full = vec!["brine", "spectrum"];
        full.extend_from_slice(argv);
        match Cli::try_parse_from(full).unwrap().command {
            Some(Command::Spectrum(a)) => a,
            other => panic!("parsed {other:?}"),
        }
    }

    fn fit_args(argv: &[&str]) -> FitArgs {
        let mut full = vec!["brine", "fit"];
        full.extend_from_slice(argv);
        match Cli::try_parse_from(full).unwrap().command {
            Some(Command::Fit(a)) => a,
            other => panic!("parsed {other:?}"),
        }
    }

    /// The JSON document holds the computed f64s themselves (no text round trip): the grid ends
    /// `lo + 0·(hi − lo)` and `lo + (hi − lo)` are exact or an ulp of 3 (4.4×10⁻¹⁶), and the
    /// sample is the same `S(ω)` of the same `ω`; 10⁻¹⁵ allows a few ulps of values of order 1.
    const JSON_F64_ABS: f64 = 1e-15;

    #[test]
    fn spectrum_json_has_the_requested_samples() {
        let a = spectrum_args(&[
            "--model",
            "pm",
            "--u10",
            "10",
            "--omega-min",
            "0.2",
            "--omega-max",
            "3",
            "--samples",
            "5",
            "--json",
        ]);
        let doc = spectrum_json(&a).unwrap();
        let omega = doc["omega"].as_array().unwrap();
        assert_eq!(omega.len(), 5);
        assert!(
            (omega[0].as_f64().unwrap() - 0.2).abs() < JSON_F64_ABS
                && (omega[4].as_f64().unwrap() - 3.0).abs() < JSON_F64_ABS
        );
        let pm = PiersonMoskowitz::from_u10(10.0).unwrap();
        let s1 = doc["s"][1].as_f64().unwrap();
        assert!((s1 - pm.s_omega(omega[1].as_f64().unwrap())).abs() < JSON_F64_ABS);
    }

    #[test]
    fn every_model_prints_a_spectrum() {
        for argv in [
            vec!["--model", "jonswap", "--fetch-m", "50000", "--gamma", "2"],
            vec!["--model", "tma", "--depth-m", "15"],
            vec!["--model", "phillips", "--u10", "7"],
            vec!["--model", "elfouhaily", "--fetch-m", "20000"],
        ] {
            let doc = spectrum_json(&spectrum_args(&argv)).unwrap();
            assert!(doc["s"].as_array().unwrap().iter().all(|v| v.as_f64().is_some_and(|x| x >= 0.0)), "{argv:?}");
        }
    }

    #[test]
    fn bad_input_is_an_input_error() {
        for argv in [
            vec!["--model", "pm", "--u10", "80"],
            vec!["--model", "pm", "--gamma", "3"],
            vec!["--model", "tma"],
            vec!["--model", "pm", "--omega-min", "0"],
            vec!["--model", "pm", "--samples", "1"],
            // Log spacing over 600 decades gave NaN frequencies.
            vec!["--model", "pm", "--omega-min", "1e-300", "--omega-max", "1e300", "--log"],
        ] {
            match spectrum_json(&spectrum_args(&argv)) {
                Err(CliError::Input(msg)) => assert!(!msg.is_empty()),
                other => panic!("{argv:?}: {other:?}"),
            }
        }
        // The flags are named as typed, with their ranges (not the fit's internal names).
        for (argv, said) in [
            (vec!["--waves", "0"], "--waves = 0 is out of range: expected [1, 10000]"),
            (vec!["--omega-max-factor", "1e300"], "--omega-max-factor = 1e300 is out of range"),
            (
                vec!["--model", "jonswap", "--fetch-m", "1e-9"],
                "--fetch-m = 1e-9 with --u10 = 10: the fetch laws give alpha",
            ),
        ] {
            match fit_json(&fit_args(&argv)) {
                Err(CliError::Input(msg)) => assert!(msg.starts_with(said), "{msg}"),
                other => panic!("{argv:?}: {other:?}"),
            }
        }
    }

    /// `Σ Aᵢ²/2` of the fit against the band's `∫ S dω`: with bin-variance amplitudes both are
    /// Simpson quadratures in `ln ω` of the same band (the fit's per bin, about 4×10³ pairs in all;
    /// `variance_between`'s with 1000 pairs), so 1 % is a loose check that the amplitudes carry
    /// the band's variance, not a quadrature accuracy.
    const BAND_VARIANCE_REL: f64 = 0.01;

    #[test]
    fn fit_json_lists_the_waves() {
        let a = fit_args(&[
            "--model",
            "jonswap",
            "--waves",
            "40",
            "--seed",
            "3",
            "--spreading",
            "donelan-banner",
            "--json",
        ]);
        let doc = fit_json(&a).unwrap();
        let waves = doc["waves"].as_array().unwrap();
        assert_eq!(waves.len(), 40);
        for key in ["amplitude_m", "wavelength_m", "direction_rad", "omega_rad_s", "phase_rad", "steepness"] {
            assert!(waves[0][key].as_f64().is_some(), "{key}");
        }
        let v = doc["variance_m2"].as_f64().unwrap();
        let band = doc["band_variance_m2"].as_f64().unwrap();
        assert!((v / band - 1.0).abs() < BAND_VARIANCE_REL);
    }
}
