//! The constants and small numeric helpers every Brine model crate shares, defined once, and the
//! pixel footprint on the sea ([`footprint`]: the fading of components smaller than it, and the
//! elliptical footprint of a pixel seen at a slant, read as a row of round reads).
//!
//! | symbol | Rust name | value | unit |
//! |---|---|---|---|
//! | `g` | [`G`] | 9.81 | m s⁻² |
//! | AU | [`AU_KM`] | 149 597 870.7 | km |
//! | `R` | [`EARTH_RADIUS_M`] | 6 371 000 | m |
//!
//! ```
//! assert_eq!(brine_core::lattice_floor(-0.5), -1.0);
//! assert!((brine_core::G - 9.81).abs() < 1e-12);
//! ```

pub mod footprint;

/// Standard gravity `g` (m s⁻²) as the wave models use it (the papers' 9.81; the CGPM's
/// conventional value is 9.806 65).
///
/// # References
/// Tessendorf 2001 and the spectra of `docs/equations.md` §4 (all written with `g = 9.81`).
pub const G: f64 = 9.81;

/// The astronomical unit (km), exact by definition.
///
/// # References
/// IAU 2012 Resolution B2.
pub const AU_KM: f64 = 149_597_870.7;

/// Mean radius of the Earth `R` (m), rounded to the kilometre (the IUGG mean radius is
/// 6 371 008.8 m): the curvature of the sea and of the atmosphere's shells.
///
/// # References
/// Moritz H. 2000, "Geodetic Reference System 1980", J. Geodesy 74:128–133 (`R₁ = 6 371 008.8 m`).
pub const EARTH_RADIUS_M: f64 = 6_371_000.0;

/// Distance along a ray from a height `h` above the mean sea to the curved mean sea: the sphere
/// of radius `R` ([`EARTH_RADIUS_M`]) under the eye.
///
/// `t = (2Rh + h²)/(−d_y (R + h) + √(d_y²(R + h)² − 2Rh − h²))`, the nearer root of
/// `|(0, R + h, 0) + t d̂|² = R²` written without the cancellation of the usual form; no root
/// (`None`) above the dip of the horizon, `d_y > −√(2Rh + h²)/(R + h)` (a dip of `√(2h/R)`:
/// 0.10° from 10 m).
///
/// # Arguments
/// - `height_m`: `h`, the eye above the mean sea (m), `≥ 0` (0 is read as 1 cm).
/// - `direction_y`: `d_y`, the vertical component of the unit ray direction, `[−1, 1]`.
///
/// # Returns
/// `t` (m), or `None` where the ray passes above the horizon.
///
/// # References
/// The ray–sphere intersection (e.g. Pharr, Jakob & Humphreys, *Physically Based Rendering*,
/// 4th ed., §6.2.2, and its stable quadratic of §B.1.1); the geometric dip of the horizon
/// `√(2h/R)` (without refraction).
pub fn mean_sea_distance(height_m: f64, direction_y: f64) -> Option<f64> {
    let h = height_m.max(0.01);
    let c = h * (2.0 * EARTH_RADIUS_M + h);
    let b = -direction_y * (EARTH_RADIUS_M + h);
    if direction_y >= 0.0 || b * b < c {
        return None;
    }
    Some(c / (b + (b * b - c).sqrt()))
}

/// Upward unit normal of the curved mean sea at the point `t` along a ray of direction `d̂` from
/// a height `h` ([`mean_sea_distance`]): `(t dₓ, R + h + t d_y, t d_z)/R`, tilted from the
/// vertical under the eye by the angle `ρ/R` of the horizontal distance `ρ` (1.6 mrad at 10 km).
///
/// # Arguments
/// - `height_m`: `h` (m), as in [`mean_sea_distance`]; `direction`: the unit ray direction
///   `(dₓ, d_y, d_z)`; `t`: the distance (m), `≥ 0`.
///
/// # Returns
/// The unit normal `(x, y, z)`.
pub fn mean_sea_normal(height_m: f64, direction: [f64; 3], t: f64) -> [f64; 3] {
    let h = height_m.max(0.01);
    let n = [t * direction[0], EARTH_RADIUS_M + h + t * direction[1], t * direction[2]];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    n.map(|v| v / len)
}

/// `⌊x⌋` by truncation, for noise lattices: equal to `f64::floor` for `|x| < 2⁶³` (lattice
/// coordinates are far smaller). On the x86-64 baseline (SSE2, no `roundsd`) `f64::floor` is a
/// library call, and this sits in per-pixel noise loops.
///
/// # Arguments
/// - `x`: any finite value below `2⁶³` in magnitude.
///
/// # Returns
/// `⌊x⌋`.
#[inline]
pub fn lattice_floor(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t > x { t - 1.0 } else { t }
}

/// A model parameter outside its documented domain: its name (as in the docs, with its unit
/// suffix), the offending value and the accepted range in words, with the unit. Every model
/// crate's error type wraps it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutOfRange {
    /// Parameter name.
    pub name: &'static str,
    /// Offending value.
    pub value: f64,
    /// Accepted range, in words, with the unit.
    pub range: &'static str,
}

impl std::fmt::Display for OutOfRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Huge and tiny values with an exponent (`1e300`, not three hundred digits).
        let v = self.value;
        if v != 0.0 && v.is_finite() && !(1e-3..1e6).contains(&v.abs()) {
            write!(f, "{} = {v:e} is out of range: expected {}", self.name, self.range)
        } else {
            write!(f, "{} = {v} is out of range: expected {}", self.name, self.range)
        }
    }
}

impl std::error::Error for OutOfRange {}

