//! The filtered frame at one sample per pixel against the same renderer at many: where the
//! pixel footprint is right, one sample shows no more pixel-to-pixel noise than sixteen.

use brine_render::scene::SurfaceKind;
use brine_render::{RenderOptions, Scene, render, tonemap};

/// The stormy-spray gallery scene (20 m/s, a camera 3 m up looking 4° down toward a sun 18° high)
/// at 320 × 180, `spp` samples per pixel, white water, spray and glare off, at a fixed
/// exposure.
fn storm(spp: u32) -> Scene {
    storm_on(spp, None)
}

/// [`storm`] on the surface `surface`, or the scene's own.
fn storm_on(spp: u32, surface: Option<SurfaceKind>) -> Scene {
    let path = format!("{}/../docs/gallery/stormy-spray.toml", env!("CARGO_MANIFEST_DIR"));
    let mut s = Scene::from_toml_str(&std::fs::read_to_string(&path).unwrap(), &path).unwrap();
    if let Some(surface) = surface {
        s.sea.surface = surface;
    }
    (s.camera.width, s.camera.height, s.camera.spp) = (320, 180, spp);
    s.phenomena.foam = false;
    s.phenomena.whitecaps = false;
    s.phenomena.spray = false;
    s.phenomena.glare = false;
    s.output.exposure_ev = Some(12.0);
    s
}

/// Root-mean-square of the 8-bit luminance minus its 3 × 3 mean over the rows `rows` (the
/// high-pass noise a viewer sees as speckle).
fn high_pass(scene: &Scene, rows: std::ops::Range<usize>) -> f64 {
    let frame = render(scene, &RenderOptions::default(), &|| {}).expect("scene renders");
    let scale = tonemap::exposure_scale(frame.exposure_ev);
    let w = scene.camera.width as usize;
    let lum: Vec<f64> = frame
        .pixels
        .iter()
        .map(|p| {
            let c = tonemap::to_srgb8(*p, scale);
            (f64::from(c[0]) + f64::from(c[1]) + f64::from(c[2])) / 3.0
        })
        .collect();
    let (mut sum, mut n) = (0.0, 0.0);
    for y in rows {
        for x in 1..w - 1 {
            let mean = (-1..=1)
                .flat_map(|dy: isize| (-1..=1).map(move |dx: isize| (dx, dy)))
                .map(|(dx, dy)| lum[(y as isize + dy) as usize * w + (x as isize + dx) as usize])
                .sum::<f64>()
                / 9.0;
            sum += (lum[y * w + x] - mean).powi(2);
            n += 1.0;
        }
    }
    (sum / n).sqrt()
}

/// Largest ratio of the near field's high-pass noise at 1 sample per pixel to that at 16. The
/// 16-sample frame filters each sample over a quarter of the pixel's width and averages them, so
/// what aliases at one sample is averaged out there, while the features the pixel resolves are
/// in both. Measured 0.97 with the pixel's footprint taken on the facet the ray meets, 1.15 with
/// the level plane's (the detail normals under-filtered on the faces turned from the eye, which
/// break into dashes along the crests at one sample); 8 % of headroom over 1.
const MAX_NOISE_RATIO: f64 = 1.08;

/// On the faces of a storm sea turned away from a low camera the pixel spans several times the
/// length it spans on the mean plane. Filtered with the mean plane's footprint, the detail normals
/// alias there; filtered over the facet's, one sample per pixel is as smooth as sixteen.
#[test]
fn a_grazing_storm_sea_aliases_no_more_at_one_sample_than_at_sixteen() {
    // The near field: the lowest three eighths of the rows, 5.5–16 m from the eye on the mean
    // plane in the centre column.
    let rows = 113..179;
    let one = high_pass(&storm(1), rows.clone());
    let many = high_pass(&storm(16), rows);
    assert!(
        one <= MAX_NOISE_RATIO * many,
        "high-pass noise at 1 spp {one:.3}, at 16 spp {many:.3}: ratio {:.3}",
        one / many
    );
}

/// The FFT sea's cascades are the drawn surface and are read through the mean plane's footprint
/// (there is no facet until they are read): the same storm on the FFT sea must not alias at one
/// sample either. Measured 0.73 (the cascades' slope pyramids filter each pixel over a box a
/// little wider than the 16 samples' spread), 1.42 with the cascades read over a footprint a
/// tenth as wide.
#[test]
fn a_grazing_storm_fft_sea_aliases_no_more_at_one_sample_than_at_sixteen() {
    let rows = 113..179;
    let one = high_pass(&storm_on(1, Some(SurfaceKind::Fft)), rows.clone());
    let many = high_pass(&storm_on(16, Some(SurfaceKind::Fft)), rows);
    assert!(
        one <= MAX_NOISE_RATIO * many,
        "FFT: high-pass noise at 1 spp {one:.3}, at 16 spp {many:.3}: ratio {:.3}",
        one / many
    );
}
