//! Inherent optical properties of Case-1 sea water by wavelength and chlorophyll: the bio-optical
//! model Premoze & Ashikhmin (2001) take from Morel (1988, 1991), on the published tables.

use crate::error::{OpticsError, check};
use crate::tables;

/// Shortest wavelength of the water model (nm): the Morel (1988) and Prieur & Sathyendranath
/// (1981) tables start here.
pub const LAMBDA_MIN_NM: f64 = 400.0;
/// Longest wavelength of the water model (nm).
pub const LAMBDA_MAX_NM: f64 = 700.0;

/// Checks a wavelength against the model's range `[400, 700]` nm.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm).
///
/// # Returns
/// `lambda_nm` (nm) if in `[400, 700]`.
///
/// # Errors
/// [`OpticsError::OutOfRange`] outside the range or for NaN.
///
/// # References
/// The common range of the tables (Morel 1988 Table 2; Prieur & Sathyendranath 1981 Table 2).
pub fn check_wavelength(lambda_nm: f64) -> Result<f64, OpticsError> {
    check("wavelength_nm", lambda_nm, (LAMBDA_MIN_NM..=LAMBDA_MAX_NM).contains(&lambda_nm), "[400, 700] nm")
}

/// Inherent optical properties of a water body at one wavelength (all m⁻¹).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Iops {
    /// Absorption coefficient `a`.
    pub a: f64,
    /// Scattering coefficient `b`.
    pub b: f64,
    /// Backscattering coefficient `b_b`.
    pub b_b: f64,
    /// Beam attenuation `c = a + b`.
    pub c: f64,
    /// Diffuse attenuation coefficient of downwelling irradiance `K_d` (an apparent property,
    /// carried with the IOPs because the Darles §4.3 radiance needs it).
    pub k_d: f64,
}

/// Chlorophyll-a concentration of Case-1 water, validated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chlorophyll(pub(crate) f64);

impl Chlorophyll {
    /// Largest accepted concentration (mg m⁻³): beyond 100 the Morel (1988) backscattering ratio
    /// `0.002 + 0.02(0.5 − 0.25 log₁₀ C)` turns negative.
    pub const MAX_MG_M3: f64 = 100.0;

    /// A concentration `C` in mg m⁻³, `[0, 100]` (the model was fitted on about 0.02–10; `0` is
    /// pure sea water).
    ///
    /// # Arguments
    /// - `c_mg_m3`: chlorophyll-a concentration (mg m⁻³), `[0, 100]`.
    ///
    /// # Returns
    /// The validated concentration.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] outside `[0, 100]` or for NaN.
    ///
    /// # References
    /// Morel A. 1988, "Optical modeling of the upper ocean in relation to its biogenous matter
    /// content (case I waters)", JGR 93(C9):10749–10768, Eq. 13 (the backscattering ratio that
    /// sets the upper bound).
    pub fn new(c_mg_m3: f64) -> Result<Self, OpticsError> {
        check("chlorophyll_mg_m3", c_mg_m3, (0.0..=Self::MAX_MG_M3).contains(&c_mg_m3), "[0, 100] mg/m3").map(Self)
    }

    /// The concentration (mg m⁻³).
    pub fn mg_m3(self) -> f64 {
        self.0
    }
}

/// Absorption coefficient of pure water (Pope & Fry 1997), linearly interpolated in their table.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[380, 700]`; clamped to that range.
///
/// # Returns
/// `a_w` (m⁻¹); the published value at each tabulated wavelength (every 2.5 nm).
///
/// # References
/// Pope R., Fry E. 1997, "Absorption spectrum (380–700 nm) of pure water. II. Integrating cavity
/// measurements", Applied Optics 36(33):8710–8723, Table 3; docs/equations.md §7.
pub fn pure_water_absorption(lambda_nm: f64) -> f64 {
    tables::pope_fry().at(0, lambda_nm)
}

/// Scattering coefficient of pure sea water `b_w` (Morel 1974 as tabulated with Morel 1988).
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped.
///
/// # Returns
/// `b_w` (m⁻¹), the tabulated value every 5 nm, linear between (the table has 2 significant
/// digits; [`pure_seawater_scattering_power_law`] is the smooth law it follows).
///
/// # References
/// Morel A. 1974, "Optical properties of pure water and pure sea water"; Morel 1988, JGR
/// 93(C9):10749–10768; docs/equations.md §7.
pub fn pure_seawater_scattering(lambda_nm: f64) -> f64 {
    let t = tables::morel();
    t.at(t.column("b_w_per_m"), lambda_nm)
}

/// Morel's power law for pure sea-water scattering, `b_w = 0.00758 (400/λ)^4.32`.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `> 0`.
///
/// # Returns
/// `b_w` (m⁻¹); `0.0029` at 500 nm.
///
/// # References
/// Morel 1974 (`b_w ∝ λ^{−4.32}`); docs/equations.md §7.
pub fn pure_seawater_scattering_power_law(lambda_nm: f64) -> f64 {
    0.00758 * (400.0 / lambda_nm).powf(4.32)
}

/// Chlorophyll-specific absorption of phytoplankton normalised at 440 nm, `a*_c(λ)`.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped.
///
/// # Returns
/// `a*_c` (dimensionless, `1` at 440 nm), the tabulated value every 5 nm, linear between.
///
/// # References
/// Prieur L., Sathyendranath S. 1981, Limnol. Oceanogr. 26(4):671–689, Table 2; used by Morel
/// 1991 and Premoze & Ashikhmin 2001; docs/equations.md §7.
pub fn chlorophyll_specific_absorption(lambda_nm: f64) -> f64 {
    tables::prieur_sathyendranath().at(0, lambda_nm)
}

