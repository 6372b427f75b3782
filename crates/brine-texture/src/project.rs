//! The paper's renderer (Lai & Wu §III.C, Fig. 5): the sea is the plane `y = 0` and each pixel
//! shows the relit texture where its ray meets the plane; the bed, when given, shows through by
//! refraction with the composed surface's normal (Fig. 9).

use brine_optics::{JerlovType, RgbBands, WATER_IOR, WaterBody, WaterRgb, fresnel_dielectric, refract};
use brine_sky::Sky;
use glam::DVec3;
use palette::{LinSrgb, Srgb};
use rayon::prelude::*;

use crate::error::check;
use crate::ocean::mip_level;
use crate::texture::bilinear;
use crate::{OceanFrame, Pinhole, RelightRule, Texture, TextureError};

/// Options of [`render_projection`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProjectionOptions {
    /// Filter the texture over each pixel's footprint with mip levels (beyond the paper, which
    /// samples bilinearly: far texels alias without it).
    pub mipmaps: bool,
    /// Depth of the bed plane below sea level (m), `(0, 1000]`; used when the ocean has a bed.
    pub bed_depth_m: f64,
    /// Beam attenuation of the water per channel (m⁻¹), each `≥ 0`: the bed seen through a path
    /// `s` is weighted by `(1 − F) e^{−c s}`.
    pub attenuation_m: [f64; 3],
}

impl Default for ProjectionOptions {
    fn default() -> Self {
        // Beam attenuation c = a + b of Jerlov IB water per channel (brine-optics, sRGB band
        // averages).
        let water = WaterRgb::new(&WaterBody::jerlov(JerlovType::IB), RgbBands::SrgbAverage);
        Self { mipmaps: true, bed_depth_m: 2.0, attenuation_m: water.c.to_array() }
    }
}

impl ProjectionOptions {
    /// Checks the fields.
    ///
    /// # Errors
    /// [`TextureError::OutOfRange`] naming the bad field.
    pub fn validate(&self) -> Result<(), TextureError> {
        check("bed_depth_m", self.bed_depth_m, self.bed_depth_m > 0.0 && self.bed_depth_m <= 1000.0, "(0, 1000] m")?;
        for c in self.attenuation_m {
            check("attenuation_m", c, c >= 0.0 && c.is_finite(), "[0, ∞) 1/m")?;
        }
        Ok(())
    }
}

/// Encodes a display-linear colour (each channel clipped to `[0, 1]`) to 8-bit sRGB.
fn encode(c: DVec3) -> [u8; 3] {
    let lin = LinSrgb::new(c.x.clamp(0.0, 1.0) as f32, c.y.clamp(0.0, 1.0) as f32, c.z.clamp(0.0, 1.0) as f32);
    let s: Srgb<u8> = Srgb::from_linear(lin);
    [s.red, s.green, s.blue]
}

/// Distance `t > 0` along the unit direction `d` from `o` to the plane `y = 0`, if the ray meets
/// it (`o.y > 0`, `d.y < 0`).
#[inline]
fn plane_hit(o: DVec3, d: DVec3) -> Option<f64> {
    (o.y > 0.0 && d.y < -1e-9).then(|| -o.y / d.y)
}

/// What a pixel of a projection view sees.
#[derive(Debug, Clone, Copy, PartialEq)]
enum ViewPixel {
    /// The sea plane at `(x, z)` (m), with the pixel's footprint there (m).
    Sea { x: f64, z: f64, footprint_m: f64 },
    /// The sky, already encoded.
    Sky([u8; 3]),
}

/// Everything of a projection that depends only on the camera, computed once per view (the
/// camera of an animation does not move): where each pixel's ray meets the plane `y = 0`, its
/// footprint there, and the colour of the pixels that see the sky.
#[derive(Debug, Clone, PartialEq)]
pub struct ProjectionView {
    camera: Pinhole,
    pixels: Vec<ViewPixel>,
}

