//! The ocean BRDF of Bruneton, Neyret & Holzschuch (2010): Gaussian facet slopes with Smith
//! shadowing and Fresnel at the half vector.
//!
//! Vectors are in the local *wind frame*: z along the mean (geometric) normal, x downwind in the
//! tangent plane, y crosswind.

use std::f64::consts::PI;

use glam::DVec3;

use crate::error::{OpticsError, check};
use crate::{WATER_IOR, fresnel_dielectric};

/// Roughness length of the sea for the wind profile of [`u12_5_from_u10`] (m): a typical open-sea
/// Charnock value at moderate wind.
pub const SEA_ROUGHNESS_LENGTH_M: f64 = 2e-4;

/// The wind 12.5 m above the sea from the wind `U₁₀` at 10 m, by the neutral logarithmic profile
/// `U(z) ∝ ln(z/z₀)`: `U₁₂.₅ = U₁₀ ln(12.5/z₀)/ln(10/z₀)`, a factor 1.0206 for
/// `z₀ =` [`SEA_ROUGHNESS_LENGTH_M`].
///
/// # Arguments
/// - `u10`: wind speed at 10 m (m s⁻¹), `[0, ∞)`.
///
/// # Returns
/// `U₁₂.₅` (m s⁻¹).
///
/// # References
/// Cox & Munk 1954 (their anemometer at 12.5 m); the neutral log profile of the surface layer
/// (e.g. Stull 1988, *An Introduction to Boundary Layer Meteorology*, §9.7).
pub fn u12_5_from_u10(u10: f64) -> f64 {
    debug_assert!(u10 >= 0.0);
    let z0 = SEA_ROUGHNESS_LENGTH_M;
    u10 * (12.5 / z0).ln() / (10.0 / z0).ln()
}

/// Smallest slope variance used, `2×10⁻⁵` (Bruneton et al. 2010 clamp; keeps the lobe finite).
pub const MIN_SLOPE_VARIANCE: f64 = 2e-5;

/// Variances of the facet slopes `(ζx, ζy)` of the waves not drawn as geometry (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeVariance {
    sigma_x2: f64,
    sigma_y2: f64,
}

impl SlopeVariance {
    /// Slope variances downwind (`σx²`) and crosswind (`σy²`), each clamped below at
    /// [`MIN_SLOPE_VARIANCE`]: `σ² ← max(σ², 2×10⁻⁵)`.
    ///
    /// # Arguments
    /// - `sigma_x2`: variance of the downwind slope `ζx = ∂η/∂x` (dimensionless), `[0, ∞)`.
    /// - `sigma_y2`: variance of the crosswind slope `ζy = ∂η/∂y` (dimensionless), `[0, ∞)`.
    ///
    /// # Returns
    /// The clamped variances.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] if either is negative, NaN or infinite.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, §4 (the clamp) and Eq. 4; docs/equations.md §11.
    pub fn new(sigma_x2: f64, sigma_y2: f64) -> Result<Self, OpticsError> {
        check("sigma_x2", sigma_x2, sigma_x2 >= 0.0, "[0, ∞)")?;
        check("sigma_y2", sigma_y2, sigma_y2 >= 0.0, "[0, ∞)")?;
        Ok(Self::clamped(sigma_x2, sigma_y2))
    }

    pub(crate) fn clamped(sigma_x2: f64, sigma_y2: f64) -> Self {
        Self { sigma_x2: sigma_x2.max(MIN_SLOPE_VARIANCE), sigma_y2: sigma_y2.max(MIN_SLOPE_VARIANCE) }
    }

    /// [`SlopeVariance::cox_munk_clean`] for the wind `U₁₀` 10 m above the sea (the height the
    /// scenes and the wave spectra use), carried to Cox & Munk's 12.5 m by [`u12_5_from_u10`]
    /// and capped at 60 m s⁻¹.
    ///
    /// # Arguments
    /// - `u10`: wind speed at 10 m (m s⁻¹), `[0, 60]`.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] outside `[0, 60]`.
    ///
    /// # References
    /// Cox & Munk 1954 (as [`SlopeVariance::cox_munk_clean`]).
    pub fn cox_munk_clean_from_u10(u10: f64) -> Result<Self, OpticsError> {
        check("u10_m_s", u10, (0.0..=60.0).contains(&u10), "[0, 60] m/s")?;
        Self::cox_munk_clean(u12_5_from_u10(u10).min(60.0))
    }

    /// Cox & Munk (1954) slope variances of a clean sea for the wind speed `U₁₂.₅` 12.5 m above
    /// it: `σ_u² = 3.16×10⁻³ U` upwind, `σ_c² = 0.003 + 1.92×10⁻³ U` crosswind.
    ///
    /// # Arguments
    /// - `u12_5`: wind speed (m s⁻¹), `[0, 60]` (measured range about 1–14 m s⁻¹).
    ///
    /// # Returns
    /// `(σx², σy²) = (σ_u², σ_c²)` (dimensionless), each clamped at [`MIN_SLOPE_VARIANCE`]:
    /// `(0.0221, 0.0164)` at 7 m s⁻¹, mean-square slope `0.003 + 5.12×10⁻³ U`.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] outside `[0, 60]`.
    ///
    /// # References
    /// Cox C., Munk W. 1954, "Measurement of the roughness of the sea surface from photographs of
    /// the sun's glitter", JOSA 44(11):838–850, Eq. 4 and Table 1 (clean surface, `U` at 12.5 m);
    /// docs/equations.md §11.
    pub fn cox_munk_clean(u12_5: f64) -> Result<Self, OpticsError> {
        let u = check("u12_5_m_s", u12_5, (0.0..=60.0).contains(&u12_5), "[0, 60] m/s")?;
        Ok(Self::clamped(3.16e-3 * u, 0.003 + 1.92e-3 * u))
    }

