/* dbs_cloud_*: creation from arrays, loading from every file format, read-back, errors. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

/* AddressSanitizer's operator new reports a failed allocation and aborts instead of throwing
 * std::bad_alloc, so the out-of-memory path can only be tested without it. */
#if defined(__SANITIZE_ADDRESS__)
#define WITH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WITH_ASAN 1
#endif
#endif

/* A pointer value no function may write: outputs must stay untouched on failure. */
#define UNTOUCHED ((dbs_cloud *)0x1)

static void create_copies_points_and_bounds(void **state) {
  (void)state;
  const double xyz[] = {1, 2, 3, -4, 5.5, 6, 7, -8, 0.25, 1e-300, 2, -1e300};
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, 4, &cloud));
  size_t count = 0;
  assert_ok(dbs_cloud_count(cloud, &count));
  assert_int_equal(count, 4);

  double min[3], max[3];
  assert_ok(dbs_cloud_bounds(cloud, min, max));
  const double expected_min[3] = {-4, -8, -1e300}, expected_max[3] = {7, 5.5, 6};
  for (int c = 0; c < 3; ++c) {
    assert_true(min[c] == expected_min[c]);
    assert_true(max[c] == expected_max[c]);
  }

  double back[12];
  assert_ok(dbs_cloud_points(cloud, back, 4));
  assert_memory_equal(back, xyz, sizeof xyz);
  dbs_cloud_destroy(cloud);
}

static void create_takes_a_copy(void **state) {
  (void)state;
  double xyz[] = {0, 0, 0, 1, 1, 1};
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, 2, &cloud));
  xyz[0] = 100;
  double back[6];
  assert_ok(dbs_cloud_points(cloud, back, 2));
  assert_true(back[0] == 0.0);
  dbs_cloud_destroy(cloud);
}

static void create_rejects_empty_and_non_finite(void **state) {
  (void)state;
  dbs_cloud *cloud = UNTOUCHED;
  double xyz[3 * 20];
  for (int i = 0; i < 60; ++i) xyz[i] = i;
  assert_failure(dbs_cloud_create(xyz, 0, &cloud), DBS_ERR_EMPTY, "dbs_cloud_create", "no points");
  assert_ptr_equal(cloud, UNTOUCHED);

  xyz[3 * 17 + 1] = NAN;
  assert_failure(dbs_cloud_create(xyz, 20, &cloud), DBS_ERR_NON_FINITE, "dbs_cloud_create", "point 17 ");
  assert_ptr_equal(cloud, UNTOUCHED);
  xyz[3 * 17 + 1] = 0;
  xyz[3 * 3 + 2] = -INFINITY;
  assert_failure(dbs_cloud_create(xyz, 20, &cloud), DBS_ERR_NON_FINITE, "dbs_cloud_create", "point 3 ");
  assert_ptr_equal(cloud, UNTOUCHED);
  /* the non-finite point beyond `count` is not read */
  assert_ok(dbs_cloud_create(xyz, 3, &cloud));
  dbs_cloud_destroy(cloud);
}

static void create_rejects_an_impossible_count(void **state) {
  (void)state;
  const double xyz[3] = {0, 0, 0};
  dbs_cloud *cloud = UNTOUCHED;
  /* no array has that many points: the count is wrong */
  assert_failure(dbs_cloud_create(xyz, (size_t)-1, &cloud), DBS_ERR_INVALID_ARGUMENT, "dbs_cloud_create", "exceeds any addressable array");
#ifndef WITH_ASAN
  /* 2^58 points (6.9 EB) fit in size_t but in no address space; nothing is read from xyz */
  assert_failure(dbs_cloud_create(xyz, (size_t)1 << 58, &cloud), DBS_ERR_NO_MEMORY, "dbs_cloud_create", "out of memory");
#endif
  assert_ptr_equal(cloud, UNTOUCHED);
}

