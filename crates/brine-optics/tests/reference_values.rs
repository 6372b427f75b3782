//! Published tables and values: the embedded data against their sources, and the models against
//! published numbers. Each tolerance is a named constant with its reason.

use approx::assert_relative_eq;
use brine_optics::*;

/// Rows `(wavelength, values…)` of an embedded CSV.
use brine_testkit::csv::numbers as rows;

const POPE_FRY: &str = include_str!("../data/pope_fry_1997_pure_water_absorption.csv");
const MOREL: &str = include_str!("../data/morel_1988_kd.csv");
const PRIEUR: &str = include_str!("../data/prieur_sathyendranath_1981_chl_absorption.csv");
const JERLOV: &str = include_str!("../data/jerlov_1976_kd.csv");

/// Values printed in docs/equations.md (3–4 significant digits): half a unit in the last digit.
const SHEET_ROUNDING: f64 = 5e-3;

#[test]
#[expect(clippy::float_cmp, reason = "tabulated values must be returned exactly")]
fn pope_fry_1997_table_is_returned_exactly() {
    let r = rows(POPE_FRY);
    assert_eq!(r.len(), 129, "380–700 nm every 2.5 nm");
    for row in &r {
        assert_eq!(pure_water_absorption(row[0]), row[1], "λ = {}", row[0]);
    }
    // Spot values of the docs/equations.md §7 (Pope & Fry 1997).
    for (l, a) in [(450.0, 0.0092), (500.0, 0.0204), (550.0, 0.0565), (600.0, 0.222), (650.0, 0.340)] {
        assert_relative_eq!(pure_water_absorption(l), a, max_relative = SHEET_ROUNDING);
    }
    // Pope & Fry's abstract: the minimum is 0.0044 ± 0.0006 m⁻¹ at 418 nm.
    let (l_min, a_min) =
        r.iter().map(|x| (x[0], x[1])).fold((0.0, f64::INFINITY), |m, x| if x.1 < m.1 { x } else { m });
    assert!((l_min - 418.0).abs() <= 2.5 && (a_min - 0.0044).abs() <= 0.0006, "{l_min} {a_min}");
}

#[test]
#[expect(clippy::float_cmp, reason = "tabulated values must be returned exactly")]
fn morel_1988_table_is_returned_exactly() {
    let r = rows(MOREL);
    assert_eq!(r.len(), 61, "400–700 nm every 5 nm");
    for row in &r {
        assert_eq!(morel_kd_coefficients(row[0]), (row[1], row[2], row[3]), "λ = {}", row[0]);
        assert_eq!(pure_seawater_scattering(row[0]), row[4], "λ = {}", row[0]);
    }
    // Sheet §7 spot values of Morel's Table 2.
    assert_eq!(morel_kd_coefficients(450.0), (0.0168, 0.0971, 0.701));
    assert_eq!(morel_kd_coefficients(550.0), (0.0640, 0.0410, 0.650));
    assert_eq!(morel_kd_coefficients(650.0), (0.3500, 0.0450, 0.672));
}

#[test]
fn morel_power_law_follows_the_scattering_table() {
    // The table prints b_w to 4 decimals; its red end (≤ 0.0016 m⁻¹, two significant digits)
    // departs from the λ^−4.32 law of Morel 1974 by up to 0.9 units of the last digit.
    /// One unit in the table's last printed digit, plus 3 % for the fit.
    const LAW: (f64, f64) = (1e-4, 0.03);
    for row in rows(MOREL) {
        let law = pure_seawater_scattering_power_law(row[0]);
        assert!((law - row[4]).abs() <= LAW.0 + LAW.1 * row[4], "λ = {}: {law} vs {}", row[0], row[4]);
    }
    assert_relative_eq!(pure_seawater_scattering_power_law(500.0), 0.0029, max_relative = SHEET_ROUNDING);
}

#[test]
#[expect(clippy::float_cmp, reason = "tabulated values must be returned exactly")]
fn prieur_sathyendranath_1981_table_is_returned_exactly() {
    let r = rows(PRIEUR);
    assert_eq!(r.len(), 61);
    for row in &r {
        assert_eq!(chlorophyll_specific_absorption(row[0]), row[1], "λ = {}", row[0]);
    }
    assert_eq!(chlorophyll_specific_absorption(440.0), 1.0, "normalised at 440 nm");
}

