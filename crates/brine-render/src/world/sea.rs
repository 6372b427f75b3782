//! The sea of a scene: its spectra, the fitted wave set or the FFT ocean, the slope statistics
//! and the detail waves.

use super::*;

/// The spectrum of `[sea]` (`U₁₀ > 0`); a spectrum the model refuses is reported with the scene
/// keys it came from ([`refused_spectrum`]).
pub(super) fn sea_spectrum(s: &SeaConfig) -> Result<Box<dyn Spectrum>, WorldError> {
    model_spectrum(s).map_err(|e| refused_spectrum(s, &e))
}

/// The error of a spectrum the model refuses, named by the scene keys it came from (the model's
/// own message names its internal parameter, such as a peak frequency).
pub(super) fn refused_spectrum(s: &SeaConfig, e: &brine_waves::WaveError) -> WorldError {
    let fetch = s.fetch_km.map_or(String::new(), |f| format!(", sea.fetch_km = {f}"));
    let depth = s.depth_m.map_or(String::new(), |d| format!(", sea.depth_m = {d}"));
    let name = match s.spectrum {
        SpectrumKind::PiersonMoskowitz => "pierson-moskowitz",
        SpectrumKind::Jonswap => "jonswap",
        SpectrumKind::Phillips => "phillips",
        SpectrumKind::Tma => "tma",
        SpectrumKind::Elfouhaily => "elfouhaily",
    };
    WorldError::Scene(format!(
        "sea.spectrum = \"{name}\" with sea.wind_speed_m_s = {}{fetch}{depth} gives no valid sea: {e}",
        s.wind_speed_m_s
    ))
}

/// The model of `[sea]`'s spectrum.
fn model_spectrum(s: &SeaConfig) -> Result<Box<dyn Spectrum>, brine_waves::WaveError> {
    let u = s.wind_speed_m_s;
    let fetch_m = s.fetch_km.map(|f| f * 1000.0);
    let jonswap = || -> Result<Jonswap, brine_waves::WaveError> {
        let j = Jonswap::from_fetch(u, fetch_m.unwrap_or(100_000.0))?;
        match s.gamma {
            Some(g) => j.with_peak_shape(g, 0.07, 0.09),
            None => Ok(j),
        }
    };
    Ok(match s.spectrum {
        SpectrumKind::PiersonMoskowitz => Box::new(PiersonMoskowitz::from_u10(u)?),
        SpectrumKind::Jonswap => Box::new(jonswap()?),
        SpectrumKind::Phillips => Box::new(Phillips::from_wind(u)?),
        SpectrumKind::Tma => Box::new(Tma::new(jonswap()?, s.depth_m.unwrap_or(f64::INFINITY))?),
        SpectrumKind::Elfouhaily => Box::new(match fetch_m {
            Some(f) => Elfouhaily::from_fetch(u, f)?,
            None => Elfouhaily::new(u, 0.84)?,
        }),
    })
}

/// The spectra of `[sea]`: the wind sea's (when `U₁₀ > 0` and it has waves) and the swell's, each
/// with its spreading, wave count and fit options (wave direction included).
pub(super) struct SeaSpectra {
    pub(super) spectra: Vec<Box<dyn Spectrum>>,
    pub(super) spreadings: Vec<Box<dyn Spreading>>,
    pub(super) counts: Vec<usize>,
    pub(super) options: Vec<FitOptions>,
    /// The wavenumber (rad m⁻¹) up to which the wind sea's spectrum holds Cox & Munk's total
    /// slope variance ([`slope_cutoff`]); infinite without a wind sea.
    pub(super) k_cox_munk: f64,
    /// The first spectrum is the wind sea's (false: no wind, no wind waves, or a wind too light
    /// to draw any).
    pub(super) wind_sea: bool,
}

/// Winds at or under this (m/s) are a flat calm without building their spectrum. Every spectrum's
/// fit would start at waves far under a millimetre there (Pierson–Moskowitz peaks at 8×10⁶ rad/s
/// at 10⁻⁶ m/s), which the rule of [`sea_spectra`] makes a calm anyway, and the peak laws `∝ 1/U₁₀`
/// overflow at the lightest winds the scene accepts (JONSWAP's under 5×10⁻³⁰⁸ m/s).
pub(super) const CALM_WIND_M_S: f64 = 1e-6;

/// Shortest wave any surface draws when the spectrum holds less slope than Cox & Munk's total
/// above it (m): 1 mm, the end of the capillary range.
pub(super) const SHORTEST_WAVE_M: f64 = 1e-3;

