//! A value against its reference within a tolerance, with one message format for every test.

use std::fmt;

/// A tolerance: absolute (the value's unit) or relative to the reference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// `|got − expected| ≤ tol`.
    Abs(f64),
    /// `|got/expected − 1| ≤ tol`.
    Rel(f64),
}

impl Tolerance {
    /// The tolerance named by a table's `abs`/`rel` field.
    ///
    /// # Panics
    /// On another kind.
    pub fn parse(kind: &str, tol: f64) -> Self {
        match kind {
            "abs" => Self::Abs(tol),
            "rel" => Self::Rel(tol),
            other => panic!("tolerance kind {other:?}: expected abs or rel"),
        }
    }

    /// The error of `got` against `expected` in this tolerance's measure.
    pub fn error(self, got: f64, expected: f64) -> f64 {
        match self {
            Self::Abs(_) => (got - expected).abs(),
            Self::Rel(_) => (got / expected - 1.0).abs(),
        }
    }

    fn bound(self) -> f64 {
        match self {
            Self::Abs(t) | Self::Rel(t) => t,
        }
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Abs(t) => write!(f, "± {t}"),
            Self::Rel(t) => write!(f, "± {t} relative"),
        }
    }
}

/// `Ok` when `got` is within `tol` of `expected` (a NaN never is), else the message
/// `"{what}: got …, expected … ± … (error …)"`.
pub fn close(what: &str, got: f64, expected: f64, tol: Tolerance) -> Result<(), String> {
    let err = tol.error(got, expected);
    if err <= tol.bound() {
        Ok(())
    } else {
        Err(format!("{what}: got {got}, expected {expected} {tol} (error {err:.3e})"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn close_accepts_within_and_names_the_failure() {
        assert!(close("x", 1.0005, 1.0, Tolerance::Rel(1e-3)).is_ok());
        assert!(close("x", f64::NAN, 1.0, Tolerance::Abs(1.0)).is_err());
        let e = close("height", 2.0, 1.0, Tolerance::Abs(0.5)).unwrap_err();
        assert!(e.starts_with("height: got 2, expected 1 ± 0.5"), "{e}");
    }
}
