//! What of a world does not depend on the frame's instant, built once for an animation.

use brine_foam::{FoamMemory, FoamMemoryParams, KoepkeFoam};
use brine_optics::SlopeVariance;
use brine_waves::{BandedTrochoids, DetailWaves, FftOcean, LoopDistortion, Ocean, TileLattice, TrochoidSet};
use brine_whitecap::{
    FftBreaking, FftInstantJacobian, FftJacobianHistory, FftJacobianStatistics, JacobianStatistics, TrochoidBreaking,
    WhiteWaterModel, WhiteWaterOptions,
};
use std::sync::{Arc, Mutex};

use glam::DVec2;
use rayon::prelude::*;

use super::white_water::{
    EDGE_SHARE, FFT_CALIBRATION_TIME_S, FFT_WHITE_WATER_SAMPLES, breaking_footprint_of, monahan_coverage,
};
use super::{WhiteWaterSea, WorldError, sea};
use crate::scene::{Scene, SurfaceKind};

/// The parts of a [`super::World`] that do not change with the frame's instant: the fitted
/// waves, the ocean model (the FFT sea's random amplitudes), the detail band's spectrum and the
/// white water's memory and calibration.
///
/// A still builds them and uses them once; an animation builds them once
/// ([`super::World::at_instant`]) and only the sea frame, the sky (the sun moves), the detail
/// band's and the white water's state at the instant are made per frame. Every part is a
/// function of the scene with its instants cleared, so a frame is the same bytes rendered
/// alone or in an animation.
pub struct Timeless {
    /// The scene these parts were built from, its instants cleared.
    key: Scene,
    /// The tile lattice the waves were snapped to, if any.
    lattice: Option<TileLattice>,
    /// The fitted wave set (empty for the FFT sea).
    pub(super) set: TrochoidSet,
    /// The trochoid sea's waves split for the grids its shorter ones are traced on (brine-waves
    /// `BandedTrochoids`; `set` is its snapped set), if they are.
    pub(super) banded: Option<BandedTrochoids>,
    /// The sea as a model of time.
    pub(super) ocean: Ocean,
    /// The detail band of a trochoid, Gerstner or sine sea.
    pub(super) detail: Option<DetailWaves>,
    /// The calibrated white water, when foam and whitecaps are drawn together.
    pub(super) white_water: Option<CalibratedWhiteWater>,
    /// The FFT sea's Jacobian means at the memory's instants of the last frame.
    past_means: PastMeans,
    /// How far the lattice's loop period moved the waves from their dispersion relation.
    pub(super) loop_distortion: Option<LoopDistortion>,
}

/// White water calibrated once on Monahan's W, to be read at a frame's instant.
pub(super) enum CalibratedWhiteWater {
    /// A trochoid (or Gerstner, or sine) set: the thresholds, and the breaking statistics whose
    /// one-pass history is set per frame ([`TrochoidBreaking::for_age`]).
    Trochoids { model: Box<WhiteWaterModel<TrochoidBreaking>>, breaking: Box<TrochoidBreaking>, forward: DVec2 },
    /// The FFT sea: calibrated at the reference instant, the frame's Jacobians made per frame.
    Fft { model: Box<WhiteWaterModel<FftBreaking>>, s_b: f64, forward: DVec2 },
}

/// The scene without its instants: the sea's time, the elapsed time and the place's UTC time.
pub(super) fn without_instants(scene: &Scene) -> Scene {
    let mut key = scene.clone();
    key.sea.time_s = 0.0;
    key.elapsed_s = 0.0;
    if let Some(place) = key.place.as_mut() {
        place.time_utc.clear();
    }
    key
}

/// The FFT sea's Jacobian at the memory's lattice instants, kept from one frame to the next: the
/// instants are multiples of the memory's step, so consecutive frames share most of them, and an
/// instant's grids are a function of the instant alone (the same bits whichever frame made them).
#[derive(Default)]
pub(super) struct PastMeans(Mutex<Vec<(u64, Arc<FftInstantJacobian>)>>);

