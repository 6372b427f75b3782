//! Schlyter's orbital elements of the Sun and the Moon by day number, with the Moon's main
//! perturbations and the local sidereal time.
//!
//! All formulas: Schlyter P., "How to compute planetary positions" (stjarnhimlen.se/comp/ppcomp.html),
//! §4–§9 and §5b; equation sheet §13. Angles in radians here (his tables are in degrees).

use crate::coords::{ecliptic_to_equatorial, rectangular, rev, spherical};

/// Obliquity of the ecliptic `ecl = 23.4393° − 3.563×10⁻⁷° d`.
///
/// # Arguments
/// - `d`: Schlyter day number (days from 1999-12-31 0h UT).
///
/// # Returns
/// `ε` (rad).
///
/// # References
/// Schlyter §5.
pub fn obliquity(d: f64) -> f64 {
    (23.4393 - 3.563e-7 * d).to_radians()
}

/// Solves Kepler's equation `E − e sin E = M` by Newton's method (Schlyter §6 iterates the same
/// way), to 10⁻¹⁴ rad.
fn eccentric_anomaly(m: f64, e: f64) -> f64 {
    let mut ea = m + e * m.sin() * (1.0 + e * m.cos());
    for _ in 0..20 {
        let step = (ea - e * ea.sin() - m) / (1.0 - e * ea.cos());
        ea -= step;
        if step.abs() < 1e-14 {
            break;
        }
    }
    ea
}

/// The Sun's orbit at day `d` (Schlyter §4–5), angles in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunOrbit {
    /// Mean anomaly `M = 356.0470° + 0.9856002585° d`.
    pub mean_anomaly: f64,
    /// Eccentric anomaly `E = M + e sin M (1 + e cos M)` (Schlyter's first-order form).
    pub eccentric_anomaly: f64,
    /// True anomaly `v`.
    pub true_anomaly: f64,
    /// Earth–Sun distance `r` (AU).
    pub distance_au: f64,
    /// Ecliptic longitude `λ = v + w` (of date).
    pub longitude: f64,
    /// Mean longitude `L = M + w`.
    pub mean_longitude: f64,
}

/// The Sun's geocentric position by Schlyter's elements:
/// `w = 282.9404° + 4.70935×10⁻⁵° d`, `e = 0.016709 − 1.151×10⁻⁹ d`,
/// `M = 356.0470° + 0.9856002585° d`; `E = M + e sin M (1 + e cos M)`;
/// `x_v = cos E − e`, `y_v = √(1 − e²) sin E`; `v = atan2(y_v, x_v)`, `r = √(x_v² + y_v²)`.
///
/// # Arguments
/// - `d`: Schlyter day number.
///
/// # Returns
/// The [`SunOrbit`].
///
/// # References
/// Schlyter §4–5; equation sheet §13 (worked example 1990-04-19 in the Test oracles).
pub fn sun_orbit(d: f64) -> SunOrbit {
    let w = (282.9404 + 4.70935e-5 * d).to_radians();
    let e = 0.016709 - 1.151e-9 * d;
    let m = rev((356.0470 + 0.985_600_258_5 * d).to_radians());
    let ea = m + e * m.sin() * (1.0 + e * m.cos());
    let xv = ea.cos() - e;
    let yv = (1.0 - e * e).sqrt() * ea.sin();
    SunOrbit {
        mean_anomaly: m,
        eccentric_anomaly: ea,
        true_anomaly: rev(yv.atan2(xv)),
        distance_au: xv.hypot(yv),
        longitude: rev(yv.atan2(xv) + w),
        mean_longitude: rev(m + w),
    }
}

/// The Moon's geocentric ecliptic position (of date), angles in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoonEcliptic {
    /// Ecliptic longitude `λ` with the perturbations.
    pub longitude: f64,
    /// Ecliptic latitude `β` with the perturbations.
    pub latitude: f64,
    /// Geocentric distance (Earth equatorial radii) with the perturbations.
    pub distance_earth_radii: f64,
}

