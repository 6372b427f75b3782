//! The footprint fading of a Gerstner field: waves fade out where the pixel footprint reaches
//! their wavelength, their height and slopes taken by the traced height and the shading.

use glam::{DVec2, DVec3};

use super::{GerstnerField, RestState};
use crate::tracing::gerstner_lanes::{self, LaneWaves};

/// A solved inversion at a point: where the next one nearby may start
/// ([`GerstnerField::faded_height_lanes_from`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct WarmStart {
    /// The horizontal position `x′` (m).
    at: DVec2,
    /// Its rest position `u′` (m).
    rest: DVec2,
    /// The Jacobian `J′` of `u ↦ u + D(u)` there, `(xx, xz, zz)`.
    jacobian: (f64, f64, f64),
    /// Newton iterations the solve took (after its start), for the tests.
    #[cfg(test)]
    pub(crate) iterations: usize,
}

impl WarmStart {
    /// The start of a solve at `target` (m): one Newton step from this solution,
    /// `u′ + J′⁻¹(x − x′)` (m).
    pub(crate) fn start(&self, target: DVec2) -> DVec2 {
        self.rest + self.solve(target - self.at)
    }
}

impl RestState for WarmStart {
    fn displacement(&self) -> DVec2 {
        self.at - self.rest
    }
    fn jacobian(&self) -> (f64, f64, f64) {
        self.jacobian
    }
}

/// Working arrays of [`GerstnerField::faded_height_lanes`]: the waves still present, weighted,
/// padded to a multiple of four for the SIMD passes.
#[derive(Debug, Clone, Default)]
pub struct FadedWaves {
    kx: Vec<f64>,
    kz: Vec<f64>,
    offset: Vec<f64>,
    amplitude: Vec<f64>,
    q_over_k2: Vec<f64>,
}

impl FadedWaves {
    fn clear(&mut self) {
        for v in [&mut self.kx, &mut self.kz, &mut self.offset, &mut self.amplitude, &mut self.q_over_k2] {
            v.clear();
        }
    }

    fn push(&mut self, kx: f64, kz: f64, offset: f64, amplitude: f64, q_over_k2: f64) {
        self.kx.push(kx);
        self.kz.push(kz);
        self.offset.push(offset);
        self.amplitude.push(amplitude);
        self.q_over_k2.push(q_over_k2);
    }

    /// Inert waves (`A = Q = 0`, `k = 0`) up to a multiple of four.
    fn pad(&mut self) {
        while !self.kx.len().is_multiple_of(4) {
            self.push(0.0, 0.0, 0.0, 0.0, 0.0);
        }
    }
}