/// The wavenumber up to which a wind sea's spectrum, from half its peak frequency (where the fit
/// starts), holds Cox & Munk's clean-surface total slope variance for `u10`; `2π/1 mm` if it holds
/// less. Beyond it no surface draws waves: at light wind the gravity-range spectra's `k⁻³` tail
/// would give the sea more slope than Cox & Munk measured (1.4× at 2 m/s for the trochoid band
/// `[0.5, 12] ω_p` of Pierson–Moskowitz), where real seas carry few capillaries.
pub(super) fn slope_cutoff(spectrum: &dyn Spectrum, u10: f64) -> Result<f64, WorldError> {
    let total = SlopeVariance::cox_munk_clean_from_u10(u10.min(60.0))?;
    let k_lo = spectrum.dispersion().wavenumber(0.5 * spectrum.peak_omega());
    let k_cap = std::f64::consts::TAU / SHORTEST_WAVE_M;
    if !(k_lo < k_cap) {
        return Ok(k_cap);
    }
    Ok(brine_waves::wavenumber_of_slope(spectrum, k_lo, total.sigma_x2() + total.sigma_y2(), k_cap))
}

/// `any_count`: include the wind sea whatever its wave count (the FFT ocean has no count).
pub(super) fn sea_spectra(s: &SeaConfig, any_count: bool) -> Result<SeaSpectra, WorldError> {
    let wind_angle = s.wind_direction_deg.to_radians();
    let mut sea_options = FitOptions { wind_direction: wind_angle, choppiness: s.choppiness, ..FitOptions::default() };
    let mut k_cox_munk = f64::INFINITY;
    let mut spectra: Vec<Box<dyn Spectrum>> = Vec::new();
    let mut spreadings: Vec<Box<dyn Spreading>> = Vec::new();
    let mut counts = Vec::new();
    let mut options = Vec::new();
    let wind_sea = if s.wind_speed_m_s > CALM_WIND_M_S && (any_count || s.wave_count() > 0) {
        let spectrum = sea_spectrum(s)?;
        // A wind so light that even the fit's longest waves, at half the peak frequency, are
        // shorter than the shortest wave any surface draws has no wind sea to draw: its waves
        // would be capillary ripples under a micrometre high (Pierson–Moskowitz below 0.017 m/s),
        // outside the gravity-wave spectra, and numerically meaningless toward nanometres. The
        // sea is then a calm whose roughness is all in the BRDF, as at 0.
        let k_lo = spectrum.dispersion().wavenumber(0.5 * spectrum.peak_omega());
        (k_lo < std::f64::consts::TAU / SHORTEST_WAVE_M).then_some(spectrum)
    } else {
        None
    };
    if let Some(spectrum) = wind_sea {
        let wp = spectrum.peak_omega();
        k_cox_munk = slope_cutoff(spectrum.as_ref(), s.wind_speed_m_s)?;
        // The fitted band ends at 12 ω_p, or sooner where the spectrum reaches Cox & Munk's total.
        let top = (spectrum.dispersion().omega(k_cox_munk) / wp).min(sea_options.omega_max_factor);
        sea_options.omega_max_factor = top.max(2.0 * sea_options.omega_min_factor);
        let spreading: Box<dyn Spreading> = match (s.spreading, s.spectrum) {
            (SpreadingKind::Auto, SpectrumKind::Elfouhaily) | (SpreadingKind::Elfouhaily, _) => {
                let e = match s.fetch_km {
                    Some(f) => Elfouhaily::from_fetch(s.wind_speed_m_s, f * 1000.0),
                    None => Elfouhaily::new(s.wind_speed_m_s, 0.84),
                }?;
                Box::new(e.spreading(Directions::Downwind))
            }
            (SpreadingKind::Auto | SpreadingKind::Cos2s, _) => Box::new(CosineTwoS::hasselmann(wp)?),
            (SpreadingKind::Mitsuyasu, _) => Box::new(CosineTwoS::mitsuyasu(wp, s.wind_speed_m_s)?),
            (SpreadingKind::DonelanBanner, _) => Box::new(DonelanBanner::new(wp)?),
            (SpreadingKind::CosSquared, _) => Box::new(CosineSquared::downwind()),
        };
        spectra.push(spectrum);
        spreadings.push(spreading);
        counts.push(s.wave_count() as usize);
        options.push(sea_options);
    }
    let drawn_wind_sea = !spectra.is_empty();
    if let Some(w) = &s.swell {
        let (spectrum, spreading) = swell_spectrum(w)?;
        spectra.push(Box::new(spectrum));
        spreadings.push(Box::new(spreading));
        counts.push(w.waves as usize);
        options.push(FitOptions {
            wind_direction: w.direction_deg.to_radians(),
            omega_max_factor: FitOptions::default().omega_max_factor,
            ..sea_options
        });
    }
    Ok(SeaSpectra { spectra, spreadings, counts, options, k_cox_munk, wind_sea: drawn_wind_sea })
}

