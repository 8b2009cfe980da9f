/*
 * dbs.h -- the C interface of libdbs, point-cloud parameterization with
 * recursive dynamic base surfaces.
 *
 * Conventions (read these once; every function follows them):
 *
 *  - Every function that can fail returns an `int` status: DBS_OK (0) on success,
 *    one of the pinned negative DBS_ERR_* codes otherwise. On failure the output
 *    arguments are left untouched and a message naming the argument, file position
 *    or value at fault is available from dbs_last_error_message() on the same thread.
 *  - Output arguments come last and are named `out` (or `out_*`).
 *  - Handles are opaque. Every *_create / *_load has one *_destroy that accepts NULL.
 *    Input handles are never modified by a function that takes them as `const`.
 *  - Arrays of 3D points are flat `double` arrays x0 y0 z0 x1 y1 z1 ..., with the
 *    number of *points* (not doubles) passed beside them. Buffers filled by the library
 *    come with the capacity of the caller's buffer in the same unit; a too-small buffer
 *    is an error (DBS_ERR_BUFFER_TOO_SMALL), never a silent truncation.
 *  - Callbacks receive the caller's `payload` as their last argument. A callback
 *    returning non-zero cancels the operation: the function returns DBS_ERR_CANCELLED,
 *    frees everything it allocated and produces no result handle.
 *  - No exception, C++ type or abort() crosses this interface. The library holds no
 *    global mutable state except the per-thread last-error message.
 *  - Only fixed-width integers, double, size_t, pointers and handles appear in
 *    prototypes (no bool, no struct by value), so Fortran (bind(C)) and Python
 *    (ctypes) bindings are mechanical. Every prototype sits on one line.
 *  - Lengths and distances are in cloud units (the unit of the input coordinates),
 *    times in seconds of wall-clock time, counts are whole numbers (returned as double
 *    by the *_stat functions), ratios and shares are plain numbers.
 *  - File formats (point clouds, boundary files, result files, the dbs-param command
 *    line) are described in docs/FORMATS.md, installed as share/doc/dbs/FORMATS.md.
 *
 * Statuses:
 *
 *  - Each function's comment lists, after "Returns", the statuses it can give besides
 *    DBS_OK. Two more are possible from every function that returns a status and are
 *    listed only where they are expected: DBS_ERR_NO_MEMORY (an allocation failed; even
 *    the message of a failed argument check is allocated) and DBS_ERR_INTERNAL (a bug in
 *    libdbs; its message starts with "internal error:"; please report it).
 *  - The message of dbs_last_error_message() is one line of English, "function: what is
 *    wrong", naming the argument, file and line, index or value at fault.
 *  - Inside a run (the work dbs_parameterize does once its arguments passed their checks)
 *    the only statuses are DBS_ERR_NO_MEMORY, DBS_ERR_CANCELLED, DBS_ERR_NUMERICAL, the
 *    input-check statuses documented for the function (DBS_ERR_DEGENERATE for a cloud or
 *    boundary found unusable) and DBS_ERR_INTERNAL, only for bugs: never
 *    DBS_ERR_INVALID_ARGUMENT or DBS_ERR_OUT_OF_RANGE for arguments that passed the checks.
 *    The same holds for the computations of dbs_mesh_create, dbs_distortion_create,
 *    dbs_mesh_distortion and dbs_report_write.
 *
 * Threads:
 *
 *  - Any number of threads may call libdbs at once on different handles.
 *  - A handle may be shared by any number of threads for simultaneous calls that take it
 *    as `const` (cloud, boundary, options, result, patches view, mesh, distortion,
 *    distances): such calls never modify it, not even a cache. For example several threads
 *    may run dbs_parameterize on the same cloud, boundary and options at once; each gets
 *    the result a lone call gives, bit for bit.
 *  - Calls that must not race (the caller synchronizes): a call taking a handle non-const
 *    (dbs_options_set_int, dbs_options_set_double, dbs_options_set_progress,
 *    dbs_options_set_level_callback, dbs_options_set_warning) must not run while any other call uses the same handle
 *    (a dbs_parameterize or dbs_report_write reading those options included), and a
 *    *_destroy must not run while any other call uses that handle or a view borrowed from
 *    it (the dbs_patches of dbs_result_patches).
 *  - libdbs starts worker threads (std::thread) inside a call and joins them before the
 *    call returns: no thread outlives a call and no pool is kept. dbs_parameterize uses up
 *    to DBS_OPT_THREADS at a time (0 = all hardware threads); with DBS_OPT_THREADS = 1 it
 *    starts none and runs on the calling thread. dbs_report_write uses the thread count of
 *    its options; dbs_mesh_create and dbs_distortion_create use all hardware threads.
 *    Results never depend on the thread count.
 *  - A worker thread that cannot be started (std::system_error, e.g. at the process's
 *    thread limit) is not an error (since 0.3): its share of the work runs on the calling
 *    thread, with the same result, only more slowly. (0.2 failed the call with
 *    DBS_ERR_INTERNAL, or terminated the process when other workers were running.)
 *
 * Lifetimes:
 *
 *  - A handle lives until its *_destroy. No pointer to a caller's array, string or handle
 *    is kept after a call returns: inputs are copied. A result does not refer to the cloud,
 *    boundary or options it was made from, nor a mesh, distortion or distances handle to
 *    its result or cloud, so either may be destroyed first.
 *  - The dbs_patches view of dbs_result_patches belongs to the result and is valid while
 *    the result lives. The `patches` view passed to the level callback and the `stage`
 *    string passed to the progress callback are valid only during that call.
 *  - The string of dbs_last_error_message() is valid until the next libdbs call on the same
 *    thread (and not after the thread ends). dbs_version_string() and dbs_status_string()
 *    return static strings, valid for ever.
 *
 * Callbacks (progress and level, set in the options):
 *
 *  - They are called on the thread that called dbs_parameterize(), never from a worker
 *    thread, and while none of that call's workers is running, so they need no locking of
 *    their own. Options shared by several threads call the same callback with the same
 *    payload from each of those threads at once: then the payload needs locking.
 *  - A callback may call any libdbs function: read the view it was given (dbs_patches_*),
 *    query any handle, even run another dbs_parameterize. dbs_parameterize reads its
 *    options (values and callbacks) once when it starts, so changing them from a callback
 *    affects only later calls. A callback must not destroy the cloud or the boundary of
 *    the running call. A libdbs call failing inside a callback sets this thread's last
 *    error message; a failure of the run replaces it.
 *  - A callback must return normally: no longjmp out of it and no C++ exception through
 *    libdbs (both skip its clean-up). To stop a run, return non-zero.
 *
 * Versions: every function and macro group carries "\since 0.N", the version that added
 * it; NEWS.md lists the additions of each version. Before calling a function newer than
 * the oldest library you accept, check DBS_AT_LEAST_VERSION when compiling and
 * dbs_version_number() when running.
 *
 * Parameter domain: S(u,v), u,v in [0,1]; S(u,0) = bottom, S(u,1) = top,
 * S(0,v) = left, S(1,v) = right. Bottom and top run in increasing u, left and right
 * in increasing v, and the four corners are shared.
 */
#ifndef DBS_H
#define DBS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- export ------------------------------------------------------------------- */
#if defined(DBS_STATIC)
#define DBS_API
#elif defined(_WIN32)
#if defined(DBS_BUILDING)
#define DBS_API __declspec(dllexport)
#else
#define DBS_API __declspec(dllimport)
#endif
#elif defined(__GNUC__)
#define DBS_API __attribute__((visibility("default")))
#else
#define DBS_API
#endif

/* ---- version ------------------------------------------------------------------ */
/* Version of this header (\since 0.1). */
#define DBS_VERSION_MAJOR 0
#define DBS_VERSION_MINOR 4
#define DBS_VERSION_PATCH 0
/** MAJOR*10000 + MINOR*100 + PATCH */
#define DBS_VERSION_NUMBER (DBS_VERSION_MAJOR * 10000 + DBS_VERSION_MINOR * 100 + DBS_VERSION_PATCH)
/** Non-zero when the header is at least version maj.min.pat. */
#define DBS_AT_LEAST_VERSION(maj, min, pat) (DBS_VERSION_NUMBER >= ((maj) * 10000 + (min) * 100 + (pat)))

/** Version of the library actually loaded, as DBS_VERSION_NUMBER. Cannot fail.
 *  \since 0.1 */
DBS_API int32_t dbs_version_number(void);
/** Version of the library actually loaded, "MAJOR.MINOR.PATCH"; static storage, never
 *  NULL. Cannot fail. \since 0.1 */
DBS_API const char *dbs_version_string(void);

/* Optional parts of the loaded library (pinned ids) for dbs_has_feature (\since 0.1,
 * except where marked). */
