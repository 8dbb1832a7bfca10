"""stressfield from Python: elastic stress fields under loaded contacts.

The same physics, checks and messages as the ``stressfield`` command line (the same Rust
library and the same studies underneath). SI units; NumPy float64 arrays in (C or Fortran
order) and out; every argument is checked against the bounds the command line keeps for the
same quantity, and arrays of text, complex numbers or booleans, and masked arrays with masked
points, are refused; the GIL is released while computing, and Ctrl-C stops a rough contact
between two solver iterations; errors raise :class:`StressfieldError` (a ``ValueError``) with
the command line's message, naming the argument; nothing is printed.

Stress components are always in the order ``sxx, syy, szz, syz, sxz, sxy`` (last axis of 6);
z points into the body; compression is negative; the tangential traction ``q = friction * p``
acts on the body in +x.
"""

from __future__ import annotations

import json as _json
import os as _os

import numpy as _np

from . import _stressfield as _ext
from ._stressfield import StressfieldError

__all__ = [
    "StressfieldError",
    "Scene",
    "ContactResult",
    "load_scene",
    "contact",
    "stress",
    "line_stress",
    "sphere_stress",
    "read_surface",
    "surface_stats",
    "batch",
    "BatchError",
    "COMPONENTS",
]

#: The order of the stress components on the last axis of every stress array.
COMPONENTS = ("sxx", "syy", "szz", "syz", "sxz", "sxy")

StressfieldError.__module__ = "stressfield"


#: What each kind of NumPy array holds, for the messages refusing it.
_KINDS = {
    "b": "booleans",
    "c": "complex numbers",
    "U": "text",
    "S": "bytes",
    "O": "Python objects",
    "M": "dates",
    "m": "time spans",
    "V": "raw records",
}


def _refused_kind(name, kind, example):
    """The error for an array (or scalar) of ``kind`` given as ``name``."""
    what = _KINDS.get(kind, f"values of kind {kind!r}")
    hint = {
        "c": "give the real part (np.real) if that is what you mean",
        "U": "convert the text to numbers first (SI units: 1e-6 for 1 µm)",
        "S": "convert the bytes to numbers first",
        "b": "give numbers (a boolean mask is not a value)",
    }.get(kind, "give real numbers (float or int)")
    return StressfieldError(f"{name} must be real numbers, got {what} ({example})\nhint: {hint}")


def _float64(name, value, ndim=None):
    """``value`` as a float64 array of ``ndim`` dimensions (any when None), without a copy when
    it is one; text, complex numbers, booleans and objects are refused (NumPy would convert
    text silently and drop an imaginary part with a warning only), and a masked array is
    refused when it masks anything (its mask would be dropped)."""
    if _np.ma.isMaskedArray(value):
        masked = int(_np.ma.count_masked(value))
        if masked:
            raise StressfieldError(
                f"{name} is a masked array with {masked} masked point(s): the mask would be "
                "dropped and the values under it used\nhint: fill the missing points first "
                "(read_surface(..., fill=\"interpolate\") fills a height file's), or pass "
                f"{name}.filled(value) for a value of your choice"
            )
        value = _np.ma.getdata(value)
    try:
        given = _np.asarray(value)
    except (TypeError, ValueError) as error:
        raise StressfieldError(f"{name} must be an array of numbers: {error}") from None
    if given.dtype.kind not in "fiu":
        example = given.flat[0] if given.size else "empty"
        raise _refused_kind(name, given.dtype.kind, repr(example))
    array = given.astype(_np.float64, copy=False)
    if ndim is not None and array.ndim != ndim:
        raise StressfieldError(
            f"{name} must be a {ndim}-D array, got shape {tuple(array.shape)}"
        )
    return array


