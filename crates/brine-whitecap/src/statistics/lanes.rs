//! The f32 lanes of the Jacobian statistics: eight waves at a time for the footprint moments
//! and the history along a drifting path, the renderer's route.

use glam::DVec2;
use wide::f32x8;

use super::{Accumulator, FootprintFilter, JacobianStatistics, MIN_GAIN, Moments, Sums, WaveTerm};

/// Per-wave phase advances of one memory lattice ([`JacobianStatistics::history_rotation`]).
#[derive(Debug, Clone)]
pub struct HistoryRotation {
    /// `Δt` (s).
    pub step_s: f64,
    /// `v` (m s⁻¹).
    pub drift_m_s: DVec2,
    rot: Vec<(f32x8, f32x8)>,
}

/// Where a history starts: the rotation from the present to the lattice's instant 0 (the age
/// `a₀` of that instant, [`JacobianStatistics::history_rotation`] of `a₀`) and the lattice's own
/// rotation from one instant to the next.
#[derive(Debug, Clone, Copy)]
pub struct HistoryStart<'a> {
    /// The rotation by `(ωᵢ − kᵢd̂ᵢ·v) a₀`.
    pub offset: &'a HistoryRotation,
    /// The rotation by `(ωᵢ − kᵢd̂ᵢ·v) Δt`.
    pub rotation: &'a HistoryRotation,
}

/// Eight sorted waves for [`JacobianStatistics::moments_at_f32`]: the phase terms in `f64` (the
/// phase is formed and reduced in `f64`), the rest in `f32`.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Octet {
    kx: [f64; 8],
    kz: [f64; 8],
    omega: [f64; 8],
    phase: [f64; 8],
    a: f32x8,
    k: f32x8,
    dd: [f32x8; 3],
    vv: [f32x8; 6],
    harm: [f32x8; 4],
}

/// Instants a history holds at most.
const MAX_HISTORY_INSTANTS: usize = 64;

/// `1` in the lanes of octet `j` that hold one of the `n` active waves, `0` beyond.
#[inline]
fn live_lanes(j: usize, n: usize) -> f32x8 {
    f32x8::new([0, 1, 2, 3, 4, 5, 6, 7].map(|l| if 8 * j + l < n { 1.0 } else { 0.0 }))
}

/// The `f32` sums of [`JacobianStatistics::moments_at_f32`] over the octets.
#[derive(Default)]
struct PresentSums {
    p: f32x8,
    q: f32x8,
    r: f32x8,
    g: [f32x8; 6],
    w: f32x8,
    h: [f32x8; 4],
}

impl PresentSums {
    /// Adds one octet's waves at cosines `cos` with footprint gains `gain` (lanes `live`).
    #[inline]
    fn add(&mut self, o: &Octet, live: f32x8, gain: f32x8, cos: f32x8) {
        let (one, zero, half) = (f32x8::ONE, f32x8::ZERO, f32x8::splat(0.5));
        let a = o.a * live;
        let agc = a * gain * cos;
        self.p -= agc * o.dd[0];
        self.q -= agc * o.dd[1];
        self.r -= agc * o.dd[2];
        // As `moments_at`; a gain that rounds to 1 in f32 is fully resolved.
        let (g2, c2) = (gain * gain, cos * cos);
        let s2 = (half + half * g2 * g2 * (c2 + c2 - one) - g2 * c2).max(zero);
        let s2 = gain.simd_lt(one).select(s2, zero);
        let weight = a * a * s2;
        for (gj, vv) in self.g.iter_mut().zip(o.vv) {
            *gj += weight * vv;
        }
        self.w += weight;
        for (hj, hm) in self.h.iter_mut().zip(o.harm) {
            *hj += weight * hm;
        }
    }

    /// The moments, with the tail of the waves beyond the active ones.
    fn finish(&self, tail: &Sums) -> Moments {
        let sum = |x: f32x8| f64::from(x.reduce_add());
        let acc = Accumulator {
            p: 1.0 + sum(self.p),
            q: sum(self.q),
            r: 1.0 + sum(self.r),
            sums: Sums { g: self.g.map(sum), w: sum(self.w), h: self.h.map(sum) },
        };
        acc.moments(tail)
    }
}

