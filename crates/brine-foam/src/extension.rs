//! The local foam amount of Darles et al. 2007 (Eq. 4, corrected): more foam on high, steep water.

use crate::error::{FoamError, check};
use crate::noise::FoamNoise;

/// Parameters of the foam extension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoamExtensionParams {
    /// Height exponent `n`, `[1, 20]`; Darles et al. found `n ∈ [6, 9]` most convincing.
    pub exponent: f64,
    /// Clamp of the normal length `‖N‖ = √(1 + |∇h|²)`, `[1, 10]`; `‖N‖` is unbounded on steep
    /// trochoid crests. The default 2 caps the slope term at 60° of slope.
    pub max_normal_norm: f64,
    /// Noise amplitude `a`, `[0, 1]`.
    pub noise_amplitude: f64,
    /// Wavelength of the first noise octave (m), `(0, 10⁴]`.
    pub noise_wavelength_m: f64,
    /// Number of noise octaves, `[1, 12]`.
    pub noise_octaves: u32,
    /// Seed of the noise lattice.
    pub seed: u64,
}

impl Default for FoamExtensionParams {
    fn default() -> Self {
        Self {
            exponent: 8.0,
            max_normal_norm: 2.0,
            noise_amplitude: 0.6,
            noise_wavelength_m: 12.0,
            noise_octaves: 5,
            seed: 1,
        }
    }
}

/// Height and slope statistics of the sea surface that normalise the foam extension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceStatistics {
    /// Lowest height of the surface `y_min` (m).
    pub y_min: f64,
    /// Highest height `y_max` (m), `> y_min`.
    pub y_max: f64,
    /// Standard deviation of the height about the mean level (m), `> 0`.
    pub height_std: f64,
    /// Mean-square slope along x, `⟨(∂h/∂x)²⟩`, `[0, 10]`.
    pub slope_variance_x: f64,
    /// Mean-square slope along z, `⟨(∂h/∂z)²⟩`, `[0, 10]`.
    pub slope_variance_z: f64,
}

/// The foam extension: local foam amount `s′` from height, slope and noise.
///
/// Darles et al. (2007, Eq. 4) make foam cling to crests and steep water by weighting the
/// whitecap coverage `W` of Eq. 3 with a height factor and the normal length. Corrected (equation
/// equations.md §5):
///
/// `w(p) = ((y − y_min)/(y_max − y_min))ⁿ · min(‖N‖, N_max)`, `‖N‖ = √(1 + |∇h|²)`,
/// `s′(p) = clamp(W · ν(p) · w(p)/⟨w⟩, 0, 1)`,
///
/// where `⟨w⟩` is the area mean of `w` (so the mean foam cover stays `W`) and `ν` the
/// footprint-filtered noise of [`FoamNoise`] (mean 1). `⟨w⟩` is computed once in the
/// constructor by quadrature, assuming Gaussian heights truncated to `[y_min, y_max]` and
/// Gaussian slopes independent of the height (true of linear waves, close for trochoid sums).
///
/// # References
/// Darles E., Crespin B., Ghazanfarpour D. 2007, "Accelerating and enhancing rendering of
/// realistic ocean scenes", WSCG, §4.1.1 Eq. 4; docs/equations.md §5 (the printed
/// `(y − y_min)/(y − y_max)` is ≤ 0, diverges at the crest, and `s′` is not normalised).
#[derive(Debug, Clone, PartialEq)]
pub struct FoamExtension {
    exponent: f64,
    max_normal_norm: f64,
    y_min: f64,
    inv_range: f64,
    mean_weight: f64,
    noise: FoamNoise,
}

