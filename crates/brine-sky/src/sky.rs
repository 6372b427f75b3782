//! The renderer-facing sky for every sun elevation from −90° to 90°: Preetham's day, twilight,
//! night glow, the Moon and its light, clouds, the sun and moon discs, and aerial perspective.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use crate::aerial::{AerialPerspective, Scattering, henyey_greenstein};
use crate::clouds::{CloudLayers, CloudParams};
use crate::error::{SkyError, check};
use crate::hosek_wilkie::{HosekWilkieSky, SEA_GROUND_ALBEDO};
use crate::night::{MOON_RADIUS_KM, lommel_seeliger_phase, moon_to_sun_illuminance, night_sky_luminance};
use crate::preetham::PreethamSky;
use crate::sun::{SUN_SOLID_ANGLE, relative_air_mass, sun_angular_radius, sun_radiance_xyz};
use crate::twilight::{EARTH_RADIUS_M, TwilightRatio};
use crate::{linear_srgb_to_xyz, xyz_to_linear_srgb};

/// Moon elevation (rad) below which the moonlit sky has faded out (−4°); Preetham's sky for
/// the Moon on the horizon is faded with a smoothstep between this and 0.
pub const MOONLIGHT_FADE: f64 = -4.0 * PI / 180.0;

/// Resolution of the sky-dome quadrature in the constructor (zenith × azimuth cells).
const DOME: (usize, usize) = (24, 48);

/// The Moon as the sky needs it (from brine-ephem's `MoonPosition`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoonParams {
    /// Unit direction toward the Moon (y up), any elevation.
    pub direction: DVec3,
    /// Phase angle Sun–Moon–observer (rad), `[0, π]`: 0 at full moon.
    pub phase_angle: f64,
    /// Observer–Moon distance (km), `[340 000, 420 000]`.
    pub distance_km: f64,
}

/// Everything that defines a sky.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SkyParams {
    /// Turbidity `T`, `[1.7, 10]`.
    pub turbidity: f64,
    /// Unit direction toward the sun (y up), any elevation from −90° to 90°.
    pub sun_direction: DVec3,
    /// Earth–Sun distance (AU), `[0.95, 1.05]`; sets the disc's size and irradiance.
    pub sun_distance_au: f64,
    /// The Moon, or `None` for no Moon.
    pub moon: Option<MoonParams>,
    /// Cloud layers, or `None` for a clear sky.
    pub clouds: Option<CloudParams>,
    /// Time (s) at which the clouds are drawn (they scroll with the wind).
    pub time_s: f64,
    /// The clear daylight sky's model.
    pub model: DaylightModel,
}

/// The analytic model of the clear daylight sky.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DaylightModel {
    /// Preetham, Shirley & Smits 1999 (the papers' sky; turbidity `[1.7, 10]`).
    #[default]
    Preetham,
    /// Hosek & Wilkie 2012, over a sea of albedo [`SEA_GROUND_ALBEDO`](crate::SEA_GROUND_ALBEDO)
    /// (the sky of pbrt-v4, Mitsuba 3 and Blender Cycles).
    HosekWilkie,
}

/// The clear day sky of a [`DaylightModel`].
#[derive(Debug, Clone, Copy, PartialEq)]
enum DaySky {
    Preetham(PreethamSky),
    HosekWilkie(HosekWilkieSky),
}

impl DaySky {
    fn radiance_rgb(&self, v: DVec3) -> DVec3 {
        match self {
            Self::Preetham(p) => p.radiance_rgb(v),
            Self::HosekWilkie(h) => h.radiance_rgb(v),
        }
    }
}

impl SkyParams {
    /// A clear, moonless sky at 1 AU.
    pub fn new(turbidity: f64, sun_direction: DVec3) -> Self {
        Self {
            turbidity,
            sun_direction,
            sun_distance_au: 1.0,
            moon: None,
            clouds: None,
            time_s: 0.0,
            model: DaylightModel::Preetham,
        }
    }
}

