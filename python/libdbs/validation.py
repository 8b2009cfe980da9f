"""The validation of a result: its Delaunay mesh, distortion, distances, the report."""
import ctypes
import os

import numpy as np

from . import _capi
from ._arrays import double_pointer, int32_pointer
from ._library import lib
from .cloud import Cloud, _Handle, _new
from .errors import check
from .result import Result


def write_report(result: Result, cloud: Cloud, directory, options=None) -> None:
    """The validation report (mesh files, pictures, summary.json) into `directory`."""
    check(lib.dbs_report_write(result.handle, cloud.handle, options.handle if options is not None else None, os.fsencode(directory)))


class Distances(_Handle):
    """Statistics of a result's point-to-surface distances (DISTANCES_*), overall or per patch."""

    _destroy_name = "dbs_distances_destroy"

    def __init__(self, result: Result, tolerance: float = 0.0):
        super().__init__(_new(lib.dbs_distances_create, result.handle, float(tolerance)))

    def stat(self, stat: int, patch: int = -1) -> float:
        out = ctypes.c_double()
        check(lib.dbs_distances_stat(self._handle, patch, stat, ctypes.byref(out)))
        return out.value


class Mesh(_Handle):
    """The Delaunay mesh of a result's (u, v) over its cloud."""

    _destroy_name = "dbs_mesh_destroy"

    def __init__(self, result: Result, cloud: Cloud):
        super().__init__(_new(lib.dbs_mesh_create, result.handle, cloud.handle))

    def _count(self, function):
        count = ctypes.c_size_t()
        check(function(self._handle, ctypes.byref(count)))
        return count.value

    @property
    def triangles(self) -> np.ndarray:
        """(T, 3) int32 vertex indices (point indices of the cloud)."""
        n = self._count(lib.dbs_mesh_triangle_count)
        out = np.empty((n, 3), dtype=np.int32)
        check(lib.dbs_mesh_triangles(self._handle, int32_pointer(out), 3 * n))
        return out

    def save(self, path) -> None:
        check(lib.dbs_mesh_save(self._handle, os.fsencode(path)))

    def distortion(self, scaling: int = _capi.SCALING_UNIFORM) -> "Distortion":
        distortion = Distortion.__new__(Distortion)
        _Handle.__init__(distortion, _new(lib.dbs_mesh_distortion, self._handle, scaling))
        return distortion


class Distortion(_Handle):
    """Per-triangle distortion of a mesh over the parameterized cloud."""

    _destroy_name = "dbs_distortion_destroy"

    def __init__(self, result: Result, cloud: Cloud, triangles, scaling: int = _capi.SCALING_UNIFORM):
        array = np.ascontiguousarray(triangles, dtype=np.int32)
        if array.ndim != 2 or array.shape[1] != 3:
            raise ValueError(f"triangles must have shape (T, 3), not {array.shape}")
        super().__init__(_new(lib.dbs_distortion_create, result.handle, cloud.handle, int32_pointer(array), array.shape[0], scaling))

    def stat(self, stat: int) -> float:
        out = ctypes.c_double()
        check(lib.dbs_distortion_stat(self._handle, stat, ctypes.byref(out)))
        return out.value

    def values(self, measure: int) -> np.ndarray:
        n = int(self.stat(_capi.DISTORTION_TRIANGLES) + self.stat(_capi.DISTORTION_CROPPED))
        out = np.empty(n)
        check(lib.dbs_distortion_values(self._handle, measure, double_pointer(out), n))
        return out


__all__ = ["write_report", "Distances", "Mesh", "Distortion"]
