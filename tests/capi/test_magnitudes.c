/* The supported magnitudes (issue 14, item 8): a unit square scaled so that its size
 * (bounding-box diagonal) sits at either end of the supported range [1e-100, 1e75]
 * parameterizes and validates like the unit square itself: the same (u,v), a Delaunay mesh,
 * undistorted triangles, finite distances and a report; just outside the range,
 * dbs_parameterize refuses it with DBS_ERR_OUT_OF_RANGE naming the range. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define N 11
#define COUNT (N * N)

static void square(double s, dbs_cloud **cloud, dbs_boundary **boundary) {
  double xyz[3 * COUNT];
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      double *p = xyz + 3 * (j * N + i);
      /* a gentle bump, so that the surface is no plane */
      p[0] = s * i / (N - 1), p[1] = s * j / (N - 1), p[2] = s * 0.05 * sin(3.0 * i / (N - 1)) * sin(3.0 * j / (N - 1));
    }
  assert_ok(dbs_cloud_create(xyz, COUNT, cloud));
  const double b[] = {0, 0, 0, s, 0, 0}, r[] = {s, 0, 0, s, s, 0}, t[] = {0, s, 0, s, s, 0}, l[] = {0, 0, 0, 0, s, 0};
  assert_ok(dbs_boundary_create(b, 2, r, 2, t, 2, l, 2, boundary));
}

/* What validation measured: the mesh's triangle count and the 95th percentile of the
 * conformal distortion (-1 without the validation room). */
typedef struct {
  size_t triangles;
  double conformal_p95, degenerate;
} measured;

/* The (u,v) of the square scaled by s, validated; into uv. */
static measured run_and_validate(double s, double *uv) {
  measured m = {0, -1.0, -1.0};
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  square(s, &cloud, &boundary);
  dbs_result *result = parameterize_or_fail(cloud, boundary, NULL);
  assert_ok(dbs_result_uv(result, uv, COUNT));
  double distances[COUNT];
  assert_ok(dbs_result_distances(result, distances, COUNT));
  for (int i = 0; i < COUNT; ++i) assert_true(isfinite(distances[i]) && distances[i] <= 0.1 * s);
  int32_t validation = 0, report = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_VALIDATION, &validation));
  assert_ok(dbs_has_feature(DBS_FEATURE_REPORT, &report));
  if (validation) {
    dbs_mesh *mesh = NULL;
    assert_ok(dbs_mesh_create(result, cloud, &mesh));
    size_t triangles = 0;
    assert_ok(dbs_mesh_triangle_count(mesh, &triangles));
    assert_true(triangles >= 2 * (N - 1) * (N - 1));
    m.triangles = triangles;
    dbs_distortion *distortion = NULL;
    assert_ok(dbs_mesh_distortion(mesh, DBS_SCALING_UNIFORM, &distortion));
    double conformal = 0, degenerate = 0, scale_u = 0;
    assert_ok(dbs_distortion_summary(distortion, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_P95, &conformal));
    m.conformal_p95 = conformal;
    assert_ok(dbs_distortion_stat(distortion, DBS_DISTORTION_DEGENERATE, &degenerate));
    assert_ok(dbs_distortion_stat(distortion, DBS_DISTORTION_SCALE_U, &scale_u));
    assert_true(conformal >= 1.0 && isfinite(conformal));
    m.degenerate = degenerate; /* zero-area slivers along the domain's edge */
    assert_true(scale_u > 0.9 * s && scale_u < 1.2 * s); /* cloud units per unit of u */
    dbs_distances *d = NULL;
    double mean = -1;
    assert_ok(dbs_distances_create(result, 0.0, &d));
    assert_ok(dbs_distances_stat(d, -1, DBS_DISTANCES_MEAN, &mean));
    assert_true(isfinite(mean) && mean >= 0.0 && mean <= 0.1 * s);
    dbs_distances_destroy(d);
    dbs_distortion_destroy(distortion);
    dbs_mesh_destroy(mesh);
    if (report) {
      char dir[512];
      temp_path(dir, sizeof dir, s < 1 ? "report_tiny" : "report_huge");
      assert_ok(dbs_report_write(result, cloud, NULL, dir));
    }
  }
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  return m;
}

static void both_ends_of_the_range_work(void **state) {
  (void)state;
  double unit[2 * COUNT], tiny[2 * COUNT], huge[2 * COUNT];
  const measured at_unit = run_and_validate(1.0, unit);
  /* sizes 1.06e-100 and 0.99e75 (the bump adds a little height) */
  const measured at_tiny = run_and_validate(0.75e-100, tiny);
  const measured at_huge = run_and_validate(0.7e75, huge);
  /* a mesh and distortion like the unit square's (the grid's points are cocircular, so
   * rounding at 1e-100 may flip a Delaunay diagonal: counts agree within a few triangles) */
  const measured *ends[2] = {&at_tiny, &at_huge};
  for (int e = 0; e < 2 && at_unit.triangles > 0; ++e) { /* without the validation: no mesh to compare */
    assert_true(ends[e]->triangles + 10 >= at_unit.triangles && ends[e]->triangles <= at_unit.triangles + 10);
    assert_true(fabs(ends[e]->degenerate - at_unit.degenerate) <= 10.0);
    assert_true(fabs(ends[e]->conformal_p95 - at_unit.conformal_p95) <= 0.05 * at_unit.conformal_p95);
  }
  /* Within 1e-9 (seen: 6e-13 tiny, 9e-16 huge): at 1e-100 the ray neighbourhoods' test once
   * underflowed and took far points too, which moved the (u,v) by 1.4e-7. */
  for (int k = 0; k < 2 * COUNT; ++k) {
    assert_true(fabs(tiny[k] - unit[k]) < 1e-9);
    assert_true(fabs(huge[k] - unit[k]) < 1e-9);
  }
}

static void just_outside_is_refused(void **state) {
  (void)state;
  const double scales[] = {0.5e-100, 1.0e75};
  for (int k = 0; k < 2; ++k) {
    dbs_cloud *cloud = NULL;
    dbs_boundary *boundary = NULL;
    square(scales[k], &cloud, &boundary);
    dbs_result *out = NULL;
    assert_failure(dbs_parameterize(cloud, boundary, NULL, &out), DBS_ERR_OUT_OF_RANGE, "dbs_parameterize", "outside the supported range [1e-100, 1e+75]");
    assert_null(out);
    dbs_boundary_destroy(boundary);
    dbs_cloud_destroy(cloud);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(both_ends_of_the_range_work),
      cmocka_unit_test(just_outside_is_refused),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
