//! The surfaces as brine-trace component sums (feature `tracing`): Lipschitz bounds, and the
//! SIMD lanes and footprint fading the surfaces' own evaluation shares.

pub(crate) mod fade;
pub(crate) mod fast_profile;
pub(crate) mod gerstner_lanes;
#[cfg(feature = "tracing")]
pub(crate) mod gerstner_lipschitz;
pub(crate) mod lanes;
#[cfg(feature = "tracing")]
pub(crate) mod lipschitz;
#[cfg(feature = "tracing")]
pub(crate) mod sea;
#[cfg(feature = "tracing")]
pub(crate) mod sine_lipschitz;
pub(crate) mod traced;
