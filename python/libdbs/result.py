"""Running libdbs and reading its result."""
import collections
import ctypes
import enum
import os

import numpy as np

from . import _capi
from ._arrays import double_pointer, int32_pointer, points_out
from ._library import lib
from .cloud import Boundary, Cloud, _Handle
from .errors import InvalidViewError, check
from .options import Options

Stat = enum.IntEnum("Stat", {name[len("STAT_"):]: value for name, value in vars(_capi).items() if name.startswith("STAT_")})
Stat.__doc__ = "The summary statistics of a result (DBS_STAT_*)."

Evaluation = collections.namedtuple("Evaluation", "points normals su sv")
Evaluation.__doc__ = "Surface points, unit normals and the derivatives dS/du, dS/dv, each (..., 3); None when not asked for."


class Patches:
    """A read-only view of patches: the quadtree of a Result, or one level in a level callback
    (valid only during that call: using it afterwards raises InvalidViewError)."""

    def __init__(self, handle, owner):
        self._handle = handle
        self._owner = owner  # keeps the result alive while the view is used

    def _invalidate(self):
        self._handle = None

    def _live(self):
        if not self._handle:
            raise InvalidViewError("this Patches view was handed to a level callback and is no longer valid after it returned")
        return self._handle

    def __len__(self):
        count = ctypes.c_size_t()
        check(lib.dbs_patches_count(self._live(), ctypes.byref(count)))
        return count.value

    def _int(self, function, i):
        out = ctypes.c_int32()
        check(function(self._live(), i, ctypes.byref(out)))
        return out.value

    def __getitem__(self, i):
        """A dict describing the i-th patch of the view."""
        if not 0 <= i < len(self):
            raise IndexError(f"patch {i} is outside the view of {len(self)}")
        handle = self._live()
        rect = np.empty(4)
        check(lib.dbs_patches_rect(handle, i, double_pointer(rect)))
        nu, nv = ctypes.c_int32(), ctypes.c_int32()
        check(lib.dbs_patches_grid_size(handle, i, ctypes.byref(nu), ctypes.byref(nv)))
        points, mean, worst, iterations = ctypes.c_size_t(), ctypes.c_double(), ctypes.c_double(), ctypes.c_int32()
        check(lib.dbs_patches_stats(handle, i, ctypes.byref(points), ctypes.byref(mean), ctypes.byref(worst), ctypes.byref(iterations)))
        return {
            "id": self._int(lib.dbs_patches_id, i),
            "level": self._int(lib.dbs_patches_level, i),
            "leaf": bool(self._int(lib.dbs_patches_is_leaf, i)),
            "parent": self._int(lib.dbs_patches_parent, i),
            "rect": tuple(rect),
            "grid": (nu.value, nv.value),
            "points": points.value,
            "mean_distance": mean.value,
            "max_distance": worst.value,
            "iterations": iterations.value,
        }

    def __repr__(self):
        return f"<libdbs.Patches view of {len(self)} patches>" if self._handle else "<libdbs.Patches (invalid: its callback returned)>"


