/* Validation (dbs_mesh_*, dbs_distortion_*, dbs_distances_*, dbs_report_write): the Delaunay
 * mesh of a planar cloud whose parameterization is an exact affine map, its distortion under
 * both domain scalings, a caller's mesh, distance statistics checked against the per-point
 * outputs, the mesh files and the report, and every error path.
 *
 * Built without the validation (DBS_HAVE_VALIDATION unset) or the report (DBS_HAVE_REPORT
 * unset), the same program checks instead that every function of the missing component is
 * exported and refuses with DBS_ERR_UNSUPPORTED and a message naming the option. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef DBS_HAVE_REPORT
#include <png.h>
#endif

#include "capi_support.h"

#define UNTOUCHED_DISTORTION ((dbs_distortion *)0x1)

#define assert_unsupported(call, function, needle) \
  assert_failure((call), DBS_ERR_UNSUPPORTED, (function), (needle))
#define WITHOUT_REPORT "built without the report (DBS_WITH_REPORT=OFF)"
#define WITHOUT_VALIDATION "built without validation (DBS_WITH_VALIDATION=OFF)"

#ifndef DBS_HAVE_REPORT
/* dbs_report_write refuses whatever its arguments and writes nothing. */
static void check_report_unsupported(const dbs_result *result, const dbs_cloud *cloud) {
  char dir[512];
  temp_path(dir, sizeof dir, "unsupported_report");
  assert_unsupported(dbs_report_write(result, cloud, NULL, dir), "dbs_report_write", WITHOUT_REPORT);
  assert_int_equal(remove(dir), -1); /* no directory was made */
  assert_unsupported(dbs_report_write(NULL, NULL, NULL, NULL), "dbs_report_write", WITHOUT_REPORT);
  int32_t built = -1;
  assert_ok(dbs_has_feature(DBS_FEATURE_REPORT, &built));
  assert_int_equal(built, 0);
}
#endif

#ifdef DBS_HAVE_VALIDATION

#define NX 41
#define NY 21
#define NPOINTS (NX * NY)
#define NCELLS ((NX - 1) * (NY - 1))

struct fixture {
  dbs_cloud *plane;
  dbs_result *plane_result;
  dbs_mesh *plane_mesh;
  dbs_cloud *bump;
  dbs_result *bump_result;
};

static int setup(void **state) {
  static struct fixture f;
  dbs_boundary *boundary = plane_boundary(5);
  f.plane = plane_cloud(NX, NY);
  f.plane_result = parameterize_or_fail(f.plane, boundary, NULL);
  dbs_boundary_destroy(boundary);
  assert_ok(dbs_mesh_create(f.plane_result, f.plane, &f.plane_mesh));
  /* an accuracy out of reach of one level of subdivision: several patches, and distances
   * that differ from point to point */
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 1));
  assert_ok(dbs_options_set_double(options, DBS_OPT_ACCURACY, 1e-6));
  f.bump = bump_cloud(40, 0.2);
  boundary = square_boundary(9);
  f.bump_result = parameterize_or_fail(f.bump, boundary, options);
  dbs_boundary_destroy(boundary);
  dbs_options_destroy(options);
  *state = &f;
  return 0;
}

static int teardown(void **state) {
  struct fixture *f = *state;
  dbs_mesh_destroy(f->plane_mesh);
  dbs_result_destroy(f->plane_result);
  dbs_cloud_destroy(f->plane);
  dbs_result_destroy(f->bump_result);
  dbs_cloud_destroy(f->bump);
  return 0;
}

static double distortion_stat(const dbs_distortion *d, int32_t id) {
  double value = NAN;
  assert_ok(dbs_distortion_stat(d, id, &value));
  return value;
}

static double distortion_summary(const dbs_distortion *d, int32_t measure, int32_t summary) {
  double value = NAN;
  assert_ok(dbs_distortion_summary(d, measure, summary, &value));
  return value;
}

static double distances_stat(const dbs_distances *d, int32_t patch, int32_t id) {
  double value = NAN;
  assert_ok(dbs_distances_stat(d, patch, id, &value));
  return value;
}

/* The grid's own triangulation, two counter-clockwise (seen from +z) triangles per cell. */
static int32_t *grid_triangles(void) {
  int32_t *t = malloc(sizeof(int32_t) * 6 * NCELLS);
  assert_non_null(t);
  int32_t *p = t;
  for (int j = 0; j + 1 < NY; ++j)
    for (int i = 0; i + 1 < NX; ++i) {
      int32_t a = j * NX + i, b = a + 1, c = a + NX, d = c + 1;
      *p++ = a, *p++ = b, *p++ = d;
      *p++ = a, *p++ = d, *p++ = c;
    }
  return t;
}