#define DBS_FEATURE_DRACO 0      /* Draco: clouds from .drc (dbs_cloud_load) and results to .drc (dbs_result_save); before 0.4 also .ply and .obj clouds, which libdbs now reads itself in every build */
#define DBS_FEATURE_VALIDATION 1 /* \since 0.2: dbs_mesh_*, dbs_distortion_*, dbs_distances_* (Qhull) */
#define DBS_FEATURE_REPORT 2     /* \since 0.2: dbs_report_write and the textured .obj of dbs_mesh_save (libpng) */
#define DBS_FEATURE_CERES 3      /* \since 0.4: the Ceres solver, DBS_SOLVER_CERES (Ceres) */
/** Sets *out to 1 when the loaded library was built with `feature` (DBS_FEATURE_*), else 0;
 *  DBS_ERR_OUT_OF_RANGE for an id not listed. Without a feature, the calls that need it
 *  fail with DBS_ERR_UNSUPPORTED.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_has_feature(int32_t feature, int32_t *out);

/* ---- status codes (pinned: never renumbered; \since 0.1) ------------------------- */
#define DBS_OK 0
#define DBS_ERR_NULL_ARGUMENT -1     /* a required pointer argument is NULL */
#define DBS_ERR_INVALID_ARGUMENT -2  /* an argument is malformed (wrong size, unknown id, ...) */
#define DBS_ERR_OUT_OF_RANGE -3      /* a value or index lies outside its documented range */
#define DBS_ERR_NON_FINITE -4        /* a coordinate or value is NaN or infinite */
#define DBS_ERR_EMPTY -5             /* no points where some are required */
#define DBS_ERR_DEGENERATE -6        /* degenerate geometry (zero-length side, corners apart, ...) */
#define DBS_ERR_IO -7                /* a file cannot be opened, read or written */
#define DBS_ERR_PARSE -8             /* a file is malformed or truncated */
#define DBS_ERR_UNSUPPORTED -9       /* a feature not compiled in or a file type not known */
#define DBS_ERR_CANCELLED -10        /* a callback returned non-zero */
#define DBS_ERR_NO_MEMORY -11        /* an allocation failed */
#define DBS_ERR_BUFFER_TOO_SMALL -12 /* a caller buffer cannot hold the requested data */
#define DBS_ERR_NUMERICAL -13        /* a numerical method failed (singular system, ...) */
#define DBS_ERR_INTERNAL -99         /* a bug in libdbs; please report the message */

/** Short English name of a status code ("ok", "null argument", ...); static storage,
 *  never NULL ("unknown status" for codes not listed above). Cannot fail. \since 0.1 */
DBS_API const char *dbs_status_string(int status);

/** Message of the last failed call on this thread; "" when none failed yet; never NULL.
 *  The string is owned by the library and stays valid until the next libdbs call
 *  on the same thread. Successful calls do not clear it. Cannot fail. \since 0.1 */
DBS_API const char *dbs_last_error_message(void);
/** The operating system's errno behind the last failure on the calling thread when it was
 *  DBS_ERR_IO (ENOENT for a missing file, EACCES for a refused one, ...), so a host can tell
 *  them apart; 0 when that failure was no I/O error or had no errno. \since 0.4 */
DBS_API int dbs_last_error_errno(void);

/* ---- point clouds (\since 0.1) ------------------------------------------------- */
/** An immutable set of 3D points, in the order given. \since 0.1 */
typedef struct dbs_cloud dbs_cloud;

/** Copies `count` points from `xyz` (3*count doubles). count >= 1, all finite.
 *  Returns DBS_ERR_NULL_ARGUMENT (xyz or out; checked before count), DBS_ERR_EMPTY
 *  (count 0), DBS_ERR_NON_FINITE (naming the first such point), DBS_ERR_INVALID_ARGUMENT
 *  (a count no array can have), DBS_ERR_OUT_OF_RANGE (more than 4294967295 points, since
 *  0.3: libdbs indexes points with 32 bits; 0.2 refused them only inside dbs_parameterize),
 *  DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_cloud_create(const double *xyz, size_t count, dbs_cloud **out);
/** Loads .xyz/.txt (text), .ply, .obj or .drc (the extension, in any case, decides); see
 *  docs/FORMATS.md. Coordinates are the exact doubles the file holds (since 0.4 also from
 *  .ply and .obj, which no longer need Draco); .drc needs DBS_FEATURE_DRACO. A file whose
 *  header claims more points than its size can hold is refused before anything is
 *  allocated for them (DBS_ERR_PARSE; a .drc point cloud: more than 1024 points per byte).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_IO (cannot open or read), DBS_ERR_PARSE (a
 *  malformed line, header or element; the message names the file and the line or
 *  element), DBS_ERR_NON_FINITE (a NaN or infinite coordinate), DBS_ERR_EMPTY (no
 *  points), DBS_ERR_UNSUPPORTED (an unknown extension; .drc without Draco;
 *  a PLY version other than 1.0), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_cloud_load(const char *path, dbs_cloud **out);
/** dbs_cloud_load with progress and cancellation, for big files: the progress callback of
 *  `options` (dbs_options_set_progress; the other options are not read; NULL options: no
 *  callback) is called on the calling thread with the stages "read" (the bytes read from
 *  the file, fractions 0 to 0.5), "parse" (the bytes parsed, 0.5 to 1; .xyz/.txt, .ply, .obj)
 *  or, for .drc, "decode" (0 before Draco decodes the file, nothing during it), and last
 *  "done" with exactly 1.0. Each stage reports when it begins and then after every 4 MiB;
 *  fractions rise monotonically. A callback returning non-zero cancels the load:
 *  DBS_ERR_CANCELLED, *out untouched, nothing left allocated.
 *  (`struct dbs_options` is the dbs_options handle of the options section below.)
 *  Returns as dbs_cloud_load, and DBS_ERR_CANCELLED. \since 0.4 */
struct dbs_options;
DBS_API int dbs_cloud_load_with_options(const char *path, const struct dbs_options *options, dbs_cloud **out);
/** Frees the cloud; NULL is ignored. Not while another call uses it. \since 0.1 */
DBS_API void dbs_cloud_destroy(dbs_cloud *cloud);
/** Number of points. Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_cloud_count(const dbs_cloud *cloud, size_t *out);
/** Axis-aligned bounding box: out_min and out_max receive 3 doubles each (cloud units).
 *  Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_cloud_bounds(const dbs_cloud *cloud, double *out_min, double *out_max);
/** Copies all points into `out_xyz`, which holds `capacity` points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_cloud_points(const dbs_cloud *cloud, double *out_xyz, size_t capacity);

/* ---- boundaries (\since 0.1) --------------------------------------------------- */
/** Four boundary curves (polylines), immutable. \since 0.1 */
typedef struct dbs_boundary dbs_boundary;

/* Side ids (pinned; \since 0.1). */
#define DBS_SIDE_BOTTOM 0
#define DBS_SIDE_RIGHT 1
#define DBS_SIDE_TOP 2
#define DBS_SIDE_LEFT 3

/** Four polylines (each >= 2 finite points) with the corner conventions above.
 *  Corners may miss each other by at most 1e-6 of the boundary's bounding-box diagonal;
 *  they are then made to coincide exactly. Larger misses, zero-length sides and a
 *  boundary of zero area are DBS_ERR_DEGENERATE. Since 0.4 so is a boundary whose own shape
 *  bounds no patch: a side folding back on itself (its direction over 5% of its length
 *  turning by more than 160 degrees) or the loop of the four sides crossing itself (seen
 *  along the normal of its best-fit plane, with the crossing strands less than 1% of the
 *  boundary's size apart; a curl shorter than 5% of the loop is tolerated): a bow-tie, a side
 *  running across the patch, a side crossing itself. The message names the side(s), the
 *  points and where (docs/FORMATS.md).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (a side with fewer than 2
 *  points), DBS_ERR_NON_FINITE, DBS_ERR_DEGENERATE (corners apart, a side of zero length or
 *  shorter than the corner tolerance, all points coincident, (almost) no area; since 0.4 a
 *  side folding back, the loop crossing itself),
 *  DBS_ERR_OUT_OF_RANGE (coordinates so large that the boundary's size overflows),
 *  DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_boundary_create(const double *bottom, size_t n_bottom, const double *right, size_t n_right, const double *top, size_t n_top, const double *left, size_t n_left, dbs_boundary **out);
/** dbs_boundary_create with corners allowed to miss each other by `tolerance`: in the
 *  boundary's units, or times its bounding-box diagonal when `relative` is non-zero (the
 *  default of dbs_boundary_create is 1e-6 relative), at most 0.1 of the diagonal. Corners
 *  within it are made to coincide exactly (each pair at its mean); `out_max_snap` (may be
 *  NULL) receives how far the farthest corner end moved (half the largest miss; 0 when all
 *  met). Sides shorter than the tolerance are DBS_ERR_DEGENERATE. Corners that miss say
 *  the fix when an evident one makes them meet ("top runs backwards (...): reverse it",
 *  "left and right are swapped").
 *  Returns as dbs_boundary_create, and DBS_ERR_OUT_OF_RANGE (a tolerance negative, not
 *  finite or above 0.1 of the diagonal); *out and *out_max_snap untouched on failure. \since 0.4 */
DBS_API int dbs_boundary_create_tolerant(const double *bottom, size_t n_bottom, const double *right, size_t n_right, const double *top, size_t n_top, const double *left, size_t n_left, double tolerance, int32_t relative, double *out_max_snap, dbs_boundary **out);
/** dbs_boundary_load with the corner tolerance of dbs_boundary_create_tolerant.
 *  Returns as dbs_boundary_load, and DBS_ERR_OUT_OF_RANGE (the tolerance). \since 0.4 */
