//! The surfaces as brine-trace component sums (feature `tracing`): Lipschitz bounds, and the
//! SIMD lanes and footprint fading the surfaces' own evaluation shares.

/// The fast path of a surface's `brine_trace::LipschitzSum`: `trace_tiered` and `certify_cone`
/// on its own tiers, `$tiers::new(surface, state, ray, t_exit, footprint_angle, half_angle)`,
/// with this thread's `$scratch` (a `RefCell<(TierScratch, state)>`); a cone is limited by
/// `cone_span` below the top `$top(surface)` (m) of the surface.
#[cfg(feature = "tracing")]
macro_rules! tiered_fast_path {
    ($scratch:ident, $tiers:ident, $top:expr) => {
        fn trace_tiered(
            &self,
            span: brine_trace::RaySpan<'_>,
            options: &brine_trace::TraceOptions,
            stats: &mut brine_trace::TraceStats,
            log: Option<&mut Vec<brine_trace::Step>>,
        ) -> Option<brine_trace::Hit> {
            $scratch.with_borrow_mut(|(scratch, state)| {
                let mut tiers = $tiers::new(self, state, span.ray, span.t_exit, options.footprint_angle, 0.0);
                brine_trace::trace_tiers_with(scratch, &mut tiers, span, options, stats, log)
            })
        }

        fn certify_cone(
            &self,
            span: brine_trace::RaySpan<'_>,
            half_angle: f64,
            options: &brine_trace::TraceOptions,
            stats: &mut brine_trace::TraceStats,
        ) -> f64 {
            let span = $crate::tracing::traced::cone_span(span, ($top)(self), options.footprint_angle);
            $scratch.with_borrow_mut(|(scratch, state)| {
                let mut tiers = $tiers::new(self, state, span.ray, span.t_exit, options.footprint_angle, half_angle);
                brine_trace::certify_cone_with(scratch, &mut tiers, span, half_angle, options, stats)
            })
        }
    };
}
#[cfg(feature = "tracing")]
pub(crate) use tiered_fast_path;

pub(crate) mod fade;
pub(crate) mod fast_profile;
pub(crate) mod gerstner_lanes;
#[cfg(feature = "tracing")]
pub(crate) mod gerstner_lipschitz;
#[cfg(feature = "tracing")]
pub(crate) mod gridded;
pub(crate) mod lanes;
#[cfg(feature = "tracing")]
pub(crate) mod lipschitz;
#[cfg(feature = "tracing")]
pub(crate) mod sea;
#[cfg(feature = "tracing")]
pub(crate) mod sine_lipschitz;
pub(crate) mod traced;
