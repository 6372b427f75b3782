//! Evaluation counters.

/// Counters accumulated by [`crate::trace`]; merge per-thread copies with [`TraceStats::merge`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Rays traced.
    pub rays: u64,
    /// Rays that found a crossing.
    pub hits: u64,
    /// Rays skipped without any evaluation (they miss the box holding the zero set).
    pub culled: u64,
    /// Rays abandoned at the step cap before reaching `t_max` (reported as misses).
    pub exhausted: u64,
    /// Evaluations of the whole function `F`, including those of the root refinement.
    pub evaluations: u64,
    /// Evaluations of single components `nᵢ` (a full evaluation of `F` counts `N`).
    pub component_evaluations: u64,
    /// Evaluations spent in root refinement (a subset of `evaluations`).
    pub refinement_evaluations: u64,
    /// [`crate::Method::Tiered`]: points where only the long tiers were evaluated, the others
    /// entering through their bounds (frequency pruning; a subset of `evaluations`).
    pub pruned_evaluations: u64,
    /// [`crate::Method::Tiered`]: probe points (a step of at most the minimum step `h`, or the
    /// Newton probe near the surface, checked at its end; a subset of `evaluations`).
    pub probe_evaluations: u64,
}

impl TraceStats {
    /// Adds the counters of `other` to `self`.
    pub fn merge(&mut self, other: &TraceStats) {
        self.rays += other.rays;
        self.hits += other.hits;
        self.culled += other.culled;
        self.exhausted += other.exhausted;
        self.evaluations += other.evaluations;
        self.component_evaluations += other.component_evaluations;
        self.refinement_evaluations += other.refinement_evaluations;
        self.pruned_evaluations += other.pruned_evaluations;
        self.probe_evaluations += other.probe_evaluations;
    }

    /// Mean evaluations of `F` per ray (0 when no ray was traced).
    pub fn evaluations_per_ray(&self) -> f64 {
        if self.rays == 0 { 0.0 } else { self.evaluations as f64 / self.rays as f64 }
    }
}
