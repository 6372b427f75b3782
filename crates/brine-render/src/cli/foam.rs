//! `brine foam` (whitecap coverage of Monahan's laws) and `brine spray` (the MSD86 spray source
//! function and the spume of Fairall et al. 1994, their extinction, optical depth and visibility).

use brine_foam::{
    CoverageParams, DARLES_ONSET_WIND_M_S, ExtinctionEfficiency, FOAM_DENSITY, FoamMemory, FoamMemoryParams,
    KOEPKE_EFFICIENCY, MSD86_RADIUS_RANGE_UM, SPUME_RADIUS_RANGE_UM, SprayMedium, SprayParams, SpumeLayer, SpumeParams,
    WIND_DRIFT_FRACTION, WhitecapLaw, f94_spume_flux, msd86_flux, whitecap_coverage,
};
use brine_waves::{Elfouhaily, PiersonMoskowitz};
use serde_json::{Value, json};

use super::CliError;

/// A coverage law on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LawArg {
    /// Monahan & Ó Muircheartaigh 1980, `3.84e-6 U^3.41` (default without temperatures).
    #[value(name = "monahan-1980")]
    Monahan1980,
    /// Monahan & Ó Muircheartaigh 1986, `2.95e-6 U^3.52`.
    #[value(name = "monahan-1986-wind")]
    Monahan1986Wind,
    /// Monahan & Ó Muircheartaigh 1986, `1.95e-5 U^2.55 exp(0.0861 ΔT)` (default with temperatures).
    #[value(name = "monahan-1986-stability")]
    Monahan1986Stability,
    /// Darles et al. 2007 Eq. 3 as printed, `1.59e-5 U^2.55 exp(0.086 ΔT)`.
    #[value(name = "darles-2007-as-printed")]
    Darles2007AsPrinted,
}

/// Arguments of `brine foam`.
#[derive(Debug, Clone, clap::Args)]
pub struct FoamArgs {
    /// Wind speed 10 m above the sea, U10 (m/s, [0, 60]).
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub u10: f64,
    /// Water temperature (°C, [-2, 40]); with --t-air-c, selects the 1986 stability law.
    #[arg(long, allow_negative_numbers = true, requires = "t_air_c", value_parser = super::finite)]
    pub t_water_c: Option<f64>,
    /// Air temperature (°C, [-60, 60]).
    #[arg(long, allow_negative_numbers = true, requires = "t_water_c", value_parser = super::finite)]
    pub t_air_c: Option<f64>,
    /// Coverage law (default: monahan-1986-stability with temperatures, monahan-1980 without).
    #[arg(long, value_enum)]
    pub law: Option<LawArg>,
    /// Wind speed below which there are no whitecaps (m/s, [0, 10]; Darles: 13 km/h).
    #[arg(long, default_value_t = DARLES_ONSET_WIND_M_S, value_parser = super::finite)]
    pub onset_m_s: f64,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// The law named by the arguments.
///
/// # Errors
/// [`CliError::Input`] for temperatures out of range or a law without its temperatures.
pub fn law_of(args: &FoamArgs) -> Result<WhitecapLaw, CliError> {
    let input = |e: brine_foam::FoamError| CliError::Input(e.to_string());
    let delta_t = match (args.t_water_c, args.t_air_c) {
        (Some(tw), Some(ta)) => match WhitecapLaw::monahan_1986_from_temperatures(tw, ta).map_err(input)? {
            WhitecapLaw::Monahan1986Stability { delta_t_c } => Some(delta_t_c),
            _ => None,
        },
        _ => None,
    };
    let need_dt =
        |name: &str| delta_t.ok_or_else(|| CliError::Input(format!("--law {name} needs --t-water-c and --t-air-c")));
    Ok(match (args.law, delta_t) {
        (Some(LawArg::Monahan1980), _) | (None, None) => WhitecapLaw::Monahan1980,
        (Some(LawArg::Monahan1986Wind), _) => WhitecapLaw::Monahan1986Wind,
        (Some(LawArg::Monahan1986Stability), _) | (None, Some(_)) => {
            WhitecapLaw::Monahan1986Stability { delta_t_c: need_dt("monahan-1986-stability")? }
        }
        (Some(LawArg::Darles2007AsPrinted), _) => {
            WhitecapLaw::Darles2007AsPrinted { delta_t_c: need_dt("darles-2007-as-printed")? }
        }
    })
}

/// The JSON answer of `brine foam`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn foam_json(args: &FoamArgs) -> Result<Value, CliError> {
    let law = law_of(args)?;
    let params = CoverageParams::new(args.u10, law, args.onset_m_s).map_err(|e| CliError::Input(e.to_string()))?;
    let delta_t = match law {
        WhitecapLaw::Monahan1986Stability { delta_t_c } | WhitecapLaw::Darles2007AsPrinted { delta_t_c } => {
            Some(delta_t_c)
        }
        _ => None,
    };
    let memory = FoamMemoryParams::for_wind(args.u10, 0.0, 1);
    let m = FoamMemory::new(&memory, KOEPKE_EFFICIENCY).map_err(|e| CliError::Input(e.to_string()))?;
    Ok(json!({
        "u10_m_s": args.u10,
        "law": law.name(),
        "delta_t_c": delta_t,
        "onset_m_s": args.onset_m_s,
        "coverage": whitecap_coverage(&params),
        "memory": {
            "decay_time_s": m.decay_time(),
            "brightness_decay_time_s": m.brightness_decay_time(),
            "foam_density": FOAM_DENSITY,
            "length_s": m.length(),
            "step_s": m.step(),
            "wind_drift_m_s": WIND_DRIFT_FRACTION * args.u10,
            "streak_stretch": memory.streak_stretch,
            "windrow_share": m.windrow_share(),
            "lace_cell_m": m.lace().map_or(0.0, |l| l.cell()),
        },
    }))
}

