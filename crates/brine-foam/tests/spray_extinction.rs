//! An independent check of the spray extinction coefficient `k_e(0) = ∫ Q_e π r² n(r, 0) dr`:
//! adaptive Simpson quadrature in the radius itself (the crate uses a fixed 512-panel Simpson rule
//! in `ln r`), with the number concentration the crate documents, `n = (dF/dr)/v_d`.

use brine_foam::{AIR_VISCOSITY, ExtinctionEfficiency, G, SEA_WATER_DENSITY, SprayMedium, SprayParams, msd86_flux};

/// Relative accuracy asked of the adaptive reference quadrature (its own error is far below the
/// tolerances it is compared with).
const REFERENCE_REL: f64 = 1e-12;

/// Relative tolerance on `k_e(0)` for `Q_e = 2`. The crate's composite Simpson rule in `ln r` has
/// the error `(b − a) h⁴ f⁗/180`; its integrand varies on scales `L` ≳ 0.4 in `ln r` (the width
/// of the MSD86 peak factor `10^{1.19 e^{−B²}}`, the knee of `1/v_d`), so with
/// `h = ln(100/0.8)/512` = 9.4×10⁻³ at most the error is about `(h/L)⁴/180` ≈ 2×10⁻⁹ relative.
const SMOOTH_REL: f64 = 1e-8;

/// Relative tolerance on `k_e(0)` with the anomalous-diffraction `Q_e` (550 nm, `m` = 1.34) on
/// 0.8–15 µm. Its oscillating part `−(4/ρ) sin ρ`, `ρ = 7.77 r`, has a period of `2π/ρ` in `ln r`;
/// Simpson's local error on it is `(hρ)⁴/180` of its amplitude `4/ρ`, which weighted by the
/// integrand and summed without any cancellation between periods is 4.7×10⁻⁷ of `k_e`
/// (`h` = 5.7×10⁻³). Twice that bound.
const OSCILLATING_REL: f64 = 1e-6;

/// Rounding of `n(r, 0)` recomputed from its documented formula (a dozen flops).
const CONCENTRATION_ROUNDING: f64 = 1e-13;

use brine_testkit::quadrature::adaptive_simpson;

/// Van de Hulst's anomalous-diffraction efficiency, written out here independently of the crate.
fn q_anomalous(r_um: f64, wavelength_nm: f64, m: f64) -> f64 {
    let rho = 4.0 * std::f64::consts::PI * r_um * 1e3 * (m - 1.0) / wavelength_nm;
    2.0 - 4.0 / rho * rho.sin() + 4.0 / (rho * rho) * (1.0 - rho.cos())
}

/// `k_e(0)` of `medium` against [`reference_extinction`] with the efficiency `q_e`, within `rel`
/// relative; prints both.
fn check_extinction(medium: &SprayMedium, q_e: impl Fn(f64) -> f64, rel: f64, case: &str) {
    let reference = reference_extinction(medium, q_e);
    let k = medium.extinction(0.0, 1.0);
    eprintln!("{case}: k_e(0) = {k:.6e} m⁻¹, rel. diff. {:.1e}", k / reference - 1.0);
    assert!((k / reference - 1.0).abs() < rel, "{case}: {k} vs {reference}");
}

/// `∫ Q_e(r) π r² n(r, 0) dr` (m⁻¹) by adaptive Simpson in `r` (µm), with `r` in metres inside
/// `π r²` and `n` in m⁻³ µm⁻¹.
fn reference_extinction(medium: &SprayMedium, q_e: impl Fn(f64) -> f64) -> f64 {
    let p = medium.params();
    let f = |r: f64| q_e(r) * std::f64::consts::PI * (r * 1e-6) * (r * 1e-6) * medium.concentration(r, 0.0);
    // A first pass sets the scale of the absolute accuracy.
    let scale = adaptive_simpson(f, p.radius_min_um, p.radius_max_um, 1e-6 * f(p.radius_min_um));
    adaptive_simpson(f, p.radius_min_um, p.radius_max_um, REFERENCE_REL * scale)
}

#[test]
fn the_concentration_is_the_documented_flux_over_deposition() {
    // n(r, 0) = (dF/dr)/(v_s + H/t_res), v_s = 2 ρ_w g r²/(9 μ_air): the number concentration the
    // reference integral uses is the crate's documented one.
    let p = SprayParams { u10: 12.0, ..SprayParams::default() };
    let m = SprayMedium::new(&p).unwrap();
    for &r in &[0.8, 1.0, 2.4, 5.0, 15.0, 60.0] {
        let v_s = 2.0 * SEA_WATER_DENSITY * G * (r * 1e-6) * (r * 1e-6) / (9.0 * AIR_VISCOSITY);
        let n = msd86_flux(r, p.u10) / (v_s + p.scale_height_m / p.residence_time_s);
        assert!((m.concentration(r, 0.0) / n - 1.0).abs() < CONCENTRATION_ROUNDING, "r = {r} µm");
    }
}

#[test]
fn geometric_optics_extinction_against_adaptive_simpson() {
    for &(u10, r_max) in &[(5.0, 15.0), (10.0, 15.0), (20.0, 15.0), (10.0, 100.0)] {
        let p = SprayParams { u10, radius_max_um: r_max, ..SprayParams::default() };
        let m = SprayMedium::new(&p).unwrap();
        check_extinction(&m, |_| 2.0, SMOOTH_REL, &format!("U10 = {u10} m/s, 0.8–{r_max} µm, Q_e = 2"));
    }
}

#[test]
fn anomalous_diffraction_extinction_against_adaptive_simpson() {
    let efficiency = ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm: 550.0, refractive_index: 1.34 };
    for &u10 in &[5.0, 10.0, 20.0] {
        let m = SprayMedium::new(&SprayParams { u10, efficiency, ..SprayParams::default() }).unwrap();
        let q = |r| q_anomalous(r, 550.0, 1.34);
        check_extinction(&m, q, OSCILLATING_REL, &format!("U10 = {u10} m/s, anomalous diffraction"));
    }
}

#[test]
fn optical_depth_is_the_height_integral_of_the_extinction() {
    // τ = ∫₀^{z_max} k_e(z) dz, here by adaptive Simpson over the height, against the closed form.
    let m = SprayMedium::new(&SprayParams::default()).unwrap();
    let z_max = m.params().max_height_m;
    let scale = m.extinction(0.0, 1.0) * z_max;
    let tau = adaptive_simpson(|z| m.extinction(z, 1.0), 0.0, z_max, REFERENCE_REL * scale);
    assert!((m.optical_depth() / tau - 1.0).abs() < SMOOTH_REL, "{} vs {tau}", m.optical_depth());
}
