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
#define DBS_VERSION_MINOR 2
#define DBS_VERSION_PATCH 0
/** MAJOR*10000 + MINOR*100 + PATCH */
#define DBS_VERSION_NUMBER (DBS_VERSION_MAJOR * 10000 + DBS_VERSION_MINOR * 100 + DBS_VERSION_PATCH)
/** Non-zero when the header is at least version maj.min.pat. */
#define DBS_AT_LEAST_VERSION(maj, min, pat) (DBS_VERSION_NUMBER >= ((maj) * 10000 + (min) * 100 + (pat)))

/** Version of the library actually loaded, as DBS_VERSION_NUMBER. */
DBS_API int32_t dbs_version_number(void);
/** Version of the library actually loaded, "MAJOR.MINOR.PATCH"; static storage. */
DBS_API const char *dbs_version_string(void);

/* Optional parts of the loaded library (pinned ids) for dbs_has_feature. */
#define DBS_FEATURE_DRACO 0      /* Draco: clouds from .ply, .obj, .drc (dbs_cloud_load) and results to .drc (dbs_result_save) */
#define DBS_FEATURE_VALIDATION 1 /* \since 0.2: dbs_mesh_*, dbs_distortion_*, dbs_distances_* (Qhull) */
#define DBS_FEATURE_REPORT 2     /* \since 0.2: dbs_report_write and the textured .obj of dbs_mesh_save (libpng) */
/** Sets *out to 1 when the loaded library was built with `feature` (DBS_FEATURE_*), else 0;
 *  DBS_ERR_OUT_OF_RANGE for an id not listed. Without a feature, the calls that need it
 *  fail with DBS_ERR_UNSUPPORTED. */
DBS_API int dbs_has_feature(int32_t feature, int32_t *out);

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

/* Option ids (pinned). Each comment: type, default, range. The typed setters and getters
 * refuse an option of the other type (DBS_ERR_INVALID_ARGUMENT). Because of the two cross
 * rules (initial grid <= max grid, own <= near), order matters: raise DBS_OPT_MAX_GRID before
 * setting DBS_OPT_INITIAL_GRID above it. */
#define DBS_OPT_ACCURACY 0          /* double; 0 = unset; >= 0. Mean-distance target in cloud units. */
#define DBS_OPT_RELATIVE_ACCURACY 1 /* double; 1e-3; [1e-9, 1]. Target as a fraction of the diagonal of the cloud's bounding box, measured in the frame of the boundary's corners (so that a rigid motion does not change it), used while DBS_OPT_ACCURACY is 0. */
#define DBS_OPT_MAX_LEVEL 2         /* int; 4; [0, 8]. Quadtree depth; 0 = a single base surface. */
#define DBS_OPT_INITIAL_GRID 3      /* int; 5; [3, 100]. Grid points per side of a new patch. */
#define DBS_OPT_MAX_GRID 4          /* int; 11; [3, 200], >= initial grid. Largest grid before subdividing. */
#define DBS_OPT_SMOOTHING 5         /* double; 0.5; [0, 0.99]. Weight gamma of eq. (6). */
#define DBS_OPT_SOLVER 6            /* int; DBS_SOLVER_LINEAR; [0, 1]. */
#define DBS_OPT_THREADS 7           /* int; 0 = all hardware threads; [0, 256]. Output never depends on it. */
#define DBS_OPT_SUBCLOUD_NEAR 8     /* double; 0.25; (0, 10]. A4.3 "near" limit, fraction of the diagonal of the child's bounding box in the frame of its corners. */
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
/** Documented range of any option (integer options report theirs as doubles). An open end
 *  is reported as its limit (DBS_OPT_SUBCLOUD_NEAR: min 0, which itself is refused) and a
 *  missing upper end as DBL_MAX (DBS_OPT_ACCURACY). */
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
#define DBS_STAT_SECONDS_INDEX 11        /* wall-clock time spent indexing the cloud */
#define DBS_STAT_SECONDS_EVOLVE 12       /* ... evolving base surfaces (all levels) */
#define DBS_STAT_SECONDS_SUBDIVIDE 13    /* ... subdividing patches and splitting subclouds */
#define DBS_STAT_SECONDS_PARAMETERIZE 14 /* ... projecting every point onto its leaves (A2) */
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

