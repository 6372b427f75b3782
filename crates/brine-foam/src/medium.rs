//! Spray as a participating medium: concentration profile, extinction, optical depth and
//! Beer–Lambert transmittance.

use crate::error::{FoamError, check};
use crate::spray::{MSD86_RADIUS_RANGE_UM, msd86_flux, stokes_settling_velocity};

/// Extinction efficiency `Q_e(r)` of a spray drop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExtinctionEfficiency {
    /// A constant `Q_e`, `(0, 5]`: Darles et al. use `Q_e ≈ 2`, the large-drop limit.
    Constant(f64),
    /// Van de Hulst's anomalous-diffraction approximation
    /// `Q_e = 2 − (4/ρ) sin ρ + (4/ρ²)(1 − cos ρ)`, `ρ = 4π r (m − 1)/λ`: rises from 0, overshoots
    /// to ~3.2 near `ρ ≈ 4` (`r ≈ 1` µm in green light) and oscillates toward 2.
    AnomalousDiffraction {
        /// Wavelength of light `λ` (nm), `[300, 2500]`.
        wavelength_nm: f64,
        /// Real refractive index of the drops `m`, `(1, 2]` (1.34 for sea-salt solution drops).
        refractive_index: f64,
    },
}

impl ExtinctionEfficiency {
    /// Extinction efficiency `Q_e` of one drop: the ratio of its extinction cross-section to its
    /// geometric cross-section `π r²`.
    ///
    /// `Q_e = const`, or `Q_e = 2 − (4/ρ) sin ρ + (4/ρ²)(1 − cos ρ)`, `ρ = 4π r (m − 1)/λ`
    /// (series `ρ²/2 − ρ⁴/36` below `ρ = 10⁻²`).
    ///
    /// # Arguments
    /// - `r_um`: drop radius `r` (µm), `> 0`.
    ///
    /// # Returns
    /// `Q_e` (dimensionless), `[0, 3.2]` for the anomalous-diffraction form.
    ///
    /// # References
    /// van de Hulst H. C. 1957, *Light scattering by small particles*, Wiley, §11.22 (anomalous
    /// diffraction); Darles et al. 2007 §4.2 (`Q_e ≈ 2`).
    pub fn q_e(&self, r_um: f64) -> f64 {
        match *self {
            Self::Constant(q) => q,
            Self::AnomalousDiffraction { wavelength_nm, refractive_index } => {
                let rho = 4.0 * std::f64::consts::PI * r_um * 1e3 * (refractive_index - 1.0) / wavelength_nm;
                if rho < 1e-2 {
                    // Series: ρ²/2 − ρ⁴/36 avoids the cancellation of the closed form.
                    rho * rho * (0.5 - rho * rho / 36.0)
                } else {
                    2.0 - 4.0 / rho * libm::sin(rho) + 4.0 / (rho * rho) * (1.0 - libm::cos(rho))
                }
            }
        }
    }
}

/// Parameters of the spray medium.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SprayParams {
    /// Wind speed at 10 m `U₁₀` (m s⁻¹), `[0, 60]`.
    pub u10: f64,
    /// Smallest drop radius integrated (µm), `(0, radius_max_um)`; default 0.8.
    pub radius_min_um: f64,
    /// Largest drop radius integrated (µm), `(radius_min_um, 100]`; default 15.
    pub radius_max_um: f64,
    /// Scale height `H` of the exponential profile (m), `(0, 10⁴]`; default 1000 m, the marine
    /// boundary-layer aerosol of Shettle & Fenn (1979).
    pub scale_height_m: f64,
    /// Height `z_max` above which there is no spray (Darles' `H_max`) (m), `(0, 10⁴]`;
    /// default 2000 m.
    pub max_height_m: f64,
    /// Residence time of small drops in the boundary layer (s), `[3600, 10⁷]`; default 2 days.
    /// Sets the removal velocity `H/t_res` that adds to Stokes settling (see
    /// [`SprayMedium::deposition_velocity`]).
    pub residence_time_s: f64,
    /// Extinction efficiency; default `Constant(2.0)` (Darles et al.).
    pub efficiency: ExtinctionEfficiency,
}

