//! The sea handed to other tools: point queries, meshes and baked maps of the surface that is
//! rendered (brine-waves `SeaFrame`, the same one the tracer draws).

pub mod bake;
pub mod mesh;
mod query;

pub use bake::{
    BakeMaps, BakeOptions, BakedFrame, GridLimit, MAP_NAMES, UpAxis, bake_frame, bake_frame_paths, write_bake_frame,
};
pub use mesh::{
    Mesh, MeshFormat, MeshGrid, camera_mesh, check_camera_mesh, grid_mesh, grid_mesh_band_limited, mesh_is_complete,
    write_mesh,
};
pub use query::{QueryPoint, QueryResult, parse_points, query_points};

/// Bytes of memory the machine can give now (`MemAvailable` of `/proc/meminfo`), or `None` where
/// it cannot be read.
pub fn available_memory_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Refuses a request whose estimated memory exceeds what the machine has.
///
/// # Errors
/// A message naming `what`, the estimate and what is available.
pub fn check_memory(what: &str, estimate_bytes: u64) -> Result<(), String> {
    let gib = |b: u64| b as f64 / f64::from(1u32 << 30);
    match available_memory_bytes() {
        Some(avail) if estimate_bytes > avail / 10 * 8 => Err(format!(
            "{what} would need about {:.1} GiB of memory; this machine has {:.1} GiB available (at most 80 % of it is used): ask for a smaller one",
            gib(estimate_bytes),
            gib(avail)
        )),
        _ => Ok(()),
    }
}
