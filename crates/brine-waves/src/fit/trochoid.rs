//! A single trochoid (Gerstner) wave and its exact height profile.

use std::f64::consts::{PI, TAU};

use glam::DVec2;

use crate::error::{WaveError, check};

/// Largest steepness accepted: at `Q = 1` the crest is a cusp with an infinite slope.
pub const MAX_STEEPNESS: f64 = 0.99;

/// One trochoid wave.
///
/// A water particle at rest position `u` (horizontal, m) moves on a circle:
/// `x = u − (Q/k) d̂ sin φ`, `y = A cos φ`, with phase `φ = k d̂·u − ω t + φ₀`. With `Q = kA` this
/// is Gerstner's exact trochoid (horizontal and vertical radii equal); a larger `Q` sharpens the
/// crests ("choppiness"). `Q < 1` keeps the profile a single-valued height field.
///
/// # References
/// Thon S., Ghazanfarpour D. 2002, "Ocean waves synthesis and animation using real world
/// information", Computers & Graphics 26(1):99–108; Darles et al. 2007, §3; docs/equations.md §1.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Trochoid {
    amplitude: f64,
    wavenumber: f64,
    direction: f64,
    omega: f64,
    phase: f64,
    steepness: f64,
}

impl Trochoid {
    /// A trochoid wave.
    ///
    /// # Arguments
    /// - `amplitude`: vertical radius `A` (m), `[0, ∞)`.
    /// - `wavenumber`: `k` (rad m⁻¹), `(0, ∞)`; wavelength `λ = 2π/k`.
    /// - `direction`: propagation angle `θ` (rad) from +x toward +z (see `docs/conventions.md`).
    /// - `omega`: angular frequency `ω` (rad s⁻¹), `[0, ∞)`.
    /// - `phase`: initial phase `φ₀` (rad), finite.
    /// - `steepness`: `Q = k × horizontal radius`, `[0, 0.99]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming the first parameter outside its range.
    pub fn new(
        amplitude: f64,
        wavenumber: f64,
        direction: f64,
        omega: f64,
        phase: f64,
        steepness: f64,
    ) -> Result<Self, WaveError> {
        Ok(Self {
            amplitude: check("amplitude_m", amplitude, amplitude >= 0.0, "[0, ∞) m")?,
            wavenumber: check("wavenumber_rad_m", wavenumber, wavenumber > 0.0, "(0, ∞) rad/m")?,
            direction: check("direction_rad", direction, true, "finite")?,
            omega: check("omega_rad_s", omega, omega >= 0.0, "[0, ∞) rad/s")?,
            phase: check("phase_rad", phase, true, "finite")?,
            steepness: check("steepness", steepness, (0.0..=MAX_STEEPNESS).contains(&steepness), "[0, 0.99]")?,
        })
    }

    /// The same wave with the steepness `Q = steepness`, `[0, 0.99]`.
    ///
    /// # Errors
    /// [`WaveError::OutOfRange`] naming `steepness` outside its range.
    pub fn with_steepness(self, steepness: f64) -> Result<Self, WaveError> {
        let steepness = check("steepness", steepness, (0.0..=MAX_STEEPNESS).contains(&steepness), "[0, 0.99]")?;
        Ok(Self { steepness, ..self })
    }

