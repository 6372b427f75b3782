//! Dispersion relations of surface waves: deep water, finite depth, capillary–gravity.

use crate::error::{WaveError, check};

/// Standard gravity `g` (m s⁻²), brine-core's.
pub const G: f64 = brine_core::G;

/// Surface tension of sea water `σ` (N m⁻¹) at about 20 °C and salinity 35 (Kinsman 1965).
pub const SEA_WATER_SURFACE_TENSION: f64 = 0.074;

/// Density of sea water `ρ` (kg m⁻³) near the surface.
pub const SEA_WATER_DENSITY: f64 = 1025.0;

/// Wavenumber `k_m` (rad m⁻¹) of the minimum phase speed in Elfouhaily et al. 1997 (Eq. 24, 59):
/// `ω² = g k (1 + (k/k_m)²)` is the capillary–gravity relation with `σ/ρ = g/k_m²`.
pub const ELFOUHAILY_K_M: f64 = 370.0;

/// Angular frequency of a deep-water gravity wave, `ω = √(g k)`.
///
/// # Arguments
/// - `k`: wavenumber (rad m⁻¹), `k ≥ 0`.
///
/// # Returns
/// `ω` (rad s⁻¹).
///
/// # References
/// Airy linear wave theory, deep-water limit `kh → ∞` of `ω² = g k tanh(k h)`; docs/equations.md §1.
pub fn omega_deep_water(k: f64) -> f64 {
    debug_assert!(k >= 0.0, "wavenumber must be non-negative, got {k}");
    (G * k).sqrt()
}

/// Wavenumber of a deep-water gravity wave of angular frequency `ω`, `k = ω²/g`.
///
/// # Arguments
/// - `omega`: angular frequency (rad s⁻¹), `ω ≥ 0`.
///
/// # Returns
/// `k` (rad m⁻¹); the wavelength is `λ = 2π/k`.
///
/// # References
/// Inverse of [`omega_deep_water`]; docs/equations.md §1.
pub fn wavenumber_deep_water(omega: f64) -> f64 {
    debug_assert!(omega >= 0.0, "angular frequency must be non-negative, got {omega}");
    omega * omega / G
}

/// A dispersion relation `ω(k)` of linear surface waves over a flat bottom:
/// `ω² = (g k + (σ/ρ) k³) tanh(k h)`.
///
/// Three cases of the same formula: deep water (`h = ∞`, `σ = 0`, `ω² = g k`), finite depth
/// (`σ = 0`, `ω² = g k tanh(k h)`) and capillary–gravity waves (`σ > 0`). Elfouhaily et al. 1997
/// write the capillary term as `ω² = g k (1 + (k/k_m)²)`, i.e. `σ/ρ = g/k_m²`.
///
/// # References
/// Lamb H. 1932, *Hydrodynamics*, 6th ed., ch. IX (surface waves, capillarity); Airy 1845;
/// docs/equations.md §1 ("Parameters from dispersion"); Elfouhaily et al. 1997, JGR 102(C7), Eq. 24.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Dispersion {
    /// Water depth `h` (m), `+∞` for deep water.
    depth: f64,
    /// Kinematic surface tension `σ/ρ` (m³ s⁻²), `0` for pure gravity waves.
    capillarity: f64,
}

impl Default for Dispersion {
    fn default() -> Self {
        Self::DEEP_WATER
    }
}

impl Dispersion {
    /// Deep-water gravity waves, `ω² = g k`.
    pub const DEEP_WATER: Self = Self { depth: f64::INFINITY, capillarity: 0.0 };

    /// Gravity waves over water of depth `h`, `ω² = g k tanh(k h)`.
    ///
    /// # Arguments
    /// - `depth_m`: water depth `h` (m), `(0, ∞]` (`f64::INFINITY` is deep water).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a depth that is not positive.
    pub fn finite_depth(depth_m: f64) -> Result<Self, WaveError> {
        let depth = check_depth(depth_m)?;
        Ok(Self { depth, capillarity: 0.0 })
    }