    /// Downwind slope variance `σx²`.
    pub fn sigma_x2(&self) -> f64 {
        self.sigma_x2
    }

    /// Crosswind slope variance `σy²`.
    pub fn sigma_y2(&self) -> f64 {
        self.sigma_y2
    }

    /// `σx² + σy²`, the mean-square slope.
    pub fn total(&self) -> f64 {
        self.sigma_x2 + self.sigma_y2
    }

    /// These variances minus those of waves drawn as geometry (the seamless transition of
    /// Bruneton et al. 2010 §4: `σ²_BRDF = σ²_total − σ²_resolved`), clamped at the minimum.
    ///
    /// # Arguments
    /// - `resolved_x2`, `resolved_y2`: slope variances of the resolved waves downwind and
    ///   crosswind (dimensionless), any real (a larger resolved variance clamps to the minimum).
    ///
    /// # Returns
    /// `max(σ² − σ²_resolved, 2×10⁻⁵)` per axis.
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, §4 ("seamless transition"); docs/equations.md §11.
    pub fn minus(&self, resolved_x2: f64, resolved_y2: f64) -> Self {
        Self::clamped(self.sigma_x2 - resolved_x2, self.sigma_y2 - resolved_y2)
    }

    /// Slope variance in the azimuth plane of the direction `s` (local frame):
    /// `σ_s² = σx² cos²φ + σy² sin²φ`, `cos²φ = s_x²/(s_x² + s_y²)` (the tangent form; the
    /// published shader's angle form is an erratum, docs/equations.md §11).
    ///
    /// # Arguments
    /// - `s`: a direction in the local wind frame (need not be unit; only its azimuth is used).
    ///
    /// # Returns
    /// `σ_s²` (dimensionless), between `σx²` and `σy²`; the mean `½(σx² + σy²)` for a vertical
    /// `s` (no azimuth).
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010, Eq. 6 (the variance of the slope along a direction of a
    /// Gaussian with diagonal covariance); docs/equations.md §11.
    pub fn along(&self, s: DVec3) -> f64 {
        let h2 = s.x * s.x + s.y * s.y;
        if h2 <= 0.0 {
            return 0.5 * (self.sigma_x2 + self.sigma_y2);
        }
        (self.sigma_x2 * s.x * s.x + self.sigma_y2 * s.y * s.y) / h2
    }
}

/// Gaussian probability density of facet slopes,
/// `p(ζ) = exp(−½(ζx²/σx² + ζy²/σy²)) / (2π σx σy)`.
///
/// # Arguments
/// - `zeta_x`, `zeta_y`: facet slopes (dimensionless), any real.
/// - `variance`: the slope variances.
///
/// # Returns
/// The density per unit slope² (dimensionless), `∫∫ p dζx dζy = 1`.
///
/// # References
/// Bruneton, Neyret & Holzschuch 2010, "Real-time realistic ocean lighting using seamless
/// transitions from geometry to BRDF", CGF 29(2), Eq. 4; docs/equations.md §11.
pub fn slope_pdf(zeta_x: f64, zeta_y: f64, variance: &SlopeVariance) -> f64 {
    let (sx2, sy2) = (variance.sigma_x2, variance.sigma_y2);
    (-0.5 * (zeta_x * zeta_x / sx2 + zeta_y * zeta_y / sy2)).exp() / (2.0 * PI * (sx2 * sy2).sqrt())
}

/// `ν` from which [`smith_lambda`] returns 0: there `Λ(ν) ≤ e^{−ν²}/(4ν³√π) ≤ 1.6×10⁻¹⁹`, below
/// half the spacing of doubles at 1 (1.1×10⁻¹⁶), so every `1 + Λ + …` it enters is unchanged,
/// and the closed form's two terms (both about `e^{−ν²}`) would only cancel. The bound is the
/// alternating asymptotic series `erfc ν = e^{−ν²}/(ν√π) (1 − 1/(2ν²) + 3/(4ν⁴) − …)` cut after
/// its second term (Abramowitz & Stegun 1964, §7.1.23). Views this far from grazing (`ν ≥ 6`:
/// `cot θ ≥ 8.5 σ`) are most of a frame's, and `erfc`'s tail is the costly branch.
pub const SMITH_NEGLIGIBLE_NU: f64 = 6.0;

/// Smith's shadowing term `Λ` for Gaussian slopes,
/// `Λ = (e^{−ν²} − ν√π erfc ν) / (2ν√π)`, `ν = μ/√(2σ_s²(1 − μ²))`.
///
/// # Arguments
/// - `cos_theta`: `μ`, cosine of the direction's angle to the mean normal, `(0, 1]`.
/// - `sigma_s2`: slope variance in the direction's azimuth plane, `> 0`.
///
/// # Returns
/// `Λ ≥ 0` (dimensionless); `0` at normal incidence, and `0` for `ν ≥` [`SMITH_NEGLIGIBLE_NU`],
/// where `Λ < 1.6×10⁻¹⁹` (so `1 + Λ` rounds to 1). Uses `libm::erfc` (full precision).
///
/// # References
/// Smith 1967; Bruneton et al. 2010, Eq. 6; docs/equations.md §11.
pub fn smith_lambda(cos_theta: f64, sigma_s2: f64) -> f64 {
    debug_assert!(sigma_s2 > 0.0);
    let mu = cos_theta.clamp(1e-6, 1.0);
    if mu >= 1.0 {
        return 0.0;
    }
    let nu = mu / (2.0 * sigma_s2 * (1.0 - mu * mu)).sqrt();
    if nu >= SMITH_NEGLIGIBLE_NU {
        return 0.0;
    }
    let sqrt_pi = PI.sqrt();
    ((-nu * nu).exp() - nu * sqrt_pi * libm::erfc(nu)) / (2.0 * nu * sqrt_pi)
}

/// The ocean BRDF `ρ(v, l) = F(v·h) p(ζ_h) / (4 h_z⁴ v_z l_z (1 + Λ(v) + Λ(l)))`,
/// `h = (v + l)/‖v + l‖`, `ζ_h = (h_x, h_y)/h_z`.
///
/// # Arguments
/// - `v`: unit direction toward the viewer, local wind frame, `v_z > 0`.
/// - `l`: unit direction toward the light, local wind frame, `l_z > 0`.
/// - `variance`: slope variances of the unresolved waves.
/// - `n_water`: index of refraction of water (1.333).
///
/// # Returns
/// `ρ` (sr⁻¹), `0` if either direction is below the mean surface. Directions within 0.01 of
/// the horizon are clamped to `z = 0.01` as in the authors' shader.
///
/// # References
/// Bruneton et al. 2010, Eq. 7–8; docs/equations.md §11 (with the visibility-weighted density of the
/// Li Ying et al. 2018 erratum).
pub fn ocean_brdf(v: DVec3, l: DVec3, variance: &SlopeVariance, n_water: f64) -> f64 {
    if v.z <= 0.0 || l.z <= 0.0 {
        return 0.0;
    }
    brdf_seen_with(v, l, variance, n_water, view_lambda(v, variance))
}

/// Smith's `Λ(v)` of the view direction `v` (`v_z > 0`) in [`ocean_brdf`], which depends on the
/// view alone: computed once for many light directions.
fn view_lambda(v: DVec3, variance: &SlopeVariance) -> f64 {
    smith_lambda(v.z.max(0.01), variance.along(v))
}

/// [`ocean_brdf`] with the view's `Λ(v)` given (`lambda_v = view_lambda(v, variance)`), for
/// `v_z > 0`, `l_z > 0`.
fn brdf_seen_with(v: DVec3, l: DVec3, variance: &SlopeVariance, n_water: f64, lambda_v: f64) -> f64 {
    let h = (v + l).normalize();
    let (vz, lz) = (v.z.max(0.01), l.z.max(0.01));
    let zeta = (h.x / h.z, h.y / h.z);
    let p = slope_pdf(zeta.0, zeta.1, variance);
    let lambda_l = smith_lambda(lz, variance.along(l));
    let f = fresnel_dielectric(v.dot(h), 1.0, n_water);
    f * p / (4.0 * h.z.powi(4) * vz * lz * (1.0 + lambda_v + lambda_l))
}

/// Sun radiance reflected toward `v`: `I_sun = ρ(v, l) E_sun l_z`, for a sun of irradiance
/// `E_sun = L_sun Ω_sun` on a plane facing it (a sun small against the BRDF lobe).
///
/// # Arguments
/// - `v`, `l`: unit view and sun directions, local wind frame.
/// - `variance`: slope variances.
/// - `sun_irradiance`: `E_sun` in any radiometric or photometric unit (W m⁻² or lx), `≥ 0`.
///
/// # Returns
/// The reflected radiance, in that unit per steradian.
///
/// # References
/// Bruneton et al. 2010, Eq. 9 ("reflectedSunRadiance" in the authors' shader); docs/equations.md §11.
pub fn reflected_sun_radiance(v: DVec3, l: DVec3, variance: &SlopeVariance, sun_irradiance: f64) -> f64 {
    ocean_brdf(v, l, variance, WATER_IOR) * sun_irradiance * l.z.max(0.0)
}

/// Cox & Munk's inversion of a glitter measurement: the density of the facet slopes that mirror
/// the sun toward the viewer, from the glitter's radiance per unit of the sun's irradiance,
/// `p(ζ) = 4 (L/E) cos θ_v cos⁴β / ρ(ω)`, `ζ = (h_x, h_y)/h_z`, `h = (v + l)/|v + l|`.
///
/// The glitter of a sea of slope density `p` is `L/E = ρ(ω) p(ζ) / (4 cos θ_v cos⁴β)` (no
/// shadowing), with `cos θ_v = v_z`, the facet tilt `cos β = h_z` and `ρ(ω)` Fresnel at
/// `cos ω = v·h`; this inverts it. On [`reflected_sun_radiance`] it returns
/// `slope_pdf / (1 + Λ(v) + Λ(l))`: the masking of the BRDF shows as a deficit at grazing views.
///
/// # Arguments
/// - `v`, `l`: unit directions toward the viewer and the sun, z up (the mean surface's normal),
///   `v_z > 0`, `l_z > 0`.
/// - `glint_per_irradiance`: `L/E` (sr⁻¹), `≥ 0`: the reflected radiance of the sun over its
///   irradiance on a plane facing it, in the same photometric or radiometric unit.
/// - `n_water`: index of refraction of water (1.333).
///
/// # Returns
/// `(ζ_x, ζ_y, p)`: the mirroring slope (1) and the slope density there (1).
///
/// # References
/// Cox C., Munk W. 1954, "Measurement of the roughness of the sea surface from photographs of
/// the sun's glitter", JOSA 44(11):838–850, Eq. 5 (the glitter equation they inverted).
pub fn glitter_slope_density(v: DVec3, l: DVec3, glint_per_irradiance: f64, n_water: f64) -> (f64, f64, f64) {
    debug_assert!(v.z > 0.0 && l.z > 0.0 && glint_per_irradiance >= 0.0);
    let h = (v + l).normalize();
    let rho = fresnel_dielectric(v.dot(h), 1.0, n_water);
    (h.x / h.z, h.y / h.z, 4.0 * glint_per_irradiance * v.z * h.z.powi(4) / rho)
}

/// The Sun (or the Moon) as a disc of uniform radiance and angular radius `r`, with product
/// quadrature rules over its solid angle for [`reflected_disc_radiance`].
///
/// **Why a quadrature and not a wider lobe.** A tilt `δ` of the light direction moves the half
/// vector by `δ/(2 v·h)` (since `‖v + l‖ = 2 v·h`) and the facet slope `ζ = (h_x, h_y)/h_z` by
/// between `1/h_z` and `1/h_z²` times that, so the disc's image in slope space has a radius
/// `a ≈ r/(2 (v·h) h_z²)` along the plane of `v` and `l`: `a = tan(r/2) ≈ r/2` for the Sun
/// overhead seen straight down. A uniform disc of radius `a` has the per-axis second moment
/// `a²/4`; adding it to `σx²`, `σy²` keeps the reflected energy and the lobe's width, but the peak
/// of a Gaussian of variance `a²/4` is `2/(πa²)`, twice the disc's `1/(πa²)`, so on a sea
/// smoother than the disc that approximation doubles the glint. The quadrature is exact in both
/// limits: it evaluates the definition `I = ∫_disc ρ(v, l′) L l′_z dω′`.
///
/// **Rules.** In the frame of the disc's centre `l`, `l′ = cos θ′ l + sin θ′ (cos φ e₁ + sin φ e₂)`,
/// `dω′ = ds dφ` with `s = 1 − cos θ′ ∈ [0, 2 sin²(r/2)]` (the cap's area is uniform in `s`):
/// `n` Gauss–Legendre nodes in `s` times `4n` equally spaced `φ`, offset by half a step on odd
/// rings; the weights sum to `Ω = 2π(1 − cos r)`. An `n`-ring rule integrates exactly the
/// polynomials in the tangent coordinates of degree up to about `4n − 2`.
///
/// **Choice of `n`.** The integrand varies over the disc on the scale of the lobe, `σ`, so the
/// rule needs `n` growing with `q = a/σ_min` ([`Self::rings_for`]). Measured against a 32-ring
/// rule on the calmest sea allowed (`σ² =` [`MIN_SLOPE_VARIANCE`], `σ = 4.5` mrad against the
/// Sun's `a ≥ 2.3` mrad), the 2-ring rule errs by `8×10⁻⁸` at `q = 0.5` (Sun overhead),
/// `8×10⁻⁶` at `q = 1` (60°), `1.5×10⁻⁴` at `q = 1.5` (70°) and `1.7×10⁻²` at `q = 3` (80°); the
/// choice `n = ⌈1.25 q + ½⌉` (one ring for `q ≤ 0.1`) stays below `10⁻⁴` up to 85° and for discs
/// eleven times the lobe (see `tests/sun_disc.rs`).
#[derive(Debug, Clone, PartialEq)]
pub struct SunDisc {
    angular_radius: f64,
    solid_angle: f64,
    min_rings: usize,
    /// `rules[k]`: the rule of `min_rings + k` rings, as `(sin θ′ cos φ, sin θ′ sin φ, cos θ′)` in
    /// the disc's frame with its weight (sr).
    rules: Vec<Vec<(DVec3, f64)>>,
}

impl SunDisc {
    /// Angular radius of the Sun at 1 AU, `asin(R_☉/1 AU) = 4.650484×10⁻³` rad (0.26645°), with
    /// the nominal solar radius 695 700 km (IAU 2015 Resolution B3) and the astronomical unit
    /// 149 597 870.7 km (IAU 2012 Resolution B2), as in brine-sky.
    pub const SUN_ANGULAR_RADIUS: f64 = 4.650_484_023_614_977e-3;

