//! Twilight: how the sky darkens and changes colour as the sun sinks below the horizon.
//!
//! The daylight models stop at the horizon. Below it, Brine keeps the luminance of the daylight
//! model's sky at sunset (Preetham's, or Hosek–Wilkie's when chosen; the sun at elevation 0 in its
//! azimuth) and scales it, per view direction, by the ratio
//! of two luminances of a *scattered* sky (single and second order) computed in a spherical
//! atmosphere: with the sun at its true depression, and with the sun on the horizon. The colour
//! moves from the sunset sky's colour to the scattered sky's own over the first 2° of depression,
//!
//! `L(v, e) = Y_D(v; 0) · (Y_ss(v; e)/Y_ss(v; 0)) · ((1 − w) c_D(v; 0) + w c_ss(v; e))`,
//!
//! `c = L/Y` a colour of unit luminance, `w = smoothstep(0°, 2°, −e)`. (A ratio per channel on
//! Preetham's sunset colour, an earlier form, kept that colour's faults and made them worse:
//! toward the sun Preetham's sunset sky is greenish yellow with no blue, 0.06 above the daylight
//! locus, and a ratio cannot add the blue it lacks; at −3° the glow was lime, 0.12 above.)
//!
//! The single-scattering model (Nishita et al. 1993 style) has Rayleigh and Mie scattering with
//! the scale heights and sea-level coefficients of Hoffman & Preetham ([`crate::Scattering`]),
//! Chappuis ozone absorption (Iqbal's `k_o`, 0.35 cm in a layer from 10 to 40 km peaking at
//! 25 km), the Earth's shadow (a point sun), and no refraction. The ratio is exactly 1 and `w`
//! is 0 at sunset, so the sky is continuous at `e = 0`. Both radiances are tabulated in the
//! constructor over view elevation and azimuth relative to the sun and interpolated bilinearly.
//!
//! **Second order.** The higher orders dominate the real sky below about −6° and light the
//! Earth's shadow, which single scattering leaves black. Brine adds the second order, in an
//! approximation: at each point `p` of a view ray the single-scattered sky around `p` is
//! scattered once more toward the eye with the Rayleigh and haze phase functions,
//!
//! `L₂(v) = ∫ T(0→p) [β_R ρ_R(p) ∫ Φ_R(ω·v) L₁(ω) dω + β_M ρ_M(p) ∫ Φ_HG(ω·v) L₁(ω) dω] · r(p) dt`,
//!
//! with `L₁` the observer's own single-scattered sky (tabulated, upper hemisphere; the ground
//! below is dark) and `r(p)` the ratio, per wavelength, of the mean single-scattered sky of an
//! observer on the ground below `p` to the observer's own: `p` lies toward the sun or away from it
//! on the curved Earth, where the sun stands higher or lower. The forward-peaked haze phase
//! makes the hazy air along the horizon toward the set sun glow in the colour of the twilight arch
//! above it, and leaves the Earth's shadow, away from the sun, lit from the blue sky overhead.
//! The third and higher orders are left out; the sky seen from `p` is the ground observer's, not
//! the one at `p`'s height. Each segment of a view ray is integrated exactly for its midpoint's
//! densities, which the near-horizontal views need (their first segments are optically thick).
//! See the docs page for the comparison with measured twilight illuminances; the night-sky glow
//! takes over in deep twilight.

use std::f64::consts::PI;

use glam::DVec3;

use crate::aerial::{
    HAZE_ASYMMETRY, MIE_SCALE_HEIGHT_M, RAYLEIGH_SCALE_HEIGHT_M, henyey_greenstein, mie_beta, rayleigh_beta,
    rayleigh_phase,
};
use crate::cie::cmf;
use crate::error::{SkyError, check};
use crate::solar_tables::{K_OZONE, interpolate, solar_radiance};
use crate::sun::OZONE_CM;
use crate::{MIN_COS_VIEW, linear_srgb_to_xyz, xyz_to_linear_srgb};

/// Mean Earth radius (m), brine-core's.
pub use brine_core::EARTH_RADIUS_M;
/// Top of the model atmosphere (m above the ground).
pub const ATMOSPHERE_TOP_M: f64 = 100_000.0;
/// Ozone layer: tent profile from 10 to 40 km, peak at 25 km (m).
const OZONE_LAYER_M: (f64, f64, f64) = (10_000.0, 25_000.0, 40_000.0);