/// The `f32` sums `(p, q, r)` of [`JacobianStatistics::mean_history`] at each instant, over the
/// octets.
struct HistorySums {
    count: usize,
    /// Whether an octet was added: the first writes the sums instead of adding to them.
    started: bool,
    sums: [[[f32; 8]; 3]; MAX_HISTORY_INSTANTS],
}

thread_local! {
    /// One set of history sums per thread, reused, never cleared: the first octet of a call
    /// writes them (clearing all 64 instants was a measurable share of a query).
    static HISTORY_SUMS: std::cell::RefCell<HistorySums> = const {
        std::cell::RefCell::new(HistorySums { count: 0, started: false, sums: [[[0.0; 8]; 3]; MAX_HISTORY_INSTANTS] })
    };
}

impl HistorySums {
    /// Runs `f` with this thread's sums, empty, for `instants` instants.
    fn with<R>(instants: usize, f: impl FnOnce(&mut HistorySums) -> R) -> R {
        HISTORY_SUMS.with_borrow_mut(|h| {
            h.count = instants.min(MAX_HISTORY_INSTANTS);
            h.started = false;
            f(h)
        })
    }

    /// Adds one octet's waves of filtered amplitudes `ag` from the cosine and sine `(c, s)` at
    /// instant 0, rotated by `turn = (cos δ, sin δ)` from one instant to the next.
    #[inline]
    fn add(&mut self, ag: f32x8, o: &Octet, (c, sn): (f32x8, f32x8), (cd, sd): (f32x8, f32x8)) {
        let w = [ag * o.dd[0], ag * o.dd[1], ag * o.dd[2]].map(f32x8::to_array);
        let rotation = Rotation { c: c.to_array(), s: sn.to_array(), cd: cd.to_array(), sd: sd.to_array() };
        rotate_and_add(&mut self.sums[..self.count], &w, &rotation, !self.started);
        self.started = true;
    }

    /// `μⱼ` into `out`.
    fn finish(&mut self, out: &mut [f64]) {
        if !self.started {
            // No wave: the sums are 0.
            self.sums[..self.count].fill([[0.0; 8]; 3]);
        }
        for (o, [p, q, r]) in out.iter_mut().zip(&self.sums[..self.count]) {
            let sum = |v: &[f32; 8]| f64::from(f32x8::new(*v).reduce_add());
            let (pi, qi, ri) = (1.0 + sum(p), sum(q), 1.0 + sum(r));
            *o = pi * ri - qi * qi;
        }
    }
}

/// An octet's cosines and sines at instant 0 and the rotation from one instant to the next.
#[derive(Clone, Copy)]
struct Rotation {
    c: [f32; 8],
    s: [f32; 8],
    cd: [f32; 8],
    sd: [f32; 8],
}

/// The history's inner loop: at each instant, `(p, q, r) −= w c` (the first octet of a call
/// writes `0 − w c` instead, the value a cleared sum would give), then `(c, s)` turned by
/// `(cos δ, sin δ)`. Plain lanes, compiled for the widest vectors the processor has and chosen
/// at run time (AVX: one instruction for the eight lanes, SSE2: two); the operations and their
/// order are the same on every route, so are the roundings (Rust never fuses a product and a sum).
#[multiversion::multiversion(targets("x86_64+avx"))]
fn rotate_and_add(sums: &mut [[[f32; 8]; 3]], w: &[[f32; 8]; 3], rotation: &Rotation, first: bool) {
    let Rotation { mut c, mut s, cd, sd } = *rotation;
    for [p, q, r] in sums.iter_mut() {
        if first {
            for l in 0..8 {
                p[l] = 0.0 - w[0][l] * c[l];
                q[l] = 0.0 - w[1][l] * c[l];
                r[l] = 0.0 - w[2][l] * c[l];
            }
        } else {
            for l in 0..8 {
                p[l] -= w[0][l] * c[l];
                q[l] -= w[1][l] * c[l];
                r[l] -= w[2][l] * c[l];
            }
        }
        for l in 0..8 {
            let turned = c[l] * cd[l] - s[l] * sd[l];
            s[l] = s[l] * cd[l] + c[l] * sd[l];
            c[l] = turned;
        }
    }
}

