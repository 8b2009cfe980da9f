/* The table of bad inputs (issue 14): each row feeds libdbs one bad input through the C API
 * and asserts its status and that the message holds the row's excerpt, and that the output
 * handle is untouched. docs/bad_inputs.md holds the same table with the messages libdbs
 * actually gives; this test regenerates it and fails when the file differs (run
 * `capi_test_bad_inputs --markdown > docs/bad_inputs.md` to refresh it after a change).
 * Rows that need the validation room expect DBS_ERR_UNSUPPORTED in a build without it, and
 * the file is compared only in a build with every feature. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "capi_support.h"

/* AddressSanitizer stops the process at an allocation no memory can hold, where libdbs
 * otherwise turns std::bad_alloc into DBS_ERR_NO_MEMORY: under it, the row that asks for one
 * is skipped (and the document, checked by the plain build, is not compared). */
#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif
#ifndef UNDER_ASAN
#define UNDER_ASAN 0
#endif

#define DIR DBS_TEST_TMP_DIR "/bad_inputs"
#define DOC DBS_TEST_DATA_DIR "/../docs/bad_inputs.md"

static char path_buffer[1024];

/* DIR/name holding `size` bytes of `bytes` (a string's length when size is 0). */
static const char *file_with(const char *name, const char *bytes, size_t size) {
  mkdir(DIR, 0777);
  snprintf(path_buffer, sizeof path_buffer, "%s/%s", DIR, name);
  FILE *f = fopen(path_buffer, "wb");
  assert_non_null(f);
  fwrite(bytes, 1, size ? size : strlen(bytes), f);
  assert_int_equal(fclose(f), 0);
  return path_buffer;
}

static const char *no_file(const char *name) {
  snprintf(path_buffer, sizeof path_buffer, "%s/%s", DIR, name);
  remove(path_buffer);
  return path_buffer;
}

static dbs_cloud *sentinel_cloud = (dbs_cloud *)(uintptr_t)0x1;
static dbs_boundary *sentinel_boundary = (dbs_boundary *)(uintptr_t)0x1;

/* Loads a cloud file; the handle must stay untouched on failure. */
static int load(const char *path) {
  dbs_cloud *out = sentinel_cloud;
  const int status = dbs_cloud_load(path, &out);
  if (status == DBS_OK) dbs_cloud_destroy(out);
  else assert_ptr_equal(out, sentinel_cloud);
  return status;
}

static int load_boundary(const char *path) {
  dbs_boundary *out = sentinel_boundary;
  const int status = dbs_boundary_load(path, &out);
  if (status == DBS_OK) dbs_boundary_destroy(out);
  else assert_ptr_equal(out, sentinel_boundary);
  return status;
}

/* The unit square's sides with the given points (3 doubles a point, 2 points a side unless
 * the count says otherwise). */
static int boundary(const double *b, size_t nb, const double *r, size_t nr, const double *t, size_t nt, const double *l, size_t nl) {
  dbs_boundary *out = sentinel_boundary;
  const int status = dbs_boundary_create(b, nb, r, nr, t, nt, l, nl, &out);
  if (status == DBS_OK) dbs_boundary_destroy(out);
  else assert_ptr_equal(out, sentinel_boundary);
  return status;
}

static const double B[] = {0, 0, 0, 1, 0, 0}, R[] = {1, 0, 0, 1, 1, 0}, T[] = {0, 1, 0, 1, 1, 0}, L[] = {0, 0, 0, 0, 1, 0};

/* The unit square scaled by `s`: an n x n grid cloud and its boundary. */
static void square(double s, int n, dbs_cloud **cloud, dbs_boundary **bound) {
  double *xyz = malloc(sizeof(double) * 3 * (size_t)n * (size_t)n);
  assert_non_null(xyz);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double *p = xyz + 3 * (j * n + i);
      p[0] = s * i / (n - 1), p[1] = s * j / (n - 1), p[2] = 0;
    }
  assert_ok(dbs_cloud_create(xyz, (size_t)(n * n), cloud));
  free(xyz);
  double b[6], r[6], t[6], l[6];
  for (int k = 0; k < 6; ++k) b[k] = s * B[k], r[k] = s * R[k], t[k] = s * T[k], l[k] = s * L[k];
  assert_ok(dbs_boundary_create(b, 2, r, 2, t, 2, l, 2, bound));
}

static int parameterize(dbs_cloud *cloud, dbs_boundary *bound, dbs_options *options) {
  dbs_result *out = (dbs_result *)(uintptr_t)0x1;
  const int status = dbs_parameterize(cloud, bound, options, &out);
  if (status == DBS_OK) dbs_result_destroy(out);
  else assert_ptr_equal(out, (dbs_result *)(uintptr_t)0x1);
  dbs_cloud_destroy(cloud);
  dbs_boundary_destroy(bound);
  dbs_options_destroy(options);
  return status;
}

static int square_scaled(double s) {
  dbs_cloud *c;
  dbs_boundary *b;
  square(s, 11, &c, &b);
  return parameterize(c, b, NULL);
}

static int cancel_at_once(double fraction, const char *stage, void *payload) {
  (void)fraction, (void)stage, (void)payload;
  return 1;
}

