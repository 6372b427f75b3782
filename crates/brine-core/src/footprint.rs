//! Pixel footprints on the sea: the fading of a component smaller than a pixel's footprint,
//! which leaves the traced surface smoothly over a distance along the ray (shared by the tracer
//! and the surfaces that fade their own waves), and the elliptical footprint of a pixel seen at a
//! slant, read as a row of round reads (shared by the mip pyramids and the foam lace).

use glam::{DVec2, DVec3};

/// Bound of `|dw/dt|·t` for `w(t) = smoothstep(1, 1.5, T/t)`: `|S'| ≤ 3` per unit of `T/t`, and
/// `|d(T/t)/dt| = (T/t)/t ≤ 1.5/t` where `w` varies.
pub const FADE_SLOPE: f64 = 4.5;

/// Bound of `|d²w/dt²|·t²` for the same `w`: `|S''| ≤ 24` and `(T/t)² ≤ 2.25` give 54, plus
/// `|S'|·|d²(T/t)/dt²| ≤ 3·3` gives 9.
pub const FADE_CURVATURE: f64 = 63.0;

/// The fade weight of a component at distance `t` along a ray, `w = smoothstep(1, 1.5, T/t)`.
///
/// `w = 0` for `t ≥ T` (the footprint exceeds the component's size: dropped), `w = 1` for
/// `t ≤ T/1.5` (kept whole), `3u² − 2u³` with `u = (T/t − 1)/0.5` between.
///
/// # Arguments
/// - `fade_distance`: `T` (m), `(0, ∞]`: the distance at which the component's size equals the
///   pixel footprint (brine-trace `LipschitzSum::component_fade_distance`).
/// - `t`: distance along the ray (m), `≥ 0`.
///
/// # Returns
/// The weight, `[0, 1]`.
///
/// # References
/// docs/equations.md §1 "Antialiasing" and §11 (Bruneton, Neyret & Holzschuch 2010, `nyquistMin` =
/// 1, `nyquistMax` = 1.5); Darles et al. 2007 §3.2 (amplitudes reduced with the pixel footprint).
#[inline]
pub fn footprint_weight(fade_distance: f64, t: f64) -> f64 {
    if t <= 0.0 || fade_distance >= 1.5 * t {
        return 1.0;
    }
    let u = ((fade_distance / t - 1.0) * 2.0).clamp(0.0, 1.0);
    u * u * (3.0 - 2.0 * u)
}

/// Derivative `dw/dt` of [`footprint_weight`] (per metre).
#[inline]
pub fn footprint_weight_slope(fade_distance: f64, t: f64) -> f64 {
    if t <= 0.0 || fade_distance >= 1.5 * t || fade_distance <= t {
        return 0.0;
    }
    let x = fade_distance / t;
    let u = (x - 1.0) * 2.0;
    // dS/du · du/dx · dx/dt = 6u(1 − u) · 2 · (−x/t).
    -12.0 * u * (1.0 - u) * x / t
}

/// Smallest `|d_y|` by which a pixel footprint is stretched along the view: the footprint on the
/// sea is `αt` across the view and `αt/max(|d_y|, 0.05)` along it (a ray of unit direction `d`,
/// `y` up; beyond 87° from the vertical the stretch stops at 20).
///
/// On the mean plane a pixel at `t` covers `αt/|d_y|` along the view, which grows without bound
/// toward the horizon and is infinite for a ray that never meets the plane (a level or rising
/// ray, which can still meet a crest above the eye). Such a ray meets the faces of the waves,
/// not the mean plane: their slopes (Cox & Munk's root-mean-square slope is 0.1 in a light air, 0.3 in a gale),
/// not the ray's, set how much of the sea the pixel spans. A fade by the unbounded stretch flattens every wave
/// along a level ray, so that it passes through the crests a camera below them must see (the
/// reference rendering, which fades nothing, sees them). Shared by the tracer's fades and the
/// shading's footprint, so that the waves a ray fades are those the shading hands to the BRDF.
pub const MIN_FOOTPRINT_GRAZING: f64 = 0.05;

