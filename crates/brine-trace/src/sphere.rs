//! Sphere tracing with a global or a directional Lipschitz constant.

use glam::DVec3;

use crate::{LipschitzSum, Ray, TraceStats, refine_crossing};

/// How the step along the ray is bounded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Hart's sphere tracing with the global constant `L = Σ Lᵢ`: step `|F(p)|/L`.
    GlobalLipschitz,
    /// Sphere tracing with the directional constant `L(d̂) = Σ Lᵢ(d̂) ≤ L` along the ray:
    /// step `|F(p)|/L(d̂)`. Safe because `t ↦ F(o + t d̂)` is `L(d̂)`-Lipschitz.
    #[default]
    Directional,
}

/// Why trace options were rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TraceOptionsError {
    /// A parameter is outside its range.
    #[error("trace option {name} = {value} is out of range ({range})")]
    OutOfRange {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
        /// Accepted range.
        range: &'static str,
    },
}

/// Options of [`trace`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceOptions {
    /// Step bound.
    pub method: Method,
    /// Start of the traced interval of `t` (m), `≥ 0`.
    pub t_min: f64,
    /// End of the traced interval of `t` (m), `> t_min`.
    pub t_max: f64,
    /// Cap on the number of steps; a ray reaching it is reported as a miss and counted in
    /// [`TraceStats::exhausted`].
    pub max_steps: u32,
    /// Absolute part of the minimum step `h` (m), `> 0`.
    pub min_step: f64,
    /// Relative part of the minimum step: `h(t) = max(min_step, min_step_relative · t)`, `≥ 0`.
    /// Crossing pairs closer than `h(t)` may be skipped (skims of depth at most `L·h/2`).
    pub min_step_relative: f64,
    /// Absolute part of the refinement tolerance (m): the final bracket is no longer than
    /// `max(tolerance, tolerance_relative · t)`.
    pub tolerance: f64,
    /// Relative part of the refinement tolerance, `≥ 0`.
    pub tolerance_relative: f64,
}

impl Default for TraceOptions {
    fn default() -> Self {
        Self {
            method: Method::Directional,
            t_min: 0.0,
            t_max: 1.0e5,
            max_steps: 20_000,
            min_step: 1.0e-4,
            min_step_relative: 1.0e-5,
            tolerance: 1.0e-6,
            tolerance_relative: 1.0e-9,
        }
    }
}

impl TraceOptions {
    /// Checks every field against its range.
    ///
    /// # Errors
    /// [`TraceOptionsError::OutOfRange`] naming the first bad field.
    pub fn validate(&self) -> Result<(), TraceOptionsError> {
        let check = |name, value: f64, ok: bool, range| {
            if ok { Ok(()) } else { Err(TraceOptionsError::OutOfRange { name, value, range }) }
        };
        check("t_min", self.t_min, self.t_min >= 0.0 && self.t_min.is_finite(), "[0, ∞)")?;
        check("t_max", self.t_max, self.t_max > self.t_min, "(t_min, ∞]")?;
        check("max_steps", f64::from(self.max_steps), self.max_steps > 0, "[1, 2³²)")?;
        check("min_step", self.min_step, self.min_step > 0.0 && self.min_step.is_finite(), "(0, ∞)")?;
        check(
            "min_step_relative",
            self.min_step_relative,
            self.min_step_relative >= 0.0 && self.min_step_relative.is_finite(),
            "[0, ∞)",
        )?;
        check("tolerance", self.tolerance, self.tolerance > 0.0 && self.tolerance.is_finite(), "(0, ∞)")?;
        check(
            "tolerance_relative",
            self.tolerance_relative,
            self.tolerance_relative >= 0.0 && self.tolerance_relative.is_finite(),
            "[0, ∞)",
        )
    }
}

/// A crossing of the zero set found by [`trace`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hit {
    /// Distance along the ray (m), within the refinement tolerance of the first crossing found.
    pub t: f64,
    /// The point `origin + t·direction`.
    pub point: DVec3,
    /// `true` if `F` went from positive to negative (entering the region `F < 0`).
    pub entering: bool,
    /// Steps taken before the crossing was bracketed.
    pub steps: u32,
}

