//! Images as the paper handles them: RGB texels in `[0, 255]` (the 8-bit sRGB-encoded values of a
//! photo, as `f32`) and scalar grids (intensities, heights), both sampled toroidally.

use std::path::Path;

use crate::TextureError;

/// Weights of the intensity `I = 0.299 R + 0.587 G + 0.114 B` (Rec. 601 luma of the 8-bit values).
pub const LUMA_WEIGHTS: [f32; 3] = [0.299, 0.587, 0.114];

/// The intensity of one texel, `I = 0.299 R + 0.587 G + 0.114 B`.
///
/// # Arguments
/// - `rgb`: channel values, each `[0, 255]`.
///
/// # Returns
/// `I` in `[0, 255]`.
///
/// # References
/// ITU-R BT.601 luma; Lai & Wu use "the intensity" of the texture without defining it.
#[inline]
pub fn intensity(rgb: [f32; 3]) -> f32 {
    LUMA_WEIGHTS[0] * rgb[0] + LUMA_WEIGHTS[1] * rgb[1] + LUMA_WEIGHTS[2] * rgb[2]
}

/// An RGB image, row-major, top row first, channel values in `[0, 255]`.
///
/// Texel `(i, j)` sits at the lattice point `(i, j)`; [`Texture::sample`] interpolates bilinearly
/// between lattice points and wraps around (every texture here is a tile of a torus).
#[derive(Debug, Clone, PartialEq)]
pub struct Texture {
    width: usize,
    height: usize,
    texels: Vec<[f32; 3]>,
}

impl Texture {
    /// A texture from its texels.
    ///
    /// # Errors
    /// [`TextureError::BadTexels`] if `texels.len() != width·height`, a size is zero, or a value is
    /// outside `[0, 255]` or not finite.
    pub fn new(width: usize, height: usize, texels: Vec<[f32; 3]>) -> Result<Self, TextureError> {
        if width == 0 || height == 0 || texels.len() != width * height {
            return Err(TextureError::BadTexels(format!(
                "a {width}×{height} texture needs {} texels, got {}",
                width * height,
                texels.len()
            )));
        }
        if let Some(bad) = texels.iter().flatten().find(|v| !(0.0..=255.0).contains(*v)) {
            return Err(TextureError::BadTexels(format!("texel value {bad} is outside [0, 255]")));
        }
        Ok(Self { width, height, texels })
    }

    /// A texture from 8-bit RGB bytes (`3·width·height` of them).
    ///
    /// # Errors
    /// [`TextureError::BadTexels`] if the length is wrong or a size is zero.
    pub fn from_rgb8(width: usize, height: usize, bytes: &[u8]) -> Result<Self, TextureError> {
        if bytes.len() != 3 * width * height {
            return Err(TextureError::BadTexels(format!(
                "a {width}×{height} RGB image needs {} bytes, got {}",
                3 * width * height,
                bytes.len()
            )));
        }
        let texels = bytes.chunks_exact(3).map(|c| [f32::from(c[0]), f32::from(c[1]), f32::from(c[2])]).collect();
        Self::new(width, height, texels)
    }

