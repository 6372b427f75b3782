//! Foam streaks along the wind: old foam gathered into lines (windrows), and the uniform noise
//! stretched along the wind that shapes both them and the foam memory's patches.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::FoamError;
use crate::noise::{FoamNoise, smoothstep};

/// Quantiles tabulated to make a stretched noise uniform (its empirical distribution function).
const QUANTILES: usize = 256;

/// Points the quantiles are estimated from (a few thousand first-octave cells).
pub(crate) const QUANTILE_SAMPLES: usize = 16_384;

/// A gradient-noise fBm read in coordinates stretched along the wind and mapped to a uniform
/// variable by its own empirical distribution function: `m = F(g((d̂·x)/σ, d̂⊥·x))`, `m ∈ [0, 1]`
/// with a uniform distribution over the sea (to sampling).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct StretchedUniform {
    along: [f64; 2],
    stretch: f64,
    noise: FoamNoise,
    cdf: EmpiricalCdf,
}

/// The empirical distribution function of a field's values, tabulated at [`QUANTILES`]
/// quantiles and read by linear interpolation: it maps the field to a variable uniform on
/// `[0, 1]` over the sea (to sampling).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct EmpiricalCdf {
    quantiles: Vec<f64>,
}

impl EmpiricalCdf {
    /// The distribution of `values` (any order; at least one).
    pub(crate) fn from_values(mut values: Vec<f64>) -> Self {
        values.sort_by(f64::total_cmp);
        let n = values.len();
        Self { quantiles: (0..=QUANTILES).map(|i| values[(i * (n - 1)) / QUANTILES]).collect() }
    }

    /// `F(g) ∈ [0, 1]`.
    pub(crate) fn uniform(&self, g: f64) -> f64 {
        let q = &self.quantiles;
        let i = q.partition_point(|&v| v < g);
        if i == 0 {
            return 0.0;
        }
        if i > QUANTILES {
            return 1.0;
        }
        let (lo, hi) = (q[i - 1], q[i]);
        let f = if hi > lo { (g - lo) / (hi - lo) } else { 0.5 };
        ((i - 1) as f64 + f) / QUANTILES as f64
    }
}

impl StretchedUniform {
    /// The noise `noise` stretched by `stretch` along the unit vector `along`, without its
    /// distribution yet ([`Self::tabulate`]).
    pub(crate) fn new(noise: FoamNoise, along: [f64; 2], stretch: f64) -> Self {
        Self { along, stretch, noise, cdf: EmpiricalCdf::default() }
    }

    /// The stretch along the wind.
    pub(crate) fn stretch(&self) -> f64 {
        self.stretch
    }

    /// Tabulates the distribution function from the values at `points`.
    pub(crate) fn tabulate(&mut self, points: &[(f64, f64)]) {
        self.cdf = EmpiricalCdf::from_values(points.iter().map(|&(x, z)| self.raw(x, z, 0.0)).collect());
    }

    /// Tabulates the distribution function from [`QUANTILE_SAMPLES`] points of a square of
    /// half-side `span_m` drawn from `seed`.
    pub(crate) fn tabulate_from_seed(&mut self, span_m: f64, seed: u64) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let points: Vec<(f64, f64)> = (0..QUANTILE_SAMPLES)
            .map(|_| (rng.random_range(-span_m..span_m), rng.random_range(-span_m..span_m)))
            .collect();
        self.tabulate(&points);
    }

    /// The noise `g − 1` at `(x, z)` in stretched coordinates, footprint-filtered.
    pub(crate) fn raw(&self, x: f64, z: f64, footprint_m: f64) -> f64 {
        let (a, c) = (self.along[0], self.along[1]);
        let (s, q) = ((x * a + z * c) / self.stretch, -x * c + z * a);
        // The footprint shrinks along the stretched axis too; take the across-wind one (the
        // shorter wavelength) so no octave aliases.
        self.noise.value(s, q, footprint_m) - 1.0
    }

    /// The uniform variable `m = F(g)` of a raw value `g` (empirical distribution function).
    pub(crate) fn uniform(&self, g: f64) -> f64 {
        self.cdf.uniform(g)
    }

    /// `m` at `(x, z)` for a footprint `ℓ` (m).
    pub(crate) fn at(&self, x: f64, z: f64, footprint_m: f64) -> f64 {
        self.uniform(self.raw(x, z, footprint_m))
    }

    /// `m` at `(x, z)` for a footprint `ℓ` (m), the filtered noise first scaled back to the full
    /// noise's variance (`g/√k`, `k` the kept share), so that `m` stays uniform at every footprint
    /// (to the octaves' being alike); `None` where the footprint keeps nothing.
    pub(crate) fn at_rescaled(&self, x: f64, z: f64, footprint_m: f64) -> Option<f64> {
        let k = self.resolved_share(footprint_m);
        (k > 0.0).then(|| self.uniform(self.raw(x, z, footprint_m) / k.sqrt()))
    }

    /// Share of the noise's variance a footprint `ℓ` (m) keeps, `[0, 1]`.
    pub(crate) fn resolved_share(&self, footprint_m: f64) -> f64 {
        self.noise.resolved_variance_share(footprint_m)
    }
}

