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

#[test]
fn full_moon_is_opposite_the_sun() {
    let o = Observer::from_degrees(43.6, 1.44, 0.0).unwrap();
    for when in FULL_MOONS_2024 {
        let t = parse_utc(when).unwrap();
        let m = moon_position(t, &o, &Options::default()).unwrap();
        let s = sun_position(t, &o, SunModel::Spa, &Options::default()).unwrap();
        // Opposite within the Moon's latitude (≤ 5.3°) and its parallax (≤ 1°).
        let sep = angle_deg(m.horizontal(), s.horizontal());
        assert!(sep > 173.5, "{when}: sun–moon {sep}°");
        // The elongation is 180° − |β| at opposition: illuminated fraction ≥ cos²(5.3°/2) = 0.9979.
        assert!(m.illuminated_fraction > 0.997, "{when}: k = {}", m.illuminated_fraction);
        assert!(m.phase_angle.to_degrees() < 5.6, "{when}: i = {}", m.phase_angle.to_degrees());
    }
    // A new moon (2024-06-06 12:38 UTC) is dark.
    let t = parse_utc("2024-06-06T12:38:00Z").unwrap();
    let m = moon_position(t, &o, &Options::default()).unwrap();
    assert!(m.illuminated_fraction < 0.003, "k = {}", m.illuminated_fraction);
}

#[test]
fn positions_are_continuous_over_a_day() {
    // Over one minute the Sun and the Moon move by at most 0.25° + 0.01° across the sky; the
    // refraction stretches altitudes near the horizon by up to 1 + 0.57 (its fade below −0.83°).
    for ((lat, lon), refraction) in [(43.6, 1.44), (-70.0, 30.0), (89.0, 0.0), (0.0, 179.9)]
        .into_iter()
        .flat_map(|p| [(p, None), (p, Some(Atmosphere::standard()))])
    {
        let limit = if refraction.is_some() { 0.26 * 1.6 } else { 0.26 };
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
            // Perihelion 0.98329 AU, aphelion 1.01671 AU.
            prop_assert!((0.9832..=1.0168).contains(&s.distance_au), "r = {}", s.distance_au);
        }
        let m = moon_position(t, &o, &opts).unwrap();
        prop_assert!(m.altitude.abs() <= std::f64::consts::FRAC_PI_2);
        prop_assert!((0.0..std::f64::consts::TAU).contains(&m.azimuth));
        // Perigee and apogee extremes of 1950–2050: 356 371 km and 406 720 km (Meeus ch. 50).
        prop_assert!((355_500.0..=407_500.0).contains(&m.distance_km), "Δ = {}", m.distance_km);
        prop_assert!((m.topocentric_distance_km - m.distance_km).abs() <= 6_400.0);
        prop_assert!((0.0..=1.0).contains(&m.illuminated_fraction));
        prop_assert!((0.0..=std::f64::consts::PI).contains(&m.phase_angle));
        // Apogee seen from the far side (413 100 km) to perigee overhead (350 000 km).
        prop_assert!((0.24..0.29).contains(&m.angular_radius().to_degrees()), "{}", m.angular_radius().to_degrees());
    }
}
