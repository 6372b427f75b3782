//! The model functions: ephemerides, spectra and the fit, optics, sky, white water and spray, each
//! evaluated over arrays with the scalar parameters of the matching `brine` subcommand.

use brine_render::cli::{self, Command};
use glam::DVec3;
use numpy::{IntoPyArray, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use crate::{bad, parse_cli, py_err};

/// Registers the functions of this file in the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(sun_position, m)?)?;
    m.add_function(wrap_pyfunction!(moon_position, m)?)?;
    m.add_function(wrap_pyfunction!(spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(spreading, m)?)?;
    m.add_function(wrap_pyfunction!(fit_trochoids, m)?)?;
    m.add_function(wrap_pyfunction!(fresnel, m)?)?;
    m.add_function(wrap_pyfunction!(water_iops, m)?)?;
    m.add_function(wrap_pyfunction!(sky_radiance, m)?)?;
    m.add_function(wrap_pyfunction!(whitecap_coverage, m)?)?;
    m.add_function(wrap_pyfunction!(spray_flux, m)?)?;
    m.add_function(wrap_pyfunction!(report, m)?)?;
    Ok(())
}

/// Work items per rayon task: small arrays stay on one thread.
const MIN_CHUNK: usize = 1024;

/// An array argument copied out of numpy (the work then runs without Python's lock).
fn values(a: &PyReadonlyArray1<'_, f64>) -> PyResult<Vec<f64>> {
    Ok(a.as_slice()?.to_vec())
}

/// Evaluates `f` on every element in parallel; the first error names its index and value.
fn map_checked<T: Send>(xs: &[f64], name: &str, f: impl Fn(f64) -> Result<T, String> + Sync) -> Result<Vec<T>, String> {
    xs.par_iter()
        .with_min_len(MIN_CHUNK)
        .enumerate()
        .map(|(i, &x)| f(x).map_err(|m| format!("{name}[{i}] = {x}: {m}")))
        .collect()
}

/// Sets `key` of `d` to the array `v`.
fn put(d: &Bound<'_, PyDict>, key: &str, v: Vec<f64>) -> PyResult<()> {
    d.set_item(key, v.into_pyarray(d.py()))
}

/// An instant given as seconds since 1970-01-01T00:00:00 UTC.
fn timestamp(t: f64) -> Result<brine_ephem::Timestamp, String> {
    if !t.is_finite() {
        return Err("expected a finite number of seconds since 1970-01-01T00:00:00Z".into());
    }
    let secs = t.floor();
    let nanos = (((t - secs) * 1e9).round() as i32).min(999_999_999);
    brine_ephem::Timestamp::new(secs as i64, nanos).map_err(|e| e.to_string())
}

/// The observer and options of `brine sun` / `brine moon` from the keywords (the instant comes
/// from the array).
fn place(sub: &str, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<(cli::ephem::SunArgs, bool)> {
    let fixed = [("time", "2000-01-01T12:00:00Z".to_owned())];
    match parse_cli(&[sub], &fixed, kwargs)? {
        Command::Sun(a) => Ok((a, true)),
        Command::Moon(a) => Ok((cli::ephem::SunArgs { place: a.place, model: cli::ephem::SunModelArg::Spa }, false)),
        _ => Err(bad("not an ephemeris")),
    }
}

/// Apparent position of the Sun at each instant.
///
/// Keywords as `brine sun`: `lat`, `lon` (degrees, required), `height_m`, `refraction`,
/// `pressure_hpa`, `temperature_c`, `model` (`"spa"` or `"schlyter"`).
///
/// Returns a dict of arrays: `altitude_deg`, `azimuth_deg` (from north through east),
/// `distance_au`.
#[pyfunction]
#[pyo3(signature = (unix_s, **kwargs))]
fn sun_position<'py>(
    py: Python<'py>,
    unix_s: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (args, _) = place("sun", kwargs)?;
    let (_, observer, options) = args.place.resolve().map_err(py_err)?;
    let model = args.model.model();
    let ts = values(&unix_s)?;
    let out = py
        .detach(|| {
            map_checked(&ts, "unix_s", |t| {
                let p =
                    brine_ephem::sun_position(timestamp(t)?, &observer, model, &options).map_err(|e| e.to_string())?;
                Ok([p.altitude.to_degrees(), p.azimuth.to_degrees(), p.distance_au])
            })
        })
        .map_err(bad)?;
    let d = PyDict::new(py);
    for (k, key) in ["altitude_deg", "azimuth_deg", "distance_au"].iter().enumerate() {
        put(&d, key, out.iter().map(|v| v[k]).collect())?;
    }
    Ok(d)
}

/// Apparent (topocentric) position and phase of the Moon at each instant.
///
/// Keywords as `brine moon`: `lat`, `lon` (degrees, required), `height_m`, `refraction`,
/// `pressure_hpa`, `temperature_c`.
///
/// Returns a dict of arrays: `altitude_deg`, `azimuth_deg`, `distance_km` (geocentric),
/// `phase_angle_deg`, `illuminated_fraction`.
#[pyfunction]
#[pyo3(signature = (unix_s, **kwargs))]
fn moon_position<'py>(
    py: Python<'py>,
    unix_s: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (args, _) = place("moon", kwargs)?;
    let (_, observer, options) = args.place.resolve().map_err(py_err)?;
    let ts = values(&unix_s)?;
    let out = py
        .detach(|| {
            map_checked(&ts, "unix_s", |t| {
                let p = brine_ephem::moon_position(timestamp(t)?, &observer, &options).map_err(|e| e.to_string())?;
                Ok([
                    p.altitude.to_degrees(),
                    p.azimuth.to_degrees(),
                    p.distance_km,
                    p.phase_angle.to_degrees(),
                    p.illuminated_fraction,
                ])
            })
        })
        .map_err(bad)?;
    let d = PyDict::new(py);
    let keys = ["altitude_deg", "azimuth_deg", "distance_km", "phase_angle_deg", "illuminated_fraction"];
    for (k, key) in keys.iter().enumerate() {
        put(&d, key, out.iter().map(|v| v[k]).collect())?;
    }
    Ok(d)
}

