//! Property tests: bounds and invariants of the foam and spray models on random inputs.

use brine_foam::{
    CoverageParams, DARLES_ONSET_WIND_M_S, ExtinctionEfficiency, FoamExtension, FoamExtensionParams, FoamHistory,
    FoamHistoryParams, FoamNoise, FoamPoint, KoepkeFoam, MAX_ABS_DELTA_T_C, MSD86_RADIUS_RANGE_UM, SprayLighting,
    SprayMedium, SprayParams, SprayRay, SprayScattering, SurfaceStatistics, WhitecapLaw, msd86_flux, whitecap_coverage,
};
use proptest::prelude::*;

/// Relative rounding of `msd86_flux` (a `pow`, an `exp` and a `10^x`, a few ulps each).
const FLUX_ROUNDING: f64 = 1e-13;

/// Steepest possible rise of `ln(dF/dr)` with `ln r` (derived from the MSD86 formula):
/// `d ln(dF/dr)/d ln r = −3 + 1.05 x/(1 + x) + (2·1.19/0.650) B e^{−B²}`, `x = 0.057 r^1.05`;
/// the second term is below 1.05 and `B e^{−B²}` at most `1/√(2e)`, so the slope is below
/// `−3 + 1.05 + 3.6615/√(2e)` = −0.3796: the source falls with the radius everywhere.
fn max_log_slope() -> f64 {
    -3.0 + 1.05 + 2.0 * 1.19 / 0.650 / (2.0 * std::f64::consts::E).sqrt()
}

/// Rounding of the noise `1 + a Σ …/Σw` against its bounds `1 ± a`.
const NOISE_ROUNDING: f64 = 1e-12;

/// Largest anomalous-diffraction efficiency: the maximum of
/// `2 − (4/ρ) sin ρ + (4/ρ²)(1 − cos ρ)` (van de Hulst 1957, §11.22) is 3.17314 at `ρ` ≈ 4.086
/// (scanned on a 10⁻⁵ grid), rounded up.
const Q_E_MAX: f64 = 3.174;

/// Rounding of a cover-weighted mean age against its bound, the history length (s).
const AGE_ROUNDING_S: f64 = 1e-9;

/// Optical depth beyond which `exp(−τ)` underflows to 0 in `f64` (`e^{−745}` ≈ 5×10⁻³²⁴), less a
/// margin for the test's estimate.
const UNDERFLOW_DEPTH: f64 = 700.0;

/// Rounding of the in-scattered radiance against its bound (sums of up to two segments).
const RADIANCE_ROUNDING: f64 = 1e-12;

