//! The unified directional spectrum of Elfouhaily et al. (1997) for long and short wind waves.

use std::f64::consts::{FRAC_PI_2, LN_2, PI};

use crate::error::{WaveError, check};
use crate::spectra::dispersion::{ELFOUHAILY_K_M, G};
use crate::spectra::spreading::{Directions, invert_cdf};
use crate::{Dispersion, Spectrum, Spreading};

/// The unified directional spectrum of Elfouhaily, Chapron, Katsaros & Vandemark (1997), the
/// spectrum Li Ying et al. (2018, §2.2, Eq. 1) drive their ocean with.
///
/// Omnidirectional (Eq. 30) `S(k) = k⁻³ [B_l(k) + B_h(k)]` (m³), directional (Eq. 67)
/// `Ψ(k, φ) = (1/(2π)) k⁻⁴ [B_l + B_h] [1 + Δ(k) cos 2(φ − φ_w)]` (m⁴), with
///
/// - phase speed (Eq. 24, 59) `c(k) = √((g/k)(1 + (k/k_m)²))`, `k_m = 370` rad m⁻¹, `c_m = 0.23` m s⁻¹;
/// - inverse wave age `Ω = U₁₀/c_p` (0.84 fully developed, up to 5 for a young sea), from the
///   fetch `x`: `Ω = 0.84 [tanh((X/X₀)^{0.4})]^{−0.75}`, `X = k₀x`, `k₀ = g/U₁₀²`, `X₀ = 2.2×10⁴`;
///   peak `k_p = k₀Ω²`, `c_p = c(k_p)`;
/// - long waves (Eq. 31–34) `B_l = ½ α_p (c_p/c) F_p`, `F_p = L_PM J_p exp[−(Ω/√10)(√(k/k_p) − 1)]`,
///   `L_PM = exp[−(5/4)(k_p/k)²]`, `J_p = γ^Γ`, `Γ = exp[−(√(k/k_p) − 1)²/(2σ²)]`,
///   `σ = 0.08(1 + 4Ω⁻³)`, `γ = 1.7` (`Ω < 1`) or `1.7 + 6 log₁₀ Ω` (`1 ≤ Ω ≤ 5`), `α_p = 6×10⁻³ √Ω`;
/// - short waves (Eq. 40–44) `B_h = ½ α_m (c_m/c) F_m [× L_PM]`, `F_m = exp[−¼(k/k_m − 1)²]`,
///   `α_m = 10⁻²[1 + ln(u*/c_m)]` (`u* ≤ c_m`) or `10⁻²[1 + 3 ln(u*/c_m)]` (`u* > c_m`);
/// - friction velocity (Eq. 60, 66) `u* = κU₁₀/ln(10/z₀)`, `z₀ = 3.7×10⁻⁵ (U₁₀²/g)(U₁₀/c_p)^{0.9}`,
///   `κ = 0.4`;
/// - spreading (Eq. 57, 59) `Δ(k) = tanh[a₀ + a_p(c/c_p)^{2.5} + a_m(c_m/c)^{2.5}]`, `a₀ = ln 2/4`,
///   `a_p = 4`, `a_m = 0.13 u*/c_m` (see [`ElfouhailySpreading`]).
///
/// The `× L_PM` on `B_h` is the published authors' correction ("Eq. 40 fixed") that keeps the
/// short-wave term from adding energy at the longest waves; it is on by default
/// ([`Elfouhaily::without_short_wave_peak_cutoff`] removes it).
///
/// # Validity
/// `U₁₀` about 2–25 m s⁻¹ (the data behind it); `Ω ∈ [0.84, 5]`. Below `u* = c_m/e`
/// (`U₁₀ ≈ 2.5` m s⁻¹) the published `α_m` turns negative: it is clamped to 0 (documented clamp).
///
/// # References
/// Elfouhaily T., Chapron B., Katsaros K., Vandemark D. 1997, "A unified directional spectrum for
/// long and short wind-driven waves", JGR 102(C7):15781–15796, Eq. 24, 30–34, 40–44, 57–67;
/// Li Ying et al. 2018, §2.2, Eq. 1 (which lost `k⁻⁴`, `1/(2π)` and `B_l + B_h`); equation
/// equations.md §4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elfouhaily {
    u10: f64,
    omega_c: f64,
    short_wave_peak_cutoff: bool,
    k_p: f64,
    c_p: f64,
    u_star: f64,
    alpha_p: f64,
    alpha_m: f64,
    gamma: f64,
    sigma: f64,
    a_m: f64,
}