/// The footprint gains of a run of octets at one footprint, kept per thread: a query, a bake
/// or a calibration asks the same footprint point after point, and the gains cost one `exp` per
/// octet. Keyed by the footprint, the filter and the octets' wavenumbers themselves (the gains
/// depend on nothing else), so no stale entry can be read.
struct GainCache {
    footprint_bits: u64,
    filter: FootprintFilter,
    k: Vec<f32x8>,
    gains: Vec<f32x8>,
}

thread_local! {
    static GAIN_CACHE: std::cell::RefCell<GainCache> = const {
        std::cell::RefCell::new(GainCache {
            footprint_bits: u64::MAX,
            filter: FootprintFilter::Gaussian,
            k: Vec::new(),
            gains: Vec::new(),
        })
    };
}

/// Runs `f` with the gains of `octets` at `footprint_m` (from this thread's cache when the same
/// octets asked for the same footprint last).
fn with_gains<R>(octets: &[Octet], footprint_m: f64, filter: FootprintFilter, f: impl FnOnce(&[f32x8]) -> R) -> R {
    GAIN_CACHE.with_borrow_mut(|c| {
        let hit = c.footprint_bits == footprint_m.to_bits()
            && c.filter == filter
            && c.k.len() == octets.len()
            && c.k.iter().zip(octets).all(|(k, o)| k.simd_eq(o.k).all());
        if !hit {
            c.footprint_bits = footprint_m.to_bits();
            c.filter = filter;
            c.k.clear();
            c.k.extend(octets.iter().map(|o| o.k));
            c.gains.clear();
            c.gains.extend(octets.iter().map(|o| o.gain(footprint_m, filter)));
        }
        f(&c.gains)
    })
}

impl Octet {
    /// The phases `k·u − ωt + φ₀` at `(u, t)`, reduced by whole turns in f64 (exact to ~10⁻¹² rad
    /// at 10⁵ rad) and then rounded to f32.
    #[inline]
    fn reduced_phase(&self, u: DVec2, t: f64) -> f32x8 {
        let mut reduced = [0.0f32; 8];
        for (l, x) in reduced.iter_mut().enumerate() {
            let phi = self.kx[l] * u.x + self.kz[l] * u.y - self.omega[l] * t + self.phase[l];
            *x = (phi - std::f64::consts::TAU * round_to_integer(phi * (1.0 / std::f64::consts::TAU))) as f32;
        }
        f32x8::new(reduced)
    }

    /// The footprint gains of the octet's waves in f32.
    #[inline]
    fn gain(&self, footprint_m: f64, filter: FootprintFilter) -> f32x8 {
        let (zero, s) = (f32x8::ZERO, f32x8::splat(footprint_m as f32));
        match filter {
            FootprintFilter::Gaussian => {
                let ks = self.k * s;
                let e = (f32x8::splat(-0.5) * ks * ks).exp();
                e.simd_lt(f32x8::splat(MIN_GAIN as f32)).select(zero, e)
            }
            FootprintFilter::Sharp => (self.k * s).simd_lt(f32x8::ONE).select(f32x8::ONE, zero),
        }
    }

    pub(super) fn new(terms: &[WaveTerm]) -> Self {
        let wide = |f: &dyn Fn(&WaveTerm) -> f64| [0, 1, 2, 3, 4, 5, 6, 7].map(|l| terms.get(l).map_or(0.0, f));
        let narrow = |f: &dyn Fn(&WaveTerm) -> f64| f32x8::new(wide(f).map(|x| x as f32));
        Self {
            kx: wide(&|t| t.kx),
            kz: wide(&|t| t.kz),
            omega: wide(&|t| t.omega),
            phase: wide(&|t| t.phase),
            a: narrow(&|t| t.a),
            k: narrow(&|t| t.k),
            dd: [0, 1, 2].map(|j| narrow(&|t| t.dd[j])),
            vv: [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)].map(|(i, j)| narrow(&|t| t.v[i] * t.v[j])),
            harm: [0, 1, 2, 3].map(|j| narrow(&|t| t.harm[j])),
        }
    }
}