impl GerstnerField<'_> {
    /// Footprint fade distances `Tᵢ` of the waves for a ray of unit direction `d` and a pixel of
    /// `footprint_angle` rad: `Tᵢ = 2π/(α √(kᵢ² + σᵢ²/max(|d_y|, 0.05)²))`, `σᵢ = kᵢ·d̂_xz` (the pixel footprint
    /// is `αt` across the view and `αt/max(|d_y|, 0.05)` along it; the rule of the trochoid tracer).
    ///
    /// # Arguments
    /// - `d`: unit ray direction.
    /// - `footprint_angle`: `α` (rad), `> 0`.
    ///
    /// # Returns
    /// `Tᵢ` (m) per wave, `> 0`.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 (waves fade when the footprint reaches their
    /// wavelength); Darles et al. 2007 §3.2.
    pub fn fade_distances(&self, d: DVec3, footprint_angle: f64) -> Vec<f64> {
        let s = self.surface;
        (0..s.len()).map(|i| crate::tracing::fade::wave_fade_distance(s.kx[i], s.kz[i], d, footprint_angle)).collect()
    }

    /// The tracer's weights `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` at `t` (m) along the unit direction `d`
    /// for a pixel of `footprint_angle` rad (`> 0`), one per wave.
    fn fade_weights(&self, d: DVec3, footprint_angle: f64, t: f64) -> Vec<f64> {
        self.fade_distances(d, footprint_angle).iter().map(|&f| brine_core::footprint::footprint_weight(f, t)).collect()
    }

    /// Height (m) of the faded Gerstner sum, each wave's amplitude and steepness scaled by its
    /// weight `wᵢ ∈ [0, 1]`: `u + Σ wᵢDᵢ(u) = x`, `h = Σ wᵢAᵢ cos φᵢ(u)` (the surface a primary ray
    /// sees at a distance where waves shorter than its footprint fade; all `wᵢ = 1` is
    /// [`GerstnerField::height`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `weights`: `wᵢ`, one per wave, each in `[0, 1]`.
    ///
    /// # Returns
    /// `h` (m), in `[−Σ wᵢAᵢ, Σ wᵢAᵢ]`.
    ///
    /// # References
    /// docs/equations.md §1(b); Bruneton, Neyret & Holzschuch 2010 §4 (amplitudes faded with the
    /// footprint).
    pub fn faded_height(&self, x: f64, z: f64, weights: &[f64]) -> f64 {
        debug_assert_eq!(weights.len(), self.surface.len());
        let w = |i: usize| weights[i];
        self.invert(x, z, |u| self.displacement_scaled(u, w), |u| self.state_scaled(u, w)).1.height
    }

    /// [`GerstnerField::faded_height`] with the passes four waves at a time (`wide::f64x4`), over
    /// the waves whose weight is not 0 only, gathered into `scratch` (reused between calls): the
    /// tracer's evaluation of the faded sum, whose far samples keep only a few long waves.
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `weights`: `wᵢ ∈ [0, 1]`, one per wave.
    /// - `scratch`: working arrays.
    ///
    /// # Returns
    /// `h` (m), equal to [`GerstnerField::faded_height`] but for the order of roundings.
    ///
    /// # References
    /// docs/equations.md §1(b); Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_height_lanes(&self, x: f64, z: f64, weights: &[f64], scratch: &mut FadedWaves) -> f64 {
        self.faded_height_lanes_from(x, z, weights, scratch, None).0
    }

    /// [`GerstnerField::faded_height_lanes`] whose Newton solve starts from a solution at a
    /// nearby point (`warm`, such as the previous sample along a ray) instead of from
    /// `u₀ = x − D(x)`: one Newton step from it, `u₀ = u′ + J′⁻¹(x − x′)`, costs no pass over the
    /// waves and starts within `O(|x − x′|²)` of the solution (plus the change of the weights
    /// between the two points). A far `x′` makes a poor start (`J′⁻¹`, up to `1/(1 − ΣQ)`, may
    /// magnify the jump), but the damped solve converges from any start: the map is one-to-one,
    /// the gradient of a strictly convex potential. Measured along primary rays, taking the warm
    /// start only within a radian of the shortest wave present was slower than taking it always,
    /// and only within `Σ wᵢQᵢ/kᵢ` (how far the waves move a point) no faster (slower with the
    /// camera among the crests). The inversion is unique
    /// (`Σ Qᵢ < 1`), so the start changes only the rounding of the result within the solve's
    /// tolerance.
    ///
    /// # Returns
    /// `(h, solution)`: the height (m) and the solution at `(x, z)`, the next solve's start.
    pub(crate) fn faded_height_lanes_from(
        &self,
        x: f64,
        z: f64,
        weights: &[f64],
        scratch: &mut FadedWaves,
        warm: Option<&WarmStart>,
    ) -> (f64, WarmStart) {
        let s = self.surface;
        scratch.clear();
        for (i, &w) in weights.iter().enumerate().take(s.len()) {
            if w > 0.0 {
                scratch.push(s.kx[i], s.kz[i], self.offset[i], s.amplitude[i] * w, s.q_over_k2[i] * w);
            }
        }
        scratch.pad();
        let lanes = LaneWaves {
            kx: &scratch.kx,
            kz: &scratch.kz,
            offset: &scratch.offset,
            amplitude: &scratch.amplitude,
            q_over_k2: &scratch.q_over_k2,
        };
        let target = DVec2::new(x, z);
        let first = |u| match warm {
            Some(w) => target - w.start(target),
            None => gerstner_lanes::displacement(lanes, u),
        };
        let (inversion, state) = self.invert(x, z, first, |u| gerstner_lanes::state(lanes, u));
        let solved = WarmStart {
            at: target,
            rest: inversion.rest,
            jacobian: state.jacobian(),
            #[cfg(test)]
            iterations: inversion.iterations,
        };
        (state.height, solved)
    }

    /// Height (m) of the faded Gerstner sum as a primary ray `t` metres along the unit direction
    /// `d` draws it, for a pixel of `footprint_angle` rad: [`GerstnerField::faded_height`] with
    /// the tracer's weights `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` (`footprint_angle = 0` or `t = 0`:
    /// every wave whole, [`GerstnerField::height`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `d`: unit ray direction; `footprint_angle` (rad) `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// `h` (m), in `[−ΣAᵢ, ΣAᵢ]`.
    ///
    /// # References
    /// docs/equations.md §1(b); Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_height_along(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> f64 {
        if footprint_angle <= 0.0 || t <= 0.0 {
            return self.height(x, z);
        }
        let weights = self.fade_weights(d, footprint_angle, t);
        self.faded_height(x, z, &weights)
    }

    /// Gradient of the faded Gerstner sum at a primary hit `t` metres along the unit direction `d`
    /// for a pixel of `footprint_angle` rad, the weights `wᵢ = smoothstep(1, 1.5, Tᵢ/t)` of the
    /// tracer (`footprint_angle = 0` or `t = 0`: every wave whole, [`GerstnerField::gradient`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m), finite.
    /// - `d`: unit ray direction; `footprint_angle` (rad) `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// `∇h` (dimensionless) of the surface that ray traced.
    ///
    /// # References
    /// docs/equations.md §1(b); Bruneton, Neyret & Holzschuch 2010 §4.
    pub fn faded_gradient(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> DVec2 {
        if footprint_angle <= 0.0 || t <= 0.0 {
            return self.gradient(x, z);
        }
        let weights = self.fade_weights(d, footprint_angle, t);
        let w = |i: usize| weights[i];
        let st = self.invert(x, z, |u| self.displacement_scaled(u, w), |u| self.state_scaled(u, w)).1;
        st.solve(st.grad_u)
    }

    /// World-axes slope covariance `(xx, xz, zz)` of what the faded waves lost at a hit `t` along
    /// `d`: `Σ (1 − wᵢ) ½(kᵢAᵢ)² (k̂ₓ², k̂ₓk̂_z, k̂_z²)` (each wave's linear slope variance), for the
    /// BRDF to carry (Bruneton et al. 2010's transition from geometry to BRDF).
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
        let s = self.surface;
        let mut out = DVec3::ZERO;
        for (i, f) in self.fade_distances(d, footprint_angle).into_iter().enumerate() {
            let lost = 1.0 - brine_core::footprint::footprint_weight(f, t);
            if lost > 0.0 {
                out += lost * crate::tracing::fade::slope_covariance(s.kx[i], s.kz[i], s.amplitude[i]);
            }
        }
        out
    }
}
