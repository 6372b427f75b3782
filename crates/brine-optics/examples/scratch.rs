use brine_optics::*;
fn main() {
    for t in JerlovType::ALL { println!("{t}: C*={:.4} rms={:.3}", t.equivalent_chlorophyll(), t.equivalent_fit_rms()); }
    for eta in [0.74, 1.0, 1.1, 1.2, 1.3, 1.33, 1.5, 2.0] {
        println!("eta {eta}: fit {:.5} exact {:.5}", diffuse_fresnel_reflectance(eta), hemispherical_fresnel_reflectance(eta, 1.0));
    }
    println!("sky on water {:.5}", hemispherical_fresnel_reflectance(1.0, 1.333));
    for c in [0.03, 0.3, 1.0, 3.0] {
        let w = WaterRgb::new(&WaterBody::case1(c).unwrap(), RgbBands::SrgbAverage);
        let s = WaterRgb::new(&WaterBody::case1(c).unwrap(), RgbBands::Wavelengths([650.0,550.0,450.0]));
        println!("C={c}: avg a={:?} R={:?}\n   single a={:?} R={:?} kd={:?}", w.a, w.reflectance, s.a, s.reflectance, s.k_d);
    }
    for set in 1..=3u8 { let p = LiYingParameters::table3(set).unwrap(); let m = p.materials(0.5, 0.74).unwrap();
      for x in m { println!("set {set}: alpha' {:.3} R {:.4} Fdr {:.4} A {:.4} Rd(0) {:.4}", x.alpha_prime(), x.total_diffuse_reflectance(), x.f_dr(), x.a(), x.diffuse_reflectance(0.0)); } }
    let s = SkyReflection::new(8, 1.333).unwrap();
    for u in [0.0, 5.0, 10.0, 20.0] { let var = SlopeVariance::cox_munk_clean(u).unwrap();
      for th in [0.0, 45.0, 80.0, 89.0f64] { let v = glam::DVec3::new(th.to_radians().sin(), 0.0, th.to_radians().cos());
        println!("U {u} th {th}: furnace {:.4} refl {:.4}", s.directional_reflectance(v, &var, true), s.directional_reflectance(v, &var, false)); } }
}
