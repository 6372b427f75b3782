//! The sine-wave sea of Chen et al. (2007), with bump-mapped detail normals.

use glam::{DVec2, DVec3};

use crate::tracing::lanes;
use crate::{TrochoidSet, WaveSurface};

/// Waves as structure-of-arrays: wave vector, frequency, phase, amplitude.
#[derive(Debug, Clone, PartialEq, Default)]
struct Waves {
    kx: Vec<f64>,
    kz: Vec<f64>,
    omega: Vec<f64>,
    phase: Vec<f64>,
    amplitude: Vec<f64>,
}

impl Waves {
    fn push(&mut self, w: &crate::Trochoid) {
        let d = w.direction_vector();
        self.kx.push(w.wavenumber() * d.x);
        self.kz.push(w.wavenumber() * d.y);
        self.omega.push(w.omega());
        self.phase.push(w.phase());
        self.amplitude.push(w.amplitude());
    }

    fn offsets(&self, t: f64) -> Vec<f64> {
        self.omega.iter().zip(&self.phase).map(|(w, p)| p - w * t).collect()
    }

    /// `(h, ∇h)` of `Σ Aᵢ cos(kᵢ·x + offᵢ)`.
    fn height_gradient(&self, off: &[f64], x: f64, z: f64) -> (f64, DVec2) {
        let (mut h, mut g) = (0.0, DVec2::ZERO);
        for (((&kx, &kz), &a), &o) in self.kx.iter().zip(&self.kz).zip(&self.amplitude).zip(off) {
            let (sn, c) = (kx * x + kz * z + o).sin_cos();
            h += a * c;
            g -= a * sn * DVec2::new(kx, kz);
        }
        (h, g)
    }
}

/// The sine-wave surface of Chen et al. (2007, §3.3), after Finch (2004): a sum of sinusoids
/// displaces a coarse mesh, and finer sinusoids only perturb the shading normal (a bump map).
///
/// Geometry `h(x, z, t) = Σᵢ Aᵢ cos(kᵢ d̂ᵢ·(x, z) − ωᵢ t + φᵢ)` (Chen and Finch write `sin`, the
/// same with `φᵢ` shifted by `π/2`); detail `h_d` likewise over the detail waves. Heights lie in
/// `±Σ Aᵢ`, slopes are at most `Σ kᵢAᵢ`. Points do not move sideways: displacement 0, Jacobian 1;
/// the particle velocity is the linear (Airy, deep-water) orbital velocity
/// `Σ (Aᵢωᵢ d̂ᵢ cos φᵢ, Aᵢωᵢ sin φᵢ)`.
///
/// [`SineSet::shading_normal`] rotates the detail normal `(−∇h_d, 1)` from the tangent frame of the
/// geometric surface (`B ∝ (1, ∂h/∂x, 0)`, `T ∝ (0, ∂h/∂z, 1)`, `N ∝ (−∂h/∂x, 1, −∂h/∂z)`), as
/// Finch's vertex shader does. With `Qᵢ → 0` the trochoid sum tends to this surface.
///
/// Chen et al.'s artist height map (wave height varying across the sea) is not modelled.
///
/// # References
/// Chen H., Li Q., Wang G., Zhou F., Tang X., Yang K. 2007, "An efficient method for real-time
/// ocean simulation", Edutainment, LNCS 4469, §3.3; Finch M. 2004, "Effective water simulation
/// from physical models", GPU Gems ch. 1, Eq. 1–6; Blinn J. 1978, "Simulation of wrinkled
/// surfaces" (bump mapping).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SineSet {
    geometry: Waves,
    detail: Waves,
    pub(crate) total_amplitude: f64,
    total_slope: f64,
}

impl SineSet {
    /// Every wave of `set` as geometry (amplitudes, wave vectors, frequencies and phases; the
    /// steepnesses are ignored).
    pub fn new(set: &TrochoidSet) -> Self {
        Self::with_detail(set, &TrochoidSet::default())
    }