DBS_API int dbs_boundary_load_tolerant(const char *path, double tolerance, int32_t relative, double *out_max_snap, dbs_boundary **out);
/** A boundary cut from one closed polyline `xyz` of `n` points (3 doubles each; the first
 *  point not repeated at the end: a last point equal to the first is dropped) at the four
 *  loop points `corners[0..3]` (indices), which become (0,0), (1,0), (1,1), (0,1). The
 *  corners must be distinct and in cyclic order along the loop, in either direction: the
 *  bottom runs along the loop from corners[0] to corners[1] (the way that passes no other
 *  corner), the right from corners[1] to corners[2], the top from corners[3] to corners[2],
 *  the left from corners[0] to corners[3]. The loop's direction does not matter (the loop
 *  reversed, its corner indices following it, gives the same boundary bit for bit); rotating
 *  the corner list rotates the domain. The sides hold the loop's own points and share the
 *  corner points exactly; then checked as dbs_boundary_create does.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (fewer than 4 points once a
 *  repeated first point is dropped, corners repeated or not in cyclic order), DBS_ERR_OUT_OF_RANGE (a corner index not below
 *  n), DBS_ERR_NON_FINITE, DBS_ERR_DEGENERATE (as dbs_boundary_create),
 *  DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_boundary_from_loop(const double *xyz, size_t n, const size_t *corners, dbs_boundary **out);
/** Loads a boundary file (docs/FORMATS.md: sections bottom, right, top, left), then checks
 *  it as dbs_boundary_create does (messages prefixed with the file name).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_IO, DBS_ERR_PARSE (a malformed line, an unknown,
 *  repeated or missing section, a section with fewer than 2 points), DBS_ERR_NON_FINITE,
 *  DBS_ERR_EMPTY (no section at all), DBS_ERR_DEGENERATE, DBS_ERR_OUT_OF_RANGE (as
 *  dbs_boundary_create), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_boundary_load(const char *path, dbs_boundary **out);
/** Writes the boundary to `path` in the boundary file format (docs/FORMATS.md), its corners
 *  as dbs_boundary_create or dbs_boundary_load made them coincide, every number as the
 *  shortest text that reads back to the same double: dbs_boundary_load of the file gives
 *  the same sides bit for bit. An existing file is replaced.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_IO (the file cannot be written, named in the
 *  message), DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_boundary_save(const dbs_boundary *boundary, const char *path);
/** Frees the boundary; NULL is ignored. Not while another call uses it. \since 0.1 */
DBS_API void dbs_boundary_destroy(dbs_boundary *boundary);
/** Number of points of one side (DBS_SIDE_*).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (side). \since 0.1 */
DBS_API int dbs_boundary_side_count(const dbs_boundary *boundary, int32_t side, size_t *out);
/** Copies one side's points into `out_xyz`, which holds `capacity` points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (side), DBS_ERR_BUFFER_TOO_SMALL.
 *  \since 0.1 */
DBS_API int dbs_boundary_side_points(const dbs_boundary *boundary, int32_t side, double *out_xyz, size_t capacity);

/* ---- options (\since 0.1) ------------------------------------------------------ */
/** The settings of a run and its callbacks. \since 0.1 */
typedef struct dbs_options dbs_options;

/* Option ids (pinned; \since 0.1). Each comment: type, default, range. The typed setters and getters
 * refuse an option of the other type (DBS_ERR_INVALID_ARGUMENT). Because of the two cross
 * rules (initial grid <= max grid, own <= near), order matters: raise DBS_OPT_MAX_GRID before
 * setting DBS_OPT_INITIAL_GRID above it. */
#define DBS_OPT_ACCURACY 0          /* double; 0 = unset; >= 0. Mean-distance target in cloud units. */
#define DBS_OPT_RELATIVE_ACCURACY 1 /* double; 1e-3; [1e-9, 1]. Target as a fraction of the diagonal of the cloud's bounding box, measured in the frame of the boundary's corners (so that a rigid motion does not change it), used while DBS_OPT_ACCURACY is 0. Since 0.4 the box is that of the cloud's body: points far outside it (DBS_STAT_FAR_POINTS) do not count. */
#define DBS_OPT_MAX_LEVEL 2         /* int; 4; [0, 8]. Quadtree depth; 0 = a single base surface. */
#define DBS_OPT_INITIAL_GRID 3      /* int; 5; [3, 100]. Grid points per side of a new patch. */
#define DBS_OPT_MAX_GRID 4          /* int; 11; [3, 200], >= initial grid. Largest grid before subdividing. */
#define DBS_OPT_SMOOTHING 5         /* double; 0.5; [0, 0.99]. Weight gamma of eq. (6). */
#define DBS_OPT_SOLVER 6            /* int; DBS_SOLVER_LINEAR; [0, 1]. */
#define DBS_OPT_THREADS 7           /* int; 0 = all hardware threads; [0, 256]. Output never depends on it. */
#define DBS_OPT_SUBCLOUD_NEAR 8     /* double; 0.25; (0, 10]. A4.3 "near" limit, fraction of the diagonal of the child's bounding box in the frame of its corners. */
#define DBS_OPT_SUBCLOUD_OWN 9      /* double; 0.05; [0, 10], <= near. A4.4 "own" limit, fraction of the child's diagonal. */
#define DBS_OPT_REPAIR 11           /* int; 1 (since 0.4; 0 in 0.3); [0, 1]. \since 0.3. 1: the last-resort repair: a point farther from the surface than 10x the target used and one spacing h (one the base surfaces never reached: under an overhang, up a steep wall; not one standing alone, a gross outlier) takes the inverse-distance mean of its 12 nearest neighbours' (u,v), then steps towards its foot, and dbs_result_repaired flags it; since 0.4 the leaves it lands on are then refitted to all their points at their (u,v) (their grids change, their boundaries do not), and every point of those leaves gets the distance of the refitted surface at its (u,v). Fewer folds where the surfaces miss the cloud, and a smaller mean distance there; a cloud the surfaces reach everywhere is left as it is. Then each repaired point and its 12 nearest points move to the (u,v) their neighbours predict where that turns fewer thin triangles over (flat neighbourhoods only), and their leaves are refitted; kept only when neither the mean distance nor the points the fold measure doubts rise (since 0.4). */
#define DBS_OPT_NOISE_FLOOR 10      /* int; 1; [0, 1]. \since 0.3. 1: the accuracy target used is the larger of the requested one and the noise floor, 1.25 sigma sqrt(2/pi) for the cloud's estimated noise sigma (the mean distance a surface on the true surface scores), so a noisy cloud is not chased to the last level; 0: the requested target as given. */
#define DBS_OPT_LOSS 12             /* int; DBS_LOSS_NONE; [0, 3]. \since 0.4. Robust loss of the Ceres solver (DBS_LOSS_*; no effect with the linear one): each point's weight in a node's mean is scaled by rho'(d^2) of its offset d along the node's line, so gross outliers of a scan pull the surface less, and the error that decides whether to grow the grid or subdivide (and whether a leaf met the target) is the mean of sqrt(rho(d^2)) instead of the mean distance d, so outliers do not force subdivision. DBS_STAT_MEAN_DISTANCE stays the plain mean. */
#define DBS_OPT_LOSS_SCALE 13       /* double; 0 = derived; >= 0. \since 0.4. Scale a of the loss in cloud units (distances below it count fully); 0: 3 sigma of the cloud's estimated noise (DBS_STAT_NOISE), at least the spacing h (DBS_STAT_LENGTH_SCALE), so a scaled cloud gets a scaled loss. The one used is DBS_STAT_LOSS_SCALE. A scale outside [1e-6, 1e6] times h makes dbs_parameterize fail with DBS_ERR_OUT_OF_RANGE. */
#define DBS_OPT_CERES_MAX_ITERATIONS 14      /* int; 25; [1, 1000]. \since 0.4. Ceres iterations per solve at most (a curve takes one to four solves, twice that with a loss). */
#define DBS_OPT_OUTLINE_NEIGHBOURS 16           /* int; 24; [6, 256]. \since 0.4. Nearest points of a neighbourhood in dbs_boundary_detect (dbs_boundary_from_corners uses the default): a point is on the cloud's outline when they leave an angular gap above 120 degrees around it (with the points that count it among theirs). Larger: fewer false outline points inside a sparse or noisy cloud, a coarser outline. */
#define DBS_OPT_CROP 17                 /* int; 0; [0, 1]. \since 0.4. 1: points outside the boundary (those DBS_STAT_CLAMPED_POINTS counts, judged before the repair) and points far outside the cloud (DBS_STAT_FAR_POINTS) are cropped instead of clamped onto the domain's edge: u, v and distance NaN, patch and level -1, DBS_POINT_CROPPED in dbs_result_point_flags, counted by DBS_STAT_CROPPED_POINTS; the fold measure, the repair, the distance statistics, the validation (dbs_mesh_*, dbs_distortion_create, dbs_distances_create, dbs_report_write) and the mesh files and the .drc result leave them out (the .csv and .ply result keep their rows, with nan and -1), and each leaf's figures (dbs_patches_stats, DBS_STAT_ACCURACY_MET) are of the points it kept. They still took part in evolving the surfaces, which bend towards them near the boundary: the kept points' distances are larger than those of a run on the kept points alone (on a saddle whose boundary cuts a 0.6 x 0.6 middle out of it: mean distance 1.3e-3 against 5.3e-5). No clamped-points warning then. */
#define DBS_OPT_STRICT 18               /* int; 0; [0, 1]. \since 0.4. 1: a gross mismatch of cloud and boundary fails dbs_parameterize with DBS_ERR_DEGENERATE and the warning's message (with its numbers), instead of a warning: the scale ratio (DBS_STAT_SCALE_RATIO) or the boundary's gap (DBS_STAT_BOUNDARY_GAP) before the run, the coverage (DBS_STAT_COVERAGE) or the clamped points (DBS_STAT_CLAMPED_POINTS; not with DBS_OPT_CROP) once every point has its foot. */
#define DBS_OPT_SMOOTH_TURNED 19        /* int; 0; [0, 1]. \since 0.4. 1: after the repair, each point on a turned sheet of the surface (DBS_STAT_TURNED_POINTS; beyond the 20,000 points the fold measure judges, each point takes the verdict of its nearest judged point) and each of its 24 nearest points takes the (u,v) that a least-squares affine map of those of its 24 nearest points on its own sheet (oriented normals within 60 degrees; itself included) predicts for it, clamped into the domain and scaled down where that neighbourhood is not flat (an apex, a finger's tip: not at all); points on the domain's edge, clamped points and the repair's outliers stay. Then the leaves they land on are refitted to their points at their (u,v) (a refit that would move the surface away from most of a leaf's points is not made), and every point of the refitted leaves gets the distance of the surface there; a moved point of a leaf not refitted keeps its new (u,v), at its distance to the surface there. Kept only when the mean distance stays within the larger of the one before and the target used (DBS_STAT_ACCURACY) and DBS_STAT_ACCURACY_MET does not go from 1 to 0; DBS_STAT_SMOOTHED_POINTS counts the points whose (u,v) changed. Its time counts in DBS_STAT_SECONDS_PARAMETERIZE. Fewer folded triangles where leaves meet under an overhang or up a steep wall (of dbs-bench-folds: the 6,084-point mushroom 22 folded reference triangles to 1, the 10,201-point tall dome 90 to 1), for more points on turned sheets (+16-19% over the fold bench's shapes); see NEWS.md. */
#define DBS_OPT_COARSE_PASS 20          /* int; 1; [0, 2]. \since 0.4. 1 (folds first) and 2 (fit first): where the run pleated its surfaces (the root's error at one of its grids was above 20 times the target used and the root was subdivided, and more than 3% of the judged points on the surface with a normal lie on turned sheets, DBS_STAT_TURNED_SHARE), the whole method runs a second time with a coarse root: the root stops growing its grid where its error is above 20 times the target and is subdivided from there, so its children start from a smoother surface (a root grown to 11 x 11 nodes pleats over a steep wall or an overhang, and its children inherit the pleats). Its result, with fewer judged points on turned sheets, is kept when its mean distance is at most the larger of the first's and the target (DBS_STAT_PASSES, DBS_STAT_COARSE). Folds first (1), it must also have no more points the fold measure cannot pass (DBS_STAT_FOLDED_POINTS + DBS_STAT_UNDECIDED_POINTS) than the first result, and where the first result has more than twice its such points and more than 0.5% of the points judged (a scrambled result: the first surfaces reached an overhang by pleating and scattered its points in (u,v)), it is kept with a mean distance up to 4 times that bound: fewer folds for a worse fit; the second pass is given up after its first level when that level fits more than twice worse than the first pass's (the points-weighted mean error of its patches). Fit first (2), it is given up when that level fits worse at all, and kept only on the fit. The second pass never fails the run on DBS_OPT_STRICT's checks (the first pass made them) nor on an error but a cancel: the first result is kept then. Such runs take up to twice the time: both passes' time counts in DBS_STAT_SECONDS and its stages (a dropped second pass's in DBS_STAT_SECONDS_EVOLVE), while DBS_STAT_ITERATIONS and the other counts are the kept pass's. The second pass reports its progress between the first's last fraction and 1, and calls the level callback for its own levels from 0 (its patches are those of its own quadtree); its warnings are given only when its result is kept, each message once. Runs that do not pleat are unchanged. On the hard shapes of dbs-bench-folds, fit first against one pass (182 clean runs at 25 densities): 3,984 -> 2,537 folded reference triangles (the 10,201-point tall dome 90 -> 7), points on turned sheets -30%, mean distance x0.95, one run folding more; folds first against fit first (132 clean runs at 22 densities, 4,489-32,761 points): 5,497 -> 4,726 folded reference triangles, no run folding more, mean distance x1.08, 7 more runs missing the target; see NEWS.md. 0: one pass. */
#define DBS_OPT_FIT_TO_TARGET 21        /* int; 1; [0, 1]. \since 0.4. 1: a patch whose largest grid stays above the target (at most 4 times it) is fitted by least squares to its error sample at their feet, and stays a leaf where that fit comes within 0.85 times the target without turning the surface under any sample point; 0: the grid projections of eq. (5) alone. */
#define DBS_OPT_CERES_FUNCTION_TOLERANCE 15  /* double; 1e-6; [1e-16, 1]. \since 0.4. Ceres stops when an iteration changes the cost by less than this fraction. */