impl Elfouhaily {
    /// `k_m` (rad m⁻¹), wavenumber of the minimum phase speed (Eq. 59).
    pub const K_M: f64 = ELFOUHAILY_K_M;
    /// `c_m` (m s⁻¹), the minimum phase speed (Eq. 59).
    pub const C_M: f64 = 0.23;
    /// Von Kármán's constant `κ`.
    pub const KAPPA: f64 = 0.4;
    /// Inverse wave age `Ω` of a fully developed sea.
    pub const FULLY_DEVELOPED: f64 = 0.84;
    /// Largest inverse wave age of the `γ` law (a very young sea).
    pub const MAX_INVERSE_WAVE_AGE: f64 = 5.0;
    /// Dimensionless fetch scale `X₀` of the `Ω(X)` law.
    pub const X0: f64 = 2.2e4;
    /// `a₀ = ln 2/4` of the spreading (Eq. 59; `ln 2/2` in some codes is a bug).
    pub const A0: f64 = LN_2 / 4.0;
    /// `a_p` of the spreading (Eq. 59).
    pub const A_P: f64 = 4.0;

    /// The spectrum of a fully developed sea (`Ω = 0.84`) under a wind `U₁₀`.
    ///
    /// # Arguments
    /// - `u10`: wind speed 10 m above the sea (m s⁻¹), `(0, 60]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for a wind outside `(0, 60]` m s⁻¹.
    pub fn fully_developed(u10: f64) -> Result<Self, WaveError> {
        Self::new(u10, Self::FULLY_DEVELOPED)
    }

    /// Inverse wave age of a sea grown over a fetch `x`:
    /// `Ω = 0.84 [tanh((X/X₀)^{0.4})]^{−0.75}`, `X = g x/U₁₀²`, clamped to `Ω ≤ 5` (very short
    /// fetches, where the `γ` law ends).
    ///
    /// # Arguments
    /// - `u10`: wind speed (m s⁻¹), `> 0`.
    /// - `fetch_m`: fetch `x` (m), `> 0`.
    ///
    /// # Returns
    /// `Ω` (dimensionless), in `[0.84, 5]`.
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 37; docs/equations.md §4.
    pub fn inverse_wave_age_from_fetch(u10: f64, fetch_m: f64) -> f64 {
        let x = G * fetch_m / (u10 * u10);
        let t = libm::tanh(libm::pow(x / Self::X0, 0.4));
        (Self::FULLY_DEVELOPED * libm::pow(t, -0.75)).min(Self::MAX_INVERSE_WAVE_AGE)
    }