/// A sun or moon disc.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    /// Unit direction toward the disc's centre.
    pub direction: DVec3,
    /// Angular radius `ρ` (rad).
    pub angular_radius: f64,
    /// Mean radiance of the disc's lit part as seen from sea level (linear sRGB, kcd m⁻²), zero
    /// once the disc has set; for the Moon, the radiance of a fully lit disc of the same
    /// irradiance.
    pub radiance_rgb: DVec3,
    /// Irradiance on a plane facing the disc at sea level, counting only the part of the disc
    /// above the horizon (linear sRGB, klx); zero once the disc has set.
    pub irradiance_rgb: DVec3,
    /// Fraction of the disc above the (flat) horizon, `[0, 1]`.
    pub visible_fraction: f64,
}

impl Disc {
    /// Cosine of the angular radius.
    pub fn cos_half_angle(&self) -> f64 {
        self.angular_radius.cos()
    }

    /// Solid angle of the disc, `Ω = 2π(1 − cos ρ)`.
    ///
    /// # Returns
    /// `Ω` (sr): 6.8×10⁻⁵ for the sun.
    ///
    /// # References
    /// The solid angle of a spherical cap.
    pub fn solid_angle(&self) -> f64 {
        TAU * (1.0 - self.angular_radius.cos())
    }
}

/// Fraction of a disc of angular radius `ρ` whose centre is at elevation `e` lying above the
/// (flat) horizon: the circular-segment area `(acos(−h) + h√(1 − h²))/π`, `h = clamp(e/ρ, −1, 1)`.
///
/// # Arguments
/// - `elevation`: `e` of the disc's centre (rad), any.
/// - `angular_radius`: `ρ` (rad), `> 0`.
///
/// # Returns
/// The fraction, `[0, 1]`: ½ with the centre on the horizon.
///
/// # References
/// The area of a circular segment (small-disc, flat-sky approximation).
pub fn visible_fraction(elevation: f64, angular_radius: f64) -> f64 {
    let h = (elevation / angular_radius).clamp(-1.0, 1.0);
    ((-h).acos() + h * (1.0 - h * h).sqrt()) / PI
}

/// Cubic smoothstep of `x` from `a` (0) to `b` (1).
fn smoothstep(a: f64, b: f64, x: f64) -> f64 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A direction with its elevation clamped to `[0, 90°]` (same azimuth); straight down becomes
/// east on the horizon.
fn clamp_to_horizon(d: DVec3) -> DVec3 {
    let h = DVec3::new(d.x, 0.0, d.z);
    if d.y >= 0.0 {
        d
    } else if h.length_squared() > 1e-24 {
        h.normalize()
    } else {
        DVec3::X
    }
}

/// How the Moon's disc is shaded: the Lommel–Seeliger law lit from `sun_from_moon`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct MoonShading {
    sun_from_moon: DVec3,
    k: DVec3,
}

/// The sky for one instant: every sun elevation, optional Moon and clouds.
#[derive(Debug, Clone, PartialEq)]
pub struct Sky {
    turbidity: f64,
    sun: Disc,
    sun_radiance_unclipped: DVec3,
    moon: Option<(Disc, MoonShading)>,
    day: DaySky,
    twilight: Option<TwilightRatio>,
    moon_sky: Option<(PreethamSky, f64)>,
    clouds: Option<CloudLayers>,
    time_s: f64,
    cloud_diffuse: DVec3,
    cloud_sun: DVec3,
    scattering: Scattering,
    lights: [(DVec3, DVec3); 2],
    ambient: DVec3,
    horizontal_irradiance: DVec3,
}