def _number(name, value):
    """``value`` as one real number; text, booleans, complex numbers, arrays of more than one
    value and masked values are refused, naming ``name``."""
    if isinstance(value, (str, bytes)):
        raise StressfieldError(
            f"{name} must be a number, got text {value!r}\nhint: give a number in SI units "
            "(e.g. 1e-6 for 1 µm, 115e9 for 115 GPa)"
        )
    if value is _np.ma.masked:
        raise StressfieldError(f"{name} must be a number, got a masked value")
    if isinstance(value, (bool, _np.bool_)):
        raise StressfieldError(f"{name} must be a number, got {value!r}")
    if isinstance(value, (_np.ndarray, _np.generic)):
        if value.dtype.kind not in "fiu":
            raise _refused_kind(name, value.dtype.kind, repr(value))
        if value.ndim != 0:
            raise StressfieldError(
                f"{name} must be one number, got an array of shape {tuple(value.shape)}"
            )
    if isinstance(value, complex):
        raise _refused_kind(name, "c", repr(value))
    try:
        return float(value)
    except (TypeError, ValueError):
        raise StressfieldError(f"{name} must be a number, got {value!r}") from None


def _spacing(spacing, name="spacing"):
    """A spacing (m): one number for both axes, or a pair ``(dx, dy)``."""
    if isinstance(spacing, (str, bytes)) or _np.ndim(spacing) == 0:
        d = _number(name, spacing)
        return d, d
    values = list(_np.asarray(spacing, dtype=object).ravel())
    if len(values) != 2:
        raise StressfieldError(
            f"{name} must be a number (m) or a pair (dx, dy), got {len(values)} values"
        )
    return _number(name, values[0]), _number(name, values[1])


class ContactResult:
    """A solved rough contact: the keys of ``stressfield contact --json`` as attributes
    (SI units: ``contact_fraction``, ``load_n``, ``mean_pressure_pa``, ``max_pressure_pa``,
    ``approach_m``, ``von_mises_max_pa``, ...), and ``pressure``, the contact pressure in Pa
    with the heights' shape ``[rows = y, columns = x]``.
    """

    def __init__(self, values: dict, pressure: _np.ndarray):
        self._values = dict(values)
        self.pressure = pressure

    def __getattr__(self, key):
        values = self.__dict__.get("_values", {})
        if key in values:
            return values[key]
        raise AttributeError(key)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._values))

    def keys(self):
        """The JSON keys, in the command line's order."""
        return list(self._values)

    def to_dict(self) -> dict:
        """The result as ``contact --json`` prints it (without the pressure)."""
        return dict(self._values)

    def __repr__(self):
        return (
            f"ContactResult(contact_fraction={self._values.get('contact_fraction')!r}, "
            f"load_n={self._values.get('load_n')!r}, pressure shape {self.pressure.shape})"
        )


