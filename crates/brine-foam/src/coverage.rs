//! Whitecap coverage laws of Monahan & Ó Muircheartaigh (1980, 1986).

use crate::error::{FoamError, check};

/// Wind speed below which the sea carries no whitecaps in Darles et al. 2007 (§4.1):
/// 13 km/h = 3.611 m s⁻¹.
///
/// Observations agree: whitecaps form from about 3 m s⁻¹ (Monahan & Ó Muircheartaigh 1986;
/// Hanson & Phillips 1999) and the wind-only fit of Callaghan et al. (2008) starts at 3.70 m s⁻¹.
pub const DARLES_ONSET_WIND_M_S: f64 = 13.0 / 3.6;

/// Largest wind speed accepted (m s⁻¹), as for the wave spectra.
pub const MAX_WIND_M_S: f64 = 60.0;

/// Largest air–sea temperature difference `|ΔT| = |T_w − T_a|` (°C) accepted by the stability
/// forms: 30 °C.
///
/// This is Brine's envelope, not a published bound: docs/equations.md (§5) gives no range of
/// `ΔT` for the 1986 fit, which was made on open-ocean observations, where the air–sea
/// difference rarely exceeds a few degrees (the marine boundary layer is close to neutral). At
/// ±30 °C the factor `exp(0.0861 ΔT)` is already 13.2 (or 1/13.2), an
/// extrapolation far beyond any fitted condition; beyond it the law is refused rather than
/// clamped, so a wrong input cannot pass silently.
pub const MAX_ABS_DELTA_T_C: f64 = 30.0;

/// Room for the rounding of a difference of two temperatures given in decimals (°C): far below
/// any physical meaning, far above the f64 rounding of values within ±60 °C (about 10⁻¹⁴).
const DECIMAL_ROUNDING_C: f64 = 1e-9;

/// Checks `ΔT` against [`MAX_ABS_DELTA_T_C`].
fn check_delta_t(delta_t_c: f64) -> Result<f64, FoamError> {
    check(
        "delta_t_c",
        delta_t_c,
        delta_t_c.abs() <= MAX_ABS_DELTA_T_C,
        "[-30, 30] °C (delta_t_c = t_water_c − t_air_c)",
    )
}

/// An empirical law of the fraction of the sea surface covered by whitecaps.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum WhitecapLaw {
    /// Monahan & Ó Muircheartaigh 1980: `W = 3.84×10⁻⁶ U₁₀^3.41` (wind only; the law to use when
    /// the air–sea temperature difference is unknown).
    Monahan1980,
    /// Monahan & Ó Muircheartaigh 1986, wind-only form: `W = 2.95×10⁻⁶ U₁₀^3.52` (used by the 6S
    /// radiative-transfer code).
    Monahan1986Wind,
    /// Monahan & Ó Muircheartaigh 1986, stability form:
    /// `W = 1.95×10⁻⁵ U₁₀^2.55 exp(0.0861 ΔT)`, `ΔT = T_w − T_a` (°C). Warm water under cold air
    /// (unstable) gives more whitecaps.
    Monahan1986Stability {
        /// `ΔT = T_w − T_a` (°C), `[−30, 30]`.
        delta_t_c: f64,
    },
    /// Darles et al. 2007 Eq. 3 as printed: `s = 1.59×10⁻⁵ U₁₀^2.55 exp(0.086 ΔT)`. The
    /// coefficient is the 1986 stability form's 1.95 with two digits swapped; kept only to
    /// reproduce the paper (its coverage is 18 % low).
    Darles2007AsPrinted {
        /// `ΔT = T_w − T_a` (°C), `[−30, 30]`.
        delta_t_c: f64,
    },
}

