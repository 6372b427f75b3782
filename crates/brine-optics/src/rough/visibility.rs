//! Which facets a grazing viewer sees: the visibility of a facet given its slope, measured on
//! Gaussian profiles of the sea's short-wave spectrum, where Smith's function assumes it does not
//! depend on the slope.
//!
//! **Why.** Smith's masking function (Smith 1967) gives the share of the facets facing a viewer
//! that the viewer sees, `G₁ = 1/(1 + Λ)`, and takes it to be the same for every facing slope.
//! Its total is exact: over the facing facets, weighted by their projected area, the visible
//! share of any surface is `cot θ_v ⁄ E[(cot θ_v − ζ)⁺]`, which is `G₁` for Gaussian slopes. How
//! the visible facets are spread over the slopes is not: along a grazing ray, a facet that rises
//! steeply toward the viewer lifts the surface in front of it out of the ray's way, one that
//! barely faces the viewer lies in the shadow of the slope before it. Measured on Gaussian
//! profiles (below), at `ν = cot θ_v/σ = 0.1` a facet 2.5 σ steeper toward the viewer than the
//! grazing one is seen about 1.5 times as often as Smith says, one 0.3 σ from grazing a quarter as
//! often. The facets seen lean toward the viewer more than Smith says, meet the view less
//! obliquely and reflect less: for a sea of slope deviation 0.16 seen 1°–2° above the horizon,
//! the Fresnel reflectance averaged over the facets seen is 0.29 against Smith's 0.35.
//!
//! **The measurement.** A Gaussian profile `h(x)` of the saturation range's spectrum along the
//! view, `F(k) ∝ k⁻³` over four decades of wavenumber (the section of a `k⁻⁴` sea; Phillips
//! 1958, the short-wave range of Elfouhaily et al. 1997), 2²² points, four points per shortest
//! wave, four realisations; slopes in units of their deviation. A point is seen from a viewer
//! at `−∞` along rays descending at slope `ν` iff `g(x) = h(x) + νx` is not below any `g(x′)`,
//! `x′ < x` (the profile is periodic, so the earlier periods are `g − νL`). The table holds, for
//! each `ν` and each distance `s = (cot θ_v − ζ)/σ` of the slope from the grazing one, the
//! visible share of the facets of that slope over the projected-area mean `G₁`:
//! `r(ν, s) = P(seen | s) / G₁`, renormalised so that `∫ r(ν, s) s φ(s − ν) ds = ∫ s φ(s − ν) ds`
//! (the visible normals stay normalised).
//!
//! **Error model.** Two independent measurements (seeds 1–4 and 101–104) differ cell by cell by
//! up to 5 % where the facets weigh (`s φ(s − ν)` above a tenth of its peak) and 10 % in the
//! tail (a twentieth of the peak), under 1 % from `ν = 0.5`; the reflectances they give differ
//! by at most 0.4 % (`R_seen` at 88° and σ = 0.2: 0.2265 and 0.2273). A cell with fewer than 4000
//! facets holds the nearest better-sampled cell's value. The ratio depends on the spectrum's breadth: over three decades instead of
//! four the reflectance's change from Smith's is about 70 % as large, over two a quarter
//! (`docs/models/brine-optics.md`). The cross-view slope does not enter the visibility (a ray's
//! shadowing is decided along its vertical plane); the height correlation of the shadowing of
//! the reflected direction keeps Smith's form.

use std::sync::OnceLock;

/// The stored table, `data/slope_visibility.csv`: `nu, s, r` by rows of `ν`.
const STORED: &str = include_str!("../../data/slope_visibility.csv");

