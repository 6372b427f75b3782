"""Reference sun and moon positions for brine-ephem's tests (tests/reference_values.rs).

Generates `reference_positions.csv`: 2000 instants drawn uniformly over 1950-01-01 .. 2050-12-31 UTC
(seed 4), each at a place drawn uniformly on the sphere's land-or-sea (latitude in [-65, 65] deg,
longitude in [-180, 180) deg, height 0 m). For each, the topocentric *airless* (no refraction)
altitude and azimuth (from north through east) of the Sun and the Moon, the geocentric distances,
and the Moon's illuminated fraction.

Ephemeris: astropy 8.0 (8.0.2, pyerfa 2.0.1.5) with `solar_system_ephemeris = "builtin"`:
- Moon: ERFA `eraMoon98` (Meeus 1998, Astronomical Algorithms ch. 47, full ELP-2000/82 truncation);
  ERFA documents RMS errors of 2.9 arcsec (worst 18.3 arcsec) in geocentric direction against
  ELP/MPP02 over 1950-2100.
- Sun/Earth: ERFA `eraEpv00` (VSOP2000 fit; errors of a few km in the Earth's position, i.e.
  well below 0.1 arcsec in direction).
- Frames: GCRS -> AltAz (IAU 2006/2000A precession-nutation, annual aberration and light time
  included, polar motion from the bundled IERS tables or their 50-year mean), UT1 = UTC,
  pressure 0 (no refraction).

Run: `python3 -m venv v && v/bin/pip install astropy && v/bin/python make_reference_positions.py`.
"""

import numpy as np
from astropy import units as u
from astropy.coordinates import AltAz, EarthLocation, get_body, solar_system_ephemeris
from astropy.time import Time
from astropy.utils import iers

iers.conf.auto_download = False
iers.conf.iers_degraded_accuracy = "warn"

rng = np.random.default_rng(4)
n = 2000
t0 = Time("1950-01-01T00:00:00", scale="utc").unix
t1 = Time("2050-12-31T00:00:00", scale="utc").unix
unix = np.round(rng.uniform(t0, t1, n))
lat = np.round(np.degrees(np.arcsin(rng.uniform(np.sin(np.radians(-65)), np.sin(np.radians(65)), n))), 4)
lon = np.round(rng.uniform(-180.0, 180.0, n), 4)

# The labels written to the CSV, to the second; the positions are computed at exactly these
# labels (on a day with a leap second, astropy's "unix" instants fall a fraction of a second
# after their truncated labels, 0.24 s on 2008-12-31, i.e. 0.0009 deg of solar motion).
labels = [s[:19] for s in Time(unix, format="unix", scale="utc").isot]
times = Time(labels, format="isot", scale="utc")
# The models under test take the UTC instant as UT1 (as SPA and Schlyter do): set UT1 = UTC so that
# both sides see the same Earth rotation. TT - UTC follows the leap-second table (32.184 s before
# 1961, 69.184 s after 2017), within 30 s of the true Delta T: 15 arcsec of lunar motion at most.
times.delta_ut1_utc = np.zeros(n)
loc = EarthLocation.from_geodetic(lon * u.deg, lat * u.deg, 0 * u.m)
frame = AltAz(obstime=times, location=loc, pressure=0 * u.hPa)
with solar_system_ephemeris.set("builtin"):
    sun = get_body("sun", times, loc)
    moon = get_body("moon", times, loc)
    sun_geo = get_body("sun", times)
    moon_geo = get_body("moon", times)
sun_h = sun.transform_to(frame)
moon_h = moon.transform_to(frame)
elong = sun_geo.separation(moon_geo).rad
r_sun = sun_geo.distance.to(u.km).value
r_moon = moon_geo.distance.to(u.km).value
phase = np.arctan2(r_sun * np.sin(elong), r_moon - r_sun * np.cos(elong))
frac = (1 + np.cos(phase)) / 2

with open("reference_positions.csv", "w") as f:
    f.write(__doc__.replace("\n", "\n# ").replace('"""', "").strip().join(["# ", "\n"]))
    f.write(
        "utc,latitude_deg,longitude_deg,sun_altitude_deg,sun_azimuth_deg,sun_distance_au,"
        "moon_altitude_deg,moon_azimuth_deg,moon_distance_km,moon_illuminated_fraction\n"
    )
    for i in range(n):
        iso = labels[i] + "Z"
        f.write(
            f"{iso},{lat[i]:.4f},{lon[i]:.4f},{sun_h.alt.deg[i]:.6f},{sun_h.az.deg[i]:.6f},"
            f"{sun_geo.distance.to(u.au).value[i]:.8f},{moon_h.alt.deg[i]:.6f},{moon_h.az.deg[i]:.6f},"
            f"{r_moon[i]:.3f},{frac[i]:.6f}\n"
        )
