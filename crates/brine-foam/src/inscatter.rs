//! The light spray drops scatter toward the eye from the sky and the sea all round them: the
//! radiance field integrated through the drops' phase function, tabulated over view directions.

use rayon::prelude::*;

use crate::error::{FoamError, check};
use crate::scattering::henyey_greenstein;

/// Cells of the quadrature over the sphere of incoming directions in polar angle (3.75° each).
const QUAD_THETA: usize = 48;
/// Cells of that quadrature in azimuth (5.6° each).
const QUAD_PHI: usize = 64;
/// Nodes of the table in elevation, −90° to 90° every 5°.
pub const LOBE_TABLE_ELEVATIONS: usize = 37;
/// Nodes of the table in azimuth, every 5°.
pub const LOBE_TABLE_AZIMUTHS: usize = 72;

/// The in-scattering source of spray drops lit by a radiance field, for every view direction.
///
/// `J(d) = ∫_{4π} L(ω) p_HG(ω·d) dω` — `L(ω)` the radiance arriving at a drop from direction `ω`
/// (sky above the horizon, the sea's reflection of it below), `p_HG` the Henyey–Greenstein phase
/// function of the drops, `d` the direction from the eye. `J` is a radiance; the source of the
/// single-scattering integral along a camera ray is `ϖ J` ([`crate::SprayRay`] with
/// `sky_radiance = 2J`, since it counts `½ L̄` for a uniform upper hemisphere).
///
/// Drops larger than the wavelength scatter forward (`g` ≈ 0.75–0.85): a near-horizontal ray
/// through spray gathers mostly the horizon sky behind it and the sea below it, which is why the
/// haze over a windy sea has the colour and brightness of the horizon, not of the sky's mean.
///
/// The integral is a midpoint rule on 48 × 64 cells in polar angle and azimuth, each weighted
/// by its exact solid angle (3.75° of elevation; the lobe's half-width at half maximum is 12.7°
/// for `g = 0.75`) and normalised by the same rule's integral of `p_HG`, so that a uniform
/// field gives back its radiance exactly; tabulated on 5° nodes in elevation and azimuth and read
/// bilinearly.
///
/// # References
/// Chandrasekhar S. 1960, *Radiative transfer*, Dover, §1 (the source function of single
/// scattering); Henyey L., Greenstein J. 1941, Astrophys. J. 93:70–83.
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseLobeTable {
    values: Vec<[f64; 3]>,
}

impl PhaseLobeTable {
    /// Integrates `J` for every node of the table.
    ///
    /// # Arguments
    /// - `asymmetry`: Henyey–Greenstein `g`, `[0, 0.95]`.
    /// - `radiance`: `L(ω)` for a unit direction `ω = [x, y, z]` (y up) toward where the light
    ///   comes from; three channels, each `≥ 0` and finite, in any radiance unit.
    ///
    /// # Returns
    /// The table (2664 nodes; 8.2 M phase evaluations).
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] for `asymmetry` outside its range.
    ///
    /// # References
    /// See [`PhaseLobeTable`].
    pub fn new(asymmetry: f64, radiance: impl Fn([f64; 3]) -> [f64; 3]) -> Result<Self, FoamError> {
        check("asymmetry", asymmetry, (0.0..=0.95).contains(&asymmetry), "[0, 0.95]")?;
        let (dtheta, dphi) = (std::f64::consts::PI / QUAD_THETA as f64, 2.0 * std::f64::consts::PI / QUAD_PHI as f64);
        let mut sources = Vec::with_capacity(QUAD_THETA * QUAD_PHI);
        for i in 0..QUAD_THETA {
            let theta = (i as f64 + 0.5) * dtheta;
            // The cell's exact solid angle, (cos θ_a − cos θ_b) Δφ.
            let cell = (libm::cos(i as f64 * dtheta) - libm::cos((i + 1) as f64 * dtheta)) * dphi;
            let (s, mu) = (libm::sin(theta), libm::cos(theta));
            for j in 0..QUAD_PHI {
                let phi = (j as f64 + 0.5) * dphi;
                let w = [s * libm::cos(phi), mu, s * libm::sin(phi)];
                let l = radiance(w);
                debug_assert!(l.iter().all(|c| c.is_finite() && *c >= 0.0), "L({w:?}) = {l:?}");
                sources.push((w, l, cell));
            }
        }
        // Each node is summed on its own, in the same order, whatever the thread count.
        let values = (0..LOBE_TABLE_ELEVATIONS * LOBE_TABLE_AZIMUTHS)
            .into_par_iter()
            .map(|i| {
                let d = node_direction(i / LOBE_TABLE_AZIMUTHS, i % LOBE_TABLE_AZIMUTHS);
                let (mut j, mut norm) = ([0.0; 3], 0.0);
                for (w, l, cell) in &sources {
                    let p = henyey_greenstein(w[0] * d[0] + w[1] * d[1] + w[2] * d[2], asymmetry) * cell;
                    norm += p;
                    for c in 0..3 {
                        j[c] += l[c] * p;
                    }
                }
                j.map(|x| x / norm)
            })
            .collect();
        Ok(Self { values })
    }

    /// `J(d)`, read bilinearly between the table's nodes.
    ///
    /// # Arguments
    /// - `d`: view direction from the eye, y up (need not be unit; not zero).
    ///
    /// # Returns
    /// `J` in the unit of the radiance the table was built from, per channel.
    pub fn lookup(&self, d: [f64; 3]) -> [f64; 3] {
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        debug_assert!(len > 0.0);
        let elevation = libm::asin((d[1] / len).clamp(-1.0, 1.0));
        let azimuth = libm::atan2(d[2], d[0]).rem_euclid(2.0 * std::f64::consts::PI);
        let step = 5f64.to_radians();
        let fe = ((elevation + std::f64::consts::FRAC_PI_2) / step).clamp(0.0, (LOBE_TABLE_ELEVATIONS - 1) as f64);
        let fa = azimuth / step;
        let (e0, a0) = ((fe.floor() as usize).min(LOBE_TABLE_ELEVATIONS - 2), fa.floor() as usize);
        let (te, ta) = (fe - e0 as f64, fa - a0 as f64);
        let at = |e: usize, a: usize| self.values[e * LOBE_TABLE_AZIMUTHS + a % LOBE_TABLE_AZIMUTHS];
        let (v00, v01, v10, v11) = (at(e0, a0), at(e0, a0 + 1), at(e0 + 1, a0), at(e0 + 1, a0 + 1));
        std::array::from_fn(|c| {
            (1.0 - te) * ((1.0 - ta) * v00[c] + ta * v01[c]) + te * ((1.0 - ta) * v10[c] + ta * v11[c])
        })
    }
}