impl ProjectionView {
    /// The view of `camera` with brine-sky's sky behind the sea: its radiance `L` scaled by the
    /// zenith luminance `Y_z` and mapped per channel by `x/(1 + x)`, `x = L/Y_z` (the zenith at
    /// ½), sRGB-encoded (a display choice: the paper shows no sky model).
    pub fn new(camera: &Pinhole, sky: &Sky) -> Self {
        let zenith = sky.radiance_rgb(DVec3::Y);
        let y = 0.2126 * zenith.x + 0.7152 * zenith.y + 0.0722 * zenith.z;
        let k = if y > 0.0 { 1.0 / y } else { 0.0 };
        Self::build(camera, &|d| {
            let x = sky.background_rgb(d) * k;
            encode(x / (DVec3::ONE + x))
        })
    }

    /// The view of `camera` with a uniform colour behind the sea.
    pub fn with_background(camera: &Pinhole, colour: [u8; 3]) -> Self {
        Self::build(camera, &|_| colour)
    }

    fn build(camera: &Pinhole, sky: &(dyn Fn(DVec3) -> [u8; 3] + Sync)) -> Self {
        let (w, h) = (camera.width, camera.height);
        let alpha = camera.pixel_angle();
        let o = camera.position;
        let pixels = (0..w * h)
            .into_par_iter()
            .map(|p| {
                let d = camera.direction(f64::from(p % w) + 0.5, f64::from(p / w) + 0.5);
                match plane_hit(o, d) {
                    // Footprint: t α across the view, t α/|d_y| along it; their geometric mean.
                    Some(t) => {
                        ViewPixel::Sea { x: o.x + t * d.x, z: o.z + t * d.z, footprint_m: t * alpha / (-d.y).sqrt() }
                    }
                    None => ViewPixel::Sky(sky(d)),
                }
            })
            .collect();
        Self { camera: *camera, pixels }
    }

    /// The camera.
    pub fn camera(&self) -> &Pinhole {
        &self.camera
    }
}

/// Renders a frame by plain perspective projection of the plane `y = 0` (Lai & Wu §III.C): each
/// pixel's ray meets the plane at `(x, z)`, which shows the relit colour `S_c(x, z, t)`
/// (Eq. 11), filtered over the pixel's footprint when `options.mipmaps`. With a bed, the
/// composed surface's normal refracts the ray (Snell, `n = 1.333`) onto the bed plane
/// `y = −bed_depth_m`, and the colour is `T·bed + (1 − T)·S_c` with `T = (1 − F(θ)) e^{−c s}`
/// per channel (exact Fresnel `F`, path `s` below the surface), as in their Fig. 9.
///
/// # Arguments
/// - `frame`: the ocean at one animation frame.
/// - `view`: the camera's precomputed view ([`ProjectionView::new`]).
/// - `options`: filtering and bed.
///
/// # Returns
/// The 8-bit sRGB image (the texture's own encoding).
///
/// # References
/// Lai & Wu §III.C (Fig. 5), §IV (Fig. 9: "refraction result with a rock texture as the bed").
pub fn render_projection(
    frame: &OceanFrame<'_>,
    view: &ProjectionView,
    options: &ProjectionOptions,
) -> image::RgbImage {
    let camera = &view.camera;
    let (w, h) = (camera.width, camera.height);
    let bed = frame.ocean().bed().is_some();
    let fast = FastFrame::new(frame);
    let mut bytes = vec![0u8; (w * h * 3) as usize];
    bytes.par_chunks_mut((w * 3) as usize).enumerate().for_each(|(j, row)| {
        let pixels = &view.pixels[j * w as usize..(j + 1) * w as usize];
        for (i, (px, pixel)) in row.chunks_exact_mut(3).zip(pixels).enumerate() {
            let (x, z, footprint_m) = match *pixel {
                ViewPixel::Sky(c) => {
                    px.copy_from_slice(&c);
                    continue;
                }
                ViewPixel::Sea { x, z, footprint_m } => (x, z, footprint_m),
            };
            let mut c = fast.colour(frame, x, z, if options.mipmaps { footprint_m } else { 0.0 });
            if bed {
                let d = camera.direction(i as f64 + 0.5, j as f64 + 0.5);
                let n = frame.normal(x, z);
                let cos_i = (-d.dot(n)).clamp(0.0, 1.0);
                let f = fresnel_dielectric(cos_i, 1.0, WATER_IOR);
                if let Some(r) = refract(d, n, 1.0, WATER_IOR).filter(|r| r.y < -1e-6) {
                    let s = options.bed_depth_m / -r.y;
                    let b = frame.bed_colour(x + s * r.x, z + s * r.z).unwrap_or(c);
                    for k in 0..3 {
                        let tr = ((1.0 - f) * (-options.attenuation_m[k] * s).exp()) as f32;
                        c[k] = tr * b[k] + (1.0 - tr) * c[k];
                    }
                }
            }
            for k in 0..3 {
                px[k] = (c[k].clamp(0.0, 255.0) + 0.5) as u8;
            }
        }
    });
    image::RgbImage::from_raw(w, h, bytes).expect("sizes match")
}

