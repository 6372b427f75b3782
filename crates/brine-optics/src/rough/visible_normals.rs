//! What the facets a viewer sees do with the light they reflect toward it: to the sky, or into
//! the neighbouring waves. An accurate integral over Smith's visible normals (Heitz 2014), for the
//! rough-reflectance tables.

use super::visibility::SlopeVisibility;
use crate::fresnel_dielectric;
use crate::ocean_brdf::smith_lambda;
use crate::quadrature::gauss_legendre;

/// Half-width of the integrated slope range, in slope deviations: the Gaussian beyond it holds
/// under `10⁻¹¹` of the facets.
const TAIL_SIGMAS: f64 = 7.0;
/// Panels of the outer rule (the slope along the view's azimuth).
const OUTER_PANELS: usize = 24;
/// Gauss–Legendre points per outer panel.
const OUTER_POINTS: usize = 8;
/// Gauss–Legendre points of the inner rule (the slope across the view's azimuth).
const INNER_POINTS: usize = 32;

/// The reflectance of a rough sea of isotropic Gaussian slopes toward a viewer, split by where the
/// reflected light goes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReflectanceSplit {
    /// `R_sky`: the share of the light the viewer receives by reflection that comes from the sky
    /// unobstructed (reflected above the horizon and not shadowed by another facet), for a
    /// uniform unit sky (dimensionless, `[0, 1]`).
    pub to_sky: f64,
    /// `R_seen`: the Fresnel reflectance averaged over the visible facets, wherever the reflected
    /// direction goes (dimensionless, `[0, 1]`, `≥ to_sky`). `R_seen − R_sky` is the light the
    /// viewer receives from the waves that the reflected direction meets.
    pub seen: f64,
    /// `μ_r`: the mean cosine of the visible facets' mirror directions to the mean normal,
    /// weighted as `R_seen`'s integrand (dimensionless, `[−1, 1]`, negative for a mirror
    /// direction into the sea; `cos θ_v`, the mirror's, on calm water). The facets seen lean
    /// toward the viewer, so at grazing views they reflect the sky well above the mirror
    /// direction of the mean normal.
    pub mirror_cosine: f64,
}

/// The rough sea's reflectance toward a viewer, split between the sky and the other waves: the
/// Fresnel reflectance averaged over the visible normals `D_v` (`R_seen`), and the part of it
/// whose mirror direction leaves above the horizon unshadowed (`R_sky`, Smith's height-correlated
/// masking–shadowing with the measured escape of the facets seen), as integrals over the slopes
/// `ζ`:
///
/// `R_seen = ∫∫_{v·n>0} F(v·n) p(ζ) q(ζ) r(ν, s) / (1 + Λ(v)) d²ζ`,
/// `R_sky  = ∫∫_{v·n>0, l_z>0} F(v·n) p(ζ) q(ζ) r(ν, s) e(ν, s) / (1 + Λ(v) + Λ(l)) d²ζ`,
///
/// `q = (v·n)/(n_z v_z)` (the facet's projected area), `l = 2(v·n)n − v` the mirror direction,
/// `p` the isotropic Gaussian of slope deviation `σ` per axis, `Λ` Smith's term, and
/// `r(ν, s)` ([`SlopeVisibility`]) how much more or less often than Smith's `G₁ = 1/(1 + Λ(v))`
/// a facet is seen given its slope along the view, `ν = cot θ_v/σ`, `s = (cot θ_v − ζ_x)/σ`:
/// measured on Gaussian profiles of the sea's short-wave spectrum, it leans the visible facets
/// toward the viewer at grazing views; `e(ν, s)` ([`SlopeVisibility::escape`]) how much more or
/// less often than Smith's height-correlated form the mirror direction of a facet seen at that
/// slope clears the surface, measured on the same profiles: near grazing the reflections that
/// barely rise meet the crest beyond (Smith's forms are `r = e = 1`,
/// [`reflectance_split_uncorrelated`]). `∫∫ p q r / (1 + Λ(v)) = 1` over the facing facets
/// (the visible normals' normalisation, to the table's interpolation), so `R_seen = 1` for `F = 1`.
///
/// With the view in the `xz` plane, `v·n > 0` is `ζ_x < cot θ_v` and `l_z > 0` is `ζ_y² <
/// 2q − 1 − ζ_x²`, so both integrals are taken exactly over their domains: composite
/// Gauss–Legendre in `ζ_x` over `[−7σ, min(cot θ_v, 7σ)]` (24 panels of 8 points), Gauss–Legendre
/// in `ζ_y` (32 points) over `[−7σ, 7σ]` or the reflected-above-the-horizon chord. Measured error:
/// `|R_seen − 1| < 10⁻⁹` for `F = 1` up to 89.9° with Smith's form, `< 2×10⁻³` with the measured
/// visibility (tested).
///
/// # Arguments
/// - `cos_theta_v`: `cos θ_v` of the view to the mean normal, `(0, 1]`.
/// - `sigma`: slope deviation per axis, `> 0`.
/// - `fresnel`: the facets' reflectance at `cos θ_i = v·n`, `[0, 1]` (water's, or 1 for the
///   white-furnace check).
///
/// # Returns
/// The split, both parts in `[0, 1]`.
///
/// # References
/// Bruneton E., Neyret F., Holzschuch N. 2010, CGF 29(2), Eq. 7–8 (the integrand); Heitz E. 2014,
/// "Understanding the masking-shadowing function in microfacet-based BRDFs", JCGT 3(2), Eq. 2
/// (the visible normals) and §6 (the height-correlated form); Smith B.G. 1967 (Λ); the
/// visibility's measurement in [`SlopeVisibility`].
pub fn reflectance_split(cos_theta_v: f64, sigma: f64, fresnel: impl Fn(f64) -> f64) -> ReflectanceSplit {
    split(cos_theta_v, sigma, fresnel, Some(SlopeVisibility::stored()))
}