    /// The spectrum of a wind `U₁₀` blowing over a fetch `x`.
    ///
    /// # Arguments
    /// - `u10`: wind speed (m s⁻¹), `(0, 60]`.
    /// - `fetch_m`: fetch (m), `(0, 10⁸]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn from_fetch(u10: f64, fetch_m: f64) -> Result<Self, WaveError> {
        let u10 = check("u10_m_s", u10, u10 > 0.0 && u10 <= 60.0, "(0, 60] m/s")?;
        let fetch = check("fetch_m", fetch_m, fetch_m > 0.0 && fetch_m <= 1e8, "(0, 1e8] m")?;
        Self::new(u10, Self::inverse_wave_age_from_fetch(u10, fetch))
    }

    /// The spectrum of a wind `U₁₀` and an inverse wave age `Ω`.
    ///
    /// # Arguments
    /// - `u10`: wind speed (m s⁻¹), `(0, 60]`.
    /// - `inverse_wave_age`: `Ω = U₁₀/c_p` (dimensionless), `[0.84, 5]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn new(u10: f64, inverse_wave_age: f64) -> Result<Self, WaveError> {
        let u10 = check("u10_m_s", u10, u10 > 0.0 && u10 <= 60.0, "(0, 60] m/s")?;
        let om = check(
            "inverse_wave_age",
            inverse_wave_age,
            (Self::FULLY_DEVELOPED..=Self::MAX_INVERSE_WAVE_AGE).contains(&inverse_wave_age),
            "[0.84, 5]",
        )?;
        let k_p = G * (om / u10) * (om / u10);
        let c_p = phase_speed(k_p);
        let z0 = 3.7e-5 * u10 * u10 / G * libm::pow(u10 / c_p, 0.9);
        let u_star = Self::KAPPA * u10 / libm::log(10.0 / z0);
        let ratio = u_star / Self::C_M;
        let alpha_m =
            (1e-2 * if ratio <= 1.0 { 1.0 + libm::log(ratio) } else { 1.0 + 3.0 * libm::log(ratio) }).max(0.0);
        let gamma = if om < 1.0 { 1.7 } else { 1.7 + 6.0 * libm::log10(om) };
        Ok(Self {
            u10,
            omega_c: om,
            short_wave_peak_cutoff: true,
            k_p,
            c_p,
            u_star,
            alpha_p: 6e-3 * libm::sqrt(om),
            alpha_m,
            gamma,
            sigma: 0.08 * (1.0 + 4.0 / (om * om * om)),
            a_m: 0.13 * u_star / Self::C_M,
        })
    }

    /// The same spectrum with `B_h` as printed in the paper, without the `L_PM` factor.
    pub fn without_short_wave_peak_cutoff(self) -> Self {
        Self { short_wave_peak_cutoff: false, ..self }
    }

    /// Wind speed `U₁₀` (m s⁻¹).
    pub fn u10(&self) -> f64 {
        self.u10
    }
    /// Inverse wave age `Ω` (dimensionless).
    pub fn inverse_wave_age(&self) -> f64 {
        self.omega_c
    }
    /// Peak wavenumber `k_p = k₀Ω²` (rad m⁻¹).
    pub fn k_p(&self) -> f64 {
        self.k_p
    }
    /// Phase speed at the peak `c_p` (m s⁻¹).
    pub fn c_p(&self) -> f64 {
        self.c_p
    }
    /// Friction velocity `u*` (m s⁻¹).
    pub fn u_star(&self) -> f64 {
        self.u_star
    }
    /// Generalised Phillips–Kitaigorodskii parameters `(α_p, α_m)` (dimensionless).
    pub fn alphas(&self) -> (f64, f64) {
        (self.alpha_p, self.alpha_m)
    }
    /// Peak enhancement `γ` (dimensionless).
    pub fn gamma(&self) -> f64 {
        self.gamma
    }

    /// Phase speed of capillary–gravity waves, `c(k) = √((g/k)(1 + (k/k_m)²))`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `c` (m s⁻¹).
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 24.
    pub fn phase_speed(&self, k: f64) -> f64 {
        phase_speed(k)
    }

    /// `L_PM = exp[−(5/4)(k_p/k)²]`.
    fn l_pm(&self, k: f64) -> f64 {
        let r = self.k_p / k;
        libm::exp(-1.25 * r * r)
    }

    /// Long-wave curvature spectrum, `B_l(k) = ½ α_p (c_p/c) F_p`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `B_l` (dimensionless; `k³ S_l(k)`).
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 31–34; docs/equations.md §4.
    pub fn curvature_long(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let q = libm::sqrt(k / self.k_p) - 1.0;
        let big_gamma = libm::exp(-q * q / (2.0 * self.sigma * self.sigma));
        let j_p = libm::pow(self.gamma, big_gamma);
        let f_p = self.l_pm(k) * j_p * libm::exp(-self.omega_c / libm::sqrt(10.0) * q);
        0.5 * self.alpha_p * self.c_p / phase_speed(k) * f_p
    }

    /// Short-wave curvature spectrum, `B_h(k) = ½ α_m (c_m/c) F_m [× L_PM]`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `B_h` (dimensionless).
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 40–44; docs/equations.md §4 (the `L_PM` factor of the authors' code).
    pub fn curvature_short(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let q = k / Self::K_M - 1.0;
        let f_m = libm::exp(-0.25 * q * q);
        let b = 0.5 * self.alpha_m * Self::C_M / phase_speed(k) * f_m;
        if self.short_wave_peak_cutoff { b * self.l_pm(k) } else { b }
    }

    /// Up-wind/cross-wind ratio of the spreading, `Δ(k) = tanh[a₀ + a_p(c/c_p)^{2.5} + a_m(c_m/c)^{2.5}]`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `Δ` (dimensionless, in `(0, 1)`).
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 57, 59; docs/equations.md §4.
    pub fn spreading_delta(&self, k: f64) -> f64 {
        let c = phase_speed(k);
        libm::tanh(Self::A0 + Self::A_P * libm::pow(c / self.c_p, 2.5) + self.a_m * libm::pow(Self::C_M / c, 2.5))
    }

    /// Directional spectrum `Ψ(k, φ) = (1/(2π)) k⁻⁴ (B_l + B_h)(1 + Δ(k) cos 2φ)`.
    ///
    /// # Arguments
    /// - `k`: wavenumber (rad m⁻¹), `> 0`.
    /// - `phi`: angle of the wave vector from the wind (rad).
    ///
    /// # Returns
    /// `Ψ` (m⁴, variance per unit `d²k`); `∫∫ Ψ k dk dφ = m₀`; `0` for `k ≤ 0`.
    ///
    /// # References
    /// Elfouhaily et al. 1997, Eq. 67; docs/equations.md §4.
    pub fn directional(&self, k: f64, phi: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        let b = self.curvature_long(k) + self.curvature_short(k);
        b * (1.0 + self.spreading_delta(k) * libm::cos(2.0 * phi)) / (2.0 * PI * k * k * k * k)
    }

    /// Up-wind and cross-wind slope variances of the waves with `k ≤ k_max`:
    /// `σ_u² = ∫ k² S(k) (1 + Δ/2)/2 dk`, `σ_c² = ∫ k² S(k) (1 − Δ/2)/2 dk` (dimensionless).
    ///
    /// # Arguments
    /// - `k_max`: largest wavenumber (rad m⁻¹), `> 0`.
    ///
    /// # Returns
    /// `(σ_u², σ_c²)` (dimensionless), summing to [`Spectrum::mean_square_slope`].
    ///
    /// # References
    /// Elfouhaily et al. 1997, §6; docs/equations.md §11.
    pub fn slope_variances(&self, k_max: f64) -> (f64, f64) {
        let k_lo = self.k_p / 400.0;
        if !(k_max > k_lo) {
            return (0.0, 0.0);
        }
        let up = crate::spectra::integrate::simpson_log(
            |k| k * k * self.s_k(k) * 0.5 * (1.0 + 0.5 * self.spreading_delta(k)),
            k_lo,
            k_max,
            4000,
        );
        (up, self.mean_square_slope_between(k_lo, k_max) - up)
    }

    /// The spreading `D(θ; ω) = (1 + Δ(k(ω)) cos 2θ)/(2π)` of this spectrum.
    ///
    /// # Arguments
    /// - `directions`: [`Directions::BothWays`] as published (half the energy travels up-wind),
    ///   or [`Directions::Downwind`] (folded onto `|θ| ≤ π/2`, density `(1 + Δ cos 2θ)/π`, as
    ///   the published authors' code does for travelling waves).
    pub fn spreading(&self, directions: Directions) -> ElfouhailySpreading {
        ElfouhailySpreading { spectrum: *self, directions }
    }
}