impl JacobianStatistics {
    /// The per-wave phase advance `δᵢ = (ωᵢ − kᵢd̂ᵢ·v)Δt` of [`Self::mean_history`], as
    /// `(cos δᵢ, sin δᵢ)` in lanes: computed once per memory lattice and drift.
    ///
    /// # Arguments
    /// - `step_s`: `Δt` (s), `> 0`; `drift_m_s`: `v` (m s⁻¹).
    pub fn history_rotation(&self, step_s: f64, drift_m_s: DVec2) -> HistoryRotation {
        let rot = self
            .octets
            .iter()
            .map(|o| {
                let d = [0, 1, 2, 3, 4, 5, 6, 7]
                    .map(|l| (o.omega[l] - (o.kx[l] * drift_m_s.x + o.kz[l] * drift_m_s.y)) * step_s);
                (f32x8::new(d.map(|x| x.cos() as f32)), f32x8::new(d.map(|x| x.sin() as f32)))
            })
            .collect();
        HistoryRotation { step_s, drift_m_s, rot }
    }

    /// Footprint means `μⱼ` of `J` at evenly spaced past instants along a drifting path: the
    /// memory of the whitecaps that foam keeps (brine-foam `FoamMemory`).
    ///
    /// Instant `j` is `tⱼ = t₀ − jΔt` at the rest position `uⱼ = u₀ − v jΔt`, so every phase
    /// advances by a constant `δᵢ = (ωᵢ − kᵢd̂ᵢ·v)Δt` from one instant to the next: each wave's
    /// cosine is computed once and then rotated by `rotation` ([`Self::history_rotation`]), in
    /// `f32` lanes of eight waves. `μⱼ` is the determinant of the footprint-filtered sums, as in
    /// [`Self::moments_at`] (the footprint variance `σ²` is not repeated: the caller keeps the
    /// present one). Rounding: below `10⁻⁵` over 64 instants (test
    /// `the_history_follows_the_moments_along_the_path`).
    ///
    /// # Arguments
    /// - `u0`: rest position of instant 0 (m); `t0`: its time (s).
    /// - `rotation`: the lattice's step and drift, precomputed.
    /// - `footprint_m`, `filter`: as [`Self::moments_from_cosines`].
    /// - `out`: receives `μⱼ` for `j < out.len()` (at most 64 instants; dimensionless).
    ///
    /// # References
    /// Dupuy & Bruneton 2012 (footprint means); as [`Self::moments_from_cosines`].
    pub fn mean_history(
        &self,
        u0: DVec2,
        t0: f64,
        rotation: &HistoryRotation,
        footprint_m: f64,
        filter: FootprintFilter,
        out: &mut [f64],
    ) {
        debug_assert!(footprint_m >= 0.0 && rotation.rot.len() == self.octets.len());
        let n = self.active_count(footprint_m, filter);
        let octets = &self.octets[..n.div_ceil(8)];
        with_gains(octets, footprint_m, filter, |gains| {
            HistorySums::with(out.len(), |history| {
                for (j, ((o, &turn), &gain)) in octets.iter().zip(&rotation.rot).zip(gains).enumerate() {
                    let (sn, c) = o.reduced_phase(u0, t0).sin_cos();
                    history.add(o.a * live_lanes(j, n) * gain, o, (c, sn), turn);
                }
                history.finish(out);
            })
        });
    }

    /// [`Self::moments_at`] in `f32` lanes, eight waves at a time: the renderer's route (about
    /// twice as fast on the SSE2 baseline). Each phase is formed and reduced to `[−π, π]` in
    /// `f64`, then its cosine, the gains and the sums run in `f32`; `μ` and `σ²` are within
    /// [`F32_MOMENTS_ERROR`] of [`Self::moments_at`] (test `f32_moments_match_the_f64_ones`),
    /// below the `1.5×10⁻⁷` of the Abramowitz–Stegun `erf` the renderer reads the coverage with.
    ///
    /// # Arguments
    /// As [`Self::moments_at`].
    ///
    /// # Returns
    /// [`Moments`] `(μ, σ²)`.
    ///
    /// # References
    /// As [`Self::moments_from_cosines`].
    pub fn moments_at_f32(&self, u: DVec2, t: f64, footprint_m: f64, filter: FootprintFilter) -> Moments {
        debug_assert!(footprint_m >= 0.0);
        let n = self.active_count(footprint_m, filter);
        let mut present = PresentSums::default();
        let octets = &self.octets[..n.div_ceil(8)];
        with_gains(octets, footprint_m, filter, |gains| {
            for (j, (o, &gain)) in octets.iter().zip(gains).enumerate() {
                let cos = o.reduced_phase(u, t).cos();
                present.add(o, live_lanes(j, n), gain, cos);
            }
        });
        present.finish(&self.tail[n])
    }