/// View elevations of the table: `a₀ + (90° − a₀)(i/(N − 1))²`, dense near the horizon, from
/// `a₀ = asin(0.01)` (0.573°, Preetham's lowest view, [`crate::MIN_COS_VIEW`]).
const N_ELEVATION: usize = 16;
/// Relative azimuths of the table: `0..180°` uniform (the sky is symmetric about the sun's
/// vertical plane).
const N_AZIMUTH: usize = 19;
/// Samples along a view ray and along a sun ray.
const N_VIEW: usize = 40;
const N_SUN: usize = 32;
/// Depression of the sun (rad) over which the sky's colour moves from the sunset sky's colour to
/// the scattered sky's: 2° (Brine's choice, about eight minutes at mid-latitudes).
pub const TWILIGHT_COLOUR_DEPRESSION: f64 = 2.0 * PI / 180.0;
/// Wavelengths of the spectral single scattering: 400, 420, …, 700 nm.
const N_LAMBDA: usize = 16;

/// Per-wavelength constants of the single-scattering integral.
struct Spectral {
    rayleigh: [f64; N_LAMBDA],
    mie: [f64; N_LAMBDA],
    ozone: [f64; N_LAMBDA],
    /// `L₀(λ) [x̄, ȳ, z̄](λ) Δλ`: weights from spectral radiance to XYZ.
    to_xyz: [DVec3; N_LAMBDA],
}

impl Spectral {
    fn new(turbidity: f64) -> Self {
        // Preetham's K(λ) between his three knots (0.666 at 450, 0.678 at 550, 0.686 at 680 nm).
        let k =
            |l: f64| interpolate(&[(380.0, 0.666), (450.0, 0.666), (550.0, 0.678), (680.0, 0.686), (780.0, 0.686)], l);
        let lambda = |i: usize| 400.0 + 20.0 * i as f64;
        Self {
            rayleigh: std::array::from_fn(|i| rayleigh_beta(lambda(i))),
            mie: std::array::from_fn(|i| mie_beta(lambda(i), turbidity, k(lambda(i)))),
            // τ_O = k_o (cm⁻¹) · l (cm) · ∫ρ_O dt, the last factor the layer's relative air mass.
            ozone: std::array::from_fn(|i| interpolate(&K_OZONE, lambda(i)) * OZONE_CM),
            to_xyz: std::array::from_fn(|i| DVec3::from(cmf(lambda(i))) * solar_radiance(lambda(i)) * 20.0),
        }
    }
}

/// Densities relative to sea level `(ρ_R, ρ_M, ρ_O)` at height `h` (m); `ρ_O` is per metre of
/// the layer's vertical column (its vertical integral is 1).
fn densities(h: f64) -> DVec3 {
    let (lo, peak, hi) = OZONE_LAYER_M;
    let ozone = if h <= lo || h >= hi {
        0.0
    } else if h < peak {
        (h - lo) / (peak - lo)
    } else {
        (hi - h) / (hi - peak)
    };
    DVec3::new((-h / RAYLEIGH_SCALE_HEIGHT_M).exp(), (-h / MIE_SCALE_HEIGHT_M).exp(), ozone * 2.0 / (hi - lo))
}

/// Distance along the ray `p + t d` to the sphere of radius `r` (the far root), or `None`.
fn exit_distance(p: DVec3, d: DVec3, r: f64) -> Option<f64> {
    let b = p.dot(d);
    let c = p.length_squared() - r * r;
    let disc = b * b - c;
    (disc >= 0.0).then(|| -b + disc.sqrt())
}

/// Whether the ray `p + t d`, `t > 0`, hits the ground sphere.
fn hits_ground(p: DVec3, d: DVec3) -> bool {
    let b = p.dot(d);
    if b >= 0.0 {
        return false;
    }
    let c = p.length_squared() - EARTH_RADIUS_M * EARTH_RADIUS_M;
    b * b - c > 0.0
}

/// Column amounts `(∫ρ_R, ∫ρ_M, ∫ρ_O)` (m) from `p` to the top of the atmosphere along `d`.
fn column_to_top(p: DVec3, d: DVec3) -> DVec3 {
    let top = EARTH_RADIUS_M + ATMOSPHERE_TOP_M;
    let Some(t_exit) = exit_distance(p, d, top) else { return DVec3::ZERO };
    let dt = t_exit / N_SUN as f64;
    (0..N_SUN).map(|k| densities((p + d * ((k as f64 + 0.5) * dt)).length() - EARTH_RADIUS_M)).sum::<DVec3>() * dt
}

/// A spectral radiance: 16 wavelengths from 400 to 700 nm, relative to the solar spectrum.
type Spectrum = [f64; N_LAMBDA];

