//! Wave surfaces as height fields: the trochoid sum, the Gerstner sum, the sine waves, detail normals, the sea floor.

/// Implements `WaveSurface` methods of signature `(x, z, t)` by the surface's field frozen at `t`:
/// `self.at_time(t).method(x, z)`.
macro_rules! by_frozen_field {
    ($($method:ident -> $ret:ty),* $(,)?) => {
        $(fn $method(&self, x: f64, z: f64, t: f64) -> $ret {
            self.at_time(t).$method(x, z)
        })*
    };
}

pub(crate) mod detail;
pub(crate) mod gerstner;
pub(crate) mod seabed;
pub(crate) mod sine;
pub(crate) mod surface;