    /// Capillary–gravity waves over water of depth `h`, `ω² = (g k + σ k³/ρ) tanh(k h)`.
    ///
    /// # Arguments
    /// - `depth_m`: water depth `h` (m), `(0, ∞]`.
    /// - `surface_tension_n_m`: surface tension `σ` (N m⁻¹), `[0, 1]`
    ///   ([`SEA_WATER_SURFACE_TENSION`] = 0.074 for sea water).
    /// - `density_kg_m3`: water density `ρ` (kg m⁻³), `[500, 2000]` ([`SEA_WATER_DENSITY`]).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn capillary_gravity(depth_m: f64, surface_tension_n_m: f64, density_kg_m3: f64) -> Result<Self, WaveError> {
        let depth = check_depth(depth_m)?;
        let sigma = check(
            "surface_tension_n_m",
            surface_tension_n_m,
            (0.0..=1.0).contains(&surface_tension_n_m),
            "[0, 1] N/m",
        )?;
        let rho =
            check("density_kg_m3", density_kg_m3, (500.0..=2000.0).contains(&density_kg_m3), "[500, 2000] kg/m³")?;
        Ok(Self { depth, capillarity: sigma / rho })
    }

    /// The deep-water capillary–gravity relation of Elfouhaily et al. 1997 (Eq. 24),
    /// `ω² = g k (1 + (k/k_m)²)` with `k_m = 370` rad m⁻¹ (`σ/ρ = g/k_m² = 7.17×10⁻⁵ m³ s⁻²`).
    pub fn elfouhaily() -> Self {
        Self { depth: f64::INFINITY, capillarity: G / (ELFOUHAILY_K_M * ELFOUHAILY_K_M) }
    }

    /// Water depth `h` (m), `+∞` for deep water.
    pub fn depth(&self) -> f64 {
        self.depth
    }

    /// Kinematic surface tension `σ/ρ` (m³ s⁻²).
    pub fn capillarity(&self) -> f64 {
        self.capillarity
    }

    /// `tanh(k h)`, `1` in deep water.
    fn depth_factor(&self, k: f64) -> f64 {
        if self.depth.is_infinite() { 1.0 } else { libm::tanh(k * self.depth) }
    }

    /// Angular frequency `ω(k) = √((g k + (σ/ρ) k³) tanh(k h))`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `k ≥ 0`.
    ///
    /// # Returns
    /// `ω` (rad s⁻¹); `0` for `k ≤ 0`.
    ///
    /// # References
    /// Lamb 1932, ch. IX; docs/equations.md §1.
    pub fn omega(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        libm::sqrt((G * k + self.capillarity * k * k * k) * self.depth_factor(k))
    }

    /// Group velocity `c_g = dω/dk` (m s⁻¹):
    /// `dω/dk = [(g + 3(σ/ρ)k²) tanh(kh) + (g k + (σ/ρ)k³) h sech²(kh)] / (2ω)`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `k > 0`.
    ///
    /// # Returns
    /// `dω/dk` (m s⁻¹); in deep water without capillarity `g/(2ω)`.
    ///
    /// # References
    /// Derivative of [`Dispersion::omega`]; Lamb 1932, ch. IX (group velocity).
    pub fn group_velocity(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            // Limit k → 0: √(g h) over finite depth, +∞ in deep water.
            return if self.depth.is_infinite() { f64::INFINITY } else { libm::sqrt(G * self.depth) };
        }
        let w = self.omega(k);
        let t = self.depth_factor(k);
        let mut d = (G + 3.0 * self.capillarity * k * k) * t;
        if self.depth.is_finite() {
            let sech = 1.0 / libm::cosh(k * self.depth);
            d += (G * k + self.capillarity * k * k * k) * self.depth * sech * sech;
        }
        d / (2.0 * w)
    }

    /// Phase speed `c = ω/k` (m s⁻¹).
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `k > 0`.
    ///
    /// # Returns
    /// `c` (m s⁻¹).
    ///
    /// # References
    /// Lamb 1932, ch. IX; Elfouhaily et al. 1997, Eq. 24.
    pub fn phase_speed(&self, k: f64) -> f64 {
        self.omega(k) / k
    }

    /// Wavenumber `k(ω)`: the inverse of [`Dispersion::omega`], which is strictly increasing.
    ///
    /// Exact in deep water without capillarity (`k = ω²/g`); otherwise Newton's method on
    /// `ω(k)² − ω²`, safeguarded by a bracket, to a relative step of `10⁻¹⁴` (at most 200
    /// iterations; usually 4–6).
    ///
    /// # Arguments
    /// - `omega`: angular frequency (rad s⁻¹), `ω ≥ 0`.
    ///
    /// # Returns
    /// `k` (rad m⁻¹); `0` for `ω ≤ 0`.
    ///
    /// # References
    /// Inverse of the relation of Lamb 1932, ch. IX; docs/equations.md §1.
    pub fn wavenumber(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        let w2 = omega * omega;
        if self.depth.is_infinite() && self.capillarity == 0.0 {
            return w2 / G;
        }
        let f = |k: f64| (G * k + self.capillarity * k * k * k) * self.depth_factor(k) - w2;
        // Without capillarity k ≥ max(ω²/g, ω/√(gh)); start there and bracket outward.
        let shallow = if self.depth.is_finite() { omega / libm::sqrt(G * self.depth) } else { 0.0 };
        let mut k = (w2 / G).max(shallow);
        let (mut lo, mut hi) = (k, k);
        while f(lo) > 0.0 {
            lo *= 0.5;
        }
        while f(hi) < 0.0 {
            hi *= 2.0;
        }
        k = k.clamp(lo, hi);
        for _ in 0..200 {
            let fk = f(k);
            if fk > 0.0 {
                hi = k;
            } else {
                lo = k;
            }
            // d(ω²)/dk = 2 ω c_g.
            let w = self.omega(k);
            let slope = 2.0 * w * self.group_velocity(k);
            let next = k - fk / slope;
            let next = if next > lo && next < hi { next } else { 0.5 * (lo + hi) };
            let done = (next - k).abs() <= 1e-14 * k;
            k = next;
            if done || hi - lo <= 1e-15 * hi {
                break;
            }
        }
        k
    }
}

