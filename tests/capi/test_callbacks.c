/* Progress, level and warning callbacks: what they receive, on which thread, and cancellation. */
#define _POSIX_C_SOURCE 200809L /* pthread_self */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define MAX_CALLS 100000
#define STAGE_SIZE 16

struct progress_log {
  double fractions[MAX_CALLS];
  char stages[MAX_CALLS][STAGE_SIZE]; /* copies: `stage` is only valid during the call */
  size_t calls;
  size_t cancel_at; /* 1-based call that returns non-zero; 0 = never */
  int wrong_thread;
  pthread_t caller;
};

static int record_progress(double fraction, const char *stage, void *payload) {
  struct progress_log *log = payload;
  if (!pthread_equal(pthread_self(), log->caller)) log->wrong_thread = 1;
  if (log->calls < MAX_CALLS) {
    log->fractions[log->calls] = fraction;
    snprintf(log->stages[log->calls], STAGE_SIZE, "%s", stage);
  }
  ++log->calls;
  return log->calls == log->cancel_at;
}

static struct progress_log *new_progress_log(void) {
  struct progress_log *log = calloc(1, sizeof *log);
  assert_non_null(log);
  log->caller = pthread_self();
  return log;
}

/* The subdividing case: a bump one patch cannot fit to 1e-6, at most two levels below the root. */
static dbs_options *subdividing_options(void) {
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_double(options, DBS_OPT_ACCURACY, 1e-6));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 2));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_GRID, 6));
  assert_ok(dbs_options_set_int(options, DBS_OPT_THREADS, 2));
  return options;
}

/* A test's run: the cloud, the boundary and the options it parameterizes with. */
struct run {
  dbs_cloud *cloud;
  dbs_boundary *boundary;
  dbs_options *options;
};

static struct run the_run;

/* The subdividing case: the bump and subdividing_options(). */
static int subdividing_setup(void **state) {
  the_run.cloud = bump_cloud(40, 0.2);
  the_run.boundary = square_boundary(3);
  the_run.options = subdividing_options();
  *state = &the_run;
  return 0;
}

/* The plane with the default options: one patch, a quick run. */
static int plane_setup(void **state) {
  the_run.cloud = plane_cloud(11, 6);
  the_run.boundary = plane_boundary(2);
  the_run.options = NULL;
  assert_ok(dbs_options_create(&the_run.options));
  *state = &the_run;
  return 0;
}

static int run_teardown(void **state) {
  struct run *r = *state;
  dbs_options_destroy(r->options);
  dbs_boundary_destroy(r->boundary);
  dbs_cloud_destroy(r->cloud);
  return 0;
}

static void progress_rises_to_exactly_one(void **state) {
  const struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *options = r->options;
  struct progress_log *log = new_progress_log();
  assert_ok(dbs_options_set_progress(options, record_progress, log));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);

  assert_true(log->calls >= 3 && log->calls <= MAX_CALLS);
  assert_false(log->wrong_thread);
  static const char *known[] = {"index", "evolve", "subdivide", "parameterize", "folds", "done"};
  for (size_t i = 0; i < log->calls; ++i) {
    assert_true(log->fractions[i] >= 0.0 && log->fractions[i] <= 1.0);
    if (i > 0) assert_true(log->fractions[i] >= log->fractions[i - 1]);
    int stage_known = 0;
    for (int k = 0; k < 6; ++k) stage_known |= strcmp(log->stages[i], known[k]) == 0;
    assert_true(stage_known);
  }
  assert_true(log->fractions[log->calls - 1] == 1.0);
  assert_string_equal(log->stages[log->calls - 1], "done");
  assert_string_equal(log->stages[0], "index");
  /* 1.0 only at the end: the earlier stages leave room for the later ones */
  assert_true(log->fractions[log->calls - 2] < 1.0);

  dbs_result_destroy(result);
  free(log);
}