/* ---- validation ------------------------------------------------------------------- */
/* The four judgements of a parameterization of the paper's section 7, as numbers and files:
 * (a) a mesh of the cloud from the 2D Delaunay triangulation of its (u,v), with the triangles
 * that bridge across the surface flagged; (b) how much each triangle is distorted between 3D
 * and (u,v); (c) a texture of black disks mapped through (u,v) (dbs_mesh_save and the
 * report); (d) the point-to-surface distances, per leaf patch and overall. */
typedef struct dbs_mesh dbs_mesh;

/** A triangle is suspicious when one of its 3D edges is longer than this many times the
 *  local spacing of both its end points (a point's distance to its 6th nearest other point):
 *  the mesh bridges across the surface, or along a ragged outline of the cloud. */
#define DBS_MESH_SUSPICIOUS_FACTOR 4.0

/** Triangulates the result's (u,v) in the plane (2D Delaunay, Qhull) and takes the triangles
 *  over `cloud`, the cloud that was parameterized: vertex i is cloud point i. Triangles are
 *  counter-clockwise in (u,v); a point whose (u,v) coincides with another's is the vertex of
 *  no triangle. DBS_ERR_INVALID_ARGUMENT when the cloud's size differs from the result's,
 *  DBS_ERR_DEGENERATE when the (u,v) do not span the plane. */
DBS_API int dbs_mesh_create(const dbs_result *result, const dbs_cloud *cloud, dbs_mesh **out);
DBS_API void dbs_mesh_destroy(dbs_mesh *mesh);
/** Number of vertices (the cloud's point count). */
DBS_API int dbs_mesh_vertex_count(const dbs_mesh *mesh, size_t *out);
/** Vertex positions (the cloud's points) into `out_xyz`, which holds `capacity` points. */
DBS_API int dbs_mesh_vertices(const dbs_mesh *mesh, double *out_xyz, size_t capacity);
/** Vertex parameters u0 v0 u1 v1 ... into `out_uv`, which holds `capacity` pairs. */
DBS_API int dbs_mesh_uv(const dbs_mesh *mesh, double *out_uv, size_t capacity);
DBS_API int dbs_mesh_triangle_count(const dbs_mesh *mesh, size_t *out);
/** Vertex indices a0 b0 c0 a1 b1 c1 ... into `out`, which holds `capacity` triangles. */
DBS_API int dbs_mesh_triangles(const dbs_mesh *mesh, int32_t *out, size_t capacity);
DBS_API int dbs_mesh_suspicious_count(const dbs_mesh *mesh, size_t *out);
/** Indices (ascending) of the suspicious triangles into `out`, which holds `capacity` values. */
DBS_API int dbs_mesh_suspicious(const dbs_mesh *mesh, int32_t *out, size_t capacity);
/** Writes the mesh by extension: .obj with vt = (u,v), plus STEM.mtl and the disk texture
 *  STEM_texture.png beside it (so any viewer shows method (c)); or binary .ply with float
 *  x y z u v per vertex. Other extensions are DBS_ERR_UNSUPPORTED. */
DBS_API int dbs_mesh_save(const dbs_mesh *mesh, const char *path);

typedef struct dbs_distortion dbs_distortion;

/* How the (u,v) domain is scaled before triangles are compared (pinned). Both end with the
 * total (u,v) area of the measured triangles equal to their total 3D area. */
#define DBS_SCALING_UNIFORM 0  /* u and v alike: [0,1]^2's aspect ratio counts as distortion */
#define DBS_SCALING_PER_AXIS 1 /* u and v first by the surface's typical (3D-area-weighted median) speed along each */

/* Per-triangle measures (pinned). J maps the 3D triangle (in its plane) to its scaled (u,v)
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

/* Summary statistics of a measure over the non-degenerate triangles (pinned). */
#define DBS_SUMMARY_MIN 0
#define DBS_SUMMARY_MEAN 1
#define DBS_SUMMARY_P95 2 /* 95th percentile, interpolated between order statistics */
#define DBS_SUMMARY_MAX 3

