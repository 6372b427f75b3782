//! The sky dome prefiltered by angular Gaussians of growing width: the environment a rough sea
//! reflects, looked up once per pixel with the width of the reflection lobe.

use glam::{DVec3, Vec3};
use rayon::prelude::*;

/// Angular standard deviation of the finest level (rad): 1°, about two texels of the finest map,
/// so that its bilinear lookup is itself smooth at that scale.
pub const FILTERED_SKY_BASE_SIGMA: f64 = 0.0175;

/// Number of levels: widths `σ₀ 2^l`, `l = 0 … 6`, from 1° to 64° (the reflection lobe of a
/// storm sea at grazing view is about ±30°).
pub const FILTERED_SKY_LEVELS: usize = 7;

/// One level: the upper hemisphere on an azimuth × elevation grid, linear sRGB in f32.
#[derive(Debug, Clone)]
struct Level {
    width: usize,
    height: usize,
    texels: Vec<Vec3>,
}

/// The grid position of a direction: azimuth `φ = atan2(z, x)` over `[0, 1)` and elevation
/// `e ∈ [0, π/2]` over `[0, 1]` (directions below the horizon take the horizon's row).
fn grid_of(d: DVec3) -> (f64, f64) {
    let phi = d.z.atan2(d.x);
    let u = (phi / std::f64::consts::TAU).rem_euclid(1.0);
    let e = d.y.clamp(0.0, 1.0).asin();
    (u, e / std::f64::consts::FRAC_PI_2)
}

/// The direction of grid position `(u, v)`.
fn direction_of(u: f64, v: f64) -> DVec3 {
    let phi = u * std::f64::consts::TAU;
    let e = v * std::f64::consts::FRAC_PI_2;
    DVec3::new(e.cos() * phi.cos(), e.sin(), e.cos() * phi.sin())
}

impl Level {
    /// Bilinear lookup, wrapping in azimuth, clamped in elevation.
    fn lookup(&self, d: DVec3) -> DVec3 {
        let (u, v) = grid_of(d);
        let x = u * self.width as f64 - 0.5;
        let y = v * (self.height - 1) as f64;
        let (x0, y0) = (x.floor(), y.floor().min((self.height - 2) as f64));
        let (fx, fy) = (x - x0, (y - y0).clamp(0.0, 1.0));
        let i0 = (x0 as i64).rem_euclid(self.width as i64) as usize;
        let i1 = (i0 + 1) % self.width;
        let j0 = y0 as usize;
        let at = |i: usize, j: usize| self.texels[j * self.width + i].as_dvec3();
        let row = |j: usize| at(i0, j) * (1.0 - fx) + at(i1, j) * fx;
        row(j0) * (1.0 - fy) + row(j0 + 1) * fy
    }
}

/// Offsets `(a, b, weight)` of a two-dimensional Gaussian of unit standard deviation: the centre
/// and two rings of eight at radii 1 and 2 (the second turned by π/8), each point weighted by the
/// Gaussian at its radius times the area it stands for (a disc of radius ½, annuli
/// `[½, 1½]` and `[1½, 2½]` shared by eight), normalised to 1. The rule's own variance is scaled
/// out by [`ring_scale`].
fn kernel() -> Vec<(f64, f64, f64)> {
    let quarter_disc = std::f64::consts::PI / 4.0;
    let mut k = vec![(0.0, 0.0, quarter_disc)];
    for (r, turn) in [(1.0f64, 0.0), (2.0f64, std::f64::consts::PI / 8.0)] {
        let w = (-0.5 * r * r).exp() * std::f64::consts::TAU * r / 8.0;
        for s in 0..8 {
            let a = f64::from(s) * std::f64::consts::TAU / 8.0 + turn;
            k.push((r * a.cos(), r * a.sin(), w));
        }
    }
    let total: f64 = k.iter().map(|x| x.2).sum();
    k.iter().map(|&(a, b, w)| (a, b, w / total)).collect()
}

/// The factor that gives [`kernel`] a unit standard deviation per axis.
fn ring_scale(k: &[(f64, f64, f64)]) -> f64 {
    let var: f64 = k.iter().map(|&(a, b, w)| w * (a * a + b * b) / 2.0).sum();
    1.0 / var.sqrt()
}