    /// Fewest and most rings [`Self::new`] chooses from, `1` and `16` (4 and 1024 directions).
    pub const ADAPTIVE_RINGS: (usize, usize) = (1, 16);

    /// Largest number of rings accepted by [`Self::with_rings`], `64` (`64 × 256` directions).
    pub const MAX_RINGS: usize = 64;

    /// A disc with the rules of 1 to 16 rings, the number used for each evaluation chosen by
    /// [`Self::rings_for`] (what the renderer should use).
    ///
    /// # Arguments
    /// - `angular_radius_rad`: angular radius `r` of the disc (rad), `[0, π/4]`; `0` is a point
    ///   source ([`reflected_disc_radiance`] then is [`reflected_sun_radiance`]).
    ///
    /// # Returns
    /// The disc, with `Ω = 2π(1 − cos r)` and the rules of [`Self::ADAPTIVE_RINGS`] rings.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming `angular_radius_rad` outside `[0, π/4]`.
    ///
    /// # References
    /// Product rule on the spherical cap (uniform measure in `cos θ′`): Stroud A. 1971,
    /// *Approximate Calculation of Multiple Integrals*, §2.7; Gauss–Legendre nodes: Abramowitz &
    /// Stegun 1964, *Handbook of Mathematical Functions*, §25.4.29.
    pub fn new(angular_radius_rad: f64) -> Result<Self, OpticsError> {
        Self::build(angular_radius_rad, Self::ADAPTIVE_RINGS.0, Self::ADAPTIVE_RINGS.1)
    }