impl Default for SprayParams {
    fn default() -> Self {
        Self {
            u10: 10.0,
            radius_min_um: MSD86_RADIUS_RANGE_UM.0,
            radius_max_um: MSD86_RADIUS_RANGE_UM.1,
            scale_height_m: 1000.0,
            max_height_m: 2000.0,
            residence_time_s: 2.0 * 86_400.0,
            efficiency: ExtinctionEfficiency::Constant(2.0),
        }
    }
}

/// Number of Simpson panels in `ln r` for the extinction integral (relative error < 10⁻⁸ on the
/// smooth integrand; the anomalous-diffraction oscillations have a period of ~0.5 µm, resolved
/// by 512 panels over 0.8–15 µm).
const RADIUS_PANELS: usize = 512;

/// Sea spray above the sea as a participating medium.
///
/// - Surface concentration (steady state, flux balanced by removal):
///   `n(r, 0) = (dF/dr)/v_d(r)` (m⁻³ µm⁻¹), `v_d = v_s(r) + H/t_res`.
/// - Vertical profile: `n(r, z) = n(r, 0) e^{−z/H}` for `0 ≤ z ≤ z_max`, 0 above.
/// - Extinction: `k_e(z) = ∫ Q_e(r) π r² n(r, z) dr` (m⁻¹; `r` in m inside `π r²`, `dr` in µm),
///   integrated once in the constructor.
/// - Vertical optical depth: `τ = ∫₀^{z_max} k_e dz = k_e(0) H (1 − e^{−z_max/H})`.
/// - Beer–Lambert transmittance along a ray: `T = exp(−∫ k_e ds)`.
///
/// Locally the extinction is multiplied by the foam factor `s′/W`
/// ([`crate::spray_foam_factor`]): more spray above foam.
///
/// # References
/// Monahan, Spiel & Davidson 1986 (source); Shettle E., Fenn R. 1979, AFGL-TR-79-0214 (profile);
/// Darles et al. 2007 §4.2 and its errata in the docs/equations.md §6 (the printed `k_e` integrates
/// the flux without `dr`; it must be a concentration; Eq. 7, Beer–Lambert, is missing).
#[derive(Debug, Clone, PartialEq)]
pub struct SprayMedium {
    params: SprayParams,
    removal_velocity: f64,
    extinction_0: f64,
}

