//! The surfaces as brine-trace component sums: Lipschitz bounds, SIMD lanes, footprint fading.

pub(crate) mod fade;
pub(crate) mod fast_profile;
pub(crate) mod gerstner_lanes;
pub(crate) mod gerstner_lipschitz;
pub(crate) mod lanes;
pub(crate) mod lipschitz;
pub(crate) mod sine_lipschitz;
pub(crate) mod traced;
