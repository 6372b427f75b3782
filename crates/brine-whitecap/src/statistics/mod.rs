//! The Jacobian of the horizontal displacement of a trochoid set, and its mean and variance over
//! a pixel footprint.

use brine_waves::TrochoidSet;
use glam::DVec2;
use wide::f64x4;

use crate::error::{WhitecapError, check};

mod lanes;

use lanes::Octet;
pub use lanes::{F32_MOMENTS_ERROR, HistoryRotation, HistoryStart};

/// Footprint gain below which a wave counts as entirely unresolved (its share of the mean is then
/// below 10⁻⁶ of its amplitude).
const MIN_GAIN: f64 = 1e-6;

/// `k s` beyond which the Gaussian gain `e^{−k²s²/2}` is below [`MIN_GAIN`]: `√(2 ln 10⁶)`.
pub(crate) const GAUSSIAN_CUTOFF: f64 = 5.256_521_769_756_932;

/// Mean `μ` and variance `σ²` of the Jacobian `J` over a pixel footprint.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Moments {
    /// Mean `μ` (dimensionless).
    pub mu: f64,
    /// Variance `σ²` (dimensionless, `≥ 0`).
    pub sigma2: f64,
}

/// How a pixel footprint filters a wave of wavenumber `k`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FootprintFilter {
    /// A Gaussian footprint of standard deviation `s`: a wave keeps the fraction
    /// `g = e^{−k²s²/2}` of its local value; the rest, of footprint variance
    /// `½ + ½g⁴ cos 2φ − g² cos² φ`, goes to `σ²`. Smooth in `s`.
    #[default]
    Gaussian,
    /// The sharp split of the docs/equations.md §10: waves with `k s < 1` (wavelength above `2πs`)
    /// are resolved (exact local value in `μ`), the others unresolved (only their share of `σ²`).
    Sharp,
}