    /// A texture whose texel `(i, j)` is `f(i, j)`, each channel clamped to `[0, 255]` (NaN to 0).
    pub fn from_fn(width: usize, height: usize, f: impl Fn(usize, usize) -> [f32; 3]) -> Self {
        assert!(width > 0 && height > 0, "Texture::from_fn: empty size {width}×{height}");
        let clamp = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 255.0) };
        let texels =
            (0..height).flat_map(|j| (0..width).map(move |i| (i, j))).map(|(i, j)| f(i, j).map(clamp)).collect();
        Self { width, height, texels }
    }

    /// Internal constructor for texels known to be in range.
    pub(crate) fn from_texels_unchecked(width: usize, height: usize, texels: Vec<[f32; 3]>) -> Self {
        debug_assert_eq!(texels.len(), width * height);
        Self { width, height, texels }
    }

    /// Reads a PNG or JPEG photo (any bit depth; alpha is ignored).
    ///
    /// # Arguments
    /// - `path`: the file.
    /// - `what`: its role, used in error messages (e.g. `"--small"`).
    ///
    /// # Errors
    /// [`TextureError::Io`] if the file cannot be opened, [`TextureError::Decode`] if it is not a
    /// PNG or JPEG image or is corrupt.
    pub fn load(path: &Path, what: &str) -> Result<Self, TextureError> {
        let shown = path.display().to_string();
        let io = |source| TextureError::Io { what: what.to_owned(), path: shown.clone(), source };
        let decode = |message: String| TextureError::Decode { what: what.to_owned(), path: shown.clone(), message };
        let reader = image::ImageReader::open(path).map_err(io)?.with_guessed_format().map_err(io)?;
        if reader.format().is_none() {
            return Err(decode("unsupported image format (expected PNG or JPEG)".to_owned()));
        }
        let img = reader.decode().map_err(|e| match e {
            image::ImageError::Unsupported(u) => decode(format!("unsupported image: {u} (expected PNG or JPEG)")),
            other => decode(format!("cannot decode: {other}")),
        })?;
        let rgb = img.to_rgb8();
        Self::from_rgb8(rgb.width() as usize, rgb.height() as usize, rgb.as_raw())
    }

    /// The texture as an 8-bit image (values rounded).
    pub fn to_image(&self) -> image::RgbImage {
        let bytes = self.texels.iter().flat_map(|t| t.map(|v| v.round().clamp(0.0, 255.0) as u8)).collect();
        image::RgbImage::from_raw(self.width as u32, self.height as u32, bytes).expect("sizes match")
    }

    /// Width (texels).
    #[inline]
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height (texels).
    #[inline]
    pub fn height(&self) -> usize {
        self.height
    }

    /// The texels, row-major.
    #[inline]
    pub fn texels(&self) -> &[[f32; 3]] {
        &self.texels
    }

    /// Texel `(i, j)`, `i < width`, `j < height`.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> [f32; 3] {
        self.texels[j * self.width + i]
    }

    /// Texel `(i mod width, j mod height)`.
    #[inline]
    pub fn get_wrapped(&self, i: isize, j: isize) -> [f32; 3] {
        let x = i.rem_euclid(self.width as isize) as usize;
        let y = j.rem_euclid(self.height as isize) as usize;
        self.texels[y * self.width + x]
    }

    /// Bilinear, toroidal sample at `(u, v)` (texels; texel `(i, j)` at the lattice point).
    #[inline(always)]
    pub fn sample(&self, u: f64, v: f64) -> [f32; 3] {
        bilinear(&self.texels, self.width, self.height, u, v)
    }

    /// The intensity [`intensity`] of every texel.
    pub fn intensity(&self) -> Grid {
        Grid::from_values_unchecked(self.width, self.height, self.texels.iter().map(|t| intensity(*t)).collect())
    }

    /// Smallest and largest intensity `(I_min, I_max)`.
    pub fn intensity_range(&self) -> (f32, f32) {
        self.texels
            .iter()
            .map(|t| intensity(*t))
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), i| (lo.min(i), hi.max(i)))
    }

    /// Mean of each channel.
    pub fn mean(&self) -> [f64; 3] {
        let mut s = [0.0f64; 3];
        for t in &self.texels {
            for k in 0..3 {
                s[k] += f64::from(t[k]);
            }
        }
        s.map(|v| v / self.texels.len() as f64)
    }

    /// The `w × h` window with top-left texel `(x, y)`, wrapping around.
    pub fn window(&self, x: isize, y: isize, w: usize, h: usize) -> Texture {
        let texels = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| self.get_wrapped(x + i as isize, y + j as isize))
            .collect();
        Self { width: w, height: h, texels }
    }

    /// The image downsampled by 2 with a 2×2 box filter, toroidally (odd sizes round up).
    pub fn half(&self) -> Texture {
        let (w, h) = (self.width.div_ceil(2).max(1), self.height.div_ceil(2).max(1));
        let mut texels = Vec::with_capacity(w * h);
        for j in 0..h {
            let (y0, y1) = ((2 * j) % self.height, (2 * j + 1) % self.height);
            for i in 0..w {
                let (x0, x1) = ((2 * i) % self.width, (2 * i + 1) % self.width);
                let q = [self.get(x0, y0), self.get(x1, y0), self.get(x0, y1), self.get(x1, y1)];
                texels.push(std::array::from_fn(|k| 0.25 * (q[0][k] + q[1][k] + q[2][k] + q[3][k])));
            }
        }
        Self { width: w, height: h, texels }
    }
}

/// `i mod n` in `[0, n)`, with a mask when `n` is a power of two.
#[inline(always)]
pub(crate) fn wrap_index(i: i64, n: usize) -> usize {
    if n.is_power_of_two() { (i & (n as i64 - 1)) as usize } else { i.rem_euclid(n as i64) as usize }
}

/// `⌊x⌋` as an integer without a call to `floor` (which is a library call on baseline x86-64);
/// values beyond ±2⁶³ saturate, NaN gives 0.
#[inline(always)]
pub(crate) fn floor_i64(x: f64) -> i64 {
    let i = x as i64;
    if (i as f64) > x { i - 1 } else { i }
}