static void test_plane_mesh(void **state) {
  struct fixture *f = *state;
  size_t vertices = 0, count = 0, suspicious = 99;
  assert_ok(dbs_mesh_vertex_count(f->plane_mesh, &vertices));
  assert_int_equal(vertices, NPOINTS);
  assert_ok(dbs_mesh_triangle_count(f->plane_mesh, &count));
  assert_int_equal(count, 2 * NCELLS); /* the grid's cells, each cut in two */
  assert_ok(dbs_mesh_suspicious_count(f->plane_mesh, &suspicious));
  assert_int_equal(suspicious, 0);

  int32_t *triangles = malloc(sizeof(int32_t) * 3 * count);
  double *uv = malloc(sizeof(double) * 2 * NPOINTS);
  double *xyz = malloc(sizeof(double) * 3 * NPOINTS);
  assert_ok(dbs_mesh_triangles(f->plane_mesh, triangles, count));
  assert_ok(dbs_mesh_uv(f->plane_mesh, uv, NPOINTS));
  assert_ok(dbs_mesh_vertices(f->plane_mesh, xyz, NPOINTS));
  /* vertices are the cloud's points in input order; uv the result's */
  double *result_uv = malloc(sizeof(double) * 2 * NPOINTS);
  assert_ok(dbs_result_uv(f->plane_result, result_uv, NPOINTS));
  assert_memory_equal(uv, result_uv, sizeof(double) * 2 * NPOINTS);
  assert_true(fabs(xyz[3 * (NPOINTS - 1)] - PLANE_W) < 1e-15 && fabs(xyz[3 * (NPOINTS - 1) + 1] - PLANE_H) < 1e-15);
  /* every triangle counter-clockwise in (u,v), half a grid cell each */
  double total = 0.0;
  const double half_cell = 0.5 / NCELLS;
  for (size_t t = 0; t < count; ++t) {
    const int32_t *v = triangles + 3 * t;
    for (int k = 0; k < 3; ++k) assert_true(v[k] >= 0 && v[k] < NPOINTS);
    double area = 0.5 * ((uv[2 * v[1]] - uv[2 * v[0]]) * (uv[2 * v[2] + 1] - uv[2 * v[0] + 1]) - (uv[2 * v[1] + 1] - uv[2 * v[0] + 1]) * (uv[2 * v[2]] - uv[2 * v[0]]));
    assert_true(fabs(area - half_cell) < 1e-6 * half_cell);
    total += area;
  }
  assert_true(fabs(total - 1.0) < 1e-9);
  free(result_uv);
  free(xyz);
  free(uv);
  free(triangles);
}

static void test_plane_distortion(void **state) {
  struct fixture *f = *state;
  /* The plane is 2 x 1 and (u,v) = (x/2, y): per axis, the domain is scaled back by (2, 1)
   * and every triangle is an isometry; uniformly, by sqrt(2) and every triangle has singular
   * values sqrt(2) and 1/sqrt(2), a conformal distortion of 2. */
  dbs_distortion *per_axis = NULL, *uniform = NULL;
  assert_ok(dbs_mesh_distortion(f->plane_mesh, DBS_SCALING_PER_AXIS, &per_axis));
  assert_ok(dbs_mesh_distortion(f->plane_mesh, DBS_SCALING_UNIFORM, &uniform));
  assert_true(distortion_stat(per_axis, DBS_DISTORTION_TRIANGLES) == 2.0 * NCELLS);
  assert_true(distortion_stat(per_axis, DBS_DISTORTION_FOLDED) == 0.0);
  assert_true(distortion_stat(per_axis, DBS_DISTORTION_DEGENERATE) == 0.0);
  assert_true(fabs(distortion_stat(per_axis, DBS_DISTORTION_SCALE_U) - PLANE_W) < 1e-6);
  assert_true(fabs(distortion_stat(per_axis, DBS_DISTORTION_SCALE_V) - PLANE_H) < 1e-6);
  assert_true(fabs(distortion_summary(per_axis, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MAX) - 1.0) < 1e-6);
  assert_true(fabs(distortion_summary(per_axis, DBS_MEASURE_AREA, DBS_SUMMARY_MIN) - 1.0) < 1e-6);
  assert_true(distortion_summary(per_axis, DBS_MEASURE_EDGE_DIFFERENCE, DBS_SUMMARY_MAX) < 1e-6);
  assert_true(fabs(distortion_stat(per_axis, DBS_DISTORTION_MESH_STRETCH_L2) - 1.0) < 1e-6);
  assert_true(fabs(distortion_stat(uniform, DBS_DISTORTION_SCALE_U) - sqrt(2.0)) < 1e-6);
  assert_true(fabs(distortion_summary(uniform, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MEAN) - 2.0) < 1e-6);
  assert_true(fabs(distortion_summary(uniform, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_P95) - 2.0) < 1e-6);
  assert_true(fabs(distortion_summary(uniform, DBS_MEASURE_SIGMA1, DBS_SUMMARY_MEAN) - sqrt(2.0)) < 1e-6);
  assert_true(fabs(distortion_summary(uniform, DBS_MEASURE_SIGMA2, DBS_SUMMARY_MEAN) - sqrt(0.5)) < 1e-6);
  assert_true(fabs(distortion_summary(uniform, DBS_MEASURE_STRETCH_LINF, DBS_SUMMARY_MAX) - sqrt(2.0)) < 1e-6);
  /* per-triangle values */
  double *values = malloc(sizeof(double) * 2 * NCELLS);
  assert_ok(dbs_distortion_values(uniform, DBS_MEASURE_CONFORMAL, values, 2 * NCELLS));
  for (int t = 0; t < 2 * NCELLS; ++t) assert_true(fabs(values[t] - 2.0) < 1e-6);
  assert_ok(dbs_distortion_values(uniform, DBS_MEASURE_FOLDED, values, 2 * NCELLS));
  for (int t = 0; t < 2 * NCELLS; ++t) assert_true(values[t] == 0.0);
  free(values);
  dbs_distortion_destroy(uniform);
  dbs_distortion_destroy(per_axis);
}

