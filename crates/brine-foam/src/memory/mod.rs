//! White water with a memory: active whitecaps leave foam on the water, which drifts, breaks
//! into patches and streaks, and decays.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{FoamError, check};
use crate::lace::{FoamLace, LACE_CELL_M};
use crate::noise::{FoamNoise, smoothstep};
pub use crate::tiling::{PeriodicPatches, periodic_patches};
use crate::windrows::{
    QUANTILE_SAMPLES, StretchedUniform, WINDROW_SHARE, WINDROW_SPACING_M, WINDROW_STRETCH, Windrows,
};
use brine_core::footprint::EllipticalFootprint;

/// E-folding time of a whitecap's foam area in sea water, `τ = 3.85 s` (Monahan 1971; 2.54 s in
/// fresh water). Callaghan et al. (2012) measured 0.5–8 s for single whitecaps.
pub const MONAHAN_1971_DECAY_TIME_S: f64 = 3.85;

/// Wind drift of surface foam relative to the water's orbital motion, as a fraction of `U₁₀`:
/// about 3 % (Wu 1983).
pub const WIND_DRIFT_FRACTION: f64 = 0.03;

/// Aspect ratio (along / across the wind) of the foam patches at Beaufort 8 and above: Brine's
/// choice for "foam blown in well-marked streaks along the direction of the wind"; the Beaufort
/// descriptions give no number.
pub const STREAK_STRETCH: f64 = 6.0;

/// Winds (m s⁻¹) over which the patches stretch from round (Beaufort 6's upper end) to
/// [`STREAK_STRETCH`] (Beaufort 8's lower end): the Beaufort scale's "foam begins to be blown in
/// streaks" (Beaufort 7, 13.9–17.1 m s⁻¹).
pub const STREAK_WINDS_M_S: (f64, f64) = (12.0, 17.2);

/// Share of the water a breaking crest swept that its foam covers once the crest has passed,
/// `A₀` of the area law: foam left behind is a lace of bubbles rafts, never a sheet (Brine's
/// choice; the breaking crest itself is solid white).
pub const FOAM_DENSITY: f64 = 0.8;

/// Largest number of lattice instants a [`FoamMemory`] reads.
pub const MAX_MEMORY_INSTANTS: usize = 64;

/// Number of octaves of the patch noise and of the edge noise.
const NOISE_OCTAVES: u32 = 5;

/// Half-width of the survival step in the uniform patch variable, as a share of
/// `min(θ, 1 − θ)`: a patch's cover falls from full to none across the quantiles `θ ± ε`, so
/// residual foam thins toward its edges (drawn by the lace as filaments that break up) instead of
/// ending at a line. Brine's choice, from photographs of decaying whitecap foam, whose rafts fray
/// over a fringe a fraction of their size wide; the area mean stays `θ` because the step is
/// symmetric about it and stays inside `[0, 1]`.
pub const PATCH_FRINGE: f64 = 0.6;

/// Smallest half-width of the survival step (in the uniform patch variable): even the smallest
/// patches are smoothed over a little of the quantile instead of aliasing.
const MIN_EDGE_SOFTNESS: f64 = 0.002;

/// Clear share `1 − a′` below which a laced residual is scaled rather than solved from the union.
const WELL_CONDITIONED: f64 = 1e-6;

/// Survivals below this are skipped (the source is not evaluated there).
const NEGLIGIBLE_SURVIVAL: f64 = 1e-4;

/// Offset (m) of the lace that draws the foam's ageing from the one that draws its cover: a few
/// hundred first-octave cells, in no ratio to the cell, so that the two are independent.
const AGEING_LACE_OFFSET_M: [f64; 2] = [271.828_182_8, -314.159_265_4];

