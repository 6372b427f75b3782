//! The `brine foam`, `brine spray` and `brine whitecap` commands, run as a user runs them: their
//! JSON against the published laws evaluated here, and bad input exiting with code 2.

use std::process::{Command, Output};

use serde_json::Value;

/// Relative difference allowed between the command's coverage and Monahan's law evaluated here:
/// the same formula through `libm::pow`/`exp` there and `f64::powf`/`exp` here, a few ulps each,
/// printed by `serde_json` with round-trip precision.
const FORMULA_ROUNDING: f64 = 1e-12;

/// Relative tolerance on values printed with 4 significant digits (the reference's (docs/equations.md) oracles).
const FOUR_DIGITS: f64 = 6e-4;

/// `½(1 + erf(0))` is exactly ½; only the last ulp may differ.
const HALF_ROUNDING: f64 = 1e-15;

/// Rounding of the log-spaced radii `a (b/a)^{i/(n−1)}` against the ends of their range (µm).
const RADIUS_ROUNDING_UM: f64 = 1e-9;

/// The acceptance tolerance for the calibrated whitecap coverage against Monahan's.
const CALIBRATION_REL: f64 = 0.10;

fn brine(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).args(args).output().expect("brine runs")
}

/// Runs `brine ARGS`, asserts success and parses its standard output as JSON.
fn brine_json(args: &[&str]) -> Value {
    let out = brine(args);
    assert_eq!(out.status.code(), Some(0), "brine {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("brine {args:?}: not JSON ({e})"))
}

fn number(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("missing number {key} in {v}"))
}

#[test]
fn foam_coverage_is_monahan_and_o_muircheartaigh_1986() {
    let v = brine_json(&["foam", "--u10", "10", "--t-water-c", "12", "--t-air-c", "20", "--json"]);
    // Monahan & Ó Muircheartaigh 1986, stability form: W = 1.95×10⁻⁵ U₁₀^2.55 exp(0.0861 ΔT),
    // ΔT = T_w − T_a = 12 − 20 = −8 °C.
    let expected = 1.95e-5 * 10f64.powf(2.55) * (0.0861f64 * (12.0 - 20.0)).exp();
    let coverage = number(&v, "coverage");
    assert!((coverage / expected - 1.0).abs() < FORMULA_ROUNDING, "{coverage} vs {expected}");
    // The sheet's ΔT = 0 oracle, 6.919×10⁻³, times e^{−0.6888}: 3.475×10⁻³.
    assert!((coverage / (6.919e-3 * (-0.6888f64).exp()) - 1.0).abs() < FOUR_DIGITS);
    assert_eq!(v["law"], "monahan-1986-stability");
    assert!((number(&v, "delta_t_c") + 8.0).abs() < FORMULA_ROUNDING);
}

#[test]
fn spray_has_the_documented_keys_and_a_physical_distribution() {
    let v = brine_json(&["spray", "--u10", "10", "--radius-um", "1:100:50", "--json"]);
    for key in [
        "u10_m_s",
        "units",
        "validity_range_um",
        "distribution",
        "extinction_m",
        "optical_depth",
        "scale_height_m",
        "max_height_m",
        "q_e",
    ] {
        assert!(v.get(key).is_some(), "missing key {key} in {v}");
    }
    let d = v["distribution"].as_array().expect("distribution is an array");
    assert_eq!(d.len(), 50);
    let mut previous_radius = 0.0;
    for row in d {
        for key in ["radius_um", "dF_dr", "concentration_m3_um", "in_validity_range"] {
            assert!(row.get(key).is_some(), "missing key {key} in {row}");
        }
        let (r, f, n) = (number(row, "radius_um"), number(row, "dF_dr"), number(row, "concentration_m3_um"));
        assert!(f.is_finite() && f >= 0.0, "dF/dr({r}) = {f}");
        assert!(n.is_finite() && n >= 0.0, "n({r}) = {n}");
        assert!(
            r > previous_radius && (1.0 - RADIUS_ROUNDING_UM..=100.0 + RADIUS_ROUNDING_UM).contains(&r),
            "radius {r}"
        );
        assert_eq!(row["in_validity_range"].as_bool(), Some((0.8..=15.0).contains(&r)), "r = {r}");
        previous_radius = r;
    }
    // Monahan, Spiel & Davidson 1986 at 1 µm and 10 m/s: 2.614×10⁴ m⁻² s⁻¹ µm⁻¹ (sheet oracle).
    assert!((number(&d[0], "dF_dr") / 2.614e4 - 1.0).abs() < FOUR_DIGITS);
    let (k_e, tau) = (number(&v, "extinction_m"), number(&v, "optical_depth"));
    assert!(k_e.is_finite() && k_e > 0.0 && tau.is_finite() && tau > 0.0, "k_e {k_e}, τ {tau}");
}

#[test]
fn whitecap_coverage_at_the_mean_is_one_half() {
    let v = brine_json(&["whitecap", "--mu", "0", "--sigma", "1", "--alpha", "0", "--json"]);
    assert!((number(&v, "coverage") - 0.5).abs() < HALF_ROUNDING, "{v}");
}

#[test]
fn calibrated_whitecaps_cover_the_sea_as_monahan() {
    let v = brine_json(&["whitecap", "--u10", "10", "--calibrate", "--json"]);
    let (alpha, coverage, monahan) = (number(&v, "alpha"), number(&v, "coverage"), number(&v, "monahan_coverage"));
    assert!(alpha.is_finite(), "α = {alpha}");
    // Monahan & Ó Muircheartaigh 1980 at 10 m/s: 9.870×10⁻³ (sheet oracle).
    assert!((monahan / 9.870e-3 - 1.0).abs() < FOUR_DIGITS, "{monahan}");
    assert!((coverage / monahan - 1.0).abs() < CALIBRATION_REL, "surface coverage {coverage} vs Monahan {monahan}");
}

#[test]
fn bad_arguments_exit_with_code_2() {
    for args in [
        &["foam", "--u10", "ten", "--json"][..],
        &["foam", "--u10", "80", "--json"],
        &["foam", "--u10", "10", "--t-water-c", "40", "--t-air-c", "0", "--json"],
        &["spray", "--u10", "10", "--radius-um", "0:5:3", "--json"],
        &["whitecap", "--mu", "0", "--sigma", "-1", "--alpha", "0", "--json"],
        &["whitecap", "--u10", "10", "--calibrate", "--alpha", "0.5"],
    ] {
        let out = brine(args);
        assert_eq!(out.status.code(), Some(2), "brine {args:?}");
        assert!(out.stdout.is_empty(), "brine {args:?} printed {}", String::from_utf8_lossy(&out.stdout));
        assert!(!out.stderr.is_empty(), "brine {args:?}: no message");
    }
    // A temperature difference beyond ±30 °C is refused, naming it (not clamped to 30 °C).
    let out = brine(&["foam", "--u10", "10", "--t-water-c", "40", "--t-air-c", "0", "--json"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("delta_t_c = 40") && err.contains("[-30, 30]"), "{err}");
}
