"""The models from Python: the same numbers as the `brine` command, checks against independent
formulas and packages, and bad input raising."""

import datetime as dt
import math

import numpy as np
import pytest

import brine

PARIS = dict(lat=48.8566, lon=2.3522)


# --- The same values as the command line (exact: JSON carries every bit of a float). -------


def test_sun_equals_the_cli(brine_cli):
    times = ["2024-06-21T12:00:00Z", "2024-12-21T08:30:00Z", "1999-08-11T10:15:00Z"]
    py = brine.sun_position(times, **PARIS, refraction=True)
    for i, t in enumerate(times):
        cli = brine_cli("sun", "--lat", "48.8566", "--lon", "2.3522", "--time", t, "--refraction", "--json")
        assert py["altitude_deg"][i] == cli["altitude_deg"]
        assert py["azimuth_deg"][i] == cli["azimuth_deg"]
        assert py["distance_au"][i] == cli["distance_au"]


def test_moon_equals_the_cli(brine_cli):
    t = "2024-03-25T07:00:00Z"
    py = brine.moon_position([t], **PARIS)
    cli = brine_cli("moon", "--lat", "48.8566", "--lon", "2.3522", "--time", t, "--json")
    for k in ["altitude_deg", "azimuth_deg", "distance_km", "phase_angle_deg", "illuminated_fraction"]:
        assert py[k][0] == cli[k], k


def test_spectrum_and_fit_equal_the_cli(brine_cli):
    cli = brine_cli("spectrum", "--model", "jonswap", "--u10", "12", "--fetch-m", "50000", "--samples", "7", "--json")
    py = brine.spectrum(np.array(cli["omega"]), model="jonswap", u10=12, fetch_m=50000)
    assert py["s"].tolist() == cli["s"]
    assert py["peak_omega_rad_s"] == cli["peak_omega_rad_s"]
    fit = brine_cli("fit", "--u10", "9", "--waves", "12", "--seed", "3", "--json")
    pyfit = brine.fit_trochoids(u10=9, waves=12, seed=3)
    assert pyfit["amplitude_m"].tolist() == [w["amplitude_m"] for w in fit["waves"]]
    assert pyfit["direction_rad"].tolist() == [w["direction_rad"] for w in fit["waves"]]
    assert pyfit["total_steepness"] == fit["total_steepness"]


def test_optics_equal_the_cli(brine_cli):
    cli = brine_cli("optics", "fresnel", "--n1", "1.0", "--n2", "1.34", "--cos-theta", "0.3", "--json")
    py = brine.fresnel([0.3], n1=1.0, n2=1.34)
    assert py["reflectance"][0] == cli["reflectance"] and py["schlick"][0] == cli["schlick"]
    cli = brine_cli("optics", "water", "--type", "II", "--wavelength-nm", "420,480,550", "--json")
    py = brine.water_iops([420, 480, 550], type="II")
    assert py["absorption"].tolist() == cli["absorption"] and py["kd"].tolist() == cli["kd"]


def test_sky_equals_the_cli(brine_cli):
    args = ["--sun-elevation-deg", "25", "--sun-azimuth-deg", "120", "--turbidity", "4"]
    cli = brine_cli("sky", *args, "--view-elevation-deg", "12", "--view-azimuth-deg", "200", "--json")
    py = brine.sky_radiance([12], [200], sun_elevation_deg=25, sun_azimuth_deg=120, turbidity=4)
    assert py["rgb"][0].tolist() == cli["rgb_kcd_m2"] and py["xyz"][0].tolist() == cli["xyz_kcd_m2"]


def test_white_water_equals_the_cli(brine_cli):
    cli = brine_cli("foam", "--u10", "14", "--t-water-c", "15", "--t-air-c", "12", "--json")
    assert brine.whitecap_coverage([14], t_water_c=15, t_air_c=12)[0] == cli["coverage"]
    assert brine.foam_report(u10=14, t_water_c=15, t_air_c=12) == cli
    assert brine.spray_report(u10=20) == brine_cli("spray", "--u10", "20", "--json")


# --- Against independent packages and formulas. ---------------------------------------------