impl WhitecapLaw {
    /// The 1986 stability form from the water and air temperatures, `ΔT = T_w − T_a`.
    ///
    /// `W = 1.95×10⁻⁵ U₁₀^2.55 exp(0.0861 ΔT)` with `ΔT = T_w − T_a` (°C), taken as given: a
    /// difference outside [`MAX_ABS_DELTA_T_C`] is an error, not clamped (the water and air
    /// ranges alone allow `ΔT` from −62 to +100 °C).
    ///
    /// # Arguments
    /// - `t_water_c`: sea-surface temperature `T_w` (°C), `[−2, 40]` (sea water freezes near
    ///   −1.9 °C; 40 °C bounds the warmest seas).
    /// - `t_air_c`: air temperature `T_a` (°C), `[−60, 60]`.
    ///
    /// Their difference `ΔT = t_water_c − t_air_c` (°C) must also lie in `[−30, 30]`.
    ///
    /// # Returns
    /// [`WhitecapLaw::Monahan1986Stability`] with `delta_t_c = t_water_c − t_air_c` (°C), exactly
    /// but for a difference within 10⁻⁹ °C of ±30 (the rounding of decimal inputs), which is ±30.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming `t_water_c` or `t_air_c` outside its range, or
    /// `delta_t_c` (with the value `t_water_c − t_air_c`) outside `[−30, 30]` °C.
    ///
    /// # References
    /// Monahan E., Ó Muircheartaigh I. 1986, "Whitecaps and the passive remote sensing of the
    /// ocean surface", Int. J. Remote Sens. 7(5):627–642 (stability-dependent fit); Darles et al.
    /// 2007 Eq. 3; docs/equations.md §5.
    pub fn monahan_1986_from_temperatures(t_water_c: f64, t_air_c: f64) -> Result<Self, FoamError> {
        let t_water_c = check("t_water_c", t_water_c, (-2.0..=40.0).contains(&t_water_c), "[-2, 40] °C")?;
        let t_air_c = check("t_air_c", t_air_c, (-60.0..=60.0).contains(&t_air_c), "[-60, 60] °C")?;
        // Two temperatures written with a few decimals differ by their rounding as well
        // (12.7 − 42.7 = −30.000000000000004): a difference within DECIMAL_ROUNDING_C of the
        // envelope is the envelope.
        let raw = t_water_c - t_air_c;
        let delta_t_c = if raw.abs() <= MAX_ABS_DELTA_T_C + DECIMAL_ROUNDING_C {
            raw.clamp(-MAX_ABS_DELTA_T_C, MAX_ABS_DELTA_T_C)
        } else {
            raw
        };
        let delta_t_c = check_delta_t(delta_t_c)?;
        Ok(Self::Monahan1986Stability { delta_t_c })
    }

    /// A short name for JSON and plots.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Monahan1980 => "monahan-1980",
            Self::Monahan1986Wind => "monahan-1986-wind",
            Self::Monahan1986Stability { .. } => "monahan-1986-stability",
            Self::Darles2007AsPrinted { .. } => "darles-2007-as-printed",
        }
    }
}

/// Checked parameters of a whitecap-coverage evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoverageParams {
    u10: f64,
    law: WhitecapLaw,
    onset: f64,
}

