//! The CIE 1931 2° standard colorimetric observer.
//!
//! Colour-matching functions `x̄(λ)`, `ȳ(λ)`, `z̄(λ)` from 360 to 830 nm every 5 nm: the 5 nm
//! values of the 1 nm table of CIE 15:2004 *Colorimetry*, Table T.4 (CVRL file `ciexyz31_1`),
//! transcribed from `observers/cie-1931-2.json` of the public repository `coloria-dev/color-data`.
//! Sums of that 1 nm table: `Σx̄ = 106.8655`, `Σȳ = 106.8569`, `Σz̄ = 106.8923` nm.

/// First wavelength of [`CIE_1931_2DEG`] (nm).
pub const CMF_START_NM: f64 = 360.0;

/// Step of [`CIE_1931_2DEG`] (nm).
pub const CMF_STEP_NM: f64 = 5.0;

/// Maximum luminous efficacy of radiation `K_m` (lm W⁻¹), at 555 nm (540 THz).
///
/// # References
/// BIPM SI Brochure, 9th ed. (2019), definition of the candela (683 lm W⁻¹ at 540×10¹² Hz).
pub const MAX_LUMINOUS_EFFICACY: f64 = 683.0;

/// `[x̄, ȳ, z̄]` at `360 + 5i` nm, `i = 0..95` (CIE 15:2004 Table T.4).
pub const CIE_1931_2DEG: [[f64; 3]; 95] = [
    [0.0001299, 3.917e-06, 0.0006061],   // 360 nm
    [0.0002321, 6.965e-06, 0.001086],    // 365 nm
    [0.0004149, 1.239e-05, 0.001946],    // 370 nm
    [0.0007416, 2.202e-05, 0.003486],    // 375 nm
    [0.001368, 3.9e-05, 0.006450001],    // 380 nm
    [0.002236, 6.4e-05, 0.01054999],     // 385 nm
    [0.004243, 0.00012, 0.02005001],     // 390 nm
    [0.00765, 0.000217, 0.03621],        // 395 nm
    [0.01431, 0.000396, 0.06785001],     // 400 nm
    [0.02319, 0.00064, 0.1102],          // 405 nm
    [0.04351, 0.00121, 0.2074],          // 410 nm
    [0.07763, 0.00218, 0.3713],          // 415 nm
    [0.13438, 0.004, 0.6456],            // 420 nm
    [0.21477, 0.0073, 1.0390501],        // 425 nm
    [0.2839, 0.0116, 1.3856],            // 430 nm
    [0.3285, 0.01684, 1.62296],          // 435 nm
    [0.34828, 0.023, 1.74706],           // 440 nm
    [0.34806, 0.0298, 1.7826],           // 445 nm
    [0.3362, 0.038, 1.77211],            // 450 nm
    [0.3187, 0.048, 1.7441],             // 455 nm
    [0.2908, 0.06, 1.6692],              // 460 nm
    [0.2511, 0.0739, 1.5281],            // 465 nm
    [0.19536, 0.09098, 1.28764],         // 470 nm
    [0.1421, 0.1126, 1.0419],            // 475 nm
    [0.09564, 0.13902, 0.8129501],       // 480 nm
    [0.05795001, 0.1693, 0.6162],        // 485 nm
    [0.03201, 0.20802, 0.46518],         // 490 nm
    [0.0147, 0.2586, 0.3533],            // 495 nm
    [0.0049, 0.323, 0.272],              // 500 nm
    [0.0024, 0.4073, 0.2123],            // 505 nm
    [0.0093, 0.503, 0.1582],             // 510 nm
    [0.0291, 0.6082, 0.1117],            // 515 nm
    [0.06327, 0.71, 0.07824999],         // 520 nm
    [0.1096, 0.7932, 0.05725001],        // 525 nm
    [0.1655, 0.862, 0.04216],            // 530 nm
    [0.2257499, 0.9148501, 0.02984],     // 535 nm
    [0.2904, 0.954, 0.0203],             // 540 nm
    [0.3597, 0.9803, 0.0134],            // 545 nm
    [0.4334499, 0.9949501, 0.008749999], // 550 nm
    [0.5120501, 1.0, 0.005749999],       // 555 nm
    [0.5945, 0.995, 0.0039],             // 560 nm
    [0.6784, 0.9786, 0.002749999],       // 565 nm
    [0.7621, 0.952, 0.0021],             // 570 nm
    [0.8425, 0.9154, 0.0018],            // 575 nm
    [0.9163, 0.87, 0.001650001],         // 580 nm
    [0.9786, 0.8163, 0.0014],            // 585 nm
    [1.0263, 0.757, 0.0011],             // 590 nm
    [1.0567, 0.6949, 0.001],             // 595 nm
    [1.0622, 0.631, 0.0008],             // 600 nm
    [1.0456, 0.5668, 0.0006],            // 605 nm
    [1.0026, 0.503, 0.00034],            // 610 nm
    [0.9384, 0.4412, 0.00024],           // 615 nm
    [0.8544499, 0.381, 0.00019],         // 620 nm
    [0.7514, 0.321, 0.0001],             // 625 nm
    [0.6424, 0.265, 4.999999e-05],       // 630 nm
    [0.5419, 0.217, 3e-05],              // 635 nm
    [0.4479, 0.175, 2e-05],              // 640 nm
    [0.3608, 0.1382, 1e-05],             // 645 nm
    [0.2835, 0.107, 0.0],                // 650 nm
    [0.2187, 0.0816, 0.0],               // 655 nm
    [0.1649, 0.061, 0.0],                // 660 nm
    [0.1212, 0.04458, 0.0],              // 665 nm
    [0.0874, 0.032, 0.0],                // 670 nm
    [0.0636, 0.0232, 0.0],               // 675 nm
    [0.04677, 0.017, 0.0],               // 680 nm
    [0.0329, 0.01192, 0.0],              // 685 nm
    [0.0227, 0.00821, 0.0],              // 690 nm
    [0.01584, 0.005723, 0.0],            // 695 nm
    [0.01135916, 0.004102, 0.0],         // 700 nm
    [0.008110916, 0.002929, 0.0],        // 705 nm
    [0.005790346, 0.002091, 0.0],        // 710 nm
    [0.004109457, 0.001484, 0.0],        // 715 nm
    [0.002899327, 0.001047, 0.0],        // 720 nm
    [0.00204919, 0.00074, 0.0],          // 725 nm
    [0.001439971, 0.00052, 0.0],         // 730 nm
    [0.0009999493, 0.0003611, 0.0],      // 735 nm
    [0.0006900786, 0.0002492, 0.0],      // 740 nm
    [0.0004760213, 0.0001719, 0.0],      // 745 nm
    [0.0003323011, 0.00012, 0.0],        // 750 nm
    [0.0002348261, 8.48e-05, 0.0],       // 755 nm
    [0.0001661505, 6e-05, 0.0],          // 760 nm
    [0.000117413, 4.24e-05, 0.0],        // 765 nm
    [8.307527e-05, 3e-05, 0.0],          // 770 nm
    [5.870652e-05, 2.12e-05, 0.0],       // 775 nm
    [4.150994e-05, 1.499e-05, 0.0],      // 780 nm
    [2.935326e-05, 1.06e-05, 0.0],       // 785 nm
    [2.067383e-05, 7.4657e-06, 0.0],     // 790 nm
    [1.455977e-05, 5.2578e-06, 0.0],     // 795 nm
    [1.025398e-05, 3.7029e-06, 0.0],     // 800 nm
    [7.221456e-06, 2.6078e-06, 0.0],     // 805 nm
    [5.085868e-06, 1.8366e-06, 0.0],     // 810 nm
    [3.581652e-06, 1.2934e-06, 0.0],     // 815 nm
    [2.522525e-06, 9.1093e-07, 0.0],     // 820 nm
    [1.776509e-06, 6.4153e-07, 0.0],     // 825 nm
    [1.251141e-06, 4.5181e-07, 0.0],     // 830 nm
];