/// `1/max(|d_y|, MIN_FOOTPRINT_GRAZING)²`: the squared stretch of a pixel footprint along the
/// view, for the fade distance `T = 2π/(α √(k² + σ² · this))` of a wave of wavenumber `k` whose
/// wave vector has the component `σ = k·d̂_xz` along the view.
///
/// # Arguments
/// - `d_y`: vertical component of the ray's unit direction, `[-1, 1]`.
///
/// # Returns
/// The squared stretch (dimensionless), `[1, 400]`.
///
/// # References
/// docs/equations.md §1 "Antialiasing" (the footprint on the sea; the floor is Brine's);
/// Bruneton, Neyret & Holzschuch 2010 (waves faded as the footprint reaches them).
#[inline]
pub fn footprint_stretch_squared(d_y: f64) -> f64 {
    debug_assert!((-1.0..=1.0).contains(&d_y), "d_y = {d_y} is not a unit vector's component");
    let g = d_y.abs().max(MIN_FOOTPRINT_GRAZING);
    1.0 / (g * g)
}

/// `√12`: a box of width `w` has the standard deviation `w/√12`, so a Gaussian footprint of
/// standard deviation `s` reads the pyramid level of texel width `√12 s` (same spread).
pub const BOX_WIDTH_PER_SIGMA: f64 = 3.464_101_615_137_754_6;

/// Largest ratio of an [`EllipticalFootprint`]'s major axis to its minor axis that is read as
/// such: beyond it the minor axis is widened to `major/8`, as GPUs cap anisotropic filtering, so
/// that at most 15 probes cover the ellipse.
pub const MAX_ANISOTROPY: f64 = 8.0;

/// Ratio of the probe spacing to the minor axis's standard deviation that the probes of an
/// [`EllipticalFootprint`] stay within: a row of round Gaussians of standard deviation `s`
/// spaced `2s` apart sums to a flat band within `2e^{−2π²/4} ≈ 1.4 %`.
const PROBE_SPACING_PER_SIGMA: f64 = 2.0;

/// An elliptical Gaussian footprint on the sea (a pixel seen at a slant: stretched along the
/// view), read as GPUs filter anisotropically: a row of round reads of the minor axis's width
/// along the major axis (brine-waves' mip pyramids, brine-foam's lace). A round read of the
/// ellipse's area instead keeps detail along the view that the pixel cannot hold: waves alias
/// into speckle, thin lines across the view into rows of dots.
///
/// The ellipse of standard deviations `(s_major, s_minor)` is the round Gaussian of `s_minor`
/// convolved with a 1-D Gaussian of `s_e = √(s_major² − s_minor²)` along the major axis; that
/// 1-D blur is replaced by `n` equal probes spaced `h` apart with the same variance,
/// `h² (n² − 1)/12 = s_e²`, `n ≥ 2` the fewest with `h ≤ 2 s_minor` (15 at most). A ratio above
/// [`MAX_ANISOTROPY`] widens the minor axis to `s_major/8`.
///
/// # References
/// Heckbert P. 1989, "Fundamentals of texture mapping and image warping" (elliptical
/// footprints); the `EXT_texture_filter_anisotropic` extension (probes along the major axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticalFootprint {
    /// The round reads' standard deviation (m), after any widening.
    minor_m: f64,
    /// The step from one probe to the next (m, along the major axis).
    step: DVec2,
    /// Number of probes `n ≥ 1`.
    count: usize,
    /// The major axis's standard deviation (m).
    major_m: f64,
    /// The standard deviation of the round footprint of the ellipse's area (m).
    area_m: f64,
}

impl EllipticalFootprint {
    /// A round footprint of standard deviation `sigma_m` (m, `≥ 0`): one read.
    pub fn round(sigma_m: f64) -> Self {
        debug_assert!(sigma_m >= 0.0);
        Self { minor_m: sigma_m, step: DVec2::ZERO, count: 1, major_m: sigma_m, area_m: sigma_m }
    }