/// Whitecap statistics of a trochoid set: the displacement Jacobian `J`, and its mean and
/// variance over a pixel footprint (Dupuy & Bruneton 2012, derived for trochoids).
///
/// **Jacobian.** The Gerstner map `x = u + D(u)`, `D = −Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ`,
/// `φᵢ = kᵢ d̂ᵢ·u − ωᵢt + φ₀ᵢ`, has `∂D/∂u = −Σ Qᵢ cos φᵢ d̂ᵢd̂ᵢᵀ`, so
/// `J = det(I − M)`, `M = Σ aᵢ cᵢ d̂ᵢd̂ᵢᵀ`, `aᵢ = Qᵢ`, `cᵢ = cos φᵢ`. For 2×2 matrices
/// `det(I − M) = 1 − tr M + det M` and, by Cauchy–Binet, `det M = Σ_{i<j} aᵢaⱼ cᵢcⱼ sin²(θᵢ − θⱼ)`:
///
/// `J = 1 − Σ aᵢcᵢ + Σ_{i<j} aᵢaⱼ sin²(θᵢ − θⱼ) cᵢcⱼ`.
///
/// (The docs/equations.md writes `aᵢ = kᵢAᵢ`, the exact trochoid; with choppiness the horizontal
/// radius is `Qᵢ/kᵢ` and `aᵢ = Qᵢ`.)
///
/// **Over the whole sea** the phases are independent and uniform (incommensurate wave vectors),
/// `E[c] = 0`, `E[c²] = ½`, `E[c²c′²] = ¼`; the linear and pair terms are uncorrelated, so
///
/// `μ = 1`, `σ² = ½ Σ aᵢ² + ¼ Σ_{i<j} aᵢ²aⱼ² sin⁴(θᵢ − θⱼ)`.
///
/// **Over a footprint** write `cᵢ = gᵢ c̄ᵢ + ηᵢ`: `c̄ᵢ` the cosine at the footprint's centre, `gᵢ`
/// the footprint gain ([`FootprintFilter`]) and `ηᵢ` a zero-mean fluctuation of variance `sᵢ²`,
/// independent between waves. With `A = I − Σ aᵢgᵢc̄ᵢ d̂ᵢd̂ᵢᵀ = [[p, q], [q, r]]` (the resolved
/// part) and `N = Σ aᵢηᵢ d̂ᵢd̂ᵢᵀ`, the 2×2 identity `det(A − N) = det A − tr(adj(A) N) + det N` is
/// exact:
///
/// `J = det A − Σ aᵢηᵢ (d̂ᵢᵀ adj(A) d̂ᵢ) + Σ_{i<j} aᵢaⱼ ηᵢηⱼ sin²(θᵢ − θⱼ)`, hence
///
/// `μ = pr − q²`,
/// `σ² = Σ aᵢ²sᵢ² (vᵢ·m)² + Σ_{i<j} aᵢ²sᵢ² aⱼ²sⱼ² sin⁴(θᵢ − θⱼ)`,
///
/// with `m = (r, q, p)` and `vᵢ = (dₓ², −2dₓd_z, d_z²)`, so that `d̂ᵀ adj(A) d̂ = v·m`. The first
/// sum is the quadratic form `mᵀ G m`, `G = Σ wᵢ vᵢvᵢᵀ`, `wᵢ = aᵢ²sᵢ²`, and the second, with
/// `sin⁴ x = (3 − 4 cos 2x + cos 4x)/8`, is `(3W² − 4|H₂|² + |H₄|²)/16`, `W = Σ wᵢ`,
/// `Hₙ = Σ wᵢ e^{inθᵢ}`: `O(N)` per pixel, and the fully unresolved waves' sums are precomputed.
/// Fully resolved waves (`g = 1`, `s = 0`) give `μ = J`, `σ² = 0`; fully unresolved ones
/// (`g = 0`, `s² = ½`) give back the whole-sea formulas. The resolved/unresolved split of the
/// docs/equations.md is the [`FootprintFilter::Sharp`] case.
///
/// # References
/// Dupuy J., Bruneton E. 2012, "Real-time animation and rendering of ocean whitecaps", SIGGRAPH
/// Asia Technical Briefs (slides: "μ, σ² can be computed analytically for trochoids");
/// docs/equations.md §10 (derived).
#[derive(Debug, Clone, PartialEq)]
pub struct JacobianStatistics {
    /// Waves sorted by increasing wavenumber.
    waves: Vec<WaveTerm>,
    /// `order[i]`: index in the set of the i-th sorted wave.
    order: Vec<usize>,
    /// `tail[i]`: sums over sorted waves `i..` taken as fully unresolved (`s² = ½`).
    tail: Vec<Sums>,
    /// The sorted waves four at a time (structure of arrays, zero-padded) for [`Self::moments_at`].
    quads: Vec<Quad>,
    /// The sorted waves eight at a time in `f32` (zero-padded) for [`Self::moments_at_f32`].
    octets: Vec<Octet>,
    variance: f64,
    total_steepness: f64,
}

/// Per-wave constants, sorted by wavenumber.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct WaveTerm {
    pub(crate) a: f64,
    pub(crate) k: f64,
    pub(crate) kx: f64,
    pub(crate) kz: f64,
    pub(crate) omega: f64,
    pub(crate) phase: f64,
    /// `(dₓ², dₓd_z, d_z²)`: the rank-one matrix `d̂d̂ᵀ`.
    pub(crate) dd: [f64; 3],
    /// `v = (dₓ², −2dₓd_z, d_z²)`.
    pub(crate) v: [f64; 3],
    /// `(cos 2θ, sin 2θ, cos 4θ, sin 4θ)`.
    pub(crate) harm: [f64; 4],
}

/// Additive sums over waves for the variance: `G` (6 entries of the symmetric 3×3), `W`, `H₂`,
/// `H₄`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Sums {
    pub(crate) g: [f64; 6],
    pub(crate) w: f64,
    pub(crate) h: [f64; 4],
}

