"""Scenes from Python: rendered, queried, meshed and baked by the same code as `brine render`,
`query`, `mesh` and `bake`."""

import numpy as np
import pytest

import brine

SMALL = {"camera": {"width": 48, "height": 27}, "sea": {"wind_speed_m_s": 12.0}}


@pytest.fixture(scope="module")
def scene():
    return brine.Scene.from_dict(SMALL)


@pytest.fixture(scope="module")
def frame(scene):
    return scene.render()


def test_a_render_is_the_cli_render(scene, frame, brine_cli, tmp_path_factory):
    openexr = pytest.importorskip("OpenEXR")
    d = tmp_path_factory.mktemp("render")
    toml = d / "scene.toml"
    toml.write_text("[camera]\nwidth = 48\nheight = 27\n[sea]\nwind_speed_m_s = 12.0\n")
    exr = d / "out.exr"
    import subprocess

    subprocess.run([str(brine_cli.path), "render", str(toml), "-o", str(exr), "-q"], check=True)
    channels = openexr.File(str(exr)).channels()
    if "RGB" in channels:
        cli = channels["RGB"].pixels
    else:
        cli = np.stack([channels[c].pixels for c in "RGB"], axis=-1)
    assert frame["rgb"].shape == (27, 48, 3) and frame["rgb"].dtype == np.float32
    np.testing.assert_array_equal(frame["rgb"], cli)


def test_renders_are_the_same_at_any_thread_count_and_from_toml(scene, frame):
    one = scene.render(threads=1)
    np.testing.assert_array_equal(one["rgb"], frame["rgb"])
    from_text = brine.Scene("[camera]\nwidth = 48\nheight = 27\n[sea]\nwind_speed_m_s = 12.0\n")
    np.testing.assert_array_equal(from_text.render()["rgb"], frame["rgb"])


def test_animation_frames_are_the_cli_frames(scene, frame, brine_cli, tmp_path):
    openexr = pytest.importorskip("OpenEXR")
    import subprocess

    toml = tmp_path / "scene.toml"
    toml.write_text("[camera]\nwidth = 48\nheight = 27\n[sea]\nwind_speed_m_s = 12.0\n")
    subprocess.run([str(brine_cli.path), "render", str(toml), "-o", str(tmp_path / "f_#.exr"), "-q", "--frames", "2..4"], check=True)
    channels = openexr.File(str(tmp_path / "f_3.exr")).channels()
    cli = channels["RGB"].pixels if "RGB" in channels else np.stack([channels[c].pixels for c in "RGB"], axis=-1)
    f3 = scene.render(frame=3)
    np.testing.assert_array_equal(f3["rgb"], cli)
    assert not np.array_equal(f3["rgb"], frame["rgb"]), "the waves did not move"
    # Frame 0 is the still.
    np.testing.assert_array_equal(scene.render(frame=0)["rgb"], frame["rgb"])
    with pytest.raises(brine.BrineError, match="frame"):
        scene.render(frame=-1)
    with pytest.raises(brine.BrineError, match="frame"):
        scene.render(frame=True)
    # A numpy integer is a frame number.
    np.testing.assert_array_equal(scene.render(frame=np.int64(3))["rgb"], cli)


def test_the_aovs_describe_sea_and_sky(frame):
    depth = frame["depth"]
    assert np.isinf(depth[0]).all(), "the top row is sky"
    assert np.isfinite(depth[-1]).all() and (depth[-1] > 0).all(), "the bottom row is sea"
    n = frame["normal"][-1]
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0, atol=1e-5)
    assert (frame["rgb"] >= 0).all() and np.isfinite(frame["exposure_ev"])


def test_queries_equal_the_cli(scene, brine_cli, tmp_path):
    toml = tmp_path / "scene.toml"
    toml.write_text("[camera]\nwidth = 48\nheight = 27\n[sea]\nwind_speed_m_s = 12.0\n")
    pts = [(0.0, 40.0, None), (12.5, -3.0, 2.0), (-80.0, 300.0, 7.25)]
    spec = ";".join(f"{x},{z}" + ("" if t is None else f",{t}") for x, z, t in pts)
    cli = brine_cli("query", str(toml), "--points", spec, "--format", "json")
    t = [scene.time_s if t is None else t for _, _, t in pts]
    py = scene.query([p[0] for p in pts], [p[1] for p in pts], t)
    for i, c in enumerate(cli):
        assert py["height_m"][i] == c["height_m"]
        assert py["normal"][i].tolist() == c["normal"]
        assert py["foam"][i] == c["foam"] and py["whitecap"][i] == c["whitecap"]