    /// Vertical radius `A` (m).
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }
    /// Wavenumber `k` (rad m⁻¹).
    pub fn wavenumber(&self) -> f64 {
        self.wavenumber
    }
    /// Wavelength `λ = 2π/k` (m).
    pub fn wavelength(&self) -> f64 {
        TAU / self.wavenumber
    }
    /// Propagation angle `θ` (rad) from +x toward +z.
    pub fn direction(&self) -> f64 {
        self.direction
    }
    /// Unit propagation vector `d̂ = (cos θ, sin θ)` in the (x, z) plane.
    pub fn direction_vector(&self) -> DVec2 {
        DVec2::new(self.direction.cos(), self.direction.sin())
    }
    /// Angular frequency `ω` (rad s⁻¹).
    pub fn omega(&self) -> f64 {
        self.omega
    }
    /// Initial phase `φ₀` (rad).
    pub fn phase(&self) -> f64 {
        self.phase
    }
    /// Steepness `Q` (dimensionless).
    pub fn steepness(&self) -> f64 {
        self.steepness
    }
    /// Horizontal radius `Q/k` (m).
    pub fn horizontal_radius(&self) -> f64 {
        self.steepness / self.wavenumber
    }

    /// Largest slope of the profile, `|dh/dx|max = kA/√(1 − Q²)`, reached where `cos θ = Q`
    /// (at height `Q·A`, not at the crest).
    ///
    /// # Returns
    /// The slope (dimensionless): the Lipschitz constant of this wave's height field.
    ///
    /// # References
    /// docs/equations.md §1, "max |slope|" (derived; Darles et al. 2007 §3.2 place it wrongly at the
    /// crest).
    pub fn max_slope(&self) -> f64 {
        self.wavenumber * self.amplitude / (1.0 - self.steepness * self.steepness).sqrt()
    }

    /// Largest downward curvature of the profile, at the crest: `−d²h/dx² ≤ k²A/(1 − Q)²`.
    ///
    /// From `d²h/dx² = k²A (Q − cos θ)/(1 − Q cos θ)³` (differentiating `dh/dx` above once more
    /// with `dθ/dx = k/(1 − Q cos θ)`), whose minimum `−k²A/(1 − Q)²` is at `θ = 0`.
    ///
    /// # Returns
    /// The curvature bound (1/m): with the wave's `σ = k k̂·d̂_xz` in place of `k`, the bound of
    /// the second derivative of `h` along a ray.
    ///
    /// # References
    /// docs/equations.md §1 (trochoid profile, `x = θ/k − (Q/k) sin θ`, `h = A cos θ`); derived.
    pub fn max_crest_curvature(&self) -> f64 {
        let q = self.steepness;
        self.wavenumber * self.wavenumber * self.amplitude / ((1.0 - q) * (1.0 - q))
    }

    /// Largest upward curvature of the profile, `max d²h/dx² = k²A·c(Q)`, with
    /// `c(Q) = 1/(1 + Q)²` (at the trough) for `Q ≤ 1/3` and `c(Q) = 4/(27 Q (1 − Q²)²)` (where
    /// `cos θ = (3Q² − 1)/(2Q)`) above.
    ///
    /// The maximum over `c = cos θ ∈ [−1, 1]` of `(Q − c)/(1 − Qc)³`: its derivative has the sign
    /// of `3Q² − 1 − 2Qc`, negative on the whole interval when `Q ≤ 1/3`. The troughs are round
    /// while the crests sharpen: at `Q = 0.9`, `c = 4.56` against the crest's `1/(1 − Q)² = 100`.
    /// For `F = y − h`, this is how concave `F` can be, which alone limits a certified step
    /// toward the surface from above.
    ///
    /// # Returns
    /// The curvature bound (1/m), used with `σ` as [`Self::max_crest_curvature`].
    ///
    /// # References
    /// docs/equations.md §1 (trochoid profile); derived here.
    pub fn max_trough_curvature(&self) -> f64 {
        self.wavenumber * self.wavenumber * self.amplitude * trough_curvature_factor(self.steepness)
    }
}

/// `c(Q) = max_θ (Q − cos θ)/(1 − Q cos θ)³` for `Q ∈ [0, 1)`: `1/(1 + Q)²` up to `Q = 1/3`,
/// `4/(27 Q (1 − Q²)²)` above (see [`Trochoid::max_trough_curvature`]).
pub(crate) fn trough_curvature_factor(q: f64) -> f64 {
    if q <= 1.0 / 3.0 { 1.0 / ((1.0 + q) * (1.0 + q)) } else { 4.0 / (27.0 * q * (1.0 - q * q).powi(2)) }
}

impl Trochoid {
    /// Mean-square slope of the profile averaged over horizontal position,
    /// `⟨(dh/dx)²⟩ = (kA)² (1 − √(1 − Q²))/Q²` (→ `(kA)²/2` as `Q → 0`), all of it along `d̂`.
    ///
    /// Derived from `dh/dx = −kA sin θ/(1 − Q cos θ)` and `dx ∝ (1 − Q cos θ) dθ`; with `Q = kA`
    /// it is the reference's (docs/equations.md) `1 − √(1 − Q²)`.
    ///
    /// # Returns
    /// The mean-square slope (dimensionless).
    ///
    /// # References
    /// docs/equations.md §1 ("mean-square slope") and §11 (trochoid slope variances).
    pub fn mean_square_slope(&self) -> f64 {
        let q = self.steepness;
        let ka2 = (self.wavenumber * self.amplitude).powi(2);
        if q < 1e-4 {
            // Series (1 − √(1 − Q²))/Q² = ½ + Q²/8 + …
            ka2 * (0.5 + q * q / 8.0)
        } else {
            ka2 * (1.0 - (1.0 - q * q).sqrt()) / (q * q)
        }
    }
}

