//! The reflectance of the rough sea toward a viewer: how much of the sky the unresolved facets
//! reflect, and how much of their reflection meets the neighbouring waves instead.

mod two_scale;
mod visibility;
mod visible_normals;

pub use two_scale::{TwoScaleFacet, drawn_escape};
pub use visibility::SlopeVisibility;
pub use visible_normals::{
    ReflectanceSplit, reflectance_split, reflectance_split_uncorrelated, water_reflectance_split,
};

use crate::error::{OpticsError, check};
use crate::{WATER_IOR, fresnel_dielectric};

/// Sea water's table, `data/rough_reflectance_water.csv`: `σ, cos θ_v, R, R_seen, μ_r` by rows of
/// `σ`.
const WATER_TABLE: &str = include_str!("../../data/rough_reflectance_water.csv");

/// The reflectance of the rough sea toward a viewer for a uniform sky, split by where the
/// reflected light comes from ([`reflectance_split`], over the visible normals with the
/// measured slope visibility of [`crate::SlopeVisibility`]):
///
/// - `R(θ_v, σ_v)`: from the sky, reflected above the horizon and not shadowed by another facet
///   (Smith's height-correlated masking–shadowing, with the measured escape of the facets seen);
/// - `R_seen(θ_v, σ_v)`: the Fresnel reflectance of the facets the viewer sees, wherever their
///   mirror directions go; `R_seen − R` comes from the waves those directions meet;
/// - `μ_r(θ_v, σ_v)`: the mean cosine of the seen facets' mirror directions to the mean normal.
///
/// Tabulated over `cos θ_v` and the slope deviation `σ_v` along the view's azimuth (isotropic
/// slopes of that deviation, as Bruneton et al.'s `F̄(v)`), for a renderer that looks the sky up
/// once near the mirror direction of the resolved normal and weights it by the rough surface's
/// reflectance instead of the smooth Fresnel factor: at grazing views the unresolved facets hide
/// part of the mirror image and reflect the rest from other directions, so the distant sea
/// reflects less sky than a mirror (`R = 0.22` and `R_seen = 0.26` instead of `F = 0.80` at 88°
/// for `σ² = 0.03`; Smith's forms, without the measured visibility and escape, give 0.30 and 0.32), and the sky it
/// reflects lies above the mirror direction (there by 20°).
///
/// Grid: `cos θ_v = u²`, `u` in 65 uniform steps on `[0, 1]` (dense at grazing); `σ_v = 0.6 w²`,
/// `w` in 41 uniform steps on `[0, 1]` (dense on calm water, where `R` leaves the Fresnel value
/// fast; `σ² ≤ 0.36`, beyond any wind sea); bilinear in `(u, w)`, clamped at the ends. Each
/// entry is [`reflectance_split`]'s integral (about 10⁴ facets, within 10⁻³ of a brute-force sum):
/// [`Self::water`] reads the table of sea water's index precomputed in the crate, [`Self::new`]
/// integrates one for another index (about 1 s).
#[derive(Debug, Clone, PartialEq)]
pub struct RoughReflectance {
    n_water: f64,
    /// `sky[j·U + i]`: `R` at `u_i`, `σ_j`.
    sky: Vec<f64>,
    /// `seen[j·U + i]`: `R_seen` at `u_i`, `σ_j`.
    seen: Vec<f64>,
    /// `mirror_cosine[j·U + i]`: `μ_r` at `u_i`, `σ_j`.
    mirror_cosine: Vec<f64>,
}

impl RoughReflectance {
    /// Steps of `u = √cos θ_v`.
    const U: usize = 65;
    /// Steps of `w = √(σ_v/0.6)`.
    const S: usize = 41;
    /// Largest tabulated slope deviation.
    pub const MAX_SIGMA: f64 = 0.6;