class Scene:
    """A validated scene (a ``scenes/*.toml`` file): ``load_scene(path)`` or
    ``Scene.from_toml(text, base_dir=".")``."""

    __slots__ = ("_scene",)

    def __init__(self, scene):
        self._scene = scene

    @classmethod
    def from_toml(cls, text: str, base_dir=".", name: str = "scene") -> "Scene":
        """Parses scene text; files it names (surfaces, tractions) are read relative to
        ``base_dir``; ``name`` names it (as a file's stem would)."""
        return cls(_ext.parse_scene(str(text), _os.fspath(base_dir), str(name)))

    @property
    def name(self) -> str:
        return self._scene.name

    @property
    def kind(self) -> str:
        """line, point, elliptical, tractions, rough or surface."""
        return self._scene.kind

    @property
    def file(self) -> str:
        return self._scene.file

    def hertz(self) -> dict:
        """The dict of ``stressfield hertz SCENE --json`` (a rough scene: ``contact --json``;
        a surface scene: ``surface --json``)."""
        return _json.loads(self._scene.hertz_json())

    def sweep(self) -> dict:
        """The table of a ``[sweep]`` scene, the dict of ``stressfield sweep SCENE --json``:
        ``units`` (column -> unit) and ``steps`` (one dict per step: the swept value and the
        values the recording charts)."""
        return _json.loads(self._scene.sweep_json())

    def contact(self) -> ContactResult:
        """The rough contact of a rough scene, as ``stressfield contact SCENE --json``, with
        the pressure (Pa)."""
        text, pressure = self._scene.contact()
        return ContactResult(_json.loads(text), pressure)

    def thermal(self) -> dict:
        """The dict of ``stressfield thermal SCENE --json`` plus ``"temperature"``: body 1's
        surface temperature rise (K, float64, ``[rows = y, columns = x]`` of the thermal
        grid)."""
        text, temperature = self._scene.thermal()
        values = _json.loads(text)
        values["temperature"] = temperature
        return values

    def ehl(self) -> dict:
        """The numerical EHL solution of a lubricated line contact: the dict of ``stressfield
        ehl SCENE --json`` plus ``"solution"``, the float64 array ``ehl --pressure`` writes,
        shape (n, 3): x (m, entrainment in +x), pressure (Pa), film (m)."""
        text, solution = self._scene.ehl()
        values = _json.loads(text)
        values["solution"] = solution
        return values

    def wear(self, arrays: bool = False) -> dict:
        """The steps of a wear scene (``[wear]`` or ``[[series]]``), the dict of ``stressfield
        wear SCENE --json``; with ``arrays=True`` also ``"heights"`` (each step's worn surface,
        m, out of body 1), ``"pressure"`` (Pa) and ``"wear_depth"`` (m), float64 arrays of
        shape ``(steps, ny, nx)``, the unworn contact first (the order of ``"steps"``)."""
        text, stacks = self._scene.wear(bool(arrays))
        out = _json.loads(text)
        if stacks is not None:
            out["heights"], out["pressure"], out["wear_depth"] = stacks
        return out

    def plastic(self, fields: bool = False) -> dict:
        """The elastic-plastic contact of a scene with ``[plasticity]``, the dict of
        ``stressfield plastic SCENE --json``; with ``fields=True`` also the arrays of
        ``plastic --fields``: ``"plastic_strain"`` (the equivalent plastic strain after the
        last step, ``(nz, ny, nx)``), ``"stress"`` (the total stress at full load) and
        ``"residual_stress"`` (after unloading, when unloaded), ``(nz, ny, nx, 6)`` Pa in the
        order of :data:`COMPONENTS`, ``"pressure"`` (Pa at full load, ``(ny, nx)``),
        ``"surface_displacement"`` (m into the body, ``(ny, nx)``: the plastic strain's surface
        displacement after the last step, the dent's profile after unloading) and the
        cell centres ``"x"``, ``"y"`` (from the axis) and ``"z"`` (depth), m. A line contact
        (plane strain) gives the line's keys (``load_n_per_m``, ``half_width_m``,
        ``plastic_area_m2``) and arrays of one row in y: ``(nz, 1, nx)``, ``y = [0]``."""
        text, arrays = self._scene.plastic(bool(fields))
        out = _json.loads(text)
        if arrays is not None:
            names = ("plastic_strain", "stress", "residual_stress", "pressure",
                     "surface_displacement", "x", "y", "z")
            for name, value in zip(names, arrays):
                if value is not None:
                    out[name] = value
        return out

    def render(self, path) -> None:
        """Draws the scene's figure (or sheet) to ``path``, PNG or SVG by the extension, as
        ``stressfield render`` draws it; written atomically."""
        self._scene.render(_os.fspath(path))

    def record(self, path) -> None:
        """Records the scene to a Rerun ``.rrd`` file (a package built with Rerun, see
        docs/python.md; otherwise a StressfieldError says how)."""
        self._scene.record(_os.fspath(path))

    def __repr__(self):
        return repr(self._scene)

    def __reduce__(self):
        raise TypeError(
            "a Scene is not pickled: pass the scene's path or TOML text to batch() instead"
        )


def load_scene(path) -> Scene:
    """Reads and validates a scene file, as every command does."""
    return Scene(_ext.load_scene(_os.fspath(path)))


