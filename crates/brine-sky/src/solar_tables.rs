//! Spectral tables of Preetham, Shirley & Smits (1999), Appendix A.1, as distributed in the
//! authors' code `RiSunConstants.C` (B. Smits, 1999; public copy in `ekmett/vr`,
//! `third-party/sunsky/RiSunConstants.C`). The absorption coefficients are those of Iqbal M.
//! 1983, *An Introduction to Solar Radiation* (Academic Press): ozone p. 127, mixed gases and
//! water vapour p. 130.

/// Extraterrestrial spectral radiance of the Sun disc, 380–750 nm every 10 nm, in the authors'
/// unit: multiply by [`SOLAR_RADIANCE_SCALE`] for W m⁻² sr⁻¹ nm⁻¹ (their code: "IN WRONG UNITS,
/// need a factor of 100").
pub const SOLAR_RADIANCE_380_750: [f64; 38] = [
    165.5, 162.3, 211.2, 258.8, 258.2, 242.3, 267.6, 296.6, 305.4, 300.6, 306.6, 288.3, 287.1, 278.2, 271.0, 272.3,
    263.6, 255.0, 250.6, 253.1, 253.5, 251.3, 246.3, 241.7, 236.8, 232.1, 228.2, 223.4, 219.7, 215.3, 211.0, 207.3,
    202.4, 198.7, 194.3, 190.7, 186.3, 182.6,
];

/// Factor from the table unit of [`SOLAR_RADIANCE_380_750`] to W m⁻² sr⁻¹ nm⁻¹.
pub const SOLAR_RADIANCE_SCALE: f64 = 100.0;

/// Ozone absorption coefficient `k_o(λ)`: `(λ nm, k_o cm⁻¹)`, Iqbal 1983 p. 127. The table jumps
/// from 355 to 445 nm (no absorption tabulated between the Huggins and Chappuis bands).
pub const K_OZONE: [(f64, f64); 64] = [
    (300.0, 10.0),
    (305.0, 4.8),
    (310.0, 2.7),
    (315.0, 1.35),
    (320.0, 0.8),
    (325.0, 0.380),
    (330.0, 0.160),
    (335.0, 0.075),
    (340.0, 0.04),
    (345.0, 0.019),
    (350.0, 0.007),
    (355.0, 0.0),
    (445.0, 0.003),
    (450.0, 0.003),
    (455.0, 0.004),
    (460.0, 0.006),
    (465.0, 0.008),
    (470.0, 0.009),
    (475.0, 0.012),
    (480.0, 0.014),
    (485.0, 0.017),
    (490.0, 0.021),
    (495.0, 0.025),
    (500.0, 0.03),
    (505.0, 0.035),
    (510.0, 0.04),
    (515.0, 0.045),
    (520.0, 0.048),
    (525.0, 0.057),
    (530.0, 0.063),
    (535.0, 0.07),
    (540.0, 0.075),
    (545.0, 0.08),
    (550.0, 0.085),
    (555.0, 0.095),
    (560.0, 0.103),
    (565.0, 0.110),
    (570.0, 0.12),
    (575.0, 0.122),
    (580.0, 0.12),
    (585.0, 0.118),
    (590.0, 0.115),
    (595.0, 0.12),
    (600.0, 0.125),
    (605.0, 0.130),
    (610.0, 0.12),
    (620.0, 0.105),
    (630.0, 0.09),
    (640.0, 0.079),
    (650.0, 0.067),
    (660.0, 0.057),
    (670.0, 0.048),
    (680.0, 0.036),
    (690.0, 0.028),
    (700.0, 0.023),
    (710.0, 0.018),
    (720.0, 0.014),
    (730.0, 0.011),
    (740.0, 0.010),
    (750.0, 0.009),
    (760.0, 0.007),
    (770.0, 0.004),
    (780.0, 0.0),
    (790.0, 0.0),
];

/// Mixed-gas (O₂ A band) absorption coefficient `k_g(λ)`: `(λ nm, k_g cm⁻¹)`, Iqbal 1983 p. 130.
pub const K_MIXED_GAS: [(f64, f64); 4] = [(759.0, 0.0), (760.0, 3.0), (770.0, 0.210), (771.0, 0.0)];

