//! Plots of brine-optics: Fresnel curves and Schlick's error, absorption and `K_d` spectra by
//! chlorophyll and Jerlov type, the dipole profiles of Li Ying et al.'s Table 3, BRDF lobes, the
//! visibility of facets by slope and the escape of their reflections, and the rough reflectance they
//! give at grazing views.

use std::path::Path;

use brine_optics::{
    JerlovType, LiYingParameters, ReflectanceSplit, SlopeVariance, SlopeVisibility, WATER_IOR, WaterBody, case1_iops,
    fresnel_dielectric, fresnel_schlick, ocean_brdf, pure_water_absorption, reflectance_split,
    reflectance_split_uncorrelated,
};
use glam::DVec3;

use super::{LineChart, Scale};

fn wavelengths() -> impl Iterator<Item = f64> {
    (0..=120).map(|i| 400.0 + 2.5 * f64::from(i))
}

/// Writes the brine-optics figures into `dir`.
pub fn plot(dir: &Path) -> Result<(), String> {
    let angles: Vec<f64> = (0..=900).map(|i| f64::from(i) * 0.1).collect();
    let curve = |n_i: f64, n_t: f64, f: fn(f64, f64, f64) -> f64| -> Vec<(f64, f64)> {
        angles.iter().map(|&d| (d, f(d.to_radians().cos(), n_i, n_t))).collect()
    };
    LineChart {
        title: "Fresnel reflectance of the air–water interface (n = 1.333)",
        x_label: "angle of incidence (deg)",
        y_label: "reflectance F",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![
            ("air → water, exact".into(), curve(1.0, WATER_IOR, fresnel_dielectric)),
            ("air → water, Schlick".into(), curve(1.0, WATER_IOR, fresnel_schlick)),
            ("water → air, exact (TIR above 48.6°)".into(), curve(WATER_IOR, 1.0, fresnel_dielectric)),
            ("water → air, Schlick".into(), curve(WATER_IOR, 1.0, fresnel_schlick)),
        ],
    }
    .write(&dir.join("optics-fresnel.svg"))?;

    let error = |n_i: f64, n_t: f64| -> Vec<(f64, f64)> {
        angles
            .iter()
            .map(|&d| {
                let c = d.to_radians().cos();
                (d, fresnel_schlick(c, n_i, n_t) - fresnel_dielectric(c, n_i, n_t))
            })
            .collect()
    };
    LineChart {
        title: "Schlick's approximation minus the exact Fresnel reflectance",
        x_label: "angle of incidence (deg)",
        y_label: "F_Schlick − F",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: vec![("air → water".into(), error(1.0, WATER_IOR)), ("water → air".into(), error(WATER_IOR, 1.0))],
    }
    .write(&dir.join("optics-schlick-error.svg"))?;

    let mut series = vec![(
        "pure water a_w (Pope & Fry 1997)".to_owned(),
        wavelengths().map(|l| (l, pure_water_absorption(l))).collect(),
    )];
    for c in [0.03, 0.1, 0.3, 1.0, 3.0, 10.0] {
        let body = WaterBody::case1(c).map_err(|e| e.to_string())?;
        series.push((format!("C = {c} mg/m³"), wavelengths().map(|l| (l, body.iops(l).a)).collect()));
    }
    LineChart {
        title: "Absorption of Case-1 water by chlorophyll (Morel 1991 / Premoze & Ashikhmin 2001)",
        x_label: "wavelength (nm)",
        y_label: "a (1/m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("optics-absorption-chlorophyll.svg"))?;

    let types = JerlovType::ALL;
    let bodies: Vec<WaterBody> = types.iter().map(|t| WaterBody::jerlov(*t)).collect();
    LineChart {
        title: "Absorption of the Jerlov types (Case-1 model at the fitted equivalent chlorophyll)",
        x_label: "wavelength (nm)",
        y_label: "a (1/m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: types
            .iter()
            .zip(&bodies)
            .map(|(t, b)| {
                (format!("{t} (C* = {:.3})", b.chlorophyll_mg_m3()), wavelengths().map(|l| (l, b.iops(l).a)).collect())
            })
            .collect(),
    }
    .write(&dir.join("optics-absorption-jerlov.svg"))?;

    LineChart {
        title: "Diffuse attenuation K_d of Jerlov's water types (Jerlov 1976, Table XXVII)",
        x_label: "wavelength (nm)",
        y_label: "K_d (1/m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series: types
            .iter()
            .map(|t| (t.to_string(), (0..=14).map(|i| 350.0 + 25.0 * f64::from(i)).map(|l| (l, t.kd(l))).collect()))
            .collect(),
    }
    .write(&dir.join("optics-kd-jerlov.svg"))?;

    let mut series = Vec::new();
    for c in [0.0, 0.03, 0.3, 1.0, 3.0, 10.0] {
        let chl = brine_optics::Chlorophyll::new(c).map_err(|e| e.to_string())?;
        series.push((format!("C = {c} mg/m³"), wavelengths().map(|l| (l, case1_iops(l, chl).k_d)).collect()));
    }
    LineChart {
        title: "Diffuse attenuation K_d = K_w + χ C^e of Case-1 water (Morel 1988)",
        x_label: "wavelength (nm)",
        y_label: "K_d (1/m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("optics-kd-chlorophyll.svg"))?;

    let radii: Vec<f64> = (0..=150).map(|i| 0.01 * 10f64.powf(f64::from(i) / 50.0)).collect();
    let mut series = Vec::new();
    for set in 1..=3u8 {
        let p = LiYingParameters::table3(set).map_err(|e| e.to_string())?;
        // Sets 2 and 3: g and η are unreadable in the source; the plot uses set 1's (0.5, 0.74).
        let (g, eta) = p.g_eta.unwrap_or((0.5, 0.74));
        let m = p.materials(g, eta).map_err(|e| e.to_string())?;
        for (ch, mat) in ["R", "G", "B"].iter().zip(m) {
            series.push((
                format!("set {set} {ch}"),
                radii.iter().map(|&r| (r, mat.diffuse_reflectance(r))).filter(|p| p.1 > 1e-7).collect(),
            ));
        }
    }
    LineChart {
        title: "Dipole R_d(r) for Li Ying et al. 2018 Table 3 (g, η of set 1 assumed for sets 2–3)",
        x_label: "r (unit length of the table's coefficients)",
        y_label: "R_d (1/length²)",
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series,
    }
    .write(&dir.join("optics-dipole-rd.svg"))?;

    // BRDF lobes in the plane of incidence: sun 30° from the zenith, view swept from −89° to 89°.
    let sun = DVec3::new(-(30f64.to_radians().sin()), 0.0, 30f64.to_radians().cos());
    let mut series = Vec::new();
    for u in [2.0, 7.0, 15.0] {
        let var = SlopeVariance::cox_munk_clean(u).map_err(|e| e.to_string())?;
        let pts = (-890..=890)
            .map(|i| {
                let t = (f64::from(i) * 0.1).to_radians();
                let v = DVec3::new(t.sin(), 0.0, t.cos());
                (f64::from(i) * 0.1, ocean_brdf(v, sun, &var, WATER_IOR) * sun.z)
            })
            .collect();
        series.push((format!("Cox–Munk U = {u} m/s (σ² = {:.3})", var.total()), pts));
    }
    LineChart {
        title: "Ocean BRDF × cos θ_sun in the plane of incidence, sun at 30° (Bruneton et al. 2010)",
        x_label: "view angle from the zenith (deg, + toward the specular side)",
        y_label: "ρ(v, l) l_z (1/sr)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("optics-brdf-lobes.svg"))?;

    // Which facets a grazing viewer sees, by slope: the measured visibility over Smith's.
    let table = SlopeVisibility::stored();
    let series = [0.03, 0.1, 0.3, 1.0, 2.0]
        .iter()
        .map(|&nu| {
            let pts = (0..=60).map(|i| f64::from(i) * 0.1).map(|s| (s - nu, table.ratio(nu, s))).collect();
            (format!("ν = cot θ_v/σ = {nu}"), pts)
        })
        .collect();
    LineChart {
        title: "Visibility of a facing facet given its slope, over Smith's (measured on Gaussian profiles)",
        x_label: "facet slope toward the viewer, in slope deviations (−ν: grazing)",
        y_label: "P(seen | slope) / G₁",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("optics-slope-visibility.svg"))?;

    // Where the seen facets' reflections go: the measured escape over Smith's height-correlated.
    let series = [0.03, 0.1, 0.3, 1.0, 2.0]
        .iter()
        .map(|&nu| {
            let pts = (0..=60)
                .map(|i| f64::from(i) * 0.1)
                .filter(|s| 2.0 * s - nu > 0.0 && 2.0 * s - nu <= 4.0)
                .map(|s| (2.0 * s - nu, table.escape(nu, s)))
                .collect();
            (format!("ν = cot θ_v/σ = {nu}"), pts)
        })
        .collect();
    LineChart {
        title: "Escape of a seen facet's reflection given its slope, over Smith's height-correlated G",
        x_label: "rise of the mirror direction, in slope deviations (2s − ν)",
        y_label: "P(clear | seen, slope) / G",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("optics-reflection-escape.svg"))?;

    // The rough reflectance of the facets seen (and toward the sky), with the measured visibility
    // and escape and with Smith's.
    let water = |c: f64| fresnel_dielectric(c, 1.0, WATER_IOR);
    let (mut series, mut sky) = (Vec::new(), Vec::new());
    for sigma in [0.1, 0.2] {
        let sweep = |uncorrelated: bool| -> Vec<(f64, ReflectanceSplit)> {
            (0..=199)
                .map(|i| 70.0 + f64::from(i) * 0.1)
                .map(|deg| {
                    let c = deg.to_radians().cos();
                    let split = if uncorrelated {
                        reflectance_split_uncorrelated(c, sigma, water)
                    } else {
                        reflectance_split(c, sigma, water)
                    };
                    (deg, split)
                })
                .collect()
        };
        let (measured, smith) = (sweep(false), sweep(true));
        let part = |s: &[(f64, ReflectanceSplit)], f: fn(&ReflectanceSplit) -> f64| -> Vec<(f64, f64)> {
            s.iter().map(|(deg, split)| (*deg, f(split))).collect()
        };
        series.push((format!("σ = {sigma}, measured visibility"), part(&measured, |s| s.seen)));
        series.push((format!("σ = {sigma}, Smith's visibility"), part(&smith, |s| s.seen)));
        sky.push((format!("σ = {sigma}, measured visibility and escape"), part(&measured, |s| s.to_sky)));
        sky.push((format!("σ = {sigma}, Smith's"), part(&smith, |s| s.to_sky)));
    }
    LineChart {
        title: "Fresnel reflectance of the facets seen toward the unobstructed sky, R, at grazing views",
        x_label: "view angle from the zenith (deg)",
        y_label: "R",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series: sky,
    }
    .write(&dir.join("optics-rough-sky.svg"))?;
    LineChart {
        title: "Fresnel reflectance of the facets seen, R_seen, at grazing views",
        x_label: "view angle from the zenith (deg)",
        y_label: "R_seen",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
        series,
    }
    .write(&dir.join("optics-rough-visibility.svg"))
}
