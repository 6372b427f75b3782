//! The FFT sea's particle kinematics (positions, velocities, accelerations of the water on its rest grids) and its Jacobian fields filtered by a footprint.

use super::*;

/// `∂h̃/∂t = −iω h̃₀(k) e^{−iωτ} + iω conj(h̃₀(−k)) e^{iωτ}`.
#[inline]
pub(super) fn evolve_rate(m: &Mode, tau: f64) -> Complex64 {
    let (s, c) = libm::sincos(m.omega * tau);
    let i_omega = Complex64::new(0.0, m.omega);
    -i_omega * (m.h0 * Complex64::new(c, -s)) + i_omega * (m.h0_minus_conj * Complex64::new(c, s))
}

/// The kinematic fields of one cascade at phase time `tau`.
pub(super) fn synthesise_kinematics(c: &CascadeSpectrum, tau: f64) -> CascadeKinematics {
    synthesise_kinematics_weighted(c, tau, &|_| 1.0)
}

/// [`synthesise_kinematics`] with each mode's amplitude times `weight(mode)` (`[0, 1]`; modes
/// of weight 0 left out, those of weight 1 unchanged to the bit).
pub(super) fn synthesise_kinematics_weighted(
    c: &CascadeSpectrum,
    tau: f64,
    weight: &(dyn Fn(&Mode) -> f64 + Sync),
) -> CascadeKinematics {
    let n = c.n;
    let mut packs: Vec<Vec<Complex64>> = (0..5).map(|_| vec![Complex64::ZERO; n * n]).collect();
    for m in &c.modes {
        let w = weight(m);
        if w <= 0.0 {
            continue;
        }
        let (h, r) =
            if w < 1.0 { (evolve(m, tau) * w, evolve_rate(m, tau) * w) } else { (evolve(m, tau), evolve_rate(m, tau)) };
        let ih = Complex64::new(-h.im, h.re);
        let ir = Complex64::new(-r.im, r.re);
        let inv_k = 1.0 / m.k;
        let (ux, uz) = (m.kx * inv_k, m.kz * inv_k);
        packs[0][m.index] = pack(ih * ux, ih * uz);
        packs[1][m.index] = pack(-h * (m.kx * ux), -h * (m.kz * uz));
        packs[2][m.index] = pack(-h * (m.kx * uz), r);
        packs[3][m.index] = pack(ir * ux, ir * uz);
        // ∂²h̃/∂t² = −ω² h̃ (each mode oscillates at its own ω).
        packs[4][m.index] = pack(-h * (m.omega * m.omega), Complex64::ZERO);
    }
    packs.par_iter_mut().for_each(|p| inverse_fft_2d(p, n, c.fft.as_ref()));
    let re = |p: &[Complex64]| p.iter().map(|v| v.re as f32).collect::<Vec<f32>>();
    let im = |p: &[Complex64]| p.iter().map(|v| v.im as f32).collect::<Vec<f32>>();
    CascadeKinematics {
        n,
        tile: c.tile,
        displacement_x: re(&packs[0]),
        displacement_z: im(&packs[0]),
        dxx: re(&packs[1]),
        dzz: im(&packs[1]),
        dxz: re(&packs[2]),
        height_rate: im(&packs[2]),
        displacement_x_rate: re(&packs[3]),
        displacement_z_rate: im(&packs[3]),
        height_acceleration: re(&packs[4]),
    }
}

/// One cascade's kinematic fields on its rest grid (f32, row by row as [`FftRestFields`]), per
/// unit choppiness for the displacements.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct CascadeKinematics {
    pub(super) n: usize,
    pub(super) tile: f64,
    pub(super) displacement_x: Vec<f32>,
    displacement_z: Vec<f32>,
    dxx: Vec<f32>,
    dzz: Vec<f32>,
    dxz: Vec<f32>,
    pub(super) height_rate: Vec<f32>,
    displacement_x_rate: Vec<f32>,
    displacement_z_rate: Vec<f32>,
    height_acceleration: Vec<f32>,
}

/// What the particles of one cascade do at a rest position: see [`FftKinematics::at_rest`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ParticleState {
    /// Horizontal displacement `λD(u)` (m).
    pub displacement: DVec2,
    /// Deformation `M = I + λ∇D` as `(M_xx, M_xz, M_zz)` (dimensionless, symmetric).
    pub deformation: DVec3,
    /// Particle velocity `(λ∂Dₓ/∂t, ∂h/∂t, λ∂D_z/∂t)` (m s⁻¹).
    pub velocity: DVec3,
    /// Vertical particle acceleration `∂²h/∂t²` (m s⁻²).
    pub vertical_acceleration: f64,
}

