//! The constants and small numeric helpers every Brine model crate shares, defined once.
//!
//! | symbol | Rust name | value | unit |
//! |---|---|---|---|
//! | `g` | [`G`] | 9.81 | m s⁻² |
//! | AU | [`AU_KM`] | 149 597 870.7 | km |
//!
//! ```
//! assert_eq!(brine_core::lattice_floor(-0.5), -1.0);
//! assert!((brine_core::G - 9.81).abs() < 1e-12);
//! ```

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
        write!(f, "{} = {} is out of range: expected {}", self.name, self.value, self.range)
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

    #[test]
    fn checks_name_the_parameter_and_refuse_non_finite_values() {
        assert_eq!(check("u10_m_s", 5.0, true, "[0, 60] m/s"), Ok(5.0));
        let e = check("u10_m_s", f64::NAN, true, "[0, 60] m/s").unwrap_err();
        assert_eq!(e.name, "u10_m_s");
        assert_eq!(
            check("u10_m_s", 70.0, false, "[0, 60] m/s").unwrap_err().to_string(),
            "u10_m_s = 70 is out of range: expected [0, 60] m/s"
        );
        assert_eq!(require(true, "t_max", f64::INFINITY, "(t_min, ∞] m"), Ok(f64::INFINITY));
        assert!(check("t_max", f64::INFINITY, true, "(t_min, ∞] m").is_err());
    }
}