/// The past and present Jacobian statistics of the FFT sea at `t` for the breaking footprint
/// `s_b`, with the memory's instants (those already made for an earlier frame taken from `kept`).
pub(super) fn fft_breaking_at(
    ocean: &FftOcean,
    memory: &FoamMemory,
    s_b: f64,
    t: f64,
    kept: &PastMeans,
) -> FftBreaking {
    let chop = ocean.options().choppiness;
    let drift = DVec2::from_array(memory.drift());
    let instants: Vec<f64> = (0..memory.sample_count()).map(|j| memory.instant(t, j).0).collect();
    let old = std::mem::take(&mut *kept.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner));
    let past: Vec<Arc<FftInstantJacobian>> = instants
        .par_iter()
        .map(|&tj| match old.iter().find(|(bits, _)| *bits == tj.to_bits()) {
            Some((_, m)) => Arc::clone(m),
            None => Arc::new(FftInstantJacobian::new(ocean, tj, s_b, drift)),
        })
        .collect();
    drop(old);
    let history = FftJacobianHistory::new(&past);
    *kept.0.lock().unwrap_or_else(std::sync::PoisonError::into_inner) =
        past.into_iter().map(|m| (m.time_s().to_bits(), m)).collect();
    let now = FftJacobianStatistics::from_rest_jacobians(&ocean.rest_jacobian_fields(t, s_b), chop);
    FftBreaking::new(now, history, s_b, ocean.jacobian_variance_removed(s_b, chop))
}

impl Timeless {
    /// Builds the instant-free parts of a validated scene, its waves snapped to `lattice` if
    /// given ([`super::World::on_lattice`]).
    ///
    /// # Errors
    /// [`WorldError`] if a model rejects a parameter.
    pub fn new(scene: &Scene, lattice: Option<&TileLattice>) -> Result<Self, WorldError> {
        let key = without_instants(scene);
        let s = &key.sea;
        let wind_angle = s.wind_direction_deg.to_radians();
        // The FFT ocean has no trochoid set: its statistics come from the frame.
        let mut loop_distortion = None;
        let set = if s.surface == SurfaceKind::Fft {
            TrochoidSet::default()
        } else {
            let fitted = sea::fit_sea(s)?;
            match lattice {
                Some(l) => {
                    loop_distortion = l.loop_distortion(&fitted);
                    l.snap(&fitted)?
                }
                None => fitted,
            }
        };
        // The shorter waves on grids: the snapped set is the sea from here on.
        let banded = match (s.surface, lattice) {
            (SurfaceKind::Trochoids, None) => sea::banded_trochoids(s, &set)?,
            _ => None,
        };
        let set = banded.as_ref().map_or(set, |b| b.set().clone());
        let ocean = match s.surface {
            SurfaceKind::Trochoids => Ocean::trochoids(set.clone()),
            SurfaceKind::Gerstner => Ocean::gerstner(set.clone())?,
            SurfaceKind::Sine => Ocean::sine(&set),
            SurfaceKind::Fft => match sea::fft_sea(s, lattice)? {
                Some(ocean) => Ocean::fft(ocean),
                None => Ocean::trochoids(set.clone()),
            },
        };
        let fft_ocean = match &ocean {
            Ocean::Fft { ocean } => Some(ocean.as_ref()),
            _ => None,
        };
        if let Some(o) = fft_ocean {
            loop_distortion = o.loop_distortion().cloned();
        }
        let flat = match fft_ocean {
            Some(o) => !(o.total_expected_variance() > 0.0),
            None => set.is_empty(),
        };
        let variance_total = SlopeVariance::cox_munk_clean_from_u10(s.wind_speed_m_s.min(60.0))?;
        let detail = || match s.surface {
            SurfaceKind::Fft => Ok(None),
            // The statistics of a fitted sea are its set's, whatever the instant.
            _ => sea::detail_waves(s, &sea::set_statistics(&set, wind_angle), &variance_total),
        };

        let ph = &key.phenomena;
        let monahan = monahan_coverage(&key)?;
        // Foam and whitecaps together: active whitecaps and the foam they leave, calibrated as one
        // on Monahan's W (brine-whitecap `WhiteWaterModel`, brine-foam `FoamMemory`); either
        // alone, or a raw threshold, keeps the separate models.
        let together = ph.foam && ph.whitecaps && ph.foam_memory && ph.whitecap_alpha.is_none();
        let past_means = PastMeans::default();
        let white_water = || -> Result<_, WorldError> {
            if !(together && monahan > 0.0 && !flat) {
                return Ok(None);
            }
            let s_b = breaking_footprint_of(s)?;
            let forward = brine_whitecap::forward_face_offset(s_b, wind_angle);
            // The edge noise has the scale of the waves just shorter than the breaking ones.
            // On a tile's lattice the foam's noises repeat over the tile too.
            let params = FoamMemoryParams {
                edge_wavelength_m: (std::f64::consts::PI * s_b).clamp(0.5, 20.0),
                tile_m: lattice.map(TileLattice::tile_m),
                ..FoamMemoryParams::for_wind(s.wind_speed_m_s, wind_angle, s.seed)
            };
            let memory = FoamMemory::new(&params, KoepkeFoam::default().efficiency())?;
            Ok(Some(match fft_ocean {
                Some(ocean) => {
                    // Calibrated on the sea at the reference instant 0 s, whatever the frame: the
                    // threshold is the same for every frame of an animation.
                    let reference = fft_breaking_at(ocean, &memory, s_b, FFT_CALIBRATION_TIME_S, &past_means);
                    let options = WhiteWaterOptions {
                        samples: FFT_WHITE_WATER_SAMPLES,
                        region_m: reference.now().largest_tile(),
                        times_s: (FFT_CALIBRATION_TIME_S, FFT_CALIBRATION_TIME_S),
                        seed: s.seed,
                        ..WhiteWaterOptions::default()
                    };
                    let model = WhiteWaterModel::new(reference, memory, s_b, EDGE_SHARE, monahan, &options)?;
                    CalibratedWhiteWater::Fft { model: Box::new(model), s_b, forward }
                }
                None => {
                    let stats = JacobianStatistics::new(&set)?;
                    let breaking = TrochoidBreaking::new(stats, memory.step(), DVec2::from_array(memory.drift()));
                    let options = WhiteWaterOptions { seed: s.seed, ..WhiteWaterOptions::default() };
                    let model = WhiteWaterModel::new(breaking.clone(), memory, s_b, EDGE_SHARE, monahan, &options)?;
                    CalibratedWhiteWater::Trochoids { model: Box::new(model), breaking: Box::new(breaking), forward }
                }
            }))
        };
        // The detail band's spectrum and the white water's calibration do not depend on each
        // other: built side by side (each the same whatever the threads).
        let (detail, white_water) = rayon::join(detail, white_water);
        let (detail, white_water) = (detail?, white_water?);
        Ok(Self {
            key,
            lattice: lattice.copied(),
            set,
            banded,
            ocean,
            detail,
            white_water,
            past_means,
            loop_distortion,
        })
    }

