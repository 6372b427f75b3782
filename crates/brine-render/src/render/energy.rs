//! The filtered frame against the reference rendering, band by band: the check that moving the
//! waves from geometry to shading normals to the BRDF, as the pixel footprint grows, adds and
//! loses no light.

use super::{RenderError, RenderOptions, render};
use crate::Scene;
use glam::DVec3;

/// Rows of a frame are compared in this many bands, top to bottom.
pub const ENERGY_BANDS: usize = 10;

/// Relative luminance of linear sRGB (ITU-R BT.709 weights).
const LUMINANCE: DVec3 = DVec3::new(0.2126, 0.7152, 0.0722);

/// The mean luminance of each tenth of the rows of `scene` rendered at one sample per pixel (the
/// filtered frame) over that of the reference rendering (nothing faded or filtered with the
/// pixel footprint, `RenderOptions::reference`) at `reference_spp` samples per pixel, top band
/// first. Sky bands read 1 (both renderings draw the same sky); a sea band within `1 ± 0.05`
/// keeps the light of the waves the footprint filters.
///
/// # Arguments
/// - `scene`: the scene (its `camera.spp` is replaced: 1 and `reference_spp`).
/// - `reference_spp`: samples per pixel of the reference, `≥ 1`.
///
/// # Returns
/// The ten ratios (dimensionless), `NaN` for a band of zero luminance in the reference.
///
/// # Errors
/// [`RenderError`] if a model rejects the scene or the thread pool cannot start.
pub fn energy_bands(scene: &Scene, reference_spp: u32) -> Result<[f64; ENERGY_BANDS], RenderError> {
    let mut scene = scene.clone();
    scene.camera.spp = 1;
    let filtered = render(&scene, &RenderOptions::default(), &|| {})?;
    scene.camera.spp = reference_spp.max(1);
    let reference = render(&scene, &RenderOptions { reference: true, ..RenderOptions::default() }, &|| {})?;
    let (w, h) = (filtered.width as usize, filtered.height as usize);
    let band = |pixels: &[DVec3], b: usize| {
        let rows = b * h / ENERGY_BANDS..(b + 1) * h / ENERGY_BANDS;
        let n = (rows.len() * w) as f64;
        pixels[rows.start * w..rows.end * w].iter().map(|c| c.dot(LUMINANCE)).sum::<f64>() / n
    };
    Ok(std::array::from_fn(|b| band(&filtered.pixels, b) / band(&reference.pixels, b)))
}
