//! Schlyter's orbital elements of the Sun and the Moon by day number, with the Moon's main
//! perturbations and the local sidereal time.
//!
//! All formulas: Schlyter P., "How to compute planetary positions" (stjarnhimlen.se/comp/ppcomp.html),
//! §4–§9 and §5b; docs/equations.md §13. Angles in radians here (his tables are in degrees).

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

/// Schlyter's first approximation of the eccentric anomaly, `E₀ = M + e sin M (1 + e cos M)`
/// (rad); the Sun uses it as its final `E` (Schlyter §5: "accurate enough" for `e = 0.017`).
fn first_eccentric_anomaly(m: f64, e: f64) -> f64 {
    m + e * m.sin() * (1.0 + e * m.cos())
}

/// Solves Kepler's equation `E − e sin E = M` by Newton's method from
/// [`first_eccentric_anomaly`] (Schlyter §6 iterates the same way), to 10⁻¹⁴ rad.
fn eccentric_anomaly(m: f64, e: f64) -> f64 {
    let mut ea = first_eccentric_anomaly(m, e);
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
    /// Longitude of perihelion `w = 282.9404° + 4.70935×10⁻⁵° d` (rad, not reduced).
    pub perihelion_longitude: f64,
    /// Eccentricity `e = 0.016709 − 1.151×10⁻⁹ d`.
    pub eccentricity: f64,
    /// Mean anomaly `M = 356.0470° + 0.9856002585° d`, reduced to `[0, 2π)`.
    pub mean_anomaly: f64,
    /// Eccentric anomaly `E = M + e sin M (1 + e cos M)` (Schlyter's first-order form).
    pub eccentric_anomaly: f64,
    /// True anomaly `v`, `[0, 2π)`.
    pub true_anomaly: f64,
    /// Earth–Sun distance `r` (AU).
    pub distance_au: f64,
    /// Ecliptic longitude `λ = v + w` (of date), `[0, 2π)`.
    pub longitude: f64,
    /// Mean longitude `L = M + w`, `[0, 2π)`.
    pub mean_longitude: f64,
}

/// The Sun's geocentric position by Schlyter's elements:
/// `w = 282.9404° + 4.70935×10⁻⁵° d`, `e = 0.016709 − 1.151×10⁻⁹ d`,
/// `M = 356.0470° + 0.9856002585° d`; `E = M + e sin M (1 + e cos M)`;
/// `x_v = cos E − e`, `y_v = √(1 − e²) sin E`; `v = atan2(y_v, x_v)`, `r = √(x_v² + y_v²)`,
/// `λ = v + w`, `L = M + w`.
///
/// # Arguments
/// - `d`: Schlyter day number (days from 1999-12-31 0h UT), any finite value (the elements are
///   meant for 1800–2200).
///
/// # Returns
/// The [`SunOrbit`] (radians; `r` in AU).
///
/// # References
/// Schlyter P., "How to compute planetary positions" §4–5, and his worked example
/// ("Computing planetary positions – a tutorial with worked examples", §5, 1990-04-19);
/// docs/equations.md §13.
pub fn sun_orbit(d: f64) -> SunOrbit {
    let w = (282.9404 + 4.70935e-5 * d).to_radians();
    let e = 0.016709 - 1.151e-9 * d;
    let m = rev((356.0470 + 0.985_600_258_5 * d).to_radians());
    let ea = first_eccentric_anomaly(m, e);
    let xv = ea.cos() - e;
    let yv = (1.0 - e * e).sqrt() * ea.sin();
    SunOrbit {
        perihelion_longitude: w,
        eccentricity: e,
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
    /// Ecliptic longitude `λ` with the perturbations, `[0, 2π)`.
    pub longitude: f64,
    /// Ecliptic latitude `β` with the perturbations.
    pub latitude: f64,
    /// Geocentric distance (Earth equatorial radii) with the perturbations.
    pub distance_earth_radii: f64,
}

/// Every intermediate quantity of Schlyter's lunar computation at day `d` (angles in radians,
/// distances in Earth equatorial radii), from the elements to the perturbed position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoonOrbit {
    /// Longitude of the ascending node `N = 125.1228° − 0.0529538083° d`, `[0, 2π)`.
    pub ascending_node: f64,
    /// Inclination `i = 5.1454°`.
    pub inclination: f64,
    /// Argument of perigee `w = 318.0634° + 0.1643573223° d`, `[0, 2π)`.
    pub perigee_argument: f64,
    /// Mean distance `a = 60.2666` Earth radii.
    pub semi_major_axis: f64,
    /// Eccentricity `e = 0.054900`.
    pub eccentricity: f64,
    /// Mean anomaly `M = 115.3654° + 13.0649929509° d`, `[0, 2π)`.
    pub mean_anomaly: f64,
    /// Eccentric anomaly `E`, Kepler's equation solved to 10⁻¹⁴ rad.
    pub eccentric_anomaly: f64,
    /// True anomaly `v`, `[0, 2π)`.
    pub true_anomaly: f64,
    /// Distance in the unperturbed orbit `r = a(1 − e cos E)`.
    pub distance: f64,
    /// Unperturbed ecliptic longitude, `[0, 2π)`.
    pub longitude: f64,
    /// Unperturbed ecliptic latitude.
    pub latitude: f64,
    /// The Moon's mean longitude `Lm = N + w + M`, `[0, 2π)`.
    pub mean_longitude: f64,
    /// The Moon's mean elongation `D = Lm − Ls`, `[0, 2π)`.
    pub mean_elongation: f64,
    /// The Moon's argument of latitude `F = Lm − N`, `[0, 2π)`.
    pub argument_of_latitude: f64,
    /// Sum of the 12 longitude perturbation terms `Δλ` (rad).
    pub longitude_perturbation: f64,
    /// Sum of the 5 latitude perturbation terms `Δβ` (rad).
    pub latitude_perturbation: f64,
    /// Sum of the 2 distance perturbation terms `Δr` (Earth radii).
    pub distance_perturbation: f64,
}

