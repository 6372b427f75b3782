//! Errors of the whitecap model.

/// A whitecap-model parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WhitecapError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
    /// The wave set has no wave.
    #[error("the wave set is empty: a flat sea has no whitecaps to calibrate")]
    EmptySet,
}

/// `Ok(value)` if `ok` and `value` is finite, else [`WhitecapError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, WhitecapError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
