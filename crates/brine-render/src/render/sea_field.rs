//! The sea of a frame as the renderer traces it: primary rays faded with the pixel footprint, secondary rays with every wave, and the shading geometry at a hit.

use super::*;
use brine_waves::EllipticalFootprint;
use glam::DVec2;

/// Smallest `|d_y|` of the pixel footprint's stretch on the sea (the tracer's fades').
pub(super) use brine_core::footprint::MIN_FOOTPRINT_GRAZING;

/// The sea of a frame ready to trace (brine-waves `TracedSea`), with the renderer's choices of
/// options: primary rays by the tiered method with the waves fading with the pixel footprint,
/// secondary rays with every wave.
pub(crate) struct SeaField<'a> {
    sea: TracedSea<'a>,
}

impl<'a> SeaField<'a> {
    pub(super) fn new(world: &'a World) -> Self {
        Self { sea: world.traced_sea() }
    }

    /// The options of a primary ray: the tiered method, the waves faded by the pixel's angle.
    pub(super) fn primary_options(world: &World) -> TraceOptions {
        TraceOptions { method: Method::Tiered, footprint_angle: world.filtering_angle(), ..world.trace }
    }

    /// Traces a primary ray (the waves fade with the pixel footprint).
    #[cfg(test)]
    pub(super) fn trace_primary(&self, ray: &Ray, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &Self::primary_options(world), stats)
    }

    /// Traces a secondary ray (every wave).
    #[cfg(test)]
    pub(super) fn trace_secondary(&self, ray: &Ray, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &world.trace, stats)
    }

    /// Traces the primary rays of a tile (`width` per row) from the camera, with footprint fading;
    /// the trochoid and FFT seas share cones among the rays (image coherence), the others trace
    /// ray by ray.
    pub(super) fn trace_tile(&self, world: &World, tile: &mut TileRays, width: usize, stats: &mut TraceStats) {
        let n = tile.directions.len();
        tile.hits.clear();
        tile.hits.resize(n, None);
        tile.costs.clear();
        tile.costs.resize(n, 0.0);
        let options = Self::primary_options(world);
        let rays = RayTile { origin: world.camera.position, directions: &tile.directions, width };
        self.sea.trace_tile(&rays, &options, stats, &mut tile.hits, &mut tile.costs);
    }

    /// Traces a secondary ray up to `t_max` metres.
    pub(super) fn trace_within(&self, ray: &Ray, t_max: f64, world: &World, stats: &mut TraceStats) -> Option<Hit> {
        self.sea.trace(ray, &TraceOptions { t_max, ..world.trace }, stats)
    }

    /// Upward unit normal of the surface as drawn at `p`, hit `t` metres along `d` (the faded
    /// waves of a primary ray are left out; `t = 0` keeps every wave).
    pub(super) fn normal(&self, p: DVec3, d: DVec3, t: f64, world: &World) -> DVec3 {
        let angle = if t > 0.0 { world.filtering_angle() } else { 0.0 };
        let g = self.sea.faded_gradient(p.x, p.z, d, angle, t);
        DVec3::new(-g.x, 1.0, -g.y).normalize()
    }

    /// The shading normal and the BRDF slope variances (the unresolved waves' plus those the
    /// tracer faded, Bruneton et al. 2010's seamless transition, in the wind frame) at a
    /// primary hit `t` along `d`, in one pass over the waves where the surface allows it.
    ///
    /// The detail normals (the waves between the traced band and the pixel) add their gradient,
    /// read through the pixel's footprint on the drawn facet, and the slopes the footprint hides
    /// join the BRDF's. The third value is the drawn facet's normal (without the detail), on
    /// which the textures laid on the surface are read.
    pub(super) fn hit_geometry(&self, p: DVec3, d: DVec3, t: f64, world: &World) -> (DVec3, SlopeVariance, DVec3) {
        let angle = world.filtering_angle();
        // The pixel on the sea: `αt` across the view, `αt/max(|d_y|, 0.05)` along it, as Gaussians of the
        // same spread as those boxes.
        let across = angle * t / brine_waves::BOX_WIDTH_PER_SIGMA;
        let along = across / d.y.abs().max(MIN_FOOTPRINT_GRAZING);
        let footprint = EllipticalFootprint::new(across, along, DVec2::new(d.x, d.z));
        let (mut g, mut c) = match (&self.sea, &world.fft_slopes) {
            // The FFT cascades read through the footprint (LEAN mapping) rather than faded whole.
            (TracedSea::Fft(_), Some(lean)) => {
                let l = lean.filtered_elliptical(p.x, p.z, &footprint);
                (l.gradient, l.covariance)
            }
            _ => self.sea.faded_gradient_and_covariance(p.x, p.z, d, angle, t),
        };
        // The facet of the drawn surface the ray meets.
        let facet = DVec3::new(-g.x, 1.0, -g.y).normalize();
        if let Some(detail) = &world.detail {
            // The detail waves ride on the drawn surface: the pixel covers them as it covers the
            // facet it meets, longer along the view on a face turned away from the eye.
            let footprint = EllipticalFootprint::on_facet(across, d, facet);
            let f = detail.filtered_elliptical(p.x, p.z, &footprint);
            g += f.gradient;
            c += f.covariance;
        }
        (DVec3::new(-g.x, 1.0, -g.y).normalize(), Self::variance_with(world, c), facet)
    }

    /// The unresolved variances plus a faded world-axes covariance `c = (xx, xz, zz)`, in the wind
    /// frame.
    pub(super) fn variance_with(world: &World, c: DVec3) -> SlopeVariance {
        if c == DVec3::ZERO {
            return world.variance_unresolved;
        }
        let (wx, wz) = (world.wind.x, world.wind.z);
        let along = c.x * wx * wx + 2.0 * c.y * wx * wz + c.z * wz * wz;
        let across = c.x * wz * wz - 2.0 * c.y * wx * wz + c.z * wx * wx;
        let v = &world.variance_unresolved;
        SlopeVariance::new(v.sigma_x2() + along.max(0.0), v.sigma_y2() + across.max(0.0)).unwrap_or(*v)
    }
}
