/// Two syntheses of the same trig polynomials (different packing): FFT rounding.
const SAME_FIELDS: f64 = 1e-12;

#[test]
fn the_jacobian_fields_are_those_of_the_full_synthesis() {
    let pm = crate::PiersonMoskowitz::from_u10(12.0).unwrap();
    let spreading = crate::CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let options = FftOptions { resolution: 64, ..FftOptions::for_spectrum(&pm, 2) };
    let ocean = FftOcean::new(&pm, &spreading, &options).unwrap();
    let full = ocean.rest_fields(3.7);
    let jac = ocean.rest_jacobian_fields(3.7, 0.0);
    assert_eq!(jac.len(), full.len());
    for (a, b) in full.iter().zip(&jac) {
        for i in 0..a.dxx.len() {
            assert!((a.dxx[i] - b.dxx[i]).abs() < SAME_FIELDS);
            assert!((a.dzz[i] - b.dzz[i]).abs() < SAME_FIELDS);
            assert!((a.dxz[i] - b.dxz[i]).abs() < SAME_FIELDS);
        }
    }
    // A footprint that washes out the second cascade's band keeps only the first.
    assert_eq!(ocean.rest_jacobian_fields(3.7, GAUSSIAN_KEEP / (ocean.band(1).0 * 0.99)).len(), 1);
    assert!(ocean.jacobian_variance_removed(0.0, 1.0).abs() < f64::MIN_POSITIVE);
}

use super::*;
use crate::Elfouhaily;

/// FFT rounding: ~10⁻¹⁵ of the sum of `|h̃|` times the largest factor (`k ≤ 0.6` rad/m here,
/// at most 1 for `D`); 10⁻¹² with margin for the `N log N` butterflies.
const FFT_ROUNDING_REL: f64 = 1e-12;

/// `ω/(2π/T)` of a looped mode is an integer up to the rounding of `ω` (~10⁻¹⁵ relative of
/// quotients up to ~10⁵).
const MULTIPLE_ABS: f64 = 1e-9;

/// Rounding of a frequency (rad/s, below 100).
const ROUND_ABS: f64 = 1e-12;

fn small_ocean(n: usize, loop_period: Option<f64>) -> FftOcean {
    let e = Elfouhaily::fully_developed(8.0).unwrap();
    let d = e.spreading(crate::Directions::Downwind);
    let options = FftOptions {
        resolution: n,
        tile_sizes: vec![300.0, 300.0 / 6.854_101_966_249_685],
        choppiness: 0.8,
        loop_period,
        seed: 9,
        wind_direction: 0.4,
        tiled: false,
    };
    FftOcean::new(&e, &d, &options).unwrap()
}

/// Direct evaluation of the trig polynomials at `(x, z)`:
/// `(h, ∂h/∂x, ∂h/∂z, Dₓ, D_z, ∂Dₓ/∂x, ∂D_z/∂z, ∂Dₓ/∂z)`.
fn direct(ocean: &FftOcean, c: usize, t: f64, x: f64, z: f64) -> [f64; 8] {
    let mut out = [0.0; 8];
    for ((kx, kz), (re, im)) in ocean.amplitudes_at(c, t) {
        let h = Complex64::new(re, im);
        let e = Complex64::from_polar(1.0, kx * x + kz * z);
        let v = h * e; // h̃ e^{ik·x}
        let iv = Complex64::new(-v.im, v.re);
        let k = (kx * kx + kz * kz).sqrt();
        out[0] += v.re;
        out[1] += (iv * kx).re;
        out[2] += (iv * kz).re;
        out[3] += (iv * (kx / k)).re;
        out[4] += (iv * (kz / k)).re;
        out[5] -= (v * (kx * kx / k)).re;
        out[6] -= (v * (kz * kz / k)).re;
        out[7] -= (v * (kx * kz / k)).re;
    }
    out
}