    /// The footprint of standard deviations `sigma_major_m ≥ sigma_minor_m ≥ 0` (m; swapped if
    /// given the other way), the major one along `major_axis` (a horizontal direction, any
    /// non-zero length; a zero or non-finite axis gives the round footprint of the major
    /// deviation's geometric mean with the minor one).
    pub fn new(sigma_minor_m: f64, sigma_major_m: f64, major_axis: DVec2) -> Self {
        let (minor, major) = if sigma_minor_m <= sigma_major_m {
            (sigma_minor_m, sigma_major_m)
        } else {
            (sigma_major_m, sigma_minor_m)
        };
        debug_assert!(minor >= 0.0 && major.is_finite());
        let area_m = (minor * major).sqrt();
        let axis = major_axis.try_normalize();
        let Some(axis) = axis else { return Self::round(area_m) };
        let minor = minor.max(major / MAX_ANISOTROPY);
        let extra2 = major * major - minor * minor;
        // Under a tenth of the minor deviation added along the axis: one read (the round one).
        if minor <= 0.0 || extra2 <= 0.01 * minor * minor {
            return Self { area_m, ..Self::round(minor) };
        }
        let extra = extra2.sqrt();
        // The fewest with `h = s_e √(12/(n² − 1)) ≤ 2 s_minor`: `n² ≥ 1 + 12 s_e²/(2 s_minor)²`.
        let ratio = extra / (PROBE_SPACING_PER_SIGMA * minor);
        let count = ((1.0 + 12.0 * ratio * ratio).sqrt().ceil() as usize).max(2);
        let spacing = extra * (12.0 / (count * count - 1) as f64).sqrt();
        Self { minor_m: minor, step: axis * spacing, count, major_m: major, area_m }
    }

    /// The footprint, in the sea's horizontal coordinates `(x, z)`, of a pixel seen along `d` on
    /// a facet of normal `n`: the pixel's round cone of standard deviation `σ` (m, at the hit,
    /// across the ray) cut by the facet's plane and projected on the horizontal.
    ///
    /// A ray of the pixel, `d + δ` with `δ ⊥ d`, meets the facet's plane, `t` metres from the
    /// eye, displaced by `t (δ − d (n·δ)/(n·d))` to first order; with `δ = (σ/t) u₁`, `(σ/t) u₂`
    /// (`u₁, u₂, d` orthonormal) the footprint's covariance in `(x, z)` is
    /// `C = σ² (a₁a₁ᵀ + a₂a₂ᵀ)`, `aᵢ` the horizontal part of `uᵢ − d (n·uᵢ)/(n·d)`, whose
    /// eigenvectors are its axes; the minor eigenvalue is taken as `det C/λ_major`,
    /// `det C = σ⁴ (a₁ × a₂)²`, which keeps its precision when the ellipse is long. On a level
    /// facet (`n = ŷ`) it is `σ` across the view and `σ/|d_y|` along it. A facet whose normal
    /// leans along the view (a face turned away from the eye) is seen at a lower grazing angle
    /// than the mean plane, and the pixel covers more of it along the view; one turned toward the
    /// eye, less. `|n·d|` is floored at [`MIN_FOOTPRINT_GRAZING`], as `|d_y|` is for the mean
    /// plane (keeping its sign, so that `n` and `−n` give the same footprint).
    ///
    /// # Arguments
    /// - `sigma_m`: `σ` (m), `≥ 0`.
    /// - `d`: unit direction of the ray; `n`: unit normal of the facet (either side).
    ///
    /// # Returns
    /// The footprint ([`EllipticalFootprint::new`] of the eigen-axes).
    ///
    /// # References
    /// Heckbert P. 1989, "Fundamentals of texture mapping and image warping", UCB/CSD-89-516 (a
    /// pixel's footprint through the Jacobian of the screen-to-texture map); Igehy H. 1999, "Tracing ray
    /// differentials" (the displacement of a ray's neighbour on the surface's tangent plane).
    pub fn on_facet(sigma_m: f64, d: DVec3, n: DVec3) -> Self {
        debug_assert!(sigma_m >= 0.0 && d.is_normalized() && n.is_normalized(), "σ {sigma_m}, d {d}, n {n}");
        let cos = n.dot(d);
        let cos = if cos < 0.0 { cos.min(-MIN_FOOTPRINT_GRAZING) } else { cos.max(MIN_FOOTPRINT_GRAZING) };
        let (u1, u2) = d.any_orthonormal_pair();
        let a = |u: DVec3| {
            let v = u - d * (n.dot(u) / cos);
            DVec2::new(v.x, v.z)
        };
        let (a1, a2) = (a(u1), a(u2));
        let (xx, xz, zz) = (a1.x * a1.x + a2.x * a2.x, a1.x * a1.y + a2.x * a2.y, a1.y * a1.y + a2.y * a2.y);
        let (mean, half) = (0.5 * (xx + zz), 0.5 * (xx - zz));
        let r = half.hypot(xz);
        let major = mean + r;
        let det = a1.perp_dot(a2).powi(2);
        let minor = if major > 0.0 { det / major } else { 0.0 };
        // The major eigenvector, from whichever row of `C − λI` is the better conditioned.
        let axis = if half >= 0.0 { DVec2::new(major - zz, xz) } else { DVec2::new(xz, major - xx) };
        Self::new(sigma_m * minor.sqrt(), sigma_m * major.sqrt(), axis)
    }