/// Bilinear, toroidal sample at `(u, v)` (texels) of the first three channels of `texels`
/// (row-major, `width × height`), interpolated in `f32`.
#[inline(always)]
pub(crate) fn bilinear<T: Copy + Into<f32>, const N: usize>(
    texels: &[[T; N]],
    width: usize,
    height: usize,
    u: f64,
    v: f64,
) -> [f32; 3] {
    let (x0, y0, x1, y1, fx, fy) = lattice(u, v, width, height);
    let (a, b, c, d) =
        (texels[y0 * width + x0], texels[y0 * width + x1], texels[y1 * width + x0], texels[y1 * width + x1]);
    let (fx, fy) = (fx as f32, fy as f32);
    std::array::from_fn(|k| {
        let (a, b, c, d): (f32, f32, f32, f32) = (a[k].into(), b[k].into(), c[k].into(), d[k].into());
        let top = a + (b - a) * fx;
        top + (c + (d - c) * fx - top) * fy
    })
}

/// Lattice cell of a toroidal bilinear lookup: `(x0, y0, x1, y1, fx, fy)`.
#[inline(always)]
pub(crate) fn lattice(u: f64, v: f64, width: usize, height: usize) -> (usize, usize, usize, usize, f64, f64) {
    let (iu, iv) = (floor_i64(u), floor_i64(v));
    // Far from the origin (beyond 2⁵² texels) the fraction loses meaning; clamp it to [0, 1].
    let (fx, fy) = ((u - iu as f64).clamp(0.0, 1.0), (v - iv as f64).clamp(0.0, 1.0));
    let (x0, y0) = (wrap_index(iu, width), wrap_index(iv, height));
    let x1 = if x0 + 1 == width { 0 } else { x0 + 1 };
    let y1 = if y0 + 1 == height { 0 } else { y0 + 1 };
    (x0, y0, x1, y1, fx, fy)
}

/// A scalar field on a `width × height` lattice (intensities or heights), sampled toroidally.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    width: usize,
    height: usize,
    values: Vec<f32>,
}

impl Grid {
    /// A grid from its values, row-major.
    ///
    /// # Errors
    /// [`TextureError::BadTexels`] if the length is wrong, a size is zero or a value is not finite.
    pub fn new(width: usize, height: usize, values: Vec<f32>) -> Result<Self, TextureError> {
        if width == 0 || height == 0 || values.len() != width * height {
            return Err(TextureError::BadTexels(format!(
                "a {width}×{height} grid needs {} values, got {}",
                width * height,
                values.len()
            )));
        }
        if values.iter().any(|v| !v.is_finite()) {
            return Err(TextureError::BadTexels("grid values must be finite".to_owned()));
        }
        Ok(Self { width, height, values })
    }

    pub(crate) fn from_values_unchecked(width: usize, height: usize, values: Vec<f32>) -> Self {
        debug_assert_eq!(values.len(), width * height);
        Self { width, height, values }
    }

    /// A grid whose value at `(i, j)` is `f(i, j)`.
    pub fn from_fn(width: usize, height: usize, f: impl Fn(usize, usize) -> f32) -> Self {
        let values = (0..height).flat_map(|j| (0..width).map(move |i| (i, j))).map(|(i, j)| f(i, j)).collect();
        Self { width, height, values }
    }

    /// Width.
    #[inline]
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height.
    #[inline]
    pub fn height(&self) -> usize {
        self.height
    }

    /// The values, row-major.
    #[inline]
    pub fn values(&self) -> &[f32] {
        &self.values
    }

    /// Value at `(i, j)`.
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> f32 {
        self.values[j * self.width + i]
    }

    /// Value at `(i mod width, j mod height)`.
    #[inline]
    pub fn get_wrapped(&self, i: isize, j: isize) -> f32 {
        let x = i.rem_euclid(self.width as isize) as usize;
        let y = j.rem_euclid(self.height as isize) as usize;
        self.values[y * self.width + x]
    }

    /// Bilinear, toroidal sample at `(u, v)` (lattice units), in `f64`.
    #[inline(always)]
    pub fn sample(&self, u: f64, v: f64) -> f64 {
        let (x0, y0, x1, y1, fx, fy) = lattice(u, v, self.width, self.height);
        let w = self.width;
        let a = f64::from(self.values[y0 * w + x0]);
        let b = f64::from(self.values[y0 * w + x1]);
        let c = f64::from(self.values[y1 * w + x0]);
        let d = f64::from(self.values[y1 * w + x1]);
        let top = a + (b - a) * fx;
        let bottom = c + (d - c) * fx;
        top + (bottom - top) * fy
    }

    /// The bilinear interpolant and its gradient `(f, ∂f/∂u, ∂f/∂v)` at `(u, v)` (one-sided on
    /// cell edges: the gradient of the cell `⌊u⌋, ⌊v⌋`).
    #[inline]
    pub fn sample_with_gradient(&self, u: f64, v: f64) -> (f64, f64, f64) {
        let (x0, y0, x1, y1, fx, fy) = lattice(u, v, self.width, self.height);
        let w = self.width;
        let a = f64::from(self.values[y0 * w + x0]);
        let b = f64::from(self.values[y0 * w + x1]);
        let c = f64::from(self.values[y1 * w + x0]);
        let d = f64::from(self.values[y1 * w + x1]);
        let top = a + (b - a) * fx;
        let bottom = c + (d - c) * fx;
        let du = (b - a) + ((d - c) - (b - a)) * fy;
        let dv = bottom - top;
        (top + dv * fy, du, dv)
    }

