"""Point clouds and boundaries."""
import ctypes
import os

import numpy as np

from . import _capi
from ._arrays import as_points, double_pointer, points_out
from ._library import lib
from .errors import check


class _Handle:
    """An owned libdbs handle, freed when collected or closed (also as a context manager)."""

    _destroy_name = None

    def __init__(self, handle):
        self._handle = handle

    @property
    def handle(self):
        return self._handle

    def close(self):
        if getattr(self, "_handle", None):
            getattr(lib, self._destroy_name)(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def _new(function, *args):
    handle = ctypes.c_void_p()
    check(function(*args, ctypes.byref(handle)))
    return handle


class Cloud(_Handle):
    """An immutable point cloud. Cloud(points) takes an (N, 3) array (without copying it on
    the Python side when it is float64 and C-contiguous); Cloud.load(path) reads a file."""

    _destroy_name = "dbs_cloud_destroy"

    def __init__(self, points):
        array = as_points(points)
        super().__init__(_new(lib.dbs_cloud_create, double_pointer(array), array.shape[0]))

    @classmethod
    def load(cls, path: "str | os.PathLike", options=None, progress=None) -> "Cloud":
        """Reads .xyz/.txt/.csv, .ply, .obj or .drc. With `progress(fraction, stage)` (or
        `options` carrying one) a big file reports its reading and may be cancelled (True);
        an exception raised in it cancels the load and is the cause of CancelledError."""
        cloud = cls.__new__(cls)
        if options is None and progress is None:
            _Handle.__init__(cloud, _new(lib.dbs_cloud_load, os.fsencode(path)))
            return cloud
        from .options import Options
        run = options if options is not None else Options()
        if progress is not None:
            run.on_progress(progress)
        handle = ctypes.c_void_p()
        status = lib.dbs_cloud_load_with_options(os.fsencode(path), run.handle, ctypes.byref(handle))
        _Handle.__init__(cloud, handle.value)  # owned before anything is raised
        failure = run.check_run(status)
        if failure is not None:
            raise failure
        return cloud

    def __len__(self) -> int:
        count = ctypes.c_size_t()
        check(lib.dbs_cloud_count(self._handle, ctypes.byref(count)))
        return count.value

    @property
    def points(self) -> np.ndarray:
        """The points, (N, 3)."""
        out = points_out(len(self))
        check(lib.dbs_cloud_points(self._handle, double_pointer(out), len(out)))
        return out

    @property
    def bounds(self):
        """(low, high) corners of the bounding box, each (3,)."""
        low, high = np.empty(3), np.empty(3)
        check(lib.dbs_cloud_bounds(self._handle, double_pointer(low), double_pointer(high)))
        return low, high

    def __repr__(self):
        return f"<libdbs.Cloud of {len(self)} points>" if self._handle else "<libdbs.Cloud (closed)>"


SIDES = ("bottom", "right", "top", "left")


class Boundary(_Handle):
    """Four boundary curves: bottom (v = 0), right (u = 1), top (v = 1), left (u = 0), the
    side indices of the C API (SIDE_BOTTOM = 0, ...)."""

    _destroy_name = "dbs_boundary_destroy"
    max_snap = 0.0
    """How far the farthest corner end was moved to make the corners meet (with a tolerance)."""

    def __init__(self, bottom, right, top, left, tolerance: "float | None" = None, relative: bool = True):
        """Corners may miss by `tolerance` (times the boundary's size when `relative`; None: the
        library's default, 1e-6 relative); they are then snapped together."""
        sides = [as_points(side, name) for side, name in zip((bottom, right, top, left), SIDES)]
        flat = [x for side in sides for x in (double_pointer(side), side.shape[0])]
        if tolerance is None:
            super().__init__(_new(lib.dbs_boundary_create, *flat))
            return
        snap = ctypes.c_double()
        super().__init__(_new(lib.dbs_boundary_create_tolerant, *flat, float(tolerance), 1 if relative else 0, ctypes.byref(snap)))
        self.max_snap = snap.value

    @classmethod
    def _wrap(cls, handle, max_snap=0.0):
        boundary = cls.__new__(cls)
        _Handle.__init__(boundary, handle)
        boundary.max_snap = max_snap
        return boundary

    @classmethod
    def load(cls, path, tolerance: "float | None" = None, relative: bool = True) -> "Boundary":
        """A boundary file (docs/FORMATS.md); `tolerance` as in Boundary()."""
        if tolerance is None:
            return cls._wrap(_new(lib.dbs_boundary_load, os.fsencode(path)))
        snap = ctypes.c_double()
        handle = _new(lib.dbs_boundary_load_tolerant, os.fsencode(path), float(tolerance), 1 if relative else 0, ctypes.byref(snap))
        return cls._wrap(handle, snap.value)

    @classmethod
    def from_loop(cls, loop, corners) -> "Boundary":
        """A closed polyline cut at four of its point indices, the corners (0,0), (1,0), (1,1), (0,1)."""
        array = as_points(loop, "loop")
        if len(corners) != 4:
            raise ValueError(f"corners needs 4 point indices, got {len(corners)}")
        indices = (ctypes.c_size_t * 4)(*[int(c) for c in corners])
        return cls._wrap(_new(lib.dbs_boundary_from_loop, double_pointer(array), array.shape[0], indices))

    @classmethod
    def detect(cls, cloud: "Cloud", options=None) -> "Boundary":
        """The cloud's outline cut at the four corners where it turns most; `holes` its inner loops."""
        return cls._wrap(_new(lib.dbs_boundary_detect, cloud.handle, options.handle if options is not None else None))

    @classmethod
    def from_corners(cls, cloud: "Cloud", corners) -> "Boundary":
        """The cloud's outline cut at its points nearest to four corner points (4, 3)."""
        array = as_points(corners, "corners")
        if array.shape[0] != 4:
            raise ValueError(f"corners must have shape (4, 3), not {array.shape}")
        return cls._wrap(_new(lib.dbs_boundary_from_corners, cloud.handle, double_pointer(array)))

    def side(self, side: "int | str") -> np.ndarray:
        """The points of a side (an index or a name: "bottom", ...), (M, 3)."""
        index = SIDES.index(side) if isinstance(side, str) else int(side)
        count = ctypes.c_size_t()
        check(lib.dbs_boundary_side_count(self._handle, index, ctypes.byref(count)))
        out = points_out(count.value)
        check(lib.dbs_boundary_side_points(self._handle, index, double_pointer(out), count.value))
        return out

    @property
    def holes(self):
        """The inner loops of a boundary found from a cloud, each (M, 3)."""
        count = ctypes.c_size_t()
        check(lib.dbs_boundary_hole_count(self._handle, ctypes.byref(count)))
        loops = []
        for hole in range(count.value):
            size = ctypes.c_size_t()
            check(lib.dbs_boundary_hole_size(self._handle, hole, ctypes.byref(size)))
            out = points_out(size.value)
            check(lib.dbs_boundary_hole_points(self._handle, hole, double_pointer(out), size.value))
            loops.append(out)
        return loops

    def save(self, path) -> None:
        """Writes the boundary file; Boundary.load(path) reads back the same sides bit for bit."""
        check(lib.dbs_boundary_save(self._handle, os.fsencode(path)))

    def write_report(self, cloud: "Cloud", directory) -> None:
        """boundary.png (the sides in colours, the corners, the holes) and boundary.json."""
        check(lib.dbs_boundary_report_write(self._handle, cloud.handle, os.fsencode(directory)))

    def __repr__(self):
        if not self._handle:
            return "<libdbs.Boundary (closed)>"
        counts = ", ".join(f"{name} {len(self.side(k))}" for k, name in enumerate(SIDES))
        return f"<libdbs.Boundary: {counts} points, {len(self.holes)} holes>"


__all__ = ["Cloud", "Boundary", "SIDES"]
