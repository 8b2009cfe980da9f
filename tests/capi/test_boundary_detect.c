/* dbs_boundary_detect, dbs_boundary_from_corners and the holes they find, through the C API:
 * a 1.2 x 1 plate of 6,000 jittered points with a round hole, its corners found within a few
 * point spacings, the hole returned as a loop round the true one, the run parameterizes, and
 * every bad argument gets its status and a message. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define UNTOUCHED ((dbs_boundary *)0x1)
#define NX 90
#define NY 75
#define HOLE_X 0.6
#define HOLE_Y 0.5
#define HOLE_R 0.15

static double lcg(unsigned long long *state) {
  *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*state >> 11) * 0x1.0p-53;
}

/* The plate z = 0.05 sin(2x) on [0, 1.2] x [0, 1], a jittered grid with the disk of the hole
 * left out; returns the point count. */
static size_t plate_points(double *xyz) {
  unsigned long long state = 12345;
  size_t n = 0;
  for (int j = 0; j < NY; ++j) {
    for (int i = 0; i < NX; ++i) {
      const double x = 1.2 * (i + 0.5 + 0.6 * (lcg(&state) - 0.5)) / NX, y = (j + 0.5 + 0.6 * (lcg(&state) - 0.5)) / NY;
      if (hypot(x - HOLE_X, y - HOLE_Y) < HOLE_R) continue;
      xyz[3 * n] = x;
      xyz[3 * n + 1] = y;
      xyz[3 * n + 2] = 0.05 * sin(2.0 * x);
      ++n;
    }
  }
  return n;
}

static dbs_cloud *plate(void) {
  static double xyz[3 * NX * NY];
  const size_t n = plate_points(xyz);
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, n, &cloud));
  return cloud;
}

static double corner_distance(const dbs_boundary *boundary, double x, double y) {
  double best = 1e300;
  for (int32_t side = 0; side < 4; ++side) {
    size_t count = 0;
    assert_ok(dbs_boundary_side_count(boundary, side, &count));
    double *pts = malloc(3 * count * sizeof(double));
    assert_ok(dbs_boundary_side_points(boundary, side, pts, count));
    for (size_t k = 0; k < count; k += count - 1) {
      const double d = hypot(pts[3 * k] - x, pts[3 * k + 1] - y);
      if (d < best) best = d;
    }
    free(pts);
  }
  return best;
}