/* A result of the 11 x 11 unit square, for the rows on results and validation. */
static dbs_cloud *r_cloud;
static dbs_boundary *r_boundary;
static dbs_result *r_result;
static const dbs_patches *r_patches;

/* ---- the rows ---------------------------------------------------------------------- */

static int c_null(void) { dbs_cloud *o = sentinel_cloud; return dbs_cloud_create(NULL, 3, &o); }
static int c_zero(void) { dbs_cloud *o = sentinel_cloud; return dbs_cloud_create(B, 0, &o); }
static int c_nan(void) { const double p[] = {0, 0, 0, 1, NAN, 0}; dbs_cloud *o = sentinel_cloud; return dbs_cloud_create(p, 2, &o); }
static int c_inf(void) { const double p[] = {0, 0, INFINITY}; dbs_cloud *o = sentinel_cloud; return dbs_cloud_create(p, 1, &o); }
static int c_huge_count(void) { dbs_cloud *o = sentinel_cloud; return dbs_cloud_create(B, SIZE_MAX, &o); }
static int l_missing(void) { return load(no_file("missing.xyz")); }
static int l_ext(void) { return load(file_with("cloud.stl", "solid x\n", 0)); }
static int l_dir(void) { mkdir(DIR "/folder.xyz", 0777); return load(DIR "/folder.xyz"); }
static int l_empty(void) { return load(file_with("empty.xyz", "", 0)); }
static int l_comments(void) { return load(file_with("comments.xyz", "# only a comment\n\n", 0)); }
static int l_two(void) { return load(file_with("two.xyz", "0 0 0\n1 2\n", 0)); }
static int l_word(void) { return load(file_with("word.xyz", "0 0 0\n1 two 3\n", 0)); }
static int l_nan(void) { return load(file_with("nan.xyz", "0 0 0\nnan 0 0\n", 0)); }
static int l_overflow(void) { return load(file_with("overflow.xyz", "0 0 0\n1e400 0 0\n", 0)); }
static int l_nul(void) { return load(file_with("nul.xyz", "0 0 0\n1 \0 2\n", 12)); }
static int l_1e300(void) { return load(file_with("big.xyz", "0 0 0\n1e300 0 0\n", 0)); }
#define PLY_HEAD(fmt, n) "ply\nformat " fmt " 1.0\nelement vertex " n "\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
static int p_empty(void) { return load(file_with("empty.ply", "", 0)); }
static int p_magic(void) { return load(file_with("magic.ply", "plx\nformat ascii 1.0\n", 0)); }
static int p_version(void) { return load(file_with("version.ply", "ply\nformat ascii 2.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n", 0)); }
static int p_format(void) { return load(file_with("format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", 0)); }
static int p_two_vertex(void) {
  return load(file_with("two_vertex.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n", 0));
}
static int p_zero(void) { return load(file_with("zero.ply", PLY_HEAD("ascii", "0"), 0)); }
static int p_no_z(void) { return load(file_with("no_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n", 0)); }
static int p_no_end(void) { return load(file_with("no_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", 0)); }
static int p_short_row(void) { return load(file_with("short_row.ply", PLY_HEAD("ascii", "2") "1 2 3\n4 5\n", 0)); }
static int p_truncated(void) { char b[200] = PLY_HEAD("binary_little_endian", "2"); size_t n = strlen(b); memset(b + n, 0, 30); return load(file_with("truncated.ply", b, n + 30)); }
static int p_lying(void) { char b[300] = PLY_HEAD("binary_little_endian", "2147483647"); size_t n = strlen(b); memset(b + n, 0, 100); return load(file_with("lying.ply", b, n + 100)); }
static int p_lying_ascii(void) { return load(file_with("lying_ascii.ply", PLY_HEAD("ascii", "2147483647") "1 2 3\n", 0)); }
static int p_empty_elements(void) {
  /* 1 KB: 40 elements of 2^31 - 1 entries without properties before the vertices */
  char b[2048] = "ply\nformat binary_little_endian 1.0\n";
  for (int k = 0; k < 40; ++k) snprintf(b + strlen(b), sizeof b - strlen(b), "element junk%d 2147483647\n", k);
  strcat(b, "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n");
  const size_t n = strlen(b);
  const double p[3] = {1, 2, 3};
  memcpy(b + n, p, sizeof p);
  return load(file_with("empty_elements.ply", b, n + sizeof p));
}
static int p_faces_first(void) { return load(file_with("faces_first.ply", "ply\nformat binary_little_endian 1.0\nelement face 2147483647\nproperty list uchar int vertex_indices\n" "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n\003", 0)); }
static int p_negative_list(void) { return load(file_with("negative_list.ply", "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list char int vertex_indices\n" "element vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n\377", 0)); }
static int p_inf(void) { return load(file_with("inf.ply", PLY_HEAD("ascii", "1") "1 inf 3\n", 0)); }
static int p_exact(void) { return load(file_with("exact.ply", PLY_HEAD("ascii", "2") "500000.123 1e300 1.000000001\n0 0 0\n", 0)); }
static int o_empty(void) { return load(file_with("empty.obj", "", 0)); }
static int o_no_v(void) { return load(file_with("faces.obj", "vn 0 0 1\nf 1 2 3\n", 0)); }
static int o_two(void) { return load(file_with("two.obj", "v 0 0 0\nv 1 2\n", 0)); }
static int o_comma(void) { return load(file_with("comma.obj", "v 0,0,0\n", 0)); }
static int o_nan_obj(void) { return load(file_with("nan.obj", "v 0 nan 0\n", 0)); }
static int b_null(void) { dbs_boundary *o = sentinel_boundary; return dbs_boundary_create(NULL, 2, R, 2, T, 2, L, 2, &o); }
static int b_one_point(void) { return boundary(B, 1, R, 2, T, 2, L, 2); }
static int b_nan(void) { const double b[] = {0, 0, 0, NAN, 0, 0, 1, 0, 0}; return boundary(b, 3, R, 2, T, 2, L, 2); }
static int b_apart(void) { const double r[] = {1, 0.1, 0, 1, 1, 0}; return boundary(B, 2, r, 2, T, 2, L, 2); }
static int b_backwards(void) { const double t[] = {1, 1, 0, 0, 1, 0}; return boundary(B, 2, R, 2, t, 2, L, 2); }
static int b_swapped(void) { return boundary(B, 2, L, 2, T, 2, R, 2); }
static int b_dot(void) { const double d[] = {1, 1, 1, 1, 1, 1}; return boundary(d, 2, d, 2, d, 2, d, 2); }
static int b_zero_side(void) { const double t[] = {0, 1, 0, 0, 1, 0}, r[] = {1, 0, 0, 0, 1, 0}; return boundary(B, 2, r, 2, t, 2, L, 2); }
static int b_line(void) { const double b[] = {0, 0, 0, 10, 0, 0}, r[] = {10, 0, 0, 12, 0, 0, 10, 0, 0}, l[] = {0, 0, 0, -3, 0, 0, 0, 0, 0}; return boundary(b, 2, r, 3, b, 2, l, 3); }
static int b_overflow(void) { const double b[] = {-1e308, 0, 0, 1e308, 0, 0}, r[] = {1e308, 0, 0, 1e308, 1e308, 0}, t[] = {-1e308, 1e308, 0, 1e308, 1e308, 0}, l[] = {-1e308, 0, 0, -1e308, 1e308, 0}; return boundary(b, 2, r, 2, t, 2, l, 2); }
static int b_bow_tie(void) { const double b[] = {0, 0, 0, 1, 1, 0}, r[] = {1, 1, 0, 1, 0, 0}, t[] = {0, 1, 0, 1, 0, 0}; return boundary(b, 2, r, 2, t, 2, L, 2); }
static int b_across(void) { const double l[] = {0, 0, 0, 1.5, 0.4, 0, 1.5, 0.6, 0, 0, 1, 0}; return boundary(B, 2, R, 2, T, 2, l, 4); }
static int b_fold(void) { const double b[] = {0, 0, 0, 0.8, 0, 0, 0.3, 0, 0, 1, 0, 0}; return boundary(b, 4, R, 2, T, 2, L, 2); }
static int b_tolerance(void) { dbs_boundary *o = sentinel_boundary; return dbs_boundary_create_tolerant(B, 2, R, 2, T, 2, L, 2, -1.0, 1, NULL, &o); }
static int b_tolerance_big(void) { dbs_boundary *o = sentinel_boundary; return dbs_boundary_create_tolerant(B, 2, R, 2, T, 2, L, 2, 0.5, 1, NULL, &o); }
#define SIDES "bottom\n0 0 0\n1 0 0\nright\n1 0 0\n1 1 0\ntop\n0 1 0\n1 1 0\n"
static int f_missing(void) { return load_boundary(no_file("missing.txt")); }
static int f_empty(void) { return load_boundary(file_with("empty.txt", "# nothing\n", 0)); }
static int f_unknown(void) { return load_boundary(file_with("unknown.txt", SIDES "middle\n0 0 0\n", 0)); }
static int f_twice(void) { return load_boundary(file_with("twice.txt", SIDES "top\n0 1 0\n1 1 0\n", 0)); }
static int f_no_left(void) { return load_boundary(file_with("no_left.txt", SIDES, 0)); }
static int f_before(void) { return load_boundary(file_with("before.txt", "0 0 0\n" SIDES "left\n0 0 0\n0 1 0\n", 0)); }
static int f_four(void) { return load_boundary(file_with("four.txt", SIDES "left\n0 0 0 7\n0 1 0\n", 0)); }
static int f_one_point(void) { return load_boundary(file_with("one_point.txt", SIDES "left\n0 0 0\n", 0)); }
static int f_inf(void) { return load_boundary(file_with("inf.txt", SIDES "left\n0 0 0\n0 inf 0\n", 0)); }
static int f_bow_tie(void) { return load_boundary(file_with("bow_tie.txt", "bottom\n0 0 0\n1 1 0\nright\n1 1 0\n1 0 0\ntop\n0 1 0\n1 0 0\nleft\n0 0 0\n0 1 0\n", 0)); }
static const double LOOP[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
static int lp_order(void) { const size_t c[4] = {0, 2, 1, 3}; dbs_boundary *o = sentinel_boundary; return dbs_boundary_from_loop(LOOP, 4, c, &o); }
static int lp_index(void) { const size_t c[4] = {0, 1, 2, 9}; dbs_boundary *o = sentinel_boundary; return dbs_boundary_from_loop(LOOP, 4, c, &o); }
static int lp_three(void) { const size_t c[4] = {0, 1, 2, 0}; dbs_boundary *o = sentinel_boundary; return dbs_boundary_from_loop(LOOP, 3, c, &o); }
static dbs_options *fresh_options(void) { dbs_options *o = NULL; assert_ok(dbs_options_create(&o)); return o; }
static int o_unknown(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_int(o, 99, 1); dbs_options_destroy(o); return s; }
static int o_level(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_int(o, DBS_OPT_MAX_LEVEL, 9); dbs_options_destroy(o); return s; }
static int o_type(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_int(o, DBS_OPT_SMOOTHING, 1); dbs_options_destroy(o); return s; }
static int o_nan(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_double(o, DBS_OPT_SMOOTHING, NAN); dbs_options_destroy(o); return s; }
static int o_relative(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_double(o, DBS_OPT_RELATIVE_ACCURACY, 0.0); dbs_options_destroy(o); return s; }
static int o_grid(void) { dbs_options *o = fresh_options(); int s = dbs_options_set_int(o, DBS_OPT_INITIAL_GRID, 12); dbs_options_destroy(o); return s; }
static int o_feature(void) { int32_t v; return dbs_has_feature(99, &v); }
static int r_null(void) { dbs_result *o = NULL; return dbs_parameterize(NULL, r_boundary, NULL, &o); }
static int r_coincident(void) {
  const double p[] = {2, 2, 2, 2, 2, 2, 2, 2, 2};
  dbs_cloud *c = NULL;
  assert_ok(dbs_cloud_create(p, 3, &c));
  dbs_boundary *b = NULL;
  assert_ok(dbs_boundary_create(B, 2, R, 2, T, 2, L, 2, &b));
  return parameterize(c, b, NULL);
}
static int r_1e100(void) { return square_scaled(1e100); }
static int r_1e_101(void) { return square_scaled(1e-101); }
static int r_far_point(void) {
  double p[3 * 122];
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 11; ++i) p[3 * (j * 11 + i)] = i / 10.0, p[3 * (j * 11 + i) + 1] = j / 10.0, p[3 * (j * 11 + i) + 2] = 0;
  p[363] = 0.5, p[364] = 0.5, p[365] = 1e300;
  dbs_cloud *c = NULL;
  assert_ok(dbs_cloud_create(p, 122, &c));
  dbs_boundary *b = NULL;
  assert_ok(dbs_boundary_create(B, 2, R, 2, T, 2, L, 2, &b));
  return parameterize(c, b, NULL);
}
static int r_cancel(void) {
  dbs_cloud *c;
  dbs_boundary *b;
  square(1.0, 11, &c, &b);
  dbs_options *o = fresh_options();
  assert_ok(dbs_options_set_progress(o, cancel_at_once, NULL));
  return parameterize(c, b, o);
}
static int l_cancel(void) {
  dbs_options *o = fresh_options();
  assert_ok(dbs_options_set_progress(o, cancel_at_once, NULL));
  dbs_cloud *out = sentinel_cloud;
  const int s = dbs_cloud_load_with_options(file_with("cancel.xyz", "0 0 0\n", 0), o, &out);
  dbs_options_destroy(o);
  return s;
}
static int s_buffer(void) { double uv[2]; return dbs_result_uv(r_result, uv, 1); }
static int s_stat(void) { double v; return dbs_result_stat(r_result, 999, &v); }
static int s_eval(void) { double p[3]; return dbs_result_evaluate(r_result, 2.0, 0.5, p, NULL); }
static int s_eval_nan(void) { double p[3]; return dbs_result_evaluate(r_result, NAN, 0.5, p, NULL); }
static int s_index(void) { int32_t v; return dbs_patches_level(r_patches, SIZE_MAX, &v); }
static int s_side(void) { size_t n; return dbs_boundary_side_count(r_boundary, 7, &n); }
static int s_save_ext(void) { return dbs_result_save(r_result, r_cloud, no_file("result.stl")); }
static int s_save_dir(void) { return dbs_result_save(r_result, r_cloud, DIR "/no/such/dir/result.csv"); }
static int s_save_cloud(void) { dbs_cloud *c = plane_cloud(3, 3); int s = dbs_result_save(r_result, c, no_file("result.csv")); dbs_cloud_destroy(c); return s; }
static int v_mesh_cloud(void) { dbs_cloud *c = plane_cloud(3, 3); dbs_mesh *m = NULL; int s = dbs_mesh_create(r_result, c, &m); dbs_cloud_destroy(c); return s; }
static int v_tri_count(void) { const int32_t t[3] = {0, 1, 2}; dbs_distortion *d = NULL; return dbs_distortion_create(r_result, r_cloud, t, SIZE_MAX / 12, 0, &d); }
static int v_tri_memory(void) { const int32_t t[3] = {0, 1, 2}; dbs_distortion *d = NULL; return dbs_distortion_create(r_result, r_cloud, t, SIZE_MAX / 24, 0, &d); }
static int v_tri_index(void) { const int32_t t[3] = {0, 1, 121}; dbs_distortion *d = NULL; return dbs_distortion_create(r_result, r_cloud, t, 1, 0, &d); }
static int v_scaling(void) { const int32_t t[3] = {0, 1, 12}; dbs_distortion *d = NULL; return dbs_distortion_create(r_result, r_cloud, t, 1, 7, &d); }
static int v_tolerance(void) { dbs_distances *d = NULL; return dbs_distances_create(r_result, -1.0, &d); }
static int v_report(void) { return dbs_report_write(r_result, r_cloud, NULL, file_with("a_file", "x", 0)); }
static int v_mesh_ext(void) {
  dbs_mesh *m = NULL;
  const int created = dbs_mesh_create(r_result, r_cloud, &m);
  if (created != DBS_OK) return created; /* a build without the validation: its refusal */
  const int s = dbs_mesh_save(m, no_file("mesh.stl"));
  dbs_mesh_destroy(m);
  return s;
}