impl MoonOrbit {
    /// The perturbed position `(λ + Δλ, β + Δβ, r + Δr)`, λ reduced to `[0, 2π)`.
    ///
    /// # Returns
    /// The [`MoonEcliptic`] position (radians; Earth equatorial radii).
    ///
    /// # References
    /// Schlyter §9; tutorial §8 (306.9484°, −0.5856°, 60.6779 for 1990-04-19).
    pub fn ecliptic(&self) -> MoonEcliptic {
        MoonEcliptic {
            longitude: rev(self.longitude + self.longitude_perturbation),
            latitude: self.latitude + self.latitude_perturbation,
            distance_earth_radii: self.distance + self.distance_perturbation,
        }
    }
}

/// Schlyter's lunar computation at day `d`, every step kept: the elements
/// `N = 125.1228° − 0.0529538083° d`, `i = 5.1454°`, `w = 318.0634° + 0.1643573223° d`,
/// `a = 60.2666`, `e = 0.0549`, `M = 115.3654° + 13.0649929509° d`; Kepler's equation
/// `E − e sin E = M`; `x = a(cos E − e)`, `y = a√(1 − e²) sin E`, `v = atan2(y, x)`,
/// `r = √(x² + y²)`; the position in the orbit rotated by `N`, `i`, `w`:
/// `x_ecl = r(cos N cos(v + w) − sin N sin(v + w) cos i)`,
/// `y_ecl = r(sin N cos(v + w) + cos N sin(v + w) cos i)`, `z_ecl = r sin(v + w) sin i`;
/// then the perturbations
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
/// longitude, [`sun_orbit`]).
///
/// # Arguments
/// - `d`: Schlyter day number (days from 1999-12-31 0h UT), any finite value (meant for
///   1800–2200).
///
/// # Returns
/// The [`MoonOrbit`] (radians; distances in Earth equatorial radii).
///
/// # References
/// Schlyter, "How to compute planetary positions" §4, §6–7, §9, and the tutorial's worked
/// example §7–8 (1990-04-19); docs/equations.md §13.
pub fn moon_orbit(d: f64) -> MoonOrbit {
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
    let (lon, lat, _) = spherical(h);

    let sun = sun_orbit(d);
    let ms = sun.mean_anomaly;
    let mm = m;
    let lm = rev(n + w + m);
    let dd = rev(lm - sun.mean_longitude);
    let f = rev(lm - n);
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
    MoonOrbit {
        ascending_node: n,
        inclination: i,
        perigee_argument: w,
        semi_major_axis: a,
        eccentricity: e,
        mean_anomaly: m,
        eccentric_anomaly: ea,
        true_anomaly: rev(v),
        distance: r,
        longitude: lon,
        latitude: lat,
        mean_longitude: lm,
        mean_elongation: dd,
        argument_of_latitude: f,
        longitude_perturbation: dlon.to_radians(),
        latitude_perturbation: dlat.to_radians(),
        distance_perturbation: dr,
    }
}