/// The spectrum parameters of `brine spectrum` from the keywords.
fn spectrum_params(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<cli::waves::SpectrumParams> {
    match parse_cli(&["spectrum"], &[], kwargs)? {
        Command::Spectrum(a) => Ok(a.spectrum),
        _ => Err(bad("not a spectrum")),
    }
}

/// An ocean spectrum `S(ω)` at each angular frequency.
///
/// Keywords as `brine spectrum`: `model` (`"pm"`, `"jonswap"`, `"phillips"`, `"tma"`,
/// `"elfouhaily"`), `u10` (m/s), `fetch_m`, `depth_m`, `gamma`.
///
/// Returns a dict: `s` (m² s rad⁻¹, an array), `peak_omega_rad_s`, `significant_wave_height_m`,
/// `model`.
#[pyfunction]
#[pyo3(signature = (omega, **kwargs))]
fn spectrum<'py>(
    py: Python<'py>,
    omega: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let params = spectrum_params(kwargs)?;
    let s = params.build().map_err(py_err)?;
    let w = values(&omega)?;
    let check =
        |x: f64| if x > 0.0 && x.is_finite() { Ok(()) } else { Err("expected ω in (0, ∞) rad/s".to_owned()) };
    let out: Vec<f64> = {
        let mut v = Vec::with_capacity(w.len());
        for (i, &x) in w.iter().enumerate() {
            check(x).map_err(|m| bad(format!("omega[{i}] = {x}: {m}")))?;
            v.push(s.s_omega(x));
        }
        v
    };
    let d = PyDict::new(py);
    put(&d, "s", out)?;
    d.set_item("peak_omega_rad_s", s.peak_omega())?;
    d.set_item("significant_wave_height_m", s.significant_wave_height())?;
    d.set_item("model", params.model_name())?;
    Ok(d)
}

