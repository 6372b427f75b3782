//! Jerlov's optical water types: classes of measured diffuse attenuation `K_d(λ)`.

use std::fmt;
use std::str::FromStr;

use crate::error::OpticsError;
use crate::iop::{Chlorophyll, LAMBDA_MAX_NM, LAMBDA_MIN_NM, morel_kd};
use crate::tables;

/// A Jerlov water type: oceanic I, IA, IB, II, III and coastal 1, 3, 5, 7, 9.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JerlovType {
    /// Oceanic I: the clearest open ocean.
    I,
    /// Oceanic IA.
    IA,
    /// Oceanic IB.
    IB,
    /// Oceanic II.
    II,
    /// Oceanic III.
    III,
    /// Coastal 1.
    Coastal1,
    /// Coastal 3.
    Coastal3,
    /// Coastal 5.
    Coastal5,
    /// Coastal 7.
    Coastal7,
    /// Coastal 9: the most turbid.
    Coastal9,
}

impl JerlovType {
    /// All types, clearest first.
    pub const ALL: [JerlovType; 10] = [
        JerlovType::I,
        JerlovType::IA,
        JerlovType::IB,
        JerlovType::II,
        JerlovType::III,
        JerlovType::Coastal1,
        JerlovType::Coastal3,
        JerlovType::Coastal5,
        JerlovType::Coastal7,
        JerlovType::Coastal9,
    ];

    /// The type's name as Jerlov prints it (`"I"`, `"IA"`, …, `"1C"`, …, `"9C"`).
    pub fn name(self) -> &'static str {
        match self {
            JerlovType::I => "I",
            JerlovType::IA => "IA",
            JerlovType::IB => "IB",
            JerlovType::II => "II",
            JerlovType::III => "III",
            JerlovType::Coastal1 => "1C",
            JerlovType::Coastal3 => "3C",
            JerlovType::Coastal5 => "5C",
            JerlovType::Coastal7 => "7C",
            JerlovType::Coastal9 => "9C",
        }
    }

    /// Whether the type is oceanic (I–III) rather than coastal.
    pub fn is_oceanic(self) -> bool {
        matches!(self, JerlovType::I | JerlovType::IA | JerlovType::IB | JerlovType::II | JerlovType::III)
    }

    fn column(self) -> usize {
        Self::ALL.iter().position(|t| *t == self).unwrap_or(0)
    }

    /// Jerlov's diffuse attenuation coefficient of downwelling irradiance for this type,
    /// linearly interpolated between his 25 nm columns.
    ///
    /// # Arguments
    /// - `lambda_nm`: wavelength (nm), `[350, 700]`; clamped.
    ///
    /// # Returns
    /// `K_d` (m⁻¹); the published value at each tabulated wavelength.
    ///
    /// # References
    /// Jerlov N. G. 1976, *Marine Optics* (2nd ed., Elsevier), Table XXVII; docs/equations.md §7.
    pub fn kd(self, lambda_nm: f64) -> f64 {
        tables::jerlov().at(self.column(), lambda_nm)
    }

    /// The Case-1 chlorophyll whose Morel (1988) `K_d(λ)` best matches this type's table:
    /// `C* = argmin Σ_λ [ln K_d^Morel(λ, C) − ln K_d^Jerlov(λ)]²` over the table's wavelengths
    /// 400–700 nm (13 columns), `C ∈ [0.001, 100]` mg m⁻³, by golden-section search in `log C`.
    ///
    /// This is Brine's own derivation (not a published table): it gives a named type the
    /// absorption and scattering Jerlov did not measure. For the coastal types (Case-2 water,
    /// coloured by dissolved matter and sediment) the fit is poor; see [`Self::equivalent_fit_rms`].
    ///
    /// # Returns
    /// `C*` (mg m⁻³).
    ///
    /// # References
    /// Method after Solonenko M., Mobley C. 2015, "Inherent optical properties of Jerlov water
    /// types", Applied Optics 54(17):5392–5401 (who fit a richer IOP model to the same `K_d`).
    pub fn equivalent_chlorophyll(self) -> f64 {
        let cost = |log_c: f64| {
            let chl = Chlorophyll(10f64.powf(log_c));
            (0..=12)
                .map(|i| {
                    let lambda = LAMBDA_MIN_NM + 25.0 * f64::from(i);
                    let r = morel_kd(lambda, chl).ln() - self.kd(lambda).ln();
                    r * r
                })
                .sum::<f64>()
        };
        let (mut lo, mut hi) = (-3.0f64, 2.0f64);
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        let (mut x1, mut x2) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
        let (mut f1, mut f2) = (cost(x1), cost(x2));
        for _ in 0..80 {
            if f1 < f2 {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - phi * (hi - lo);
                f1 = cost(x1);
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + phi * (hi - lo);
                f2 = cost(x2);
            }
        }
        10f64.powf(0.5 * (lo + hi))
    }

    /// Root-mean-square of `ln(K_d^Morel/K_d^Jerlov)` at [`Self::equivalent_chlorophyll`] over
    /// 400–700 nm: how well a Case-1 water stands for this type (0.1 ≈ 10 % typical error).
    pub fn equivalent_fit_rms(self) -> f64 {
        let chl = Chlorophyll(self.equivalent_chlorophyll());
        let s: f64 = (0..=12)
            .map(|i| {
                let lambda = LAMBDA_MIN_NM + 25.0 * f64::from(i);
                (morel_kd(lambda, chl) / self.kd(lambda)).ln().powi(2)
            })
            .sum();
        (s / 13.0).sqrt()
    }
}