/// The wind sea (and swell) of `[sea]` as one trochoid set, fitted under one steepness cap
/// (Thon & Ghazanfarpour 2002 as in Darles et al. 2007 §3; brine-waves `fit_sea_state`).
pub(super) fn fit_sea(s: &SeaConfig) -> Result<TrochoidSet, WorldError> {
    let SeaSpectra { spectra, spreadings, counts, options, .. } = sea_spectra(s, false)?;
    if spectra.is_empty() {
        return Ok(TrochoidSet::default());
    }
    let sea_options = options[0];
    let components: Vec<SeaComponent<'_>> = (0..spectra.len())
        .map(|i| SeaComponent {
            spectrum: spectra[i].as_ref(),
            spreading: spreadings[i].as_ref(),
            n_waves: counts[i],
            options: options[i],
        })
        .collect();
    Ok(fit_sea_state(&components, s.seed, sea_options.max_total_steepness, SteepnessLimit::ScaleAll)?)
}

/// The sea (and swell) of `[sea]` as Tessendorf's FFT cascades and their frame at the frame's
/// time, or `None` for a flat calm (brine-waves `FftOcean`).
pub(super) fn fft_sea(s: &SeaConfig, lattice: Option<&TileLattice>) -> Result<Option<FftOcean>, WorldError> {
    let SeaSpectra { spectra, spreadings, options, k_cox_munk, .. } = sea_spectra(s, true)?;
    if spectra.is_empty() {
        return Ok(None);
    }
    let wind = options[0].wind_direction;
    let directions: Vec<f64> = options.iter().map(|o| o.wind_direction).collect();
    let summed = SummedSpectrum::new(&spectra, &spreadings, &directions);
    let f = &s.fft;
    let mut fft_options = FftOptions {
        resolution: f.resolution as usize,
        choppiness: f.choppiness,
        loop_period: f.loop_period_s,
        seed: s.seed,
        wind_direction: wind,
        tiled: !f.blend,
        ..FftOptions::for_spectrum(&summed, f.cascades as usize)
    };
    if let Some(l) = lattice {
        fft_options.tile_sizes = l.commensurate_tiles(&fft_options.tile_sizes);
        fft_options.loop_period = l.loop_period_s().or(fft_options.loop_period);
        fft_options.tiled = true;
    }
    // No cascade draws waves beyond the one where the wind sea reaches Cox & Munk's total.
    let drawn = BandLimited::between_wavenumbers(&summed, 0.0, k_cox_munk);
    Ok(Some(FftOcean::new(&drawn, &summed, &fft_options)?))
}

/// A swell: brine-waves `Jonswap::swell` (its significant height and peak period) with a
/// constant-`s` cos-2s spreading.
pub(super) fn swell_spectrum(w: &SwellConfig) -> Result<(Jonswap, CosineTwoS), brine_waves::WaveError> {
    Ok((Jonswap::swell(w.significant_height_m, w.peak_period_s, w.gamma)?, CosineTwoS::constant(w.spreading_s)?))
}

/// Height and slope statistics of the traced sea, for the BRDF's unresolved variance and the foam.
pub(super) struct SeaStatistics {
    /// No waves at all (a flat calm).
    pub(super) flat: bool,
    /// Slope variance of the traced waves along the wind (dimensionless).
    pub(super) slope_along: f64,
    /// Slope variance across the wind (dimensionless).
    pub(super) slope_across: f64,
    /// Height range, height deviation and slope variances along the world axes, for the foam.
    pub(super) surface: SurfaceStatistics,
}

