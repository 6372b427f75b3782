//! Analytic limits and properties of brine-ephem: solar noon at the solstices and equinoxes, the
//! full moon opposite the Sun, continuity over a day, and ranges on random instants and places.

use brine_ephem::{Atmosphere, Horizontal, Observer, Options, SunModel, moon_position, parse_utc, sun_position};
use jiff::{SignedDuration, Timestamp};
use proptest::prelude::*;

/// Angle between two horizontal directions (degrees).
fn angle_deg(a: Horizontal, b: Horizontal) -> f64 {
    let (u, v) = (a.direction(), b.direction());
    let c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]).clamp(-1.0, 1.0);
    let cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    (cross[0].hypot(cross[1]).hypot(cross[2])).atan2(c).to_degrees()
}

/// Highest altitude (degrees) of the Sun within ±3 h of `t`, by 20 s steps and a parabola.
fn max_altitude(t: Timestamp, o: &Observer, model: SunModel) -> f64 {
    let alt = |s: i64| {
        let ti = t.checked_add(SignedDuration::from_secs(s)).unwrap();
        sun_position(ti, o, model, &Options::default()).unwrap().altitude.to_degrees()
    };
    let mut best = (-10_800, f64::NEG_INFINITY);
    for s in (-10_800..=10_800).step_by(20) {
        let a = alt(s);
        if a > best.1 {
            best = (s, a);
        }
    }
    // Parabolic refinement through the three samples around the maximum.
    let (a0, a1, a2) = (alt(best.0 - 20), best.1, alt(best.0 + 20));
    let den = a0 - 2.0 * a1 + a2;
    if den.abs() > 0.0 { a1 - (a2 - a0).powi(2) / (8.0 * den) } else { a1 }
}

/// Solar noon altitude: `90° − |φ − δ|`, δ = ±ε at the solstices, 0 at the equinoxes. The
/// obliquity of date in 2024 is 23.4361° (IAU 2006: 23.43929° − 0.013° T, T = 0.244).
/// Tolerance 0.03°: within ±1 h of an equinox δ moves by 0.016°, Schlyter's Sun adds 0.01°.
const NOON_DEG: f64 = 0.03;

#[test]
fn solar_noon_at_solstices_and_equinoxes() {
    let eps = 23.4361;
    // (instant of the season (USNO, 2024), longitude whose local noon is near it, declination).
    let seasons = [
        ("2024-03-20T03:06:00Z", 133.5, 0.0),
        ("2024-06-20T20:51:00Z", -132.75, eps),
        ("2024-09-22T12:44:00Z", -11.0, 0.0),
        ("2024-12-21T09:20:00Z", 40.0, -eps),
    ];
    for (when, lon, dec) in seasons {
        let t = parse_utc(when).unwrap();
        for lat in [-33.9, 0.0, 43.6, 60.0] {
            let o = Observer::from_degrees(lat, lon, 0.0).unwrap();
            for model in [SunModel::Spa, SunModel::Schlyter] {
                let expected: f64 = 90.0 - (lat - dec).abs();
                let got = max_altitude(t, &o, model);
                assert!((got - expected).abs() < NOON_DEG, "{when} {lat}° {model:?}: {got} vs {expected}");
            }
        }
    }
}

/// Full moons of 2024 (Espenak & Meeus, "Six Millennium Catalog of Phases of the Moon"; USNO):
/// at these instants the Moon's ecliptic longitude is the Sun's + 180°.
const FULL_MOONS_2024: [&str; 12] = [
    "2024-01-25T17:54:00Z",
    "2024-02-24T12:30:00Z",
    "2024-03-25T07:00:00Z",
    "2024-04-23T23:49:00Z",
    "2024-05-23T13:53:00Z",
    "2024-06-22T01:08:00Z",
    "2024-07-21T10:17:00Z",
    "2024-08-19T18:26:00Z",
    "2024-09-18T02:34:00Z",
    "2024-10-17T11:26:00Z",
    "2024-11-15T21:28:00Z",
    "2024-12-15T09:02:00Z",
];

