//! Spume: the large drops the wind tears from breaking crests, their source function, their fall
//! speed and the layer of haze they make over a windy sea.

use crate::error::{FoamError, check};
use crate::spray::{AIR_VISCOSITY, G, SEA_WATER_DENSITY};

/// Radius range `[15, 250)` µm (at 80 % relative humidity) of the spume branches of the source
/// function of Fairall, Kepert & Holland (1994). Below 15 µm the bubble-mediated drops of
/// Monahan et al. (1986) are used ([`crate::msd86_flux`]); above 250 µm the function is zero.
pub const SPUME_RADIUS_RANGE_UM: (f64, f64) = (15.0, 250.0);

/// Wind speed at which the shape of the Fairall et al. (1994) function was given (m s⁻¹).
pub const F94_REFERENCE_WIND_M_S: f64 = 11.0;

/// Exponent of the whitecap law of Monahan & Ó Muircheartaigh (1980), `W ∝ U₁₀^3.41`, which
/// scales the spume flux from 11 m s⁻¹ to any wind.
pub const MONAHAN_1980_EXPONENT: f64 = 3.41;

/// Density of air `ρ_a` (kg m⁻³) near 15 °C at sea level, for the drops' Reynolds number.
pub const AIR_DENSITY: f64 = 1.225;

/// Von Kármán's constant `κ`.
pub const VON_KARMAN: f64 = 0.4;

/// Spume source function: drops torn from the crests per square metre of sea, per second, per
/// micrometre of radius.
///
/// `dF/dr₈₀ = (U₁₀/11)^3.41 f(r₈₀)`, with at 11 m s⁻¹
/// - `f = 1.02×10⁴ r⁻¹` for 15 ≤ r < 37.5 µm,
/// - `f = 6.95×10⁶ r^−2.8` for 37.5 ≤ r < 100 µm,
/// - `f = 1.75×10¹⁷ r⁻⁸` for 100 ≤ r < 250 µm,
/// - 0 from 250 µm.
///
/// The branches join continuously (within 0.3 %) and the first continues the polynomial that the
/// same function uses below 15 µm, where Brine takes Monahan et al. (1986) instead. The wind factor
/// is the ratio of the whitecap coverages of Monahan & Ó Muircheartaigh (1980), `W(U₁₀)/W(11)`:
/// the spume comes from the breaking crests.
///
/// # Arguments
/// - `r80_um`: drop radius at 80 % relative humidity `r₈₀` (µm), `> 0`; 0 outside
///   [`SPUME_RADIUS_RANGE_UM`].
/// - `u10`: wind speed at 10 m `U₁₀` (m s⁻¹), `[0, 60]`.
///
/// # Returns
/// `dF/dr₈₀` (drops m⁻² s⁻¹ µm⁻¹), `≥ 0`.
///
/// # References
/// Fairall C. W., Kepert J. D., Holland G. J. 1994, "The effect of sea spray on surface energy
/// transports over the ocean", Global Atmos. Ocean Syst. 2:121–142 (the function, whose shape at
/// 11 m s⁻¹ is Andreas 1992's); Andreas E. L. 2002, "A review of the sea spray generation
/// function for the open ocean", in *Atmosphere–Ocean Interactions* 1, WIT Press, 1–46; Mueller
/// J. A., Veron F. 2014, "Impact of sea spray on air–sea fluxes. Part I", JPO 44:2817–2834,
/// Eq. 20–24; Monahan & Ó Muircheartaigh 1980 (the wind factor).
pub fn f94_spume_flux(r80_um: f64, u10: f64) -> f64 {
    debug_assert!(r80_um > 0.0 && (0.0..=60.0).contains(&u10), "r = {r80_um} µm, U10 = {u10} m/s");
    let shape = if !(SPUME_RADIUS_RANGE_UM.0..SPUME_RADIUS_RANGE_UM.1).contains(&r80_um) {
        return 0.0;
    } else if r80_um < 37.5 {
        1.02e4 / r80_um
    } else if r80_um < 100.0 {
        6.95e6 * libm::pow(r80_um, -2.8)
    } else {
        1.75e17 * libm::pow(r80_um, -8.0)
    };
    libm::pow(u10 / F94_REFERENCE_WIND_M_S, MONAHAN_1980_EXPONENT) * shape
}