static void progress_can_cancel_at_any_call(void **state) {
  const struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *options = r->options;
  struct progress_log *log = new_progress_log();
  assert_ok(dbs_options_set_progress(options, record_progress, log));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  dbs_result_destroy(result);
  const size_t total = log->calls;

  const size_t cancel_at[] = {1, total / 2, total};
  for (int k = 0; k < 3; ++k) {
    log->calls = 0;
    log->cancel_at = cancel_at[k];
    result = NULL;
    assert_failure(dbs_parameterize(cloud, boundary, options, &result), DBS_ERR_CANCELLED, "dbs_parameterize", "cancelled");
    assert_null(result);
    /* no call after the one that cancelled */
    assert_int_equal(log->calls, cancel_at[k]);
  }
  free(log);
}

static void cleared_progress_is_not_called(void **state) {
  const struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *options = r->options;
  struct progress_log *log = new_progress_log();
  log->cancel_at = 1; /* would cancel if it were called */
  assert_ok(dbs_options_set_progress(options, record_progress, log));
  assert_ok(dbs_options_set_progress(options, NULL, log));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  assert_int_equal(log->calls, 0);
  dbs_result_destroy(result);
  free(log);
}

static void clones_carry_the_callbacks(void **state) {
  struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *clone = NULL;
  struct progress_log *log = new_progress_log();
  assert_ok(dbs_options_set_progress(r->options, record_progress, log));
  assert_ok(dbs_options_clone(r->options, &clone));
  dbs_options_destroy(r->options); /* the clone outlives its original */
  r->options = NULL;
  dbs_result *result = parameterize_or_fail(cloud, boundary, clone);
  assert_true(log->calls >= 2);
  assert_true(log->fractions[log->calls - 1] == 1.0);
  dbs_result_destroy(result);
  free(log);
  dbs_options_destroy(clone);
}

#define MAX_LEVELS 16

struct level_log {
  int32_t levels[MAX_LEVELS];
  size_t counts[MAX_LEVELS];
  size_t points[MAX_LEVELS]; /* sum over the level's patches of their subcloud sizes */
  int consistent;            /* every patch read through the view agreed with the level */
  size_t calls;
  size_t cancel_at;
  int wrong_thread;
  pthread_t caller;
};

/* The view's grid and boundary of patch i: finite, and the grid's first and last points are
 * the boundary's corners (the grid interpolates the boundary). */
static int grid_and_boundary_agree(const dbs_patches *patches, size_t i, int32_t nu, int32_t nv) {
  const size_t n = (size_t)nu * (size_t)nv;
  double *grid = malloc(sizeof(double) * 3 * n);
  if (!grid) return 0;
  int ok = dbs_patches_grid_points(patches, i, grid, n) == DBS_OK;
  for (size_t k = 0; ok && k < 3 * n; ++k) ok = isfinite(grid[k]);
  size_t bottom = 0, top = 0;
  ok = ok && dbs_patches_boundary_count(patches, i, DBS_SIDE_BOTTOM, &bottom) == DBS_OK && dbs_patches_boundary_count(patches, i, DBS_SIDE_TOP, &top) == DBS_OK && bottom >= 2 && top >= 2;
  double *first = ok ? malloc(sizeof(double) * 3 * bottom) : NULL, *last = ok ? malloc(sizeof(double) * 3 * top) : NULL;
  ok = ok && first && last && dbs_patches_boundary_points(patches, i, DBS_SIDE_BOTTOM, first, bottom) == DBS_OK && dbs_patches_boundary_points(patches, i, DBS_SIDE_TOP, last, top) == DBS_OK;
  for (int c = 0; ok && c < 3; ++c) ok = fabs(grid[c] - first[c]) < 1e-12 && fabs(grid[3 * (n - 1) + c] - last[3 * (top - 1) + c]) < 1e-12;
  free(grid);
  free(first);
  free(last);
  return ok;
}

