/* The validation calls on the result of a small run decoded from the fuzz input
 * (fuzz_decode_run): the Delaunay mesh of its (u,v) (Qhull on coincident, collinear, huge
 * and tiny parameters), the distortion of that mesh and of a caller's mesh whose vertex
 * indices come from the input (negative, past the cloud, repeated), the distance
 * statistics with a tolerance from the input, every id in and out of range. Each call
 * either fails with a documented status or gives what dbs.h promises. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_support.h"

static void check_distortion(const dbs_distortion *distortion, size_t triangles) {
  double count = -1.0, value = 0.0;
  FUZZ_CHECK(dbs_distortion_stat(distortion, DBS_DISTORTION_TRIANGLES, &count) == DBS_OK && count == (double)triangles);
  for (int32_t stat = -1; stat <= 6; ++stat) {
    const int status = dbs_distortion_stat(distortion, stat, &value);
    FUZZ_CHECK(status == DBS_OK || (status == DBS_ERR_OUT_OF_RANGE && (stat < 0 || stat > 5)));
  }
  for (int32_t measure = -1; measure <= 9; ++measure) {
    for (int32_t summary = -1; summary <= 4; ++summary) {
      const int status = dbs_distortion_summary(distortion, measure, summary, &value);
      FUZZ_CHECK(status == DBS_OK || status == DBS_ERR_OUT_OF_RANGE);
      if (status == DBS_OK) FUZZ_CHECK(!isnan(value));
    }
    double *values = malloc(sizeof(double) * (triangles + 1));
    FUZZ_CHECK(values != NULL);
    const int status = dbs_distortion_values(distortion, measure, values, triangles);
    FUZZ_CHECK(status == DBS_OK || status == DBS_ERR_OUT_OF_RANGE);
    free(values);
  }
}

static void check_mesh(const dbs_result *result, const dbs_cloud *cloud, struct fuzz_bytes *in) {
  dbs_mesh *mesh = NULL;
  const int status = dbs_mesh_create(result, cloud, &mesh);
  if (status != DBS_OK) {
    FUZZ_CHECK(status == DBS_ERR_DEGENERATE || status == DBS_ERR_NUMERICAL);
    FUZZ_CHECK(mesh == NULL);
    return;
  }
  size_t vertices = 0, triangles = 0, suspicious = 0;
  FUZZ_CHECK(dbs_mesh_vertex_count(mesh, &vertices) == DBS_OK);
  FUZZ_CHECK(dbs_mesh_triangle_count(mesh, &triangles) == DBS_OK);
  FUZZ_CHECK(dbs_mesh_suspicious_count(mesh, &suspicious) == DBS_OK && suspicious <= triangles);
  int32_t *corners = malloc(sizeof(int32_t) * 3 * (triangles + 1));
  int32_t *flagged = malloc(sizeof(int32_t) * (suspicious + 1));
  FUZZ_CHECK(corners != NULL && flagged != NULL);
  FUZZ_CHECK(dbs_mesh_triangles(mesh, corners, triangles) == DBS_OK);
  for (size_t i = 0; i < 3 * triangles; ++i) FUZZ_CHECK(corners[i] >= 0 && (size_t)corners[i] < vertices);
  FUZZ_CHECK(dbs_mesh_suspicious(mesh, flagged, suspicious) == DBS_OK);
  for (size_t i = 0; i < suspicious; ++i) FUZZ_CHECK(flagged[i] >= 0 && (size_t)flagged[i] < triangles);
  free(corners);
  free(flagged);

  const int32_t scaling = fuzz_int(in, -1, 2);
  dbs_distortion *distortion = NULL;
  const int d = dbs_mesh_distortion(mesh, scaling, &distortion);
  if (d == DBS_OK) {
    check_distortion(distortion, triangles);
    dbs_distortion_destroy(distortion);
  } else {
    FUZZ_CHECK(d == DBS_ERR_OUT_OF_RANGE && (scaling < 0 || scaling > 1) && distortion == NULL);
  }
  dbs_mesh_destroy(mesh);
}

/* A caller's mesh: up to 12 triangles, each index the cloud's point count plus a small
 * signed offset from the input, or raw 32 bits. */