/// The visibility of a facet given its slope, relative to Smith's (see the module's notes):
/// `r(ν, s)`, with `ν = cot θ_v/σ` and `s = (cot θ_v − ζ)/σ`, `ζ` the facet's slope away from the
/// viewer along the view's azimuth and `σ` the slope deviation along it.
///
/// Grid: `ν = 8 (j/32)²`, `j = 0…32` (dense near grazing; `r = 1` from `ν = 8`, where every facing
/// facet is seen); `s = 0.1 i`, `i = 0…70`; bilinear, clamped at the ends.
#[derive(Debug, Clone, PartialEq)]
pub struct SlopeVisibility {
    /// `r[j·S + i]` at `ν_j`, `s_i`.
    r: Vec<f64>,
}

impl SlopeVisibility {
    /// Steps of `w = √(ν/ν_max)`.
    pub(crate) const NU_STEPS: usize = 33;
    /// Largest tabulated `ν` (the table's last row is 1).
    pub const NU_MAX: f64 = 8.0;
    /// Steps of `s`.
    pub(crate) const S_STEPS: usize = 71;
    /// Spacing of `s`.
    pub(crate) const S_STEP: f64 = 0.1;

    /// The stored table (parsed once).
    ///
    /// # Returns
    /// The table measured on Gaussian profiles (see the module's notes).
    pub fn stored() -> &'static Self {
        static TABLE: OnceLock<SlopeVisibility> = OnceLock::new();
        TABLE.get_or_init(|| {
            let r: Vec<f64> = STORED
                .lines()
                .filter(|l| !l.is_empty() && !l.starts_with('#'))
                .skip(1)
                // The file is part of the crate and a test reads every entry: never user input.
                .map(|l| l.rsplit(',').next().and_then(|f| f.parse().ok()).expect("stored visibility value"))
                .collect();
            debug_assert_eq!(r.len(), Self::NU_STEPS * Self::S_STEPS);
            Self { r }
        })
    }

    /// A table from its values, `r[j·S + i]` (for the measurement that makes it).
    #[cfg(test)]
    pub(crate) fn from_values(r: Vec<f64>) -> Self {
        assert_eq!(r.len(), Self::NU_STEPS * Self::S_STEPS);
        Self { r }
    }

    /// The values, `r[j·S + i]`.
    #[cfg(test)]
    pub(crate) fn values(&self) -> &[f64] {
        &self.r
    }

    /// `ν` of row `j`.
    #[cfg(test)]
    pub(crate) fn nu_at(j: usize) -> f64 {
        let w = j as f64 / (Self::NU_STEPS - 1) as f64;
        Self::NU_MAX * w * w
    }

    /// `r(ν, s)`: how much more (`> 1`) or less often than Smith's `G₁` a facing facet at slope
    /// distance `s` from the grazing one is seen at `ν`.
    ///
    /// # Arguments
    /// - `nu`: `ν = cot θ_v/σ` (dimensionless), `≥ 0`; 1 is returned from [`Self::NU_MAX`].
    /// - `s`: `(cot θ_v − ζ)/σ` (dimensionless), `≥ 0` (facing facets); clamped to the grid.
    ///
    /// # Returns
    /// `r ≥ 0` (dimensionless).
    ///
    /// # References
    /// Smith B.G. 1967, IEEE Trans. Antennas Propag. 15(5) (the uncorrelated form this corrects);
    /// the measurement in the module's notes.
    pub fn ratio(&self, nu: f64, s: f64) -> f64 {
        if !(nu < Self::NU_MAX) {
            return 1.0;
        }
        let w = (nu.max(0.0) / Self::NU_MAX).sqrt() * (Self::NU_STEPS - 1) as f64;
        let u = (s.max(0.0) / Self::S_STEP).min((Self::S_STEPS - 1) as f64);
        let (j, i) = ((w as usize).min(Self::NU_STEPS - 2), (u as usize).min(Self::S_STEPS - 2));
        let (fw, fu) = (w - j as f64, u - i as f64);
        let at = |j: usize, i: usize| self.r[j * Self::S_STEPS + i];
        let low = at(j, i) * (1.0 - fu) + at(j, i + 1) * fu;
        let high = at(j + 1, i) * (1.0 - fu) + at(j + 1, i + 1) * fu;
        low * (1.0 - fw) + high * fw
    }
}