/// Parameters of the foam memory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoamMemoryParams {
    /// E-folding time `τ` of the foam area (s), `(0, 60]`; default
    /// [`MONAHAN_1971_DECAY_TIME_S`].
    pub decay_time_s: f64,
    /// Spacing `Δt` of the global time lattice at which past breaking is read (s),
    /// `(0, decay_time_s]`; default 0.5 s.
    pub step_s: f64,
    /// Length of the memory in decay times `T/τ`, `[1, 5]`; default 2 (foam older than `2τ` keeps
    /// 14 % of its area and fades out over the last step).
    pub length_in_decay_times: f64,
    /// Drift of the foam relative to the water particles `(v_x, v_z)` (m s⁻¹), each within ±5;
    /// see [`FoamMemoryParams::for_wind`].
    pub drift_m_s: [f64; 2],
    /// Wavelength of the first octave of the patch noise across the wind (m), `(0, 10⁴]`.
    pub patch_wavelength_m: f64,
    /// Stretch of the patches along the wind, `[1, 20]` (1: round patches).
    pub streak_stretch: f64,
    /// Direction the wind blows toward, from +x toward +z (rad), finite.
    pub wind_direction_rad: f64,
    /// Wavelength of the first octave of the edge noise (m), `(0, 10⁴]`.
    pub edge_wavelength_m: f64,
    /// Share of the mean white cover held in foam streaks along the wind ([`Windrows`]),
    /// `[0, 1)`; default 0 (none), [`WINDROW_SHARE`] from Beaufort 8 in
    /// [`FoamMemoryParams::for_wind`].
    pub windrow_share: f64,
    /// First-octave cell of the lace the foam is drawn as ([`FoamLace`], m), `[0, 100]`;
    /// 0 draws the cover as a veil of its opacity. Default [`LACE_CELL_M`].
    pub lace_cell_m: f64,
    /// Seed of the noises.
    pub seed: u64,
    /// A square tile (m, `(0, 10⁶]`) over which the foam must repeat (a baked, tileable map), or
    /// `None`: the noises' wavelengths, stretch and direction are then moved to the nearest ones
    /// that repeat over it ([`periodic_patches`]).
    pub tile_m: Option<f64>,
}

impl Default for FoamMemoryParams {
    fn default() -> Self {
        Self {
            decay_time_s: MONAHAN_1971_DECAY_TIME_S,
            step_s: 0.25,
            length_in_decay_times: 1.5,
            drift_m_s: [0.0, 0.0],
            patch_wavelength_m: 4.0,
            streak_stretch: 1.0,
            wind_direction_rad: 0.0,
            edge_wavelength_m: 1.0,
            windrow_share: 0.0,
            lace_cell_m: LACE_CELL_M,
            seed: 1,
            tile_m: None,
        }
    }
}

impl FoamMemoryParams {
    /// The defaults for a wind of `u10` (m s⁻¹, `[0, 60]`) blowing toward `direction_rad`: a drift
    /// of [`WIND_DRIFT_FRACTION`] `U₁₀` downwind and patches stretched along the wind from
    /// round below 12 m s⁻¹ to [`STREAK_STRETCH`] from 17.2 m s⁻¹, and [`WINDROW_SHARE`] of the
    /// white cover in foam streaks along the wind from 17.2 m s⁻¹ (smoothstep between for both).
    ///
    /// # References
    /// Wu J. 1983, "Sea-surface drift currents induced by wind and waves", JPO 13:1441–1451;
    /// the Beaufort scale's sea-state descriptions (WMO No. 8).
    pub fn for_wind(u10: f64, direction_rad: f64, seed: u64) -> Self {
        let drift = WIND_DRIFT_FRACTION * u10;
        let streaky = smoothstep(STREAK_WINDS_M_S.0, STREAK_WINDS_M_S.1, u10);
        Self {
            drift_m_s: [drift * direction_rad.cos(), drift * direction_rad.sin()],
            streak_stretch: 1.0 + (STREAK_STRETCH - 1.0) * streaky,
            windrow_share: WINDROW_SHARE * streaky,
            wind_direction_rad: direction_rad,
            seed,
            ..Self::default()
        }
    }
}

/// One past instant of the memory ([`FoamMemory::compose`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemorySample {
    /// Index of the instant, 0 the newest.
    pub index: usize,
    /// The lattice instant `tⱼ = Δt(⌊t/Δt⌋ − j)` (s).
    pub time_s: f64,
    /// Age of foam made then, `aⱼ = t − tⱼ` (s).
    pub age_s: f64,
    /// Offset to add to the current point's rest coordinates to find where that foam was made,
    /// `−v aⱼ` (m).
    pub rest_offset_m: [f64; 2],
    /// Share of that foam still there, `Sⱼ ∈ [0, 1]`.
    pub survival: f64,
}

/// White water at one point: the active whitecap, the foam it left, and the two together.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WhiteWater {
    /// Cover of actively breaking water (stage A), `[0, 1]`.
    pub active: f64,
    /// Cover of the foam left behind (stage B), `[0, 1]`.
    pub residual: f64,
    /// White cover `1 − (1 − active)(1 − residual)`, `[0, 1]`.
    pub white: f64,
    /// Reflectance of the white water relative to the mean of fresh foam, `(0, 1]`, up to
    /// `1 +` [`crate::LACE_THICKNESS_CONTRAST`] where thick foam in a lace is brighter than the mean (1
    /// where there is none). Where it is below 1 the water shows through (ageing foam thins).
    pub brightness: f64,
}