    /// The round reads' standard deviation (m).
    pub fn minor_m(&self) -> f64 {
        self.minor_m
    }

    /// The number of probes.
    pub fn probes(&self) -> usize {
        self.count
    }

    /// The major axis's standard deviation (m).
    pub fn major_m(&self) -> f64 {
        self.major_m
    }

    /// The standard deviation of the round footprint of the same area, `√(s_minor s_major)` of
    /// the axes given (m): what an isotropic filter reads.
    pub fn area_sigma_m(&self) -> f64 {
        self.area_m
    }

    /// The probes' offsets from the centre (m, `(x, z)`), evenly spaced along the major axis and
    /// centred.
    pub fn offsets(&self) -> impl Iterator<Item = DVec2> + '_ {
        let half = 0.5 * (self.count - 1) as f64;
        (0..self.count).map(move |i| self.step * (i as f64 - half))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative rounding of the probes' variance: a sum of at most 14 squares.
    const PROBE_VARIANCE_ROUNDING: f64 = 1e-12;

    /// The stretch along the view is the mean plane's `1/|d_y|` down to 87° from the vertical
    /// and 20 beyond, for falling, level and rising rays: values worked by hand.
    #[test]
    fn the_stretch_is_the_mean_planes_down_to_the_floor() {
        for (d_y, stretch) in
            [(-1.0, 1.0), (0.5, 2.0), (-0.1, 10.0), (-0.05, 20.0), (-0.01, 20.0), (0.0, 20.0), (0.02, 20.0)]
        {
            let s2 = footprint_stretch_squared(d_y);
            assert!((s2 - stretch * stretch).abs() <= 1e-12 * s2, "d_y = {d_y}: {s2}");
        }
    }