    /// [`Self::moments_at_f32`] at `(u, t)` and [`Self::mean_history`] from the lattice instant
    /// `t₀ = t − a₀` at `u₀ = u − v a₀` in one pass: each wave's phase, cosine, sine and gain are
    /// computed once, and the history's first phase is the present one advanced by
    /// `(ωᵢ − kᵢd̂ᵢ·v) a₀` (`offset`, [`Self::history_rotation`] of `a₀`) before the lattice's
    /// rotations. Within `f32` rounding of the two separate calls (test
    /// `the_fused_history_matches_the_separate_calls`).
    ///
    /// # Arguments
    /// - `u`, `t`, `footprint_m`, `filter`: as [`Self::moments_at`].
    /// - `start`: the rotation by the age `a₀ ≥ 0` of instant 0 (with the lattice's drift) and the
    ///   lattice's own ([`HistoryStart`]).
    /// - `out`: receives `μⱼ`, as [`Self::mean_history`].
    ///
    /// # Returns
    /// [`Moments`] `(μ, σ²)` at `(u, t)`.
    pub fn moments_and_history_f32(
        &self,
        u: DVec2,
        t: f64,
        footprint_m: f64,
        filter: FootprintFilter,
        start: &HistoryStart<'_>,
        out: &mut [f64],
    ) -> Moments {
        let HistoryStart { offset, rotation } = *start;
        debug_assert!(footprint_m >= 0.0);
        debug_assert!(rotation.rot.len() == self.octets.len() && offset.rot.len() == self.octets.len());
        let n = self.active_count(footprint_m, filter);
        let mut present = PresentSums::default();
        let octets = &self.octets[..n.div_ceil(8)];
        with_gains(octets, footprint_m, filter, |gains| {
            HistorySums::with(out.len(), |history| {
                for (j, (((o, &turn), &(c0, s0)), &gain)) in
                    octets.iter().zip(&rotation.rot).zip(&offset.rot).zip(gains).enumerate()
                {
                    let (sin, cos) = o.reduced_phase(u, t).sin_cos();
                    let live = live_lanes(j, n);
                    present.add(o, live, gain, cos);
                    // The history: from the present phase advanced by the age of instant 0.
                    history.add(o.a * live * gain, o, (cos * c0 - sin * s0, sin * c0 + cos * s0), turn);
                }
                history.finish(out);
            })
        });
        present.finish(&self.tail[n])
    }
}

/// Largest difference between [`JacobianStatistics::moments_at_f32`] and
/// [`JacobianStatistics::moments_at`] in `μ` and `σ²`, for sets with `Σ Qᵢ ≤ 1`: the f32 phase
/// rounds by ≤ 2.4×10⁻⁷ rad (half an ulp at π) and its cosine adds ~10⁻⁷, so each term of `μ`
/// moves by ≤ 4×10⁻⁷ of its `|aᵢ dᵢ|`, whose sum is at most `Σ Qᵢ ≤ 1`; the f32 sums of up to a few
/// hundred such terms add ~10⁻⁷ more, and `σ²` (terms of `aᵢ²`) is smaller still.
pub const F32_MOMENTS_ERROR: f64 = 1e-6;

/// `x` rounded to the nearest integer without the `libm` call of `f64::round` on the SSE2
/// baseline (`|x| < 2⁵¹`; ties to even).
#[inline]
fn round_to_integer(x: f64) -> f64 {
    const MAGIC: f64 = 6_755_399_441_055_744.0; // 1.5·2⁵²
    (x + MAGIC) - MAGIC
}
