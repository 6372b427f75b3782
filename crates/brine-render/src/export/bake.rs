//! Tileable maps of the sea over a square: `brine bake` (OpenEXR, or 16-bit PNG).

use std::path::{Path, PathBuf};

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use brine_waves::{BOX_WIDTH_PER_SIGMA, FrameSurface, SeaFrame};

use crate::World;

/// The up axis of the maps' vectors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum, serde::Serialize)]
pub enum UpAxis {
    /// Brine's, glTF's, Houdini's, Unity's: `(x east, y up, z south)`.
    #[default]
    Y,
    /// Blender's: `(X east, Y north, Z up)` = `(x, −z, y)`.
    Z,
}

impl UpAxis {
    /// A vector of Brine's axes in this convention.
    pub fn convert(self, v: DVec3) -> DVec3 {
        match self {
            UpAxis::Y => v,
            UpAxis::Z => DVec3::new(v.x, -v.z, v.y),
        }
    }
}

/// What to bake.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BakeOptions {
    /// Texels per side, `[2, 16384]`.
    pub size: usize,
    /// Side of the tile (m); the waves are snapped to its lattice by the world.
    pub tile_m: f64,
    /// Up axis of the vector maps.
    pub up: UpAxis,
}

/// Largest map side of `brine bake` (memory refuses far smaller ones first on most machines).
pub const MAX_BAKE_SIZE: usize = 1 << 20;

/// Bytes per texel while baking: six maps of up to 3 f32 channels (13 floats), held once as
/// computed and once encoded.
const BYTES_PER_TEXEL: u64 = 2 * 13 * 4;

impl BakeOptions {
    /// Estimated peak memory of one frame (bytes).
    pub fn memory_estimate(&self) -> u64 {
        (self.size as u64).saturating_mul(self.size as u64).saturating_mul(BYTES_PER_TEXEL)
    }

    /// Checks the options and the memory they need.
    ///
    /// # Errors
    /// A message naming the flag and its range, or the memory estimate.
    pub fn check(&self) -> Result<(), String> {
        if !(2..=MAX_BAKE_SIZE).contains(&self.size) {
            return Err(format!("--size = {} is out of range: expected [2, {MAX_BAKE_SIZE}] texels", self.size));
        }
        if !(1e-3..=1e6).contains(&self.tile_m) {
            return Err(format!(
                "--tile-m = {} is out of range: expected [0.001, 1e6] m",
                crate::cli::num(self.tile_m)
            ));
        }
        super::check_memory(&format!("a {0} × {0} bake", self.size), self.memory_estimate())
    }
}

/// The maps of one frame, row-major (row `j` at `z = jL/N`, top row first; column `i` at
/// `x = iL/N`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BakedFrame {
    /// Texels per side.
    pub size: usize,
    /// Time of the frame (s).
    pub time: f64,
    /// The maps.
    pub maps: BakeMaps,
    /// What the grid could not carry ([`GridLimit`]): for a trochoid or Gerstner sea the waves
    /// left out; for the FFT sea the modes left out, with the slopes its filtered normals average
    /// away (baked at the world's own time, whose slope pyramids the world holds; at another
    /// instant its normals are those of the band-limited sea, and the slopes are those of the
    /// modes left out); `None` for the sine sea, whose maps are point samples.
    pub limit: Option<GridLimit>,
}

/// The waves a bake's grid leaves out: those shorter than two texels, which the grid would show
/// as other, longer waves (brine-waves `grid_band`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridLimit {
    /// Waves shorter than this are left out (m): two texels.
    pub shortest_wave_m: f64,
    /// Waves faded (shorter than three texels), of which those under two are left out; for the
    /// FFT sea, its modes (each wave vector of its spectral grids once).
    pub faded_waves: Option<usize>,
    /// Slope covariance `(⟨ζx²⟩, ⟨ζx ζz⟩, ⟨ζz²⟩)` (dimensionless, Brine's axes x east, z south)
    /// of what the fade removed (for the FFT sea: what the normals' filter averaged away, the
    /// mean over the texels): for a roughness added to the normal map's.
    pub lost_slope_covariance: [f64; 3],
}