    /// On a level facet the footprint is the mean plane's, `σ` across and `σ/max(|d_y|, 0.05)`
    /// along the view; on a facet tilted by `β` about the axis across the view, seen `γ` below the
    /// horizon, it is `σ cos β / sin(γ − β)` along (`n·d = −sin(γ − β)`, the tangent-plane length
    /// `σ/|n·d|` projected by `cos β`): longer on a face turned away from the eye (`β > 0`), shorter
    /// on one turned toward it. Values worked by hand.
    #[test]
    fn a_facet_turned_away_stretches_the_footprint_along_the_view() {
        let sigma = 0.02;
        for (gamma_deg, beta_deg) in
            [(10.0, 0.0), (10.0, 5.0), (10.0, -5.0), (30.0, 20.0), (60.0, -25.0), (2.0, 0.0), (12.0, 10.0)]
        {
            let (g, b) = (f64::to_radians(gamma_deg), f64::to_radians(beta_deg));
            for yaw in [0.0, 1.0, 2.5] {
                let along = DVec2::from_angle(yaw);
                let d = DVec3::new(g.cos() * along.x, -g.sin(), g.cos() * along.y);
                let n = DVec3::new(b.sin() * along.x, b.cos(), b.sin() * along.y);
                let e = EllipticalFootprint::on_facet(sigma, d, n);
                // Seen from below the facet (`n·d > 0`) the footprint is the same.
                let below = EllipticalFootprint::on_facet(sigma, d, -n);
                assert!((below.major_m() - e.major_m()).abs() <= 1e-15 * e.major_m(), "γ {gamma_deg}, β {beta_deg}");
                assert!((below.minor_m() - e.minor_m()).abs() <= 1e-15 * e.major_m(), "γ {gamma_deg}, β {beta_deg}");
                // Under the floor the along axis is `u₂ − d (n·u₂)/(−0.05)` projected, `u₂` the
                // unit vector across `d` in the vertical plane: `n·u₂ = cos(γ − β)`, so
                // `cos(γ − β)/0.05` along the facet, whose horizontal part is
                // `(sin γ + cos γ cos(γ − β)/0.05)`. On a level facet (γ = 2°, β = 0) that is
                // `sin γ + cos²γ/0.05`, 20.01 where the mean plane's stretch stops at 20.
                let expected = if (g - b).sin() >= MIN_FOOTPRINT_GRAZING {
                    sigma * b.cos() / (g - b).sin()
                } else {
                    sigma * (g.sin() + g.cos() * (g - b).cos() / MIN_FOOTPRINT_GRAZING)
                };
                let level = EllipticalFootprint::new(sigma, expected, along);
                assert!(
                    (e.major_m() - level.major_m()).abs() <= 1e-12 * expected,
                    "γ {gamma_deg}, β {beta_deg}: {e:?}"
                );
                assert!(
                    (e.area_sigma_m() - (sigma * expected).sqrt()).abs() <= 1e-12 * sigma,
                    "γ {gamma_deg}, β {beta_deg}"
                );
                assert!((e.minor_m() - level.minor_m()).abs() <= 1e-12 * sigma, "γ {gamma_deg}, β {beta_deg}: {e:?}");
                assert_eq!(e.probes(), level.probes(), "γ {gamma_deg}, β {beta_deg}");
                if e.probes() > 1 && expected > sigma {
                    assert!(
                        e.step.perp_dot(along).abs() <= 1e-12 * e.step.length(),
                        "γ {gamma_deg}, β {beta_deg}: {e:?}"
                    );
                }
            }
        }
    }

    /// Relative error of the central difference below: `O(ε²)` with `ε = 10⁻⁵` and
    /// `1/|n·d| ≤ 10`, far under this.
    const RAY_DIFFERENCE: f64 = 1e-6;

