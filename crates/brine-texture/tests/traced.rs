//! The traced mode's optics on a nearly flat sea, against hand geometry and the exact Fresnel
//! equations: the sun's highlight sits where the mirror reflection of the sun is, and the sky is
//! reflected with the Fresnel reflectance of the viewing angle.

use brine_optics::WATER_IOR;
use brine_texture::{
    OceanParams, PhotoOcean, Pinhole, SynthesisParams, Texture, TracedImage, TracedParams, TracedScene, render_traced,
};
use glam::DVec3;

/// Height factor `hf` of both photos (m): Eq. 1 heights lie in `[0, hf]`, so a neighbour
/// difference is at most `hf` and every slope of the composed surface at most
/// `√2 (hf/texel + hf/(texel·scale))` = 2·10⁻⁸ with the texels below: the sea is flat to
/// 10⁻⁸ rad, far below anything the tests resolve.
const FLAT_HF_M: f64 = 1e-9;

/// Small-wave texel (m) and the main structure's scale.
const TEXEL_M: f64 = 0.08;
const SCALE: f64 = 8.0;

/// A non-uniform test "photo" (Eq. 1 needs `I_max > I_min`).
fn photo(a: usize, b: usize) -> Texture {
    Texture::from_fn(72, 72, |i, j| [40.0 + ((i * a + j * b) % 29) as f32 * 6.0, 110.0, 170.0])
}

/// A nearly flat photo ocean (heights ≤ [`FLAT_HF_M`]) whose main structure moves along
/// `main_velocity` (`[east, south]`, m/s): that direction is the x axis of the traced BRDF.
fn flat_ocean(main_velocity: [f64; 2]) -> PhotoOcean {
    let params = OceanParams {
        synthesis: SynthesisParams { patch_size: 24, boundary_width: 4, ..SynthesisParams::default() },
        small_size: 64,
        main_size: 64,
        bed_size: 64,
        frames: 2,
        links_per_frame: 1,
        morph_steps: 2,
        mesh_spacing: 16,
        height_factor_small_m: FLAT_HF_M,
        height_factor_main_m: FLAT_HF_M,
        texel_m: TEXEL_M,
        scale: SCALE,
        main_velocity_m_s: main_velocity,
        ..OceanParams::default()
    };
    PhotoOcean::new(&photo(7, 3), &photo(2, 5), None, &params, 3, &|_| {}).unwrap()
}

/// Unit direction of a compass bearing and an elevation, y up, north = −z, east = +x (Brine's
/// convention, written out here): `(sin B cos E, sin E, −cos B cos E)`.
fn bearing(bearing_deg: f64, elevation_deg: f64) -> DVec3 {
    let (b, e) = (bearing_deg.to_radians(), elevation_deg.to_radians());
    DVec3::new(b.sin() * e.cos(), e.sin(), -b.cos() * e.cos())
}

/// Traced parameters: the sun at `sun`, a calm sea (wind 0: Cox–Munk's narrowest lobe), no
/// aerial perspective (the tests compare surface radiances).
fn calm(sun: DVec3) -> TracedParams {
    TracedParams { sun_direction: sun, wind_speed_m_s: 0.0, aerial_perspective: false, ..TracedParams::default() }
}

/// Unpolarised Fresnel reflectance of the air–water interface from Snell's law and the two
/// amplitude coefficients, `R = ½(r_s² + r_p²)`, `r_s = (cos i − n cos t)/(cos i + n cos t)`,
/// `r_p = (cos t − n cos i)/(cos t + n cos i)`, `sin t = sin i/n` (Born & Wolf, *Principles of
/// Optics*, §1.5.2) — another form than brine-optics' Cook–Torrance expression.
fn fresnel_exact(cos_i: f64, n: f64) -> f64 {
    let sin_t = (1.0 - cos_i * cos_i).sqrt() / n;
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    let rp = (cos_t - n * cos_i) / (cos_t + n * cos_i);
    0.5 * (rs * rs + rp * rp)
}