/// Foam that remembers: a stateless function of the rest position and the time.
///
/// A breaking crest (an active whitecap, stage A of Monahan & Lu 1990) covers the water it passes
/// with foam; once the crest has gone the foam (stage B) drifts with the surface and its area
/// decays exponentially, `A(a) = A₀ e^{−a/τ}` (Monahan 1971, Callaghan et al. 2012). Brine makes
/// that decay a shape: the foam of age `a` survives where a uniform patch variable `m(u)` carried
/// by the water is below `e^{−a/τ}`, so the foam of one breaking event shrinks into patches and
/// threads with exactly the exponential area law, and a still is the state reached from the past:
///
/// `residual(u, t) = 1 − Πⱼ (1 − Aⱼ Sⱼ)`, `Aⱼ = A(u − v aⱼ, tⱼ)`, `Sⱼ = S(m(u), aⱼ)`,
///
/// over the instants `tⱼ` of a global lattice of step `Δt` and ages `aⱼ = t − tⱼ ≤ T`, where `A`
/// is the active cover (the caller's source, e.g. Dupuy & Bruneton's Jacobian whitecaps), `v` the
/// drift of the foam relative to the water (wind drift), and
///
/// `S(m, a) = (1 − r) · smoothstep(θ + ε, θ − ε, m) + r θ`, `θ(a) = A₀ e^{−a/τ} min(1, (T − a)/Δt)`,
///
/// with `r` the share of the patch noise that the pixel footprint does not resolve (a far pixel
/// sees the mean survival, a near one the patches) and `ε = 0.6 min(θ, 1 − θ)` the half-width of
/// the patches' fringe ([`PATCH_FRINGE`]): a patch is full in its core and thins across a fringe
/// whose width grows and shrinks with the patch, so that residual foam frays at its edges (the
/// lace draws the thin cover there as broken filaments) instead of ending at a line. Both terms
/// have area mean `θ`, so the filtering keeps the mean foam at every distance. `m = F(g)` is the
/// empirical distribution function of a gradient-noise fBm `g` (tabulated in the constructor,
/// so `m` is uniform to sampling), evaluated in coordinates stretched along the wind by
/// `streak_stretch`: foam streaks along the wind. The brightness of foam of age `a` relative
/// to fresh foam is `e^{−a/τ_R}`, `τ_R = τ f_ef/(1 − f_ef)`, so that the area-weighted mean over
/// the exponential age distribution of the residual foam is Koepke's efficiency `f_ef`.
///
/// Active whitecaps are given a lacy edge by [`FoamMemory::edge_noise`], a zero-mean noise of
/// unit variance carried by the water, which the caller adds (scaled) to the breaking variable.
///
/// Because every term is a function of `(u, t)` on a global lattice, frame `k` is the same alone,
/// in a sequence or resumed, at any thread count. The approximation: the rest position of a hit
/// is the caller's (the renderer takes the displaced position); the source is read at the
/// lattice instants only, so a crest moving faster than its width per `Δt` leaves a dotted trail.
///
/// # References
/// Monahan E. C. 1971, "Oceanic whitecaps", JPO 1:139–144 (decay time 3.85 s); Monahan E. C.,
/// Lu M. 1990, IEEE J. Oceanic Eng. 15(4):340–349 (stages A and B); Callaghan A. H., Deane G. B.,
/// Stokes M. D. 2012, JGR 117:C09015 (exponential area decay); Koepke P. 1984, Appl. Opt.
/// 23(11):1816–1824 (`f_ef`); Wu J. 1983, JPO 13:1441–1451 (wind drift).
#[derive(Debug, Clone, PartialEq)]
pub struct FoamMemory {
    tau: f64,
    tau_r: f64,
    step: f64,
    /// `e^{−Δt/τ}`, the area decay from one instant to the next.
    step_decay: f64,
    length: f64,
    count: usize,
    drift: [f64; 2],
    patches: StretchedUniform,
    edges: FoamNoise,
    edge_std: f64,
    windrow_share: f64,
    windrows: Option<Windrows>,
    lace: Option<FoamLace>,
}