#[test]
fn fft_fields_equal_the_direct_trig_sums() {
    let ocean = small_ocean(64, None);
    let t = 3.7;
    let fields = ocean.rest_fields(t);
    for (c, f) in fields.iter().enumerate() {
        let dx = f.tile_size / f.resolution as f64;
        let scale: f64 = ocean.amplitudes_at(c, t).iter().map(|(_, (a, b))| a.hypot(*b)).sum::<f64>();
        for &(i, j) in &[(0usize, 0usize), (3, 17), (63, 5), (32, 40), (9, 62)] {
            let idx = j * 64 + i;
            let d = direct(&ocean, c, t, i as f64 * dx, j as f64 * dx);
            let got = [
                f.height[idx],
                f.slope_x[idx],
                f.slope_z[idx],
                f.displacement_x[idx],
                f.displacement_z[idx],
                f.dxx[idx],
                f.dzz[idx],
                f.dxz[idx],
            ];
            for q in 0..8 {
                assert!(
                    (got[q] - d[q]).abs() < FFT_ROUNDING_REL * scale,
                    "cascade {c} field {q} at ({i}, {j}): {} vs {}",
                    got[q],
                    d[q]
                );
            }
        }
    }
}

#[test]
fn seeding_is_keyed_by_the_wave_vector() {
    let a = small_ocean(64, None);
    let b = small_ocean(128, None);
    for c in 0..2 {
        for (nx, nz) in [(1, 0), (-3, 5), (7, -2), (0, 4)] {
            let (x, y) = (a.amplitude(c, nx, nz), b.amplitude(c, nx, nz));
            assert!(x == y, "cascade {c} ({nx}, {nz}): {x:?} vs {y:?}");
        }
    }
    assert!(word_position(1, 2) != word_position(2, 1) && word_position(-1, 0) != word_position(1, 0));
}

#[test]
fn looping_quantises_every_frequency() {
    let ocean = small_ocean(64, Some(40.0));
    let base = TAU / 40.0;
    for c in 0..2 {
        for m in &ocean.cascades[c].modes {
            let q = m.omega / base;
            assert!((q - q.round()).abs() < MULTIPLE_ABS && q >= 1.0 - ROUND_ABS);
            // Rounded to the nearest multiple (or 1): off by at most half a step.
            let exact = ocean.dispersion.omega(m.k);
            assert!((m.omega - exact).abs() <= 0.5 * base + ROUND_ABS || (m.omega - base).abs() < ROUND_ABS);
        }
    }
}

/// The loop's distortion counts the modes of every cascade: small for a loop far longer than the
/// sea's periods, most of the variance moved for one shorter than its peak period, and the
/// suggested period keeps at most 5 % of the variance moved by more than 5 %; without a loop
/// there is none.
#[test]
fn the_loop_distortion_counts_every_mode() {
    assert!(small_ocean(64, None).loop_distortion().is_none());
    // Elfouhaily's fully developed sea at 8 m/s: ω_p = 0.84 g/U ≈ 1.03 rad/s, a period of 6.1 s.
    let long = small_ocean(64, Some(2000.0));
    let d = long.loop_distortion().expect("a loop");
    // Every mode with a period under 400 s moves by at most P/(2T) ≤ 0.1; the tile's longest
    // wave (300 m: 13.9 s) by 0.35 %.
    assert!(d.rms() < 0.0035 && d.share_moved() == 0.0, "rms {}", d.rms());
    let short = small_ocean(64, Some(2.0));
    let d = short.loop_distortion().expect("a loop");
    assert!(d.rms() > 0.5 && d.share_moved() > 0.95, "rms {}, moved {}", d.rms(), d.share_moved());
    // The suggestion keeps 95 % of the variance within 5 %: ten times a period near the peak's.
    let p = d.suggested_period_s();
    assert!((40.0..200.0).contains(&p), "{p}");
    let again = small_ocean(64, Some(p));
    let moved = again.loop_distortion().expect("a loop").share_moved();
    assert!(moved <= 0.05 + 1e-12, "{moved}");
}

