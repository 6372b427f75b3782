//! The Sun's apparent position: NREL SPA (default) or Schlyter's elements.

use jiff::Timestamp;
use solar_positioning::{Location, SolarPositions, delta_t, time::JulianDate};

use crate::coords::{Horizontal, spherical, topocentric};
use crate::observer::EARTH_EQUATORIAL_RADIUS_KM;
use crate::schlyter::{equatorial_vector, local_sidereal_time, sun_orbit};
use crate::time::{check_range, decimal_year, julian_date, schlyter_day, ut_hours};
use crate::{Atmosphere, EphemError, Observer};

/// The astronomical unit (km), IAU 2012.
pub const AU_KM: f64 = brine_core::AU_KM;

/// Which model computes the Sun's position.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SunModel {
    /// NREL's Solar Position Algorithm (Reda & Andreas 2004, ±0.0003° over −2000..6000) through
    /// the `solar-positioning` crate: nutation, aberration, topocentric parallax. The default.
    #[default]
    Spa,
    /// Schlyter's orbital elements (mean equinox of date; no nutation or aberration), with the
    /// topocentric parallax: about 0.01° (measured, see the crate docs).
    Schlyter,
}

/// Options of the position computations.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Options {
    /// Air for the refraction; `None` gives the airless (true) altitude.
    pub refraction: Option<Atmosphere>,
    /// ΔT = TT − UT1 (s) for SPA; `None` uses the Espenak–Meeus estimate of `solar-positioning`.
    pub delta_t_s: Option<f64>,
}

/// The Sun as seen by the observer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunPosition {
    /// Topocentric altitude (rad), apparent when refraction was requested.
    pub altitude: f64,
    /// Azimuth from north through east (rad), `[0, 2π)`.
    pub azimuth: f64,
    /// Earth–Sun distance (AU), from Schlyter's elements in both models (≈ 10⁻⁴ AU).
    pub distance_au: f64,
}

impl SunPosition {
    /// Altitude and azimuth as a [`Horizontal`].
    pub fn horizontal(&self) -> Horizontal {
        Horizontal { altitude: self.altitude, azimuth: self.azimuth }
    }
}

/// The apparent topocentric position of the Sun at `t` for `observer`.
///
/// SPA: Reda & Andreas 2004 steps 1–3.14 via `solar-positioning` (JD from the UTC instant, ΔT
/// from [`Options::delta_t_s`] or estimated). Schlyter: [`sun_orbit`] → equatorial of date →
/// observer (parallax) → hour angle `H = LST − α` → altitude, azimuth. Then, if asked,
/// [`Atmosphere::refraction`] is added to the altitude (the same formula for both models).
///
/// # Arguments
/// - `t`: UTC instant (taken as UT1), 1800..2200.
/// - `observer`: the place.
/// - `model`: [`SunModel`].
/// - `options`: refraction and ΔT.
///
/// # Returns
/// The [`SunPosition`] (radians; distance in AU).
///
/// # Errors
/// [`EphemError::Time`] outside 1800..2200, [`EphemError::OutOfRange`] for a non-finite ΔT.
///
/// # References
/// Reda I., Andreas A. 2004, "Solar position algorithm for solar radiation applications",
/// Solar Energy 76(5):577–589; Schlyter, "How to compute planetary positions" §4–5, §12.
pub fn sun_position(
    t: Timestamp,
    observer: &Observer,
    model: SunModel,
    options: &Options,
) -> Result<SunPosition, EphemError> {
    check_range(t)?;
    let d = schlyter_day(t);
    let orbit = sun_orbit(d);
    let mut h = match model {
        SunModel::Spa => spa(t, observer, options)?,
        SunModel::Schlyter => {
            let r = orbit.distance_au * AU_KM / EARTH_EQUATORIAL_RADIUS_KM;
            let geo = equatorial_vector(orbit.longitude, 0.0, r, d);
            let lst = local_sidereal_time(d, ut_hours(t), observer.longitude());
            let (ra, dec, _) = spherical(topocentric(geo, lst, observer));
            Horizontal::from_equatorial(lst - ra, dec, observer.latitude())
        }
    };
    if let Some(air) = options.refraction {
        // Refraction vanishes at the zenith: the `min` absorbs rounding only.
        debug_assert!(h.altitude + air.refraction(h.altitude) <= std::f64::consts::FRAC_PI_2 + 1e-9);
        h.altitude = (h.altitude + air.refraction(h.altitude)).min(std::f64::consts::FRAC_PI_2);
    }
    Ok(SunPosition { altitude: h.altitude, azimuth: h.azimuth, distance_au: orbit.distance_au })
}

