//! Directional spreading functions `D(θ; ω)`, normalised so that `∫_{−π}^{π} D dθ = 1`.

use std::f64::consts::{FRAC_PI_2, PI};

use crate::error::{WaveError, check};

/// A directional spreading function: the share of the energy at frequency `ω` travelling at
/// angle `θ` from the mean wind direction.
///
/// Implemented by [`CosineTwoS`] (Longuet-Higgins / Mitsuyasu / Hasselmann), [`DonelanBanner`],
/// [`CosineSquared`] and [`crate::ElfouhailySpreading`].
///
/// `Sync`: the FFT ocean integrates its grids over rows in parallel.
pub trait Spreading: Sync {
    /// Directional spreading density `D(θ; ω)`: the share of the variance at frequency `ω` per
    /// radian of direction, `∫_{−π}^{π} D(θ; ω) dθ = 1`.
    ///
    /// # Arguments
    /// - `theta`: direction relative to the mean wind direction (rad), `(−π, π]`.
    /// - `omega`: angular frequency (rad s⁻¹), `> 0`.
    ///
    /// # Returns
    /// `D` (rad⁻¹), `≥ 0`.
    ///
    /// # References
    /// docs/equations.md §1 (each implementation cites its law).
    fn density(&self, theta: f64, omega: f64) -> f64;

    /// Draws a direction from `D(·; ω)`: the inverse `C⁻¹(u)` of the cumulative distribution
    /// `C(θ) = ∫_{−π}^{θ} D(θ'; ω) dθ'`, here tabulated on 2048 trapezoids and interpolated
    /// linearly. Deterministic for a given `u`; implementations with a closed-form distribution
    /// override it.
    ///
    /// # Arguments
    /// - `omega`: angular frequency (rad s⁻¹), `> 0`.
    /// - `u`: uniform variate, `[0, 1]` (clamped).
    ///
    /// # Returns
    /// `θ` (rad) relative to the mean wind direction, in `[−π, π]` (`[−π/2, π/2]` for down-wind
    /// laws).
    ///
    /// # References
    /// Inverse-transform sampling (Devroye 1986, *Non-Uniform Random Variate Generation*, §II.2).
    fn sample(&self, omega: f64, u: f64) -> f64 {
        tabulated_inverse(|theta| self.density(theta, omega), u)
    }
}

/// The inverse `C⁻¹(u)` of the cumulative distribution of `density` over `(−π, π]`, tabulated on
/// 2048 trapezoids and interpolated linearly ([`Spreading::sample`]'s default).
fn tabulated_inverse(density: impl Fn(f64) -> f64, u: f64) -> f64 {
    const N: usize = 2048;
    let h = 2.0 * PI / N as f64;
    let mut cdf = Vec::with_capacity(N + 1);
    cdf.push(0.0);
    let mut prev = density(-PI);
    let mut acc = 0.0;
    for j in 1..=N {
        let d = density(-PI + j as f64 * h);
        acc += 0.5 * (prev + d) * h;
        cdf.push(acc);
        prev = d;
    }
    let target = u.clamp(0.0, 1.0) * acc;
    let j = cdf.partition_point(|&c| c < target).clamp(1, N);
    let (c0, c1) = (cdf[j - 1], cdf[j]);
    let frac = if c1 > c0 { (target - c0) / (c1 - c0) } else { 0.5 };
    -PI + (j as f64 - 1.0 + frac) * h
}

/// Which directions a spreading symmetric under `θ → θ + π` covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Directions {
    /// Up-wind and down-wind alike, over `(−π, π]` (the published form of Tessendorf's and
    /// Elfouhaily's spreadings: a height spectrum cannot tell `k` from `−k`).
    BothWays,
    /// Folded onto the down-wind half `|θ| ≤ π/2` with twice the density: every wave travels
    /// with the wind (what a wind sea does, and what the fit wants).
    #[default]
    Downwind,
}

/// Solves `cdf(θ) = u` on `[lo, hi]` for a continuous increasing `cdf` with derivative `pdf`, by
/// Newton's method safeguarded with bisection, to `|Δθ| ≤ 10⁻¹³` (at most 100 iterations).
pub(crate) fn invert_cdf(cdf: impl Fn(f64) -> f64, pdf: impl Fn(f64) -> f64, lo: f64, hi: f64, u: f64) -> f64 {
    let u = u.clamp(0.0, 1.0);
    let (mut a, mut b) = (lo, hi);
    let mut t = lo + u * (hi - lo);
    for _ in 0..100 {
        let f = cdf(t) - u;
        if f > 0.0 {
            b = t;
        } else {
            a = t;
        }
        let p = pdf(t);
        let next = if p > 0.0 { t - f / p } else { f64::NAN };
        let next = if next > a && next < b { next } else { 0.5 * (a + b) };
        let done = (next - t).abs() <= 1e-13;
        t = next;
        if done || b - a <= 1e-13 {
            break;
        }
    }
    t
}

