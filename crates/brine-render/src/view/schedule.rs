//! The progressive preview's schedule: which pass to render next for the view on screen.
//!
//! A new view (the camera moved, the sea or the hour changed) first gets the finest pass whose
//! predicted time fits the frame budget, so that a moving camera is redrawn at a steady rate.
//! While the view stays still it is refined: pixels halved down to the preview's own, then more
//! samples per pixel. The prediction is the measured time per pixel-sample of the passes
//! already rendered.

/// Preview blocks tried, coarsest first: a pass at block `b` renders one pixel per `b × b`
/// pixels of the preview.
pub const BLOCKS: [u32; 4] = [8, 4, 2, 1];

/// Samples per pixel of the refining passes at the preview's resolution.
pub const SAMPLES: [u32; 3] = [1, 4, 16];

/// Time a pass of a moving view may take (s): 0.08 s leaves 20 ms of the 10-frames-a-second
/// budget to tone-map, upload and draw.
pub const FRAME_BUDGET_S: f64 = 0.08;

/// One pass of the progressive preview.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pass {
    /// Preview pixels per rendered pixel along each axis (one of [`BLOCKS`]).
    pub block: u32,
    /// Samples per rendered pixel.
    pub spp: u32,
}

impl Pass {
    /// The size of this pass's image for a preview of `width × height` (at least 1 × 1).
    pub fn size(self, width: u32, height: u32) -> (u32, u32) {
        (width.div_ceil(self.block).max(1), height.div_ceil(self.block).max(1))
    }

    /// Pixel-samples this pass renders for a preview of `width × height`.
    pub fn work(self, width: u32, height: u32) -> u64 {
        let (w, h) = self.size(width, height);
        u64::from(w) * u64::from(h) * u64::from(self.spp)
    }
}

/// The schedule of one preview: what has been shown of the current view and what passes cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Schedule {
    width: u32,
    height: u32,
    budget_s: f64,
    /// Seconds per pixel-sample, smoothed over the passes rendered (`None` before the first).
    cost: Option<f64>,
    /// Whether `cost` comes from passes of block 2 or finer.
    measured_fine: bool,
    /// The finest pass shown of the current view.
    shown: Option<Pass>,
}

impl Schedule {
    /// A schedule for a `width × height` preview whose moving views must each render within
    /// `budget_s` (s).
    pub fn new(width: u32, height: u32, budget_s: f64) -> Self {
        Self { width: width.max(1), height: height.max(1), budget_s, cost: None, measured_fine: false, shown: None }
    }

    /// A new view: nothing of it shown yet. The preview may change size.
    pub fn restart(&mut self, width: u32, height: u32) {
        (self.width, self.height) = (width.max(1), height.max(1));
        self.shown = None;
    }

    /// The pass to render next, or `None` when the view is fully refined.
    pub fn next(&self) -> Option<Pass> {
        match self.shown {
            None => Some(Pass { block: self.affordable_block(), spp: 1 }),
            Some(p) if p.block > 1 => Some(Pass { block: p.block / 2, spp: 1 }),
            Some(p) => SAMPLES.iter().find(|&&s| s > p.spp).map(|&spp| Pass { block: 1, spp }),
        }
    }

    /// Whether the next pass is the first of its view (which is always finished, so that a
    /// moving view is drawn; later passes are given up when the view changes).
    pub fn is_first(&self) -> bool {
        self.shown.is_none()
    }

    /// The finest block whose one-sample pass is predicted to fit the budget; the coarsest
    /// before any pass has been timed.
    pub fn affordable_block(&self) -> u32 {
        let Some(cost) = self.cost else { return BLOCKS[0] };
        BLOCKS
            .iter()
            .rev()
            .copied()
            .find(|&b| cost * Pass { block: b, spp: 1 }.work(self.width, self.height) as f64 <= self.budget_s)
            .unwrap_or(BLOCKS[0])
    }

    /// Records a pass rendered in `seconds` and shown.
    ///
    /// The time per pixel-sample is taken from passes of at least a quarter of the preview's
    /// pixels (block 2 or finer) once there is one: the smaller passes are mostly the frame's
    /// fixed costs (exposure, glare, threads), which would make the prediction too slow.
    pub fn done(&mut self, pass: Pass, seconds: f64) {
        let work = pass.work(self.width, self.height) as f64;
        let telling = pass.block <= 2 || !self.measured_fine;
        if seconds.is_finite() && seconds > 0.0 && telling {
            if pass.block <= 2 && !self.measured_fine {
                // The first fine pass replaces the small passes' estimate.
                self.measured_fine = true;
                self.cost = None;
            }
            let c = seconds / work;
            // Smoothed, so that one slow pass (another program, a first touch of memory) does not
            // throw the next view back to the coarsest block.
            self.cost = Some(self.cost.map_or(c, |old| 0.5 * (old + c)));
        }
        self.shown = Some(pass);
    }

