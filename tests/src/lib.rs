//! Helpers shared by Brine's cross-crate integration tests.