static void points_buffer_too_small(void **state) {
  (void)state;
  dbs_cloud *cloud = plane_cloud(5, 4);
  double buffer[3 * 20];
  for (int i = 0; i < 60; ++i) buffer[i] = -7.0;
  assert_failure(dbs_cloud_points(cloud, buffer, 19), DBS_ERR_BUFFER_TOO_SMALL, "dbs_cloud_points", "holds 19 points but 20 are needed");
  for (int i = 0; i < 60; ++i) assert_true(buffer[i] == -7.0);
  assert_failure(dbs_cloud_points(cloud, buffer, 0), DBS_ERR_BUFFER_TOO_SMALL, "dbs_cloud_points", "holds 0 points but 20");
  /* a larger buffer is fine and only the points are written */
  double larger[3 * 21];
  larger[60] = -7.0;
  assert_ok(dbs_cloud_points(cloud, larger, 21));
  assert_true(larger[60] == -7.0);
  assert_true(larger[3 * 19] == PLANE_W && larger[3 * 19 + 1] == PLANE_H);
  dbs_cloud_destroy(cloud);
}

static void load_xyz_text(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "cloud.xyz",
             "# a comment line\n"
             "1 2 3\n"
             "\n"
             "4,5,6\n"
             "\t7\t8\t9  extra columns 10 11\n"
             "-1.5e2 +2.25 -0 # trailing comment\n");
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load(path, &cloud));
  size_t count = 0;
  assert_ok(dbs_cloud_count(cloud, &count));
  assert_int_equal(count, 4);
  double xyz[12];
  assert_ok(dbs_cloud_points(cloud, xyz, 4));
  const double expected[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, -150, 2.25, 0};
  for (int i = 0; i < 12; ++i) assert_true(xyz[i] == expected[i]);
  dbs_cloud_destroy(cloud);

  /* .txt is the same format, and the extension is case-insensitive */
  temp_file(path, sizeof path, "cloud.TXT", "0 0 0\n1 0 0\n");
  assert_ok(dbs_cloud_load(path, &cloud));
  assert_ok(dbs_cloud_count(cloud, &count));
  assert_int_equal(count, 2);
  dbs_cloud_destroy(cloud);
}

static void load_text_errors_name_file_and_line(void **state) {
  (void)state;
  assert_load_error(LOAD_CLOUD, "malformed.xyz", "0 0 0\n# comment\n1 2 x\n", 3, DBS_ERR_PARSE, NULL);
  assert_load_error(LOAD_CLOUD, "short.xyz", "0 0 0\n1 2\n", 2, DBS_ERR_PARSE, NULL);
  assert_load_error(LOAD_CLOUD, "nan.xyz", "0 0 0\n1 1 1\n2 nan 2\n", 3, DBS_ERR_NON_FINITE, NULL);
  assert_load_error(LOAD_CLOUD, "empty.xyz", "# nothing but a comment\n\n", 0, DBS_ERR_EMPTY, NULL);
  assert_load_error(LOAD_CLOUD, "missing.xyz", NULL, 0, DBS_ERR_IO, NULL);
  assert_load_error(LOAD_CLOUD, "cloud.unknown", "0 0 0\n", 0, DBS_ERR_UNSUPPORTED, ".unknown");
}

/* The errno behind an I/O failure: ENOENT for a missing file, ENOTDIR for a path through a
 * file; 0 after a failure that is no I/O error; kept across successful calls. */
static void io_failures_tell_their_errno(void **state) {
  (void)state;
  char path[512];
  temp_path(path, sizeof path, "no_such_cloud.xyz");
  dbs_cloud *cloud = NULL;
  assert_int_equal(dbs_cloud_load(path, &cloud), DBS_ERR_IO);
  assert_int_equal(dbs_last_error_errno(), ENOENT);
  int32_t built = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_DRACO, &built));
  assert_int_equal(dbs_last_error_errno(), ENOENT);
  temp_file(path, sizeof path, "a_file.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  strcat(path, "/below.xyz");
  assert_int_equal(dbs_cloud_load(path, &cloud), DBS_ERR_IO);
  assert_int_equal(dbs_last_error_errno(), ENOTDIR);
  assert_int_equal(dbs_cloud_create(NULL, 3, &cloud), DBS_ERR_NULL_ARGUMENT);
  assert_int_equal(dbs_last_error_errno(), 0);
  assert_null(cloud);
}

