//! Plots of brine-ephem (none yet: add them with the crate's issue).

use std::path::Path;

/// Writes the brine-ephem figures into `dir`.
pub fn plot(dir: &Path) -> Result<(), String> {
    let _ = dir;
    Ok(())
}
