//! Image and temporal coherence (Darles et al. 2007 §3.3).

use glam::DVec3;

use crate::{Hit, LipschitzSum, Ray, RaySpan, TraceOptions, TraceStats, trace};

/// The primary rays of an image tile: from `origin` (m), unit `directions` row by row, `width`
/// per row (dividing `directions.len()`).
#[derive(Debug, Clone, Copy)]
pub struct RayTile<'a> {
    /// The eye (m).
    pub origin: DVec3,
    /// Unit directions, row-major.
    pub directions: &'a [DVec3],
    /// Rays per row.
    pub width: usize,
}

/// Nodes with at most this many rays trace their rays one by one (a cone costs about as much as
/// the steps it saves for fewer rays).
pub const MIN_CONE_RAYS: usize = 4;

/// Traces a tile of primary rays that share one origin, with image coherence: a quadtree of cones.
///
/// The tile's rays (row-major, `width` per row) are split recursively into quarters. Each node
/// traces the cone around its mean direction that contains all its rays
/// ([`LipschitzSum::certify_cone`]): the distance `t_c` it certifies free for every ray of the node
/// is where its four children start, down to nodes of [`MIN_CONE_RAYS`] rays, whose rays are traced
/// from their node's `t_c` by [`trace`] with `options.method`. The spheres of one cone are thus
/// shared by all the rays below it in the quadtree, the image-space form of the sphere quadtree
/// of Darles et al. (their Fig. 3); the hits are those of [`trace`] on each ray alone.
///
/// # Arguments
/// - `surface`: the implicit function.
/// - `tile`: the rays ([`RayTile`]: the common origin, the directions row by row, `width ≥ 1`
///   per row).
/// - `options`: as [`trace`].
/// - `stats`: counters (cone evaluations included).
/// - `hits`: receives the hit of each ray (same length as `directions`).
/// - `costs`: if given, receives the evaluations spent per ray, cones shared equally among the rays
///   below them.
///
/// # References
/// Darles et al. 2007 §3.3, "Image coherence" and Fig. 3b; Hart 1996 (unbounding spheres).
pub fn trace_tile<S: LipschitzSum + ?Sized>(
    surface: &S,
    tile: &RayTile<'_>,
    options: &TraceOptions,
    stats: &mut TraceStats,
    hits: &mut [Option<Hit>],
    mut costs: Option<&mut [f64]>,
) {
    let RayTile { origin, directions, width } = *tile;
    debug_assert!(width > 0 && directions.len().is_multiple_of(width) && hits.len() == directions.len());
    let height = directions.len() / width;
    if let Some(c) = costs.as_deref_mut() {
        c.iter_mut().for_each(|v| *v = 0.0);
    }
    let mut tile = Tile { surface, origin, directions, width, options, stats, hits, costs };
    tile.node(0, 0, width, height, options.t_min);
}

struct Tile<'a, 'b, S: LipschitzSum + ?Sized> {
    surface: &'a S,
    origin: DVec3,
    directions: &'a [DVec3],
    width: usize,
    options: &'a TraceOptions,
    stats: &'b mut TraceStats,
    hits: &'b mut [Option<Hit>],
    costs: Option<&'b mut [f64]>,
}