/// The Moon's geocentric ecliptic position of date by Schlyter's elements and his main
/// perturbations: [`moon_orbit`] followed by [`MoonOrbit::ecliptic`],
/// `λ = λ₀ + Δλ`, `β = β₀ + Δβ`, `r = r₀ + Δr`.
///
/// # Arguments
/// - `d`: Schlyter day number (days from 1999-12-31 0h UT).
///
/// # Returns
/// The [`MoonEcliptic`] position (radians; distance in Earth equatorial radii).
///
/// # References
/// Schlyter §4, §6–7, §9; docs/equations.md §13.
pub fn moon_ecliptic(d: f64) -> MoonEcliptic {
    moon_orbit(d).ecliptic()
}

/// Greenwich mean sidereal time at 0h UT of day `d`, Schlyter's `GMST0 = L_s + 180°` (the
/// Sun's mean longitude plus 180°; within a few seconds of the IAU expression over 1900–2100).
///
/// # Arguments
/// - `d`: Schlyter day number (its fraction of a day moves `L_s` by 0.986° per day, as in
///   Schlyter, who evaluates it at the instant).
///
/// # Returns
/// `GMST0` (rad), `[0, 2π)`.
///
/// # References
/// Schlyter §5b; tutorial §6.
pub fn gmst0(d: f64) -> f64 {
    rev(sun_orbit(d).mean_longitude + std::f64::consts::PI)
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
    rev(gmst0(d) + (15.0 * ut_hours).to_radians() + longitude)
}

/// Geocentric equatorial rectangular coordinates of an ecliptic position of date.
pub(crate) fn equatorial_vector(lon: f64, lat: f64, r: f64, d: f64) -> [f64; 3] {
    ecliptic_to_equatorial(rectangular(lon, lat, r), obliquity(d))
}

#[cfg(test)]
mod tests {
    //! Schlyter's worked example, 1990-04-19 0h UT (d = −3543), at 60.0° N 15.0° E, as printed in
    //! "Computing planetary positions – a tutorial with worked examples" (stjarnhimlen.se/comp/
    //! tutorial.html, §5–§9), the companion of "How to compute planetary positions". Every
    //! printed figure is tested to half a unit of its last digit. Schlyter carried his rounded
    //! intermediate values on a 12-digit calculator, so a few printed figures differ from the
    //! exact chain by the propagated rounding of their printed inputs (allowances below, each
    //! derived from the input's half unit), and two are slips (errata, `docs/models/brine-ephem.md`).

    use approx::assert_abs_diff_eq;

    use super::*;