#[cfg(test)]
pub(crate) mod measurement {
    //! The Monte-Carlo measurement the stored table comes from.

    use super::SlopeVisibility;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;
    use rustfft::FftPlanner;
    use rustfft::num_complex::Complex;

    /// Points per profile.
    const POINTS: usize = 1 << 22;
    /// Ratio of the shortest wave's wavenumber to the longest's.
    const BREADTH: f64 = 1e4;
    /// Realisations pooled.
    const REALISATIONS: u64 = 4;
    /// Fewest facets (in linear-interpolation weight) for a cell's ratio to be kept.
    const MIN_FACETS: f64 = 4000.0;

    /// A Gaussian profile of `F(k) ∝ k⁻³` on `[k₀, BREADTH·k₀]`: heights and slopes, slopes in
    /// units of their deviation, and the point spacing in the same units.
    fn profile(seed: u64) -> (Vec<f64>, Vec<f64>, f64) {
        let n = POINTS;
        // Four points per shortest wave; k₀ = 1.
        let k_max = BREADTH;
        let dx = std::f64::consts::PI / (2.0 * k_max);
        let dk = std::f64::consts::TAU / (n as f64 * dx);
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut height = vec![Complex::new(0.0, 0.0); n];
        let mut slope = vec![Complex::new(0.0, 0.0); n];
        for j in 1..n / 2 {
            let k = j as f64 * dk;
            // Box–Muller: two standard normal deviates.
            let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
            let radius = (-2.0 * u1.ln()).sqrt();
            let (g1, g2) = (radius * (std::f64::consts::TAU * u2).cos(), radius * (std::f64::consts::TAU * u2).sin());
            if !(1.0..=k_max).contains(&k) {
                continue;
            }
            let a = (k.powi(-3) * dk / 2.0).sqrt();
            let c = Complex::new(a * g1, a * g2);
            height[j] = c;
            height[n - j] = c.conj();
            slope[j] = Complex::new(0.0, k) * c;
            slope[n - j] = slope[j].conj();
        }
        let mut planner = FftPlanner::new();
        let fft = planner.plan_fft_inverse(n);
        fft.process(&mut height);
        fft.process(&mut slope);
        let h: Vec<f64> = height.iter().map(|c| c.re).collect();
        let z: Vec<f64> = slope.iter().map(|c| c.re).collect();
        let deviation = (z.iter().map(|v| v * v).sum::<f64>() / n as f64).sqrt();
        (h.iter().map(|v| v / deviation).collect(), z.iter().map(|v| v / deviation).collect(), dx)
    }

