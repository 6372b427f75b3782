//! Point queries of the surface that is rendered: `brine query`.

use std::collections::BTreeMap;

use glam::{DVec2, DVec3};
use rayon::prelude::*;

use crate::{Scene, World, WorldError};

/// A point and instant to query: horizontal position `(x, z)` (m) and time `t` (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QueryPoint {
    /// East coordinate (m).
    pub x: f64,
    /// South coordinate (m).
    pub z: f64,
    /// Time (s), on the scene's clock (`sea.time_s` is the still's instant).
    pub t: f64,
}

/// What the rendered sea does at a [`QueryPoint`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct QueryResult {
    /// East coordinate (m).
    pub x: f64,
    /// South coordinate (m).
    pub z: f64,
    /// Time (s).
    pub t: f64,
    /// Surface height above mean sea level (m).
    pub height_m: f64,
    /// Upward unit normal `(x, y, z)`.
    pub normal: [f64; 3],
    /// Horizontal displacement of the water particle at the surface (m): its rest position is
    /// `(x, z)` minus it.
    pub displacement_m: [f64; 2],
    /// Velocity of that particle (m/s).
    pub velocity_m_s: [f64; 3],
    /// Its vertical acceleration (m/s²).
    pub vertical_acceleration_m_s2: f64,
    /// Jacobian determinant of the horizontal map (`≤ 0` where the surface folds).
    pub jacobian: f64,
    /// Share of the point under foam, `[0, 1]`.
    pub foam: f64,
    /// Share of the point under active whitecaps, `[0, 1]`.
    pub whitecap: f64,
}

/// Parses points written `x,z` or `x,z,t`, separated by `;` or new lines (blank lines and `#`
/// comments skipped); a point without `t` takes `default_t`.
///
/// # Errors
/// A message naming the point (its line for `source = "stdin"`, its rank otherwise) and what
/// was expected.
pub fn parse_points(text: &str, default_t: f64, source: &str) -> Result<Vec<QueryPoint>, String> {
    let mut out = Vec::new();
    let by_line = source == "stdin";
    let items: Vec<&str> = if by_line { text.lines().collect() } else { text.split(';').collect() };
    for (i, raw) in items.iter().enumerate() {
        let item = raw.split('#').next().unwrap_or("").trim();
        if item.is_empty() {
            continue;
        }
        let at = if by_line { format!("{source} line {}", i + 1) } else { format!("{source} point {}", i + 1) };
        let fields: Vec<&str> = item.split([',', ' ', '\t']).filter(|f| !f.is_empty()).collect();
        if !(2..=3).contains(&fields.len()) {
            return Err(format!("{at}: expected x,z or x,z,t (metres, seconds), got {item:?}"));
        }
        let mut v = [0.0; 3];
        for (k, f) in fields.iter().enumerate() {
            let name = ["x", "z", "t"][k];
            v[k] = f
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite() && x.abs() <= 1e9)
                .ok_or_else(|| format!("{at}: {name} = {f:?} is not a finite number in [-1e9, 1e9]"))?;
        }
        out.push(QueryPoint { x: v[0], z: v[1], t: if fields.len() == 3 { v[2] } else { default_t } });
    }
    Ok(out)
}

/// Queries the sea of `scene` (the world built for its still, `world`) at `points`, in parallel,
/// results in the order of the points.
///
/// The surface is the one the renderer traces (brine-waves `SeaFrame::sample`, frozen at each
/// point's time); foam and whitecaps are the renderer's cover at a point footprint
/// ([`World::cover_at`]). Trochoid, Gerstner and sine seas answer at any time from the one
/// world; the FFT sea's whitecap statistics belong to its frame, so a world is built per
/// distinct time.
///
/// # Errors
/// [`WorldError`] if a world at another time cannot be built.
pub fn query_points(scene: &Scene, world: &World, points: &[QueryPoint]) -> Result<Vec<QueryResult>, WorldError> {
    let mut times: BTreeMap<u64, f64> = BTreeMap::new();
    for p in points {
        times.insert(p.t.to_bits(), p.t);
    }
    let fft = matches!(world.sea.surface(), brine_waves::FrameSurface::Fft(_));
    // One frame (and, for the FFT sea, one world) per distinct time.
    let mut worlds: BTreeMap<u64, World> = BTreeMap::new();
    let mut frames: BTreeMap<u64, brine_waves::SeaFrame> = BTreeMap::new();
    for (&bits, &t) in &times {
        if t.to_bits() == world.time.to_bits() {
            continue;
        }
        if fft {
            let mut s = scene.clone();
            s.sea.time_s = t;
            worlds.insert(bits, World::new(&s)?);
        } else {
            frames.insert(bits, world.ocean.at_time(t));
        }
    }
    Ok(points
        .par_iter()
        .with_min_len(256)
        .map(|p| {
            let bits = p.t.to_bits();
            let w = worlds.get(&bits).unwrap_or(world);
            let frame = frames.get(&bits).unwrap_or(&w.sea);
            let s = frame.sample(p.x, p.z);
            let at = DVec3::new(p.x, s.height, p.z);
            let cover = w.cover_at_time(at, s.normal, p.t, 0.0);
            let d: DVec2 = s.displacement;
            QueryResult {
                x: p.x,
                z: p.z,
                t: p.t,
                height_m: s.height,
                normal: s.normal.to_array(),
                displacement_m: d.to_array(),
                velocity_m_s: s.velocity.to_array(),
                vertical_acceleration_m_s2: s.vertical_acceleration,
                jacobian: s.jacobian,
                foam: cover.foam,
                whitecap: cover.whitecap,
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_parse_and_bad_ones_are_named() {
        let p = parse_points("1,2; 3.5,-4,10 ;", 7.0, "--points").unwrap();
        assert_eq!(p, vec![QueryPoint { x: 1.0, z: 2.0, t: 7.0 }, QueryPoint { x: 3.5, z: -4.0, t: 10.0 }]);
        let s = parse_points("# header\n1 2\n\n3,4,5\n", 0.0, "stdin").unwrap();
        assert_eq!(s.len(), 2);
        let e = parse_points("1,2\n3,nan\n", 0.0, "stdin").unwrap_err();
        assert!(e.contains("stdin line 2") && e.contains("z = \"nan\""), "{e}");
        let e = parse_points("1,2;3", 0.0, "--points").unwrap_err();
        assert!(e.contains("--points point 2") && e.contains("expected x,z"), "{e}");
    }
}