    /// A disc with the single rule of `rings` rings (`rings × 4·rings` directions), whatever the
    /// lobe: a reference, or a fixed cost.
    ///
    /// # Arguments
    /// - `angular_radius_rad`: as [`Self::new`].
    /// - `rings`: Gauss–Legendre nodes in `s`, `[1, 64]`.
    ///
    /// # Returns
    /// The disc, whose only rule has `rings` rings.
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] naming the argument outside its range.
    ///
    /// # References
    /// As [`Self::new`].
    pub fn with_rings(angular_radius_rad: f64, rings: usize) -> Result<Self, OpticsError> {
        if !(1..=Self::MAX_RINGS).contains(&rings) {
            return Err(OpticsError::OutOfRange(brine_core::OutOfRange {
                name: "rings",
                value: rings as f64,
                range: "[1, 64]",
            }));
        }
        Self::build(angular_radius_rad, rings, rings)
    }

    fn build(angular_radius_rad: f64, min_rings: usize, max_rings: usize) -> Result<Self, OpticsError> {
        let r = check(
            "angular_radius_rad",
            angular_radius_rad,
            (0.0..=std::f64::consts::FRAC_PI_4).contains(&angular_radius_rad),
            "[0, π/4] rad",
        )?;
        // 1 − cos r without cancellation.
        let s_max = 2.0 * (0.5 * r).sin().powi(2);
        let solid_angle = 2.0 * PI * s_max;
        if r == 0.0 {
            return Ok(Self { angular_radius: 0.0, solid_angle: 0.0, min_rings, rules: Vec::new() });
        }
        let rule = |rings: usize| {
            let spokes = 4 * rings;
            let (x, w) = crate::quadrature::gauss_legendre(rings);
            let mut nodes = Vec::with_capacity(rings * spokes);
            for (k, (x, w)) in x.iter().zip(&w).enumerate() {
                let s = 0.5 * s_max * (x + 1.0);
                let (sin_t, cos_t) = ((s * (2.0 - s)).max(0.0).sqrt(), 1.0 - s);
                let weight = 0.5 * s_max * w * 2.0 * PI / spokes as f64;
                let offset = if k % 2 == 1 { 0.5 } else { 0.0 };
                for j in 0..spokes {
                    let phi = 2.0 * PI * (j as f64 + offset) / spokes as f64;
                    nodes.push((DVec3::new(sin_t * phi.cos(), sin_t * phi.sin(), cos_t), weight));
                }
            }
            nodes
        };
        Ok(Self { angular_radius: r, solid_angle, min_rings, rules: (min_rings..=max_rings).map(rule).collect() })
    }