/// The baked maps (f32 per channel).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BakeMaps {
    /// Vector displacement `(D_x, h, D_z)` (m, in the up axis' convention): the texel's rest
    /// position `u` goes to `u + (D_x, 0, D_z)` and up by `h`.
    pub displacement: Vec<[f32; 3]>,
    /// Unit normal of the surface there.
    pub normal: Vec<[f32; 3]>,
    /// Foam cover `[0, 1]`.
    pub foam: Vec<f32>,
    /// Active whitecap cover `[0, 1]`.
    pub whitecap: Vec<f32>,
    /// Jacobian determinant of the horizontal map.
    pub jacobian: Vec<f32>,
    /// The minor eigenvector of the deformation (horizontal, unit: `(e_x, e_z)` or `(e_X, e_Y)`)
    /// and its eigenvalue `μ₋` (Blender's "spray" map: where `μ₋ < 0` the surface folds).
    pub spray: Vec<[f32; 3]>,
}

/// Bakes the sea of `world` (built on the tile's lattice, `World::on_lattice`) at time `t`.
///
/// Texel `(i, j)` is the rest position `u = (iL/N, jL/N)`: it goes to `x = u + D(u)` (brine-waves
/// `SeaFrame::rest_displacement`), and the maps hold the traced surface there (`SeaFrame::sample`)
/// and the renderer's white water at a footprint of one texel. A trochoid or Gerstner sea is
/// baked band-limited to the grid: its waves shorter than two texels are left out, those up to
/// three faded (brine-waves `Ocean::grid_band`), so that no wave shows in the maps as another
/// (sampled on the grid, a wave beyond the grid's Nyquist wavenumber reads as a longer wave of
/// another direction); [`BakedFrame::limit`] says what was left out. The FFT sea is baked with
/// the same weights on its modes (brine-waves `FftOcean::at_time_on_grid`), and its normal map
/// read through the whole sea's slope pyramids over two texels. The white water is the whole
/// sea's.
///
/// # Arguments
/// - `world`: the world on the lattice; `t`: time (s), finite; `options`: checked options.
///
/// # Returns
/// The [`BakedFrame`].
pub fn bake_frame(world: &World, t: f64, options: &BakeOptions) -> BakedFrame {
    let texel = options.tile_m / options.size as f64;
    // A valid sea's faded Gerstner sum always builds (fading only lowers ΣQ); were it refused,
    // the maps would be the point samples of the sine and FFT seas.
    // The FFT sea: its modes too short for the texels left out of its cascades; its normal map
    // is read through the whole sea's slope pyramids (`bake_sea`), whose box filter reports the
    // slopes it averaged away.
    if world.ocean().fft_ocean().is_some_and(|o| o.modes_faded_on_grid(texel) == 0) {
        // Every mode fits: the world's own sea, unchanged (no second synthesis).
        let mut baked = bake_frame_of(world, t, options, None);
        let limit = baked.limit.get_or_insert(GridLimit {
            shortest_wave_m: 2.0 * texel,
            faded_waves: None,
            lost_slope_covariance: [0.0; 3],
        });
        limit.faded_waves = Some(0);
        return baked;
    }
    if let Some((frame, band)) = world.ocean().fft_frame_on_grid(t, texel) {
        let mut baked = bake_frame_of(world, t, options, Some(&frame));
        let limit = baked.limit.get_or_insert(GridLimit {
            shortest_wave_m: 2.0 * texel,
            faded_waves: None,
            lost_slope_covariance: band.lost_slope_covariance.to_array(),
        });
        limit.faded_waves = Some(band.faded);
        return baked;
    }
    match world.ocean().grid_band(texel).ok().flatten() {
        Some((ocean, band)) => {
            let limit = Some(GridLimit {
                shortest_wave_m: 2.0 * texel,
                faded_waves: Some(band.faded),
                lost_slope_covariance: band.lost_slope_covariance.to_array(),
            });
            let mut baked = if band.faded == 0 {
                // Every wave fits: the world's own sea, unchanged.
                bake_frame_of(world, t, options, None)
            } else {
                bake_frame_of(world, t, options, Some(&ocean.at_time(t)))
            };
            baked.limit = limit;
            baked
        }
        None => bake_frame_of(world, t, options, None),
    }
}

