//! Height fields from intensities (Lai & Wu Eq. 1, the "dark is deep" shape-from-shading
//! heuristic they borrow from Textureshop) and the bounds of their bilinear interpolant.

use crate::error::check;
use crate::{Grid, Texture, TextureError};

/// Smallest intensity range `I_max − I_min` accepted by Eq. 1 (levels): below it the image is
/// uniform and Eq. 1 would divide by zero.
pub const MIN_INTENSITY_RANGE: f64 = 1e-6;

/// Height of a texel from its intensity (Lai & Wu Eq. 1):
/// `height = hf (I − I_min)/(I_max − I_min)`.
///
/// # Arguments
/// - `i`: intensity `I` of the texel, `[I_min, I_max]` (levels, `[0, 255]`).
/// - `i_min`, `i_max`: smallest and largest intensity of the image, `I_max − I_min > 0`.
/// - `hf`: height factor (m), `> 0`.
///
/// # Returns
/// The height (m), `[0, hf]`.
///
/// # References
/// Lai & Wu, "Ocean surface rendering using temporal texture synthesis", Eq. 1, after Fang &
/// Hart 2004, "Textureshop", ACM TOG 23(3); docs/equations.md §14.
#[inline]
pub fn height_from_intensity(i: f64, i_min: f64, i_max: f64, hf: f64) -> f64 {
    debug_assert!(i_max - i_min > 0.0 && hf > 0.0);
    hf * (i - i_min) / (i_max - i_min)
}

/// Intensity of a height, Eq. 1 inverted (Lai & Wu Eq. 4):
/// `I = I_min + height (I_max − I_min)/hf`.
///
/// # Arguments
/// - `height`: height (m), `[0, hf]`.
/// - `i_min`, `i_max`: intensity range of the image (levels).
/// - `hf`: height factor (m), `> 0`.
///
/// # Returns
/// `I` (levels).
///
/// # References
/// Lai & Wu Eq. 4; docs/equations.md §14.
#[inline]
pub fn intensity_from_height(height: f64, i_min: f64, i_max: f64, hf: f64) -> f64 {
    debug_assert!(hf > 0.0);
    i_min + height * (i_max - i_min) / hf
}

/// Intensity change of a height change (Lai & Wu Eq. 5):
/// `ΔI = Δheight (I_max − I_min)/hf`. (The renderer relights with Eq. 7–9 instead, which keep
/// the intensity in range; see [`crate::relight_intensity`].)
///
/// # Arguments
/// - `delta_height`: height change (m).
/// - `i_min`, `i_max`: intensity range (levels).
/// - `hf`: height factor (m), `> 0`.
///
/// # Returns
/// `ΔI` (levels).
///
/// # References
/// Lai & Wu Eq. 5; docs/equations.md §14.
#[inline]
pub fn intensity_change(delta_height: f64, i_min: f64, i_max: f64, hf: f64) -> f64 {
    debug_assert!(hf > 0.0);
    delta_height * (i_max - i_min) / hf
}

/// A height field on a toroidal lattice, with its statistics and the slope bounds of its
/// bilinear interpolant.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightField {
    grid: Grid,
    mean: f64,
    min: f64,
    max: f64,
    max_du: f64,
    max_dv: f64,
    max_gradient: f64,
}

impl HeightField {
    /// Heights of an image by Eq. 1, from its intensities ([`crate::intensity`]).
    ///
    /// # Arguments
    /// - `texture`: the image.
    /// - `hf`: height factor (m), `(0, 1000]`.
    /// - `what`: the image's name in error messages.
    ///
    /// # Returns
    /// The height field (m), `[0, hf]`, one height per texel.
    ///
    /// # Errors
    /// [`TextureError::Flat`] if the image is uniform (`I_max = I_min`);
    /// [`TextureError::OutOfRange`] for a bad `hf`.
    ///
    /// # References
    /// Lai & Wu Eq. 1; Fang & Hart 2004 (Textureshop's "dark is deep" heuristic).
    pub fn from_texture(texture: &Texture, hf: f64, what: &str) -> Result<Self, TextureError> {
        Self::from_intensity(&texture.intensity(), hf, what)
    }

    /// Heights of an intensity grid by Eq. 1.
    ///
    /// # Errors
    /// As [`HeightField::from_texture`].
    pub fn from_intensity(intensity: &Grid, hf: f64, what: &str) -> Result<Self, TextureError> {
        check("height_factor_m", hf, hf > 0.0 && hf <= 1000.0, "(0, 1000] m")?;
        let (lo, hi) = intensity.range();
        let (i_min, i_max) = (f64::from(lo), f64::from(hi));
        if !(i_max - i_min > MIN_INTENSITY_RANGE) {
            return Err(TextureError::Flat { what: what.to_owned(), level: i_min });
        }
        let values =
            intensity.values().iter().map(|&i| height_from_intensity(f64::from(i), i_min, i_max, hf) as f32).collect();
        Ok(Self::from_heights(Grid::from_values_unchecked(intensity.width(), intensity.height(), values)))
    }