/// Share of the mean white cover held in foam streaks along the wind at Beaufort 8 and above
/// (0 below Beaufort 6's upper end, a smoothstep between): Brine's choice. Foam a minute old or
/// more, out of reach of the crest that made it, is gathered by the wind-driven Langmuir
/// circulation into lines along the wind — the "well-marked streaks" of the Beaufort scale —
/// and counts toward the whitecap coverage of photographs as stage-B foam (Monahan & Lu 1990).
pub const WINDROW_SHARE: f64 = 0.3;

/// Spacing of the foam streaks across the wind (m): the first-octave wavelength of their noise.
/// Brine's choice at the small end of the metres-to-tens-of-metres spacings of Langmuir
/// windrows (Thorpe 2004).
pub const WINDROW_SPACING_M: f64 = 3.0;

/// Stretch of the foam streaks along the wind: their noise is this many times longer along the
/// wind than across (Brine's choice; the streaks of a gale run for tens of metres).
pub const WINDROW_STRETCH: f64 = 20.0;

/// Share of a streak's area its foam covers, `ρ`: a streak is a line of lace (the foam memory's
/// lace draws it as filaments), not a sheet (Brine's choice, as [`crate::FOAM_DENSITY`]). For a
/// mean cover `q > ρ²` it is `√q`, so that the streaks never fill the sea.
pub const WINDROW_DENSITY: f64 = 0.5;

/// Octaves of the streak noise.
const WINDROW_OCTAVES: u32 = 3;

/// Softness of a streak's edge: the step at `m = p` is smoothed over `p ± this · min(p, 1 − p)`,
/// which keeps the area mean exactly `p`.
const WINDROW_EDGE_SOFTNESS: f64 = 0.75;

/// Foam streaks along the wind: old foam gathered by the Langmuir circulation into lines
/// parallel to the wind.
///
/// The streaks cover `c(u) = ρ [(1 − r) H(p − m(u)) + r p]`, `p = q/ρ`, where `ρ` is the
/// [`WINDROW_DENSITY`] of the foam inside a streak, `m` a uniform noise carried by the water,
/// stretched [`WINDROW_STRETCH`] times along the wind with a first octave of
/// [`WINDROW_SPACING_M`] across it, `H` a step smoothed over `p ± ¾ min(p, 1 − p)`, `q` the mean
/// cover asked for and `r` the share of the noise the pixel footprint does not resolve (the
/// footprint-filtered noise is scaled back to full variance before it is made uniform): lines of
/// lace where the noise is lowest near the eye, their mean `q` far away, the area mean `q` at
/// every distance.
/// Their foam is old: its brightness relative to fresh foam is Koepke's life-mean efficiency.
///
/// The model is statistical: the streaks are not advected from the crests that made their foam
/// (that foam is older than the memory of [`crate::FoamMemory`]), and they do not move in rest
/// coordinates (Langmuir cells change over minutes, longer than the animations rendered).
///
/// # References
/// Langmuir I. 1938, "Surface motion of water induced by wind", Science 87:119–123; Thorpe S. A.
/// 2004, "Langmuir circulation", Annu. Rev. Fluid Mech. 36:55–79 (windrow spacing); Monahan E. C.,
/// Lu M. 1990, IEEE J. Oceanic Eng. 15(4):340–349 (stage-B foam); the Beaufort scale (WMO No. 8).
#[derive(Debug, Clone, PartialEq)]
pub struct Windrows {
    field: StretchedUniform,
    brightness: f64,
}

