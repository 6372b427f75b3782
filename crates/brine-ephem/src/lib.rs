//! # brine-ephem — sun and moon positions
//!
//! Apparent positions of the sun and the moon for a UTC instant and a place on Earth, after
//! Schlyter's "How to compute planetary positions" (as used by Li Ying et al. 2018, §2.1) and the
//! NREL Solar Position Algorithm; moon phase angle and illuminated fraction.
//!
//! ## Status
//!
//! **Skeleton.** Nothing in this crate is implemented yet; the models above arrive with
//! issue #4. No function here pretends to compute them.
