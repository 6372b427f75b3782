//! Published reference values: Monahan's coverage laws, Koepke's effective reflectance, the
//! MSD86 spray source function.

use brine_foam::{CoverageParams, KoepkeFoam, WhitecapLaw, msd86_flux, whitecap_coverage};

/// Relative tolerance on values printed with 4 significant digits (half a unit in the last
/// place is at most 5e-4 relative at a leading 1).
const FOUR_DIGITS: f64 = 6e-4;

/// Rounding of the product 0.4 × 0.55 (one flop).
const PRODUCT_ROUNDING: f64 = 1e-15;

use brine_testkit::csv::records as csv;

#[test]
fn monahan_coverage_laws() {
    let rows = csv(include_str!("data/whitecap_coverage.csv"));
    assert_eq!(rows.len(), 5, "the table's five published values");
    for row in rows {
        let (u, dt, expected): (f64, f64, f64) =
            (row[1].parse().unwrap(), row[2].parse().unwrap(), row[3].parse().unwrap());
        let law = match row[0] {
            "monahan-1980" => WhitecapLaw::Monahan1980,
            "monahan-1986-stability" => WhitecapLaw::Monahan1986Stability { delta_t_c: dt },
            "monahan-1986-wind" => WhitecapLaw::Monahan1986Wind,
            other => panic!("unknown law {other}"),
        };
        let w = whitecap_coverage(&CoverageParams::new(u, law, 3.0).unwrap());
        assert!((w / expected - 1.0).abs() < FOUR_DIGITS, "{} at {u} m/s: {w} vs {expected}", row[0]);
    }
}

#[test]
fn koepke_effective_reflectance() {
    // Koepke 1984: f_ef = 0.4, R_f = 0.55 give R_ef = 0.22 (sheet oracle).
    let k = KoepkeFoam::new(0.55, 0.4).unwrap();
    assert!((k.effective_reflectance() - 0.22).abs() < PRODUCT_ROUNDING);
    assert!((KoepkeFoam::default().effective_reflectance() - 0.22).abs() < PRODUCT_ROUNDING);
}

#[test]
fn msd86_source_function() {
    let rows = csv(include_str!("data/msd86_flux.csv"));
    assert_eq!(rows.len(), 4, "the table's four published values");
    for row in rows {
        let (u, expected): (f64, f64) = (row[0].parse().unwrap(), row[2].parse().unwrap());
        let value = if let Some((a, b)) = row[1].split_once('-') {
            // Simpson's rule in ln r on 2000 panels: converged to 1e-9.
            let (a, b): (f64, f64) = (a.parse::<f64>().unwrap().ln(), b.parse::<f64>().unwrap().ln());
            let n = 2000;
            let h = (b - a) / n as f64;
            let f = |l: f64| msd86_flux(l.exp(), u) * l.exp();
            let mut s = f(a) + f(b);
            for i in 1..n {
                s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h);
            }
            s * h / 3.0
        } else {
            msd86_flux(row[1].parse().unwrap(), u)
        };
        assert!((value / expected - 1.0).abs() < FOUR_DIGITS, "r = {}: {value} vs {expected}", row[1]);
    }
}
