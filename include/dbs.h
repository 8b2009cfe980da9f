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
 *  - Callbacks are always called on the thread that called dbs_parameterize(), never
 *    from a worker thread, so they need no locking of their own.
 *  - No exception, C++ type or abort() crosses this interface. The library holds no
 *    global mutable state except the per-thread last-error message.
 *  - Only fixed-width integers, double, size_t, pointers and handles appear in
 *    prototypes (no bool, no struct by value), so Fortran (bind(C)) and Python
 *    (ctypes) bindings are mechanical. Every prototype sits on one line.
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
#define DBS_VERSION_MAJOR 0
#define DBS_VERSION_MINOR 1
#define DBS_VERSION_PATCH 0
/** MAJOR*10000 + MINOR*100 + PATCH */
#define DBS_VERSION_NUMBER (DBS_VERSION_MAJOR * 10000 + DBS_VERSION_MINOR * 100 + DBS_VERSION_PATCH)
/** Non-zero when the header is at least version maj.min.pat. */
#define DBS_AT_LEAST_VERSION(maj, min, pat) (DBS_VERSION_NUMBER >= ((maj) * 10000 + (min) * 100 + (pat)))

/** Version of the library actually loaded, as DBS_VERSION_NUMBER. */
DBS_API int32_t dbs_version_number(void);
/** Version of the library actually loaded, "MAJOR.MINOR.PATCH"; static storage. */
DBS_API const char *dbs_version_string(void);

/* ---- status codes (pinned: never renumbered) ------------------------------------ */
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
 *  never NULL ("unknown status" for codes not listed above). */
DBS_API const char *dbs_status_string(int status);

/** Message of the last failed call on this thread; "" when none failed yet.
 *  The string is owned by the library and stays valid until the next libdbs call
 *  on the same thread. Successful calls do not clear it. */
DBS_API const char *dbs_last_error_message(void);

/* ---- point clouds ------------------------------------------------------------ */
typedef struct dbs_cloud dbs_cloud;

/** Copies `count` points from `xyz` (3*count doubles). count >= 1, all finite. */
DBS_API int dbs_cloud_create(const double *xyz, size_t count, dbs_cloud **out);
/** Loads .xyz/.txt (text), .ply, .obj or .drc (the extension decides); see FORMATS.md. */
DBS_API int dbs_cloud_load(const char *path, dbs_cloud **out);
DBS_API void dbs_cloud_destroy(dbs_cloud *cloud);
DBS_API int dbs_cloud_count(const dbs_cloud *cloud, size_t *out);
/** Axis-aligned bounding box: out_min and out_max receive 3 doubles each. */
DBS_API int dbs_cloud_bounds(const dbs_cloud *cloud, double *out_min, double *out_max);
/** Copies all points into `out_xyz`, which holds `capacity` points. */
DBS_API int dbs_cloud_points(const dbs_cloud *cloud, double *out_xyz, size_t capacity);

/* ---- boundaries ---------------------------------------------------------------- */
typedef struct dbs_boundary dbs_boundary;

#define DBS_SIDE_BOTTOM 0
#define DBS_SIDE_RIGHT 1
#define DBS_SIDE_TOP 2
#define DBS_SIDE_LEFT 3

/** Four polylines (each >= 2 finite points) with the corner conventions above.
 *  Corners may miss each other by at most 1e-6 of the boundary's bounding-box diagonal;
 *  they are then made to coincide exactly. Larger misses, zero-length sides and a
 *  boundary of zero area are DBS_ERR_DEGENERATE. */
DBS_API int dbs_boundary_create(const double *bottom, size_t n_bottom, const double *right, size_t n_right, const double *top, size_t n_top, const double *left, size_t n_left, dbs_boundary **out);
/** Loads a boundary file (FORMATS.md: sections bottom/right/top/left). */
DBS_API int dbs_boundary_load(const char *path, dbs_boundary **out);
DBS_API void dbs_boundary_destroy(dbs_boundary *boundary);
/** Number of points of one side (DBS_SIDE_*). */
DBS_API int dbs_boundary_side_count(const dbs_boundary *boundary, int32_t side, size_t *out);
/** Copies one side's points into `out_xyz`, which holds `capacity` points. */
DBS_API int dbs_boundary_side_points(const dbs_boundary *boundary, int32_t side, double *out_xyz, size_t capacity);

/* ---- options ------------------------------------------------------------------ */
typedef struct dbs_options dbs_options;

