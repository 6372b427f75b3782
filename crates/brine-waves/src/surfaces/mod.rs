//! Wave surfaces as height fields: the trochoid sum, the Gerstner sum, the sine waves, detail normals, the sea floor.

pub(crate) mod detail;
pub(crate) mod gerstner;
pub(crate) mod seabed;
pub(crate) mod sine;
pub(crate) mod surface;