    /// The Sun at [`Self::SUN_ANGULAR_RADIUS`] with the adaptive rules.
    pub fn sun() -> Self {
        Self::new(Self::SUN_ANGULAR_RADIUS).unwrap_or_else(|_| unreachable!("the Sun's radius is in range"))
    }

    /// Angular radius `r` (rad).
    pub fn angular_radius(&self) -> f64 {
        self.angular_radius
    }

    /// Solid angle `Ω = 2π(1 − cos r)` (sr).
    pub fn solid_angle(&self) -> f64 {
        self.solid_angle
    }

    /// The fewest and most rings this disc's rules have.
    pub fn ring_range(&self) -> (usize, usize) {
        (self.min_rings, self.min_rings + self.rules.len().saturating_sub(1))
    }

    /// The disc's image in slope space over the lobe's narrower standard deviation,
    /// `q = r/(2 (v·h) h_z² σ_min)` (`h` the half vector, `v·h ≥ 0.01`, `h_z² ≥ 0.01`): how far the
    /// disc is from a point source for this glint.
    ///
    /// # Arguments
    /// - `v`, `l`: unit view and disc directions, local wind frame.
    /// - `variance`: slope variances.
    ///
    /// # Returns
    /// `q` (dimensionless, `≥ 0`).
    pub fn image_size(&self, v: DVec3, l: DVec3, variance: &SlopeVariance) -> f64 {
        let h = (v + l).normalize_or(DVec3::Z);
        let sigma = variance.sigma_x2.min(variance.sigma_y2).sqrt();
        self.angular_radius / (2.0 * v.dot(h).max(0.01) * (h.z * h.z).max(0.01) * sigma)
    }