fn law() -> impl Strategy<Value = WhitecapLaw> {
    prop_oneof![
        Just(WhitecapLaw::Monahan1980),
        Just(WhitecapLaw::Monahan1986Wind),
        (-30.0f64..30.0).prop_map(|delta_t_c| WhitecapLaw::Monahan1986Stability { delta_t_c }),
        (-30.0f64..30.0).prop_map(|delta_t_c| WhitecapLaw::Darles2007AsPrinted { delta_t_c }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn coverage_is_the_law_up_to_a_white_sea_and_non_decreasing_in_wind(
        law in law(),
        u in 0.0f64..60.0,
        du in 0.0f64..20.0,
    ) {
        let w = |u: f64| whitecap_coverage(&CoverageParams::new(u.min(60.0), law, DARLES_ONSET_WIND_M_S).unwrap());
        // The power laws written out here, unclamped: W is the law wherever the law is a fraction,
        // and the whole sea (1) only where the law passes 1; `libm::pow` against `f64::powf` and
        // one `exp` differ by a few ulps of each.
        const POWER_LAW_ROUNDING: f64 = 1e-13;
        let raw = |u: f64| match law {
            WhitecapLaw::Monahan1980 => 3.84e-6 * u.powf(3.41),
            WhitecapLaw::Monahan1986Wind => 2.95e-6 * u.powf(3.52),
            WhitecapLaw::Monahan1986Stability { delta_t_c } => 1.95e-5 * u.powf(2.55) * (0.0861 * delta_t_c).exp(),
            WhitecapLaw::Darles2007AsPrinted { delta_t_c } => 1.59e-5 * u.powf(2.55) * (0.086 * delta_t_c).exp(),
        };
        let (a, b) = (w(u), w(u + du));
        prop_assert!(b >= a);
        if u < DARLES_ONSET_WIND_M_S {
            prop_assert!(a.abs() < f64::MIN_POSITIVE);
        } else if raw(u) <= 1.0 {
            prop_assert!((a / raw(u) - 1.0).abs() < POWER_LAW_ROUNDING, "{a} against the law's {}", raw(u));
        } else {
            prop_assert!((a - 1.0).abs() < f64::MIN_POSITIVE, "a white sea beyond the law's 1, got {a}");
        }
    }

    /// Where each law passes 1 (the doc comment's figures): the 1980 and 1986 wind laws at 38.7
    /// and 37.2 m/s, the stability law at 25.5 m/s with `ΔT = +30 °C`.
    #[test]
    fn the_laws_pass_one_only_far_outside_their_fit(eps in 0.01f64..0.1) {
        let w = |u: f64, law| whitecap_coverage(&CoverageParams::new(u, law, DARLES_ONSET_WIND_M_S).unwrap());
        let stable = WhitecapLaw::Monahan1986Stability { delta_t_c: 30.0 };
        for (law, crossing) in [(WhitecapLaw::Monahan1980, 38.74), (WhitecapLaw::Monahan1986Wind, 37.25), (stable, 25.53)] {
            prop_assert!(w(crossing - eps, law) < 1.0 && (w(crossing + eps, law) - 1.0).abs() < f64::MIN_POSITIVE);
        }
    }

    #[test]
    fn spray_source_is_finite_non_negative_bounded_and_falling(
        r_frac in 0.0f64..=1.0, u in 0.0f64..60.0, r_out in 1e-3f64..1e3, grow in 1e-3f64..2.0, u_pos in 0.1f64..60.0,
    ) {
        // A radius of the fitted range, from its ends (so the range itself is what is sampled).
        let (lo, hi) = MSD86_RADIUS_RANGE_UM;
        let r = lo * (hi / lo).powf(r_frac);
        let f = msd86_flux(r, u);
        prop_assert!(f.is_finite() && f >= 0.0);
        // Outside the fitted range the formula stays finite and non-negative (extrapolation).
        let g = msd86_flux(r_out, u);
        prop_assert!(g.is_finite() && g >= 0.0);
        // Envelope: 10^{1.19 e^{−B²}} lies in [1, 10^1.19], so dF/dr lies between
        // 1.373 U^3.41 r⁻³ (1 + 0.057 r^1.05) and 10^1.19 times that, for every r > 0.
        let base = 1.373 * u.powf(3.41) * r_out.powi(-3) * (1.0 + 0.057 * r_out.powf(1.05));
        prop_assert!(g >= base * (1.0 - FLUX_ROUNDING), "{g} < {base}");
        prop_assert!(g <= base * 10f64.powf(1.19) * (1.0 + FLUX_ROUNDING), "{g} > 10^1.19 · {base}");
        // Larger drops are rarer: ln(dF/dr) falls by at least 0.3796 per unit of ln r.
        let (f1, f2) = (msd86_flux(r_out, u_pos), msd86_flux(r_out * (1.0 + grow), u_pos));
        prop_assert!(
            (f2 / f1).ln() <= max_log_slope() * (1.0 + grow).ln() + FLUX_ROUNDING,
            "r = {r_out}: ln ratio {} over ln r step {}", (f2 / f1).ln(), (1.0 + grow).ln()
        );
    }

    #[test]
    fn stability_law_from_temperatures_is_exact_or_refused(tw in -2.0f64..=40.0, ta in -60.0f64..=60.0) {
        // ΔT = T_w − T_a is kept exactly when |ΔT| ≤ 30 °C, and refused (never clamped) beyond,
        // with the same verdict as CoverageParams::new on the same ΔT.
        let dt = tw - ta;
        match WhitecapLaw::monahan_1986_from_temperatures(tw, ta) {
            Ok(law) => {
                prop_assert!(dt.abs() <= MAX_ABS_DELTA_T_C);
                prop_assert_eq!(law, WhitecapLaw::Monahan1986Stability { delta_t_c: dt });
                prop_assert!(CoverageParams::new(10.0, law, DARLES_ONSET_WIND_M_S).is_ok());
            }
            Err(e) => {
                prop_assert!(dt.abs() > MAX_ABS_DELTA_T_C, "{e}");
                prop_assert!(e.to_string().starts_with("delta_t_c = "), "{e}");
                let law = WhitecapLaw::Monahan1986Stability { delta_t_c: dt };
                prop_assert!(CoverageParams::new(10.0, law, DARLES_ONSET_WIND_M_S).is_err());
            }
        }
    }

    #[test]
    fn anomalous_diffraction_efficiency_is_bounded(r in 1e-4f64..100.0, lambda in 300.0f64..2500.0, m in 1.01f64..2.0) {
        let q = ExtinctionEfficiency::AnomalousDiffraction { wavelength_nm: lambda, refractive_index: m }.q_e(r);
        prop_assert!((0.0..=Q_E_MAX).contains(&q), "Q_e = {q}");
    }

    #[test]
    fn foam_amount_and_noise_are_bounded(
        w in 0.0f64..1.0, y in -5.0f64..5.0, sx in -5.0f64..5.0, sz in -5.0f64..5.0,
        x in -1e4f64..1e4, z in -1e4f64..1e4, fp in 0.0f64..100.0, n in 1.0f64..20.0, a in 0.0f64..1.0, seed in 0u64..100,
    ) {
        let p = FoamExtensionParams { exponent: n, noise_amplitude: a, seed, ..FoamExtensionParams::default() };
        let s = SurfaceStatistics { y_min: -2.0, y_max: 2.0, height_std: 0.6, slope_variance_x: 0.03, slope_variance_z: 0.02 };
        let ext = FoamExtension::new(&p, &s).unwrap();
        let amount = ext.foam_amount(w, &FoamPoint { height: y, slope: [sx, sz], rest: [x, z], footprint_m: fp });
        prop_assert!((0.0..=1.0).contains(&amount));
        let nu = FoamNoise::new(a, 10.0, 5, seed).unwrap().value(x, z, fp);
        prop_assert!(nu >= 1.0 - a - NOISE_ROUNDING && nu <= 1.0 + a + NOISE_ROUNDING);
    }

    #[test]
    fn foam_history_is_bounded(t in 0.0f64..1e5, c in 0.0f64..1.0, f in 0.01f64..3.0, tau in 0.5f64..8.0) {
        let p = FoamHistoryParams { decay_time_s: tau, step_s: tau / 4.0, ..FoamHistoryParams::default() };
        let h = FoamHistory::new(&p, &KoepkeFoam::default()).unwrap();
        let s = h.accumulate(t, |s| c * (0.5 + 0.5 * (f * s.time_s).sin()));
        prop_assert!((0.0..=1.0).contains(&s.cover));
        prop_assert!(s.brightness > 0.0 && s.brightness <= 1.0);
        prop_assert!(s.mean_age_s >= 0.0 && s.mean_age_s <= 4.0 * tau + AGE_ROUNDING_S);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn extinction_and_depth_increase_with_wind(u in 0.5f64..55.0, du in 0.1f64..5.0) {
        let a = SprayMedium::new(&SprayParams { u10: u, ..SprayParams::default() }).unwrap();
        let b = SprayMedium::new(&SprayParams { u10: u + du, ..SprayParams::default() }).unwrap();
        prop_assert!(b.extinction(0.0, 1.0) > a.extinction(0.0, 1.0));
        prop_assert!(b.optical_depth() > a.optical_depth());
    }

    #[test]
    fn transmittance_and_scattering_are_physical(
        u in 0.0f64..60.0, z0 in -10.0f64..3000.0, z1 in -10.0f64..3000.0, extra in 0.0f64..5000.0, f in 0.0f64..50.0,
        sun in 0.0f64..100.0, sky in 0.0f64..10.0, cos_vs in -1.0f64..1.0, sin_h in 0.0f64..1.0,
    ) {
        let m = SprayMedium::new(&SprayParams { u10: u, ..SprayParams::default() }).unwrap();
        let len = (z1 - z0).abs() + extra;
        let t = m.transmittance(z0, z1, len, f);
        // T ∈ (0, 1]; exp(−τ) underflows to 0 only beyond τ ≈ 745 (a 2.6 km path in 50 m/s
        // spray thirty times denser than the mean reaches it).
        let tau = m.segment_optical_depth(z0, z1, len, f);
        prop_assert!(t <= 1.0 && (t > 0.0 || tau > UNDERFLOW_DEPTH), "T = {t}, τ = {tau}");
        let light = SprayLighting { sun_irradiance: sun, sin_sun_elevation: sin_h, cos_view_sun: cos_vs, sky_radiance: sky };
        let mut ray = SprayRay::new(&m, &SprayScattering::default(), &light);
        ray.step(z0, z1, len, f);
        ray.step(z1, z1 + 1.0, 100.0, f);
        prop_assert!(ray.transmittance() >= 0.0 && ray.transmittance() <= 1.0);
        prop_assert!(ray.in_scattered() >= 0.0 && ray.in_scattered().is_finite());
        // In-scattered light is bounded by the brightest source term: ϖ (E p_max + ½ L̄).
        let p_max = brine_foam::henyey_greenstein(1.0, 0.75);
        prop_assert!(ray.in_scattered() <= sun * p_max + 0.5 * sky + RADIANCE_ROUNDING);
    }
}

/// Relative rounding of a sum of twelve exponentials and their differences.
const SPUME_ROUNDING: f64 = 1e-12;

fn spume(u: f64, u_star: f64, z_s: f64) -> brine_foam::SpumeLayer {
    brine_foam::SpumeLayer::new(&brine_foam::SpumeParams {
        u10: u,
        friction_velocity_m_s: u_star,
        source_height_m: z_s,
    })
    .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// More wind, more spume (the friction velocity `c U₁₀` and the wave amplitude `f U₁₀²` rising
    /// with it, as over a real sea: `c` 0.03–0.06, `√C_D`; `f` 0.005–0.015 m⁻¹ s², around
    /// Pierson–Moskowitz's 0.0107); the haze thins upward; a ray that climbs more steeply, or
    /// starts higher, crosses less of it.
    #[test]
    fn spume_grows_with_wind_and_thins_upward(
        u in 3.0f64..40.0, du in 0.1f64..5.0, c in 0.03f64..0.06, f in 0.005f64..0.015,
        z in 0.0f64..200.0, dz in 0.01f64..50.0, y0 in 0.0f64..50.0, dy in 0.0f64..0.9, ddy in 0.001f64..0.1,
    ) {
        let layer = |u: f64| spume(u, c * u, (f * u * u).clamp(0.01, 20.0));
        let (a, b) = (layer(u), layer(u + du));
        // Strictly at the sea; higher up both may underflow to 0 (scale heights of centimetres
        // at light wind).
        prop_assert!(b.extinction(0.0) > a.extinction(0.0) && a.extinction(0.0) > 0.0);
        prop_assert!(b.extinction(z) >= a.extinction(z));
        prop_assert!(a.extinction(z + dz) < a.extinction(z) || a.extinction(z) <= 0.0);
        prop_assert!(a.optical_depth_above(z + dz) <= a.optical_depth_above(z) * (1.0 + SPUME_ROUNDING));
        let t = a.optical_depth_to_space(y0, dy);
        prop_assert!(t.is_finite() && t > 0.0);
        prop_assert!(a.optical_depth_to_space(y0, dy + ddy) < t);
        prop_assert!(a.optical_depth_to_space(y0 + dz, dy) < t);
        // Every class's scale height follows from the fall speed: smaller drops rise higher.
        let c = a.classes();
        prop_assert!(c.windows(2).all(|w| w[1].scale_height_m < w[0].scale_height_m && w[0].radius_um < w[1].radius_um));
    }

    /// A straight segment's optical depth is additive: split anywhere, the parts sum to the whole.
    #[test]
    fn spume_segments_add_up(
        u in 1.0f64..40.0, z0 in -5.0f64..60.0, z1 in -5.0f64..60.0, extra in 0.0f64..3000.0, s in 0.01f64..0.99,
    ) {
        let l = spume(u, 0.7, 3.0);
        let len = (z1 - z0).abs() + extra;
        let zm = z0 + s * (z1 - z0);
        let whole = l.segment_optical_depth(z0, z1, len);
        let parts = l.segment_optical_depth(z0, zm, s * len) + l.segment_optical_depth(zm, z1, (1.0 - s) * len);
        prop_assert!(whole >= 0.0);
        prop_assert!((whole - parts).abs() <= 1e-9 * whole.max(1e-12), "{whole} vs {parts}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// The lobe-weighted field is a weighted mean of the field: between its least and greatest
    /// values, channel by channel.
    #[test]
    fn the_lobe_is_a_mean_of_the_field(
        g in 0.0f64..0.95, a in 0.0f64..10.0, b in 0.0f64..10.0, dx in -1.0f64..1.0, dy in -1.0f64..1.0, dz in -1.0f64..1.0,
    ) {
        prop_assume!(dx * dx + dy * dy + dz * dz > 1e-3);
        let field = |w: [f64; 3]| [a + b * w[1].max(0.0), b * (1.0 - w[0].abs()), a];
        let t = brine_foam::PhaseLobeTable::new(g, field).unwrap();
        let j = t.lookup([dx, dy, dz]);
        let (lo, hi) = ([a, 0.0, a], [a + b, b, a]);
        for c in 0..3 {
            prop_assert!(j[c] >= lo[c] * (1.0 - SPUME_ROUNDING) - 1e-12 && j[c] <= hi[c] * (1.0 + SPUME_ROUNDING) + 1e-12, "{c}: {j:?}");
        }
    }
}