/// The colour-matching functions at `wavelength_nm`, linearly interpolated; zero outside
/// 360–830 nm.
///
/// # Arguments
/// - `wavelength_nm`: wavelength (nm).
///
/// # Returns
/// `[x̄, ȳ, z̄]` (dimensionless, `ȳ` peaks at 1 at 555 nm).
///
/// # References
/// CIE 15:2004, Table T.4.
pub fn cmf(wavelength_nm: f64) -> [f64; 3] {
    let u = (wavelength_nm - CMF_START_NM) / CMF_STEP_NM;
    if !(0.0..=(CIE_1931_2DEG.len() - 1) as f64).contains(&u) {
        return [0.0; 3];
    }
    let i = (u as usize).min(CIE_1931_2DEG.len() - 2);
    let f = u - i as f64;
    let (a, b) = (CIE_1931_2DEG[i], CIE_1931_2DEG[i + 1]);
    [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 5 nm rectangle rule against the CIE's 1 nm sums: 10⁻⁴ relative (measured 3×10⁻⁶).
    const RULE_5NM: f64 = 1e-4;
    /// Table values and linear interpolation reproduced exactly, up to rounding.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn integrals_match_the_published_sums() {
        // The 5 nm rectangle rule against the 1 nm sums of the CIE table: the functions are smooth,
        // so the two agree to 10⁻⁴ relative (measured 3×10⁻⁶; the tolerance leaves room).
        let mut s = [0.0; 3];
        for row in CIE_1931_2DEG {
            for k in 0..3 {
                s[k] += row[k] * CMF_STEP_NM;
            }
        }
        for (got, want) in s.iter().zip([106.8655, 106.8569, 106.8923]) {
            assert!((got / want - 1.0).abs() < RULE_5NM, "{got} vs {want}");
        }
        // Equal-energy white is (1/3, 1/3) within 10⁻⁴ (the CIE normalisation).
        let t = s[0] + s[1] + s[2];
        assert!((s[0] / t - 1.0 / 3.0).abs() < RULE_5NM && (s[1] / t - 1.0 / 3.0).abs() < RULE_5NM);
    }

    #[test]
    fn luminosity_peak_and_interpolation() {
        assert!((cmf(555.0)[1] - 1.0).abs() < ROUNDING);
        let mid = cmf(557.5)[1];
        assert!((mid - 0.5 * (1.0 + 0.995)).abs() < ROUNDING);
        assert!(cmf(300.0).iter().all(|c| c.abs() < f64::MIN_POSITIVE));
        assert!(cmf(900.0).iter().all(|c| c.abs() < f64::MIN_POSITIVE));
    }
}
