//! `brine optics fresnel …`, `brine optics rough …` and `brine optics water …`: queries of the
//! brine-optics models.

use brine_optics::{
    JerlovType, LAMBDA_MAX_NM, LAMBDA_MIN_NM, RoughReflectance, WATER_IOR, WaterBody, check_wavelength, critical_angle,
    fresnel_dielectric, fresnel_schlick, reflectance_split_uncorrelated, water_reflectance_split,
};
use clap::Subcommand;
use serde::Serialize;

use super::CliError;

/// Arguments of `brine optics`.
#[derive(Debug, clap::Args)]
pub struct OpticsArgs {
    /// The query.
    #[command(subcommand)]
    pub command: OpticsCommand,
}

/// The `brine optics` queries.
#[derive(Debug, Subcommand)]
pub enum OpticsCommand {
    /// Exact unpolarised Fresnel reflectance of a dielectric interface (and Schlick's value).
    Fresnel(FresnelArgs),
    /// The reflectance of a rough sea toward a viewer: the sky's share and the visible facets'
    /// whole Fresnel reflectance (the rest reflected into the neighbouring waves).
    Rough(RoughArgs),
    /// Inherent optical properties of sea water (m⁻¹) by wavelength, for a Jerlov type or a
    /// chlorophyll concentration.
    Water(WaterArgs),
}