/// Schlick's approximation `F₀ + (1 − F₀)(1 − cos i)⁵` (only to show the test tells it apart).
fn fresnel_schlick(cos_i: f64, n: f64) -> f64 {
    let f0 = ((n - 1.0) / (n + 1.0)).powi(2);
    f0 + (1.0 - f0) * (1.0 - cos_i).powi(5)
}

fn pixel(img: &TracedImage, i: u32, j: u32) -> DVec3 {
    img.pixels[(j * img.width + i) as usize]
}

/// How far (pixels, per axis) the brightest pixel may lie from the pixel holding the mirror
/// point. On the calm sea the BRDF lobe along the plane of incidence has the clamp's slope
/// variance `σ² = 2·10⁻⁵` (σ = 4.5 mrad, a view angle of 9 mrad against the 11 mrad pixel), and
/// the factors besides the slope density (Fresnel, `1/v_z`, Smith, `h_z⁻⁴`) shift its peak by
/// `σ² |d ln(…)/dζ| ≲ 2·10⁻⁵ × 10` in slope, `4·10⁻⁴` rad of view: 0.04 pixel. The brightest
/// sample is therefore the pixel containing the mirror point; one pixel of slack covers a mirror
/// point near a pixel edge, where the (asymmetric) water colour can tip the choice.
const MIRROR_PIXELS: i64 = 1;

/// The highlight must stand out: its pixel at least this many times the image's median radiance
/// (the calm sun glint is ~10⁵ kcd m⁻² against ~1 of sky reflection and water, so a missing or
/// misplaced sun term fails by orders of magnitude).
const HIGHLIGHT_CONTRAST: f64 = 100.0;

#[test]
fn the_sun_highlight_sits_at_the_mirror_point() {
    // (sun bearing °, sun elevation °, camera pitch down °). The camera looks toward the sun's
    // bearing, so the plane of incidence is the image's middle column (odd width: pixel 24 of 49
    // is centred on it). The mirror ray leaves the eye at depression E, i.e. at (p − E) above the
    // view axis, and a pinhole puts that at row y = (h/2)(1 − tan(p − E)/tan(fov/2)).
    let (w, h, fov) = (49u32, 48u32, 30.0f64);
    for (sun_bearing, sun_elevation, pitch_down) in [(200.0, 30.0, 40.0), (75.0, 50.0, 45.0), (320.0, 20.0, 22.0)] {
        let b = f64::to_radians(sun_bearing);
        // The BRDF's x axis (narrow lobe, σ² = 2·10⁻⁵) along the plane of incidence.
        let ocean = flat_ocean([2.5 * b.sin(), -2.5 * b.cos()]);
        let scene = TracedScene::new(&calm(bearing(sun_bearing, sun_elevation)), &ocean).unwrap();
        let camera = Pinhole::from_angles(DVec3::new(0.0, 4.0, 0.0), sun_bearing, -pitch_down, fov, w, h).unwrap();
        let img = render_traced(&ocean.frame(0), &camera, &scene).unwrap();

        let rise = f64::to_radians(pitch_down - sun_elevation).tan() / f64::to_radians(fov / 2.0).tan();
        let y_mirror = 0.5 * f64::from(h) * (1.0 - rise);
        let x_mirror = 0.5 * f64::from(w);
        let expected = (x_mirror.floor() as i64, y_mirror.floor() as i64);

        let luminance = |p: DVec3| p.dot(DVec3::new(0.2126, 0.7152, 0.0722));
        let (mut best, mut at) = (f64::NEG_INFINITY, (0, 0));
        for j in 0..h {
            for i in 0..w {
                let l = luminance(pixel(&img, i, j));
                if l > best {
                    (best, at) = (l, (i64::from(i), i64::from(j)));
                }
            }
        }
        let what = format!("sun at {sun_bearing}°/{sun_elevation}°, camera {pitch_down}° down");
        assert!(
            (at.0 - expected.0).abs() <= MIRROR_PIXELS && (at.1 - expected.1).abs() <= MIRROR_PIXELS,
            "{what}: brightest pixel {at:?}, mirror point ({x_mirror:.2}, {y_mirror:.2}) in pixel {expected:?}"
        );
        let mut all: Vec<f64> = img.pixels.iter().map(|p| luminance(*p)).collect();
        all.sort_by(f64::total_cmp);
        let median = all[all.len() / 2];
        assert!(best > HIGHLIGHT_CONTRAST * median, "{what}: highlight {best:.3e}, median {median:.3e}");
    }
}