impl FoamMemory {
    /// Checks the parameters and tabulates the distribution of the patch noise.
    ///
    /// # Arguments
    /// - `params`: [`FoamMemoryParams`].
    /// - `efficiency`: Koepke's `f_ef`, `(0, 1)` (0.4), for the brightness decay.
    ///
    /// # Errors
    /// [`FoamError::OutOfRange`] naming the first parameter out of its range.
    pub fn new(params: &FoamMemoryParams, efficiency: f64) -> Result<Self, FoamError> {
        let (tau, step, ratio) = crate::history::check_lattice(
            params.decay_time_s,
            params.step_s,
            (params.length_in_decay_times, (1.0, 5.0), "[1, 5]"),
            params.drift_m_s,
        )?;
        check("streak_stretch", params.streak_stretch, (1.0..=20.0).contains(&params.streak_stretch), "[1, 20]")?;
        check("wind_direction_rad", params.wind_direction_rad, true, "finite rad")?;
        check("efficiency", efficiency, efficiency > 0.0 && efficiency < 1.0, "(0, 1)")?;
        check("windrow_share", params.windrow_share, (0.0..1.0).contains(&params.windrow_share), "[0, 1)")?;
        check("lace_cell_m", params.lace_cell_m, (0.0..=100.0).contains(&params.lace_cell_m), "[0, 100] m")?;
        let lace = if params.lace_cell_m > 0.0 {
            Some(FoamLace::new(params.lace_cell_m, params.tile_m, params.seed ^ 0x1ace)?)
        } else {
            None
        };
        let count = (ratio * tau / step).ceil() as usize + 1;
        if count > MAX_MEMORY_INSTANTS {
            return Err(FoamError::OutOfRange(brine_core::OutOfRange {
                name: "step_s",
                value: step,
                range: "at least length_in_decay_times · decay_time_s / 63 s (at most 64 instants)",
            }));
        }
        let mut patches = FoamNoise::new(1.0, params.patch_wavelength_m, NOISE_OCTAVES, params.seed)?;
        let mut edges = FoamNoise::new(1.0, params.edge_wavelength_m, NOISE_OCTAVES, params.seed ^ 0x5eed_ed9e)?;
        let wind = [params.wind_direction_rad.cos(), params.wind_direction_rad.sin()];
        let (mut along, mut stretch) = (wind, params.streak_stretch);
        let (mut windrow_along, mut windrow_spacing, mut windrow_stretch, mut windrow_period) =
            (wind, WINDROW_SPACING_M, WINDROW_STRETCH, None);
        if let Some(tile) = params.tile_m {
            check("tile_m", tile, tile > 0.0 && tile <= 1e6, "(0, 1e6] m")?;
            let p = periodic_patches(tile, params.patch_wavelength_m, params.streak_stretch, params.wind_direction_rad);
            let r = (p.m * p.m + p.n * p.n) as f64;
            along = [p.m as f64 / r.sqrt(), p.n as f64 / r.sqrt()];
            stretch = p.g as f64 / p.stretch_divisor as f64;
            patches = FoamNoise::new(1.0, tile / (p.g as f64 * r.sqrt()), NOISE_OCTAVES, params.seed)?
                .periodic([p.m * p.stretch_divisor, -p.g * p.n], [p.n * p.stretch_divisor, p.g * p.m])?;
            let cells = (tile / params.edge_wavelength_m).round().max(1.0);
            edges = FoamNoise::new(1.0, tile / cells, NOISE_OCTAVES, params.seed ^ 0x5eed_ed9e)?
                .periodic([cells as i64, 0], [0, cells as i64])?;
            let w = periodic_patches(tile, WINDROW_SPACING_M, WINDROW_STRETCH, params.wind_direction_rad);
            let r = ((w.m * w.m + w.n * w.n) as f64).sqrt();
            windrow_along = [w.m as f64 / r, w.n as f64 / r];
            windrow_spacing = tile / (w.g as f64 * r);
            windrow_stretch = w.g as f64 / w.stretch_divisor as f64;
            windrow_period = Some(([w.m * w.stretch_divisor, -w.g * w.n], [w.n * w.stretch_divisor, w.g * w.m]));
        }
        // The empirical distribution of the patch noise and the standard deviation of the edge
        // noise, from the same deterministic points spread over many first-octave cells.
        let mut rng = ChaCha8Rng::seed_from_u64(params.seed ^ 0x0a11_7e57);
        let span = 200.0 * params.patch_wavelength_m.max(params.edge_wavelength_m) * stretch;
        let points: Vec<(f64, f64)> =
            (0..QUANTILE_SAMPLES).map(|_| (rng.random_range(-span..span), rng.random_range(-span..span))).collect();
        let mut patches = StretchedUniform::new(patches, along, stretch);
        patches.tabulate(&points);
        let e2: f64 = points
            .iter()
            .map(|&(x, z)| {
                let e = edges.value(x, z, 0.0) - 1.0;
                e * e
            })
            .sum();
        let windrows = if params.windrow_share > 0.0 {
            Some(Windrows::new(
                windrow_spacing,
                windrow_stretch,
                windrow_along,
                windrow_period,
                efficiency,
                params.seed,
            )?)
        } else {
            None
        };
        Ok(Self {
            tau,
            tau_r: tau * efficiency / (1.0 - efficiency),
            step,
            step_decay: libm::exp(-step / tau),
            length: step * (count - 1) as f64,
            count,
            drift: params.drift_m_s,
            patches,
            edges,
            edge_std: (e2 / QUANTILE_SAMPLES as f64).sqrt().max(f64::MIN_POSITIVE),
            windrow_share: params.windrow_share,
            windrows,
            lace,
        })
    }