/// The samples of a view ray from the ground: for each of its `N_VIEW` segments, the densities at
/// its middle, the segment's point, and the transmittance-weighted length
/// `T(start) (1 − e^{−σ_ext Δt})/σ_ext` per wavelength.
///
/// Each segment is integrated exactly with its midpoint's densities and sources. A midpoint rule
/// would lose most of the blue of the first, hazy segments of a view along the horizon, which are
/// optically thick at this step (28 km).
fn view_segments(view: DVec3, sp: &Spectral) -> Vec<(DVec3, DVec3, Spectrum)> {
    let origin = DVec3::new(0.0, EARTH_RADIUS_M + 1.0, 0.0);
    let top = EARTH_RADIUS_M + ATMOSPHERE_TOP_M;
    let t_end = exit_distance(origin, view, top).unwrap_or(0.0);
    let dt = t_end / N_VIEW as f64;
    let mut view_col = DVec3::ZERO;
    (0..N_VIEW)
        .map(|k| {
            let p = origin + view * ((k as f64 + 0.5) * dt);
            let rho = densities(p.length() - EARTH_RADIUS_M);
            let reach = std::array::from_fn(|i| {
                let extinction = sp.rayleigh[i] * rho.x + sp.mie[i] * rho.y + sp.ozone[i] * rho.z;
                let tau = sp.rayleigh[i] * view_col.x + sp.mie[i] * view_col.y + sp.ozone[i] * view_col.z;
                let segment = if extinction * dt > 1e-9 { -(-extinction * dt).exp_m1() / extinction } else { dt };
                (-tau).exp() * segment
            });
            view_col += rho * dt;
            (p, rho, reach)
        })
        .collect()
}

/// The sun's light scattered once toward the ground observer looking along `view`.
fn single_scattering(view: DVec3, sun: DVec3, sp: &Spectral) -> Spectrum {
    let cos_theta = view.dot(sun);
    let (phase_r, phase_m) = (rayleigh_phase(cos_theta), henyey_greenstein(cos_theta, HAZE_ASYMMETRY));
    let mut l = [0.0; N_LAMBDA];
    for (p, rho, reach) in view_segments(view, sp) {
        if hits_ground(p, sun) {
            continue;
        }
        let col = column_to_top(p, sun);
        for (i, li) in l.iter_mut().enumerate() {
            let tau = sp.rayleigh[i] * col.x + sp.mie[i] * col.y + sp.ozone[i] * col.z;
            *li += (sp.rayleigh[i] * rho.x * phase_r + sp.mie[i] * rho.y * phase_m) * (-tau).exp() * reach[i];
        }
    }
    l
}

/// The second order toward the ground observer looking along `view`: at each point `p` of the
/// ray, the single-scattered sky around it scattered once more toward the eye,
/// `σ_R ∫ Φ_R L dω + σ_M ∫ Φ_HG L dω`, attenuated along the view like the single scattering.
///
/// The phase-weighted integrals `around` (Rayleigh, haze) are the observer's own sky's; at `p`
/// they are scaled per wavelength by the ratio of the ambient field at `p`'s local sun elevation
/// to the observer's (`p` lies toward the sun or away from it on a curved Earth).
fn second_order(
    view: DVec3,
    sun: DVec3,
    e_observer: f64,
    around: &(Spectrum, Spectrum),
    ambient: &Ambient,
    sp: &Spectral,
) -> Spectrum {
    let here = ambient.at(e_observer);
    let mut l = [0.0; N_LAMBDA];
    for (p, rho, reach) in view_segments(view, sp) {
        let there = ambient.at(sun.dot(p.normalize()).clamp(-1.0, 1.0).asin());
        for (i, li) in l.iter_mut().enumerate() {
            let scale = if here[i] > 0.0 { there[i] / here[i] } else { 0.0 };
            *li += (sp.rayleigh[i] * rho.x * around.0[i] + sp.mie[i] * rho.y * around.1[i]) * scale * reach[i];
        }
    }
    l
}

/// The table's directions as a quadrature of the upper hemisphere: each cell's direction and its
/// mirror about the sun's vertical plane, with half the cell's solid angle each (the weights sum
/// to 2π).
fn hemisphere_cells() -> Vec<(DVec3, DVec3, f64)> {
    let d_phi = PI / (N_AZIMUTH - 1) as f64;
    (0..N_ELEVATION * N_AZIMUTH)
        .map(|c| {
            let (i, j) = (c / N_AZIMUTH, c % N_AZIMUTH);
            let (lo, hi) = elevation_band(i);
            let (a, phi) = (elevation_of(i), d_phi * j as f64);
            let w = (hi.sin() - lo.sin()) * d_phi * if j == 0 || j + 1 == N_AZIMUTH { 0.5 } else { 1.0 };
            let (x, y, z) = (a.cos() * phi.cos(), a.sin(), a.cos() * phi.sin());
            (DVec3::new(x, y, z), DVec3::new(x, y, -z), w)
        })
        .collect()
}