/// [`bake_frame`] on the world's sea at `t`, or on `frame` when given (the band-limited sea).
fn bake_frame_of(world: &World, t: f64, options: &BakeOptions, frame: Option<&SeaFrame>) -> BakedFrame {
    match frame {
        Some(f) => bake_sea(world, f, t, options),
        None => world.with_sea_at(t, |f| bake_sea(world, f, t, options)),
    }
}

/// The maps of the sea `frame` at `t`, with `world`'s white water.
fn bake_sea(world: &World, frame: &SeaFrame, t: f64, options: &BakeOptions) -> BakedFrame {
    let n = options.size;
    let texel = options.tile_m / n as f64;
    let up = options.up;
    let f3 = |v: DVec3| v.as_vec3().to_array();
    let mut maps = BakeMaps {
        displacement: vec![[0.0; 3]; n * n],
        normal: vec![[0.0; 3]; n * n],
        foam: vec![0.0; n * n],
        whitecap: vec![0.0; n * n],
        jacobian: vec![0.0; n * n],
        spray: vec![[0.0; 3]; n * n],
    };
    // Row by row, each texel written in place in every map.
    let rows = maps
        .displacement
        .par_chunks_mut(n)
        .zip(maps.normal.par_chunks_mut(n))
        .zip(maps.foam.par_chunks_mut(n))
        .zip(maps.whitecap.par_chunks_mut(n))
        .zip(maps.jacobian.par_chunks_mut(n))
        .zip(maps.spray.par_chunks_mut(n))
        .enumerate();
    // The FFT sea's normals are read through its slope pyramids over a box of two texels (a
    // Gaussian of the same spread), so that no cascade finer than the texels aliases into them;
    // the slopes the box averages away are summed for `grid_limit`.
    let lean = match frame.surface() {
        FrameSurface::Fft(_) if frame.time().to_bits() == world.time().to_bits() => world.fft_slopes.as_ref(),
        _ => None,
    };
    let nyquist_sigma = 2.0 * texel / BOX_WIDTH_PER_SIGMA;
    let lost: Vec<DVec3> = rows
        .map(|(j, (((((disp, nrm), foam), wcap), jac), spray))| {
            let mut lost = DVec3::ZERO;
            for i in 0..n {
                let u = DVec2::new(i as f64, j as f64) * texel;
                let (d, s) = frame.sample_at_rest(u);
                let x = u + d;
                let p = DVec3::new(x.x, s.height, x.y);
                let cover = world.cover_at_time(p, s.normal, t, texel);
                let (mu, e) = s.minor_eigen();
                let e3 = up.convert(DVec3::new(e.x, 0.0, e.y));
                disp[i] = f3(up.convert(DVec3::new(d.x, s.height, d.y)));
                let normal = match lean {
                    Some(l) => {
                        let f = l.filtered(x.x, x.y, nyquist_sigma);
                        lost += f.covariance;
                        DVec3::new(-f.gradient.x, 1.0, -f.gradient.y).normalize()
                    }
                    None => s.normal,
                };
                nrm[i] = f3(up.convert(normal));
                foam[i] = cover.foam as f32;
                wcap[i] = cover.whitecap as f32;
                jac[i] = s.jacobian as f32;
                spray[i] = match up {
                    UpAxis::Y => [e3.x as f32, e3.z as f32, mu as f32],
                    UpAxis::Z => [e3.x as f32, e3.y as f32, mu as f32],
                };
            }
            lost
        })
        .collect();
    let limit = lean.map(|_| {
        let mean = lost.iter().fold(DVec3::ZERO, |a, &b| a + b) / (n * n) as f64;
        GridLimit { shortest_wave_m: 2.0 * texel, faded_waves: None, lost_slope_covariance: mean.to_array() }
    });
    BakedFrame { size: n, time: t, maps, limit }
}

/// Encoding of the 16-bit PNG maps: `value = offset + scale × code/65535`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PngScale {
    /// Value of code 0.
    pub offset: f64,
    /// Value of code 65535 minus that of code 0.
    pub scale: f64,
}

