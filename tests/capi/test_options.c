/* dbs_options_*: defaults, documented ranges, type checks, cross-option rules, cloning. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "capi_support.h"

/* One row per option, as documented beside DBS_OPT_* in dbs.h. */
struct option_row {
  int32_t id;
  const char *name;
  int is_integer;
  double default_value;
  double min, max;
  int min_allowed; /* 0 when the lower end is open */
  double below, above; /* just outside the range; above = NAN when there is no upper end */
};

static const struct option_row kOptions[] = {
    {DBS_OPT_ACCURACY, "accuracy", 0, 0.0, 0.0, DBL_MAX, 1, -1e-12, NAN},
    {DBS_OPT_RELATIVE_ACCURACY, "relative_accuracy", 0, 1e-3, 1e-9, 1.0, 1, 0.99e-9, 1.5},
    {DBS_OPT_MAX_LEVEL, "max_level", 1, 4, 0, 8, 1, -1, 9},
    {DBS_OPT_INITIAL_GRID, "initial_grid", 1, 5, 3, 100, 1, 2, 101},
    {DBS_OPT_MAX_GRID, "max_grid", 1, 11, 3, 200, 1, 2, 201},
    {DBS_OPT_SMOOTHING, "smoothing", 0, 0.5, 0.0, 0.99, 1, -1e-9, 0.991},
    {DBS_OPT_SOLVER, "solver", 1, DBS_SOLVER_LINEAR, 0, 1, 1, -1, 2},
    {DBS_OPT_THREADS, "threads", 1, 0, 0, 256, 1, -1, 257},
    {DBS_OPT_SUBCLOUD_NEAR, "subcloud_near", 0, 0.25, 0.0, 10.0, 0, -0.5, 10.5},
    {DBS_OPT_SUBCLOUD_OWN, "subcloud_own", 0, 0.05, 0.0, 10.0, 1, -1e-9, 10.5},
    {DBS_OPT_NOISE_FLOOR, "noise_floor", 1, 1, 0.0, 1.0, 1, -1, 2},
    {DBS_OPT_REPAIR, "repair", 1, 1, 0.0, 1.0, 1, -1, 2}, /* on by default since 0.4 */
    {DBS_OPT_LOSS, "loss", 1, DBS_LOSS_NONE, 0.0, 3.0, 1, -1, 4},
    {DBS_OPT_LOSS_SCALE, "loss_scale", 0, 0.0, 0.0, DBL_MAX, 1, -1e-12, NAN},
    {DBS_OPT_CERES_MAX_ITERATIONS, "ceres_max_iterations", 1, 25, 1, 1000, 1, 0, 1001},
    {DBS_OPT_CERES_FUNCTION_TOLERANCE, "ceres_function_tolerance", 0, 1e-6, 1e-16, 1.0, 1, 0.5e-16, 1.5},
    {DBS_OPT_OUTLINE_NEIGHBOURS, "outline_neighbours", 1, 24, 6, 256, 1, 5, 257},
    {DBS_OPT_CROP, "crop", 1, 0, 0, 1, 1, -1, 2},
    {DBS_OPT_STRICT, "strict", 1, 0, 0, 1, 1, -1, 2},
    {DBS_OPT_SMOOTH_TURNED, "smooth_turned", 1, 0, 0, 1, 1, -1, 2},
    {DBS_OPT_COARSE_PASS, "coarse_pass", 1, 1, 0, 2, 1, -1, 3},
    {DBS_OPT_FIT_TO_TARGET, "fit_to_target", 1, 1, 0, 1, 1, -1, 2},
};
#define OPTION_COUNT (sizeof kOptions / sizeof kOptions[0])

static int ceres_built(void) {
  int32_t built = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_CERES, &built));
  return built;
}

static dbs_options *new_options(void) {
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_non_null(options);
  return options;
}

static double get_value(const dbs_options *options, const struct option_row *row) {
  if (row->is_integer) {
    int32_t value = -12345;
    assert_ok(dbs_options_get_int(options, row->id, &value));
    return value;
  }
  double value = -12345;
  assert_ok(dbs_options_get_double(options, row->id, &value));
  return value;
}