#[test]
#[expect(clippy::float_cmp, reason = "tabulated values must be returned exactly")]
fn jerlov_1976_table_is_returned_exactly() {
    let r = rows(JERLOV);
    assert_eq!(r.len(), 15, "350–700 nm every 25 nm");
    for row in &r {
        for (j, t) in JerlovType::ALL.iter().enumerate() {
            assert_eq!(t.kd(row[0]), row[j + 1], "type {t}, λ = {}", row[0]);
        }
    }
    // Spot values of Jerlov's Table XXVII (printed in 10⁻² m⁻¹): I 1.8 at 475, II 6.2 at 475,
    // III 11.5 at 500, coastal 9 at 550: 63.
    assert_eq!(JerlovType::I.kd(475.0), 0.018);
    assert_eq!(JerlovType::II.kd(475.0), 0.062);
    assert_eq!(JerlovType::III.kd(500.0), 0.115);
    assert_eq!(JerlovType::Coastal9.kd(550.0), 0.63);
}

#[test]
#[expect(clippy::float_cmp, reason = "Jerlov's printed digits must be returned exactly")]
fn jerlov_1976_against_an_independent_transcription() {
    // Jerlov's Table XXVII as transcribed independently of this crate's CSV in the Dstl data set
    // of Williamson C. A., Hollins R. C. 2022, "Measured IOPs of Jerlov water types", Applied
    // Optics 61(33):9951–9960 (figshare 10.6084/m9.figshare.20290782, file ip_jerlov.csv, 1 nm
    // steps, linearly interpolated between Jerlov's 25 nm columns and rounded to 4 decimals), as
    // redistributed in the `jerlov` Python package (tishibashi-cpu/jerlov,
    // jerlov/data/jerlov1976_kd.csv). It settles the one entry on which the CSV's two sources
    // disagree: type I at 400 nm is 0.028 there too.
    let columns: [(JerlovType, &[(f64, f64)]); 4] = [
        (
            JerlovType::I,
            &[
                (350.0, 0.062),
                (375.0, 0.038),
                (400.0, 0.028),
                (450.0, 0.019),
                (475.0, 0.018),
                (500.0, 0.027),
                (550.0, 0.063),
                (600.0, 0.235),
                (650.0, 0.36),
                (675.0, 0.42),
                (700.0, 0.56),
            ],
        ),
        (
            JerlovType::II,
            &[
                (450.0, 0.068),
                (475.0, 0.062),
                (500.0, 0.070),
                (525.0, 0.076),
                (550.0, 0.089),
                (575.0, 0.115),
                (600.0, 0.26),
                (625.0, 0.335),
                (650.0, 0.40),
                (675.0, 0.465),
                (700.0, 0.61),
            ],
        ),
        (
            JerlovType::III,
            &[
                (350.0, 0.32),
                (375.0, 0.22),
                (400.0, 0.185),
                (425.0, 0.16),
                (450.0, 0.135),
                (475.0, 0.116),
                (500.0, 0.115),
            ],
        ),
        (
            JerlovType::Coastal9,
            &[
                (375.0, 3.0),
                (400.0, 2.4),
                (425.0, 1.9),
                (450.0, 1.6),
                (475.0, 1.23),
                (500.0, 0.99),
                (525.0, 0.78),
                (550.0, 0.63),
                (575.0, 0.58),
                (600.0, 0.60),
                (625.0, 0.65),
                (650.0, 0.76),
                (675.0, 0.92),
                (700.0, 1.1),
            ],
        ),
    ];
    for (t, values) in columns {
        for &(l, k) in values {
            assert_eq!(t.kd(l), k, "type {t}, λ = {l}");
        }
    }
    // Its 1 nm values between the columns check the interpolation.
    /// The data set rounds to 4 decimals: half a unit in the last place.
    const FOUR_DECIMALS: f64 = 5e-5;
    for (t, l, k) in [
        (JerlovType::I, 510.0, 0.0334),
        (JerlovType::I, 590.0, 0.1766),
        (JerlovType::II, 480.0, 0.0636),
        (JerlovType::II, 610.0, 0.29),
        (JerlovType::III, 490.0, 0.1154),
        (JerlovType::Coastal9, 451.0, 1.5852),
        (JerlovType::Coastal9, 463.0, 1.4076),
    ] {
        assert!((t.kd(l) - k).abs() <= FOUR_DECIMALS, "type {t}, λ = {l}: {} vs {k}", t.kd(l));
    }
}

