"""Speed of the bindings against the same work in Rust: `python python/benches/bench.py` (after
`pip install ./python` and `cargo bench -p brine-render --bench export --no-run`).

Times 10⁶ surface queries of the default sea with 50 waves, as the export bench pins it, through
`brine.Scene.query` (the points of the export bench), medians of 5, and runs the export bench's query task for the Rust figure; prints
the ratio. Also times 10⁶ sun positions and 10⁶ sky radiances (no Rust counterpart printed).
"""

import glob
import os
import re
import statistics
import subprocess
import sys
import time

import numpy as np

import brine

RUNS = 5


def median_s(f):
    times = []
    for _ in range(RUNS):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def main():
    n = 1_000_000
    i = np.arange(n, dtype=float)
    a, b = np.modf(i * 0.618_034)[0], np.modf(i * 0.754_878)[0]
    x, z = 1000.0 * a - 500.0, 1000.0 * b - 500.0
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with open(os.path.join(root, "crates", "brine-render", "scenes", "default.toml"), encoding="utf-8") as f:
        default = f.read()
    assert "\n[sea]\n" in default, "the default scene has a [sea] table"
    scene = brine.Scene(default.replace("\n[sea]\n", "\n[sea]\nwaves = 50\n", 1), "default scene, 50 waves")
    scene.query(x[:10], z[:10])  # the world, built once outside the timings as in the Rust bench
    py = median_s(lambda: scene.query(x, z))
    print(f"Python: 10⁶ queries of the default sea, 50 waves: {py:.3f} s ({1 / py:.2f} M points/s)")
    unix = 1.7e9 + i * 60.0
    sun = median_s(lambda: brine.sun_position(unix, lat=45.0, lon=-3.0))
    print(f"Python: 10⁶ sun positions (SPA): {sun:.3f} s")
    e, az = (i % 900) / 10.0, (i * 0.37) % 360.0
    sky = median_s(lambda: brine.sky_radiance(e, az, sun_elevation_deg=30.0))
    print(f"Python: 10⁶ sky radiances (Preetham): {sky:.3f} s")
    benches = sorted(glob.glob(os.path.join(root, "target", "release", "deps", "export-*")), key=os.path.getmtime)
    benches = [p for p in benches if os.access(p, os.X_OK) and not p.endswith(".d")]
    if not benches:
        print("Rust: no export bench built (cargo bench -p brine-render --bench export --no-run)")
        return 0
    out = subprocess.run([benches[-1], "query"], capture_output=True, text=True, check=True).stdout
    # The bench prints the default's 150 waves, then the 50 waves measured here.
    m = re.search(r"\| query 10⁶ points \| [^|]* \| ([0-9.]+) s", out)
    rust = float(m.group(1))
    print(f"Rust:   10⁶ queries of the default sea, 50 waves: {rust:.3f} s")
    print(f"ratio Python / Rust: {py / rust:.2f} (goal ≤ 2)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