/// The particle kinematics of an [`FftOcean`] at one instant ([`FftOcean::kinematics`]): per
/// cascade, the displacement `λD(u)`, its gradient and the time derivatives of height and
/// displacement on the rest grid, read bilinearly (periodic).
#[derive(Debug, Clone, PartialEq)]
pub struct FftKinematics {
    pub(super) choppiness: f64,
    pub(super) cascades: Vec<CascadeKinematics>,
    /// Per cascade, its tile-and-blend (as the frame's).
    pub(super) blends: Vec<Option<TileBlend>>,
}

/// Newton steps of the rest-position search ([`FftKinematics::rest_position`]): each squares the
/// error while the cascade does not fold; 6 reach the f32 fields' rounding from `u = x`.
pub(super) const REST_NEWTON_STEPS: usize = 6;

impl FftKinematics {
    /// Number of cascades.
    pub fn cascade_count(&self) -> usize {
        self.cascades.len()
    }

    /// The state of cascade `c`'s particle of rest position `u`.
    ///
    /// # Arguments
    /// - `c`: cascade, `< cascade_count()`; `u`: rest position (m), finite.
    ///
    /// # Returns
    /// The [`ParticleState`] (bilinear in the grid's cells).
    pub fn at_rest(&self, c: usize, u: DVec2) -> ParticleState {
        match &self.blends[c] {
            None => self.tile_at_rest(c, u),
            // The corners' states blended as the height is (the deformation's `D ∇ŵ` terms, of
            // relative size `|D|/S`, left out).
            Some(b) => {
                let mut out = ParticleState {
                    displacement: DVec2::ZERO,
                    deformation: DVec3::new(1.0, 0.0, 1.0),
                    velocity: DVec3::ZERO,
                    vertical_acceleration: 0.0,
                };
                for k in b.corners(u.x, u.y) {
                    if k.weight > 0.0 {
                        let p = self.tile_at_rest(c, u + DVec2::new(k.offset[0], k.offset[1]));
                        out.displacement += k.weight * p.displacement;
                        out.deformation += k.weight * (p.deformation - DVec3::new(1.0, 0.0, 1.0));
                        out.velocity += k.weight * p.velocity;
                        out.vertical_acceleration += k.weight * p.vertical_acceleration;
                    }
                }
                out
            }
        }
    }

    /// [`Self::at_rest`] on the tile itself (no blend).
    fn tile_at_rest(&self, c: usize, u: DVec2) -> ParticleState {
        let k = &self.cascades[c];
        let l = self.choppiness;
        let (i00, i10, i01, i11, s, t) = bilinear_cell(k.n, k.tile, u);
        let f = |v: &[f32]| {
            let a = f64::from(v[i00]) + (f64::from(v[i10]) - f64::from(v[i00])) * s;
            let b = f64::from(v[i01]) + (f64::from(v[i11]) - f64::from(v[i01])) * s;
            a + (b - a) * t
        };
        ParticleState {
            displacement: l * DVec2::new(f(&k.displacement_x), f(&k.displacement_z)),
            deformation: DVec3::new(1.0 + l * f(&k.dxx), l * f(&k.dxz), 1.0 + l * f(&k.dzz)),
            velocity: DVec3::new(l * f(&k.displacement_x_rate), f(&k.height_rate), l * f(&k.displacement_z_rate)),
            vertical_acceleration: f(&k.height_acceleration),
        }
    }

    /// The rest position `u` of cascade `c`'s particle now above `x`: `u + λD(u) = x`, by Newton's
    /// method from `u = x` (where the cascade folds, the sheet found first).
    ///
    /// # Arguments
    /// - `c`: cascade; `x`: horizontal position (m), finite.
    ///
    /// # Returns
    /// `u` (m) and the particle's state there.
    pub fn rest_position(&self, c: usize, x: DVec2) -> (DVec2, ParticleState) {
        let mut u = x;
        let mut p = self.at_rest(c, u);
        for _ in 0..REST_NEWTON_STEPS {
            let r = u + p.displacement - x;
            let m = p.deformation;
            let det = m.x * m.z - m.y * m.y;
            // Near a fold the Newton step is unreliable: fall back to the fixed-point step.
            let step = if det > 0.05 { DVec2::new(m.z * r.x - m.y * r.y, m.x * r.y - m.y * r.x) / det } else { r };
            u -= step;
            p = self.at_rest(c, u);
        }
        (u, p)
    }
}