/// Arguments of `brine optics fresnel`.
#[derive(Debug, Clone, clap::Args)]
pub struct FresnelArgs {
    /// Index of the medium the light comes from (1.0 for air).
    #[arg(long, value_parser = super::finite)]
    pub n1: f64,
    /// Index of the medium across the interface (1.333 for water).
    #[arg(long, value_parser = super::finite)]
    pub n2: f64,
    /// Cosine of the angle of incidence, [0, 1].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub cos_theta: f64,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// Arguments of `brine optics rough`.
#[derive(Debug, Clone, clap::Args)]
pub struct RoughArgs {
    /// Cosine of the view's angle to the mean normal, [0.001, 1].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub cos_theta: f64,
    /// Slope deviation of the facets per axis (isotropic Gaussian slopes), [1e-6, 0.6].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub sigma: f64,
    /// Index of water, (1, 2].
    #[arg(long, default_value_t = WATER_IOR, allow_hyphen_values = true, value_parser = super::finite)]
    pub n_water: f64,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// The answer of `brine optics rough`.
#[derive(Debug, Serialize)]
pub struct RoughOut {
    /// Cosine of the view's angle to the mean normal.
    pub cos_theta: f64,
    /// Slope deviation per axis.
    pub sigma: f64,
    /// Index of water.
    pub n_water: f64,
    /// `R`: the sky's share (reflected above the horizon, not shadowed).
    pub sky: f64,
    /// `R_seen`: the visible facets' Fresnel reflectance.
    pub seen: f64,
    /// `R_seen − R`: reflected into the neighbouring waves.
    pub into_waves: f64,
    /// `μ_r`: the mean cosine of the seen facets' mirror directions to the mean normal.
    pub mirror_cosine: f64,
    /// `R` with Smith's uncorrelated visibility (every facing slope as likely seen).
    pub smith_sky: f64,
    /// `R_seen` with Smith's uncorrelated visibility.
    pub smith_seen: f64,
    /// The smooth surface's Fresnel reflectance at the same angle.
    pub fresnel: f64,
    /// `R` as the renderer reads it from its table (sea water's index only; else null).
    pub table_sky: Option<f64>,
}

/// The rough-reflectance answer for `a`, its arguments checked.
///
/// # Errors
/// [`CliError::Input`] for an argument out of range.
pub fn rough_of(a: &RoughArgs) -> Result<RoughOut, CliError> {
    // The quadrature's tested domain: to 89.94° from the normal (its error is measured to 89.9°;
    // nearer grazing the facets' projected areas divide by a vanishing cosine), and slopes whose
    // variance does not underflow (below σ = 10⁻⁶ the answer is Fresnel's to 10⁻¹²).
    if !(a.cos_theta >= 1e-3 && a.cos_theta <= 1.0) {
        return Err(CliError::Input(format!(
            "--cos-theta = {} is out of range: expected [0.001, 1]",
            super::num(a.cos_theta)
        )));
    }
    if !(a.sigma >= 1e-6 && a.sigma <= RoughReflectance::MAX_SIGMA) {
        return Err(CliError::Input(format!(
            "--sigma = {} is out of range: expected [1e-6, 0.6]",
            super::num(a.sigma)
        )));
    }
    if !(a.n_water > 1.0 && a.n_water <= 2.0) {
        return Err(CliError::Input(format!("--n-water = {} is out of range: expected (1, 2]", a.n_water)));
    }
    let split = water_reflectance_split(a.cos_theta, a.sigma, a.n_water);
    let smith = reflectance_split_uncorrelated(a.cos_theta, a.sigma, |c| fresnel_dielectric(c, 1.0, a.n_water));
    let table_sky = (a.n_water == WATER_IOR).then(|| RoughReflectance::water().reflectance(a.cos_theta, a.sigma));
    Ok(RoughOut {
        cos_theta: a.cos_theta,
        sigma: a.sigma,
        n_water: a.n_water,
        sky: split.to_sky,
        seen: split.seen,
        into_waves: split.seen - split.to_sky,
        mirror_cosine: split.mirror_cosine,
        smith_sky: smith.to_sky,
        smith_seen: smith.seen,
        fresnel: fresnel_dielectric(a.cos_theta, 1.0, a.n_water),
        table_sky,
    })
}

fn run_rough(a: &RoughArgs) -> Result<(), CliError> {
    let out = rough_of(a)?;
    if a.json {
        print_json(&out)
    } else {
        super::outln!(
            "sky {:.6}  seen {:.6}  into the waves {:.6}  (smooth Fresnel {:.6})",
            out.sky,
            out.seen,
            out.into_waves,
            out.fresnel
        );
        super::outln!(
            "mean mirror direction {:.2}° above the mean plane (the mirror's {:.2}°); Smith's visibility: sky {:.6}  seen {:.6}",
            out.mirror_cosine.clamp(-1.0, 1.0).asin().to_degrees(),
            a.cos_theta.asin().to_degrees(),
            out.smith_sky,
            out.smith_seen
        );
        Ok(())
    }
}

/// Arguments of `brine optics water`.
#[derive(Debug, clap::Args)]
#[command(group(clap::ArgGroup::new("water").required(true).args(["water_type", "chlorophyll_mg_m3"])))]
pub struct WaterArgs {
    /// Jerlov water type: I, IA, IB, II, III, 1C, 3C, 5C, 7C or 9C.
    #[arg(long = "type")]
    pub water_type: Option<String>,
    /// Chlorophyll-a concentration of Case-1 water (mg m⁻³), [0, 100].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub chlorophyll_mg_m3: Option<f64>,
    /// Wavelengths (nm) in [400, 700]: one value, a list `450,550,650` or a range `start:stop:step`.
    #[arg(long, default_value = "400:700:10", allow_hyphen_values = true)]
    pub wavelength_nm: String,
    /// Print JSON.
    #[arg(long)]
    pub json: bool,
}

/// The answer of `brine optics fresnel`.
#[derive(Debug, Serialize)]
pub struct FresnelOut {
    /// Refractive index of the incident medium.
    pub n1: f64,
    /// Refractive index of the transmitting medium.
    pub n2: f64,
    /// Cosine of the angle of incidence.
    pub cos_theta: f64,
    /// Unpolarised Fresnel reflectance.
    pub reflectance: f64,
    /// `1 − reflectance`.
    pub transmittance: f64,
    /// Schlick's approximation of the reflectance.
    pub schlick: f64,
    /// Whether the incidence is beyond the critical angle.
    pub total_internal_reflection: bool,
}

#[derive(Debug, Serialize)]
struct WaterOut {
    water: String,
    chlorophyll_mg_m3: f64,
    iop_source: String,
    kd_source: String,
    wavelength_nm: Vec<f64>,
    absorption: Vec<f64>,
    scattering: Vec<f64>,
    backscattering: Vec<f64>,
    attenuation: Vec<f64>,
    kd: Vec<f64>,
}

fn input<E: std::fmt::Display>(e: E) -> CliError {
    CliError::Input(e.to_string())
}

fn print_json<T: Serialize>(value: &T) -> Result<(), CliError> {
    let text = serde_json::to_string_pretty(value).map_err(|e| CliError::Failure(e.to_string()))?;
    super::outln!("{text}");
    Ok(())
}

/// Runs `brine optics`.
///
/// # Errors
/// [`CliError::Input`] for parameters out of range or malformed.
pub fn run_optics(args: &OpticsArgs) -> Result<(), CliError> {
    match &args.command {
        OpticsCommand::Fresnel(a) => run_fresnel(a),
        OpticsCommand::Rough(a) => run_rough(a),
        OpticsCommand::Water(a) => run_water(a),
    }
}

/// The Fresnel answer for `a`, its indices and angle checked.
///
/// # Errors
/// [`CliError::Input`] for an index or a cosine out of range.
pub fn fresnel_of(a: &FresnelArgs) -> Result<FresnelOut, CliError> {
    for (name, n) in [("--n1", a.n1), ("--n2", a.n2)] {
        if !(n.is_finite() && (0.1..=10.0).contains(&n)) {
            return Err(CliError::Input(format!("{name} = {n} is out of range: expected [0.1, 10]")));
        }
    }
    if !(0.0..=1.0).contains(&a.cos_theta) {
        return Err(CliError::Input(format!("--cos-theta = {} is out of range: expected [0, 1]", a.cos_theta)));
    }
    let reflectance = fresnel_dielectric(a.cos_theta, a.n1, a.n2);
    let tir = critical_angle(a.n1, a.n2).is_some_and(|theta_c| a.cos_theta.acos() > theta_c);
    let out = FresnelOut {
        n1: a.n1,
        n2: a.n2,
        cos_theta: a.cos_theta,
        reflectance,
        transmittance: 1.0 - reflectance,
        schlick: fresnel_schlick(a.cos_theta, a.n1, a.n2),
        total_internal_reflection: tir,
    };
    Ok(out)
}

fn run_fresnel(a: &FresnelArgs) -> Result<(), CliError> {
    let out = fresnel_of(a)?;
    let tir = out.total_internal_reflection;
    if a.json {
        print_json(&out)
    } else {
        super::outln!(
            "reflectance {:.6}  transmittance {:.6}  Schlick {:.6}{}",
            out.reflectance,
            out.transmittance,
            out.schlick,
            if tir { "  (total internal reflection)" } else { "" }
        );
        Ok(())
    }
}

/// Parses `550`, `450,550,650` or `400:700:10` into wavelengths, each checked against the model.
fn parse_wavelengths(spec: &str) -> Result<Vec<f64>, CliError> {
    let bad = || {
        CliError::Input(format!(
            "--wavelength-nm = {spec:?} is malformed: expected a value, a list like 450,550,650 or a range start:stop:step"
        ))
    };
    let num = |s: &str| s.trim().parse::<f64>().map_err(|_| bad());
    let values = if spec.contains(':') {
        let parts: Vec<&str> = spec.split(':').collect();
        if parts.len() != 3 {
            return Err(bad());
        }
        let (start, stop, step) = (num(parts[0])?, num(parts[1])?, num(parts[2])?);
        if !(step > 0.0 && step.is_finite()) || stop < start {
            return Err(CliError::Input(format!(
                "--wavelength-nm = {spec:?}: the range needs start <= stop and a step > 0"
            )));
        }
        let count = ((stop - start) / step + 1e-9).floor() as usize + 1;
        if count > 10_000 {
            return Err(CliError::Input(format!(
                "--wavelength-nm = {spec:?} asks for {count} wavelengths (at most 10000)"
            )));
        }
        (0..count).map(|i| start + step * i as f64).collect()
    } else {
        spec.split(',').map(num).collect::<Result<Vec<_>, _>>()?
    };
    for &l in &values {
        check_wavelength(l).map_err(|_| {
            CliError::Input(format!(
                "--wavelength-nm: {l} is out of range: expected [{LAMBDA_MIN_NM}, {LAMBDA_MAX_NM}] nm"
            ))
        })?;
    }
    Ok(values)
}

/// The water body `a` names, and its name.
///
/// # Errors
/// [`CliError::Input`] for an unknown type, a concentration out of range, or neither or both.
pub fn water_body(a: &WaterArgs) -> Result<(WaterBody, String), CliError> {
    Ok(match (&a.water_type, a.chlorophyll_mg_m3) {
        (Some(t), None) => {
            let t: JerlovType = t.parse().map_err(|e: brine_optics::OpticsError| {
                CliError::Input(e.to_string().replacen("jerlov_type", "--type", 1))
            })?;
            (WaterBody::jerlov(t), format!("Jerlov {t}"))
        }
        (None, Some(c)) => (WaterBody::case1(c).map_err(input)?, format!("Case-1, C = {c} mg/m3")),
        _ => return Err(CliError::Input("give exactly one of --type and --chlorophyll-mg-m3".to_owned())),
    })
}

fn run_water(a: &WaterArgs) -> Result<(), CliError> {
    let (body, name) = water_body(a)?;
    let wavelength_nm = parse_wavelengths(&a.wavelength_nm)?;
    let iops: Vec<_> = wavelength_nm.iter().map(|&l| body.iops(l)).collect();
    let out = WaterOut {
        water: name,
        chlorophyll_mg_m3: body.chlorophyll_mg_m3(),
        iop_source: body.iop_source(),
        kd_source: body.kd_source(),
        absorption: iops.iter().map(|i| i.a).collect(),
        scattering: iops.iter().map(|i| i.b).collect(),
        backscattering: iops.iter().map(|i| i.b_b).collect(),
        attenuation: iops.iter().map(|i| i.c).collect(),
        kd: iops.iter().map(|i| i.k_d).collect(),
        wavelength_nm,
    };
    if a.json {
        print_json(&out)
    } else {
        super::outln!("{} ({}; K_d: {})", out.water, out.iop_source, out.kd_source);
        super::outln!("{:>8} {:>10} {:>10} {:>10} {:>10} {:>10}", "nm", "a", "b", "b_b", "c", "K_d");
        for (l, i) in out.wavelength_nm.iter().zip(&iops) {
            super::outln!("{l:>8.1} {:>10.5} {:>10.5} {:>10.6} {:>10.5} {:>10.5}", i.a, i.b, i.b_b, i.c, i.k_d);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wavelength_specs() {
        assert_eq!(parse_wavelengths("400:700:10").unwrap().len(), 31);
        assert_eq!(parse_wavelengths("450, 550,650").unwrap(), vec![450.0, 550.0, 650.0]);
        assert_eq!(parse_wavelengths("550").unwrap(), vec![550.0]);
        for bad in ["300:400:10", "400:700", "400:700:0", "x", "700:400:10", "400:700:1e-9"] {
            assert!(matches!(parse_wavelengths(bad), Err(CliError::Input(_))), "{bad}");
        }
    }

    #[test]
    fn bad_fresnel_input_is_an_input_error() {
        let args = FresnelArgs { n1: 1.0, n2: 1.333, cos_theta: 1.5, json: true };
        assert!(matches!(run_fresnel(&args), Err(CliError::Input(_))));
        let args = FresnelArgs { n1: f64::NAN, n2: 1.333, cos_theta: 0.5, json: true };
        assert!(matches!(run_fresnel(&args), Err(CliError::Input(_))));
    }

    /// `brine optics rough` refuses each argument out of range by name, and at sea water's index
    /// its table agrees with its integral (the table is bilinear: within 0.03 of it, see
    /// brine-optics `RoughReflectance`).
    #[test]
    fn rough_names_its_bad_arguments_and_reads_the_table() {
        const BILINEAR_GRAZING: f64 = 0.03;
        let ok = RoughArgs { cos_theta: 0.1, sigma: 0.2, n_water: WATER_IOR, json: true };
        for (bad, name) in [
            (RoughArgs { cos_theta: 0.0, ..ok.clone() }, "--cos-theta"),
            // Where the quadrature's projected areas overflowed (a reflectance of 10²⁹³)...
            (RoughArgs { cos_theta: 1e-300, ..ok.clone() }, "--cos-theta"),
            (RoughArgs { sigma: 0.7, ..ok.clone() }, "--sigma"),
            // ...and where the slope variance underflowed (NaN).
            (RoughArgs { sigma: 1e-300, ..ok.clone() }, "--sigma"),
            (RoughArgs { n_water: 2.5, ..ok.clone() }, "--n-water"),
        ] {
            match rough_of(&bad) {
                Err(CliError::Input(m)) => assert!(m.contains(name), "{m}"),
                other => panic!("{name}: {other:?}"),
            }
        }
        // At the domain's edges the answers are reflectances.
        for (cos_theta, sigma) in [(1e-3, 0.2), (1e-3, 1e-6), (1.0, 1e-6), (0.5, 0.6)] {
            let out = rough_of(&RoughArgs { cos_theta, sigma, ..ok.clone() }).unwrap();
            assert!(out.sky >= 0.0 && out.sky <= out.seen && out.seen <= 1.0, "{out:?}");
        }
        let out = rough_of(&ok).unwrap();
        assert!(out.sky > 0.0 && out.sky <= out.seen && out.seen < out.fresnel, "{out:?}");
        assert!((out.table_sky.unwrap() - out.sky).abs() < BILINEAR_GRAZING, "{out:?}");
        assert!(rough_of(&RoughArgs { n_water: 1.34, ..ok }).unwrap().table_sky.is_none());
    }
}