/// `∫ Φ(ω·v) L(ω) dω` over the upper hemisphere for the Rayleigh and the haze phase functions,
/// for each of the `skies` (single-scattered skies tabulated over the table's directions,
/// mirrored about the sun's vertical plane), on the quadrature of [`hemisphere_cells`]. The lower
/// hemisphere is dark.
fn phase_weighted<const N: usize>(
    skies: [&[Spectrum]; N],
    cells: &[(DVec3, DVec3, f64)],
    view: DVec3,
) -> [(Spectrum, Spectrum); N] {
    let g = HAZE_ASYMMETRY;
    // Henyey–Greenstein as `henyey_greenstein`, with `x^{3/2}` as `x √x`.
    let hg = |c: f64| {
        let x = 1.0 + g * g - 2.0 * g * c;
        (1.0 - g * g) / (4.0 * PI * x * x.sqrt())
    };
    let mut out = [([0.0; N_LAMBDA], [0.0; N_LAMBDA]); N];
    for (cell, &(plus, minus, w)) in cells.iter().enumerate() {
        let (c1, c2) = (plus.dot(view), minus.dot(view));
        let pr = (rayleigh_phase(c1) + rayleigh_phase(c2)) * w;
        let pm = (hg(c1) + hg(c2)) * w;
        for (sky, (r, m)) in skies.iter().zip(out.iter_mut()) {
            let l = &sky[cell];
            for k in 0..N_LAMBDA {
                r[k] += pr * l[k];
                m[k] += pm * l[k];
            }
        }
    }
    out
}

/// A spectral radiance (relative to the solar spectrum) in linear sRGB.
fn to_rgb(l: &[f64; N_LAMBDA], sp: &Spectral) -> DVec3 {
    let xyz: DVec3 = (0..N_LAMBDA).map(|i| sp.to_xyz[i] * l[i]).sum();
    // Saturated reds toward the setting sun fall outside the sRGB gamut (negative G, B): floor
    // each channel at 10⁻³ of the largest so that the ratios stay defined.
    let rgb = xyz_to_linear_srgb(xyz);
    rgb.max(DVec3::splat(1e-3 * rgb.max_element().max(0.0)))
}

/// Below this sun elevation, −21°, no air the view rays cross is lit: the Earth's shadow stands
/// `R(1/cos e − 1)` above the ground, 100 km (the model's top) at 10.1° of depression, and the
/// farthest air a view reaches lies about 10° of arc away, where the sun stands up to 10.2°
/// higher.
const DARK_AIR: f64 = -21.0 * PI / 180.0;

/// Rows and columns of the coarse domes whose mean single scattering is the ambient field.
const N_AMBIENT_ELEVATION: usize = 6;
const N_AMBIENT_AZIMUTH: usize = 7;
/// Step (rad) of the ambient table in the local sun elevation: 1°.
const AMBIENT_STEP: f64 = PI / 180.0;
/// Below this local sun elevation, −20°, the single-scattered ambient is taken as 0: at −10° it
/// is already below 10⁻⁴ of its value at sunset (measured, T = 3: 9×10⁻⁵).
const AMBIENT_FLOOR: f64 = -20.0 * PI / 180.0;

/// The ambient single-scattered field: the dome's mean single-scattered spectral radiance for an
/// observer on the ground, tabulated over the local sun elevation from `e₀` up to 0° (the sunset
/// value is kept for a sun above the local horizon: a lower bound there).
#[derive(Debug, Clone, PartialEq)]
struct Ambient {
    e0: f64,
    means: Vec<[f64; N_LAMBDA]>,
}

