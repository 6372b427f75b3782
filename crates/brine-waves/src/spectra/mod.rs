//! Ocean wave spectra, directional spreading and dispersion.

pub(crate) mod dispersion;
pub(crate) mod elfouhaily;
pub(crate) mod integrate;
pub(crate) mod jonswap;
pub(crate) mod phillips;
pub(crate) mod pierson_moskowitz;
pub(crate) mod spectrum;
pub(crate) mod spreading;
pub(crate) mod summed;
pub(crate) mod tma;
