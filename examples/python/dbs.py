"""Python bindings of libdbs through ctypes (standard library only).

The library is found through the environment variable DBS_LIBRARY (a path to libdbs.so),
then through the system's search (ctypes.util.find_library). Every function of dbs.h is
declared below with its argtypes and restype: a ctypes function left with the default `int`
return would truncate 64-bit pointers.

The raw functions are available as attributes of `lib` (lib.dbs_cloud_create, ...); the
classes Cloud, Boundary, Options and Result wrap them, raise DbsError on a failed status
and free their handle when collected or when closed.
"""
import ctypes
import ctypes.util
import os

# ---- the shared library ---------------------------------------------------------------


def _load_library():
    path = os.environ.get("DBS_LIBRARY") or ctypes.util.find_library("dbs")
    if not path:
        raise OSError("libdbs not found: set DBS_LIBRARY to the path of libdbs.so")
    return ctypes.CDLL(path)


lib = _load_library()

# ---- constants of dbs.h (the DBS_ prefix dropped) --------------------------------------------

VERSION_MAJOR = 0
VERSION_MINOR = 4
VERSION_PATCH = 0

OK = 0
ERR_NULL_ARGUMENT = -1
ERR_INVALID_ARGUMENT = -2
ERR_OUT_OF_RANGE = -3
ERR_NON_FINITE = -4
ERR_EMPTY = -5
ERR_DEGENERATE = -6
ERR_IO = -7
ERR_PARSE = -8
ERR_UNSUPPORTED = -9
ERR_CANCELLED = -10
ERR_NO_MEMORY = -11
ERR_BUFFER_TOO_SMALL = -12
ERR_NUMERICAL = -13
ERR_INTERNAL = -99

SIDE_BOTTOM, SIDE_RIGHT, SIDE_TOP, SIDE_LEFT = 0, 1, 2, 3

OPT_ACCURACY = 0
OPT_RELATIVE_ACCURACY = 1
OPT_MAX_LEVEL = 2
OPT_INITIAL_GRID = 3
OPT_MAX_GRID = 4
OPT_SMOOTHING = 5
OPT_SOLVER = 6
OPT_THREADS = 7
OPT_SUBCLOUD_NEAR = 8
OPT_SUBCLOUD_OWN = 9
OPT_NOISE_FLOOR = 10
OPT_REPAIR = 11
OPT_LOSS = 12
OPT_LOSS_SCALE = 13
OPT_CERES_MAX_ITERATIONS = 14
OPT_CERES_FUNCTION_TOLERANCE = 15
OPT_OUTLINE_NEIGHBOURS = 16
INT_OPTIONS = (OPT_MAX_LEVEL, OPT_INITIAL_GRID, OPT_MAX_GRID, OPT_SOLVER, OPT_THREADS, OPT_NOISE_FLOOR, OPT_REPAIR,
               OPT_LOSS, OPT_CERES_MAX_ITERATIONS, OPT_OUTLINE_NEIGHBOURS)

FEATURE_DRACO = 0
FEATURE_VALIDATION = 1
FEATURE_REPORT = 2
FEATURE_CERES = 3

SOLVER_LINEAR = 0
SOLVER_CERES = 1

LOSS_NONE = 0
LOSS_HUBER = 1
LOSS_CAUCHY = 2
LOSS_SOFT_L1 = 3

STAT_MEAN_DISTANCE = 0
STAT_MAX_DISTANCE = 1
STAT_RMS_DISTANCE = 2
STAT_ACCURACY = 3
STAT_ACCURACY_MET = 4
STAT_LEVELS = 5
STAT_PATCHES = 6
STAT_LEAVES = 7
STAT_ITERATIONS = 8
STAT_SECONDS = 9
STAT_LENGTH_SCALE = 10
STAT_SECONDS_INDEX = 11
STAT_SECONDS_EVOLVE = 12
STAT_SECONDS_SUBDIVIDE = 13
STAT_SECONDS_PARAMETERIZE = 14
STAT_SECONDS_FOLDS = 15
STAT_REQUESTED_ACCURACY = 16
STAT_REQUESTED_MET = 17
STAT_NOISE = 18
STAT_FOLDED_SHARE = 19
STAT_FOLDED_POINTS = 20
STAT_UNDECIDED_POINTS = 21
STAT_COINCIDENT_POINTS = 22
STAT_JUDGED_POINTS = 23
STAT_REPAIRED_POINTS = 24
STAT_SOLVER = 25
STAT_CERES_ITERATIONS = 26
STAT_LOSS_SCALE = 27
STAT_COLLAPSED_POINTS = 28
STAT_BOUNDARY_GAP = 29
STAT_SCALE_RATIO = 30
STAT_COVERAGE = 31
STAT_CLAMPED_POINTS = 32
STAT_FAR_POINTS = 33