/// `c(k) = √((g/k)(1 + (k/k_m)²))`.
fn phase_speed(k: f64) -> f64 {
    let r = k / ELFOUHAILY_K_M;
    libm::sqrt(G / k * (1.0 + r * r))
}

impl Spectrum for Elfouhaily {
    /// `S(ω) = S(k) dk/dω` with `ω² = g k (1 + (k/k_m)²)`.
    fn s_omega(&self, omega: f64) -> f64 {
        if !(omega > 0.0) {
            return 0.0;
        }
        let d = self.dispersion();
        let k = d.wavenumber(omega);
        self.s_k(k) / d.group_velocity(k)
    }

    /// `ω(k_p)`, the spectrum's peak parameter. The maximum of `S(ω)` lies within a few per cent
    /// of it (the `c_p/c` and `exp[−Ω(√(k/k_p) − 1)/√10]` factors move it slightly).
    fn peak_omega(&self) -> f64 {
        self.dispersion().omega(self.k_p)
    }

    fn dispersion(&self) -> Dispersion {
        Dispersion::elfouhaily()
    }

    /// `S(k) = k⁻³ (B_l + B_h)` (m³), Eq. 30.
    fn s_k(&self, k: f64) -> f64 {
        if !(k > 0.0) {
            return 0.0;
        }
        (self.curvature_long(k) + self.curvature_short(k)) / (k * k * k)
    }
}

