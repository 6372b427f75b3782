//! # brine-whitecap — whitecaps from the displacement Jacobian
//!
//! Whitecap coverage W = ½(1 + erf((α − μ)/√(2σ²))) from the mean μ and variance σ² of the
//! Jacobian of the horizontal displacement of the sea surface over a pixel footprint
//! (Dupuy & Bruneton 2012), with analytic statistics for trochoid sets and a calibration of α
//! against the Monahan coverage of brine-foam.
//!
//! ## Status
//!
//! **Skeleton.** Nothing in this crate is implemented yet; the models above arrive with
//! issue #6. No function here pretends to compute them.