/// Four sorted waves side by side (lanes beyond the set have `a = 0`): the per-wave constants of
/// [`Accumulator::add`] with `v vᵀ` precomputed, for `f64x4` lanes.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Quad {
    a: f64x4,
    k: f64x4,
    kx: f64x4,
    kz: f64x4,
    omega: f64x4,
    phase: f64x4,
    dd: [f64x4; 3],
    /// `(v₀v₀, v₀v₁, v₀v₂, v₁v₁, v₁v₂, v₂v₂)`, the entries of `G` per unit weight.
    vv: [f64x4; 6],
    harm: [f64x4; 4],
}

impl Quad {
    fn new(terms: &[WaveTerm]) -> Self {
        let lane = |f: &dyn Fn(&WaveTerm) -> f64| f64x4::new([0, 1, 2, 3].map(|l| terms.get(l).map_or(0.0, f)));
        Self {
            a: lane(&|t| t.a),
            k: lane(&|t| t.k),
            kx: lane(&|t| t.kx),
            kz: lane(&|t| t.kz),
            omega: lane(&|t| t.omega),
            phase: lane(&|t| t.phase),
            dd: [0, 1, 2].map(|j| lane(&|t| t.dd[j])),
            vv: [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)].map(|(i, j)| lane(&|t| t.v[i] * t.v[j])),
            harm: [0, 1, 2, 3].map(|j| lane(&|t| t.harm[j])),
        }
    }
}
impl Sums {
    #[inline]
    pub(crate) fn add(&mut self, t: &WaveTerm, w: f64) {
        let v = t.v;
        self.g[0] += w * v[0] * v[0];
        self.g[1] += w * v[0] * v[1];
        self.g[2] += w * v[0] * v[2];
        self.g[3] += w * v[1] * v[1];
        self.g[4] += w * v[1] * v[2];
        self.g[5] += w * v[2] * v[2];
        self.w += w;
        for (h, c) in self.h.iter_mut().zip(t.harm) {
            *h += w * c;
        }
    }

    #[inline]
    pub(crate) fn merge(&mut self, o: &Sums) {
        for (a, b) in self.g.iter_mut().zip(o.g) {
            *a += b;
        }
        self.w += o.w;
        for (a, b) in self.h.iter_mut().zip(o.h) {
            *a += b;
        }
    }

    /// `σ² = mᵀ G m + (3W² − 4|H₂|² + |H₄|²)/16`.
    #[inline]
    pub(crate) fn variance(&self, m: [f64; 3]) -> f64 {
        let g = &self.g;
        let quad = g[0] * m[0] * m[0]
            + g[3] * m[1] * m[1]
            + g[5] * m[2] * m[2]
            + 2.0 * (g[1] * m[0] * m[1] + g[2] * m[0] * m[2] + g[4] * m[1] * m[2]);
        let h2 = self.h[0] * self.h[0] + self.h[1] * self.h[1];
        let h4 = self.h[2] * self.h[2] + self.h[3] * self.h[3];
        let pairs = (3.0 * self.w * self.w - 4.0 * h2 + h4) / 16.0;
        // `G` is a Gram matrix and the pair term a variance: both ≥ 0 but for the rounding of
        // the (possibly f32) sums, which alone the clamps absorb: a few hundred terms of ~6×10⁻⁸
        // each, relative to their size, with margin.
        const F32_SUMS_ROUNDING: f64 = 1e-4;
        let diagonal = g[0] * m[0] * m[0] + g[3] * m[1] * m[1] + g[5] * m[2] * m[2];
        debug_assert!(quad >= -F32_SUMS_ROUNDING * diagonal, "mᵀGm = {quad} (diagonal {diagonal})");
        debug_assert!(pairs >= -F32_SUMS_ROUNDING * self.w * self.w, "pair variance {pairs}");
        (quad + pairs.max(0.0)).max(0.0)
    }
}

/// Accumulator of the resolved matrix `A` and the fluctuation sums.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Accumulator {
    pub(crate) p: f64,
    pub(crate) q: f64,
    pub(crate) r: f64,
    pub(crate) sums: Sums,
}