/* Solvers for DBS_OPT_SOLVER (pinned; \since 0.1). */
#define DBS_SOLVER_LINEAR 0 /* banded linear least squares (always available) */
#define DBS_SOLVER_CERES 1  /* since 0.4: the linear solve, then each projected curve (grid row or column, middle curve) refined by Ceres with the weights of eq. (5) taken at the node's current position and an optional robust loss (DBS_OPT_LOSS); needs DBS_FEATURE_CERES (before 0.4, and in a build without Ceres: DBS_ERR_UNSUPPORTED) */

/* Robust losses for DBS_OPT_LOSS (pinned; \since 0.4): rho of a squared distance s, scale a. */
#define DBS_LOSS_NONE 0    /* rho(s) = s: least squares */
#define DBS_LOSS_HUBER 1   /* s up to a^2, 2 a sqrt(s) - a^2 beyond */
#define DBS_LOSS_CAUCHY 2  /* a^2 log(1 + s / a^2) */
#define DBS_LOSS_SOFT_L1 3 /* 2 a^2 (sqrt(1 + s / a^2) - 1) */

/** Progress: `fraction` rises monotonically in [0,1] and the last call has exactly 1.0;
 *  `stage` names the running stage ("index", "evolve", "subdivide", "parameterize",
 *  "folds" (since 0.3: the repair, when on, runs at the end of "parameterize", the fold
 *  measure in "folds"), "done");
 *  the string is valid only during the call. Called on the thread that called
 *  dbs_parameterize (see "Callbacks" above); must return normally.
 *  Since 0.4 it is called after every 2048 units of work (a point projected or measured, a
 *  node of a grid section solved) in every stage but "index" (the k-d tree build), the same
 *  number of times for any thread count, and a cancel stops every worker at its next unit.
 *  Return 0 to go on, non-zero to cancel (dbs_parameterize returns DBS_ERR_CANCELLED).
 *  \since 0.1 */
typedef int (*dbs_progress_fn)(double fraction, const char *stage, void *payload);

/** A read-only view of a set of base-surface patches (one quadtree level in the level
 *  callback, the whole quadtree in a result); read with the dbs_patches_* functions.
 *  Owned by libdbs, never destroyed by the caller. \since 0.1 */
typedef struct dbs_patches dbs_patches;

/** Called once per finished quadtree level (0 = the root) with that level's patches,
 *  after they were evolved and those that missed the target were subdivided (so
 *  dbs_patches_is_leaf tells which were split; ids are those of the result).
 *  `patches` is valid only during the call. Called on the thread that called
 *  dbs_parameterize; may call any libdbs function; must return normally.
 *  Return 0 to go on, non-zero to cancel (dbs_parameterize returns DBS_ERR_CANCELLED).
 *  \since 0.1 */
typedef int (*dbs_level_fn)(int32_t level, const dbs_patches *patches, void *payload);

/** New options with every default and no callbacks.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_options_create(dbs_options **out);
/** A copy of `options`: values, callbacks and their payloads.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_options_clone(const dbs_options *options, dbs_options **out);
/** Frees the options; NULL is ignored. Not while another call uses them. \since 0.1 */
DBS_API void dbs_options_destroy(dbs_options *options);
/** Integer options (DBS_OPT_MAX_LEVEL, _INITIAL_GRID, _MAX_GRID, _SOLVER, _THREADS).
 *  Modifies `options`: must not race with any other use of them.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an unknown id or a real
 *  option), DBS_ERR_OUT_OF_RANGE (outside the range, or breaking a cross rule),
 *  DBS_ERR_UNSUPPORTED (DBS_SOLVER_CERES without DBS_FEATURE_CERES). \since 0.1 (since 0.4
 *  also _LOSS, _CERES_MAX_ITERATIONS) */
DBS_API int dbs_options_set_int(dbs_options *options, int32_t option, int32_t value);
/** Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an unknown id or a real
 *  option). \since 0.1 */
DBS_API int dbs_options_get_int(const dbs_options *options, int32_t option, int32_t *out);
/** Real options (DBS_OPT_ACCURACY, _RELATIVE_ACCURACY, _SMOOTHING, _SUBCLOUD_NEAR, _SUBCLOUD_OWN;
 *  since 0.4 _LOSS_SCALE, _CERES_FUNCTION_TOLERANCE).
 *  Modifies `options`: must not race with any other use of them.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an unknown id or an integer
 *  option), DBS_ERR_NON_FINITE, DBS_ERR_OUT_OF_RANGE (outside the range, or breaking a
 *  cross rule). \since 0.1 */
DBS_API int dbs_options_set_double(dbs_options *options, int32_t option, double value);
/** Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an unknown id or an integer
 *  option). \since 0.1 */
DBS_API int dbs_options_get_double(const dbs_options *options, int32_t option, double *out);
/** Documented range of any option (integer options report theirs as doubles). An open end
 *  is reported as its limit (DBS_OPT_SUBCLOUD_NEAR: min 0, which itself is refused) and a
 *  missing upper end as DBL_MAX (DBS_OPT_ACCURACY).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an unknown id). \since 0.1 */
DBS_API int dbs_option_bounds(int32_t option, double *out_min, double *out_max);
/** Sets (or with fn == NULL clears) the progress callback; `payload` is passed to it as
 *  given (never dereferenced by libdbs). Modifies `options`: must not race with any other
 *  use of them. Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_options_set_progress(dbs_options *options, dbs_progress_fn fn, void *payload);
/** Sets (or with fn == NULL clears) the per-level inspection callback; `payload` as for
 *  dbs_options_set_progress. Modifies `options`: must not race with any other use of them.
 *  Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_options_set_level_callback(dbs_options *options, dbs_level_fn fn, void *payload);

/** Called with one line naming a likely mistake in the inputs, each time one is found
 *  during dbs_parameterize: the boundary's size against the cloud's, its distance to the
 *  cloud, points far outside the cloud's body (all before the run), the share of the domain
 *  the points cover and the points clamped onto the domain's edge (after it); see
 *  DBS_STAT_BOUNDARY_GAP and the four after it. The run goes on. The string is valid only during the call. Called on the thread that
 *  called dbs_parameterize; must return normally. \since 0.4 */