impl<S: LipschitzSum + ?Sized> Tile<'_, '_, S> {
    fn node(&mut self, x0: usize, y0: usize, w: usize, h: usize, t_start: f64) {
        if w == 0 || h == 0 {
            return;
        }
        let index = |x: usize, y: usize| y * self.width + x;
        if t_start >= self.options.t_max {
            // A cone proved every ray free up to the end of the traced interval.
            for y in y0..y0 + h {
                for x in x0..x0 + w {
                    self.hits[index(x, y)] = None;
                    self.stats.rays += 1;
                }
            }
            return;
        }
        if w * h <= MIN_CONE_RAYS {
            for y in y0..y0 + h {
                for x in x0..x0 + w {
                    let i = index(x, y);
                    let before = self.stats.evaluations;
                    let options = TraceOptions { t_min: t_start, ..*self.options };
                    self.hits[i] = Ray::new(self.origin, self.directions[i])
                        .ok()
                        .and_then(|ray| trace(self.surface, &ray, &options, self.stats));
                    if let Some(c) = self.costs.as_deref_mut() {
                        c[i] += (self.stats.evaluations - before) as f64;
                    }
                }
            }
            return;
        }
        // The cone: mean direction, and the largest angle to it.
        let mut axis = DVec3::ZERO;
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                axis += self.directions[index(x, y)];
            }
        }
        let axis = axis.normalize_or_zero();
        let mut chord = 0.0f64;
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                chord = chord.max((self.directions[index(x, y)] - axis).length());
            }
        }
        let half_angle = 2.0 * (0.5 * chord).min(1.0).asin() * (1.0 + 1e-9) + 1e-15;
        let mut t_c = t_start;
        if let Ok(ray) = Ray::new(self.origin, axis) {
            let before = self.stats.evaluations;
            t_c = self.surface.certify_cone(
                RaySpan::new(&ray, t_start, self.options.t_max),
                half_angle,
                self.options,
                self.stats,
            );
            if let Some(c) = self.costs.as_deref_mut() {
                let share = (self.stats.evaluations - before) as f64 / (w * h) as f64;
                for y in y0..y0 + h {
                    for x in x0..x0 + w {
                        c[index(x, y)] += share;
                    }
                }
            }
        }
        let (w1, h1) = (w.div_ceil(2), h.div_ceil(2));
        self.node(x0, y0, w1, h1, t_c);
        self.node(x0 + w1, y0, w - w1, h1, t_c);
        self.node(x0, y0 + h1, w1, h - h1, t_c);
        self.node(x0 + w1, y0 + h1, w - w1, h - h1, t_c);
    }
}

/// Temporal coherence for a fixed camera (Darles et al. 2007 §3.3, steps 1–4, corrected).
///
/// Given the hit distance `previous` of the same ray in the previous frame:
/// 1. the ray is traced *backwards* from the previous hit point toward its origin;
/// 2. if that finds no crossing, `[t_min, previous]` holds none either (up to skims) and the ray
///    is traced forward from `previous` (the surface moved away: paper step 4);
/// 3. if it finds one at `t_b`, the first crossing is at most `t_b`: the ray is traced forward
///    on `[t_min, t_b + tolerance + h]` (paper step 3 stops at `t_b`, which need not be the first
///    crossing; the margin covers the tolerance of `t_b` and the evaluator's error).
///
/// With `previous = None`, or with footprint fading (the backward ray would fade its components
/// by its own distance, not the forward ray's: another surface), it is [`trace`].
///
/// # Arguments
/// - `previous`: last frame's hit distance along this ray (m), if any.
/// - The others as [`trace`].
///
/// # Returns
/// As [`trace`].
///
/// # References
/// Darles et al. 2007 §3.3, "temporal coherence", Fig. 4.
pub fn trace_temporal<S: LipschitzSum + ?Sized>(
    surface: &S,
    ray: &Ray,
    previous: Option<f64>,
    options: &TraceOptions,
    stats: &mut TraceStats,
) -> Option<Hit> {
    let Some(t_prev) = previous.filter(|t| *t > options.t_min && *t < options.t_max && options.footprint_angle == 0.0)
    else {
        return trace(surface, ray, options, stats);
    };
    let back = Ray::new(ray.at(t_prev), -ray.direction()).ok()?;
    let back_options = TraceOptions { t_min: 0.0, t_max: t_prev - options.t_min, ..*options };
    // The backward ray's work counts, not its ray, hit or miss.
    let mut back_stats = TraceStats::default();
    let found = trace(surface, &back, &back_options, &mut back_stats);
    stats.evaluations += back_stats.evaluations;
    stats.component_evaluations += back_stats.component_evaluations;
    stats.refinement_evaluations += back_stats.refinement_evaluations;
    stats.pruned_evaluations += back_stats.pruned_evaluations;
    stats.probe_evaluations += back_stats.probe_evaluations;
    let forward = match found {
        None => TraceOptions { t_min: t_prev, ..*options },
        Some(b) => {
            let t_b = t_prev - b.t;
            // The backward hit is within the tolerance of a crossing of the exact F; the sampled
            // F̃ (within ε of F) may change sign slightly later: one minimum step of margin.
            let margin = options.tolerance_at(t_b) + options.min_step_at(t_b);
            TraceOptions { t_max: (t_b + margin).min(options.t_max), ..*options }
        }
    };
    trace(surface, ray, &forward, stats)
}