impl fmt::Display for JerlovType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for JerlovType {
    type Err = OpticsError;

    /// Parses `I`, `IA`, `IB`, `II`, `III` (case-insensitive) and the coastal types as `1`, `1C`,
    /// `C1` (likewise 3, 5, 7, 9).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let u = s.trim().to_ascii_uppercase();
        let coastal = u.trim_start_matches('C').trim_end_matches('C');
        Ok(match (u.as_str(), coastal) {
            ("I", _) => JerlovType::I,
            ("IA", _) => JerlovType::IA,
            ("IB", _) => JerlovType::IB,
            ("II", _) => JerlovType::II,
            ("III", _) => JerlovType::III,
            (_, "1") => JerlovType::Coastal1,
            (_, "3") => JerlovType::Coastal3,
            (_, "5") => JerlovType::Coastal5,
            (_, "7") => JerlovType::Coastal7,
            (_, "9") => JerlovType::Coastal9,
            _ => {
                return Err(OpticsError::UnknownName {
                    name: "jerlov_type",
                    value: s.to_owned(),
                    expected: "I, IA, IB, II, III, 1C, 3C, 5C, 7C or 9C",
                });
            }
        })
    }
}

/// The water "types A, B, C" (clear, turbid, very turbid) of Darles et al. 2007 §4.3.
///
/// They are not a standard; Brine maps them to Jerlov types (its own choice, documented here):
/// clear → oceanic I, turbid → oceanic III, very turbid → coastal 5.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DarlesWater {
    /// "A", clear water → Jerlov I.
    Clear,
    /// "B", turbid water → Jerlov III.
    Turbid,
    /// "C", very turbid water → Jerlov coastal 5.
    VeryTurbid,
}

impl DarlesWater {
    /// The Jerlov type Brine uses for this class.
    pub fn jerlov(self) -> JerlovType {
        match self {
            DarlesWater::Clear => JerlovType::I,
            DarlesWater::Turbid => JerlovType::III,
            DarlesWater::VeryTurbid => JerlovType::Coastal5,
        }
    }
}

/// Range of [`JerlovType::kd`] (nm).
pub const JERLOV_LAMBDA_RANGE_NM: (f64, f64) = (350.0, LAMBDA_MAX_NM);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for t in JerlovType::ALL {
            assert_eq!(t.name().parse::<JerlovType>().unwrap(), t);
        }
        assert_eq!("c5".parse::<JerlovType>().unwrap(), JerlovType::Coastal5);
        assert_eq!("7".parse::<JerlovType>().unwrap(), JerlovType::Coastal7);
        assert!("IV".parse::<JerlovType>().is_err());
    }

    #[test]
    fn type_ii_kd_at_480_is_about_0_064() {
        // docs/equations.md §7: Jerlov II K_d(480) ≈ 0.064 m⁻¹; linear between 0.062 (475) and
        // 0.070 (500): 0.062 + 0.2 × 0.008 = 0.0636.
        /// Rounding only (the interpolation is exact in decimal to 4 places).
        const ROUNDING: f64 = 1e-15;
        assert!((JerlovType::II.kd(480.0) - 0.0636).abs() < ROUNDING);
    }

    #[test]
    fn equivalent_chlorophyll_increases_with_turbidity() {
        let c: Vec<f64> = [JerlovType::I, JerlovType::IA, JerlovType::IB, JerlovType::II, JerlovType::III]
            .map(|t| t.equivalent_chlorophyll())
            .to_vec();
        assert!(c.windows(2).all(|w| w[0] < w[1]), "{c:?}");
    }
}
