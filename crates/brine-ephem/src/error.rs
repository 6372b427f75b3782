//! Errors of the ephemeris.

/// A bad input to the ephemeris.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EphemError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
    /// A time that cannot be parsed or used.
    #[error("time {input:?}: {message}")]
    Time {
        /// The input as given.
        input: String,
        /// What is wrong with it.
        message: String,
    },
}

/// `Ok(value)` if `ok` and `value` is finite, else [`EphemError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, EphemError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