/// The sky dome, clouds included, prefiltered by angular Gaussians of standard deviation
/// `σ_l = σ₀ 2^l` ([`FILTERED_SKY_BASE_SIGMA`], [`FILTERED_SKY_LEVELS`]), for the reflection of a
/// rough sea: the environment weighted by the distribution of the reflected directions, looked
/// up once per pixel at the mirror direction with the lobe's width (Bruneton, Neyret & Holzschuch
/// 2010 §5.2: a mip-mapped sky map sampled with a footprint given by the slope variance; the
/// Dupuy–Bruneton demo filters the sky the same way).
///
/// Level 0 samples the sky on an azimuth × elevation grid of the upper hemisphere and filters it
/// to `σ₀`; each next level convolves the previous one with a Gaussian of standard deviation
/// `√3 σ_l` (variances add: `σ_l² + 3σ_l² = (2σ_l)²`) by a 17-point rule on the tangent plane, on
/// a grid half as fine. [`FilteredSky::radiance`] interpolates between levels in `log₂ σ` and,
/// below `σ₀`, between the exact sky and level 0, so that a calm sea is a mirror. The filters are
/// normalised: a uniform sky is returned unchanged at every width, so the filtered sky carries
/// the energy of the sky it filters.
///
/// Directions below the horizon see the horizon (the renderer's convention for reflections that
/// would enter the sea); the filters average over the upper hemisphere only (renormalised), so a
/// lobe centred on the horizon sees the sky just above it, not the horizon's colour stretched
/// down.
#[derive(Debug, Clone)]
pub struct FilteredSky {
    levels: Vec<Level>,
}

impl FilteredSky {
    /// Prefilters the sky `radiance` (linear sRGB, a function of the unit direction, y up) on a
    /// grid of `width × height` texels at level 0 (azimuth × elevation; `width ≥ 16`,
    /// `height ≥ 4`), built in parallel.
    ///
    /// # Arguments
    /// - `width`, `height`: level-0 grid (texels); 512 × 128 gives 0.7° texels.
    /// - `radiance`: the sky to filter (kcd m⁻² or any linear unit), finite and `≥ 0`.
    ///
    /// # Returns
    /// The filtered sky.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 §5.2.
    pub fn new(width: usize, height: usize, radiance: impl Fn(DVec3) -> DVec3 + Sync) -> Self {
        let (width, height) = (width.max(16), height.max(4));
        let k = kernel();
        let scale = ring_scale(&k);
        // The exact sky on a grid twice as fine, then filtered to σ₀ into level 0.
        let fine =
            Level { width: 2 * width, height: 2 * height - 1, texels: vec![Vec3::ZERO; 2 * width * (2 * height - 1)] };
        let mut fine = fine;
        let w = fine.width;
        fine.texels.par_chunks_mut(w).enumerate().for_each(|(j, row)| {
            for (i, t) in row.iter_mut().enumerate() {
                let d = direction_of((i as f64 + 0.5) / w as f64, j as f64 / (2 * height - 2) as f64);
                *t = radiance(d).as_vec3();
            }
        });
        let mut levels = vec![blur(&fine, width, height, FILTERED_SKY_BASE_SIGMA, &k, scale)];
        for l in 1..FILTERED_SKY_LEVELS {
            let prev = &levels[l - 1];
            let sigma = FILTERED_SKY_BASE_SIGMA * f64::from(1u32 << (l - 1)) * 3f64.sqrt();
            let (w, h) = ((prev.width / 2).max(16), (prev.height / 2).max(4));
            let next = blur(prev, w, h, sigma, &k, scale);
            levels.push(next);
        }
        Self { levels }
    }

    /// The sky seen through an angular Gaussian of standard deviation `sigma` (rad) around `d`.
    ///
    /// # Arguments
    /// - `d`: unit direction (below the horizon: the horizon).
    /// - `sigma`: width of the filter (rad), `≥ 0`; 0 gives `exact(d)`.
    /// - `exact`: the unfiltered sky, used below `σ₀`.
    ///
    /// # Returns
    /// The filtered radiance (unit of the sky given to [`FilteredSky::new`]).
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 §5.2 (the mip-mapped sky lookup).
    pub fn radiance(&self, d: DVec3, sigma: f64, exact: impl FnOnce(DVec3) -> DVec3) -> DVec3 {
        let s0 = FILTERED_SKY_BASE_SIGMA;
        if !(sigma > 0.5 * s0) {
            return exact(d);
        }
        if sigma < s0 {
            let w = (sigma - 0.5 * s0) / (0.5 * s0);
            return exact(d) * (1.0 - w) + self.levels[0].lookup(d) * w;
        }
        let x = (sigma / s0).log2().min((self.levels.len() - 1) as f64);
        let l = (x.floor() as usize).min(self.levels.len() - 2);
        let f = (x - l as f64).clamp(0.0, 1.0);
        self.levels[l].lookup(d) * (1.0 - f) + self.levels[l + 1].lookup(d) * f
    }
}

