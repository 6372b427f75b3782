//! Errors of the ephemeris.

/// A bad input to the ephemeris.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EphemError {
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
    /// A time that cannot be parsed or used.
    #[error("time {input:?}: {message}")]
    Time {
        /// The input as given.
        input: String,
        /// What is wrong with it.
        message: String,
    },
}

pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, EphemError> {
    if ok && value.is_finite() { Ok(value) } else { Err(EphemError::OutOfRange { name, value, range }) }
}