impl Trochoid {
    /// Mean height of the profile over horizontal position, `⟨h⟩ = −Q A/2` (m): the trochoid spends
    /// longer in its troughs than on its crests (`dx ∝ (1 − Q cos θ) dθ`). With `Q = kA` it is the
    /// docs/equations.md's `−kA²/2`.
    ///
    /// # Returns
    /// The mean height (m) relative to the orbit centres `y₀ = 0`.
    ///
    /// # References
    /// docs/equations.md §1, "Exact single-trochoid statistics" (derived).
    pub fn mean_height(&self) -> f64 {
        -0.5 * self.steepness * self.amplitude
    }

    /// Variance of the height over horizontal position, `A² (2 − Q²)/4`; with `Q = kA` the
    /// docs/equations.md's `A² (2 − k²A²)/4`.
    ///
    /// # Returns
    /// The variance (m²).
    ///
    /// # References
    /// docs/equations.md §1 (derived).
    pub fn height_variance(&self) -> f64 {
        0.25 * self.amplitude * self.amplitude * (2.0 - self.steepness * self.steepness)
    }

    /// Height at which the slope is steepest, `Q·A` (where `cos θ = Q`).
    ///
    /// # Returns
    /// The height (m) above the orbit centres.
    ///
    /// # References
    /// docs/equations.md §1 ("max |slope| … reached where cos φ = Q").
    pub fn max_slope_height(&self) -> f64 {
        self.steepness * self.amplitude
    }

    /// A point of the profile in the wave's own frame at particle phase `θ`: `(s/k, A cos θ)` with
    /// `s = θ − Q sin θ`.
    ///
    /// # Arguments
    /// - `theta`: particle phase `θ` (rad), finite.
    ///
    /// # Returns
    /// `(position along d̂ (m), height (m))`.
    ///
    /// # References
    /// docs/equations.md §1 (the trochoid profile); Thon & Ghazanfarpour 2002.
    pub fn profile_point(&self, theta: f64) -> (f64, f64) {
        ((theta - self.steepness * theta.sin()) / self.wavenumber, self.amplitude * theta.cos())
    }
}

