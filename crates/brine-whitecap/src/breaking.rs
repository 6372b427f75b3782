//! Which waves break: the breaking waves' footprint, the forward face of their crests.

use glam::DVec2;

/// Share of the breaking waves' slowest phase speed in the peak's: `c_b = c_p/4`.
pub const BREAKING_SPEED_SHARE: f64 = 0.25;

/// The footprint `s_b = 1/k_b` (m) that keeps the waves faster than `c_b = c_p/4` in the
/// breaking variable, `k_b = g/c_b²` (deep water): whitecaps are the breaking of waves near the
/// spectral peak, whose crests move at a sizeable fraction of the peak's phase speed `c_p`
/// (Melville & Matusov 2002; Gemmrich, Banner & Garrett 2008); the short waves riding on them
/// break without entraining air. The share 1/4 is Brine's choice within the crest speeds those
/// studies report.
///
/// # Arguments
/// - `peak_phase_speed_m_s`: `c_p = g/ω_p` (m s⁻¹), `> 0`.
///
/// # Returns
/// `s_b` (m).
///
/// # References
/// Melville W. K., Matusov P. 2002, "Distribution of breaking waves at the ocean surface",
/// Nature 417:58–63; Gemmrich J. R., Banner M. L., Garrett C. 2008, JPO 38:1296–1312.
pub fn breaking_footprint(peak_phase_speed_m_s: f64) -> f64 {
    debug_assert!(peak_phase_speed_m_s > 0.0);
    let c_b = BREAKING_SPEED_SHARE * peak_phase_speed_m_s;
    c_b * c_b / brine_waves::G
}

/// How far ahead of the crest the whitecap of a breaking wave lies: an eighth of the breaking
/// wavelength `λ_b = 2π s_b` along the direction the waves travel. The turbulent roller of a
/// breaking wave rides on its forward face, from the crest down (Duncan 1981); the Jacobian of the
/// breaking waves is lowest at the crest itself. An eighth (the middle of the upper half of the
/// face) is Brine's choice.
///
/// # Arguments
/// - `breaking_footprint_m`: `s_b` (m), `≥ 0`.
/// - `direction_rad`: direction the waves travel, from +x toward +z (rad).
///
/// # Returns
/// The offset `(Δx, Δz)` (m).
///
/// # References
/// Duncan J. H. 1981, "An experimental investigation of breaking waves produced by a towed
/// hydrofoil", Proc. R. Soc. Lond. A 377:331–348.
pub fn forward_face_offset(breaking_footprint_m: f64, direction_rad: f64) -> DVec2 {
    let delta = std::f64::consts::TAU * breaking_footprint_m / 8.0;
    DVec2::new(direction_rad.cos(), direction_rad.sin()) * delta
}

/// The wavenumber beyond which a Gaussian footprint `s_b` (m) leaves less than `10⁻⁶` of a wave
/// (rad m⁻¹): the waves a breaking variable filtered by `s_b` can do without.
pub fn breaking_wavenumber_cut(breaking_footprint_m: f64) -> f64 {
    crate::statistics::GAUSSIAN_CUTOFF / breaking_footprint_m.max(f64::MIN_POSITIVE)
}