/// Terminal fall speed of a water drop in still air, Stokes' law corrected for the drag of a
/// sphere at drop Reynolds numbers up to a few hundred.
///
/// `v = v_s / (1 + 0.15 Re^0.687)`, `Re = 2 r v ρ_a/μ_a`, `v_s = 2 ρ_w g r²/(9 μ_a)`, solved by
/// fixed-point iteration (to 10⁻¹² relative).
///
/// # Arguments
/// - `r_um`: drop radius `r` (µm), `(0, 500]`; the drag law holds for `Re < 800` and the drop
///   stays nearly spherical below ~500 µm.
///
/// # Returns
/// `v` (m s⁻¹): 0.27 m s⁻¹ at 50 µm, 0.72 m s⁻¹ at 100 µm; Stokes' `v_s` for small drops.
///
/// # References
/// Schiller L., Naumann A. 1933, "Über die grundlegenden Berechnungen bei der
/// Schwerkraftaufbereitung", Z. Ver. Dtsch. Ing. 77:318–320 (the drag correlation); Clift R.,
/// Grace J., Weber M. 1978, *Bubbles, drops and particles*, Academic Press, Table 5.2; measured:
/// Gunn R., Kinzer G. 1949, "The terminal velocity of fall for water droplets in stagnant air",
/// J. Meteor. 6:243–248.
pub fn terminal_velocity(r_um: f64) -> f64 {
    debug_assert!(r_um > 0.0 && r_um <= 500.0, "r = {r_um} µm");
    let r = r_um * 1e-6;
    let stokes = 2.0 * SEA_WATER_DENSITY * G * r * r / (9.0 * AIR_VISCOSITY);
    let mut v = stokes;
    for _ in 0..200 {
        let re = 2.0 * r * v * AIR_DENSITY / AIR_VISCOSITY;
        let next = stokes / (1.0 + 0.15 * libm::pow(re, 0.687));
        // Average with the last iterate: the plain iteration oscillates for large drops.
        let next = 0.5 * (v + next);
        if (next - v).abs() <= 1e-12 * next {
            return next;
        }
        v = next;
    }
    v
}

/// Parameters of the spume layer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpumeParams {
    /// Wind speed at 10 m `U₁₀` (m s⁻¹), `[0, 60]`.
    pub u10: f64,
    /// Friction velocity of the wind over the sea `u*` (m s⁻¹), `(0, 5]`.
    pub friction_velocity_m_s: f64,
    /// Height at which the drops are torn off `z_s` (m), `(0, 30]`: the significant wave
    /// amplitude `A_1/3 = H_s/2` (Andreas 1992).
    pub source_height_m: f64,
}

/// Number of radius classes of the layer (log-spaced over [`SPUME_RADIUS_RANGE_UM`]).
pub const SPUME_CLASSES: usize = 12;

/// Simpson panels per class for its extinction (the integrand is smooth within a class: the
/// flux's kinks fall on class edges or change the integral by < 10⁻⁴).
const PANELS_PER_CLASS: usize = 32;

/// One radius class of the layer: its sea-level extinction and its scale height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpumeClass {
    /// Geometric-mean radius of the class `r₈₀` (µm).
    pub radius_um: f64,
    /// Extinction of the class at the sea `k_i(0)` (m⁻¹).
    pub extinction_0: f64,
    /// Scale height of the class `H_i = κ u* z_s / v(r_i)` (m).
    pub scale_height_m: f64,
}