impl Ambient {
    fn new(e0: f64, sp: &Spectral) -> Self {
        use rayon::prelude::*;
        let e0 = e0.clamp(AMBIENT_FLOOR, 0.0);
        let n = ((-e0 / AMBIENT_STEP).ceil() as usize).max(1) + 1;
        let e0 = -((n - 1) as f64) * AMBIENT_STEP;
        let means = (0..n)
            .into_par_iter()
            .map(|j| {
                let e = e0 + j as f64 * AMBIENT_STEP;
                let sun = DVec3::new(e.cos(), e.sin(), 0.0);
                let (mut sum, mut weight) = ([0.0; N_LAMBDA], 0.0);
                for i in 0..N_AMBIENT_ELEVATION {
                    // Rows at the midpoints of equal bands of sin a (equal solid angle).
                    let s = (i as f64 + 0.5) / N_AMBIENT_ELEVATION as f64;
                    let a = s.asin().max(MIN_COS_VIEW.asin());
                    for k in 0..N_AMBIENT_AZIMUTH {
                        let phi = PI * k as f64 / (N_AMBIENT_AZIMUTH - 1) as f64;
                        let w = if k == 0 || k + 1 == N_AMBIENT_AZIMUTH { 0.5 } else { 1.0 };
                        let v = DVec3::new(a.cos() * phi.cos(), a.sin(), a.cos() * phi.sin());
                        let l = single_scattering(v, sun, sp);
                        for (acc, li) in sum.iter_mut().zip(l) {
                            *acc += li * w;
                        }
                        weight += w;
                    }
                }
                sum.map(|x| x / weight)
            })
            .collect();
        Self { e0, means }
    }

    /// The mean at local sun elevation `e` (rad), interpolated geometrically between the rows (it
    /// changes tenfold over about 2°; linearly where a row is 0); 0 below the first row, the
    /// sunset value above 0°.
    fn at(&self, e: f64) -> [f64; N_LAMBDA] {
        if e < self.e0 {
            return [0.0; N_LAMBDA];
        }
        let u = ((e - self.e0) / AMBIENT_STEP).min((self.means.len() - 1) as f64);
        let j = (u as usize).min(self.means.len().saturating_sub(2));
        let f = u - j as f64;
        let (a, b) = (self.means[j], self.means[(j + 1).min(self.means.len() - 1)]);
        std::array::from_fn(|i| {
            if a[i] > 0.0 && b[i] > 0.0 { a[i] * (b[i] / a[i]).powf(f) } else { a[i] + (b[i] - a[i]) * f }
        })
    }
}

/// The tabulated scattered skies (single and second order) with the
/// sun at one depression `e` and on the horizon, which turn the daylight model's sunset sky into the
/// twilight sky.
#[derive(Debug, Clone, PartialEq)]
pub struct TwilightRatio {
    /// `L₁ + L₂` with the sun at `e`, per cell (linear sRGB, relative units).
    num: Vec<DVec3>,
    /// `L₁ + L₂` with the sun on the horizon, per cell.
    den: Vec<DVec3>,
    /// `w`, the share of the scattered sky's colour.
    colour_weight: f64,
}

impl TwilightRatio {
    /// Tabulates the ratio for a sun at elevation `sun_elevation` (rad, ≤ 0) and turbidity `T`
    /// (16 × 19 view directions, each with the single and second order for both suns, 16
    /// wavelengths from 400 to 700 nm weighted by the solar spectrum and the CIE matching
    /// functions, then linear sRGB; about 40 ms on two threads).
    ///
    /// # Arguments
    /// - `sun_elevation`: `e` (rad), `[−π/2, π/2]`; above 0 it is treated as 0 (the ratio is 1).
    /// - `turbidity`: `T`, `[1.7, 10]`.
    ///
    /// # Returns
    /// The tabulated [`TwilightRatio`] (dimensionless ratios per linear sRGB channel, `[0, 1]`).
    ///
    /// # Errors
    /// [`SkyError::OutOfRange`] naming `sun_elevation` or `turbidity` outside its range or not
    /// finite.
    ///
    /// # References
    /// Nishita T. et al. 1993, "Display of the Earth taking into account atmospheric scattering",
    /// SIGGRAPH 175–182 (single scattering in a spherical atmosphere); the second order as in the
    /// type's documentation.
    pub fn new(sun_elevation: f64, turbidity: f64) -> Result<Self, SkyError> {
        check("sun_elevation", sun_elevation, sun_elevation.abs() <= PI / 2.0, "[-π/2, π/2] rad")?;
        check("turbidity", turbidity, (1.7..=10.0).contains(&turbidity), "[1.7, 10]")?;
        let e = sun_elevation.min(0.0);
        let u = (-e / TWILIGHT_COLOUR_DEPRESSION).clamp(0.0, 1.0);
        let colour_weight = u * u * (3.0 - 2.0 * u);
        if e < DARK_AIR {
            // No air the view rays cross is lit: both orders are 0 (`apply` gives black).
            let dark = vec![DVec3::ZERO; N_ELEVATION * N_AZIMUTH];
            return Ok(Self { num: dark.clone(), den: dark, colour_weight });
        }
        let sp = Spectral::new(turbidity);
        // The view rays reach about 10° of arc of the Earth away; the ambient table spans the
        // local sun elevations they meet, for both skies.
        let ambient = Ambient::new(e - 11.0 * PI / 180.0, &sp);
        let views: Vec<DVec3> = (0..N_ELEVATION * N_AZIMUTH)
            .map(|c| {
                let (a, phi) = (elevation_of(c / N_AZIMUTH), PI * (c % N_AZIMUTH) as f64 / (N_AZIMUTH - 1) as f64);
                DVec3::new(a.cos() * phi.cos(), a.sin(), a.cos() * phi.sin())
            })
            .collect();
        use rayon::prelude::*;
        let (sun, sunset) = (DVec3::new(e.cos(), e.sin(), 0.0), DVec3::X);
        let first = |s: DVec3| -> Vec<Spectrum> { views.par_iter().map(|&v| single_scattering(v, s, &sp)).collect() };
        let (first_num, first_den) = (first(sun), first(sunset));
        let cells = hemisphere_cells();
        let (num, den): (Vec<DVec3>, Vec<DVec3>) = views
            .par_iter()
            .enumerate()
            .map(|(c, &v)| {
                let [around_num, around_den] = phase_weighted([&first_num, &first_den], &cells, v);
                let total = |l1: &Spectrum, l2: Spectrum| to_rgb(&std::array::from_fn(|k| l1[k] + l2[k]), &sp);
                (
                    total(&first_num[c], second_order(v, sun, e, &around_num, &ambient, &sp)),
                    total(&first_den[c], second_order(v, sunset, 0.0, &around_den, &ambient, &sp)),
                )
            })
            .unzip();
        Ok(Self { num, den, colour_weight })
    }

