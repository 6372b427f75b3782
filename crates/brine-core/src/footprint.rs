//! Footprint fading: a component smaller than a pixel's footprint leaves the traced surface
//! smoothly, over a distance along the ray (shared by the tracer and the surfaces that fade
//! their own waves).

/// Bound of `|dw/dt|·t` for `w(t) = smoothstep(1, 1.5, T/t)`: `|S'| ≤ 3` per unit of `T/t`, and
/// `|d(T/t)/dt| = (T/t)/t ≤ 1.5/t` where `w` varies.
pub const FADE_SLOPE: f64 = 4.5;

/// Bound of `|d²w/dt²|·t²` for the same `w`: `|S''| ≤ 24` and `(T/t)² ≤ 2.25` give 54, plus
/// `|S'|·|d²(T/t)/dt²| ≤ 3·3` gives 9.
pub const FADE_CURVATURE: f64 = 63.0;

/// The fade weight of a component at distance `t` along a ray, `w = smoothstep(1, 1.5, T/t)`.
///
/// `w = 0` for `t ≥ T` (the footprint exceeds the component's size: dropped), `w = 1` for
/// `t ≤ T/1.5` (kept whole), `3u² − 2u³` with `u = (T/t − 1)/0.5` between.
///
/// # Arguments
/// - `fade_distance`: `T` (m), `(0, ∞]`: the distance at which the component's size equals the
///   pixel footprint (brine-trace `LipschitzSum::component_fade_distance`).
/// - `t`: distance along the ray (m), `≥ 0`.
///
/// # Returns
/// The weight, `[0, 1]`.
///
/// # References
/// docs/equations.md §1 "Antialiasing" and §11 (Bruneton, Neyret & Holzschuch 2010, `nyquistMin` =
/// 1, `nyquistMax` = 1.5); Darles et al. 2007 §3.2 (amplitudes reduced with the pixel footprint).
#[inline]
pub fn footprint_weight(fade_distance: f64, t: f64) -> f64 {
    if t <= 0.0 || fade_distance >= 1.5 * t {
        return 1.0;
    }
    let u = ((fade_distance / t - 1.0) * 2.0).clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

/// Derivative `dw/dt` of [`footprint_weight`] (per metre).
#[inline]
pub fn footprint_weight_slope(fade_distance: f64, t: f64) -> f64 {
    if t <= 0.0 || fade_distance >= 1.5 * t || fade_distance <= t {
        return 0.0;
    }
    let x = fade_distance / t;
    let u = (x - 1.0) * 2.0;
    // dS/du · du/dx · dx/dt = 6u(1 − u) · 2 · (−x/t).
    -12.0 * u * (1.0 - u) * x / t
}
