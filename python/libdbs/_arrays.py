"""NumPy arrays in and out of libdbs."""
import ctypes

import numpy as np

_DOUBLE_P = ctypes.POINTER(ctypes.c_double)
_INT32_P = ctypes.POINTER(ctypes.c_int32)


def as_points(points, name="points"):
    """An (N, 3) float64 C-contiguous array of `points`: the array itself when it is one
    already (no copy), else converted once. (3, N) and ragged input are refused."""
    if isinstance(points, np.ndarray) and points.dtype == np.float64 and points.ndim == 2 and points.shape[1] == 3 and points.flags.c_contiguous:
        return points
    try:
        array = np.asarray(points, dtype=np.float64)
    except (ValueError, TypeError) as error:
        raise ValueError(f"{name} must be an (N, 3) array of numbers: {error}") from None
    if array.ndim != 2 or array.shape[1] != 3:
        hint = ": transpose it" if array.ndim == 2 and array.shape[0] == 3 else ""
        raise ValueError(f"{name} must have shape (N, 3), not {array.shape}{hint}")
    return np.ascontiguousarray(array)


def double_pointer(array):
    return array.ctypes.data_as(_DOUBLE_P)


def int32_pointer(array):
    return array.ctypes.data_as(_INT32_P)


def points_out(count):
    return np.empty((count, 3), dtype=np.float64)
