//! The sea frame as the tracer sees it ([`TracedSea`], feature `tracing`): each surface traced
//! by the method that certifies it.

use brine_trace::{Hit, Method, Ray, RayTile, TraceOptions, TraceStats};
use glam::{DVec2, DVec3};

use crate::{FftFrame, FrameSurface, GerstnerField, GriddedTrochoids, SeaFrame, SineField, TracedTrochoids};

/// A [`SeaFrame`] ready to trace: the Gerstner and sine sums frozen at the frame's time once
/// ([`SeaFrame::traced`]), each surface traced by the method that certifies it.
#[derive(Debug)]
pub enum TracedSea<'a> {
    /// Darles et al.'s trochoid sum (the tiered tracer, footprint fading, image coherence).
    Trochoids(&'a TracedTrochoids),
    /// The Gerstner sum at the frame's time.
    Gerstner(GerstnerField<'a>),
    /// The trochoid sum with its shorter waves on grids ([`GriddedTrochoids`]): traced through
    /// `grid`, shaded, faded and exported as the snapped waves `waves` it stands for.
    Gridded {
        /// The snapped waves at the frame's time ([`crate::BandedTrochoids::set`]).
        waves: &'a TracedTrochoids,
        /// The same sea with its shorter waves on grids, at the same time.
        grid: &'a GriddedTrochoids,
    },
    /// Chen et al.'s sine waves at the frame's time.
    Sine(SineField<'a>),
    /// The FFT cascades (the tiered tracer, one tier per cascade, image coherence).
    Fft(&'a FftFrame),
}

impl SeaFrame {
    /// The frame ready to trace ([`TracedSea`]); cheap (the Gerstner and sine sums' phase offsets).
    pub fn traced(&self) -> TracedSea<'_> {
        match &self.surface {
            FrameSurface::Trochoids(t) => TracedSea::Trochoids(t),
            FrameSurface::Gerstner(g) => TracedSea::Gerstner(g.at_time(self.time)),
            FrameSurface::Sine(s) => TracedSea::Sine(s.at_time(self.time)),
            FrameSurface::Fft(f) => TracedSea::Fft(f),
        }
    }

    /// The frame ready to trace through `grid`, the same sea with its shorter waves on grids
    /// ([`TracedSea::Gridded`]); the frame as [`Self::traced`] if it is not a trochoid sea.
    ///
    /// # Arguments
    /// - `grid`: built from the [`crate::BandedTrochoids`] whose set this frame's ocean holds, at
    ///   the frame's time.
    ///
    /// # Returns
    /// [`TracedSea::Gridded`] for a trochoid frame, else [`Self::traced`].
    pub fn traced_through<'a>(&'a self, grid: &'a GriddedTrochoids) -> TracedSea<'a> {
        debug_assert!(grid.time().to_bits() == self.time.to_bits(), "the grid's time is the frame's");
        match &self.surface {
            FrameSurface::Trochoids(waves) => TracedSea::Gridded { waves, grid },
            _ => self.traced(),
        }
    }
}

impl TracedSea<'_> {
    /// The options a surface is traced with: the trochoid and FFT seas always by
    /// [`Method::Tiered`] (their fast path), the Gerstner and sine sums by `options.method` (the
    /// tiered method too for footprint fading).
    fn options_for(&self, options: &TraceOptions) -> TraceOptions {
        match self {
            TracedSea::Trochoids(_) | TracedSea::Gridded { .. } | TracedSea::Fft(_) => {
                TraceOptions { method: Method::Tiered, ..*options }
            }
            _ => *options,
        }
    }

    /// The first crossing of `ray` with the surface, the waves fading with the pixel footprint
    /// `options.footprint_angle` (0 keeps every wave: secondary rays).
    ///
    /// # Arguments
    /// - `ray`: the ray; `options`: the tracer's options (see [`TracedSea`] for the method);
    ///   `stats`: receives the evaluations.
    ///
    /// # Returns
    /// The hit, or `None` within `options.t_max`.
    pub fn trace(&self, ray: &Ray, options: &TraceOptions, stats: &mut TraceStats) -> Option<Hit> {
        let o = self.options_for(options);
        match self {
            TracedSea::Trochoids(t) => brine_trace::trace(*t, ray, &o, stats),
            TracedSea::Gridded { grid, .. } => brine_trace::trace(*grid, ray, &o, stats),
            TracedSea::Gerstner(f) => brine_trace::trace(f, ray, &o, stats),
            TracedSea::Sine(f) => brine_trace::trace(f, ray, &o, stats),
            TracedSea::Fft(f) => brine_trace::trace(*f, ray, &o, stats),
        }
    }

    /// The primary rays of an image tile: the trochoid and FFT seas share cones among
    /// neighbouring rays (brine-trace `trace_tile`), the others trace ray by ray; `costs[i]`
    /// receives each ray's evaluations.
    ///
    /// # Arguments
    /// - `tile`: the rays ([`RayTile`]); `options`, `stats`: as [`TracedSea::trace`]; `hits`,
    ///   `costs`: one per direction.
    pub fn trace_tile(
        &self,
        tile: &RayTile<'_>,
        options: &TraceOptions,
        stats: &mut TraceStats,
        hits: &mut [Option<Hit>],
        costs: &mut [f64],
    ) {
        let o = self.options_for(options);
        let (origin, dirs) = (tile.origin, tile.directions);
        match self {
            TracedSea::Trochoids(t) => brine_trace::trace_tile(*t, tile, &o, stats, hits, Some(costs)),
            TracedSea::Gridded { grid, .. } => brine_trace::trace_tile(*grid, tile, &o, stats, hits, Some(costs)),
            TracedSea::Fft(f) => brine_trace::trace_tile(*f, tile, &o, stats, hits, Some(costs)),
            _ => {
                for (i, d) in dirs.iter().enumerate() {
                    let before = stats.evaluations;
                    hits[i] = Ray::new(origin, *d).ok().and_then(|ray| self.trace(&ray, options, stats));
                    costs[i] = (stats.evaluations - before) as f64;
                }
            }
        }
    }

    /// The height of the surface as drawn at `(x, z)` by a primary ray `t` metres along `d` with
    /// the waves faded by `footprint_angle` (0 keeps every wave): the surface the ray traced,
    /// which `brine mesh --camera --faded` exports (for [`TracedSea::Gridded`], the long waves
    /// faded one by one and each grid as a whole: [`GriddedTrochoids::faded_height`]).
    ///
    /// # Arguments
    /// - `x`, `z`: horizontal position (m); `d`: unit ray direction; `footprint_angle` (rad)
    ///   `≥ 0`; `t` (m) `≥ 0`.
    ///
    /// # Returns
    /// The height (m).
    ///
    /// # References
    /// Bruneton, Neyret & Holzschuch 2010 §4 (waves faded with the pixel footprint);
    /// docs/equations.md §1 and §1(b).
    pub fn faded_height(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> f64 {
        match self {
            TracedSea::Trochoids(s) => s.faded_height(x, z, d, footprint_angle, t),
            TracedSea::Gridded { grid, .. } => grid.faded_height(x, z, d, footprint_angle, t),
            TracedSea::Gerstner(f) => f.faded_height_along(x, z, d, footprint_angle, t),
            TracedSea::Sine(f) => f.faded_height(x, z, d, footprint_angle, t),
            TracedSea::Fft(f) => f.faded_height(x, z, d, footprint_angle, t),
        }
    }

    /// The gradient of the surface as drawn at `(x, z)`, hit `t` metres along `d` with the waves
    /// faded by `footprint_angle` (0 keeps every wave; the sine sea's detail waves left out).
    pub fn faded_gradient(&self, x: f64, z: f64, d: DVec3, footprint_angle: f64, t: f64) -> DVec2 {
        match self {
            TracedSea::Trochoids(s) | TracedSea::Gridded { waves: s, .. } => {
                s.faded_gradient(x, z, d, footprint_angle, t)
            }
            TracedSea::Gerstner(f) => f.faded_gradient(x, z, d, footprint_angle, t),
            TracedSea::Sine(f) => f.faded_gradient(x, z, d, footprint_angle, t),
            TracedSea::Fft(f) => f.faded_gradient(x, z, d, footprint_angle, t),
        }
    }

    /// The shading gradient at a primary hit and the world-axes covariance `(xx, xz, zz)` of the
    /// slopes the fading removed (they go to the BRDF: Bruneton et al. 2010's seamless
    /// transition), in one pass over the waves where the surface allows it; the sine sea's
    /// bump-mapped detail waves included, faded as the geometric ones.
    ///
    /// # Arguments
    /// As [`TracedSea::faded_gradient`].
    ///
    /// # Returns
    /// `(∇h, c)` (dimensionless).
    pub fn faded_gradient_and_covariance(
        &self,
        x: f64,
        z: f64,
        d: DVec3,
        footprint_angle: f64,
        t: f64,
    ) -> (DVec2, DVec3) {
        match self {
            TracedSea::Trochoids(s) | TracedSea::Gridded { waves: s, .. } => {
                s.faded_gradient_and_covariance(x, z, d, footprint_angle, t)
            }
            TracedSea::Gerstner(f) => {
                (f.faded_gradient(x, z, d, footprint_angle, t), f.faded_slope_covariance(d, footprint_angle, t))
            }
            TracedSea::Sine(f) => {
                let (gd, cd) = f.faded_detail(x, z, d, footprint_angle, t);
                (
                    f.faded_gradient(x, z, d, footprint_angle, t) + gd,
                    f.faded_slope_covariance(d, footprint_angle, t) + cd,
                )
            }
            TracedSea::Fft(f) => {
                (f.faded_gradient(x, z, d, footprint_angle, t), f.faded_slope_covariance(d, footprint_angle, t))
            }
        }
    }
}
