/* An outside program on the installed libdbs: the header and the loaded library agree on the
 * version, and a planar cloud inside a rectangle gets the affine parameters of its points. */
#include <math.h>
#include <stdio.h>

#include <dbs.h>

#define SIDE 30

int main(void) {
  static const double bottom[] = {1, 2, 0, 5, 2, 0}, right[] = {5, 2, 0, 5, 4, 0};
  static const double top[] = {1, 4, 0, 5, 4, 0}, left[] = {1, 2, 0, 1, 4, 0};
  static double xyz[3 * SIDE * SIDE], uv[2 * SIDE * SIDE];
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_result *result = NULL;
  double worst = 0.0;
  size_t i, count = SIDE * SIDE;
  int status;

  if (dbs_version_number() != DBS_VERSION_NUMBER) {
    fprintf(stderr, "consumer: header %d, library %d\n", DBS_VERSION_NUMBER, (int)dbs_version_number());
    return 1;
  }
  for (i = 0; i < count; ++i) {
    xyz[3 * i] = 1.0 + 4.0 * ((double)(i % SIDE) + 0.5) / SIDE;
    xyz[3 * i + 1] = 2.0 + 2.0 * ((double)(i / SIDE) + 0.5) / SIDE;
    xyz[3 * i + 2] = 0.0;
  }
  status = dbs_cloud_create(xyz, count, &cloud);
  if (status == DBS_OK) status = dbs_boundary_create(bottom, 2, right, 2, top, 2, left, 2, &boundary);
  if (status == DBS_OK) status = dbs_parameterize(cloud, boundary, NULL, &result);
  if (status == DBS_OK) status = dbs_result_uv(result, uv, count);
  if (status != DBS_OK) {
    fprintf(stderr, "consumer: %s (%s)\n", dbs_last_error_message(), dbs_status_string(status));
    return 1;
  }
  for (i = 0; i < count; ++i) {
    double du = fabs(uv[2 * i] - (xyz[3 * i] - 1.0) / 4.0);
    double dv = fabs(uv[2 * i + 1] - (xyz[3 * i + 1] - 2.0) / 2.0);
    if (du > worst) worst = du;
    if (dv > worst) worst = dv;
  }
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  if (worst > 1e-9) {
    fprintf(stderr, "consumer: (u,v) is off the affine map by %g\n", worst);
    return 1;
  }
  printf("consumer: libdbs %s parameterized %lu planar points, largest (u,v) error %.1e\n", dbs_version_string(), (unsigned long)count, worst);
  return 0;
}