/// Solves Kepler's equation of the trochoid, `θ − Q sin θ = s`, for the particle phase `θ`.
///
/// A particle of phase `θ` sits at horizontal phase coordinate `s = θ − Q sin θ` (the horizontal
/// position times `k`), so the profile of one wave is `h(s) = A cos θ(s)`. The map is monotone
/// for `Q < 1`; `|θ − s| ≤ Q`. Newton's method from `θ₀ = s + Q sin s / (1 − Q cos s)`, safeguarded
/// by the bracket `[s − Q, s + Q]`, to `|Δθ| ≤ 10⁻¹³` (usually 2–4 iterations, at most 60).
///
/// # Arguments
/// - `s`: horizontal phase (rad), any finite value.
/// - `q`: steepness `Q`, `[0, 0.99]`.
///
/// # Returns
/// `(θ, cos θ, sin θ)`, with `θ − s` reduced to the principal branch (`θ` is within `Q` of `s`
/// reduced to `(−π, π]`).
///
/// # References
/// docs/equations.md §1 (`τ_Q(s) = cos θ` with `θ` solving `s = θ − Q sin θ`); Thon & Ghazanfarpour 2002.
#[inline]
pub fn solve_trochoid_phase(s: f64, q: f64) -> (f64, f64, f64) {
    debug_assert!((0.0..=MAX_STEEPNESS).contains(&q), "steepness {q} outside [0, 0.99]");
    // Reduce s to (−π, π]: the profile is 2π-periodic in s.
    let s = s - TAU * ((s + PI) / TAU).floor();
    let (ss, cs) = s.sin_cos();
    let mut theta = (s + q * ss / (1.0 - q * cs)).clamp(s - q, s + q);
    let (mut lo, mut hi) = (s - q, s + q);
    for _ in 0..60 {
        let (sn, cn) = theta.sin_cos();
        let f = theta - q * sn - s;
        if f == 0.0 {
            break;
        }
        if f > 0.0 {
            hi = theta;
        } else {
            lo = theta;
        }
        let step = f / (1.0 - q * cn);
        if step.abs() <= 1e-13 {
            theta -= step;
            break;
        }
        let next = theta - step;
        theta = if next > lo && next < hi { next } else { 0.5 * (lo + hi) };
    }
    let (sn, cn) = theta.sin_cos();
    (theta, cn, sn)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Kepler's equation after the solver's last Newton step (`|Δθ| ≤ 10⁻¹³`) and the reduction of
    /// `s` to `(−π, π]` (`|s| ≤ 20`: a few ulp).
    const KEPLER_ABS: f64 = 1e-12;

    /// The reference values are printed to 6 decimals (the accuracy asked of the fit is 10⁻⁶).
    const ORACLE_ABS: f64 = 1e-6;

    /// Exact fractions computed in a few operations.
    const ROUND_ABS: f64 = 1e-12;

    /// The midpoint rule on a smooth periodic function converges spectrally: with 20 000 cells
    /// only rounding remains (~10⁻¹³); 10⁻¹⁰ is loose.
    const PERIODIC_MIDPOINT_ABS: f64 = 1e-10;

    /// A grid of spacing `h = 2π/20 000` misses the exact maximum of the slope by `O(h²)`
    /// relative (~10⁻⁷ at `Q = 0.55`).
    const GRID_MAX_REL: f64 = 1e-6;

    #[test]
    fn phase_solution_satisfies_keplers_equation() {
        for &q in &[0.0, 0.3, 0.7, 0.95, 0.99] {
            for j in -50..=50 {
                let s = j as f64 * 0.37;
                let (theta, c, sn) = solve_trochoid_phase(s, q);
                let s_red = s - TAU * ((s + PI) / TAU).floor();
                assert!((theta - q * theta.sin() - s_red).abs() < KEPLER_ABS, "q = {q}, s = {s}");
                assert_eq!((c.to_bits(), sn.to_bits()), (theta.cos().to_bits(), theta.sin().to_bits()));
            }
        }
    }

    #[test]
    fn with_steepness_changes_the_steepness_alone_and_checks_it() {
        let w = Trochoid::new(0.5, 1.0, 0.3, 3.1, 0.7, 0.2).unwrap();
        assert_eq!(w.with_steepness(0.6).unwrap(), Trochoid::new(0.5, 1.0, 0.3, 3.1, 0.7, 0.6).unwrap());
        assert!(w.with_steepness(0.995).is_err() && w.with_steepness(-0.1).is_err());
    }

    #[test]
    fn slope_oracles() {
        // Reference values (docs/equations.md), k = 1, A = Q: the largest slope and the mean-square
        // slope, 0.577350 and 0.133975 at Q = 0.5, 1.333333 and 0.4 at Q = 0.8.
        for (q, max_slope, mss) in [(0.5, 0.577350, 0.133975), (0.8, 1.333333, 0.4)] {
            let w = Trochoid::new(q, 1.0, 0.0, 0.0, 0.0, q).unwrap();
            assert!((w.max_slope() - max_slope).abs() < ORACLE_ABS, "max slope at Q = {q}");
            assert!((w.mean_square_slope() - mss).abs() < ORACLE_ABS, "mean-square slope at Q = {q}");
        }
    }

    #[test]
    fn single_trochoid_statistics_oracle() {
        // Reference value (docs/equations.md): k = 1, A = 0.5 (Q = 0.5): max slope at y − y0 = 0.25 m, mean height
        // −0.125 m, height variance 0.109375 m².
        let w = Trochoid::new(0.5, 1.0, 0.0, 0.0, 0.0, 0.5).unwrap();
        assert!((w.max_slope_height() - 0.25).abs() < ROUND_ABS);
        assert!((w.mean_height() + 0.125).abs() < ROUND_ABS);
        assert!((w.height_variance() - 0.109375).abs() < ROUND_ABS);
    }

    #[test]
    fn statistics_match_a_quadrature_over_x() {
        // Sample the exact profile on a uniform x grid (not a θ grid) and average.
        let w = Trochoid::new(0.3, 2.0, 0.0, 0.0, 0.0, 0.55).unwrap();
        let n = 20_000;
        let (mut m1, mut m2, mut slope2, mut smax) = (0.0, 0.0, 0.0, 0.0f64);
        for j in 0..n {
            let s = -PI + TAU * (j as f64 + 0.5) / n as f64;
            let (_, c, sn) = solve_trochoid_phase(s, w.steepness());
            let h = w.amplitude() * c;
            let dh = -w.wavenumber() * w.amplitude() * sn / (1.0 - w.steepness() * c);
            m1 += h;
            m2 += h * h;
            slope2 += dh * dh;
            smax = smax.max(dh.abs());
        }
        let (m1, m2, slope2) = (m1 / n as f64, m2 / n as f64, slope2 / n as f64);
        assert!((m1 - w.mean_height()).abs() < PERIODIC_MIDPOINT_ABS);
        assert!((m2 - m1 * m1 - w.height_variance()).abs() < PERIODIC_MIDPOINT_ABS);
        assert!((slope2 - w.mean_square_slope()).abs() < PERIODIC_MIDPOINT_ABS);
        assert!(smax <= w.max_slope() && smax > w.max_slope() * (1.0 - GRID_MAX_REL));
    }

    #[test]
    fn invalid_parameters_are_named() {
        let e = Trochoid::new(1.0, 0.0, 0.0, 0.0, 0.0, 0.5).unwrap_err();
        assert!(e.to_string().contains("wavenumber_rad_m"), "{e}");
        let e = Trochoid::new(1.0, 1.0, 0.0, 0.0, 0.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("steepness"), "{e}");
    }

    /// Second differences of `h(x) = A cos θ(kx)` at `dx = 10⁻³ m` (k = 1): truncation
    /// `h⁗ dx²/12` and the grid's miss of the extremum stay below 10⁻³ of the bounds for
    /// `Q ≤ 0.9`; rounding `4·A·2⁻⁵²/dx²` is 10⁻¹⁰.
    const CURVATURE_FD_REL: f64 = 1e-3;

    /// `c(0) = 1/(1 + 0)²` is exact; 10⁻¹⁵ (about 4.5 ulps of 1) only allows for rounding.
    const EXACT_FACTOR_ABS: f64 = 1e-15;

    /// Just above `Q = 1/3` the other closed form applies; the branches meet there with the same
    /// slope (`c′(1/3)` = −0.84 on both), so across the offset 10⁻¹² the factor moves by
    /// 0.84×10⁻¹² plus rounding. 10⁻⁹ would catch a jump between the branches beyond that.
    const BRANCH_JOIN_ABS: f64 = 1e-9;

    /// The crest and trough curvature bounds are the extremes of `d²h/dx²`, found here by
    /// finite differences of heights from Kepler's equation over one wavelength.
    #[test]
    fn curvature_bounds_are_the_extremes_of_the_profiles_second_derivative() {
        for q in [0.0, 0.01, 0.2, 1.0 / 3.0, 0.5, 0.7, 0.9] {
            let w = Trochoid::new(0.5, 1.0, 0.0, 0.0, 0.0, q).unwrap();
            let h = |x: f64| 0.5 * solve_trochoid_phase(x, q).1;
            let dx = 1e-3;
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            let steps = (std::f64::consts::TAU / dx) as usize;
            for i in 0..steps {
                let x = -std::f64::consts::PI + i as f64 * dx;
                let second = (h(x + dx) - 2.0 * h(x) + h(x - dx)) / (dx * dx);
                lo = lo.min(second);
                hi = hi.max(second);
            }
            let (crest, trough) = (w.max_crest_curvature(), w.max_trough_curvature());
            assert!((-lo - crest).abs() <= CURVATURE_FD_REL * crest, "Q = {q}: crest {} vs {crest}", -lo);
            assert!((hi - trough).abs() <= CURVATURE_FD_REL * trough, "Q = {q}: trough {hi} vs {trough}");
            assert!(trough <= crest, "Q = {q}");
        }
        // Closed forms: Q = 0 is a cosine (both k²A); Q = 0.9 gives 4/(27·0.9·0.19²) against 100.
        assert!((trough_curvature_factor(0.0) - 1.0).abs() < EXACT_FACTOR_ABS);
        assert!((trough_curvature_factor(0.9) - 4.0 / (27.0 * 0.9 * 0.19 * 0.19)).abs() < ROUND_ABS);
        // Both branches meet at Q = 1/3: 1/(4/3)² = 4/(27·(1/3)·(8/9)²) = 9/16.
        assert!((trough_curvature_factor(1.0 / 3.0) - 9.0 / 16.0).abs() < ROUND_ABS);
        assert!((trough_curvature_factor(1.0 / 3.0 + 1e-12) - 9.0 / 16.0).abs() < BRANCH_JOIN_ABS);
    }
}