/// A texture packed as 8-bit RGBA texels (a quarter of the memory of `[f32; 3]`, so that the
/// per-pixel lookups stay in cache), sampled bilinearly in `f32`.
struct Packed {
    width: usize,
    height: usize,
    texels: Vec<[u8; 4]>,
}

impl Packed {
    fn new(t: &Texture) -> Self {
        let texels = t.texels().iter().map(|c| [q8(c[0]), q8(c[1]), q8(c[2]), 0]).collect();
        Self { width: t.width(), height: t.height(), texels }
    }

    #[inline(always)]
    fn sample(&self, u: f64, v: f64) -> [f32; 3] {
        bilinear(&self.texels, self.width, self.height, u, v)
    }
}

/// A level rounded to 8 bits.
#[inline]
fn q8(v: f32) -> u8 {
    (v.clamp(0.0, 255.0) + 0.5) as u8
}

/// The per-frame data of the projection's inner loop: the small-wave colour and its mip levels
/// packed to 8 bits, the relighting constants in `f32`. Matches [`OceanFrame::colour_filtered`]
/// up to the 8-bit rounding of the texels (tested).
struct FastFrame {
    levels: Vec<Packed>,
    inv_delta_max: f32,
    /// `Δheight_max^{−3/4}`: Eq. 9's `(room/Δh_max)^{3/4} = room^{3/4} Δh_max^{−3/4}`.
    inv_delta_max_34: f32,
    /// `k^{3/4}` for `k = 0, 1, …, 256`, interpolated linearly between levels (error below 0.1
    /// level on `room^{3/4}`, at `room < 1`).
    pow34_table: [f32; 257],
    rule: RelightRule,
}

impl FastFrame {
    fn new(frame: &OceanFrame<'_>) -> Self {
        let levels = std::iter::once(&frame.small.colour).chain(&frame.small.mips).map(Packed::new).collect();
        let r = frame.ocean().relighting();
        let inv_delta_max = if r.delta_height_max > 0.0 { (1.0 / r.delta_height_max) as f32 } else { 0.0 };
        let pow34_table = std::array::from_fn(|k| pow34(k as f32));
        Self { levels, inv_delta_max, inv_delta_max_34: pow34(inv_delta_max), pow34_table, rule: r.rule }
    }