    /// The twilight sky toward a view, from the daylight model's sunset sky there:
    /// `L = Y_D · (Y_ss(e)/Y_ss(0)) · ((1 − w) L_D/Y_D + w L_ss(e)/Y_ss(e))`.
    ///
    /// # Arguments
    /// - `sunset`: `L_D(v; 0)`, the daylight model's sky toward the view with the sun on the
    ///   horizon in its azimuth (linear sRGB, kcd m⁻², `≥ 0`).
    /// - `elevation`, `relative_azimuth`: the view, as for [`Self::ratio`] (rad).
    ///
    /// # Returns
    /// The twilight radiance (linear sRGB, kcd m⁻², `≥ 0`); `sunset` itself when the sun is on
    /// the horizon.
    ///
    /// # References
    /// Preetham et al. 1999 or Hosek & Wilkie 2012 (the sunset sky); Nishita et al. 1993 (single
    /// scattering).
    pub fn apply(&self, sunset: DVec3, elevation: f64, relative_azimuth: f64) -> DVec3 {
        let (num, den) = self.cells(elevation, relative_azimuth);
        let (y_num, y_den, y_p) = (luminance(num), luminance(den), luminance(sunset));
        if !(y_num > 0.0 && y_den > 0.0 && y_p > 0.0) {
            return DVec3::ZERO;
        }
        let ratio = (y_num / y_den).min(1.0);
        let w = self.colour_weight;
        let colour = sunset / y_p * (1.0 - w) + num / y_num * w;
        (colour * (y_p * ratio)).max(DVec3::ZERO)
    }

    /// The two tabulated skies toward a view, bilinear in the table.
    fn cells(&self, elevation: f64, relative_azimuth: f64) -> (DVec3, DVec3) {
        let a0 = MIN_COS_VIEW.asin();
        let a = elevation.clamp(a0, PI / 2.0);
        let u = (((a - a0) / (PI / 2.0 - a0)).sqrt() * (N_ELEVATION - 1) as f64).min((N_ELEVATION - 1) as f64);
        let phi = relative_azimuth.rem_euclid(2.0 * PI);
        let phi = if phi > PI { 2.0 * PI - phi } else { phi };
        let w = (phi / PI * (N_AZIMUTH - 1) as f64).clamp(0.0, (N_AZIMUTH - 1) as f64);
        let (i, j) = ((u as usize).min(N_ELEVATION - 2), (w as usize).min(N_AZIMUTH - 2));
        let (fu, fw) = (u - i as f64, w - j as f64);
        let lerp = |t: &[DVec3]| {
            let at = |i: usize, j: usize| t[i * N_AZIMUTH + j];
            at(i, j).lerp(at(i, j + 1), fw).lerp(at(i + 1, j).lerp(at(i + 1, j + 1), fw), fu)
        };
        (lerp(&self.num), lerp(&self.den))
    }