static void detects_the_plate_and_its_hole(void **state) {
  (void)state;
  dbs_cloud *cloud = plate();
  dbs_boundary *boundary = NULL;
  assert_ok(dbs_boundary_detect(cloud, NULL, &boundary));
  /* the spacing is about 0.013: the corners within three of it */
  const double corners[4][2] = {{0, 0}, {1.2, 0}, {1.2, 1}, {0, 1}};
  for (int c = 0; c < 4; ++c) assert_true(corner_distance(boundary, corners[c][0], corners[c][1]) < 0.04);
  size_t holes = 0, size = 0;
  assert_ok(dbs_boundary_hole_count(boundary, &holes));
  assert_int_equal(holes, 1);
  assert_ok(dbs_boundary_hole_size(boundary, 0, &size));
  assert_true(size > 40);
  double *loop = malloc(3 * size * sizeof(double));
  assert_failure(dbs_boundary_hole_points(boundary, 0, loop, size - 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_boundary_hole_points", "out_xyz");
  assert_ok(dbs_boundary_hole_points(boundary, 0, loop, size));
  for (size_t k = 0; k < size; ++k) assert_true(fabs(hypot(loop[3 * k] - HOLE_X, loop[3 * k + 1] - HOLE_Y) - HOLE_R) < 0.03);
  assert_failure(dbs_boundary_hole_size(boundary, 1, &size), DBS_ERR_OUT_OF_RANGE, "dbs_boundary_hole_size", "hole 1");
  assert_failure(dbs_boundary_hole_points(boundary, (size_t)-1, loop, 10), DBS_ERR_OUT_OF_RANGE, "dbs_boundary_hole_points", "18446744073709551615");
  free(loop);
  /* the detected boundary parameterizes the cloud */
  dbs_result *result = NULL;
  assert_ok(dbs_parameterize(cloud, boundary, NULL, &result));
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void corners_given_as_points(void **state) {
  (void)state;
  dbs_cloud *cloud = plate();
  const double corners[12] = {0, 0, 0, 1.2, 0, 0.05 * sin(2.4), 1.2, 1, 0.05 * sin(2.4), 0, 1, 0};
  dbs_boundary *boundary = NULL;
  assert_ok(dbs_boundary_from_corners(cloud, corners, &boundary));
  for (int c = 0; c < 4; ++c) {
    /* corner c of the domain is the given point c */
    const int32_t side = c < 2 ? DBS_SIDE_BOTTOM : DBS_SIDE_TOP;
    size_t count = 0;
    assert_ok(dbs_boundary_side_count(boundary, side, &count));
    double *pts = malloc(3 * count * sizeof(double));
    assert_ok(dbs_boundary_side_points(boundary, side, pts, count));
    const size_t k = (c == 0 || c == 3) ? 0 : count - 1;
    assert_true(hypot(pts[3 * k] - corners[3 * c], pts[3 * k + 1] - corners[3 * c + 1]) < 0.04);
    free(pts);
  }
  size_t holes = 7;
  assert_ok(dbs_boundary_hole_count(boundary, &holes));
  assert_int_equal(holes, 1);
  dbs_boundary_destroy(boundary);
  /* out of cyclic order, far from the outline, not finite */
  dbs_boundary *untouched = UNTOUCHED;
  const double crossed[12] = {0, 0, 0, 1.2, 1, 0, 1.2, 0, 0, 0, 1, 0};
  assert_failure(dbs_boundary_from_corners(cloud, crossed, &untouched), DBS_ERR_INVALID_ARGUMENT, "dbs_boundary_from_corners", "cyclic order");
  const double far[12] = {0, 0, 0, 1.2, 0, 0, 1.2, 1, 0, 0, 1, 5};
  assert_failure(dbs_boundary_from_corners(cloud, far, &untouched), DBS_ERR_INVALID_ARGUMENT, "dbs_boundary_from_corners", "corner 3 lies");
  const double nan_corner[12] = {0, 0, 0, NAN, 0, 0, 1.2, 1, 0, 0, 1, 0};
  assert_failure(dbs_boundary_from_corners(cloud, nan_corner, &untouched), DBS_ERR_NON_FINITE, "dbs_boundary_from_corners", "corner 1");
  assert_true(untouched == UNTOUCHED);
  dbs_cloud_destroy(cloud);
}

/* The boundary's report: boundary.png (a PNG of 960 x 520) and boundary.json naming the hole;
 * bad arguments refused. The picture's content is checked by core_test_boundary_report. */
static void writes_the_boundary_report(void **state) {
  (void)state;
  dbs_cloud *cloud = plate();
  dbs_boundary *boundary = NULL;
  assert_ok(dbs_boundary_detect(cloud, NULL, &boundary));
  char dir[512], path[600];
  temp_path(dir, sizeof dir, "boundary_report");
  int32_t report = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_REPORT, &report));
  if (!report) {
    assert_failure(dbs_boundary_report_write(boundary, cloud, dir), DBS_ERR_UNSUPPORTED, "dbs_boundary_report_write", "without the report");
  } else {
    assert_ok(dbs_boundary_report_write(boundary, cloud, dir));
    size_t size = 0;
    snprintf(path, sizeof path, "%s/boundary.png", dir);
    unsigned char *png = (unsigned char *)read_all(path, &size);
    assert_true(size > 24 && memcmp(png, "\x89PNG\r\n\x1a\n", 8) == 0);
    /* IHDR: width and height, big-endian, at bytes 16 and 20 */
    assert_int_equal(((unsigned)png[16] << 24) | ((unsigned)png[17] << 16) | ((unsigned)png[18] << 8) | png[19], 960);
    assert_int_equal(((unsigned)png[20] << 24) | ((unsigned)png[21] << 16) | ((unsigned)png[22] << 8) | png[23], 520);
    free(png);
    snprintf(path, sizeof path, "%s/boundary.json", dir);
    char *json = read_all(path, &size);
    const char *holes = strstr(json, "\"holes\": [");
    assert_non_null(holes);
    assert_non_null(strstr(holes, "\"points\": ")); /* the one hole's object */
    assert_non_null(strstr(json, "\"name\": \"bottom v=0\""));
    free(json);
    /* a directory that cannot be made: a file stands in its way */
    snprintf(path, sizeof path, "%s/boundary.json/sub", dir);
    assert_failure(dbs_boundary_report_write(boundary, cloud, path), DBS_ERR_IO, "dbs_boundary_report_write", "cannot create the report directory");
    snprintf(path, sizeof path, "%s/boundary.png", dir);
    remove(path);
    snprintf(path, sizeof path, "%s/boundary.json", dir);
    remove(path);
    remove(dir);
    assert_failure(dbs_boundary_report_write(NULL, cloud, dir), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_report_write", "boundary");
    assert_failure(dbs_boundary_report_write(boundary, NULL, dir), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_report_write", "cloud");
    assert_failure(dbs_boundary_report_write(boundary, cloud, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_report_write", "dir");
  }
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void bad_arguments(void **state) {
  (void)state;
  dbs_cloud *cloud = plate();
  dbs_boundary *boundary = UNTOUCHED;
  const double corners[12] = {0};
  assert_failure(dbs_boundary_detect(NULL, NULL, &boundary), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_detect", "cloud");
  assert_failure(dbs_boundary_detect(cloud, NULL, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_detect", "out");
  assert_failure(dbs_boundary_from_corners(cloud, NULL, &boundary), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_from_corners", "corners_xyz");
  assert_failure(dbs_boundary_from_corners(NULL, corners, &boundary), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_from_corners", "cloud");
  size_t count = 0;
  assert_failure(dbs_boundary_hole_count(NULL, &count), DBS_ERR_NULL_ARGUMENT, "dbs_boundary_hole_count", "boundary");
  /* a boundary made from sides has no holes */
  const double b[] = {0, 0, 0, 1, 0, 0}, r[] = {1, 0, 0, 1, 1, 0}, t[] = {0, 1, 0, 1, 1, 0}, l[] = {0, 0, 0, 0, 1, 0};
  dbs_boundary *square = NULL;
  assert_ok(dbs_boundary_create(b, 2, r, 2, t, 2, l, 2, &square));
  count = 9;
  assert_ok(dbs_boundary_hole_count(square, &count));
  assert_int_equal(count, 0);
  assert_failure(dbs_boundary_hole_size(square, 0, &count), DBS_ERR_OUT_OF_RANGE, "dbs_boundary_hole_size", "hole 0");
  dbs_boundary_destroy(square);
  /* the neighbourhood: an option out of range, and more neighbours than points */
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_failure(dbs_options_set_int(options, DBS_OPT_OUTLINE_NEIGHBOURS, 5), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_int", "outline_neighbours");
  const double few[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0};
  dbs_cloud *small = NULL;
  assert_ok(dbs_cloud_create(few, 5, &small));
  assert_failure(dbs_boundary_detect(small, options, &boundary), DBS_ERR_INVALID_ARGUMENT, "dbs_boundary_detect", "at least 25");
  assert_true(boundary == UNTOUCHED);
  dbs_cloud_destroy(small);
  dbs_options_destroy(options);
  dbs_cloud_destroy(cloud);
}

static void a_closed_surface_has_no_outline(void **state) {
  (void)state;
  /* 4,000 points of a sphere (a Fibonacci spiral) */
  enum { N = 4000 };
  static double xyz[3 * N];
  for (int k = 0; k < N; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / N, r = sqrt(1.0 - z * z), phi = 2.399963229728653 * k;
    xyz[3 * k] = r * cos(phi);
    xyz[3 * k + 1] = r * sin(phi);
    xyz[3 * k + 2] = z;
  }
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, N, &cloud));
  dbs_boundary *boundary = UNTOUCHED;
  assert_failure(dbs_boundary_detect(cloud, NULL, &boundary), DBS_ERR_DEGENERATE, "dbs_boundary_detect", "closed surface");
  assert_true(boundary == UNTOUCHED);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(detects_the_plate_and_its_hole),
      cmocka_unit_test(corners_given_as_points),
      cmocka_unit_test(writes_the_boundary_report),
      cmocka_unit_test(bad_arguments),
      cmocka_unit_test(a_closed_surface_has_no_outline),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