    /// Share of the mean white cover held in foam streaks along the wind (0: none).
    pub fn windrow_share(&self) -> f64 {
        self.windrow_share
    }

    /// The foam streaks along the wind, when the share is above 0.
    pub fn windrows(&self) -> Option<&Windrows> {
        self.windrows.as_ref()
    }

    /// White water with the foam streaks of cover `c` (from [`Windrows::cover`]) added as old
    /// foam: `residual′ = 1 − (1 − residual)(1 − c)`, `white′ = 1 − (1 − white)(1 − c)`, the
    /// brightness their cover-weighted mean.
    ///
    /// # Arguments
    /// - `ww`: the white water without the streaks; `cover`: `c ∈ [0, 1]`.
    pub fn with_windrows(&self, ww: WhiteWater, cover: f64) -> WhiteWater {
        let Some(w) = &self.windrows else { return ww };
        if cover <= 0.0 {
            return ww;
        }
        let c = cover.clamp(0.0, 1.0);
        let added = (1.0 - ww.white) * c;
        let white = ww.white + added;
        let brightness = if white > 0.0 { (ww.white * ww.brightness + added * w.brightness()) / white } else { 1.0 };
        // A weighted mean of two brightnesses in [0, 1]: the clamp below absorbs rounding only.
        debug_assert!(brightness <= ww.brightness.max(w.brightness()) + 1e-12, "brightness {brightness}");
        WhiteWater {
            active: ww.active,
            residual: 1.0 - (1.0 - ww.residual) * (1.0 - c),
            white,
            brightness: brightness.clamp(0.0, 1.0),
        }
    }

    /// Cover of the foam streaks at rest position `(x, z)` for a Gaussian footprint `σ` (m) and
    /// mean cover `q` ([`Windrows::cover_with_density`]): lines of lace of density
    /// `1 − (1 − ρ) k_L(σ)` ([`crate::WINDROW_DENSITY`] where the lace's filaments are resolved,
    /// solid lines where they are not), 0 without streaks.
    pub fn windrow_cover(&self, x: f64, z: f64, sigma_m: f64, mean_cover: f64) -> f64 {
        let Some(w) = &self.windrows else { return 0.0 };
        let k = self.lace.as_ref().map_or(0.0, |l| l.resolved_share(sigma_m));
        w.cover_with_density(x, z, sigma_m, mean_cover, 1.0 - (1.0 - crate::WINDROW_DENSITY) * k)
    }

    /// The lace the white water is drawn as, when its cell is above 0.
    pub fn lace(&self) -> Option<&FoamLace> {
        self.lace.as_ref()
    }

    /// White water drawn as lace ([`FoamLace::cover_and_shade_over`]) at rest position `(x, z)`
    /// seen through a pixel footprint: the white cover `w` becomes `c`, of the same area mean; the active
    /// cover scales with it, `a′ = a c/w`, and the residual is what makes
    /// `1 − (1 − a′)(1 − residual′) = c` (where `a′` is within 10⁻⁶ of 1 the residual scales
    /// with `c/w` instead).
    ///
    /// The brightness `b` (Koepke's falling reflectance of ageing foam, over fresh foam's) is
    /// drawn as holes opening in the foam rather than as a uniform dimming: a second lace,
    /// independent of the first (a few hundred cells away), of cover `b`, so that where a
    /// pixel resolves it old foam is a net of bright filaments around open water and where it does
    /// not the pixel sees its local cover ([`FoamLace::local_cover`]; `b` itself where the
    /// footprint does not resolve that either). Both laces' thickness shading
    /// ([`FoamLace::cover_and_shade`], mean 1 over the foam) multiply the brightness. The area
    /// means of the cover and of `cover × brightness` are unchanged. Unchanged without a lace.
    /// Where the lace leaves open water (`c = 0`) the brightness is the mean's, `b`, and the
    /// second lace is not read (only its local cover, at the centre). Through an elliptical footprint both laces are read at its probes
    /// ([`FoamLace::cover_and_shade_over`]), the second only at those that hold foam, and the
    /// brightness is the foam-weighted mean of the probes'.
    pub fn laced(&self, ww: WhiteWater, x: f64, z: f64, footprint: &EllipticalFootprint) -> WhiteWater {
        let Some(lace) = &self.lace else { return ww };
        if ww.white <= 0.0 {
            return ww;
        }
        // Read at the footprint's probes along its long axis ([`FoamLace::cover_and_shade_over`]),
        // the ageing lace only at the probes that hold foam.
        let [dx, dz] = AGEING_LACE_OFFSET_M;
        let (sigma, major, b) = (footprint.minor_m(), footprint.major_m(), ww.brightness.clamp(0.0, 1.0));
        // Each lace's local cover, read once at the centre (it varies over cells).
        let (white, aged) = (lace.local_cover(x, z, major, ww.white), lace.local_cover(x + dx, z + dz, major, b));
        // Where both laces' features are wider than the footprint is long, its centre stands for
        // it (one probe).
        let whole = lace.draws_whole(major, white) && lace.draws_whole(major, aged);
        let centre = EllipticalFootprint::round(sigma);
        let footprint = if whole { &centre } else { footprint };
        let (mut cover, mut lit) = (0.0, 0.0);
        for o in footprint.offsets() {
            let (c, shade) = lace.laced_cover_and_shade(x + o.x, z + o.y, sigma, white);
            if c > 0.0 {
                let (thick, thick_shade) = lace.laced_cover_and_shade(x + o.x + dx, z + o.y + dz, sigma, aged);
                cover += c;
                lit += c * shade * thick * thick_shade;
            }
        }
        if cover <= 0.0 {
            // Open water between the filaments: no white, so no brightness to draw (the second
            // lace is not read; the brightness stays the mean's, as where there is no white).
            return WhiteWater { active: 0.0, residual: 0.0, white: 0.0, brightness: ww.brightness };
        }
        let c = cover / footprint.probes() as f64;
        let brightness = lit / cover;
        let active = (ww.active * c / ww.white).min(c);
        // `(c − a′)/(1 − a′)`; where the active cover is within 10⁻⁶ of 1 the union is white
        // whatever the residual, and the quotient is ill-conditioned: the residual scales.
        let residual = if 1.0 - active > WELL_CONDITIONED {
            ((c - active) / (1.0 - active)).clamp(0.0, 1.0)
        } else {
            (ww.residual * c / ww.white).min(1.0)
        };
        WhiteWater { active, residual, white: c, brightness }
    }

