//! brine-sky against the reference's (docs/equations.md) oracles (`tests/data/sheet_oracles.csv`, see its header):
//! values of Preetham's formulas evaluated independently from their printed coefficients, each
//! with the tolerance of its printed digits. These check the transcription of the formulas, not
//! the model against the sky. The published, measured figures are tested next to the models:
//! the solar illuminance constant, direct-normal daylight, the Rayleigh optical depth, Kasten's
//! air mass and the Sun's semidiameter (`sun::tests`), the ozone cross-section
//! (`solar_tables::tests`), the full Moon's brightness and the night-sky glow (`night::tests`);
//! see `docs/validation.md`.

use brine_sky::{
    PerezCoefficients, henyey_greenstein, mie_beta, perez, rayleigh_beta, rayleigh_phase, zenith_chromaticity_xy,
    zenith_luminance,
};
use brine_testkit::check::{Tolerance, close};

/// Rows of `tests/data/sheet_oracles.csv`.
const N_ORACLES: usize = 13;

#[test]
fn sheet_oracles() {
    let mut n = 0;
    for f in brine_testkit::csv::records(include_str!("data/sheet_oracles.csv")) {
        let num = |i: usize| f[i].parse::<f64>().unwrap_or(f64::NAN);
        let (t, ts) = (num(1), num(2).to_radians());
        let got = match f[0] {
            "zenith_Y" => zenith_luminance(t, ts),
            "zenith_x" => zenith_chromaticity_xy(t, ts).0,
            "zenith_y" => zenith_chromaticity_xy(t, ts).1,
            "perez_ratio_Y" => {
                let k = PerezCoefficients::luminance(t);
                perez(num(3).to_radians().cos(), num(4).to_radians(), &k) / perez(1.0, ts, &k)
            }
            "beta_R" => rayleigh_beta(num(5)),
            "beta_M" => mie_beta(num(5), t, 0.678),
            "phase_R" => rayleigh_phase(0.0),
            "phase_iso" => henyey_greenstein(0.3, 0.0),
            other => panic!("unknown oracle {other}"),
        };
        let (want, tol) = (num(6), num(7));
        let what = f.join(",");
        close(&what, got, want, Tolerance::parse(f[8], tol)).unwrap_or_else(|e| panic!("{e}"));
        n += 1;
    }
    assert_eq!(n, N_ORACLES);
}