/// Runs `brine foam`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn run_foam(args: &FoamArgs) -> Result<(), CliError> {
    let v = foam_json(args)?;
    if args.json {
        super::outln!("{v}");
    } else {
        super::outln!(
            "whitecap coverage W = {:.6} ({:.4} %) at U10 = {} m/s ({})",
            v["coverage"].as_f64().unwrap_or(0.0),
            100.0 * v["coverage"].as_f64().unwrap_or(0.0),
            args.u10,
            v["law"].as_str().unwrap_or("")
        );
        let m = &v["memory"];
        super::outln!(
            "foam left by breaking: area decays in {} s (brightness in {:.2} s), drifts {:.2} m/s downwind, patches {:.1}× longer along the wind; {:.0} % of the white cover in wind streaks",
            m["decay_time_s"],
            m["brightness_decay_time_s"].as_f64().unwrap_or(0.0),
            m["wind_drift_m_s"].as_f64().unwrap_or(0.0),
            m["streak_stretch"].as_f64().unwrap_or(1.0),
            100.0 * m["windrow_share"].as_f64().unwrap_or(0.0)
        );
        super::outln!(
            "white water drawn as a lace of foam filaments, cells of {:.2} m down to a ninth of it (same mean cover)",
            m["lace_cell_m"].as_f64().unwrap_or(0.0)
        );
    }
    Ok(())
}