    /// `geometry` displaces the surface, `detail` only perturbs the shading normal.
    pub fn with_detail(geometry: &TrochoidSet, detail: &TrochoidSet) -> Self {
        let mut s = Self::default();
        for w in geometry.waves() {
            s.geometry.push(w);
            s.total_amplitude += w.amplitude();
            s.total_slope += w.wavenumber() * w.amplitude();
        }
        for w in detail.waves() {
            s.detail.push(w);
        }
        s
    }

    /// Waves of at least `min_geometry_wavelength_m` (m) displace the surface; shorter ones only
    /// perturb the normal (Chen's coarse mesh and bump map).
    pub fn split_at_wavelength(set: &TrochoidSet, min_geometry_wavelength_m: f64) -> Self {
        let (long, short): (Vec<_>, Vec<_>) =
            set.waves().iter().partition(|w| w.wavelength() >= min_geometry_wavelength_m);
        Self::with_detail(&TrochoidSet::new(long), &TrochoidSet::new(short))
    }

    /// Number of geometric waves.
    pub fn len(&self) -> usize {
        self.geometry.kx.len()
    }

    /// `true` without geometric waves.
    pub fn is_empty(&self) -> bool {
        self.geometry.kx.is_empty()
    }

    /// Number of detail (normal-only) waves.
    pub fn detail_len(&self) -> usize {
        self.detail.kx.len()
    }

    /// The surface frozen at time `t` (s).
    pub fn at_time(&self, t: f64) -> SineField<'_> {
        SineField { set: self, offset: self.geometry.offsets(t), detail_offset: self.detail.offsets(t) }
    }

    /// Shading normal with the detail waves' bump (unit, upward) at `(x, z, t)`.
    pub fn shading_normal(&self, x: f64, z: f64, t: f64) -> DVec3 {
        self.at_time(t).shading_normal(x, z)
    }
}

/// A [`SineSet`] frozen at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct SineField<'a> {
    set: &'a SineSet,
    offset: Vec<f64>,
    detail_offset: Vec<f64>,
}

