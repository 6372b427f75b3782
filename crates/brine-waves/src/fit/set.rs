//! A set of trochoid waves and the Gerstner displacement it defines.

use glam::{DVec2, DVec3};

use crate::Trochoid;

/// An ordered set of trochoid waves about the mean sea level `y = 0`.
///
/// The set is data; [`crate::TrochoidSum`] turns it into the surface that Darles et al. trace.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct TrochoidSet {
    waves: Vec<Trochoid>,
}

impl TrochoidSet {
    /// A set from its waves (each already validated by [`Trochoid::new`]).
    pub fn new(waves: Vec<Trochoid>) -> Self {
        Self { waves }
    }

    /// The waves.
    pub fn waves(&self) -> &[Trochoid] {
        &self.waves
    }

    /// Number of waves `N`.
    pub fn len(&self) -> usize {
        self.waves.len()
    }

    /// `true` for a flat sea.
    pub fn is_empty(&self) -> bool {
        self.waves.is_empty()
    }

    /// Appends the waves of `other` (sea plus swell).
    pub fn extend(&mut self, other: &TrochoidSet) {
        self.waves.extend_from_slice(&other.waves);
    }

    /// `Σ Aᵢ` (m): the surface lies within `±Σ Aᵢ` of the mean level.
    pub fn total_amplitude(&self) -> f64 {
        self.waves.iter().map(Trochoid::amplitude).sum()
    }

    /// `Σ Qᵢ`: the Gerstner sum cannot fold while it is below 1 (docs/equations.md §1).
    pub fn total_steepness(&self) -> f64 {
        self.waves.iter().map(Trochoid::steepness).sum()
    }

    /// Elevation variance of the sinusoidal limit of the set, `Σ Aᵢ²/2`: the quantity the fit matches
    /// to `∫ S dω` over the band.
    ///
    /// # Returns
    /// The variance (m²).
    ///
    /// # References
    /// Thon & Ghazanfarpour 2002; docs/equations.md §1 ("Extraction from a spectrum").
    pub fn variance(&self) -> f64 {
        self.waves.iter().map(|w| 0.5 * w.amplitude() * w.amplitude()).sum()
    }

    /// Slope variances of the exact trochoid profiles along and across a direction `θ_w` (rad):
    /// `(Σ cos²(θᵢ − θ_w) ⟨sᵢ²⟩, Σ sin²(θᵢ − θ_w) ⟨sᵢ²⟩)` with `⟨sᵢ²⟩` each wave's
    /// [`Trochoid::mean_square_slope`] (dimensionless). For the renderer's BRDF: the slope variance
    /// the drawn waves already resolve.
    ///
    /// # Arguments
    /// - `direction`: reference direction `θ_w` (rad) from +x toward +z.
    ///
    /// # Returns
    /// `(σ_along², σ_across²)` (dimensionless).
    ///
    /// # References
    /// docs/equations.md §11 (trochoid set: `σ_x² = Σ cos²θᵢ (1 − √(1 − kᵢ²Aᵢ²))`).
    pub fn slope_variances(&self, direction: f64) -> (f64, f64) {
        let (mut along, mut across) = (0.0, 0.0);
        for w in &self.waves {
            let c = (w.direction() - direction).cos();
            let m = w.mean_square_slope();
            along += m * c * c;
            across += m * (1.0 - c * c);
        }
        (along, across)
    }

    /// Gerstner displacement of the particle at rest position `u = (x, z)` at time `t`:
    /// `(−Σ (Qᵢ/kᵢ) d̂ᵢ sin φᵢ, Σ Aᵢ cos φᵢ)`, `φᵢ = kᵢ d̂ᵢ·u − ωᵢt + φ₀ᵢ`.
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// `(dx, y, dz)` (m): horizontal displacement and height.
    ///
    /// # References
    /// docs/equations.md §1, "Sum of N trochoids".
    pub fn gerstner_displacement(&self, u: DVec2, t: f64) -> DVec3 {
        let mut out = DVec3::ZERO;
        for w in &self.waves {
            let d = w.direction_vector();
            let phi = w.wavenumber() * d.dot(u) - w.omega() * t + w.phase();
            let (s, c) = phi.sin_cos();
            let r = w.horizontal_radius();
            out.x -= r * d.x * s;
            out.z -= r * d.y * s;
            out.y += w.amplitude() * c;
        }
        out
    }

    /// Jacobian determinant of the horizontal Gerstner map `u ↦ u + D(u)` at rest position `u`:
    /// `J = det(I − Σ Qᵢ d̂ᵢ d̂ᵢᵀ cos φᵢ)`. `J < 1` where the surface is compressed, `J < 0` where it
    /// folds.
    ///
    /// # Arguments
    /// - `u`: rest position (m), finite.
    /// - `t`: time (s), finite.
    ///
    /// # Returns
    /// `J` (dimensionless).
    ///
    /// # References
    /// Dupuy & Bruneton 2012; docs/equations.md §10.
    pub fn gerstner_jacobian(&self, u: DVec2, t: f64) -> f64 {
        let (mut jxx, mut jxz, mut jzz) = (1.0, 0.0, 1.0);
        for w in &self.waves {
            let d = w.direction_vector();
            let phi = w.wavenumber() * d.dot(u) - w.omega() * t + w.phase();
            let qc = w.steepness() * phi.cos();
            jxx -= qc * d.x * d.x;
            jxz -= qc * d.x * d.y;
            jzz -= qc * d.y * d.y;
        }
        jxx * jzz - jxz * jxz
    }
}