static void check_caller_mesh(const dbs_result *result, const dbs_cloud *cloud, struct fuzz_bytes *in) {
  size_t n = 0;
  FUZZ_CHECK(dbs_cloud_count(cloud, &n) == DBS_OK);
  const size_t triangles = (size_t)fuzz_int(in, 0, 12);
  int32_t corners[36];
  for (size_t i = 0; i < 3 * triangles; ++i) {
    const uint8_t b = fuzz_byte(in);
    if (b < 250) {
      corners[i] = (int32_t)(b % (n + 2)) - 1; /* -1 .. n */
    } else {
      uint32_t raw = 0;
      for (int k = 0; k < 4; ++k) raw = raw << 8 | fuzz_byte(in);
      memcpy(&corners[i], &raw, sizeof raw);
    }
  }
  dbs_distortion *distortion = NULL;
  const int status = dbs_distortion_create(result, cloud, triangles ? corners : NULL, triangles, DBS_SCALING_PER_AXIS, &distortion);
  if (status == DBS_OK) {
    for (size_t i = 0; i < 3 * triangles; ++i) FUZZ_CHECK(corners[i] >= 0 && (size_t)corners[i] < n);
    check_distortion(distortion, triangles);
    dbs_distortion_destroy(distortion);
  } else {
    FUZZ_CHECK(status == DBS_ERR_OUT_OF_RANGE || status == DBS_ERR_NUMERICAL);
    FUZZ_CHECK(distortion == NULL);
  }
}

static void check_distances(const dbs_result *result, struct fuzz_bytes *in) {
  const double tolerance = fuzz_double(in);
  dbs_distances *distances = NULL;
  const int status = dbs_distances_create(result, tolerance, &distances);
  if (status != DBS_OK) {
    FUZZ_CHECK((status == DBS_ERR_NON_FINITE && !isfinite(tolerance)) || (status == DBS_ERR_OUT_OF_RANGE && tolerance < 0.0));
    FUZZ_CHECK(distances == NULL);
    return;
  }
  double patches = 0.0, value = 0.0;
  FUZZ_CHECK(dbs_result_stat(result, DBS_STAT_PATCHES, &patches) == DBS_OK);
  for (int32_t patch = -2; patch <= (int32_t)patches; ++patch)
    for (int32_t stat = -1; stat <= 10; ++stat) {
      const int s = dbs_distances_stat(distances, patch, stat, &value);
      FUZZ_CHECK(s == DBS_OK || s == DBS_ERR_OUT_OF_RANGE);
      if (s == DBS_OK) FUZZ_CHECK(isfinite(value) && value >= 0.0);
    }
  dbs_distances_destroy(distances);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  struct fuzz_bytes in = {data, size};
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_options *options = NULL;
  if (fuzz_decode_run(&in, &cloud, &boundary, &options) != DBS_OK) return 0;
  dbs_result *result = NULL;
  if (dbs_parameterize(cloud, boundary, options, &result) == DBS_OK) {
    /* the validation reads the input after the run's own bytes */
    check_mesh(result, cloud, &in);
    check_caller_mesh(result, cloud, &in);
    check_distances(result, &in);

    /* a cloud of another size is refused */
    const double one[3] = {0, 0, 0};
    dbs_cloud *other = NULL;
    dbs_mesh *mesh = NULL;
    size_t n = 0;
    FUZZ_CHECK(dbs_cloud_count(cloud, &n) == DBS_OK);
    FUZZ_CHECK(dbs_cloud_create(one, 1, &other) == DBS_OK);
    if (n != 1) FUZZ_CHECK(dbs_mesh_create(result, other, &mesh) == DBS_ERR_INVALID_ARGUMENT && mesh == NULL);
    dbs_cloud_destroy(other);
    dbs_result_destroy(result);
  }
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  return 0;
}