impl Windrows {
    /// Streaks along the unit vector `along` with their noise's first octave `spacing_m` (m)
    /// across the wind, stretched `stretch` along it, periodic over the cell vectors `period`
    /// when given (a tile), of brightness `brightness` relative to fresh foam.
    pub(crate) fn new(
        spacing_m: f64,
        stretch: f64,
        along: [f64; 2],
        period: Option<([i64; 2], [i64; 2])>,
        brightness: f64,
        seed: u64,
    ) -> Result<Self, FoamError> {
        let mut noise = FoamNoise::new(1.0, spacing_m, WINDROW_OCTAVES, seed ^ 0x3a1e_5eed)?;
        if let Some((p1, p2)) = period {
            noise = noise.periodic(p1, p2)?;
        }
        let mut field = StretchedUniform::new(noise, along, stretch);
        field.tabulate_from_seed(200.0 * spacing_m * stretch, seed ^ 0x71de_0a11);
        Ok(Self { field, brightness })
    }

    /// Cover of the streaks at rest position `(x, z)` for a pixel footprint `ℓ`, with area mean
    /// `mean_cover`.
    ///
    /// # Arguments
    /// - `x`, `z`: rest position (m), finite.
    /// - `footprint_m`: `ℓ` (m), `≥ 0`.
    /// - `mean_cover`: `q`, the area mean, `[0, 1)`.
    ///
    /// # Returns
    /// `c ∈ [0, 1]`.
    pub fn cover(&self, x: f64, z: f64, footprint_m: f64, mean_cover: f64) -> f64 {
        self.cover_with_density(x, z, footprint_m, mean_cover, WINDROW_DENSITY)
    }

    /// [`Self::cover`] with the density `ρ` of the foam inside a streak, `(0, 1]` (1: solid
    /// lines, for a pixel that resolves no lace; [`crate::FoamMemory::windrow_cover`] chooses).
    pub fn cover_with_density(&self, x: f64, z: f64, footprint_m: f64, mean_cover: f64, density: f64) -> f64 {
        debug_assert!(footprint_m >= 0.0 && (0.0..1.0).contains(&mean_cover) && density > 0.0 && density <= 1.0);
        if mean_cover <= 0.0 {
            return 0.0;
        }
        let Some(m) = self.field.at_rescaled(x, z, footprint_m) else { return mean_cover };
        let r = 1.0 - self.field.resolved_share(footprint_m);
        // The streaks cover `p = q/ρ` of the sea, their foam `ρ` of each streak.
        let density = density.max(mean_cover.sqrt());
        let p = mean_cover / density;
        let e = WINDROW_EDGE_SOFTNESS * p.min(1.0 - p);
        density * ((1.0 - r) * smoothstep(p + e, p - e, m) + r * p)
    }

    /// Brightness of the streaks' foam relative to fresh foam, `(0, 1]`.
    pub fn brightness(&self) -> f64 {
        self.brightness
    }

    /// The stretch along the wind (after any snapping to a tile).
    pub fn stretch(&self) -> f64 {
        self.field.stretch()
    }
}

#[cfg(test)]
mod tests {
    use crate::{FoamMemory, FoamMemoryParams, WhiteWater};

    /// Standard error of a cover of `q ≈ 0.02` measured on 40 000 points whose streak variable is
    /// correlated over about one first-octave cell (a few thousand independent cells across the
    /// sampled square): `√(q/3000) ≈ 0.0026`; the tolerance is three of them, relative to `q`.
    const MEAN_REL_TOL: f64 = 0.4;

    fn streaks(tile_m: Option<f64>) -> FoamMemory {
        let params = FoamMemoryParams { tile_m, ..FoamMemoryParams::for_wind(20.0, 0.4, 7) };
        FoamMemory::new(&params, 0.4).unwrap()
    }

    fn points() -> impl Iterator<Item = (f64, f64)> {
        (0..40_000).map(|i| {
            let f = f64::from(i);
            (3000.0 * (f * 0.618_034).fract() - 1500.0, 3000.0 * (f * 0.754_878).fract() - 1500.0)
        })
    }