impl Sky {
    /// Builds the sky: checks the parameters, evaluates the sun and moon discs through the
    /// atmosphere, tabulates the twilight ratio when the sun is below the horizon, seeds the
    /// clouds, and integrates the dome once for the horizontal irradiance and the ambient
    /// in-scattering.
    ///
    /// # Arguments
    /// - `params`: the [`SkyParams`] (ranges in their field docs; the Moon's and the clouds'
    ///   parameters are checked too).
    ///
    /// # Returns
    /// The [`Sky`], ready to be evaluated (no call after this one integrates or allocates).
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming the first parameter outside its range.
    ///
    /// # References
    /// Preetham et al. 1999; Hoffman & Preetham 2002; Jensen et al. 2001; Chen et al. 2007 §3.1–3.2.
    pub fn new(params: &SkyParams) -> Result<Self, SkyError> {
        let t = check("turbidity", params.turbidity, (1.7..=10.0).contains(&params.turbidity), "[1.7, 10]")?;
        let sd = params.sun_direction;
        check("sun_direction", sd.length(), sd.is_finite() && sd.length() > 1e-12, "a non-zero finite vector")?;
        let s = sd.normalize();
        let au = params.sun_distance_au;
        check("sun_distance_au", au, (0.95..=1.05).contains(&au), "[0.95, 1.05] AU")?;
        check("time_s", params.time_s, params.time_s.is_finite(), "a finite time")?;
        let sun_elevation = s.y.clamp(-1.0, 1.0).asin();

        // The sun disc.
        let rho = sun_angular_radius(au);
        let omega = TAU * (1.0 - rho.cos());
        let air_mass = relative_air_mass(s.y.clamp(0.0, 1.0).acos());
        let sun_rgb = xyz_to_linear_srgb(sun_radiance_xyz(t, air_mass)).max(DVec3::ZERO);
        let fraction = visible_fraction(sun_elevation, rho);
        let sun = Disc {
            direction: s,
            angular_radius: rho,
            radiance_rgb: if fraction > 0.0 { sun_rgb } else { DVec3::ZERO },
            irradiance_rgb: sun_rgb * omega * fraction,
            visible_fraction: fraction,
        };

        // Day and twilight.
        let day = match params.model {
            DaylightModel::Preetham => DaySky::Preetham(PreethamSky::new(t, clamp_to_horizon(s))?),
            DaylightModel::HosekWilkie => {
                DaySky::HosekWilkie(HosekWilkieSky::new(t, clamp_to_horizon(s), SEA_GROUND_ALBEDO)?)
            }
        };
        let twilight = (sun_elevation < 0.0).then(|| TwilightRatio::new(sun_elevation, t)).transpose()?;

        // The Moon.
        let mut moon = None;
        let mut moon_sky = None;
        if let Some(m) = params.moon {
            let md = m.direction;
            check("moon.direction", md.length(), md.is_finite() && md.length() > 1e-12, "a non-zero finite vector")?;
            let md = md.normalize();
            check("moon.phase_angle", m.phase_angle, (0.0..=PI).contains(&m.phase_angle), "[0, π] rad")?;
            check(
                "moon.distance_km",
                m.distance_km,
                (340_000.0..=420_000.0).contains(&m.distance_km),
                "[340000, 420000] km",
            )?;
            let ratio = moon_to_sun_illuminance(m.phase_angle, m.distance_km);
            let moon_elevation = md.y.clamp(-1.0, 1.0).asin();
            let rho_m = (MOON_RADIUS_KM / m.distance_km).asin();
            let omega_m = TAU * (1.0 - rho_m.cos());
            let m_air = relative_air_mass(md.y.clamp(0.0, 1.0).acos());
            // Moonlight is sunlight: the sun's spectrum through the Moon's air mass, scaled.
            let e_full = xyz_to_linear_srgb(sun_radiance_xyz(t, m_air)).max(DVec3::ZERO) * (SUN_SOLID_ANGLE * ratio);
            let f = visible_fraction(moon_elevation, rho_m);
            // The terminator: the sun as seen from the Moon, at angle π − φ from the Moon's
            // direction, in the plane of the Moon and the Sun.
            let perp = s - md * s.dot(md);
            let perp = if perp.length_squared() > 1e-20 { perp.normalize() } else { md.any_orthonormal_vector() };
            let sun_from_moon = md * (PI - m.phase_angle).cos() + perp * (PI - m.phase_angle).sin();
            let phi_ls = lommel_seeliger_phase(m.phase_angle).max(1e-3);
            let shading = MoonShading { sun_from_moon, k: e_full * (2.0 / (omega_m * phi_ls)) };
            moon = Some((
                Disc {
                    direction: md,
                    angular_radius: rho_m,
                    radiance_rgb: e_full / omega_m,
                    irradiance_rgb: e_full * f,
                    visible_fraction: f,
                },
                shading,
            ));
            let fade = smoothstep(MOONLIGHT_FADE, 0.0, moon_elevation);
            if fade > 0.0 {
                moon_sky = Some((PreethamSky::new(t, clamp_to_horizon(md))?, ratio * fade));
            }
        }

        let clouds = params.clouds.as_ref().map(CloudLayers::new).transpose()?;
        let lights =
            [(s, sun.irradiance_rgb), moon.map_or((DVec3::Y, DVec3::ZERO), |(d, _)| (d.direction, d.irradiance_rgb))];
        let mut sky = Self {
            turbidity: t,
            sun,
            sun_radiance_unclipped: sun_rgb,
            moon,
            day,
            twilight,
            moon_sky,
            clouds: None,
            time_s: params.time_s,
            cloud_diffuse: DVec3::ZERO,
            cloud_sun: DVec3::ZERO,
            scattering: Scattering::new(t)?,
            lights,
            ambient: DVec3::ZERO,
            horizontal_irradiance: DVec3::ZERO,
        };
        if let Some(c) = clouds {
            // Light on the clouds: the clear sky's and the Moon's irradiance from above, and the
            // sun as seen from the cloud altitude (it sets there later: depression
            // acos(R/(R + H))), reddened by the horizon air mass when it is low.
            let (e_clear, _) = sky.integrate_dome();
            let dip = (EARTH_RADIUS_M / (EARTH_RADIUS_M + c.params().altitude_m)).acos();
            let sun_at_cloud = sky.sun_radiance_unclipped * omega * visible_fraction(sun_elevation + dip, rho);
            let moon_h = sky.moon.map_or(DVec3::ZERO, |(d, _)| d.irradiance_rgb * d.direction.y.max(0.0));
            sky.cloud_diffuse = (e_clear + moon_h) / PI;
            sky.cloud_sun = sun_at_cloud;
            sky.clouds = Some(c);
        }
        let (e_h, scalar) = sky.integrate_dome();
        sky.horizontal_irradiance = e_h;
        sky.ambient = scalar / (4.0 * PI);
        Ok(sky)
    }