MESH_SUSPICIOUS_FACTOR = 4.0

SCALING_UNIFORM = 0
SCALING_PER_AXIS = 1

MEASURE_CONFORMAL = 0
MEASURE_AREA = 1
MEASURE_STRETCH_L2 = 2
MEASURE_STRETCH_LINF = 3
MEASURE_EDGE_DIFFERENCE = 4
MEASURE_SIGMA1 = 5
MEASURE_SIGMA2 = 6
MEASURE_FOLDED = 7
MEASURE_DEGENERATE = 8

SUMMARY_MIN = 0
SUMMARY_MEAN = 1
SUMMARY_P95 = 2
SUMMARY_MAX = 3

DISTORTION_TRIANGLES = 0
DISTORTION_DEGENERATE = 1
DISTORTION_FOLDED = 2
DISTORTION_SCALE_U = 3
DISTORTION_SCALE_V = 4
DISTORTION_MESH_STRETCH_L2 = 5

DISTANCES_COUNT = 0
DISTANCES_MEAN = 1
DISTANCES_RMS = 2
DISTANCES_MAX = 3
DISTANCES_P50 = 4
DISTANCES_P90 = 5
DISTANCES_P95 = 6
DISTANCES_P99 = 7
DISTANCES_WITHIN = 8
DISTANCES_TOLERANCE = 9

# ---- prototypes -------------------------------------------------------------------------

_int = ctypes.c_int
_i32 = ctypes.c_int32
_size = ctypes.c_size_t
_dbl = ctypes.c_double
_ptr = ctypes.c_void_p  # every opaque handle
_str = ctypes.c_char_p
_P = ctypes.POINTER

PROGRESS_FN = ctypes.CFUNCTYPE(_int, _dbl, _str, _ptr)  # (fraction, stage, payload)
LEVEL_FN = ctypes.CFUNCTYPE(_int, _i32, _ptr, _ptr)  # (level, patches, payload)
WARNING_FN = ctypes.CFUNCTYPE(None, _str, _ptr)  # (message, payload)

