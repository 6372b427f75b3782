//! The Hosek & Wilkie (2012) clear sky: an extended Perez distribution fitted, per colour
//! channel, to path-traced skies of a given turbidity, sun elevation and ground albedo.

use glam::DVec3;
use hw_skymodel::rgb::{Channel, SkyParams as HwParams, SkyState};

use crate::cie::MAX_LUMINOUS_EFFICACY;
use crate::error::{SkyError, check};

/// Ground albedo under an open sea (1): the hemispherical Fresnel reflectance of water (0.066)
/// plus the little light the water sends back (a few thousandths in blue water). The sky model
/// takes it as the albedo of the ground that lights the atmosphere from below.
pub const SEA_GROUND_ALBEDO: f64 = 0.07;

/// A Hosek–Wilkie sky for one turbidity, sun position and ground albedo.
///
/// The radiance of each linear sRGB channel toward a view at zenith angle `θ`, angle `γ` from
/// the sun, is
///
/// `L = L_M (1 + A e^{B/(cos θ + 0.01)}) (C + D e^{Eγ} + F cos²γ + G χ(H, γ) + I √cos θ)`,
/// `χ(H, γ) = (1 + cos²γ) / (1 + H² − 2H cos γ)^{3/2}`,
///
/// the nine coefficients `A…I` and the scale `L_M` interpolated from the authors' dataset: in
/// the sun elevation by a quintic Bézier curve in `(θ_e/(π/2))^{1/3}`, linearly in the turbidity
/// and in the albedo. The evaluation is the `hw-skymodel` crate's port of the authors' reference
/// code with their RGB dataset (version 1.4a, single precision); this type checks the parameters,
/// converts units and handles views at and below the horizon.
///
/// Unlike Preetham's fit, whose chromaticity near the horizon falls 0.01 below the daylight
/// locus (a magenta cast), the Hosek–Wilkie horizon lies on the green side of it (see
/// `docs/models/brine-sky.md`); the sun disc is not part of this model (brine keeps Preetham's
/// spectral sun for both skies).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HosekWilkieSky {
    state: SkyState,
    turbidity: f64,
    albedo: f64,
    sun_direction: DVec3,
}

impl HosekWilkieSky {
    /// The sky for turbidity `T`, a unit direction toward the sun (y up) and a ground albedo.
    ///
    /// # Arguments
    /// - `turbidity`: `T`, `[1, 10]` (the range of the fitted dataset).
    /// - `sun_direction`: direction toward the sun, y up; its elevation must be in `[0°, 90°]`.
    /// - `albedo`: ground albedo (1), `[0, 1]`, the same for the three channels.
    ///
    /// # Returns
    /// The sky, its coefficients interpolated once.
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming `turbidity`, `sun_elevation_deg` or `albedo`.
    ///
    /// # References
    /// Hosek L., Wilkie A. 2012, "An analytic model for full spectral sky-dome radiance", ACM
    /// Trans. Graph. 31(4):95, Eq. 9 and §5 (the interpolation).
    pub fn new(turbidity: f64, sun_direction: DVec3, albedo: f64) -> Result<Self, SkyError> {
        let turbidity = check("turbidity", turbidity, (1.0..=10.0).contains(&turbidity), "[1, 10]")?;
        let albedo = check("albedo", albedo, (0.0..=1.0).contains(&albedo), "[0, 1]")?;
        let d = sun_direction.normalize_or_zero();
        let elevation = d.y.clamp(-1.0, 1.0).asin();
        check("sun_elevation_deg", elevation.to_degrees(), d.y >= 0.0, "[0, 90]°")?;
        // The port validates in single precision: keep the elevation inside its range after the cast.
        let elevation32 = (elevation as f32).clamp(0.0, std::f32::consts::FRAC_PI_2);
        let params = HwParams { elevation: elevation32, turbidity: turbidity as f32, albedo: [albedo as f32; 3] };
        // The port checks the same ranges (in single precision), so it cannot refuse them.
        let state = SkyState::new(&params).map_err(|_| {
            SkyError::OutOfRange(brine_core::OutOfRange {
                name: "turbidity",
                value: turbidity,
                range: "[1, 10], sun elevation [0, 90]°, albedo [0, 1]",
            })
        })?;
        Ok(Self { state, turbidity, albedo, sun_direction: d })
    }

