//! Errors of the optics models.

/// An optical parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OpticsError {
    /// A parameter is outside its range.
    #[error("{name} = {value} is out of range: expected {range}")]
    OutOfRange {
        /// Parameter name with its unit suffix.
        name: &'static str,
        /// Offending value.
        value: f64,
        /// Accepted range, in words.
        range: &'static str,
    },
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

pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, OpticsError> {
    if ok && value.is_finite() { Ok(value) } else { Err(OpticsError::OutOfRange { name, value, range }) }
}