def test_a_bake_samples_one_surface_at_any_size(scene):
    n, tile = 64, 16.0
    b = scene.bake(size=n, tile_m=tile)
    assert b["displacement"].shape == (n, n, 3) and b["foam"].shape == (n, n) and b["tile_m"] == tile
    fine = scene.bake(size=2 * n, tile_m=tile)
    # 0.25 m and 0.125 m texels hold every wave of this sea (its shortest is 0.83 m, over three
    # texels), so neither bake leaves one out...
    assert b["grid_limit"]["faded_waves"] == 0 and fine["grid_limit"]["faded_waves"] == 0
    # ...and texel (i, j) is the rest point (i, j)·tile/n (exact here): the finer bake's even
    # texels are the same rest points, so the same surface to the bit.
    np.testing.assert_array_equal(fine["displacement"][::2, ::2], b["displacement"])
    np.testing.assert_array_equal(fine["normal"][::2, ::2], b["normal"])
    h = b["displacement"][..., 1]
    assert 0.1 < h.std() < 5.0
    np.testing.assert_allclose(np.linalg.norm(b["normal"], axis=-1), 1.0, atol=1e-5)
    # Blender's axes: (x, −z, y).
    zup = scene.bake(size=n, tile_m=tile, up="z")["displacement"]
    np.testing.assert_array_equal(zup[..., 2], b["displacement"][..., 1])
    np.testing.assert_array_equal(zup[..., 1], -b["displacement"][..., 2])
    # 2 m texels cannot hold the waves under 4 m: the bake leaves them out and says what slopes
    # they took, as `brine bake` writes in bake.json.
    coarse = scene.bake(size=8, tile_m=tile)["grid_limit"]
    assert coarse["shortest_wave_m"] == 4.0 and coarse["faded_waves"] > 0, coarse
    assert coarse["lost_mean_square_slope"] > 0.0


def test_a_looped_bake_repeats_and_warns_when_it_moves_the_waves(brine_cli, tmp_path):
    s = brine.Scene.from_dict(SMALL)
    # A period long against the sea's: maps that repeat after it, no warning, and the same
    # figures as the command's bake.json.
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        a = s.bake(size=16, tile_m=40.0, t=0.0, loop_s=200.0)
        b = s.bake(size=16, tile_m=40.0, t=200.0, loop_s=200.0)
    np.testing.assert_allclose(a["displacement"], b["displacement"], atol=1e-4)
    assert a["loop_period_s"] == 200.0
    assert a["loop_distortion"]["variance_share_moved_over_5_percent"] <= 0.05
    (tmp_path / "scene.toml").write_text(s.toml)
    import subprocess

    subprocess.run(
        [str(brine_cli.path), "bake", "scene.toml", "-q", "-o", "maps", "--size", "16", "--tile-m", "40", "--loop-s", "200"],
        cwd=tmp_path,
        check=True,
    )
    import json

    cli = json.loads((tmp_path / "maps" / "bake.json").read_text())["loop_distortion"]
    for k, v in cli.items():
        assert a["loop_distortion"][k] == pytest.approx(v, rel=1e-12), k
    # A 2 s loop moves nearly every wave: warned of, as the command warns.
    with pytest.warns(UserWarning, match=r"loop_s = 2 s moves \d+ % of the sea's height variance"):
        c = s.bake(size=16, tile_m=40.0, loop_s=2.0)
    assert c["loop_distortion"]["variance_share_moved_over_5_percent"] > 0.9
    assert s.bake(size=8, tile_m=40.0)["loop_distortion"] is None
    with pytest.raises(brine.BrineError, match="loop_s"):
        s.bake(size=8, tile_m=40.0, loop_s=-1.0)


def _read_ply(path):
    """Vertices `(n, 8)` (x y z nx ny nz foam whitecap) and triangles `(m, 3)` of a `brine mesh`
    PLY file."""
    data = path.read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    n = int(header.split("element vertex ")[1].split()[0])
    m = int(header.split("element face ")[1].split()[0])
    vertices = np.frombuffer(data, dtype="<f4", count=8 * n, offset=end).reshape(n, 8)
    faces = np.frombuffer(data[end + 32 * n :], dtype=np.dtype([("k", "u1"), ("i", "<u4", (3,))]), count=m)
    assert (faces["k"] == 3).all()
    return vertices, faces["i"]


