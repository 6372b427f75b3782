//! Methods, options, hits and the step log.

use glam::DVec3;

/// How the tracer advances along the ray. All methods trace the same function and return its
/// first sign change; they differ in how many evaluations they spend.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Fixed-step marching with `Δt = march_step` (or `min_feature_size/4`), then bisection: the
    /// baseline of Darles et al. 2007 §3.1 ("brute-force ray marching").
    BruteForce,
    /// Hart's sphere tracing with the global constant `L = Σ Lᵢ`: step `|F(p)|/L`.
    GlobalLipschitz,
    /// Sphere tracing with the directional constant `L(d̂) = Σ Lᵢ(d̂) ≤ L` along the ray:
    /// step `|F(p)|/L(d̂)`. Safe because `t ↦ F(o + t d̂)` is `L(d̂)`-Lipschitz.
    #[default]
    Directional,
    /// Directional sphere tracing over-relaxed by `ω` (Keinert et al. 2014): step `ω|F|/L(d̂)`,
    /// undone whenever the unbounding intervals of the two ends do not overlap.
    Relaxed,
    /// Darles et al. 2007 Algorithm 1 as corrected in the docs/equations.md §2: the efficient step
    /// `max_S (M + Σ_{i∈S}(vᵢ − mᵢ))/Σ_{i∈S} Lᵢ(d̂)` over prefixes sorted by `(vᵢ − mᵢ)/Lᵢ`
    /// estimated from the previous point (spatial coherence); only the visited components are
    /// evaluated.
    Darles,
    /// Brine's method: components in tiers of decreasing length scale; far from the surface only
    /// the long tiers are evaluated and the rest enter through their bounds (frequency pruning);
    /// the step is the first root of a certified piecewise-quadratic lower bound that uses the
    /// derivative along the ray and a curvature bound, over-relaxed when a certified backward step
    /// confirms it; near the surface, Newton probes on stretches where `F` provably decreases and
    /// a crossing enclosed by certified bounds; optional footprint fading. See
    /// [`crate::trace_tiers`].
    Tiered,
    /// Segment tracing (Galin et al. 2020, Algorithm 2) on the same tiers as [`Method::Tiered`]:
    /// every tier evaluated at every point, step `min(s, |F|/λ_s)` with `λ_s = Σⱼ min(Lⱼ, |dⱼ| +
    /// Kⱼ s)` the Lipschitz bound local to the candidate segment `[t, t + s]`, next candidate
    /// `κ` times the step. See [`crate::trace_segments`].
    Segment,
}

impl Method {
    /// Every method, in the order of the benchmark tables.
    pub const ALL: [Method; 7] = [
        Method::BruteForce,
        Method::GlobalLipschitz,
        Method::Directional,
        Method::Relaxed,
        Method::Darles,
        Method::Segment,
        Method::Tiered,
    ];

    /// A short name for tables.
    pub fn name(self) -> &'static str {
        match self {
            Method::BruteForce => "brute force",
            Method::GlobalLipschitz => "global L (Hart)",
            Method::Directional => "directional L",
            Method::Relaxed => "relaxed (Keinert)",
            Method::Darles => "Darles Alg. 1",
            Method::Segment => "segment (Galin)",
            Method::Tiered => "tiered (Brine)",
        }
    }
}

/// Why trace options were rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TraceOptionsError {
    /// A parameter is outside its range.
    #[error("trace option {0}")]
    OutOfRange(#[from] brine_core::OutOfRange),
}

/// Options of [`crate::trace`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceOptions {
    /// Step rule.
    pub method: Method,
    /// Start of the traced interval of `t` (m), `≥ 0`.
    pub t_min: f64,
    /// End of the traced interval of `t` (m), `> t_min`.
    pub t_max: f64,
    /// Cap on the number of steps; a ray reaching it is reported as a miss and counted in
    /// [`crate::TraceStats::exhausted`].
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
    /// Step of [`Method::BruteForce`] (m); `0` (the default) uses a quarter of the surface's
    /// [`min_feature_size`](crate::LipschitzSum::min_feature_size). `≥ 0`.
    pub march_step: f64,
    /// Over-relaxation factor `ω` of [`Method::Relaxed`], `[1, 2)` (Keinert et al. suggest 1.2–1.6).
    pub relaxation: f64,
    /// Angular width of a pixel's footprint (rad), `≥ 0`; `0` (the default) disables fading.
    /// With [`Method::Tiered`] (and [`Method::Segment`], which traces the same tiers), component
    /// `i` is weighted by `smoothstep(1, 1.5, Tᵢ/t)` along the ray, `Tᵢ` its
    /// [fade distance](crate::LipschitzSum::component_fade_distance): components smaller than the
    /// footprint are dropped from the traced surface (the renderer moves them into the BRDF;
    /// [`crate::faded_components`] lists them). The other methods ignore it.
    pub footprint_angle: f64,
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
            march_step: 0.0,
            relaxation: 1.5,
            footprint_angle: 0.0,
        }
    }
}