/// Water-vapour absorption coefficient `k_wa(λ)`: `(λ nm, k_wa cm⁻¹)`, Iqbal 1983 p. 130.
pub const K_WATER_VAPOUR: [(f64, f64); 13] = [
    (689.0, 0.0),
    (690.0, 0.160e-1),
    (700.0, 0.240e-1),
    (710.0, 0.125e-1),
    (720.0, 0.100e+1),
    (730.0, 0.870),
    (740.0, 0.610e-1),
    (750.0, 0.100e-2),
    (760.0, 0.100e-4),
    (770.0, 0.100e-4),
    (780.0, 0.600e-3),
    (790.0, 0.175e-1),
    (800.0, 0.360e-1),
];

/// Linear interpolation in an irregular `(x, y)` table; 0 outside it (as the authors'
/// `RiIrregularSpectralCurve`): `y = y_i + (x − x_i)(y_{i+1} − y_i)/(x_{i+1} − x_i)`.
///
/// # Arguments
/// - `table`: `(x, y)` pairs sorted by `x`, at least two.
/// - `x`: where to evaluate.
///
/// # Returns
/// The interpolated `y` (the table's unit); 0 outside `[x_first, x_last]`.
///
/// # References
/// Preetham et al.'s code (`RiIrregularSpectralCurve`).
pub fn interpolate(table: &[(f64, f64)], x: f64) -> f64 {
    let (first, last) = (table[0], table[table.len() - 1]);
    if !(first.0..=last.0).contains(&x) {
        return 0.0;
    }
    let i = table.partition_point(|p| p.0 <= x).clamp(1, table.len() - 1);
    let (a, b) = (table[i - 1], table[i]);
    a.1 + (x - a.0) / (b.0 - a.0) * (b.1 - a.1)
}

/// Extraterrestrial spectral radiance of the sun's disc, linear in the 10 nm table of
/// Preetham's code, `L₀(λ) = 100 · table(λ)`.
///
/// # Arguments
/// - `wavelength_nm`: λ (nm); 0 outside 380–750 nm.
///
/// # Returns
/// `L₀(λ)` in W m⁻² sr⁻¹ nm⁻¹, `≥ 0`.
///
/// # References
/// Preetham et al. 1999, Appendix A.1 and the authors' `RiSunConstants.C` (the table × 100).
pub fn solar_radiance(wavelength_nm: f64) -> f64 {
    let u = (wavelength_nm - 380.0) / 10.0;
    if !(0.0..=37.0).contains(&u) {
        return 0.0;
    }
    let i = (u as usize).min(36);
    let f = u - i as f64;
    SOLAR_RADIANCE_SCALE * (SOLAR_RADIANCE_380_750[i] + f * (SOLAR_RADIANCE_380_750[i + 1] - SOLAR_RADIANCE_380_750[i]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Linear interpolation reproduced exactly, up to rounding (relative to values of order 1).
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn chappuis_peak_matches_the_ozone_cross_section() {
        // Independent check of the transcription: the O₃ absorption cross-section at 602 nm is
        // 5.2×10⁻²¹ cm² (Burrows et al. 1999, J. Atmos. Chem. 34), i.e. k_o = σ N_L with the
        // Loschmidt number 2.687×10¹⁹ cm⁻³ = 0.140 cm⁻¹. Iqbal's 0.125–0.130 at 600–605 nm is
        // within 12 %; tolerance 15 % (older band measurements).
        const OLDER_BAND_DATA: f64 = 0.15;
        let k = interpolate(&K_OZONE, 602.0);
        assert!((k / (5.2e-21 * 2.687e19) - 1.0).abs() < OLDER_BAND_DATA, "k_o(602) = {k}");
        assert!((interpolate(&K_OZONE, 400.0) - 0.0015).abs() < ROUNDING, "linear across the gap");
        assert!(interpolate(&K_OZONE, 850.0).abs() < f64::MIN_POSITIVE);
    }

    #[test]
    fn tables_are_sorted_and_in_range() {
        for t in [&K_OZONE[..], &K_MIXED_GAS[..], &K_WATER_VAPOUR[..]] {
            assert!(t.windows(2).all(|w| w[0].0 < w[1].0));
            assert!(t.iter().all(|p| p.1 >= 0.0));
        }
        assert!((solar_radiance(555.0) - 100.0 * 0.5 * (255.0 + 250.6)).abs() < ROUNDING * 1e4);
    }
}