/// The haze of spume drops over the sea.
///
/// - Concentration at the sea: production over the effective production velocity, `n(r, 0) =
///   (dF/dr)/V_eff` (m⁻³ µm⁻¹), with [`f94_spume_flux`] and `V_eff` the wind at the significant
///   wave amplitude ([`production_velocity`]): the relation by which the function's shape was
///   obtained from measured concentrations.
/// - Vertical profile: turbulence with the eddy diffusivity of the surface layer `K = κ u* z`,
///   held at its value at the source height `z_s`, against settling: `n(r, z) = n(r, 0)
///   e^{−z/H(r)}`, `H(r) = κ u* z_s / v(r)` — the steady solution of `K dn/dz + v n = 0`.
///   Drops of 15 µm rise tens of metres, drops of 200 µm stay within a metre or two of the crests.
/// - Extinction: `k(z) = Σᵢ kᵢ(0) e^{−z/Hᵢ}` over [`SPUME_CLASSES`] log-spaced radius classes,
///   `kᵢ(0) = ∫_class Q_e π r² n(r, 0) dr` with `Q_e = 2` (drops much larger than the wavelength).
///
/// The drops' cross-section is taken at `r₈₀`; near the sea they are about twice as large
/// (they have not dried to 80 % humidity), so the haze is, if anything, underestimated by that.
/// Balancing production by settling alone, `n = (dF/dr)/v(r)`, would give 10 to 700 times more
/// drops: the upper bound any removal allows, which Fairall et al. (2009) found in a wind tunnel;
/// over the open sea Andreas et al. (2010) found the wind-speed scale instead.
///
/// # References
/// Fairall, Kepert & Holland 1994 (source, [`f94_spume_flux`]); Andreas et al. 2010 (production
/// velocity, [`production_velocity`]); Fairall C. W., Larsen S. E. 1984,
/// "Dry deposition, surface production and dynamics of aerosols in the marine boundary layer",
/// Atmos. Environ. 18:69–77 (production against settling in the surface layer); Fairall C. W.,
/// Banner M., Peirson W., Asher W., Morison R. 2009, JGR 114, C10001 (the balance observed);
/// Andreas E. L. 1992, "Sea spray and the turbulent air–sea heat fluxes", JGR 97:11429–11441
/// (drops produced at the significant wave amplitude).
#[derive(Debug, Clone, PartialEq)]
pub struct SpumeLayer {
    params: SpumeParams,
    classes: [SpumeClass; SPUME_CLASSES],
    /// Per class, the constants of the per-ray formulas.
    terms: [ClassTerms; SPUME_CLASSES],
}

/// The constants of one class that every ray uses.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ClassTerms {
    /// `kᵢ(0)` (m⁻¹).
    k0: f64,
    /// `1/Hᵢ` (m⁻¹).
    inv_h: f64,
    /// `kᵢ(0) Hᵢ`, the class's vertical optical depth.
    k0_h: f64,
    /// `kᵢ(0) √(π R Hᵢ/2)`, its optical depth along the horizon from the sea.
    k0_chapman: f64,
    /// `√(R/(2Hᵢ))`.
    a_per_dy: f64,
}

impl SpumeLayer {
    /// The spume of a wind over a sea: checks the parameters and integrates each class once.
    ///
    /// # Arguments
    /// - `params`: [`SpumeParams`] — `u10` (m s⁻¹, `[0, 60]`), `friction_velocity_m_s` (m s⁻¹,
    ///   `(0, 5]`), `source_height_m` (m, `(0, 30]`).
    ///
    /// # Returns
    /// The layer, every class's `kᵢ(0)` (m⁻¹, 0 at `U₁₀ = 0`) and `Hᵢ` (m) precomputed.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the first parameter outside its range.
    ///
    /// # References
    /// See [`SpumeLayer`].
    pub fn new(params: &SpumeParams) -> Result<Self, FoamError> {
        let p = *params;
        check("u10_m_s", p.u10, (0.0..=60.0).contains(&p.u10), "[0, 60] m/s")?;
        let u_star = p.friction_velocity_m_s;
        check("friction_velocity_m_s", u_star, u_star > 0.0 && u_star <= 5.0, "(0, 5] m/s")?;
        let z_s = p.source_height_m;
        check("source_height_m", z_s, z_s > 0.0 && z_s <= 30.0, "(0, 30] m")?;
        let diffusivity = VON_KARMAN * u_star * z_s;
        let v_eff = production_velocity(p.u10, u_star, z_s);
        let (a, b) = (libm::log(SPUME_RADIUS_RANGE_UM.0), libm::log(SPUME_RADIUS_RANGE_UM.1));
        let width = (b - a) / SPUME_CLASSES as f64;
        let classes = std::array::from_fn(|i| {
            let lo = a + i as f64 * width;
            let radius_um = libm::exp(lo + 0.5 * width);
            SpumeClass {
                radius_um,
                extinction_0: class_extinction(p.u10, v_eff, lo, lo + width),
                scale_height_m: diffusivity / terminal_velocity(radius_um),
            }
        });
        let r = brine_core::EARTH_RADIUS_M;
        let terms = classes.map(|c| ClassTerms {
            k0: c.extinction_0,
            inv_h: 1.0 / c.scale_height_m,
            k0_h: c.extinction_0 * c.scale_height_m,
            k0_chapman: c.extinction_0 * libm::sqrt(std::f64::consts::PI * r * c.scale_height_m / 2.0),
            a_per_dy: libm::sqrt(r / (2.0 * c.scale_height_m)),
        });
        Ok(Self { params: p, classes, terms })
    }