/// The cos-2s spreading `D(θ) = 2^{2s−1} Γ(s+1)² / (π Γ(2s+1)) |cos(θ/2)|^{2s}` with an exponent
/// `s(ω) = s_a (ω/ω_p)^{p_a}` below the peak and `s_b (ω/ω_p)^{p_b}` above it.
///
/// Three parameterisations: Hasselmann et al. 1980 as simplified in docs/equations.md
/// (`s = 6.97 (ω/ω_p)^5` below, `9.77 (ω/ω_p)^{−2.5}` above), Mitsuyasu et al. 1975
/// (`s = s_max (ω/ω_p)^5` below, `s_max (ω/ω_p)^{−2.5}` above, `s_max = 11.5 (ω_p U₁₀/g)^{−2.5}`)
/// and a constant `s` (Longuet-Higgins et al. 1963).
///
/// # References
/// Longuet-Higgins M.S., Cartwright D.E., Smith N.D. 1963 (the cos-2s form); Mitsuyasu H. et al.
/// 1975, JPO 5; Hasselmann D., Dunckel M., Ewing J. 1980, "Directional wave spectra observed
/// during JONSWAP 1973", JPO 10; docs/equations.md §1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CosineTwoS {
    omega_p: f64,
    s_below: f64,
    s_above: f64,
    p_below: f64,
    p_above: f64,
}

impl CosineTwoS {
    /// The Hasselmann et al. 1980 spreading around a spectral peak `ω_p` (rad s⁻¹, `> 0`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] if `ω_p` is not positive and finite.
    pub fn hasselmann(omega_p: f64) -> Result<Self, WaveError> {
        let omega_p = check("omega_p_rad_s", omega_p, omega_p > 0.0, "(0, ∞) rad/s")?;
        Ok(Self { omega_p, s_below: 6.97, s_above: 9.77, p_below: 5.0, p_above: -2.5 })
    }

    /// The Mitsuyasu et al. 1975 spreading around `ω_p` (rad s⁻¹, `> 0`) for a wind `U₁₀`
    /// (m s⁻¹, `(0, 60]`): `s_max = 11.5 (ω_p U₁₀/g)^{−2.5}`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn mitsuyasu(omega_p: f64, u10: f64) -> Result<Self, WaveError> {
        let omega_p = check("omega_p_rad_s", omega_p, omega_p > 0.0, "(0, ∞) rad/s")?;
        let u10 = check("u10_m_s", u10, u10 > 0.0 && u10 <= 60.0, "(0, 60] m/s")?;
        let s_max = 11.5 * libm::pow(omega_p * u10 / crate::G, -2.5);
        Ok(Self { omega_p, s_below: s_max, s_above: s_max, p_below: 5.0, p_above: -2.5 })
    }

    /// A frequency-independent exponent `s` (dimensionless, `[0, 1000]`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] for `s` outside `[0, 1000]`.
    pub fn constant(s: f64) -> Result<Self, WaveError> {
        let s = check("s", s, (0.0..=1000.0).contains(&s), "[0, 1000]")?;
        Ok(Self { omega_p: 1.0, s_below: s, s_above: s, p_below: 0.0, p_above: 0.0 })
    }

    /// The spreading exponent, `s(ω) = s_a (ω/ω_p)^{p_a}` below the peak, `s_b (ω/ω_p)^{p_b}` above.
    ///
    /// # Arguments
    /// - `omega`: angular frequency (rad s⁻¹), `> 0`.
    ///
    /// # Returns
    /// `s` (dimensionless).
    ///
    /// # References
    /// Mitsuyasu et al. 1975; Hasselmann et al. 1980; docs/equations.md §1.
    pub fn exponent(&self, omega: f64) -> f64 {
        let r = omega / self.omega_p;
        if r < 1.0 { self.s_below * libm::pow(r, self.p_below) } else { self.s_above * libm::pow(r, self.p_above) }
    }
}