/// `src` convolved with an angular Gaussian of standard deviation `sigma` (rad), on a grid of
/// `width × height`: each texel averages `src` at the kernel's points on its tangent plane.
fn blur(src: &Level, width: usize, height: usize, sigma: f64, k: &[(f64, f64, f64)], scale: f64) -> Level {
    let mut out = Level { width, height, texels: vec![Vec3::ZERO; width * height] };
    let texel_dir = |i: usize, j: usize| direction_of((i as f64 + 0.5) / width as f64, j as f64 / (height - 1) as f64);
    out.texels.par_chunks_mut(width).enumerate().for_each(|(j, row)| {
        for (i, t) in row.iter_mut().enumerate() {
            let c = texel_dir(i, j);
            // Tangent frame: east-like and north-like unit vectors (at the zenith, any pair).
            let a = if c.y > 0.999_999 { DVec3::X } else { DVec3::Y.cross(c).normalize() };
            let b = c.cross(a);
            // Kernel points below the horizon are left out and the rest renormalised: the part
            // of a lobe that points into the sea sees the sky the rest of the lobe sees, rather
            // than the horizon's colour stretched down.
            let (mut sum, mut total) = (DVec3::ZERO, 0.0);
            for &(x, y, w) in k {
                let d = (c + (x * a + y * b) * (sigma * scale)).normalize();
                if d.y >= 0.0 {
                    sum += w * src.lookup(d);
                    total += w;
                }
            }
            *t = (sum / total).as_vec3();
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f32 texels and a normalised kernel: a uniform sky comes back to f32 rounding.
    const F32_ROUNDING: f64 = 1e-5;
    /// Four composed 17-point blurs on grids halved each time against the exact Gaussian of the
    /// same width: the rule's truncation at 2.5σ and the coarse grids' bilinear lookups.
    const COMPOSED_BLURS: f64 = 0.15;

    #[test]
    fn a_uniform_sky_is_unchanged_at_every_width() {
        let sky = FilteredSky::new(64, 16, |_| DVec3::new(1.0, 2.0, 3.0));
        for sigma in [0.0, 0.01, 0.02, 0.1, 0.5, 2.0] {
            for d in [DVec3::X, DVec3::Y, DVec3::new(0.3, 0.1, -0.9).normalize(), DVec3::new(0.0, -1.0, 0.0)] {
                let l = sky.radiance(d, sigma, |_| DVec3::new(1.0, 2.0, 3.0));
                assert!((l - DVec3::new(1.0, 2.0, 3.0)).abs().max_element() < F32_ROUNDING * 3.0, "{sigma} {d}: {l}");
            }
        }
    }

    #[test]
    fn a_calm_sea_is_a_mirror_and_wider_lobes_blur_more() {
        // A sky bright in a 10° cap around the zenith, dark elsewhere.
        let cap = |d: DVec3| if d.y > 10f64.to_radians().cos() { DVec3::ONE } else { DVec3::ZERO };
        let sky = FilteredSky::new(256, 64, cap);
        let edge = direction_of(0.0, (80.0 - 0.5) / 90.0);
        // σ = 0: the exact sky.
        assert_eq!(sky.radiance(edge, 0.0, cap), cap(edge));
        // Inside the cap the value falls, 10° outside it rises, as the lobe widens to 0.2 rad
        // (wider lobes spread the cap so far that the value 10° out falls again).
        let inside = DVec3::Y;
        let outside = direction_of(0.0, 70.0 / 90.0);
        let mut last = (2.0, -1.0);
        for sigma in [0.02, 0.05, 0.1, 0.2] {
            let (a, b) = (sky.radiance(inside, sigma, cap).x, sky.radiance(outside, sigma, cap).x);
            assert!(a < last.0 + 1e-6 && b > last.1 - 1e-6, "σ = {sigma}: {a}, {b} after {last:?}");
            last = (a, b);
        }
        // The share of a 10° cap (θ = 0.1745 rad) seen at its centre through the Gaussian of
        // level 4 (σ = 16σ₀ = 0.28 rad): 1 − e^{−θ²/2σ²} = 0.177 for small angles.
        let sigma = 16.0 * FILTERED_SKY_BASE_SIGMA;
        let want = 1.0 - (-(0.1745f64.powi(2)) / (2.0 * sigma * sigma)).exp();
        let got = sky.radiance(inside, sigma, cap).x;
        assert!((got - want).abs() < COMPOSED_BLURS * want, "{got} vs {want}");
    }
}
