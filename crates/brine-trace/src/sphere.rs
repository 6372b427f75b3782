//! Sphere tracing with a global or a directional Lipschitz constant, optionally over-relaxed, and
//! brute-force marching.

use crate::options::log_step;
use crate::{Hit, LipschitzSum, Ray, Step, StepKind, TraceOptions, TraceStats, bisect_crossing, refine_crossing};

/// `F` along a ray, counting evaluations.
pub(crate) struct Along<'a, S: LipschitzSum + ?Sized> {
    pub(crate) surface: &'a S,
    pub(crate) ray: &'a Ray,
    pub(crate) n: u64,
}

impl<S: LipschitzSum + ?Sized> Along<'_, S> {
    #[inline]
    pub(crate) fn eval(&self, t: f64, stats: &mut TraceStats) -> f64 {
        stats.evaluations += 1;
        stats.component_evaluations += self.n;
        self.surface.value(self.ray.at(t))
    }

    /// `F(t)` at the start of a walk, or the hit when the ray starts on the surface.
    pub(crate) fn start(&self, t: f64, stats: &mut TraceStats) -> Result<f64, Hit> {
        let f = self.eval(t, stats);
        if f == 0.0 {
            stats.hits += 1;
            return Err(Hit { t, point: self.ray.at(t), entering: true, steps: 0 });
        }
        Ok(f)
    }

    /// Refines a bracketed crossing with the Illinois method (bisection when `bisection`) and
    /// returns the hit.
    pub(crate) fn finish(
        &self,
        stats: &mut TraceStats,
        options: &TraceOptions,
        bracket: Bracket,
        bisection: bool,
    ) -> Hit {
        let Bracket { a: (a, fa), b: (b, fb), entering, steps } = bracket;
        let tolerance = options.tolerance_at(b);
        let mut refinement = 0u64;
        let f = |s: f64| {
            refinement += 1;
            self.surface.value(self.ray.at(s))
        };
        let (t_hit, _) = if bisection {
            bisect_crossing(f, a, fa, b, fb, tolerance)
        } else {
            refine_crossing(f, a, fa, b, fb, tolerance)
        };
        stats.evaluations += refinement;
        stats.refinement_evaluations += refinement;
        stats.component_evaluations += refinement * self.n;
        stats.hits += 1;
        Hit { t: t_hit, point: self.ray.at(t_hit), entering, steps }
    }
}

/// A sign change of `F` between `a = (t, F(t))` and `b`, found after `steps` steps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Bracket {
    pub(crate) a: (f64, f64),
    pub(crate) b: (f64, f64),
    /// Whether the ray enters the water there.
    pub(crate) entering: bool,
    pub(crate) steps: u32,
}

/// Sphere tracing on `[t0, t1]` with the constant `lambda` along the ray, over-relaxed by `omega`
/// (1: plain Hart).
///
/// A step `ω|F|/Λ` is kept only if the unbounding intervals of its two ends overlap
/// (`|F(t)|/Λ + |F(t + ω r)|/Λ ≥ ω r`, Keinert et al. 2014); otherwise the tracer falls back to
/// the certified step `|F(t)|/Λ`. Steps shorter than `h(t)` are probes checked at their end.
pub(crate) fn sphere_trace<S: LipschitzSum + ?Sized>(
    along: &Along<'_, S>,
    (t0, t1): (f64, f64),
    lambda: f64,
    omega: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    let mut t = t0;
    let mut f = match along.start(t, stats) {
        Ok(f) => f,
        Err(hit) => return Some(hit),
    };
    let positive = f > 0.0;
    let radius = |f: f64| if lambda > 0.0 { f.abs() / lambda } else { f64::INFINITY };
    let mut steps = 0u32;
    let mut relax = omega;
    loop {
        if !options.take_step(&mut steps, stats) {
            return None;
        }
        let r = radius(f);
        let h = options.min_step_at(t);
        let certified = r >= h;
        let len = if certified { (relax * r).max(h) } else { h };
        let t_next = (t + len).min(t1);
        let f_next = along.eval(t_next, stats);
        let crossed = f_next == 0.0 || (f_next > 0.0) != positive;
        if relax > 1.0 && certified && t_next - t > r && radius(f_next) + r < t_next - t {
            // The relaxed step is not covered by the two spheres: undo it, step by r alone.
            log_step(&mut log, t, t_next, StepKind::Rejected);
            relax = 1.0;
            continue;
        }
        if crossed {
            log_step(&mut log, t, t_next, StepKind::Bracket);
            return Some(along.finish(
                stats,
                options,
                Bracket { a: (t, f), b: (t_next, f_next), entering: positive, steps },
                false,
            ));
        }
        log_step(&mut log, t, t_next, if certified { StepKind::Certified } else { StepKind::Probe });
        if t_next >= t1 {
            return None;
        }
        relax = omega;
        t = t_next;
        f = f_next;
    }
}