    /// The parameters.
    pub fn params(&self) -> &SpumeParams {
        &self.params
    }

    /// The production velocity `V_eff = U(A_⅓)` (m s⁻¹): see [`production_velocity`].
    pub fn production_velocity(&self) -> f64 {
        production_velocity(self.params.u10, self.params.friction_velocity_m_s, self.params.source_height_m)
    }

    /// The radius classes, smallest drops first.
    pub fn classes(&self) -> &[SpumeClass; SPUME_CLASSES] {
        &self.classes
    }

    /// Extinction coefficient at a height, `k(z) = Σᵢ kᵢ(0) e^{−z/Hᵢ}` (0 below the sea).
    ///
    /// # Arguments
    /// - `z`: height above the sea (m).
    ///
    /// # Returns
    /// `k` (m⁻¹), `≥ 0`.
    ///
    /// # References
    /// See [`SpumeLayer`].
    pub fn extinction(&self, z: f64) -> f64 {
        if z < 0.0 {
            return 0.0;
        }
        self.terms.iter().map(|c| c.k0 * libm::exp(-z * c.inv_h)).sum()
    }

    /// Meteorological visibility at a height, `V = ln(50)/k(z)` (the distance at which a black
    /// object's contrast against the horizon sky falls to 2 %; Koschmieder 1924).
    ///
    /// # Arguments
    /// - `z`: height above the sea (m), `≥ 0`.
    ///
    /// # Returns
    /// `V` (m), infinite without spume.
    ///
    /// # References
    /// Koschmieder H. 1924, Beitr. Phys. freien Atmos. 12:33–53; WMO 2018, *Guide to
    /// instruments and methods of observation*, Vol. I, §9.1 (the 2 % threshold).
    pub fn visibility_m(&self, z: f64) -> f64 {
        let k = self.extinction(z);
        if k > 0.0 { libm::log(50.0) / k } else { f64::INFINITY }
    }

    /// Optical depth of the layer above a height, `Σᵢ kᵢ(0) Hᵢ e^{−z/Hᵢ}` (the whole column for
    /// `z ≤ 0`).
    ///
    /// # Arguments
    /// - `z`: height above the sea (m).
    ///
    /// # Returns
    /// The vertical optical depth (dimensionless, `≥ 0`).
    ///
    /// # References
    /// See [`SpumeLayer`].
    pub fn optical_depth_above(&self, z: f64) -> f64 {
        let z = z.max(0.0);
        self.terms.iter().map(|c| c.k0_h * libm::exp(-z * c.inv_h)).sum()
    }

    /// Optical depth of a straight segment from height `z0` to `z1` of length `length_m`,
    /// `∫ k ds`, exact for the layer's exponentials (the part below the sea counts nothing).
    ///
    /// # Arguments
    /// - `z0`, `z1`: heights above the sea of the segment's ends (m), finite.
    /// - `length_m`: the segment length (m), `≥ |z1 − z0|`.
    ///
    /// # Returns
    /// The optical depth (dimensionless, `≥ 0`).
    ///
    /// # References
    /// Beer–Lambert law; see [`SpumeLayer`].
    pub fn segment_optical_depth(&self, z0: f64, z1: f64, length_m: f64) -> f64 {
        debug_assert!(length_m >= 0.0 && z0.is_finite() && z1.is_finite());
        if length_m <= 0.0 {
            return 0.0;
        }
        let dz = z1 - z0;
        if dz.abs() <= 1e-9 * length_m.max(1.0) {
            return length_m * self.extinction(0.5 * (z0 + z1));
        }
        let (lo, hi) = (z0.min(z1).max(0.0), z0.max(z1));
        if hi <= lo {
            return 0.0;
        }
        (length_m / dz.abs()) * (self.optical_depth_above(lo) - self.optical_depth_above(hi))
    }