/// Smallest Sun–Moon separation at full moon: 180° less the Moon's greatest ecliptic latitude
/// (5.3°) and its parallax (1°), plus 0.2° for the topocentric Sun and the 1-minute catalogue
/// rounding (the Moon moves 0.55′ per minute relative to the Sun).
const FULL_MOON_MIN_SEPARATION_DEG: f64 = 173.5;
/// Smallest illuminated fraction at full moon: the elongation is at least 180° − 5.3°, so
/// `k ≥ cos²(5.3°/2) = 0.9979`; 0.997 leaves the 0.0008 measured error of `k`.
const FULL_MOON_MIN_FRACTION: f64 = 0.997;
/// Largest phase angle at full moon: the Moon's latitude 5.3° plus 0.3° (minute rounding and the
/// Meeus phase-angle correction with the distances).
const FULL_MOON_MAX_PHASE_DEG: f64 = 5.6;
/// Largest illuminated fraction at new moon: `(1 − cos 5.6°)/2 = 0.0024`, rounded up.
const NEW_MOON_MAX_FRACTION: f64 = 0.003;

#[test]
fn full_moon_is_opposite_the_sun() {
    let o = Observer::from_degrees(43.6, 1.44, 0.0).unwrap();
    for when in FULL_MOONS_2024 {
        let t = parse_utc(when).unwrap();
        let m = moon_position(t, &o, &Options::default()).unwrap();
        let s = sun_position(t, &o, SunModel::Spa, &Options::default()).unwrap();
        // Opposite within the Moon's latitude (≤ 5.3°) and its parallax (≤ 1°).
        let sep = angle_deg(m.horizontal(), s.horizontal());
        assert!(sep > FULL_MOON_MIN_SEPARATION_DEG, "{when}: sun–moon {sep}°");
        // The elongation is 180° − |β| at opposition: illuminated fraction ≥ cos²(5.3°/2) = 0.9979.
        assert!(m.illuminated_fraction > FULL_MOON_MIN_FRACTION, "{when}: k = {}", m.illuminated_fraction);
        assert!(m.phase_angle.to_degrees() < FULL_MOON_MAX_PHASE_DEG, "{when}: i = {}", m.phase_angle.to_degrees());
    }
    // A new moon (2024-06-06 12:38 UTC) is dark.
    let t = parse_utc("2024-06-06T12:38:00Z").unwrap();
    let m = moon_position(t, &o, &Options::default()).unwrap();
    assert!(m.illuminated_fraction < NEW_MOON_MAX_FRACTION, "k = {}", m.illuminated_fraction);
}

/// Largest motion across the sky in one minute: the Earth's rotation moves the Sun and the Moon
/// by at most 0.25° (0.2507° sidereal), plus 0.01° for the Moon's parallax change and own motion.
const MOTION_PER_MINUTE_DEG: f64 = 0.26;
/// The refraction stretches the apparent altitude near the horizon by up to 1 + 0.57 (its fade
/// below −0.83°): 1.6.
const REFRACTION_STRETCH: f64 = 1.6;

#[test]
fn positions_are_continuous_over_a_day() {
    for ((lat, lon), refraction) in [(43.6, 1.44), (-70.0, 30.0), (89.0, 0.0), (0.0, 179.9)]
        .into_iter()
        .flat_map(|p| [(p, None), (p, Some(Atmosphere::standard()))])
    {
        let limit =
            if refraction.is_some() { MOTION_PER_MINUTE_DEG * REFRACTION_STRETCH } else { MOTION_PER_MINUTE_DEG };
        let o = Observer::from_degrees(lat, lon, 0.0).unwrap();
        let start = parse_utc("2024-06-21T00:00:00Z").unwrap();
        let opts = Options { refraction, delta_t_s: None };
        let at = |i: i64| start.checked_add(SignedDuration::from_mins(i)).unwrap();
        let mut last: Option<(Horizontal, Horizontal, Horizontal)> = None;
        for i in 0..=1440 {
            let t = at(i);
            let a = sun_position(t, &o, SunModel::Spa, &opts).unwrap().horizontal();
            let b = sun_position(t, &o, SunModel::Schlyter, &opts).unwrap().horizontal();
            let c = moon_position(t, &o, &opts).unwrap().horizontal();
            if let Some((pa, pb, pc)) = last {
                for (p, q) in [(pa, a), (pb, b), (pc, c)] {
                    assert!(angle_deg(p, q) < limit, "jump of {}° at {lat}, {lon}, minute {i}", angle_deg(p, q));
                }
            }
            last = Some((a, b, c));
        }
    }
}

