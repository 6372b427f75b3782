//! Footprint-filtered gradient noise that breaks the regularity of the foam pattern.

use brine_core::lattice_floor;
use rand::SeedableRng;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

use crate::error::{FoamError, check};

/// Largest `|n(x, z)|` of 2-D gradient noise with unit gradients is `√2/2`; dividing by it maps
/// each octave into `[−1, 1]`.
const PERLIN_2D_BOUND: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// Rounding of a noise value (a few flops of order one) past its bound.
const NOISE_ROUNDING: f64 = 1e-12;

/// `1/`[`PERLIN_2D_BOUND`]: a product instead of a division in every octave.
const PERLIN_2D_SCALE: f64 = 1.0 / PERLIN_2D_BOUND;

/// Gradient-noise fractal ("fBm") over the horizontal plane, filtered by the pixel footprint.
///
/// `ν(x, z; ℓ) = 1 + a · Σₒ fₒ(ℓ) wₒ nₒ(x/λₒ, z/λₒ)`, with Perlin gradient noise `nₒ ∈ [−1, 1]`
/// (zero mean), octave wavelengths `λₒ = λ₀/2ᵒ`, weights `wₒ = 2⁻ᵒ/Σ 2⁻ᵒ` and the footprint fade
/// `fₒ(ℓ) = smoothstep(1, 1.5, λₒ/ℓ)`: an octave whose wavelength is not at least 1.5 pixel
/// footprints `ℓ` is faded to its mean 0 instead of aliasing (the antialiasing rule of Darles et
/// al. §3.2 and of Bruneton et al. 2010). Hence `ν ∈ [1 − a, 1 + a]` and its area mean is 1, so
/// multiplying the foam amount by `ν` keeps the mean coverage.
///
/// The lattice permutation is shuffled by ChaCha8 from the seed: same seed, same noise on every
/// platform.
///
/// # References
/// Perlin K. 2002, "Improving noise", SIGGRAPH (gradient noise and quintic fade); Darles et al.
/// 2007 §4.1 ("a noise function is added, filtered according to the distance to the viewer").
#[derive(Debug, Clone, PartialEq)]
pub struct FoamNoise {
    perm: [u8; 512],
    amplitude: f64,
    wavelength: f64,
    octaves: u32,
    weight_sum: f64,
    /// The lattice of periods in first-octave cells, when the noise repeats ([`FoamNoise::periodic`]).
    period: Option<CellPeriod>,
}

/// A lattice of periods `{k₁(a, b) + k₂(0, c)}` of the noise in first-octave cell indices (the
/// Hermite normal form of two period vectors): cell `(i, j)` and its translates are hashed alike.
#[derive(Debug, Clone, Copy, PartialEq)]
struct CellPeriod {
    a: i64,
    b: i64,
    c: i64,
    /// `1/(2ᵒa)` and `1/(2ᵒc)` of each octave `o`, for [`div_rem_euclid`].
    inverses: [(f64, f64); FoamNoise::MAX_OCTAVES as usize],
    /// Each octave's offset `(s, −s)`, `s = 17.31 o` cells, moved by a period of the octave into
    /// `[0, 2ᵒa) × [0, 2ᵒc)`: the same noise, and a point reduced by [`Self::reduce_point`]
    /// then lands within one period of the canonical cells.
    shifts: [(f64, f64); FoamNoise::MAX_OCTAVES as usize],
}

