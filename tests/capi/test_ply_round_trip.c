/* The .ply files libdbs writes hold doubles (issue 14, item 5): a cloud at map coordinates
 * (500000.123, 4000000.456, ...) saved as a result .ply (dbs_result_save) and as a mesh .ply
 * (dbs_mesh_save) reads back with dbs_cloud_load bit for bit, and the result's u, v and
 * distance in the file are the result's own doubles. (They were 32-bit floats: 500000.123
 * came back as 500000.125.) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define N 12 /* points per row */
#define COUNT (N * N)

/* A gently curved patch 10 m across, east 500000.123 m, north 4000000.456 m, 123.789 m up:
 * coordinates no float holds. */
static dbs_cloud *map_cloud(double *xyz) {
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      double *p = xyz + 3 * (j * N + i);
      const double x = 10.0 * i / (N - 1), y = 10.0 * j / (N - 1);
      p[0] = 500000.123 + x;
      p[1] = 4000000.456 + y;
      p[2] = 123.789 + 0.01 * (x - 5) * (y - 5);
    }
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, COUNT, &cloud));
  return cloud;
}

static dbs_boundary *map_boundary(void) {
  double bottom[6], right[6], top[6], left[6];
  const double c[4][3] = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}}; /* corner (u,v) = (0,0), (1,0), (0,1), (1,1) */
  double at[4][3];
  for (int k = 0; k < 4; ++k) {
    at[k][0] = 500000.123 + c[k][0];
    at[k][1] = 4000000.456 + c[k][1];
    at[k][2] = 123.789 + 0.01 * (c[k][0] - 5) * (c[k][1] - 5);
  }
  memcpy(bottom, at[0], 24), memcpy(bottom + 3, at[1], 24);
  memcpy(right, at[1], 24), memcpy(right + 3, at[3], 24);
  memcpy(top, at[2], 24), memcpy(top + 3, at[3], 24);
  memcpy(left, at[0], 24), memcpy(left + 3, at[2], 24);
  dbs_boundary *boundary = NULL;
  assert_ok(dbs_boundary_create(bottom, 2, right, 2, top, 2, left, 2, &boundary));
  return boundary;
}

/* The little-endian double at p. */
static double le_double(const unsigned char *p) {
  uint64_t bits = 0;
  for (int k = 7; k >= 0; --k) bits = (bits << 8) | p[k];
  double x;
  memcpy(&x, &bits, 8);
  return x;
}

/* Loads `path` as a cloud and asserts it holds exactly the points xyz. */
static void assert_reads_back_exactly(const char *path, const double *xyz) {
  dbs_cloud *back = NULL;
  assert_ok(dbs_cloud_load(path, &back));
  size_t count = 0;
  assert_ok(dbs_cloud_count(back, &count));
  assert_int_equal(count, COUNT);
  double *again = malloc(sizeof(double) * 3 * COUNT);
  assert_non_null(again);
  assert_ok(dbs_cloud_points(back, again, COUNT));
  for (int k = 0; k < 3 * COUNT; ++k) {
    if (again[k] != xyz[k]) print_error("%s: value %d is %.17g, written %.17g\n", path, k, again[k], xyz[k]);
    assert_true(again[k] == xyz[k]);
  }
  assert_true(again[0] == 500000.123);
  free(again);
  dbs_cloud_destroy(back);
}

static void result_ply_is_exact(void **state) {
  (void)state;
  static double xyz[3 * COUNT];
  dbs_cloud *cloud = map_cloud(xyz);
  dbs_boundary *boundary = map_boundary();
  dbs_result *result = parameterize_or_fail(cloud, boundary, NULL);
  char path[512];
  temp_path(path, sizeof path, "map_result.ply");
  assert_ok(dbs_result_save(result, cloud, path));
  assert_reads_back_exactly(path, xyz);

  /* the body after the header: x y z u v distance (doubles) and patch (int) per point */
  size_t size = 0;
  char *bytes = read_all(path, &size);
  const char *end = strstr(bytes, "end_header\n");
  assert_non_null(end);
  assert_non_null(strstr(bytes, "property double x\nproperty double y\nproperty double z\nproperty double u\nproperty double v\nproperty double distance\nproperty int patch\n"));
  const unsigned char *body = (const unsigned char *)end + strlen("end_header\n");
  assert_int_equal(size - (size_t)((const char *)body - bytes), (size_t)COUNT * 52);
  static double uv[2 * COUNT], distance[COUNT];
  assert_ok(dbs_result_uv(result, uv, COUNT));
  assert_ok(dbs_result_distances(result, distance, COUNT));
  for (int i = 0; i < COUNT; ++i) {
    const unsigned char *row = body + 52 * i;
    assert_true(le_double(row) == xyz[3 * i]);
    assert_true(le_double(row + 24) == uv[2 * i]);
    assert_true(le_double(row + 32) == uv[2 * i + 1]);
    assert_true(le_double(row + 40) == distance[i]);
  }
  free(bytes);
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

static void mesh_ply_is_exact(void **state) {
  (void)state;
  int32_t built = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_VALIDATION, &built));
  if (!built) skip();
  static double xyz[3 * COUNT];
  dbs_cloud *cloud = map_cloud(xyz);
  dbs_boundary *boundary = map_boundary();
  dbs_result *result = parameterize_or_fail(cloud, boundary, NULL);
  dbs_mesh *mesh = NULL;
  assert_ok(dbs_mesh_create(result, cloud, &mesh));
  char path[512];
  temp_path(path, sizeof path, "map_mesh.ply");
  assert_ok(dbs_mesh_save(mesh, path));
  assert_reads_back_exactly(path, xyz);
  size_t size = 0;
  char *bytes = read_all(path, &size);
  assert_non_null(strstr(bytes, "property double x\nproperty double y\nproperty double z\nproperty double u\nproperty double v\n"));
  free(bytes);
  dbs_mesh_destroy(mesh);
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(result_ply_is_exact),
      cmocka_unit_test(mesh_ply_is_exact),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
