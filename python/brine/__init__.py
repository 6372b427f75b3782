"""Brine from Python: realistic ocean scenes and the physics behind them, on numpy arrays.

Every model takes its arrays positionally (broadcast against each other, any shape) and its
scalar parameters as keywords named as the flags of the ``brine`` command (``u10``,
``fetch_m``, ``sun_elevation_deg``...): the defaults, ranges and error messages are the
command's, and the values are the same numbers the command prints. Heavy work runs on Brine's
threads with Python's lock released.

>>> import numpy as np, brine
>>> brine.spectrum(np.array([0.5, 1.0]), model="pm", u10=10.0)["s"].shape
(2,)
>>> sea = brine.Scene.from_dict({"camera": {"width": 64, "height": 36}})
>>> sea.render()["rgb"].shape
(36, 64, 3)

Units: metres, seconds, radians or degrees as each name says (``_deg``, ``_m``, ``_s``),
radiance in kcd m⁻² (linear sRGB). Instants are seconds since 1970-01-01T00:00:00Z, or numpy
``datetime64``, ``datetime.datetime`` (naive ones read as UTC) or ISO 8601 strings.

Bad input raises :class:`BrineError` (a ``ValueError``) naming the parameter and its range.
See docs/python.md.
"""

from __future__ import annotations

import datetime as _dt
import operator
from typing import Any, Mapping, Optional

import numpy as _np

from . import _brine
from ._brine import BrineError, __version__

__all__ = [
    "BrineError",
    "Scene",
    "__version__",
    "fit_trochoids",
    "foam_report",
    "fresnel",
    "moon_position",
    "sky_radiance",
    "spectrum",
    "spray_flux",
    "spray_report",
    "spreading",
    "sun_position",
    "unix_seconds",
    "water_iops",
    "whitecap_coverage",
    "whitecap_report",
]


def unix_seconds(times: Any) -> _np.ndarray:
    """Instants as float seconds since 1970-01-01T00:00:00Z (UTC).

    Numbers pass through; numpy ``datetime64`` values, ``datetime.datetime`` objects (naive
    ones are read as UTC) and ISO 8601 strings (``"2024-06-21T12:00:00Z"``) are converted.
    """
    a = _np.asarray(times)
    if a.dtype.kind in "fiu":
        return a.astype(float)
    if a.dtype.kind == "M":
        ns = a.astype("datetime64[ns]").astype("int64")
        return ns // 1_000_000_000 + (ns % 1_000_000_000) / 1e9

    def one(x: Any) -> float:
        if isinstance(x, str):
            x = _dt.datetime.fromisoformat(x.replace("Z", "+00:00"))
        if isinstance(x, _np.datetime64):
            return float(unix_seconds(x))
        if isinstance(x, _dt.datetime):
            if x.tzinfo is None:
                x = x.replace(tzinfo=_dt.timezone.utc)
            return x.timestamp()
        return float(x)

    return _np.vectorize(one, otypes=[float])(a) if a.ndim else _np.asarray(one(a.item()))


def _flat(*arrays: Any) -> tuple[tuple[int, ...], list[_np.ndarray]]:
    """The arrays broadcast together: their shape and each flattened to contiguous float64."""
    b = _np.broadcast_arrays(*[_np.asarray(a, dtype=float) for a in arrays])
    shape = b[0].shape
    return shape, [_np.ascontiguousarray(x, dtype=float).ravel() for x in b]


def _shaped(d: dict, shape: tuple[int, ...], n: int) -> dict:
    """Every array of length ``n`` in ``d`` (or of ``n`` rows) reshaped to ``shape`` (+ its row)."""
    out = {}
    for k, v in d.items():
        if isinstance(v, _np.ndarray) and v.ndim >= 1 and v.shape[0] == n:
            out[k] = v.reshape(shape + v.shape[1:])
        else:
            out[k] = v
    return out


def sun_position(times: Any, **place: Any) -> dict:
    """Apparent position of the Sun (NREL SPA, or Schlyter's elements) at each instant.

    Keywords as ``brine sun``: ``lat``, ``lon`` (degrees, required; north and east positive),
    ``height_m``, ``refraction`` (bool), ``pressure_hpa``, ``temperature_c``, ``model``
    (``"spa"``, ``"schlyter"``).

    Returns a dict of arrays shaped as ``times``: ``altitude_deg``, ``azimuth_deg`` (from north
    through east), ``distance_au``.
    """
    shape, (t,) = _flat(unix_seconds(times))
    return _shaped(_brine.sun_position(t, **place), shape, t.size)