impl CoverageParams {
    /// The inputs of a whitecap-coverage evaluation, checked once.
    ///
    /// # Arguments
    /// - `u10`: wind speed 10 m above the sea `U₁₀` (m s⁻¹), `[0, 60]`.
    /// - `law`: the coverage law; a stability form's `delta_t_c` must lie in `[−30, 30]` °C.
    /// - `onset_m_s`: wind speed below which the coverage is zero (m s⁻¹), `[0, 10]`; use
    ///   [`DARLES_ONSET_WIND_M_S`] (3.61 m s⁻¹) unless you have a reason.
    ///
    /// # Returns
    /// The checked parameters, for [`whitecap_coverage`].
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the first parameter outside its range (`u10_m_s`,
    /// `onset_m_s`, `delta_t_c`).
    ///
    /// # References
    /// Monahan & Ó Muircheartaigh 1980, 1986 (laws fitted on ~4–20 m s⁻¹); Darles et al. 2007 §4.1
    /// (onset 13 km/h); docs/equations.md §5.
    pub fn new(u10: f64, law: WhitecapLaw, onset_m_s: f64) -> Result<Self, FoamError> {
        let u10 = check("u10_m_s", u10, (0.0..=MAX_WIND_M_S).contains(&u10), "[0, 60] m/s")?;
        let onset = check("onset_m_s", onset_m_s, (0.0..=10.0).contains(&onset_m_s), "[0, 10] m/s")?;
        if let WhitecapLaw::Monahan1986Stability { delta_t_c } | WhitecapLaw::Darles2007AsPrinted { delta_t_c } = law {
            check_delta_t(delta_t_c)?;
        }
        Ok(Self { u10, law, onset })
    }

    /// Wind speed `U₁₀` (m s⁻¹).
    pub fn u10(&self) -> f64 {
        self.u10
    }
    /// The law.
    pub fn law(&self) -> WhitecapLaw {
        self.law
    }
    /// Onset wind speed (m s⁻¹).
    pub fn onset(&self) -> f64 {
        self.onset
    }
}

/// Fraction of the sea surface covered by whitecaps.
///
/// `W = 3.84×10⁻⁶ U₁₀^3.41` (1980), `2.95×10⁻⁶ U₁₀^3.52` (1986, wind),
/// `1.95×10⁻⁵ U₁₀^2.55 e^{0.0861 ΔT}` (1986, stability), or Darles' printed
/// `1.59×10⁻⁵ U₁₀^2.55 e^{0.086 ΔT}`; `W = 0` below the onset wind, and `W = min(law, 1)`: the
/// whole sea white where a law passes 1, far outside the 4–20 m s⁻¹ they were fitted on — beyond
/// 38.7 m s⁻¹ (1980), 37.2 m s⁻¹ (1986, wind), and for the stability laws beyond 25.5 m s⁻¹ at
/// `ΔT = +30 °C` (27.7 as printed by Darles), 70 m s⁻¹ at `ΔT = 0` (past the 60 m s⁻¹ allowed).
///
/// # Arguments
/// - `params`: checked wind, law and onset ([`CoverageParams::new`]).
///
/// # Returns
/// The covered fraction `W` (dimensionless), in `[0, 1]`; non-decreasing in `U₁₀`.
///
/// # References
/// Monahan E., Ó Muircheartaigh I. 1980, "Optimal power-law description of oceanic whitecap
/// coverage dependence on wind speed", JPO 10:2094–2099; Monahan E., Ó Muircheartaigh I. 1986,
/// "Whitecaps and the passive remote sensing of the ocean surface", Int. J. Remote Sens.
/// 7(5):627–642; Darles et al. 2007 Eq. 3 (with its coefficient erratum); docs/equations.md §5.
pub fn whitecap_coverage(params: &CoverageParams) -> f64 {
    let u = params.u10;
    if u < params.onset || u <= 0.0 {
        return 0.0;
    }
    let w = match params.law {
        WhitecapLaw::Monahan1980 => 3.84e-6 * libm::pow(u, 3.41),
        WhitecapLaw::Monahan1986Wind => 2.95e-6 * libm::pow(u, 3.52),
        WhitecapLaw::Monahan1986Stability { delta_t_c } => 1.95e-5 * libm::pow(u, 2.55) * libm::exp(0.0861 * delta_t_c),
        WhitecapLaw::Darles2007AsPrinted { delta_t_c } => 1.59e-5 * libm::pow(u, 2.55) * libm::exp(0.086 * delta_t_c),
    };
    w.clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative tolerance for the reference's oracles, printed to 4 significant digits.
    const ORACLE_REL: f64 = 1e-4;

    fn cover(u: f64, law: WhitecapLaw) -> f64 {
        whitecap_coverage(&CoverageParams::new(u, law, DARLES_ONSET_WIND_M_S).unwrap())
    }

    #[test]
    fn zero_below_onset_and_at_calm() {
        assert!(cover(0.0, WhitecapLaw::Monahan1980).abs() < f64::MIN_POSITIVE);
        assert!(cover(3.6, WhitecapLaw::Monahan1980).abs() < f64::MIN_POSITIVE);
        assert!(cover(3.62, WhitecapLaw::Monahan1980) > 0.0);
    }

    #[test]
    fn a_difference_of_thirty_degrees_written_in_decimals_is_accepted() {
        // 12.7 − 42.7 rounds to −30.000000000000004 in f64; it is the envelope's end, not past it.
        let law = WhitecapLaw::monahan_1986_from_temperatures(12.7, 42.7).unwrap();
        assert_eq!(law, WhitecapLaw::Monahan1986Stability { delta_t_c: -30.0 });
        let law = WhitecapLaw::monahan_1986_from_temperatures(32.2, 2.2).unwrap();
        assert_eq!(law, WhitecapLaw::Monahan1986Stability { delta_t_c: 30.0 });
        // A real step past it is still refused.
        assert!(WhitecapLaw::monahan_1986_from_temperatures(12.7, 42.8).is_err());
    }

    #[test]
    fn stability_form_from_temperatures() {
        // Darles' figure 6 conditions: T_w = 12 °C, T_a = 20 °C, so ΔT = −8 °C.
        let law = WhitecapLaw::monahan_1986_from_temperatures(12.0, 20.0).unwrap();
        assert_eq!(law, WhitecapLaw::Monahan1986Stability { delta_t_c: -8.0 });
        let w = cover(10.0, law);
        let expected = 6.919e-3 * (0.0861f64 * -8.0).exp();
        assert!((w / expected - 1.0).abs() < ORACLE_REL, "{w} vs {expected}");
        assert!(WhitecapLaw::monahan_1986_from_temperatures(50.0, 20.0).is_err());
    }

    #[test]
    fn temperature_difference_beyond_30_is_an_error_not_a_clamp() {
        // Both temperatures in range, ΔT = 40 − 0 = 40 °C and −2 − (−60) = 58 °C: refused, with
        // the parameter, its value and its range in the message.
        for (tw, ta, dt) in [(40.0, 0.0, 40.0), (-2.0, -60.0, 58.0), (0.0, 45.0, -45.0), (10.0, 40.5, -30.5)] {
            let e = WhitecapLaw::monahan_1986_from_temperatures(tw, ta).unwrap_err();
            assert_eq!(
                e,
                FoamError::OutOfRange(brine_core::OutOfRange { name: "delta_t_c", value: dt, range: e_range(&e) })
            );
            let msg = e.to_string();
            assert!(
                msg.contains("delta_t_c") && msg.contains("[-30, 30]") && msg.contains("t_water_c − t_air_c"),
                "{msg}"
            );
        }
        // The ends of the range are accepted, unchanged: ΔT = 10 − 40 = −30 °C, 40 − 10 = +30 °C.
        let cold = WhitecapLaw::monahan_1986_from_temperatures(10.0, 40.0).unwrap();
        assert_eq!(cold, WhitecapLaw::Monahan1986Stability { delta_t_c: -30.0 });
        let warm = WhitecapLaw::monahan_1986_from_temperatures(40.0, 10.0).unwrap();
        assert_eq!(warm, WhitecapLaw::Monahan1986Stability { delta_t_c: 30.0 });
        // At ΔT = +30 °C the reference's ΔT = 0 oracle times e^{0.0861·30} = e^{2.583}.
        let expected = 6.919e-3 * (0.0861f64 * 30.0).exp();
        assert!((cover(10.0, warm) / expected - 1.0).abs() < ORACLE_REL);
    }

    /// The `range` text of an [`FoamError::OutOfRange`].
    fn e_range(e: &FoamError) -> &'static str {
        let FoamError::OutOfRange(brine_core::OutOfRange { range, .. }) = e;
        range
    }

    #[test]
    fn bad_input_is_named() {
        let e = CoverageParams::new(61.0, WhitecapLaw::Monahan1980, 3.0).unwrap_err();
        assert!(e.to_string().contains("u10_m_s"), "{e}");
        let e = CoverageParams::new(f64::NAN, WhitecapLaw::Monahan1980, 3.0).unwrap_err();
        assert!(e.to_string().contains("u10_m_s"), "{e}");
        let e = CoverageParams::new(5.0, WhitecapLaw::Monahan1986Stability { delta_t_c: 40.0 }, 3.0).unwrap_err();
        assert!(e.to_string().contains("delta_t_c"), "{e}");
    }
}
