/* Every function with each of its pointer arguments NULL: DBS_ERR_NULL_ARGUMENT, a message
 * "function: argument 'name' is NULL", and the other outputs untouched. */
#include <string.h>

#include "capi_support.h"

#define assert_null_argument(call, function, name) \
  assert_failure((call), DBS_ERR_NULL_ARGUMENT, (function), "argument '" name "' is NULL")

struct fixture {
  dbs_cloud *cloud;
  dbs_boundary *boundary;
  dbs_options *options;
  dbs_result *result;
  const dbs_patches *patches;
};

static int setup(void **state) {
  static struct fixture f;
  f.cloud = plane_cloud(11, 6);
  f.boundary = plane_boundary(2);
  assert_ok(dbs_options_create(&f.options));
  f.result = parameterize_or_fail(f.cloud, f.boundary, NULL);
  assert_ok(dbs_result_patches(f.result, &f.patches));
  *state = &f;
  return 0;
}

static int teardown(void **state) {
  struct fixture *f = *state;
  dbs_result_destroy(f->result);
  dbs_options_destroy(f->options);
  dbs_boundary_destroy(f->boundary);
  dbs_cloud_destroy(f->cloud);
  return 0;
}

static void cloud_functions(void **state) {
  struct fixture *f = *state;
  const double xyz[3] = {0, 0, 0};
  dbs_cloud *cloud = (dbs_cloud *)0x1;
  size_t count = 7;
  double min[3] = {-7, -7, -7}, max[3] = {-7, -7, -7}, points[3 * 66];
  assert_null_argument(dbs_cloud_create(NULL, 1, &cloud), "dbs_cloud_create", "xyz");
  assert_null_argument(dbs_cloud_create(xyz, 1, NULL), "dbs_cloud_create", "out");
  assert_null_argument(dbs_cloud_load(NULL, &cloud), "dbs_cloud_load", "path");
  assert_null_argument(dbs_cloud_load("cloud.xyz", NULL), "dbs_cloud_load", "out");
  assert_null_argument(dbs_cloud_load_with_options(NULL, NULL, &cloud), "dbs_cloud_load_with_options", "path");
  assert_null_argument(dbs_cloud_load_with_options("cloud.xyz", NULL, NULL), "dbs_cloud_load_with_options", "out");
  assert_ptr_equal(cloud, (dbs_cloud *)0x1);
  assert_null_argument(dbs_cloud_count(NULL, &count), "dbs_cloud_count", "cloud");
  assert_null_argument(dbs_cloud_count(f->cloud, NULL), "dbs_cloud_count", "out");
  assert_int_equal(count, 7);
  assert_null_argument(dbs_cloud_bounds(NULL, min, max), "dbs_cloud_bounds", "cloud");
  assert_null_argument(dbs_cloud_bounds(f->cloud, NULL, max), "dbs_cloud_bounds", "out_min");
  assert_null_argument(dbs_cloud_bounds(f->cloud, min, NULL), "dbs_cloud_bounds", "out_max");
  for (int c = 0; c < 3; ++c) assert_true(min[c] == -7 && max[c] == -7);
  assert_null_argument(dbs_cloud_points(NULL, points, 66), "dbs_cloud_points", "cloud");
  assert_null_argument(dbs_cloud_points(f->cloud, NULL, 66), "dbs_cloud_points", "out_xyz");
}