/// Normalisation `2^{2s−1} Γ(s+1)² / (π Γ(2s+1))` of the cos-2s law, through `ln Γ` so that it
/// stays finite for large `s`.
fn cos2s_normalisation(s: f64) -> f64 {
    let ln =
        (2.0 * s - 1.0) * std::f64::consts::LN_2 + 2.0 * libm::lgamma(s + 1.0) - libm::lgamma(2.0 * s + 1.0) - LN_PI;
    libm::exp(ln)
}

/// `ln π`, the value `libm::log(π)` rounds to.
const LN_PI: f64 = 1.144_729_885_849_400_2;

impl CosineTwoS {
    /// `θ ↦ D(θ; ω)` with the exponent and the normalisation, which depend on `ω` alone, computed
    /// once.
    fn density_at(&self, omega: f64) -> impl Fn(f64) -> f64 {
        let s = self.exponent(omega);
        let norm = cos2s_normalisation(s);
        move |theta| norm * libm::pow(libm::fabs(libm::cos(0.5 * theta)), 2.0 * s)
    }
}

impl Spreading for CosineTwoS {
    fn density(&self, theta: f64, omega: f64) -> f64 {
        self.density_at(omega)(theta)
    }

    /// The default tabulated inverse, with the exponent and the normalisation computed once for
    /// the 2049 densities (the same numbers as [`Spreading::sample`]'s default).
    fn sample(&self, omega: f64, u: f64) -> f64 {
        tabulated_inverse(self.density_at(omega), u)
    }
}

/// The sech² spreading of Donelan, Hamilton & Hui (1985) with Banner's (1990) extension above
/// `1.6 ω_p`: `D(θ) = β sech²(βθ) / (2 tanh(βπ))`,
/// `β = 2.61 r^{1.3}` (`0.56 < r < 0.95`), `2.28 r^{−1.3}` (`0.95 ≤ r < 1.6`),
/// `10^{−0.4 + 0.8393 exp(−0.567 ln r²)}` (`r ≥ 1.6`), `r = ω/ω_p`, and `β = 1.24` below
/// `r = 0.56` (the value at 0.56).
///
/// The factor `1/tanh(βπ)` (at most 1.0008 here) renormalises the law to the circle `(−π, π]`.
///
/// # References
/// Donelan M.A., Hamilton J., Hui W.H. 1985, "Directional spectra of wind-generated waves",
/// Phil. Trans. R. Soc. A315:509–562; Banner M.L. 1990, "Equilibrium spectra of wind waves", JPO
/// 20:966–984; Horvath C.J. 2015, "Empirical directional wave spectra for computer graphics",
/// `DigiPro` 2015.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DonelanBanner {
    omega_p: f64,
}

impl DonelanBanner {
    /// The spreading around a spectral peak `ω_p` (rad s⁻¹, `> 0`).
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] if `ω_p` is not positive and finite.
    pub fn new(omega_p: f64) -> Result<Self, WaveError> {
        let omega_p = check("omega_p_rad_s", omega_p, omega_p > 0.0, "(0, ∞) rad/s")?;
        Ok(Self { omega_p })
    }

    /// The width parameter `β(ω)` of the sech² law (branches in the type's documentation).
    ///
    /// # Arguments
    /// - `omega`: angular frequency (rad s⁻¹), `> 0`.
    ///
    /// # Returns
    /// `β` (dimensionless).
    ///
    /// # References
    /// Donelan, Hamilton & Hui 1985 (the sech² fit); Banner 1990 (above `1.6 ω_p`); as collected by
    /// Horvath 2015.
    pub fn beta(&self, omega: f64) -> f64 {
        let r = omega / self.omega_p;
        if r < 0.56 {
            2.61 * libm::pow(0.56, 1.3)
        } else if r < 0.95 {
            2.61 * libm::pow(r, 1.3)
        } else if r < 1.6 {
            2.28 * libm::pow(r, -1.3)
        } else {
            libm::pow(10.0, -0.4 + 0.8393 * libm::exp(-0.567 * libm::log(r * r)))
        }
    }
}

impl Spreading for DonelanBanner {
    fn density(&self, theta: f64, omega: f64) -> f64 {
        let b = self.beta(omega);
        let sech = 1.0 / libm::cosh(b * theta);
        b * sech * sech / (2.0 * libm::tanh(b * PI))
    }

    /// Closed-form inverse: `θ = atanh((2u − 1) tanh(βπ))/β`.
    fn sample(&self, omega: f64, u: f64) -> f64 {
        let b = self.beta(omega);
        let u = u.clamp(0.0, 1.0);
        libm::atanh((2.0 * u - 1.0) * libm::tanh(b * PI)) / b
    }
}