typedef void (*dbs_warning_fn)(const char *message, void *payload);
/** Sets (or with fn == NULL clears) the warning callback; `payload` as for
 *  dbs_options_set_progress. Modifies `options`: must not race with any other use of them.
 *  Returns DBS_ERR_NULL_ARGUMENT. \since 0.4 */
DBS_API int dbs_options_set_warning(dbs_options *options, dbs_warning_fn fn, void *payload);

/* ---- boundaries from the cloud itself (\since 0.4) -------------------------------- */
/** The boundary of an open scan found from its points alone: its outline (the points whose
 *  DBS_OPT_OUTLINE_NEIGHBOURS nearest points, with the points that count them among theirs,
 *  leave an angular gap above 120 degrees in their tangent plane), ordered into closed loops,
 *  smoothed along their arc length and pushed out to run on or just outside the outermost
 *  points (a void of the sampling that opens onto the outline, or a slot narrower than three
 *  point spacings, is bridged); coincident points count once. The loop enclosing the largest
 *  area in the cloud's principal plane is the outer one; the others inside it are holes
 *  (dbs_boundary_hole_count), unless they are shorter than 16 point spacings (a hole less
 *  than about 5 spacings across cannot be told from a void of the sampling). It is cut at four corners: where it turns most in the surface's
 *  tangent plane (the four largest maxima at least 5% of the perimeter apart), or, for
 *  a round outline (the fourth turning below 30 degrees), the loop points nearest to the
 *  corners of its minimum-area bounding rectangle in the plane of its principal axes. Of
 *  those, the one that comes from the cloud point of the lowest index is (0,0), and the bottom
 *  runs towards its neighbouring corner of the lower index: the same boundary for the cloud
 *  moved, rotated or scaled. `options` may be NULL (the defaults; only DBS_OPT_THREADS and
 *  DBS_OPT_OUTLINE_NEIGHBOURS are read). Measured on open analytic surfaces of 10,000 random
 *  points (tests/core/test_boundary_detect.cpp): the outline within 1.4 point spacings of the
 *  true one, the corners within 3.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (fewer distinct points than the
 *  neighbourhood), DBS_ERR_DEGENERATE (no closed outline: a closed surface, or a border
 *  sampled too thinly; most points looking like border points, as scan lines far apart: a
 *  larger DBS_OPT_OUTLINE_NEIGHBOURS; separate pieces; no four distinct corners; sides the
 *  boundary checks refuse), DBS_ERR_OUT_OF_RANGE (more than 2^32 points, a boundary beyond
 *  the supported magnitudes), DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_boundary_detect(const dbs_cloud *cloud, const dbs_options *options, dbs_boundary **out);
/** The outer loop of dbs_boundary_detect's outline cut at the loop points nearest to the
 *  four points `corners_xyz` (x, y, z of each), which become (0,0), (1,0), (1,1), (0,1) in
 *  that order; they must follow each other around the outline, in either direction. With the
 *  default options (DBS_OPT_OUTLINE_NEIGHBOURS 24, all hardware threads; see
 *  dbs_boundary_detect).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_NON_FINITE (a corner), DBS_ERR_INVALID_ARGUMENT (two
 *  corners at one loop point, corners not in cyclic order, a corner farther than 5% of the
 *  outline's perimeter from it: the message says which and how far), DBS_ERR_DEGENERATE (as
 *  dbs_boundary_detect), DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_boundary_from_corners(const dbs_cloud *cloud, const double *corners_xyz, dbs_boundary **out);
/** Number of holes (inner loops of the outline) of a boundary made by dbs_boundary_detect or
 *  dbs_boundary_from_corners; 0 for every other boundary. \since 0.4 */
DBS_API int dbs_boundary_hole_count(const dbs_boundary *boundary, size_t *out);
/** Number of points of hole `hole` (a closed loop, its first point not repeated).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (hole). \since 0.4 */
DBS_API int dbs_boundary_hole_size(const dbs_boundary *boundary, size_t hole, size_t *out);
/** Copies the points of hole `hole` into `out_xyz`, which holds `capacity` points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (hole), DBS_ERR_BUFFER_TOO_SMALL.
 *  \since 0.4 */
DBS_API int dbs_boundary_hole_points(const dbs_boundary *boundary, size_t hole, double *out_xyz, size_t capacity);

/* ---- parameterization (\since 0.1) --------------------------------------------- */
/** The outcome of a run: per-point parameters, the patch quadtree, statistics. Immutable;
 *  independent of the cloud, boundary and options it was made from. \since 0.1 */
typedef struct dbs_result dbs_result;

/** Parameterizes `cloud` inside `boundary`. `options` may be NULL for the defaults; they
 *  are read once, when the call starts. Starts worker threads (see "Threads" above) and
 *  calls the callbacks of `options` on the calling thread. On failure *out is untouched
 *  and nothing is left allocated.
 *  Returns DBS_ERR_NULL_ARGUMENT (cloud, boundary or out), DBS_ERR_DEGENERATE (the cloud or
 *  boundary found unusable: all points coincide, fewer than two distinct points, a zero
 *  direction or a middle curve of zero length met while projecting or subdividing),
 *  DBS_ERR_NUMERICAL (a projection system singular or without finite solution),
 *  DBS_ERR_OUT_OF_RANGE (since 0.4: the cloud's body or the boundary is smaller than 1e-100
 *  or larger than 1e75 across, the magnitudes supported, or a loss scale out of range),
 *  DBS_ERR_CANCELLED (a callback returned non-zero), DBS_ERR_NO_MEMORY, DBS_ERR_INTERNAL
 *  (a bug; since 0.3 not a worker thread that could not be started, see "Threads").
 *  \since 0.1 */
DBS_API int dbs_parameterize(const dbs_cloud *cloud, const dbs_boundary *boundary, const dbs_options *options, dbs_result **out);
/** Frees the result and its dbs_patches view; NULL is ignored. Not while another call uses
 *  the result or its view. \since 0.1 */
DBS_API void dbs_result_destroy(dbs_result *result);

/** Number of parameterized points (equals the cloud's count, input order kept).
 *  Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_result_point_count(const dbs_result *result, size_t *out);
/** u0 v0 u1 v1 ... into `out_uv`, which holds `capacity` pairs; each in [0,1] (NaN for a
 *  cropped point, DBS_OPT_CROP).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_result_uv(const dbs_result *result, double *out_uv, size_t capacity);
/** Distance of each point to the base surface (>= 0, cloud units; NaN for a cropped point); `capacity` in values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_result_distances(const dbs_result *result, double *out, size_t capacity);
/** Id of the leaf patch that parameterized each point (an index for dbs_patches_* on the
 *  view of dbs_result_patches; -1 for a cropped point); `capacity` in values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_result_point_patches(const dbs_result *result, int32_t *out, size_t capacity);
/** Quadtree level of that leaf for each point (0 = the root; -1 for a cropped point); `capacity` in values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_result_point_levels(const dbs_result *result, int32_t *out, size_t capacity);
/** 1 for each point whose (u,v) the last-resort repair gave (DBS_OPT_REPAIR), else 0; all 0
 *  when the repair was off; `capacity` in values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.3 */
DBS_API int dbs_result_repaired(const dbs_result *result, int32_t *out, size_t capacity);

/* Per-point flags of dbs_result_point_flags, bits that may combine (pinned; \since 0.4). */
#define DBS_POINT_REPAIRED 1 /* the last-resort repair gave it its (u,v) (as dbs_result_repaired) */
#define DBS_POINT_FAR 2      /* far outside the cloud's body (DBS_STAT_FAR_POINTS): took the (u,v) of its nearest point of the body, or was cropped */
#define DBS_POINT_CLAMPED 4  /* outside the boundary (DBS_STAT_CLAMPED_POINTS): its foot, before the repair, lay on the domain's edge more than a point spacing from the surface */
#define DBS_POINT_CROPPED 8  /* cropped (DBS_OPT_CROP): u, v and distance NaN, patch and level -1 */
#define DBS_POINT_TURNED 16  /* \since 0.4: one of the DBS_STAT_TURNED_POINTS: judged by the fold measure, on the surface, and on a sheet of it turned against the cloud (points the measure does not judge, beyond 20,000, carry no verdict) */
/** The DBS_POINT_* bits of each point, in input order, into `out`, which holds `capacity` values (at least the point count).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.4 */
DBS_API int dbs_result_point_flags(const dbs_result *result, int32_t *out, size_t capacity);

/** Point (and, if out_normal is not NULL, unit normal) of the base surface at (u,v) in [0,1]^2;
 *  3 doubles each. A (u,v) on a seam between leaves is evaluated on the leaf with the
 *  larger u and v (the seams are C0, so the point agrees).
 *  Returns DBS_ERR_NULL_ARGUMENT (result or out_xyz), DBS_ERR_NON_FINITE (u or v),
 *  DBS_ERR_OUT_OF_RANGE (u or v outside [0,1]), DBS_ERR_NUMERICAL (a normal was asked
 *  where the surface has none, e.g. a collapsed patch). \since 0.1 */