    /// A height field from heights (m) on a lattice.
    pub fn from_heights(grid: Grid) -> Self {
        let (w, h) = (grid.width(), grid.height());
        let (mut max_du, mut max_dv, mut max_gradient) = (0.0f64, 0.0f64, 0.0f64);
        for j in 0..h {
            let j1 = (j + 1) % h;
            for i in 0..w {
                let i1 = (i + 1) % w;
                let h00 = f64::from(grid.get(i, j));
                let h10 = f64::from(grid.get(i1, j));
                let h01 = f64::from(grid.get(i, j1));
                let h11 = f64::from(grid.get(i1, j1));
                let a = (h10 - h00).abs().max((h11 - h01).abs());
                let b = (h01 - h00).abs().max((h11 - h10).abs());
                max_du = max_du.max(a);
                max_dv = max_dv.max(b);
                max_gradient = max_gradient.max(a.hypot(b));
            }
        }
        let (lo, hi) = grid.range();
        let mean = grid.mean();
        Self { grid, mean, min: f64::from(lo), max: f64::from(hi), max_du, max_dv, max_gradient }
    }

    /// The heights (m).
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Mean height (m).
    pub fn mean(&self) -> f64 {
        self.mean
    }

    /// Smallest height (m).
    pub fn min(&self) -> f64 {
        self.min
    }

    /// Largest height (m).
    pub fn max(&self) -> f64 {
        self.max
    }

    /// Bound of `|∂h/∂u|` of the bilinear interpolant (m per texel): the largest difference
    /// between horizontal neighbours.
    pub fn max_du(&self) -> f64 {
        self.max_du
    }

    /// Bound of `|∂h/∂v|` (m per texel): the largest difference between vertical neighbours.
    pub fn max_dv(&self) -> f64 {
        self.max_dv
    }

    /// The Lipschitz constant of the bilinear interpolant (m per texel): the largest gradient
    /// norm, `max over cells √(A² + B²)`, `A = max(|h₁₀ − h₀₀|, |h₁₁ − h₀₁|)`,
    /// `B = max(|h₀₁ − h₀₀|, |h₁₁ − h₁₀|)`.
    ///
    /// Inside a cell `∂h/∂u = (1 − f_v)(h₁₀ − h₀₀) + f_v(h₁₁ − h₀₁)` is a convex combination, so
    /// `|∂h/∂u| ≤ A`, and likewise `|∂h/∂v| ≤ B`; the interpolant is continuous across cells, so
    /// the largest gradient norm bounds `|h(p) − h(q)|/|p − q|` on every segment.
    ///
    /// # Returns
    /// The Lipschitz constant of the interpolant in metres per texel, `≥ 0`.
    ///
    /// # References
    /// Hart 1996 (Lipschitz bounds for sphere tracing); docs/equations.md §3.
    pub fn max_gradient(&self) -> f64 {
        self.max_gradient
    }

    /// Bilinear, toroidal height at `(u, v)` (texels), m.
    #[inline]
    pub fn sample(&self, u: f64, v: f64) -> f64 {
        self.grid.sample(u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn eq1_maps_the_intensity_range_to_zero_hf_and_eq4_inverts_it() {
        assert_relative_eq!(height_from_intensity(20.0, 20.0, 220.0, 3.0), 0.0);
        assert_relative_eq!(height_from_intensity(220.0, 20.0, 220.0, 3.0), 3.0);
        assert_relative_eq!(height_from_intensity(70.0, 20.0, 220.0, 3.0), 0.75);
        assert_relative_eq!(intensity_from_height(0.75, 20.0, 220.0, 3.0), 70.0);
        assert_relative_eq!(intensity_change(0.75, 20.0, 220.0, 3.0), 50.0);
    }

    #[test]
    fn a_uniform_image_is_an_error() {
        let grey = Texture::from_fn(8, 8, |_, _| [128.0; 3]);
        let e = HeightField::from_texture(&grey, 1.0, "grey.png").unwrap_err();
        assert!(matches!(e, TextureError::Flat { .. }), "{e}");
        assert!(e.to_string().contains("grey.png"));
    }

    /// Heights are stored in `f32`: `0.1 i` and their differences carry a relative rounding of
    /// ~10⁻⁷; a wrong neighbour or a missed wrap is off by ≥ 30 %.
    const F32_REL: f64 = 1e-6;

    #[test]
    fn slope_bounds_of_a_ramp() {
        // h = 0.1 i on a 4-periodic lattice: the wrap jumps by 0.3.
        let hf = HeightField::from_heights(Grid::from_fn(4, 4, |i, _| 0.1 * i as f32));
        assert_relative_eq!(hf.max_du(), 0.3, max_relative = F32_REL);
        assert_relative_eq!(hf.max_dv(), 0.0);
        assert_relative_eq!(hf.max_gradient(), 0.3, max_relative = F32_REL);
        assert_relative_eq!(hf.mean(), 0.15, max_relative = F32_REL);
    }
}