static void boundary_functions(void **state) {
  struct fixture *f = *state;
  const double b[] = {0, 0, 0, 1, 0, 0}, r[] = {1, 0, 0, 1, 1, 0}, t[] = {0, 1, 0, 1, 1, 0}, l[] = {0, 0, 0, 0, 1, 0};
  dbs_boundary *boundary = (dbs_boundary *)0x1;
  size_t count = 7;
  double points[6];
  assert_null_argument(dbs_boundary_create(NULL, 2, r, 2, t, 2, l, 2, &boundary), "dbs_boundary_create", "bottom");
  assert_null_argument(dbs_boundary_create(b, 2, NULL, 2, t, 2, l, 2, &boundary), "dbs_boundary_create", "right");
  assert_null_argument(dbs_boundary_create(b, 2, r, 2, NULL, 2, l, 2, &boundary), "dbs_boundary_create", "top");
  assert_null_argument(dbs_boundary_create(b, 2, r, 2, t, 2, NULL, 2, &boundary), "dbs_boundary_create", "left");
  assert_null_argument(dbs_boundary_create(b, 2, r, 2, t, 2, l, 2, NULL), "dbs_boundary_create", "out");
  assert_null_argument(dbs_boundary_load(NULL, &boundary), "dbs_boundary_load", "path");
  assert_null_argument(dbs_boundary_load("boundary.txt", NULL), "dbs_boundary_load", "out");
  assert_ptr_equal(boundary, (dbs_boundary *)0x1);
  assert_null_argument(dbs_boundary_side_count(NULL, 0, &count), "dbs_boundary_side_count", "boundary");
  assert_null_argument(dbs_boundary_side_count(f->boundary, 0, NULL), "dbs_boundary_side_count", "out");
  assert_int_equal(count, 7);
  assert_null_argument(dbs_boundary_side_points(NULL, 0, points, 2), "dbs_boundary_side_points", "boundary");
  assert_null_argument(dbs_boundary_side_points(f->boundary, 0, NULL, 2), "dbs_boundary_side_points", "out_xyz");
}

static int never_called_progress(double fraction, const char *stage, void *payload) {
  (void)fraction, (void)stage, (void)payload;
  return 1;
}

static int never_called_level(int32_t level, const dbs_patches *patches, void *payload) {
  (void)level, (void)patches, (void)payload;
  return 1;
}

static void options_functions(void **state) {
  struct fixture *f = *state;
  dbs_options *options = (dbs_options *)0x1;
  int32_t int_value = -7;
  double double_value = -7, min = -7, max = -7;
  assert_null_argument(dbs_options_create(NULL), "dbs_options_create", "out");
  assert_null_argument(dbs_options_clone(NULL, &options), "dbs_options_clone", "options");
  assert_null_argument(dbs_options_clone(f->options, NULL), "dbs_options_clone", "out");
  assert_ptr_equal(options, (dbs_options *)0x1);
  assert_null_argument(dbs_options_set_int(NULL, DBS_OPT_MAX_LEVEL, 1), "dbs_options_set_int", "options");
  assert_null_argument(dbs_options_get_int(NULL, DBS_OPT_MAX_LEVEL, &int_value), "dbs_options_get_int", "options");
  assert_null_argument(dbs_options_get_int(f->options, DBS_OPT_MAX_LEVEL, NULL), "dbs_options_get_int", "out");
  assert_null_argument(dbs_options_set_double(NULL, DBS_OPT_SMOOTHING, 0.1), "dbs_options_set_double", "options");
  assert_null_argument(dbs_options_get_double(NULL, DBS_OPT_SMOOTHING, &double_value), "dbs_options_get_double", "options");
  assert_null_argument(dbs_options_get_double(f->options, DBS_OPT_SMOOTHING, NULL), "dbs_options_get_double", "out");
  assert_null_argument(dbs_option_bounds(DBS_OPT_SMOOTHING, NULL, &max), "dbs_option_bounds", "out_min");
  assert_null_argument(dbs_option_bounds(DBS_OPT_SMOOTHING, &min, NULL), "dbs_option_bounds", "out_max");
  assert_true(int_value == -7 && double_value == -7 && min == -7 && max == -7);
  assert_null_argument(dbs_options_set_progress(NULL, never_called_progress, NULL), "dbs_options_set_progress", "options");
  assert_null_argument(dbs_options_set_level_callback(NULL, never_called_level, NULL), "dbs_options_set_level_callback", "options");
}

static void parameterize(void **state) {
  struct fixture *f = *state;
  dbs_result *result = (dbs_result *)0x1;
  assert_null_argument(dbs_parameterize(NULL, f->boundary, f->options, &result), "dbs_parameterize", "cloud");
  assert_null_argument(dbs_parameterize(f->cloud, NULL, f->options, &result), "dbs_parameterize", "boundary");
  assert_null_argument(dbs_parameterize(f->cloud, f->boundary, f->options, NULL), "dbs_parameterize", "out");
  assert_ptr_equal(result, (dbs_result *)0x1);
}