DBS_API int dbs_result_evaluate(const dbs_result *result, double u, double v, double *out_xyz, double *out_normal);

/* Summary statistics (pinned ids; \since 0.1) for dbs_result_stat, each with its unit. */
#define DBS_STAT_MEAN_DISTANCE 0 /* mean point-to-surface distance over all points (since 0.4: but those far outside the cloud, DBS_STAT_FAR_POINTS, and cropped ones), cloud units */
#define DBS_STAT_MAX_DISTANCE 1  /* largest point-to-surface distance, cloud units */
#define DBS_STAT_RMS_DISTANCE 2  /* root mean square of the point-to-surface distances, cloud units */
#define DBS_STAT_ACCURACY 3      /* the mean-distance target that was used, in cloud units: the requested one, raised to the noise floor when DBS_OPT_NOISE_FLOOR is 1 (since 0.3) */
#define DBS_STAT_ACCURACY_MET 4  /* 1 when every leaf met the target that was used (DBS_STAT_ACCURACY), else 0; since 0.4, with a robust loss (DBS_OPT_LOSS) a leaf's error is its mean robust distance */
#define DBS_STAT_LEVELS 5        /* number of quadtree levels (1 = root only), a count */
#define DBS_STAT_PATCHES 6       /* number of patches in the quadtree, a count */
#define DBS_STAT_LEAVES 7        /* number of leaf patches, a count */
#define DBS_STAT_ITERATIONS 8    /* grid evolutions over all patches (since 0.4 with each patch's warm-up grid and a root's restarts), a count */
#define DBS_STAT_SECONDS 9       /* wall-clock time of dbs_parameterize, seconds */
#define DBS_STAT_LENGTH_SCALE 10 /* the cloud's length scale h (mean nearest-neighbour spacing), cloud units */
#define DBS_STAT_SECONDS_INDEX 11        /* wall-clock time spent indexing the cloud, seconds */
#define DBS_STAT_SECONDS_EVOLVE 12       /* ... evolving base surfaces (all levels), seconds */
#define DBS_STAT_SECONDS_SUBDIVIDE 13    /* ... subdividing patches and splitting subclouds, seconds */
#define DBS_STAT_SECONDS_PARAMETERIZE 14 /* ... projecting every point onto its leaves (A2), seconds */
#define DBS_STAT_SECONDS_FOLDS 15        /* \since 0.3: ... measuring the folds (DBS_STAT_FOLDED_*), seconds */
#define DBS_STAT_REQUESTED_ACCURACY 16   /* \since 0.3: the target the options asked for (absolute, or relative times the diagonal), cloud units */
#define DBS_STAT_REQUESTED_MET 17        /* \since 0.3: 1 when every leaf met the requested target, else 0 (its error judged as for DBS_STAT_ACCURACY_MET) */
#define DBS_STAT_NOISE 18                /* \since 0.3: the cloud's estimated noise sigma (deviation along the normal, from local quadric fits), cloud units; 0 on a clean cloud */
#define DBS_STAT_FOLDED_SHARE 19         /* \since 0.3: share in [0,1] of the decided points whose neighbourhood (k nearest in 3D, consistently oriented tangent frames) is mapped to (u,v) with reversed orientation; needs no mesh and does not trust the base surfaces */
#define DBS_STAT_FOLDED_POINTS 20        /* \since 0.3: number of such folded points, a count */
#define DBS_STAT_UNDECIDED_POINTS 21     /* \since 0.3: points whose neighbourhood is not surface-like enough to decide (not counted as folded), a count */
#define DBS_STAT_COINCIDENT_POINTS 22    /* \since 0.3: points sharing one (u,v) with another point, a count */
#define DBS_STAT_REPAIRED_POINTS 24      /* \since 0.3: points the last-resort repair gave their (u,v) (DBS_OPT_REPAIR), a count */
#define DBS_STAT_JUDGED_POINTS 23        /* \since 0.3: points the fold measure judged: all of them up to 20,000 (10,000 before 0.4), beyond that 20,000 evenly spread over the input order and over the cloud's body (the FOLDED/UNDECIDED/COINCIDENT counts are of these), a count */
#define DBS_STAT_SOLVER 25                /* \since 0.4: the solver that ran, DBS_SOLVER_* */
#define DBS_STAT_CERES_ITERATIONS 26      /* \since 0.4: Ceres iterations over all refined grid sections of all patches (0 with the linear solver), a count */
#define DBS_STAT_LOSS_SCALE 27            /* \since 0.4: the scale of the robust loss used (DBS_OPT_LOSS_SCALE, or the derived one), cloud units; 0 without a loss or with the linear solver */
#define DBS_STAT_COLLAPSED_POINTS 28      /* \since 0.4: of the UNDECIDED points, those whose neighbourhood is squeezed in (u,v) (most neighbours share its (u,v), the local map to (u,v) has rank about one, or its determinant is below 1e-3 of the median): where a surface never reached the cloud, points pile up without turning over, which the FOLDED count cannot see; a count */
#define DBS_STAT_BOUNDARY_GAP 29          /* \since 0.4: the boundary's distance to the cloud: of 256 points spread along its sides, 90% lie within this distance of their nearest cloud point, in point spacings (DBS_STAT_LENGTH_SCALE), each measured against the local spacing there (so a sparse part of a scan is no gap); about 1 for a boundary on its scan's edges; above 4 a warning (dbs_options_set_warning) asks whether the sides follow the scan's edges (four straight lines between the corners of a curved part run through the air), above 10 whether the boundary belongs to this cloud */
#define DBS_STAT_SCALE_RATIO 30           /* \since 0.4: the cloud's bounding-box diagonal over the boundary's, a ratio (about 1 when the boundary surrounds its scan; beyond 10 or below 1/10 a warning asks whether they are in the same units) */
#define DBS_STAT_COVERAGE 31              /* \since 0.4: the share of [0,1]^2 the points' (u,v) cover: cells of a grid with about 16 points per cell (at least 2 x 2, at most 256 x 256) holding a point, in [0,1]; below 0.75 a warning says the cloud covers only part of the boundary */
#define DBS_STAT_CLAMPED_POINTS 32        /* \since 0.4: points whose (u,v) lies on the domain's edge while they are farther than a point spacing from the surface there (outside the boundary, clamped onto it), a count; beyond 1% of the points (and at least 10) a warning asks whether the scan is larger than its boundary */
#define DBS_STAT_CROPPED_POINTS 34        /* \since 0.4: points cropped (DBS_OPT_CROP): no (u,v), left out of every statistic, the validation and the files; a count (0 without the option) */
#define DBS_STAT_FAR_POINTS 33            /* \since 0.4: points far outside the cloud's body (beyond 10 times its extent from the box between its 1% and 99% coordinate quantiles in the boundary's corner frame: a 1e9 or 1e300 glitch next to a scan): left out of the relative target, the spacing, the surfaces, the repair, the fold measure and the distance statistics; each takes the (u,v), patch and level of its nearest point of the body and its finite distance to the surface there; a count, with a warning */
#define DBS_STAT_TURNED_POINTS 35         /* \since 0.4: of the judged points (DBS_STAT_JUDGED_POINTS) on the surface (within the larger of 10 times DBS_STAT_ACCURACY and one DBS_STAT_LENGTH_SCALE of it; a point farther off has no sheet under it), those on a turned sheet of the surface: its Su x Sv at the point's (u,v) points away from the normal the fold measure finds for the point from the cloud (its PCA normal, oriented consistently over the cloud and signed by the majority of the (u,v) maps around it). There a mesh of the surface over the domain overlaps itself and the normals of dbs_result_evaluate point the wrong way, even where the points' (u,v) are in order (a base surface pleated between its grid nodes, or refitted by the repair through a band squeezed in (u,v)); a count */
#define DBS_STAT_TURNED_SHARE 36          /* \since 0.4: DBS_STAT_TURNED_POINTS over the judged points on the surface with such a normal (points outside the measure's orientation graph, or in a part of it without a majority, have none), in [0,1] */
#define DBS_STAT_SMOOTHED_POINTS 37       /* \since 0.4: points whose (u,v) the smoothing of turned sheets (DBS_OPT_SMOOTH_TURNED) moved, a count; 0 when it was off, found no turned sheet, or was undone */
#define DBS_STAT_PASSES 38                /* \since 0.4: passes of the method run, 1 or 2 (a coarse pass after the plain one, DBS_OPT_COARSE_PASS) */
#define DBS_STAT_COARSE 39                /* \since 0.4: 1 when the result is the coarse pass's (DBS_OPT_COARSE_PASS), else 0 */
/** One summary statistic (DBS_STAT_*) of the result, in the unit given beside its id.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (stat). \since 0.1 */
DBS_API int dbs_result_stat(const dbs_result *result, int32_t stat, double *out);
/** dbs_result_evaluate at n points at once, with the derivatives: `uv` holds n pairs (u, v),
 *  each in [0, 1]; out_xyz receives 3n values (the surface points), and out_normal (unit
 *  normals), out_su and out_sv (the partial derivatives dS/du and dS/dv of the global
 *  parameters, cloud units per unit of u or v), 3n values each when not NULL. uv and out_xyz
 *  may be NULL when n is 0. Uses all hardware threads; the values do not depend on them.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_NON_FINITE, DBS_ERR_OUT_OF_RANGE (a parameter, named
 *  with its pair's index; nothing is written then), DBS_ERR_INVALID_ARGUMENT (n beyond any
 *  array), DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_result_evaluate_many(const dbs_result *result, const double *uv, size_t n, double *out_xyz, double *out_normal, double *out_su, double *out_sv);

/** The result's quadtree: all patches, indexed by patch id; valid while `result` lives
 *  (owned by the result: do not destroy it). Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_result_patches(const dbs_result *result, const dbs_patches **out);

/** Writes .csv, .ply or .drc (the extension, in any case, decides; docs/FORMATS.md).
 *  `cloud` is the cloud that was parameterized (its points are written in .ply and .drc;
 *  since 0.4 the .ply holds doubles, so its points read back bit for bit).
 *  An existing file is replaced. .drc needs DBS_FEATURE_DRACO.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (the cloud's point count differs
 *  from the result's), DBS_ERR_UNSUPPORTED (an unknown extension; .drc without Draco),
 *  DBS_ERR_IO (cannot create or write the file), DBS_ERR_OUT_OF_RANGE (.drc: a coordinate
 *  beyond the 32-bit float range), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_result_save(const dbs_result *result, const dbs_cloud *cloud, const char *path);

/* ---- patches (\since 0.1) ------------------------------------------------------- */
/* Every dbs_patches_* function reads the i-th patch of a view (0 <= i < count) and
 * returns DBS_ERR_NULL_ARGUMENT for a NULL pointer and DBS_ERR_OUT_OF_RANGE for an i
 * outside the view; the view may be read by many threads at once. */
