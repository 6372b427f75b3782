//! Errors of the foam and spray models.

/// A foam or spray parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FoamError {
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
}

/// Returns `Ok(value)` if `ok` and `value` is finite, else the [`FoamError::OutOfRange`] naming
/// the parameter.
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, FoamError> {
    if ok && value.is_finite() { Ok(value) } else { Err(FoamError::OutOfRange { name, value, range }) }
}