/// [`reflectance_split`] with Smith's uncorrelated visibility and height-correlated escape
/// (`r = e = 1`: every facing facet as likely to be seen, and its reflection as likely to clear
/// the surface, whatever its slope), the form of Bruneton et al. 2010 and Heitz 2014.
///
/// # Arguments
/// As [`reflectance_split`].
///
/// # Returns
/// The split, both parts in `[0, 1]`.
///
/// # References
/// As [`reflectance_split`].
pub fn reflectance_split_uncorrelated(cos_theta_v: f64, sigma: f64, fresnel: impl Fn(f64) -> f64) -> ReflectanceSplit {
    split(cos_theta_v, sigma, fresnel, None)
}

/// The integrals of [`reflectance_split`], with the measured visibility or Smith's (`None`).
fn split(
    cos_theta_v: f64,
    sigma: f64,
    fresnel: impl Fn(f64) -> f64,
    visibility: Option<&SlopeVisibility>,
) -> ReflectanceSplit {
    debug_assert!(cos_theta_v > 0.0 && cos_theta_v <= 1.0 && sigma > 0.0);
    let c = cos_theta_v;
    let s = (1.0 - c * c).max(0.0).sqrt();
    let sigma2 = sigma * sigma;
    let lambda_v = smith_lambda(c, sigma2);
    // ν = cot θ_v/σ, infinite at normal incidence (where every facet is seen).
    let cot = if s > 0.0 { c / s } else { f64::INFINITY };
    let nu = cot / sigma;
    let (outer_x, outer_w) = gauss_legendre(OUTER_POINTS);
    let (inner_x, inner_w) = gauss_legendre(INNER_POINTS);
    let lo = -TAIL_SIGMAS * sigma;
    let hi = if s > 0.0 { (c / s).min(TAIL_SIGMAS * sigma) } else { TAIL_SIGMAS * sigma };
    let gauss = |z: f64| (-0.5 * z * z / sigma2).exp() / ((2.0 * std::f64::consts::PI).sqrt() * sigma);
    let panel = (hi - lo) / OUTER_PANELS as f64;
    let (mut seen, mut to_sky, mut mirror) = (0.0, 0.0, 0.0);
    for m in 0..OUTER_PANELS {
        let mid = lo + (m as f64 + 0.5) * panel;
        for (xi, wi) in outer_x.iter().zip(&outer_w) {
            let zx = mid + 0.5 * panel * xi;
            // q = (v·n)/(n_z v_z) = (c − ζx s)/c, ≥ 0 on the facing side.
            let facing = c - zx * s;
            if facing <= 0.0 {
                continue;
            }
            let q = facing / c;
            let seen_given_slope = visibility.map_or(1.0, |t| t.ratio(nu, (cot - zx) / sigma));
            // Once seen, how much more or less often than Smith's its reflection escapes.
            let escape_given_slope = visibility.map_or(1.0, |t| t.escape(nu, (cot - zx) / sigma));
            let weight = 0.5 * panel * wi * gauss(zx) * q * seen_given_slope;
            let across = TAIL_SIGMAS * sigma;
            let (mut sum_seen, mut sum_mirror) = (0.0, 0.0);
            for (yj, wj) in inner_x.iter().zip(&inner_w) {
                let zy = across * yj;
                let n2 = 1.0 + zx * zx + zy * zy;
                let cos_i = facing / n2.sqrt();
                let term = across * wj * gauss(zy) * fresnel(cos_i);
                sum_seen += term;
                // l_z = 2(v·n)n_z − v_z.
                sum_mirror += term * (2.0 * facing / n2 - c);
            }
            seen += weight * sum_seen;
            mirror += weight * sum_mirror;
            let chord2 = 2.0 * q - 1.0 - zx * zx;
            if chord2 <= 0.0 {
                continue;
            }
            let chord = chord2.sqrt().min(across);
            let mut sum_sky = 0.0;
            for (yj, wj) in inner_x.iter().zip(&inner_w) {
                let zy = chord * yj;
                let n2 = 1.0 + zx * zx + zy * zy;
                let l_z = 2.0 * facing / n2 - c;
                if l_z <= 0.0 {
                    continue;
                }
                let cos_i = facing / n2.sqrt();
                let lambda_l = smith_lambda(l_z.min(1.0), sigma2);
                sum_sky += chord * wj * gauss(zy) * fresnel(cos_i) / (1.0 + lambda_v + lambda_l);
            }
            to_sky += weight * escape_given_slope * sum_sky;
        }
    }
    let mirror_cosine = if seen > 0.0 { (mirror / seen).clamp(-1.0, 1.0) } else { c };
    ReflectanceSplit { to_sky, seen: seen / (1.0 + lambda_v), mirror_cosine }
}

