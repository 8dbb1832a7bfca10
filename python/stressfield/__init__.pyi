"""Type stubs of the stressfield package (SI units; float64 arrays)."""

import os
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Float64Array = npt.NDArray[np.float64]
Spacing = Union[float, Tuple[float, float], Sequence[float]]
PathLike = Union[str, os.PathLike]

COMPONENTS: Tuple[str, str, str, str, str, str]

class StressfieldError(ValueError):
    """An input or computation failed; the message is the command line's."""

class BatchError(StressfieldError):
    """Tasks of batch() failed: the first is named by its index; `results` holds every task's
    dict (None where it failed), `errors` each failed task's error by index."""

    results: list[Optional[dict[str, Any]]]
    errors: dict[int, StressfieldError]

class ContactResult:
    """The keys of `contact --json` as attributes (SI), and `pressure` (Pa, the heights'
    shape [rows = y, columns = x])."""

    pressure: Float64Array
    contact_fraction: float
    spots: int
    largest_spot_cells: int
    load_n: float
    mean_pressure_pa: float
    max_pressure_pa: float
    approach_m: float
    mean_gap_m: float
    iterations: int
    residual: float
    tolerance: float
    von_mises_max_pa: float
    von_mises_max_depth_m: float
    max_shear_max_pa: float
    max_shear_max_depth_m: float
    search_depth_m: float
    plastic_cells: int
    plasticity_index: Optional[float]
    e_star_pa: float
    hardness_pa: Optional[float]
    friction: float
    poisson: float
    periodic: bool
    rows: int
    columns: int
    spacing_m: list[float]
    warnings: list[str]
    def __init__(self, values: dict[str, Any], pressure: Float64Array) -> None: ...
    def keys(self) -> list[str]: ...
    def to_dict(self) -> dict[str, Any]: ...

class Scene:
    """A validated scene."""

    @classmethod
    def from_toml(cls, text: str, base_dir: PathLike = ".", name: str = "scene") -> "Scene": ...
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def file(self) -> str: ...
    def hertz(self) -> dict[str, Any]:
        """The keys of `hertz SCENE --json`."""
    def sweep(self) -> dict[str, Any]:
        """The keys of `sweep SCENE --json`."""
    def contact(self) -> ContactResult: ...
    def thermal(self) -> dict[str, Any]:
        """The keys of `thermal SCENE --json` and "temperature" (K, float64 2-D)."""
    def wear(self) -> dict[str, Any]:
        """The keys of `wear SCENE --json`."""
    def render(self, path: PathLike) -> None: ...
    def record(self, path: PathLike) -> None: ...

def load_scene(path: PathLike) -> Scene: ...
def contact(
    heights: ArrayLike,
    spacing: Spacing,
    e_star: float,
    *,
    load: Optional[float] = None,
    mean_pressure: Optional[float] = None,
    approach: Optional[float] = None,
    periodic: bool = True,
    hardness: Optional[float] = None,
    friction: float = 0.0,
    poisson: float = 0.3,
    tolerance: float = 1e-8,
) -> ContactResult:
    """heights: (rows, columns) m; spacing m; e_star Pa; one of load N, mean_pressure Pa,
    approach m."""

def stress(
    pressure: Optional[ArrayLike],
    spacing: Spacing,
    depths: ArrayLike,
    *,
    shear_x: Optional[ArrayLike] = None,
    shear_y: Optional[ArrayLike] = None,
    poisson: float = 0.3,
    periodic: bool = False,
) -> Float64Array:
    """Tractions (rows, columns) Pa, depths (d,) m -> (d, rows, columns, 6) Pa."""

def line_stress(x: ArrayLike, z: ArrayLike, *, friction: float = 0.0, poisson: float = 0.3) -> Float64Array:
    """Points in units of a (broadcast, shape S) -> S + (6,) in units of p0."""

def sphere_stress(
    x: ArrayLike, y: ArrayLike, z: ArrayLike, *, friction: float = 0.0, poisson: float = 0.3
) -> Float64Array:
    """Points in units of a (broadcast, shape S) -> S + (6,) in units of p0."""

def read_surface(
    path: PathLike,
    *,
    spacing: Optional[Spacing] = None,
    height_unit: Optional[str] = None,
    length_unit: Optional[str] = None,
    fill: str = "refuse",
) -> Tuple[Float64Array, Tuple[float, float]]:
    """-> (heights (rows, columns) m, (dx, dy) m)."""

def surface_stats(
    heights: ArrayLike,
    spacing: Spacing,
    *,
    form: str = "plane",
    band: Optional[Tuple[float, float]] = None,
    e_star: Optional[float] = None,
    hardness: Optional[float] = None,
    window: bool = True,
) -> dict[str, Any]:
    """The keys of `surface --json`."""

def batch(
    tasks: Sequence[Union[PathLike, str, Scene]], client: Any = None, *, errors: str = "raise"
) -> list[Any]:
    """One `hertz --json` dict per task, in order; with a dask.distributed Client, on its
    cluster. errors="raise": BatchError if any task failed (with the others' results);
    errors="return": each failed task's StressfieldError in its place."""