    proptest::proptest! {
        /// The footprint is the pixel's rays cut by the facet's plane, computed without the
        /// formula: rays `d ± ε uᵢ` from an eye `t` before the hit meet the plane exactly, and
        /// the central differences of their horizontal hits give the covariance `σ² Σ aᵢaᵢᵀ`,
        /// whose eigenvalues are the footprint's axes. Its area is `σ² |n_y|/|n·d|` (the pixel's
        /// cross-section divided by `|n·d|` on the facet, projected by `|n_y|`).
        #[test]
        fn the_footprint_is_the_pixels_rays_cut_by_the_facet(
            down in 0.1f64..1.5, yaw in 0.0f64..std::f64::consts::TAU,
            tilt in 0.0f64..0.9, tilt_dir in 0.0f64..std::f64::consts::TAU, sigma in 1e-3f64..1.0,
        ) {
            let d = DVec3::new(down.cos() * yaw.cos(), -down.sin(), down.cos() * yaw.sin());
            let n = DVec3::new(tilt.sin() * tilt_dir.cos(), tilt.cos(), tilt.sin() * tilt_dir.sin());
            proptest::prop_assume!(n.dot(d) <= -0.1);
            let (t, eps) = (50.0, 1e-5);
            let hit = DVec3::new(3.0, 0.5, -7.0);
            let eye = hit - t * d;
            let (u1, u2) = d.any_orthonormal_pair();
            let offset = |u: DVec3| {
                let at = |s: f64| {
                    let r = (d + s * u).normalize();
                    let x = eye + r * (n.dot(hit - eye) / n.dot(r)) - hit;
                    DVec2::new(x.x, x.z)
                };
                (at(eps) - at(-eps)) / (2.0 * eps * t)
            };
            let (a1, a2) = (offset(u1), offset(u2));
            let (xx, xz, zz) = (a1.x * a1.x + a2.x * a2.x, a1.x * a1.y + a2.x * a2.y, a1.y * a1.y + a2.y * a2.y);
            let r = (0.5 * (xx - zz)).hypot(xz);
            let (major, minor) = ((0.5 * (xx + zz) + r).sqrt() * sigma, (0.5 * (xx + zz) - r).max(0.0).sqrt() * sigma);
            let e = EllipticalFootprint::on_facet(sigma, d, n);
            // The area's closed form against the formula's: rounding only.
            let area = sigma * (n.y / n.dot(d)).abs().sqrt();
            proptest::prop_assert!((e.area_sigma_m() - area).abs() <= 1e-12 * area, "{e:?} against area {area}");
            // A nearly round footprint (`major² ≤ 1.01 minor²`) is read as the round one of its
            // minor axis; beyond a ratio of 8 the minor axis is widened.
            if major > 1.006 * minor {
                proptest::prop_assert!((e.major_m() - major).abs() <= RAY_DIFFERENCE * major, "{e:?} against {major}");
                if major <= 7.9 * minor {
                    proptest::prop_assert!((e.minor_m() - minor).abs() <= RAY_DIFFERENCE * major, "{e:?} against {minor}");
                }
            }
            if e.probes() > 1 && major > 1.01 * minor {
                // Along the major eigenvector: `C v = λ v`, within 10⁻⁴ λ (the differences' error
                // is about 10⁻⁸; an axis 0.3° off the eigenvector of a ratio of 1.01 fails).
                let v = e.step.normalize();
                let cv = DVec2::new(xx * v.x + xz * v.y, xz * v.x + zz * v.y) * sigma * sigma;
                proptest::prop_assert!((cv - v * major * major).length() <= 1e-4 * major * major, "{e:?}");
            }
        }

        /// The probes have the ellipse's extra variance along the axis, `s_major² − s_minor²`
        /// (the minor axis widened to `s_major/8` beyond [`MAX_ANISOTROPY`]), at most 15 of them,
        /// spaced at most `2 s_minor` apart, centred.
        #[test]
        fn the_probes_carry_the_ellipses_variance(
            minor in 1e-3f64..10.0, ratio in 1.0f64..40.0, angle in 0.0f64..std::f64::consts::TAU,
        ) {
            let major = minor * ratio;
            let e = EllipticalFootprint::new(minor, major, DVec2::from_angle(angle) * 3.0);
            let widened = minor.max(major / MAX_ANISOTROPY);
            proptest::prop_assert!((e.minor_m() - widened).abs() <= 1e-15 * widened);
            let n = e.probes() as f64;
            proptest::prop_assert!(e.probes() <= 15);
            let offsets: Vec<DVec2> = e.offsets().collect();
            let mean = offsets.iter().sum::<DVec2>() / n;
            proptest::prop_assert!(mean.length() <= 1e-12 * major);
            let variance = offsets.iter().map(|o| o.length_squared()).sum::<f64>() / n;
            let extra = major * major - widened * widened;
            if e.probes() > 1 {
                proptest::prop_assert!((variance - extra).abs() <= PROBE_VARIANCE_ROUNDING * extra);
                proptest::prop_assert!(e.step.length() <= PROBE_SPACING_PER_SIGMA * widened * (1.0 + 1e-12));
                // Along the axis given.
                proptest::prop_assert!(e.step.perp_dot(DVec2::from_angle(angle)).abs() <= 1e-12 * e.step.length());
            } else {
                proptest::prop_assert!(extra <= 0.01 * widened * widened * (1.0 + 1e-12));
            }
        }

    }
}