static int set_value(dbs_options *options, const struct option_row *row, double value) {
  return row->is_integer ? dbs_options_set_int(options, row->id, (int32_t)value) : dbs_options_set_double(options, row->id, value);
}

static const char *setter_name(const struct option_row *row) { return row->is_integer ? "dbs_options_set_int" : "dbs_options_set_double"; }

static void defaults_are_documented(void **state) {
  (void)state;
  dbs_options *options = new_options();
  for (size_t k = 0; k < OPTION_COUNT; ++k) assert_true(get_value(options, &kOptions[k]) == kOptions[k].default_value);
  dbs_options_destroy(options);
}

static void bounds_are_documented(void **state) {
  (void)state;
  for (size_t k = 0; k < OPTION_COUNT; ++k) {
    double min = -1, max = -1;
    assert_ok(dbs_option_bounds(kOptions[k].id, &min, &max));
    assert_true(min == kOptions[k].min);
    assert_true(max == kOptions[k].max);
  }
}

/* Options whose partner in a cross rule must be moved first so that `value` is allowed. */
static void make_room(dbs_options *options, int32_t id, double value) {
  if (id == DBS_OPT_INITIAL_GRID && value > 11) assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 200));
  if (id == DBS_OPT_MAX_GRID && value < 5) assert_ok(dbs_options_set_int(options, DBS_OPT_INITIAL_GRID, 3));
  if (id == DBS_OPT_SUBCLOUD_OWN && value > 0.25) assert_ok(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_NEAR, 10));
  if (id == DBS_OPT_SUBCLOUD_NEAR && value < 0.05) assert_ok(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_OWN, 0));
}

static void range_ends_are_accepted(void **state) {
  (void)state;
  for (size_t k = 0; k < OPTION_COUNT; ++k) {
    const struct option_row *row = &kOptions[k];
    if (row->id == DBS_OPT_SOLVER && !ceres_built()) continue; /* its maximum is the unsupported Ceres solver */
    dbs_options *options = new_options();
    make_room(options, row->id, row->max);
    assert_ok(set_value(options, row, row->max));
    assert_true(get_value(options, row) == row->max);
    if (row->min_allowed) {
      make_room(options, row->id, row->min);
      assert_ok(set_value(options, row, row->min));
      assert_true(get_value(options, row) == row->min);
    } else {
      assert_failure(set_value(options, row, row->min), DBS_ERR_OUT_OF_RANGE, setter_name(row), row->name);
      assert_true(get_value(options, row) == row->max);
    }
    dbs_options_destroy(options);
  }
}

/* "%s = %g" as libdbs writes it: %g without the exponent's leading zero (1e-9, not 1e-09). */
static void name_and_value(char *out, size_t size, const char *name, double value) {
  snprintf(out, size, "%s = %g", name, value);
  char *e = strstr(out, "e-0");
  if (!e) e = strstr(out, "e+0");
  if (e && e[3] != '\0') memmove(e + 2, e + 3, strlen(e + 3) + 1);
}

