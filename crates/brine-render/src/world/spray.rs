//! The spray over the sea: the bubble drops of the whitecaps, the spume torn from the crests,
//! and the light of the sky and the sea that the drops scatter toward the eye.

use super::*;
use brine_foam::{PhaseLobeTable, SprayScattering, SpumeLayer, SpumeParams};

/// The spray of a scene, when on and the wind blows.
#[derive(Debug, Clone)]
pub(crate) struct Spray {
    /// Bubble drops (Monahan et al. 1986), with the boundary layer's scale height.
    pub(crate) medium: SprayMedium,
    /// Spume drops (Fairall et al. 1994) in a layer a few wave heights deep.
    pub(crate) spume: SpumeLayer,
    /// `J(d)`: the sky and the sea's reflection of it seen through the drops' phase function.
    pub(crate) light: PhaseLobeTable,
}

/// The spray of `[sea]` under `sky`.
///
/// The spume is produced at the significant wave amplitude `H_s/2` of the wind sea's spectrum and
/// mixed by the friction velocity of Elfouhaily et al. (1997, Eq. 60–66) for the scene's wind
/// and fetch. The light the drops scatter is the sky above the horizon and, below it, the sky
/// reflected by the rough sea: `R(θ, σ) L_sky(mirror)`, with the reflectance of Bruneton et
/// al.'s rough surface (brine-optics `RoughReflectance`) for Cox & Munk's total slope variance
/// (isotropic mean). The light leaving the water column (a few per cent of the sky's) and the
/// white water are left out of that lower half.
pub(super) fn spray(s: &SeaConfig, sky: &Sky, variance_total: &SlopeVariance) -> Result<Spray, WorldError> {
    let u = s.wind_speed_m_s;
    let medium = SprayMedium::new(&SprayParams { u10: u, ..SprayParams::default() })?;
    let elfouhaily = match s.fetch_km {
        Some(f) => Elfouhaily::from_fetch(u, f * 1000.0)?,
        None => Elfouhaily::new(u, 0.84)?,
    };
    let amplitude = 0.5 * sea::sea_spectrum(s)?.significant_wave_height();
    let spume = SpumeLayer::new(&SpumeParams {
        u10: u,
        friction_velocity_m_s: elfouhaily.u_star().clamp(1e-3, 5.0),
        source_height_m: amplitude.clamp(1e-3, 30.0),
    })?;
    let sigma = (0.5 * variance_total.total()).sqrt();
    let rough = rough_reflectance();
    let light = PhaseLobeTable::new(SprayScattering::default().asymmetry, |w| {
        let w = DVec3::from_array(w);
        let l = if w.y >= 0.0 {
            sky.radiance_rgb(w)
        } else {
            sky.radiance_rgb(DVec3::new(w.x, -w.y, w.z)) * rough.reflectance(-w.y, sigma)
        };
        l.max(DVec3::ZERO).to_array()
    })?;
    Ok(Spray { medium, spume, light })
}
