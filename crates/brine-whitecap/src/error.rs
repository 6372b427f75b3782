//! Errors of the whitecap model.

/// A whitecap-model parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WhitecapError {
    /// A parameter is outside its range.
    #[error("{name} = {value} is out of range: expected {range}")]
    OutOfRange {
        /// Parameter name, as in the docs (with its unit suffix).
        name: &'static str,
        /// Offending value.
        value: f64,
        /// Accepted range, in words, with the unit.
        range: &'static str,
    },
    /// The wave set has no wave.
    #[error("the wave set is empty: a flat sea has no whitecaps to calibrate")]
    EmptySet,
}

/// Returns `Ok(value)` if `ok` and `value` is finite, else the [`WhitecapError::OutOfRange`]
/// naming the parameter.
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, WhitecapError> {
    if ok && value.is_finite() { Ok(value) } else { Err(WhitecapError::OutOfRange { name, value, range }) }
}