    /// Rings needed for the glint toward `v` of the disc at `l` on slopes of `variance`:
    /// `n = 1` if `q ≤ 0.1`, else `⌈1.25 q + ½⌉`, clamped to [`Self::ring_range`], with
    /// `q = r/(2 (v·h) h_z² σ_min)` the disc's image in slope space over the lobe's narrower
    /// standard deviation (`v·h ≥ 0.01`, `h_z² ≥ 0.01`; see the type's documentation).
    ///
    /// # Arguments
    /// - `v`, `l`: unit view and disc directions, local wind frame.
    /// - `variance`: slope variances.
    ///
    /// # Returns
    /// The number of rings, in [`Self::ring_range`].
    ///
    /// # References
    /// Brine's error model of the rule, fitted to the measurements quoted above.
    pub fn rings_for(&self, v: DVec3, l: DVec3, variance: &SlopeVariance) -> usize {
        let (lo, hi) = self.ring_range();
        let q = self.image_size(v, l, variance);
        let n = if q <= 0.1 { 1 } else { (1.25 * q + 0.5).ceil().min(Self::MAX_RINGS as f64) as usize };
        n.clamp(lo, hi)
    }

    /// Number of directions of the `rings`-ring rule (clamped to [`Self::ring_range`]).
    pub fn node_count(&self, rings: usize) -> usize {
        self.rule(rings).len()
    }

    fn rule(&self, rings: usize) -> &[(DVec3, f64)] {
        let (lo, hi) = self.ring_range();
        self.rules.get(rings.clamp(lo, hi) - lo).map_or(&[], Vec::as_slice)
    }

    /// `∫_disc f(l′) dω′` over the disc centred on `l`, by the `rings`-ring rule.
    ///
    /// # Arguments
    /// - `l`: direction of the disc's centre (normalised here; `z` if zero).
    /// - `rings`: the rule, clamped to [`Self::ring_range`].
    /// - `f`: the integrand, a function of the unit direction `l′`.
    ///
    /// # Returns
    /// The integral, in the unit of `f` times steradians; `0` for a point disc (`r = 0`).
    ///
    /// # References
    /// As [`Self::new`].
    pub fn integrate(&self, l: DVec3, rings: usize, mut f: impl FnMut(DVec3) -> f64) -> f64 {
        let l = l.normalize_or(DVec3::Z);
        let (e1, e2) = l.any_orthonormal_pair();
        self.rule(rings).iter().map(|&(q, w)| w * f(q.x * e1 + q.y * e2 + q.z * l)).sum()
    }
}

/// Sun radiance reflected toward `v` by the facets of the unresolved waves, for a sun of finite
/// angular size: the BRDF integrated over the disc of uniform radiance `L = E_sun/Ω`,
/// `I_sun = (E_sun/Ω) ∫_disc ρ(v, l′) l′_z dω′`, by the rule [`SunDisc::rings_for`] picks.
///
/// It tends to [`reflected_sun_radiance`] `ρ(v, l) E_sun l_z` as `r → 0` (relative difference
/// `O((a/σ)²)`, `a ≈ r/(2 v·h)` the disc's image in slope space), conserves the reflected energy
/// of that point form to `O(r²)`, and on a sea much smoother than the disc (`σ ≪ a`) tends to the
/// mirror image of the disc, `F(v_z) L` within the reflected disc and `0` outside. For the Sun
/// overhead on the calmest sea allowed the point form is 7 % too bright at the peak (`r²/(8σ²) =
/// 0.135` against `1 − e^{−r²/(8σ²)} = 0.127`). Parts of the disc below the mean surface's
/// horizon (`l′_z ≤ 0`) contribute nothing.
///
/// # Arguments
/// - `v`: unit direction toward the viewer, local wind frame, `v_z > 0`.
/// - `l`: unit direction toward the disc's centre, local wind frame (normalised here).
/// - `variance`: slope variances of the unresolved waves.
/// - `sun_irradiance`: `E_sun = L Ω`, the irradiance of the whole disc on a plane facing it, in
///   any radiometric or photometric unit (W m⁻² or lx), `≥ 0`.
/// - `disc`: the disc's angular radius and rules ([`SunDisc::sun`] for the Sun).
///
/// # Returns
/// The reflected radiance, in the unit of `sun_irradiance` per steradian; `≥ 0`, finite.
///
/// # References
/// Bruneton, Neyret & Holzschuch 2010, Eq. 7–9 (the BRDF and the reflected sun); docs/equations.md
/// §11; the disc integral is the definition of reflected radiance, `L_r = ∫ ρ L_i cos θ_i dω_i`
/// (Nicodemus et al. 1977, "Geometrical considerations and nomenclature for reflectance", NBS
/// Monograph 160).
pub fn reflected_disc_radiance(
    v: DVec3,
    l: DVec3,
    variance: &SlopeVariance,
    sun_irradiance: f64,
    disc: &SunDisc,
) -> f64 {
    if disc.rules.is_empty() {
        return reflected_sun_radiance(v, l, variance, sun_irradiance);
    }
    let rings = disc.rings_for(v, l, variance);
    // `ocean_brdf` node by node, the view's `Λ(v)` computed once.
    let lambda_v = if v.z > 0.0 { view_lambda(v, variance) } else { 0.0 };
    let sum = disc.integrate(l, rings, |d| {
        if v.z <= 0.0 || d.z <= 0.0 {
            return 0.0;
        }
        brdf_seen_with(v, d, variance, WATER_IOR, lambda_v) * d.z
    });
    sun_irradiance / disc.solid_angle * sum
}

/// Disc image in slope space ([`SunDisc::image_size`]) below which [`reflected_source_radiance`]
/// treats the disc as a point (relative error `O(q²)`, under 10⁻³).
pub const POINT_DISC_Q: f64 = 0.03;