/* Whole-mesh figures for dbs_distortion_stat (pinned). */
#define DBS_DISTORTION_TRIANGLES 0       /* measured triangles */
#define DBS_DISTORTION_DEGENERATE 1      /* degenerate triangles */
#define DBS_DISTORTION_FOLDED 2          /* folded triangles */
#define DBS_DISTORTION_SCALE_U 3         /* the scaling applied to u */
#define DBS_DISTORTION_SCALE_V 4         /* the scaling applied to v */
#define DBS_DISTORTION_MESH_STRETCH_L2 5 /* Sander's L2 stretch of the mesh (3D-area-weighted RMS); 1 = isometric */

/** Distortion of the Delaunay mesh. A triangle is folded when the sign of det J times the
 *  sign of its 3D normal against the base surface's normal differs from the majority's, so
 *  a fold of the parameterization shows although every Delaunay triangle turns the same way in (u,v). */
DBS_API int dbs_mesh_distortion(const dbs_mesh *mesh, int32_t scaling, dbs_distortion **out);
/** Distortion of the caller's mesh over the parameterized cloud: `triangles` holds
 *  3*n_triangles vertex indices into the cloud (NULL allowed when n_triangles is 0); folds
 *  judged as in dbs_mesh_distortion, so a mesh of either orientation works. */
DBS_API int dbs_distortion_create(const dbs_result *result, const dbs_cloud *cloud, const int32_t *triangles, size_t n_triangles, int32_t scaling, dbs_distortion **out);
DBS_API void dbs_distortion_destroy(dbs_distortion *distortion);
/** A whole-mesh figure (DBS_DISTORTION_*). */
DBS_API int dbs_distortion_stat(const dbs_distortion *distortion, int32_t stat, double *out);
/** A summary (DBS_SUMMARY_*) of a measure (DBS_MEASURE_CONFORMAL .. DBS_MEASURE_SIGMA2); 0 when no triangle counts. */
DBS_API int dbs_distortion_summary(const dbs_distortion *distortion, int32_t measure, int32_t summary, double *out);
/** One measure (DBS_MEASURE_*) per triangle, in triangle order, into `out`, which holds `capacity` values. */
DBS_API int dbs_distortion_values(const dbs_distortion *distortion, int32_t measure, double *out, size_t capacity);

typedef struct dbs_distances dbs_distances;

/* Distance statistics (pinned ids) for dbs_distances_stat. */
#define DBS_DISTANCES_COUNT 0
#define DBS_DISTANCES_MEAN 1
#define DBS_DISTANCES_RMS 2
#define DBS_DISTANCES_MAX 3
#define DBS_DISTANCES_P50 4 /* percentiles interpolated between order statistics */
#define DBS_DISTANCES_P90 5
#define DBS_DISTANCES_P95 6
#define DBS_DISTANCES_P99 7
#define DBS_DISTANCES_WITHIN 8    /* share of the points with distance <= tolerance, in [0,1] */
#define DBS_DISTANCES_TOLERANCE 9 /* the tolerance used */

/** Statistics of the point-to-surface distances of a result, overall and per patch.
 *  `tolerance` >= 0 in cloud units; 0 = the result's accuracy target (DBS_STAT_ACCURACY). */
DBS_API int dbs_distances_create(const dbs_result *result, double tolerance, dbs_distances **out);
DBS_API void dbs_distances_destroy(dbs_distances *distances);
/** A statistic (DBS_DISTANCES_*) over all points (patch = -1) or over the points a patch
 *  parameterized (a patch id; 0 points and all statistics 0 for a patch that is no leaf). */
DBS_API int dbs_distances_stat(const dbs_distances *distances, int32_t patch, int32_t stat, double *out);

/** Writes a validation report into `dir` (created if missing): mesh.obj + mesh.mtl +
 *  mesh_texture.png, mesh.ply, view.png (the mesh shaded and textured with the disks),
 *  domain.png (the parameter domain: leaf rectangles, triangles coloured by conformal
 *  distortion, suspicious and folded ones marked), distances.png (histogram) and
 *  summary.json (options, timings, quadtree, patches, distances, mesh, distortion for both
 *  scalings). `options` are those the result was made with (NULL: the defaults); the
 *  distance tolerance is the result's accuracy target. */
DBS_API int dbs_report_write(const dbs_result *result, const dbs_cloud *cloud, const dbs_options *options, const char *dir);

#ifdef __cplusplus
}
#endif
#endif /* DBS_H */