/// The 16-bit PNG encodings of the maps: displacement over `±range_m`, unit vectors over
/// `[−1, 1]`, covers over `[0, 1]`, Jacobian and eigenvalue over `[−1, 3]`.
pub fn png_scales(range_m: f64) -> [(&'static str, PngScale); 4] {
    [
        ("displacement", PngScale { offset: -range_m, scale: 2.0 * range_m }),
        ("unit vectors", PngScale { offset: -1.0, scale: 2.0 }),
        ("cover", PngScale { offset: 0.0, scale: 1.0 }),
        ("jacobian and eigenvalue", PngScale { offset: -1.0, scale: 4.0 }),
    ]
}

/// One map to write: its name, its named channels and their 16-bit PNG encodings.
type Map<'a> = (&'a str, Vec<(String, Vec<f32>)>, Vec<PngScale>);

/// The maps a bake writes per frame, in `bake.json`'s order.
pub const MAP_NAMES: [&str; 6] = ["displacement", "normal", "foam", "whitecap", "jacobian", "spray"];

/// The files [`write_bake_frame`] writes for frame `index` into `dir`: `NAME_0007.exr` (or
/// `.png` for 16-bit PNG maps), one per map of [`MAP_NAMES`], in that order.
pub fn bake_frame_paths(dir: &Path, index: u32, png16: bool) -> Vec<PathBuf> {
    let ext = if png16 { "png" } else { "exr" };
    MAP_NAMES.iter().map(|name| dir.join(format!("{name}_{index:04}.{ext}"))).collect()
}

/// The six maps of `frame` by name (in the order of [`MAP_NAMES`]), with their channels and
/// their 16-bit encodings for a displacement range of `range_m` (m).
fn named_maps(frame: &BakedFrame, range_m: f64) -> Vec<Map<'static>> {
    let m = &frame.maps;
    let rgb = |v: &[[f32; 3]]| -> Vec<(String, Vec<f32>)> {
        ["R", "G", "B"]
            .iter()
            .enumerate()
            .map(|(c, name)| ((*name).to_owned(), v.iter().map(|p| p[c]).collect()))
            .collect()
    };
    let grey = |v: &[f32]| vec![("Y".to_owned(), v.to_vec())];
    let s = png_scales(range_m);
    vec![
        ("displacement", rgb(&m.displacement), vec![s[0].1; 3]),
        ("normal", rgb(&m.normal), vec![s[1].1; 3]),
        ("foam", grey(&m.foam), vec![s[2].1]),
        ("whitecap", grey(&m.whitecap), vec![s[2].1]),
        ("jacobian", grey(&m.jacobian), vec![s[3].1]),
        ("spray", rgb(&m.spray), vec![s[1].1, s[1].1, s[3].1]),
    ]
}