static int record_level(int32_t level, const dbs_patches *patches, void *payload) {
  struct level_log *log = payload;
  if (!pthread_equal(pthread_self(), log->caller)) log->wrong_thread = 1;
  size_t count = 0;
  if (dbs_patches_count(patches, &count) != DBS_OK) log->consistent = 0;
  if (log->calls < MAX_LEVELS) {
    log->levels[log->calls] = level;
    log->counts[log->calls] = count;
    log->points[log->calls] = 0;
  }
  for (size_t i = 0; i < count; ++i) {
    int32_t patch_level = -1, nu = 0, nv = 0, iterations = 0;
    size_t points = 0;
    double rect[4], mean = -1, max = -1;
    int ok = dbs_patches_level(patches, i, &patch_level) == DBS_OK && dbs_patches_rect(patches, i, rect) == DBS_OK &&
             dbs_patches_grid_size(patches, i, &nu, &nv) == DBS_OK && dbs_patches_stats(patches, i, &points, &mean, &max, &iterations) == DBS_OK;
    /* a level-L patch covers 1/2^L of [0,1] along each direction */
    double side = 1.0 / (double)(1 << level);
    if (!ok || patch_level != level || rect[2] - rect[0] != side || rect[3] - rect[1] != side || nu < 5 || nv < 5 || max < mean) log->consistent = 0;
    if (ok && !grid_and_boundary_agree(patches, i, nu, nv)) log->consistent = 0;
    if (log->calls < MAX_LEVELS) log->points[log->calls] += points;
  }
  int32_t beyond = 0;
  if (dbs_patches_level(patches, count, &beyond) != DBS_ERR_OUT_OF_RANGE) log->consistent = 0;
  ++log->calls;
  return log->calls == log->cancel_at;
}

static struct level_log *new_level_log(void) {
  struct level_log *log = calloc(1, sizeof *log);
  assert_non_null(log);
  log->consistent = 1;
  log->caller = pthread_self();
  return log;
}

struct warning_log {
  char messages[8][512];
  size_t calls;
  int wrong_thread;
  pthread_t caller;
};

static void record_warning(const char *message, void *payload) {
  struct warning_log *log = payload;
  if (!pthread_equal(pthread_self(), log->caller)) log->wrong_thread = 1;
  if (log->calls < 8) snprintf(log->messages[log->calls], sizeof log->messages[0], "%s", message);
  ++log->calls;
}

static void warnings_name_mismatched_inputs(void **state) {
  struct run *r = *state;
  struct warning_log log = {.calls = 0, .wrong_thread = 0, .caller = pthread_self()};
  assert_ok(dbs_options_set_warning(r->options, record_warning, &log));
  /* The plane and its own boundary: nothing to say. */
  dbs_result *result = parameterize_or_fail(r->cloud, r->boundary, r->options);
  dbs_result_destroy(result);
  assert_int_equal(log.calls, 0);
  /* The same plane, its boundary in other units (1000 times smaller, at the same corner):
     the scale ratio and the points clamped outside it are both named, with their numbers;
     the run goes on. */
  const double w = PLANE_W / 1000, h = PLANE_H / 1000, z = PLANE_Z;
  const double bottom[] = {0, 0, z, w, 0, z}, right[] = {w, 0, z, w, h, z}, top[] = {0, h, z, w, h, z}, left[] = {0, 0, z, 0, h, z};
  dbs_boundary *tiny = NULL;
  assert_ok(dbs_boundary_create(bottom, 2, right, 2, top, 2, left, 2, &tiny));
  result = parameterize_or_fail(r->cloud, tiny, r->options);
  assert_int_equal(log.calls, 2);
  assert_false(log.wrong_thread);
  assert_non_null(strstr(log.messages[0], "the cloud is 1e+3 times the size of the boundary"));
  assert_non_null(strstr(log.messages[0], "same units"));
  assert_non_null(strstr(log.messages[1], " of 66 points lie outside the boundary by more than a point spacing and were clamped onto the domain's edge"));
  double ratio = 0.0, clamped = 0.0;
  assert_ok(dbs_result_stat(result, DBS_STAT_SCALE_RATIO, &ratio));
  assert_ok(dbs_result_stat(result, DBS_STAT_CLAMPED_POINTS, &clamped));
  assert_true(fabs(ratio - 1000.0) < 1e-6);
  assert_true(clamped >= 60 && clamped <= 66);
  dbs_result_destroy(result);
  /* A clone carries the callback; cleared, it is not called. */
  dbs_options *copy = NULL;
  assert_ok(dbs_options_clone(r->options, &copy));
  log.calls = 0;
  result = parameterize_or_fail(r->cloud, tiny, copy);
  dbs_result_destroy(result);
  assert_int_equal(log.calls, 2);
  assert_ok(dbs_options_set_warning(copy, NULL, &log));
  log.calls = 0;
  result = parameterize_or_fail(r->cloud, tiny, copy);
  dbs_result_destroy(result);
  assert_int_equal(log.calls, 0);
  dbs_options_destroy(copy);
  dbs_boundary_destroy(tiny);
  assert_failure(dbs_options_set_warning(NULL, record_warning, &log), DBS_ERR_NULL_ARGUMENT, "dbs_options_set_warning", "options");
}

