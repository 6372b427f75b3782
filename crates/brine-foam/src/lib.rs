//! # brine-foam — Monahan foam and sea spray
//!
//! Whitecap coverage after Monahan & Ó Muircheartaigh (1980, 1986), the foam extension of
//! Darles et al. 2007 (§4.1, Eq. 3–4, corrected in `shared/reference/equations.md` §5), foam
//! radiance after Koepke (1984), and the sea-spray size distribution of Monahan, Spiel & Davidson
//! (1986) with its vertical profile, extinction and optical depth (Darles et al. 2007, §4.2).
//!
//! ## Status
//!
//! **Skeleton.** Nothing in this crate is implemented yet; the models above arrive with
//! issue #6. No function here pretends to compute them.
