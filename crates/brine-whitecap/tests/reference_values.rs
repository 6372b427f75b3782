//! Published reference values: the maximum errors of the erf approximations.

use brine_whitecap::{WINITZKI_A, WINITZKI_A_DEMO, erf_abramowitz_stegun, erf_winitzki};

/// Grid spacing of the error scan; the error curves vary on scales ≥ 0.1, so 10⁻⁵ finds each
/// maximum to a relative 10⁻⁸.
const STEP: f64 = 1e-5;

/// Relative tolerance on the published maxima, printed with 5 significant digits.
const MAX_REL: f64 = 5e-4;

/// Tolerance on the abscissa of the maximum, printed with 3 decimals.
const AT_TOL: f64 = 2e-3;

/// `(max |approx − erf|, argmax)` over `x ∈ [0, 6]` (both functions are odd; beyond 6 both are 1
/// to double precision).
fn scan(f: impl Fn(f64) -> f64) -> (f64, f64) {
    let (mut worst, mut at) = (0.0, 0.0);
    let n = (6.0 / STEP) as usize;
    for i in 0..=n {
        let x = i as f64 * STEP;
        let e = (f(x) - libm::erf(x)).abs();
        if e > worst {
            worst = e;
            at = x;
        }
    }
    (worst, at)
}

fn rows() -> Vec<(String, f64, Option<f64>)> {
    brine_testkit::csv::records(include_str!("data/erf_max_errors.csv"))
        .into_iter()
        .map(|c| (c[0].to_owned(), c[1].parse().unwrap(), c.get(2).and_then(|s| s.parse().ok())))
        .collect()
}

#[test]
fn erf_approximation_maximum_errors() {
    let rows = rows();
    assert_eq!(rows.len(), 3, "the table's three approximations");
    for (method, published, at) in rows {
        let (worst, x) = match method.as_str() {
            "winitzki_0.147" => scan(|x| erf_winitzki(x, WINITZKI_A)),
            "winitzki_0.140012" => scan(|x| erf_winitzki(x, WINITZKI_A_DEMO)),
            "abramowitz_stegun_7.1.26" => scan(erf_abramowitz_stegun),
            other => panic!("unknown method {other}"),
        };
        eprintln!("{method}: max |error| = {worst:.5e} at x = {x:.4}");
        match at {
            Some(at) => {
                assert!((worst / published - 1.0).abs() < MAX_REL, "{method}: {worst:e} vs {published:e}");
                assert!((x - at).abs() < AT_TOL, "{method}: at {x} vs {at}");
            }
            // A&S give a bound, not the maximum.
            None => assert!(worst <= published, "{method}: {worst:e} > {published:e}"),
        }
    }
}