impl Accumulator {
    #[inline]
    pub(crate) fn new() -> Self {
        Self { p: 1.0, q: 0.0, r: 1.0, sums: Sums::default() }
    }

    /// Adds a wave of gain `g` whose centre cosine is `c`.
    #[inline]
    pub(crate) fn add(&mut self, t: &WaveTerm, g: f64, c: f64) {
        let agc = t.a * g * c;
        self.p -= agc * t.dd[0];
        self.q -= agc * t.dd[1];
        self.r -= agc * t.dd[2];
        // A wave kept at more than 1 − 10⁻⁹ of its value fluctuates by less than 2·10⁻⁹ of its
        // variance over the footprint: count it as fully resolved.
        if g < 1.0 - 1e-9 {
            let g2 = g * g;
            // Var over the footprint of cos(φ̄ + X), X ~ N(0, k²s²):
            // ½ + ½ g⁴ cos 2φ̄ − g² cos² φ̄.
            let s2 = (0.5 + 0.5 * g2 * g2 * (2.0 * c * c - 1.0) - g2 * c * c).max(0.0);
            self.sums.add(t, t.a * t.a * s2);
        }
    }

    #[inline]
    pub(crate) fn moments(&self, tail: &Sums) -> Moments {
        let mut sums = self.sums;
        sums.merge(tail);
        Moments { mu: self.p * self.r - self.q * self.q, sigma2: sums.variance([self.r, self.q, self.p]) }
    }
}

impl JacobianStatistics {
    /// Precomputes the statistics of the displacement Jacobian of a trochoid set.
    ///
    /// Sorts the waves by wavenumber, stores per wave `aᵢ = Qᵢ`, `kᵢd̂ᵢ`, `ωᵢ`, `φ₀ᵢ`, `d̂ᵢd̂ᵢᵀ`,
    /// `vᵢ` and `e^{2iθᵢ}`, `e^{4iθᵢ}`, the suffix sums of the fully unresolved waves (`sᵢ² = ½`),
    /// and the whole-sea variance `σ² = ½ Σ Qᵢ² + ¼ Σ_{i<j} Qᵢ²Qⱼ² sin⁴(θᵢ − θⱼ)`.
    ///
    /// # Arguments
    /// - `set`: the trochoid set (brine-waves), at least one wave; steepnesses `Qᵢ` (dimensionless),
    ///   wavenumbers (rad m⁻¹), directions (rad).
    ///
    /// # Returns
    /// The statistics (`O(N)` memory), for [`Self::moments_at`] and [`Self::jacobian_at`].
    ///
    /// # Errors
    /// [`WhitecapError::EmptySet`] for a set without waves.
    ///
    /// # References
    /// Dupuy & Bruneton 2012 ("μ, σ² can be computed analytically for trochoids"); docs/equations.md
    /// §10 (derived in the type's documentation).
    pub fn new(set: &TrochoidSet) -> Result<Self, WhitecapError> {
        if set.is_empty() {
            return Err(WhitecapError::EmptySet);
        }
        let mut order: Vec<usize> = (0..set.len()).collect();
        let waves = set.waves();
        order.sort_by(|&i, &j| waves[i].wavenumber().total_cmp(&waves[j].wavenumber()).then(i.cmp(&j)));
        let terms: Vec<WaveTerm> = order
            .iter()
            .map(|&i| {
                let w = &waves[i];
                let d = w.direction_vector();
                let th = w.direction();
                WaveTerm {
                    a: w.steepness(),
                    k: w.wavenumber(),
                    kx: w.wavenumber() * d.x,
                    kz: w.wavenumber() * d.y,
                    omega: w.omega(),
                    phase: w.phase(),
                    dd: [d.x * d.x, d.x * d.y, d.y * d.y],
                    v: [d.x * d.x, -2.0 * d.x * d.y, d.y * d.y],
                    harm: [(2.0 * th).cos(), (2.0 * th).sin(), (4.0 * th).cos(), (4.0 * th).sin()],
                }
            })
            .collect();
        let mut tail = vec![Sums::default(); terms.len() + 1];
        for i in (0..terms.len()).rev() {
            let mut s = tail[i + 1];
            s.add(&terms[i], 0.5 * terms[i].a * terms[i].a);
            tail[i] = s;
        }
        let variance = tail[0].variance([1.0, 0.0, 1.0]);
        let total_steepness = terms.iter().map(|t| t.a).sum();
        let quads = terms.chunks(4).map(Quad::new).collect();
        let octets = terms.chunks(8).map(Octet::new).collect();
        Ok(Self { waves: terms, order, tail, quads, octets, variance, total_steepness })
    }