    /// The worked example's day number (Schlyter §3: 1990 April 19, 0:00 UT).
    const D: f64 = -3543.0;
    /// Half a unit of the 4th decimal: angles printed as `104.0653_deg`.
    const HALF_4DP: f64 = 5e-5;
    /// Half a unit of the 5th decimal: hours (`13.78925 h`), Moon coordinates (`60.67134`).
    const HALF_5DP: f64 = 5e-6;
    /// Half a unit of the 6th decimal: `e = 0.016713`, `r = 1.004323`, `x = -0.275370`.
    const HALF_6DP: f64 = 5e-7;
    /// Half a unit of the 3rd decimal: `g = 88.642`.
    const HALF_3DP: f64 = 5e-4;
    /// Half a unit of the 2nd decimal: `gclat = 59.83`.
    const HALF_2DP: f64 = 5e-3;
    /// Half a unit of the printed tenth of a second: `14h 47m 21.3s`.
    const HALF_TENTH_SECOND: f64 = 0.05;
    /// Schlyter's Sun longitude `105.9134° + 282.7735° = 28.6869°` adds `v` and `w` rounded to 4
    /// decimals: up to 2 half units (10⁻⁴°) more than the exact sum, 28.68699°.
    const CARRIED_SUN_LONGITUDE_DEG: f64 = 2.0 * HALF_4DP;
    /// Error of Schlyter's λ☉ (rounded inputs and its own rounding), 1.5×10⁻⁴°, carried into his
    /// x, y = r(cos λ, sin λ) (× r π/180 = 2.63×10⁻⁶) and α, δ (|∂α/∂λ| ≤ sec ε = 1.090).
    const SUN_LONGITUDE_ERROR_DEG: f64 = CARRIED_SUN_LONGITUDE_DEG + HALF_4DP;
    /// Schlyter's `GMST0 = 26.8388°/15 + 12 h` uses `L` rounded to 4 decimals: 3.3×10⁻⁶ h.
    const CARRIED_GMST0_H: f64 = HALF_4DP / 15.0;
    /// Schlyter's `x = cos HA cos δ`, `y = sin HA cos δ`, `z = sin δ` use HA = 195.1808° and
    /// Decl = +11.0084° rounded: each moves by at most the two half units in radians, 1.7×10⁻⁶.
    const CARRIED_HA_DEC: f64 = 2.0 * HALF_4DP * std::f64::consts::PI / 180.0;
    /// Schlyter's lunar `x = a(cos E − e)`, `v` use `E = 262.9735°` rounded: the error of `E`
    /// (half a unit, 8.7×10⁻⁷ rad) times `|∂x/∂E| = a |sin E| = 59.81` is 5.2×10⁻⁵; `v` moves by
    /// `∂v/∂E = √(1 − e²)/(1 − e cos E) = 1.0031` times 5×10⁻⁵°.
    const CARRIED_MOON_E_X: f64 = 59.81 * HALF_4DP * std::f64::consts::PI / 180.0;
    const CARRIED_MOON_E_V_DEG: f64 = 1.0031 * HALF_4DP;
    /// His topocentric RA and Decl are first order in the parallax (`mpar · ρ cos φ′ sin H/cos δ`);
    /// the neglected terms are of order `mpar²` = (0.01648 rad)² = 2.7×10⁻⁴ rad = 0.0156°.
    /// Ours subtracts the observer's position vector (exact): the two differ by 0.0001° and 0.0040°.
    const SCHLYTER_FIRST_ORDER_PARALLAX_DEG: f64 = 0.0156;

    fn deg(x: f64) -> f64 {
        x.to_degrees()
    }

    #[test]
    fn worked_example_sun_elements_and_orbit() {
        let s = sun_orbit(D);
        // §5: w = 282.7735°, a = 1.000000, e = 0.016713, M = 104.0653° (reduced),
        // L = 26.8388°, oblecl = 23.4406°, E = 104.9904°, x = −0.275370, y = +0.965834,
        // r = 1.004323, v = 105.9134°.
        assert_abs_diff_eq!(deg(s.perihelion_longitude), 282.7735, epsilon = HALF_4DP);
        assert_abs_diff_eq!(s.eccentricity, 0.016713, epsilon = HALF_6DP);
        assert_abs_diff_eq!(deg(s.mean_anomaly), 104.0653, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(s.mean_longitude), 26.8388, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(obliquity(D)), 23.4406, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(s.eccentric_anomaly), 104.9904, epsilon = HALF_4DP);
        let (xv, yv) = (s.distance_au * s.true_anomaly.cos(), s.distance_au * s.true_anomaly.sin());
        assert_abs_diff_eq!(xv, -0.275370, epsilon = HALF_6DP);
        assert_abs_diff_eq!(yv, 0.965834, epsilon = HALF_6DP);
        assert_abs_diff_eq!(s.distance_au, 1.004323, epsilon = HALF_6DP);
        assert_abs_diff_eq!(deg(s.true_anomaly), 105.9134, epsilon = HALF_4DP);
        // lon = 28.6869° (from the rounded v and w; the exact sum is 28.68699°).
        assert_abs_diff_eq!(deg(s.longitude), 28.6869, epsilon = HALF_4DP + CARRIED_SUN_LONGITUDE_DEG);
    }