/// Largest relative difference allowed between the reflected sky of a pixel and the exact
/// Fresnel reflectance times the sky radiance in the mirror direction. The two sides differ only
/// by the surface's tilt (≤ 2·10⁻⁸ rad, see [`FLAT_HF_M`]): it changes the incidence angle by as
/// much, with `|d ln F/dθ| < 20` below 86°, and the mirror direction by twice as much, with a
/// relative sky gradient well under 50 rad⁻¹ (Preetham's sky varies over tens of degrees):
/// `2·10⁻⁸ × (20 + 100) ≈ 2·10⁻⁶`, plus f64 rounding. Schlick's approximation, off by ≥ 1 % at
/// these angles, fails by three orders of magnitude.
const FRESNEL_REL: f64 = 1e-5;

#[test]
fn the_sky_is_reflected_with_the_exact_fresnel_reflectance() {
    // Sun behind the camera (north, 40° up), camera looking south 45° down over an 80° field:
    // rows from 5° below the horizon (grazing, incidence 85°) to 85° below (steep, incidence 5°).
    // The half vector of every pixel is ≥ 27° from the vertical, where the calm lobe (σ² ≤ 0.003)
    // is below e⁻⁴⁰: no sun in the image. With no light below the surface (`e_below = 0`) the
    // water adds nothing, so each pixel is L = F(θ) L_sky(r), r the mirror direction.
    let ocean = flat_ocean(OceanParams::default().main_velocity_m_s);
    let mut scene = TracedScene::new(&calm(bearing(0.0, 40.0)), &ocean).unwrap();
    scene.e_below = DVec3::ZERO;
    let (w, h) = (33u32, 33u32);
    let camera = Pinhole::from_angles(DVec3::new(0.0, 3.0, 0.0), 180.0, -45.0, 80.0, w, h).unwrap();
    let img = render_traced(&ocean.frame(0), &camera, &scene).unwrap();

    // F of a pixel as the image shows it: L / L_sky(r), per channel, with its exact value.
    let measured = |i: u32, j: u32| {
        let d = camera.direction(f64::from(i) + 0.5, f64::from(j) + 0.5);
        let r = DVec3::new(d.x, -d.y, d.z);
        let sky = scene.sky.radiance_rgb(r);
        let l = pixel(&img, i, j);
        (DVec3::new(l.x / sky.x, l.y / sky.y, l.z / sky.z), -d.y)
    };
    let mut worst = 0.0f64;
    let mut worst_schlick = 0.0f64;
    for j in 0..h {
        for i in 0..w {
            let (f, cos_i) = measured(i, j);
            let exact = fresnel_exact(cos_i, WATER_IOR);
            for c in f.to_array() {
                worst = worst.max((c / exact - 1.0).abs());
                worst_schlick = worst_schlick.max((c / fresnel_schlick(cos_i, WATER_IOR) - 1.0).abs());
            }
        }
    }
    assert!(worst <= FRESNEL_REL, "largest relative departure from exact Fresnel {worst:.2e}");
    assert!(worst_schlick > 100.0 * FRESNEL_REL, "Schlick is told apart: {worst_schlick:.2e}");

    // Grazing pixels reflect more sky than steep ones, in the exact Fresnel ratio.
    let mid = w / 2;
    let ((f_grazing, cos_g), (f_steep, cos_s)) = (measured(mid, 0), measured(mid, h - 1));
    let expected = fresnel_exact(cos_g, WATER_IOR) / fresnel_exact(cos_s, WATER_IOR);
    assert!(expected > 20.0, "the test spans grazing to steep: exact ratio {expected:.1}");
    for (g, s) in f_grazing.to_array().into_iter().zip(f_steep.to_array()) {
        let ratio = g / s;
        // Two pixels, each within FRESNEL_REL: the ratio within twice that.
        assert!((ratio / expected - 1.0).abs() <= 2.0 * FRESNEL_REL, "grazing/steep {ratio:.4} vs {expected:.4}");
    }
}