/// The fit arguments of `brine fit` from the keywords.
fn fit_args(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<cli::waves::FitArgs> {
    match parse_cli(&["fit"], &[], kwargs)? {
        Command::Fit(a) => Ok(a),
        _ => Err(bad("not a fit")),
    }
}

/// The directional spreading `D(θ; ω)` (rad⁻¹) at each pair of direction and frequency.
///
/// `theta`: direction from the wind (rad); `omega`: angular frequency (rad/s), `> 0`; arrays of
/// one length. Keywords as `brine fit`: `spreading` (`"hasselmann"`, `"mitsuyasu"`,
/// `"donelan-banner"`, `"elfouhaily"`, `"cos2"`) and the spectrum's (`model`, `u10`, `fetch_m`,
/// …), which set the peak frequency.
#[pyfunction]
#[pyo3(signature = (theta, omega, **kwargs))]
fn spreading<'py>(
    py: Python<'py>,
    theta: PyReadonlyArray1<'py, f64>,
    omega: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, numpy::PyArray1<f64>>> {
    let args = fit_args(kwargs)?;
    let s = args.spectrum.build().map_err(py_err)?;
    let d = cli::waves::spreading_of(&args, s.peak_omega()).map_err(py_err)?;
    let (th, w) = (values(&theta)?, values(&omega)?);
    if th.len() != w.len() {
        return Err(bad(format!("theta has {} values and omega {}: expected one length", th.len(), w.len())));
    }
    let mut out = Vec::with_capacity(th.len());
    for (i, (&t, &x)) in th.iter().zip(&w).enumerate() {
        if !(x > 0.0 && x.is_finite() && t.is_finite()) {
            return Err(bad(format!("(theta, omega)[{i}] = ({t}, {x}): expected a finite θ and ω in (0, ∞) rad/s")));
        }
        // θ wrapped to (−π, π], the density's domain.
        let pi = std::f64::consts::PI;
        let wrapped = (t + pi).rem_euclid(std::f64::consts::TAU) - pi;
        let wrapped = if wrapped <= -pi { pi } else { wrapped };
        out.push(d.density(wrapped, x));
    }
    Ok(out.into_pyarray(py))
}

/// The trochoid wave set fitted to a spectrum (Darles et al. 2007), as arrays.
///
/// Keywords as `brine fit`: `waves`, `seed`, `spreading`, `partition`, `amplitudes`,
/// `wind_direction_deg`, `choppiness`, `max_total_steepness`, `omega_min_factor`,
/// `omega_max_factor`, `high_frequency_gain`, `high_frequency_start_factor` and the spectrum's.
///
/// Returns a dict: arrays `amplitude_m`, `wavelength_m`, `direction_rad`, `omega_rad_s`,
/// `phase_rad`, `steepness`; numbers `variance_m2`, `total_amplitude_m`, `total_steepness`,
/// `peak_omega_rad_s`.
#[pyfunction]
#[pyo3(signature = (**kwargs))]
fn fit_trochoids<'py>(py: Python<'py>, kwargs: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyDict>> {
    let args = fit_args(kwargs)?;
    let (s, set) = cli::waves::fit_set(&args).map_err(py_err)?;
    let d = PyDict::new(py);
    let waves = set.waves();
    put(&d, "amplitude_m", waves.iter().map(|w| w.amplitude()).collect())?;
    put(&d, "wavelength_m", waves.iter().map(|w| w.wavelength()).collect())?;
    put(&d, "direction_rad", waves.iter().map(|w| w.direction()).collect())?;
    put(&d, "omega_rad_s", waves.iter().map(|w| w.omega()).collect())?;
    put(&d, "phase_rad", waves.iter().map(|w| w.phase()).collect())?;
    put(&d, "steepness", waves.iter().map(|w| w.steepness()).collect())?;
    d.set_item("variance_m2", set.variance())?;
    d.set_item("total_amplitude_m", set.total_amplitude())?;
    d.set_item("total_steepness", set.total_steepness())?;
    d.set_item("peak_omega_rad_s", s.peak_omega())?;
    Ok(d)
}

/// Fresnel reflectance of a smooth interface at each cosine of incidence.
///
/// Keywords as `brine optics fresnel`: `n1`, `n2` (refractive indices, required).
///
/// Returns a dict of arrays: `reflectance`, `transmittance`, `schlick`,
/// `total_internal_reflection` (booleans).
#[pyfunction]
#[pyo3(signature = (cos_theta, **kwargs))]
fn fresnel<'py>(
    py: Python<'py>,
    cos_theta: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let Command::Optics(o) = parse_cli(&["optics", "fresnel"], &[("cos_theta", "1".to_owned())], kwargs)? else {
        return Err(bad("not optics"));
    };
    let cli::optics::OpticsCommand::Fresnel(args) = o.command else {
        return Err(bad("not fresnel"));
    };
    let c = values(&cos_theta)?;
    let out = map_checked(&c, "cos_theta", |x| {
        let a = cli::optics::FresnelArgs { cos_theta: x, ..args.clone() };
        cli::optics::fresnel_of(&a).map_err(|e| e.to_string())
    })
    .map_err(bad)?;
    let d = PyDict::new(py);
    put(&d, "reflectance", out.iter().map(|o| o.reflectance).collect())?;
    put(&d, "transmittance", out.iter().map(|o| o.transmittance).collect())?;
    put(&d, "schlick", out.iter().map(|o| o.schlick).collect())?;
    let tir: Vec<bool> = out.iter().map(|o| o.total_internal_reflection).collect();
    d.set_item("total_internal_reflection", tir.into_pyarray(py))?;
    Ok(d)
}