    #[test]
    fn worked_example_sun_equatorial() {
        let s = sun_orbit(D);
        // §5: ecliptic x = 0.881048, y = 0.482098; equatorial x = 0.881048, y = 0.442312,
        // z = 0.191778; RA = 26.6580° = 1.77720 h, Decl = +11.0084°, r unchanged.
        let along = SUN_LONGITUDE_ERROR_DEG.to_radians() * s.distance_au;
        let [x, y, _] = rectangular(s.longitude, 0.0, s.distance_au);
        assert_abs_diff_eq!(x, 0.881048, epsilon = HALF_6DP + along);
        assert_abs_diff_eq!(y, 0.482098, epsilon = HALF_6DP + along);
        let v = equatorial_vector(s.longitude, 0.0, s.distance_au, D);
        assert_abs_diff_eq!(v[0], 0.881048, epsilon = HALF_6DP + along);
        assert_abs_diff_eq!(v[1], 0.442312, epsilon = HALF_6DP + along);
        assert_abs_diff_eq!(v[2], 0.191778, epsilon = HALF_6DP + along);
        let (ra, dec, r) = spherical(v);
        let carried = 1.090 * SUN_LONGITUDE_ERROR_DEG;
        assert_abs_diff_eq!(deg(ra), 26.6580, epsilon = HALF_4DP + carried);
        assert_abs_diff_eq!(deg(ra) / 15.0, 1.77720, epsilon = HALF_5DP + carried / 15.0);
        assert_abs_diff_eq!(deg(dec), 11.0084, epsilon = HALF_4DP);
        assert_abs_diff_eq!(r, 1.004323, epsilon = HALF_6DP);
        // Fed Schlyter's own rounded λ = 28.6869°, r = 1.004323 and ecl = 23.4406°, the rotation
        // gives his digits.
        let rounded = rectangular(28.6869f64.to_radians(), 0.0, 1.004323);
        let (ra, dec, _) = spherical(ecliptic_to_equatorial(rounded, 23.4406f64.to_radians()));
        assert_abs_diff_eq!(deg(ra), 26.6580, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(dec), 11.0084, epsilon = HALF_4DP);
    }

    #[test]
    fn worked_example_sidereal_time_and_sun_horizontal() {
        // §6: GMST0 = 13.78925 h, SIDTIME = 14.78925 h (14h 47m 21.3s) at 15° E, 0h UT;
        // HA = 13.01205 h = 195.1808°; x = −0.947346, y = −0.257047, z = +0.190953;
        // azimuth 15.6767°, altitude −17.9570° at 60° N (geocentric).
        let g = deg(gmst0(D)) / 15.0;
        assert_abs_diff_eq!(g, 13.78925, epsilon = HALF_5DP + CARRIED_GMST0_H);
        let lst = local_sidereal_time(D, 0.0, 15f64.to_radians());
        let lst_h = deg(lst) / 15.0;
        assert_abs_diff_eq!(lst_h, 14.78925, epsilon = HALF_5DP + CARRIED_GMST0_H);
        let seconds = (lst_h - 14.0) * 3600.0 - 47.0 * 60.0;
        assert_abs_diff_eq!(seconds, 21.3, epsilon = HALF_TENTH_SECOND);
        assert_abs_diff_eq!(deg(lst), 221.8388, epsilon = HALF_4DP);

        let s = sun_orbit(D);
        let (ra, dec, _) = spherical(equatorial_vector(s.longitude, 0.0, s.distance_au, D));
        let ha = rev(lst - ra);
        assert_abs_diff_eq!(deg(ha) / 15.0, 13.01205, epsilon = HALF_5DP);
        assert_abs_diff_eq!(deg(ha), 195.1808, epsilon = HALF_4DP);
        let [x, y, z] = rectangular(ha, dec, 1.0);
        assert_abs_diff_eq!(x, -0.947346, epsilon = HALF_6DP + CARRIED_HA_DEC);
        assert_abs_diff_eq!(y, -0.257047, epsilon = HALF_6DP + CARRIED_HA_DEC);
        assert_abs_diff_eq!(z, 0.190953, epsilon = HALF_6DP + CARRIED_HA_DEC);
        let h = crate::Horizontal::from_equatorial(ha, dec, 60f64.to_radians());
        assert_abs_diff_eq!(h.azimuth_deg(), 15.6767, epsilon = HALF_4DP);
        assert_abs_diff_eq!(h.altitude_deg(), -17.9570, epsilon = HALF_4DP);
    }