    /// The ratio `R(v, e)` for a view at elevation `a` and azimuth `φ` from the sun's vertical
    /// plane, bilinear in the table (rows at `a₀ + (90° − a₀)(i/15)²`, columns every 10°).
    ///
    /// # Arguments
    /// - `elevation`: `a` (rad), any; clamped to `[0.573°, 90°]` (Preetham's lowest view).
    /// - `relative_azimuth`: `φ` (rad), any; folded to `[0, π]` (the sky is symmetric).
    ///
    /// # Returns
    /// The ratio per linear sRGB channel, `[0, 1]`; exactly 1 when the sun is on the horizon.
    ///
    /// # References
    /// Nishita T. et al. 1993 (single scattering), with the second order, tabulated here.
    pub fn ratio(&self, elevation: f64, relative_azimuth: f64) -> DVec3 {
        let (num, den) = self.cells(elevation, relative_azimuth);
        (num / den).min(DVec3::ONE)
    }
}

/// Luminance `Y` of a linear sRGB radiance (its unit).
fn luminance(rgb: DVec3) -> f64 {
    linear_srgb_to_xyz(rgb).y
}

/// The band of elevations (rad) of table row `i`: from the middle between it and the row below
/// (the lowest row from the horizon) to the middle between it and the row above (the top row to 90°).
fn elevation_band(i: usize) -> (f64, f64) {
    let lo = if i == 0 { 0.0 } else { 0.5 * (elevation_of(i - 1) + elevation_of(i)) };
    let hi = if i + 1 == N_ELEVATION { PI / 2.0 } else { 0.5 * (elevation_of(i) + elevation_of(i + 1)) };
    (lo, hi)
}