/// `Ok(value)` if `ok` and `value` is finite, else the [`OutOfRange`] naming the parameter: the
/// one check every model constructor makes.
///
/// # Errors
/// [`OutOfRange`] with `name`, `value` and `range`.
#[inline]
pub fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, OutOfRange> {
    require(ok && value.is_finite(), name, value, range)
}

/// `Ok(value)` if `ok` (infinite values allowed, for ranges that include them), else the
/// [`OutOfRange`] naming the parameter.
///
/// # Errors
/// [`OutOfRange`] with `name`, `value` and `range`.
#[inline]
pub fn require(ok: bool, name: &'static str, value: f64, range: &'static str) -> Result<f64, OutOfRange> {
    if ok { Ok(value) } else { Err(OutOfRange { name, value, range }) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact equality is the claim (±0 compare equal).
    #[test]
    #[allow(clippy::float_cmp)]
    fn lattice_floor_is_floor() {
        for i in -2000..2000 {
            let x = f64::from(i) * 0.37 - 0.5;
            for v in [x, x.floor(), x.floor() - 1e-12, x.floor() + 1e-12, -0.0, 0.0] {
                assert_eq!(lattice_floor(v), v.floor(), "{v}");
            }
        }
        assert_eq!(lattice_floor(-1e15 - 0.5), (-1e15f64 - 0.5).floor());
    }

    /// Millimetres against metres to kilometres: the hit is on the sphere to float rounding of
    /// `R` (10⁻⁹ m), far below this.
    const ON_SPHERE_M: f64 = 1e-6;

    /// The curved sea's hit lies on the sphere, straight down it is `h` away, near the eye it is
    /// the flat sea's distance lowered by the drop `ρ²/2R` (the paraboloid, solved by fixed
    /// point), and rays stop meeting it at the geometric dip `√(2h/R)`: 0.1015° from 10 m.
    #[test]
    fn the_curved_sea_is_met_below_the_dip_of_the_horizon() {
        for h in [0.5, 2.0, 10.0, 100.0, 1000.0] {
            let dip = ((2.0 * EARTH_RADIUS_M * h + h * h).sqrt() / (EARTH_RADIUS_M + h)).asin();
            assert!(mean_sea_distance(h, -(dip * 0.999).sin()).is_none(), "h = {h}");
            let t_far = mean_sea_distance(h, -(dip * 1.001).sin()).expect("below the dip");
            assert!(t_far > 0.9 * (2.0 * EARTH_RADIUS_M * h).sqrt(), "h = {h}: {t_far}");
            assert!((mean_sea_distance(h, -1.0).unwrap() - h).abs() < 1e-9);
            for dy in [-0.9, -0.3, -0.05, -(dip * 1.5).sin(), -(dip * 1.001).sin()] {
                let t = mean_sea_distance(h, dy).unwrap();
                let dx = (1.0 - dy * dy).sqrt();
                let r = (t * t * dx * dx + (EARTH_RADIUS_M + h + t * dy).powi(2)).sqrt();
                assert!(
                    (r - EARTH_RADIUS_M).abs() < ON_SPHERE_M,
                    "h = {h}, d_y = {dy}: |p| − R = {}",
                    r - EARTH_RADIUS_M
                );
                let n = mean_sea_normal(h, [dx, dy, 0.0], t);
                // Tilted by the central angle, `ρ/R` to (h/R, ρ/R)-relative terms.
                let (tilt, rho_over_r) = (n[0].atan2(n[1]), t * dx / EARTH_RADIUS_M);
                assert!((tilt - rho_over_r).abs() <= 1e-3 * rho_over_r + 1e-15, "{tilt} vs {rho_over_r}");
            }
        }
        let dip_10m = (2.0 * 10.0 / EARTH_RADIUS_M).sqrt().to_degrees();
        assert!((dip_10m - 0.1015).abs() < 1e-4, "{dip_10m}");
        // Near the eye: h + t d_y = −ρ²/2R (the paraboloid, to (ρ/R)² relative), t = 1 km.
        let (h, dy) = (10.0, -0.01f64);
        let rho2 = |t: f64| t * t * (1.0 - dy * dy);
        let mut t = h / -dy;
        for _ in 0..20 {
            t = (h + rho2(t) / (2.0 * EARTH_RADIUS_M)) / -dy;
        }
        assert!((mean_sea_distance(h, dy).unwrap() - t).abs() < 1e-3, "{t}");
        assert!(mean_sea_distance(h, 0.0).is_none() && mean_sea_distance(h, 0.2).is_none());
    }

    #[test]
    fn checks_name_the_parameter_and_refuse_non_finite_values() {
        assert_eq!(check("u10_m_s", 5.0, true, "[0, 60] m/s"), Ok(5.0));
        let e = check("u10_m_s", f64::NAN, true, "[0, 60] m/s").unwrap_err();
        assert_eq!(e.name, "u10_m_s");
        assert_eq!(
            check("u10_m_s", 70.0, false, "[0, 60] m/s").unwrap_err().to_string(),
            "u10_m_s = 70 is out of range: expected [0, 60] m/s"
        );
        // Huge and tiny values with an exponent.
        assert_eq!(
            check("height_m", 1e300, false, "[-500, 9000] m").unwrap_err().to_string(),
            "height_m = 1e300 is out of range: expected [-500, 9000] m"
        );
        assert_eq!(
            check("sigma", 2.5e-300, false, "(0, 0.6]").unwrap_err().to_string(),
            "sigma = 2.5e-300 is out of range: expected (0, 0.6]"
        );
        assert_eq!(require(true, "t_max", f64::INFINITY, "(t_min, ∞] m"), Ok(f64::INFINITY));
        assert!(check("t_max", f64::INFINITY, true, "(t_min, ∞] m").is_err());
    }
}