/* Option ids (pinned). Each comment: type, default, range. */
#define DBS_OPT_ACCURACY 0          /* double; 0 = unset; >= 0. Mean-distance target in cloud units. */
#define DBS_OPT_RELATIVE_ACCURACY 1 /* double; 1e-3; [1e-9, 1]. Target as a fraction of the cloud's bounding-box diagonal, used while DBS_OPT_ACCURACY is 0. */
#define DBS_OPT_MAX_LEVEL 2         /* int; 4; [0, 8]. Quadtree depth; 0 = a single base surface. */
#define DBS_OPT_INITIAL_GRID 3      /* int; 5; [3, 100]. Grid points per side of a new patch. */
#define DBS_OPT_MAX_GRID 4          /* int; 11; [3, 200], >= initial grid. Largest grid before subdividing. */
#define DBS_OPT_SMOOTHING 5         /* double; 0.5; [0, 0.99]. Weight gamma of eq. (6). */
#define DBS_OPT_SOLVER 6            /* int; DBS_SOLVER_LINEAR. */
#define DBS_OPT_THREADS 7           /* int; 0 = all hardware threads; [0, 256]. Output never depends on it. */
#define DBS_OPT_SUBCLOUD_NEAR 8     /* double; 0.25; (0, 10]. A4.3 "near" limit, fraction of the child's diagonal. */
#define DBS_OPT_SUBCLOUD_OWN 9      /* double; 0.05; [0, 10], <= near. A4.4 "own" limit, fraction of the child's diagonal. */

#define DBS_SOLVER_LINEAR 0 /* banded linear least squares (always available) */
#define DBS_SOLVER_CERES 1  /* Ceres refinement: DBS_ERR_UNSUPPORTED until it is implemented */

/** Progress: `fraction` rises monotonically in [0,1] and the last call has exactly 1.0;
 *  `stage` names the running stage ("index", "evolve", "subdivide", "parameterize", "done").
 *  Return 0 to go on, non-zero to cancel. */
typedef int (*dbs_progress_fn)(double fraction, const char *stage, void *payload);

/** A read-only view of a set of base-surface patches (one quadtree level in the level
 *  callback, the whole quadtree in a result); read with the dbs_patches_* functions. */
typedef struct dbs_patches dbs_patches;

/** Called once per finished quadtree level (0 = the root) with that level's patches.
 *  `patches` is valid only during the call. Return 0 to go on, non-zero to cancel. */
typedef int (*dbs_level_fn)(int32_t level, const dbs_patches *patches, void *payload);

DBS_API int dbs_options_create(dbs_options **out);
DBS_API int dbs_options_clone(const dbs_options *options, dbs_options **out);
DBS_API void dbs_options_destroy(dbs_options *options);
/** Integer options (DBS_OPT_MAX_LEVEL, _INITIAL_GRID, _MAX_GRID, _SOLVER, _THREADS). */
DBS_API int dbs_options_set_int(dbs_options *options, int32_t option, int32_t value);
DBS_API int dbs_options_get_int(const dbs_options *options, int32_t option, int32_t *out);
/** Real options (DBS_OPT_ACCURACY, _RELATIVE_ACCURACY, _SMOOTHING, _SUBCLOUD_NEAR, _SUBCLOUD_OWN). */
DBS_API int dbs_options_set_double(dbs_options *options, int32_t option, double value);
DBS_API int dbs_options_get_double(const dbs_options *options, int32_t option, double *out);
/** Documented range of any option (integer options report theirs as doubles). */
DBS_API int dbs_option_bounds(int32_t option, double *out_min, double *out_max);
/** Sets (or with fn == NULL clears) the progress callback. */
DBS_API int dbs_options_set_progress(dbs_options *options, dbs_progress_fn fn, void *payload);
/** Sets (or with fn == NULL clears) the per-level inspection callback. */
DBS_API int dbs_options_set_level_callback(dbs_options *options, dbs_level_fn fn, void *payload);

/* ---- parameterization ------------------------------------------------------------ */
typedef struct dbs_result dbs_result;

/** Parameterizes `cloud` inside `boundary`. `options` may be NULL for the defaults. */
DBS_API int dbs_parameterize(const dbs_cloud *cloud, const dbs_boundary *boundary, const dbs_options *options, dbs_result **out);
DBS_API void dbs_result_destroy(dbs_result *result);