/// Elevation (rad) of table row `i`.
fn elevation_of(i: usize) -> f64 {
    let s = i as f64 / (N_ELEVATION - 1) as f64;
    let a0 = MIN_COS_VIEW.asin();
    a0 + (PI / 2.0 - a0) * s * s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At sunset the ratio is a number divided by itself: exact up to rounding.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn ratio_is_one_at_sunset_and_falls_with_depression() {
        let at0 = TwilightRatio::new(0.0, 3.0).unwrap();
        for (a, p) in [(0.0, 0.0), (0.3, 1.0), (1.5, 3.0)] {
            let r = at0.ratio(a, p);
            assert!((r - DVec3::ONE).abs().max_element() < ROUNDING, "{r:?}");
        }
        let mut last = DVec3::ONE;
        for e in [-2.0f64, -4.0, -6.0, -9.0, -12.0] {
            let r = TwilightRatio::new(e.to_radians(), 3.0).unwrap().ratio(1.2, 2.0);
            assert!(r.max_element() < last.max_element(), "{e}: {r:?}");
            assert!(r.min_element() >= 0.0 && r.is_finite());
            last = r;
        }
    }

    /// Two sunset colours of the same luminance: a greenish yellow with no blue (Preetham's toward
    /// the sun) and a grey.
    fn bases() -> (DVec3, DVec3) {
        let a = DVec3::new(1.0, 0.8, 0.0);
        let grey = DVec3::splat(1.0);
        (a, grey * (luminance(a) / luminance(grey)))
    }

    /// At sunset `apply` is the identity: the sky is continuous at `e = 0`, whatever its colour.
    #[test]
    fn apply_is_the_sunset_sky_at_sunset() {
        let at0 = TwilightRatio::new(0.0, 3.0).unwrap();
        let (a, b) = bases();
        for (elevation, azimuth) in [(0.01, 0.0), (0.3, 1.0), (1.5, 3.0)] {
            for base in [a, b, DVec3::new(0.2, 0.3, 0.9)] {
                let l = at0.apply(base, elevation, azimuth);
                assert!(((l - base) / base.max_element()).abs().max_element() < 1e-12, "{base:?} → {l:?}");
            }
        }
        assert_eq!(at0.apply(DVec3::ZERO, 0.3, 1.0), DVec3::ZERO, "a black sky stays black, not NaN");
    }

    /// The twilight's luminance depends on the sunset sky's luminance only; its colour is the
    /// sunset sky's weighted by `1 − w`: half at 1° of depression (`smoothstep` at its middle), none
    /// from 2° on, where two sunset colours of one luminance give one twilight sky.
    #[test]
    fn apply_blends_the_sunset_colour_out_over_two_degrees() {
        let (a, b) = bases();
        for (depression, sunset_share) in [(1.0f64, 0.5), (2.0, 0.0), (5.0, 0.0)] {
            let tw = TwilightRatio::new(-depression.to_radians(), 3.0).unwrap();
            for (elevation, azimuth) in [(0.05, 0.0), (0.4, 2.0), (1.2, 3.1)] {
                let (la, lb) = (tw.apply(a, elevation, azimuth), tw.apply(b, elevation, azimuth));
                let scale = luminance(la) / luminance(a);
                assert!(
                    (luminance(la) - luminance(lb)).abs() < 1e-12 * luminance(la),
                    "−{depression}°: luminances differ"
                );
                let expected = (a - b) * (sunset_share * scale);
                assert!(
                    ((la - lb) - expected).abs().max_element() < 1e-12 * la.max_element(),
                    "−{depression}°: {la:?} − {lb:?} against {expected:?}"
                );
            }
        }
    }

    /// The chromaticity `(x, y)` of the twilight sky's single- and second-order table toward a view.
    fn table_xy(tw: &TwilightRatio, elevation_deg: f64, azimuth_deg: f64) -> (f64, f64) {
        let xyz = linear_srgb_to_xyz(tw.cells(elevation_deg.to_radians(), azimuth_deg.to_radians()).0);
        let sum = xyz.x + xyz.y + xyz.z;
        (xyz.x / sum, xyz.y / sum)
    }

    /// With the sun 3.6° down, the sky along the horizon: toward the set sun the haze glows in the
    /// colour of the twilight arch it scatters forward, warmer than daylight white, not the pale
    /// lavender of the dome's mean; away from it the Earth's shadow is bluer than the Belt of Venus
    /// above it (Lee 2015). The shares follow from the phase functions of the second order and
    /// from its integration over the thick hazy segments along the horizon. Measured at T = 3:
    /// x = 0.340 at 1° toward the sun, 0.396 at 3°; away from it 0.289 at 2° and 0.306 at 10°.
    /// With the earlier isotropic second order (half the dome's mean, added to every direction)
    /// the glow 1° up measured x = 0.304, a lavender white: the bound 0.325 lies between, above
    /// D65's 0.313. The shadow's margin, 0.01, is about half the measured 0.017.
    #[test]
    fn the_horizon_glows_toward_the_set_sun_and_the_earths_shadow_is_blue() {
        /// Between the isotropic term's 0.304 and this model's 0.340, above D65's 0.313.
        const WARMER_THAN_WHITE: f64 = 0.325;
        let tw = TwilightRatio::new(-3.6f64.to_radians(), 3.0).unwrap();
        let (glow, _) = table_xy(&tw, 1.0, 0.0);
        assert!(glow > WARMER_THAN_WHITE, "toward the set sun, 1° up: x = {glow:.3}");
        let (arch, _) = table_xy(&tw, 3.0, 0.0);
        assert!(arch > glow, "the arch 3° up (x = {arch:.3}) is deeper orange than the hazy horizon");
        let (shadow, _) = table_xy(&tw, 2.0, 180.0);
        let (belt, _) = table_xy(&tw, 10.0, 180.0);
        assert!(shadow < 0.3 && shadow < belt - 0.01, "away from the sun: shadow x = {shadow:.3}, belt x = {belt:.3}");
    }

    /// Below `DARK_AIR` the tables are not computed: just above it they come out black already
    /// (no lit air on any view ray, and so no second order either), so the shortcut changes
    /// nothing.
    #[test]
    fn the_dark_air_shortcut_changes_nothing() {
        let just_above = TwilightRatio::new(DARK_AIR + 1e-3, 3.0).unwrap();
        assert!(just_above.num.iter().all(|c| *c == DVec3::ZERO), "lit air above −21°");
        let below = TwilightRatio::new(DARK_AIR - 1e-3, 3.0).unwrap();
        assert_eq!(below.apply(DVec3::ONE, 0.01, 0.0), DVec3::ZERO);
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = TwilightRatio::new(-0.1, 12.0).unwrap_err();
        assert!(e.to_string().contains("turbidity"), "{e}");
        let e = TwilightRatio::new(f64::NAN, 3.0).unwrap_err();
        assert!(e.to_string().contains("sun_elevation"), "{e}");
        assert!(TwilightRatio::new(-2.0, 3.0).is_err());
    }

    #[test]
    fn zenith_turns_blue_in_twilight() {
        // The Chappuis band absorbs green and red light along the long, high sun paths: the
        // twilight zenith loses less blue than red (Hulburt 1953, JOSA 43:113).
        let r = TwilightRatio::new(-4f64.to_radians(), 3.0).unwrap().ratio(PI / 2.0, 0.0);
        assert!(r.z > r.x, "{r:?}");
    }
}