    /// `τ`, the decay time of the foam area (s).
    pub fn decay_time(&self) -> f64 {
        self.tau
    }

    /// `τ_R`, the decay time of the foam's brightness (s).
    pub fn brightness_decay_time(&self) -> f64 {
        self.tau_r
    }

    /// `T`, the age at which foam is dropped (s).
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Number of lattice instants read at most per point.
    pub fn sample_count(&self) -> usize {
        self.count
    }

    /// Unit-variance, zero-mean edge noise carried by the water at rest position `(x, z)` and the
    /// share of its variance the footprint keeps.
    ///
    /// # Arguments
    /// - `x`, `z`: rest position (m), finite.
    /// - `footprint_m`: pixel footprint `ℓ` (m), `≥ 0`.
    ///
    /// # Returns
    /// `(e, k)`: the resolved noise `e` (dimensionless; variance `k` over the sea) and `k ∈ [0, 1]`.
    /// A caller adding `σ_e e` to a Gaussian breaking variable adds `σ_e²(1 − k)` to its variance.
    pub fn edge_noise(&self, x: f64, z: f64, footprint_m: f64) -> (f64, f64) {
        debug_assert!(footprint_m >= 0.0);
        ((self.edges.value(x, z, footprint_m) - 1.0) / self.edge_std, self.edges.resolved_variance_share(footprint_m))
    }

    /// Spacing `Δt` of the lattice (s).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// Drift `v` of the foam relative to the water (m s⁻¹).
    pub fn drift(&self) -> [f64; 2] {
        self.drift
    }

    /// Lattice instant `j` before `t` and the age of its foam: `(tⱼ, aⱼ)` (s).
    pub fn instant(&self, t: f64, j: usize) -> (f64, f64) {
        let time_s = ((t / self.step).floor() - j as f64) * self.step;
        (time_s, (t - time_s).max(0.0))
    }

    /// Survivals `Sⱼ` of the foam of the lattice instants before `t` at rest position `u`, for a
    /// footprint `ℓ`: writes `out[j]` and returns how many instants can hold foam (those beyond
    /// are 0; at most `out.len()` and [`Self::sample_count`]).
    ///
    /// # Arguments
    /// - `u`: rest position (m); `t`: time (s); `footprint_m`: `ℓ` (m), `≥ 0`.
    /// - `out`: receives `Sⱼ ∈ [0, 1]`.
    pub fn survivals(&self, u: [f64; 2], t: f64, footprint_m: f64, out: &mut [f64]) -> usize {
        debug_assert!(t.is_finite() && footprint_m >= 0.0);
        self.survivals_from(self.thresholds(self.instant(t, 0).1), u, footprint_m, out)
    }

    /// [`Self::survivals`] at a time of `clock` (the same values, without the per-point
    /// exponential).
    pub fn survivals_at(&self, clock: &MemoryClock, u: [f64; 2], footprint_m: f64, out: &mut [f64]) -> usize {
        debug_assert!(footprint_m >= 0.0);
        self.survivals_from(clock.theta[..clock.count].iter().copied(), u, footprint_m, out)
    }

