//! `brine sky`: sky radiance for a view direction (JSON), or a fisheye sky-dome image (brine-sky).

use std::path::PathBuf;

use brine_sky::{
    CloudParams, DaylightModel, MoonParams, Sky, SkyParams, chromaticity, daylight_locus_y, fisheye_pixel_direction,
    linear_srgb_to_xyz,
};
use glam::{DVec2, DVec3};

use super::CliError;
use crate::write_image;

/// Arguments of `brine sky`.
#[derive(Debug, Clone, clap::Args)]
pub struct SkyArgs {
    /// Turbidity T, [1.7, 10].
    #[arg(long, default_value_t = 3.0, value_parser = super::within(1.7, 10.0))]
    pub turbidity: f64,
    /// Clear daylight sky: Preetham et al. 1999 or Hosek & Wilkie 2012.
    #[arg(long, value_enum, default_value_t = ModelArg::Preetham)]
    pub model: ModelArg,
    /// Sun elevation (degrees), [-90, 90].
    #[arg(long, allow_hyphen_values = true, value_parser = super::within(-90.0, 90.0))]
    pub sun_elevation_deg: f64,
    /// Sun azimuth, compass bearing from north through east (degrees).
    #[arg(long, default_value_t = 180.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub sun_azimuth_deg: f64,
    /// Moon elevation (degrees), [-90, 90]; with --moon-azimuth-deg adds the Moon.
    #[arg(long, allow_hyphen_values = true, requires = "moon_azimuth_deg", value_parser = super::within(-90.0, 90.0))]
    pub moon_elevation_deg: Option<f64>,
    /// Moon azimuth (degrees from north through east).
    #[arg(long, allow_hyphen_values = true, requires = "moon_elevation_deg", value_parser = super::finite)]
    pub moon_azimuth_deg: Option<f64>,
    /// Moon phase angle (degrees, 0 = full), [0, 180].
    #[arg(long, default_value_t = 0.0, value_parser = super::within(0.0, 180.0))]
    pub moon_phase_deg: f64,
    /// Moon distance (km), [300 000, 420 000] (perigee 356 400, apogee 406 700).
    #[arg(long, default_value_t = 384_400.0, value_parser = super::within(3.0e5, 4.2e5))]
    pub moon_distance_km: f64,
    /// Cloud cover, [0, 1]; 0 (default) is a clear sky.
    #[arg(long, default_value_t = 0.0, value_parser = super::within(0.0, 1.0))]
    pub clouds: f64,
    /// Cloud seed.
    #[arg(long, default_value_t = 1)]
    pub cloud_seed: u64,
    /// Time (s, [-1e9, 1e9]) at which the clouds are drawn.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = super::within(-1e9, 1e9))]
    pub time_s: f64,
    /// View elevation (degrees) for --json, [-90, 90].
    #[arg(long, default_value_t = 90.0, allow_hyphen_values = true, value_parser = super::within(-90.0, 90.0))]
    pub view_elevation_deg: f64,
    /// View azimuth (degrees from north through east) for --json.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub view_azimuth_deg: f64,
    /// Print the radiance toward the view direction as JSON (XYZ and linear sRGB, kcd/m²), with
    /// the sun's, the sky's and their sum's irradiance (klx) and the offsets of the view's and
    /// the sum's chromaticity below the CIE daylight locus.
    #[arg(long)]
    pub json: bool,
    /// Write a fisheye image of the dome (.png or .exr): zenith at the centre, north up, east to
    /// the left (the sky seen from below), horizon on the circle.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Image size in pixels (square).
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=8192))]
    pub size: u32,
    /// Exposure EV, [-10, 30] (1.2·2^EV cd/m² maps to white); default: the zenith at mid-grey.
    #[arg(long, allow_hyphen_values = true, value_parser = super::within(-10.0, 30.0))]
    pub exposure_ev: Option<f64>,
}

/// `y_D(x) − y` for the chromaticity of `xyz`: how far below the CIE daylight locus it lies
/// (positive toward magenta), `None` for black.
fn daylight_locus_offset(xyz: DVec3) -> Option<f64> {
    chromaticity(xyz).map(|(x, y)| daylight_locus_y(x) - y)
}

/// `--model` of `brine sky`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ModelArg {
    /// Preetham, Shirley & Smits 1999.
    Preetham,
    /// Hosek & Wilkie 2012.
    HosekWilkie,
}

/// Unit vector of a compass bearing and an elevation, in degrees (y up, x east, z south).
pub fn direction(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
    DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos())
}