    #[test]
    fn the_streaks_keep_their_mean_at_every_footprint() {
        let mem = streaks(None);
        let w = mem.windrows().expect("streaks at 20 m/s");
        let q = 0.02;
        for s in [0.0, 0.5, 2.0, 50.0] {
            let mean = points().map(|(x, z)| w.cover(x, z, s, q)).sum::<f64>() / 40_000.0;
            assert!((mean / q - 1.0).abs() < MEAN_REL_TOL, "footprint {s}: mean {mean}");
        }
        // Far away, nothing is resolved: every point sees the mean itself.
        let far = w.cover(12.3, -4.5, 1e4, q);
        assert!((far - q).abs() < 1e-12, "{far}");
    }

    #[test]
    fn the_streaks_lie_along_the_wind() {
        // P(streak at u + d | streak at u): along the wind against across, 1 m apart.
        let mem = streaks(None);
        let w = mem.windrows().unwrap();
        let (a, c) = (0.4f64.cos(), 0.4f64.sin());
        let q = 0.05;
        let (mut inside, mut along, mut across) = (0.0, 0.0, 0.0);
        for (x, z) in points() {
            // Inside a streak the cover is its density; half of it marks the streak.
            let half = 0.5 * super::WINDROW_DENSITY;
            if w.cover(x, z, 0.0, q) > half {
                inside += 1.0;
                along += f64::from(u8::from(w.cover(x + a, z + c, 0.0, q) > half));
                across += f64::from(u8::from(w.cover(x - c, z + a, 0.0, q) > half));
            }
        }
        assert!(inside > 500.0, "{inside}");
        assert!(along / inside > 0.8 && across / inside < 0.5, "along {along}, across {across} of {inside}");
    }

    #[test]
    fn streaks_repeat_over_a_tile() {
        let tile = 150.0;
        let mem = streaks(Some(tile));
        let w = mem.windrows().unwrap();
        for (x, z) in points().take(2000) {
            let c = w.cover(x, z, 0.0, 0.03);
            for (dx, dz) in [(tile, 0.0), (0.0, tile), (-tile, 2.0 * tile)] {
                // Whole turns of the gradient lattice: the same value to rounding.
                assert!((w.cover(x + dx, z + dz, 0.0, 0.03) - c).abs() < 1e-9, "({x}, {z}) + ({dx}, {dz})");
            }
        }
    }

    #[test]
    fn no_streaks_below_beaufort_6_and_a_bad_share_is_named() {
        let calm = FoamMemory::new(&FoamMemoryParams::for_wind(10.0, 0.0, 1), 0.4).unwrap();
        assert!(calm.windrows().is_none());
        let ww = WhiteWater { active: 0.1, residual: 0.2, white: 0.28, brightness: 0.7 };
        assert_eq!(calm.with_windrows(ww, 0.5), ww);
        let e = FoamMemory::new(&FoamMemoryParams { windrow_share: 1.0, ..FoamMemoryParams::default() }, 0.4)
            .unwrap_err()
            .to_string();
        assert!(e.contains("windrow_share"), "{e}");
    }

    proptest::proptest! {
        #[test]
        fn streaks_only_add_white(active in 0.0..=1.0f64, residual in 0.0..=1.0f64, b in 0.05..=1.0f64, c in 0.0..=1.0f64) {
            let mem = streaks(None);
            let white = 1.0 - (1.0 - active) * (1.0 - residual);
            let ww = WhiteWater { active, residual, white, brightness: b };
            let out = mem.with_windrows(ww, c);
            proptest::prop_assert!(out.white >= white - 1e-15 && out.white <= 1.0 + 1e-15);
            proptest::prop_assert!(out.residual >= residual - 1e-15 && out.residual <= 1.0 + 1e-15);
            proptest::prop_assert!((0.0..=1.0).contains(&out.brightness));
            // The white cover is still the union of the active cover and the residual.
            proptest::prop_assert!((out.white - (1.0 - (1.0 - active) * (1.0 - out.residual))).abs() < 1e-12);
            proptest::prop_assert_eq!(out.active.to_bits(), active.to_bits());
        }
    }
}