    /// The survival thresholds `θⱼ = ρ e^{−aⱼ/τ} min(1, (T − aⱼ)/Δt)` (0 past the memory's
    /// length `T`) of the instants whose newest is `a₀` old (s), newest first.
    fn thresholds(&self, a0: f64) -> impl Iterator<Item = f64> + '_ {
        // e^{−aⱼ/τ} by recurrence: aⱼ = a₀ + jΔt.
        (0..self.count).scan(libm::exp(-a0 / self.tau), move |decay, j| {
            let age = a0 + j as f64 * self.step;
            let theta = if age <= self.length {
                FOAM_DENSITY * *decay * ((self.length - age) / self.step).min(1.0)
            } else {
                0.0
            };
            *decay *= self.step_decay;
            Some(theta)
        })
    }

    /// The survivals for the thresholds `θⱼ` ([`Self::thresholds`]).
    fn survivals_from(
        &self,
        thetas: impl Iterator<Item = f64>,
        u: [f64; 2],
        footprint_m: f64,
        out: &mut [f64],
    ) -> usize {
        let r = 1.0 - self.patches.resolved_share(footprint_m);
        let m = self.patches.at(u[0], u[1], footprint_m);
        let mut used = 0;
        for (j, theta) in thetas.take(out.len()).enumerate() {
            let survival = (1.0 - r) * survival_step(theta, m) + r * theta;
            out[j] = if survival < NEGLIGIBLE_SURVIVAL { 0.0 } else { survival };
            if out[j] > 0.0 {
                used = j + 1;
            } else if r <= 0.0 && j > 0 && theta + patch_fringe(theta) < m {
                break; // Older foam has a lower threshold still.
            }
        }
        used
    }

    /// The memory seen from time `t` (s, finite): what [`Self::survivals_at`] and
    /// [`Self::combine_at`] share between every point at that time — and at every time whose
    /// newest lattice instant is as old ([`MemoryClock::holds`]).
    pub fn clock(&self, t: f64) -> MemoryClock {
        debug_assert!(t.is_finite());
        let age0_s = self.instant(t, 0).1;
        let mut clock = MemoryClock {
            age0_s,
            count: self.count,
            theta: [0.0; MAX_MEMORY_INSTANTS],
            brightness: [0.0; MAX_MEMORY_INSTANTS],
        };
        for (j, theta) in self.thresholds(age0_s).enumerate() {
            clock.theta[j] = theta;
            clock.brightness[j] = self.brightness(age0_s, j);
        }
        clock
    }

    /// `e^{−aⱼ/τ_R}`, `aⱼ = a₀ + jΔt`: the brightness of the foam of instant `j` when the newest
    /// is `a₀` old (s).
    fn brightness(&self, a0: f64, j: usize) -> f64 {
        libm::exp(-(a0 + j as f64 * self.step) / self.tau_r)
    }

    /// White water from the active cover now and at the lattice instants.
    ///
    /// # Arguments
    /// - `t`: time (s).
    /// - `active`: active cover now, `[0, 1]`.
    /// - `survivals`: `Sⱼ` of [`Self::survivals`].
    /// - `sources`: the active cover `Aⱼ` at instant `j` where the foam now at the point was then
    ///   (`u − v aⱼ`), same length as `survivals`, `[0, 1]`.
    ///
    /// # Returns
    /// [`WhiteWater`]: `residual = 1 − Πⱼ(1 − AⱼSⱼ)`, `white = 1 − (1 − active)(1 − residual)`.
    pub fn combine(&self, t: f64, active: f64, survivals: &[f64], sources: &[f64]) -> WhiteWater {
        let a0 = self.instant(t, 0).1;
        self.combine_with(|j| self.brightness(a0, j), active, survivals, sources)
    }

    /// [`Self::combine`] at a time of `clock`.
    pub fn combine_at(&self, clock: &MemoryClock, active: f64, survivals: &[f64], sources: &[f64]) -> WhiteWater {
        self.combine_with(|j| clock.brightness[j], active, survivals, sources)
    }

    fn combine_with(
        &self,
        brightness: impl Fn(usize) -> f64,
        active: f64,
        survivals: &[f64],
        sources: &[f64],
    ) -> WhiteWater {
        debug_assert_eq!(survivals.len(), sources.len());
        let active = active.clamp(0.0, 1.0);
        let (mut clear, mut bright) = (1.0, 0.0);
        for (j, (&s, &a)) in survivals.iter().zip(sources).enumerate() {
            let c = (a.clamp(0.0, 1.0) * s).min(1.0);
            if c > 0.0 {
                bright += clear * c * brightness(j);
                clear *= 1.0 - c;
            }
        }
        let residual = 1.0 - clear;
        let white = 1.0 - (1.0 - active) * clear;
        // Fresh foam where active, the residual's own brightness elsewhere (`bright` is the
        // brightness-weighted union, `≤ residual`).
        let brightness = if white > 0.0 { (active + (1.0 - active) * bright) / white } else { 1.0 };
        WhiteWater { active, residual, white, brightness: brightness.clamp(0.0, 1.0) }
    }

    /// White water at rest position `u` and time `t`: the active cover now and the foam left by
    /// the active cover at the lattice instants, read from `past` (called only for instants whose
    /// foam can still be there).
    ///
    /// # Arguments
    /// - `u`: rest position `(x, z)` (m), finite.
    /// - `t`: time (s), finite.
    /// - `footprint_m`: pixel footprint `ℓ` (m), `≥ 0`.
    /// - `active`: active cover at `(u, t)`, `[0, 1]`.
    /// - `past`: the active cover at `(u + rest_offset, time_s)` of a [`MemorySample`], `[0, 1]`.
    ///
    /// # Returns
    /// [`WhiteWater`], as [`Self::combine`].
    pub fn compose(
        &self,
        u: [f64; 2],
        t: f64,
        footprint_m: f64,
        active: f64,
        mut past: impl FnMut(&MemorySample) -> f64,
    ) -> WhiteWater {
        let mut surv = [0.0; MAX_MEMORY_INSTANTS];
        let n = self.survivals(u, t, footprint_m, &mut surv);
        let mut src = [0.0; MAX_MEMORY_INSTANTS];
        for j in 0..n {
            if surv[j] > 0.0 {
                let (time_s, age_s) = self.instant(t, j);
                src[j] = past(&MemorySample {
                    index: j,
                    time_s,
                    age_s,
                    rest_offset_m: [-self.drift[0] * age_s, -self.drift[1] * age_s],
                    survival: surv[j],
                });
            }
        }
        self.combine(t, active, &surv[..n], &src[..n])
    }
}

