//! Errors of the foam and spray models.

/// A foam or spray parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FoamError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
}

/// `Ok(value)` if `ok` and `value` is finite, else [`FoamError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, FoamError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