    /// Optical depth from a point at height `y0` out to space along a ray climbing at
    /// `sin e = d_y ≥ 0` over the curved Earth, whose height grows as `z(s) = y0 + s d_y +
    /// s²/(2R)`.
    ///
    /// `τ = Σᵢ kᵢ(0) e^{−y0/Hᵢ} √(π R Hᵢ/2) · erfcx(d_y √(R/(2Hᵢ)))`, `erfcx(a) = e^{a²} erfc(a)`:
    /// `Hᵢ/d_y` for a ray well above the horizon, `√(π R Hᵢ/2)` (16 km for `H` = 25 m) along it.
    ///
    /// # Arguments
    /// - `y0`: height of the start above the sea (m), `≥ 0`.
    /// - `d_y`: sine of the ray's elevation, `[0, 1]`.
    ///
    /// # Returns
    /// The optical depth (dimensionless, `≥ 0`).
    ///
    /// # References
    /// The Chapman integral of an exponential atmosphere in its parabolic (flat-Earth plus
    /// curvature) approximation, e.g. Chapman S. 1931, Proc. Phys. Soc. 43:483–501; see
    /// [`SpumeLayer`].
    pub fn optical_depth_to_space(&self, y0: f64, d_y: f64) -> f64 {
        debug_assert!(y0 >= 0.0 && (0.0..=1.0).contains(&d_y));
        self.terms.iter().map(|c| c.k0_chapman * libm::exp(-y0 * c.inv_h) * erfcx(d_y * c.a_per_dy)).sum()
    }
}

/// The effective production velocity of spume, the wind at the significant wave amplitude,
/// `V_eff = U(z_s) = U₁₀ + (u*/κ) ln(z_s/10)` (the logarithmic profile through `U₁₀`), at least
/// `u*`.
///
/// The spume source function's shape is Andreas (1992)'s, which he obtained from drop
/// concentrations measured near the sea as `dF/dr = C(r) U_A⅓`; Andreas et al. (2010) found that
/// over the open sea the concentrations of 13 data sets and a reliable source function are related
/// by a velocity of that order for drops of 20–300 µm, and worst by the deposition velocity.
///
/// # Arguments
/// - `u10`: `U₁₀` (m s⁻¹), `≥ 0`; `u_star`: `u*` (m s⁻¹), `> 0`; `z_s`: `A_⅓` (m), `> 0`.
///
/// # Returns
/// `V_eff` (m s⁻¹): 20.5 m s⁻¹ at 22 m s⁻¹ (`u*` = 1.0 m s⁻¹, `z_s` = 5.4 m).
///
/// # References
/// Andreas E. L. 1992, JGR 97:11429–11441; Andreas E. L., Jones K. F., Fairall C. W. 2010,
/// "Production velocity of sea spray droplets", JGR 115, C12065.
pub fn production_velocity(u10: f64, u_star: f64, z_s: f64) -> f64 {
    debug_assert!(u10 >= 0.0 && u_star > 0.0 && z_s > 0.0);
    (u10 + u_star / VON_KARMAN * libm::log(z_s / 10.0)).max(u_star)
}

/// The scaled complementary error function `erfcx(a) = e^{a²} erfc(a)`, `a ≥ 0`: `libm::erfc`
/// below 5, the asymptotic series `(1 − 1/(2a²) + 3/(4a⁴) − 15/(8a⁶) + 105/(16a⁸))/(a √π)`
/// above (its next term, `945/(32a¹⁰)`, is 3×10⁻⁶ of the leading one at 5).
fn erfcx(a: f64) -> f64 {
    debug_assert!(a >= 0.0);
    if a < 5.0 {
        libm::exp(a * a) * libm::erfc(a)
    } else {
        let x = 1.0 / (a * a);
        (1.0 - 0.5 * x + 0.75 * x * x - 1.875 * x * x * x + 6.5625 * x * x * x * x) / (a * std::f64::consts::PI.sqrt())
    }
}