static void values_outside_the_range_are_rejected(void **state) {
  (void)state;
  dbs_options *options = new_options();
  for (size_t k = 0; k < OPTION_COUNT; ++k) {
    const struct option_row *row = &kOptions[k];
    char value_text[64];
    name_and_value(value_text, sizeof value_text, row->name, row->below);
    assert_failure(set_value(options, row, row->below), DBS_ERR_OUT_OF_RANGE, setter_name(row), value_text);
    assert_true(get_value(options, row) == row->default_value);
    if (!isnan(row->above)) {
      name_and_value(value_text, sizeof value_text, row->name, row->above);
      assert_failure(set_value(options, row, row->above), DBS_ERR_OUT_OF_RANGE, setter_name(row), value_text);
      assert_true(get_value(options, row) == row->default_value);
    }
  }
  /* the message states the range */
  assert_failure(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 9), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_int", "range [0, 8]");
  assert_failure(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_NEAR, 0), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", "range (0, 10]");
  assert_failure(dbs_options_set_double(options, DBS_OPT_ACCURACY, -1), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", ">= 0");
  dbs_options_destroy(options);
}

static void non_finite_reals_are_rejected(void **state) {
  (void)state;
  dbs_options *options = new_options();
  const double bad[] = {NAN, INFINITY, -INFINITY};
  for (size_t k = 0; k < OPTION_COUNT; ++k) {
    const struct option_row *row = &kOptions[k];
    if (row->is_integer) continue;
    for (int b = 0; b < 3; ++b) {
      assert_failure(dbs_options_set_double(options, row->id, bad[b]), DBS_ERR_NON_FINITE, "dbs_options_set_double", row->name);
      assert_true(get_value(options, row) == row->default_value);
    }
  }
  dbs_options_destroy(options);
}

static void the_wrong_type_is_rejected(void **state) {
  (void)state;
  dbs_options *options = new_options();
  for (size_t k = 0; k < OPTION_COUNT; ++k) {
    const struct option_row *row = &kOptions[k];
    int32_t int_value = -777;
    double double_value = -777;
    if (row->is_integer) {
      assert_failure(dbs_options_set_double(options, row->id, row->default_value), DBS_ERR_INVALID_ARGUMENT, "dbs_options_set_double", row->name);
      assert_failure(dbs_options_get_double(options, row->id, &double_value), DBS_ERR_INVALID_ARGUMENT, "dbs_options_get_double", "integer option");
    } else {
      assert_failure(dbs_options_set_int(options, row->id, 0), DBS_ERR_INVALID_ARGUMENT, "dbs_options_set_int", row->name);
      assert_failure(dbs_options_get_int(options, row->id, &int_value), DBS_ERR_INVALID_ARGUMENT, "dbs_options_get_int", "real option");
    }
    assert_int_equal(int_value, -777);
    assert_true(double_value == -777);
    assert_true(get_value(options, row) == row->default_value);
  }
  dbs_options_destroy(options);
}

static void unknown_ids_are_rejected(void **state) {
  (void)state;
  dbs_options *options = new_options();
  const int32_t unknown[] = {-1, 22, 1000};
  for (int k = 0; k < 3; ++k) {
    char needle[48];
    snprintf(needle, sizeof needle, "option id %d", (int)unknown[k]);
    int32_t int_value = -777;
    double min = -777, max = -777, double_value = -777;
    assert_failure(dbs_options_set_int(options, unknown[k], 1), DBS_ERR_INVALID_ARGUMENT, "dbs_options_set_int", needle);
    assert_failure(dbs_options_set_double(options, unknown[k], 1), DBS_ERR_INVALID_ARGUMENT, "dbs_options_set_double", needle);
    assert_failure(dbs_options_get_int(options, unknown[k], &int_value), DBS_ERR_INVALID_ARGUMENT, "dbs_options_get_int", needle);
    assert_failure(dbs_options_get_double(options, unknown[k], &double_value), DBS_ERR_INVALID_ARGUMENT, "dbs_options_get_double", needle);
    assert_failure(dbs_option_bounds(unknown[k], &min, &max), DBS_ERR_INVALID_ARGUMENT, "dbs_option_bounds", needle);
    assert_int_equal(int_value, -777);
    assert_true(double_value == -777 && min == -777 && max == -777);
  }
  dbs_options_destroy(options);
}

/* The Ceres solver is taken exactly when the build has it (dbs_has_feature agrees with the
 * build's own definitions); a run with it says so in its statistics. */
static void ceres_solver_follows_the_feature(void **state) {
  (void)state;
  int32_t built = -1;
  assert_ok(dbs_has_feature(DBS_FEATURE_CERES, &built));
#ifdef DBS_HAVE_CERES
  assert_int_equal(built, 1);
#else
  assert_int_equal(built, 0);
#endif
  dbs_options *options = new_options();
  int32_t solver = -1;
  if (!built) {
    assert_failure(dbs_options_set_int(options, DBS_OPT_SOLVER, DBS_SOLVER_CERES), DBS_ERR_UNSUPPORTED, "dbs_options_set_int", "built without Ceres");
    assert_ok(dbs_options_get_int(options, DBS_OPT_SOLVER, &solver));
    assert_int_equal(solver, DBS_SOLVER_LINEAR);
    /* the loss options are still accepted (they act on the Ceres solver only) */
    assert_ok(dbs_options_set_int(options, DBS_OPT_LOSS, DBS_LOSS_HUBER));
    dbs_options_destroy(options);
    return;
  }
  assert_ok(dbs_options_set_int(options, DBS_OPT_SOLVER, DBS_SOLVER_CERES));
  assert_ok(dbs_options_get_int(options, DBS_OPT_SOLVER, &solver));
  assert_int_equal(solver, DBS_SOLVER_CERES);
  assert_ok(dbs_options_set_int(options, DBS_OPT_LOSS, DBS_LOSS_HUBER));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 0));
  dbs_cloud *cloud = bump_cloud(40, 0.1);
  dbs_boundary *boundary = square_boundary(20);
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  double ran = -1, iterations = -1, scale = -1, h = -1;
  assert_ok(dbs_result_stat(result, DBS_STAT_SOLVER, &ran));
  assert_ok(dbs_result_stat(result, DBS_STAT_CERES_ITERATIONS, &iterations));
  assert_ok(dbs_result_stat(result, DBS_STAT_LOSS_SCALE, &scale));
  assert_ok(dbs_result_stat(result, DBS_STAT_LENGTH_SCALE, &h));
  assert_true(ran == DBS_SOLVER_CERES);
  assert_true(iterations >= 1);
  assert_true(scale >= h && h > 0); /* derived: 3 sigma, at least h */
  /* the patch view says which solver ran and what it cost: the root holds every iteration */
  const dbs_patches *patches = NULL;
  assert_ok(dbs_result_patches(result, &patches));
  int32_t patch_solver = -1;
  size_t patch_iterations = 0;
  assert_ok(dbs_patches_solver(patches, 0, &patch_solver, &patch_iterations));
  assert_int_equal(patch_solver, DBS_SOLVER_CERES);
  assert_true((double)patch_iterations == iterations);
  assert_failure(dbs_patches_solver(patches, 1, &patch_solver, &patch_iterations), DBS_ERR_OUT_OF_RANGE, "dbs_patches_solver", NULL);
  dbs_result_destroy(result);
  /* a scale far outside the cloud's spacing is refused by the run, naming it */
  assert_ok(dbs_options_set_double(options, DBS_OPT_LOSS_SCALE, 1e300));
  dbs_result *refused = NULL;
  assert_failure(dbs_parameterize(cloud, boundary, options, &refused), DBS_ERR_OUT_OF_RANGE, "dbs_parameterize", "loss scale");
  assert_null(refused);
  /* an explicit scale is the one used */
  assert_ok(dbs_options_set_double(options, DBS_OPT_LOSS_SCALE, 0.01));
  result = parameterize_or_fail(cloud, boundary, options);
  assert_ok(dbs_result_stat(result, DBS_STAT_LOSS_SCALE, &scale));
  assert_true(scale == 0.01);
  dbs_result_destroy(result);
  dbs_cloud_destroy(cloud);
  dbs_boundary_destroy(boundary);
  dbs_options_destroy(options);
}