#[test]
fn jerlov_types_are_ordered_by_turbidity_in_the_blue() {
    // Jerlov's classification: K_d(λ ≤ 500 nm) increases from I to III and from coastal 1 to 9.
    for l in [400.0, 425.0, 450.0, 475.0] {
        let k: Vec<f64> = JerlovType::ALL.iter().map(|t| t.kd(l)).collect();
        assert!(k.windows(2).all(|w| w[0] < w[1]), "λ = {l}: {k:?}");
    }
}

#[test]
fn case1_fit_reproduces_jerlov_oceanic_kd() {
    // A Case-1 water at the fitted chlorophyll reproduces Jerlov's oceanic K_d(λ) to about 10 %
    // rms in log (Jerlov's classes are themselves about ±10 % wide at a given λ).
    /// rms of `ln(K_Morel/K_Jerlov)` allowed for the oceanic types.
    const OCEANIC_RMS: f64 = 0.10;
    for t in [JerlovType::I, JerlovType::IA, JerlovType::IB, JerlovType::II, JerlovType::III] {
        assert!(t.equivalent_fit_rms() < OCEANIC_RMS, "type {t}: {}", t.equivalent_fit_rms());
    }
}

#[test]
fn morel_1988_kd_and_backscattering_oracles() {
    // Sheet "Test oracles": K_d at C = 0.1 / 1 mg m⁻³ (4 digits), b_b(450, C = 1) (3 digits).
    /// Half a unit in the 4th significant digit of the smallest value (0.0361).
    const FOUR_DIGITS: f64 = 1.5e-3;
    let c01 = Chlorophyll::new(0.1).unwrap();
    let c1 = Chlorophyll::new(1.0).unwrap();
    for (l, k01, k1) in [(450.0, 0.0361, 0.1139), (550.0, 0.0732, 0.1050), (650.0, 0.3596, 0.3950)] {
        assert_relative_eq!(morel_kd(l, c01), k01, max_relative = FOUR_DIGITS);
        assert_relative_eq!(morel_kd(l, c1), k1, max_relative = FOUR_DIGITS);
    }
    /// Three significant digits.
    const THREE_DIGITS: f64 = 1e-3;
    assert_relative_eq!(case1_iops(450.0, c1).b_b, 0.00652, max_relative = THREE_DIGITS);
}

#[test]
fn fresnel_oracles() {
    // Sheet oracle, 6 significant digits.
    const SIX_DIGITS: f64 = 2e-5;
    for (deg, f) in [(0.0f64, 0.020373), (45.0, 0.027898), (60.0, 0.059691), (80.0, 0.347917)] {
        assert_relative_eq!(fresnel_dielectric(deg.to_radians().cos(), 1.0, 1.333), f, max_relative = SIX_DIGITS);
    }
    assert_relative_eq!(critical_angle(1.333, 1.0).unwrap().to_degrees(), 48.607, max_relative = SIX_DIGITS);
    // The hemispherical reflectance of a uniform sky on flat water, 0.066 (Mobley 1994, Light and
    // Water §4.3, for n = 1.34; 0.0664 at 1.333).
    /// Mobley prints two significant digits (0.066): half a unit of the last.
    const TWO_DIGITS: f64 = 5e-4;
    assert!((hemispherical_fresnel_reflectance(1.0, 1.333) - 0.066).abs() < TWO_DIGITS);
    // Inside water: 0.474591 by an independent 2×10⁵-point midpoint sum; and the reciprocity
    // relation of diffuse transmittance, 1 − F_int = (1 − F_ext)/n².
    /// The midpoint sum's own error (2×10⁵ points, kink at the critical angle) and its 6 digits.
    const MIDPOINT_SUM: f64 = 1e-5;
    assert!((hemispherical_fresnel_reflectance(1.333, 1.0) - 0.474591).abs() < MIDPOINT_SUM);
    /// An exact identity; the two 64-point quadratures are each good to ~10⁻¹².
    const IDENTITY: f64 = 1e-9;
    for n in [1.1, 1.333, 1.5, 2.0] {
        let (ext, int) = (hemispherical_fresnel_reflectance(1.0, n), hemispherical_fresnel_reflectance(n, 1.0));
        assert_relative_eq!(1.0 - int, (1.0 - ext) / (n * n), max_relative = IDENTITY);
    }
}