    /// Turbidity `T`.
    pub fn turbidity(&self) -> f64 {
        self.turbidity
    }

    /// Ground albedo (1).
    pub fn albedo(&self) -> f64 {
        self.albedo
    }

    /// The nine coefficients `A…I` of each channel (R, G, B), in the paper's order, and the
    /// channel scales `L_M` (W m⁻² sr⁻¹, before the luminous efficacy), as interpolated for this
    /// sky. (The authors' dataset stores them in the order `A…G, I, H`.)
    pub fn coefficients(&self) -> ([[f64; 9]; 3], [f64; 3]) {
        let (p, r) = self.state.raw();
        let c = |k: usize| {
            let mut c: [f64; 9] = std::array::from_fn(|i| f64::from(p[9 * k + i]));
            c.swap(7, 8);
            c
        };
        ([c(0), c(1), c(2)], r.map(f64::from))
    }

    /// Sky radiance as linear sRGB toward a view direction (kcd m⁻²: the model's W m⁻² sr⁻¹
    /// times 683 lm W⁻¹). Views below the horizon see the sky at the horizon.
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here).
    ///
    /// # Returns
    /// Linear sRGB radiance, each channel `≥ 0`, its luminance in kcd m⁻².
    ///
    /// # References
    /// Hosek & Wilkie 2012, Eq. 9; version 1.1 of the authors' code (the output times 683 lm/W
    /// is luminance).
    pub fn radiance_rgb(&self, view: DVec3) -> DVec3 {
        let v = view.normalize_or_zero();
        let theta = v.y.clamp(0.0, 1.0).acos() as f32;
        let gamma = v.dot(self.sun_direction).clamp(-1.0, 1.0).acos() as f32;
        let l = [Channel::R, Channel::G, Channel::B].map(|c| f64::from(self.state.radiance(theta, gamma, c)));
        DVec3::from_array(l).max(DVec3::ZERO) * (MAX_LUMINOUS_EFFICACY * 1e-3)
    }

    /// Irradiance from the sky dome on a horizontal surface facing up, `E = ∫ L(ω) cos θ dω`
    /// (linear sRGB, klx), by the midpoint rule on 48 × 96 cells.
    pub fn horizontal_irradiance_rgb(&self) -> DVec3 {
        crate::preetham::horizontal_irradiance(|v| self.radiance_rgb(v))
    }
}

