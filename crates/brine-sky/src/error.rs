//! Errors of the sky models.

/// A sky parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SkyError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
}

/// `Ok(value)` if `ok` and `value` is finite, else [`SkyError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, SkyError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