/// Inherent optical properties of a water body at each wavelength.
///
/// Keywords as `brine optics water`: `type` (a Jerlov type, `"I"` … `"9C"`) or
/// `chlorophyll_mg_m3` (Case-1 water).
///
/// Returns a dict: arrays (m⁻¹) `absorption`, `scattering`, `backscattering`, `attenuation`,
/// `kd`; strings `water`, `iop_source`, `kd_source`.
#[pyfunction]
#[pyo3(signature = (wavelength_nm, **kwargs))]
fn water_iops<'py>(
    py: Python<'py>,
    wavelength_nm: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let Command::Optics(o) = parse_cli(&["optics", "water"], &[], kwargs)? else {
        return Err(bad("not optics"));
    };
    let cli::optics::OpticsCommand::Water(args) = o.command else {
        return Err(bad("not water"));
    };
    let (body, name) = cli::optics::water_body(&args).map_err(py_err)?;
    let l = values(&wavelength_nm)?;
    let iops = map_checked(&l, "wavelength_nm", |x| {
        brine_optics::check_wavelength(x).map_err(|e| e.to_string())?;
        Ok(body.iops(x))
    })
    .map_err(bad)?;
    let d = PyDict::new(py);
    put(&d, "absorption", iops.iter().map(|i| i.a).collect())?;
    put(&d, "scattering", iops.iter().map(|i| i.b).collect())?;
    put(&d, "backscattering", iops.iter().map(|i| i.b_b).collect())?;
    put(&d, "attenuation", iops.iter().map(|i| i.c).collect())?;
    put(&d, "kd", iops.iter().map(|i| i.k_d).collect())?;
    d.set_item("water", name)?;
    d.set_item("iop_source", body.iop_source())?;
    d.set_item("kd_source", body.kd_source())?;
    Ok(d)
}

/// Sky radiance in each view direction (elevation and azimuth in degrees, azimuth from north
/// through east).
///
/// Keywords as `brine sky`: `sun_elevation_deg` (required), `sun_azimuth_deg`, `turbidity`,
/// `model` (`"preetham"`, `"hosek-wilkie"`), `moon_elevation_deg`, `moon_azimuth_deg`,
/// `moon_phase_deg`, `moon_distance_km`, `clouds`, `cloud_seed`, `time_s`.
///
/// Returns a dict: `rgb` and `xyz` (kcd m⁻², arrays of shape `(n, 3)`, linear sRGB and CIE
/// XYZ); `sun_radiance_rgb`, `sun_irradiance_rgb` (klx), `sky_horizontal_irradiance_rgb` (klx).
#[pyfunction]
#[pyo3(signature = (elevation_deg, azimuth_deg, **kwargs))]
fn sky_radiance<'py>(
    py: Python<'py>,
    elevation_deg: PyReadonlyArray1<'py, f64>,
    azimuth_deg: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let Command::Sky(args) = parse_cli(&["sky"], &[], kwargs)? else {
        return Err(bad("not a sky"));
    };
    let sky = cli::sky::sky_of(&args).map_err(py_err)?;
    let (e, a) = (values(&elevation_deg)?, values(&azimuth_deg)?);
    if e.len() != a.len() {
        return Err(bad(format!(
            "elevation_deg has {} values and azimuth_deg {}: expected one length",
            e.len(),
            a.len()
        )));
    }
    for (i, (&x, &y)) in e.iter().zip(&a).enumerate() {
        if !((-90.0..=90.0).contains(&x) && y.is_finite()) {
            return Err(bad(format!(
                "(elevation_deg, azimuth_deg)[{i}] = ({x}, {y}): expected an elevation in [-90, 90]° and a finite azimuth"
            )));
        }
    }
    let out: Vec<(DVec3, DVec3)> = py.detach(|| {
        e.par_iter()
            .zip(&a)
            .with_min_len(MIN_CHUNK)
            .map(|(&x, &y)| {
                let v = cli::sky::direction(x, y);
                (sky.radiance_rgb(v), sky.radiance_xyz(v))
            })
            .collect()
    });
    let rows = |f: &dyn Fn(&(DVec3, DVec3)) -> DVec3| -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
        let flat: Vec<f64> = out.iter().flat_map(|p| f(p).to_array()).collect();
        flat.into_pyarray(py).reshape([out.len(), 3])
    };
    let d = PyDict::new(py);
    d.set_item("rgb", rows(&|p| p.0)?)?;
    d.set_item("xyz", rows(&|p| p.1)?)?;
    let sun = sky.sun();
    d.set_item("sun_radiance_rgb", sun.radiance_rgb.to_array())?;
    d.set_item("sun_irradiance_rgb", sun.irradiance_rgb.to_array())?;
    d.set_item("sky_horizontal_irradiance_rgb", sky.horizontal_irradiance_rgb().to_array())?;
    Ok(d)
}