impl CellPeriod {
    /// The Hermite normal form of the lattice spanned by `p1`, `p2` (integer, independent).
    fn new(p1: [i64; 2], p2: [i64; 2]) -> Option<Self> {
        let det = p1[0] * p2[1] - p1[1] * p2[0];
        if det == 0 {
            return None;
        }
        // g = gcd(p1x, p2x) = s p1x + t p2x (extended Euclid); v = s p1 + t p2 = (g, b).
        let (mut r0, mut r1, mut s0, mut s1, mut t0, mut t1) = (p1[0], p2[0], 1i64, 0i64, 0i64, 1i64);
        while r1 != 0 {
            let q = r0.div_euclid(r1);
            (r0, r1) = (r1, r0 - q * r1);
            (s0, s1) = (s1, s0 - q * s1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        let (g, s, t) = if r0 < 0 { (-r0, -s0, -t0) } else { (r0, s0, t0) };
        let c = det.abs() / g;
        let inverses = std::array::from_fn(|o| (1.0 / (g << o) as f64, 1.0 / (c << o) as f64));
        let mut period = Self {
            a: g,
            b: (s * p1[1] + t * p2[1]).rem_euclid(c),
            c,
            inverses,
            shifts: [(0.0, 0.0); FoamNoise::MAX_OCTAVES as usize],
        };
        for o in 0..FoamNoise::MAX_OCTAVES {
            let shift = octave_shift(o);
            period.shifts[o as usize] = period.reduce_point(shift, -shift, o);
        }
        Some(period)
    }

    /// The point `(x, z)` (octave-`o` cells) moved by a period of octave `o` into
    /// `[0, 2ᵒa) × [0, 2ᵒc)`.
    fn reduce_point(&self, x: f64, z: f64, o: u32) -> (f64, f64) {
        let (a, b, c) = ((self.a << o) as f64, (self.b << o) as f64, (self.c << o) as f64);
        let (inv_a, inv_c) = self.inverses[o as usize];
        let k = lattice_floor(x * inv_a);
        let (x, z) = (x - k * a, z - k * b);
        // The product's rounding can leave the point a period out: one step back.
        let (x, z) = if x < 0.0 {
            (x + a, z + b)
        } else if x >= a {
            (x - a, z - b)
        } else {
            (x, z)
        };
        let z = z - lattice_floor(z * inv_c) * c;
        let z = if z < 0.0 {
            z + c
        } else if z >= c {
            z - c
        } else {
            z
        };
        (x.clamp(0.0, a), z.clamp(0.0, c))
    }

    /// The canonical representative of cell `(i, j)` at octave `o` (periods scaled by `2ᵒ`).
    fn reduce(&self, i: i64, j: i64, o: u32) -> (i64, i64) {
        let (a, b, c) = (self.a << o, self.b << o, self.c << o);
        let (inv_a, inv_c) = self.inverses[o as usize];
        // A reduced point's cells are within a period of the canonical ones: no division then.
        let (k, i) = match i {
            _ if (0..a).contains(&i) => (0, i),
            _ if (a..2 * a).contains(&i) => (1, i - a),
            _ => div_rem_euclid(i, a, inv_a),
        };
        let j = j - k * b;
        let j = match j {
            _ if (0..c).contains(&j) => j,
            _ if (c..2 * c).contains(&j) => j - c,
            _ if (-c..0).contains(&j) => j + c,
            _ => div_rem_euclid(j, c, inv_c).1,
        };
        (i, j)
    }

    /// [`Self::reduce`] of `(i₀ + di, j₀ + dj)` for a reduced `(i₀, j₀)` and `di, dj ∈ {0, 1}`:
    /// at most one period to take off each coordinate, no division.
    #[inline]
    fn step(&self, i0: i64, j0: i64, di: i64, dj: i64, o: u32) -> (i64, i64) {
        let (a, b, c) = (self.a << o, self.b << o, self.c << o);
        let (mut i, mut j) = (i0 + di, j0 + dj);
        if i >= a {
            i -= a;
            j -= b;
        }
        // `j₀ ∈ [0, c)` and `b ∈ [0, c)`, so `j ∈ (−c, c]`: one period at most, no division.
        if j < 0 {
            j += c;
        } else if j >= c {
            j -= c;
        }
        (i, j)
    }
}

/// `(⌊x/m⌋, x − m⌊x/m⌋)` for `m > 0` and `|x| < 2⁵⁰`, given `inv_m ≈ 1/m`: `div_euclid` and
/// `rem_euclid` by a float product corrected by one step (an integer division costs several times
/// more, and the periodic noise makes two per octave). `x·inv_m` is within `|x|·2⁻⁵¹ < ½` of
/// `x/m`, so its floor is off by one at most.
#[inline]
fn div_rem_euclid(x: i64, m: i64, inv_m: f64) -> (i64, i64) {
    debug_assert!(m > 0);
    let mut q = lattice_floor(x as f64 * inv_m) as i64;
    let mut r = x - q * m;
    if r < 0 {
        r += m;
        q -= 1;
    } else if r >= m {
        r -= m;
        q += 1;
    }
    (q, r)
}

impl FoamNoise {
    /// Largest number of octaves.
    pub const MAX_OCTAVES: u32 = 12;

    /// A noise field.
    ///
    /// # Arguments
    /// - `amplitude`: `a`, `[0, 1]` (0 disables the noise).
    /// - `wavelength_m`: `λ₀` of the first octave (m), `(0, 10⁴]`.
    /// - `octaves`: number of octaves, `[1, 12]`.
    /// - `seed`: seed of the lattice.
    ///
    /// # Returns
    /// The noise field `ν`, with values in `[1 − a, 1 + a]`.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the parameter.
    ///
    /// # References
    /// Perlin 2002 (gradient noise); Darles et al. 2007 §4.1 (filtered noise).
    pub fn new(amplitude: f64, wavelength_m: f64, octaves: u32, seed: u64) -> Result<Self, FoamError> {
        check("noise_amplitude", amplitude, (0.0..=1.0).contains(&amplitude), "[0, 1]")?;
        check("noise_wavelength_m", wavelength_m, wavelength_m > 0.0 && wavelength_m <= 1e4, "(0, 10000] m")?;
        check("noise_octaves", f64::from(octaves), (1..=Self::MAX_OCTAVES).contains(&octaves), "[1, 12]")?;
        let mut table: Vec<u8> = (0..=255).collect();
        table.shuffle(&mut ChaCha8Rng::seed_from_u64(seed));
        let mut perm = [0u8; 512];
        for (i, p) in perm.iter_mut().enumerate() {
            *p = table[i & 255];
        }
        let weight_sum = OCTAVE_SCALE[..octaves as usize].iter().sum();
        Ok(Self { perm, amplitude, wavelength: wavelength_m, octaves, weight_sum, period: None })
    }

    /// The same noise made periodic: its values repeat under the translations `p1`, `p2`, given
    /// in first-octave cells (`λ₀` units of the coordinates `value` is called with). Every octave
    /// repeats with them (its cells are `2ᵒ` times smaller). The distribution of the values is
    /// unchanged (the same gradients, hashed on a torus).
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] if `p1` and `p2` are parallel (no torus).
    pub fn periodic(mut self, p1: [i64; 2], p2: [i64; 2]) -> Result<Self, FoamError> {
        self.period = Some(CellPeriod::new(p1, p2).ok_or(FoamError::OutOfRange(brine_core::OutOfRange {
            name: "noise_period",
            value: 0.0,
            range: "two independent integer period vectors",
        }))?);
        Ok(self)
    }

    /// Noise amplitude `a`.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// The multiplicative noise `ν(x, z; ℓ)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite; use the undisplaced (rest) coordinates so the
    ///   pattern moves with the water.
    /// - `footprint_m`: pixel footprint `ℓ` on the sea (m), `[0, ∞)`; 0 keeps every octave.
    ///
    /// # Returns
    /// `ν` (dimensionless), in `[1 − a, 1 + a]`.
    ///
    /// # References
    /// Perlin 2002; Darles et al. 2007 §4.1.1 and §3.2 (footprint filtering).
    pub fn value(&self, x: f64, z: f64, footprint_m: f64) -> f64 {
        debug_assert!(x.is_finite() && z.is_finite() && footprint_m >= 0.0);
        if self.amplitude <= 0.0 {
            return 1.0;
        }
        // Octave `o` reads the lattice at `x/λₒ = (x/λ₀)·2ᵒ`: scaling by a power of two is exact,
        // so one division serves every octave.
        let (xs, zs) = (x / self.wavelength, z / self.wavelength);
        // λₒ/ℓ = (λ₀/ℓ)·2⁻ᵒ: one division for every octave's fade, too.
        let ratio = if footprint_m > 0.0 { self.wavelength / footprint_m } else { f64::INFINITY };
        // A periodic noise reads the point moved by a period into the canonical cells, each
        // octave's offset too ([`CellPeriod::shifts`]): the same values, and no division per
        // octave to find the canonical cell.
        let (xs, zs) = match &self.period {
            Some(per) => per.reduce_point(xs, zs, 0),
            None => (xs, zs),
        };
        let mut sum = 0.0;
        for o in 0..self.octaves {
            let down = OCTAVE_SCALE[o as usize];
            let fade = smoothstep(1.0, 1.5, ratio * down);
            if fade <= 0.0 {
                break; // Later octaves are shorter still.
            }
            // Offset each octave so their lattices do not line up at the origin.
            let up = f64::from(1u32 << o);
            let (sx, sz) = match &self.period {
                Some(per) => per.shifts[o as usize],
                None => (octave_shift(o), -octave_shift(o)),
            };
            sum += fade * down * self.gradient_noise(xs * up + sx, zs * up + sz, o);
        }
        // Each octave is in [−1, 1] and weighs at most its weight: |sum| ≤ Σ wₒ, so the clamp
        // absorbs rounding only.
        debug_assert!(sum.abs() <= self.weight_sum * (1.0 + NOISE_ROUNDING), "sum {sum} of {}", self.weight_sum);
        (1.0 + self.amplitude * sum / self.weight_sum).clamp(1.0 - self.amplitude, 1.0 + self.amplitude)
    }

    /// Share of the noise's variance that a footprint `ℓ` keeps: `Σₒ (fₒ(ℓ) wₒ)² / Σₒ wₒ²`,
    /// treating the octaves as uncorrelated with equal variance per unit weight (each octave is
    /// the same gradient noise at another scale). 1 at `ℓ = 0`, 0 beyond every octave.
    ///
    /// # Arguments
    /// - `footprint_m`: pixel footprint `ℓ` on the sea (m), `[0, ∞)`.
    ///
    /// # Returns
    /// The kept share, `[0, 1]`.
    ///
    /// # References
    /// Perlin 2002 (octaves of one noise); Darles et al. 2007 §3.2 (footprint fade).
    pub fn resolved_variance_share(&self, footprint_m: f64) -> f64 {
        debug_assert!(footprint_m >= 0.0);
        let (mut kept, mut total) = (0.0, 0.0);
        let ratio = self.wavelength / footprint_m.max(f64::MIN_POSITIVE);
        for &scale in &OCTAVE_SCALE[..self.octaves as usize] {
            let fade = smoothstep(1.0, 1.5, ratio * scale);
            // `wₒ² ∝ 2⁻²ᵒ`, exact as a square of `2⁻ᵒ`.
            let w2 = scale * scale;
            kept += fade * fade * w2;
            total += w2;
        }
        kept / total
    }

    /// Perlin gradient noise in `[−1, 1]` at lattice coordinates `(x, z)` of octave `octave`.
    #[inline]
    fn gradient_noise(&self, x: f64, z: f64, octave: u32) -> f64 {
        let (xf, zf) = (lattice_floor(x), lattice_floor(z));
        let (dx, dz) = (x - xf, z - zf);
        let p = &self.perm;
        let (ci, cj) = (xf as i64, zf as i64);
        let hash = |i: i64, j: i64| p[p[(i & 255) as usize] as usize + (j & 255) as usize];
        let [h00, h10, h01, h11] = match &self.period {
            None => [hash(ci, cj), hash(ci + 1, cj), hash(ci, cj + 1), hash(ci + 1, cj + 1)],
            Some(per) => {
                let (i0, j0) = per.reduce(ci, cj, octave);
                let at = |di: i64, dj: i64| {
                    let (i, j) = per.step(i0, j0, di, dj, octave);
                    hash(i, j)
                };
                [at(0, 0), at(1, 0), at(0, 1), at(1, 1)]
            }
        };
        let (u, v) = (fade(dx), fade(dz));
        let n00 = grad(h00, dx, dz);
        let n10 = grad(h10, dx - 1.0, dz);
        let n01 = grad(h01, dx, dz - 1.0);
        let n11 = grad(h11, dx - 1.0, dz - 1.0);
        let a = n00 + u * (n10 - n00);
        let b = n01 + u * (n11 - n01);
        let n = (a + v * (b - a)) * PERLIN_2D_SCALE;
        // |n| ≤ √2/2 before the scale: the clamp absorbs rounding only.
        debug_assert!(n.abs() <= 1.0 + NOISE_ROUNDING, "octave value {n}");
        n.clamp(-1.0, 1.0)
    }
}

/// The offset `s` (cells) of octave `o`'s lattice, along `(1, −1)`: so the octaves' lattices do
/// not line up at the origin.
fn octave_shift(o: u32) -> f64 {
    17.31 * f64::from(o)
}

/// `2⁻ᵒ`, the wavelength (and weight) of octave `o` relative to the first.
const OCTAVE_SCALE: [f64; FoamNoise::MAX_OCTAVES as usize] = {
    let mut s = [1.0; FoamNoise::MAX_OCTAVES as usize];
    let mut o = 1;
    while o < s.len() {
        s[o] = s[o - 1] * 0.5;
        o += 1;
    }
    s
};

/// Perlin's quintic fade `6t⁵ − 15t⁴ + 10t³`.
fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// The eight unit gradients a cell corner's hash picks, as `(sₓ, s_z, d)`: the gradient's dot
/// product with an offset `(x, z)` is `(sₓx + s_z z)·d` (exact up to the final product, as
/// `sₓ, s_z ∈ {0, ±1}`). The four axis gradients have `d = 1`, the four diagonals `d = √2/2`; a
/// table read rather than a branch on a random hash, which the processor cannot predict.
const GRADIENTS: [(f64, f64, f64); 8] = {
    const D: f64 = std::f64::consts::FRAC_1_SQRT_2;
    [
        (1.0, 0.0, 1.0),
        (-1.0, 0.0, 1.0),
        (0.0, 1.0, 1.0),
        (0.0, -1.0, 1.0),
        (1.0, 1.0, D),
        (1.0, -1.0, D),
        (-1.0, 1.0, D),
        (-1.0, -1.0, D),
    ]
};

/// Dot product of the offset `(x, z)` with the unit gradient the hash picks ([`GRADIENTS`]).
#[inline]
fn grad(hash: u8, x: f64, z: f64) -> f64 {
    let (sx, sz, d) = GRADIENTS[usize::from(hash & 7)];
    (sx * x + sz * z) * d
}

/// `smoothstep(e0, e1, x)`: 0 below `e0`, 1 above `e1`, `3t² − 2t³` between.
pub(crate) fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 4·10⁴ samples over ~750 decorrelated cells of the first octave: standard error of the
    /// mean ≈ 0.01; four of them.
    const MEAN_TOL: f64 = 0.04;

