//! Mip-mapped slope statistics of an FFT ocean frame: the mean shading gradient over a pixel
//! footprint and the slope covariance the footprint hides, for the BRDF.

use glam::{DVec2, DVec3};

use crate::fft::blend::TileBlend;
use crate::{EllipticalFootprint, FftFrame, FftPyramid};

/// The slopes of an FFT sea over a pixel footprint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilteredSlopes {
    /// Mean shading gradient `⟨∇h⟩ = Σ_c ⟨∇h_c⟩` over the footprint (dimensionless); the upward
    /// normal is `(−gₓ, 1, −g_z)/‖·‖`.
    pub gradient: DVec2,
    /// Covariance `(⟨ζₓ²⟩ − ⟨ζₓ⟩², ⟨ζₓζ_z⟩ − ⟨ζₓ⟩⟨ζ_z⟩, ⟨ζ_z²⟩ − ⟨ζ_z⟩²)` of the slopes inside the
    /// footprint, summed over the cascades (dimensionless, world axes): the roughness the
    /// footprint averages away, for the BRDF.
    pub covariance: DVec3,
}

/// Mip-mapped slope moments of an [`FftFrame`] (LEAN mapping on the FFT grids): per cascade a
/// pyramid of `(ζₓ, ζ_z, ζₓ², ζₓζ_z, ζ_z²)`, `ζ` the shading gradient at the grid points.
///
/// Over a footprint the mean gradient shades the pixel and the covariance
/// `⟨ζζᵀ⟩ − ⟨ζ⟩⟨ζ⟩ᵀ` (positive semi-definite: each texel and each trilinear weight is a mean) is the
/// slope variance the footprint resolves no more: adding it to the BRDF's unresolved variance
/// keeps the mean reflectance of a distant sea (Bruneton et al. 2010's seamless transition from
/// geometry to BRDF). The cascades are independent, so their means and covariances add. A
/// footprint is a Gaussian of standard deviation `s`, read at box width `√12 s` (see
/// [`FftPyramid`]); at `s = 0` the gradient is [`FftFrame::gradient`] and the covariance that of
/// the bilinear interpolation (0 at a grid point); beyond the largest tile it is the whole sea's.
///
/// # References
/// Olano M., Baker D. 2010, "LEAN mapping", I3D; Bruneton E., Neyret F., Holzschuch N. 2010,
/// CGF 29(2) (geometry-to-BRDF transition); docs/equations.md §11.
#[derive(Debug, Clone, PartialEq)]
pub struct FftSlopeFilter {
    /// Per cascade, the pyramid of `(ζₓ, ζ_z, ζₓ², ζₓζ_z, ζ_z², h)` and the cascade's blend.
    cascades: Vec<(FftPyramid<6>, Option<TileBlend>)>,
}

impl FftSlopeFilter {
    /// Builds the pyramids of every cascade of `frame` (`O(N²)` per cascade; once per frame).
    pub fn new(frame: &FftFrame) -> Self {
        let cascades = frame
            .cascades()
            .iter()
            .map(|c| {
                let base = c
                    .gradients()
                    .iter()
                    .zip(c.heights())
                    .map(|(g, &h)| {
                        let (x, z) = (f64::from(g[0]), f64::from(g[1]));
                        [x, z, x * x, x * z, z * z, f64::from(h)]
                    })
                    .collect();
                (FftPyramid::new(c.resolution(), c.spacing(), base), c.blend().copied())
            })
            .collect();
        Self { cascades }
    }

    /// Mean gradient and slope covariance over a Gaussian footprint.
    ///
    /// # Arguments
    /// - `x`, `z`: footprint centre on the sea (m).
    /// - `footprint_m`: standard deviation `s` (m), `≥ 0` (a square pixel of side `ℓ` on the sea:
    ///   `s ≈ ℓ/√12`).
    ///
    /// # Returns
    /// [`FilteredSlopes`].
    pub fn filtered(&self, x: f64, z: f64, footprint_m: f64) -> FilteredSlopes {
        debug_assert!(footprint_m >= 0.0);
        self.blended(x, z, |p, x, z| p.footprint_mean(x, z, footprint_m))
    }

    /// Mean gradient and slope covariance over an elliptical Gaussian footprint (a pixel seen at
    /// a slant, stretched along the view): as [`Self::filtered`], each cascade read by
    /// [`FftPyramid::ellipse_mean`]. The waves along the major axis are averaged over its length,
    /// those across it over the minor axis only, and what the footprint averages away joins the
    /// covariance.
    ///
    /// # Arguments
    /// - `x`, `z`: footprint centre on the sea (m).
    /// - `footprint`: the ellipse ([`EllipticalFootprint`]).
    ///
    /// # Returns
    /// [`FilteredSlopes`].
    pub fn filtered_elliptical(&self, x: f64, z: f64, footprint: &EllipticalFootprint) -> FilteredSlopes {
        self.blended(x, z, |p, x, z| p.ellipse_mean(x, z, footprint))
    }

    /// Sums the cascades' footprint moments read by `read`: a blended cascade (see
    /// `FftCascade`) reads its corners at their offsets, and its slopes `Σ ŵ_k ζ_k + Σ h_k ∇ŵ_k`
    /// have the mean `Σ (ŵ_k ⟨ζ⟩_k + ⟨h⟩_k ∇ŵ_k)` and, the corners' reads being independent, the
    /// covariance `Σ ŵ_k² cov_k` (the weights taken at the footprint's centre).
    fn blended(&self, x: f64, z: f64, read: impl Fn(&FftPyramid<6>, f64, f64) -> [f64; 6]) -> FilteredSlopes {
        let mut out = FilteredSlopes { gradient: DVec2::ZERO, covariance: DVec3::ZERO };
        for (p, blend) in &self.cascades {
            match blend {
                None => {
                    let (g, cov) = Self::gradient_and_covariance(&read(p, x, z));
                    out.gradient += g;
                    out.covariance += cov;
                }
                Some(b) => {
                    for c in b.corners(x, z) {
                        if c.weight > 0.0 {
                            let m = read(p, x + c.offset[0], z + c.offset[1]);
                            let (g, cov) = Self::gradient_and_covariance(&m);
                            out.gradient += c.weight * g + m[5] * DVec2::new(c.gradient[0], c.gradient[1]);
                            out.covariance += c.weight * c.weight * cov;
                        }
                    }
                }
            }
        }
        out
    }

    /// The mean gradient and the covariance of one read's footprint moments
    /// `(ζₓ, ζ_z, ζₓ², ζₓζ_z, ζ_z², h)`.
    fn gradient_and_covariance(m: &[f64; 6]) -> (DVec2, DVec3) {
        // Footprint means are convex combinations, so the covariance is a covariance (Jensen,
        // Cauchy–Schwarz) but for the f32 storage, which alone the clamps absorb.
        let tol = 1e-5 * (m[2].abs() + m[4].abs() + m[0] * m[0] + m[1] * m[1]) + 1e-12;
        debug_assert!(m[2] - m[0] * m[0] >= -tol && m[4] - m[1] * m[1] >= -tol, "footprint moments {m:?}");
        let (xx, zz) = ((m[2] - m[0] * m[0]).max(0.0), (m[4] - m[1] * m[1]).max(0.0));
        debug_assert!((m[3] - m[0] * m[1]).abs() <= (xx * zz).sqrt() + tol, "footprint moments {m:?}");
        let xz = (m[3] - m[0] * m[1]).clamp(-(xx * zz).sqrt(), (xx * zz).sqrt());
        (DVec2::new(m[0], m[1]), DVec3::new(xx, xz, zz))
    }
}