static void test_caller_mesh(void **state) {
  struct fixture *f = *state;
  int32_t *triangles = grid_triangles();
  dbs_distortion *d = NULL;
  assert_ok(dbs_distortion_create(f->plane_result, f->plane, triangles, 2 * NCELLS, DBS_SCALING_PER_AXIS, &d));
  assert_true(distortion_stat(d, DBS_DISTORTION_TRIANGLES) == 2.0 * NCELLS);
  assert_true(distortion_stat(d, DBS_DISTORTION_FOLDED) == 0.0);
  assert_true(fabs(distortion_summary(d, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MAX) - 1.0) < 1e-6);
  dbs_distortion_destroy(d);
  /* The same mesh turned the other way round, one triangle flat: folds are judged against
   * the base surface's normals, so the orientation does not matter; the flat triangle is
   * degenerate, NaN in the values and in no summary. */
  for (int t = 0; t < 2 * NCELLS; ++t) {
    int32_t swap = triangles[3 * t + 1];
    triangles[3 * t + 1] = triangles[3 * t + 2];
    triangles[3 * t + 2] = swap;
  }
  triangles[0] = 0, triangles[1] = 1, triangles[2] = 2; /* three points of the first row */
  assert_ok(dbs_distortion_create(f->plane_result, f->plane, triangles, 2 * NCELLS, DBS_SCALING_UNIFORM, &d));
  assert_true(distortion_stat(d, DBS_DISTORTION_FOLDED) == 0.0);
  assert_true(distortion_stat(d, DBS_DISTORTION_DEGENERATE) == 1.0);
  assert_true(fabs(distortion_summary(d, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MIN) - 2.0) < 1e-6);
  double *values = malloc(sizeof(double) * 2 * NCELLS);
  assert_ok(dbs_distortion_values(d, DBS_MEASURE_DEGENERATE, values, 2 * NCELLS));
  assert_true(values[0] == 1.0 && values[1] == 0.0);
  assert_ok(dbs_distortion_values(d, DBS_MEASURE_CONFORMAL, values, 2 * NCELLS));
  assert_true(isnan(values[0]) && fabs(values[1] - 2.0) < 1e-6);
  free(values);
  dbs_distortion_destroy(d);
  /* no triangles at all */
  assert_ok(dbs_distortion_create(f->plane_result, f->plane, NULL, 0, DBS_SCALING_UNIFORM, &d));
  assert_true(distortion_stat(d, DBS_DISTORTION_TRIANGLES) == 0.0);
  assert_true(distortion_summary(d, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MAX) == 0.0);
  dbs_distortion_destroy(d);
  /* a triangle count no array can have: refused, not an internal error (it was
   * DBS_ERR_INTERNAL before 0.4), and nothing is read from the array */
  d = UNTOUCHED_DISTORTION;
  assert_failure(dbs_distortion_create(f->plane_result, f->plane, triangles, SIZE_MAX / 12, DBS_SCALING_UNIFORM, &d), DBS_ERR_INVALID_ARGUMENT, "dbs_distortion_create", "exceeds any addressable array");
  assert_ptr_equal(d, UNTOUCHED_DISTORTION);
  free(triangles);
}

static int compare_doubles(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static void test_distances(void **state) {
  struct fixture *f = *state;
  size_t n = 0;
  assert_ok(dbs_result_point_count(f->bump_result, &n));
  double *d = malloc(sizeof(double) * n);
  int32_t *patch = malloc(sizeof(int32_t) * n);
  assert_ok(dbs_result_distances(f->bump_result, d, n));
  assert_ok(dbs_result_point_patches(f->bump_result, patch, n));
  double accuracy = NAN, mean = NAN, max = NAN, rms = NAN;
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_ACCURACY, &accuracy));
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_MEAN_DISTANCE, &mean));
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_MAX_DISTANCE, &max));
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_RMS_DISTANCE, &rms));

  dbs_distances *stats = NULL;
  assert_ok(dbs_distances_create(f->bump_result, 0.0, &stats)); /* 0: the accuracy target */
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_TOLERANCE) == accuracy);
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_COUNT) == (double)n);
  assert_true(fabs(distances_stat(stats, -1, DBS_DISTANCES_MEAN) - mean) <= 1e-12 * mean);
  assert_true(fabs(distances_stat(stats, -1, DBS_DISTANCES_RMS) - rms) <= 1e-12 * rms);
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_MAX) == max);
  /* the same figures counted here from the per-point distances */
  double sum = 0, sum2 = 0, largest = 0;
  for (size_t i = 0; i < n; ++i) {
    sum += d[i];
    sum2 += d[i] * d[i];
    largest = d[i] > largest ? d[i] : largest;
  }
  assert_true(fabs(sum / n - mean) <= 1e-12 * mean);
  assert_true(fabs(sqrt(sum2 / n) - rms) <= 1e-12 * rms);
  assert_true(largest == max);
  /* the share within the tolerance and the median, counted here independently */
  size_t within = 0;
  for (size_t i = 0; i < n; ++i) within += d[i] <= accuracy;
  assert_true(fabs(distances_stat(stats, -1, DBS_DISTANCES_WITHIN) - (double)within / n) < 1e-15);
  assert_true(within > 0 && within < n); /* the bump is not fitted everywhere by one patch */
  double *sorted = malloc(sizeof(double) * n);
  memcpy(sorted, d, sizeof(double) * n);
  qsort(sorted, n, sizeof(double), compare_doubles);
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  assert_true(fabs(distances_stat(stats, -1, DBS_DISTANCES_P50) - median) <= 1e-12 * max);
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_P90) <= distances_stat(stats, -1, DBS_DISTANCES_P95));
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_P95) <= distances_stat(stats, -1, DBS_DISTANCES_P99));
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_P99) <= max);
  /* per patch: the leaves' counts and maxima are those of their points, other patches empty */
  double patches = 0;
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_PATCHES, &patches));
  assert_true(patches > 1);
  double counted = 0;
  for (int32_t p = 0; p < (int32_t)patches; ++p) {
    size_t own = 0;
    double own_max = 0.0;
    for (size_t i = 0; i < n; ++i)
      if (patch[i] == p) ++own, own_max = fmax(own_max, d[i]);
    assert_true(distances_stat(stats, p, DBS_DISTANCES_COUNT) == (double)own);
    assert_true(distances_stat(stats, p, DBS_DISTANCES_MAX) == own_max);
    counted += distances_stat(stats, p, DBS_DISTANCES_COUNT);
  }
  assert_true(counted == (double)n);
  dbs_distances_destroy(stats);
  /* an explicit tolerance: the largest distance takes in every point */
  assert_ok(dbs_distances_create(f->bump_result, max, &stats));
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_WITHIN) == 1.0);
  assert_true(distances_stat(stats, -1, DBS_DISTANCES_TOLERANCE) == max);
  dbs_distances_destroy(stats);
  free(sorted);
  free(patch);
  free(d);
}

