//! The trochoid wave and the fit of wave sets to a spectrum.

pub(crate) mod extraction;
pub(crate) mod lattice;
pub(crate) mod set;
pub(crate) mod trochoid;