    #[test]
    fn worked_example_moon_elements_and_orbit() {
        let m = moon_orbit(D);
        // §7 (reduced to [0°, 360°)): N = 312.7381°, i = 5.1454°, w = 95.7454°, a = 60.2666,
        // e = 0.054900, M = 266.0954°.
        assert_abs_diff_eq!(deg(m.ascending_node), 312.7381, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.inclination), 5.1454, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.perigee_argument), 95.7454, epsilon = HALF_4DP);
        assert_abs_diff_eq!(m.semi_major_axis, 60.2666, epsilon = HALF_4DP);
        assert_abs_diff_eq!(m.eccentricity, 0.054900, epsilon = HALF_6DP);
        assert_abs_diff_eq!(deg(m.mean_anomaly), 266.0954, epsilon = HALF_4DP);
        // E₀ = 262.9689° (first approximation), E = 262.9735° after iterating.
        assert_abs_diff_eq!(deg(first_eccentric_anomaly(m.mean_anomaly, m.eccentricity)), 262.9689, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.eccentric_anomaly), 262.9735, epsilon = HALF_4DP);
        // x = −10.68095, y = −59.72377 (from the rounded E; exact x = −10.68099),
        // r = 60.67134, v = 259.8605° (from the rounded E; exact 259.86042°).
        let (x, y) = (m.distance * m.true_anomaly.cos(), m.distance * m.true_anomaly.sin());
        assert_abs_diff_eq!(x, -10.68095, epsilon = HALF_5DP + CARRIED_MOON_E_X);
        assert_abs_diff_eq!(y, -59.72377, epsilon = HALF_5DP);
        assert_abs_diff_eq!(m.distance, 60.67134, epsilon = HALF_5DP);
        assert_abs_diff_eq!(deg(m.true_anomaly), 259.8605, epsilon = HALF_4DP + CARRIED_MOON_E_V_DEG);
        // Ecliptic x = +37.65311, y = −47.57180, z = −0.41687; long = 308.3616°,
        // lat = −0.3937°, r = 60.6713. Erratum: his own r, v, w, N, i give y = −47.57183 and
        // z = −0.41689 (the exact chain: −47.57185, −0.41689); the printed y and z are slips.
        let [xe, ye, ze] = rectangular(m.longitude, m.latitude, m.distance);
        assert_abs_diff_eq!(xe, 37.65311, epsilon = HALF_5DP);
        assert_abs_diff_eq!(ye, -47.57185, epsilon = HALF_5DP);
        assert_abs_diff_eq!(ze, -0.41689, epsilon = HALF_5DP);
        assert_abs_diff_eq!(deg(m.longitude), 308.3616, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.latitude), -0.3937, epsilon = HALF_4DP);
        assert_abs_diff_eq!(m.distance, 60.6713, epsilon = HALF_4DP);
    }

    #[test]
    fn worked_example_moon_perturbations() {
        let m = moon_orbit(D);
        // §8: Ms = 104.0653°, Mm = 266.0954°, Ls = 26.8388°, Lm = 674.5789° = 314.5789°,
        // D = 287.7401°, F = 1.8408°.
        assert_abs_diff_eq!(deg(m.mean_longitude), 314.5789, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.mean_elongation), 287.7401, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.argument_of_latitude), 1.8408, epsilon = HALF_4DP);
        // Δλ = −1.4132°, Δβ = −0.1919°, Δr = +0.0066 Earth radii. Erratum: the ninth
        // longitude term, −0.035° sin D, is printed −0.0333; sin D < 0 at D = 287.74°, so it is
        // +0.0333, and only that sign gives his printed sum. (His second distance term, 0.3745,
        // is 0.374585 truncated; the sum is unaffected.)
        assert_abs_diff_eq!(deg(m.longitude_perturbation), -1.4132, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(m.latitude_perturbation), -0.1919, epsilon = HALF_4DP);
        assert_abs_diff_eq!(m.distance_perturbation, 0.0066, epsilon = HALF_4DP);
        assert!((-0.035 * m.mean_elongation.sin() - 0.0333).abs() < HALF_4DP);
        // long = 306.9484°, lat = −0.5856°, r = 60.6779; RA = 309.5011°, Decl = −19.1032°.
        let e = m.ecliptic();
        assert_abs_diff_eq!(deg(e.longitude), 306.9484, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(e.latitude), -0.5856, epsilon = HALF_4DP);
        assert_abs_diff_eq!(e.distance_earth_radii, 60.6779, epsilon = HALF_4DP);
        let (ra, dec, _) = spherical(equatorial_vector(e.longitude, e.latitude, 1.0, D));
        assert_abs_diff_eq!(deg(ra), 309.5011, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(dec), -19.1032, epsilon = HALF_4DP);
        assert_eq!(moon_ecliptic(D), e);
    }

    #[test]
    fn worked_example_moon_topocentric() {
        // §9: LST = 221.8388°, HA = −87.6623° = 272.3377°; at 60° N gclat = 59.83°, rho = 0.9975;
        // mpar = 0.9443°, g = 88.642°; topRA = 310.0017°, topDecl = −19.8790°.
        let e = moon_ecliptic(D);
        let observer = crate::Observer::from_degrees(60.0, 15.0, 0.0).unwrap();
        let lst = local_sidereal_time(D, 0.0, observer.longitude());
        let geo = equatorial_vector(e.longitude, e.latitude, e.distance_earth_radii, D);
        let (ra, _, _) = spherical(geo);
        assert_abs_diff_eq!(deg(lst - ra), -87.6623, epsilon = HALF_4DP);
        assert_abs_diff_eq!(deg(rev(lst - ra)), 272.3377, epsilon = HALF_4DP);
        let (rc, rs) = observer.geocentric_terms();
        assert_abs_diff_eq!(deg(rs.atan2(rc)), 59.83, epsilon = HALF_2DP);
        assert_abs_diff_eq!(rc.hypot(rs), 0.9975, epsilon = HALF_4DP);
        let mpar = (1.0 / e.distance_earth_radii).asin();
        assert_abs_diff_eq!(deg(mpar), 0.9443, epsilon = HALF_4DP);
        let g = (rs.atan2(rc).tan() / (lst - ra).cos()).atan();
        // g from our exact geocentric latitude (59.8331°) is 88.6418°, his from 59.83° 88.642°.
        assert_abs_diff_eq!(deg(g), 88.642, epsilon = HALF_3DP);
        let (top_ra, top_dec, _) = spherical(crate::coords::topocentric(geo, lst, &observer));
        assert_abs_diff_eq!(deg(top_ra), 310.0017, epsilon = SCHLYTER_FIRST_ORDER_PARALLAX_DEG);
        assert_abs_diff_eq!(deg(top_dec), -19.8790, epsilon = SCHLYTER_FIRST_ORDER_PARALLAX_DEG);
    }

    #[test]
    fn worked_example_against_the_astronomical_almanac() {
        // Schlyter's comparison (tutorial §5, §8): the Astronomical Almanac gives the Sun at
        // λ = 28.6813°, r = 1.004311 (his: +20″, +1.2×10⁻⁵) and RA 1h 46m 36.0s, Decl +11° 0′ 22″;
        // the Moon at λ = 306.94°, β = −0.55°, RA 309.4881°, Decl −19.0741°. Tolerances: his
        // stated aim, 1′ for the Sun and "1–2′" for the Moon (2′), plus half a unit of the
        // almanac's λ, β printed to 0.01°; the distance to 2×10⁻⁵ AU (his 1/3 Earth radius).
        const SUN_ALMANAC_DEG: f64 = 1.0 / 60.0;
        const SUN_ALMANAC_AU: f64 = 2e-5;
        const MOON_ALMANAC_DEG: f64 = 2.0 / 60.0;
        const ALMANAC_2DP: f64 = 5e-3;
        let s = sun_orbit(D);
        assert_abs_diff_eq!(deg(s.longitude), 28.6813, epsilon = SUN_ALMANAC_DEG);
        assert_abs_diff_eq!(s.distance_au, 1.004311, epsilon = SUN_ALMANAC_AU);
        let (ra, dec, _) = spherical(equatorial_vector(s.longitude, 0.0, 1.0, D));
        assert_abs_diff_eq!(deg(ra), (1.0 + 46.0 / 60.0 + 36.0 / 3600.0) * 15.0, epsilon = SUN_ALMANAC_DEG);
        assert_abs_diff_eq!(deg(dec), 11.0 + 22.0 / 3600.0, epsilon = SUN_ALMANAC_DEG);
        let m = moon_ecliptic(D);
        assert_abs_diff_eq!(deg(m.longitude), 306.94, epsilon = MOON_ALMANAC_DEG + ALMANAC_2DP);
        assert_abs_diff_eq!(deg(m.latitude), -0.55, epsilon = MOON_ALMANAC_DEG + ALMANAC_2DP);
        let (ra, dec, _) = spherical(equatorial_vector(m.longitude, m.latitude, 1.0, D));
        assert_abs_diff_eq!(deg(ra), 309.4881, epsilon = MOON_ALMANAC_DEG);
        assert_abs_diff_eq!(deg(dec), -19.0741, epsilon = MOON_ALMANAC_DEG);
    }
}