    /// Whether these parts are those of `scene`: the same scene but for its instants.
    pub fn fits(&self, scene: &Scene) -> bool {
        self.key == without_instants(scene)
    }

    /// The tile lattice the waves were snapped to, if any.
    pub fn lattice(&self) -> Option<&TileLattice> {
        self.lattice.as_ref()
    }

    /// The white water at the frame's instant `t` (s): the calibrated thresholds over the
    /// breaking statistics of that instant.
    pub(super) fn white_water_at(&self, t: f64) -> Option<WhiteWaterSea> {
        Some(match self.white_water.as_ref()? {
            CalibratedWhiteWater::Fft { model, s_b, forward } => {
                let Ocean::Fft { ocean } = &self.ocean else { return None };
                let model = model.as_ref().clone();
                // A frame at the reference instant reads the sea it was calibrated on.
                let model = if t.to_bits() == FFT_CALIBRATION_TIME_S.to_bits() {
                    model
                } else {
                    let now = fft_breaking_at(ocean, model.memory(), *s_b, t, &self.past_means);
                    model.with_source(now)
                };
                WhiteWaterSea::Fft(model.with_forward_face(*forward).for_time(t))
            }
            CalibratedWhiteWater::Trochoids { model, breaking, forward } => {
                // The frame's present and history in one pass.
                let age = model.memory().instant(t, 0).1;
                let model = model.as_ref().clone().with_source(breaking.as_ref().clone().for_age(age));
                WhiteWaterSea::Trochoids(model.with_forward_face(*forward).for_time(t))
            }
        })
    }
}