impl SprayMedium {
    /// Sea spray of a wind: checks the parameters and integrates the sea-level extinction
    /// coefficient once.
    ///
    /// `k_e(0) = ∫_{r_min}^{r_max} Q_e(r) π r² (dF/dr)/v_d(r) dr`, by Simpson's rule on 512 panels
    /// in `ln r` (`dr = r d ln r`).
    ///
    /// # Arguments
    /// - `params`: [`SprayParams`] — `u10` (m s⁻¹, `[0, 60]`), `radius_min_um` (µm, `> 0`),
    ///   `radius_max_um` (µm, `(radius_min_um, 100]`), `scale_height_m` and `max_height_m` (m,
    ///   `(0, 10⁴]`), `residence_time_s` (s, `[3600, 10⁷]`), `efficiency` (a constant `Q_e` in
    ///   `(0, 5]`, or anomalous diffraction with `λ` in `[300, 2500]` nm and `m` in `(1, 2]`).
    ///
    /// # Returns
    /// The medium, with `k_e(0)` (m⁻¹) precomputed (`≥ 0`, 0 at `U₁₀ = 0`).
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the first parameter outside its range.
    ///
    /// # References
    /// Monahan, Spiel & Davidson 1986 (`dF/dr`); Darles et al. 2007 §4.2 (`k_e`, `Q_e ≈ 2`);
    /// docs/equations.md §6 ("concentration from flux", "extinction and optical depth").
    pub fn new(params: &SprayParams) -> Result<Self, FoamError> {
        let p = *params;
        check("u10_m_s", p.u10, (0.0..=60.0).contains(&p.u10), "[0, 60] m/s")?;
        check("radius_min_um", p.radius_min_um, p.radius_min_um > 0.0, "(0, radius_max_um) µm")?;
        check(
            "radius_max_um",
            p.radius_max_um,
            p.radius_max_um > p.radius_min_um && p.radius_max_um <= 100.0,
            "(radius_min_um, 100] µm",
        )?;
        check("scale_height_m", p.scale_height_m, p.scale_height_m > 0.0 && p.scale_height_m <= 1e4, "(0, 10000] m")?;
        check("max_height_m", p.max_height_m, p.max_height_m > 0.0 && p.max_height_m <= 1e4, "(0, 10000] m")?;
        check("residence_time_s", p.residence_time_s, (3600.0..=1e7).contains(&p.residence_time_s), "[3600, 1e7] s")?;
        match p.efficiency {
            ExtinctionEfficiency::Constant(q) => {
                check("q_e", q, q > 0.0 && q <= 5.0, "(0, 5]")?;
            }
            ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm, refractive_index } => {
                check("wavelength_nm", wavelength_nm, (300.0..=2500.0).contains(&wavelength_nm), "[300, 2500] nm")?;
                check(
                    "refractive_index",
                    refractive_index,
                    refractive_index > 1.0 && refractive_index <= 2.0,
                    "(1, 2]",
                )?;
            }
        }
        let mut medium = Self { params: p, removal_velocity: p.scale_height_m / p.residence_time_s, extinction_0: 0.0 };
        medium.extinction_0 = medium.integrate_extinction();
        Ok(medium)
    }

    /// The parameters.
    pub fn params(&self) -> &SprayParams {
        &self.params
    }

    /// Deposition velocity `v_d(r) = v_s(r) + H/t_res` (m s⁻¹): Stokes settling plus the
    /// removal of a boundary layer of depth `H` every residence time. Settling alone (the lower
    /// bound of docs/equations.md) would let sub-5-µm drops pile up for weeks; Hoppel et al.
    /// (2002) show small drops never reach the settling equilibrium because other sinks
    /// (precipitation, mixing out of the boundary layer) act in days.
    ///
    /// # Arguments
    /// - `r_um`: drop radius (µm), `> 0`.
    ///
    /// # Returns
    /// `v_d` (m s⁻¹).
    ///
    /// # References
    /// docs/equations.md §6 (`v_d ≥ v_s`); Hoppel W., Frick G., Fitzgerald J. 2002, "Surface source
    /// function for sea-salt aerosol and aerosol dry deposition to the ocean surface", JGR
    /// 107(D19), 4382.
    pub fn deposition_velocity(&self, r_um: f64) -> f64 {
        stokes_settling_velocity(r_um) + self.removal_velocity
    }

    /// Drop concentration `n(r, z) = (dF/dr)/v_d · e^{−z/H}` for `0 ≤ z ≤ z_max`.
    ///
    /// # Arguments
    /// - `r_um`: drop radius `r₈₀` (µm), `> 0`.
    /// - `z`: height above the sea (m); 0 below 0 and above `z_max`.
    ///
    /// # Returns
    /// `n` (drops m⁻³ µm⁻¹).
    ///
    /// # References
    /// docs/equations.md §6 ("concentration from flux", "vertical profile").
    pub fn concentration(&self, r_um: f64, z: f64) -> f64 {
        self.profile(z) * msd86_flux(r_um, self.params.u10) / self.deposition_velocity(r_um)
    }

    /// `e^{−z/H}` on `[0, z_max]`, 0 outside.
    fn profile(&self, z: f64) -> f64 {
        if (0.0..=self.params.max_height_m).contains(&z) { libm::exp(-z / self.params.scale_height_m) } else { 0.0 }
    }

    /// Extinction coefficient `k_e(z) = f ∫ Q_e π r² n(r, z) dr`.
    ///
    /// # Arguments
    /// - `z`: height above the sea (m).
    /// - `foam_factor`: local factor `s′/W` (`≥ 0`; 1 for the sea-wide mean).
    ///
    /// # Returns
    /// `k_e` (m⁻¹).
    ///
    /// # References
    /// Darles et al. 2007 §4.2 (`k_e`, `k(r) = Q_e π r²`); docs/equations.md §6.
    pub fn extinction(&self, z: f64, foam_factor: f64) -> f64 {
        debug_assert!(foam_factor >= 0.0);
        self.extinction_0 * foam_factor * self.profile(z)
    }

    /// Vertical optical depth of the whole spray column, for the sea-wide mean foam.
    ///
    /// `τ = ∫₀^{z_max} k_e dz = k_e(0) H (1 − e^{−z_max/H})`.
    ///
    /// # Returns
    /// `τ` (dimensionless, `≥ 0`).
    ///
    /// # References
    /// Darles et al. 2007 §4.2 (`τ_aod`); docs/equations.md §6.
    pub fn optical_depth(&self) -> f64 {
        let h = self.params.scale_height_m;
        self.extinction_0 * h * (1.0 - libm::exp(-self.params.max_height_m / h))
    }

    /// Optical depth of the spray above a height, `∫_z^{z_max} k_e dz' = k_e(0) f H (e^{−z/H} − e^{−z_max/H})`.
    ///
    /// # Arguments
    /// - `z`: height above the sea (m); clamped to `[0, z_max]`.
    /// - `foam_factor`: `s′/W` below (`≥ 0`).
    ///
    /// # Returns
    /// The vertical optical depth (dimensionless, `≥ 0`): the whole column for `z ≤ 0`, 0 above
    /// `z_max`.
    ///
    /// # References
    /// Darles et al. 2007 §4.2 (`τ_aod`); docs/equations.md §6.
    pub fn optical_depth_above(&self, z: f64, foam_factor: f64) -> f64 {
        let (h, zmax) = (self.params.scale_height_m, self.params.max_height_m);
        let z = z.clamp(0.0, zmax);
        self.extinction_0 * foam_factor * h * (libm::exp(-z / h) - libm::exp(-zmax / h))
    }

    /// Optical depth of a straight segment from height `z0` to `z1` of length `length_m`,
    /// `∫ k_e ds`, exact for the exponential profile clipped to `[0, z_max]`.
    ///
    /// # Arguments
    /// - `z0`, `z1`: heights above the sea of the segment's ends (m), finite.
    /// - `length_m`: the segment length (m), `≥ |z1 − z0|`.
    /// - `foam_factor`: `s′/W` below the segment (`≥ 0`).
    ///
    /// # Returns
    /// The optical depth (dimensionless, `≥ 0`).
    ///
    /// # References
    /// Beer–Lambert law; docs/equations.md §6 (the attenuation equation missing from Darles et al.).
    pub fn segment_optical_depth(&self, z0: f64, z1: f64, length_m: f64, foam_factor: f64) -> f64 {
        debug_assert!(length_m >= 0.0 && foam_factor >= 0.0 && z0.is_finite() && z1.is_finite());
        if length_m <= 0.0 || foam_factor <= 0.0 {
            return 0.0;
        }
        let (h, zmax) = (self.params.scale_height_m, self.params.max_height_m);
        let dz = z1 - z0;
        let k = self.extinction_0 * foam_factor;
        if dz.abs() <= 1e-9 * length_m.max(1.0) {
            return k * length_m * self.profile(0.5 * (z0 + z1));
        }
        // Clip the parameter interval to the slab 0 ≤ z ≤ z_max; ds = (length/dz) dz.
        let (lo, hi) = (z0.min(z1).max(0.0), z0.max(z1).min(zmax));
        if hi <= lo {
            return 0.0;
        }
        k * (length_m / dz.abs()) * h * (libm::exp(-lo / h) - libm::exp(-hi / h))
    }

    /// Fraction of light that crosses a straight segment of spray unscattered and unabsorbed.
    ///
    /// `T = exp(−∫ k_e ds)` (Beer–Lambert), with the optical depth of
    /// [`Self::segment_optical_depth`].
    ///
    /// # Arguments
    /// - `z0`, `z1`: heights above the sea of the segment's ends (m), finite.
    /// - `length_m`: the segment length (m), `≥ |z1 − z0|`.
    /// - `foam_factor`: `s′/W` below the segment (dimensionless, `≥ 0`; 1 for the mean sea).
    ///
    /// # Returns
    /// `T` (dimensionless), in `(0, 1]` (it underflows to 0 only beyond an optical depth of ~745).
    ///
    /// # References
    /// Beer–Lambert law; docs/equations.md §6 (the attenuation equation, Darles' missing Eq. 7).
    pub fn transmittance(&self, z0: f64, z1: f64, length_m: f64, foam_factor: f64) -> f64 {
        libm::exp(-self.segment_optical_depth(z0, z1, length_m, foam_factor))
    }

    /// `∫ Q_e π r² n(r, 0) dr` by Simpson's rule in `ln r`.
    fn integrate_extinction(&self) -> f64 {
        let (a, b) = (libm::log(self.params.radius_min_um), libm::log(self.params.radius_max_um));
        let h = (b - a) / RADIUS_PANELS as f64;
        let f = |lr: f64| {
            let r = libm::exp(lr);
            let r_m = r * 1e-6;
            // dr = r d(ln r).
            self.params.efficiency.q_e(r) * std::f64::consts::PI * r_m * r_m * self.concentration(r, 0.0) * r
        };
        let mut s = f(a) + f(b);
        for i in 1..RADIUS_PANELS {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(a + i as f64 * h);
        }
        s * h / 3.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint rule on 2·10⁵ points along a segment: the clipped ends (a kink at `z = 0` or
    /// `z_max`) cost up to one step, 5×10⁻⁶ of the path; 10⁻⁴ leaves a margin of 20.
    const MIDPOINT_REL: f64 = 1e-4;

    /// Absolute floor for segments entirely outside the spray (optical depth 0).
    const ZERO_DEPTH: f64 = 1e-12;

    /// At `ρ` = 7.8×10⁻⁴ (`r` = 10⁻⁴ µm at 550 nm) `Q_e ≈ ρ²/2` = 3×10⁻⁷, well under 10⁻⁴.
    const SMALL_DROP_Q: f64 = 1e-4;

    /// At `ρ` ≈ 1550 (`r` = 200 µm) `|Q_e − 2| ≤ 4/ρ + 8/ρ²` ≈ 2.6×10⁻³; 0.02 allows the bound.
    const LARGE_DROP_Q: f64 = 0.02;

    /// Both sides of the switch at `ρ` = 10⁻² against the series to `ρ⁶`
    /// (`Q_e = ρ²/2 − ρ⁴/36 + ρ⁶/1440 − …`, the Taylor expansions of `sin` and `cos` to `ρ⁸`):
    /// the next term is ~10⁻¹⁹, and the closed form loses about `(4/ρ²)·ε/2` ≈ 4×10⁻¹² to the
    /// cancellation in `1 − cos ρ`. 2×10⁻¹¹ bounds that, and is 7× below the change a wrong
    /// `ρ⁴` coefficient (`1/24` for `1/36`) would make.
    const SERIES_SWITCH: f64 = 2e-11;

    #[test]
    fn segment_depth_matches_brute_force() {
        let m = SprayMedium::new(&SprayParams { max_height_m: 50.0, scale_height_m: 20.0, ..SprayParams::default() })
            .unwrap();
        for &(z0, z1, len, f) in
            &[(1.0, 30.0, 500.0, 1.0), (60.0, -2.0, 100.0, 2.5), (5.0, 5.0, 80.0, 1.0), (55.0, 70.0, 30.0, 1.0)]
        {
            let n = 200_000;
            let mut brute = 0.0;
            for i in 0..n {
                let t = (i as f64 + 0.5) / n as f64;
                brute += m.extinction(z0 + t * (z1 - z0), f) * len / n as f64;
            }
            let exact = m.segment_optical_depth(z0, z1, len, f);
            assert!((exact - brute).abs() <= MIDPOINT_REL * brute + ZERO_DEPTH, "{z0} {z1}: {exact} vs {brute}");
        }
    }

    #[test]
    fn anomalous_diffraction_limits() {
        let e = ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm: 550.0, refractive_index: 1.34 };
        assert!(e.q_e(1e-4) < SMALL_DROP_Q);
        assert!((e.q_e(200.0) - 2.0).abs() < LARGE_DROP_Q);
        // Just below the switch (series) and just above it (closed form), against the series to ρ⁶.
        let r_of_rho = |rho: f64| rho * 550.0 / (4.0 * std::f64::consts::PI * 1e3 * 0.34);
        for rho in [1e-2 * (1.0 - 1e-6), 1e-2 * (1.0 + 1e-6)] {
            let expected = rho * rho * (0.5 - rho * rho * (1.0 / 36.0 - rho * rho / 1440.0));
            let q = e.q_e(r_of_rho(rho));
            assert!((q - expected).abs() < SERIES_SWITCH, "ρ = {rho}: {q} vs {expected}");
        }
    }
}
