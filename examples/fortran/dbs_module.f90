! Fortran 2003 bindings of libdbs: one bind(C) interface per function of dbs.h.
!
! The map from dbs.h is mechanical: int -> integer(c_int), int32_t -> integer(c_int32_t),
! size_t -> integer(c_size_t), double -> real(c_double), input scalars by `value`, arrays as
! assumed-size dummies, handles as type(c_ptr) (`value` when passed in, plain when the C side
! writes them through a pointer), strings as NUL-terminated character arrays (dbs_c_string)
! and returned C strings converted with dbs_f_string. Every function returns the C status
! (DBS_OK = 0); dbs_last_error_message() tells what failed.
module dbs
  use, intrinsic :: iso_c_binding
  implicit none

  ! ---- version ----------------------------------------------------------------------
  integer(c_int32_t), parameter :: DBS_VERSION_MAJOR = 0, DBS_VERSION_MINOR = 4, DBS_VERSION_PATCH = 0
  integer(c_int32_t), parameter :: DBS_FEATURE_DRACO = 0
  integer(c_int32_t), parameter :: DBS_FEATURE_VALIDATION = 1
  integer(c_int32_t), parameter :: DBS_FEATURE_REPORT = 2
  integer(c_int32_t), parameter :: DBS_FEATURE_CERES = 3

  ! ---- status codes (pinned) ---------------------------------------------------------
  integer(c_int), parameter :: DBS_OK = 0
  integer(c_int), parameter :: DBS_ERR_NULL_ARGUMENT = -1, DBS_ERR_INVALID_ARGUMENT = -2
  integer(c_int), parameter :: DBS_ERR_OUT_OF_RANGE = -3, DBS_ERR_NON_FINITE = -4, DBS_ERR_EMPTY = -5
  integer(c_int), parameter :: DBS_ERR_DEGENERATE = -6, DBS_ERR_IO = -7, DBS_ERR_PARSE = -8
  integer(c_int), parameter :: DBS_ERR_UNSUPPORTED = -9, DBS_ERR_CANCELLED = -10, DBS_ERR_NO_MEMORY = -11
  integer(c_int), parameter :: DBS_ERR_BUFFER_TOO_SMALL = -12, DBS_ERR_NUMERICAL = -13, DBS_ERR_INTERNAL = -99

  ! ---- boundary sides ----------------------------------------------------------------
  integer(c_int32_t), parameter :: DBS_SIDE_BOTTOM = 0, DBS_SIDE_RIGHT = 1, DBS_SIDE_TOP = 2, DBS_SIDE_LEFT = 3

  ! ---- option ids and solvers ----------------------------------------------------------
  integer(c_int32_t), parameter :: DBS_OPT_ACCURACY = 0, DBS_OPT_RELATIVE_ACCURACY = 1, DBS_OPT_MAX_LEVEL = 2
  integer(c_int32_t), parameter :: DBS_OPT_INITIAL_GRID = 3, DBS_OPT_MAX_GRID = 4, DBS_OPT_SMOOTHING = 5
  integer(c_int32_t), parameter :: DBS_OPT_SOLVER = 6, DBS_OPT_THREADS = 7
  integer(c_int32_t), parameter :: DBS_OPT_SUBCLOUD_NEAR = 8, DBS_OPT_SUBCLOUD_OWN = 9
  integer(c_int32_t), parameter :: DBS_OPT_NOISE_FLOOR = 10
  integer(c_int32_t), parameter :: DBS_OPT_REPAIR = 11
  integer(c_int32_t), parameter :: DBS_OPT_LOSS = 12, DBS_OPT_LOSS_SCALE = 13
  integer(c_int32_t), parameter :: DBS_OPT_CERES_MAX_ITERATIONS = 14, DBS_OPT_CERES_FUNCTION_TOLERANCE = 15
  integer(c_int32_t), parameter :: DBS_OPT_OUTLINE_NEIGHBOURS = 16
  integer(c_int32_t), parameter :: DBS_SOLVER_LINEAR = 0, DBS_SOLVER_CERES = 1
  integer(c_int32_t), parameter :: DBS_LOSS_NONE = 0, DBS_LOSS_HUBER = 1, DBS_LOSS_CAUCHY = 2, DBS_LOSS_SOFT_L1 = 3

  ! ---- result statistics ---------------------------------------------------------------
  integer(c_int32_t), parameter :: DBS_STAT_MEAN_DISTANCE = 0, DBS_STAT_MAX_DISTANCE = 1, DBS_STAT_RMS_DISTANCE = 2
  integer(c_int32_t), parameter :: DBS_STAT_ACCURACY = 3, DBS_STAT_ACCURACY_MET = 4, DBS_STAT_LEVELS = 5
  integer(c_int32_t), parameter :: DBS_STAT_PATCHES = 6, DBS_STAT_LEAVES = 7, DBS_STAT_ITERATIONS = 8
  integer(c_int32_t), parameter :: DBS_STAT_SECONDS = 9, DBS_STAT_LENGTH_SCALE = 10
  integer(c_int32_t), parameter :: DBS_STAT_SECONDS_INDEX = 11, DBS_STAT_SECONDS_EVOLVE = 12
  integer(c_int32_t), parameter :: DBS_STAT_SECONDS_SUBDIVIDE = 13, DBS_STAT_SECONDS_PARAMETERIZE = 14
  integer(c_int32_t), parameter :: DBS_STAT_SECONDS_FOLDS = 15, DBS_STAT_REQUESTED_ACCURACY = 16
  integer(c_int32_t), parameter :: DBS_STAT_REQUESTED_MET = 17, DBS_STAT_NOISE = 18
  integer(c_int32_t), parameter :: DBS_STAT_FOLDED_SHARE = 19, DBS_STAT_FOLDED_POINTS = 20
  integer(c_int32_t), parameter :: DBS_STAT_UNDECIDED_POINTS = 21, DBS_STAT_COINCIDENT_POINTS = 22
  integer(c_int32_t), parameter :: DBS_STAT_JUDGED_POINTS = 23
  integer(c_int32_t), parameter :: DBS_STAT_REPAIRED_POINTS = 24
  integer(c_int32_t), parameter :: DBS_STAT_SOLVER = 25, DBS_STAT_CERES_ITERATIONS = 26, DBS_STAT_LOSS_SCALE = 27
  integer(c_int32_t), parameter :: DBS_STAT_COLLAPSED_POINTS = 28
  integer(c_int32_t), parameter :: DBS_STAT_BOUNDARY_GAP = 29, DBS_STAT_SCALE_RATIO = 30
  integer(c_int32_t), parameter :: DBS_STAT_COVERAGE = 31, DBS_STAT_CLAMPED_POINTS = 32
  integer(c_int32_t), parameter :: DBS_STAT_FAR_POINTS = 33

  ! ---- validation: meshes, distortion, distances ----------------------------------------
  real(c_double), parameter :: DBS_MESH_SUSPICIOUS_FACTOR = 4.0_c_double
  integer(c_int32_t), parameter :: DBS_SCALING_UNIFORM = 0, DBS_SCALING_PER_AXIS = 1
  integer(c_int32_t), parameter :: DBS_MEASURE_CONFORMAL = 0, DBS_MEASURE_AREA = 1, DBS_MEASURE_STRETCH_L2 = 2
  integer(c_int32_t), parameter :: DBS_MEASURE_STRETCH_LINF = 3, DBS_MEASURE_EDGE_DIFFERENCE = 4
  integer(c_int32_t), parameter :: DBS_MEASURE_SIGMA1 = 5, DBS_MEASURE_SIGMA2 = 6
  integer(c_int32_t), parameter :: DBS_MEASURE_FOLDED = 7, DBS_MEASURE_DEGENERATE = 8
  integer(c_int32_t), parameter :: DBS_SUMMARY_MIN = 0, DBS_SUMMARY_MEAN = 1, DBS_SUMMARY_P95 = 2, DBS_SUMMARY_MAX = 3
  integer(c_int32_t), parameter :: DBS_DISTORTION_TRIANGLES = 0, DBS_DISTORTION_DEGENERATE = 1
  integer(c_int32_t), parameter :: DBS_DISTORTION_FOLDED = 2, DBS_DISTORTION_SCALE_U = 3
  integer(c_int32_t), parameter :: DBS_DISTORTION_SCALE_V = 4, DBS_DISTORTION_MESH_STRETCH_L2 = 5
  integer(c_int32_t), parameter :: DBS_DISTANCES_COUNT = 0, DBS_DISTANCES_MEAN = 1, DBS_DISTANCES_RMS = 2
  integer(c_int32_t), parameter :: DBS_DISTANCES_MAX = 3, DBS_DISTANCES_P50 = 4, DBS_DISTANCES_P90 = 5
  integer(c_int32_t), parameter :: DBS_DISTANCES_P95 = 6, DBS_DISTANCES_P99 = 7
  integer(c_int32_t), parameter :: DBS_DISTANCES_WITHIN = 8, DBS_DISTANCES_TOLERANCE = 9

  interface
    ! ---- version and errors ----------------------------------------------------------
    function dbs_version_number() bind(C, name="dbs_version_number")
      import :: c_int32_t
      integer(c_int32_t) :: dbs_version_number
    end function
    function dbs_version_string() bind(C, name="dbs_version_string")
      import :: c_ptr
      type(c_ptr) :: dbs_version_string
    end function
    function dbs_has_feature(feature, out) bind(C, name="dbs_has_feature")
      import :: c_int, c_int32_t
      integer(c_int32_t), value :: feature
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_has_feature
    end function
    function dbs_status_string(status) bind(C, name="dbs_status_string")
      import :: c_ptr, c_int
      integer(c_int), value :: status
      type(c_ptr) :: dbs_status_string
    end function
    function dbs_last_error_message() bind(C, name="dbs_last_error_message")
      import :: c_ptr
      type(c_ptr) :: dbs_last_error_message
    end function

    ! ---- point clouds ------------------------------------------------------------------
    function dbs_cloud_create(xyz, count, out) bind(C, name="dbs_cloud_create")
      import :: c_int, c_double, c_size_t, c_ptr
      real(c_double), intent(in) :: xyz(*)
      integer(c_size_t), value :: count
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_cloud_create
    end function
    function dbs_cloud_load(path, out) bind(C, name="dbs_cloud_load")
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_cloud_load
    end function
    function dbs_cloud_load_with_options(path, options, out) bind(C, name="dbs_cloud_load_with_options")
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), value :: options
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_cloud_load_with_options
    end function
    subroutine dbs_cloud_destroy(cloud) bind(C, name="dbs_cloud_destroy")
      import :: c_ptr
      type(c_ptr), value :: cloud
    end subroutine
    function dbs_cloud_count(cloud, out) bind(C, name="dbs_cloud_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: cloud
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_cloud_count
    end function
    function dbs_cloud_bounds(cloud, out_min, out_max) bind(C, name="dbs_cloud_bounds")
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: cloud
      real(c_double), intent(out) :: out_min(3), out_max(3)
      integer(c_int) :: dbs_cloud_bounds
    end function
    function dbs_cloud_points(cloud, out_xyz, capacity) bind(C, name="dbs_cloud_points")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: cloud
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_cloud_points
    end function

    ! ---- boundaries --------------------------------------------------------------------
    function dbs_boundary_create(bottom, n_bottom, right, n_right, top, n_top, left, n_left, out) &
        bind(C, name="dbs_boundary_create")
      import :: c_int, c_double, c_size_t, c_ptr
      real(c_double), intent(in) :: bottom(*), right(*), top(*), left(*)
      integer(c_size_t), value :: n_bottom, n_right, n_top, n_left
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_create
    end function
    function dbs_boundary_create_tolerant(bottom, n_bottom, right, n_right, top, n_top, left, n_left, &
        tolerance, relative, out_max_snap, out) bind(C, name="dbs_boundary_create_tolerant")
      import :: c_int, c_int32_t, c_double, c_size_t, c_ptr
      real(c_double), intent(in) :: bottom(*), right(*), top(*), left(*)
      integer(c_size_t), value :: n_bottom, n_right, n_top, n_left
      real(c_double), value :: tolerance
      integer(c_int32_t), value :: relative
      real(c_double), intent(out) :: out_max_snap
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_create_tolerant
    end function
    function dbs_boundary_load_tolerant(path, tolerance, relative, out_max_snap, out) &
        bind(C, name="dbs_boundary_load_tolerant")
      import :: c_int, c_int32_t, c_char, c_double, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      real(c_double), value :: tolerance
      integer(c_int32_t), value :: relative
      real(c_double), intent(out) :: out_max_snap
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_load_tolerant
    end function
    function dbs_boundary_from_loop(xyz, n, corners, out) bind(C, name="dbs_boundary_from_loop")
      import :: c_int, c_double, c_size_t, c_ptr
      real(c_double), intent(in) :: xyz(*)
      integer(c_size_t), value :: n
      integer(c_size_t), intent(in) :: corners(4)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_from_loop
    end function
    function dbs_boundary_load(path, out) bind(C, name="dbs_boundary_load")
      import :: c_int, c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_load
    end function
    function dbs_boundary_save(boundary, path) bind(C, name="dbs_boundary_save")
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: boundary
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: dbs_boundary_save
    end function
    subroutine dbs_boundary_destroy(boundary) bind(C, name="dbs_boundary_destroy")
      import :: c_ptr
      type(c_ptr), value :: boundary
    end subroutine
    function dbs_boundary_side_count(boundary, side, out) bind(C, name="dbs_boundary_side_count")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: boundary
      integer(c_int32_t), value :: side
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_boundary_side_count
    end function
    function dbs_boundary_side_points(boundary, side, out_xyz, capacity) bind(C, name="dbs_boundary_side_points")
      import :: c_int, c_int32_t, c_double, c_size_t, c_ptr
      type(c_ptr), value :: boundary
      integer(c_int32_t), value :: side
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_boundary_side_points
    end function

    ! ---- options -----------------------------------------------------------------------
    function dbs_options_create(out) bind(C, name="dbs_options_create")
      import :: c_int, c_ptr
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_options_create
    end function
    function dbs_options_clone(options, out) bind(C, name="dbs_options_clone")
      import :: c_int, c_ptr
      type(c_ptr), value :: options
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_options_clone
    end function
    subroutine dbs_options_destroy(options) bind(C, name="dbs_options_destroy")
      import :: c_ptr
      type(c_ptr), value :: options
    end subroutine
    function dbs_options_set_int(options, option, value) bind(C, name="dbs_options_set_int")
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: options
      integer(c_int32_t), value :: option, value
      integer(c_int) :: dbs_options_set_int
    end function
    function dbs_options_get_int(options, option, out) bind(C, name="dbs_options_get_int")
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: options
      integer(c_int32_t), value :: option
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_options_get_int
    end function
    function dbs_options_set_double(options, option, value) bind(C, name="dbs_options_set_double")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: options
      integer(c_int32_t), value :: option
      real(c_double), value :: value
      integer(c_int) :: dbs_options_set_double
    end function
    function dbs_options_get_double(options, option, out) bind(C, name="dbs_options_get_double")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: options
      integer(c_int32_t), value :: option
      real(c_double), intent(out) :: out
      integer(c_int) :: dbs_options_get_double
    end function
    function dbs_option_bounds(option, out_min, out_max) bind(C, name="dbs_option_bounds")
      import :: c_int, c_int32_t, c_double
      integer(c_int32_t), value :: option
      real(c_double), intent(out) :: out_min, out_max
      integer(c_int) :: dbs_option_bounds
    end function
    ! fn: c_funloc of a bind(C) function
    !   integer(c_int) function f(fraction, stage, payload): real(c_double), value; type(c_ptr), value (x2)
    ! or c_null_funptr to clear.
    function dbs_options_set_progress(options, fn, payload) bind(C, name="dbs_options_set_progress")
      import :: c_int, c_ptr, c_funptr
      type(c_ptr), value :: options
      type(c_funptr), value :: fn
      type(c_ptr), value :: payload
      integer(c_int) :: dbs_options_set_progress
    end function
    ! fn: c_funloc of a bind(C) function
    !   integer(c_int) function f(level, patches, payload): integer(c_int32_t), value; type(c_ptr), value (x2)
    function dbs_options_set_level_callback(options, fn, payload) bind(C, name="dbs_options_set_level_callback")
      import :: c_int, c_ptr, c_funptr
      type(c_ptr), value :: options
      type(c_funptr), value :: fn
      type(c_ptr), value :: payload
      integer(c_int) :: dbs_options_set_level_callback
    end function
    function dbs_options_set_warning(options, fn, payload) bind(C, name="dbs_options_set_warning")
      import :: c_int, c_ptr, c_funptr
      type(c_ptr), value :: options
      type(c_funptr), value :: fn
      type(c_ptr), value :: payload
      integer(c_int) :: dbs_options_set_warning
    end function

    ! ---- boundaries from the cloud itself ------------------------------------------------
    ! options may be c_null_ptr for the defaults.
    function dbs_boundary_detect(cloud, options, out) bind(C, name="dbs_boundary_detect")
      import :: c_int, c_ptr
      type(c_ptr), value :: cloud, options
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_detect
    end function
    function dbs_boundary_from_corners(cloud, corners_xyz, out) bind(C, name="dbs_boundary_from_corners")
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: cloud
      real(c_double), intent(in) :: corners_xyz(12)
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_boundary_from_corners
    end function
    function dbs_boundary_hole_count(boundary, out) bind(C, name="dbs_boundary_hole_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: boundary
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_boundary_hole_count
    end function
    function dbs_boundary_hole_size(boundary, hole, out) bind(C, name="dbs_boundary_hole_size")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: boundary
      integer(c_size_t), value :: hole
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_boundary_hole_size
    end function
    function dbs_boundary_hole_points(boundary, hole, out_xyz, capacity) bind(C, name="dbs_boundary_hole_points")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: boundary
      integer(c_size_t), value :: hole
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_boundary_hole_points
    end function

    ! ---- parameterization ----------------------------------------------------------------
    ! options may be c_null_ptr for the defaults.
    function dbs_parameterize(cloud, boundary, options, out) bind(C, name="dbs_parameterize")
      import :: c_int, c_ptr
      type(c_ptr), value :: cloud, boundary, options
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_parameterize
    end function
    subroutine dbs_result_destroy(result) bind(C, name="dbs_result_destroy")
      import :: c_ptr
      type(c_ptr), value :: result
    end subroutine
    function dbs_result_point_count(result, out) bind(C, name="dbs_result_point_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: result
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_result_point_count
    end function
    function dbs_result_uv(result, out_uv, capacity) bind(C, name="dbs_result_uv")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: result
      real(c_double), intent(out) :: out_uv(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_result_uv
    end function
    function dbs_result_distances(result, out, capacity) bind(C, name="dbs_result_distances")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: result
      real(c_double), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_result_distances
    end function
    function dbs_result_point_patches(result, out, capacity) bind(C, name="dbs_result_point_patches")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: result
      integer(c_int32_t), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_result_point_patches
    end function
    function dbs_result_point_levels(result, out, capacity) bind(C, name="dbs_result_point_levels")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: result
      integer(c_int32_t), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_result_point_levels
    end function
    function dbs_result_repaired(result, out, capacity) bind(C, name="dbs_result_repaired")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: result
      integer(c_int32_t), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_result_repaired
    end function
    ! out_normal is optional: left out, the C side receives NULL.
    function dbs_result_evaluate(result, u, v, out_xyz, out_normal) bind(C, name="dbs_result_evaluate")
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: result
      real(c_double), value :: u, v
      real(c_double), intent(out) :: out_xyz(3)
      real(c_double), intent(out), optional :: out_normal(3)
      integer(c_int) :: dbs_result_evaluate
    end function
    function dbs_result_stat(result, stat, out) bind(C, name="dbs_result_stat")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: result
      integer(c_int32_t), value :: stat
      real(c_double), intent(out) :: out
      integer(c_int) :: dbs_result_stat
    end function
    function dbs_result_patches(result, out) bind(C, name="dbs_result_patches")
      import :: c_int, c_ptr
      type(c_ptr), value :: result
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_result_patches
    end function
    function dbs_result_save(result, cloud, path) bind(C, name="dbs_result_save")
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: result, cloud
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: dbs_result_save
    end function

    ! ---- patches (i is the 0-based index into the view) ------------------------------------
    function dbs_patches_count(patches, out) bind(C, name="dbs_patches_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_patches_count
    end function
    function dbs_patches_id(patches, i, out) bind(C, name="dbs_patches_id")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_patches_id
    end function
    function dbs_patches_level(patches, i, out) bind(C, name="dbs_patches_level")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_patches_level
    end function
    function dbs_patches_is_leaf(patches, i, out) bind(C, name="dbs_patches_is_leaf")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_patches_is_leaf
    end function
    function dbs_patches_parent(patches, i, out) bind(C, name="dbs_patches_parent")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out
      integer(c_int) :: dbs_patches_parent
    end function
    function dbs_patches_rect(patches, i, out_rect) bind(C, name="dbs_patches_rect")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      real(c_double), intent(out) :: out_rect(4)
      integer(c_int) :: dbs_patches_rect
    end function
    function dbs_patches_grid_size(patches, i, out_nu, out_nv) bind(C, name="dbs_patches_grid_size")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out_nu, out_nv
      integer(c_int) :: dbs_patches_grid_size
    end function
    function dbs_patches_grid_points(patches, i, out_xyz, capacity) bind(C, name="dbs_patches_grid_points")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_patches_grid_points
    end function
    function dbs_patches_boundary_count(patches, i, side, out) bind(C, name="dbs_patches_boundary_count")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), value :: side
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_patches_boundary_count
    end function
    function dbs_patches_boundary_points(patches, i, side, out_xyz, capacity) bind(C, name="dbs_patches_boundary_points")
      import :: c_int, c_int32_t, c_double, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), value :: side
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_patches_boundary_points
    end function
    function dbs_patches_stats(patches, i, out_points, out_mean, out_max, out_iterations) bind(C, name="dbs_patches_stats")
      import :: c_int, c_int32_t, c_double, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_size_t), intent(out) :: out_points
      real(c_double), intent(out) :: out_mean, out_max
      integer(c_int32_t), intent(out) :: out_iterations
      integer(c_int) :: dbs_patches_stats
    end function
    function dbs_patches_solver(patches, i, out_solver, out_ceres_iterations) bind(C, name="dbs_patches_solver")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: patches
      integer(c_size_t), value :: i
      integer(c_int32_t), intent(out) :: out_solver
      integer(c_size_t), intent(out) :: out_ceres_iterations
      integer(c_int) :: dbs_patches_solver
    end function

    ! ---- validation ----------------------------------------------------------------------
    function dbs_mesh_create(result, cloud, out) bind(C, name="dbs_mesh_create")
      import :: c_int, c_ptr
      type(c_ptr), value :: result, cloud
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_mesh_create
    end function
    subroutine dbs_mesh_destroy(mesh) bind(C, name="dbs_mesh_destroy")
      import :: c_ptr
      type(c_ptr), value :: mesh
    end subroutine
    function dbs_mesh_vertex_count(mesh, out) bind(C, name="dbs_mesh_vertex_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_mesh_vertex_count
    end function
    function dbs_mesh_vertices(mesh, out_xyz, capacity) bind(C, name="dbs_mesh_vertices")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      real(c_double), intent(out) :: out_xyz(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_mesh_vertices
    end function
    function dbs_mesh_uv(mesh, out_uv, capacity) bind(C, name="dbs_mesh_uv")
      import :: c_int, c_double, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      real(c_double), intent(out) :: out_uv(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_mesh_uv
    end function
    function dbs_mesh_triangle_count(mesh, out) bind(C, name="dbs_mesh_triangle_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_mesh_triangle_count
    end function
    ! 0-based vertex indices, 3 per triangle
    function dbs_mesh_triangles(mesh, out, capacity) bind(C, name="dbs_mesh_triangles")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_int32_t), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_mesh_triangles
    end function
    function dbs_mesh_suspicious_count(mesh, out) bind(C, name="dbs_mesh_suspicious_count")
      import :: c_int, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_size_t), intent(out) :: out
      integer(c_int) :: dbs_mesh_suspicious_count
    end function
    function dbs_mesh_suspicious(mesh, out, capacity) bind(C, name="dbs_mesh_suspicious")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_int32_t), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_mesh_suspicious
    end function
    function dbs_mesh_save(mesh, path) bind(C, name="dbs_mesh_save")
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: mesh
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: dbs_mesh_save
    end function
    function dbs_mesh_distortion(mesh, scaling, out) bind(C, name="dbs_mesh_distortion")
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: mesh
      integer(c_int32_t), value :: scaling
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_mesh_distortion
    end function
    ! triangles: 0-based cloud indices, 3 per triangle
    function dbs_distortion_create(result, cloud, triangles, n_triangles, scaling, out) bind(C, name="dbs_distortion_create")
      import :: c_int, c_int32_t, c_size_t, c_ptr
      type(c_ptr), value :: result, cloud
      integer(c_int32_t), intent(in) :: triangles(*)
      integer(c_size_t), value :: n_triangles
      integer(c_int32_t), value :: scaling
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_distortion_create
    end function
    subroutine dbs_distortion_destroy(distortion) bind(C, name="dbs_distortion_destroy")
      import :: c_ptr
      type(c_ptr), value :: distortion
    end subroutine
    function dbs_distortion_stat(distortion, stat, out) bind(C, name="dbs_distortion_stat")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: distortion
      integer(c_int32_t), value :: stat
      real(c_double), intent(out) :: out
      integer(c_int) :: dbs_distortion_stat
    end function
    function dbs_distortion_summary(distortion, measure, summary, out) bind(C, name="dbs_distortion_summary")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: distortion
      integer(c_int32_t), value :: measure, summary
      real(c_double), intent(out) :: out
      integer(c_int) :: dbs_distortion_summary
    end function
    function dbs_distortion_values(distortion, measure, out, capacity) bind(C, name="dbs_distortion_values")
      import :: c_int, c_int32_t, c_double, c_size_t, c_ptr
      type(c_ptr), value :: distortion
      integer(c_int32_t), value :: measure
      real(c_double), intent(out) :: out(*)
      integer(c_size_t), value :: capacity
      integer(c_int) :: dbs_distortion_values
    end function
    function dbs_distances_create(result, tolerance, out) bind(C, name="dbs_distances_create")
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: result
      real(c_double), value :: tolerance
      type(c_ptr), intent(out) :: out
      integer(c_int) :: dbs_distances_create
    end function
    subroutine dbs_distances_destroy(distances) bind(C, name="dbs_distances_destroy")
      import :: c_ptr
      type(c_ptr), value :: distances
    end subroutine
    ! patch = -1 for all points
    function dbs_distances_stat(distances, patch, stat, out) bind(C, name="dbs_distances_stat")
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: distances
      integer(c_int32_t), value :: patch, stat
      real(c_double), intent(out) :: out
      integer(c_int) :: dbs_distances_stat
    end function
    ! options may be c_null_ptr for the defaults
    function dbs_report_write(result, cloud, options, dir) bind(C, name="dbs_report_write")
      import :: c_int, c_char, c_ptr
      type(c_ptr), value :: result, cloud, options
      character(kind=c_char), intent(in) :: dir(*)
      integer(c_int) :: dbs_report_write
    end function
  end interface

contains

  !> A Fortran string as a NUL-terminated C string, for path arguments.
  function dbs_c_string(text) result(c_text)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=len_trim(text) + 1) :: c_text
    c_text = trim(text) // c_null_char
  end function

  !> Copies a C string owned by the library (dbs_version_string, dbs_status_string,
  !> dbs_last_error_message) into a Fortran string; "" for a null pointer.
  function dbs_f_string(c_text) result(text)
    type(c_ptr), intent(in) :: c_text
    character(len=:), allocatable :: text
    character(kind=c_char), pointer :: chars(:)
    integer(c_size_t) :: n, i
    interface
      function c_strlen(s) bind(C, name="strlen")
        import :: c_ptr, c_size_t
        type(c_ptr), value :: s
        integer(c_size_t) :: c_strlen
      end function
    end interface
    if (.not. c_associated(c_text)) then
      text = ""
      return
    end if
    n = c_strlen(c_text)
    call c_f_pointer(c_text, chars, [n])
    allocate(character(len=n) :: text)
    do i = 1, n
      text(i:i) = chars(i)
    end do
  end function

  !> The message of the last failed call on this thread.
  function dbs_error_text() result(text)
    character(len=:), allocatable :: text
    text = dbs_f_string(dbs_last_error_message())
  end function

end module dbs