/// Mahalanobis distance of the mirroring slope beyond which (plus the disc image `q`) a glint is
/// in the far tail of the lobe (below `e^{−12.5}` of the peak) and [`reflected_source_radiance`]
/// treats the disc as a point whatever its size.
pub const POINT_DISC_TAIL: f64 = 5.0;

/// The glint of a sun or moon disc toward `v`: [`reflected_sun_radiance`] (a point source) where
/// the disc's image in slope space is small (`q ≤` [`POINT_DISC_Q`], the point form errs by
/// `O(q²) ≤ 10⁻³`) or the mirroring slope lies in the lobe's far tail (beyond
/// [`POINT_DISC_TAIL`]` + q` standard deviations), else [`reflected_disc_radiance`] (the BRDF
/// integrated over the disc, for calmer water).
///
/// # Arguments
/// As [`reflected_disc_radiance`].
///
/// # Returns
/// The reflected radiance, in the unit of `sun_irradiance` per steradian; `≥ 0`, finite.
///
/// # References
/// As [`reflected_disc_radiance`].
pub fn reflected_source_radiance(
    v: DVec3,
    l: DVec3,
    variance: &SlopeVariance,
    sun_irradiance: f64,
    disc: &SunDisc,
) -> f64 {
    let q = disc.image_size(v, l, variance);
    let h = (v + l).normalize_or(DVec3::Z);
    let hz = h.z.max(1e-3);
    let tail = ((h.x / hz).powi(2) / variance.sigma_x2() + (h.y / hz).powi(2) / variance.sigma_y2()).sqrt();
    if q <= POINT_DISC_Q || tail > POINT_DISC_TAIL + q {
        reflected_sun_radiance(v, l, variance, sun_irradiance)
    } else {
        reflected_disc_radiance(v, l, variance, sun_irradiance, disc)
    }
}