/// Hosek & Wilkie 2012 Eq. 9: the extended Perez distribution of one channel,
/// `(1 + A e^{B/(cos θ + 0.01)}) (C + D e^{Eγ} + F cos²γ + G χ(H, γ) + I √cos θ)`.
///
/// # Arguments
/// - `k`: the nine coefficients `A…I` (1; `H ∈ (−1, 1)`).
/// - `cos_theta`: cosine of the view zenith angle, `[0, 1]`.
/// - `gamma`: view–sun angle (rad), `[0, π]`.
///
/// # Returns
/// The distribution (1), to be multiplied by the channel scale `L_M`.
///
/// # References
/// Hosek & Wilkie 2012, Eq. 9.
pub fn hosek_wilkie_distribution(k: &[f64; 9], cos_theta: f64, gamma: f64) -> f64 {
    debug_assert!((0.0..=1.0).contains(&cos_theta) && (0.0..=std::f64::consts::PI).contains(&gamma));
    let [a, b, c, d, e, f, g, h, i] = *k;
    let cg = gamma.cos();
    let chi = (1.0 + cg * cg) / (1.0 + h * h - 2.0 * h * cg).powf(1.5);
    (1.0 + a * (b / (cos_theta + 0.01)).exp())
        * (c + d * (e * gamma).exp() + f * cg * cg + g * chi + i * cos_theta.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::colour::linear_srgb_to_xyz;
    use approx::assert_relative_eq;

    /// The port evaluates in single precision: 10⁻⁵ relative of the f64 evaluation.
    const SINGLE_PRECISION: f64 = 1e-5;
    /// The dataset values are printed with 7 significant digits in the authors' header.
    const PRINTED: f64 = 1e-6;

    fn dir(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
        let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
        DVec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin())
    }

    /// At the ends of the interpolation (sun on the horizon: the first Bézier control point;
    /// turbidity 1 or 10, albedo 0 or 1) the coefficients are entries of the authors' RGB
    /// dataset, `ArHosekSkyModelData_RGB.h` version 1.4a: the first entry of `datasetRGB1` and
    /// `datasetRGBRad1` (albedo 0, turbidity 1), the first of the albedo-1 half of `datasetRGB2`,
    /// and the last entries of `datasetRGB3`, `datasetRGBRad2` and `datasetRGBRad3` (albedo 1,
    /// turbidity 10, the zenith sun).
    #[test]
    fn the_coefficients_at_the_grid_ends_are_the_published_dataset() {
        let low = HosekWilkieSky::new(1.0, DVec3::X, 0.0).unwrap();
        let (k, r) = low.coefficients();
        assert_relative_eq!(k[0][0], -1.099459, max_relative = PRINTED);
        assert_relative_eq!(r[0], 1.962684, max_relative = PRINTED);
        let low_white = HosekWilkieSky::new(1.0, DVec3::X, 1.0).unwrap();
        assert_relative_eq!(low_white.coefficients().0[1][0], -1.129907, max_relative = PRINTED);
        let high = HosekWilkieSky::new(10.0, DVec3::Y, 1.0).unwrap();
        let (k, r) = high.coefficients();
        // The dataset's last entry of a control point is H (stored after I).
        assert_relative_eq!(k[2][7], 0.6966285, max_relative = PRINTED);
        assert_relative_eq!(r[1], 26.43066, max_relative = PRINTED);
        assert_relative_eq!(r[2], 28.93432, max_relative = PRINTED);
    }

    /// The radiance is Eq. 9 with the interpolated coefficients, times the channel scale and
    /// 683 lm/W, evaluated here independently in double precision.
    #[test]
    fn the_radiance_is_equation_9() {
        for (t, sun_el) in [(2.0, 5.0), (3.0, 30.0), (6.5, 60.0)] {
            let s = dir(sun_el, 0.0);
            let sky = HosekWilkieSky::new(t, s, SEA_GROUND_ALBEDO).unwrap();
            let (k, r) = sky.coefficients();
            for (el, az) in [(1.0, 90.0), (10.0, 180.0), (45.0, 30.0), (89.0, 0.0)] {
                let v = dir(el, az);
                let gamma = v.dot(s).clamp(-1.0, 1.0).acos();
                let l = sky.radiance_rgb(v);
                for c in 0..3 {
                    let expected = r[c] * hosek_wilkie_distribution(&k[c], v.y, gamma) * 0.683;
                    assert_relative_eq!(l[c], expected, max_relative = 20.0 * SINGLE_PRECISION);
                }
            }
        }
    }

    /// A clear sky is brighter toward the sun and at the horizon than at the zenith 90° away,
    /// bluest at the zenith, and its zenith luminance for a 30° sun is of the order measured in
    /// clear skies (1–5 kcd m⁻², the CIE clear-sky standard gives about 2.5 at turbidity 3).
    #[test]
    fn a_clear_sky_has_the_shape_of_a_clear_sky() {
        let s = dir(30.0, 0.0);
        let sky = HosekWilkieSky::new(3.0, s, SEA_GROUND_ALBEDO).unwrap();
        let lum = |v: DVec3| linear_srgb_to_xyz(sky.radiance_rgb(v)).y;
        let zenith = lum(DVec3::Y);
        assert!((1.0..5.0).contains(&zenith), "zenith luminance {zenith} kcd/m²");
        assert!(lum(dir(35.0, 0.0)) > 3.0 * zenith);
        assert!(lum(dir(2.0, 90.0)) > zenith);
        let blue = |v: DVec3| {
            let l = sky.radiance_rgb(v);
            l.z / l.x
        };
        assert!(blue(DVec3::Y) > blue(dir(2.0, 90.0)));
    }

    /// Radiance from the authors' reference implementation (`ArHosekSkyModel.c`, version 1.4a,
    /// double precision, albedo 0.07): turbidity, sun elevation (°), view elevation and azimuth
    /// from the sun (°), then the RGB dataset's channels and the CIE XYZ dataset's channels
    /// (W m⁻² sr⁻¹), printed to 7 significant digits.
    #[allow(clippy::type_complexity)]
    const AUTHORS_CODE: [(f64, f64, f64, f64, [f64; 3], [f64; 3]); 12] = [
        (2.0, 5.0, 1.0, 90.0, [6.412831, 5.471358, 2.329136], [5.305304, 5.635594, 3.109396]),
        (2.0, 5.0, 10.0, 180.0, [7.423283, 8.302181, 6.659170], [7.303183, 8.049778, 7.509927]),
        (2.0, 5.0, 45.0, 30.0, [1.753014, 2.559363, 3.379404], [2.256429, 2.450335, 3.539425]),
        (2.0, 5.0, 89.0, 0.0, [0.6961818, 1.227054, 1.883962], [1.137790, 1.195806, 2.003734]),
        (3.0, 30.0, 1.0, 90.0, [10.26845, 13.01355, 13.29365], [11.35779, 12.50618, 14.44637]),
        (3.0, 30.0, 10.0, 180.0, [8.988809, 14.27882, 19.68841], [12.29037, 13.48197, 20.60475]),
        (3.0, 30.0, 45.0, 30.0, [5.420741, 7.757300, 11.55825], [7.155898, 7.567984, 12.07719]),
        (3.0, 30.0, 89.0, 0.0, [1.598859, 3.015557, 6.022394], [2.883315, 2.957290, 6.134768]),
        (6.5, 60.0, 1.0, 90.0, [12.00902, 12.74280, 14.62375], [11.81268, 12.50978, 15.81805]),
        (6.5, 60.0, 10.0, 180.0, [8.230659, 12.30111, 19.17616], [11.16750, 11.93128, 19.90071]),
        (6.5, 60.0, 45.0, 30.0, [21.23827, 24.08419, 27.44692], [22.21236, 23.63936, 29.19281]),
        (6.5, 60.0, 89.0, 0.0, [9.804554, 11.70739, 15.40726], [10.92574, 11.48197, 16.21030]),
    ];

    /// The sky is the authors' reference code, to single precision, times 683 lm/W.
    #[test]
    fn the_radiance_is_the_authors_reference_code() {
        for (t, sun_el, el, az, rgb, _) in AUTHORS_CODE {
            let sky = HosekWilkieSky::new(t, dir(sun_el, 0.0), SEA_GROUND_ALBEDO).unwrap();
            let l = sky.radiance_rgb(dir(el, az));
            for c in 0..3 {
                assert_relative_eq!(l[c], rgb[c] * 0.683, max_relative = 20.0 * SINGLE_PRECISION + PRINTED);
            }
        }
    }

    /// The RGB dataset's white is D65 (sRGB), not illuminant E: read as linear sRGB with the D65
    /// matrix, its chromaticity is that of the authors' separate CIE XYZ fit of the same skies
    /// to within 0.008 in x and y, while an equal-energy white would move it by about 0.02.
    /// So the green side of the horizon is the model's own, not a conversion error.
    #[test]
    fn the_rgb_dataset_is_linear_srgb_with_a_d65_white() {
        // The two datasets are separate fits; they differ most at low suns near the horizon.
        const SEPARATE_FITS: f64 = 0.008;
        for (t, sun_el, el, az, _, xyz) in AUTHORS_CODE {
            let sky = HosekWilkieSky::new(t, dir(sun_el, 0.0), SEA_GROUND_ALBEDO).unwrap();
            let (x, y) = crate::chromaticity(linear_srgb_to_xyz(sky.radiance_rgb(dir(el, az)))).unwrap();
            let (xr, yr) = crate::chromaticity(DVec3::from_array(xyz)).unwrap();
            assert!(
                (x - xr).abs() < SEPARATE_FITS && (y - yr).abs() < SEPARATE_FITS,
                "{t} {sun_el} {el} {az}: ({x:.4}, {y:.4}) against ({xr:.4}, {yr:.4})"
            );
        }
    }

    #[test]
    fn parameters_out_of_range_name_themselves() {
        for (t, s, a, name) in [
            (0.5, DVec3::Y, 0.1, "turbidity"),
            (3.0, dir(-5.0, 0.0), 0.1, "sun_elevation_deg"),
            (3.0, DVec3::Y, 1.5, "albedo"),
        ] {
            let e = HosekWilkieSky::new(t, s, a).unwrap_err();
            assert!(e.to_string().contains(name), "{e}");
        }
    }
}
