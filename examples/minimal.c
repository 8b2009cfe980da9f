/*
 * The smallest complete use of libdbs: a cloud and a boundary from arrays, the default
 * options, and the parameters of a few points.
 *
 * The cloud samples the bump z = 0.1 sin(pi x) sin(pi y) over the square [0,2] x [0,1]; the
 * boundary is the square's four straight sides, so u follows x/2 and v follows y.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "dbs.h"

#define ROWS 60
#define COLUMNS 120
#define PI 3.14159265358979323846

static int check(int status, const char *what) {
  if (status != DBS_OK) fprintf(stderr, "minimal: %s failed: %s (%s)\n", what, dbs_last_error_message(), dbs_status_string(status));
  return status != DBS_OK;
}

int main(void) {
  /* Corners (0,0,0) (2,0,0) (2,1,0) (0,1,0); bottom and top run in increasing u (x),
   * left and right in increasing v (y). */
  static const double bottom[] = {0, 0, 0, 2, 0, 0};
  static const double right[] = {2, 0, 0, 2, 1, 0};
  static const double top[] = {0, 1, 0, 2, 1, 0};
  static const double left[] = {0, 0, 0, 0, 1, 0};
  double *xyz = malloc(sizeof(double) * 3 * ROWS * COLUMNS);
  double *uv = malloc(sizeof(double) * 2 * ROWS * COLUMNS);
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_result *result = NULL;
  double mean_distance = 0.0, largest_offset = 0.0;
  size_t i, count = (size_t)ROWS * COLUMNS;
  int failed = 1;

  if (xyz == NULL || uv == NULL) {
    fprintf(stderr, "minimal: out of memory\n");
    goto done;
  }
  /* A slightly jittered grid so that the points are not aligned with anything. */
  for (i = 0; i < count; ++i) {
    double x = 2.0 * ((double)(i % COLUMNS) + 0.5 + 0.3 * sin(7.0 * (double)i)) / COLUMNS;
    double y = ((double)(i / COLUMNS) + 0.5 + 0.3 * cos(5.0 * (double)i)) / ROWS;
    xyz[3 * i] = x;
    xyz[3 * i + 1] = y;
    xyz[3 * i + 2] = 0.1 * sin(PI * x / 2.0) * sin(PI * y);
  }

  if (check(dbs_cloud_create(xyz, count, &cloud), "dbs_cloud_create")) goto done;
  if (check(dbs_boundary_create(bottom, 2, right, 2, top, 2, left, 2, &boundary), "dbs_boundary_create")) goto done;
  if (check(dbs_parameterize(cloud, boundary, NULL, &result), "dbs_parameterize")) goto done;
  if (check(dbs_result_uv(result, uv, count), "dbs_result_uv")) goto done;
  if (check(dbs_result_stat(result, DBS_STAT_MEAN_DISTANCE, &mean_distance), "dbs_result_stat")) goto done;

  /* The bump is shallow: u stays close to x/2 and v to y. */
  for (i = 0; i < count; ++i) {
    double du = fabs(uv[2 * i] - xyz[3 * i] / 2.0), dv = fabs(uv[2 * i + 1] - xyz[3 * i + 1]);
    if (du > largest_offset) largest_offset = du;
    if (dv > largest_offset) largest_offset = dv;
  }
  printf("libdbs %s: %lu points, mean distance %.3g, (u,v) within %.2g of (x/2,y)\n", dbs_version_string(), (unsigned long)count, mean_distance, largest_offset);
  printf("%10s %10s %10s   %8s %8s\n", "x", "y", "z", "u", "v");
  for (i = 37; i < count; i += count / 6 + 41) {
    printf("%10.4f %10.4f %10.4f   %8.4f %8.4f\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], uv[2 * i], uv[2 * i + 1]);
  }
  failed = largest_offset > 0.01;

done:
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  free(uv);
  free(xyz);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