/// The `cos²θ` spreading: `D = (2/π) cos²θ` on the down-wind half (the reference's (docs/equations.md)
/// "simplest" law), or `D = (1/π) cos²θ` over the whole circle, the `|k̂·ŵ|²` of Tessendorf's
/// Phillips spectrum.
///
/// # References
/// Tessendorf 2001, §3.3; docs/equations.md §1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CosineSquared {
    directions: Directions,
}

impl CosineSquared {
    /// `(2/π) cos²θ` for `|θ| ≤ π/2`.
    pub fn downwind() -> Self {
        Self { directions: Directions::Downwind }
    }

    /// `(1/π) cos²θ` over `(−π, π]` (Tessendorf's `|k̂·ŵ|²`).
    pub fn both_ways() -> Self {
        Self { directions: Directions::BothWays }
    }
}

impl Spreading for CosineSquared {
    fn density(&self, theta: f64, _omega: f64) -> f64 {
        let c = libm::cos(theta);
        match self.directions {
            Directions::BothWays => c * c / PI,
            Directions::Downwind if theta.abs() <= FRAC_PI_2 => 2.0 * c * c / PI,
            Directions::Downwind => 0.0,
        }
    }

    /// Inverts `C(θ) = (θ + θ₀ + ½ sin 2θ)/(2θ₀)` (`θ₀ = π` or `π/2`).
    fn sample(&self, _omega: f64, u: f64) -> f64 {
        let half = match self.directions {
            Directions::BothWays => PI,
            Directions::Downwind => FRAC_PI_2,
        };
        let cdf = |t: f64| (t + half + 0.5 * libm::sin(2.0 * t)) / (2.0 * half);
        let pdf = |t: f64| (1.0 + libm::cos(2.0 * t)) / (2.0 * half);
        invert_cdf(cdf, pdf, -half, half, u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `∫D dθ = 1` by the midpoint rule on 20 000 cells. Smooth periodic integrands (or a kink at
    /// `±π/2` for the down-wind fold) converge fast; cos-2s with `s < ½` (Hasselmann and Mitsuyasu
    /// well below the peak) has an infinite slope at `±π`, where the rule converges only as
    /// `h^{1+2s}`: 2×10⁻⁶ at 20 000 cells for `s = 0.017`.
    const NORMALISATION_ABS: f64 = 2e-6;

    /// The median of the 2048-trapezoid table of a symmetric law is 0 up to the table's linear
    /// interpolation: a fraction of its cell `2π/2048` = 3×10⁻³ rad.
    const MEDIAN_TABLE_RAD: f64 = 2e-3;

    /// The closed-form distribution against a 40 000-cell midpoint quadrature (kinks only at
    /// `±π/2`: error below 10⁻⁸) and the Newton inversion (10⁻¹³).
    const CDF_QUADRATURE_ABS: f64 = 1e-7;

    /// Below `r = 0.56` the law is held at its branch value `2.61·0.56^{1.3}`, so it is continuous
    /// there: the two sides differ by the slope (≈ 2.9) times the 2×10⁻¹² step, plus rounding.
    const CONTINUITY_ABS: f64 = 1e-9;

    /// Donelan et al. 1985's two branches meet within 2 % at `r = 0.95` (their own fit).
    const DONELAN_BRANCH_REL: f64 = 0.02;

    /// Banner's extension meets Donelan's branch at `r = 1.6` to the 4 printed digits (1.238).
    const BANNER_BRANCH_REL: f64 = 1e-3;

    /// The same `pow` expression two ways.
    const ROUND_ABS: f64 = 1e-10;

    /// `s_max = 17.01` printed to 2 decimals.
    const PRINTED_2_DECIMALS: f64 = 0.005;

    #[test]
    fn ln_pi_is_what_libm_gives() {
        assert_eq!(LN_PI.to_bits(), libm::log(PI).to_bits());
    }

    proptest::proptest! {
        /// The cos-2s law's own inverse (exponent and normalisation once per `ω`) draws exactly
        /// the direction the default tabulated inverse of its density draws.
        #[test]
        fn the_cos2s_inverse_is_the_default_one(
            omega in 0.05f64..20.0, u in 0.0f64..=1.0, which in 0usize..3,
        ) {
            let d = match which {
                0 => CosineTwoS::hasselmann(0.9).unwrap(),
                1 => CosineTwoS::mitsuyasu(0.7, 12.0).unwrap(),
                _ => CosineTwoS::constant(7.5).unwrap(),
            };
            let default = tabulated_inverse(|theta| d.density(theta, omega), u);
            proptest::prop_assert_eq!(d.sample(omega, u).to_bits(), default.to_bits());
        }
    }

    /// `∫_{−π}^{π} D dθ` by the midpoint rule on `n` cells.
    fn integral(d: &dyn Spreading, omega: f64, n: usize) -> f64 {
        let h = 2.0 * PI / n as f64;
        (0..n).map(|j| d.density(-PI + (j as f64 + 0.5) * h, omega) * h).sum()
    }

    #[test]
    fn cos2s_integrates_to_one_for_several_exponents() {
        for omega in [0.3, 0.8, 1.0, 2.0, 5.0] {
            let d = CosineTwoS::hasselmann(1.0).unwrap();
            let total = integral(&d, omega, 20_000);
            assert!((total - 1.0).abs() < NORMALISATION_ABS, "ω = {omega}: ∫D = {total}");
        }
    }

    #[test]
    fn every_spreading_integrates_to_one() {
        let list: Vec<Box<dyn Spreading>> = vec![
            Box::new(CosineTwoS::mitsuyasu(0.8, 10.0).unwrap()),
            Box::new(CosineTwoS::constant(3.0).unwrap()),
            Box::new(DonelanBanner::new(0.8).unwrap()),
            Box::new(CosineSquared::downwind()),
            Box::new(CosineSquared::both_ways()),
        ];
        for d in &list {
            for omega in [0.3, 0.7, 0.8, 1.1, 2.0, 6.0] {
                let total = integral(d.as_ref(), omega, 20_000);
                assert!((total - 1.0).abs() < NORMALISATION_ABS, "ω = {omega}: ∫D = {total}");
            }
        }
    }

    #[test]
    fn cos2s_is_symmetric_and_sampling_is_centred() {
        let d = CosineTwoS::hasselmann(1.0).unwrap();
        assert_eq!(d.density(0.4, 1.0).to_bits(), d.density(-0.4, 1.0).to_bits());
        assert!(d.sample(1.0, 0.5).abs() < MEDIAN_TABLE_RAD);
        assert!(d.sample(1.0, 0.1) < 0.0 && d.sample(1.0, 0.9) > 0.0);
    }

    #[test]
    fn closed_form_samplers_invert_the_density() {
        let list: Vec<Box<dyn Spreading>> = vec![
            Box::new(DonelanBanner::new(1.0).unwrap()),
            Box::new(CosineSquared::downwind()),
            Box::new(CosineSquared::both_ways()),
        ];
        for d in &list {
            for u in [0.02, 0.3, 0.5, 0.81, 0.97] {
                let theta = d.sample(1.3, u);
                let n = 40_000;
                let h = (theta + PI) / n as f64;
                let c: f64 = (0..n).map(|j| d.density(-PI + (j as f64 + 0.5) * h, 1.3) * h).sum();
                assert!((c - u).abs() < CDF_QUADRATURE_ABS, "u = {u}: C(θ) = {c}");
            }
        }
    }

    #[test]
    fn donelan_banner_beta_is_continuous_at_the_branch_points() {
        let d = DonelanBanner::new(1.0).unwrap();
        assert!((d.beta(0.56 - 1e-12) - d.beta(0.56 + 1e-12)).abs() < CONTINUITY_ABS);
        // Donelan's two branches meet within 2 % at r = 0.95 (2.61·0.95^1.3 = 2.446, 2.28·0.95^−1.3 = 2.437).
        assert!((d.beta(0.95 - 1e-9) / d.beta(0.95) - 1.0).abs() < DONELAN_BRANCH_REL);
        // Banner's extension meets Donelan's branch at r = 1.6: 10^(−0.4 + 0.8393·2.56^−0.567) = 1.238,
        // 2.28·1.6^−1.3 = 1.238.
        assert!((d.beta(1.6) / d.beta(1.6 - 1e-9) - 1.0).abs() < BANNER_BRANCH_REL);
    }

    #[test]
    fn mitsuyasu_s_max_oracle() {
        // s_max = 11.5 (ω_p U/g)^−2.5; with ω_p U/g = 0.855 (fully developed), s_max = 17.01.
        let u = 10.0;
        let wp = 0.855 * crate::G / u;
        let d = CosineTwoS::mitsuyasu(wp, u).unwrap();
        let expected = 11.5 * 0.855f64.powf(-2.5);
        assert!((d.exponent(wp) - expected).abs() < ROUND_ABS);
        assert!((expected - 17.01).abs() < PRINTED_2_DECIMALS);
    }
}