PROTOTYPES = {
    # name: (restype, argtypes)
    "dbs_version_number": (_i32, []),
    "dbs_version_string": (_str, []),
    "dbs_has_feature": (_int, [_i32, _P(_i32)]),
    "dbs_status_string": (_str, [_int]),
    "dbs_last_error_message": (_str, []),
    "dbs_cloud_create": (_int, [_P(_dbl), _size, _P(_ptr)]),
    "dbs_cloud_load": (_int, [_str, _P(_ptr)]),
    "dbs_cloud_load_with_options": (_int, [_str, _ptr, _P(_ptr)]),
    "dbs_cloud_destroy": (None, [_ptr]),
    "dbs_cloud_count": (_int, [_ptr, _P(_size)]),
    "dbs_cloud_bounds": (_int, [_ptr, _P(_dbl), _P(_dbl)]),
    "dbs_cloud_points": (_int, [_ptr, _P(_dbl), _size]),
    "dbs_boundary_create": (_int, [_P(_dbl), _size, _P(_dbl), _size, _P(_dbl), _size, _P(_dbl), _size, _P(_ptr)]),
    "dbs_boundary_create_tolerant": (_int, [_P(_dbl), _size, _P(_dbl), _size, _P(_dbl), _size, _P(_dbl), _size, _dbl, _i32, _P(_dbl), _P(_ptr)]),
    "dbs_boundary_load_tolerant": (_int, [_str, _dbl, _i32, _P(_dbl), _P(_ptr)]),
    "dbs_boundary_from_loop": (_int, [_P(_dbl), _size, _P(_size), _P(_ptr)]),
    "dbs_boundary_load": (_int, [_str, _P(_ptr)]),
    "dbs_boundary_save": (_int, [_ptr, _str]),
    "dbs_boundary_destroy": (None, [_ptr]),
    "dbs_boundary_side_count": (_int, [_ptr, _i32, _P(_size)]),
    "dbs_boundary_side_points": (_int, [_ptr, _i32, _P(_dbl), _size]),
    "dbs_options_create": (_int, [_P(_ptr)]),
    "dbs_options_clone": (_int, [_ptr, _P(_ptr)]),
    "dbs_options_destroy": (None, [_ptr]),
    "dbs_options_set_int": (_int, [_ptr, _i32, _i32]),
    "dbs_options_get_int": (_int, [_ptr, _i32, _P(_i32)]),
    "dbs_options_set_double": (_int, [_ptr, _i32, _dbl]),
    "dbs_options_get_double": (_int, [_ptr, _i32, _P(_dbl)]),
    "dbs_option_bounds": (_int, [_i32, _P(_dbl), _P(_dbl)]),
    "dbs_options_set_progress": (_int, [_ptr, PROGRESS_FN, _ptr]),
    "dbs_options_set_level_callback": (_int, [_ptr, LEVEL_FN, _ptr]),
    "dbs_options_set_warning": (_int, [_ptr, WARNING_FN, _ptr]),
    "dbs_boundary_detect": (_int, [_ptr, _ptr, _P(_ptr)]),
    "dbs_boundary_from_corners": (_int, [_ptr, _P(_dbl), _P(_ptr)]),
    "dbs_boundary_hole_count": (_int, [_ptr, _P(_size)]),
    "dbs_boundary_hole_size": (_int, [_ptr, _size, _P(_size)]),
    "dbs_boundary_hole_points": (_int, [_ptr, _size, _P(_dbl), _size]),
    "dbs_parameterize": (_int, [_ptr, _ptr, _ptr, _P(_ptr)]),
    "dbs_result_destroy": (None, [_ptr]),
    "dbs_result_point_count": (_int, [_ptr, _P(_size)]),
    "dbs_result_uv": (_int, [_ptr, _P(_dbl), _size]),
    "dbs_result_distances": (_int, [_ptr, _P(_dbl), _size]),
    "dbs_result_point_patches": (_int, [_ptr, _P(_i32), _size]),
    "dbs_result_point_levels": (_int, [_ptr, _P(_i32), _size]),
    "dbs_result_repaired": (_int, [_ptr, _P(_i32), _size]),
    "dbs_result_evaluate": (_int, [_ptr, _dbl, _dbl, _P(_dbl), _P(_dbl)]),
    "dbs_result_stat": (_int, [_ptr, _i32, _P(_dbl)]),
    "dbs_result_patches": (_int, [_ptr, _P(_ptr)]),
    "dbs_result_save": (_int, [_ptr, _ptr, _str]),
    "dbs_patches_count": (_int, [_ptr, _P(_size)]),
    "dbs_patches_id": (_int, [_ptr, _size, _P(_i32)]),
    "dbs_patches_level": (_int, [_ptr, _size, _P(_i32)]),
    "dbs_patches_is_leaf": (_int, [_ptr, _size, _P(_i32)]),
    "dbs_patches_parent": (_int, [_ptr, _size, _P(_i32)]),
    "dbs_patches_rect": (_int, [_ptr, _size, _P(_dbl)]),
    "dbs_patches_grid_size": (_int, [_ptr, _size, _P(_i32), _P(_i32)]),
    "dbs_patches_grid_points": (_int, [_ptr, _size, _P(_dbl), _size]),
    "dbs_patches_boundary_count": (_int, [_ptr, _size, _i32, _P(_size)]),
    "dbs_patches_boundary_points": (_int, [_ptr, _size, _i32, _P(_dbl), _size]),
    "dbs_patches_stats": (_int, [_ptr, _size, _P(_size), _P(_dbl), _P(_dbl), _P(_i32)]),
    "dbs_patches_solver": (_int, [_ptr, _size, _P(_i32), _P(_size)]),
    "dbs_mesh_create": (_int, [_ptr, _ptr, _P(_ptr)]),
    "dbs_mesh_destroy": (None, [_ptr]),
    "dbs_mesh_vertex_count": (_int, [_ptr, _P(_size)]),
    "dbs_mesh_vertices": (_int, [_ptr, _P(_dbl), _size]),
    "dbs_mesh_uv": (_int, [_ptr, _P(_dbl), _size]),
    "dbs_mesh_triangle_count": (_int, [_ptr, _P(_size)]),
    "dbs_mesh_triangles": (_int, [_ptr, _P(_i32), _size]),
    "dbs_mesh_suspicious_count": (_int, [_ptr, _P(_size)]),
    "dbs_mesh_suspicious": (_int, [_ptr, _P(_i32), _size]),
    "dbs_mesh_save": (_int, [_ptr, _str]),
    "dbs_mesh_distortion": (_int, [_ptr, _i32, _P(_ptr)]),
    "dbs_distortion_create": (_int, [_ptr, _ptr, _P(_i32), _size, _i32, _P(_ptr)]),
    "dbs_distortion_destroy": (None, [_ptr]),
    "dbs_distortion_stat": (_int, [_ptr, _i32, _P(_dbl)]),
    "dbs_distortion_summary": (_int, [_ptr, _i32, _i32, _P(_dbl)]),
    "dbs_distortion_values": (_int, [_ptr, _i32, _P(_dbl), _size]),
    "dbs_distances_create": (_int, [_ptr, _dbl, _P(_ptr)]),
    "dbs_distances_destroy": (None, [_ptr]),
    "dbs_distances_stat": (_int, [_ptr, _i32, _i32, _P(_dbl)]),
    "dbs_report_write": (_int, [_ptr, _ptr, _ptr, _str]),
}