typedef struct {
  const char *input;    /* what is fed */
  const char *call;     /* the function called */
  int (*run)(void);
  int status;           /* expected */
  const char *excerpt;  /* in the message */
  int needs_validation; /* DBS_ERR_UNSUPPORTED without DBS_FEATURE_VALIDATION */
} row;

static const row rows[] = {
    {"a NULL array", "dbs_cloud_create", c_null, DBS_ERR_NULL_ARGUMENT, "xyz", 0},
    {"0 points", "dbs_cloud_create", c_zero, DBS_ERR_EMPTY, "", 0},
    {"a NaN coordinate", "dbs_cloud_create", c_nan, DBS_ERR_NON_FINITE, "point 1", 0},
    {"an infinite coordinate", "dbs_cloud_create", c_inf, DBS_ERR_NON_FINITE, "point 0", 0},
    {"a count of SIZE_MAX points", "dbs_cloud_create", c_huge_count, DBS_ERR_INVALID_ARGUMENT, "", 0},
    {"a file that does not exist", "dbs_cloud_load", l_missing, DBS_ERR_IO, "missing.xyz", 0},
    {"an unknown extension (.stl)", "dbs_cloud_load", l_ext, DBS_ERR_UNSUPPORTED, ".stl", 0},
    {"a directory named like a cloud", "dbs_cloud_load", l_dir, DBS_ERR_IO, "folder.xyz", 0},
    {"an empty .xyz", "dbs_cloud_load", l_empty, DBS_ERR_EMPTY, "no points", 0},
    {"a .xyz of comments only", "dbs_cloud_load", l_comments, DBS_ERR_EMPTY, "no points", 0},
    {"a .xyz line of 2 numbers", "dbs_cloud_load", l_two, DBS_ERR_PARSE, "two.xyz:2", 0},
    {"a .xyz line with a word", "dbs_cloud_load", l_word, DBS_ERR_PARSE, "'two'", 0},
    {"a .xyz `nan`", "dbs_cloud_load", l_nan, DBS_ERR_NON_FINITE, "nan.xyz:2", 0},
    {"a .xyz 1e400 (beyond double)", "dbs_cloud_load", l_overflow, DBS_ERR_NON_FINITE, "overflow.xyz:2", 0},
    {"a .xyz line with a NUL byte", "dbs_cloud_load", l_nul, DBS_ERR_PARSE, "\\x00", 0},
    {"a .xyz 1e300 (finite, far)", "dbs_cloud_load", l_1e300, DBS_OK, "", 0},
    {"an empty .ply", "dbs_cloud_load", p_empty, DBS_ERR_EMPTY, "empty", 0},
    {"a .ply not starting with `ply`", "dbs_cloud_load", p_magic, DBS_ERR_PARSE, "magic.ply", 0},
    {"a PLY of version 2.0", "dbs_cloud_load", p_version, DBS_ERR_UNSUPPORTED, "2.0", 0},
    {"a PLY of an unknown format", "dbs_cloud_load", p_format, DBS_ERR_PARSE, "binary_middle_endian", 0},
    {"a PLY with two `element vertex`", "dbs_cloud_load", p_two_vertex, DBS_ERR_PARSE, "second 'vertex' element", 0},
    {"a PLY of 0 vertices", "dbs_cloud_load", p_zero, DBS_ERR_EMPTY, "zero.ply", 0},
    {"a PLY vertex without z", "dbs_cloud_load", p_no_z, DBS_ERR_PARSE, "z", 0},
    {"a PLY header without end", "dbs_cloud_load", p_no_end, DBS_ERR_PARSE, "end_header", 0},
    {"an ASCII PLY row of 2 values", "dbs_cloud_load", p_short_row, DBS_ERR_PARSE, "short_row.ply:9", 0},
    {"a binary PLY cut inside vertex 1", "dbs_cloud_load", p_truncated, DBS_ERR_PARSE, "truncated", 0},
    {"a binary PLY claiming 2^31-1 vertices in 100 bytes", "dbs_cloud_load", p_lying, DBS_ERR_PARSE, "of 2147483647", 0},
    {"an ASCII PLY claiming 2^31-1 vertices in 6 bytes", "dbs_cloud_load", p_lying_ascii, DBS_ERR_PARSE, "of 2147483647", 0},
    {"a 1 KB binary PLY, 40 property-less elements of 2^31-1 before `vertex`", "dbs_cloud_load", p_empty_elements, DBS_OK, "", 0},
    {"a binary PLY, 2^31-1 faces before `vertex`, 1 byte of data", "dbs_cloud_load", p_faces_first, DBS_ERR_PARSE, "truncated", 0},
    {"a binary PLY list of length -1", "dbs_cloud_load", p_negative_list, DBS_ERR_PARSE, "negative list length", 0},
    {"a PLY `inf`", "dbs_cloud_load", p_inf, DBS_ERR_NON_FINITE, "vertex 0", 0},
    {"a PLY 500000.123, 1e300, 1.000000001 (kept exactly)", "dbs_cloud_load", p_exact, DBS_OK, "", 0},
    {"an empty .obj", "dbs_cloud_load", o_empty, DBS_ERR_EMPTY, "empty", 0},
    {"an .obj without `v` lines", "dbs_cloud_load", o_no_v, DBS_ERR_EMPTY, "no 'v' lines", 0},
    {"an .obj `v` of 2 numbers", "dbs_cloud_load", o_two, DBS_ERR_PARSE, "vertex 1", 0},
    {"an .obj `v 0,0,0`", "dbs_cloud_load", o_comma, DBS_ERR_PARSE, "comma", 0},
    {"an .obj `v 0 nan 0`", "dbs_cloud_load", o_nan_obj, DBS_ERR_NON_FINITE, "vertex 0", 0},
    {"a callback cancelling at once", "dbs_cloud_load_with_options", l_cancel, DBS_ERR_CANCELLED, "\"read\"", 0},
    {"a NULL side", "dbs_boundary_create", b_null, DBS_ERR_NULL_ARGUMENT, "bottom", 0},
    {"a side of 1 point", "dbs_boundary_create", b_one_point, DBS_ERR_INVALID_ARGUMENT, "'bottom'", 0},
    {"a NaN point", "dbs_boundary_create", b_nan, DBS_ERR_NON_FINITE, "point 1", 0},
    {"corners 0.1 apart", "dbs_boundary_create", b_apart, DBS_ERR_DEGENERATE, "corner (u=1,v=0)", 0},
    {"the top running backwards", "dbs_boundary_create", b_backwards, DBS_ERR_DEGENERATE, "top runs backwards", 0},
    {"left and right swapped", "dbs_boundary_create", b_swapped, DBS_ERR_DEGENERATE, "swapped", 0},
    {"all points at one place", "dbs_boundary_create", b_dot, DBS_ERR_DEGENERATE, "zero size", 0},
    {"a side of zero length", "dbs_boundary_create", b_zero_side, DBS_ERR_DEGENERATE, "zero length", 0},
    {"all sides on one line", "dbs_boundary_create", b_line, DBS_ERR_DEGENERATE, "no area", 0},
    {"coordinates +-1e308 (the size overflows)", "dbs_boundary_create", b_overflow, DBS_ERR_OUT_OF_RANGE, "overflows", 0},
    {"a bow-tie (corners (1,0) and (1,1) swapped)", "dbs_boundary_create", b_bow_tie, DBS_ERR_DEGENERATE, "bow-tie", 0},
    {"the left side running across into the right", "dbs_boundary_create", b_across, DBS_ERR_DEGENERATE, "crosses", 0},
    {"the bottom folding back (0 -> 0.8 -> 0.3 -> 1)", "dbs_boundary_create", b_fold, DBS_ERR_DEGENERATE, "folds back", 0},
    {"a negative corner tolerance", "dbs_boundary_create_tolerant", b_tolerance, DBS_ERR_OUT_OF_RANGE, "tolerance", 0},
    {"a corner tolerance of 0.5 of the size", "dbs_boundary_create_tolerant", b_tolerance_big, DBS_ERR_OUT_OF_RANGE, "above 0.1", 0},
    {"a boundary file that does not exist", "dbs_boundary_load", f_missing, DBS_ERR_IO, "missing.txt", 0},
    {"a boundary file without sections", "dbs_boundary_load", f_empty, DBS_ERR_EMPTY, "empty.txt", 0},
    {"an unknown section `middle`", "dbs_boundary_load", f_unknown, DBS_ERR_PARSE, "middle", 0},
    {"a section given twice", "dbs_boundary_load", f_twice, DBS_ERR_PARSE, "twice.txt", 0},
    {"no `left` section", "dbs_boundary_load", f_no_left, DBS_ERR_PARSE, "left", 0},
    {"a point before the first section", "dbs_boundary_load", f_before, DBS_ERR_PARSE, "before.txt:1", 0},
    {"a point line of 4 numbers", "dbs_boundary_load", f_four, DBS_ERR_PARSE, "four.txt:11", 0},
    {"a section of 1 point", "dbs_boundary_load", f_one_point, DBS_ERR_PARSE, "left", 0},
    {"an `inf` coordinate", "dbs_boundary_load", f_inf, DBS_ERR_NON_FINITE, "inf.txt:12", 0},
    {"a bow-tie file", "dbs_boundary_load", f_bow_tie, DBS_ERR_DEGENERATE, "bow_tie.txt", 0},
    {"corners out of cyclic order", "dbs_boundary_from_loop", lp_order, DBS_ERR_INVALID_ARGUMENT, "cyclic order", 0},
    {"a corner index beyond the loop", "dbs_boundary_from_loop", lp_index, DBS_ERR_OUT_OF_RANGE, "index 9", 0},
    {"a loop of 3 points", "dbs_boundary_from_loop", lp_three, DBS_ERR_INVALID_ARGUMENT, "at least 4", 0},
    {"an unknown option id 99", "dbs_options_set_int", o_unknown, DBS_ERR_INVALID_ARGUMENT, "99", 0},
    {"DBS_OPT_MAX_LEVEL 9", "dbs_options_set_int", o_level, DBS_ERR_OUT_OF_RANGE, "9", 0},
    {"an integer for a real option", "dbs_options_set_int", o_type, DBS_ERR_INVALID_ARGUMENT, "", 0},
    {"a NaN smoothing", "dbs_options_set_double", o_nan, DBS_ERR_NON_FINITE, "", 0},
    {"a relative accuracy of 0", "dbs_options_set_double", o_relative, DBS_ERR_OUT_OF_RANGE, "", 0},
    {"an initial grid above the maximum grid", "dbs_options_set_int", o_grid, DBS_ERR_OUT_OF_RANGE, "", 0},
    {"an unknown feature id 99", "dbs_has_feature", o_feature, DBS_ERR_OUT_OF_RANGE, "99", 0},
    {"a NULL cloud", "dbs_parameterize", r_null, DBS_ERR_NULL_ARGUMENT, "cloud", 0},
    {"3 coincident points", "dbs_parameterize", r_coincident, DBS_ERR_DEGENERATE, "", 0},
    {"the unit square x 1e100", "dbs_parameterize", r_1e100, DBS_ERR_OUT_OF_RANGE, "supported range", 0},
    {"the unit square x 1e-101", "dbs_parameterize", r_1e_101, DBS_ERR_OUT_OF_RANGE, "supported range", 0},
    {"a 1e300 point beside a unit square (a far point)", "dbs_parameterize", r_far_point, DBS_OK, "", 0},
    {"a progress callback cancelling at once", "dbs_parameterize", r_cancel, DBS_ERR_CANCELLED, "cancelled", 0},
    {"a buffer of 1 pair for 121 points", "dbs_result_uv", s_buffer, DBS_ERR_BUFFER_TOO_SMALL, "", 0},
    {"an unknown statistic 999", "dbs_result_stat", s_stat, DBS_ERR_OUT_OF_RANGE, "999", 0},
    {"u = 2", "dbs_result_evaluate", s_eval, DBS_ERR_OUT_OF_RANGE, "", 0},
    {"u = NaN", "dbs_result_evaluate", s_eval_nan, DBS_ERR_NON_FINITE, "", 0},
    {"patch index SIZE_MAX", "dbs_patches_level", s_index, DBS_ERR_OUT_OF_RANGE, "18446744073709551615", 0},
    {"side id 7", "dbs_boundary_side_count", s_side, DBS_ERR_OUT_OF_RANGE, "7", 0},
    {"a result named .stl", "dbs_result_save", s_save_ext, DBS_ERR_UNSUPPORTED, ".stl", 0},
    {"a result in a missing directory", "dbs_result_save", s_save_dir, DBS_ERR_IO, "no/such/dir", 0},
    {"another cloud of 9 points", "dbs_result_save", s_save_cloud, DBS_ERR_INVALID_ARGUMENT, "", 0},
    {"another cloud of 9 points", "dbs_mesh_create", v_mesh_cloud, DBS_ERR_INVALID_ARGUMENT, "", 1},
    {"SIZE_MAX / 12 triangles", "dbs_distortion_create", v_tri_count, DBS_ERR_INVALID_ARGUMENT, "exceeds any addressable array", 1},
    {"SIZE_MAX / 24 triangles", "dbs_distortion_create", v_tri_memory, DBS_ERR_NO_MEMORY, "out of memory", 1},
    {"a vertex index beyond the cloud", "dbs_distortion_create", v_tri_index, DBS_ERR_OUT_OF_RANGE, "121", 1},
    {"scaling 7", "dbs_distortion_create", v_scaling, DBS_ERR_OUT_OF_RANGE, "7", 1},
    {"a tolerance of -1", "dbs_distances_create", v_tolerance, DBS_ERR_OUT_OF_RANGE, "", 1},
    {"a mesh named .stl", "dbs_mesh_save", v_mesh_ext, DBS_ERR_UNSUPPORTED, ".stl", 1},
    {"a report directory that is a file", "dbs_report_write", v_report, DBS_ERR_IO, "a_file", 1},
};

