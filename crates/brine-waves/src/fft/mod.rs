//! Tessendorf's FFT sea: spectrum, cascades, frames, certified splines, footprint-filtered slopes.

pub(crate) mod blend;
pub(crate) mod frame;
#[cfg(feature = "tracing")]
pub(crate) mod lipschitz;
pub(crate) mod ocean;
pub(crate) mod options;
pub(crate) mod pyramid;
pub(crate) mod resample;
pub(crate) mod slopes;
pub(crate) mod spectrum;
pub(crate) mod spline;