/// Whitecap coverage `W` (fraction of the sea) of Monahan's laws at each wind speed (m/s).
///
/// Keywords as `brine foam`: `law` (`"monahan-1980"`, `"monahan-1986-wind"`,
/// `"monahan-1986-stability"`, `"darles-2007-as-printed"`), `t_water_c`, `t_air_c`,
/// `onset_m_s`.
#[pyfunction]
#[pyo3(signature = (u10, **kwargs))]
fn whitecap_coverage<'py>(
    py: Python<'py>,
    u10: PyReadonlyArray1<'py, f64>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, numpy::PyArray1<f64>>> {
    let Command::Foam(args) = parse_cli(&["foam"], &[("u10", "10".to_owned())], kwargs)? else {
        return Err(bad("not foam"));
    };
    let law = cli::foam::law_of(&args).map_err(py_err)?;
    let u = values(&u10)?;
    let out = map_checked(&u, "u10", |x| {
        let p = brine_foam::CoverageParams::new(x, law, args.onset_m_s).map_err(|e| e.to_string())?;
        Ok(brine_foam::whitecap_coverage(&p))
    })
    .map_err(bad)?;
    Ok(out.into_pyarray(py))
}

/// The sea-spray source function of Monahan, Spiel & Davidson (1986), `dF/dr₈₀` (drops m⁻² s⁻¹
/// µm⁻¹), at each pair of drop radius `r80_um` (µm, `> 0`; fitted on [0.8, 15]) and wind speed
/// `u10` (m/s, [0, 60]); arrays of one length.
#[pyfunction]
fn spray_flux<'py>(
    py: Python<'py>,
    r80_um: PyReadonlyArray1<'py, f64>,
    u10: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, numpy::PyArray1<f64>>> {
    let (r, u) = (values(&r80_um)?, values(&u10)?);
    if r.len() != u.len() {
        return Err(bad(format!("r80_um has {} values and u10 {}: expected one length", r.len(), u.len())));
    }
    let mut out = Vec::with_capacity(r.len());
    for (i, (&a, &b)) in r.iter().zip(&u).enumerate() {
        if !(a > 0.0 && a.is_finite()) {
            return Err(bad(format!("r80_um[{i}] = {a} is out of range: expected (0, ∞) µm")));
        }
        if !(0.0..=60.0).contains(&b) {
            return Err(bad(format!("u10[{i}] = {b} is out of range: expected [0, 60] m/s")));
        }
        out.push(brine_foam::msd86_flux(a, b));
    }
    Ok(out.into_pyarray(py))
}

/// The JSON report of `brine foam`, `brine spray` or `brine whitecap` (`command`), as Python
/// objects: the same keywords as the command's flags.
#[pyfunction]
#[pyo3(signature = (command, **kwargs))]
fn report<'py>(py: Python<'py>, command: &str, kwargs: Option<&Bound<'py, PyDict>>) -> PyResult<Bound<'py, PyAny>> {
    let value = match parse_cli(&[command], &[], kwargs)? {
        Command::Foam(a) => cli::foam::foam_json(&a),
        Command::Spray(a) => cli::foam::spray_json(&a),
        Command::Whitecap(a) => py.detach(|| cli::whitecap::whitecap_json(&a)),
        _ => return Err(bad(format!("{command}: expected foam, spray or whitecap"))),
    }
    .map_err(py_err)?;
    Ok(pythonize::pythonize(py, &value)?)
}