/// The directional spreading of the Elfouhaily spectrum, `D(θ; ω) = (1 + Δ(k) cos 2θ)/(2π)`,
/// `k = k(ω)` by the capillary–gravity dispersion.
///
/// # References
/// Elfouhaily et al. 1997, Eq. 49, 57, 67.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElfouhailySpreading {
    spectrum: Elfouhaily,
    directions: Directions,
}

impl ElfouhailySpreading {
    fn delta(&self, omega: f64) -> f64 {
        self.spectrum.spreading_delta(Dispersion::elfouhaily().wavenumber(omega))
    }
}

impl Spreading for ElfouhailySpreading {
    fn density(&self, theta: f64, omega: f64) -> f64 {
        let d = self.delta(omega);
        match self.directions {
            Directions::BothWays => (1.0 + d * libm::cos(2.0 * theta)) / (2.0 * PI),
            Directions::Downwind if theta.abs() <= FRAC_PI_2 => (1.0 + d * libm::cos(2.0 * theta)) / PI,
            Directions::Downwind => 0.0,
        }
    }

    /// Inverts the closed-form distribution `C(θ) = (θ + θ₀ + (Δ/2) sin 2θ)/(2θ₀)`
    /// (`θ₀ = π` both ways, `π/2` down-wind) by safeguarded Newton.
    fn sample(&self, omega: f64, u: f64) -> f64 {
        let d = self.delta(omega);
        let half = match self.directions {
            Directions::BothWays => PI,
            Directions::Downwind => FRAC_PI_2,
        };
        let cdf = |t: f64| (t + half + 0.5 * d * libm::sin(2.0 * t)) / (2.0 * half);
        let pdf = |t: f64| (1.0 + d * libm::cos(2.0 * t)) / (2.0 * half);
        invert_cdf(cdf, pdf, -half, half, u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Oracle values printed to 5 significant digits (`0.06922`, `11.905`): half a unit of the
    /// last digit is ≤ 7×10⁻⁵ relative; 10⁻⁴ with the reference's own rounding.
    const PRINTED_5_DIGITS_REL: f64 = 1e-4;

    /// Oracle values printed to 4 significant digits (`0.3868`, `5.665×10⁻³`): half a unit is
    /// ≤ 1.3×10⁻⁴ relative.
    const PRINTED_4_DIGITS_REL: f64 = 2e-4;

    /// `Δ` printed to 4 decimals.
    const PRINTED_4_DECIMALS: f64 = 1e-4;

    /// `Ω(x)` printed to 4 digits; the reference rounds 2.1795 (x = 10⁴ m) up to 2.180.
    const FETCH_OMEGA_ABS: f64 = 1e-3;

    /// The midpoint rule on the trigonometric polynomial `1 + Δ cos 2φ` over its period is exact
    /// up to rounding.
    const PERIODIC_MIDPOINT_REL: f64 = 1e-12;

    /// A 20 000-cell midpoint quadrature of the density (error `O(h²)` ≈ 10⁻¹⁰) against the
    /// Newton inversion (stopped at 10⁻¹³ in `θ`).
    const CDF_QUADRATURE_ABS: f64 = 1e-8;

    #[test]
    fn oracle_at_10_m_s() {
        // Reference value (docs/equations.md) (U10 = 10, Ω = 0.84, κ = 0.4, B_h × L_PM), printed to 4–5 digits.
        let e = Elfouhaily::fully_developed(10.0).unwrap();
        assert!((e.k_p() / 0.06922 - 1.0).abs() < PRINTED_5_DIGITS_REL);
        assert!((e.c_p() / 11.905 - 1.0).abs() < PRINTED_5_DIGITS_REL);
        assert!((e.u_star() / 0.3868 - 1.0).abs() < PRINTED_4_DIGITS_REL);
        assert!((e.s_k(1.0) / 5.665e-3 - 1.0).abs() < PRINTED_4_DIGITS_REL);
        assert!((e.spreading_delta(e.k_p()) - 0.9995).abs() < PRINTED_4_DECIMALS);
        assert!((e.spreading_delta(100.0) - 0.2602).abs() < PRINTED_4_DECIMALS);
    }

    #[test]
    fn fetch_oracle() {
        // Reference value (docs/equations.md): U10 = 10, x = 10⁴, 10⁵, 10⁶ m ⇒ Ω = 2.180, 1.203, 0.874.
        for (x, om) in [(1e4, 2.180), (1e5, 1.203), (1e6, 0.874)] {
            let got = Elfouhaily::inverse_wave_age_from_fetch(10.0, x);
            assert!((got - om).abs() < FETCH_OMEGA_ABS, "x = {x}: Ω = {got}");
        }
    }

    #[test]
    fn directional_form_integrates_to_s_k() {
        let e = Elfouhaily::from_fetch(12.0, 5e4).unwrap();
        for k in [0.05, 1.0, 300.0] {
            let n = 2000;
            let h = 2.0 * PI / n as f64;
            let s: f64 = (0..n).map(|j| e.directional(k, -PI + (j as f64 + 0.5) * h) * k * h).sum();
            assert!((s / e.s_k(k) - 1.0).abs() < PERIODIC_MIDPOINT_REL, "k = {k}");
        }
    }

    #[test]
    fn spreading_samples_invert_the_distribution() {
        let e = Elfouhaily::fully_developed(8.0).unwrap();
        for dirs in [Directions::BothWays, Directions::Downwind] {
            let d = e.spreading(dirs);
            for u in [0.01, 0.2, 0.5, 0.77, 0.99] {
                let theta = d.sample(3.0, u);
                // Midpoint quadrature of the density up to θ reproduces u.
                let lo = if dirs == Directions::BothWays { -PI } else { -FRAC_PI_2 };
                let n = 20_000;
                let h = (theta - lo) / n as f64;
                let c: f64 = (0..n).map(|j| d.density(lo + (j as f64 + 0.5) * h, 3.0) * h).sum();
                assert!((c - u).abs() < CDF_QUADRATURE_ABS, "{dirs:?} u = {u}: C(θ) = {c}");
            }
        }
    }

    #[test]
    fn calm_winds_clamp_alpha_m_at_zero() {
        let e = Elfouhaily::fully_developed(1.0).unwrap();
        assert!(e.alphas().1 >= 0.0);
        assert!(e.s_k(400.0) >= 0.0);
    }

    #[test]
    fn bad_parameters_are_named() {
        assert!(Elfouhaily::new(10.0, 0.5).unwrap_err().to_string().contains("inverse_wave_age"));
        assert!(Elfouhaily::from_fetch(10.0, -1.0).unwrap_err().to_string().contains("fetch_m"));
        assert!(Elfouhaily::fully_developed(0.0).unwrap_err().to_string().contains("u10_m_s"));
    }
}