impl FoamExtension {
    /// Checks the parameters and computes the area mean `⟨w⟩` of the foam weight.
    ///
    /// `⟨w⟩ = E[((y − y_min)/(y_max − y_min))ⁿ] · E[min(√(1 + |∇h|²), N_max)]`, heights
    /// `N(0, σ_h²)` truncated to `[y_min, y_max]` (Simpson, 2000 panels) and slopes
    /// `N(0, diag(σ_x², σ_z²))` independent of the height (midpoint quadrature).
    ///
    /// # Arguments
    /// - `params`: [`FoamExtensionParams`] — `exponent` `n` (`[1, 20]`), `max_normal_norm`
    ///   `N_max` (`[1, 10]`), the noise (`noise_amplitude` `[0, 1]`, `noise_wavelength_m` m
    ///   `(0, 10⁴]`, `noise_octaves` `[1, 12]`, `seed`).
    /// - `surface`: [`SurfaceStatistics`] — `y_min`, `y_max > y_min`, `height_std > 0` (m), slope
    ///   variances `[0, 10]` (dimensionless).
    ///
    /// # Returns
    /// The extension, with `⟨w⟩` (dimensionless, `> 0`) precomputed.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the first parameter outside its range.
    ///
    /// # References
    /// Darles et al. 2007 §4.1.1 Eq. 4; docs/equations.md §5 (`⟨w⟩` normalisation).
    pub fn new(params: &FoamExtensionParams, surface: &SurfaceStatistics) -> Result<Self, FoamError> {
        let n = check("exponent", params.exponent, (1.0..=20.0).contains(&params.exponent), "[1, 20]")?;
        let nmax = check(
            "max_normal_norm",
            params.max_normal_norm,
            (1.0..=10.0).contains(&params.max_normal_norm),
            "[1, 10]",
        )?;
        check("y_min_m", surface.y_min, true, "finite m")?;
        check("y_max_m", surface.y_max, surface.y_max > surface.y_min, "(y_min, ∞) m")?;
        check("height_std_m", surface.height_std, surface.height_std > 0.0, "(0, ∞) m")?;
        for (name, v) in
            [("slope_variance_x", surface.slope_variance_x), ("slope_variance_z", surface.slope_variance_z)]
        {
            check(name, v, (0.0..=10.0).contains(&v), "[0, 10]")?;
        }
        let noise =
            FoamNoise::new(params.noise_amplitude, params.noise_wavelength_m, params.noise_octaves, params.seed)?;
        let mean_weight = mean_height_factor(surface, n) * mean_normal_norm(surface, nmax);
        Ok(Self {
            exponent: n,
            max_normal_norm: nmax,
            y_min: surface.y_min,
            inv_range: 1.0 / (surface.y_max - surface.y_min),
            mean_weight,
            noise,
        })
    }

    /// `⟨w⟩`, the area mean of the weight (dimensionless).
    pub fn mean_weight(&self) -> f64 {
        self.mean_weight
    }

    /// The noise field.
    pub fn noise(&self) -> &FoamNoise {
        &self.noise
    }

    /// The unnormalised weight `w = ((y − y_min)/(y_max − y_min))ⁿ · min(√(1 + |∇h|²), N_max)`.
    ///
    /// # Arguments
    /// - `height`: surface height `y` (m); clamped to `[y_min, y_max]`.
    /// - `slope_x`, `slope_z`: `∂h/∂x`, `∂h/∂z` (dimensionless), finite.
    ///
    /// # Returns
    /// `w` (dimensionless), in `[0, N_max]`.
    ///
    /// # References
    /// Darles et al. 2007 Eq. 4, corrected in the docs/equations.md §5.
    pub fn weight(&self, height: f64, slope_x: f64, slope_z: f64) -> f64 {
        debug_assert!(height.is_finite() && slope_x.is_finite() && slope_z.is_finite());
        let t = ((height - self.y_min) * self.inv_range).clamp(0.0, 1.0);
        let norm = (1.0 + slope_x * slope_x + slope_z * slope_z).sqrt().min(self.max_normal_norm);
        libm::pow(t, self.exponent) * norm
    }

    /// Local foam amount `s′ = clamp(W ν w/⟨w⟩, 0, 1)` (Darles Eq. 4, corrected).
    ///
    /// # Arguments
    /// - `coverage`: whitecap coverage `W` of the sea (`[0, 1]`, from [`crate::whitecap_coverage`]).
    /// - `point`: the surface point, its slopes and footprint ([`FoamPoint`]).
    ///
    /// # Returns
    /// `s′`, the fraction of the pixel covered by foam, in `[0, 1]`.
    ///
    /// # References
    /// Darles et al. 2007 §4.1.1 Eq. 3–4; docs/equations.md §5.
    pub fn foam_amount(&self, coverage: f64, point: &FoamPoint) -> f64 {
        debug_assert!((0.0..=1.0).contains(&coverage));
        if coverage <= 0.0 {
            return 0.0;
        }
        let FoamPoint { height, slope: [slope_x, slope_z], rest: [rest_x, rest_z], footprint_m } = *point;
        let nu = self.noise.value(rest_x, rest_z, footprint_m);
        let s = coverage * nu * self.weight(height, slope_x, slope_z) / self.mean_weight;
        // Non-negative and finite by construction; Darles' clamp to 1 is the model (a pixel is at
        // most all foam), the one at 0 absorbs nothing.
        debug_assert!(s >= 0.0 && s.is_finite(), "s′ = {s}");
        s.clamp(0.0, 1.0)
    }
}

/// A point of the surface where [`FoamExtension::foam_amount`] is read.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FoamPoint {
    /// Surface height `y` (m), finite.
    pub height: f64,
    /// Surface gradient `(∂h/∂x, ∂h/∂z)` (dimensionless), finite.
    pub slope: [f64; 2],
    /// Undisplaced horizontal coordinates `(x, z)` (m) where the noise is read, so that the
    /// pattern moves with the water.
    pub rest: [f64; 2],
    /// Pixel footprint on the sea (m, `≥ 0`) that filters the noise.
    pub footprint_m: f64,
}

