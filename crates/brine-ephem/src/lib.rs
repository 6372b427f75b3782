//! # brine-ephem — sun and moon positions
//!
//! Apparent positions of the Sun and the Moon for a UTC instant and a place on Earth, after
//! Schlyter's "How to compute planetary positions" (the simplified astronomical model of Li Ying
//! et al. 2018, §2.1): orbital elements by day number, the Moon's main perturbations, local
//! sidereal time, the topocentric correction (the Moon's parallax reaches 1°) and refraction as an
//! option. For the Sun, NREL's Solar Position Algorithm (Reda & Andreas 2004, through the
//! `solar-positioning` crate) is the default, high-accuracy path. Moon phase angle, illuminated
//! fraction and distance; Earth–Sun distance. Dates are parsed by `jiff`.
//!
//! ## Notation
//!
//! | symbol | Rust | unit | meaning |
//! |---|---|---|---|
//! | `d` | [`schlyter_day`] | day | days since 1999-12-31 0h UT |
//! | `φ`, `λ_obs`, `H` | [`Observer`] | rad, rad, m | geodetic latitude, east longitude, height |
//! | `h`, `A` | `altitude`, `azimuth` | rad | altitude; azimuth from north through east |
//! | `λ`, `β` | `longitude`, `latitude` | rad | ecliptic coordinates of date |
//! | `α`, `δ` | — | rad | right ascension, declination |
//! | `ε` | [`obliquity`] | rad | obliquity of the ecliptic |
//! | `LST` | [`local_sidereal_time`] | rad | local sidereal time |
//! | `ψ`, `i`, `k` | `elongation`, `phase_angle`, `illuminated_fraction` | rad, rad, 1 | Moon phase |
//! | `R` | [`Atmosphere::refraction`] | rad | refraction added to the altitude |
//!
//! ## Validity and accuracy
//!
//! Instants 1800–2200 (checked). Measured against astropy's ERFA ephemeris at 2000 instants over
//! 1950–2050 (see `docs/models/brine-ephem.md`): the SPA Sun within 0.0015° (RMS 0.0001°), the
//! Schlyter Sun within 0.0095° (RMS 0.004°), the Schlyter Moon (topocentric) within 0.0975°
//! (RMS 0.034°), just inside the 0.1° target.
//!
//! ## Example
//!
//! ```
//! use brine_ephem::{Observer, Options, SunModel, moon_position, parse_utc, sun_position};
//! let t = parse_utc("2024-06-21T12:00:00Z")?;
//! let toulouse = Observer::from_degrees(43.6, 1.44, 0.0)?;
//! let sun = sun_position(t, &toulouse, SunModel::Spa, &Options::default())?;
//! assert!((sun.altitude.to_degrees() - 69.8).abs() < 0.2);
//! let moon = moon_position(t, &toulouse, &Options::default())?;
//! assert!(moon.illuminated_fraction > 0.9); // full moon on 2024-06-22
//! # Ok::<(), brine_ephem::EphemError>(())
//! ```
//!
//! ## References
//!
//! - Schlyter P., "How to compute planetary positions", stjarnhimlen.se/comp/ppcomp.html.
//! - Reda I., Andreas A. 2004, "Solar position algorithm for solar radiation applications",
//!   Solar Energy 76(5):577–589 (NREL/TP-560-34302).
//! - Meeus J. 1998, *Astronomical Algorithms*, 2nd ed., Willmann-Bell (ch. 7, 11, 16, 40, 48).
//! - Li Ying et al. 2018, J. Computer-Aided Design & Computer Graphics (time-and-space-driven ocean), §2.1.

mod coords;
mod error;
mod moon;
mod observer;
mod refraction;
mod schlyter;
mod sun;
mod time;

pub use coords::Horizontal;
pub use error::EphemError;
/// The UTC instant type of the API (re-exported from `jiff`).
pub use jiff::Timestamp;
pub use moon::{MOON_RADIUS_KM, MoonPosition, moon_position, phase_angle};
pub use observer::{EARTH_EQUATORIAL_RADIUS_KM, EARTH_FLATTENING, Observer};
pub use refraction::{Atmosphere, REFRACTION_CUTOFF_DEG, REFRACTION_FADE_DEG};
pub use schlyter::{
    MoonEcliptic, MoonOrbit, SunOrbit, gmst0, local_sidereal_time, moon_ecliptic, moon_orbit, obliquity, sun_orbit,
};
pub use sun::{AU_KM, Options, SunModel, SunPosition, sun_position};
pub use time::{check_range, decimal_year, julian_date, parse_utc, schlyter_day, ut_hours};