    /// `(∫ L cos θ dω, ∫ L dω)` over the upper hemisphere, midpoint rule on 24 × 48 cells.
    fn integrate_dome(&self) -> (DVec3, DVec3) {
        let (mut e, mut scalar) = (DVec3::ZERO, DVec3::ZERO);
        crate::preetham::for_each_dome_cell(DOME, |v, (ct, st), (dt, dp)| {
            let l = self.radiance_rgb(v) * (st * dt * dp);
            e += l * ct;
            scalar += l;
        });
        (e, scalar)
    }

    /// Turbidity `T`.
    pub fn turbidity(&self) -> f64 {
        self.turbidity
    }

    /// The sun disc (direction, radiance, irradiance; zero irradiance once it has set).
    pub fn sun(&self) -> &Disc {
        &self.sun
    }

    /// The Moon's disc, if there is a Moon.
    pub fn moon(&self) -> Option<&Disc> {
        self.moon.as_ref().map(|(d, _)| d)
    }

    /// Radiance of the sky without clouds, sun or moon discs (linear sRGB, kcd m⁻²):
    /// `L = T(L_P(v; ŝ⁺)) + f_m L_P(v; m̂⁺) + L_night(v)`, where `L_P` is Preetham's sky with
    /// the sun (or the Moon) clamped to the horizon, `T` the twilight (the identity by day,
    /// [`TwilightRatio::apply`]),
    /// `f_m` the Moon-to-Sun illuminance ratio (faded below the horizon) and `L_night` the
    /// natural night glow (white).
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here); below the horizon it sees the sky at
    ///   the horizon.
    ///
    /// # Returns
    /// Linear sRGB radiance (kcd m⁻²), finite and `≥ 0`.
    ///
    /// # References
    /// Preetham et al. 1999; Nishita et al. 1993 (twilight); Jensen et al. 2001 (moonlit
    /// sky); Krisciunas & Schaefer 1991 (night glow).
    pub fn clear_radiance_rgb(&self, view: DVec3) -> DVec3 {
        let v = view.normalize_or_zero();
        let mut l = self.day.radiance_rgb(v);
        if let Some(tw) = &self.twilight {
            let s = self.sun.direction;
            let (sh, vh) = (DVec3::new(s.x, 0.0, s.z), DVec3::new(v.x, 0.0, v.z));
            let den = (sh.length_squared() * vh.length_squared()).sqrt();
            let phi = if den > 1e-24 { (sh.dot(vh) / den).clamp(-1.0, 1.0).acos() } else { 0.0 };
            l = tw.apply(l, v.y.clamp(-1.0, 1.0).asin(), phi);
        }
        if let Some((ms, scale)) = &self.moon_sky {
            l += ms.radiance_rgb(v) * *scale;
        }
        l + DVec3::splat(night_sky_luminance(v.y))
    }

    /// Radiance of the sky toward a unit view direction, clouds included, discs excluded (linear
    /// sRGB, kcd m⁻²): `L = (1 − α) L_clear + α L_cloud`, `α` the cloud opacity. Views below the
    /// horizon see the sky at the horizon.
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here).
    ///
    /// # Returns
    /// Linear sRGB radiance (kcd m⁻²), finite and non-negative for every direction and every
    /// sun elevation.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (clouds over the sky sphere).
    pub fn radiance_rgb(&self, view: DVec3) -> DVec3 {
        let v = view.normalize_or_zero();
        let clear = self.clear_radiance_rgb(v);
        let Some(c) = &self.clouds else { return clear };
        let alpha = c.opacity(v, self.time_s);
        if alpha <= 0.0 {
            return clear;
        }
        clear * (1.0 - alpha) + self.cloud_radiance_rgb(v, alpha) * alpha
    }

    /// Radiance of a cloud of opacity `α` toward `v`: diffuse light from above, transmitted less
    /// through thick parts, plus sunlight forward-scattered through thin edges (a
    /// Henyey–Greenstein lobe, `g = 0.6`) and a side-lit term when the sun is low. Procedural
    /// (Chen et al.'s clouds are textures); not a radiative-transfer model.
    fn cloud_radiance_rgb(&self, v: DVec3, alpha: f64) -> DVec3 {
        let s = self.sun.direction;
        let transmitted = 1.0 - 0.4 * alpha;
        let sun = self.cloud_sun
            * (transmitted * s.y.max(0.0) / PI + 0.25 / PI + 0.6 * henyey_greenstein(v.dot(s), 0.6) * (1.0 - alpha));
        self.cloud_diffuse * transmitted + sun
    }

    /// Radiance of the sun disc toward `view`: the disc's radiance inside its angular radius,
    /// zero outside or once it has set (linear sRGB, kcd m⁻²). The horizon does not cut the disc
    /// here (the sea hides its lower part).
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here).
    ///
    /// # Returns
    /// Linear sRGB radiance (kcd m⁻²): the disc's, or 0.
    ///
    /// # References
    /// Preetham et al. 1999, Appendix A.1 (the disc's radiance).
    pub fn sun_radiance_rgb(&self, view: DVec3) -> DVec3 {
        if view.normalize_or_zero().dot(self.sun.direction) >= self.sun.cos_half_angle() {
            self.sun.radiance_rgb
        } else {
            DVec3::ZERO
        }
    }

    /// Radiance of the Moon's disc toward `view` (linear sRGB, kcd m⁻²): the Lommel–Seeliger
    /// law `L = K cos i/(cos i + cos e)` on the sphere lit from the Sun's direction (the phase
    /// and the terminator), `K` normalised so that the disc's integral is the Moon's
    /// irradiance; zero outside the disc, on its dark side or without a Moon.
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here).
    ///
    /// # Returns
    /// Linear sRGB radiance (kcd m⁻²), `≥ 0`.
    ///
    /// # References
    /// Jensen et al. 2001, §4.1 (Lommel–Seeliger lunar reflectance).
    pub fn moon_radiance_rgb(&self, view: DVec3) -> DVec3 {
        let Some((disc, shade)) = &self.moon else { return DVec3::ZERO };
        let v = view.normalize_or_zero();
        let m = disc.direction;
        let w = v - m * v.dot(m);
        let sin_rho = disc.angular_radius.sin();
        if v.dot(m) <= 0.0 || w.length_squared() > sin_rho * sin_rho {
            return DVec3::ZERO;
        }
        let u = w / sin_rho;
        let cos_e = (1.0 - u.length_squared()).max(0.0).sqrt();
        let normal = u - m * cos_e;
        let cos_i = normal.dot(shade.sun_from_moon);
        if cos_i <= 0.0 {
            return DVec3::ZERO;
        }
        shade.k * (cos_i / (cos_i + cos_e))
    }

    /// Everything seen toward `view`: the sky (with clouds) and, where the clouds let them
    /// through, the sun and moon discs (linear sRGB, kcd m⁻²):
    /// `L = L_sky + (1 − α)(L_sun + L_moon)`.
    ///
    /// # Arguments
    /// - `view`: view direction, y up (normalised here).
    ///
    /// # Returns
    /// Linear sRGB radiance (kcd m⁻²), finite and `≥ 0`.
    ///
    /// # References
    /// Chen et al. 2007, §3.1; Preetham et al. 1999.
    pub fn background_rgb(&self, view: DVec3) -> DVec3 {
        let v = view.normalize_or_zero();
        let sky = self.radiance_rgb(v);
        let discs = self.sun_radiance_rgb(v) + self.moon_radiance_rgb(v);
        if discs == DVec3::ZERO {
            return sky;
        }
        let alpha = self.clouds.as_ref().map_or(0.0, |c| c.opacity(v, self.time_s));
        sky + discs * (1.0 - alpha)
    }

    /// The cloud layers, when the sky has clouds.
    pub fn clouds(&self) -> Option<&CloudLayers> {
        self.clouds.as_ref()
    }

    /// The time (s) at which the clouds are drawn ([`SkyParams::time_s`]).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Fraction of the sun's (or the moon's) direct light that reaches the sea point `point`
    /// through the clouds, `1 − α_shadow` ([`CloudLayers::shadow`]); 1 without clouds.
    ///
    /// # Arguments
    /// - `point`: the sea point (m, in the sea's frame; the clouds' [`CloudParams::origin_m`] is
    ///   the eye's position in that frame).
    /// - `toward`: unit direction of the light.
    ///
    /// # Returns
    /// The transmitted fraction, `[0, 1]`.
    ///
    /// # References
    /// Chen et al. 2007, §3.1 (cloud layers); a straight shadow ray through the shell.
    pub fn cloud_transmittance(&self, point: DVec3, toward: DVec3) -> f64 {
        self.clouds.as_ref().map_or(1.0, |c| 1.0 - c.shadow(point.x, point.z, toward, self.time_s))
    }

    /// The sky radiance as CIE XYZ, `XYZ = M_{sRGB→XYZ} · RGB` of [`Sky::radiance_rgb`].
    ///
    /// # Arguments
    /// - `view`: view direction, y up.
    ///
    /// # Returns
    /// `(X, Y, Z)` in kcd m⁻², `≥ 0`.
    ///
    /// # References
    /// IEC 61966-2-1 (sRGB, D65); CIE 15:2004.
    pub fn radiance_xyz(&self, view: DVec3) -> DVec3 {
        linear_srgb_to_xyz(self.radiance_rgb(view))
    }

    /// Irradiance from the sky dome (clouds included, discs excluded) on a horizontal surface
    /// facing up, `∫ L cos θ dω` (linear sRGB, klx); computed once in the constructor.
    pub fn horizontal_irradiance_rgb(&self) -> DVec3 {
        self.horizontal_irradiance
    }

    /// The sky radiance averaged over the whole sphere, `(1/4π) ∫_{upper} L dω` (the ground
    /// contributes nothing): the isotropic ambient of the aerial perspective (kcd m⁻²).
    pub fn ambient_radiance_rgb(&self) -> DVec3 {
        self.ambient
    }

    /// Aerial perspective of the segment from the eye at height `h₀` (m), direction `d`, length
    /// `s` (m): extinction `F_ex` and in-scattering `L_in` of Hoffman & Preetham with the
    /// exponential Rayleigh and haze layers, lit by the sun and the Moon (their irradiance at sea
    /// level, zero below the horizon) and the ambient sky; see
    /// [`Scattering::aerial_perspective`]. Apply as `L = L₀ F_ex + L_in`.
    ///
    /// # Arguments
    /// - `height_m`: eye height `h₀` (m), `≥ 0` in a scene.
    /// - `direction`: view direction (normalised here).
    /// - `length_m`: segment length `s ≥ 0` (m).
    ///
    /// # Returns
    /// The [`AerialPerspective`]: `F_ex ∈ (0, 1]`, `L_in ≥ 0` (kcd m⁻²).
    ///
    /// # References
    /// Hoffman & Preetham 2002; Chen et al. 2007, Eq. 2–8.
    pub fn aerial_perspective(&self, height_m: f64, direction: DVec3, length_m: f64) -> AerialPerspective {
        self.scattering.aerial_perspective(
            height_m,
            direction.normalize_or_zero(),
            length_m,
            &self.lights,
            self.ambient,
        )
    }

    /// The sea-level scattering coefficients of this sky's turbidity.
    pub fn scattering(&self) -> &Scattering {
        &self.scattering
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// By day `Sky` adds only the night glow to Preetham's sky: 2.5×10⁻⁷ kcd m⁻² at the zenith,
    /// at most 6.7×10⁻⁷ at the horizon.
    const NIGHT_GLOW_MAX: f64 = 1e-6;
    /// Relative jump allowed across e = 0 for a 2×10⁻⁷ rad change of the sun's elevation.
    const SUNSET_CONTINUITY: f64 = 1e-4;
    /// Closed forms evaluated in double precision.
    const ROUNDING: f64 = 1e-12;
    /// Midpoint rule on 200 × 200 cells over the disc: 0.5 % from the edge cells; 1 %.
    const DISC_QUADRATURE: f64 = 0.01;

    fn dir(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
        let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
        DVec3::new(a.sin() * e.cos(), e.sin(), -a.cos() * e.cos())
    }

    #[test]
    fn matches_preetham_by_day() {
        let s = dir(30.0, 180.0);
        let sky = Sky::new(&SkyParams::new(3.0, s)).unwrap();
        let p = PreethamSky::new(3.0, s).unwrap();
        for v in [dir(90.0, 0.0), dir(10.0, 90.0), dir(45.0, 200.0)] {
            let d = sky.clear_radiance_rgb(v) - p.radiance_rgb(v);
            // Only the night glow (2.5×10⁻⁷ kcd m⁻² at the zenith, ≤ 6.7×10⁻⁷) is added.
            assert!(d.abs().max_element() < NIGHT_GLOW_MAX, "{d:?}");
        }
    }

    /// The horizon's colour is the model's own: the sky the renderer reads near the horizon has
    /// the chromaticity of Preetham's fit (no clipping or conversion shifts it), and with
    /// `DaylightModel::HosekWilkie` it is the Hosek–Wilkie sky plus the night glow.
    #[test]
    fn the_horizon_colour_is_the_models_own() {
        /// Chromaticity after the sRGB round trip: the matrices are inverse to 10⁻⁶.
        const ROUND_TRIP_XY: f64 = 1e-5;
        let s = dir(30.0, 0.0);
        let sky = Sky::new(&SkyParams::new(3.0, s)).unwrap();
        let p = PreethamSky::new(3.0, s).unwrap();
        for v in [dir(2.0, 90.0), dir(2.0, 180.0), dir(5.0, 270.0)] {
            let xyz = sky.radiance_xyz(v);
            let (_, x, y) = p.yxy(v);
            assert!((xyz.x / xyz.element_sum() - x).abs() < ROUND_TRIP_XY, "{v}");
            assert!((xyz.y / xyz.element_sum() - y).abs() < ROUND_TRIP_XY, "{v}");
        }
        let hw = Sky::new(&SkyParams { model: DaylightModel::HosekWilkie, ..SkyParams::new(3.0, s) }).unwrap();
        let h = HosekWilkieSky::new(3.0, s, SEA_GROUND_ALBEDO).unwrap();
        for v in [dir(2.0, 90.0), dir(45.0, 200.0)] {
            let d = hw.clear_radiance_rgb(v) - h.radiance_rgb(v);
            assert!(d.abs().max_element() < NIGHT_GLOW_MAX, "{d:?}");
        }
    }

    #[test]
    fn continuous_through_sunset() {
        let v = dir(20.0, 250.0);
        let above = Sky::new(&SkyParams::new(3.0, dir(1e-7, 270.0))).unwrap().radiance_rgb(v);
        let below = Sky::new(&SkyParams::new(3.0, dir(-1e-7, 270.0))).unwrap().radiance_rgb(v);
        assert!(((above - below) / above).abs().max_element() < SUNSET_CONTINUITY, "{above:?} {below:?}");
    }

    /// Twilight colours stay near the daylight locus: blue at the zenith, orange toward the sun,
    /// pale between, as clear twilight skies are. Preetham's sunset sky toward the sun is greenish
    /// yellow, 0.06 above the locus; a ratio per channel on it once made the glow lime, 0.12
    /// above it at −3°. The single-scattering sky the twilight takes its colour from lies within
    /// 0.021 of the locus over these directions (measured, 2 to 6° of depression).
    #[test]
    fn twilight_colours_stay_near_the_daylight_locus() {
        /// The twilight sky's largest distance from the locus here, 0.021, with margin.
        const TWILIGHT_LOCUS: f64 = 0.03;
        for depression in [2.0, 3.0, 4.0, 6.0] {
            let sky = Sky::new(&SkyParams::new(3.0, dir(-depression, 0.0))).unwrap();
            for (elevation, azimuth) in [
                (1.0, 0.0),
                (5.0, 0.0),
                (20.0, 0.0),
                (60.0, 0.0),
                (90.0, 0.0),
                (5.0, 90.0),
                (5.0, 180.0),
                (30.0, 180.0),
            ] {
                let (x, y) = crate::chromaticity(sky.radiance_xyz(dir(elevation, azimuth))).unwrap();
                let off = y - crate::daylight_locus_y(x);
                assert!(
                    off.abs() <= TWILIGHT_LOCUS,
                    "sun −{depression}°, view ({elevation}°, {azimuth}°): xy ({x:.3}, {y:.3}), {off:+.3} from the locus"
                );
            }
        }
    }

    #[test]
    fn visible_fraction_limits() {
        assert!((visible_fraction(0.0, 0.01) - 0.5).abs() < ROUNDING);
        assert!((visible_fraction(0.02, 0.01) - 1.0).abs() < ROUNDING);
        assert!(visible_fraction(-0.02, 0.01).abs() < ROUNDING);
    }

    #[test]
    fn full_moon_disc_integrates_to_its_irradiance() {
        // ∫_disc L dω over the shaded disc equals the irradiance (midpoint rule on a 200 × 200
        // grid over the disc: 0.5 % for the edge cells).
        for phase_deg in [0.0f64, 60.0, 120.0] {
            let m =
                MoonParams { direction: dir(40.0, 120.0), phase_angle: phase_deg.to_radians(), distance_km: 384_400.0 };
            let sun = dir(-20.0, 300.0);
            let sky = Sky::new(&SkyParams { moon: Some(m), ..SkyParams::new(3.0, sun) }).unwrap();
            let disc = *sky.moon().unwrap();
            let c = disc.direction;
            let a = c.any_orthonormal_vector();
            let b = c.cross(a);
            let n = 200;
            let r = disc.angular_radius * 1.001;
            let cell = (2.0 * r / n as f64).powi(2);
            let mut e = DVec3::ZERO;
            for i in 0..n {
                for j in 0..n {
                    let x = -r + (i as f64 + 0.5) * 2.0 * r / n as f64;
                    let y = -r + (j as f64 + 0.5) * 2.0 * r / n as f64;
                    e += sky.moon_radiance_rgb(c + a * x + b * y) * cell;
                }
            }
            let want = disc.irradiance_rgb / disc.visible_fraction;
            assert!(((e - want) / want).abs().max_element() < DISC_QUADRATURE, "{phase_deg}: {e:?} vs {want:?}");
        }
    }
}
