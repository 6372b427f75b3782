//! How much of a sea's slopes a handful of wave vectors hold: the lattice measure of a top-down
//! normal map.
//!
//! A sea of a few crossing waves shows its glitter as a lattice of glints; its slopes' 2-D power
//! spectrum is then a few spikes. The measure is the share of the slope power (both components,
//! mean removed) in the `2 · peaks` strongest bins of the 2-D spectrum of a square top-down map of
//! shading normals: a real field's spectrum is symmetric, so a wave that fits the map a whole
//! number of times is two bins, and the untapered share is that of its `peaks` strongest wave
//! vectors. Tapered (the resolved share), each wave vector spreads over 3 × 3 bins or more, so
//! the same bins hold fewer wave vectors.
//!
//! ```
//! use brine_testkit::lattice::{PeakShare, peak_share};
//! // One plane wave along x: all of its slope power in one wave vector.
//! let n = 32;
//! let normals: Vec<[f32; 3]> = (0..n * n)
//!     .map(|i| {
//!         let s = 0.1 * (std::f64::consts::TAU * 5.0 * (i % n) as f64 / n as f64).sin();
//!         [-(s as f32), 1.0, 0.0]
//!     })
//!     .collect();
//! let share = peak_share(&normals, n, &PeakShare { peaks: 1, resolved_cycles: None });
//! assert!((share - 1.0).abs() < 1e-9);
//! ```

use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;

/// What [`peak_share`] counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakShare {
    /// How many peaks count (`≥ 1`): the `2 · peaks` strongest bins.
    pub peaks: usize,
    /// `None`: the map as it is (the plain share). `Some(c)`: the map tapered by a Hann window
    /// (so that its edges leak no power) and only the wave vectors of at least `c` cycles across
    /// it counted (the resolved share): a wave longer than a few cycles of the view shows as a
    /// tilt or a bend of it, not as a wave vector the view can tell from its neighbours. `c` in
    /// `[0, n/√2]`: above it no bin is left and the share is 0.
    pub resolved_cycles: Option<f64>,
}

