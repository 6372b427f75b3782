//! Time scales: UTC instants (through `jiff`), Julian dates and Schlyter's day number.

use jiff::Timestamp;

use crate::EphemError;

/// Seconds per day.
const SECONDS_PER_DAY: f64 = 86_400.0;

/// Julian date of the Unix epoch, 1970-01-01 00:00 UTC.
const JD_UNIX_EPOCH: f64 = 2_440_587.5;

/// Julian date of Schlyter's day 0, 1999-12-31 00:00 UT ("2000 Jan 0.0").
const JD_SCHLYTER_EPOCH: f64 = 2_451_543.5;

/// The instants accepted, the years 1800 to 2200 inclusive: from 1800-01-01 00:00 UTC up to, not
/// including, 2201-01-01 00:00 UTC (Unix seconds). Outside, Schlyter's linear elements and the ΔT
/// estimate lose their meaning.
const VALID_UNIX_SECONDS: (i64, i64) = (-5_364_662_400, 7_289_654_400);

/// Parses an ISO 8601 / RFC 3339 UTC instant such as `2024-06-21T12:00:00Z` (an offset such as
/// `+02:00` is also accepted and converted to UTC).
///
/// # Arguments
/// - `text`: the instant; must lie in the years 1800–2200 (UTC), both included.
///
/// # Returns
/// The instant as a [`Timestamp`].
///
/// # Errors
/// [`EphemError::Time`] if `text` is not an instant with a UTC offset or lies outside the range.
///
/// # References
/// RFC 3339; parsing by the `jiff` crate (no hand-written calendar code).
pub fn parse_utc(text: &str) -> Result<Timestamp, EphemError> {
    let t: Timestamp = text.trim().parse().map_err(|e: jiff::Error| EphemError::Time {
        input: text.to_string(),
        message: format!("{e} (expected e.g. 2024-06-21T12:00:00Z)"),
    })?;
    check_range(t)?;
    Ok(t)
}

/// Checks that `t` lies in the supported range, the years 1800–2200 (UTC), both included.
///
/// # Arguments
/// - `t`: the instant.
///
/// # Returns
/// `t` unchanged.
///
/// # Errors
/// [`EphemError::Time`] outside the range.
pub fn check_range(t: Timestamp) -> Result<Timestamp, EphemError> {
    let s = t.as_second();
    if s < VALID_UNIX_SECONDS.0 || s >= VALID_UNIX_SECONDS.1 {
        return Err(EphemError::Time {
            input: t.to_string(),
            message: "outside the supported years 1800–2200".to_string(),
        });
    }
    Ok(t)
}

/// Seconds since the Unix epoch, with the sub-second part.
fn unix_seconds(t: Timestamp) -> f64 {
    t.as_second() as f64 + f64::from(t.subsec_nanosecond()) * 1e-9
}

/// Julian date of a UTC instant, `JD = 2440587.5 + t_unix/86400` (UTC taken as UT1).
///
/// # Arguments
/// - `t`: the instant.
///
/// # Returns
/// The Julian date (days).
///
/// # References
/// Meeus J. 1998, Astronomical Algorithms, 2nd ed., ch. 7.
pub fn julian_date(t: Timestamp) -> f64 {
    JD_UNIX_EPOCH + unix_seconds(t) / SECONDS_PER_DAY
}

/// Schlyter's day number `d`: days since 1999-12-31 00:00 UT, including the fraction of the day
/// (`d = 367y − ⌊7(y + ⌊(m+9)/12⌋)/4⌋ + ⌊275m/9⌋ + D − 730530 + UT/24` in his notation; computed
/// here from the Julian date, which gives the same value for every date).
///
/// # Arguments
/// - `t`: the instant.
///
/// # Returns
/// `d` (days); 0 at 1999-12-31 00:00 UT, −3543 at 1990-04-19 00:00 UT.
///
/// # References
/// Schlyter P., "How to compute planetary positions", §3 (docs/equations.md §13).
pub fn schlyter_day(t: Timestamp) -> f64 {
    julian_date(t) - JD_SCHLYTER_EPOCH
}

/// Universal time of day: the hours elapsed since the last 0h UTC, `UT = (t_unix mod 86400)/3600`
/// (UTC taken as UT; leap seconds are not counted, as in `jiff`'s Unix timestamps).
///
/// # Arguments
/// - `t`: the instant.
///
/// # Returns
/// `UT` (h), `[0, 24)`.
///
/// # References
/// Schlyter, "How to compute planetary positions" §5b (`SIDTIME = GMST0 + UT + LON/15`).
pub fn ut_hours(t: Timestamp) -> f64 {
    unix_seconds(t).rem_euclid(SECONDS_PER_DAY) / 3600.0
}

/// The instant as a decimal year, `y = 2000 + (JD − 2451545)/365.25` (Julian years from J2000):
/// the argument of the Espenak–Meeus ΔT polynomials.
///
/// # Arguments
/// - `t`: the instant.
///
/// # Returns
/// `y` (years): 2000.0 at 2000-01-01 12h UT.
///
/// # References
/// Espenak F., Meeus J. 2006, "Five millennium canon of solar eclipses", NASA/TP-2006-214141
/// (`y = year + (month − 0.5)/12`; the Julian-year form differs by < 0.05 yr, < 0.1 s of ΔT).
pub fn decimal_year(t: Timestamp) -> f64 {
    2000.0 + (julian_date(t) - 2_451_545.0) / 365.25
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Julian date near 2.4×10⁶ days carries 5×10⁻¹⁰ day of double-precision rounding.
    const JD_ROUNDING_DAYS: f64 = 1e-9;
    /// Meeus prints JD 2436116.31 for 1957 October 4.81 exactly (19:26:24 UT); 10⁻⁶ day = 0.09 s.
    const MEEUS_JD_DAYS: f64 = 1e-6;
    /// `ut_hours` of a whole hour: exact up to rounding.
    const HOURS_ROUNDING: f64 = 1e-12;

    #[test]
    fn schlyter_day_of_his_worked_example() {
        // Schlyter §3: 1990 April 19, 0:00 UT is d = −3543.
        let t = parse_utc("1990-04-19T00:00:00Z").unwrap();
        assert!((schlyter_day(t) + 3543.0).abs() < JD_ROUNDING_DAYS);
        // Meeus Example 7.a: 1957 October 4.81 is JD 2436116.31.
        let t = parse_utc("1957-10-04T19:26:24Z").unwrap();
        assert!((julian_date(t) - 2_436_116.31).abs() < MEEUS_JD_DAYS);
    }

    #[test]
    fn offsets_and_bad_input() {
        let a = parse_utc("2024-06-21T14:00:00+02:00").unwrap();
        let b = parse_utc("2024-06-21T12:00:00Z").unwrap();
        assert_eq!(a, b);
        assert!((ut_hours(b) - 12.0).abs() < HOURS_ROUNDING);
        assert!(parse_utc("2024-06-21 noon").is_err());
        assert!(parse_utc("2024-06-21T12:00:00").is_err(), "a civil time without offset is ambiguous");
        assert!(parse_utc("2300-01-01T00:00:00Z").is_err());
    }
}