    /// The table measured on [`REALISATIONS`] profiles (see the module's notes).
    pub(crate) fn measure() -> SlopeVisibility {
        let (nu_steps, s_steps) = (SlopeVisibility::NU_STEPS, SlopeVisibility::S_STEPS);
        let mut facing = vec![0.0; nu_steps * s_steps];
        let mut seen = vec![0.0; nu_steps * s_steps];
        let mut area = vec![(0.0, 0.0); nu_steps];
        for seed in 1..=REALISATIONS {
            let (h, z, dx) = profile(seed);
            let period = h.len() as f64 * dx;
            for j in 1..nu_steps - 1 {
                let nu = SlopeVisibility::nu_at(j);
                // The periods before this one: `g − νL`.
                let mut highest =
                    h.iter().enumerate().map(|(i, hi)| hi + nu * i as f64 * dx).fold(f64::MIN, f64::max) - nu * period;
                for (i, (hi, zi)) in h.iter().zip(&z).enumerate() {
                    let g = hi + nu * i as f64 * dx;
                    let visible = g >= highest;
                    highest = highest.max(g);
                    let s = zi + nu;
                    if s <= 0.0 {
                        continue;
                    }
                    let v = f64::from(u8::from(visible));
                    area[j].0 += s;
                    area[j].1 += s * v;
                    let u = (s / SlopeVisibility::S_STEP).min((s_steps - 1) as f64);
                    let c = (u as usize).min(s_steps - 2);
                    let f = u - c as f64;
                    for (cell, weight) in [(c, 1.0 - f), (c + 1, f)] {
                        facing[j * s_steps + cell] += weight;
                        seen[j * s_steps + cell] += weight * v;
                    }
                }
            }
        }
        let mut r = vec![1.0; nu_steps * s_steps];
        for j in 1..nu_steps - 1 {
            let g1 = area[j].1 / area[j].0;
            let row = &mut r[j * s_steps..(j + 1) * s_steps];
            let sampled: Vec<Option<f64>> = (0..s_steps)
                .map(|i| {
                    let n = facing[j * s_steps + i];
                    (n >= MIN_FACETS).then(|| seen[j * s_steps + i] / n / g1)
                })
                .collect();
            for i in 0..s_steps {
                // Hold the nearest well-sampled cell's value where a cell is thin.
                row[i] = sampled[i]
                    .or_else(|| {
                        (1..s_steps).find_map(|d| {
                            let below = i.checked_sub(d).and_then(|k| sampled[k]);
                            let above = sampled.get(i + d).copied().flatten();
                            below.or(above)
                        })
                    })
                    .unwrap_or(1.0);
            }
        }
        // Grazing (ν = 0) takes the first measured row.
        let first: Vec<f64> = r[s_steps..2 * s_steps].to_vec();
        r[..s_steps].copy_from_slice(&first);
        let mut table = SlopeVisibility::from_values(r);
        renormalise(&mut table);
        table
    }

    /// Scales each row so that `∫ r(ν, s) s φ(s − ν) ds = ∫ s φ(s − ν) ds` with the table's own
    /// interpolation (Simpson over `[0, 14]`, 2800 steps).
    fn renormalise(table: &mut SlopeVisibility) {
        let s_steps = SlopeVisibility::S_STEPS;
        let mut r = table.values().to_vec();
        for j in 0..SlopeVisibility::NU_STEPS - 1 {
            let nu = SlopeVisibility::nu_at(j);
            let (with, without) = weighted_means(table, nu);
            for v in &mut r[j * s_steps..(j + 1) * s_steps] {
                *v *= without / with;
            }
        }
        *table = SlopeVisibility::from_values(r);
    }

