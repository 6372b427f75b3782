//! The directional wavenumber spectrum `Ψ(k)` of a one-sided `S(ω)` with a spreading `D(θ; ω)`,
//! and its integral over the wave-vector cells of an FFT grid.

use std::f64::consts::{PI, TAU};

use crate::{Spectrum, Spreading};

/// Directional wavenumber spectrum `Ψ(k, θ) = S(k) D(θ; ω(k)) / k` (m⁴): the elevation variance
/// per unit area `d²k = k dk dθ` of the wave-vector plane.
///
/// From the one-sided frequency spectrum `S(ω)` (m² s rad⁻¹) and a spreading `D(θ; ω)`
/// (rad⁻¹, `∫ D dθ = 1`): the change of variables `ω → k` gives `S(k) = S(ω(k)) dω/dk`
/// (m³ rad⁻¹, [`Spectrum::s_k`]) and the polar area element `k dk dθ` gives the `1/k`, so that
/// `∫∫ Ψ d²k = ∫∫ Ψ k dk dθ = ∫ S(k) dk = ∫ S(ω) dω = m₀`. For Elfouhaily's spectrum with its own
/// spreading (both ways) this is Eq. 67, `(1/2π) k⁻⁴ (B_l + B_h)(1 + Δ cos 2φ)`; for
/// [`crate::Phillips`] with [`crate::CosineSquared::both_ways`] it is Tessendorf's
/// `P_h(k) = A e^{−1/(kL)²}/k⁴ |k̂·ŵ|² e^{−k²ℓ²}` (both tested).
///
/// # Arguments
/// - `spectrum`: `S(ω)` and its dispersion relation.
/// - `spreading`: `D(θ; ω)`.
/// - `k`: wavenumber (rad m⁻¹), `> 0` (`0` returned otherwise).
/// - `theta`: angle of the wave vector from the mean wind direction (rad), any value (wrapped to
///   `(−π, π]`).
///
/// # Returns
/// `Ψ` (m⁴).
///
/// # References
/// docs/equations.md §4 ("Units … Change of variable"); Tessendorf 2001, §3.3 (`P_h` per `d²k`);
/// Elfouhaily et al. 1997, Eq. 67.
pub fn directional_spectrum(spectrum: &dyn Spectrum, spreading: &dyn Spreading, k: f64, theta: f64) -> f64 {
    if !(k > 0.0) {
        return 0.0;
    }
    let omega = spectrum.dispersion().omega(k);
    spectrum.s_k(k) * spreading.density(wrap_angle(theta), omega) / k
}

/// `θ` wrapped to `(−π, π]`.
pub(crate) fn wrap_angle(theta: f64) -> f64 {
    let w = theta - TAU * libm::round(theta / TAU);
    if w <= -PI { w + TAU } else { w }
}

/// A square ring of the wave-vector plane, `lo ≤ |k|_∞ < hi` (rad m⁻¹): the band a cascade holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Band {
    pub(crate) lo: f64,
    pub(crate) hi: f64,
}

impl Band {
    /// `true` if `(kx, kz)` lies in the band.
    #[inline]
    pub(crate) fn contains(&self, kx: f64, kz: f64) -> bool {
        let m = kx.abs().max(kz.abs());
        m >= self.lo && m < self.hi
    }
}

/// Gauss–Legendre nodes on `[−1, 1]` and weights, for 1, 2, 4 and 8 points.
const GL1: [(f64, f64); 1] = [(0.0, 2.0)];
const GL2: [(f64, f64); 2] = [(-0.577_350_269_189_625_8, 1.0), (0.577_350_269_189_625_8, 1.0)];
const GL4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];
const GL8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// Cells closer to the origin than this many cell widths (`|n|_∞`) get the 8×8 Gauss rule.
const FINE_INDEX: f64 = 16.0;
/// Cells closer than this get 4×4 points; farther ones 2×2 up to [`COARSE_INDEX`], then 1.
const MEDIUM_INDEX: f64 = 40.0;
/// Beyond this index a cell spans less than 1/64 of its wavenumber: the midpoint rule's relative
/// error, about `(Δk/k)²/24 ≈ 10⁻⁵` for a smooth power law, is enough.
const COARSE_INDEX: f64 = 64.0;