def test_a_mesh_is_the_cli_mesh(scene, brine_cli, tmp_path):
    import subprocess

    toml = tmp_path / "scene.toml"
    toml.write_text("[camera]\nwidth = 48\nheight = 27\n[sea]\nwind_speed_m_s = 12.0\n")
    for flags, kwargs in [([], {}), (["--band-limit"], {"band_limit": True})]:
        ply = tmp_path / "sea.ply"
        args = ["mesh", str(toml), "-o", str(ply), "-q", "--size-m", "12", "--spacing-m", "1.5", "--center", "3,-2"]
        subprocess.run([str(brine_cli.path), *args, *flags], check=True)
        cli_v, cli_f = _read_ply(ply)
        m = scene.mesh(size_m=12.0, spacing_m=1.5, center=(3.0, -2.0), **kwargs)
        assert m["positions"].shape == (81, 3) and m["positions"].dtype == np.float32
        assert m["indices"].shape == (128, 3) and m["indices"].dtype == np.uint32
        np.testing.assert_array_equal(m["positions"], cli_v[:, 0:3])
        np.testing.assert_array_equal(m["normals"], cli_v[:, 3:6])
        np.testing.assert_array_equal(m["foam"], cli_v[:, 6])
        np.testing.assert_array_equal(m["indices"], cli_f)
    # 1.5 m apart the grid cannot carry the waves under 3 m: the band-limited mesh leaves them
    # out (its vertices differ from the plain mesh's) and says which slopes it lost.
    plain, band = scene.mesh(size_m=12.0, spacing_m=1.5), scene.mesh(size_m=12.0, spacing_m=1.5, band_limit=True)
    assert plain["grid_limit"] is None
    assert band["grid_limit"]["shortest_wave_m"] == 3.0 and band["grid_limit"]["faded_waves"] > 0
    assert np.abs(band["positions"][:, 1] - plain["positions"][:, 1]).max() > 1e-3
    cam = scene.mesh(camera=True, pixels=1.0, faded=True)
    assert cam["positions"].shape[0] > 100 and cam["indices"].max() < cam["positions"].shape[0]
    np.testing.assert_allclose(np.linalg.norm(cam["normals"], axis=-1), 1.0, atol=1e-5)


def test_bad_scenes_and_arguments_raise():
    with pytest.raises(brine.BrineError, match=r"my\.toml line 2: sea\.wind_speed_m_s = 900"):
        brine.Scene("[sea]\nwind_speed_m_s = 900\n", "my.toml")
    with pytest.raises(brine.BrineError, match="camera.width"):
        brine.Scene.from_dict({"camera": {"width": -4}})
    with pytest.raises(brine.BrineError, match="size"):
        brine.Scene.from_dict(SMALL).bake(size=1)
    with pytest.raises(brine.BrineError, match="point 0"):
        brine.Scene.from_dict(SMALL).query([np.nan], [0.0])
    with pytest.raises(brine.BrineError, match="up"):
        brine.Scene.from_dict(SMALL).bake(size=8, up="x")
    with pytest.raises(brine.BrineError, match=r"spacing_m = 0 is out of range"):
        brine.Scene.from_dict(SMALL).mesh(spacing_m=0.0)
    with pytest.raises(brine.BrineError, match=r"band_limit: the sine sea"):
        brine.Scene.from_dict({"sea": {"surface": "sine"}}).mesh(size_m=4.0, band_limit=True)
    with pytest.raises(brine.BrineError, match=r"pixels.*0.01 is out of range"):
        brine.Scene.from_dict(SMALL).mesh(camera=True, pixels=0.01)
    with pytest.raises(brine.BrineError, match=r"'t'"):
        brine.Scene.from_dict(SMALL).mesh(size_m=4.0, t=1e17)
    with pytest.raises(brine.BrineError, match=r"pass camera=True"):
        brine.Scene.from_dict(SMALL).mesh(pixels=4.0)


def test_a_loop_that_moves_the_waves_is_warned_of():
    looped = {"camera": {"width": 16, "height": 9}, "sea": {"surface": "fft", "wind_speed_m_s": 10.0, "fft": {"loop_period_s": 10.0}}}
    s = brine.Scene.from_dict(looped)
    with pytest.warns(UserWarning, match=r"sea\.fft\.loop_period_s = 10 s moves \d+ % of the sea's height variance"):
        s.render()
    with pytest.warns(UserWarning, match="loop_period_s"):
        s.render(frame=1)
    # A loop long enough for the sea, and no loop at all, say nothing.
    import warnings

    for fft in ({"loop_period_s": 2000.0}, {}):
        quiet = brine.Scene.from_dict({**looped, "sea": {**looped["sea"], "fft": fft}})
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            quiet.render()