/// Arguments of `brine spray`.
#[derive(Debug, Clone, clap::Args)]
pub struct SprayArgs {
    /// Wind speed 10 m above the sea, U10 (m/s, [0, 60]).
    #[arg(long, allow_negative_numbers = true, value_parser = super::finite)]
    pub u10: f64,
    /// Drop radii r80 (µm) for the size distribution: one value, or START:STOP:COUNT
    /// (log-spaced, both ends included; COUNT in [1, 10000]).
    #[arg(long, default_value = "0.8:15:20", allow_hyphen_values = true)]
    pub radius_um: String,
    /// Scale height of the exponential profile (m, (0, 10000]).
    #[arg(long, default_value_t = 1000.0, value_parser = super::finite)]
    pub scale_height_m: f64,
    /// Height above which there is no spray, Darles' maximal height (m, (0, 10000]).
    #[arg(long, default_value_t = 2000.0, value_parser = super::finite)]
    pub max_height_m: f64,
    /// Wavelength of light (nm, [300, 2500]): anomalous-diffraction extinction efficiency instead of 2.
    #[arg(long, value_parser = super::finite)]
    pub wavelength_nm: Option<f64>,
    /// Friction velocity u* for the spume layer (m/s, (0, 5]); default: Elfouhaily et al.'s for
    /// a fully developed sea at U10, held within [0.001, 5] as the renderer holds it.
    #[arg(long, value_parser = super::finite)]
    pub u_star_m_s: Option<f64>,
    /// Height at which spume is torn off, the significant wave amplitude, half the significant height (m, (0, 30]);
    /// default: half the Pierson–Moskowitz significant height at U10, held within [0.001, 30] m as
    /// the renderer holds it.
    #[arg(long, value_parser = super::finite)]
    pub source_height_m: Option<f64>,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// Parses `A` or `START:STOP:COUNT` into log-spaced radii (µm).
fn radii(spec: &str) -> Result<Vec<f64>, CliError> {
    let bad = |why: &str| {
        CliError::Input(format!("--radius-um {spec}: {why} (expected R or START:STOP:COUNT, radii in (0, 1000] µm)"))
    };
    let num = |s: &str| s.trim().parse::<f64>().map_err(|_| bad("not a number"));
    let parts: Vec<&str> = spec.split(':').collect();
    let list = match parts.as_slice() {
        [r] => vec![num(r)?],
        [a, b, n] => {
            let (a, b) = (num(a)?, num(b)?);
            let n: usize = n.trim().parse().map_err(|_| bad("COUNT is not a whole number"))?;
            if !(1..=10_000).contains(&n) {
                return Err(bad("COUNT outside [1, 10000]"));
            }
            if !(a > 0.0 && b >= a) {
                return Err(bad("need 0 < START ≤ STOP"));
            }
            if n == 1 { vec![a] } else { (0..n).map(|i| a * (b / a).powf(i as f64 / (n - 1) as f64)).collect() }
        }
        _ => return Err(bad("wrong form")),
    };
    if list.iter().any(|r| !(r.is_finite() && *r > 0.0 && *r <= 1000.0)) {
        return Err(bad("radius outside (0, 1000] µm"));
    }
    Ok(list)
}

/// The JSON answer of `brine spray`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn spray_json(args: &SprayArgs) -> Result<Value, CliError> {
    let efficiency = match args.wavelength_nm {
        Some(wavelength_nm) => ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm, refractive_index: 1.34 },
        None => ExtinctionEfficiency::Constant(2.0),
    };
    let params = SprayParams {
        u10: args.u10,
        scale_height_m: args.scale_height_m,
        max_height_m: args.max_height_m,
        efficiency,
        ..SprayParams::default()
    };
    let medium = SprayMedium::new(&params).map_err(|e| CliError::Input(e.to_string()))?;
    let spume = spume_layer(args)?;
    let (lo, hi) = MSD86_RADIUS_RANGE_UM;
    let distribution: Vec<Value> = radii(&args.radius_um)?
        .into_iter()
        .map(|r| {
            json!({
                "radius_um": r,
                "dF_dr": msd86_flux(r, args.u10),
                "concentration_m3_um": medium.concentration(r, 0.0),
                "in_validity_range": (lo..=hi).contains(&r),
                "spume_dF_dr": f94_spume_flux(r, args.u10),
            })
        })
        .collect();
    let visibility = |z: f64| {
        let k = medium.extinction(z, 1.0) + spume.as_ref().map_or(0.0, |s| s.extinction(z));
        if k > 0.0 { json!(50f64.ln() / k) } else { Value::Null }
    };
    let spume_json = spume.as_ref().map_or(Value::Null, |s| {
        json!({
            "source": "Fairall, Kepert & Holland 1994",
            "range_um": [SPUME_RADIUS_RANGE_UM.0, SPUME_RADIUS_RANGE_UM.1],
            "u_star_m_s": s.params().friction_velocity_m_s,
            "source_height_m": s.params().source_height_m,
            "production_velocity_m_s": s.production_velocity(),
            "extinction_m": s.extinction(0.0),
            "extinction_10m_m": s.extinction(10.0),
            "optical_depth": s.optical_depth_above(0.0),
            "classes": s.classes().iter().map(|c| json!({
                "radius_um": c.radius_um,
                "extinction_m": c.extinction_0,
                "scale_height_m": c.scale_height_m,
            })).collect::<Vec<_>>(),
        })
    });
    Ok(json!({
        "u10_m_s": args.u10,
        "units": { "dF_dr": "drops m^-2 s^-1 um^-1", "concentration": "drops m^-3 um^-1", "extinction": "m^-1" },
        "validity_range_um": [lo, hi],
        "distribution": distribution,
        "extinction_m": medium.extinction(0.0, 1.0),
        "optical_depth": medium.optical_depth(),
        "scale_height_m": args.scale_height_m,
        "max_height_m": args.max_height_m,
        "spume": spume_json,
        "visibility_m": { "sea_level": visibility(0.0), "at_10_m": visibility(10.0) },
        "q_e": match efficiency {
            ExtinctionEfficiency::Constant(q) => json!(q),
            ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm, .. } => json!({ "anomalous_diffraction_nm": wavelength_nm }),
        },
    }))
}