static void grid_sizes_keep_their_order(void **state) {
  (void)state;
  dbs_options *options = new_options();
  int32_t initial = 0, max = 0;
  /* either option, set past the other, names both */
  assert_failure(dbs_options_set_int(options, DBS_OPT_INITIAL_GRID, 12), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_int", "initial_grid = 12 and max_grid = 11");
  assert_failure(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 4), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_int", "initial_grid = 5 and max_grid = 4");
  assert_ok(dbs_options_get_int(options, DBS_OPT_INITIAL_GRID, &initial));
  assert_ok(dbs_options_get_int(options, DBS_OPT_MAX_GRID, &max));
  assert_int_equal(initial, 5);
  assert_int_equal(max, 11);
  /* equal is allowed from both sides */
  assert_ok(dbs_options_set_int(options, DBS_OPT_INITIAL_GRID, 11));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 11));
  assert_failure(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 10), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_int", "initial_grid <= max_grid");
  assert_ok(dbs_options_get_int(options, DBS_OPT_MAX_GRID, &max));
  assert_int_equal(max, 11);
  dbs_options_destroy(options);
}

static void subcloud_limits_keep_their_order(void **state) {
  (void)state;
  dbs_options *options = new_options();
  double own = 0, near = 0;
  assert_failure(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_OWN, 0.3), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", "subcloud_own = 0.3 and subcloud_near = 0.25");
  assert_failure(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_NEAR, 0.04), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", "subcloud_own = 0.05 and subcloud_near = 0.04");
  assert_ok(dbs_options_get_double(options, DBS_OPT_SUBCLOUD_OWN, &own));
  assert_ok(dbs_options_get_double(options, DBS_OPT_SUBCLOUD_NEAR, &near));
  assert_true(own == 0.05 && near == 0.25);
  assert_ok(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_OWN, 0.25));
  assert_ok(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_NEAR, 0.25));
  assert_failure(dbs_options_set_double(options, DBS_OPT_SUBCLOUD_NEAR, 0.2), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", "subcloud_own <= subcloud_near");
  dbs_options_destroy(options);
}

