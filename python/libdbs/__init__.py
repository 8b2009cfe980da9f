"""libdbs: parameterize unorganized 3D point clouds within four boundary curves.

    import numpy as np, libdbs
    boundary = libdbs.Boundary.load("part_boundary.txt")
    result = libdbs.parameterize(points, boundary, accuracy=0.1, max_level=3)
    uv = result.uv                      # (N, 2)
    surface = result.evaluate(0.5, 0.5, normals=True)

The C API itself is in libdbs.capi (constants without the DBS_ prefix) and libdbs.lib (the
loaded library, every function declared).
"""
from . import _capi as capi
from ._library import lib
from .cloud import SIDES, Boundary, Cloud
from .errors import (CancelledError, DbsError, DbsFileNotFoundError, DbsMemoryError, DbsOSError, DbsPermissionError, DbsValueError, InternalError,
                     InvalidViewError, NumericalError, UnsupportedError)
from .options import Loss, Option, Options, Solver
from .result import Evaluation, Patches, Result, Stat, parameterize
from .validation import Distances, Distortion, Mesh, write_report

__version__ = "0.4.0"


def library_version() -> str:
    """The loaded libdbs's version, e.g. "0.4.0"."""
    return lib.dbs_version_string().decode()


def has_feature(feature: int) -> bool:
    """True when the loaded libdbs was built with `feature` (capi.FEATURE_*)."""
    import ctypes
    from .errors import check
    out = ctypes.c_int32()
    check(lib.dbs_has_feature(feature, ctypes.byref(out)))
    return bool(out.value)