/// Earth–Sun distance range (AU): perihelion 0.98329, aphelion 1.01671 (1950–2050), widened by the
/// 7.6×10⁻⁵ AU error of Schlyter's elements.
const SUN_DISTANCE_AU: std::ops::RangeInclusive<f64> = 0.9832..=1.0168;
/// Geocentric Moon distance range (km): perigee 356 371 km and apogee 406 720 km are the
/// extremes of 1950–2050 (Meeus ch. 50), widened by the model's 0.33 % (about 1 300 km) error.
const MOON_DISTANCE_KM: std::ops::RangeInclusive<f64> = 355_000.0..=408_000.0;
/// The observer is at most one Earth radius plus 5 km from the centre: 6 400 km.
const TOPOCENTRIC_OFFSET_KM: f64 = 6_400.0;
/// The Moon's angular radius (degrees): from 0.24° (apogee, seen from the far side, 413 100 km)
/// to 0.29° (perigee overhead, 350 000 km).
const MOON_RADIUS_DEG: std::ops::Range<f64> = 0.24..0.29;

/// The illuminated fraction from the phase angle against that from the elongation: the Sun's
/// parallax seen from the Moon (`Δ_moon/Δ_sun ≤ 0.0027`) moves `k` by at most half of it.
const ELONGATION_FRACTION: f64 = 0.0015;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn ranges_over_1950_2050(
        secs in -631_152_000i64..2_556_057_600i64,
        lat in -90.0f64..=90.0,
        lon in -180.0f64..360.0,
        height in 0.0f64..5000.0,
        refract in any::<bool>(),
    ) {
        let t = Timestamp::from_second(secs).unwrap();
        let o = Observer::from_degrees(lat, lon, height).unwrap();
        let opts = Options { refraction: refract.then(Atmosphere::standard), delta_t_s: None };
        for model in [SunModel::Spa, SunModel::Schlyter] {
            let s = sun_position(t, &o, model, &opts).unwrap();
            prop_assert!(s.altitude.abs() <= std::f64::consts::FRAC_PI_2);
            prop_assert!((0.0..std::f64::consts::TAU).contains(&s.azimuth));
            prop_assert!(SUN_DISTANCE_AU.contains(&s.distance_au), "r = {}", s.distance_au);
        }
        let m = moon_position(t, &o, &opts).unwrap();
        prop_assert!(m.altitude.abs() <= std::f64::consts::FRAC_PI_2);
        prop_assert!((0.0..std::f64::consts::TAU).contains(&m.azimuth));
        prop_assert!(MOON_DISTANCE_KM.contains(&m.distance_km), "Δ = {}", m.distance_km);
        prop_assert!((m.topocentric_distance_km - m.distance_km).abs() <= TOPOCENTRIC_OFFSET_KM);
        // The illuminated fraction `(1 + cos i)/2` against the elongation ψ's `(1 − cos ψ)/2`
        // (`i ≈ π − ψ` for a Sun at infinity; the Sun's finite distance moves `i` by up to
        // Δ_moon/Δ_sun ≈ 0.0026 rad, so `k` by up to 0.0013).
        let from_elongation = 0.5 * (1.0 - m.elongation.cos());
        prop_assert!((m.illuminated_fraction - from_elongation).abs() < ELONGATION_FRACTION, "k = {}", m.illuminated_fraction);
        prop_assert!((0.0..=std::f64::consts::PI).contains(&m.phase_angle));
        prop_assert!(MOON_RADIUS_DEG.contains(&m.angular_radius().to_degrees()), "{}", m.angular_radius().to_degrees());
    }
}