def moon_position(times: Any, **place: Any) -> dict:
    """Apparent (topocentric) position and phase of the Moon (Schlyter's lunar theory) at each instant.

    Keywords as ``brine moon``: ``lat``, ``lon`` (degrees, required), ``height_m``,
    ``refraction``, ``pressure_hpa``, ``temperature_c``.

    Returns a dict of arrays: ``altitude_deg``, ``azimuth_deg``, ``distance_km``,
    ``phase_angle_deg``, ``illuminated_fraction``.
    """
    shape, (t,) = _flat(unix_seconds(times))
    return _shaped(_brine.moon_position(t, **place), shape, t.size)


def spectrum(omega: Any, **params: Any) -> dict:
    """An ocean spectrum ``S(ω)`` (m² s rad⁻¹) at angular frequencies ``omega`` (rad/s, > 0).

    Keywords as ``brine spectrum``: ``model`` (``"pm"``, ``"jonswap"``, ``"phillips"``,
    ``"tma"``, ``"elfouhaily"``), ``u10`` (m/s), ``fetch_m``, ``depth_m``, ``gamma``.

    Returns a dict: ``s`` (shaped as ``omega``), ``peak_omega_rad_s``,
    ``significant_wave_height_m``, ``model``.
    """
    shape, (w,) = _flat(omega)
    return _shaped(_brine.spectrum(w, **params), shape, w.size)


def spreading(theta: Any, omega: Any, **params: Any) -> _np.ndarray:
    """Directional spreading density ``D(θ; ω)`` (rad⁻¹; ``∫ D dθ = 1`` over a turn).

    ``theta``: direction from the wind (rad); ``omega``: angular frequency (rad/s, > 0),
    broadcast together. Keywords as ``brine fit``: ``spreading`` (``"hasselmann"``,
    ``"mitsuyasu"``, ``"donelan-banner"``, ``"elfouhaily"``, ``"cos2"``) and the spectrum's
    (``model``, ``u10``, ``fetch_m``...), which set the peak frequency.
    """
    shape, (th, w) = _flat(theta, omega)
    return _brine.spreading(th, w, **params).reshape(shape)


def fit_trochoids(**params: Any) -> dict:
    """The trochoid wave set fitted to a spectrum (Darles et al. 2007), as arrays.

    Keywords as ``brine fit`` (``waves``, ``seed``, ``spreading``, ``partition``,
    ``amplitudes``, ``wind_direction_deg``, ``choppiness``, ``max_total_steepness``...) and the
    spectrum's. Returns arrays ``amplitude_m``, ``wavelength_m``, ``direction_rad``,
    ``omega_rad_s``, ``phase_rad``, ``steepness`` and the set's ``variance_m2``,
    ``total_amplitude_m``, ``total_steepness``, ``peak_omega_rad_s``.
    """
    return _brine.fit_trochoids(**params)


def fresnel(cos_theta: Any, **indices: Any) -> dict:
    """Fresnel reflectance of a smooth interface (unpolarised) at each cosine of incidence.

    Keywords as ``brine optics fresnel``: ``n1``, ``n2`` (required). Returns arrays
    ``reflectance``, ``transmittance``, ``schlick``, ``total_internal_reflection``.
    """
    shape, (c,) = _flat(cos_theta)
    return _shaped(_brine.fresnel(c, **indices), shape, c.size)


def water_iops(wavelength_nm: Any, **water: Any) -> dict:
    """Inherent optical properties (m⁻¹) of a water body at each wavelength (nm).

    Keywords as ``brine optics water``: ``type`` (a Jerlov type such as ``"IB"`` or ``"3C"``)
    or ``chlorophyll_mg_m3`` (Case-1 water). Returns arrays ``absorption``, ``scattering``,
    ``backscattering``, ``attenuation``, ``kd`` and the sources' names.
    """
    shape, (lam,) = _flat(wavelength_nm)
    return _shaped(_brine.water_iops(lam, **water), shape, lam.size)


