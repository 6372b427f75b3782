"""Mitsuba 3's side of `cargo xtask bench peers` (run by benches/peers.rs in its venv).

Arguments: camera.json, depth.f32 (Brine's depth AOV, row-major f32, top row first), runs,
ranges (m, comma-separated), then the meshes (PLY). For each mesh, prints (as one JSON list on standard output)
the median time of loading the scene (the BVH build) and of one 1-spp pass of the depth AOV
integrator at the pixel centres, and the 99th percentiles of |depth − Brine's| and of the height
difference |depth − Brine's|·|d_y| over the pixels where Brine's depth is below each range,
silhouette pixels left out.
"""

import json
import statistics
import sys
import time

import mitsuba as mi
import numpy as np

mi.set_variant("llvm_ad_rgb")
mi.set_log_level(mi.LogLevel.Error)


def median_time(f, runs):
    times, out = [], None
    for _ in range(runs):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main():
    cam = json.load(open(sys.argv[1]))
    w, h = cam["width"], cam["height"]
    brine = np.fromfile(sys.argv[2], dtype="<f4").reshape(h, w)
    runs, reaches = int(sys.argv[3]), [float(r) for r in sys.argv[4].split(",")]
    pos = np.array(cam["position"])
    target = pos + np.array(cam["forward"])
    # Pixels on a silhouette (a crest in front of the sea behind it): Brine's depth jumps by more
    # than 2 % to a neighbour in the same row (along a row the depth of a smooth sea changes
    # slowly; down a column it changes fast by itself at grazing angles, so columns are not
    # read). There a sub-millimetre change of the surface moves the pixel centre's ray from one
    # wave to the other: the depth measures which side the centre falls on, not how close the
    # surfaces are. They are left out and counted.
    d = np.where(np.isfinite(brine), brine, 1e9)
    jump = np.abs(np.diff(d, axis=1)) > 0.02 * np.minimum(d[:, 1:], d[:, :-1])
    silhouettes = np.zeros_like(jump, shape=d.shape)
    silhouettes[:, 1:] |= jump
    silhouettes[:, :-1] |= jump
    # The vertical component of each pixel-centre ray (Brine's pinhole camera): a depth
    # difference `e` along a ray is a height difference `e |d_y|` between the two surfaces.
    fw, up, right = (np.array(cam[k]) for k in ("forward", "up", "right"))
    tan = np.tan(np.radians(cam["fov_y_deg"]) / 2.0)
    xs = (2.0 * (np.arange(w) + 0.5) / w - 1.0) * tan * w / h
    ys = (1.0 - 2.0 * (np.arange(h) + 0.5) / h) * tan
    rays = fw + xs[None, :, None] * right + ys[:, None, None] * up
    dy = np.abs(rays[..., 1]) / np.linalg.norm(rays, axis=-1)
    results = []
    for path in sys.argv[5:]:
        desc = {
            "type": "scene",
            "integrator": {"type": "aov", "aovs": "dd.y:depth"},
            "sensor": {
                "type": "perspective",
                "fov": cam["fov_y_deg"],
                "fov_axis": "y",
                # Rays from the eye itself (the default 1 cm near plane would shorten every depth).
                "near_clip": 1e-6,
                "to_world": mi.ScalarTransform4f().look_at(
                    origin=pos.tolist(), target=target.tolist(), up=cam["up"]
                ),
                # One sample at each pixel's centre, as Brine's 1-spp frame.
                "sampler": {"type": "stratified", "sample_count": 1, "jitter": False},
                "film": {"type": "hdrfilm", "width": w, "height": h, "rfilter": {"type": "box"}},
            },
            "sea": {"type": "ply", "filename": path, "face_normals": True},
        }
        load_s, scene = median_time(lambda: mi.load_dict(desc), runs)

        def trace():
            img = mi.render(scene, spp=1)
            return np.array(img)

        trace_s, img = median_time(trace, runs)
        depth = img[..., -1]
        err = np.abs(depth - brine)
        ok = np.isfinite(brine) & (depth > 0) & ~silhouettes
        p99, height = [], []
        for reach in reaches:
            sel = ok & (brine < reach)
            p99.append(float(np.percentile(err[sel], 99)) if sel.any() else float("nan"))
            height.append(float(np.percentile((err * dy)[sel], 99)) if sel.any() else float("nan"))
        results.append(
            {
                "load_s": load_s,
                "trace_s": trace_s,
                "depth_p99_m": p99,
                "height_p99_m": height,
                "silhouette_pixels": int(silhouettes.sum()),
            }
        )
    print(json.dumps(results))


if __name__ == "__main__":
    main()