def test_sun_and_moon_agree_with_pyephem():
    ephem = pytest.importorskip("ephem")
    when = [dt.datetime(2024, m, 15, h, 0, tzinfo=dt.timezone.utc) for m in (1, 4, 7, 10) for h in (6, 12, 18)]
    sun = brine.sun_position(when, **PARIS)
    moon = brine.moon_position(when, **PARIS)
    obs = ephem.Observer()
    obs.lat, obs.lon, obs.elevation, obs.pressure = str(PARIS["lat"]), str(PARIS["lon"]), 0.0, 0.0
    for i, w in enumerate(when):
        obs.date = w.replace(tzinfo=None)
        s, m = ephem.Sun(obs), ephem.Moon(obs)
        # Airless apparent positions; NREL SPA is ±0.0003°, PyEphem (VSOP87) a few arcseconds.
        assert sun["altitude_deg"][i] == pytest.approx(math.degrees(s.alt), abs=0.01)
        assert sun["azimuth_deg"][i] == pytest.approx(math.degrees(s.az), abs=0.02)
        # Schlyter's lunar series is good to a few arcminutes; PyEphem's ELP to arcseconds.
        assert moon["altitude_deg"][i] == pytest.approx(math.degrees(m.alt), abs=0.1)
        assert moon["illuminated_fraction"][i] == pytest.approx(m.moon_phase, abs=0.005)


def test_fresnel_matches_the_equations():
    n1, n2 = 1.0, 1.34
    c = np.linspace(0.0, 1.0, 101)
    s = np.sqrt(np.maximum(0.0, 1.0 - (n1 / n2) ** 2 * (1.0 - c**2)))
    rs = ((n1 * c - n2 * s) / (n1 * c + n2 * s)) ** 2
    rp = ((n1 * s - n2 * c) / (n1 * s + n2 * c)) ** 2
    np.testing.assert_allclose(brine.fresnel(c, n1=n1, n2=n2)["reflectance"], 0.5 * (rs + rp), atol=1e-12)


def test_whitecap_law_and_spray_source_match_the_papers():
    u = np.array([4.0, 8.0, 12.0, 20.0])
    # Monahan & Ó Muircheartaigh 1980: W = 3.84e-6 U^3.41.
    np.testing.assert_allclose(brine.whitecap_coverage(u), 3.84e-6 * u**3.41, rtol=1e-12)
    # Monahan, Spiel & Davidson 1986, the bubble-mediated source function.
    r = np.array([0.8, 2.0, 5.0, 10.0])
    b = (0.380 - np.log10(r)) / 0.650
    msd = 1.373 * 10.0**3.41 * r**-3 * (1 + 0.057 * r**1.05) * 10 ** (1.19 * np.exp(-b * b))
    np.testing.assert_allclose(brine.spray_flux(r, 10.0), msd, rtol=1e-12)


def test_spectra_and_spreading_integrate_as_they_must():
    w = np.linspace(0.05, 25.0, 200_001)
    sp = brine.spectrum(w, model="pm", u10=10)
    hs = 4.0 * math.sqrt(np.trapezoid(sp["s"], w))
    assert hs == pytest.approx(sp["significant_wave_height_m"], rel=1e-3)
    theta = np.linspace(-math.pi, math.pi, 20_001)
    for model in ["hasselmann", "donelan-banner", "cos2", "mitsuyasu"]:
        d = brine.spreading(theta, 1.2, spreading=model, u10=10)
        assert np.trapezoid(d, theta) == pytest.approx(1.0, abs=2e-3), model


def test_arrays_keep_their_shape():
    t = np.array([["2024-01-01T00:00", "2024-01-01T06:00"]], dtype="datetime64[s]")
    assert brine.sun_position(t, **PARIS)["altitude_deg"].shape == (1, 2)
    grid = brine.sky_radiance(np.full((3, 4), 30.0), np.zeros((3, 4)), sun_elevation_deg=40)
    assert grid["rgb"].shape == (3, 4, 3)
    assert brine.spray_flux(np.ones((2, 5)), 12.0).shape == (2, 5)


# --- Bad input. -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: brine.spectrum([1.0], u10=100), "u10"),
        (lambda: brine.spectrum([-1.0], u10=10), "omega[0]"),
        (lambda: brine.spectrum([1.0], model="nope"), "nope"),
        (lambda: brine.spectrum([1.0], bogus=1), "bogus"),
        (lambda: brine.sun_position([0.0], lat=100, lon=0), "lat"),
        (lambda: brine.sun_position([float("nan")], lat=10, lon=0), "unix_s[0]"),
        (lambda: brine.fresnel([1.5], n1=1.0, n2=1.34), "cos"),
        (lambda: brine.water_iops([100.0], type="I"), "wavelength"),
        (lambda: brine.sky_radiance([95.0], [0.0], sun_elevation_deg=30), "elevation"),
        (lambda: brine.whitecap_coverage([70.0]), "u10"),
        (lambda: brine.spray_flux([0.0], 10.0), "r80_um"),
        (lambda: brine.fit_trochoids(waves=0), "waves"),
    ],
)
def test_bad_input_raises_a_named_error(call, words):
    with pytest.raises(brine.BrineError) as e:
        call()
    assert words in str(e.value)
    assert isinstance(e.value, ValueError)