def contact(
    heights,
    spacing,
    e_star,
    *,
    load=None,
    mean_pressure=None,
    approach=None,
    periodic=True,
    hardness=None,
    friction=0.0,
    poisson=0.3,
    tolerance=1e-8,
) -> ContactResult:
    """Solves the rough contact of ``heights`` against a flat (DC-FFT + conjugate gradients,
    Polonsky & Keer) and reports it as ``stressfield contact --json`` reports a scene.

    heights: 2-D array (m), ``[rows = y, columns = x]``, heights out of the body.
    spacing: m, a number or ``(dx, dy)``. e_star: combined modulus E* (Pa).
    Exactly one of load (N), mean_pressure (Pa) or approach (m).
    periodic: the map is one period (else an isolated contact, DC-FFT).
    hardness: Pa, the pressure cap (perfectly plastic asperities) and the plasticity index.
    friction, poisson: body 1's, for the subsurface maxima (q = friction p in +x).
    tolerance: the solver's convergence tolerance.
    Returns a :class:`ContactResult` whose ``pressure`` (Pa) has the heights' shape.
    """
    heights = _float64("heights", heights, 2)
    dx, dy = _spacing(spacing)
    given = [
        (name, value)
        for name, value in (("load", load), ("mean_pressure", mean_pressure), ("approach", approach))
        if value is not None
    ]
    if len(given) != 1:
        names = ", ".join(name for name, _ in given) or "none"
        raise StressfieldError(
            f"give exactly one of load (N), mean_pressure (Pa) or approach (m), got {names}"
        )
    control, value = given[0]
    text, pressure = _ext.contact(
        heights,
        dx,
        dy,
        _number("e_star", e_star),
        control,
        _number(control, value),
        bool(periodic),
        None if hardness is None else _number("hardness", hardness),
        _number("friction", friction),
        _number("poisson", poisson),
        _number("tolerance", tolerance),
    )
    return ContactResult(_json.loads(text), pressure)


def stress(
    pressure,
    spacing,
    depths,
    *,
    shear_x=None,
    shear_y=None,
    poisson=0.3,
    periodic=False,
) -> _np.ndarray:
    """The stresses (Pa) under tractions uniform on each cell of a grid (DC-FFT, Liu, Wang &
    Liu 2000), at the cell centres, at each depth.

    pressure, shear_x, shear_y: 2-D arrays (Pa) of one shape ``[rows = y, columns = x]``
    (pressure pushes into the body; shears act on it in +x and +y); pressure may be None
    when a shear is given. spacing: m, a number or ``(dx, dy)``. depths: 1-D (m, >= 0).
    periodic: the grid is one period of tractions repeating in x and y.
    Returns float64 ``(len(depths), rows, columns, 6)``: sxx, syy, szz, syz, sxz, sxy.
    """
    arrays = {}
    for name, value in (("pressure", pressure), ("shear_x", shear_x), ("shear_y", shear_y)):
        arrays[name] = None if value is None else _float64(name, value, 2)
    dx, dy = _spacing(spacing)
    depths = _np.atleast_1d(_float64("depths", depths))
    if depths.ndim != 1:
        raise StressfieldError(
            f"depths must be a number or a 1-D array, got shape {tuple(depths.shape)}"
        )
    return _ext.stress(
        arrays["pressure"],
        dx,
        dy,
        depths,
        arrays["shear_x"],
        arrays["shear_y"],
        _number("poisson", poisson),
        bool(periodic),
    )


def _closed_form(points, evaluate):
    coordinates = [_float64(name, p) for name, p in points]
    try:
        broadcast = _np.broadcast_arrays(*coordinates)
    except ValueError as error:
        raise StressfieldError(f"the coordinates do not broadcast together: {error}") from None
    shape = broadcast[0].shape
    flat = [_np.ascontiguousarray(b).reshape(-1) for b in broadcast]
    return evaluate(*flat).reshape(shape + (6,))