class Result(_Handle):
    """The parameters of every point and the quadtree of base surfaces."""

    _destroy_name = "dbs_result_destroy"

    def __len__(self):
        count = ctypes.c_size_t()
        check(lib.dbs_result_point_count(self._handle, ctypes.byref(count)))
        return count.value

    def _values(self, function, dtype):
        """(N,) values of a per-point function of the C API."""
        out = np.empty(len(self), dtype=dtype)
        check(function(self._handle, double_pointer(out) if dtype == np.float64 else int32_pointer(out), len(out)))
        return out

    @property
    def uv(self) -> np.ndarray:
        """(N, 2): each point's (u, v) (NaN for a cropped point)."""
        n = len(self)
        out = np.empty((n, 2))
        check(lib.dbs_result_uv(self._handle, double_pointer(out), n))  # capacity in pairs
        return out

    @property
    def distances(self) -> np.ndarray:
        """(N,): each point's distance to the surface, cloud units."""
        return self._values(lib.dbs_result_distances, np.float64)

    @property
    def patches_of_points(self) -> np.ndarray:
        """(N,) int32: the leaf patch that parameterized each point (-1: cropped)."""
        return self._values(lib.dbs_result_point_patches, np.int32)

    @property
    def levels(self) -> np.ndarray:
        """(N,) int32: the quadtree level of that leaf."""
        return self._values(lib.dbs_result_point_levels, np.int32)

    @property
    def flags(self) -> np.ndarray:
        """(N,) int32: the POINT_* bits of each point (repaired, far, clamped, cropped, turned)."""
        return self._values(lib.dbs_result_point_flags, np.int32)

    def stat(self, stat: "Stat | int | str") -> float:
        """A summary statistic: Stat.MEAN_DISTANCE, its number or its name ("mean_distance")."""
        stat = Stat[stat.upper()] if isinstance(stat, str) else Stat(stat)
        out = ctypes.c_double()
        check(lib.dbs_result_stat(self._handle, stat, ctypes.byref(out)))
        return out.value

    @property
    def stats(self) -> dict:
        """Every statistic by name."""
        return {s.name.lower(): self.stat(s) for s in Stat}

    @property
    def patches(self) -> Patches:
        handle = ctypes.c_void_p()
        check(lib.dbs_result_patches(self._handle, ctypes.byref(handle)))
        return Patches(handle, owner=self)

    def evaluate(self, u, v, normals: bool = False, derivatives: bool = False) -> Evaluation:
        """The surface at (u, v) (arrays of any shape, broadcast together, each in [0, 1])."""
        u, v = np.broadcast_arrays(np.asarray(u, dtype=np.float64), np.asarray(v, dtype=np.float64))
        uv = np.ascontiguousarray(np.stack([u.ravel(), v.ravel()], axis=1))
        n = uv.shape[0]
        outs = [points_out(n), points_out(n) if normals else None, points_out(n) if derivatives else None, points_out(n) if derivatives else None]
        pointers = [double_pointer(o) if o is not None else None for o in outs]
        check(lib.dbs_result_evaluate_many(self._handle, double_pointer(uv), n, *pointers))
        return Evaluation(*[o.reshape(u.shape + (3,)) if o is not None else None for o in outs])

    def save(self, cloud: Cloud, path) -> None:
        """Writes .csv, .ply or .drc (by the extension)."""
        check(lib.dbs_result_save(self._handle, cloud.handle, os.fsencode(path)))

    def __repr__(self):
        if not self._handle:
            return "<libdbs.Result (closed)>"
        return f"<libdbs.Result of {len(self)} points: {int(self.stat(Stat.LEAVES))} leaves on {int(self.stat(Stat.LEVELS))} levels, mean distance {self.stat(Stat.MEAN_DISTANCE):.6g}>"


def parameterize(points, boundary: Boundary, options: "Options | None" = None, *, progress=None, level=None, warning=None, **option_values) -> Result:
    """Parameterizes `points` (a Cloud, or an (N, 3) array) within `boundary`.

    Options by keyword (accuracy=0.1, max_level=3, ...) on top of `options`; progress(fraction,
    stage), level(level, patches) and warning(message) callbacks. An exception raised in a
    callback cancels the run and is raised as the cause of CancelledError; Ctrl-C during the
    run cancels it and raises KeyboardInterrupt.
    """
    cloud = points if isinstance(points, Cloud) else Cloud(points)
    run = Options()
    if options is not None:
        clone = ctypes.c_void_p()
        check(lib.dbs_options_clone(options.handle, ctypes.byref(clone)))
        lib.dbs_options_destroy(run._handle)
        run._handle = clone
    for key, value in option_values.items():
        run.set(key, value)
    # A progress callback always runs, so that Python sees Ctrl-C during a long run (signal
    # handlers run between Python instructions, i.e. in the callback) and can cancel it.
    run.on_progress(progress if progress is not None else (lambda fraction, stage: False))
    if level is not None:
        run.on_level(level)
    if warning is not None:
        run.on_warning(warning)
    handle = ctypes.c_void_p()
    status = lib.dbs_parameterize(cloud.handle, boundary.handle, run.handle, ctypes.byref(handle))
    result = Result(handle.value)  # owned (and freed if anything is raised) at once
    failure = run.check_run(status)
    if failure is not None:  # a warning callback that raised: the run went on
        raise failure
    return result


__all__ = ["Result", "Patches", "Stat", "Evaluation", "parameterize"]
