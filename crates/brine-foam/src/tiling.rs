//! The foam's noises made periodic over a square tile, for baked maps that repeat.

/// The patch noise made periodic over a tile ([`periodic_patches`]): direction `(m, n)` (coprime
/// integers), `g` first-octave cells across the wind per `√(m² + n²)` of tile, stretch
/// `g/stretch_divisor`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PeriodicPatches {
    /// Direction along the wind, x component (integer).
    pub m: i64,
    /// Direction along the wind, z component (integer).
    pub n: i64,
    /// Cells across the wind per `√(m² + n²)` of tile.
    pub g: i64,
    /// The stretch is `g/stretch_divisor`.
    pub stretch_divisor: i64,
}

/// The patch noise's direction, wavelength and stretch nearest to `direction_rad`,
/// `wavelength_m` and `stretch` for which the noise repeats over a square tile of side `tile_m`.
///
/// The noise is read at `(s, q) = ((d̂·x)/σ, d̂⊥·x)/λ₀`; it repeats over the tile when the tile's
/// sides map to whole cells: `d̂ = (m, n)/√(m² + n²)`, `λ₀ = L/(g√(m² + n²))` and `σ = g/M` with
/// integers `m, n, g, M`. The search minimises `|ln(λ₀′/λ₀)| + |ln(σ′/σ)| + |Δθ|` over
/// `|m|, |n| ≤ min(L/λ₀, 256)`. Round patches (`σ = 1`) keep their stretch exactly; the
/// wavelength and direction move by about `λ₀/(2L)` (relative, rad).
///
/// # Arguments
/// - `tile_m`: `L` (m), `> 0`; `wavelength_m`: `λ₀` (m), `> 0`; `stretch`: `σ ≥ 1`;
///   `direction_rad`: the wind's direction.
///
/// # Returns
/// The [`PeriodicPatches`].
pub fn periodic_patches(tile_m: f64, wavelength_m: f64, stretch: f64, direction_rad: f64) -> PeriodicPatches {
    let cells = tile_m / wavelength_m;
    let reach = cells.ceil().clamp(1.0, 256.0) as i64;
    let mut best = (f64::INFINITY, PeriodicPatches { m: 1, n: 0, g: 1, stretch_divisor: 1 });
    let gcd = |mut a: i64, mut b: i64| {
        (a, b) = (a.abs(), b.abs());
        while b != 0 {
            (a, b) = (b, a % b);
        }
        a
    };
    for m in -reach..=reach {
        for n in -reach..=reach {
            if gcd(m, n) != 1 {
                continue;
            }
            let r = ((m * m + n * n) as f64).sqrt();
            let g = (cells / r).round().max(1.0);
            let divisor = (g / stretch).round().max(1.0);
            let mut turn = (n as f64).atan2(m as f64) - direction_rad;
            turn = (turn + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
            let cost = ((g * r) / cells).ln().abs() + ((g / divisor) / stretch).ln().abs() + turn.abs();
            if cost < best.0 {
                best = (cost, PeriodicPatches { m, n, g: g as i64, stretch_divisor: divisor as i64 });
            }
        }
    }
    best.1
}
