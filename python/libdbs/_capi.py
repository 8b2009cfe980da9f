"""The C API of libdbs as ctypes declarations: every constant and function of dbs.h.

Generated from include/dbs.h by scripts/generate_bindings.py: do not edit (a test
compares this file with what the script writes)."""
import ctypes

# ---- constants (the DBS_ prefix dropped) ----
VERSION_MAJOR = 0
VERSION_MINOR = 4
VERSION_PATCH = 0
FEATURE_DRACO = 0
FEATURE_VALIDATION = 1
FEATURE_REPORT = 2
FEATURE_CERES = 3
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
SIDE_BOTTOM = 0
SIDE_RIGHT = 1
SIDE_TOP = 2
SIDE_LEFT = 3
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
OPT_REPAIR = 11
OPT_NOISE_FLOOR = 10
OPT_LOSS = 12
OPT_LOSS_SCALE = 13
OPT_CERES_MAX_ITERATIONS = 14
OPT_OUTLINE_NEIGHBOURS = 16
OPT_CROP = 17
OPT_STRICT = 18
OPT_SMOOTH_TURNED = 19
OPT_COARSE_PASS = 20
OPT_FIT_TO_TARGET = 21
OPT_CERES_FUNCTION_TOLERANCE = 15
SOLVER_LINEAR = 0
SOLVER_CERES = 1
LOSS_NONE = 0
LOSS_HUBER = 1
LOSS_CAUCHY = 2
LOSS_SOFT_L1 = 3
POINT_REPAIRED = 1
POINT_FAR = 2
POINT_CLAMPED = 4
POINT_CROPPED = 8
POINT_TURNED = 16
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
STAT_REPAIRED_POINTS = 24
STAT_JUDGED_POINTS = 23
STAT_SOLVER = 25
STAT_CERES_ITERATIONS = 26
STAT_LOSS_SCALE = 27
STAT_COLLAPSED_POINTS = 28
STAT_BOUNDARY_GAP = 29
STAT_SCALE_RATIO = 30
STAT_COVERAGE = 31
STAT_CLAMPED_POINTS = 32
STAT_CROPPED_POINTS = 34
STAT_FAR_POINTS = 33
STAT_TURNED_POINTS = 35
STAT_TURNED_SHARE = 36
STAT_SMOOTHED_POINTS = 37
STAT_PASSES = 38
STAT_COARSE = 39
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
MEASURE_CROPPED = 9
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
DISTORTION_CROPPED = 6
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

# the options whose values are integers ("int;" beside them in dbs.h)
INTEGER_OPTIONS = (OPT_MAX_LEVEL, OPT_INITIAL_GRID, OPT_MAX_GRID, OPT_SOLVER, OPT_THREADS, OPT_REPAIR, OPT_NOISE_FLOOR, OPT_LOSS, OPT_CERES_MAX_ITERATIONS, OPT_OUTLINE_NEIGHBOURS, OPT_CROP, OPT_STRICT, OPT_SMOOTH_TURNED, OPT_COARSE_PASS, OPT_FIT_TO_TARGET,)

# ---- callback types ----
PROGRESS_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, ctypes.c_char_p, ctypes.c_void_p)
LEVEL_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_int32, ctypes.c_void_p, ctypes.c_void_p)
WARNING_FN = ctypes.CFUNCTYPE(None, ctypes.c_char_p, ctypes.c_void_p)