/// The authors' fit of the Fresnel reflectance averaged over the facet slopes seen from `v`:
/// `F̄(v) = 0.02 + 0.98 (1 − v_z)^{5 exp(−2.69 σ_v)} / (1 + 22.7 σ_v^{1.5})`.
///
/// # Arguments
/// - `cos_theta_v`: `v_z`, cosine of the view angle to the mean normal, `[0, 1]`.
/// - `sigma_v`: slope standard deviation in the view's azimuth plane, `√σ_v²`, `≥ 0`.
///
/// # Returns
/// `F̄` in `[0.02, 1]`.
///
/// # References
/// Bruneton et al. 2010, §5.2 (`meanFresnel` in the authors' shader); docs/equations.md §11.
pub fn mean_fresnel(cos_theta_v: f64, sigma_v: f64) -> f64 {
    let vz = cos_theta_v.clamp(0.0, 1.0);
    let s = sigma_v.max(0.0);
    (0.02 + 0.98 * (1.0 - vz).powf(5.0 * (-2.69 * s).exp()) / (1.0 + 22.7 * s.powf(1.5))).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The choice: the point form for a disc much smaller than the lobe, the disc's integral on
    /// a sea as smooth as the disc is wide.
    #[test]
    fn the_source_is_a_point_or_a_disc_as_its_image_needs() {
        let sun = SunDisc::sun();
        let (v, l) = (DVec3::new(0.3, 0.0, 1.0).normalize(), DVec3::new(-0.3, 0.0, 1.0).normalize());
        let rough = SlopeVariance::new(0.04, 0.03).unwrap();
        assert!(sun.image_size(v, l, &rough) <= POINT_DISC_Q);
        assert_eq!(
            reflected_source_radiance(v, l, &rough, 1.0, &sun).to_bits(),
            reflected_sun_radiance(v, l, &rough, 1.0).to_bits()
        );
        let calm = SlopeVariance::new(1e-5, 1e-5).unwrap();
        assert!(sun.image_size(v, l, &calm) > POINT_DISC_Q);
        assert_eq!(
            reflected_source_radiance(v, l, &calm, 1.0, &sun).to_bits(),
            reflected_disc_radiance(v, l, &calm, 1.0, &sun).to_bits()
        );
        // Far in the tail, the point form again.
        let away = DVec3::new(0.9, 0.0, 0.2).normalize();
        assert_eq!(
            reflected_source_radiance(v, away, &calm, 1.0, &sun).to_bits(),
            reflected_sun_radiance(v, away, &calm, 1.0).to_bits()
        );
    }

    /// The profile's factor `ln(62 500)/ln(50 000)` = 1.020 62.
    #[test]
    fn the_wind_profile_raises_u10_by_two_percent() {
        assert!((u12_5_from_u10(10.0) - 10.206_2).abs() < 1e-3);
        let a = SlopeVariance::cox_munk_clean_from_u10(7.0).unwrap();
        let b = SlopeVariance::cox_munk_clean(7.0 * 1.020_62).unwrap();
        assert!((a.sigma_x2() - b.sigma_x2()).abs() < 1e-6);
        assert!(SlopeVariance::cox_munk_clean_from_u10(61.0).is_err());
    }
    use approx::assert_relative_eq;

    /// Oracle values of docs/equations.md are given to 5 significant digits.
    const ORACLE: f64 = 1e-4;

    /// The glitter equation inverts the BRDF's sun reflection: the density it returns is the
    /// Gaussian slope density at the mirroring slope, less the BRDF's masking `1 + Λ_v + Λ_l`
    /// (computed here from the closed forms, not from `ocean_brdf`).
    #[test]
    fn the_glitter_equation_inverts_the_sun_reflection() {
        /// Same formula rearranged: rounding only.
        const ROUNDING: f64 = 1e-12;
        let variance = SlopeVariance::new(0.02, 0.012).unwrap();
        let dir = |theta_deg: f64, phi_deg: f64| {
            let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
            DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
        };
        for (v, l) in
            [(dir(40.0, 180.0), dir(55.0, 0.0)), (dir(70.0, 170.0), dir(60.0, 20.0)), (dir(5.0, 0.0), dir(8.0, 90.0))]
        {
            let glint = reflected_sun_radiance(v, l, &variance, 1.0);
            let (zx, zy, p) = glitter_slope_density(v, l, glint, WATER_IOR);
            let h = (v + l).normalize();
            assert_relative_eq!(zx, h.x / h.z, max_relative = ROUNDING);
            assert_relative_eq!(zy, h.y / h.z, max_relative = ROUNDING);
            let sigma2 = |d: DVec3| {
                let c = (d.x * d.x + d.y * d.y).max(1e-300);
                (d.x * d.x * 0.02 + d.y * d.y * 0.012) / c
            };
            let masking = 1.0 + smith_lambda(v.z, sigma2(v)) + smith_lambda(l.z, sigma2(l));
            let gaussian = (-0.5 * (zx * zx / 0.02 + zy * zy / 0.012)).exp() / (2.0 * PI * (0.02f64 * 0.012).sqrt());
            assert_relative_eq!(p * masking, gaussian, max_relative = 1e-9);
        }
    }

    /// At [`SMITH_NEGLIGIBLE_NU`] the closed form is already below the bound that makes `1 + Λ`
    /// round to 1, so returning 0 from there on changes no sum `1 + Λ + …`.
    #[test]
    fn smith_lambda_is_negligible_where_it_is_cut() {
        // ν = μ/√(2σ²(1 − μ²)) with σ² = ½: μ = ν/√(1 + ν²).
        let at = |nu: f64| smith_lambda(nu / (1.0 + nu * nu).sqrt(), 0.5);
        /// `e^{−ν²}/(4ν³√π)` at ν = 6 (the bound of the constant's documentation).
        const BOUND_AT_6: f64 = 1.6e-19;
        let below = SMITH_NEGLIGIBLE_NU * (1.0 - 1e-9);
        let closed = at(below);
        assert!((0.0..=BOUND_AT_6).contains(&closed), "Λ(6⁻) = {closed:e}");
        assert_eq!((1.0 + closed).to_bits(), 1.0f64.to_bits());
        assert_eq!(at(SMITH_NEGLIGIBLE_NU).to_bits(), 0.0f64.to_bits());
        // The bound itself, from the asymptotic series.
        let nu: f64 = SMITH_NEGLIGIBLE_NU;
        assert!((-nu * nu).exp() / (4.0 * nu.powi(3) * PI.sqrt()) <= BOUND_AT_6);
        // Well below the cut, the closed form is untouched: Λ(1) = (e⁻¹ − √π erfc 1)/(2√π) =
        // 0.025127 (evaluated with Python's `math.erfc`).
        assert_relative_eq!(at(1.0), 0.025_127, max_relative = ORACLE);
    }

    #[test]
    fn smith_lambda_oracles() {
        assert_relative_eq!(smith_lambda(0.3, 0.05), 2.5705e-2, max_relative = ORACLE);
        assert_relative_eq!(smith_lambda(0.1, 0.1), 0.81811, max_relative = ORACLE);
    }

    #[test]
    fn mean_fresnel_oracle() {
        assert_relative_eq!(mean_fresnel(0.5, 0.1), 0.06037, max_relative = ORACLE);
    }

    #[test]
    fn brdf_is_reciprocal() {
        let var = SlopeVariance::new(0.02, 0.01).unwrap();
        let v = DVec3::new(0.3, -0.2, 0.7).normalize();
        let l = DVec3::new(-0.5, 0.1, 0.4).normalize();
        /// The formula is symmetric in `v`, `l` up to the order of the sums `v + l`, `Λ(v) + Λ(l)`.
        const ROUNDING: f64 = 1e-12;
        assert_relative_eq!(ocean_brdf(v, l, &var, 1.333), ocean_brdf(l, v, &var, 1.333), max_relative = ROUNDING);
    }

    proptest::proptest! {
        /// The disc's glint computes the view's `Λ(v)` once, not per node: the same numbers as
        /// integrating [`ocean_brdf`] itself over the disc.
        #[test]
        fn the_disc_glint_integrates_the_brdf_itself(
            view in (-1.0f64..1.0, -1.0f64..1.0, 0.01f64..1.0), light in (-1.0f64..1.0, -1.0f64..1.0, -0.02f64..1.0),
            sx in 1e-5f64..0.1, sy in 1e-5f64..0.1, rings in 1usize..6,
        ) {
            let v = DVec3::new(view.0, view.1, view.2).normalize();
            let l = DVec3::new(light.0, light.1, light.2).normalize();
            let var = SlopeVariance::new(sx, sy).unwrap();
            let disc = SunDisc::with_rings(0.02, rings).unwrap();
            let direct = disc.integrate(l, rings, |d| ocean_brdf(v, d, &var, WATER_IOR) * d.z.max(0.0));
            let glint = reflected_disc_radiance(v, l, &var, disc.solid_angle(), &disc);
            proptest::prop_assert_eq!(glint.to_bits(), (disc.solid_angle() / disc.solid_angle() * direct).to_bits());
        }
    }
}