/// The first value of `maps` beyond its 16-bit encoding's range (by more than half a code), as
/// `"MAP CHANNEL: value is beyond the 16-bit encoding's range [lo, hi]"`.
fn unencodable(maps: &[Map<'_>]) -> Option<String> {
    for (name, channels, scales) in maps {
        for (ch, s) in channels.iter().zip(scales) {
            let (lo, hi) = (s.offset, s.offset + s.scale);
            let half_code = 0.5 * s.scale / 65535.0;
            if let Some(v) = ch.1.iter().map(|&v| f64::from(v)).find(|&v| !(v >= lo - half_code && v <= hi + half_code))
            {
                return Some(format!(
                    "{name} {}: {v:.4} is beyond the 16-bit encoding's range [{lo:.4}, {hi:.4}]",
                    ch.0
                ));
            }
        }
    }
    None
}

/// The first value of `frame`'s maps that no 16-bit encoding holds: beyond its fixed range (unit
/// vectors, covers, the Jacobian and the eigenvalue), or beyond `±range_m` for the displacement
/// (not checked when `None`).
///
/// # Returns
/// A message naming the map, the channel, the value and the range; `None` when all fit.
pub fn png_unencodable(frame: &BakedFrame, range_m: Option<f64>) -> Option<String> {
    let maps = named_maps(frame, range_m.unwrap_or(f64::INFINITY));
    let checked: Vec<_> = maps.into_iter().filter(|m| range_m.is_some() || m.0 != "displacement").collect();
    unencodable(&checked)
}

/// Writes the six maps of `frame` into `dir` as `NAME_FFFF.exr` (or `.png`, 16 bits, with
/// `png_range_m` the displacement range), each atomically.
///
/// # Errors
/// A message naming the file and the cause.
pub fn write_bake_frame(
    dir: &Path,
    index: u32,
    frame: &BakedFrame,
    png_range_m: Option<f64>,
) -> Result<Vec<PathBuf>, String> {
    let n = frame.size;
    let paths = bake_frame_paths(dir, index, png_range_m.is_some());
    let maps = named_maps(frame, png_range_m.unwrap_or(1.0));
    // A 16-bit map holds only its encoding's range: a value beyond it is refused, before any map
    // of the frame is written, rather than clipped in silence.
    if png_range_m.is_some()
        && let Some(e) = unencodable(&maps)
    {
        return Err(format!("frame {index}, {e}; bake EXR maps (without --png16)"));
    }
    let mut written = Vec::new();
    for ((_, channels, scales), p) in maps.into_iter().zip(paths) {
        let shown = p.display().to_string();
        if png_range_m.is_some() {
            let c = channels.len();
            let mut codes: Vec<u16> = Vec::with_capacity(n * n * c);
            for k in 0..n * n {
                for (ch, s) in channels.iter().zip(&scales) {
                    let v = (f64::from(ch.1[k]) - s.offset) / s.scale;
                    codes.push((v.clamp(0.0, 1.0) * 65535.0).round() as u16);
                }
            }
            // The encoder takes 16-bit samples in the machine's byte order (it writes them
            // big-endian, as PNG stores them).
            let bytes: Vec<u8> = codes.iter().flat_map(|v| v.to_ne_bytes()).collect();
            let colour = if c == 1 { image::ExtendedColorType::L16 } else { image::ExtendedColorType::Rgb16 };
            crate::output::write_atomic(&p, |w| {
                use image::ImageEncoder as _;
                image::codecs::png::PngEncoder::new(w)
                    .write_image(&bytes, n as u32, n as u32, colour)
                    .map_err(std::io::Error::other)
            })
            .map_err(|e| format!("cannot write {shown}: {e}"))?;
        } else {
            let mut failed = None;
            crate::output::write_atomic(&p, |w| {
                crate::output::encode_exr(w, n, n, channels).map_err(|e| {
                    failed = Some(e.clone());
                    std::io::Error::other(e)
                })
            })
            .map_err(|e| failed.map_or_else(|| e.to_string(), |f| format!("cannot encode {shown}: {f}")))?;
        }
        written.push(p);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bake_sizes_are_checked_and_huge_ones_refused() {
        let o = BakeOptions { size: 1024, tile_m: 100.0, up: UpAxis::Y };
        assert!(o.check().is_ok());
        assert!(BakeOptions { size: 1, ..o }.check().unwrap_err().contains("--size"));
        // 65 536² × 104 B = 447 GB: refused with the estimate on any machine with less.
        if let Some(avail) = super::super::available_memory_bytes()
            && avail < 400 << 30
        {
            let e = BakeOptions { size: 65536, ..o }.check().unwrap_err();
            assert!(e.contains("65536 × 65536") && e.contains("GiB"), "{e}");
        }
        assert!(BakeOptions { tile_m: -1.0, ..o }.check().unwrap_err().contains("--tile-m"));
        assert_eq!(BakeOptions { size: 65536, ..o }.memory_estimate(), 65536 * 65536 * BYTES_PER_TEXEL);
    }

    #[test]
    fn blender_axes_are_right_handed_z_up() {
        let b = |v: DVec3| UpAxis::Z.convert(v);
        // East stays X, up becomes Z, north (−z) becomes Y: east × north = up.
        assert_eq!((b(DVec3::X), b(DVec3::Y), b(DVec3::NEG_Z)), (DVec3::X, DVec3::Z, DVec3::Y));
        assert_eq!(b(DVec3::X).cross(b(DVec3::NEG_Z)), b(DVec3::Y));
    }
}