    /// The table for water of index `n_water`, integrated here (about 2.7×10⁷ facet evaluations,
    /// about 1 s; [`Self::water`] reads the one of [`WATER_IOR`] precomputed).
    ///
    /// # Arguments
    /// - `n_water`: index of water, `(1, 2]`.
    ///
    /// # Returns
    /// The table.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming `n_water`.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, Eq. 7–8 (the integrand) and §5.2 (`F̄(v)`, the role the
    /// table plays); Heitz 2014 (the visible normals); docs/equations.md §11.
    pub fn new(n_water: f64) -> Result<Self, OpticsError> {
        check("n_water", n_water, n_water > 1.0 && n_water <= 2.0, "(1, 2]")?;
        let mut sky = Vec::with_capacity(Self::U * Self::S);
        let mut seen = Vec::with_capacity(Self::U * Self::S);
        let mut mirror_cosine = Vec::with_capacity(Self::U * Self::S);
        for j in 0..Self::S {
            let w = j as f64 / (Self::S - 1) as f64;
            let sigma = Self::MAX_SIGMA * w * w;
            for i in 0..Self::U {
                let u = i as f64 / (Self::U - 1) as f64;
                let c = u * u;
                let split = if c <= 0.0 {
                    ReflectanceSplit { to_sky: 0.0, seen: 0.0, mirror_cosine: 0.0 }
                } else if sigma <= 0.0 {
                    // Calm water: the mirror, where both parts are Fresnel's.
                    let f = fresnel_dielectric(c, 1.0, n_water);
                    ReflectanceSplit { to_sky: f, seen: f, mirror_cosine: c }
                } else {
                    water_reflectance_split(c, sigma, n_water)
                };
                sky.push(split.to_sky);
                seen.push(split.seen);
                mirror_cosine.push(split.mirror_cosine);
            }
        }
        Ok(Self { n_water, sky, seen, mirror_cosine })
    }

