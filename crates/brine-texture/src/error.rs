//! Errors of the photo-based ocean.

/// Why an input or a parameter was rejected.
#[derive(Debug, thiserror::Error)]
pub enum TextureError {
    /// The file could not be opened or read.
    #[error("{what} {path}: cannot read: {source}")]
    Io {
        /// Role of the file (e.g. `small-wave image`).
        what: String,
        /// Path as given.
        path: String,
        /// Cause.
        source: std::io::Error,
    },
    /// The file is not an image of a supported format (PNG or JPEG), or is corrupt.
    #[error("{what} {path}: {message}")]
    Decode {
        /// Role of the file.
        what: String,
        /// Path as given.
        path: String,
        /// What the decoder said.
        message: String,
    },
    /// An image is smaller than a synthesis patch.
    #[error(
        "{what} is {width}×{height} px, smaller than the patch size {patch} px (give a larger image or a smaller --patch)"
    )]
    TooSmall {
        /// Which image.
        what: String,
        /// Its width (px).
        width: usize,
        /// Its height (px).
        height: usize,
        /// The patch size (px).
        patch: usize,
    },
    /// A uniform image: Eq. 1 divides by `I_max − I_min`.
    #[error(
        "{what} has a uniform intensity (I_max = I_min = {level:.3}): the height of Eq. 1 divides by I_max − I_min"
    )]
    Flat {
        /// Which image.
        what: String,
        /// Its single intensity level, `[0, 255]`.
        level: f64,
    },
    /// A parameter outside its documented domain (its name, value and range).
    #[error(transparent)]
    OutOfRange(#[from] brine_core::OutOfRange),
    /// Texel data of the wrong length or with a value outside `[0, 255]`.
    #[error("{0}")]
    BadTexels(String),
}

/// `Ok(value)` if `ok`, else [`TextureError::OutOfRange`] (brine-core's `require`).
pub(crate) fn check(name: &'static str, value: f64, ok: bool, range: &'static str) -> Result<f64, TextureError> {
    Ok(brine_core::require(ok, name, value, range)?)
}