/// The bilinear cell of `u` on a periodic `n × n` grid of side `tile`: four indices and the
/// fractions.
pub(super) fn bilinear_cell(n: usize, tile: f64, u: DVec2) -> (usize, usize, usize, usize, f64, f64) {
    let inv = n as f64 / tile;
    let (a, b) = (u.x * inv, u.y * inv);
    let (fa, fb) = (a.floor(), b.floor());
    let nn = n as i64;
    let (i0, j0) = ((fa as i64).rem_euclid(nn), (fb as i64).rem_euclid(nn));
    let (i1, j1) = ((i0 + 1) % nn, (j0 + 1) % nn);
    let idx = |i: i64, j: i64| (j * nn + i) as usize;
    (idx(i0, j0), idx(i1, j0), idx(i0, j1), idx(i1, j1), a - fa, b - fb)
}

/// A Gaussian gain `e^{−x²/2}` falls below `10⁻⁶` beyond `x = 5.26`.
pub(super) const GAUSSIAN_KEEP: f64 = 5.256_521_769_756_932;

/// The three displacement derivatives of one cascade's modes below `k_max` at phase time `tau`,
/// each mode filtered by the Gaussian footprint `s`.
pub(super) fn synthesise_jacobian(
    c: &CascadeSpectrum,
    tau: f64,
    s: f64,
    k_max: f64,
    shift_m: [f64; 2],
) -> FftRestJacobian {
    let n = c.n;
    let mut packs: Vec<Vec<Complex64>> = (0..2).map(|_| vec![Complex64::ZERO; n * n]).collect();
    // The modes lie on the tile's lattice, `k = (2π/L)(i, j)`, so a shift by whole tiles changes
    // nothing, and `e^{ik·a} = e^{i i θₓ} e^{i j θ_z}` with `θ = 2πa/L`: one table per axis.
    let (sx, sz) = (shift_m[0].rem_euclid(c.tile), shift_m[1].rem_euclid(c.tile));
    let shifted = sx != 0.0 || sz != 0.0;
    // Tables over the wave numbers `−N/2 ..= N/2`, read at each mode's own `(i, j) = kL/2π`.
    let half = (n / 2) as i64;
    let table = |a: f64| -> Vec<Complex64> {
        let theta = std::f64::consts::TAU * a / c.tile;
        (-half..=half)
            .map(|i| {
                let (sin, cos) = libm::sincos(i as f64 * theta);
                Complex64::new(cos, sin)
            })
            .collect()
    };
    let (phase_x, phase_z) = if shifted { (table(sx), table(sz)) } else { (Vec::new(), Vec::new()) };
    let wave = |k: f64| ((k * c.tile / std::f64::consts::TAU).round() as i64 + half) as usize;
    for m in c.modes.iter().filter(|m| m.k <= k_max) {
        let mut h = evolve(m, tau) * (-0.5 * m.k * m.k * s * s).exp();
        if shifted {
            h *= phase_x[wave(m.kx)] * phase_z[wave(m.kz)];
        }
        let inv_k = 1.0 / m.k;
        let (ux, uz) = (m.kx * inv_k, m.kz * inv_k);
        packs[0][m.index] = pack(-h * (m.kx * ux), -h * (m.kz * uz));
        packs[1][m.index] = pack(-h * (m.kx * uz), Complex64::ZERO);
    }
    packs.par_iter_mut().for_each(|p| inverse_fft_2d(p, n, c.fft.as_ref()));
    FftRestJacobian {
        resolution: n,
        blend: None,
        tile_size: c.tile,
        dxx: packs[0].iter().map(|v| v.re).collect(),
        dzz: packs[0].iter().map(|v| v.im).collect(),
        dxz: packs[1].iter().map(|v| v.re).collect(),
    }
}

/// The horizontal-displacement derivatives of one cascade on its rest grid, per unit choppiness
/// ([`FftOcean::rest_jacobian_fields`]); same conventions as [`FftRestFields`].
#[derive(Debug, Clone, PartialEq)]
pub struct FftRestJacobian {
    /// Grid resolution `N`.
    pub resolution: usize,
    /// The cascade's tile-and-blend ([`FftOcean::tile_blend`]): read the grid at its corners'
    /// offsets (rest positions), `None` for a tiled sea.
    pub blend: Option<TileBlend>,
    /// Tile size `L` (m).
    pub tile_size: f64,
    /// `∂Dₓ/∂x` (dimensionless).
    pub dxx: Vec<f64>,
    /// `∂D_z/∂z`.
    pub dzz: Vec<f64>,
    /// `∂Dₓ/∂z`.
    pub dxz: Vec<f64>,
}

impl FftRestJacobian {
    /// `J = (1 + λ∂Dₓ/∂x)(1 + λ∂D_z/∂z) − λ²(∂Dₓ/∂z)²` at grid index `idx` for choppiness `λ`.
    pub fn jacobian(&self, idx: usize, choppiness: f64) -> f64 {
        let l = choppiness;
        (1.0 + l * self.dxx[idx]) * (1.0 + l * self.dzz[idx]) - l * l * self.dxz[idx] * self.dxz[idx]
    }
}