/** Number of patches in the view. Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_patches_count(const dbs_patches *patches, size_t *out);
/** Patch id (the index used by dbs_result_point_patches) of the i-th patch of the view.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_id(const dbs_patches *patches, size_t i, int32_t *out);
/** Quadtree level of the patch (0 = the root).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_level(const dbs_patches *patches, size_t i, int32_t *out);
/** 1 for a leaf, 0 for a patch that was subdivided.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_is_leaf(const dbs_patches *patches, size_t i, int32_t *out);
/** Id of the parent patch, -1 for the root.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_parent(const dbs_patches *patches, size_t i, int32_t *out);
/** The patch's rectangle of the global domain: u0 v0 u1 v1 into out_rect (4 doubles).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_rect(const dbs_patches *patches, size_t i, double *out_rect);
/** Grid size: points along u and along v.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_grid_size(const dbs_patches *patches, size_t i, int32_t *out_nu, int32_t *out_nv);
/** Grid points, u fastest: point (iu, iv) at index iv*nu + iu; `capacity` in points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_patches_grid_points(const dbs_patches *patches, size_t i, double *out_xyz, size_t capacity);
/** Number of points of one side (DBS_SIDE_*) of the patch's own boundary.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (i or side). \since 0.1 */
DBS_API int dbs_patches_boundary_count(const dbs_patches *patches, size_t i, int32_t side, size_t *out);
/** That side's points into `out_xyz`, which holds `capacity` points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (i or side), DBS_ERR_BUFFER_TOO_SMALL.
 *  \since 0.1 */
DBS_API int dbs_patches_boundary_points(const dbs_patches *patches, size_t i, int32_t side, double *out_xyz, size_t capacity);
/** Points of the patch's subcloud (a count), their mean and max distance to the patch
 *  (cloud units), grid evolutions (a count). Since 0.4 the distances of a leaf are over all
 *  of its points, those of a patch that was split over the evenly strided sample (4096 to
 *  8191 of its points, all of them when fewer) that decided its growth and its split;
 *  since 0.4 the distances of a leaf the repair refitted (DBS_OPT_REPAIR) are over the
 *  points it parameterizes, at their (u,v) on its refitted surface.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.1 */
DBS_API int dbs_patches_stats(const dbs_patches *patches, size_t i, size_t *out_points, double *out_mean, double *out_max, int32_t *out_iterations);
/** The solver that projected the patch's grids (DBS_SOLVER_*: DBS_SOLVER_CERES when the run
 *  asked for it, also for a patch without points) and the Ceres iterations over its refined
 *  grid sections (a count; 0 with the linear solver), so a level callback can tell which
 *  solver ran and what it cost.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE. \since 0.4 */
DBS_API int dbs_patches_solver(const dbs_patches *patches, size_t i, int32_t *out_solver, size_t *out_ceres_iterations);

/* ---- validation (\since 0.1) ---------------------------------------------------- */
/* The four judgements of a parameterization of the paper's section 7, as numbers and files:
 * (a) a mesh of the cloud from the 2D Delaunay triangulation of its (u,v), with the triangles
 * that bridge across the surface flagged; (b) how much each triangle is distorted between 3D
 * and (u,v); (c) a texture of black disks mapped through (u,v) (dbs_mesh_save and the
 * report); (d) the point-to-surface distances, per leaf patch and overall.
 * Every function of this section is exported in every build; in a library built without
 * DBS_FEATURE_VALIDATION each one (but the *_destroy functions, which accept NULL) returns
 * DBS_ERR_UNSUPPORTED, which the lists below therefore do not repeat. A mesh, distortion or
 * distances handle owns copies of what it needs: its result and cloud may be destroyed
 * first. */
/** The Delaunay mesh of a result's (u,v) over its cloud. \since 0.1 */
typedef struct dbs_mesh dbs_mesh;

/** A triangle is suspicious when one of its 3D edges is longer than this many times the
 *  local spacing of both its end points (a point's distance to its 6th nearest other point):
 *  the mesh bridges across the surface, or along a ragged outline of the cloud. */
#define DBS_MESH_SUSPICIOUS_FACTOR 4.0 /* \since 0.1 */

/** Triangulates the result's (u,v) in the plane (2D Delaunay, Qhull) and takes the triangles
 *  over `cloud`, the cloud that was parameterized: vertex i is cloud point i (a cropped point,
 *  DBS_OPT_CROP, is the vertex of no triangle and its (u,v) is NaN). Triangles are
 *  counter-clockwise in (u,v); a point whose (u,v) coincides with another's is the vertex of
 *  no triangle. DBS_ERR_INVALID_ARGUMENT when the cloud's size differs from the result's,
 *  DBS_ERR_DEGENERATE when the (u,v) do not span the plane. Uses all hardware threads.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (the cloud's size differs from
 *  the result's; more than INT32_MAX points), DBS_ERR_DEGENERATE (fewer than 3 distinct
 *  (u,v), or all on one line), DBS_ERR_NUMERICAL (Qhull failed; no surface normal at a
 *  triangle's centre), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_mesh_create(const dbs_result *result, const dbs_cloud *cloud, dbs_mesh **out);
/** Frees the mesh; NULL is ignored. Not while another call uses it. \since 0.1 */
DBS_API void dbs_mesh_destroy(dbs_mesh *mesh);
/** Number of vertices (the cloud's point count). Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_mesh_vertex_count(const dbs_mesh *mesh, size_t *out);
/** Vertex positions (the cloud's points) into `out_xyz`, which holds `capacity` points.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_mesh_vertices(const dbs_mesh *mesh, double *out_xyz, size_t capacity);
/** Vertex parameters u0 v0 u1 v1 ... into `out_uv`, which holds `capacity` pairs.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_mesh_uv(const dbs_mesh *mesh, double *out_uv, size_t capacity);
/** Number of triangles. Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_mesh_triangle_count(const dbs_mesh *mesh, size_t *out);
/** Vertex indices a0 b0 c0 a1 b1 c1 ... into `out`, which holds `capacity` triangles.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_mesh_triangles(const dbs_mesh *mesh, int32_t *out, size_t capacity);
/** Number of suspicious triangles. Returns DBS_ERR_NULL_ARGUMENT. \since 0.1 */
DBS_API int dbs_mesh_suspicious_count(const dbs_mesh *mesh, size_t *out);
/** Indices (ascending) of the suspicious triangles into `out`, which holds `capacity` values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_BUFFER_TOO_SMALL. \since 0.1 */
DBS_API int dbs_mesh_suspicious(const dbs_mesh *mesh, int32_t *out, size_t capacity);
/** Writes the mesh by extension: .obj with vt = (u,v), plus STEM.mtl and the disk texture
 *  STEM_texture.png beside it (so any viewer shows method (c)); or binary .ply with double
 *  x y z u v per vertex (since 0.4; float before). Cropped points (NaN (u,v)) are not written
 *  and the later vertices are numbered on, so a file's vertex k is cloud point k only without
 *  cropping. Other extensions are DBS_ERR_UNSUPPORTED. Existing files are replaced; see
 *  docs/FORMATS.md.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_UNSUPPORTED (another extension; .obj without
 *  DBS_FEATURE_REPORT), DBS_ERR_IO (cannot create or write a file), DBS_ERR_NO_MEMORY.
 *  \since 0.1 */
DBS_API int dbs_mesh_save(const dbs_mesh *mesh, const char *path);

/** Distortion measures of a mesh's triangles. \since 0.1 */
typedef struct dbs_distortion dbs_distortion;

/* How the (u,v) domain is scaled before triangles are compared (pinned; \since 0.1). Both end with the
 * total (u,v) area of the measured triangles equal to their total 3D area. */
#define DBS_SCALING_UNIFORM 0  /* u and v alike: [0,1]^2's aspect ratio counts as distortion */
#define DBS_SCALING_PER_AXIS 1 /* u and v first by the surface's typical (3D-area-weighted median) speed along each */

/* Per-triangle measures (pinned; \since 0.1): 0-6 dimensionless ratios, 7-8 flags. J maps the 3D triangle (in its plane) to its scaled (u,v)
 * image; sigma1 >= sigma2 are its singular values. Degenerate triangles (zero area in 3D or
 * in (u,v)) have NaN for measures 0-6 and are in no summary. */
