//! Shared helpers of Brine's tests and benchmarks, so that every crate integrates, times, reads
//! its reference tables and words its failures the same way.
//!
//! - [`quadrature`]: composite Simpson, adaptive Simpson (Lyness 1969) and composite
//!   Gauss–Legendre rules, written independently of the model crates they check.
//! - [`timing`]: medians of repeated runs (benchmarks report medians: single timings on a 2-core
//!   machine spread by about ±10 %).
//! - [`directions`]: unit vectors from elevation and azimuth or from polar angles, and the angle
//!   between two sky positions.
//! - [`csv`]: the records of the embedded reference tables.
//! - [`check`]: a value against a reference within a named tolerance, with one message format.
//! - [`lattice`]: the share of a top-down normal map's slope power in its strongest wave vectors
//!   (a lattice of glints).
//! - [`strategies`] (feature `waves`): `proptest` strategies of random trochoid sets.
//!
//! Formulas, sources and limits: `docs/models/brine-testkit.md`.
//!
//! ```
//! use brine_testkit::quadrature::simpson;
//! let area = simpson(|x| x * x, 0.0, 3.0, 1);
//! assert!((area - 9.0).abs() < 1e-12); // Simpson is exact for cubics.
//! ```

pub mod check;
pub mod csv;
pub mod directions;
pub mod lattice;
pub mod quadrature;
#[cfg(feature = "waves")]
pub mod strategies;
pub mod timing;