/* Number of lines of `text` starting with `prefix`. */
static size_t count_lines(const char *text, const char *prefix) {
  size_t count = 0, len = strlen(prefix);
  for (const char *line = text; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL)
    if (strncmp(line, prefix, len) == 0) ++count;
  return count;
}

#ifdef DBS_HAVE_REPORT
/* Decodes a PNG file completely with libpng (a truncated or corrupt file fails here) and gives
 * its size; the picture must not be blank: at least two distinct pixel values. */
static void png_size(const char *path, uint32_t *width, uint32_t *height) {
  png_image image;
  memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path)) fail_msg("%s: %s", path, image.message);
  image.format = PNG_FORMAT_RGB;
  const size_t size = PNG_IMAGE_SIZE(image);
  unsigned char *pixels = malloc(size);
  assert_non_null(pixels);
  if (!png_image_finish_read(&image, NULL, pixels, 0, NULL)) fail_msg("%s: %s", path, image.message);
  size_t differ = 0;
  for (size_t k = 3; k < size; k += 3) differ += memcmp(pixels + k, pixels, 3) != 0;
  assert_true(differ > 0);
  *width = image.width;
  *height = image.height;
  free(pixels);
}
#endif

static void test_mesh_files(void **state) {
  struct fixture *f = *state;
  char obj[512], mtl[512], texture[512], ply[512], text[512];
  temp_path(obj, sizeof obj, "plane_mesh.obj");
  temp_path(mtl, sizeof mtl, "plane_mesh.mtl");
  temp_path(texture, sizeof texture, "plane_mesh_texture.png");
  temp_path(ply, sizeof ply, "plane_mesh.ply");
#ifdef DBS_HAVE_REPORT
  assert_ok(dbs_mesh_save(f->plane_mesh, obj));
  char *content = read_all(obj, NULL);
  const char *slash = strrchr(mtl, '/');
  snprintf(text, sizeof text, "mtllib %s\n", slash + 1);
  assert_non_null(strstr(content, text)); /* the OBJ names its MTL */
  assert_int_equal(count_lines(content, "v "), NPOINTS);
  assert_int_equal(count_lines(content, "vt "), NPOINTS); /* one vt per v */
  assert_int_equal(count_lines(content, "f "), 2 * NCELLS);
  int a = 0, at = -1, b = 0, bt = -1, c = 0, ct = -1; /* faces use the vt of their v */
  assert_int_equal(sscanf(strstr(content, "\nf ") + 1, "f %d/%d %d/%d %d/%d", &a, &at, &b, &bt, &c, &ct), 6);
  assert_true(a == at && b == bt && c == ct && a >= 1 && a <= NPOINTS);
  free(content);
  content = read_all(mtl, NULL);
  snprintf(text, sizeof text, "map_Kd %s\n", strrchr(texture, '/') + 1);
  assert_non_null(strstr(content, text)); /* the MTL names the texture */
  free(content);
  uint32_t width = 0, height = 0;
  png_size(texture, &width, &height);
  assert_int_equal(width, 1024); /* the plane is twice as long as wide: so is the texture */
  assert_int_equal(height, 512);
#else
  /* the textured OBJ needs the report's texture; the PLY does not */
  assert_unsupported(dbs_mesh_save(f->plane_mesh, obj), "dbs_mesh_save", WITHOUT_REPORT);
  assert_int_equal(remove(obj), -1);
  assert_int_equal(remove(mtl), -1);
  assert_int_equal(remove(texture), -1);
  char *content = NULL;
#endif

  assert_ok(dbs_mesh_save(f->plane_mesh, ply));
  size_t size = 0;
  content = read_all(ply, &size);
  snprintf(text, sizeof text, "element vertex %d\n", NPOINTS);
  assert_non_null(strstr(content, text));
  snprintf(text, sizeof text, "element face %d\n", 2 * NCELLS);
  assert_non_null(strstr(content, text));
  const char *end = strstr(content, "end_header\n");
  assert_non_null(end);
  /* binary body: 5 doubles per vertex (since 0.4), 1 + 3*4 bytes per face */
  assert_int_equal(size - (size_t)(end + strlen("end_header\n") - content), (size_t)NPOINTS * 40 + (size_t)2 * NCELLS * 13);
  free(content);

  char stl[512];
  temp_path(stl, sizeof stl, "plane_mesh.stl");
  assert_failure(dbs_mesh_save(f->plane_mesh, stl), DBS_ERR_UNSUPPORTED, "dbs_mesh_save", ".stl");
  char missing[600];
  snprintf(missing, sizeof missing, "%s/no/such/dir/mesh.ply", DBS_TEST_TMP_DIR);
  assert_failure(dbs_mesh_save(f->plane_mesh, missing), DBS_ERR_IO, "dbs_mesh_save", "no/such/dir");
}

