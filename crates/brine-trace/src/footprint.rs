//! Footprint fading: components smaller than a pixel's footprint leave the traced surface.

use glam::DVec3;

use crate::LipschitzSum;
pub use brine_core::footprint::{FADE_CURVATURE, FADE_SLOPE, footprint_weight, footprint_weight_slope};

/// The fade weights of every component of `surface` at a hit `t` along a ray of direction `d̂`:
/// what the tracer dropped or faded, so that a renderer can move the missing slopes into its
/// BRDF (Bruneton et al. 2010). All weights are 1 when `footprint_angle` is 0.
///
/// `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` ([`footprint_weight`]) with `Tᵢ` =
/// [`LipschitzSum::component_fade_distance`]: the surface the tiered method traces (and on which
/// its hit lies) is `Σᵢ wᵢ(t) nᵢ(p)`, with the weights of the distance `t` of each point along the
/// ray.
///
/// # Arguments
/// - `surface`: the traced function.
/// - `direction`: the unit ray direction.
/// - `footprint_angle`: the option used to trace (rad), `≥ 0`.
/// - `t`: the hit distance (m), `≥ 0`.
///
/// # Returns
/// `wᵢ ∈ [0, 1]` for each component, non-increasing in `t`.
///
/// # References
/// docs/equations.md §1 "Antialiasing" and §11; Bruneton, Neyret & Holzschuch 2010 (§4: the
/// geometry's lost slopes move into the BRDF).
pub fn component_weights<S: LipschitzSum + ?Sized>(
    surface: &S,
    direction: DVec3,
    footprint_angle: f64,
    t: f64,
) -> Vec<f64> {
    (0..surface.component_count())
        .map(|i| {
            if footprint_angle > 0.0 {
                footprint_weight(surface.component_fade_distance(i, direction, footprint_angle), t)
            } else {
                1.0
            }
        })
        .collect()
}

/// Which components footprint fading removed from the traced surface at one point of a ray.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FadedComponents {
    /// Components with weight 0: dropped from the traced surface altogether (their footprint
    /// `t ≥ Tᵢ` exceeds their feature size), in increasing index order.
    pub dropped: Vec<usize>,
    /// Components with a weight in `(0, 1)`: partly faded (`Tᵢ/1.5 < t < Tᵢ`), in increasing index
    /// order. Every other component is traced whole.
    pub fading: Vec<usize>,
}

/// The components that footprint fading dropped or faded at a hit `t`: the tracer's report of
/// which waves it left out, so that a renderer can move them into its BRDF roughness. A partition of the weights of [`component_weights`].
///
/// # Arguments
/// - `surface`: the traced function.
/// - `direction`: the unit ray direction (as traced).
/// - `footprint_angle`: the option used to trace (rad), `≥ 0`; `0` gives empty lists.
/// - `t`: the hit distance (m), `≥ 0`.
///
/// # Returns
/// The indices with `wᵢ(t) = 0` and those with `0 < wᵢ(t) < 1`.
///
/// # References
/// Bruneton, Neyret & Holzschuch 2010 (seamless transition from geometry to BRDF); docs/equations.md
/// §11.
pub fn faded_components<S: LipschitzSum + ?Sized>(
    surface: &S,
    direction: DVec3,
    footprint_angle: f64,
    t: f64,
) -> FadedComponents {
    let mut out = FadedComponents::default();
    for (i, w) in component_weights(surface, direction, footprint_angle, t).into_iter().enumerate() {
        if w <= 0.0 {
            out.dropped.push(i);
        } else if w < 1.0 {
            out.fading.push(i);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The weights at the ends of the transition come from exact branches (the early return 1, or
    /// `u = 0`); 10⁻¹⁵ (about 4.5 ulps of 1) only allows for rounding.
    const END_WEIGHT: f64 = 1e-15;

    /// At `T/t = 1.25` the smoothstep is at `u = 1/2`, `S = 1/2`, every step exact in binary;
    /// 10⁻¹² is a rounding allowance only.
    const MID_WEIGHT: f64 = 1e-12;

    #[test]
    fn weight_is_one_near_zero_far_and_smooth_between() {
        assert!((footprint_weight(15.0, 10.0) - 1.0).abs() < END_WEIGHT);
        assert!(footprint_weight(10.0, 10.0).abs() < END_WEIGHT);
        assert!((footprint_weight(12.5, 10.0) - 0.5).abs() < MID_WEIGHT);
        assert!((footprint_weight(f64::INFINITY, 1e9) - 1.0).abs() < END_WEIGHT);
    }

    /// The central difference at `h = 10⁻⁵` against `FADE_SLOPE/t` (0.64–0.96 here), relative: its
    /// truncation `h²|w‴|/6` is ≈ 10⁻¹⁰ (`|w‴| ≲ 6.4` on this grid, whose points stay ≥ 5.8×10⁻⁴
    /// from the two kinks where `w″` jumps) and its rounding `ε/h` ≈ 2×10⁻¹¹; 10⁻⁶ is a wide margin.
    const SLOPE_FD_REL: f64 = 1e-6;

    /// The second difference at `h = 10⁻⁵` against `FADE_CURVATURE/t²` (≥ 63/49 ≈ 1.3 here),
    /// relative: its rounding `4ε/h²` ≈ 9×10⁻⁶ absolute dominates (truncation `h²|w⁗|/12` is far
    /// smaller); 10⁻³ is a margin of about 100.
    const CURVATURE_FD_REL: f64 = 1e-3;

    /// The analytic slope against the central difference (per metre): truncation ≈ 10⁻¹⁰ and
    /// rounding ≈ 2×10⁻¹¹ as for [`SLOPE_FD_REL`]; 10⁻⁶ is a wide margin.
    const SLOPE_FD_ABS: f64 = 1e-6;

    #[test]
    fn slope_and_curvature_bounds_hold_on_a_fine_grid() {
        // Central differences of w(t) over the transition, against FADE_SLOPE/t and FADE_CURVATURE/t².
        let big_t = 7.0;
        for j in 1..4000 {
            let t = big_t / 1.5 + (big_t - big_t / 1.5) * j as f64 / 4000.0;
            let h = 1e-5;
            let d1 = (footprint_weight(big_t, t + h) - footprint_weight(big_t, t - h)) / (2.0 * h);
            let d2 = (footprint_weight(big_t, t + h) - 2.0 * footprint_weight(big_t, t)
                + footprint_weight(big_t, t - h))
                / (h * h);
            assert!(d1.abs() <= FADE_SLOPE / t * (1.0 + SLOPE_FD_REL), "t = {t}: {d1}");
            assert!(d2.abs() <= FADE_CURVATURE / (t * t) * (1.0 + CURVATURE_FD_REL), "t = {t}: {d2}");
            assert!((footprint_weight_slope(big_t, t) - d1).abs() < SLOPE_FD_ABS, "t = {t}");
        }
    }
}