def line_stress(x, z, *, friction=0.0, poisson=0.3) -> _np.ndarray:
    """Exact stresses under a Hertzian line contact (plane strain) sliding with ``friction``
    (McEwen 1949; Johnson, Contact Mechanics, ch. 7), at points ``x, z`` in units of the
    half-width ``a`` (broadcast together; z >= 0 into the body). Returns stresses over p0 with
    a last axis of 6 (sxx, syy, szz, syz, sxz, sxy; syy = nu (sxx + szz))."""
    f, nu = _number("friction", friction), _number("poisson", poisson)
    return _closed_form((("x", x), ("z", z)), lambda x, z: _ext.line_stress(x, z, f, nu))


def sphere_stress(x, y, z, *, friction=0.0, poisson=0.3) -> _np.ndarray:
    """Exact stresses under a Hertzian point (sphere) contact sliding with ``friction``
    (Hamilton 1983), at points ``x, y, z`` in units of the contact radius ``a`` (broadcast
    together; z >= 0). Returns stresses over p0 with a last axis of 6."""
    f, nu = _number("friction", friction), _number("poisson", poisson)
    return _closed_form(
        (("x", x), ("y", y), ("z", z)), lambda x, y, z: _ext.sphere_stress(x, y, z, f, nu)
    )


def read_surface(path, *, spacing=None, height_unit=None, length_unit=None, fill="refuse"):
    """Reads a height file as ``stressfield surface FILE`` does (ASCII matrix .asc/.txt/.csv,
    XYZ, .x3p, .npy via scenes). Options as the command line's: spacing (m, number or pair)
    and height_unit (m, mm, um, nm) for files that do not say them, length_unit of an XYZ
    file, fill = "refuse" or "interpolate" for missing points.
    Returns ``(heights, (dx, dy))``: heights in m, float64 ``[rows = y, columns = x]``."""
    pair = None if spacing is None else _spacing(spacing)
    heights, (dx, dy) = _ext.read_surface(
        _os.fspath(path), pair, height_unit, length_unit, str(fill)
    )
    return heights, (dx, dy)


def surface_stats(
    heights, spacing, *, form="plane", band=None, e_star=None, hardness=None, window=True
) -> dict:
    """The characterisation of a height map, the dict of ``stressfield surface FILE --json``
    (ISO 25178 parameters, spectra, summits, Greenwood-Williamson values; SI).

    heights: 2-D (m), ``[rows = y, columns = x]``. spacing: m, number or ``(dx, dy)``.
    form: "plane" or "quadratic" removed before the statistics. band: ``(shortest,
    longest)`` wavelength (m) of the Hurst fit. e_star, hardness: Pa (GW load, plasticity
    index). window: window the map for its spectra (True for a measured map, as the command
    line does for files; False for a periodic generated one)."""
    heights = _float64("heights", heights, 2)
    dx, dy = _spacing(spacing)
    band = None if band is None else _spacing(band, "band")
    text = _ext.surface_stats(
        heights,
        dx,
        dy,
        str(form),
        band,
        None if e_star is None else _number("e_star", e_star),
        None if hardness is None else _number("hardness", hardness),
        bool(window),
    )
    return _json.loads(text)


class BatchError(StressfieldError):
    """Tasks of :func:`batch` failed: the message names the first failed task by its index
    and gives its error; ``results`` holds every task's dict in order (``None`` where the task
    failed) and ``errors`` maps each failed task's index to its :class:`StressfieldError`."""

    def __init__(self, message, results, errors):
        super().__init__(message)
        self.results = results
        self.errors = errors


def _task_label(task):
    """How a batch task is named in messages."""
    if isinstance(task, Scene):
        return f"scene {task.name} ({task.file})"
    if isinstance(task, _os.PathLike) or (
        isinstance(task, str) and "\n" not in task and task.strip().endswith(".toml")
    ):
        return _os.fspath(task)
    if isinstance(task, str):
        return "TOML text"
    return type(task).__name__