    /// The table of sea water ([`WATER_IOR`]), precomputed by [`Self::new`] and stored in the
    /// crate (a test checks every entry against the integral).
    ///
    /// # Returns
    /// The table.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn water() -> Self {
        let mut sky = Vec::with_capacity(Self::U * Self::S);
        let mut seen = Vec::with_capacity(Self::U * Self::S);
        let mut mirror_cosine = Vec::with_capacity(Self::U * Self::S);
        for line in WATER_TABLE.lines().filter(|l| !l.is_empty() && !l.starts_with('#')).skip(1) {
            // The file is part of the crate and a test reads every entry: never user input.
            let mut fields = line.split(',').skip(2).map(|f| f.parse::<f64>().expect("stored table value"));
            sky.push(fields.next().expect("R"));
            seen.push(fields.next().expect("R_seen"));
            mirror_cosine.push(fields.next().expect("mu_r"));
        }
        debug_assert_eq!(sky.len(), Self::U * Self::S);
        Self { n_water: WATER_IOR, sky, seen, mirror_cosine }
    }

    /// Index of water the table was made for.
    pub fn n_water(&self) -> f64 {
        self.n_water
    }

    /// `R(θ_v, σ_v)`: the sky's share, bilinear in the table.
    ///
    /// # Arguments
    /// - `cos_theta_v`: `cos θ_v` to the mean (resolved) normal, `[0, 1]` (clamped).
    /// - `sigma_v`: slope deviation of the unresolved waves along the view's azimuth, `≥ 0`
    ///   (clamped to [`Self::MAX_SIGMA`]).
    ///
    /// # Returns
    /// `R` (dimensionless), in `[0, 1]`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn reflectance(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        Self::lookup(&self.sky, cos_theta_v, sigma_v)
    }

    /// `R_seen(θ_v, σ_v)`: the Fresnel reflectance of the visible facets, wherever they reflect,
    /// bilinear in the table.
    ///
    /// # Arguments
    /// As [`Self::reflectance`].
    ///
    /// # Returns
    /// `R_seen` (dimensionless), in `[0, 1]`, `≥ R` up to the interpolation's rounding.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn seen_reflectance(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        Self::lookup(&self.seen, cos_theta_v, sigma_v)
    }

    /// `μ_r(θ_v, σ_v)`: the mean cosine of the visible facets' mirror directions to the mean normal,
    /// weighted as `R_seen` ([`ReflectanceSplit::mirror_cosine`]), bilinear in the table: where a
    /// renderer that looks the sky up once through the reflection lobe should centre the lobe,
    /// at the mirror direction's azimuth (at grazing views well above the mirror direction of the
    /// mean normal, `cos θ_v`).
    ///
    /// # Arguments
    /// As [`Self::reflectance`].
    ///
    /// # Returns
    /// `μ_r` (dimensionless), in `[−1, 1]`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn mirror_cosine(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        Self::lookup(&self.mirror_cosine, cos_theta_v, sigma_v)
    }

    /// The rough surface's sky reflectance relative to the smooth one's at the same angle,
    /// `R(θ_v, σ_v)/R(θ_v, 0)`: the factor that turns the exact Fresnel reflectance of the resolved
    /// facet into the reflectance of the rough surface around it (1 at `σ_v = 0`).
    ///
    /// # Arguments
    /// As [`Self::reflectance`].
    ///
    /// # Returns
    /// The ratio (dimensionless), `≥ 0`; 1 where `R(θ_v, 0) = 0`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn roughness_factor(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        let smooth = self.reflectance(cos_theta_v, 0.0);
        if smooth > 0.0 { self.reflectance(cos_theta_v, sigma_v) / smooth } else { 1.0 }
    }

    /// The light the facets reflect into the neighbouring waves relative to the smooth
    /// reflectance, `(R_seen − R)/R(θ_v, 0)` (0 at `σ_v = 0`): with [`Self::roughness_factor`],
    /// what the rough surface reflects in all, so that none of it is counted as transmitted.
    ///
    /// # Arguments
    /// As [`Self::reflectance`].
    ///
    /// # Returns
    /// The ratio (dimensionless), `≥ 0`; 0 where `R(θ_v, 0) = 0`.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn met_factor(&self, cos_theta_v: f64, sigma_v: f64) -> f64 {
        let smooth = self.reflectance(cos_theta_v, 0.0);
        if smooth > 0.0 {
            (self.seen_reflectance(cos_theta_v, sigma_v) - self.reflectance(cos_theta_v, sigma_v)).max(0.0) / smooth
        } else {
            0.0
        }
    }

    /// Bilinear lookup of `table` at `(√cos θ_v, √(σ_v/0.6))`, clamped to `[0, 1]`.
    fn lookup(table: &[f64], cos_theta_v: f64, sigma_v: f64) -> f64 {
        let u = cos_theta_v.clamp(0.0, 1.0).sqrt() * (Self::U - 1) as f64;
        let s = (sigma_v.max(0.0) / Self::MAX_SIGMA).min(1.0).sqrt() * (Self::S - 1) as f64;
        let (i, j) = ((u as usize).min(Self::U - 2), (s as usize).min(Self::S - 2));
        let (fu, fs) = (u - i as f64, s - j as f64);
        let at = |i: usize, j: usize| table[j * Self::U + i];
        let low = at(i, j) * (1.0 - fu) + at(i + 1, j) * fu;
        let high = at(i, j + 1) * (1.0 - fu) + at(i + 1, j + 1) * fu;
        (low * (1.0 - fs) + high * fs).clamp(0.0, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The text of `data/rough_reflectance_water.csv`: one row per node, each `f64` written to
    /// round-trip exactly.
    fn source(sky: &[f64], seen: &[f64], mirror_cosine: &[f64]) -> String {
        let mut text = String::from(
            "# The rough reflectance of sea water (index 1.333) toward a viewer, split between the sky (R)\n\
             # and the visible facets in all (R_seen), with the mean cosine of their mirror directions to\n\
             # the mean normal (mirror_cosine): brine-optics RoughReflectance::new(1.333), Bruneton et al. 2010\n\
             # Eq. 7-8 over the visible normals (Heitz 2014) seen with the measured slope visibility and\n\
             # reflection escape (SlopeVisibility, data/slope_visibility.csv). Nodes: sigma = 0.6 w^2, w = j/40;\n\
             # cos_theta = u^2, u = i/64. Generated: BRINE_BLESS=1 cargo test -p brine-optics\n\
             # the_stored_table_is_the_integral; do not edit.\n\
             sigma,cos_theta,sky,seen,mirror_cosine\n",
        );
        for j in 0..RoughReflectance::S {
            let w = j as f64 / (RoughReflectance::S - 1) as f64;
            for i in 0..RoughReflectance::U {
                let u = i as f64 / (RoughReflectance::U - 1) as f64;
                let k = j * RoughReflectance::U + i;
                text.push_str(&format!(
                    "{:?},{:?},{:?},{:?},{:?}\n",
                    RoughReflectance::MAX_SIGMA * w * w,
                    u * u,
                    sky[k],
                    seen[k],
                    mirror_cosine[k]
                ));
            }
        }
        text
    }

    /// The stored table is [`RoughReflectance::new`]'s for sea water, entry by entry. With
    /// `BRINE_BLESS=1` the test writes it (`data/rough_reflectance_water.csv`) instead.
    #[test]
    fn the_stored_table_is_the_integral() {
        let fresh = RoughReflectance::new(WATER_IOR).unwrap();
        if std::env::var_os("BRINE_BLESS").is_some() {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/rough_reflectance_water.csv");
            std::fs::write(&path, source(&fresh.sky, &fresh.seen, &fresh.mirror_cosine)).unwrap();
            return;
        }
        // The same arithmetic in the same order; the margin allows a platform's last-bit
        // differences in `exp` and `erfc`.
        const PLATFORM_ROUNDING: f64 = 1e-12;
        let stored = RoughReflectance::water();
        let pairs = stored.sky.iter().zip(&fresh.sky).chain(stored.seen.iter().zip(&fresh.seen));
        for (k, (a, b)) in pairs.chain(stored.mirror_cosine.iter().zip(&fresh.mirror_cosine)).enumerate() {
            assert!((a - b).abs() <= PLATFORM_ROUNDING, "entry {k}: stored {a}, integral {b}");
        }
    }

    /// The table against the integral it samples, half-way between its nodes, and its limits.
    #[test]
    fn the_table_interpolates_the_integral() {
        // Bilinear error half-way between nodes, measured: 0.012 up to 82° (at σ ≈ 0.04, where R
        // leaves the Fresnel value fastest), 0.03 beyond. The last grazing steps (θ > 89.4°) are
        // only checked for bounds.
        const BILINEAR: f64 = 0.013;
        const BILINEAR_GRAZING: f64 = 0.03;
        let t = RoughReflectance::water();
        for j in (0..40).step_by(3) {
            let w = (j as f64 + 0.5) / 40.0;
            let sigma = 0.6 * w * w;
            for i in (6..64).step_by(2) {
                let u = (i as f64 + 0.5) / 64.0;
                let c = u * u;
                let direct = water_reflectance_split(c, sigma, WATER_IOR);
                let tolerance = if c >= 0.14 { BILINEAR } else { BILINEAR_GRAZING };
                let got = t.reflectance(c, sigma);
                assert!((got - direct.to_sky).abs() < tolerance, "cos θ {c}, σ {sigma}: {got} vs {}", direct.to_sky);
                let got = t.seen_reflectance(c, sigma);
                assert!((got - direct.seen).abs() < tolerance, "cos θ {c}, σ {sigma}: {got} vs {}", direct.seen);
            }
        }
        // Smooth water: the Fresnel reflectance; the factors are 1 and 0 there.
        // (cos θ = 0.25 is a node: u = ½.)
        assert_relative_eq!(t.reflectance(0.25, 0.0), fresnel_dielectric(0.25, 1.0, WATER_IOR), max_relative = 1e-12);
        assert_relative_eq!(t.roughness_factor(0.3, 0.0), 1.0, max_relative = 1e-12);
        assert!(t.met_factor(0.3, 0.0).abs() < 1e-12);
        // Each entry a reflectance, the sky's share at most the whole.
        for (k, (sky, seen)) in t.sky.iter().zip(&t.seen).enumerate() {
            assert!((0.0..=1.0).contains(sky) && (0.0..=1.0).contains(seen), "entry {k}: {sky}, {seen}");
            assert!(sky <= seen, "entry {k}: R {sky} > R_seen {seen}");
        }
    }
}