def sky_radiance(elevation_deg: Any, azimuth_deg: Any, **sky: Any) -> dict:
    """Sky radiance (kcd m⁻²) in each view direction (degrees; azimuth from north through east).

    Keywords as ``brine sky``: ``sun_elevation_deg`` (required), ``sun_azimuth_deg``,
    ``turbidity``, ``model`` (``"preetham"``, ``"hosek-wilkie"``), ``moon_elevation_deg``,
    ``moon_azimuth_deg``, ``moon_phase_deg``, ``moon_distance_km``, ``clouds``, ``cloud_seed``,
    ``time_s``. Returns ``rgb`` and ``xyz`` shaped as the directions plus 3, and the sun's
    radiance and irradiances.
    """
    shape, (e, a) = _flat(elevation_deg, azimuth_deg)
    return _shaped(_brine.sky_radiance(e, a, **sky), shape, e.size)


def whitecap_coverage(u10: Any, **law: Any) -> _np.ndarray:
    """Whitecap coverage ``W`` (fraction of the sea) of Monahan's laws at each wind speed (m/s).

    Keywords as ``brine foam``: ``law``, ``t_water_c``, ``t_air_c`` (both, for the 1986
    stability law), ``onset_m_s``.
    """
    shape, (u,) = _flat(u10)
    return _brine.whitecap_coverage(u, **law).reshape(shape)


def spray_flux(r80_um: Any, u10: Any) -> _np.ndarray:
    """Monahan, Spiel & Davidson's (1986) spray source ``dF/dr₈₀`` (m⁻² s⁻¹ µm⁻¹).

    ``r80_um``: drop radius at 80 % humidity (µm, > 0; fitted on [0.8, 15]); ``u10``: wind
    speed (m/s, [0, 60]); broadcast together.
    """
    shape, (r, u) = _flat(r80_um, u10)
    return _brine.spray_flux(r, u).reshape(shape)


def foam_report(**params: Any) -> Any:
    """The JSON answer of ``brine foam`` (coverage, memory and decay figures) as Python objects."""
    return _brine.report("foam", **params)


def spray_report(**params: Any) -> Any:
    """The JSON answer of ``brine spray`` (size distribution, extinction, optical depth, the spume layer, visibility)."""
    return _brine.report("spray", **params)


def whitecap_report(**params: Any) -> Any:
    """The JSON answer of ``brine whitecap`` (Jacobian statistics, calibration, visible cover)."""
    return _brine.report("whitecap", **params)


