//! Errors of the wave models.

/// A wave-model parameter outside its documented domain.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WaveError {
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
    /// The spectrum holds no energy in the requested band.
    #[error("the spectrum has no energy between {omega_min} and {omega_max} rad/s")]
    EmptyBand {
        /// Lower band edge (rad/s).
        omega_min: f64,
        /// Upper band edge (rad/s).
        omega_max: f64,
    },
    /// The waves ask for more total steepness than the surface can bear without folding.
    #[error(
        "the waves' total steepness ΣQ = {total_steepness} exceeds {limit}: the surface would fold \
         (lower the choppiness or the wave count, or scale the steepness down)"
    )]
    TooSteep {
        /// `Σ Qᵢ` of the waves (dimensionless).
        total_steepness: f64,
        /// The largest accepted `Σ Qᵢ`.
        limit: f64,
    },
    /// Two options that are each valid but do not work together.
    #[error("{option} = {value} cannot be used with {other}: {reason}")]
    IncompatibleOptions {
        /// The option refused (as named in the docs).
        option: &'static str,
        /// Its value, in words.
        value: &'static str,
        /// The option it conflicts with, and that option's value.
        other: &'static str,
        /// Why, and what to use instead.
        reason: &'static str,
    },
}

/// `Ok(value)` if `ok` and `value` is finite, else [`WaveError::OutOfRange`] (brine-core's `check`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, WaveError> {
    Ok(brine_core::check(name, value, ok, range)?)
}