static void result_functions(void **state) {
  struct fixture *f = *state;
  size_t count = 7;
  double doubles[2 * 66], xyz[3] = {-7, -7, -7}, normal[3], value = -7;
  int32_t ints[66];
  const dbs_patches *patches = (const dbs_patches *)0x1;
  assert_null_argument(dbs_result_point_count(NULL, &count), "dbs_result_point_count", "result");
  assert_null_argument(dbs_result_point_count(f->result, NULL), "dbs_result_point_count", "out");
  assert_int_equal(count, 7);
  assert_null_argument(dbs_result_uv(NULL, doubles, 66), "dbs_result_uv", "result");
  assert_null_argument(dbs_result_uv(f->result, NULL, 66), "dbs_result_uv", "out_uv");
  assert_null_argument(dbs_result_distances(NULL, doubles, 66), "dbs_result_distances", "result");
  assert_null_argument(dbs_result_distances(f->result, NULL, 66), "dbs_result_distances", "out");
  assert_null_argument(dbs_result_point_patches(NULL, ints, 66), "dbs_result_point_patches", "result");
  assert_null_argument(dbs_result_point_patches(f->result, NULL, 66), "dbs_result_point_patches", "out");
  assert_null_argument(dbs_result_point_levels(NULL, ints, 66), "dbs_result_point_levels", "result");
  assert_null_argument(dbs_result_point_levels(f->result, NULL, 66), "dbs_result_point_levels", "out");
  assert_null_argument(dbs_result_evaluate(NULL, 0.5, 0.5, xyz, normal), "dbs_result_evaluate", "result");
  assert_null_argument(dbs_result_evaluate(f->result, 0.5, 0.5, NULL, normal), "dbs_result_evaluate", "out_xyz");
  assert_true(xyz[0] == -7);
  assert_null_argument(dbs_result_stat(NULL, DBS_STAT_LEVELS, &value), "dbs_result_stat", "result");
  assert_null_argument(dbs_result_stat(f->result, DBS_STAT_LEVELS, NULL), "dbs_result_stat", "out");
  assert_true(value == -7);
  assert_null_argument(dbs_result_patches(NULL, &patches), "dbs_result_patches", "result");
  assert_null_argument(dbs_result_patches(f->result, NULL), "dbs_result_patches", "out");
  assert_ptr_equal(patches, (const dbs_patches *)0x1);
  assert_null_argument(dbs_result_save(NULL, f->cloud, "result.csv"), "dbs_result_save", "result");
  assert_null_argument(dbs_result_save(f->result, NULL, "result.csv"), "dbs_result_save", "cloud");
  assert_null_argument(dbs_result_save(f->result, f->cloud, NULL), "dbs_result_save", "path");
}

