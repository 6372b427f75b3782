//! The Moon's topocentric position, distance and phase (Schlyter's model).

use jiff::Timestamp;

use crate::coords::{Horizontal, spherical, topocentric};
use crate::observer::EARTH_EQUATORIAL_RADIUS_KM;
use crate::schlyter::{equatorial_vector, local_sidereal_time, moon_ecliptic, sun_orbit};
use crate::sun::{AU_KM, Options};
use crate::time::{check_range, schlyter_day, ut_hours};
use crate::{EphemError, Observer};

/// Mean radius of the Moon (km), IAU.
pub const MOON_RADIUS_KM: f64 = 1737.4;

/// The Moon as seen by the observer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoonPosition {
    /// Topocentric altitude (rad), apparent when refraction was requested.
    pub altitude: f64,
    /// Topocentric azimuth from north through east (rad), `[0, 2π)`.
    pub azimuth: f64,
    /// Geocentric (Earth centre to Moon centre) distance (km).
    pub distance_km: f64,
    /// Observer-to-Moon distance (km); sets the disc's angular size.
    pub topocentric_distance_km: f64,
    /// Geocentric elongation from the Sun `ψ` (rad), `[0, π]`.
    pub elongation: f64,
    /// Phase angle Sun–Moon–Earth `i` (rad), `[0, π]`: 0 at full moon.
    pub phase_angle: f64,
    /// Illuminated fraction of the disc `k = (1 + cos i)/2`, `[0, 1]`.
    pub illuminated_fraction: f64,
}

impl MoonPosition {
    /// Altitude and azimuth as a [`Horizontal`].
    pub fn horizontal(&self) -> Horizontal {
        Horizontal { altitude: self.altitude, azimuth: self.azimuth }
    }

    /// Angular radius of the disc seen by the observer, `ρ = asin(R_moon/Δ_topo)`.
    ///
    /// # Returns
    /// `ρ` (rad): 0.24°–0.29° (apogee to perigee), about 0.26°.
    ///
    /// # References
    /// IAU mean lunar radius 1737.4 km; Meeus 1998 ch. 55.
    pub fn angular_radius(&self) -> f64 {
        (MOON_RADIUS_KM / self.topocentric_distance_km).asin()
    }
}

/// Phase angle from the elongation and the distances:
/// `i = atan2(R sin ψ, Δ − R cos ψ)`, `R` the Earth–Sun and `Δ` the Earth–Moon distance.
///
/// # Arguments
/// - `elongation`: `ψ` (rad), `[0, π]`.
/// - `sun_distance_km`, `moon_distance_km`: `R`, `Δ` (km).
///
/// # Returns
/// `i` (rad), `[0, π]` (Schlyter's approximation is `i ≈ π − ψ`).
///
/// # References
/// Meeus 1998, Eq. 48.3; Schlyter §15 (`FV = 180° − elong`).
pub fn phase_angle(elongation: f64, sun_distance_km: f64, moon_distance_km: f64) -> f64 {
    (sun_distance_km * elongation.sin()).atan2(moon_distance_km - sun_distance_km * elongation.cos())
}

/// The topocentric position, distance and phase of the Moon at `t` for `observer`.
///
/// [`moon_ecliptic`] (Schlyter's elements and perturbations) → equatorial of date → the observer's
/// position on the WGS84 ellipsoid subtracted (the full parallax, up to 1°, in altitude and
/// azimuth) → hour angle → altitude and azimuth; refraction if asked
/// ([`Options::refraction`]; [`Options::delta_t_s`] is unused: Schlyter's elements run on UT).
/// Phase: `cos ψ = ŝ · m̂` from the geocentric Sun and Moon vectors, [`phase_angle`],
/// `k = (1 + cos i)/2`.
///
/// # Arguments
/// - `t`: UTC instant (taken as UT1), 1800..2200.
/// - `observer`: the place.
/// - `options`: refraction.
///
/// # Returns
/// The [`MoonPosition`].
///
/// # Errors
/// [`EphemError::Time`] outside 1800..2200.
///
/// # References
/// Schlyter, "How to compute planetary positions" §6–9, §12–13, §15; Meeus 1998 ch. 40, 48.
pub fn moon_position(t: Timestamp, observer: &Observer, options: &Options) -> Result<MoonPosition, EphemError> {
    check_range(t)?;
    let d = schlyter_day(t);
    let m = moon_ecliptic(d);
    let geo = equatorial_vector(m.longitude, m.latitude, m.distance_earth_radii, d);
    let lst = local_sidereal_time(d, ut_hours(t), observer.longitude());
    let topo = topocentric(geo, lst, observer);
    let (ra, dec, r_topo) = spherical(topo);
    let mut h = Horizontal::from_equatorial(lst - ra, dec, observer.latitude());
    if let Some(air) = options.refraction {
        // Refraction vanishes at the zenith: the `min` absorbs rounding only.
        debug_assert!(h.altitude + air.refraction(h.altitude) <= std::f64::consts::FRAC_PI_2 + 1e-9);
        h.altitude = (h.altitude + air.refraction(h.altitude)).min(std::f64::consts::FRAC_PI_2);
    }

    let sun = sun_orbit(d);
    let sun_km = sun.distance_au * AU_KM;
    let moon_km = m.distance_earth_radii * EARTH_EQUATORIAL_RADIUS_KM;
    let cos_psi = (m.longitude - sun.longitude).cos() * m.latitude.cos();
    let elongation = cos_psi.clamp(-1.0, 1.0).acos();
    let i = phase_angle(elongation, sun_km, moon_km);
    Ok(MoonPosition {
        altitude: h.altitude,
        azimuth: h.azimuth,
        distance_km: moon_km,
        topocentric_distance_km: r_topo * EARTH_EQUATORIAL_RADIUS_KM,
        elongation,
        phase_angle: i,
        illuminated_fraction: 0.5 * (1.0 + i.cos()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse_utc;

    #[test]
    fn schlyter_worked_example_topocentric() {
        // Equation-sheet oracle (§13) from Schlyter's method for his worked example, 1990-04-19
        // 0h UT at 60° N 15° E (his tutorial stops at the topocentric RA and Decl, tested in
        // `schlyter::tests`): geocentric altitude −15.3167°, azimuth 101.7868° lowered by his
        // `mpar cos(alt)` to −16.23°, azimuth kept 101.79°; phase (1 + cos(180° − elong))/2 =
        // 0.428 (printed to 2–3 decimals). His parallax step is first order on a spherical Earth
        // and leaves the azimuth unchanged; ours subtracts the observer's position on the
        // ellipsoid (exact): the neglected second order is mpar² = 0.0156°, the ellipsoid moves
        // the azimuth by up to 0.01°. Our phase angle is Meeus's (with the distances), 0.15° from
        // his 180° − elongation: dk = sin i/2 · di = 0.0013.
        const ALT_AZ_DEG: f64 = 0.005 + 0.0156 + 0.01;
        const FRACTION: f64 = 5e-4 + 1.3e-3;
        let t = parse_utc("1990-04-19T00:00:00Z").unwrap();
        let o = Observer::from_degrees(60.0, 15.0, 0.0).unwrap();
        let p = moon_position(t, &o, &Options::default()).unwrap();
        assert!((p.altitude.to_degrees() + 16.23).abs() < ALT_AZ_DEG, "alt {}", p.altitude.to_degrees());
        assert!((p.azimuth.to_degrees() - 101.79).abs() < ALT_AZ_DEG, "az {}", p.azimuth.to_degrees());
        assert!((p.illuminated_fraction - 0.428).abs() < FRACTION, "k {}", p.illuminated_fraction);
    }
}