def _run_task(task, command="hertz") -> dict:
    """One batch task: a scene path, TOML text or Scene -> the dict of ``hertz --json`` (or
    of ``wear --json`` with ``command="wear"``)."""
    if isinstance(task, Scene):
        scene = task
    elif isinstance(task, _os.PathLike) or (
        isinstance(task, str) and "\n" not in task and task.strip().endswith(".toml")
    ):
        scene = load_scene(task)
    elif isinstance(task, str):
        scene = Scene.from_toml(task)
    else:
        raise StressfieldError(
            f"a batch task is a scene path, TOML text or Scene, got {type(task).__name__}"
        )
    return scene.wear() if command == "wear" else scene.hertz()


def _run_task_caught(task, command="hertz"):
    """``_run_task`` with its StressfieldError returned as its message, so that one task's
    failure does not lose the others' results (other exceptions, such as KeyboardInterrupt,
    propagate)."""
    try:
        return True, _run_task(task, command)
    except StressfieldError as error:
        return False, str(error)


def batch(tasks, client=None, *, command="hertz", errors="raise") -> list:
    """Runs a list of scenes (paths, TOML texts or :class:`Scene` objects) and returns one
    dict per task, in order: each scene's ``stressfield hertz SCENE --json`` (for a rough
    scene that of ``contact --json``, for a coated one the coated contact with its
    ``coating``), or with ``command="wear"`` its ``stressfield wear SCENE --json`` (wear
    scenes: ``[wear]`` or ``[[series]]``).

    client: a ``dask.distributed.Client``: the tasks are mapped over its cluster (a
    LocalCluster, or one from dask-jobqueue on Slurm/PBS); None runs them here, one after the
    other (each one uses every core). Scenes are sent as their file paths or text: paths must
    be readable by the workers.

    errors: every task runs whatever the others do. ``"raise"`` (the default): if any task
    failed, a :class:`BatchError` (a StressfieldError) names the first failed task by its
    index, with ``.results`` (every task's dict, None where it failed) and ``.errors``;
    ``"return"``: the list is returned with each failed task's StressfieldError in its place.
    """
    if errors not in ("raise", "return"):
        raise StressfieldError(f'errors must be "raise" or "return", got {errors!r}')
    if command not in ("hertz", "wear"):
        raise StressfieldError(f'command must be "hertz" or "wear", got {command!r}')
    tasks = list(tasks)
    if client is None:
        outcomes = [_run_task_caught(task, command) for task in tasks]
    else:
        portable = []
        for task in tasks:
            if isinstance(task, Scene):
                # A Scene lives in this process: send what it was read from.
                if not _os.path.exists(task.file):
                    raise StressfieldError(
                        f"scene {task.name} was not read from a file: pass its TOML text to batch() to run it on a cluster"
                    )
                portable.append(task.file)
            else:
                portable.append(_os.fspath(task) if isinstance(task, _os.PathLike) else task)
        futures = client.map(_run_task_caught, portable, command=command, pure=False)
        outcomes = client.gather(futures)
    results, failed = [], {}
    for index, (task, (ok, value)) in enumerate(zip(tasks, outcomes)):
        if ok:
            results.append(value)
        else:
            failed[index] = StressfieldError(
                f"batch: tasks[{index}] of {len(tasks)} ({_task_label(task)}): {value}"
            )
            results.append(None)
    if not failed:
        return results
    if errors == "return":
        return [failed.get(index, result) for index, result in enumerate(results)]
    first = min(failed)
    others = sorted(failed)[1:]
    more = ""
    if others:
        listed = ", ".join(map(str, others[:10])) + (", ..." if len(others) > 10 else "")
        more = f"\n{len(others)} more task(s) failed: tasks[{listed}]"
    raise BatchError(
        f"{failed[first]}{more}\nhint: the {len(tasks) - len(failed)} other task(s) ran: "
        "their results are in this error's .results (None where a task failed), its .errors "
        "has each failure; batch(..., errors=\"return\") returns them with each failure in its "
        "place",
        results,
        failed,
    )