impl TraceOptions {
    /// The settings the benchmarks and plots compare the methods at: `method`, rays to 3 km, at
    /// most 2×10⁵ steps, minimum steps of 1 mm + 10⁻⁴ t, crossings to 0.1 mm + 10⁻⁶ t, and the
    /// footprint fading of `footprint_angle` (rad, `≥ 0`; 0: none).
    pub fn comparison(method: Method, footprint_angle: f64) -> Self {
        Self {
            method,
            t_max: 3000.0,
            max_steps: 200_000,
            min_step: 1e-3,
            min_step_relative: 1e-4,
            tolerance: 1e-4,
            tolerance_relative: 1e-6,
            footprint_angle,
            ..Self::default()
        }
    }

    /// Counts one more step of a walk that has taken `steps`: `false`, with the walk counted as
    /// exhausted in `stats`, once [`Self::max_steps`] are spent.
    pub(crate) fn take_step(&self, steps: &mut u32, stats: &mut crate::TraceStats) -> bool {
        if *steps >= self.max_steps {
            stats.exhausted += 1;
            return false;
        }
        *steps += 1;
        true
    }

    /// Checks every field against its range.
    ///
    /// # Errors
    /// [`TraceOptionsError::OutOfRange`] naming the first bad field.
    pub fn validate(&self) -> Result<(), TraceOptionsError> {
        let check = |name, value: f64, ok: bool, range| brine_core::require(ok, name, value, range).map(|_| ());
        let nonneg = |v: f64| v >= 0.0 && v.is_finite();
        let pos = |v: f64| v > 0.0 && v.is_finite();
        check("t_min", self.t_min, nonneg(self.t_min), "[0, ∞) m")?;
        check("t_max", self.t_max, self.t_max > self.t_min, "(t_min, ∞] m")?;
        check("max_steps", f64::from(self.max_steps), self.max_steps > 0, "[1, 2³²)")?;
        check("min_step", self.min_step, pos(self.min_step), "(0, ∞) m")?;
        check("min_step_relative", self.min_step_relative, nonneg(self.min_step_relative), "[0, ∞)")?;
        check("tolerance", self.tolerance, pos(self.tolerance), "(0, ∞) m")?;
        check("tolerance_relative", self.tolerance_relative, nonneg(self.tolerance_relative), "[0, ∞)")?;
        check("march_step", self.march_step, nonneg(self.march_step), "[0, ∞) m")?;
        check("relaxation", self.relaxation, (1.0..2.0).contains(&self.relaxation), "[1, 2)")?;
        Ok(check("footprint_angle", self.footprint_angle, nonneg(self.footprint_angle), "[0, ∞) rad")?)
    }

    /// The minimum step `h(t) = max(min_step, min_step_relative · t)` (m).
    #[inline]
    pub fn min_step_at(&self, t: f64) -> f64 {
        self.min_step.max(self.min_step_relative * t)
    }

    /// The refinement tolerance `max(tolerance, tolerance_relative · t)` (m).
    #[inline]
    pub fn tolerance_at(&self, t: f64) -> f64 {
        self.tolerance.max(self.tolerance_relative * t)
    }
}

/// A crossing of the zero set found by [`crate::trace`].
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

/// What a logged step certified.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepKind {
    /// A step whose length a bound certifies free of zeros (Lipschitz, efficient or second-order).
    Certified,
    /// A step of at most the minimum step `h` (or a brute-force step), checked only at its end.
    Probe,
    /// An over-relaxed step that was undone (its end is not the next point).
    Rejected,
    /// The final bracket `[t_from, t_to]` of the crossing, before refinement.
    Bracket,
}

/// One step of a trace, recorded by [`crate::trace_logged`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// Start of the step (m along the ray).
    pub t_from: f64,
    /// End of the step (m).
    pub t_to: f64,
    /// What the step certified.
    pub kind: StepKind,
}

/// Pushes a step onto an optional log.
#[inline]
pub(crate) fn log_step(log: &mut Option<&mut Vec<Step>>, t_from: f64, t_to: f64, kind: StepKind) {
    if let Some(l) = log.as_deref_mut() {
        l.push(Step { t_from, t_to, kind });
    }
}
