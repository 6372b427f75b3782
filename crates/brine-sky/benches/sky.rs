//! `cargo bench -p brine-sky --bench sky`: per-call costs of the sky a renderer pays per pixel,
//! and the constructor costs, measured side by side in one process (medians of repeated runs).

use brine_sky::{
    CloudParams, DaylightModel, HosekWilkieSky, MoonParams, PreethamSky, SEA_GROUND_ALBEDO, Sky, SkyParams, Sun,
};
use glam::DVec3;

use brine_testkit::directions::from_elevation_azimuth_deg as dir;
use brine_testkit::timing::median_ns_per_call as median_ns;

fn main() {
    let views: Vec<DVec3> = (0..4096).map(|i| dir((i % 90) as f64, (i * 37 % 360) as f64)).collect();
    let v = |i: usize| views[i % views.len()];
    let moon = MoonParams { direction: dir(30.0, 150.0), phase_angle: 0.3, distance_km: 384_400.0 };
    let day = Sky::new(&SkyParams::new(3.0, dir(30.0, 180.0))).unwrap();
    let dusk = Sky::new(&SkyParams::new(3.0, dir(-5.0, 270.0))).unwrap();
    let night = Sky::new(&SkyParams { moon: Some(moon), ..SkyParams::new(3.0, dir(-30.0, 0.0)) }).unwrap();
    let cloudy =
        Sky::new(&SkyParams { clouds: Some(CloudParams::default()), ..SkyParams::new(3.0, dir(30.0, 180.0)) }).unwrap();
    let preetham = PreethamSky::new(3.0, dir(30.0, 180.0)).unwrap();
    let hosek = HosekWilkieSky::new(3.0, dir(30.0, 180.0), SEA_GROUND_ALBEDO).unwrap();
    let day_hw =
        Sky::new(&SkyParams { model: DaylightModel::HosekWilkie, ..SkyParams::new(3.0, dir(30.0, 180.0)) }).unwrap();

    let n = 200_000;
    let base = median_ns(n, 9, |i| preetham.radiance_rgb(v(i)));
    let rows = [
        ("PreethamSky::radiance_rgb (day)", base),
        ("HosekWilkieSky::radiance_rgb (day)", median_ns(n, 9, |i| hosek.radiance_rgb(v(i)))),
        ("Sky::radiance_rgb, day", median_ns(n, 9, |i| day.radiance_rgb(v(i)))),
        ("Sky::radiance_rgb, day, Hosek–Wilkie", median_ns(n, 9, |i| day_hw.radiance_rgb(v(i)))),
        ("Sky::radiance_rgb, twilight (sun −5°)", median_ns(n, 9, |i| dusk.radiance_rgb(v(i)))),
        ("Sky::radiance_rgb, night with Moon", median_ns(n, 9, |i| night.radiance_rgb(v(i)))),
        ("Sky::radiance_rgb, day with clouds", median_ns(n, 9, |i| cloudy.radiance_rgb(v(i)))),
        ("Sky::background_rgb, night (discs)", median_ns(n, 9, |i| night.background_rgb(v(i)))),
        (
            "Sky::aerial_perspective",
            median_ns(n, 9, |i| {
                let ap = day.aerial_perspective(5.0, v(i) * DVec3::new(1.0, -0.2, 1.0), 1000.0 + i as f64);
                ap.extinction + ap.inscatter
            }),
        ),
    ];
    println!("{:<44} {:>12} {:>10}", "per call", "median (ns)", "× Preetham");
    for (name, t) in rows {
        println!("{name:<44} {t:>12.1} {:>10.2}", t / base);
    }
    let ctor = |f: &dyn Fn() -> DVec3| median_ns(1, 15, |_| f()) / 1e3;
    let rows = [
        (
            "Sun::through_atmosphere (spectral)",
            ctor(&|| Sun::through_atmosphere(3.0, dir(30.0, 0.0)).unwrap().radiance_rgb()),
        ),
        (
            "Sky::new, day",
            ctor(&|| Sky::new(&SkyParams::new(3.0, dir(30.0, 0.0))).unwrap().horizontal_irradiance_rgb()),
        ),
        (
            "Sky::new, day, Hosek–Wilkie",
            ctor(&|| {
                let p = SkyParams { model: DaylightModel::HosekWilkie, ..SkyParams::new(3.0, dir(30.0, 0.0)) };
                Sky::new(&p).unwrap().horizontal_irradiance_rgb()
            }),
        ),
        (
            "Sky::new, twilight (twilight table)",
            ctor(&|| Sky::new(&SkyParams::new(3.0, dir(-5.0, 0.0))).unwrap().horizontal_irradiance_rgb()),
        ),
        (
            "Sky::new, day with clouds",
            ctor(&|| {
                let p = SkyParams { clouds: Some(CloudParams::default()), ..SkyParams::new(3.0, dir(30.0, 0.0)) };
                Sky::new(&p).unwrap().horizontal_irradiance_rgb()
            }),
        ),
    ];
    println!("\n{:<44} {:>12}", "constructor", "median (µs)");
    for (name, t) in rows {
        println!("{name:<44} {t:>12.1}");
    }
}