/// Brute-force marching with a fixed step `Δ`, each end checked for a sign change, the bracket
/// refined by bisection (Darles et al. 2007 §3.1, the baseline).
pub(crate) fn march<S: LipschitzSum + ?Sized>(
    along: &Along<'_, S>,
    t0: f64,
    t1: f64,
    delta: f64,
    options: &TraceOptions,
    stats: &mut TraceStats,
    mut log: Option<&mut Vec<Step>>,
) -> Option<Hit> {
    let mut t = t0;
    let mut f = match along.start(t, stats) {
        Ok(f) => f,
        Err(hit) => return Some(hit),
    };
    let positive = f > 0.0;
    let mut steps = 0u32;
    while t < t1 {
        if !options.take_step(&mut steps, stats) {
            return None;
        }
        let t_next = (t + delta).min(t1);
        let f_next = along.eval(t_next, stats);
        if f_next == 0.0 || (f_next > 0.0) != positive {
            log_step(&mut log, t, t_next, StepKind::Bracket);
            return Some(along.finish(
                stats,
                options,
                Bracket { a: (t, f), b: (t_next, f_next), entering: positive, steps },
                true,
            ));
        }
        log_step(&mut log, t, t_next, StepKind::Probe);
        t = t_next;
        f = f_next;
    }
    None
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::{Aabb, LipschitzSum, Method, Ray, TraceOptions, TraceStats, trace};

    /// F(p) = y − a sin(k x): a sine height field, L = sqrt(1 + (ak)²) ≤ 1 + ak.
    struct Sine {
        a: f64,
        k: f64,
    }

    impl LipschitzSum for Sine {
        fn component_count(&self) -> usize {
            2
        }
        fn component(&self, i: usize, p: DVec3) -> f64 {
            if i == 0 { p.y } else { -self.a * (self.k * p.x).sin() }
        }
        fn component_lipschitz(&self, i: usize) -> f64 {
            if i == 0 { 1.0 } else { self.a * self.k }
        }
        fn component_directional_lipschitz(&self, i: usize, d: DVec3) -> f64 {
            if i == 0 { d.y.abs() } else { self.a * self.k * d.x.abs() }
        }
        fn component_min(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
            if i == 0 { a.y.min(b.y) } else { -self.a }
        }
        fn component_max(&self, i: usize, a: DVec3, b: DVec3) -> f64 {
            if i == 0 { a.y.max(b.y) } else { self.a }
        }
        fn component_directional_derivative(&self, i: usize, p: DVec3, d: DVec3) -> Option<f64> {
            Some(if i == 0 { d.y } else { -self.a * self.k * (self.k * p.x).cos() * d.x })
        }
        fn component_directional_curvature(&self, i: usize, d: DVec3) -> f64 {
            if i == 0 { 0.0 } else { self.a * (self.k * d.x).powi(2) }
        }
        fn component_feature_size(&self, i: usize) -> f64 {
            if i == 0 { f64::INFINITY } else { std::f64::consts::TAU / self.k }
        }
        fn zero_set_bounds(&self) -> Aabb {
            Aabb::slab_y(-self.a, self.a)
        }
    }

    /// Refinement tolerance of the default options (1e-6) plus slack for the probe bracket.
    const HIT_TOLERANCE: f64 = 1e-5;

    #[test]
    fn every_method_stops_at_the_first_crossing() {
        // Horizontal ray at y = 0.5 through sin waves of amplitude 1 starting at x0 = 0.6, where
        // sin(0.6) = 0.565 > 0.5, so F < 0: the ray starts inside and leaves where sin x = 0.5
        // again, x = 5π/6.
        let s = Sine { a: 1.0, k: 1.0 };
        let ray = Ray::new(DVec3::new(0.6, 0.5, 0.0), DVec3::X).unwrap();
        let expected = 5.0 * std::f64::consts::PI / 6.0 - 0.6;
        for method in Method::ALL {
            let options = TraceOptions { method, ..TraceOptions::default() };
            let mut stats = TraceStats::default();
            let hit = trace(&s, &ray, &options, &mut stats).unwrap();
            assert!((hit.t - expected).abs() < HIT_TOLERANCE, "{method:?}: t = {}", hit.t);
            assert!(!hit.entering, "{method:?}");
        }
    }

    /// A sea with no waves is the plane `y = 0`: every method finds it from above and from below
    /// (where the one point of the clipped span has `F` of either sign by rounding), at the
    /// distance to the plane, and a ray along it misses.
    #[test]
    fn a_flat_sea_is_hit_from_above_and_below() {
        let s = Sine { a: 0.0, k: 1.0 };
        for (y0, dy) in [(-3.0_f64, 0.8_f64), (-0.37, 0.013), (10.0, -0.2), (1e3, -0.999)] {
            let d = DVec3::new((1.0 - dy * dy).sqrt(), dy, 0.0);
            let ray = Ray::new(DVec3::new(0.3, y0, -2.0), d).unwrap();
            let expected = -y0 / ray.direction().y;
            for method in Method::ALL {
                let options = TraceOptions { method, t_max: 1e6, ..TraceOptions::default() };
                let hit = trace(&s, &ray, &options, &mut TraceStats::default());
                let hit = hit.unwrap_or_else(|| panic!("{method:?}: the ray from y = {y0} missed the plane"));
                assert!((hit.t - expected).abs() <= 1e-12 * expected, "{method:?}: t = {} vs {expected}", hit.t);
                assert_eq!((hit.point.y, hit.entering), (0.0, dy < 0.0), "{method:?}");
            }
        }
        let along = Ray::new(DVec3::new(0.0, 0.5, 0.0), DVec3::X).unwrap();
        assert!(trace(&s, &along, &TraceOptions::default(), &mut TraceStats::default()).is_none());
        // Waves thinner than the ray's rounding (10⁻²⁰ m at 3 m) are the same plane to the ray;
        // a trace that ends where the ray enters the slab does not reach it.
        let thin = Sine { a: 1e-20, k: 1.0 };
        let up = Ray::new(DVec3::new(0.3, -3.0, 0.0), DVec3::new(0.6, 0.8, 0.0)).unwrap();
        for method in Method::ALL {
            let options = TraceOptions { method, ..TraceOptions::default() };
            let hit = trace(&thin, &up, &options, &mut TraceStats::default());
            assert!(hit.is_some_and(|h| (h.t - 3.75).abs() < 1e-12), "{method:?}: {hit:?}");
        }
        let thick = Sine { a: 0.5, k: 1.0 };
        let short = TraceOptions { t_max: 3.125, ..TraceOptions::default() };
        assert!(trace(&thick, &up, &short, &mut TraceStats::default()).is_none());
    }

    #[test]
    fn a_ray_skimming_above_a_crest_is_not_a_hit() {
        let s = Sine { a: 1.0, k: 1.0 };
        let ray = Ray::new(DVec3::new(0.0, 1.0 + 1e-7, 0.0), DVec3::X).unwrap();
        for method in Method::ALL {
            let options = TraceOptions { method, t_max: 20.0, ..TraceOptions::default() };
            let mut stats = TraceStats::default();
            assert!(trace(&s, &ray, &options, &mut stats).is_none(), "{method:?}");
        }
    }

    #[test]
    fn vertical_rays_land_on_the_sine_for_every_method() {
        // Straight down the wave is constant along the ray and every bound is exact: certified
        // steps end on F = 0 up to rounding (either side). Expected hit: t = y₀ − a sin(k x₀).
        let s = Sine { a: 0.7, k: 1.3 };
        for j in 0..200 {
            let x0 = 0.0137 * f64::from(j);
            let y0 = 3.0 + 0.01 * f64::from(j);
            let ray = Ray::new(DVec3::new(x0, y0, 0.0), -DVec3::Y).unwrap();
            let expected = y0 - 0.7 * (1.3 * x0).sin();
            for method in Method::ALL {
                let options = TraceOptions { method, ..TraceOptions::default() };
                let hit = trace(&s, &ray, &options, &mut TraceStats::default()).unwrap();
                assert!((hit.t - expected).abs() < HIT_TOLERANCE, "{method:?}, x0 = {x0}: {} vs {expected}", hit.t);
                assert!(hit.entering);
            }
        }
    }

    #[test]
    fn a_descending_ray_hits_the_sine_where_it_first_crosses() {
        // From (0, 2, 0) along (1, −0.2, 0): y = 2 − 0.2 x meets sin x first near x = 2.4.
        let s = Sine { a: 1.0, k: 1.0 };
        let d = DVec3::new(1.0, -0.2, 0.0);
        let ray = Ray::new(DVec3::new(0.0, 2.0, 0.0), d).unwrap();
        // Reference root by bisection on 2 − 0.2x − sin x after the first sign change on a fine grid.
        let g = |x: f64| 2.0 - 0.2 * x - x.sin();
        let mut x = 0.0;
        while g(x + 1e-3) > 0.0 {
            x += 1e-3;
        }
        let (mut lo, mut hi) = (x, x + 1e-3);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if g(m) > 0.0 { lo = m } else { hi = m }
        }
        let t_ref = lo * d.length();
        for method in Method::ALL {
            let options = TraceOptions { method, ..TraceOptions::default() };
            let mut stats = TraceStats::default();
            let hit = trace(&s, &ray, &options, &mut stats).unwrap();
            assert!((hit.t - t_ref).abs() < HIT_TOLERANCE, "{method:?}: {} vs {t_ref}", hit.t);
            assert!(hit.entering);
        }
    }
}
