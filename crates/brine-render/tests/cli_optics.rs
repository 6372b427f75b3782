//! `brine optics` as a process: the Fresnel query against an independent computation, the water
//! query's JSON schema and values, and bad arguments (exit code 2, one error line, no panic).

use std::process::{Command, Output};

use serde_json::Value;

/// Runs `brine optics ARGS`.
fn optics(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_brine")).arg("optics").args(args).output().expect("brine runs")
}

/// Runs `brine optics ARGS`, asserts success and parses stdout as JSON.
fn optics_json(args: &[&str]) -> Value {
    let out = optics(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    serde_json::from_slice(&out.stdout).expect("stdout is JSON")
}

/// Unpolarised reflectance from the amplitude coefficients, independently of brine-optics' `g`
/// form: `r_s = (n₁c − n₂c_t)/(n₁c + n₂c_t)`, `r_p = (n₂c − n₁c_t)/(n₂c + n₁c_t)`,
/// `R = ½(r_s² + r_p²)` (Born & Wolf 1999, *Principles of Optics*, §1.5.2 Eq. 21).
fn amplitude_reflectance(n1: f64, n2: f64, c: f64) -> f64 {
    let ct = (1.0 - (n1 / n2).powi(2) * (1.0 - c * c)).sqrt();
    let rs = (n1 * c - n2 * ct) / (n1 * c + n2 * ct);
    let rp = (n2 * c - n1 * ct) / (n2 * c + n1 * ct);
    0.5 * (rs * rs + rp * rp)
}

#[test]
fn fresnel_reflectance_matches_an_independent_computation() {
    let json = optics_json(&["fresnel", "--n1", "1.0", "--n2", "1.333", "--cos-theta", "0.5", "--json"]);
    let r = json["reflectance"].as_f64().expect("reflectance is a number");
    /// JSON carries the f64 exactly (shortest round-trip form); the two formulas differ by a few
    /// roundings of order-one terms.
    const ROUNDING: f64 = 1e-14;
    assert!((r - amplitude_reflectance(1.0, 1.333, 0.5)).abs() < ROUNDING, "{r}");
    // And the reference's (docs/equations.md) oracle F(60°) = 0.059691, printed to 6 significant digits.
    /// Half a unit in the 6th digit, relative.
    const SIX_DIGITS: f64 = 1e-5;
    assert!((r / 0.059691 - 1.0).abs() < SIX_DIGITS, "{r}");
    let t = json["transmittance"].as_f64().unwrap();
    assert!((r + t - 1.0).abs() < ROUNDING);
    assert_eq!(json["total_internal_reflection"], Value::Bool(false));
}

#[test]
fn water_json_has_the_documented_keys_and_31_physical_entries() {
    let json = optics_json(&["water", "--type", "II", "--wavelength-nm", "400:700:10", "--json"]);
    let obj = json.as_object().expect("a JSON object");
    // The keys documented in docs/models/brine-optics.md ("Command line").
    let mut keys: Vec<&str> = obj.keys().map(String::as_str).collect();
    keys.sort_unstable();
    let mut expected = vec![
        "water",
        "chlorophyll_mg_m3",
        "iop_source",
        "kd_source",
        "wavelength_nm",
        "absorption",
        "scattering",
        "backscattering",
        "attenuation",
        "kd",
    ];
    expected.sort_unstable();
    assert_eq!(keys, expected);
    let series = |k: &str| -> Vec<f64> {
        obj[k].as_array().unwrap_or_else(|| panic!("{k} is an array")).iter().map(|v| v.as_f64().unwrap()).collect()
    };
    for k in ["wavelength_nm", "absorption", "scattering", "backscattering", "attenuation", "kd"] {
        let s = series(k);
        assert_eq!(s.len(), 31, "{k}");
        assert!(s.iter().all(|v| v.is_finite() && *v >= 0.0), "{k}: {s:?}");
    }
    let lambda = series("wavelength_nm");
    /// The grid `400 + 10 i` nm is exact in f64 and its integers survive the JSON text exactly;
    /// 10⁻⁹ nm is a rounding allowance only.
    const GRID_NM: f64 = 1e-9;
    for (i, l) in lambda.iter().enumerate() {
        assert!((l - (400.0 + 10.0 * i as f64)).abs() < GRID_NM, "{l}");
    }
    // K_d is Jerlov's type II (Table XXVII) at his 50 nm columns, as transcribed independently in
    // the Dstl data set of Williamson & Hollins 2022 (Applied Optics 61(33):9951; figshare
    // 10.6084/m9.figshare.20290782, ip_jerlov.csv): 0.096, 0.068, 0.070, 0.089, 0.26, 0.40,
    // 0.61 m⁻¹ at 400, 450, …, 700 nm.
    let kd = series("kd");
    /// Jerlov prints two or three significant digits, reproduced exactly; JSON round-trips f64.
    const EXACT: f64 = 1e-12;
    for (i, k) in [0.096, 0.068, 0.070, 0.089, 0.26, 0.40, 0.61].iter().enumerate() {
        assert!((kd[5 * i] - k).abs() < EXACT, "{} nm: {} vs {k}", lambda[5 * i], kd[5 * i]);
    }
    // c = a + b and b_b < b.
    let (a, b, bb, c) = (series("absorption"), series("scattering"), series("backscattering"), series("attenuation"));
    /// `c` is computed as `a + b` (one rounding, half an ulp of `c`); the JSON text and its parse
    /// and the test's own subtraction add a few ulps of `c` more (2.2×10⁻¹⁶ relative each);
    /// 10⁻¹² relative is a wide margin.
    const SUM_REL: f64 = 1e-12;
    for i in 0..31 {
        assert!((c[i] - a[i] - b[i]).abs() <= SUM_REL * c[i] && bb[i] < b[i], "{} nm", lambda[i]);
    }
}

#[test]
fn bad_arguments_exit_with_code_2() {
    for args in [
        &["fresnel", "--n1", "1.0", "--n2", "1.333", "--cos-theta", "1.5", "--json"][..],
        &["fresnel", "--n1", "0", "--n2", "1.333", "--cos-theta", "0.5"],
        &["fresnel", "--n1", "1.0", "--n2", "1.333"],
        &["water", "--type", "IV", "--json"],
        &["water", "--type", "II", "--wavelength-nm", "300:700:10", "--json"],
        &["water", "--type", "II", "--chlorophyll-mg-m3", "1.0"],
        &["water", "--chlorophyll-mg-m3", "-1"],
        &["water", "--type", "II", "--wavelength-nm", "400:700"],
    ] {
        let out = optics(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(err.contains("error"), "{args:?}: {err}");
        assert!(out.stdout.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&out.stdout));
    }
}
