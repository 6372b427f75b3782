//! # brine-texture — the photo-based ocean of Lai & Wu
//!
//! A texture-based ocean built from two photographs (Lai & Wu): tileable and temporal texture
//! synthesis, height fields by the paper's shading heuristic (Eq. 1), surface composition,
//! relighting (Eq. 6–9) and animation by shifting (Eq. 10–11).
//!
//! ## Status
//!
//! **Skeleton.** Nothing in this crate is implemented yet; the models above arrive with
//! issue #8. No function here pretends to compute them.