#ifdef DBS_HAVE_REPORT
static void test_report(void **state) {
  struct fixture *f = *state;
  char dir[512], path[700];
  temp_path(dir, sizeof dir, "report");
  static const char *files[] = {"mesh.obj", "mesh.mtl", "mesh_texture.png", "mesh.ply", "view.png", "domain.png", "distances.png", "summary.json"};
  const size_t nfiles = sizeof files / sizeof files[0];
  assert_ok(dbs_report_write(f->bump_result, f->bump, NULL, dir));
  uint32_t width = 0, height = 0;
  snprintf(path, sizeof path, "%s/view.png", dir);
  png_size(path, &width, &height);
  assert_true(width == 720 && height == 540);
  snprintf(path, sizeof path, "%s/domain.png", dir);
  png_size(path, &width, &height);
  assert_true(width == 560 && height > width);
  snprintf(path, sizeof path, "%s/distances.png", dir);
  png_size(path, &width, &height);
  assert_true(width == 640 && height == 320);
  snprintf(path, sizeof path, "%s/mesh_texture.png", dir);
  png_size(path, &width, &height);
  assert_true(width == 1024 && height == 1024); /* the bump's domain is square */
  /* summary.json carries the figures the C API gives */
  snprintf(path, sizeof path, "%s/summary.json", dir);
  char *json = read_all(path, NULL);
  size_t n = 0;
  assert_ok(dbs_result_point_count(f->bump_result, &n));
  char expected[128];
  snprintf(expected, sizeof expected, "\"points\": %zu,", n);
  assert_non_null(strstr(json, expected));
  dbs_mesh *mesh = NULL;
  size_t triangles = 0;
  assert_ok(dbs_mesh_create(f->bump_result, f->bump, &mesh));
  assert_ok(dbs_mesh_triangle_count(mesh, &triangles));
  size_t suspicious = 99;
  assert_ok(dbs_mesh_suspicious_count(mesh, &suspicious));
  assert_int_equal(suspicious, 0); /* a good result on a regular grid bridges nothing */
  assert_true(triangles >= 2 * 39 * 39 - 10);
  snprintf(expected, sizeof expected, "\"triangles\": %zu,", triangles);
  assert_non_null(strstr(json, expected));
  dbs_distortion *d = NULL;
  assert_ok(dbs_mesh_distortion(mesh, DBS_SCALING_PER_AXIS, &d));
  assert_true(distortion_stat(d, DBS_DISTORTION_FOLDED) == 0);
  /* numbers are written to read back exactly (since 0.4; %.10g before) */
  const char *scale_u = strstr(json, "\"scale_u\": ");
  assert_non_null(scale_u);
  assert_true(strtod(scale_u + strlen("\"scale_u\": "), NULL) == distortion_stat(d, DBS_DISTORTION_SCALE_U));
  assert_non_null(strstr(json, "\"max_level\": 4,")); /* the default options */
  assert_non_null(strstr(json, "\"noise_floor\": 1")); /* the default options */
  /* the reference-free fold measure, as dbs_result_stat gives it */
  double judged = 0, folded = -1;
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_JUDGED_POINTS, &judged));
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_FOLDED_POINTS, &folded));
  assert_true(judged == (double)n && folded == 0);
  snprintf(expected, sizeof expected, "\"judged_points\": %zu,", n);
  assert_non_null(strstr(json, expected));
  assert_non_null(strstr(json, "\"folded_points\": 0,"));
  /* the bump's surface turns nowhere against its cloud (since 0.4) */
  double turned = -1;
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_TURNED_POINTS, &turned));
  assert_true(turned == 0);
  assert_non_null(strstr(json, "\"turned_points\": 0,"));
  assert_non_null(strstr(json, "\"per_axis\""));
  assert_non_null(strstr(json, "\"uniform\""));
  assert_non_null(strstr(json, "\"timings_seconds\""));
  dbs_distortion_destroy(d);
  dbs_mesh_destroy(mesh);
  free(json);
  for (size_t i = 0; i < nfiles; ++i) {
    snprintf(path, sizeof path, "%s/%s", dir, files[i]);
    assert_int_equal(remove(path), 0); /* every file was written */
  }
  assert_int_equal(remove(dir), 0);
  /* a directory that cannot be created: a file is in the way */
  char blocker[512];
  temp_file(blocker, sizeof blocker, "report_blocker", "x");
  snprintf(path, sizeof path, "%s/sub", blocker);
  assert_failure(dbs_report_write(f->bump_result, f->bump, NULL, path), DBS_ERR_IO, "dbs_report_write", "report_blocker");
}
#else
static void test_report(void **state) {
  struct fixture *f = *state;
  check_report_unsupported(f->bump_result, f->bump);
}
#endif