static void patches_functions(void **state) {
  struct fixture *f = *state;
  const dbs_patches *p = f->patches;
  size_t count = 7;
  int32_t value = -7, nu = -7, nv = -7;
  double rect[4] = {-7, -7, -7, -7}, xyz[3 * 200], mean = -7, max = -7;
  assert_null_argument(dbs_patches_count(NULL, &count), "dbs_patches_count", "patches");
  assert_null_argument(dbs_patches_count(p, NULL), "dbs_patches_count", "out");
  assert_null_argument(dbs_patches_id(NULL, 0, &value), "dbs_patches_id", "patches");
  assert_null_argument(dbs_patches_id(p, 0, NULL), "dbs_patches_id", "out");
  assert_null_argument(dbs_patches_level(NULL, 0, &value), "dbs_patches_level", "patches");
  assert_null_argument(dbs_patches_level(p, 0, NULL), "dbs_patches_level", "out");
  assert_null_argument(dbs_patches_is_leaf(NULL, 0, &value), "dbs_patches_is_leaf", "patches");
  assert_null_argument(dbs_patches_is_leaf(p, 0, NULL), "dbs_patches_is_leaf", "out");
  assert_null_argument(dbs_patches_parent(NULL, 0, &value), "dbs_patches_parent", "patches");
  assert_null_argument(dbs_patches_parent(p, 0, NULL), "dbs_patches_parent", "out");
  assert_null_argument(dbs_patches_rect(NULL, 0, rect), "dbs_patches_rect", "patches");
  assert_null_argument(dbs_patches_rect(p, 0, NULL), "dbs_patches_rect", "out_rect");
  assert_null_argument(dbs_patches_grid_size(NULL, 0, &nu, &nv), "dbs_patches_grid_size", "patches");
  assert_null_argument(dbs_patches_grid_size(p, 0, NULL, &nv), "dbs_patches_grid_size", "out_nu");
  assert_null_argument(dbs_patches_grid_size(p, 0, &nu, NULL), "dbs_patches_grid_size", "out_nv");
  assert_null_argument(dbs_patches_grid_points(NULL, 0, xyz, 200), "dbs_patches_grid_points", "patches");
  assert_null_argument(dbs_patches_grid_points(p, 0, NULL, 200), "dbs_patches_grid_points", "out_xyz");
  assert_null_argument(dbs_patches_boundary_count(NULL, 0, 0, &count), "dbs_patches_boundary_count", "patches");
  assert_null_argument(dbs_patches_boundary_count(p, 0, 0, NULL), "dbs_patches_boundary_count", "out");
  assert_null_argument(dbs_patches_boundary_points(NULL, 0, 0, xyz, 200), "dbs_patches_boundary_points", "patches");
  assert_null_argument(dbs_patches_boundary_points(p, 0, 0, NULL, 200), "dbs_patches_boundary_points", "out_xyz");
  assert_null_argument(dbs_patches_stats(NULL, 0, &count, &mean, &max, &value), "dbs_patches_stats", "patches");
  assert_null_argument(dbs_patches_stats(p, 0, NULL, &mean, &max, &value), "dbs_patches_stats", "out_points");
  assert_null_argument(dbs_patches_stats(p, 0, &count, NULL, &max, &value), "dbs_patches_stats", "out_mean");
  assert_null_argument(dbs_patches_stats(p, 0, &count, &mean, NULL, &value), "dbs_patches_stats", "out_max");
  assert_null_argument(dbs_patches_stats(p, 0, &count, &mean, &max, NULL), "dbs_patches_stats", "out_iterations");
  assert_null_argument(dbs_patches_solver(NULL, 0, &value, &count), "dbs_patches_solver", "patches");
  assert_null_argument(dbs_patches_solver(p, 0, NULL, &count), "dbs_patches_solver", "out_solver");
  assert_null_argument(dbs_patches_solver(p, 0, &value, NULL), "dbs_patches_solver", "out_ceres_iterations");
  assert_true(count == 7 && value == -7 && nu == -7 && nv == -7 && mean == -7 && max == -7);
  for (int c = 0; c < 4; ++c) assert_true(rect[c] == -7);
}

/* The arguments documented as optional really are. */
static void optional_pointers_may_be_null(void **state) {
  struct fixture *f = *state;
  dbs_result *result = NULL;
  assert_ok(dbs_parameterize(f->cloud, f->boundary, NULL, &result));
  dbs_result_destroy(result);
  double xyz[3];
  assert_ok(dbs_result_evaluate(f->result, 0.25, 0.75, xyz, NULL));
  assert_ok(dbs_options_set_progress(f->options, NULL, NULL));
  assert_ok(dbs_options_set_level_callback(f->options, NULL, NULL));
}

static void destroy_accepts_null(void **state) {
  (void)state;
  dbs_cloud_destroy(NULL);
  dbs_boundary_destroy(NULL);
  dbs_options_destroy(NULL);
  dbs_result_destroy(NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(cloud_functions),
      cmocka_unit_test(boundary_functions),
      cmocka_unit_test(options_functions),
      cmocka_unit_test(parameterize),
      cmocka_unit_test(result_functions),
      cmocka_unit_test(patches_functions),
      cmocka_unit_test(optional_pointers_may_be_null),
      cmocka_unit_test(destroy_accepts_null),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