/// `∫ Q_e π r² n(r, 0) dr` over one class `[e^lo, e^hi]` µm, `Q_e = 2`, by Simpson's rule in
/// `ln r`, with `n(r, 0) = (dF/dr)/V_eff`.
fn class_extinction(u10: f64, production_velocity: f64, lo: f64, hi: f64) -> f64 {
    let h = (hi - lo) / PANELS_PER_CLASS as f64;
    let f = |lr: f64| {
        let r = libm::exp(lr);
        // Just inside the class so the closing edge at 250 µm reads the last branch.
        let r = r.clamp(SPUME_RADIUS_RANGE_UM.0, SPUME_RADIUS_RANGE_UM.1 * (1.0 - 1e-12));
        let r_m = r * 1e-6;
        // dr = r d(ln r).
        2.0 * std::f64::consts::PI * r_m * r_m * f94_spume_flux(r, u10) / production_velocity * r
    };
    let mut s = f(lo) + f(hi);
    for i in 1..PANELS_PER_CLASS {
        s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(lo + i as f64 * h);
    }
    s * h / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The printed coefficients have three significant digits: adjacent branches meet within
    /// half a unit of the third digit of each, 0.1 % + 0.1 % plus rounding: 0.3 %.
    const BRANCH_JOIN_REL: f64 = 3e-3;

    /// Gunn & Kinzer's table gives speeds to 1 cm s⁻¹ (of 27–206 cm s⁻¹, ≤ 4 % at the smallest)
    /// and the drag correlation itself is good to about 5 % below Re ≈ 800 (Clift et al.): 6 %.
    const GUNN_KINZER_REL: f64 = 0.06;

    /// Simpson on the brute-force path and exact exponentials: 10⁻⁴ relative.
    const PATH_REL: f64 = 1e-4;

    fn layer(u10: f64) -> SpumeLayer {
        SpumeLayer::new(&SpumeParams { u10, friction_velocity_m_s: 0.9, source_height_m: 5.0 }).unwrap()
    }

    #[test]
    #[allow(clippy::float_cmp)]
    fn the_branches_join() {
        for (r, below, above) in [
            // 15 µm: the polynomial part of F94 (outside the spume range) gives 10^2.835 = 684.
            (37.5, 1.02e4 / 37.5, 6.95e6 * 37.5f64.powf(-2.8)),
            (100.0, 6.95e6 * 100f64.powf(-2.8), 1.75e17 * 100f64.powf(-8.0)),
        ] {
            assert!((below / above - 1.0).abs() < BRANCH_JOIN_REL, "{r}: {below} vs {above}");
            let just_above = f94_spume_flux(r, 11.0);
            assert!((just_above / above - 1.0).abs() < 1e-12, "{r}");
        }
        // The published value at 11 m/s: 1.02e4/20 = 510 drops m⁻² s⁻¹ µm⁻¹ at 20 µm.
        assert!((f94_spume_flux(20.0, 11.0) - 510.0).abs() < 1e-9);
        // Outside the spume range the function is exactly zero.
        assert!(f94_spume_flux(14.9, 30.0) == 0.0 && f94_spume_flux(250.0, 30.0) == 0.0);
    }

    #[test]
    fn the_flux_follows_the_whitecap_law() {
        let ratio = f94_spume_flux(50.0, 22.0) / f94_spume_flux(50.0, 11.0);
        assert!((ratio - 2f64.powf(3.41)).abs() < 1e-12);
    }

    #[test]
    fn fall_speeds_match_gunn_and_kinzer() {
        // Gunn & Kinzer 1949, Table 2: diameters 0.1–0.5 mm fall at 27, 72, 117, 162, 206 cm/s.
        for (d_mm, v_cm_s) in [(0.1, 27.0), (0.2, 72.0), (0.3, 117.0), (0.4, 162.0), (0.5, 206.0)] {
            let v = terminal_velocity(d_mm * 500.0) * 100.0;
            assert!((v / v_cm_s - 1.0).abs() < GUNN_KINZER_REL, "{d_mm} mm: {v} cm/s against {v_cm_s}");
        }
        // Small drops: Stokes' law. At 1 µm, Re = 1.7×10⁻⁵ and the drag correction
        // 0.15 Re^0.687 is 8×10⁻⁵.
        let s = crate::stokes_settling_velocity(1.0);
        assert!((terminal_velocity(1.0) / s - 1.0).abs() < 2e-4);
    }

    #[test]
    fn a_segment_matches_the_brute_force_sum() {
        let l = layer(22.0);
        for &(z0, z1, len) in &[(10.0, 0.0, 3000.0), (0.5, 4.0, 50.0), (3.0, 3.0, 800.0), (2.0, -1.0, 30.0)] {
            let n = 200_000;
            let brute: f64 =
                (0..n).map(|i| l.extinction(z0 + (i as f64 + 0.5) / n as f64 * (z1 - z0)) * len / n as f64).sum();
            let exact = l.segment_optical_depth(z0, z1, len);
            assert!((exact - brute).abs() <= PATH_REL * brute, "{z0} {z1}: {exact} vs {brute}");
        }
    }

    #[test]
    fn the_path_to_space_matches_the_brute_force_sum() {
        let l = layer(22.0);
        let r = brine_core::EARTH_RADIUS_M;
        for &(y0, dy) in &[(10.0, 0.0), (3.0, 0.002), (10.0, 0.05), (1.0, 0.6)] {
            // Midpoint rule in s out to where the heights leave the layer (z > 40 H).
            let (n, s_max) = (2_000_000, 200_000.0);
            let ds = s_max / n as f64;
            let brute: f64 = (0..n)
                .map(|i| {
                    let s = (i as f64 + 0.5) * ds;
                    l.extinction(y0 + s * dy + s * s / (2.0 * r)) * ds
                })
                .sum();
            let exact = l.optical_depth_to_space(y0, dy);
            assert!((exact - brute).abs() <= PATH_REL * brute, "{y0} {dy}: {exact} vs {brute}");
        }
    }

    #[test]
    fn the_production_velocity_is_the_wind_at_the_wave_amplitude() {
        // The log profile through U10: U(10 m) = U10; U(5.43 m) = 22 + (1/0.4) ln 0.543.
        assert!((production_velocity(22.0, 1.0, 10.0) - 22.0).abs() < 1e-12);
        assert!((production_velocity(22.0, 1.0, 5.43) - (22.0 + 2.5 * 0.543f64.ln())).abs() < 1e-12);
        // Never below u*.
        assert!((production_velocity(0.5, 0.3, 0.01) - 0.3).abs() < 1e-15);
        // The layer's concentration is the flux over it.
        let l = layer(22.0);
        assert!((l.production_velocity() - production_velocity(22.0, 0.9, 5.0)).abs() < 1e-15);
    }

    /// The midpoint rule on 10⁶ cells in r against the class sums (Simpson on 32 panels per class,
    /// the branch kinks at 37.5 and 100 µm inside classes): 10⁻³ relative bounds both.
    const CLASS_SUM_REL: f64 = 1e-3;

    #[test]
    fn the_sea_level_extinction_is_the_written_out_integral() {
        // k(0) = ∫ 2π r² (dF/dr)/V_eff dr over 15–250 µm, with Fairall et al.'s coefficients and
        // the wind at the wave amplitude written out here, independently of the crate's code.
        let (u10, u_star, z_s) = (22.0, 0.9, 5.0);
        let v_eff = u10 + u_star / 0.4 * (z_s / 10.0f64).ln();
        let f = |r: f64| {
            let shape = if r < 37.5 {
                1.02e4 / r
            } else if r < 100.0 {
                6.95e6 * r.powf(-2.8)
            } else {
                1.75e17 * r.powf(-8.0)
            };
            (u10 / 11.0f64).powf(3.41) * shape
        };
        let n = 1_000_000;
        let dr = (250.0 - 15.0) / n as f64;
        let brute: f64 = (0..n)
            .map(|i| {
                let r = 15.0 + (i as f64 + 0.5) * dr;
                2.0 * std::f64::consts::PI * (r * 1e-6) * (r * 1e-6) * f(r) / v_eff * dr
            })
            .sum();
        let l = layer(u10);
        let k0 = l.extinction(0.0);
        assert!((k0 / brute - 1.0).abs() < CLASS_SUM_REL, "{k0} against {brute}");
    }

    #[test]
    fn erfcx_is_continuous_at_the_switch() {
        let (below, above) = (erfcx(5.0 - 1e-9), erfcx(5.0 + 1e-9));
        assert!((below / above - 1.0).abs() < 1e-5, "{below} vs {above}");
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = SpumeLayer::new(&SpumeParams { u10: 10.0, friction_velocity_m_s: 0.0, source_height_m: 1.0 });
        assert!(format!("{}", e.unwrap_err()).contains("friction_velocity_m_s"));
        let e = SpumeLayer::new(&SpumeParams { u10: 10.0, friction_velocity_m_s: 0.4, source_height_m: f64::NAN });
        assert!(format!("{}", e.unwrap_err()).contains("source_height_m"));
    }
}