    /// Number of waves.
    pub fn len(&self) -> usize {
        self.waves.len()
    }

    /// Always `false`: an empty set is rejected by [`Self::new`].
    pub fn is_empty(&self) -> bool {
        self.waves.is_empty()
    }

    pub(crate) fn terms(&self) -> &[WaveTerm] {
        &self.waves
    }

    pub(crate) fn tail(&self, from: usize) -> &Sums {
        &self.tail[from]
    }

    /// Mean of `J` over the whole sea, `μ = 1` (exact for any set: `E[cᵢ] = 0`).
    pub fn mean(&self) -> f64 {
        1.0
    }

    /// Variance of `J` over the whole sea, `σ² = ½ Σ Qᵢ² + ¼ Σ_{i<j} Qᵢ²Qⱼ² sin⁴(θᵢ − θⱼ)`.
    ///
    /// # Returns
    /// `σ²` (dimensionless), precomputed.
    ///
    /// # References
    /// docs/equations.md §10 (derived; here with `aᵢ = Qᵢ`).
    pub fn variance(&self) -> f64 {
        self.variance
    }

    /// `Σ Qᵢ`: `J` stays within `[(1 − ΣQ)², (1 + ΣQ)²]` when `ΣQ ≤ 1`.
    pub fn total_steepness(&self) -> f64 {
        self.total_steepness
    }

    /// Bounds of `J` over all positions and times: the eigenvalues of `M` lie in
    /// `[−ΣQ, ΣQ]`, so `J ∈ [min((1 − ΣQ)², 1 − (ΣQ)²), (1 + ΣQ)²]`.
    ///
    /// # Returns
    /// `(J_min, J_max)` (dimensionless).
    ///
    /// # References
    /// Derived (Weyl: the eigenvalues of a sum of `Qᵢ cos φᵢ d̂ᵢd̂ᵢᵀ` lie within `±Σ Qᵢ`).
    pub fn bounds(&self) -> (f64, f64) {
        let s = self.total_steepness;
        (((1.0 - s) * (1.0 - s)).min(1.0 - s * s), (1.0 + s) * (1.0 + s))
    }

    /// Exact `J = det(I − Σ Qᵢ cos φᵢ d̂ᵢd̂ᵢᵀ)` from the cosines of the wave phases.
    ///
    /// # Arguments
    /// - `cos_phi`: `cos φᵢ` for each wave, in the order of the set (`len()` values in `[−1, 1]`).
    ///   For the trochoid-sum surface of Darles et al., use the cosines of the particle phases
    ///   `θᵢ` solved at the surface point.
    ///
    /// # Returns
    /// `J` (dimensionless).
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
    pub fn jacobian_from_cosines(&self, cos_phi: &[f64]) -> f64 {
        debug_assert_eq!(cos_phi.len(), self.len());
        let mut acc = Accumulator::new();
        for (t, &i) in self.waves.iter().zip(&self.order) {
            acc.add(t, 1.0, cos_phi[i]);
        }
        acc.p * acc.r - acc.q * acc.q
    }