/// The unit direction of table node `(e, a)`: elevation `−90° + 5° e`, azimuth `5° a` from +x
/// toward +z.
fn node_direction(e: usize, a: usize) -> [f64; 3] {
    let step = 5f64.to_radians();
    let (el, az) = (-std::f64::consts::FRAC_PI_2 + e as f64 * step, a as f64 * step);
    [libm::cos(el) * libm::cos(az), libm::sin(el), libm::cos(el) * libm::sin(az)]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normalised rule returns a uniform field to rounding (3072 terms of 10⁻¹⁶).
    const UNIFORM_ROUNDING: f64 = 1e-12;

    /// The midpoint rule with 3.75° cells against the closed-form half-space share of the
    /// Henyey–Greenstein lobe (`g` = 0.8, peak 4.5 sr⁻¹): the cells cut by the horizon are
    /// split exactly, the lobe's curvature over a cell costs ~10⁻³; 5×10⁻³ leaves a margin.
    const LOBE_QUADRATURE: f64 = 5e-3;

    #[test]
    fn a_uniform_field_gives_its_radiance() {
        for g in [0.0, 0.5, 0.75, 0.85] {
            let t = PhaseLobeTable::new(g, |_| [1.0, 2.0, 3.0]).unwrap();
            for d in [[1.0, 0.0, 0.0], [0.3, -0.9, 0.2], [0.0, 1.0, 0.0], [-0.7, 0.05, -0.7]] {
                let j = t.lookup(d);
                for (c, want) in [1.0, 2.0, 3.0].into_iter().enumerate() {
                    assert!((j[c] / want - 1.0).abs() < UNIFORM_ROUNDING, "g = {g}, {d:?}: {j:?}");
                }
            }
        }
    }

    #[test]
    fn a_forward_lobe_sees_what_is_ahead() {
        // Bright upper hemisphere, dark lower: looking up gathers the lobe's share in the upper
        // half, (1 − g²)/(2g) · (1/(1 − g) − 1/√(1 + g²)) (0.949 for g = 0.8, ½ for g = 0);
        // looking along the horizon gathers half, by symmetry.
        let field = |w: [f64; 3]| if w[1] > 0.0 { [1.0; 3] } else { [0.0; 3] };
        let (iso, fwd) = (PhaseLobeTable::new(0.0, field).unwrap(), PhaseLobeTable::new(0.8, field).unwrap());
        let up = [0.0, 1.0, 0.0];
        let g: f64 = 0.8;
        let share = (1.0 - g * g) / (2.0 * g) * (1.0 / (1.0 - g) - 1.0 / (1.0 + g * g).sqrt());
        assert!((iso.lookup(up)[0] - 0.5).abs() < LOBE_QUADRATURE);
        assert!((fwd.lookup(up)[0] - share).abs() < LOBE_QUADRATURE, "{:?} against {share}", fwd.lookup(up));
        assert!((fwd.lookup([1.0, 0.0, 0.0])[0] - 0.5).abs() < LOBE_QUADRATURE);
    }

    #[test]
    fn a_bad_asymmetry_is_named() {
        let e = PhaseLobeTable::new(0.99, |_| [1.0; 3]).unwrap_err();
        assert!(format!("{e}").contains("asymmetry"));
    }
}