#[test]
fn jensen_f_dr_fit_against_the_exact_integral() {
    // Egan & Hilgeman's fit is quoted to about 10⁻³ (Donner & Jensen 2005); the exact
    // hemispherical integral is computed by quadrature.
    /// Largest |fit − exact| found over η ∈ [1.1, 2] and at 0.74, with margin.
    const FIT: f64 = 2e-3;
    for eta in [0.74, 1.1, 1.2, 1.3, 1.33, 1.4, 1.5, 1.7, 2.0] {
        let exact = hemispherical_fresnel_reflectance(eta, 1.0);
        assert!((diffuse_fresnel_reflectance(eta) - exact).abs() < FIT, "η = {eta}");
    }
}

#[test]
fn dipole_oracles() {
    // Sheet oracles (5 digits): F_dr, A at η = 1.3, 1.33; apple R_d(0), R_d(1 mm), total R.
    const FIVE_DIGITS: f64 = 1e-4;
    let m = DipoleMaterial::new(0.0034, 2.39, 0.0, 1.3).unwrap();
    assert_relative_eq!(m.f_dr(), 0.44476, max_relative = FIVE_DIGITS);
    assert_relative_eq!(m.a(), 2.60206, max_relative = FIVE_DIGITS);
    assert_relative_eq!(m.diffuse_reflectance(0.0), 0.47626, max_relative = FIVE_DIGITS);
    assert_relative_eq!(m.diffuse_reflectance(1.0), 4.0672e-2, max_relative = FIVE_DIGITS);
    assert_relative_eq!(m.total_diffuse_reflectance(), 0.84068, max_relative = FIVE_DIGITS);
    let w = DipoleMaterial::new(0.01, 1.0, 0.0, 1.33).unwrap();
    assert_relative_eq!(w.f_dr(), 0.47236, max_relative = FIVE_DIGITS);
    assert_relative_eq!(w.a(), 2.79044, max_relative = FIVE_DIGITS);
}

#[test]
fn brdf_oracles() {
    const FIVE_DIGITS: f64 = 1e-4;
    assert_relative_eq!(smith_lambda(0.3, 0.05), 2.5705e-2, max_relative = FIVE_DIGITS);
    assert_relative_eq!(smith_lambda(0.1, 0.1), 0.81811, max_relative = FIVE_DIGITS);
    assert_relative_eq!(mean_fresnel(0.5, 0.1), 0.06037, max_relative = FIVE_DIGITS);
    /// Six printed digits (0.133975 = 1 − √3/2).
    const SIX_DIGITS: f64 = 1e-5;
    /// `1 − √(1 − 0.64) = 0.4` up to rounding.
    const ROUNDING: f64 = 1e-12;
    assert_relative_eq!(trochoid_mean_square_slope(0.5), 0.133975, max_relative = SIX_DIGITS);
    assert_relative_eq!(trochoid_mean_square_slope(0.8), 0.4, max_relative = ROUNDING);
}

#[test]
fn quan_fry_index_of_pure_water() {
    // n_D(20 °C) of pure water = 1.33299 (IAPWS 1997); Quan & Fry's fit is good to ~3×10⁻⁵.
    /// Quan & Fry's fit accuracy (~3×10⁻⁵) with margin, plus the wavelength rounding.
    const FIT: f64 = 1e-4;
    let n = Seawater::new(20.0, 0.0).unwrap().refractive_index(589.3);
    assert!((n - 1.33299).abs() < FIT, "{n}");
}