/// The spume layer of the command line (`None` without wind): `u*` and the source height from
/// the options, or Elfouhaily et al.'s `u*` and half the Pierson–Moskowitz `H_s` of a fully
/// developed sea.
fn spume_layer(args: &SprayArgs) -> Result<Option<SpumeLayer>, CliError> {
    let input = |e: &dyn std::fmt::Display| CliError::Input(e.to_string());
    if !(args.u10 > 0.0 && args.u10 <= 60.0) {
        return Ok(None);
    }
    // The defaults are the renderer's (brine-render's spray): held within the spume model's
    // ranges, which the fully developed sea leaves near calm (u* → 0) and in a hurricane (half
    // the Pierson–Moskowitz H_s passes 30 m from U10 ≈ 52 m/s).
    let within = |v: f64, lo: f64, hi: f64| if v.is_finite() { v.clamp(lo, hi) } else { lo };
    let u_star = match args.u_star_m_s {
        Some(u) => u,
        None => within(Elfouhaily::new(args.u10, 0.84).map_err(|e| input(&e))?.u_star(), 1e-3, 5.0),
    };
    let source_height_m = match args.source_height_m {
        Some(z) => z,
        None => within(
            0.5 * PiersonMoskowitz::from_u10(args.u10).map_err(|e| input(&e))?.significant_wave_height(),
            1e-3,
            30.0,
        ),
    };
    SpumeLayer::new(&SpumeParams { u10: args.u10, friction_velocity_m_s: u_star, source_height_m })
        .map(Some)
        .map_err(|e| input(&e))
}