/// The airless SPA position.
fn spa(t: Timestamp, observer: &Observer, options: &Options) -> Result<Horizontal, EphemError> {
    let time_error = |e: solar_positioning::Error| EphemError::Time { input: t.to_string(), message: e.to_string() };
    let dt = match options.delta_t_s {
        Some(v) => crate::error::check("delta_t_s", v, v.abs() < 1.0e4, "(-10000, 10000) s")?,
        None => delta_t::estimate(decimal_year(t)).map_err(time_error)?,
    };
    let jd = JulianDate::new(julian_date(t), dt).map_err(time_error)?;
    let mut lon = observer.longitude().to_degrees();
    if lon > 180.0 {
        lon -= 360.0;
    }
    let location = Location { latitude: observer.latitude().to_degrees(), longitude: lon };
    let p = SolarPositions::new().at_from_julian(jd, location, observer.height_m(), None).map_err(time_error)?;
    Ok(Horizontal { altitude: p.elevation_angle().to_radians(), azimuth: p.azimuth().to_radians() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse_utc;

    #[test]
    fn nrel_spa_published_example() {
        // Reda & Andreas 2004, Table A5.1: 2003-10-17 12:30:30 local (UTC−7), 39.742476° N,
        // 105.1786° W, 1830.14 m, 820 hPa, 11 °C, ΔT = 67 s: topocentric zenith 50.11162°,
        // azimuth 194.34024°. Tolerance: half a unit of the 5th printed decimal.
        const HALF_5DP: f64 = 5e-6;
        let t = parse_utc("2003-10-17T12:30:30-07:00").unwrap();
        let o = Observer::from_degrees(39.742476, -105.1786, 1830.14).unwrap();
        let opts = Options { refraction: Some(Atmosphere::new(820.0, 11.0).unwrap()), delta_t_s: Some(67.0) };
        let p = sun_position(t, &o, SunModel::Spa, &opts).unwrap();
        assert!((90.0 - p.altitude.to_degrees() - 50.11162).abs() < HALF_5DP, "{}", 90.0 - p.altitude.to_degrees());
        assert!((p.azimuth.to_degrees() - 194.34024).abs() < HALF_5DP, "{}", p.azimuth.to_degrees());
    }

    #[test]
    fn schlyter_worked_example_alt_az() {
        // Schlyter's tutorial §6: 1990-04-19 0h UT at 60° N, 15° E: Sun azimuth 15.6767°,
        // altitude −17.9570° (geocentric; 4 printed decimals). Ours is topocentric: the solar
        // parallax, 8.794″/r = 0.00243°, lowers the altitude by up to that much (by 8.794″ cos h).
        const HALF_4DP: f64 = 5e-5;
        const SOLAR_PARALLAX_DEG: f64 = 8.794 / 3600.0 / 1.004323;
        let t = parse_utc("1990-04-19T00:00:00Z").unwrap();
        let o = Observer::from_degrees(60.0, 15.0, 0.0).unwrap();
        let p = sun_position(t, &o, SunModel::Schlyter, &Options::default()).unwrap();
        let lowered = -17.9570 - SOLAR_PARALLAX_DEG * 17.9570f64.to_radians().cos();
        assert!((p.altitude.to_degrees() - lowered).abs() < HALF_4DP, "{}", p.altitude.to_degrees());
        assert!((p.azimuth.to_degrees() - 15.6767).abs() < HALF_4DP, "{}", p.azimuth.to_degrees());
    }

    #[test]
    fn greenwich_noon_of_j2000() {
        // Reference value (docs/equations.md): 2000-01-01 12h UT at 0° N 0° E: altitude 66.95°, azimuth 178.06°
        // (2 printed decimals). Tolerances: half a unit, plus for the azimuth the Schlyter Sun's
        // 0.01° error seen 23° from the zenith (0.01°/sin 23° = 0.026°).
        const ALTITUDE_DEG: f64 = 0.005 + 0.005;
        const AZIMUTH_DEG: f64 = 0.005 + 0.026;
        let t = parse_utc("2000-01-01T12:00:00Z").unwrap();
        let o = Observer::from_degrees(0.0, 0.0, 0.0).unwrap();
        for model in [SunModel::Schlyter, SunModel::Spa] {
            let p = sun_position(t, &o, model, &Options::default()).unwrap();
            assert!((p.altitude.to_degrees() - 66.95).abs() < ALTITUDE_DEG, "{model:?} {}", p.altitude.to_degrees());
            assert!((p.azimuth.to_degrees() - 178.06).abs() < AZIMUTH_DEG, "{model:?} {}", p.azimuth.to_degrees());
        }
    }
}