    /// Smallest and largest value.
    pub fn range(&self) -> (f32, f32) {
        self.values.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }

    /// Mean value (summed in `f64`, in order).
    pub fn mean(&self) -> f64 {
        self.values.iter().map(|&v| f64::from(v)).sum::<f64>() / self.values.len() as f64
    }

    /// Central-difference derivatives `(∂f/∂u, ∂f/∂v)` at every lattice point (toroidal), per
    /// lattice unit.
    pub fn central_gradients(&self) -> (Grid, Grid) {
        let (w, h) = (self.width, self.height);
        let mut du = Vec::with_capacity(w * h);
        let mut dv = Vec::with_capacity(w * h);
        for j in 0..h {
            let (up, down) = ((j + h - 1) % h, (j + 1) % h);
            for i in 0..w {
                let (left, right) = ((i + w - 1) % w, (i + 1) % w);
                du.push(0.5 * (self.get(right, j) - self.get(left, j)));
                dv.push(0.5 * (self.get(i, down) - self.get(i, up)));
            }
        }
        (Self { width: w, height: h, values: du }, Self { width: w, height: h, values: dv })
    }

    /// The grid as a 16-bit greyscale image, `lo ↦ 0` and `hi ↦ 65535` (clamped).
    pub fn to_grey16(&self, lo: f64, hi: f64) -> image::ImageBuffer<image::Luma<u16>, Vec<u16>> {
        let span = (hi - lo).max(f64::MIN_POSITIVE);
        let data = self
            .values
            .iter()
            .map(|&v| ((f64::from(v) - lo) / span * 65535.0).round().clamp(0.0, 65535.0) as u16)
            .collect();
        image::ImageBuffer::from_raw(self.width as u32, self.height as u32, data).expect("sizes match")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `f32` bilinear interpolation of levels ≤ 255: a few roundings of 2⁻²⁴ relative, ~10⁻⁵
    /// level; a wrong texel or weight is off by levels.
    const F32_LEVELS: f32 = 1e-4;
    /// The same interpolant evaluated by two routes in `f64`.
    const SAME_F64: f64 = 1e-12;
    /// Inside a cell the bilinear interpolant is linear along each axis, so a central difference
    /// with `h = 10⁻⁶` is exact up to the round-off `ε|f|/h` ≈ 10⁻¹⁶ · 30/10⁻⁶ ≈ 10⁻⁹.
    const CENTRAL_DIFFERENCE: f64 = 1e-6;

    #[test]
    fn bilinear_sample_hits_lattice_points_and_wraps() {
        let t = Texture::from_fn(4, 3, |i, j| [(10 * i + j) as f32, 0.0, 255.0]);
        // At a lattice point the bilinear weights are 1 and 0: the texel itself, up to f32 rounding.
        let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= F32_LEVELS);
        assert!(close(t.sample(2.0, 1.0), t.get(2, 1)), "{:?}", t.sample(2.0, 1.0));
        assert!(close(t.sample(6.0, -2.0), t.get(2, 1)), "{:?}", t.sample(6.0, -2.0));
        // Between texel 3 and texel 0 of row 0 (the wrap).
        let s = t.sample(3.5, 0.0);
        assert!((s[0] - 0.5 * (30.0 + 0.0)).abs() < F32_LEVELS, "{s:?}");
    }

    #[test]
    fn grid_gradient_matches_the_interpolant() {
        let g = Grid::from_fn(5, 5, |i, j| (i * i + 3 * j) as f32);
        let (f, du, dv) = g.sample_with_gradient(1.25, 2.5);
        assert!((f - g.sample(1.25, 2.5)).abs() < SAME_F64);
        let h = 1e-6;
        assert!((du - (g.sample(1.25 + h, 2.5) - g.sample(1.25 - h, 2.5)) / (2.0 * h)).abs() < CENTRAL_DIFFERENCE);
        assert!((dv - (g.sample(1.25, 2.5 + h) - g.sample(1.25, 2.5 - h)) / (2.0 * h)).abs() < CENTRAL_DIFFERENCE);
    }

    #[test]
    fn out_of_range_texels_are_rejected() {
        assert!(Texture::new(1, 1, vec![[0.0, 256.0, 0.0]]).is_err());
        assert!(Texture::new(2, 1, vec![[0.0; 3]]).is_err());
        assert!(Texture::from_rgb8(1, 1, &[1, 2]).is_err());
    }
}