#define ROWS (sizeof rows / sizeof rows[0])

static int has(int32_t feature) {
  int32_t built = 0;
  assert_ok(dbs_has_feature(feature, &built));
  return built;
}

/* The message without its "function: " prefix and with the temporary directory dropped, cut
 * to 150 characters, '|' escaped for markdown. */
static void excerpt_of(const char *message, char *out, size_t size) {
  const char *colon = strstr(message, ": ");
  const char *m = colon ? colon + 2 : message;
  char clean[2048] = "";
  const char *dir = DIR "/";
  for (size_t n = 0; *m && n + 1 < sizeof clean;) {
    if (strncmp(m, dir, strlen(dir)) == 0) {
      m += strlen(dir);
      continue;
    }
    clean[n++] = *m++;
    clean[n] = '\0';
  }
  size_t n = 0;
  for (const char *c = clean; *c && n + 3 < size; ++c) {
    if (c - clean >= 150) {
      strcpy(out + n, "...");
      return;
    }
    if (*c == '|') out[n++] = '\\';
    out[n++] = *c;
  }
  out[n] = '\0';
}

static void set_up_result(void) {
  square(1.0, 11, &r_cloud, &r_boundary);
  assert_ok(dbs_parameterize(r_cloud, r_boundary, NULL, &r_result));
  assert_ok(dbs_result_patches(r_result, &r_patches));
}