fn check_depth(depth_m: f64) -> Result<f64, WaveError> {
    if depth_m == f64::INFINITY {
        return Ok(depth_m);
    }
    check("depth_m", depth_m, depth_m > 0.0, "(0, ∞] m")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{PI, TAU};

    /// `8.0030` s is printed to 4 decimals: half a unit is 5×10⁻⁵ s; 10⁻⁴ leaves room for the
    /// rounding of `√(2πλ/g)` in the reference.
    const PRINTED_4_DIGITS_S: f64 = 1e-4;

    /// A few ulp of closed forms that must agree to rounding.
    const ROUND_REL: f64 = 1e-14;

    /// Central difference with `h = 10⁻⁵ k`: truncation `O(h²ω''')` ≈ 10⁻¹⁰ relative, rounding
    /// `ε ω/h` ≈ 10⁻¹¹ relative; 10⁻⁷ is loose.
    const GROUP_FD_REL: f64 = 1e-7;

    /// `kh = 10⁻⁴`: the shallow-water limit `ω = k√(gh)` has relative corrections `(kh)²/6`
    /// ≈ 2×10⁻⁹ (and `(kh)²/2` for `c_g`).
    const SHALLOW_REL: f64 = 1e-8;

    /// Elfouhaily's `c_m = 0.23` m/s is printed to 2 digits; `√(2g/k_m)` = 0.2303.
    const PRINTED_2_DIGITS_M_S: f64 = 5e-4;

    /// `λ_m = 1.705` cm for sea water, printed to 4 digits (in m: 10⁻⁵; 10⁻⁴ m covers the spread of
    /// sea-water surface tensions and densities in the literature).
    const LAMBDA_M_ABS: f64 = 1e-4;

    #[test]
    fn a_100_m_wave_has_an_8_s_period() {
        // λ = 100 m ⇒ T = √(2πλ/g) = √(628.3185/9.81) = 8.0030 s.
        let k = 2.0 * PI / 100.0;
        let t = 2.0 * PI / omega_deep_water(k);
        assert!((t - 8.0030).abs() < PRINTED_4_DIGITS_S, "T = {t}");
        assert!((wavenumber_deep_water(omega_deep_water(k)) - k).abs() < ROUND_REL * k);
    }

    /// Newton is stopped at a relative step of 10⁻¹⁴; allow a few ulps more.
    const INVERSE_REL: f64 = 1e-12;

    #[test]
    fn wavenumber_inverts_omega_in_every_regime() {
        let cases = [
            Dispersion::DEEP_WATER,
            Dispersion::finite_depth(5.0).unwrap(),
            Dispersion::finite_depth(0.3).unwrap(),
            Dispersion::elfouhaily(),
            Dispersion::capillary_gravity(2.0, SEA_WATER_SURFACE_TENSION, SEA_WATER_DENSITY).unwrap(),
        ];
        for d in cases {
            for j in 0..60 {
                let k = 1e-3 * 10f64.powf(j as f64 / 10.0);
                let back = d.wavenumber(d.omega(k));
                assert!((back / k - 1.0).abs() < INVERSE_REL, "{d:?}: k = {k}, back = {back}");
            }
        }
    }

    #[test]
    fn group_velocity_matches_a_central_difference() {
        for d in [Dispersion::finite_depth(3.0).unwrap(), Dispersion::elfouhaily(), Dispersion::DEEP_WATER] {
            for k in [0.01, 0.3, 2.0, 50.0, 400.0, 3000.0] {
                let h = 1e-5 * k;
                let fd = (d.omega(k + h) - d.omega(k - h)) / (2.0 * h);
                assert!((d.group_velocity(k) / fd - 1.0).abs() < GROUP_FD_REL, "{d:?} k = {k}");
            }
        }
    }

    #[test]
    fn deep_and_shallow_limits() {
        // kh ≫ 1: finite depth equals deep water; kh ≪ 1: ω = k √(g h).
        let d = Dispersion::finite_depth(1000.0).unwrap();
        assert!((d.omega(1.0) / omega_deep_water(1.0) - 1.0).abs() < ROUND_REL);
        let s = Dispersion::finite_depth(1.0).unwrap();
        let k = 1e-4;
        assert!((s.omega(k) / (k * G.sqrt()) - 1.0).abs() < SHALLOW_REL);
        assert!((s.group_velocity(k) / G.sqrt() - 1.0).abs() < SHALLOW_REL);
    }

    #[test]
    fn capillary_gravity_minimum_phase_speed() {
        // c(k) = √(g/k + σk/ρ) is smallest at k_m = √(gρ/σ), c_m = (4gσ/ρ)^{1/4};
        // for Elfouhaily's k_m = 370 rad/m: c_m = √(2g/k_m) = 0.2303 m/s (their c_m = 0.23).
        let d = Dispersion::elfouhaily();
        let c_m = d.phase_speed(ELFOUHAILY_K_M);
        assert!((c_m - (2.0 * G / ELFOUHAILY_K_M).sqrt()).abs() < ROUND_REL * c_m);
        assert!((c_m - 0.23).abs() < PRINTED_2_DIGITS_M_S, "c_m = {c_m}");
        assert!(d.phase_speed(0.9 * ELFOUHAILY_K_M) > c_m && d.phase_speed(1.1 * ELFOUHAILY_K_M) > c_m);
        // A 1.73 cm ripple: λ_m = 2π/k_m for sea water.
        let sea = Dispersion::capillary_gravity(f64::INFINITY, SEA_WATER_SURFACE_TENSION, SEA_WATER_DENSITY).unwrap();
        let k_m = (G / sea.capillarity()).sqrt();
        assert!((TAU / k_m - 0.01705).abs() < LAMBDA_M_ABS, "λ_m = {}", TAU / k_m);
    }

    #[test]
    fn bad_parameters_are_named() {
        assert!(Dispersion::finite_depth(0.0).unwrap_err().to_string().contains("depth_m"));
        assert!(Dispersion::finite_depth(f64::NAN).is_err());
        assert!(Dispersion::capillary_gravity(1.0, -1.0, 1000.0).unwrap_err().to_string().contains("surface_tension"));
    }
}