/// Morel's (1988) coefficients `(K_w, χ, e)` of `K_d = K_w + χ C^e` at one wavelength.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped.
///
/// # Returns
/// `K_w` (m⁻¹), `χ` (m⁻¹ (mg m⁻³)^{−e}), `e` (1); linear between the 5 nm rows.
///
/// # References
/// Morel A. 1988, "Optical modeling of the upper ocean in relation to its biogenous matter
/// content (case I waters)", JGR 93(C9):10749–10768, Table 2; docs/equations.md §7.
pub fn morel_kd_coefficients(lambda_nm: f64) -> (f64, f64, f64) {
    let t = tables::morel();
    (t.at(0, lambda_nm), t.at(1, lambda_nm), t.at(2, lambda_nm))
}

/// Diffuse attenuation of downwelling irradiance in Case-1 water, `K_d = K_w + χ C^e`.
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped.
/// - `chl`: chlorophyll concentration.
///
/// # Returns
/// `K_d` (m⁻¹); e.g. 0.1139 m⁻¹ at 450 nm for `C = 1`.
///
/// # References
/// Morel 1988, Eq. 7 and Table 2; docs/equations.md §7.
pub fn morel_kd(lambda_nm: f64, chl: Chlorophyll) -> f64 {
    let (k_w, chi, e) = morel_kd_coefficients(lambda_nm);
    if chl.0 == 0.0 { k_w } else { k_w + chi * chl.0.powf(e) }
}

/// The Case-1 inherent optical properties of Premoze & Ashikhmin (2001) after Morel:
///
/// - `a = [a_w + 0.06 a*_c C^0.65] [1 + 0.2 e^{−0.014(λ − 440)}]` (Morel 1991, with yellow
///   substance; as printed, the bracket includes `a_w`, so `C = 0` gives `1.2 a_w` at 440 nm);
/// - `b = b_w + 0.30 C^0.62 (550/λ)` (Gordon & Morel 1983);
/// - `b_b = ½ b_w + b̃_b · 0.30 C^0.62`, `b̃_b = 0.002 + 0.02 (0.5 − 0.25 log₁₀ C)(550/λ)`
///   (Morel 1988: flat particle scattering, the `550/λ` in the ratio);
/// - `c = a + b`; `K_d = K_w + χ C^e` (Morel 1988).
///
/// # Arguments
/// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped to it.
/// - `chl`: chlorophyll concentration.
///
/// # Returns
/// The [`Iops`] (m⁻¹).
///
/// # References
/// Premoze S., Ashikhmin M. 2001, "Rendering natural waters", CGF 20(4):189–200, §3; Morel A.
/// 1988, JGR 93(C9), Eq. 3, 7, 12 and Table 2; Morel A. 1991, Prog. Oceanogr. 26:263–306;
/// Gordon H., Morel A. 1983; docs/equations.md §7.
pub fn case1_iops(lambda_nm: f64, chl: Chlorophyll) -> Iops {
    let lambda = lambda_nm.clamp(LAMBDA_MIN_NM, LAMBDA_MAX_NM);
    let c = chl.0;
    let a_w = pure_water_absorption(lambda);
    let b_w = pure_seawater_scattering(lambda);
    let yellow = 1.0 + 0.2 * (-0.014 * (lambda - 440.0)).exp();
    let (a, b, b_b) = if c == 0.0 {
        (a_w * yellow, b_w, 0.5 * b_w)
    } else {
        let a = (a_w + 0.06 * chlorophyll_specific_absorption(lambda) * c.powf(0.65)) * yellow;
        let b_p = 0.30 * c.powf(0.62);
        let b = b_w + b_p * (550.0 / lambda);
        let ratio = 0.002 + 0.02 * (0.5 - 0.25 * c.log10()) * (550.0 / lambda);
        (a, b, 0.5 * b_w + ratio * b_p)
    };
    Iops { a, b, b_b, c: a + b, k_d: morel_kd(lambda, chl) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The sheet's oracle values are printed to 4 significant digits: half a unit of the 4th
    /// digit of the smallest value at C = 1 (0.1050).
    const ORACLE: f64 = 5e-4;
    /// At C = 0.1 the smallest oracle is 0.0361: half a unit of its last digit is 1.4×10⁻³.
    const ORACLE_LOW_C: f64 = 2e-3;
    /// Three significant digits (0.00652).
    const THREE_DIGITS: f64 = 1e-3;

    #[test]
    fn morel_kd_oracles() {
        let c01 = Chlorophyll::new(0.1).unwrap();
        let c1 = Chlorophyll::new(1.0).unwrap();
        for (lambda, k01, k1) in [(450.0, 0.0361, 0.1139), (550.0, 0.0732, 0.1050), (650.0, 0.3596, 0.3950)] {
            assert_relative_eq!(morel_kd(lambda, c01), k01, max_relative = ORACLE_LOW_C);
            assert_relative_eq!(morel_kd(lambda, c1), k1, max_relative = ORACLE);
        }
    }

    #[test]
    fn backscattering_oracle() {
        // b_b(450, C = 1, Morel form) = 0.00652 m⁻¹ (sheet oracle, 3 significant digits).
        let iops = case1_iops(450.0, Chlorophyll::new(1.0).unwrap());
        assert_relative_eq!(iops.b_b, 0.00652, max_relative = THREE_DIGITS);
    }

    #[test]
    fn chlorophyll_range_is_checked() {
        assert!(Chlorophyll::new(-1.0).is_err());
        assert!(Chlorophyll::new(f64::NAN).is_err());
        assert!(Chlorophyll::new(101.0).is_err());
        assert!(check_wavelength(399.0).is_err());
        assert!(check_wavelength(550.0).is_ok());
    }
}
