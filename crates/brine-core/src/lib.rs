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
}
