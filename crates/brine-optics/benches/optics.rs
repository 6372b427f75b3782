//! Per-call cost of the functions the renderer calls per pixel, and of the per-scene setup.

use std::hint::black_box;

use brine_optics::{
    DipoleMaterial, RgbBands, SkyReflection, SlopeVariance, WATER_IOR, WaterBody, WaterRgb, fresnel_dielectric,
    fresnel_schlick, reflected_sky_radiance_filtered, reflected_sun_radiance,
};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::DVec3;

fn per_pixel(c: &mut Criterion) {
    let mut g = c.benchmark_group("per_pixel");
    g.bench_function("fresnel_exact", |b| b.iter(|| fresnel_dielectric(black_box(0.37), 1.0, WATER_IOR)));
    g.bench_function("fresnel_schlick", |b| b.iter(|| fresnel_schlick(black_box(0.37), 1.0, WATER_IOR)));
    let var = SlopeVariance::cox_munk_clean(7.0).unwrap();
    let v = DVec3::new(0.6, 0.1, 0.79).normalize();
    let l = DVec3::new(-0.5, 0.05, 0.86).normalize();
    g.bench_function("reflected_sun_radiance", |b| b.iter(|| reflected_sun_radiance(black_box(v), l, &var, 100.0)));
    let sky = |d: DVec3| DVec3::new(1.0, 1.2, 1.5) * (0.5 + d.z);
    for order in [2usize, 4, 8] {
        let s = SkyReflection::new(order, WATER_IOR).unwrap();
        g.bench_function(format!("sky_quadrature_{order}x{order}"), |b| {
            b.iter(|| s.reflected_radiance(black_box(v), &var, sky))
        });
    }
    g.bench_function("sky_filtered_bruneton", |b| {
        b.iter(|| reflected_sky_radiance_filtered(black_box(v), &var, |d, _| sky(d)))
    });
    let water = WaterRgb::new(&WaterBody::case1(0.3).unwrap(), RgbBands::SrgbAverage);
    g.bench_function("water_refracted_ray_radiance", |b| {
        b.iter(|| water.refracted_ray_radiance(black_box(DVec3::splat(40.0)), 0.8, 12.0, DVec3::splat(0.3)))
    });
    let m = DipoleMaterial::new(0.05, 0.3, 0.9, 1.33).unwrap();
    g.bench_function("dipole_crest_radiance", |b| b.iter(|| m.crest_radiance(black_box(100.0), 0.6, 0.8, 0.4)));
    g.finish();
}

fn per_scene(c: &mut Criterion) {
    let mut g = c.benchmark_group("per_scene");
    g.sample_size(20);
    g.bench_function("water_rgb_case1_srgb_average", |b| {
        b.iter(|| WaterRgb::new(&WaterBody::case1(black_box(0.3)).unwrap(), RgbBands::SrgbAverage))
    });
    g.bench_function("water_body_jerlov_fit", |b| {
        b.iter(|| WaterBody::jerlov(black_box(brine_optics::JerlovType::II)))
    });
    g.finish();
}

criterion_group!(benches, per_pixel, per_scene);
criterion_main!(benches);