impl SineField<'_> {
    /// The underlying set.
    pub fn set(&self) -> &SineSet {
        self.set
    }

    /// Number of geometric waves.
    pub fn len(&self) -> usize {
        self.set.len()
    }

    /// `true` without geometric waves.
    pub fn is_empty(&self) -> bool {
        self.set.is_empty()
    }

    /// Height of geometric wave `i` alone, `hᵢ = Aᵢ cos(kᵢ·x + offᵢ)`, `offᵢ = φᵢ − ωᵢt`.
    ///
    /// # Arguments
    /// - `i`: wave index, `< len()`.
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `hᵢ` (m), in `[−Aᵢ, Aᵢ]`.
    ///
    /// # References
    /// Chen et al. 2007, §3.3; Finch 2004, Eq. 1.
    #[inline]
    pub fn wave_height(&self, i: usize, x: f64, z: f64) -> f64 {
        let g = &self.set.geometry;
        g.amplitude[i] * (g.kx[i] * x + g.kz[i] * z + self.offset[i]).cos()
    }

    /// Phase `kᵢ·x + offᵢ` (rad) of geometric wave `i` at `(x, z)`.
    #[inline]
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    pub(crate) fn wave_phase(&self, i: usize, x: f64, z: f64) -> f64 {
        let g = &self.set.geometry;
        g.kx[i] * x + g.kz[i] * z + self.offset[i]
    }

    /// Amplitude `Aᵢ` (m), wavenumber vector `(kxᵢ, kzᵢ)` (rad m⁻¹) of geometric wave `i`.
    #[cfg_attr(not(feature = "tracing"), allow(dead_code))]
    pub(crate) fn wave(&self, i: usize) -> (f64, f64, f64) {
        let g = &self.set.geometry;
        (g.amplitude[i], g.kx[i], g.kz[i])
    }

    /// Height of the geometry, `h = Σ Aᵢ cos(kᵢ·x + offᵢ)`, one wave at a time.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `h` (m), in `[−ΣAᵢ, ΣAᵢ]`.
    ///
    /// # References
    /// Chen et al. 2007, §3.3; Finch 2004, Eq. 1.
    pub fn height(&self, x: f64, z: f64) -> f64 {
        (0..self.set.len()).map(|i| self.wave_height(i, x, z)).sum()
    }

    /// Height `h = Σ Aᵢ cos(kᵢ·x + offᵢ)`, four waves at a time in SIMD lanes (a cosine-only Taylor kernel
    /// on the reduced phase); equal to [`SineField::height`] to `~10⁻¹⁴ Σ Aᵢ`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `h` (m).
    ///
    /// # References
    /// Finch 2004, Eq. 1.
    pub fn height_lanes(&self, x: f64, z: f64) -> f64 {
        let g = &self.set.geometry;
        lanes::sine_height(&g.kx, &g.kz, &self.offset, &g.amplitude, x, z)
    }

    /// Heights at many points, each by [`SineField::height_lanes`].
    ///
    /// # Arguments
    /// - `xs`, `zs`: horizontal positions (m), equal lengths.
    /// - `out`: receives the heights (m), same length.
    ///
    /// # Panics
    /// If the three slices differ in length.
    ///
    /// # References
    /// docs/equations.md §1.
    pub fn heights(&self, xs: &[f64], zs: &[f64], out: &mut [f64]) {
        assert!(xs.len() == zs.len() && xs.len() == out.len(), "heights: slices differ in length");
        for ((o, &x), &z) in out.iter_mut().zip(xs).zip(zs) {
            *o = self.height_lanes(x, z);
        }
    }

    /// Gradient of the geometry, `∇h = −Σ Aᵢ kᵢ sin(kᵢ·x + offᵢ)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `∇h` (dimensionless), `|∇h| ≤ Σ kᵢAᵢ`.
    ///
    /// # References
    /// Finch 2004, Eq. 4–5.
    pub fn gradient(&self, x: f64, z: f64) -> DVec2 {
        self.set.geometry.height_gradient(&self.offset, x, z).1
    }

    /// Height of the geometry as a primary ray `t` metres along the unit direction `d` draws it,
    /// each wave weighted by the tracer's footprint weight `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` for a
    /// pixel of `footprint_angle` rad: `h = Σ wᵢAᵢ cos(kᵢ·x + offᵢ)` (`footprint_angle = 0` or
    /// `t = 0`: [`SineField::height`]). The detail waves are normals only, never height.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `d`: unit ray direction; `footprint_angle` (rad) `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// `h` (m), within `±Σ Aᵢ`.
    ///
    /// # References
    /// Finch 2004, Eq. 1; Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_height(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> f64 {
        if footprint_angle <= 0.0 || t <= 0.0 {
            return self.height(x, z);
        }
        let g = &self.set.geometry;
        let mut out = 0.0;
        for i in 0..g.kx.len() {
            let w = brine_core::footprint::footprint_weight(
                crate::tracing::fade::wave_fade_distance(g.kx[i], g.kz[i], d, footprint_angle),
                t,
            );
            if w > 0.0 {
                out += w * g.amplitude[i] * (g.kx[i] * x + g.kz[i] * z + self.offset[i]).cos();
            }
        }
        out
    }

    /// Gradient of the geometry at a primary hit `t` metres along the unit direction `d` for a
    /// pixel of `footprint_angle` rad, each wave weighted by the tracer's footprint weight
    /// `wᵢ = smoothstep(1, 1.5, Tᵢ/t)`: `∇h = −Σ wᵢAᵢkᵢ sin(kᵢ·x + offᵢ)` (`footprint_angle = 0` or
    /// `t = 0`: [`SineField::gradient`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `d`: unit ray direction; `footprint_angle` (rad) `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// `∇h` (dimensionless) of the surface that ray traced.
    ///
    /// # References
    /// Finch 2004, Eq. 4–5; Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_gradient(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> DVec2 {
        if footprint_angle <= 0.0 || t <= 0.0 {
            return self.gradient(x, z);
        }
        let g = &self.set.geometry;
        let mut out = DVec2::ZERO;
        for i in 0..g.kx.len() {
            let w = brine_core::footprint::footprint_weight(
                crate::tracing::fade::wave_fade_distance(g.kx[i], g.kz[i], d, footprint_angle),
                t,
            );
            if w > 0.0 {
                let sn = (g.kx[i] * x + g.kz[i] * z + self.offset[i]).sin();
                out -= w * g.amplitude[i] * sn * DVec2::new(g.kx[i], g.kz[i]);
            }
        }
        out
    }

    /// World-axes slope covariance `(xx, xz, zz)` the faded geometric waves lost at a hit `t` along
    /// `d`: `Σ (1 − wᵢ) ½Aᵢ² (kₓ², kₓk_z, k_z²)`, for the BRDF to carry.
    ///
    /// # Arguments
    /// - `d`: unit ray direction; `footprint_angle` (rad) `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// `(xx, xz, zz)` (dimensionless), zero without fading.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_slope_covariance(&self, d: DVec3, footprint_angle: f64, t: f64) -> DVec3 {
        if footprint_angle <= 0.0 || t <= 0.0 {
            return DVec3::ZERO;
        }
        let g = &self.set.geometry;
        let mut out = DVec3::ZERO;
        for i in 0..g.kx.len() {
            let lost = 1.0
                - brine_core::footprint::footprint_weight(
                    crate::tracing::fade::wave_fade_distance(g.kx[i], g.kz[i], d, footprint_angle),
                    t,
                );
            if lost > 0.0 {
                out += lost * crate::tracing::fade::slope_covariance(g.kx[i], g.kz[i], g.amplitude[i]);
            }
        }
        out
    }

    /// Gradient of the detail (bump-map) waves, `∇h_d = −Σ_d A_d k_d sin(k_d·x + off_d)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `∇h_d` (dimensionless).
    ///
    /// # References
    /// Chen et al. 2007, §3.3; Blinn 1978.
    pub fn detail_gradient(&self, x: f64, z: f64) -> DVec2 {
        self.set.detail.height_gradient(&self.detail_offset, x, z).1
    }

    /// The detail (bump-map) waves faded with the pixel footprint as the geometric ones are
    /// ([`Self::faded_gradient`]): the gradient of what a pixel at `t` along `d` still resolves,
    /// `−Σ_d w_d A_d k_d sin(k_d·x + off_d)`, and the world-axes slope covariance `(xx, xz, zz)`
    /// of what it no longer does, `Σ_d (1 − w_d) ½A_d² (kₓ², kₓk_z, k_z²)`, for the BRDF.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite; `d`: unit ray direction;
    ///   `footprint_angle` (rad) `≥ 0` and `t` (m) `≥ 0` (either 0: no fading).
    ///
    /// # Returns
    /// `(∇h_d, covariance)`, both dimensionless.
    ///
    /// # References
    /// Chen et al. 2007, §3.3 (bump-mapped detail); Bruneton, Neyret & Holzschuch 2010 §4 (fading).
    pub fn faded_detail(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> (DVec2, DVec3) {
        let w = &self.set.detail;
        let (mut g, mut c) = (DVec2::ZERO, DVec3::ZERO);
        for i in 0..w.kx.len() {
            let weight = if footprint_angle > 0.0 && t > 0.0 {
                brine_core::footprint::footprint_weight(
                    crate::tracing::fade::wave_fade_distance(w.kx[i], w.kz[i], d, footprint_angle),
                    t,
                )
            } else {
                1.0
            };
            if weight > 0.0 {
                let sn = (w.kx[i] * x + w.kz[i] * z + self.detail_offset[i]).sin();
                g -= weight * w.amplitude[i] * sn * DVec2::new(w.kx[i], w.kz[i]);
            }
            if weight < 1.0 {
                c += (1.0 - weight) * crate::tracing::fade::slope_covariance(w.kx[i], w.kz[i], w.amplitude[i]);
            }
        }
        (g, c)
    }

    /// Shading normal: the detail normal `(−∇h_d, 1)` expressed in the tangent frame of the geometry,
    /// `B ∝ (1, ∂h/∂x, 0)`, `T ∝ (0, ∂h/∂z, 1)`, `N ∝ (−∂h/∂x, 1, −∂h/∂z)`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// The normal (unit, upward).
    ///
    /// # References
    /// Finch 2004, §1.2.4; Chen et al. 2007, §3.3.
    pub fn shading_normal(&self, x: f64, z: f64) -> DVec3 {
        let g = self.gradient(x, z);
        let d = self.detail_gradient(x, z);
        let b = DVec3::new(1.0, g.x, 0.0).normalize();
        let t = DVec3::new(0.0, g.y, 1.0).normalize();
        let n = DVec3::new(-g.x, 1.0, -g.y).normalize();
        let local = DVec3::new(-d.x, -d.y, 1.0).normalize();
        (local.x * b + local.y * t + local.z * n).normalize()
    }

    /// Linear (Airy, deep-water) orbital velocity of the geometric waves at the surface,
    /// `Σ (Aᵢωᵢ d̂ᵢ cos φᵢ, Aᵢωᵢ sin φᵢ)`, `φᵢ = kᵢ·x + offᵢ`; `v_y = ∂h/∂t`.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `(v_x, v_y, v_z)` (m s⁻¹).
    ///
    /// # References
    /// Airy linear wave theory (Dean & Dalrymple 1991, *Water Wave Mechanics for Engineers and
    /// Scientists*); docs/equations.md §1.
    pub fn velocity(&self, x: f64, z: f64) -> DVec3 {
        let g = &self.set.geometry;
        let mut v = DVec3::ZERO;
        for i in 0..g.kx.len() {
            let (sn, c) = (g.kx[i] * x + g.kz[i] * z + self.offset[i]).sin_cos();
            let k = (g.kx[i] * g.kx[i] + g.kz[i] * g.kz[i]).sqrt();
            let aw = g.amplitude[i] * g.omega[i];
            v += DVec3::new(aw * c * g.kx[i] / k, aw * sn, aw * c * g.kz[i] / k);
        }
        v
    }
}