/// `E[((y − y_min)/(y_max − y_min))ⁿ]` for a Gaussian height `N(0, σ²)` truncated to
/// `[y_min, y_max]`, by Simpson's rule on 2000 panels.
fn mean_height_factor(s: &SurfaceStatistics, n: f64) -> f64 {
    let panels = 2000;
    let h = (s.y_max - s.y_min) / panels as f64;
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..=panels {
        let y = s.y_min + i as f64 * h;
        let c = if i == 0 || i == panels {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let density = c * libm::exp(-0.5 * (y / s.height_std).powi(2));
        num += density * libm::pow((y - s.y_min) / (s.y_max - s.y_min), n);
        den += density;
    }
    num / den
}

/// `E[min(√(1 + sx² + sz²), N_max)]` for independent Gaussian slopes, by the midpoint rule on a
/// 128 × 128 grid over ±6 standard deviations (a point mass at 0 when a variance is 0).
fn mean_normal_norm(s: &SurfaceStatistics, nmax: f64) -> f64 {
    let m = 128;
    let axis = |var: f64| -> Vec<(f64, f64)> {
        if var <= 0.0 {
            return vec![(0.0, 1.0)];
        }
        let sd = var.sqrt();
        let h = 12.0 * sd / m as f64;
        let pts: Vec<(f64, f64)> = (0..m)
            .map(|i| {
                let x = -6.0 * sd + (i as f64 + 0.5) * h;
                (x, libm::exp(-0.5 * (x / sd).powi(2)))
            })
            .collect();
        let total: f64 = pts.iter().map(|p| p.1).sum();
        pts.into_iter().map(|(x, w)| (x, w / total)).collect()
    };
    let (ax, az) = (axis(s.slope_variance_x), axis(s.slope_variance_z));
    let mut e = 0.0;
    for &(x, wx) in &ax {
        for &(z, wz) in &az {
            e += wx * wz * (1.0 + x * x + z * z).sqrt().min(nmax);
        }
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Midpoint rule on 400² points against the constructor's Simpson (2000 panels) and midpoint
    /// (128²) quadratures: each is converged to better than 10⁻⁴, so 10⁻³ leaves a margin.
    const QUADRATURE_REL: f64 = 1e-3;

    /// Smallest crest/trough ratio expected: the height factor alone gives
    /// `((1.5 + 2)/(−1.5 + 2))⁸ = 7⁸ ≈ 5.8×10⁶`; 100 only asks for a clear ordering.
    const CREST_OVER_TROUGH: f64 = 100.0;

    fn surface() -> SurfaceStatistics {
        SurfaceStatistics { y_min: -2.0, y_max: 2.0, height_std: 0.5, slope_variance_x: 0.02, slope_variance_z: 0.01 }
    }

    #[test]
    fn mean_foam_amount_is_the_coverage() {
        // Sample heights and slopes from the same distributions as the normalisation, on a
        // deterministic stratified grid, with the noise off: the area mean of s′ must be W.
        let p = FoamExtensionParams { noise_amplitude: 0.0, ..FoamExtensionParams::default() };
        // The z slope is held at 0, so normalise for that surface.
        let s = SurfaceStatistics { slope_variance_z: 0.0, ..surface() };
        let ext = FoamExtension::new(&p, &s).unwrap();
        let w = 0.01;
        let m = 400;
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..m {
            let y = s.y_min + (s.y_max - s.y_min) * (i as f64 + 0.5) / m as f64;
            let py = (-0.5 * (y / s.height_std).powi(2)).exp();
            for j in 0..m {
                // ±6 standard deviations of the x slope.
                let sx = s.slope_variance_x.sqrt() * (-6.0 + 12.0 * (j as f64 + 0.5) / m as f64);
                let px = (-0.5 * sx * sx / s.slope_variance_x).exp();
                num += py * px * ext.foam_amount(w, &FoamPoint { height: y, slope: [sx, 0.0], ..FoamPoint::default() });
                den += py * px;
            }
        }
        assert!((num / den / w - 1.0).abs() < QUADRATURE_REL, "{} vs {w}", num / den);
    }

    #[test]
    fn crest_has_more_foam_than_trough() {
        let ext = FoamExtension::new(&FoamExtensionParams::default(), &surface()).unwrap();
        let crest = ext
            .foam_amount(0.01, &FoamPoint { height: 1.5, slope: [0.2, 0.0], footprint_m: 1e3, ..FoamPoint::default() });
        let trough = ext.foam_amount(
            0.01,
            &FoamPoint { height: -1.5, slope: [0.2, 0.0], footprint_m: 1e3, ..FoamPoint::default() },
        );
        assert!(crest > CREST_OVER_TROUGH * trough, "{crest} vs {trough}");
    }

    #[test]
    fn bad_parameters_are_named() {
        let p = FoamExtensionParams { exponent: 0.0, ..FoamExtensionParams::default() };
        assert!(FoamExtension::new(&p, &surface()).unwrap_err().to_string().contains("exponent"));
        let s = SurfaceStatistics { y_max: -3.0, ..surface() };
        assert!(FoamExtension::new(&FoamExtensionParams::default(), &s).unwrap_err().to_string().contains("y_max_m"));
    }
}
