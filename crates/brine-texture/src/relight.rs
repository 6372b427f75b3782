//! Relighting by the main-structure height field (Lai & Wu Eq. 6–9).

/// Which form of the relighting factor to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RelightRule {
    /// Eq. 7–9 as printed, `ΔI = Δh · ((255 − I)/Δh_max)^{3/4}` (resp. `(I/Δh_max)^{3/4}`),
    /// then `I' = I + ΔI` clamped to `[0, 255]`: the printed factor keeps `I'` in range only when
    /// `Δh_max ≤ 255 − I` (resp. `≤ I`), so the clamp is needed.
    #[default]
    Paper,
    /// The docs/equations.md's bounded form, `I' = I + (255 − I)(Δh/Δh_max)^{3/4}` (`Δh ≥ 0`),
    /// `I' = I − I(|Δh|/Δh_max)^{3/4}` (`Δh < 0`): in range by construction, independent of
    /// the unit of the heights.
    Bounded,
}

/// `x^{3/4}` for `x ≥ 0`, as `√(x √x)` (two square roots, exact up to rounding): the exponent of
/// Eq. 9.
///
/// # Arguments
/// - `x`: `[0, ∞)`; negative values are treated as 0.
///
/// # Returns
/// `x^{3/4} ≥ 0`.
///
/// # References
/// Lai & Wu Eq. 9 (the exponent ¾).
#[inline]
pub fn pow_three_quarters(x: f64) -> f64 {
    let x = x.max(0.0);
    (x * x.sqrt()).sqrt()
}

/// The relit intensity `I' = I + ΔI` of Lai & Wu Eq. 6–9.
///
/// Paper form (Eq. 7–9): `ΔI = Δheight · dhfac`,
/// `dhfac = ((255 − I)/Δheight_max)^{3/4}` if `Δheight ≥ 0`, `(I/Δheight_max)^{3/4}` otherwise,
/// then `I'` clamped to `[0, 255]`. Bounded form: see [`RelightRule::Bounded`].
///
/// # Arguments
/// - `i`: intensity `I` (levels), `[0, 255]`; applied per colour channel.
/// - `delta_height`: `Δheight = M_h(x/scale, y/scale) − mean(M_h)` (Eq. 8), m.
/// - `delta_height_max`: `Δheight_max`, the largest `|Δheight|` of the field (m), `≥ 0`; `0`
///   leaves `I` unchanged.
/// - `rule`: which form.
///
/// # Returns
/// `I'` in `[0, 255]` for every finite input.
///
/// # References
/// Lai & Wu, "Ocean surface rendering using temporal texture synthesis", Eq. 6–9 (exponent ¾ set
/// experimentally by the authors); docs/equations.md §14 (range note and bounded form).
#[inline]
pub fn relight_intensity(i: f64, delta_height: f64, delta_height_max: f64, rule: RelightRule) -> f64 {
    if !(delta_height_max > 0.0) || !delta_height.is_finite() {
        return i.clamp(0.0, 255.0);
    }
    let i = i.clamp(0.0, 255.0);
    let room = if delta_height >= 0.0 { 255.0 - i } else { i };
    let out = match rule {
        RelightRule::Paper => i + delta_height * pow_three_quarters(room / delta_height_max),
        RelightRule::Bounded => {
            let r = pow_three_quarters((delta_height.abs() / delta_height_max).min(1.0));
            let out = if delta_height >= 0.0 { i + room * r } else { i - room * r };
            // `r ∈ [0, 1]` of the room left: the bounded form needs the clamp for rounding only.
            debug_assert!((-1e-9..=255.0 + 1e-9).contains(&out), "bounded relighting gave {out}");
            out
        }
    };
    out.clamp(0.0, 255.0)
}

/// The relighting of one texture by one height offset: the per-rule factors precomputed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Relighting {
    /// `Δheight_max` (m).
    pub delta_height_max: f64,
    /// The form of the factor.
    pub rule: RelightRule,
}

impl Relighting {
    /// Relights the three channels of a texel by `delta_height` ([`relight_intensity`] per
    /// channel, so every channel stays in `[0, 255]`).
    ///
    /// # Arguments
    /// - `rgb`: the texel (levels `[0, 255]`).
    /// - `delta_height`: `Δheight` of Eq. 8 (m).
    ///
    /// # Returns
    /// The relit texel, every channel in `[0, 255]`.
    ///
    /// # References
    /// Lai & Wu Eq. 6–9.
    #[inline]
    pub fn apply(&self, rgb: [f32; 3], delta_height: f64) -> [f32; 3] {
        rgb.map(|c| relight_intensity(f64::from(c), delta_height, self.delta_height_max, self.rule) as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// `√(x√x)` against `powf(x, 0.75)`: two correctly rounded square roots and a product
    /// (≤ 1.5 ulp) against `powf`'s ≤ 1 ulp — a few 10⁻¹⁶.
    const POW_REL: f64 = 1e-14;
    /// Eq. 9 evaluated by hand with `powf` and by the code with `√(x√x)`: the same, a few ulps.
    const BY_HAND_REL: f64 = 1e-12;

    #[test]
    fn three_quarters_power() {
        for x in [0.0, 1e-9, 0.3, 1.0, 7.5, 255.0] {
            assert_relative_eq!(pow_three_quarters(x), f64::powf(x, 0.75), max_relative = POW_REL);
        }
    }

    #[test]
    fn printed_factor_by_hand() {
        // I = 100, Δh = 0.5, Δh_max = 2: ΔI = 0.5 · (155/2)^{3/4} = 0.5 · 26.1.. = 13.07.
        let expected = 100.0 + 0.5 * (155.0f64 / 2.0).powf(0.75);
        assert_relative_eq!(
            relight_intensity(100.0, 0.5, 2.0, RelightRule::Paper),
            expected,
            max_relative = BY_HAND_REL
        );
        let expected = 100.0 - 0.5 * (100.0f64 / 2.0).powf(0.75);
        assert_relative_eq!(
            relight_intensity(100.0, -0.5, 2.0, RelightRule::Paper),
            expected,
            max_relative = BY_HAND_REL
        );
    }

    #[test]
    fn printed_factor_overshoots_without_the_clamp() {
        // Δh_max = 300 > 255 − I: the unclamped printed form exceeds 255.
        let unclamped = 250.0 + 300.0 * (5.0f64 / 300.0).powf(0.75);
        assert!(unclamped > 255.0);
        assert_relative_eq!(relight_intensity(250.0, 300.0, 300.0, RelightRule::Paper), 255.0);
    }

    #[test]
    fn bounded_form_reaches_the_ends_at_the_extreme_heights() {
        assert_relative_eq!(relight_intensity(80.0, 2.0, 2.0, RelightRule::Bounded), 255.0);
        assert_relative_eq!(relight_intensity(80.0, -2.0, 2.0, RelightRule::Bounded), 0.0);
        assert_relative_eq!(relight_intensity(80.0, 0.0, 2.0, RelightRule::Bounded), 80.0);
    }
}