    /// Exact `J = det(I − Σ Qᵢ cos φᵢ d̂ᵢd̂ᵢᵀ)` of the Gerstner map at a rest position,
    /// `φᵢ = kᵢ d̂ᵢ·u − ωᵢt + φ₀ᵢ`.
    ///
    /// # Arguments
    /// - `u`: rest position `(x, z)` (m), finite.
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// `J` (dimensionless), within [`Self::bounds`].
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
    pub fn jacobian_at(&self, u: DVec2, t: f64) -> f64 {
        let mut acc = Accumulator::new();
        for w in &self.waves {
            acc.add(w, 1.0, (w.kx * u.x + w.kz * u.y - w.omega * t + w.phase).cos());
        }
        acc.p * acc.r - acc.q * acc.q
    }

    /// Number of (sorted) waves that the footprint does not wash out entirely.
    pub(crate) fn active_count(&self, footprint_m: f64, filter: FootprintFilter) -> usize {
        let cut = match filter {
            FootprintFilter::Gaussian => GAUSSIAN_CUTOFF,
            FootprintFilter::Sharp => 1.0,
        };
        if footprint_m <= 0.0 {
            return self.waves.len();
        }
        let k_cut = cut / footprint_m;
        self.waves.partition_point(|w| w.k < k_cut)
    }