static void test_errors(void **state) {
  struct fixture *f = *state;
  dbs_mesh *mesh = NULL;
  dbs_distortion *d = NULL;
  dbs_distances *stats = NULL;
  double value = 0.0;
  int32_t index = 0;
  assert_failure(dbs_mesh_create(f->plane_result, f->bump, &mesh), DBS_ERR_INVALID_ARGUMENT, "dbs_mesh_create", "cloud");
  assert_null(mesh);
  /* too small buffers: an error, nothing written */
  int32_t small[6] = {-7, -7, -7, -7, -7, -7};
  assert_failure(dbs_mesh_triangles(f->plane_mesh, small, 2), DBS_ERR_BUFFER_TOO_SMALL, "dbs_mesh_triangles", "out");
  for (int k = 0; k < 6; ++k) assert_int_equal(small[k], -7);
  double xyz[3] = {-7, -7, -7};
  assert_failure(dbs_mesh_vertices(f->plane_mesh, xyz, 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_mesh_vertices", "out_xyz");
  assert_true(xyz[0] == -7);
  assert_failure(dbs_mesh_uv(f->plane_mesh, xyz, 1), DBS_ERR_BUFFER_TOO_SMALL, "dbs_mesh_uv", "out_uv");
  assert_ok(dbs_mesh_suspicious(f->plane_mesh, &index, 0)); /* none to copy: any capacity will do */

  assert_failure(dbs_mesh_distortion(f->plane_mesh, 2, &d), DBS_ERR_OUT_OF_RANGE, "dbs_mesh_distortion", "scaling");
  const int32_t bad[3] = {0, 1, NPOINTS};
  assert_failure(dbs_distortion_create(f->plane_result, f->plane, bad, 1, DBS_SCALING_UNIFORM, &d), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_create", "vertex index");
  assert_failure(dbs_distortion_create(f->plane_result, f->bump, bad, 1, DBS_SCALING_UNIFORM, &d), DBS_ERR_INVALID_ARGUMENT, "dbs_distortion_create", "cloud");
  assert_failure(dbs_distortion_create(f->plane_result, f->plane, bad, 1, -1, &d), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_create", "scaling");
  assert_null(d);
  assert_ok(dbs_mesh_distortion(f->plane_mesh, DBS_SCALING_UNIFORM, &d));
  assert_failure(dbs_distortion_stat(d, DBS_DISTORTION_CROPPED + 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_stat", "stat");
  assert_failure(dbs_distortion_stat(d, -1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_stat", "stat");
  assert_failure(dbs_distortion_summary(d, DBS_MEASURE_FOLDED, DBS_SUMMARY_MEAN, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_summary", "measure");
  assert_failure(dbs_distortion_summary(d, DBS_MEASURE_AREA, DBS_SUMMARY_MAX + 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_summary", "summary");
  assert_failure(dbs_distortion_values(d, DBS_MEASURE_CROPPED + 1, xyz, 3), DBS_ERR_OUT_OF_RANGE, "dbs_distortion_values", "measure");
  assert_failure(dbs_distortion_values(d, DBS_MEASURE_AREA, xyz, 3), DBS_ERR_BUFFER_TOO_SMALL, "dbs_distortion_values", "out");
  dbs_distortion_destroy(d);

  assert_failure(dbs_distances_create(f->bump_result, -1.0, &stats), DBS_ERR_OUT_OF_RANGE, "dbs_distances_create", "tolerance");
  assert_failure(dbs_distances_create(f->bump_result, NAN, &stats), DBS_ERR_NON_FINITE, "dbs_distances_create", "tolerance");
  assert_null(stats);
  assert_ok(dbs_distances_create(f->bump_result, 0.0, &stats));
  double patches = 0;
  assert_ok(dbs_result_stat(f->bump_result, DBS_STAT_PATCHES, &patches));
  assert_failure(dbs_distances_stat(stats, (int32_t)patches, DBS_DISTANCES_MEAN, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distances_stat", "patch");
  assert_failure(dbs_distances_stat(stats, -2, DBS_DISTANCES_MEAN, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distances_stat", "patch");
  assert_failure(dbs_distances_stat(stats, -1, DBS_DISTANCES_TOLERANCE + 1, &value), DBS_ERR_OUT_OF_RANGE, "dbs_distances_stat", "stat");
  dbs_distances_destroy(stats);

#ifdef DBS_HAVE_REPORT
  assert_failure(dbs_report_write(f->plane_result, f->bump, NULL, DBS_TEST_TMP_DIR), DBS_ERR_INVALID_ARGUMENT, "dbs_report_write", "cloud");
#endif
  /* destroying NULL is allowed */
  dbs_mesh_destroy(NULL);
  dbs_distortion_destroy(NULL);
  dbs_distances_destroy(NULL);
}

#define assert_null_argument(call, function, name) \
  assert_failure((call), DBS_ERR_NULL_ARGUMENT, (function), "argument '" name "' is NULL")

static void test_null_arguments(void **state) {
  struct fixture *f = *state;
  dbs_mesh *mesh = NULL;
  dbs_distortion *d = NULL;
  dbs_distances *stats = NULL;
  const int32_t triangle[3] = {0, 1, 2};
  double value = 0.0, buffer[6] = {0};
  int32_t indices[3] = {0};
  size_t count = 0;
  assert_null_argument(dbs_mesh_create(NULL, f->plane, &mesh), "dbs_mesh_create", "result");
  assert_null_argument(dbs_mesh_create(f->plane_result, NULL, &mesh), "dbs_mesh_create", "cloud");
  assert_null_argument(dbs_mesh_create(f->plane_result, f->plane, NULL), "dbs_mesh_create", "out");
  assert_null_argument(dbs_mesh_vertex_count(NULL, &count), "dbs_mesh_vertex_count", "mesh");
  assert_null_argument(dbs_mesh_vertex_count(f->plane_mesh, NULL), "dbs_mesh_vertex_count", "out");
  assert_null_argument(dbs_mesh_vertices(NULL, buffer, 2), "dbs_mesh_vertices", "mesh");
  assert_null_argument(dbs_mesh_vertices(f->plane_mesh, NULL, NPOINTS), "dbs_mesh_vertices", "out_xyz");
  assert_null_argument(dbs_mesh_uv(NULL, buffer, 3), "dbs_mesh_uv", "mesh");
  assert_null_argument(dbs_mesh_uv(f->plane_mesh, NULL, NPOINTS), "dbs_mesh_uv", "out_uv");
  assert_null_argument(dbs_mesh_triangle_count(NULL, &count), "dbs_mesh_triangle_count", "mesh");
  assert_null_argument(dbs_mesh_triangle_count(f->plane_mesh, NULL), "dbs_mesh_triangle_count", "out");
  assert_null_argument(dbs_mesh_triangles(NULL, indices, 1), "dbs_mesh_triangles", "mesh");
  assert_null_argument(dbs_mesh_triangles(f->plane_mesh, NULL, 2 * NCELLS), "dbs_mesh_triangles", "out");
  assert_null_argument(dbs_mesh_suspicious_count(NULL, &count), "dbs_mesh_suspicious_count", "mesh");
  assert_null_argument(dbs_mesh_suspicious_count(f->plane_mesh, NULL), "dbs_mesh_suspicious_count", "out");
  assert_null_argument(dbs_mesh_suspicious(NULL, indices, 3), "dbs_mesh_suspicious", "mesh");
  assert_null_argument(dbs_mesh_suspicious(f->plane_mesh, NULL, 3), "dbs_mesh_suspicious", "out");
  assert_null_argument(dbs_mesh_save(NULL, "x.ply"), "dbs_mesh_save", "mesh");
  assert_null_argument(dbs_mesh_save(f->plane_mesh, NULL), "dbs_mesh_save", "path");
  assert_null_argument(dbs_mesh_distortion(NULL, DBS_SCALING_UNIFORM, &d), "dbs_mesh_distortion", "mesh");
  assert_null_argument(dbs_mesh_distortion(f->plane_mesh, DBS_SCALING_UNIFORM, NULL), "dbs_mesh_distortion", "out");
  assert_null_argument(dbs_distortion_create(NULL, f->plane, triangle, 1, DBS_SCALING_UNIFORM, &d), "dbs_distortion_create", "result");
  assert_null_argument(dbs_distortion_create(f->plane_result, NULL, triangle, 1, DBS_SCALING_UNIFORM, &d), "dbs_distortion_create", "cloud");
  assert_null_argument(dbs_distortion_create(f->plane_result, f->plane, NULL, 1, DBS_SCALING_UNIFORM, &d), "dbs_distortion_create", "triangles");
  assert_null_argument(dbs_distortion_create(f->plane_result, f->plane, triangle, 1, DBS_SCALING_UNIFORM, NULL), "dbs_distortion_create", "out");
  assert_null(d);
  assert_ok(dbs_mesh_distortion(f->plane_mesh, DBS_SCALING_UNIFORM, &d));
  assert_null_argument(dbs_distortion_stat(NULL, 0, &value), "dbs_distortion_stat", "distortion");
  assert_null_argument(dbs_distortion_stat(d, 0, NULL), "dbs_distortion_stat", "out");
  assert_null_argument(dbs_distortion_summary(NULL, 0, 0, &value), "dbs_distortion_summary", "distortion");
  assert_null_argument(dbs_distortion_summary(d, 0, 0, NULL), "dbs_distortion_summary", "out");
  assert_null_argument(dbs_distortion_values(NULL, 0, buffer, 6), "dbs_distortion_values", "distortion");
  assert_null_argument(dbs_distortion_values(d, 0, NULL, 2 * NCELLS), "dbs_distortion_values", "out");
  dbs_distortion_destroy(d);
  assert_null_argument(dbs_distances_create(NULL, 0.0, &stats), "dbs_distances_create", "result");
  assert_null_argument(dbs_distances_create(f->bump_result, 0.0, NULL), "dbs_distances_create", "out");
  assert_null(stats);
  assert_ok(dbs_distances_create(f->bump_result, 0.0, &stats));
  assert_null_argument(dbs_distances_stat(NULL, -1, 0, &value), "dbs_distances_stat", "distances");
  assert_null_argument(dbs_distances_stat(stats, -1, 0, NULL), "dbs_distances_stat", "out");
  dbs_distances_destroy(stats);
#ifdef DBS_HAVE_REPORT
  assert_null_argument(dbs_report_write(NULL, f->bump, NULL, DBS_TEST_TMP_DIR), "dbs_report_write", "result");
  assert_null_argument(dbs_report_write(f->bump_result, NULL, NULL, DBS_TEST_TMP_DIR), "dbs_report_write", "cloud");
  assert_null_argument(dbs_report_write(f->bump_result, f->bump, NULL, NULL), "dbs_report_write", "dir");
#endif
  assert_true(value == 0.0 && count == 0 && indices[0] == 0 && buffer[0] == 0.0); /* outputs untouched */
}

static void test_degenerate_parameters(void **state) {
  (void)state;
  /* Points on one line across the plane: their (u,v) lie on one line too, no triangle exists. */
  double xyz[3 * 8];
  for (int i = 0; i < 8; ++i) xyz[3 * i] = i, xyz[3 * i + 1] = 0.5, xyz[3 * i + 2] = 0.5;
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, 8, &cloud));
  dbs_boundary *boundary = plane_boundary(3);
  dbs_result *result = parameterize_or_fail(cloud, boundary, NULL);
  dbs_mesh *mesh = NULL;
  assert_failure(dbs_mesh_create(result, cloud, &mesh), DBS_ERR_DEGENERATE, "dbs_mesh_create", "line");
  assert_null(mesh);
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_plane_mesh),
      cmocka_unit_test(test_plane_distortion),
      cmocka_unit_test(test_caller_mesh),
      cmocka_unit_test(test_distances),
      cmocka_unit_test(test_mesh_files),
      cmocka_unit_test(test_report),
      cmocka_unit_test(test_errors),
      cmocka_unit_test(test_null_arguments),
      cmocka_unit_test(test_degenerate_parameters),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}

#else /* a libdbs built without validation */

/* Every validation function is exported and refuses, whatever its arguments (there are no
 * validation handles to give it); its outputs are left untouched. */
static void test_without_validation(void **state) {
  (void)state;
  int32_t built = -1;
  assert_ok(dbs_has_feature(DBS_FEATURE_VALIDATION, &built));
  assert_int_equal(built, 0);
  dbs_cloud *cloud = plane_cloud(5, 3);
  dbs_boundary *boundary = plane_boundary(3);
  dbs_result *result = parameterize_or_fail(cloud, boundary, NULL);
  dbs_mesh *mesh = NULL;
  dbs_distortion *distortion = NULL;
  dbs_distances *distances = NULL;
  size_t count = 7;
  double xyz[3] = {-7, -7, -7}, value = -7;
  int32_t indices[3] = {-7, -7, -7};
  const int32_t triangle[3] = {0, 1, 5};
  char path[512];
  temp_path(path, sizeof path, "unsupported_mesh.ply");

  assert_unsupported(dbs_mesh_create(result, cloud, &mesh), "dbs_mesh_create", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_vertex_count(mesh, &count), "dbs_mesh_vertex_count", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_vertices(mesh, xyz, 1), "dbs_mesh_vertices", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_uv(mesh, xyz, 1), "dbs_mesh_uv", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_triangle_count(mesh, &count), "dbs_mesh_triangle_count", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_triangles(mesh, indices, 1), "dbs_mesh_triangles", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_suspicious_count(mesh, &count), "dbs_mesh_suspicious_count", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_suspicious(mesh, indices, 3), "dbs_mesh_suspicious", WITHOUT_VALIDATION);
  assert_unsupported(dbs_mesh_save(mesh, path), "dbs_mesh_save", WITHOUT_VALIDATION);
  assert_int_equal(remove(path), -1); /* nothing written */
  assert_unsupported(dbs_mesh_distortion(mesh, DBS_SCALING_UNIFORM, &distortion), "dbs_mesh_distortion", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distortion_create(result, cloud, triangle, 1, DBS_SCALING_PER_AXIS, &distortion), "dbs_distortion_create", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distortion_stat(distortion, DBS_DISTORTION_TRIANGLES, &value), "dbs_distortion_stat", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distortion_summary(distortion, DBS_MEASURE_CONFORMAL, DBS_SUMMARY_MEAN, &value), "dbs_distortion_summary", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distortion_values(distortion, DBS_MEASURE_AREA, xyz, 3), "dbs_distortion_values", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distances_create(result, 0.0, &distances), "dbs_distances_create", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distances_stat(distances, -1, DBS_DISTANCES_MEAN, &value), "dbs_distances_stat", WITHOUT_VALIDATION);
  /* NULL arguments: still "unsupported", the first thing a caller needs to know */
  assert_unsupported(dbs_mesh_create(NULL, NULL, NULL), "dbs_mesh_create", WITHOUT_VALIDATION);
  assert_unsupported(dbs_distances_create(NULL, 0.0, NULL), "dbs_distances_create", WITHOUT_VALIDATION);
  assert_null(mesh);
  assert_null(distortion);
  assert_null(distances);
  assert_true(count == 7 && value == -7 && xyz[0] == -7 && indices[0] == -7);
  dbs_mesh_destroy(NULL); /* the destroy functions accept NULL as always */
  dbs_distortion_destroy(NULL);
  dbs_distances_destroy(NULL);
  check_report_unsupported(result, cloud); /* no report without validation */

  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_without_validation),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}

#endif
