//! The white water of a world: foam and whitecaps, separate or with the foam's memory.

use super::*;

/// Share of Monahan's whitecap coverage drawn as active whitecaps (Dupuy & Bruneton) when foam
/// (Darles' extension) draws the rest: Brine's split of stage A (active breaking) and stage B
/// (decaying foam) whitecaps, so that the two models together cover Monahan's `W` once.
pub const ACTIVE_WHITECAP_SHARE: f64 = 0.2;

/// White water of the sea: the active whitecaps of its displacement Jacobian and the foam they
/// leave, one model per surface (brine-whitecap `WhiteWaterModel`).
// One per frame, never in a collection: the size difference costs nothing.
#[allow(clippy::large_enum_variant)]
pub enum WhiteWaterSea {
    /// Trochoid (or Gerstner, or sine) sets: analytic moments, phases rotated into the past.
    Trochoids(WhiteWaterModel<TrochoidBreaking>),
    /// The FFT sea: Jacobian pyramids of the frame and of the frames at the memory's instants.
    Fft(WhiteWaterModel<FftBreaking>),
}

impl WhiteWaterSea {
    /// White water at `u` (the hit's horizontal position, taken as the rest position), time `t`
    /// and round Gaussian footprint `sigma_m`.
    pub fn at(&self, u: DVec2, t: f64, sigma_m: f64) -> WhiteWater {
        self.at_over(u, t, &EllipticalFootprint::round(sigma_m))
    }

    /// [`WhiteWaterSea::at`] through an elliptical Gaussian pixel footprint.
    pub fn at_over(&self, u: DVec2, t: f64, footprint: &EllipticalFootprint) -> WhiteWater {
        match self {
            WhiteWaterSea::Trochoids(m) => m.at_over(u, t, footprint),
            WhiteWaterSea::Fft(m) => m.at_over(u, t, footprint),
        }
    }
}

/// The footprint of the breaking waves for the wind sea of `[sea]` (brine-whitecap
/// `breaking_footprint` of its peak phase speed `g/ω_p`); 0 without a wind sea.
/// Monahan's whitecap coverage `W` of the scene's wind (the 1980 law, or 1986's with the
/// water–air temperature difference when both temperatures are given), shared between foam and
/// active whitecaps.
pub(super) fn monahan_coverage(scene: &Scene) -> Result<f64, WorldError> {
    let law = match (scene.water.temperature_c, scene.water.air_temperature_c) {
        (Some(tw), Some(ta)) => WhitecapLaw::monahan_1986_from_temperatures(tw, ta)?,
        _ => WhitecapLaw::Monahan1980,
    };
    Ok(brine_foam::whitecap_coverage(&CoverageParams::new(scene.sea.wind_speed_m_s, law, DARLES_ONSET_WIND_M_S)?))
}

pub(super) fn breaking_footprint_of(s: &SeaConfig) -> Result<f64, WorldError> {
    let SeaSpectra { spectra, wind_sea, .. } = sea_spectra(s, true)?;
    let wind_sea = spectra.first().filter(|_| wind_sea);
    Ok(wind_sea.map_or(0.0, |sp| brine_whitecap::breaking_footprint(brine_waves::G / sp.peak_omega())))
}

/// Calibration points of the FFT sea's white water: its sea is one tile at one instant, and every
/// point reads the memory's instants from grids (16 384: the threshold's sampling error is
/// `√((1 − W)/(W M))`, 3.5 % at `W` = 5 %).
pub(super) const FFT_WHITE_WATER_SAMPLES: usize = 16_384;

/// The instant of the FFT sea on which its white water is calibrated (s): one for every frame.
pub(super) const FFT_CALIBRATION_TIME_S: f64 = 0.0;

/// Share of the short waves' Jacobian that shapes the edge of a whitecap (brine-whitecap
/// `WhiteWaterModel`): Brine's choice, 0.7 of their standard deviation.
pub(crate) const EDGE_SHARE: f64 = 0.7;

/// Foam on crests: Darles et al.'s extension of Monahan's coverage with Koepke's reflectance.
pub struct Foam {
    /// The extension (height, slope and noise weighting).
    pub extension: FoamExtension,
    /// Coverage distributed by the extension, `[0, 1]`.
    pub coverage: f64,
    /// Effective foam reflectance `R_ef = f_ef R_f` (Koepke 1984).
    pub reflectance: f64,
}

/// Active whitecaps: the Jacobian statistics of the sea and the calibrated (or raw) threshold.
pub enum Whitecaps {
    /// Of a trochoid (or Gerstner, or sine) set: analytic footprint moments.
    Trochoids {
        /// Statistics of the set's displacement Jacobian.
        stats: JacobianStatistics,
        /// Calibrated threshold, or `None` for the raw `alpha`.
        calibration: Option<Calibration>,
        /// Raw `α` when not calibrated.
        alpha: f64,
    },
    /// Of an FFT frame: mip-mapped moments of the Jacobian grids (Dupuy & Bruneton 2012).
    Fft {
        /// Pyramids of `kᵢ = Jᵢ − 1 + 1/n` and `kᵢ²` per cascade.
        stats: Box<FftJacobianStatistics>,
        /// Calibrated threshold per footprint size, or `None` for the raw `alpha`.
        calibration: Option<FftCalibration>,
        /// Raw `α` when not calibrated.
        alpha: f64,
    },
}

impl Whitecaps {
    /// Coverage `W` over a Gaussian footprint of standard deviation `sigma_m` centred at `u`, the
    /// hit point's horizontal position (for trochoids, taken as the rest position).
    pub fn coverage(&self, u: DVec2, t: f64, sigma_m: f64) -> f64 {
        match self {
            Whitecaps::Trochoids { stats, calibration, alpha } => {
                let m = stats.moments_at_f32(u, t, sigma_m, FootprintFilter::Gaussian);
                match calibration {
                    Some(c) => c.coverage(m, sigma_m, ErfMethod::AbramowitzStegun),
                    None => whitecap_coverage(m, *alpha, ErfMethod::AbramowitzStegun),
                }
            }
            Whitecaps::Fft { stats, calibration, alpha } => {
                let m = stats.moments_at(u.x, u.y, sigma_m);
                match calibration {
                    Some(c) => c.coverage(m, sigma_m, ErfMethod::AbramowitzStegun),
                    None => whitecap_coverage(m, *alpha, ErfMethod::AbramowitzStegun),
                }
            }
        }
    }
}