    /// Footprint gain of a wave.
    #[inline]
    pub(crate) fn gain(k: f64, footprint_m: f64, filter: FootprintFilter) -> f64 {
        match filter {
            FootprintFilter::Gaussian => {
                let ks = k * footprint_m;
                let g = (-0.5 * ks * ks).exp();
                if g < MIN_GAIN { 0.0 } else { g }
            }
            FootprintFilter::Sharp => {
                if k * footprint_m < 1.0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// Mean and variance of `J` over a footprint, from the phase cosines at its centre.
    ///
    /// # Arguments
    /// - `cos_phi`: `cos φᵢ` at the footprint centre, in the order of the set (`len()` values).
    /// - `footprint_m`: footprint size `s` (m), `≥ 0`: the standard deviation of a Gaussian
    ///   footprint (for a square pixel of side `ℓ` on the sea, `s ≈ ℓ/√12`), or the radius of the
    ///   sharp split (waves with `k s < 1` are resolved). 0 resolves every wave.
    /// - `filter`: [`FootprintFilter`].
    ///
    /// # Returns
    /// [`Moments`] `(μ, σ²)`: `μ = J`, `σ² = 0` at `s = 0`; `(1, variance())` as `s → ∞`.
    ///
    /// # References
    /// Derived in the type's documentation; Dupuy & Bruneton 2012 (per-footprint `μ`, `σ²`);
    /// docs/equations.md §10 (resolved waves in `μ`, unresolved in `σ²`).
    pub fn moments_from_cosines(&self, cos_phi: &[f64], footprint_m: f64, filter: FootprintFilter) -> Moments {
        debug_assert_eq!(cos_phi.len(), self.len());
        debug_assert!(footprint_m >= 0.0);
        let n = self.active_count(footprint_m, filter);
        let mut acc = Accumulator::new();
        for (t, &i) in self.waves[..n].iter().zip(&self.order[..n]) {
            acc.add(t, Self::gain(t.k, footprint_m, filter), cos_phi[i]);
        }
        acc.moments(&self.tail[n])
    }

    /// Mean and variance of `J` over a footprint centred at the Gerstner rest position `u` at
    /// time `t`. Only the waves the footprint does not wash out are evaluated.
    ///
    /// # Arguments
    /// - `u`: rest position `(x, z)` of the footprint centre (m).
    /// - `t`: time (s).
    /// - `footprint_m`, `filter`: as [`Self::moments_from_cosines`].
    ///
    /// # Returns
    /// [`Moments`] `(μ, σ²)`.
    ///
    /// # References
    /// As [`Self::moments_from_cosines`].
    pub fn moments_at(&self, u: DVec2, t: f64, footprint_m: f64, filter: FootprintFilter) -> Moments {
        debug_assert!(footprint_m >= 0.0);
        let n = self.active_count(footprint_m, filter);
        // Four waves at a time in `wide::f64x4` lanes: the cosines (Agner Fog's VCL sin/cos after
        // a three-part reduction: a few ulps of the phase), the gains and the sums of
        // `Accumulator::add`, reduced over the lanes at the end (test
        // `simd_moments_match_the_scalar_ones`).
        let (ux, uz, t) = (f64x4::splat(u.x), f64x4::splat(u.y), f64x4::splat(t));
        let (one, zero, half) = (f64x4::ONE, f64x4::ZERO, f64x4::splat(0.5));
        let (mut p, mut q, mut r) = (zero, zero, zero);
        let (mut g, mut w, mut h) = ([zero; 6], zero, [zero; 4]);
        for (j, c) in self.quads[..n.div_ceil(4)].iter().enumerate() {
            // Lanes at or beyond the active count belong to the tail sums.
            let live = f64x4::new([0, 1, 2, 3].map(|l| if 4 * j + l < n { 1.0 } else { 0.0 }));
            let cos = (c.kx * ux + c.kz * uz - c.omega * t + c.phase).sin_cos().1;
            let gain = match filter {
                FootprintFilter::Gaussian => {
                    let ks = c.k * f64x4::splat(footprint_m);
                    let e = (f64x4::splat(-0.5) * ks * ks).exp();
                    e.simd_lt(f64x4::splat(MIN_GAIN)).select(zero, e)
                }
                FootprintFilter::Sharp => (c.k * f64x4::splat(footprint_m)).simd_lt(one).select(one, zero),
            };
            let a = c.a * live;
            let agc = a * gain * cos;
            p -= agc * c.dd[0];
            q -= agc * c.dd[1];
            r -= agc * c.dd[2];
            // Var of cos(φ̄ + X), X ~ N(0, k²s²), over the footprint: ½ + ½g⁴ cos 2φ̄ − g² cos² φ̄;
            // waves kept at more than 1 − 10⁻⁹ count as fully resolved (as `Accumulator::add`).
            let (g2, c2) = (gain * gain, cos * cos);
            let s2 = (half + half * g2 * g2 * (c2 + c2 - one) - g2 * c2).max(zero);
            let s2 = gain.simd_lt(f64x4::splat(1.0 - 1e-9)).select(s2, zero);
            let weight = a * a * s2;
            for (gj, vv) in g.iter_mut().zip(c.vv) {
                *gj += weight * vv;
            }
            w += weight;
            for (hj, hm) in h.iter_mut().zip(c.harm) {
                *hj += weight * hm;
            }
        }
        let acc = Accumulator {
            p: 1.0 + p.reduce_add(),
            q: q.reduce_add(),
            r: 1.0 + r.reduce_add(),
            sums: Sums { g: g.map(|x| x.reduce_add()), w: w.reduce_add(), h: h.map(|x| x.reduce_add()) },
        };
        acc.moments(&self.tail[n])
    }

    /// The scalar reference of [`Self::moments_at`] (one `f64::cos` and `exp` per wave).
    #[cfg(test)]
    fn moments_at_scalar(&self, u: DVec2, t: f64, footprint_m: f64, filter: FootprintFilter) -> Moments {
        let n = self.active_count(footprint_m, filter);
        let mut acc = Accumulator::new();
        for w in &self.waves[..n] {
            let c = (w.kx * u.x + w.kz * u.y - w.omega * t + w.phase).cos();
            acc.add(w, Self::gain(w.k, footprint_m, filter), c);
        }
        acc.moments(&self.tail[n])
    }

    /// Checks a footprint size.
    ///
    /// # Errors
    /// [`WhitecapError::OutOfRange`] unless `footprint_m` is finite and `≥ 0`.
    pub fn check_footprint(footprint_m: f64) -> Result<f64, WhitecapError> {
        check("footprint_m", footprint_m, footprint_m >= 0.0, "[0, ∞) m")
    }
}

#[cfg(test)]
mod tests;
