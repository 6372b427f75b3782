//! Refinement of a bracketed sign change.

/// Refines a bracketed crossing of `f` on `[a, b]` (where `f(a)` and `f(b)` have opposite signs,
/// or one of them is zero) until the bracket is no longer than `tolerance`.
///
/// Uses the Illinois variant of regula falsi (Dowell & Jarratt 1971), which keeps the bracket and
/// converges superlinearly on smooth functions; a bisection step is forced whenever an Illinois
/// step fails to halve the bracket, so at most `2·log₂((b − a)/tolerance) + 2` evaluations are
/// spent.
///
/// # Arguments
/// - `f`: the function along the ray, `t ↦ F(o + t d̂)`.
/// - `a`, `fa`, `b`, `fb`: bracket ends and their values, `a < b`, `fa·fb ≤ 0`.
/// - `tolerance`: bracket length at which to stop, `> 0` (same unit as `t`).
///
/// # Returns
/// `(t, evaluations)`: the midpoint of the final bracket (within `tolerance/2` of a crossing) and
/// the number of evaluations of `f` made.
pub fn refine_crossing(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    mut fa: f64,
    mut b: f64,
    mut fb: f64,
    tolerance: f64,
) -> (f64, u32) {
    debug_assert!(a <= b, "refine_crossing: a = {a} > b = {b}");
    debug_assert!(fa * fb <= 0.0, "refine_crossing: no sign change ({fa}, {fb})");
    debug_assert!(tolerance > 0.0);
    if fa == 0.0 {
        return (a, 0);
    }
    if fb == 0.0 {
        return (b, 0);
    }
    let mut evaluations = 0;
    // Which end was retained on the previous step (−1 left, +1 right, 0 none).
    let mut side = 0i8;
    let mut width = b - a;
    while b - a > tolerance && evaluations < 200 {
        let illinois = (a * fb - b * fa) / (fb - fa);
        // Fall back to bisection when the secant point is outside the open bracket or the last
        // step did not at least halve the bracket.
        let t = if illinois > a && illinois < b && (b - a) <= 0.5 * width + f64::EPSILON * b.abs() {
            illinois
        } else {
            0.5 * (a + b)
        };
        width = b - a;
        let ft = f(t);
        evaluations += 1;
        if ft == 0.0 {
            return (t, evaluations);
        }
        if (ft < 0.0) == (fa < 0.0) {
            a = t;
            fa = ft;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            b = t;
            fb = ft;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
    }
    (0.5 * (a + b), evaluations)
}

/// Refines a bracketed crossing of `f` on `[a, b]` by bisection until the bracket is no longer
/// than `tolerance`: `⌈log₂((b − a)/tolerance)⌉` evaluations (the refinement of brute-force
/// marching, Darles et al. 2007 §3.1).
///
/// # Arguments
/// As [`refine_crossing`].
///
/// # Returns
/// `(t, evaluations)`: the midpoint of the final bracket and the number of evaluations of `f`.
pub fn bisect_crossing(
    mut f: impl FnMut(f64) -> f64,
    mut a: f64,
    fa: f64,
    mut b: f64,
    fb: f64,
    tolerance: f64,
) -> (f64, u32) {
    debug_assert!(a <= b && fa * fb <= 0.0 && tolerance > 0.0);
    if fa == 0.0 {
        return (a, 0);
    }
    if fb == 0.0 {
        return (b, 0);
    }
    let mut evaluations = 0;
    while b - a > tolerance && evaluations < 200 {
        let m = 0.5 * (a + b);
        let fm = f(m);
        evaluations += 1;
        if fm == 0.0 {
            return (m, evaluations);
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    (0.5 * (a + b), evaluations)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bracket length requested of the refinement, which the test also uses as the bound on
    /// the error of the root: the returned midpoint is within half of it of a crossing, so the
    /// other half covers the rounding of the reference root.
    const CUBIC_TOLERANCE: f64 = 1e-10;

    #[test]
    fn finds_the_root_of_a_cubic_to_tolerance() {
        let f = |t: f64| t * t * t - 2.0;
        let (t, n) = refine_crossing(f, 0.0, f(0.0), 2.0, f(2.0), CUBIC_TOLERANCE);
        assert!((t - 2f64.cbrt()).abs() <= CUBIC_TOLERANCE, "t = {t}");
        assert!(n < 80, "{n} evaluations");
    }

    /// The bracket length requested of the bisection and the bound on the error of its midpoint
    /// (within half of it of the crossing, as for [`CUBIC_TOLERANCE`]); 30 halvings of `[0, 1]`
    /// reach it.
    const BISECTION_TOLERANCE: f64 = 1e-9;

    #[test]
    fn bisection_halves_to_tolerance() {
        let f = |t: f64| t - 0.3;
        let (t, n) = bisect_crossing(f, 0.0, -0.3, 1.0, 0.7, BISECTION_TOLERANCE);
        assert!((t - 0.3).abs() <= BISECTION_TOLERANCE);
        assert_eq!(n, 30); // ⌈log₂(10⁹)⌉
    }

    /// The bracket length requested on the step function, and the bound on the distance of the
    /// result from the jump at 0.3 (the final bracket holds the jump).
    const STEP_TOLERANCE: f64 = 1e-9;

    #[test]
    fn keeps_the_bracket_on_a_step_function() {
        // A discontinuous function still has its sign change located within the tolerance.
        let f = |t: f64| if t < 0.3 { 1.0 } else { -1.0 };
        let (t, _) = refine_crossing(f, 0.0, 1.0, 1.0, -1.0, STEP_TOLERANCE);
        assert!((t - 0.3).abs() <= STEP_TOLERANCE);
    }
}