/// Runs `brine spray`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn run_spray(args: &SprayArgs) -> Result<(), CliError> {
    let v = spray_json(args)?;
    if args.json {
        super::outln!("{v}");
        return Ok(());
    }
    super::outln!(
        "U10 = {} m/s: k_e(0) = {:.4e} m^-1, optical depth τ = {:.4e}",
        args.u10,
        v["extinction_m"].as_f64().unwrap_or(f64::NAN),
        v["optical_depth"].as_f64().unwrap_or(f64::NAN)
    );
    if let Some(s) = v["spume"].as_object() {
        let f = |k: &str| s.get(k).and_then(Value::as_f64).unwrap_or(f64::NAN);
        super::outln!(
            "spume (15–250 µm, u* = {:.3} m/s, torn off at {:.2} m): k(0) = {:.4e} m^-1, k(10 m) = {:.4e} m^-1, τ = {:.4e}",
            f("u_star_m_s"),
            f("source_height_m"),
            f("extinction_m"),
            f("extinction_10m_m"),
            f("optical_depth")
        );
    }
    let vis = |k: &str| v["visibility_m"][k].as_f64().map_or("unlimited".to_string(), |m| format!("{:.0} m", m));
    super::outln!("visibility (ln 50 / k): {} at the sea, {} at 10 m", vis("sea_level"), vis("at_10_m"));
    super::outln!("{:>12} {:>14} {:>16}", "r80 (µm)", "dF/dr", "n(r, 0)");
    for d in v["distribution"].as_array().into_iter().flatten() {
        super::outln!(
            "{:>12.4} {:>14.5e} {:>16.5e}{}",
            d["radius_um"].as_f64().unwrap_or(f64::NAN),
            d["dF_dr"].as_f64().unwrap_or(f64::NAN),
            d["concentration_m3_um"].as_f64().unwrap_or(f64::NAN),
            if d["in_validity_range"].as_bool() == Some(true) { "" } else { "  (outside 0.8–15 µm)" }
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;
    use clap::Parser;

    use super::*;

    #[derive(Parser)]
    struct Foam {
        #[command(flatten)]
        args: FoamArgs,
    }

    #[derive(Parser)]
    struct Spray {
        #[command(flatten)]
        args: SprayArgs,
    }

    fn foam(line: &str) -> Result<Value, CliError> {
        foam_json(&Foam::try_parse_from(std::iter::once("foam").chain(line.split_whitespace())).unwrap().args)
    }

    fn spray(line: &str) -> Result<Value, CliError> {
        spray_json(&Spray::try_parse_from(std::iter::once("spray").chain(line.split_whitespace())).unwrap().args)
    }

    #[test]
    fn foam_documented_example() {
        // The JSON carries the library's f64 value: a few roundings of pow and exp.
        const ROUNDING: f64 = 1e-12;
        // Monahan & O'Muircheartaigh 1986, W = 1.95×10⁻⁵ U^2.55 e^{0.0861 ΔT}, at ΔT = 12 − 20 =
        // −8 °C: 1.95e-5 · 10^2.55 · e^{−0.6888} = 3.4745×10⁻³ (the documented example).
        let v = foam("--u10 10 --t-water-c 12 --t-air-c 20 --json").unwrap();
        let expected = 1.95e-5 * 10f64.powf(2.55) * (0.0861 * -8.0f64).exp();
        assert_relative_eq!(v["coverage"].as_f64().unwrap(), expected, max_relative = ROUNDING);
        assert_eq!(v["law"], "monahan-1986-stability");
        // Monahan & O'Muircheartaigh 1980, W = 3.84×10⁻⁶ U^3.41: 9.870×10⁻³ at 10 m/s.
        let v = foam("--u10 10 --json").unwrap();
        assert_relative_eq!(v["coverage"].as_f64().unwrap(), 3.84e-6 * 10f64.powf(3.41), max_relative = ROUNDING);
        let v = foam("--u10 3 --json").unwrap();
        assert!(v["coverage"].as_f64().unwrap().abs() < 1e-300);
    }

    /// Over the whole documented wind range the spume's defaults stay within the model's ranges
    /// (as the renderer holds them): a hurricane's half `H_s` passes 30 m from 52 m/s, and a
    /// near calm has `u* → 0`.
    #[test]
    fn spray_answers_at_every_documented_wind() {
        for u in ["1e-300", "0.01", "1", "10", "51", "55", "60"] {
            let v = spray(&format!("--u10 {u} --json")).unwrap_or_else(|e| panic!("--u10 {u}: {e}"));
            let z = v["spume"]["source_height_m"].as_f64().unwrap();
            assert!(z > 0.0 && z <= 30.0, "--u10 {u}: source height {z}");
        }
        let v = spray("--u10 60 --json").unwrap();
        assert_eq!(v["spume"]["source_height_m"].as_f64(), Some(30.0));
    }

    #[test]
    fn foam_bad_input() {
        for line in
            ["--u10 80", "--u10 -1", "--u10 10 --t-water-c 50 --t-air-c 20", "--u10 10 --law darles-2007-as-printed"]
        {
            match foam(line) {
                Err(CliError::Input(m)) => assert!(!m.is_empty()),
                other => panic!("{line}: {other:?}"),
            }
        }
    }

    #[test]
    fn spray_documented_example() {
        let v = spray("--u10 10 --radius-um 1:100:50 --json").unwrap();
        let d = v["distribution"].as_array().unwrap();
        assert_eq!(d.len(), 50);
        assert!((d[0]["dF_dr"].as_f64().unwrap() / 2.614e4 - 1.0).abs() < 6e-4);
        assert!((d[49]["radius_um"].as_f64().unwrap() - 100.0).abs() < 1e-9);
        assert_eq!(d[49]["in_validity_range"], false);
        let (ke, tau) = (v["extinction_m"].as_f64().unwrap(), v["optical_depth"].as_f64().unwrap());
        assert!(ke > 0.0 && tau > 0.0 && (tau / (ke * 1000.0 * (1.0 - (-2.0f64).exp())) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn spray_bad_input() {
        for line in [
            "--u10 70",
            "--u10 10 --radius-um 0:5:3",
            "--u10 10 --radius-um 5:1:3",
            "--u10 10 --radius-um a",
            "--u10 10 --radius-um 1:2:0",
            "--u10 10 --wavelength-nm 100",
        ] {
            match spray(line) {
                Err(CliError::Input(m)) => assert!(!m.is_empty()),
                other => panic!("{line}: {other:?}"),
            }
        }
    }
}