static void clones_are_independent(void **state) {
  (void)state;
  dbs_options *original = new_options();
  assert_ok(dbs_options_set_int(original, DBS_OPT_MAX_LEVEL, 2));
  assert_ok(dbs_options_set_double(original, DBS_OPT_SMOOTHING, 0.75));
  dbs_options *clone = NULL;
  assert_ok(dbs_options_clone(original, &clone));
  assert_ptr_not_equal(clone, original);

  int32_t level = -1;
  double smoothing = -1;
  assert_ok(dbs_options_get_int(clone, DBS_OPT_MAX_LEVEL, &level));
  assert_ok(dbs_options_get_double(clone, DBS_OPT_SMOOTHING, &smoothing));
  assert_int_equal(level, 2);
  assert_true(smoothing == 0.75);

  assert_ok(dbs_options_set_int(clone, DBS_OPT_MAX_LEVEL, 7));
  assert_ok(dbs_options_set_double(original, DBS_OPT_SMOOTHING, 0.1));
  assert_ok(dbs_options_get_int(original, DBS_OPT_MAX_LEVEL, &level));
  assert_int_equal(level, 2);
  assert_ok(dbs_options_get_double(clone, DBS_OPT_SMOOTHING, &smoothing));
  assert_true(smoothing == 0.75);

  dbs_options_destroy(original);
  assert_ok(dbs_options_get_int(clone, DBS_OPT_MAX_LEVEL, &level)); /* outlives the original */
  assert_int_equal(level, 7);
  dbs_options_destroy(clone);
}

static void destroy_accepts_null(void **state) {
  (void)state;
  dbs_options_destroy(NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(defaults_are_documented),
      cmocka_unit_test(bounds_are_documented),
      cmocka_unit_test(range_ends_are_accepted),
      cmocka_unit_test(values_outside_the_range_are_rejected),
      cmocka_unit_test(non_finite_reals_are_rejected),
      cmocka_unit_test(the_wrong_type_is_rejected),
      cmocka_unit_test(unknown_ids_are_rejected),
      cmocka_unit_test(ceres_solver_follows_the_feature),
      cmocka_unit_test(grid_sizes_keep_their_order),
      cmocka_unit_test(subcloud_limits_keep_their_order),
      cmocka_unit_test(clones_are_independent),
      cmocka_unit_test(destroy_accepts_null),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