    /// A fully filtered noise is `1 + a·0/Σw` exactly, up to one rounding.
    const ROUNDING: f64 = 1e-15;

    /// Smallest summed difference over 50 points between two seeds: independent noises of
    /// amplitude 0.5 differ by a sizeable part of it at most points; 0.1 only asks that they
    /// differ at all.
    const DIFFERENT_SEEDS: f64 = 0.1;

    #[test]
    fn area_mean_is_one_and_far_field_is_flat() {
        let n = FoamNoise::new(0.8, 10.0, 4, 3).unwrap();
        let mut sum = 0.0;
        let m = 200;
        for i in 0..m {
            for j in 0..m {
                sum += n.value(i as f64 * 1.37, j as f64 * 1.41, 0.0);
            }
        }
        let mean = sum / (m * m) as f64;
        assert!((mean - 1.0).abs() < MEAN_TOL, "mean {mean}");
        // A footprint longer than every octave removes the noise entirely.
        assert!((n.value(3.3, 4.4, 100.0) - 1.0).abs() < ROUNDING);
    }

    #[test]
    fn periodic_noise_repeats_under_its_periods() {
        let n = FoamNoise::new(0.8, 2.0, 5, 3).unwrap().periodic([7, -3], [2, 5]).unwrap();
        // The periods in metres: λ₀ = 2 m per cell.
        let (p1, p2) = ((14.0, -6.0), (4.0, 10.0));
        for (x, z) in [(0.3, 0.7), (-13.1, 4.4), (101.0, -57.5)] {
            let v = n.value(x, z, 0.0);
            for (k1, k2) in [(1.0, 0.0), (0.0, 1.0), (-2.0, 3.0)] {
                let w = n.value(x + k1 * p1.0 + k2 * p2.0, z + k1 * p1.1 + k2 * p2.1, 0.0);
                assert!((v - w).abs() < 1e-9, "{v} {w}");
            }
        }
        assert!(FoamNoise::new(0.8, 2.0, 5, 3).unwrap().periodic([2, 4], [1, 2]).is_err());
        // The canonical representatives of the lattice points are the origin.
        let per = CellPeriod::new([7, -3], [2, 5]).unwrap();
        assert_eq!(per.a * per.c, 41);
        assert_eq!(per.reduce(9, 2, 0), (0, 0));
        assert_eq!(per.reduce(14, -6, 1), (0, 0));
        // The neighbours of a reduced cell, without division, are the full reduction's.
        for (i, j) in [(0, 0), (40, 3), (-17, 88), (123, -45), (6, 40)] {
            for o in 0..4 {
                let (i0, j0) = per.reduce(i, j, o);
                for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    assert_eq!(
                        per.step(i0, j0, di, dj, o),
                        per.reduce(i + di, j + dj, o),
                        "({i}, {j}) + ({di}, {dj}), octave {o}"
                    );
                }
            }
        }
    }

    /// A periodic noise read at the point moved into its canonical cells (with each octave's offset
    /// moved likewise) is the noise read where the point is: the sum written out here reads every
    /// octave at its unmoved lattice point, the cells reduced by division.
    #[test]
    fn the_reduced_point_reads_the_same_noise() {
        let n = FoamNoise::new(0.8, 2.0, 5, 3).unwrap().periodic([7, -3], [2, 5]).unwrap();
        let direct = |x: f64, z: f64| {
            let (xs, zs) = (x / 2.0, z / 2.0);
            let sum: f64 = (0..5)
                .map(|o| {
                    let (up, shift) = (f64::from(1u32 << o), octave_shift(o));
                    OCTAVE_SCALE[o as usize] * n.gradient_noise(xs * up + shift, zs * up - shift, o)
                })
                .sum();
            (1.0 + 0.8 * sum / n.weight_sum).clamp(0.2, 1.8)
        };
        for (x, z) in [(0.3, 0.7), (-13.1, 4.4), (101.0, -57.5), (1234.5, 987.6), (-0.001, -0.002)] {
            assert!((n.value(x, z, 0.0) - direct(x, z)).abs() < 1e-9, "({x}, {z})");
        }
    }

    /// The float division with its correction is integer division, at the ends of its range too.
    #[test]
    fn float_division_matches_integer_division() {
        let xs: [i64; 12] =
            [0, 1, -1, 7, -7, 41, -41, 123_456_789, -987_654_321, (1 << 50) - 1, -(1 << 50) + 1, 1 << 40];
        for m in [1i64, 2, 3, 7, 41, 1 << 12, 1_000_003, (1 << 31) - 1] {
            for &x in &xs {
                for dx in -3..=3 {
                    let x = x + dx * m;
                    if x.abs() < 1 << 50 {
                        let q = div_rem_euclid(x, m, 1.0 / m as f64);
                        assert_eq!(q, (x.div_euclid(m), x.rem_euclid(m)), "{x} / {m}");
                    }
                }
            }
        }
    }

    #[test]
    fn same_seed_same_noise() {
        let a = FoamNoise::new(0.5, 7.0, 3, 11).unwrap();
        let b = FoamNoise::new(0.5, 7.0, 3, 11).unwrap();
        let c = FoamNoise::new(0.5, 7.0, 3, 12).unwrap();
        assert_eq!(a, b);
        let diff: f64 = (0..50).map(|i| (a.value(i as f64, 0.5, 0.0) - c.value(i as f64, 0.5, 0.0)).abs()).sum();
        assert!(diff > DIFFERENT_SEEDS);
    }
}