/// [`reflectance_split`] with the Fresnel reflectance of water of index `n_water` (unpolarised).
///
/// # Arguments
/// - `cos_theta_v`, `sigma`: as [`reflectance_split`].
/// - `n_water`: index of water, `(1, 2]`.
///
/// # Returns
/// The split (dimensionless).
///
/// # References
/// As [`reflectance_split`].
pub fn water_reflectance_split(cos_theta_v: f64, sigma: f64, n_water: f64) -> ReflectanceSplit {
    reflectance_split(cos_theta_v, sigma, |ci| fresnel_dielectric(ci, 1.0, n_water))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The visible normals integrate to 1 (Smith's normalisation): the white-furnace `R_seen`,
    /// with Smith's visibility to the quadrature's accuracy, with the measured one to that of
    /// the visibility table's interpolation between its rows of `ν`.
    #[test]
    fn the_visible_normals_hold_every_viewer() {
        const QUADRATURE: f64 = 1e-9;
        // The table's rows are renormalised; between rows the linear interpolation is not
        // (`SlopeVisibility`'s own test: 2×10⁻³), and the Gauss–Legendre panels add ~10⁻⁴.
        const BETWEEN_ROWS: f64 = 2.5e-3;
        for sigma in [0.01, 0.05, 0.1, 0.2, 0.4, 0.6] {
            for deg in [0.0, 30.0, 60.0, 80.0, 85.0, 88.0, 89.0, 89.5, 89.9] {
                let c = f64::to_radians(deg).cos();
                let r = reflectance_split_uncorrelated(c, sigma, |_| 1.0);
                assert!((r.seen - 1.0).abs() < QUADRATURE, "σ {sigma}, {deg}°: {}", r.seen);
                assert!(r.to_sky <= r.seen && r.to_sky > 0.0, "σ {sigma}, {deg}°: {}", r.to_sky);
                let r = reflectance_split(c, sigma, |_| 1.0);
                assert!((r.seen - 1.0).abs() < BETWEEN_ROWS, "σ {sigma}, {deg}°: measured {}", r.seen);
                assert!(r.to_sky <= r.seen && r.to_sky > 0.0, "σ {sigma}, {deg}°: measured {}", r.to_sky);
            }
        }
    }

    /// At grazing views the facets seen lean toward the viewer more than Smith says, meet the
    /// view less obliquely and reflect less: the measured visibility lowers `R_seen` there
    /// (σ = 0.16, 1° above the horizon: 0.29 on Gaussian profiles against Smith's 0.35, measured
    /// with the profiles of the table), and leaves steep views as they were.
    #[test]
    fn grazing_views_see_steeper_facets_than_smith_says() {
        let n_water = 1.333;
        let water = |ci: f64| fresnel_dielectric(ci, 1.0, n_water);
        let c = f64::to_radians(89.0).cos();
        let (measured, smith) = (reflectance_split(c, 0.16, water), reflectance_split_uncorrelated(c, 0.16, water));
        let ratio = measured.seen / smith.seen;
        assert!((0.78..0.92).contains(&ratio), "89°, σ 0.16: {} / {} = {ratio}", measured.seen, smith.seen);
        for (deg, sigma) in [(30.0, 0.2), (60.0, 0.1), (70.0, 0.05)] {
            let c = f64::to_radians(deg).cos();
            let (a, b) = (reflectance_split(c, sigma, water), reflectance_split_uncorrelated(c, sigma, water));
            assert!((a.seen / b.seen - 1.0).abs() < 0.01, "{deg}°, σ {sigma}: {} vs {}", a.seen, b.seen);
        }
    }

    /// The mean mirror direction of the facets seen: the mirror's own on calm water; below it at
    /// steep views (tilted facets reflect away from the normal: at normal incidence
    /// `E[2n_z² − 1] = E[2/(1 + ζ²) − 1] = 1 − 4σ² + 16σ⁴ − …` for isotropic slopes); well above
    /// it at grazing views, where the facets seen lean toward the viewer, more with the measured
    /// visibility than with Smith's.
    #[test]
    fn the_facets_seen_at_grazing_views_reflect_above_the_mirror() {
        let water = |ci: f64| fresnel_dielectric(ci, 1.0, 1.333);
        // Normal incidence, small slopes: the series to σ⁴; the Fresnel weight changes by O(σ²)
        // over the facets and moves the mean by O(σ⁴) (measured: 0.3 σ⁴ at σ = 0.05).
        let sigma: f64 = 0.05;
        let r = reflectance_split(1.0, sigma, water);
        let series = 1.0 - 4.0 * sigma.powi(2) + 16.0 * sigma.powi(4);
        assert!((r.mirror_cosine - series).abs() < 2.0 * sigma.powi(4), "{} vs {series}", r.mirror_cosine);
        // At grazing views the facing facets lean toward the viewer, so even Smith's visible
        // normals reflect above the mirror direction; the measured visibility, which sees the
        // facets steep toward the viewer more often (`SlopeVisibility`), raises it further.
        for (deg, sigma) in [(85.0, 0.1), (88.0, 0.16), (89.0, 0.2)] {
            let c = f64::to_radians(deg).cos();
            let rise = |mu: f64| (mu.asin() - c.asin()).to_degrees();
            let measured = rise(reflectance_split(c, sigma, water).mirror_cosine);
            let smith = rise(reflectance_split_uncorrelated(c, sigma, water).mirror_cosine);
            assert!(smith > 0.0 && measured > smith, "{deg}°, σ {sigma}: rises {measured}° (Smith's {smith}°)");
        }
    }

    /// Both parts against a brute-force midpoint sum over a fine slope grid that tests each
    /// facet's conditions (`v·n > 0`, `l_z > 0`) point by point, with `n` and `l` built as vectors.
    #[test]
    fn the_split_is_the_brute_force_sum() {
        // Midpoint rule, 1200² cells over ±7σ: its error at the domains' cut edges, measured by
        // halving the cells, is under 2×10⁻⁴ of R here.
        const MIDPOINT: f64 = 1e-3;
        let n_water = 1.333;
        for (sigma, deg) in [(0.05, 60.0), (0.05, 87.0), (0.1, 85.0), (0.2, 80.0), (0.2, 88.0), (0.4, 70.0)] {
            let c: f64 = f64::to_radians(deg).cos();
            let v = glam::DVec3::new((1.0 - c * c).sqrt(), 0.0, c);
            let lambda_v = smith_lambda(c, sigma * sigma);
            let cells = 1200;
            let h = 14.0 * sigma / cells as f64;
            let (mut seen, mut sky, mut mirror) = (0.0, 0.0, 0.0);
            for a in 0..cells {
                for b in 0..cells {
                    let (zx, zy) = (-7.0 * sigma + (a as f64 + 0.5) * h, -7.0 * sigma + (b as f64 + 0.5) * h);
                    let n = glam::DVec3::new(-zx, -zy, 1.0).normalize();
                    let vn = v.dot(n);
                    if vn <= 0.0 {
                        continue;
                    }
                    let p = (-(zx * zx + zy * zy) / (2.0 * sigma * sigma)).exp()
                        / (2.0 * std::f64::consts::PI * sigma * sigma);
                    let cot = v.x.abs().recip() * v.z;
                    let seen_given_slope = SlopeVisibility::stored().ratio(cot / sigma, (cot - zx) / sigma);
                    let w = p * vn / (n.z * v.z) * fresnel_dielectric(vn, 1.0, n_water) * h * h * seen_given_slope;
                    seen += w / (1.0 + lambda_v);
                    let l = 2.0 * vn * n - v;
                    mirror += w / (1.0 + lambda_v) * l.z;
                    if l.z > 0.0 {
                        let escape_given_slope = SlopeVisibility::stored().escape(cot / sigma, (cot - zx) / sigma);
                        sky += w * escape_given_slope / (1.0 + lambda_v + smith_lambda(l.z, sigma * sigma));
                    }
                }
            }
            let r = water_reflectance_split(c, sigma, n_water);
            assert!((r.seen - seen).abs() < MIDPOINT * seen, "σ {sigma}, {deg}°: seen {} vs {seen}", r.seen);
            assert!((r.to_sky - sky).abs() < MIDPOINT * sky, "σ {sigma}, {deg}°: sky {} vs {sky}", r.to_sky);
            let mirror = mirror / seen;
            assert!(
                (r.mirror_cosine - mirror).abs() < MIDPOINT,
                "σ {sigma}, {deg}°: μ_r {} vs {mirror}",
                r.mirror_cosine
            );
        }
    }
}
