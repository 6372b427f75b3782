//! `brine sun | moon`: apparent positions of the Sun and the Moon for a place and a UTC instant
//! (brine-ephem).

use brine_ephem::{Atmosphere, Observer, Options, SunModel, moon_position, parse_utc, sun_position};

use super::CliError;

/// Place, time and refraction, shared by `brine sun` and `brine moon`.
#[derive(Debug, Clone, clap::Args)]
pub struct PlaceArgs {
    /// Latitude (degrees, north positive), [-90, 90].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub lat: f64,
    /// Longitude (degrees, east positive), [-180, 360].
    #[arg(long, allow_hyphen_values = true, value_parser = super::finite)]
    pub lon: f64,
    /// UTC instant, ISO 8601 with an offset (e.g. 2024-06-21T12:00:00Z).
    #[arg(long)]
    pub time: String,
    /// Height above the WGS84 ellipsoid (m).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub height_m: f64,
    /// Add atmospheric refraction to the altitude (apparent instead of airless altitude).
    #[arg(long)]
    pub refraction: bool,
    /// Air pressure for the refraction (hPa).
    #[arg(long, default_value_t = 1013.25, value_parser = super::finite)]
    pub pressure_hpa: f64,
    /// Air temperature for the refraction (°C).
    #[arg(long, default_value_t = 15.0, allow_hyphen_values = true, value_parser = super::finite)]
    pub temperature_c: f64,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

impl PlaceArgs {
    /// The instant, the observer and the options these arguments name (the Python bindings
    /// read the place and the options from here, and the instants from their arrays).
    ///
    /// # Errors
    /// [`CliError::Input`] for a bad place, time or refraction setting.
    pub fn resolve(&self) -> Result<(brine_ephem::Timestamp, Observer, Options), CliError> {
        let input = |e: brine_ephem::EphemError| CliError::Input(e.to_string());
        let t = parse_utc(&self.time).map_err(input)?;
        let o = Observer::from_degrees(self.lat, self.lon, self.height_m).map_err(input)?;
        let refraction = if self.refraction {
            Some(Atmosphere::new(self.pressure_hpa, self.temperature_c).map_err(input)?)
        } else {
            None
        };
        Ok((t, o, Options { refraction, delta_t_s: None }))
    }
}

/// Sun position model on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SunModelArg {
    /// NREL SPA (±0.0003°).
    Spa,
    /// Schlyter's orbital elements (≈ 0.01°).
    Schlyter,
}

impl SunModelArg {
    /// The brine-ephem model.
    pub fn model(self) -> SunModel {
        match self {
            SunModelArg::Spa => SunModel::Spa,
            SunModelArg::Schlyter => SunModel::Schlyter,
        }
    }
}

/// Arguments of `brine sun`.
#[derive(Debug, Clone, clap::Args)]
pub struct SunArgs {
    /// Place and time.
    #[command(flatten)]
    pub place: PlaceArgs,
    /// Position model.
    #[arg(long, value_enum, default_value_t = SunModelArg::Spa)]
    pub model: SunModelArg,
}

/// Runs `brine sun`: prints altitude, azimuth (degrees) and distance (AU).
///
/// # Errors
/// [`CliError::Input`] for a bad place, time or refraction setting.
pub fn run_sun(args: &SunArgs) -> Result<(), CliError> {
    let (t, o, opts) = args.place.resolve()?;
    let model = args.model.model();
    let p = sun_position(t, &o, model, &opts).map_err(|e| CliError::Input(e.to_string()))?;
    let (alt, az) = (p.altitude.to_degrees(), p.azimuth.to_degrees());
    if args.place.json {
        let v = serde_json::json!({ "altitude_deg": alt, "azimuth_deg": az, "distance_au": p.distance_au });
        super::outln!("{v}");
    } else {
        super::outln!("sun altitude {alt:.4}°  azimuth {az:.4}°  distance {:.6} AU", p.distance_au);
    }
    Ok(())
}

/// Arguments of `brine moon`.
#[derive(Debug, Clone, clap::Args)]
pub struct MoonArgs {
    /// Place and time.
    #[command(flatten)]
    pub place: PlaceArgs,
}

/// Runs `brine moon`: prints the topocentric altitude and azimuth (degrees), the geocentric
/// distance (km), the phase angle (degrees) and the illuminated fraction.
///
/// # Errors
/// [`CliError::Input`] for a bad place, time or refraction setting.
pub fn run_moon(args: &MoonArgs) -> Result<(), CliError> {
    let (t, o, opts) = args.place.resolve()?;
    let p = moon_position(t, &o, &opts).map_err(|e| CliError::Input(e.to_string()))?;
    let (alt, az, phase) = (p.altitude.to_degrees(), p.azimuth.to_degrees(), p.phase_angle.to_degrees());
    if args.place.json {
        let v = serde_json::json!({
            "altitude_deg": alt,
            "azimuth_deg": az,
            "distance_km": p.distance_km,
            "phase_angle_deg": phase,
            "illuminated_fraction": p.illuminated_fraction,
        });
        super::outln!("{v}");
    } else {
        super::outln!(
            "moon altitude {alt:.3}°  azimuth {az:.3}°  distance {:.0} km  phase angle {phase:.2}°  illuminated {:.3}",
            p.distance_km,
            p.illuminated_fraction
        );
    }
    Ok(())
}