static void tear_down_result(void) {
  dbs_result_destroy(r_result);
  dbs_boundary_destroy(r_boundary);
  dbs_cloud_destroy(r_cloud);
}

/* Runs every row, asserting it; appends its markdown line to `table`. */
static void run_rows(char *table, size_t size) {
  const int validation = has(DBS_FEATURE_VALIDATION), report = has(DBS_FEATURE_REPORT);
  set_up_result();
  snprintf(table, size, "| # | input | call | status | message (excerpt) |\n|---|-------|------|--------|-------------------|\n");
  for (size_t k = 0; k < ROWS; ++k) {
    const row *r = &rows[k];
    if (UNDER_ASAN && r->run == v_tri_memory) continue;
    const int missing = r->needs_validation && (!validation || (r->run == v_report && !report));
    const int expected = missing ? DBS_ERR_UNSUPPORTED : r->status;
    dbs_last_error_message(); /* a successful row leaves the last message: cleared below */
    const int status = r->run();
    if (status != expected) print_error("row %zu (%s, %s): status %d, expected %d: %s\n", k + 1, r->input, r->call, status, expected, dbs_last_error_message());
    assert_int_equal(status, expected);
    char excerpt[512] = "";
    if (status != DBS_OK) {
      const char *message = dbs_last_error_message();
      /* refused for a missing feature: the message says so instead of the row's own (and may
       * come from a call the row needed first, e.g. dbs_mesh_create before dbs_mesh_save) */
      const char *wanted = missing ? "built without" : r->excerpt, *call = missing ? "dbs_" : r->call;
      if (strncmp(message, call, strlen(call)) != 0 || !strstr(message, wanted))
        print_error("row %zu: message \"%s\" should start with %s and hold \"%s\"\n", k + 1, message, call, wanted);
      assert_int_equal(strncmp(message, call, strlen(call)), 0);
      assert_non_null(strstr(message, wanted));
      excerpt_of(message, excerpt, sizeof excerpt);
    }
    snprintf(table + strlen(table), size - strlen(table), "| %zu | %s | `%s` | %s | %s |\n", k + 1, r->input, r->call, status == DBS_OK ? "DBS_OK" : dbs_status_string(status), excerpt);
  }
  tear_down_result();
}

