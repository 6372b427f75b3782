//! The sea-spray source function of Monahan, Spiel & Davidson (1986) and the drop settling
//! velocity.

/// Radius range `[0.8, 15]` µm (at 80 % relative humidity) over which the bubble-mediated
/// source function of Monahan et al. (1986) is used. Below 0.8 µm it was not fitted; from 15 µm
/// the spume drops torn from crests take over ([`crate::f94_spume_flux`]).
pub const MSD86_RADIUS_RANGE_UM: (f64, f64) = (0.8, 15.0);

/// Density of sea water `ρ_w` (kg m⁻³).
pub const SEA_WATER_DENSITY: f64 = 1025.0;

/// Dynamic viscosity of air `μ_air` (Pa s) near 15 °C.
pub const AIR_VISCOSITY: f64 = 1.8e-5;

/// Gravity (m s⁻²), as in brine-waves.
pub const G: f64 = brine_core::G;

/// Spray source function: drops produced per square metre of sea, per second, per micrometre of
/// radius, by bursting whitecap bubbles.
///
/// `dF/dr₈₀ = 1.373 U₁₀^3.41 r⁻³ (1 + 0.057 r^1.05) · 10^{1.19 exp(−B²)}`,
/// `B = (0.380 − log₁₀ r)/0.650`.
///
/// The factor `U₁₀^3.41` is the whitecap coverage of Monahan & Ó Muircheartaigh (1980): the flux
/// is proportional to the area of whitecaps.
///
/// # Arguments
/// - `r80_um`: drop radius at 80 % relative humidity `r₈₀` (µm), `> 0`. The law is fitted on
///   [`MSD86_RADIUS_RANGE_UM`]; outside it the formula is still finite and positive for every
///   `r > 0` (`∝ r⁻³` below, `∝ r^−1.95` above) but is an extrapolation.
/// - `u10`: wind speed at 10 m `U₁₀` (m s⁻¹), `[0, 60]`.
///
/// # Returns
/// `dF/dr₈₀` (drops m⁻² s⁻¹ µm⁻¹), `≥ 0`.
///
/// # References
/// Monahan E., Spiel D., Davidson K. 1986, "A model of marine aerosol generation via whitecaps
/// and wave disruption", in *Oceanic Whitecaps*, Reidel, pp. 167–174; Darles et al. 2007 Eq. 5
/// (garbled: 0.0057 for 0.057, `10^1.19 e^{−B²}` for `10^{1.19 e^{−B²}}`, `B` misprinted);
/// docs/equations.md §6.
pub fn msd86_flux(r80_um: f64, u10: f64) -> f64 {
    debug_assert!(r80_um > 0.0 && (0.0..=60.0).contains(&u10), "r = {r80_um} µm, U10 = {u10} m/s");
    let b = (0.380 - libm::log10(r80_um)) / 0.650;
    1.373
        * libm::pow(u10, 3.41)
        * libm::pow(r80_um, -3.0)
        * (1.0 + 0.057 * libm::pow(r80_um, 1.05))
        * libm::pow(10.0, 1.19 * libm::exp(-b * b))
}

/// Stokes settling velocity of a drop, `v_s = 2 ρ_w g r²/(9 μ_air)`.
///
/// # Arguments
/// - `r_um`: drop radius (µm), `> 0`; Stokes' law holds while the drop Reynolds number is below
///   ~1, i.e. `r ≲ 40` µm.
///
/// # Returns
/// `v_s` (m s⁻¹): 3.1 mm s⁻¹ at 5 µm.
///
/// # References
/// Stokes' law; docs/equations.md §6 (`v_s(5 µm) ≈ 3 mm/s`).
pub fn stokes_settling_velocity(r_um: f64) -> f64 {
    debug_assert!(r_um > 0.0);
    let r = r_um * 1e-6;
    2.0 * SEA_WATER_DENSITY * G * r * r / (9.0 * AIR_VISCOSITY)
}

/// Factor of the spray source at a point with local foam amount `s′`, `s′/W` (Darles Eq. 6,
/// corrected), or 0 where the sea has no whitecaps.
///
/// Darles et al. multiply the flux by `s′`, but the flux is already proportional to the coverage
/// `W`; dividing by `W` redistributes the same total flux toward the foam.
///
/// # Arguments
/// - `foam_amount`: `s′ ∈ [0, 1]` at the orthogonal projection of the point on the sea.
/// - `coverage`: `W ∈ [0, 1]`, the mean whitecap coverage of the sea.
///
/// # Returns
/// `s′/W` (dimensionless, `≥ 0`, mean 1 over the sea), 0 when `W = 0`.
///
/// # References
/// Darles et al. 2007 Eq. 6; docs/equations.md §6 (errata).
pub fn spray_foam_factor(foam_amount: f64, coverage: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&foam_amount) && (0.0..=1.0).contains(&coverage));
    if coverage > 0.0 { foam_amount / coverage } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Half a unit in the fifth significant digit of the hand value 3.1035×10⁻³ m/s.
    const FIVE_DIGITS_M_S: f64 = 5e-8;

    /// Rounding of a ratio of two `pow`-based evaluations (a few ulps each) of a value near 10.6.
    const RATIO_ROUNDING: f64 = 1e-12;

    #[test]
    fn settling_velocity_of_a_5_um_drop() {
        // 2·1025·9.81·(5e-6)²/(9·1.8e-5) = 5.02763e-7/1.62e-4 = 3.1035e-3 m/s (reference: "≈ 3 mm/s").
        assert!((stokes_settling_velocity(5.0) - 3.1035e-3).abs() < FIVE_DIGITS_M_S);
    }

    #[test]
    fn flux_scales_as_u_to_the_3_41() {
        let r = msd86_flux(2.0, 20.0) / msd86_flux(2.0, 10.0);
        assert!((r - 2f64.powf(3.41)).abs() < RATIO_ROUNDING);
    }
}
