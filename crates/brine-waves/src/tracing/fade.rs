//! Footprint fading of single waves: when a pixel's footprint reaches a wave's length, and the
//! slopes the wave then hands to the BRDF.

use brine_core::footprint::footprint_stretch_squared;
use glam::DVec3;

/// Fade distance of a wave of wave vector `(kx, kz)` for a ray of unit direction `d` and a pixel
/// of `footprint_angle` rad: `T = 2π/(α √(k² + σ²/max(|d_y|, 0.05)²))`, `σ = k·d̂_xz`. The pixel footprint on
/// the sea is `αt` across the view and `αt/max(|d_y|, 0.05)` along it, so its extent along the wave's
/// direction is `αt √(1 + (k̂·d̂_xz)²/max(|d_y|, 0.05)²)`; the wave fades when that reaches its wavelength.
pub(crate) fn wave_fade_distance(kx: f64, kz: f64, d: DVec3, footprint_angle: f64) -> f64 {
    let k2 = kx * kx + kz * kz;
    let sigma = kx * d.x + kz * d.z;
    std::f64::consts::TAU / (footprint_angle * (k2 + sigma * sigma * footprint_stretch_squared(d.y)).sqrt())
}

/// World-axes slope covariance `(xx, xz, zz)` of one linear wave `A cos(k·x + φ)` over its phase:
/// `½(kA)² (k̂ₓ², k̂ₓk̂_z, k̂_z²)` = `½A² (kₓ², kₓk_z, k_z²)`.
pub(crate) fn slope_covariance(kx: f64, kz: f64, amplitude: f64) -> DVec3 {
    0.5 * amplitude * amplitude * DVec3::new(kx * kx, kx * kz, kz * kz)
}