/// The variance `∫_{cell ∩ band} Ψ d²k` (m²) of the wave-vector cell centred on `(kx, kz)` of
/// width `dk` (rad m⁻¹), by Gauss–Legendre quadrature on each sub-rectangle cut by the band's
/// edges (so the bands of successive cascades partition the plane exactly, up to quadrature).
///
/// `psi(kx, kz)` is `Ψ` in Cartesian wave-vector coordinates (m⁴). The rule has 8×8, 4×4, 2×2 or
/// 1 point per piece by the cell's distance `|n|_∞` from the origin in cells (closer cells see
/// `Ψ` vary faster across them). Where the spreading jumps (a down-wind fold at `θ_w ± π/2`,
/// Hasselmann's `s` at the peak) the rule loses its order; the error measured against a polar
/// quadrature stays below `10⁻⁴` of the band (tests/fft.rs).
pub(crate) fn cell_energy(psi: &impl Fn(f64, f64) -> f64, kx: f64, kz: f64, dk: f64, band: Band) -> f64 {
    let half = 0.5 * dk;
    let index = kx.abs().max(kz.abs()) / dk;
    let rule: &[(f64, f64)] = if index < FINE_INDEX {
        &GL8
    } else if index < MEDIUM_INDEX {
        &GL4
    } else if index < COARSE_INDEX {
        &GL2
    } else {
        &GL1
    };
    let cuts = |c: f64| {
        let mut v = [c - half, 0.0, 0.0, 0.0, 0.0, c + half];
        let mut n = 1;
        for e in [-band.hi, -band.lo, band.lo, band.hi] {
            if e > c - half && e < c + half {
                v[n] = e;
                n += 1;
            }
        }
        v[n] = c + half;
        v[..=n].sort_by(f64::total_cmp);
        (v, n + 1)
    };
    let (xs, nx) = cuts(kx);
    let (zs, nz) = cuts(kz);
    let mut total = 0.0;
    for a in 0..nx - 1 {
        let (x0, x1) = (xs[a], xs[a + 1]);
        for b in 0..nz - 1 {
            let (z0, z1) = (zs[b], zs[b + 1]);
            if !(x1 > x0 && z1 > z0 && band.contains(0.5 * (x0 + x1), 0.5 * (z0 + z1))) {
                continue;
            }
            let (cx, hx, cz, hz) = (0.5 * (x0 + x1), 0.5 * (x1 - x0), 0.5 * (z0 + z1), 0.5 * (z1 - z0));
            let mut s = 0.0;
            for &(u, wu) in rule {
                for &(v, wv) in rule {
                    s += wu * wv * psi(cx + hx * u, cz + hz * v);
                }
            }
            total += s * hx * hz;
        }
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CosineSquared, Elfouhaily, Phillips};

    /// Two routes through the same closed forms; the spreading's `Δ(k(ω(k)))` round trip through
    /// the capillary–gravity dispersion is exact to 10⁻¹⁴ (Newton).
    const TWO_ROUTES_REL: f64 = 1e-12;

    /// Gauss–Legendre on a quadratic is exact: rounding of a few terms of order 0.2; angle
    /// wrapping of `±3π`: a few ulp of π.
    const ROUND_ABS: f64 = 1e-14;

    #[test]
    fn change_of_variables_reproduces_elfouhaily_eq_67() {
        let e = Elfouhaily::from_fetch(10.0, 1e5).unwrap();
        let d = e.spreading(crate::Directions::BothWays);
        for k in [0.03, 0.07, 0.5, 4.0, 90.0, 400.0, 2000.0] {
            for phi in [-3.0, -1.2, 0.0, 0.4, 1.57, 2.9] {
                let a = directional_spectrum(&e, &d, k, phi);
                let b = e.directional(k, phi);
                assert!((a / b - 1.0).abs() < TWO_ROUTES_REL, "k = {k}, φ = {phi}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn change_of_variables_reproduces_tessendorf_phillips() {
        let p = Phillips::from_wind(12.0).unwrap();
        let d = CosineSquared::both_ways();
        for k in [0.01, 0.1, 1.0, 10.0] {
            for th in [-2.0, 0.0, 0.7] {
                let a = directional_spectrum(&p, &d, k, th);
                let b = p.directional(k, th);
                assert!((a - b).abs() <= TWO_ROUTES_REL * b.abs() + f64::MIN_POSITIVE, "k = {k}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn cell_quadrature_is_exact_for_polynomials_and_splits_at_the_band() {
        // A quadratic Ψ over a cell cut by the band edge: the pieces integrate exactly.
        let psi = |x: f64, z: f64| 1.0 + x * x + 0.5 * z;
        let band = Band { lo: 0.95, hi: 10.0 };
        // Cell [0.9, 1.1] × [−0.1, 0.1]: only x ≥ 0.95 counts (|k|_∞ = x there).
        let got = cell_energy(&psi, 1.0, 0.0, 0.2, band);
        let exact = |x: f64| (x + x * x * x / 3.0) * 0.2; // ∫ over z of (1 + x² + z/2) = 0.2(1 + x²)
        let want = exact(1.1) - exact(0.95);
        assert!((got - want).abs() < ROUND_ABS, "{got} vs {want}");
        assert!((wrap_angle(3.0 * PI) - PI).abs() < ROUND_ABS && (wrap_angle(-PI) - PI).abs() < ROUND_ABS);
    }
}
