"""Type stubs of Brine's native module (PyO3). The public API is the package ``brine``, whose
wrappers broadcast arrays and convert instants; these are the functions they call.

Arrays are 1-D, contiguous float64; keywords are the flags of the matching ``brine``
subcommand (see the wrappers' docstrings for units and ranges)."""

from typing import Any, Optional

import numpy as np
import numpy.typing as npt

__version__: str

class BrineError(ValueError):
    """Bad input: the message names the parameter (or scene file, line and key) and its range."""

Array = npt.NDArray[np.float64]

def sun_position(unix_s: Array, **place: Any) -> dict[str, Array]:
    """``altitude_deg``, ``azimuth_deg`` (north through east), ``distance_au`` per instant (s since 1970 UTC)."""

def moon_position(unix_s: Array, **place: Any) -> dict[str, Array]:
    """``altitude_deg``, ``azimuth_deg``, ``distance_km``, ``phase_angle_deg``, ``illuminated_fraction``."""

def spectrum(omega: Array, **params: Any) -> dict[str, Any]:
    """``s`` (m² s rad⁻¹) at ``omega`` (rad/s), ``peak_omega_rad_s``, ``significant_wave_height_m``, ``model``."""

def spreading(theta: Array, omega: Array, **params: Any) -> Array:
    """``D(θ; ω)`` (rad⁻¹) at directions ``theta`` (rad from the wind) and frequencies ``omega`` (rad/s)."""

def fit_trochoids(**params: Any) -> dict[str, Any]:
    """The fitted set's arrays (``amplitude_m``, ``wavelength_m``, ``direction_rad``, ``omega_rad_s``, ``phase_rad``, ``steepness``)."""

def fresnel(cos_theta: Array, **indices: Any) -> dict[str, npt.NDArray[Any]]:
    """``reflectance``, ``transmittance``, ``schlick``, ``total_internal_reflection`` per cosine."""

def water_iops(wavelength_nm: Array, **water: Any) -> dict[str, Any]:
    """``absorption``, ``scattering``, ``backscattering``, ``attenuation``, ``kd`` (m⁻¹) per wavelength (nm)."""

def sky_radiance(elevation_deg: Array, azimuth_deg: Array, **sky: Any) -> dict[str, Any]:
    """``rgb``, ``xyz`` (kcd m⁻², shape ``(n, 3)``) per direction; the sun's radiance and irradiances."""

def whitecap_coverage(u10: Array, **law: Any) -> Array:
    """Whitecap coverage (fraction) per wind speed (m/s)."""

def spray_flux(r80_um: Array, u10: Array) -> Array:
    """``dF/dr₈₀`` (m⁻² s⁻¹ µm⁻¹) per drop radius (µm) and wind speed (m/s)."""

def report(command: str, **params: Any) -> Any:
    """The JSON answer of ``brine foam``, ``brine spray`` or ``brine whitecap``."""

class Scene:
    """A checked scene (docs/scene.md)."""

    def __init__(self, toml: Optional[str] = None, name: str = "<string>") -> None: ...
    @staticmethod
    def from_dict(d: dict[str, Any]) -> "Scene": ...
    @staticmethod
    def load(path: str) -> "Scene": ...
    @property
    def toml(self) -> str: ...
    @property
    def size(self) -> tuple[int, int]: ...
    @property
    def time_s(self) -> float: ...
    def render(self, threads: Optional[int] = None, reference: bool = False, frame: Optional[int] = None) -> dict[str, Any]:
        """``rgb`` (float32 ``(h, w, 3)``, kcd m⁻²), ``depth`` (m), ``normal``, ``foam``, ``whitecap``, ``glint``, ``exposure_ev``."""
    def query(self, x: Array, z: Array, t: Optional[Array] = None) -> dict[str, Array]:
        """The surface at points (m) and times (s), as ``brine query``."""
    def bake(
        self,
        size: int = 512,
        tile_m: Optional[float] = None,
        t: Optional[float] = None,
        up: str = "y",
        loop_s: Optional[float] = None,
    ) -> dict[str, Any]:
        """Tileable float32 maps, as ``brine bake``."""
    def mesh(self, **kwargs: Any) -> dict[str, Any]:
        """The sea as a triangle mesh, as ``brine mesh``."""