static char table[1 << 17];

static void every_row_gives_its_status(void **state) {
  (void)state;
  assert_true(ROWS >= 60);
  run_rows(table, sizeof table);
}

/* docs/bad_inputs.md holds the generated table between its two marker lines. */
static void the_document_shows_the_table(void **state) {
  (void)state;
  if (!has(DBS_FEATURE_VALIDATION) || !has(DBS_FEATURE_REPORT) || UNDER_ASAN) skip();
  if (!table[0]) run_rows(table, sizeof table);
  char *doc = read_all(DOC, NULL);
  const char *begin = strstr(doc, "<!-- table: begin -->\n"), *end = strstr(doc, "<!-- table: end -->");
  assert_non_null(begin);
  assert_non_null(end);
  begin += strlen("<!-- table: begin -->\n");
  const size_t n = (size_t)(end - begin);
  if (n != strlen(table) || memcmp(begin, table, n) != 0)
    print_error("%s differs from the table the rows give; regenerate it with capi_test_bad_inputs --markdown\n", DOC);
  assert_int_equal(n, strlen(table));
  assert_memory_equal(begin, table, n);
  free(doc);
}

int main(int argc, char **argv) {
  if (argc > 1 && strcmp(argv[1], "--markdown") == 0) {
    run_rows(table, sizeof table);
    fputs(table, stdout);
    return 0;
  }
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(every_row_gives_its_status),
      cmocka_unit_test(the_document_shows_the_table),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