/// The resolved survival `smoothstep(θ + ε, θ − ε, m)` of foam of threshold `θ` where the patch
/// variable is `m` (both in `[0, 1]`), `ε = ε(θ)` ([`patch_fringe`]): 1 in a patch's core, 0 outside,
/// falling across its fringe.
#[inline]
fn survival_step(theta: f64, m: f64) -> f64 {
    let e = patch_fringe(theta);
    smoothstep(theta + e, theta - e, m)
}

/// Half-width `ε(θ)` of the survival step at threshold `θ ∈ [0, 1]`: [`PATCH_FRINGE`]
/// `min(θ, 1 − θ)`, at least [`MIN_EDGE_SOFTNESS`] (which the area mean then tolerates only
/// where `θ` is within it of 0 or 1). `θ + ε(θ)` grows with `θ`, so older foam (a lower `θ`)
/// ends at a lower quantile.
#[inline]
fn patch_fringe(theta: f64) -> f64 {
    (PATCH_FRINGE * theta.min(1.0 - theta)).max(MIN_EDGE_SOFTNESS)
}

/// A [`FoamMemory`] seen from one time: each lattice instant's survival threshold and foam
/// brightness, the same for every point at that time ([`FoamMemory::clock`]); a frame computes
/// it once instead of once a pixel.
#[derive(Debug, Clone, PartialEq)]
pub struct MemoryClock {
    /// `a₀`, the age of the newest lattice instant (s): all the clock depends on.
    age0_s: f64,
    count: usize,
    theta: [f64; MAX_MEMORY_INSTANTS],
    brightness: [f64; MAX_MEMORY_INSTANTS],
}

impl MemoryClock {
    /// Whether the clock serves time `t` of `memory` (its newest lattice instant as old, bit for
    /// bit, as the one it was made for).
    pub fn holds(&self, memory: &FoamMemory, t: f64) -> bool {
        memory.instant(t, 0).1.to_bits() == self.age0_s.to_bits()
    }
}

/// The threshold `α` at which a white cover reaches its target, by bisection.
///
/// # Arguments
/// - `target`: the mean cover to reach, `[0, 1]`.
/// - `range`: `(lo, hi)` bracketing `α`, `lo < hi`.
/// - `tolerance`: the bracket width at which to stop, `> 0`.
/// - `mean_cover`: the mean cover at a threshold, non-decreasing in `α`.
///
/// # Returns
/// `α` within `tolerance` of the root (the end of the range when the target is out of reach).
pub fn calibrate_threshold(
    target: f64,
    range: (f64, f64),
    tolerance: f64,
    mut mean_cover: impl FnMut(f64) -> f64,
) -> f64 {
    debug_assert!(range.0 < range.1 && tolerance > 0.0);
    let (mut lo, mut hi) = range;
    while hi - lo > tolerance {
        let mid = 0.5 * (lo + hi);
        if mean_cover(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests;