/// The Moon's geocentric ecliptic position by Schlyter's elements and main perturbations:
/// `N = 125.1228° − 0.0529538083° d`, `i = 5.1454°`, `w = 318.0634° + 0.1643573223° d`,
/// `a = 60.2666`, `e = 0.0549`, `M = 115.3654° + 13.0649929509° d`; Kepler's equation; the
/// position in the orbit rotated by `N`, `i`, `w`; then
/// ```text
/// Δλ = −1.274° sin(Mm − 2D) + 0.658° sin 2D − 0.186° sin Ms − 0.059° sin(2Mm − 2D)
///      − 0.057° sin(Mm − 2D + Ms) + 0.053° sin(Mm + 2D) + 0.046° sin(2D − Ms)
///      + 0.041° sin(Mm − Ms) − 0.035° sin D − 0.031° sin(Mm + Ms) − 0.015° sin(2F − 2D)
///      + 0.011° sin(Mm − 4D)
/// Δβ = −0.173° sin(F − 2D) − 0.055° sin(Mm − F − 2D) − 0.046° sin(Mm + F − 2D)
///      + 0.033° sin(F + 2D) + 0.017° sin(2Mm + F)
/// Δr = −0.58 cos(Mm − 2D) − 0.46 cos 2D   (Earth radii)
/// ```
/// with `Lm = N + w + Mm`, `D = Lm − Ls`, `F = Lm − N` (`Ms`, `Ls`: the Sun's mean anomaly and
/// longitude).
///
/// # Arguments
/// - `d`: Schlyter day number.
///
/// # Returns
/// The [`MoonEcliptic`] position.
///
/// # References
/// Schlyter §4, §6–7, §9; equation sheet §13.
pub fn moon_ecliptic(d: f64) -> MoonEcliptic {
    let n = rev((125.1228 - 0.052_953_808_3 * d).to_radians());
    let i = 5.1454_f64.to_radians();
    let w = rev((318.0634 + 0.164_357_322_3 * d).to_radians());
    let a = 60.2666;
    let e = 0.054900;
    let m = rev((115.3654 + 13.064_992_950_9 * d).to_radians());
    let ea = eccentric_anomaly(m, e);
    let xv = a * (ea.cos() - e);
    let yv = a * (1.0 - e * e).sqrt() * ea.sin();
    let v = yv.atan2(xv);
    let r = xv.hypot(yv);
    let (svw, cvw) = (v + w).sin_cos();
    let (sn, cn) = n.sin_cos();
    let (si, ci) = i.sin_cos();
    let h = [r * (cn * cvw - sn * svw * ci), r * (sn * cvw + cn * svw * ci), r * svw * si];
    let (lon, lat, r) = spherical(h);

    let sun = sun_orbit(d);
    let ms = sun.mean_anomaly;
    let mm = m;
    let lm = n + w + m;
    let dd = lm - sun.mean_longitude;
    let f = lm - n;
    let s = |x: f64| x.sin();
    let dlon = -1.274 * s(mm - 2.0 * dd) + 0.658 * s(2.0 * dd)
        - 0.186 * s(ms)
        - 0.059 * s(2.0 * mm - 2.0 * dd)
        - 0.057 * s(mm - 2.0 * dd + ms)
        + 0.053 * s(mm + 2.0 * dd)
        + 0.046 * s(2.0 * dd - ms)
        + 0.041 * s(mm - ms)
        - 0.035 * s(dd)
        - 0.031 * s(mm + ms)
        - 0.015 * s(2.0 * f - 2.0 * dd)
        + 0.011 * s(mm - 4.0 * dd);
    let dlat = -0.173 * s(f - 2.0 * dd) - 0.055 * s(mm - f - 2.0 * dd) - 0.046 * s(mm + f - 2.0 * dd)
        + 0.033 * s(f + 2.0 * dd)
        + 0.017 * s(2.0 * mm + f);
    let dr = -0.58 * (mm - 2.0 * dd).cos() - 0.46 * (2.0 * dd).cos();
    MoonEcliptic {
        longitude: rev(lon + dlon.to_radians()),
        latitude: lat + dlat.to_radians(),
        distance_earth_radii: r + dr,
    }
}

/// Local sidereal time `LST = L_s + 180° + 15° UT + λ_obs` (Schlyter's `GMST0 = L_s + 180°`).
///
/// # Arguments
/// - `d`: Schlyter day number (for the Sun's mean longitude `L_s`).
/// - `ut_hours`: universal time of day (h).
/// - `longitude`: observer's longitude, east positive (rad).
///
/// # Returns
/// `LST` (rad), `[0, 2π)`.
///
/// # References
/// Schlyter §5b.
pub fn local_sidereal_time(d: f64, ut_hours: f64, longitude: f64) -> f64 {
    let gmst0 = sun_orbit(d).mean_longitude + std::f64::consts::PI;
    rev(gmst0 + (15.0 * ut_hours).to_radians() + longitude)
}

/// Geocentric equatorial rectangular coordinates of an ecliptic position of date.
pub(crate) fn equatorial_vector(lon: f64, lat: f64, r: f64, d: f64) -> [f64; 3] {
    ecliptic_to_equatorial(rectangular(lon, lat, r), obliquity(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Schlyter prints 4 decimals of a degree for the Sun and 3 for the Moon.
    const SUN_DEG: f64 = 1.5e-4;
    const MOON_DEG: f64 = 1.5e-3;

    #[test]
    fn worked_example_1990_04_19() {
        let d = -3543.0;
        let s = sun_orbit(d);
        assert!((s.mean_anomaly.to_degrees() - 104.0653).abs() < SUN_DEG);
        assert!((s.eccentric_anomaly.to_degrees() - 104.9904).abs() < SUN_DEG);
        assert!((s.true_anomaly.to_degrees() - 105.9134).abs() < SUN_DEG);
        assert!((s.distance_au - 1.004323).abs() < 1.5e-6);
        assert!((s.longitude.to_degrees() - 28.6870).abs() < SUN_DEG);
        let v = equatorial_vector(s.longitude, 0.0, s.distance_au, d);
        let (ra, dec, _) = spherical(v);
        assert!((ra.to_degrees() - 26.658).abs() < MOON_DEG, "RA {}", ra.to_degrees());
        assert!((dec.to_degrees() - 11.008).abs() < MOON_DEG, "Dec {}", dec.to_degrees());
        let m = moon_ecliptic(d);
        assert!((m.longitude.to_degrees() - 306.948).abs() < MOON_DEG, "λ {}", m.longitude.to_degrees());
        assert!((m.latitude.to_degrees() + 0.586).abs() < MOON_DEG, "β {}", m.latitude.to_degrees());
        assert!((m.distance_earth_radii - 60.68).abs() < 0.006, "r {}", m.distance_earth_radii);
    }
}