/// Statistics of the sea: of the trochoid set, or the expected ones of the FFT cascades
/// (`½ Σ |a|²` of the drawn spectrum), with the frame's exact height bounds.
pub(super) fn sea_statistics(set: &TrochoidSet, sea: &SeaFrame, wind_angle: f64) -> SeaStatistics {
    if let FrameSurface::Fft(frame) = sea.surface() {
        let c: DVec3 = frame.cascades().iter().map(|c| c.expected_slope_covariance()).sum();
        let variance: f64 = frame.cascades().iter().map(|c| c.expected_variance()).sum();
        let (wx, wz) = (wind_angle.cos(), wind_angle.sin());
        let along = c.x * wx * wx + 2.0 * c.y * wx * wz + c.z * wz * wz;
        let across = c.x * wz * wz - 2.0 * c.y * wx * wz + c.z * wx * wx;
        let (y_min, y_max) = frame.height_bounds();
        return SeaStatistics {
            flat: !(variance > 0.0),
            slope_along: along.max(0.0),
            slope_across: across.max(0.0),
            surface: SurfaceStatistics {
                y_min,
                y_max: y_max.max(y_min + 1e-9),
                height_std: variance.sqrt(),
                slope_variance_x: c.x.clamp(0.0, 10.0),
                slope_variance_z: c.z.clamp(0.0, 10.0),
            },
        };
    }
    set_statistics(set, wind_angle)
}

/// The statistics of a fitted wave set (trochoid, Gerstner or sine sea), whatever the instant.
pub(super) fn set_statistics(set: &TrochoidSet, wind_angle: f64) -> SeaStatistics {
    let (rx, ry) = set.slope_variances(wind_angle);
    let (sx, sz) = set.slope_variances(0.0);
    SeaStatistics {
        flat: set.is_empty(),
        slope_along: rx,
        slope_across: ry,
        surface: SurfaceStatistics {
            y_min: -set.total_amplitude(),
            y_max: set.total_amplitude(),
            height_std: set.variance().sqrt(),
            slope_variance_x: sx.min(10.0),
            slope_variance_z: sz.min(10.0),
        },
    }
}

/// The detail waves of a fitted sea: the wind sea's directional spectrum from the top of the
/// fitted band up to where the traced and detail slopes together reach Cox & Munk's total (or the
/// 1 cm wave), `None` when the traced waves already hold it all.
pub(super) fn detail_waves(
    s: &SeaConfig,
    stats: &SeaStatistics,
    total: &SlopeVariance,
) -> Result<Option<DetailWaves>, WorldError> {
    if stats.flat || s.wind_speed_m_s <= 0.0 || s.wave_count() == 0 {
        return Ok(None);
    }
    let SeaSpectra { spectra, spreadings, options, wind_sea, .. } = sea_spectra(s, false)?;
    if !wind_sea {
        return Ok(None);
    }
    let (spectrum, spreading, o) = (spectra[0].as_ref(), spreadings[0].as_ref(), options[0]);
    let k_lo = spectrum.dispersion().wavenumber(o.omega_max_factor * spectrum.peak_omega());
    let target = total.sigma_x2() + total.sigma_y2() - stats.slope_along - stats.slope_across;
    let Some(band) = DetailOptions::for_band(spectrum, k_lo, target) else {
        return Ok(None);
    };
    let band = DetailOptions { seed: s.seed, wind_direction: o.wind_direction, ..band };
    Ok(Some(DetailWaves::new(spectrum, spreading, &band)?))
}

/// The trochoid sea's waves split for the grids its shorter ones are traced on (brine-waves
/// `BandedTrochoids::default_layout`), as `sea.grid` asks: `auto` from
/// [`crate::scene::GRID_AUTO_WAVES`] waves up, where the layout holds; `None` otherwise (a calm,
/// with no wave, has nothing to split whatever the key).
///
/// # Arguments
/// - `s`: the scene's `[sea]`; `set`: its fitted waves (not yet snapped).
///
/// # Errors
/// [`WorldError::Scene`] for `grid = "on"` with a set the layout cannot split (too few waves, or
/// all of one length); [`WorldError`] if the split refuses the layout.
pub(super) fn banded_trochoids(s: &SeaConfig, set: &TrochoidSet) -> Result<Option<BandedTrochoids>, WorldError> {
    let wanted = match s.grid {
        GridMode::Off => false,
        GridMode::On => true,
        GridMode::Auto => s.wave_count() >= crate::scene::GRID_AUTO_WAVES,
    };
    if !wanted || set.is_empty() {
        return Ok(None);
    }
    match BandedTrochoids::default_layout(set) {
        // `auto` is a speed-up: a split the model refuses keeps every wave traced.
        Some(layout) if s.grid == GridMode::Auto => Ok(BandedTrochoids::new(set, &layout).ok()),
        Some(layout) => Ok(Some(BandedTrochoids::new(set, &layout)?)),
        None if s.grid == GridMode::On => Err(WorldError::Scene(format!(
            "sea.grid = \"on\": the {} waves cannot be split into grids and waves traced as trochoids (too few, or too close in length); use \"auto\" or \"off\"",
            set.len()
        ))),
        None => Ok(None),
    }
}