class Scene:
    """A scene of the ``brine render`` format (docs/scene.md): render it, query it, mesh it, bake it.

    ``Scene()`` is the embedded default scene; ``Scene(toml_text)`` parses TOML text;
    :meth:`from_dict` takes the same tables as a dict; :meth:`load` reads a file. The checks and
    messages (file, line, key, range) are those of ``brine render``.
    """

    def __init__(self, toml: Optional[str] = None, name: str = "<string>") -> None:
        self._scene = _brine.Scene(toml, name)

    @classmethod
    def from_dict(cls, tables: Mapping[str, Any]) -> "Scene":
        """A scene from ``{"sea": {...}, "camera": {...}, ...}``; missing keys take defaults."""
        s = cls.__new__(cls)
        s._scene = _brine.Scene.from_dict(dict(tables))
        return s

    @classmethod
    def load(cls, path: Any) -> "Scene":
        """A scene read from a TOML file."""
        s = cls.__new__(cls)
        s._scene = _brine.Scene.load(str(path))
        return s

    @property
    def toml(self) -> str:
        """The TOML text the scene was made from (empty for the default scene)."""
        return self._scene.toml

    @property
    def size(self) -> tuple[int, int]:
        """``(width, height)`` of the image (pixels)."""
        return self._scene.size

    @property
    def time_s(self) -> float:
        """The scene's time (s)."""
        return self._scene.time_s

    def render(self, threads: Optional[int] = None, reference: bool = False, frame: Optional[int] = None) -> dict:
        """Renders as ``brine render``: ``rgb`` (float32, ``(height, width, 3)``, linear sRGB,
        kcd m⁻²) and the AOVs ``depth`` (m), ``normal``, ``foam``, ``whitecap``, ``glint``, and
        ``exposure_ev``. The image does not depend on ``threads``. ``frame``: frame ``f`` of the
        scene's animation, as ``brine render --frames`` renders it (the waves at
        ``sea.time_s + f/fps``, the sun at ``place.time_utc + f/fps``); what does not change
        between frames is built once for the scene."""
        if frame is not None:
            try:
                f = None if isinstance(frame, bool) else operator.index(frame)  # numpy integers too
            except TypeError:
                f = None
            if f is None or not 0 <= f < 2**32:
                raise BrineError(f"frame = {frame!r} is out of range: expected an integer in [0, 2³²)")
            frame = f
        return self._scene.render(threads, reference, frame)

    def query(self, x: Any, z: Any, t: Any = None) -> dict:
        """The rendered surface at points ``(x, z)`` (m, east and south) and times ``t`` (s; the
        scene's time if ``None``), broadcast together, as ``brine query``: ``height_m``,
        ``normal``, ``displacement_m``, ``velocity_m_s``, ``vertical_acceleration_m_s2``,
        ``jacobian``, ``foam``, ``whitecap``."""
        if t is None:
            shape, (xs, zs) = _flat(x, z)
            ts = None
        else:
            shape, (xs, zs, ts) = _flat(x, z, t)
        return _shaped(self._scene.query(xs, zs, ts), shape, xs.size)

    def bake(
        self,
        size: int = 512,
        tile_m: Optional[float] = None,
        t: Optional[float] = None,
        up: str = "y",
        loop_s: Optional[float] = None,
    ) -> dict:
        """Tileable maps of the sea over a square tile, as ``brine bake``: ``displacement``
        (``(size, size, 3)``, m), ``normal``, ``foam``, ``whitecap``, ``jacobian``, ``spray``,
        ``tile_m``, ``time_s``, ``grid_limit``, ``loop_period_s``, ``loop_distortion``. ``up``:
        ``"y"`` (Brine, glTF, Houdini) or ``"z"`` (Blender). ``loop_s``: a loop period (s), as
        ``--loop-s``: the maps repeat after it; a ``UserWarning`` when it moves the waves off their
        dispersion relation."""
        return self._scene.bake(size, tile_m, t, up, loop_s)

    def mesh(
        self,
        size_m: Optional[float] = None,
        spacing_m: Optional[float] = None,
        center: Optional[tuple] = None,
        t: Optional[float] = None,
        band_limit: bool = False,
        camera: bool = False,
        pixels: Optional[float] = None,
        faded: bool = False,
    ) -> dict:
        """The rendered sea as a triangle mesh, as ``brine mesh``: ``positions`` (float32
        ``(n, 3)``, m, y up), ``normals``, ``foam``, ``whitecap`` (``(n,)``), ``indices`` (uint32
        ``(m, 3)``, counter-clockwise from above), ``time_s``, ``grid_limit``.

        A regular grid of rest positions ``spacing_m`` apart (default 0.5 m) over a square of
        side ``size_m`` (default 100 m) around ``center`` ``(x, z)`` (m); with ``band_limit``,
        without the waves shorter than two spacings (trochoid, Gerstner and FFT seas; ``grid_limit``
        then says what was left out). ``camera=True``: the camera-adaptive grid instead, edges
        ``pixels`` pixel footprints long (default 2, [0.125, 64]); ``faded``: the surface the
        camera's rays draw (the far waves faded with the pixel footprint). ``t``: time (s; the scene's if ``None``)."""
        if not camera and (pixels is not None or faded):
            raise BrineError("pixels and faded apply to the camera mesh: pass camera=True")
        kwargs: dict = {
            "size_m": size_m,
            "spacing_m": spacing_m,
            "time": t,
            "band_limit": band_limit,
            "camera": camera,
            "pixels": pixels,
            "faded": faded,
        }
        if center is not None:
            x, z = (float(c) for c in center)
            kwargs["center"] = f"{x!r},{z!r}"
        try:
            return self._scene.mesh(**{k: v for k, v in kwargs.items() if v is not None})
        except BrineError as e:
            # The command's keyword for the time is this method's `t`.
            raise BrineError(str(e).replace("'time'", "'t'")) from None

    def __repr__(self) -> str:
        w, h = self.size
        return f"brine.Scene({w}×{h} px, t = {self.time_s} s)"