for _name, (_restype, _argtypes) in PROTOTYPES.items():
    _function = getattr(lib, _name)
    _function.restype = _restype
    _function.argtypes = _argtypes

# ---- errors -------------------------------------------------------------------------------


class DbsError(Exception):
    """A failed libdbs call: `status` is the DBS_ERR_* code, the text libdbs's message."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


def _check(status):
    if status != OK:
        message = lib.dbs_last_error_message().decode("utf-8", "replace")
        name = lib.dbs_status_string(status).decode()
        raise DbsError(status, f"{message} ({name})" if message else name)


def version():
    """The loaded library's version string, e.g. "0.1.0"."""
    return lib.dbs_version_string().decode()


def has_feature(feature):
    """True when the loaded library was built with `feature` (FEATURE_*)."""
    out = _i32(0)
    _check(lib.dbs_has_feature(feature, ctypes.byref(out)))
    return bool(out.value)


def _points_array(points):
    """A flat ctypes double array from a sequence of (x, y, z) or a flat sequence."""
    flat = [float(c) for p in points for c in (p if hasattr(p, "__len__") else (p,))]
    if len(flat) % 3 != 0:
        raise ValueError("points need 3 coordinates each")
    return (_dbl * len(flat))(*flat), len(flat) // 3


def _triples(array):
    return [tuple(array[3 * i:3 * i + 3]) for i in range(len(array) // 3)]


class _Handle:
    _destroy = None
    _handle = None

    def __init__(self, handle):
        self._handle = handle

    @property
    def handle(self):
        return self._handle

    def close(self):
        if self._handle:
            type(self)._destroy(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


# ---- clouds and boundaries -------------------------------------------------------------------


class Cloud(_Handle):
    _destroy = lib.dbs_cloud_destroy

    @classmethod
    def from_points(cls, points):
        array, count = _points_array(points)
        handle = _ptr()
        _check(lib.dbs_cloud_create(array, count, ctypes.byref(handle)))
        return cls(handle)

    @classmethod
    def load(cls, path, options=None):
        """The cloud of a file; with `options`, their progress callback (Options.on_progress)
        follows the load and may cancel it (dbs_cloud_load_with_options)."""
        handle = _ptr()
        if options is None:
            _check(lib.dbs_cloud_load(os.fsencode(path), ctypes.byref(handle)))
        else:
            _check(lib.dbs_cloud_load_with_options(os.fsencode(path), options._handle, ctypes.byref(handle)))
        return cls(handle)

    def __len__(self):
        count = _size()
        _check(lib.dbs_cloud_count(self._handle, ctypes.byref(count)))
        return count.value

    def bounds(self):
        low, high = (_dbl * 3)(), (_dbl * 3)()
        _check(lib.dbs_cloud_bounds(self._handle, low, high))
        return tuple(low), tuple(high)

    def points(self):
        count = len(self)
        array = (_dbl * (3 * count))()
        _check(lib.dbs_cloud_points(self._handle, array, count))
        return _triples(array)


class Boundary(_Handle):
    _destroy = lib.dbs_boundary_destroy

    max_snap = 0.0
    """How far the farthest corner end was moved to make the corners meet (with a tolerance)."""

    @classmethod
    def from_sides(cls, bottom, right, top, left, tolerance=None, relative=True):
        """The four sides; corners may miss by `tolerance` (times the boundary's size when
        `relative`; None: the library's default, 1e-6 relative) and are then snapped."""
        sides = [_points_array(side) for side in (bottom, right, top, left)]
        flat = [x for side in sides for x in side]
        handle = _ptr()
        if tolerance is None:
            _check(lib.dbs_boundary_create(*flat, ctypes.byref(handle)))
            return cls(handle)
        snap = _dbl()
        _check(lib.dbs_boundary_create_tolerant(*flat, float(tolerance), 1 if relative else 0, ctypes.byref(snap), ctypes.byref(handle)))
        boundary = cls(handle)
        boundary.max_snap = snap.value
        return boundary

    @classmethod
    def from_loop(cls, loop, corners):
        """The boundary cut from a closed polyline at four of its point indices, the corners
        (0,0), (1,0), (1,1), (0,1) in that order (dbs_boundary_from_loop)."""
        array, count = _points_array(loop)
        if len(corners) != 4:
            raise ValueError("corners needs 4 point indices, got %d" % len(corners))
        indices = (_size * 4)(*[int(c) for c in corners])
        handle = _ptr()
        _check(lib.dbs_boundary_from_loop(array, count, indices, ctypes.byref(handle)))
        return cls(handle)

    @classmethod
    def detect(cls, cloud, options=None):
        """The boundary found from the cloud itself: its outline cut at the four corners where
        it turns most (dbs_boundary_detect); holes() gives its inner loops."""
        handle = _ptr()
        _check(lib.dbs_boundary_detect(cloud.handle, options.handle if options is not None else None, ctypes.byref(handle)))
        return cls(handle)

    @classmethod
    def from_corners(cls, cloud, corners):
        """The cloud's outline cut at the points nearest to four corner points (x, y, z), which
        become (0,0), (1,0), (1,1), (0,1) (dbs_boundary_from_corners)."""
        array, count = _points_array(corners)
        if count != 4:
            raise ValueError("corners needs 4 points, got %d" % count)
        handle = _ptr()
        _check(lib.dbs_boundary_from_corners(cloud.handle, array, ctypes.byref(handle)))
        return cls(handle)

    def holes(self):
        """The inner loops of a detected boundary, each a list of (x, y, z)."""
        count = _size()
        _check(lib.dbs_boundary_hole_count(self._handle, ctypes.byref(count)))
        loops = []
        for hole in range(count.value):
            size = _size()
            _check(lib.dbs_boundary_hole_size(self._handle, hole, ctypes.byref(size)))
            array = (_dbl * (3 * size.value))()
            _check(lib.dbs_boundary_hole_points(self._handle, hole, array, size.value))
            loops.append(_triples(array))
        return loops

    @classmethod
    def load(cls, path, tolerance=None, relative=True):
        """A boundary file; `tolerance` as in from_sides."""
        handle = _ptr()
        if tolerance is None:
            _check(lib.dbs_boundary_load(os.fsencode(path), ctypes.byref(handle)))
            return cls(handle)
        snap = _dbl()
        _check(lib.dbs_boundary_load_tolerant(os.fsencode(path), float(tolerance), 1 if relative else 0, ctypes.byref(snap), ctypes.byref(handle)))
        boundary = cls(handle)
        boundary.max_snap = snap.value
        return boundary

    def save(self, path):
        """Writes the boundary file; Boundary.load(path) gives the same sides bit for bit."""
        _check(lib.dbs_boundary_save(self._handle, os.fsencode(path)))

    def side(self, side):
        count = _size()
        _check(lib.dbs_boundary_side_count(self._handle, side, ctypes.byref(count)))
        array = (_dbl * (3 * count.value))()
        _check(lib.dbs_boundary_side_points(self._handle, side, array, count.value))
        return _triples(array)


# ---- options --------------------------------------------------------------------------------


class Options(_Handle):
    """Options; set(OPT_..., value) picks the integer or real setter by the option id."""

    _destroy = lib.dbs_options_destroy

    def __init__(self, handle=None):
        if handle is None:
            handle = _ptr()
            _check(lib.dbs_options_create(ctypes.byref(handle)))
        super().__init__(handle)
        self._callbacks = []  # ctypes callback objects must outlive their use by libdbs

    def set(self, option, value):
        if option in INT_OPTIONS:
            _check(lib.dbs_options_set_int(self._handle, option, int(value)))
        else:
            _check(lib.dbs_options_set_double(self._handle, option, float(value)))
        return self

    def get(self, option):
        if option in INT_OPTIONS:
            out = _i32()
            _check(lib.dbs_options_get_int(self._handle, option, ctypes.byref(out)))
        else:
            out = _dbl()
            _check(lib.dbs_options_get_double(self._handle, option, ctypes.byref(out)))
        return out.value

    @staticmethod
    def bounds(option):
        low, high = _dbl(), _dbl()
        _check(lib.dbs_option_bounds(option, ctypes.byref(low), ctypes.byref(high)))
        return low.value, high.value

    def clone(self):
        handle = _ptr()
        _check(lib.dbs_options_clone(self._handle, ctypes.byref(handle)))
        return Options(handle)

    def on_progress(self, function):
        """function(fraction, stage) -> truthy to cancel; None clears it. An exception
        raised inside it cancels the run."""

        def adaptor(fraction, stage, _payload):
            try:
                return 1 if function(fraction, stage.decode()) else 0
            except Exception:  # never let an exception unwind through C
                return 1

        callback = PROGRESS_FN(adaptor) if function else PROGRESS_FN()
        _check(lib.dbs_options_set_progress(self._handle, callback, None))
        self._callbacks.append(callback)
        return self

    def on_level(self, function):
        """function(level, Patches) -> truthy to cancel; the Patches view is valid only
        during the call. None clears it."""

        def adaptor(level, patches, _payload):
            try:
                return 1 if function(level, Patches(patches, owner=None)) else 0
            except Exception:
                return 1

        callback = LEVEL_FN(adaptor) if function else LEVEL_FN()
        _check(lib.dbs_options_set_level_callback(self._handle, callback, None))
        self._callbacks.append(callback)
        return self

    def on_warning(self, function):
        """function(message): a likely mistake in the inputs (the boundary's size or distance
        against the cloud, points far outside the cloud, the domain's coverage, points
        clamped outside the boundary); the run goes on. None clears it."""

        def adaptor(message, _payload):
            try:
                function(message.decode())
            except Exception:
                pass  # a warning must not stop the run

        callback = WARNING_FN(adaptor) if function else WARNING_FN()
        _check(lib.dbs_options_set_warning(self._handle, callback, None))
        self._callbacks.append(callback)
        return self


# ---- results ----------------------------------------------------------------------------------


class Patches:
    """A read-only view of patches (the whole quadtree of a Result, or one level)."""

    def __init__(self, handle, owner):
        self._handle = handle
        self._owner = owner  # keeps the result alive while the view is used

    def __len__(self):
        count = _size()
        _check(lib.dbs_patches_count(self._handle, ctypes.byref(count)))
        return count.value

    def _int(self, function, i):
        out = _i32()
        _check(function(self._handle, i, ctypes.byref(out)))
        return out.value

    def info(self, i):
        """A dict describing the i-th patch of the view."""
        rect = (_dbl * 4)()
        _check(lib.dbs_patches_rect(self._handle, i, rect))
        nu, nv = _i32(), _i32()
        _check(lib.dbs_patches_grid_size(self._handle, i, ctypes.byref(nu), ctypes.byref(nv)))
        points, mean, worst, iterations = _size(), _dbl(), _dbl(), _i32()
        _check(lib.dbs_patches_stats(self._handle, i, ctypes.byref(points), ctypes.byref(mean), ctypes.byref(worst), ctypes.byref(iterations)))
        solver, ceres_iterations = _i32(), _size()
        _check(lib.dbs_patches_solver(self._handle, i, ctypes.byref(solver), ctypes.byref(ceres_iterations)))
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
            "solver": "ceres" if solver.value == SOLVER_CERES else "linear",
            "ceres_iterations": ceres_iterations.value,
        }

    def grid_points(self, i):
        nu, nv = _i32(), _i32()
        _check(lib.dbs_patches_grid_size(self._handle, i, ctypes.byref(nu), ctypes.byref(nv)))
        count = nu.value * nv.value
        array = (_dbl * (3 * count))()
        _check(lib.dbs_patches_grid_points(self._handle, i, array, count))
        return _triples(array)

    def boundary(self, i, side):
        count = _size()
        _check(lib.dbs_patches_boundary_count(self._handle, i, side, ctypes.byref(count)))
        array = (_dbl * (3 * count.value))()
        _check(lib.dbs_patches_boundary_points(self._handle, i, side, array, count.value))
        return _triples(array)


class Result(_Handle):
    _destroy = lib.dbs_result_destroy

    def __len__(self):
        count = _size()
        _check(lib.dbs_result_point_count(self._handle, ctypes.byref(count)))
        return count.value

    def uv(self):
        count = len(self)
        array = (_dbl * (2 * count))()
        _check(lib.dbs_result_uv(self._handle, array, count))
        return [(array[2 * i], array[2 * i + 1]) for i in range(count)]

    def distances(self):
        count = len(self)
        array = (_dbl * count)()
        _check(lib.dbs_result_distances(self._handle, array, count))
        return list(array)

    def point_patches(self):
        count = len(self)
        array = (_i32 * count)()
        _check(lib.dbs_result_point_patches(self._handle, array, count))
        return list(array)

    def point_levels(self):
        count = len(self)
        array = (_i32 * count)()
        _check(lib.dbs_result_point_levels(self._handle, array, count))
        return list(array)

    def repaired(self):
        """1 for each point the last-resort repair (OPT_REPAIR) placed, else 0."""
        count = len(self)
        array = (_i32 * count)()
        _check(lib.dbs_result_repaired(self._handle, array, count))
        return list(array)

    def evaluate(self, u, v):
        """(point, unit normal) of the base surface at (u, v)."""
        point, normal = (_dbl * 3)(), (_dbl * 3)()
        _check(lib.dbs_result_evaluate(self._handle, u, v, point, normal))
        return tuple(point), tuple(normal)

    def stat(self, stat):
        out = _dbl()
        _check(lib.dbs_result_stat(self._handle, stat, ctypes.byref(out)))
        return out.value

    def patches(self):
        view = _ptr()
        _check(lib.dbs_result_patches(self._handle, ctypes.byref(view)))
        return Patches(view, owner=self)

    def save(self, cloud, path):
        _check(lib.dbs_result_save(self._handle, cloud.handle, os.fsencode(path)))


# ---- validation --------------------------------------------------------------------------------


class Distortion(_Handle):
    """Per-triangle distortion of a mesh between 3D and (u,v) (MEASURE_*, SUMMARY_*)."""

    _destroy = lib.dbs_distortion_destroy

    @classmethod
    def of_triangles(cls, result, cloud, triangles, scaling=SCALING_UNIFORM):
        """Distortion of the caller's triangles (a sequence of (a, b, c) cloud indices)."""
        flat = [int(i) for t in triangles for i in t]
        array = (_i32 * len(flat))(*flat)
        handle = _ptr()
        _check(lib.dbs_distortion_create(result.handle, cloud.handle, array, len(flat) // 3, scaling, ctypes.byref(handle)))
        return cls(handle)

    def stat(self, stat):
        out = _dbl()
        _check(lib.dbs_distortion_stat(self._handle, stat, ctypes.byref(out)))
        return out.value

    def summary(self, measure, summary):
        out = _dbl()
        _check(lib.dbs_distortion_summary(self._handle, measure, summary, ctypes.byref(out)))
        return out.value

    def values(self, measure):
        count = int(self.stat(DISTORTION_TRIANGLES))
        array = (_dbl * count)()
        _check(lib.dbs_distortion_values(self._handle, measure, array, count))
        return list(array)


class Mesh(_Handle):
    """The 2D Delaunay mesh of a result's (u,v) over the parameterized cloud."""

    _destroy = lib.dbs_mesh_destroy

    @classmethod
    def create(cls, result, cloud):
        handle = _ptr()
        _check(lib.dbs_mesh_create(result.handle, cloud.handle, ctypes.byref(handle)))
        return cls(handle)

    def _count(self, function):
        count = _size()
        _check(function(self._handle, ctypes.byref(count)))
        return count.value

    def vertices(self):
        count = self._count(lib.dbs_mesh_vertex_count)
        array = (_dbl * (3 * count))()
        _check(lib.dbs_mesh_vertices(self._handle, array, count))
        return _triples(array)

    def uv(self):
        count = self._count(lib.dbs_mesh_vertex_count)
        array = (_dbl * (2 * count))()
        _check(lib.dbs_mesh_uv(self._handle, array, count))
        return [(array[2 * i], array[2 * i + 1]) for i in range(count)]

    def triangles(self):
        count = self._count(lib.dbs_mesh_triangle_count)
        array = (_i32 * (3 * count))()
        _check(lib.dbs_mesh_triangles(self._handle, array, count))
        return [tuple(array[3 * i:3 * i + 3]) for i in range(count)]

    def suspicious(self):
        count = self._count(lib.dbs_mesh_suspicious_count)
        array = (_i32 * count)()
        _check(lib.dbs_mesh_suspicious(self._handle, array, count))
        return list(array)

    def save(self, path):
        _check(lib.dbs_mesh_save(self._handle, os.fsencode(path)))

    def distortion(self, scaling=SCALING_UNIFORM):
        handle = _ptr()
        _check(lib.dbs_mesh_distortion(self._handle, scaling, ctypes.byref(handle)))
        return Distortion(handle)


class Distances(_Handle):
    """Point-to-surface distance statistics (DISTANCES_*), overall (patch -1) or per leaf."""

    _destroy = lib.dbs_distances_destroy

    @classmethod
    def create(cls, result, tolerance=0.0):
        handle = _ptr()
        _check(lib.dbs_distances_create(result.handle, tolerance, ctypes.byref(handle)))
        return cls(handle)

    def stat(self, stat, patch=-1):
        out = _dbl()
        _check(lib.dbs_distances_stat(self._handle, patch, stat, ctypes.byref(out)))
        return out.value


def write_report(result, cloud, directory, options=None):
    """Writes the validation report (meshes, pictures, summary.json) into `directory`."""
    _check(lib.dbs_report_write(result.handle, cloud.handle, options.handle if options else None, os.fsencode(directory)))


def parameterize(cloud, boundary, options=None):
    """Parameterizes `cloud` inside `boundary`; returns a Result."""
    handle = _ptr()
    _check(lib.dbs_parameterize(cloud.handle, boundary.handle, options.handle if options else None, ctypes.byref(handle)))
    return Result(handle)