impl WaveSurface for SineSet {
    by_frozen_field!(height -> f64, gradient -> DVec2, velocity -> DVec3);

    fn height_bounds(&self) -> (f64, f64) {
        (-self.total_amplitude, self.total_amplitude)
    }

    fn max_slope(&self) -> f64 {
        self.total_slope
    }

    fn displacement(&self, _x: f64, _z: f64, _t: f64) -> DVec2 {
        DVec2::ZERO
    }

    fn jacobian(&self, _x: f64, _z: f64, _t: f64) -> f64 {
        1.0
    }

    fn heights(&self, xs: &[f64], zs: &[f64], t: f64, out: &mut [f64]) {
        self.at_time(t).heights(xs, zs, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Trochoid;

    /// Flat geometry: the tangent frame is the identity, so the rotated normal equals the exact one
    /// up to a few roundings of unit vectors.
    const ROUND_ABS: f64 = 1e-14;

    #[test]
    fn flat_geometry_gives_the_exact_detail_normal() {
        let detail = TrochoidSet::new(vec![Trochoid::new(0.01, 20.0, 0.3, 14.0, 1.0, 0.0).unwrap()]);
        let s = SineSet::with_detail(&TrochoidSet::default(), &detail);
        let f = s.at_time(0.5);
        for j in 0..20 {
            let (x, z) = (0.13 * j as f64, -0.07 * j as f64);
            let d = f.detail_gradient(x, z);
            let exact = DVec3::new(-d.x, 1.0, -d.y).normalize();
            assert!((f.shading_normal(x, z) - exact).length() < ROUND_ABS);
        }
    }

    #[test]
    fn split_at_wavelength_sends_short_waves_to_the_bump_map() {
        let set = TrochoidSet::new(vec![
            Trochoid::new(1.0, 0.1, 0.0, 1.0, 0.0, 0.0).unwrap(),
            Trochoid::new(0.01, 10.0, 0.0, 10.0, 0.0, 0.0).unwrap(),
        ]);
        let s = SineSet::split_at_wavelength(&set, 1.0);
        assert_eq!((s.len(), s.detail_len()), (1, 1));
        assert_eq!(s.height_bounds().1.to_bits(), 1f64.to_bits());
    }
}