static const double kFilePoints[4][3] = {{0, 0, 0}, {1.5, 0, 0.25}, {0, 2, -1}, {3, 4, 5}};

static void assert_file_points(const char *path) {
  if (!reads_with_draco(path)) return;
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load(path, &cloud));
  size_t count = 0;
  assert_ok(dbs_cloud_count(cloud, &count));
  assert_int_equal(count, 4);
  double xyz[12];
  assert_ok(dbs_cloud_points(cloud, xyz, 4));
  /* read by libdbs itself in every build: in file order, exact */
  assert_memory_equal(xyz, kFilePoints, sizeof xyz);
  dbs_cloud_destroy(cloud);
}

static void load_ply_and_obj(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "cloud.ply",
             "ply\n"
             "format ascii 1.0\n"
             "element vertex 4\n"
             "property float x\n"
             "property float y\n"
             "property float z\n"
             "end_header\n"
             "0 0 0\n"
             "1.5 0 0.25\n"
             "0 2 -1\n"
             "3 4 5\n");
  assert_file_points(path);

  temp_file(path, sizeof path, "cloud.obj",
             "# four vertices and a face\n"
             "v 0 0 0\n"
             "v 1.5 0 0.25\n"
             "v 0 2 -1\n"
             "v 3 4 5\n"
             "f 1 2 3\n");
  assert_file_points(path);
}

/* Coordinates come back as the exact doubles the file holds (map coordinates, values a float
 * cannot hold, magnitudes beyond float), from ASCII PLY and OBJ alike. */
static void ply_and_obj_coordinates_are_exact(void **state) {
  (void)state;
  static const double expected[3][3] = {{500000.123, 1.000000001, 1e300}, {-4321987.654321, 0.1, -2.5e-300}, {0, 0, 0}};
  static const char *const names[2] = {"exact.ply", "exact.obj"};
  static const char *const texts[2] = {
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
      "500000.123 1.000000001 1e300\n-4321987.654321 0.1 -2.5e-300\n0 0 0\n",
      "v 500000.123 1.000000001 1e300\nv -4321987.654321 0.1 -2.5e-300\nv 0 0 0\n"};
  for (int f = 0; f < 2; ++f) {
    char path[512];
    temp_file(path, sizeof path, names[f], texts[f]);
    dbs_cloud *cloud = NULL;
    assert_ok(dbs_cloud_load(path, &cloud));
    double xyz[9];
    assert_ok(dbs_cloud_points(cloud, xyz, 3));
    assert_memory_equal(xyz, expected, sizeof xyz);
    dbs_cloud_destroy(cloud);
  }
}

static void load_broken_ply(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "broken.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n");
  if (!reads_with_draco(path)) return;
  dbs_cloud *cloud = UNTOUCHED;
  int status = dbs_cloud_load(path, &cloud);
  assert_true(status == DBS_ERR_PARSE || status == DBS_ERR_EMPTY);
  assert_non_null(strstr(dbs_last_error_message(), path));
  assert_ptr_equal(cloud, UNTOUCHED);
}

static void destroy_accepts_null(void **state) {
  (void)state;
  dbs_cloud_destroy(NULL);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(create_copies_points_and_bounds),
      cmocka_unit_test(ply_and_obj_coordinates_are_exact),
      cmocka_unit_test(create_takes_a_copy),
      cmocka_unit_test(create_rejects_empty_and_non_finite),
      cmocka_unit_test(create_rejects_an_impossible_count),
      cmocka_unit_test(points_buffer_too_small),
      cmocka_unit_test(load_xyz_text),
      cmocka_unit_test(load_text_errors_name_file_and_line),
      cmocka_unit_test(io_failures_tell_their_errno),
      cmocka_unit_test(load_ply_and_obj),
      cmocka_unit_test(load_broken_ply),
      cmocka_unit_test(destroy_accepts_null),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