    /// Seconds per pixel-sample as measured so far.
    pub fn cost(&self) -> Option<f64> {
        self.cost
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A 320 × 240 preview.
    const W: u32 = 320;
    const H: u32 = 240;

    /// The passes of one still view, from the first to the end, if each takes `seconds_per_work`
    /// per pixel-sample.
    fn passes(s: &mut Schedule, seconds_per_work: f64) -> Vec<Pass> {
        let mut out = Vec::new();
        while let Some(p) = s.next() {
            s.done(p, seconds_per_work * p.work(W, H) as f64);
            out.push(p);
            assert!(out.len() < 20, "the schedule ends");
        }
        out
    }

    #[test]
    fn a_first_view_starts_coarse_and_refines_pixels_then_samples() {
        let mut s = Schedule::new(W, H, FRAME_BUDGET_S);
        let p = passes(&mut s, 1e-6);
        let expected = [(8, 1), (4, 1), (2, 1), (1, 1), (1, 4), (1, 16)];
        assert_eq!(p, expected.map(|(block, spp)| Pass { block, spp }));
        assert_eq!(s.next(), None);
    }

    /// With 2.5 µs per pixel (a 320 × 240 pass in 0.19 s, the default sea on two cores), a
    /// moving view is drawn at block 2 (48 ms); at 0.5 µs at the preview's own pixels (38 ms).
    #[test]
    fn a_moving_view_gets_the_finest_pass_that_fits_the_budget() {
        for (cost, block) in [(2.5e-6, 2), (0.5e-6, 1), (1.5e-5, 4), (1e-3, 8)] {
            let mut s = Schedule::new(W, H, FRAME_BUDGET_S);
            passes(&mut s, cost);
            s.restart(W, H);
            assert!(s.is_first());
            assert_eq!(s.next(), Some(Pass { block, spp: 1 }), "{cost}");
        }
    }

    /// Small passes cost mostly their fixed part: a view whose block-8 pass took 12 ms (13 µs a
    /// pixel, 920 pixels) and whose full pass took 0.19 s (3.3 µs) moves at block 2 (48 ms).
    #[test]
    fn small_passes_do_not_slow_the_prediction() {
        let mut s = Schedule::new(320, 180, FRAME_BUDGET_S);
        let overhead = 0.009;
        while let Some(p) = s.next() {
            s.done(p, overhead + 3.3e-6 * p.work(320, 180) as f64);
        }
        s.restart(320, 180);
        assert_eq!(s.next(), Some(Pass { block: 2, spp: 1 }));
    }

    #[test]
    fn pass_sizes_cover_the_preview() {
        assert_eq!(Pass { block: 8, spp: 1 }.size(321, 1), (41, 1));
        assert_eq!(Pass { block: 1, spp: 16 }.work(W, H), 320 * 240 * 16);
    }

    proptest! {
        /// Whatever the costs, every view ends fully refined at the preview's pixels with the
        /// most samples, each pass finer than the one before, and a view's first pass is
        /// predicted within the budget when any block is.
        #[test]
        fn every_view_ends_refined(costs in prop::collection::vec(1e-8f64..1e-3, 1..6), w in 1u32..2000, h in 1u32..2000) {
            let mut s = Schedule::new(w, h, FRAME_BUDGET_S);
            for cost in costs {
                s.restart(w, h);
                let first = s.next().expect("a new view has a pass");
                if let Some(c) = s.cost() {
                    let fits = c * first.work(w, h) as f64 <= FRAME_BUDGET_S;
                    let none_fits = c * Pass { block: 8, spp: 1 }.work(w, h) as f64 > FRAME_BUDGET_S;
                    prop_assert!(fits || (none_fits && first.block == 8));
                }
                let mut last: Option<Pass> = None;
                while let Some(p) = s.next() {
                    if let Some(l) = last {
                        prop_assert!(p.block < l.block || (p.block == 1 && p.spp > l.spp));
                    }
                    s.done(p, cost * p.work(w, h) as f64);
                    last = Some(p);
                }
                prop_assert_eq!(last, Some(Pass { block: 1, spp: SAMPLES[SAMPLES.len() - 1] }));
            }
        }
    }
}
