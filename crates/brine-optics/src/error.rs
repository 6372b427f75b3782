//! Errors of the optics models.

/// An optical parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OpticsError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
    /// A name that is not one of the accepted ones.
    #[error("{name} = {value:?} is not known: expected {expected}")]
    UnknownName {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: String,
        /// The accepted names, in words.
        expected: &'static str,
    },
}

/// `Ok(value)` if `ok` and `value` is finite, else [`OpticsError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, OpticsError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