    /// `(∫ r s φ(s − ν) ds, ∫ s φ(s − ν) ds)` over `s ∈ [0, 14]` (Simpson, 2800 steps).
    pub(crate) fn weighted_means(table: &SlopeVisibility, nu: f64) -> (f64, f64) {
        let steps = 2800;
        let h = 14.0 / steps as f64;
        let (mut with, mut without) = (0.0, 0.0);
        for i in 0..=steps {
            let s = i as f64 * h;
            let w = if i == 0 || i == steps {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            let phi = (-0.5 * (s - nu) * (s - nu)).exp();
            with += w * table.ratio(nu, s) * s * phi;
            without += w * s * phi;
        }
        (with, without)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The text of `data/slope_visibility.csv`.
    fn source(table: &SlopeVisibility) -> String {
        let mut text = String::from(
            "# The visibility of a facing facet given its slope, over Smith's G1 (brine-optics SlopeVisibility):\n\
             # measured on Gaussian profiles of F(k) ~ k^-3 over four decades (2^22 points, 4 realisations).\n\
             # nu = cot(theta_v)/sigma = 8 (j/32)^2; s = (cot(theta_v) - zeta)/sigma = 0.1 i.\n\
             # Generated: BRINE_BLESS=1 cargo test -p brine-optics the_stored_visibility_is_the_measurement; do not edit.\n\
             nu,s,r\n",
        );
        for j in 0..SlopeVisibility::NU_STEPS {
            for i in 0..SlopeVisibility::S_STEPS {
                let r = table.r[j * SlopeVisibility::S_STEPS + i];
                text.push_str(&format!(
                    "{:?},{:?},{:.6}\n",
                    SlopeVisibility::nu_at(j),
                    i as f64 * SlopeVisibility::S_STEP,
                    r
                ));
            }
        }
        text
    }

    /// The stored table is the measurement's (to the platform's rounding of the FFT and of the
    /// six stored digits). With `BRINE_BLESS=1` the test writes it instead.
    #[test]
    fn the_stored_visibility_is_the_measurement() {
        let fresh = measurement::measure();
        if std::env::var_os("BRINE_BLESS").is_some() {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/slope_visibility.csv");
            std::fs::write(&path, source(&fresh)).unwrap();
            return;
        }
        // Six printed digits; a platform's FFT rounding can flip a point's visibility where two
        // heights tie, one point in 10⁶ of a cell's facets.
        const STORED_DIGITS: f64 = 1e-4;
        let stored = SlopeVisibility::stored();
        for (k, (a, b)) in stored.r.iter().zip(&fresh.r).enumerate() {
            assert!((a - b).abs() <= STORED_DIGITS * b.max(1.0), "cell {k}: stored {a}, measured {b}");
        }
    }

    /// The visible normals stay normalised: each row's projected-area mean of `r` is 1, also
    /// half-way between rows, where the interpolation in `ν` is not renormalised.
    #[test]
    fn the_ratio_keeps_the_visible_share() {
        // Linear interpolation between rows whose means are 1; the rows' shapes differ little
        // between neighbours.
        const BETWEEN_ROWS: f64 = 2e-3;
        // The rows are renormalised exactly, then stored to six digits.
        const STORED_DIGITS: f64 = 1e-5;
        let t = SlopeVisibility::stored();
        for j in 0..SlopeVisibility::NU_STEPS - 1 {
            let (a, b) = measurement::weighted_means(t, SlopeVisibility::nu_at(j));
            assert!((a / b - 1.0).abs() < STORED_DIGITS, "row {j}: {}", a / b);
            let mid = 0.5 * (SlopeVisibility::nu_at(j) + SlopeVisibility::nu_at(j + 1));
            let (a, b) = measurement::weighted_means(t, mid);
            assert!((a / b - 1.0).abs() < BETWEEN_ROWS, "ν {mid}: {}", a / b);
        }
    }

    /// What the measurement shows, against Smith's uncorrelated form (`r = 1`): near grazing the
    /// facets steep toward the viewer are seen more often, those barely facing it less; far from
    /// grazing (`ν ≥ 2`) every facet that faces the viewer well is seen as Smith says.
    #[test]
    fn steep_facets_are_seen_more_often_at_grazing_views() {
        let t = SlopeVisibility::stored();
        for nu in [0.03, 0.1, 0.3] {
            assert!(t.ratio(nu, 0.3 + nu) < 0.8, "ν {nu}: barely facing {}", t.ratio(nu, 0.3 + nu));
            assert!(t.ratio(nu, 2.5 + nu) > 1.2, "ν {nu}: steep {}", t.ratio(nu, 2.5 + nu));
        }
        // Increasing in s where the facets weigh, at every measured ν.
        for j in 1..SlopeVisibility::NU_STEPS - 1 {
            let nu = SlopeVisibility::nu_at(j);
            let (a, b) = (t.ratio(nu, nu.max(0.2)), t.ratio(nu, nu + 1.5));
            assert!(a <= b + 0.02, "ν {nu}: r({}) = {a} > r({}) = {b}", nu.max(0.2), nu + 1.5);
        }
        for s in [2.5, 3.0, 4.0, 5.0] {
            assert!((t.ratio(2.0, s) - 1.0).abs() < 0.05, "ν 2, s {s}: {}", t.ratio(2.0, s));
        }
        assert!((t.ratio(SlopeVisibility::NU_MAX, 0.5) - 1.0).abs() < 1e-15);
    }
}
