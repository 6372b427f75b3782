//! `cargo bench -p brine-ephem --bench ephem`: cost of one position, SPA against Schlyter's
//! elements, measured side by side in one process (medians of repeated runs).

use brine_ephem::{Observer, Options, SunModel, Timestamp, moon_position, sun_position};

/// Median time per call (ns) of `f(0) … f(n − 1)` over `reps` repetitions.
fn median_ns(n: i64, reps: usize, mut f: impl FnMut(i64) -> f64) -> f64 {
    brine_testkit::timing::median_ns_per_call(n as usize, reps, |i| f(i as i64))
}

fn main() {
    let o = Observer::from_degrees(43.6, 1.44, 0.0).unwrap();
    let opts = Options::default();
    let t = |i: i64| Timestamp::from_second(1_700_000_000 + i * 977).unwrap();
    let spa = median_ns(20_000, 9, |i| sun_position(t(i), &o, SunModel::Spa, &opts).unwrap().altitude);
    let sch = median_ns(20_000, 9, |i| sun_position(t(i), &o, SunModel::Schlyter, &opts).unwrap().altitude);
    let moon = median_ns(20_000, 9, |i| moon_position(t(i), &o, &opts).unwrap().altitude);
    println!("{:<34} {:>12} {:>8}", "position", "median (ns)", "× SPA");
    for (name, v) in [("sun, NREL SPA", spa), ("sun, Schlyter", sch), ("moon, Schlyter (topocentric)", moon)] {
        println!("{name:<34} {v:>12.1} {:>8.3}", v / spa);
    }
}