/// Traces `ray` against the zero set of `surface` and returns the first sign change of `F`.
///
/// Clips the ray to [`LipschitzSum::zero_set_bounds`] and `[t_min, t_max]`, then advances by
/// `max(|F|/Λ, h(t))` with `Λ` the global or directional constant of [`Method`]. A step of length
/// `|F|/Λ` contains no zero (Hart 1996, Lipschitz bound); a step forced to `h(t)` is checked for
/// a sign change at its end. A bracketed crossing is refined by [`refine_crossing`].
///
/// # Arguments
/// - `surface`: the implicit function.
/// - `ray`: the ray; `t` is measured along its unit direction (m).
/// - `options`: see [`TraceOptions`]; checked with `debug_assert!` (validate user input with
///   [`TraceOptions::validate`]).
/// - `stats`: counters to accumulate into.
///
/// # Returns
/// The hit, or `None` if `F` keeps its sign on the traced interval (up to skims thinner than the
/// minimum step) or the step cap is reached.
///
/// # References
/// Hart 1996, §3 (sphere tracing); Darles et al. 2007, §3.1.
pub fn trace<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    options: &TraceOptions,
    stats: &mut TraceStats,
) -> Option<Hit> {
    debug_assert!(options.validate().is_ok(), "invalid trace options {options:?}");
    stats.rays += 1;
    let Some((t0, t1)) = surface.zero_set_bounds().clip(ray, options.t_min, options.t_max) else {
        stats.culled += 1;
        return None;
    };
    let n = surface.component_count() as u64;
    let d = ray.direction();
    let lambda = match options.method {
        Method::GlobalLipschitz => surface.lipschitz(),
        Method::Directional => surface.directional_lipschitz(d),
    };
    let eval = |t: f64, stats: &mut TraceStats| {
        stats.evaluations += 1;
        stats.component_evaluations += n;
        surface.value(ray.at(t))
    };

    let mut t = t0;
    let mut f = eval(t, stats);
    if f == 0.0 {
        stats.hits += 1;
        return Some(Hit { t, point: ray.at(t), entering: true, steps: 0 });
    }
    let positive = f > 0.0;
    let mut steps = 0u32;
    loop {
        if steps >= options.max_steps {
            stats.exhausted += 1;
            return None;
        }
        steps += 1;
        let safe = if lambda > 0.0 { f.abs() / lambda } else { f64::INFINITY };
        let h = options.min_step.max(options.min_step_relative * t);
        let t_next = (t + safe.max(h)).min(t1);
        let f_next = eval(t_next, stats);
        if f_next == 0.0 || (f_next > 0.0) != positive {
            let tolerance = options.tolerance.max(options.tolerance_relative * t_next);
            let mut refinement = 0u64;
            let (t_hit, _) = refine_crossing(
                |s| {
                    refinement += 1;
                    surface.value(ray.at(s))
                },
                t,
                f,
                t_next,
                f_next,
                tolerance,
            );
            stats.evaluations += refinement;
            stats.refinement_evaluations += refinement;
            stats.component_evaluations += refinement * n;
            stats.hits += 1;
            return Some(Hit { t: t_hit, point: ray.at(t_hit), entering: positive, steps });
        }
        if t_next >= t1 {
            return None;
        }
        t = t_next;
        f = f_next;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Aabb;

    /// F(p) = y − a sin(k x): a sine height field, L = sqrt(1 + (ak)²) ≤ 1 + ak.
    struct Sine {
        a: f64,
        k: f64,
    }

    impl LipschitzSum for Sine {
        fn component_count(&self) -> usize {
            2
        }
        fn component(&self, i: usize, p: DVec3) -> f64 {
            if i == 0 { p.y } else { -self.a * (self.k * p.x).sin() }
        }
        fn component_lipschitz(&self, i: usize) -> f64 {
            if i == 0 { 1.0 } else { self.a * self.k }
        }
        fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
            if i == 0 { d.y.abs() } else { self.a * self.k * d.x.abs() }
        }
        fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
            if i == 0 { a.y.min(b.y) } else { -self.a }
        }
        fn zero_set_bounds(&self) -> Aabb {
            Aabb::slab_y(-self.a, self.a)
        }
    }

    #[test]
    fn a_ray_through_a_crest_stops_at_the_first_crossing() {
        // Horizontal ray at y = 0.5 through sin waves of amplitude 1: first crossing where
        // sin(x) = 0.5 after x0 = 0.6 is x = 5π/6 ≈ 2.618 (sin decreasing through 0.5 going from
        // above the ray... at x0 = 0.6, sin(0.6) = 0.565 > 0.5 so F < 0: the ray starts inside).
        let s = Sine { a: 1.0, k: 1.0 };
        let ray = Ray::new(DVec3::new(0.6, 0.5, 0.0), DVec3::X).unwrap();
        let mut stats = TraceStats::default();
        let hit = trace(&s, &ray, &TraceOptions::default(), &mut stats).unwrap();
        let expected = 5.0 * std::f64::consts::PI / 6.0 - 0.6;
        assert!((hit.t - expected).abs() < 1e-5, "t = {}", hit.t);
        assert!(!hit.entering);
    }

    #[test]
    fn a_ray_skimming_above_a_crest_is_not_a_hit() {
        let s = Sine { a: 1.0, k: 1.0 };
        let ray = Ray::new(DVec3::new(0.0, 1.0 + 1e-7, 0.0), DVec3::X).unwrap();
        let options = TraceOptions { t_max: 20.0, ..TraceOptions::default() };
        let mut stats = TraceStats::default();
        assert!(trace(&s, &ray, &options, &mut stats).is_none());
    }
}