#define DBS_MEASURE_CONFORMAL 0       /* sigma1 / sigma2 >= 1; 1 = angles kept */
#define DBS_MEASURE_AREA 1            /* sigma1 * sigma2; 1 = area kept */
#define DBS_MEASURE_STRETCH_L2 2      /* Sander et al.'s L2 stretch sqrt((1/sigma1^2 + 1/sigma2^2) / 2) */
#define DBS_MEASURE_STRETCH_LINF 3    /* largest stretch 1 / sigma2 */
#define DBS_MEASURE_EDGE_DIFFERENCE 4 /* largest |edge length in (u,v) - in 3D| / length in 3D of the 3 edges */
#define DBS_MEASURE_SIGMA1 5
#define DBS_MEASURE_SIGMA2 6
#define DBS_MEASURE_FOLDED 7     /* 1 when folded (orientation against the majority), else 0 */
#define DBS_MEASURE_DEGENERATE 8 /* 1 when degenerate, else 0 */
#define DBS_MEASURE_CROPPED 9    /* \since 0.4: 1 when a vertex is a cropped point (DBS_OPT_CROP): NaN for measures 0-6, in no summary and no count but DBS_DISTORTION_CROPPED */

/* Summary statistics of a measure over the non-degenerate triangles (pinned; \since 0.1),
 * in the measure's own unit. */
#define DBS_SUMMARY_MIN 0
#define DBS_SUMMARY_MEAN 1
#define DBS_SUMMARY_P95 2 /* 95th percentile, interpolated between order statistics */
#define DBS_SUMMARY_MAX 3

/* Whole-mesh figures for dbs_distortion_stat (pinned; \since 0.1). */
#define DBS_DISTORTION_TRIANGLES 0       /* measured triangles, a count */
#define DBS_DISTORTION_DEGENERATE 1      /* degenerate triangles, a count */
#define DBS_DISTORTION_FOLDED 2          /* folded triangles, a count */
#define DBS_DISTORTION_SCALE_U 3         /* the scaling applied to u (u' = scale * u), cloud units per unit of u */
#define DBS_DISTORTION_SCALE_V 4         /* the scaling applied to v, cloud units per unit of v */
#define DBS_DISTORTION_MESH_STRETCH_L2 5 /* Sander's L2 stretch of the mesh (3D-area-weighted RMS); 1 = isometric */
#define DBS_DISTORTION_CROPPED 6         /* \since 0.4: triangles with a cropped vertex (DBS_OPT_CROP), left out of every other figure, a count */

/** Distortion of the Delaunay mesh. A triangle is folded when the sign of det J times the
 *  sign of its 3D normal against a reference normal differs from the majority's, so a fold
 *  of the parameterization shows although every Delaunay triangle turns the same way in
 *  (u,v). The reference (since 0.4) is the cloud's own normal at the triangle's vertices,
 *  oriented by the fold measure (DBS_STAT_FOLDED_SHARE's; the measure of every point not left
 *  out, or above 200,000 of them of an even sample of 200,000, the others taking their nearest
 *  judged point's), or the base surface's normal at the triangle's (u,v) centre where it gives
 *  none; before 0.4 it was always the surface's, which turns over with a pleated surface and
 *  so marked the well-ordered triangles over a pleat as folded.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (scaling), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_mesh_distortion(const dbs_mesh *mesh, int32_t scaling, dbs_distortion **out);
/** Distortion of the caller's mesh over the parameterized cloud: `triangles` holds
 *  3*n_triangles vertex indices into the cloud (NULL allowed when n_triangles is 0); folds
 *  judged as in dbs_mesh_distortion, so a mesh of either orientation works. Uses all
 *  hardware threads.
 *  Returns DBS_ERR_NULL_ARGUMENT (triangles only when n_triangles > 0), DBS_ERR_OUT_OF_RANGE
 *  (scaling; a vertex index outside the cloud), DBS_ERR_INVALID_ARGUMENT (the cloud's size
 *  differs from the result's; a triangle count no array can have), DBS_ERR_NUMERICAL (no
 *  surface normal at a triangle's centre), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_distortion_create(const dbs_result *result, const dbs_cloud *cloud, const int32_t *triangles, size_t n_triangles, int32_t scaling, dbs_distortion **out);
/** Frees the distortion; NULL is ignored. Not while another call uses it. \since 0.1 */
DBS_API void dbs_distortion_destroy(dbs_distortion *distortion);
/** A whole-mesh figure (DBS_DISTORTION_*), in the unit given beside its id.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (stat). \since 0.1 */
DBS_API int dbs_distortion_stat(const dbs_distortion *distortion, int32_t stat, double *out);
/** A summary (DBS_SUMMARY_*) of a measure (DBS_MEASURE_CONFORMAL .. DBS_MEASURE_SIGMA2); 0 when no triangle counts.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (measure or summary). \since 0.1 */
DBS_API int dbs_distortion_summary(const dbs_distortion *distortion, int32_t measure, int32_t summary, double *out);
/** One measure (DBS_MEASURE_*) per triangle, in triangle order, into `out`, which holds `capacity` values.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (measure), DBS_ERR_BUFFER_TOO_SMALL.
 *  \since 0.1 */
DBS_API int dbs_distortion_values(const dbs_distortion *distortion, int32_t measure, double *out, size_t capacity);

/** Statistics of a result's point-to-surface distances. \since 0.1 */
typedef struct dbs_distances dbs_distances;

/* Distance statistics (pinned ids; \since 0.1) for dbs_distances_stat. */
#define DBS_DISTANCES_COUNT 0     /* points counted, a count */
#define DBS_DISTANCES_MEAN 1      /* mean distance, cloud units */
#define DBS_DISTANCES_RMS 2       /* root mean square distance, cloud units */
#define DBS_DISTANCES_MAX 3       /* largest distance, cloud units */
#define DBS_DISTANCES_P50 4 /* percentiles interpolated between order statistics, cloud units */
#define DBS_DISTANCES_P90 5
#define DBS_DISTANCES_P95 6
#define DBS_DISTANCES_P99 7
#define DBS_DISTANCES_WITHIN 8    /* share of the points with distance <= tolerance, in [0,1] */
#define DBS_DISTANCES_TOLERANCE 9 /* the tolerance used, cloud units */

/** Statistics of the point-to-surface distances of a result, overall and per patch; since
 *  0.4 without the points far outside the cloud's body (DBS_STAT_FAR_POINTS), as the
 *  result's own mean and max distance.
 *  `tolerance` >= 0 in cloud units; 0 = the result's accuracy target (DBS_STAT_ACCURACY).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_NON_FINITE (tolerance), DBS_ERR_OUT_OF_RANGE
 *  (a negative tolerance), DBS_ERR_NO_MEMORY. \since 0.1 */
DBS_API int dbs_distances_create(const dbs_result *result, double tolerance, dbs_distances **out);
/** Frees the statistics; NULL is ignored. Not while another call uses them. \since 0.1 */
DBS_API void dbs_distances_destroy(dbs_distances *distances);
/** A statistic (DBS_DISTANCES_*) over all points (patch = -1) or over the points a patch
 *  parameterized (a patch id; 0 points and all statistics 0 for a patch that is no leaf).
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_OUT_OF_RANGE (patch or stat). \since 0.1 */
DBS_API int dbs_distances_stat(const dbs_distances *distances, int32_t patch, int32_t stat, double *out);

/** Writes a validation report into `dir` (created if missing): mesh.obj + mesh.mtl +
 *  mesh_texture.png, mesh.ply, view.png (the mesh shaded and textured with the disks),
 *  domain.png (the parameter domain: leaf rectangles, triangles coloured by conformal
 *  distortion, suspicious and folded ones marked), distances.png (histogram) and
 *  summary.json (options, timings, quadtree, patches, distances, mesh, distortion for both
 *  scalings). `options` are those the result was made with (NULL: the defaults); the
 *  distance tolerance is the result's accuracy target. Uses the thread count of `options`.
 *  Existing files are replaced; on failure some files may already be written. The files
 *  are described in docs/FORMATS.md. Needs DBS_FEATURE_REPORT.
 *  Returns DBS_ERR_NULL_ARGUMENT (result, cloud or dir), DBS_ERR_INVALID_ARGUMENT (the
 *  cloud's size differs from the result's), DBS_ERR_DEGENERATE, DBS_ERR_NUMERICAL (as
 *  dbs_mesh_create), DBS_ERR_IO (cannot create the directory or write a file),
 *  DBS_ERR_UNSUPPORTED (built without the report or the validation), DBS_ERR_NO_MEMORY.
 *  \since 0.1 */
DBS_API int dbs_report_write(const dbs_result *result, const dbs_cloud *cloud, const dbs_options *options, const char *dir);
/** The report of a boundary against its cloud, into directory `dir` (created if missing):
 *  boundary.png (960 x 520: two 480 x 480 views, along the cloud's least principal axis and
 *  from the side: the points in grey, the sides in colours (bottom red, right green, top blue,
 *  left orange), the corners labelled (0,0), (1,0), (1,1), (0,1), the holes of a boundary
 *  found by dbs_boundary_detect or dbs_boundary_from_corners in magenta) and boundary.json
 *  (the sides' point counts and lengths, the corners, the holes' point counts and lengths;
 *  docs/FORMATS.md). Existing files are replaced. Needs DBS_FEATURE_REPORT.
 *  Returns DBS_ERR_NULL_ARGUMENT, DBS_ERR_INVALID_ARGUMENT (an empty cloud), DBS_ERR_IO
 *  (cannot create the directory or write a file), DBS_ERR_UNSUPPORTED (built without the
 *  report), DBS_ERR_NO_MEMORY. \since 0.4 */
DBS_API int dbs_boundary_report_write(const dbs_boundary *boundary, const dbs_cloud *cloud, const char *dir);

#ifdef __cplusplus
}
#endif
#endif /* DBS_H */