static void level_callback_sees_every_level(void **state) {
  const struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *options = r->options;
  struct level_log *log = new_level_log();
  assert_ok(dbs_options_set_level_callback(options, record_level, log));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);

  double levels = 0, patches = 0;
  assert_ok(dbs_result_stat(result, DBS_STAT_LEVELS, &levels));
  assert_ok(dbs_result_stat(result, DBS_STAT_PATCHES, &patches));
  assert_true(levels == 3.0); /* the bump needs every level it is allowed */
  assert_int_equal(log->calls, 3);
  assert_true(log->consistent);
  assert_false(log->wrong_thread);
  size_t total = 0;
  for (size_t k = 0; k < log->calls; ++k) {
    assert_int_equal(log->levels[k], (int32_t)k);
    total += log->counts[k];
  }
  assert_int_equal(log->counts[0], 1);
  assert_int_equal(log->points[0], 1600); /* the root holds the whole cloud */
  assert_int_equal(log->counts[1], 4);
  assert_true(total == (size_t)patches);

  dbs_result_destroy(result);
  free(log);
}

static void level_callback_can_cancel(void **state) {
  const struct run *r = *state;
  dbs_cloud *cloud = r->cloud;
  dbs_boundary *boundary = r->boundary;
  dbs_options *options = r->options;
  struct level_log *log = new_level_log();
  struct progress_log *progress = new_progress_log();
  assert_ok(dbs_options_set_level_callback(options, record_level, log));
  assert_ok(dbs_options_set_progress(options, record_progress, progress));
  for (size_t k = 1; k <= 3; ++k) {
    log->calls = 0;
    log->cancel_at = k;
    progress->calls = 0;
    dbs_result *result = NULL;
    assert_failure(dbs_parameterize(cloud, boundary, options, &result), DBS_ERR_CANCELLED, "dbs_parameterize", "level callback");
    assert_null(result);
    assert_int_equal(log->calls, k);
    /* the run stopped: progress never reached its end */
    assert_true(progress->calls > 0 && progress->fractions[progress->calls - 1] < 1.0);
  }
  free(progress);
  free(log);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(progress_rises_to_exactly_one, subdividing_setup, run_teardown),
      cmocka_unit_test_setup_teardown(progress_can_cancel_at_any_call, subdividing_setup, run_teardown),
      cmocka_unit_test_setup_teardown(cleared_progress_is_not_called, plane_setup, run_teardown),
      cmocka_unit_test_setup_teardown(clones_carry_the_callbacks, plane_setup, run_teardown),
      cmocka_unit_test_setup_teardown(warnings_name_mismatched_inputs, plane_setup, run_teardown),
      cmocka_unit_test_setup_teardown(level_callback_sees_every_level, subdividing_setup, run_teardown),
      cmocka_unit_test_setup_teardown(level_callback_can_cancel, subdividing_setup, run_teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