/// The shifted Jacobian fields hold, at grid point `p`, the direct trig sums at `p + shift`
/// (shifts of a fraction of a cell and of many tiles, so the reduction modulo the tile is used),
/// and a zero shift is the unshifted synthesis bit for bit.
#[test]
fn shifted_jacobian_fields_are_the_sea_moved() {
    let ocean = small_ocean(64, None);
    let t = 2.3;
    let plain = ocean.rest_jacobian_fields(t, 0.0);
    assert_eq!(ocean.rest_jacobian_fields_shifted(t, 0.0, [0.0, 0.0]), plain);
    for shift in [[0.37, -1.91], [1234.5, 987.6]] {
        let fields = ocean.rest_jacobian_fields_shifted(t, 0.0, shift);
        for (c, f) in fields.iter().enumerate() {
            let dx = f.tile_size / f.resolution as f64;
            let scale: f64 = ocean.amplitudes_at(c, t).iter().map(|(_, (a, b))| a.hypot(*b)).sum::<f64>();
            for &(i, j) in &[(0usize, 0usize), (3, 17), (63, 5), (32, 40)] {
                let idx = j * 64 + i;
                let d = direct(&ocean, c, t, i as f64 * dx + shift[0], j as f64 * dx + shift[1]);
                // The direct sum's phases reach k·1234 m ≈ 10³ rad: its own rounding, ~10⁻¹³ of
                // the scale, stays far below the tolerance.
                for (q, got) in [(5, f.dxx[idx]), (6, f.dzz[idx]), (7, f.dxz[idx])] {
                    assert!(
                        (got - d[q]).abs() < FFT_ROUNDING_REL * scale,
                        "shift {shift:?}, cascade {c} field {q} at ({i}, {j}): {got} vs {}",
                        d[q]
                    );
                }
            }
        }
    }
}

/// The power of each wave vector of a field on an `N × N` grid: `|Σ v(u) e^{−ik·u}|²`, indexed
/// as the field (`(n_z mod N)·N + (n_x mod N)`).
fn power(values: &[f64], n: usize) -> Vec<f64> {
    let fft = FftPlanner::new().plan_fft_forward(n);
    let mut data: Vec<Complex64> = values.iter().map(|&h| Complex64::new(h, 0.0)).collect();
    let mut scratch = vec![Complex64::ZERO; fft.get_inplace_scratch_len()];
    fft.process_with_scratch(&mut data, &mut scratch);
    transpose(&mut data, n);
    fft.process_with_scratch(&mut data, &mut scratch);
    transpose(&mut data, n);
    data.iter().map(|c| c.norm_sqr()).collect()
}

/// Checks one field of the band-limited sea against the whole sea's on a cascade's grid: no
/// power at wave vectors under `2Δ` (to `zero` of the field's total power), `w²` times the whole
/// sea's between `2Δ` and `3Δ`, the same from `3Δ` (to `rounding`). Returns the share of the
/// whole field's power left out.
fn check_band(
    whole: &[f64],
    limited: &[f64],
    n: usize,
    (tile, spacing): (f64, f64),
    (zero, rounding): (f64, f64),
) -> f64 {
    let (pa, pb) = (power(whole, n), power(limited, n));
    let total: f64 = pa.iter().sum();
    let signed = |i: usize| if i <= n / 2 { i as f64 } else { i as f64 - n as f64 };
    let mut removed = 0.0;
    for (i, (&x, &y)) in pa.iter().zip(&pb).enumerate() {
        let k = TAU / tile * signed(i % n).hypot(signed(i / n));
        let wavelength = if k > 0.0 { TAU / k } else { f64::INFINITY };
        let w = brine_core::footprint::footprint_weight(wavelength, 2.0 * spacing);
        assert!((y - w * w * x).abs() <= rounding * total, "a mode of {wavelength} m: {y} against {w}² × {x}");
        if wavelength <= 2.0 * spacing {
            assert!(y <= zero * total, "a mode of {wavelength} m kept: {y} of {total}");
            removed += x / total;
        }
    }
    removed
}