# ---- functions: name -> (restype, argtypes, parameter names) ----
FUNCTIONS = {
    "dbs_version_number": (ctypes.c_int32, [], ()),
    "dbs_version_string": (ctypes.c_char_p, [], ()),
    "dbs_has_feature": (ctypes.c_int, [ctypes.c_int32, ctypes.POINTER(ctypes.c_int32)], ('feature', 'out')),
    "dbs_status_string": (ctypes.c_char_p, [ctypes.c_int], ('status',)),
    "dbs_last_error_message": (ctypes.c_char_p, [], ()),
    "dbs_last_error_errno": (ctypes.c_int, [], ()),
    "dbs_cloud_create": (ctypes.c_int, [ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_void_p)], ('xyz', 'count', 'out')),
    "dbs_cloud_load": (ctypes.c_int, [ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p)], ('path', 'out')),
    "dbs_cloud_load_with_options": (ctypes.c_int, [ctypes.c_char_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('path', 'options', 'out')),
    "dbs_cloud_destroy": (None, [ctypes.c_void_p], ('cloud',)),
    "dbs_cloud_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('cloud', 'out')),
    "dbs_cloud_bounds": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)], ('cloud', 'out_min', 'out_max')),
    "dbs_cloud_points": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('cloud', 'out_xyz', 'capacity')),
    "dbs_boundary_create": (ctypes.c_int, [ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_void_p)], ('bottom', 'n_bottom', 'right', 'n_right', 'top', 'n_top', 'left', 'n_left', 'out')),
    "dbs_boundary_create_tolerant": (ctypes.c_int, [ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.c_double, ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_void_p)], ('bottom', 'n_bottom', 'right', 'n_right', 'top', 'n_top', 'left', 'n_left', 'tolerance', 'relative', 'out_max_snap', 'out')),
    "dbs_boundary_load_tolerant": (ctypes.c_int, [ctypes.c_char_p, ctypes.c_double, ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_void_p)], ('path', 'tolerance', 'relative', 'out_max_snap', 'out')),
    "dbs_boundary_from_loop": (ctypes.c_int, [ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_size_t), ctypes.POINTER(ctypes.c_void_p)], ('xyz', 'n', 'corners', 'out')),
    "dbs_boundary_load": (ctypes.c_int, [ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p)], ('path', 'out')),
    "dbs_boundary_save": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_char_p], ('boundary', 'path')),
    "dbs_boundary_destroy": (None, [ctypes.c_void_p], ('boundary',)),
    "dbs_boundary_side_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_size_t)], ('boundary', 'side', 'out')),
    "dbs_boundary_side_points": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('boundary', 'side', 'out_xyz', 'capacity')),
    "dbs_options_create": (ctypes.c_int, [ctypes.POINTER(ctypes.c_void_p)], ('out',)),
    "dbs_options_clone": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('options', 'out')),
    "dbs_options_destroy": (None, [ctypes.c_void_p], ('options',)),
    "dbs_options_set_int": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.c_int32], ('options', 'option', 'value')),
    "dbs_options_get_int": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_int32)], ('options', 'option', 'out')),
    "dbs_options_set_double": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.c_double], ('options', 'option', 'value')),
    "dbs_options_get_double": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double)], ('options', 'option', 'out')),
    "dbs_option_bounds": (ctypes.c_int, [ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)], ('option', 'out_min', 'out_max')),
    "dbs_options_set_progress": (ctypes.c_int, [ctypes.c_void_p, PROGRESS_FN, ctypes.c_void_p], ('options', 'fn', 'payload')),
    "dbs_options_set_level_callback": (ctypes.c_int, [ctypes.c_void_p, LEVEL_FN, ctypes.c_void_p], ('options', 'fn', 'payload')),
    "dbs_options_set_warning": (ctypes.c_int, [ctypes.c_void_p, WARNING_FN, ctypes.c_void_p], ('options', 'fn', 'payload')),
    "dbs_boundary_detect": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('cloud', 'options', 'out')),
    "dbs_boundary_from_corners": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_void_p)], ('cloud', 'corners_xyz', 'out')),
    "dbs_boundary_hole_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('boundary', 'out')),
    "dbs_boundary_hole_size": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_size_t)], ('boundary', 'hole', 'out')),
    "dbs_boundary_hole_points": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('boundary', 'hole', 'out_xyz', 'capacity')),
    "dbs_parameterize": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('cloud', 'boundary', 'options', 'out')),
    "dbs_result_destroy": (None, [ctypes.c_void_p], ('result',)),
    "dbs_result_point_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('result', 'out')),
    "dbs_result_uv": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('result', 'out_uv', 'capacity')),
    "dbs_result_distances": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('result', 'out', 'capacity')),
    "dbs_result_point_patches": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('result', 'out', 'capacity')),
    "dbs_result_point_levels": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('result', 'out', 'capacity')),
    "dbs_result_repaired": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('result', 'out', 'capacity')),
    "dbs_result_point_flags": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('result', 'out', 'capacity')),
    "dbs_result_evaluate": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)], ('result', 'u', 'v', 'out_xyz', 'out_normal')),
    "dbs_result_stat": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double)], ('result', 'stat', 'out')),
    "dbs_result_evaluate_many": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)], ('result', 'uv', 'n', 'out_xyz', 'out_normal', 'out_su', 'out_sv')),
    "dbs_result_patches": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('result', 'out')),
    "dbs_result_save": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p], ('result', 'cloud', 'path')),
    "dbs_patches_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('patches', 'out')),
    "dbs_patches_id": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out')),
    "dbs_patches_level": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out')),
    "dbs_patches_is_leaf": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out')),
    "dbs_patches_parent": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out')),
    "dbs_patches_rect": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_double)], ('patches', 'i', 'out_rect')),
    "dbs_patches_grid_size": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32), ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out_nu', 'out_nv')),
    "dbs_patches_grid_points": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('patches', 'i', 'out_xyz', 'capacity')),
    "dbs_patches_boundary_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int32, ctypes.POINTER(ctypes.c_size_t)], ('patches', 'i', 'side', 'out')),
    "dbs_patches_boundary_points": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('patches', 'i', 'side', 'out_xyz', 'capacity')),
    "dbs_patches_stats": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_size_t), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_int32)], ('patches', 'i', 'out_points', 'out_mean', 'out_max', 'out_iterations')),
    "dbs_patches_solver": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_int32), ctypes.POINTER(ctypes.c_size_t)], ('patches', 'i', 'out_solver', 'out_ceres_iterations')),
    "dbs_mesh_create": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p)], ('result', 'cloud', 'out')),
    "dbs_mesh_destroy": (None, [ctypes.c_void_p], ('mesh',)),
    "dbs_mesh_vertex_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('mesh', 'out')),
    "dbs_mesh_vertices": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('mesh', 'out_xyz', 'capacity')),
    "dbs_mesh_uv": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('mesh', 'out_uv', 'capacity')),
    "dbs_mesh_triangle_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('mesh', 'out')),
    "dbs_mesh_triangles": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('mesh', 'out', 'capacity')),
    "dbs_mesh_suspicious_count": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_size_t)], ('mesh', 'out')),
    "dbs_mesh_suspicious": (ctypes.c_int, [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t], ('mesh', 'out', 'capacity')),
    "dbs_mesh_save": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_char_p], ('mesh', 'path')),
    "dbs_mesh_distortion": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_void_p)], ('mesh', 'scaling', 'out')),
    "dbs_distortion_create": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_int32), ctypes.c_size_t, ctypes.c_int32, ctypes.POINTER(ctypes.c_void_p)], ('result', 'cloud', 'triangles', 'n_triangles', 'scaling', 'out')),
    "dbs_distortion_destroy": (None, [ctypes.c_void_p], ('distortion',)),
    "dbs_distortion_stat": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double)], ('distortion', 'stat', 'out')),
    "dbs_distortion_summary": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.c_int32, ctypes.POINTER(ctypes.c_double)], ('distortion', 'measure', 'summary', 'out')),
    "dbs_distortion_values": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.POINTER(ctypes.c_double), ctypes.c_size_t], ('distortion', 'measure', 'out', 'capacity')),
    "dbs_distances_create": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_double, ctypes.POINTER(ctypes.c_void_p)], ('result', 'tolerance', 'out')),
    "dbs_distances_destroy": (None, [ctypes.c_void_p], ('distances',)),
    "dbs_distances_stat": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_int32, ctypes.c_int32, ctypes.POINTER(ctypes.c_double)], ('distances', 'patch', 'stat', 'out')),
    "dbs_report_write": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p], ('result', 'cloud', 'options', 'dir')),
    "dbs_boundary_report_write": (ctypes.c_int, [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p], ('boundary', 'cloud', 'dir')),
}


def declare(library):
    """Sets restype and argtypes of every function of `library` (a ctypes.CDLL of libdbs):
    a function left with the default int return would truncate 64-bit pointers."""
    for name, (restype, argtypes, _names) in FUNCTIONS.items():
        function = getattr(library, name)
        function.restype = restype
        function.argtypes = argtypes
    return library
