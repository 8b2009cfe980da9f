/* A cloud that does not belong to its boundary (issue 14, item 7): 1e4 away from it, or in a
 * plane at right angles to it. The run goes on (DBS_OK; a strict mode is another option's
 * business) but says so: DBS_STAT_BOUNDARY_GAP, DBS_STAT_SCALE_RATIO and DBS_STAT_COVERAGE
 * beyond their thresholds and a warning naming each, through dbs_options_set_warning. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define N 21 /* points per row of the clouds */

typedef struct {
  int count;
  char text[8][512];
} warnings;

static void collect(const char *message, void *payload) {
  warnings *w = payload;
  if (w->count < 8) snprintf(w->text[w->count], sizeof w->text[0], "%s", message);
  w->count++;
}

/* Whether any warning holds `needle`. */
static int warned(const warnings *w, const char *needle) {
  for (int k = 0; k < w->count && k < 8; ++k)
    if (strstr(w->text[k], needle)) return 1;
  return 0;
}

/* The N x N grid over the unit square, mapped by `place` (x, y in [0,1] -> point). */
static dbs_cloud *grid_cloud(void (*place)(double x, double y, double *p)) {
  double *xyz = malloc(sizeof(double) * 3 * N * N);
  assert_non_null(xyz);
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) place((double)i / (N - 1), (double)j / (N - 1), xyz + 3 * (j * N + i));
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, N * N, &cloud));
  free(xyz);
  return cloud;
}

static void far_away(double x, double y, double *p) { p[0] = x + 1e4, p[1] = y, p[2] = 0.0; }
static void upright(double x, double y, double *p) { p[0] = x, p[1] = 0.0, p[2] = y; }

/* Runs the cloud inside the unit square's boundary (z = 0), collecting the warnings. */
static dbs_result *run(const dbs_cloud *cloud, warnings *w) {
  dbs_boundary *boundary = square_boundary(11);
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 1));
  assert_ok(dbs_options_set_warning(options, collect, w));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  return result;
}

static double stat(const dbs_result *result, int32_t id) {
  double value = 0.0;
  assert_ok(dbs_result_stat(result, id, &value));
  return value;
}

static void cloud_far_from_its_boundary_warns(void **state) {
  (void)state;
  dbs_cloud *cloud = grid_cloud(far_away);
  warnings w = {0};
  dbs_result *result = run(cloud, &w);
  /* 1e4 away with a spacing of 0.05: about 2e5 spacings; the points all clamped onto the
   * domain's edge. */
  assert_true(stat(result, DBS_STAT_BOUNDARY_GAP) > 1e5);
  assert_true(stat(result, DBS_STAT_COVERAGE) < 0.75);
  assert_true(stat(result, DBS_STAT_CLAMPED_POINTS) == N * N);
  assert_true(warned(&w, "point spacings from the cloud (90% of it within that): does it belong to this cloud?"));
  assert_true(warned(&w, "the cloud covers only part of the boundary"));
  assert_true(warned(&w, "441 of 441 points lie outside the boundary"));
  /* the result itself is sound: finite (u,v) in [0,1] */
  double uv[2 * N * N];
  assert_ok(dbs_result_uv(result, uv, N * N));
  for (int k = 0; k < 2 * N * N; ++k) assert_true(uv[k] >= 0.0 && uv[k] <= 1.0);
  dbs_result_destroy(result);
  dbs_cloud_destroy(cloud);
}

static void cloud_at_right_angles_warns(void **state) {
  (void)state;
  dbs_cloud *cloud = grid_cloud(upright);
  warnings w = {0};
  dbs_result *result = run(cloud, &w);
  /* The cloud stands on the bottom side: the rest of the boundary is up to 1 (20 spacings)
   * from it, and its (u,v) crowd along v = 0. The sizes agree: no scale warning. */
  assert_true(stat(result, DBS_STAT_BOUNDARY_GAP) > 10.0);
  assert_true(stat(result, DBS_STAT_COVERAGE) < 0.75);
  assert_true(stat(result, DBS_STAT_SCALE_RATIO) > 0.1 && stat(result, DBS_STAT_SCALE_RATIO) < 10.0);
  assert_true(warned(&w, "point spacings from the cloud (90% of it within that): does it belong to this cloud?"));
  assert_true(warned(&w, "the cloud covers only part of the boundary"));
  assert_false(warned(&w, "units"));
  dbs_result_destroy(result);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(cloud_far_from_its_boundary_warns),
      cmocka_unit_test(cloud_at_right_angles_warns),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