/// A grid of spacing `Δ` cannot carry a mode shorter than `2Δ` (sampled, it would read as a
/// longer wave of another direction). The sea synthesised for such a grid has no power at those
/// wave vectors in any cascade, `w²` times the whole sea's between `2Δ` and `3Δ`, the modes of
/// `3Δ` and longer as the whole sea has them — in its surface and in its particles' motion —
/// and on a grid finer than every mode it is the whole sea, to the bit.
#[test]
fn the_sea_on_a_grid_holds_no_mode_the_grid_cannot_carry() {
    /// Power left at a left-out mode, relative to the field's total: the FFT's rounding of
    /// the other modes (amplitudes rounded at 10⁻¹⁶–10⁻¹³ relative, squared).
    const LEFT_OUT: f64 = 1e-20;
    /// The same for fields stored in f32 (values rounded at 6×10⁻⁸ relative: the noise's power
    /// per bin is about 10⁻¹⁵/N² of the total; 10⁻¹² with margin).
    const F32_LEFT_OUT: f64 = 1e-12;
    /// Difference of a kept mode's power for f32 fields (its amplitude rounded at 6×10⁻⁸
    /// relative, against the total).
    const F32_ROUNDING: f64 = 1e-9;
    let pm = crate::PiersonMoskowitz::from_u10(12.0).unwrap();
    let spreading = crate::CosineTwoS::hasselmann(pm.peak_omega()).unwrap();
    let options = FftOptions { resolution: 64, ..FftOptions::for_spectrum(&pm, 2) };
    let ocean = FftOcean::new(&pm, &spreading, &options).unwrap();
    let full = ocean.rest_fields(3.7);
    let (same, band) = ocean.rest_fields_on_grid(3.7, 1e-4);
    assert_eq!((band.faded, band.lost_slope_covariance), (0, DVec3::ZERO));
    for (a, b) in full.iter().zip(&same) {
        assert!(a.height.iter().zip(&b.height).all(|(x, y)| x.to_bits() == y.to_bits()));
        assert!(a.dxx.iter().zip(&b.dxx).all(|(x, y)| x.to_bits() == y.to_bits()));
    }
    // Texels of four of the finer cascade's grid spacings: most of its modes are too short.
    let spacing = 4.0 * full[1].tile_size / full[1].resolution as f64;
    let (limited, band) = ocean.rest_fields_on_grid(3.7, spacing);
    assert!(band.faded > 100, "modes faded: {}", band.faded);
    let mut removed = 0.0;
    for (a, b) in full.iter().zip(&limited) {
        removed += check_band(&a.height, &b.height, a.resolution, (a.tile_size, spacing), (LEFT_OUT, FFT_ROUNDING_REL));
    }
    assert!(removed > 0.01, "the whole sea had little to leave out: {removed}");
    // The particles' displacement (f32 fields: their rounding, squared, against the total).
    let (whole_k, limited_k) = (ocean.kinematics(3.7), ocean.kinematics_on_grid(3.7, spacing));
    for (a, b) in whole_k.cascades.iter().zip(&limited_k.cascades) {
        let f64s = |v: &[f32]| v.iter().map(|&x| f64::from(x)).collect::<Vec<_>>();
        for (x, y) in [(&a.displacement_x, &b.displacement_x), (&a.height_rate, &b.height_rate)] {
            check_band(&f64s(x), &f64s(y), a.n, (a.tile, spacing), (F32_LEFT_OUT, F32_ROUNDING));
        }
    }
    // The slopes left out: the whole sea's mean slope products minus the limited sea's, each
    // cascade's over its own tile (Parseval), summed over the cascades.
    let mean_products = |fields: &[FftRestFields]| {
        fields.iter().fold(DVec3::ZERO, |a, f| {
            let n = f.slope_x.len() as f64;
            a + f.slope_x.iter().zip(&f.slope_z).fold(DVec3::ZERO, |b, (&x, &z)| b + DVec3::new(x * x, x * z, z * z))
                / n
        })
    };
    let lost = mean_products(&full) - mean_products(&limited);
    let scale = mean_products(&full).x + mean_products(&full).z;
    assert!(
        (lost - band.lost_slope_covariance).abs().max_element() < FFT_ROUNDING_REL * scale,
        "{lost} against {}",
        band.lost_slope_covariance
    );
}