/// Share of the slope power in the strongest wave vectors of a top-down normal map.
///
/// The slopes are `(−nₓ/n_y, −n_z/n_y)` (`n_y` floored at 0.05), their means removed; the share is
/// `Σ_{2·peaks strongest bins} |Ŝₓ|² + |Ŝ_z|²` over the sum of all counted bins.
///
/// # Arguments
/// - `normals`: `n × n` normals `[nₓ, n_y, n_z]` (any length: only their ratios count), row after
///   row (y up).
/// - `n`: side of the map (pixels, `≥ 2`).
/// - `what`: the peaks and, for the resolved share, the fewest cycles.
///
/// # Returns
/// The share, `[0, 1]` (0 for a flat map).
///
/// # Panics
/// If `n < 2`, `normals.len() ≠ n²` or `what.peaks` is 0.
pub fn peak_share(normals: &[[f32; 3]], n: usize, what: &PeakShare) -> f64 {
    assert!(n >= 2 && normals.len() == n * n, "an n × n map, n ≥ 2");
    assert!(what.peaks >= 1, "at least one peak");
    let hann: Vec<f64> =
        (0..n).map(|i| 0.5 - 0.5 * (std::f64::consts::TAU * (i as f64 + 0.5) / n as f64).cos()).collect();
    let weight = |i: usize| if what.resolved_cycles.is_some() { hann[i % n] * hann[i / n] } else { 1.0 };
    let w_sum: f64 = (0..n * n).map(weight).sum();
    let fft = FftPlanner::new().plan_fft_forward(n);
    let mut power = vec![0.0; n * n];
    for component in [0usize, 2] {
        let slope: Vec<f64> = normals.iter().map(|a| -f64::from(a[component]) / f64::from(a[1].max(0.05))).collect();
        let mean = (0..n * n).map(|i| weight(i) * slope[i]).sum::<f64>() / w_sum;
        let mut grid: Vec<Complex64> = (0..n * n).map(|i| Complex64::new(weight(i) * (slope[i] - mean), 0.0)).collect();
        for row in grid.chunks_mut(n) {
            fft.process(row);
        }
        let mut column = vec![Complex64::ZERO; n];
        for x in 0..n {
            for y in 0..n {
                column[y] = grid[y * n + x];
            }
            fft.process(&mut column);
            for y in 0..n {
                power[y * n + x] += column[y].norm_sqr();
            }
        }
    }
    let cycles = |i: usize| {
        let f = |j: usize| if j <= n / 2 { j as f64 } else { j as f64 - n as f64 };
        f(i % n).hypot(f(i / n))
    };
    let mut counted: Vec<f64> = match what.resolved_cycles {
        None => power,
        Some(c) => power.into_iter().enumerate().filter(|&(i, _)| cycles(i) >= c).map(|(_, p)| p).collect(),
    };
    let total: f64 = counted.iter().sum();
    if total <= 0.0 {
        return 0.0;
    }
    counted.sort_by(|a, b| b.total_cmp(a));
    counted.iter().take(2 * what.peaks).sum::<f64>() / total
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A map of the slopes `s(x, z)` given as a function of the pixel.
    fn map(n: usize, s: impl Fn(f64, f64) -> (f64, f64)) -> Vec<[f32; 3]> {
        (0..n * n)
            .map(|i| {
                let (sx, sz) = s((i % n) as f64, (i / n) as f64);
                [-(sx as f32), 1.0, -(sz as f32)]
            })
            .collect()
    }

    #[test]
    fn two_waves_of_equal_slope_share_the_power() {
        // Two periodic waves: all the power in their two wave vectors, half in each.
        let n = 64;
        let tau = std::f64::consts::TAU;
        let m = map(n, |x, z| (0.1 * (tau * 3.0 * x / n as f64).cos(), 0.1 * (tau * 7.0 * z / n as f64).sin()));
        let one = peak_share(&m, n, &PeakShare { peaks: 1, resolved_cycles: None });
        let two = peak_share(&m, n, &PeakShare { peaks: 2, resolved_cycles: None });
        // f32 normals: the power outside the two waves is rounding, under 1e-12 of the total.
        assert!((one - 0.5).abs() < 1e-6, "{one}");
        assert!((two - 1.0).abs() < 1e-6, "{two}");
    }

    #[test]
    fn a_wave_of_few_cycles_is_not_resolved() {
        let n = 64;
        let tau = std::f64::consts::TAU;
        // A 2-cycle tilt and an 8-cycle wave of a tenth of its slope. Plain: the tilt holds
        // 100/101 of the power. Resolved: the Hann window spreads each wave vector over the 3 × 3
        // bins around it (the centre 4/9 of its power) and the tilt's block lies under 4 cycles,
        // so the 8-cycle wave's 9 wave vectors hold all that is counted.
        let m = map(n, |x, _| (0.1 * (tau * 2.0 * x / n as f64).sin() + 0.01 * (tau * 8.0 * x / n as f64).sin(), 0.0));
        let plain = peak_share(&m, n, &PeakShare { peaks: 1, resolved_cycles: None });
        let centre = peak_share(&m, n, &PeakShare { peaks: 1, resolved_cycles: Some(4.0) });
        let block = peak_share(&m, n, &PeakShare { peaks: 9, resolved_cycles: Some(4.0) });
        assert!((plain - 100.0 / 101.0).abs() < 1e-6, "{plain}");
        assert!((centre - 4.0 / 9.0).abs() < 1e-6, "{centre}");
        assert!((block - 1.0).abs() < 1e-6, "{block}");
    }

    #[test]
    fn a_flat_map_has_no_peaks() {
        let m = vec![[0.0, 1.0, 0.0]; 16 * 16];
        assert!(peak_share(&m, 16, &PeakShare { peaks: 20, resolved_cycles: None }) == 0.0, "a flat map");
    }
}