    /// Relit colour at `(x, z)` over a footprint of `footprint_m` metres (0: no filtering).
    #[inline(always)]
    fn colour(&self, frame: &OceanFrame<'_>, x: f64, z: f64, footprint_m: f64) -> [f32; 3] {
        let s = frame.small_uv(x, z);
        let lod = mip_level(footprint_m / frame.ocean().params().texel_m).min((self.levels.len() - 1) as f64);
        let l0 = lod as usize;
        let f = (lod - l0 as f64) as f32;
        let at = |l: usize| -> [f32; 3] {
            let scale = (1u64 << l) as f64;
            let off = 0.5 * (scale - 1.0);
            self.levels[l].sample((s.x - off) / scale, (s.y - off) / scale)
        };
        let mut c = at(l0);
        if f > 0.0 && l0 + 1 < self.levels.len() {
            let b = at(l0 + 1);
            for k in 0..3 {
                c[k] += (b[k] - c[k]) * f;
            }
        }
        let dh = frame.delta_height(x, z) as f32;
        if self.inv_delta_max > 0.0 {
            let up = dh >= 0.0;
            let sign = if up { 1.0 } else { -1.0 };
            match self.rule {
                RelightRule::Paper => {
                    let k = dh.abs() * self.inv_delta_max_34;
                    for v in &mut c {
                        let room = if up { 255.0 - *v } else { *v };
                        *v = (*v + sign * k * self.pow34_lookup(room)).clamp(0.0, 255.0);
                    }
                }
                RelightRule::Bounded => {
                    let r = pow34((dh.abs() * self.inv_delta_max).min(1.0));
                    for v in &mut c {
                        let room = if up { 255.0 - *v } else { *v };
                        *v = (*v + sign * room * r).clamp(0.0, 255.0);
                    }
                }
            }
        }
        c
    }
}

impl FastFrame {
    /// `x^{3/4}` for `x ∈ [0, 255]` from the table.
    #[inline(always)]
    fn pow34_lookup(&self, x: f32) -> f32 {
        let x = x.clamp(0.0, 255.0);
        let i = x as usize;
        let f = x - i as f32;
        let (a, b) = (self.pow34_table[i], self.pow34_table[i + 1]);
        a + (b - a) * f
    }
}

/// `x^{3/4} = √(x √x)` in `f32`, `x ≥ 0`.
#[inline(always)]
fn pow34(x: f32) -> f32 {
    let x = x.max(0.0);
    (x * x.sqrt()).sqrt()
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::{OceanParams, PhotoOcean, SynthesisParams};

    /// The fast path rounds texels to 8 bits (±0.5 level) and computes in `f32`.
    const FAST_PATH_LEVELS: f32 = 1.0;

    #[test]
    fn fast_colour_matches_the_reference_composition() {
        let small = Texture::from_fn(40, 40, |i, j| [30.0 + ((i * 7 + j * 13) % 29) as f32 * 7.0, 100.0, 170.0]);
        let main = Texture::from_fn(40, 40, |i, j| [50.0 + ((i * 3 + j * 5) % 37) as f32 * 5.0, 90.0, 140.0]);
        for rule in [RelightRule::Paper, RelightRule::Bounded] {
            let params = OceanParams {
                synthesis: SynthesisParams { patch_size: 16, boundary_width: 2, ..SynthesisParams::default() },
                small_size: 48,
                main_size: 48,
                bed_size: 48,
                frames: 2,
                links_per_frame: 1,
                mesh_spacing: 12,
                relight: rule,
                ..OceanParams::default()
            };
            let ocean = PhotoOcean::new(&small, &main, None, &params, 3, &|_| {}).unwrap();
            let frame = ocean.frame(3);
            let fast = FastFrame::new(&frame);
            for k in 0..200 {
                let (x, z) = (k as f64 * 0.731 - 40.0, k as f64 * 0.377 + 3.0);
                let footprint = [0.0, 0.05, 0.3, 2.0][k % 4];
                let reference = frame.colour_filtered(x, z, footprint);
                let got = fast.colour(&frame, x, z, footprint);
                for c in 0..3 {
                    assert!(
                        (reference[c] - got[c]).abs() <= FAST_PATH_LEVELS,
                        "{rule:?} at ({x}, {z}): {reference:?} vs {got:?}"
                    );
                }
            }
        }
        let _ = DVec3::ZERO;
    }
}
