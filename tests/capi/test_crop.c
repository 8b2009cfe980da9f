/* DBS_OPT_CROP, DBS_OPT_STRICT and dbs_result_point_flags through the C API: the 2 x 1 plane
 * of 81 x 41 points (spacing 0.025) with the boundary of its middle [0.5, 1.5] x [0.25, 0.75].
 * Points outside it by two spacings or more are cropped (NaN, -1, flagged, no row in the
 * .csv), points inside keep the exact affine parameters; strict makes the same inputs
 * without cropping an error naming the clamped points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define NX 81
#define NY 41
#define SPACING 0.025
#define U0 0.5
#define U1 1.5
#define V0 0.25
#define V1 0.75

static dbs_boundary *middle_boundary(void) {
  double sides[4][3 * 11];
  for (int k = 0; k <= 10; ++k) {
    const double t = k / 10.0;
    const double pts[4][2] = {{U0 + t * (U1 - U0), V0}, {U1, V0 + t * (V1 - V0)}, {U0 + t * (U1 - U0), V1}, {U0, V0 + t * (V1 - V0)}};
    for (int s = 0; s < 4; ++s) {
      sides[s][3 * k] = pts[s][0];
      sides[s][3 * k + 1] = pts[s][1];
      sides[s][3 * k + 2] = PLANE_Z;
    }
  }
  dbs_boundary *boundary = NULL;
  assert_ok(dbs_boundary_create(sides[0], 11, sides[1], 11, sides[2], 11, sides[3], 11, &boundary));
  return boundary;
}

/* How far (x, y) lies outside the boundary's rectangle; 0 inside or on it. */
static double outside_by(double x, double y) {
  double d = 0.0;
  if (U0 - x > d) d = U0 - x;
  if (x - U1 > d) d = x - U1;
  if (V0 - y > d) d = V0 - y;
  if (y - V1 > d) d = y - V1;
  return d;
}

static dbs_options *options_with(int crop, int strict) {
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 0));
  assert_ok(dbs_options_set_int(options, DBS_OPT_CROP, crop));
  assert_ok(dbs_options_set_int(options, DBS_OPT_STRICT, strict));
  return options;
}

static void points_outside_are_cropped(void **state) {
  (void)state;
  dbs_cloud *cloud = plane_cloud(NX, NY);
  dbs_boundary *boundary = middle_boundary();
  dbs_options *options = options_with(1, 0);
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  const size_t n = NX * NY;
  double *xyz = plane_points(NX, NY), *uv = malloc(2 * n * sizeof(double)), *distance = malloc(n * sizeof(double));
  int32_t *flags = malloc(n * sizeof(int32_t)), *patch = malloc(n * sizeof(int32_t));
  assert_ok(dbs_result_uv(result, uv, 2 * n));
  assert_ok(dbs_result_distances(result, distance, n));
  assert_ok(dbs_result_point_patches(result, patch, n));
  assert_failure(dbs_result_point_flags(result, flags, n - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_result_point_flags", "out");
  assert_ok(dbs_result_point_flags(result, flags, n));
  size_t cropped = 0;
  for (size_t i = 0; i < n; ++i) {
    const double x = xyz[3 * i], y = xyz[3 * i + 1], by = outside_by(x, y);
    if (flags[i] & DBS_POINT_CROPPED) {
      assert_int_equal(flags[i], DBS_POINT_CROPPED | DBS_POINT_CLAMPED);
      assert_true(isnan(uv[2 * i]) && isnan(uv[2 * i + 1]) && isnan(distance[i]));
      assert_int_equal(patch[i], -1);
      assert_true(by > 0.5 * SPACING);
      ++cropped;
    } else {
      assert_int_equal(flags[i], 0);
      assert_true(by < 1.5 * SPACING); /* two spacings out or more: cropped */
      /* kept points just outside (a spacing out) lie on the edge at that distance */
      assert_true(distance[i] <= by + 1e-9);
      if (by == 0.0) {
        assert_true(fabs(uv[2 * i] - (x - U0) / (U1 - U0)) < 1e-9);
        assert_true(fabs(uv[2 * i + 1] - (y - V0) / (V1 - V0)) < 1e-9);
      }
    }
  }
  double stat = 0.0;
  assert_ok(dbs_result_stat(result, DBS_STAT_CROPPED_POINTS, &stat));
  assert_true(stat == (double)cropped);
  assert_true(cropped > n / 2);
  assert_ok(dbs_result_stat(result, DBS_STAT_MEAN_DISTANCE, &stat));
  assert_true(stat >= 0.0 && stat < SPACING); /* over the kept points: not NaN */

  /* The .csv has a row per point, the cropped ones with nan and -1. */
  char path[512];
  temp_path(path, sizeof path, "cropped.csv");
  assert_ok(dbs_result_save(result, cloud, path));
  size_t size = 0;
  char *text = read_all(path, &size);
  size_t rows = 0, empty = 0;
  for (size_t k = 0; k < size; ++k) rows += text[k] == '\n';
  for (const char *p = text; (p = strstr(p, ",nan,nan,nan,-1,-1\n")) != NULL; ++p) ++empty;
  assert_int_equal(rows, 1 + n);
  assert_int_equal(empty, cropped);
  free(text);
  remove(path);

  free(xyz);
  free(uv);
  free(distance);
  free(flags);
  free(patch);
  dbs_result_destroy(result);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void strict_refuses_a_larger_scan(void **state) {
  (void)state;
  dbs_cloud *cloud = plane_cloud(NX, NY);
  dbs_boundary *boundary = middle_boundary();
  dbs_options *options = options_with(0, 1);
  dbs_result *result = (dbs_result *)0x1;
  assert_failure(dbs_parameterize(cloud, boundary, options, &result), DBS_ERR_DEGENERATE, "dbs_parameterize",
                 "strict input checks: ");
  assert_non_null(strstr(dbs_last_error_message(), "points lie outside the boundary by more than a point spacing and were clamped onto the domain's edge"));
  assert_true(result == (dbs_result *)0x1);
  /* cropped, the same inputs pass strict */
  assert_ok(dbs_options_set_int(options, DBS_OPT_CROP, 1));
  result = parameterize_or_fail(cloud, boundary, options);
  dbs_result_destroy(result);
  /* without either, the run clamps and flags */
  dbs_options_destroy(options);
  options = options_with(0, 0);
  result = parameterize_or_fail(cloud, boundary, options);
  int32_t *flags = malloc(NX * NY * sizeof(int32_t));
  assert_ok(dbs_result_point_flags(result, flags, NX * NY));
  size_t clamped = 0;
  for (size_t i = 0; i < NX * NY; ++i) {
    assert_int_equal(flags[i] & DBS_POINT_CROPPED, 0);
    clamped += (flags[i] & DBS_POINT_CLAMPED) != 0;
  }
  double stat = 0.0;
  assert_ok(dbs_result_stat(result, DBS_STAT_CLAMPED_POINTS, &stat));
  assert_true(stat == (double)clamped && clamped > 0);
  assert_failure(dbs_result_point_flags(NULL, flags, 1), DBS_ERR_NULL_ARGUMENT, "dbs_result_point_flags", "result");
  assert_failure(dbs_result_point_flags(result, NULL, 1), DBS_ERR_NULL_ARGUMENT, "dbs_result_point_flags", "out");
  free(flags);
  dbs_result_destroy(result);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(points_outside_are_cropped),
      cmocka_unit_test(strict_refuses_a_larger_scan),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
