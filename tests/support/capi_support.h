/* Shared helpers of the C API tests: test geometry, temporary files, status checks. */
#ifndef DBS_CAPI_SUPPORT_H
#define DBS_CAPI_SUPPORT_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>

#include <cmocka.h>

#include "dbs.h"

/* The planar test case: the rectangle [0, W] x [0, H] in the plane z = Z, sampled on an
 * nx x ny grid of points (boundary included). Its parameterization is the affine map
 * u = x / W, v = y / H. */
#define PLANE_W 2.0
#define PLANE_H 1.0
#define PLANE_Z 0.5

/* nx * ny points of the plane, row by row (x fastest); the caller frees the array. */
double *plane_points(int nx, int ny);
/* The plane as a cloud; fails the test if creation fails. */
dbs_cloud *plane_cloud(int nx, int ny);
/* The plane's rectangle, each side with `per_side` evenly spaced points (>= 2). */
dbs_boundary *plane_boundary(int per_side);

/* The unit square with the height field z = amplitude * sin(pi x) sin(pi y), sampled on an
 * n x n grid: a surface that one patch cannot fit to a small accuracy. */
dbs_cloud *bump_cloud(int n, double amplitude);
/* The unit square's boundary at z = 0, `per_side` points per side. */
dbs_boundary *square_boundary(int per_side);

/* Parameterizes, failing the test on any error; the caller destroys the result. */
dbs_result *parameterize_or_fail(const dbs_cloud *cloud, const dbs_boundary *boundary, const dbs_options *options);

/* A path in the test's temporary directory, unique to this process (DIR/PID_name); the file
 * is removed when the program exits. */
void temp_path(char *buffer, size_t size, const char *name);
/* Writes `text` to `path`, failing the test if that is impossible. */
void write_text(const char *path, const char *text);
/* The whole content of the file at `path`, NUL-terminated (binary content may hold more NULs),
 * its size in *out_size when that is not NULL; the caller frees it. */
char *read_all(const char *path, size_t *out_size);
/* temp_path(name) holding `text`: a fresh temporary file, its path in `buffer`. */
void temp_file(char *buffer, size_t size, const char *name, const char *text);

/* The loaders whose file errors assert_load_error checks. */
enum load_kind { LOAD_CLOUD, LOAD_BOUNDARY };
/* Writes `text` into the temporary file `name` (text NULL: makes sure there is no such file),
 * loads it with dbs_cloud_load or dbs_boundary_load and asserts that the load fails with
 * `expected`, a message naming the file (as "PATH:LINE" when `line` > 0) and holding `needle`
 * (when not NULL), and that the output handle is left untouched. */
#define assert_load_error(kind, name, text, line, expected, needle) \
  check_load_error((kind), (name), (text), (line), (expected), (needle), __FILE__, __LINE__)
void check_load_error(enum load_kind kind, const char *name, const char *text, int line, int expected, const char *needle, const char *file, int source_line);

/* 1 when the loaded libdbs has Draco (dbs_has_feature), else 0. */
int has_draco(void);
/* 1 when the loaded libdbs reads `path`: a .ply or .obj file in every build (since 0.4), a
 * .drc file when it has Draco. Without Draco, asserts that loading a .drc file is refused as
 * unsupported, naming Draco, and returns 0: the caller then skips what only Draco can read. */
int reads_with_draco(const char *path);

/* Asserts that `status` equals `expected` and that the thread's last error message starts
 * with "function:" and contains `needle` (skipped when NULL); prints the message on failure. */
#define assert_failure(status, expected, function, needle) \
  check_failure((status), (expected), (function), (needle), __FILE__, __LINE__)
void check_failure(int status, int expected, const char *function, const char *needle, const char *file, int line);

/* Asserts DBS_OK, printing the last error message otherwise. */
#define assert_ok(status) check_ok((status), #status, __FILE__, __LINE__)
void check_ok(int status, const char *call, const char *file, int line);

#endif