/** Number of parameterized points (equals the cloud's count, input order kept). */
DBS_API int dbs_result_point_count(const dbs_result *result, size_t *out);
/** u0 v0 u1 v1 ... into `out_uv`, which holds `capacity` pairs. */
DBS_API int dbs_result_uv(const dbs_result *result, double *out_uv, size_t capacity);
/** Distance of each point to the base surface. */
DBS_API int dbs_result_distances(const dbs_result *result, double *out, size_t capacity);
/** Id of the leaf patch that parameterized each point (an index for dbs_patches_*). */
DBS_API int dbs_result_point_patches(const dbs_result *result, int32_t *out, size_t capacity);
/** Quadtree level of that leaf for each point. */
DBS_API int dbs_result_point_levels(const dbs_result *result, int32_t *out, size_t capacity);

/** Point (and, if out_normal is not NULL, unit normal) of the base surface at (u,v) in [0,1]^2. */
DBS_API int dbs_result_evaluate(const dbs_result *result, double u, double v, double *out_xyz, double *out_normal);

/* Summary statistics (pinned ids) for dbs_result_stat. */
#define DBS_STAT_MEAN_DISTANCE 0 /* mean point-to-surface distance */
#define DBS_STAT_MAX_DISTANCE 1
#define DBS_STAT_RMS_DISTANCE 2
#define DBS_STAT_ACCURACY 3      /* the mean-distance target that was used, in cloud units */
#define DBS_STAT_ACCURACY_MET 4  /* 1 when every leaf met the target, else 0 */
#define DBS_STAT_LEVELS 5        /* number of quadtree levels (1 = root only) */
#define DBS_STAT_PATCHES 6       /* number of patches in the quadtree */
#define DBS_STAT_LEAVES 7        /* number of leaf patches */
#define DBS_STAT_ITERATIONS 8    /* grid evolutions over all patches */
#define DBS_STAT_SECONDS 9       /* wall-clock time of dbs_parameterize */
#define DBS_STAT_LENGTH_SCALE 10 /* the cloud's length scale h (mean nearest-neighbour spacing) */
DBS_API int dbs_result_stat(const dbs_result *result, int32_t stat, double *out);

/** The result's quadtree: all patches, indexed by patch id; valid while `result` lives. */
DBS_API int dbs_result_patches(const dbs_result *result, const dbs_patches **out);

/** Writes .csv, .ply or .drc (the extension decides; FORMATS.md). `cloud` is the cloud
 *  that was parameterized (its points are written in .ply and .drc). */
DBS_API int dbs_result_save(const dbs_result *result, const dbs_cloud *cloud, const char *path);

/* ---- patches ---------------------------------------------------------------------- */
DBS_API int dbs_patches_count(const dbs_patches *patches, size_t *out);
/** Patch id (the index used by dbs_result_point_patches) of the i-th patch of the view. */
DBS_API int dbs_patches_id(const dbs_patches *patches, size_t i, int32_t *out);
DBS_API int dbs_patches_level(const dbs_patches *patches, size_t i, int32_t *out);
/** 1 for a leaf, 0 for a patch that was subdivided. */
DBS_API int dbs_patches_is_leaf(const dbs_patches *patches, size_t i, int32_t *out);
/** Id of the parent patch, -1 for the root. */
DBS_API int dbs_patches_parent(const dbs_patches *patches, size_t i, int32_t *out);
/** The patch's rectangle of the global domain: u0 v0 u1 v1 into out_rect (4 doubles). */
DBS_API int dbs_patches_rect(const dbs_patches *patches, size_t i, double *out_rect);
/** Grid size: points along u and along v. */
DBS_API int dbs_patches_grid_size(const dbs_patches *patches, size_t i, int32_t *out_nu, int32_t *out_nv);
/** Grid points, u fastest: point (iu, iv) at index iv*nu + iu; `capacity` in points. */
DBS_API int dbs_patches_grid_points(const dbs_patches *patches, size_t i, double *out_xyz, size_t capacity);
DBS_API int dbs_patches_boundary_count(const dbs_patches *patches, size_t i, int32_t side, size_t *out);
DBS_API int dbs_patches_boundary_points(const dbs_patches *patches, size_t i, int32_t side, double *out_xyz, size_t capacity);
/** Points of the patch's subcloud, their mean and max distance to the patch, grid evolutions. */
DBS_API int dbs_patches_stats(const dbs_patches *patches, size_t i, size_t *out_points, double *out_mean, double *out_max, int32_t *out_iterations);

#ifdef __cplusplus
}
#endif
#endif /* DBS_H */