/// The sky `args` describe (sun, moon, clouds, model).
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range.
pub fn sky_of(args: &SkyArgs) -> Result<Sky, CliError> {
    let moon = match (args.moon_elevation_deg, args.moon_azimuth_deg) {
        (Some(e), Some(a)) => Some(MoonParams {
            direction: direction(e, a),
            phase_angle: args.moon_phase_deg.to_radians(),
            distance_km: args.moon_distance_km,
        }),
        _ => None,
    };
    let clouds = (args.clouds > 0.0).then(|| CloudParams {
        cover: args.clouds,
        seed: args.cloud_seed,
        wind_m_s: DVec2::new(8.0, 0.0),
        ..CloudParams::default()
    });
    let params = SkyParams {
        moon,
        clouds,
        time_s: args.time_s,
        model: match args.model {
            ModelArg::Preetham => DaylightModel::Preetham,
            ModelArg::HosekWilkie => DaylightModel::HosekWilkie,
        },
        ..SkyParams::new(args.turbidity, direction(args.sun_elevation_deg, args.sun_azimuth_deg))
    };
    Sky::new(&params).map_err(|e| CliError::Input(e.to_string()))
}

/// Runs `brine sky`.
///
/// # Errors
/// [`CliError::Input`] for a parameter out of range or a missing output; [`CliError::Failure`]
/// if the image cannot be written.
pub fn run_sky(args: &SkyArgs) -> Result<(), CliError> {
    let input = |m: String| CliError::Input(m);
    if !args.json && args.out.is_none() {
        return Err(input("nothing to do: give --json and/or --out FILE".to_string()));
    }
    if let Some(path) = &args.out {
        crate::output::OutputFormat::from_path(path).map_err(|m| input(m.replacen("output.path", "--out", 1)))?;
        crate::output::check_writable(path).map_err(|m| input(format!("--out: {m}")))?;
        // An interrupted run leaves no temporary file behind.
        crate::output::remove_temporaries_on_signal().map_err(CliError::Failure)?;
    }
    let sky = sky_of(args)?;

    if args.json {
        let v = direction(args.view_elevation_deg, args.view_azimuth_deg);
        let rgb = sky.radiance_rgb(v);
        let xyz = sky.radiance_xyz(v);
        let sun = sky.sun();
        // What lights a horizontal white surface: the sun on the plane and the sky's irradiance.
        let global = sky.horizontal_irradiance_rgb() + sun.irradiance_rgb * sun.direction.y.max(0.0);
        let mut out = serde_json::json!({
            "view_elevation_deg": args.view_elevation_deg,
            "view_azimuth_deg": args.view_azimuth_deg,
            "xyz_kcd_m2": xyz.to_array(),
            "chromaticity_xy": chromaticity(xyz).map(|(x, y)| [x, y]),
            "below_daylight_locus": daylight_locus_offset(xyz),
            "rgb_kcd_m2": rgb.to_array(),
            "sun_radiance_rgb_kcd_m2": sun.radiance_rgb.to_array(),
            "sun_irradiance_rgb_klx": sun.irradiance_rgb.to_array(),
            "sky_horizontal_irradiance_rgb_klx": sky.horizontal_irradiance_rgb().to_array(),
            "global_horizontal_irradiance_rgb_klx": global.to_array(),
            "global_below_daylight_locus": daylight_locus_offset(linear_srgb_to_xyz(global)),
        });
        if let Some(m) = sky.moon() {
            out["moon_irradiance_rgb_klx"] = serde_json::json!(m.irradiance_rgb.to_array());
        }
        super::outln!("{out}");
    }
    if let Some(path) = &args.out {
        let n = args.size;
        let mut pixels = vec![DVec3::ZERO; (n * n) as usize];
        for j in 0..n {
            for i in 0..n {
                if let Some(v) = fisheye_pixel_direction(i, j, n) {
                    pixels[(j * n + i) as usize] = sky.background_rgb(v);
                }
            }
        }
        let ev = args.exposure_ev.unwrap_or_else(|| {
            let zenith_cd = sky.radiance_xyz(DVec3::Y).y.max(1e-12) * 1000.0;
            (2.0 * zenith_cd / 1.2).log2()
        });
        write_image(path, n, n, &pixels, ev).map_err(|e| match e {
            crate::OutputError::Format(m) => CliError::Input(m.replacen("output.path", "--out", 1)),
            other => CliError::Failure(other.to_string()),
        })?;
        eprintln!("wrote {} ({n}×{n}, EV {ev:.2})", path.display());
    }
    Ok(())
}
