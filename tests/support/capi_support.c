#define _POSIX_C_SOURCE 200809L /* getpid */

#include "capi_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

double *plane_points(int nx, int ny) {
  double *xyz = malloc(sizeof(double) * 3 * (size_t)nx * (size_t)ny);
  assert_non_null(xyz);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      double *p = xyz + 3 * ((size_t)j * nx + i);
      p[0] = PLANE_W * i / (nx - 1);
      p[1] = PLANE_H * j / (ny - 1);
      p[2] = PLANE_Z;
    }
  }
  return xyz;
}

dbs_cloud *plane_cloud(int nx, int ny) {
  double *xyz = plane_points(nx, ny);
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, (size_t)nx * ny, &cloud));
  free(xyz);
  return cloud;
}

/* `n` evenly spaced points from a to b. */
static double *segment(const double a[3], const double b[3], int n) {
  double *xyz = malloc(sizeof(double) * 3 * (size_t)n);
  assert_non_null(xyz);
  for (int k = 0; k < n; ++k) {
    double t = (double)k / (n - 1);
    for (int c = 0; c < 3; ++c) xyz[3 * k + c] = k == n - 1 ? b[c] : a[c] + t * (b[c] - a[c]);
  }
  return xyz;
}

/* The rectangle with corners c00, c10, c01, c11 (corner (u,v)) as straight sides. */
static dbs_boundary *quad_boundary(const double c00[3], const double c10[3], const double c01[3], const double c11[3], int per_side) {
  double *bottom = segment(c00, c10, per_side);
  double *right = segment(c10, c11, per_side);
  double *top = segment(c01, c11, per_side);
  double *left = segment(c00, c01, per_side);
  dbs_boundary *boundary = NULL;
  size_t n = (size_t)per_side;
  assert_ok(dbs_boundary_create(bottom, n, right, n, top, n, left, n, &boundary));
  free(bottom);
  free(right);
  free(top);
  free(left);
  return boundary;
}

dbs_boundary *plane_boundary(int per_side) {
  const double c00[3] = {0, 0, PLANE_Z}, c10[3] = {PLANE_W, 0, PLANE_Z};
  const double c01[3] = {0, PLANE_H, PLANE_Z}, c11[3] = {PLANE_W, PLANE_H, PLANE_Z};
  return quad_boundary(c00, c10, c01, c11, per_side);
}

dbs_cloud *bump_cloud(int n, double amplitude) {
  const double pi = 3.14159265358979323846;
  double *xyz = malloc(sizeof(double) * 3 * (size_t)n * (size_t)n);
  assert_non_null(xyz);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      double *p = xyz + 3 * ((size_t)j * n + i);
      p[0] = (double)i / (n - 1);
      p[1] = (double)j / (n - 1);
      p[2] = amplitude * sin(pi * p[0]) * sin(pi * p[1]);
    }
  }
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_create(xyz, (size_t)n * n, &cloud));
  free(xyz);
  return cloud;
}

dbs_boundary *square_boundary(int per_side) {
  const double c00[3] = {0, 0, 0}, c10[3] = {1, 0, 0}, c01[3] = {0, 1, 0}, c11[3] = {1, 1, 0};
  return quad_boundary(c00, c10, c01, c11, per_side);
}

dbs_result *parameterize_or_fail(const dbs_cloud *cloud, const dbs_boundary *boundary, const dbs_options *options) {
  dbs_result *result = NULL;
  assert_ok(dbs_parameterize(cloud, boundary, options, &result));
  assert_non_null(result);
  return result;
}

/* Every temporary path handed out, removed when the test program exits. */
#define MAX_TEMP_PATHS 64
static char temp_paths[MAX_TEMP_PATHS][512];
static int temp_path_count;

static void remove_temp_files(void) {
  for (int i = 0; i < temp_path_count; ++i) remove(temp_paths[i]);
}

void temp_path(char *buffer, size_t size, const char *name) {
  int n = snprintf(buffer, size, "%s/%ld_%s", DBS_TEST_TMP_DIR, (long)getpid(), name);
  assert_true(n > 0 && (size_t)n < size && (size_t)n < sizeof temp_paths[0]);
  assert_true(temp_path_count < MAX_TEMP_PATHS);
  if (temp_path_count == 0) atexit(remove_temp_files);
  strcpy(temp_paths[temp_path_count++], buffer);
}

void write_text(const char *path, const char *text) {
  FILE *file = fopen(path, "wb");
  assert_non_null(file);
  assert_int_equal(fputs(text, file) >= 0, 1);
  assert_int_equal(fclose(file), 0);
}

char *read_all(const char *path, size_t *out_size) {
  FILE *file = fopen(path, "rb");
  assert_non_null(file);
  assert_int_equal(fseek(file, 0, SEEK_END), 0);
  long size = ftell(file);
  assert_true(size >= 0);
  rewind(file);
  char *text = malloc((size_t)size + 1);
  assert_non_null(text);
  assert_int_equal(fread(text, 1, (size_t)size, file), (size_t)size);
  text[size] = '\0';
  fclose(file);
  if (out_size) *out_size = (size_t)size;
  return text;
}

void temp_file(char *buffer, size_t size, const char *name, const char *text) {
  temp_path(buffer, size, name);
  write_text(buffer, text);
}

void check_load_error(enum load_kind kind, const char *name, const char *text, int line, int expected, const char *needle, const char *file, int source_line) {
  char path[512], where[600];
  temp_path(path, sizeof path, name);
  if (text != NULL) {
    write_text(path, text);
  } else {
    remove(path);
  }
  if (line > 0) {
    snprintf(where, sizeof where, "%s:%d", path, line);
  } else {
    snprintf(where, sizeof where, "%s", path);
  }
  int status, touched;
  const char *function;
  if (kind == LOAD_CLOUD) {
    dbs_cloud *const untouched = (dbs_cloud *)0x1;
    dbs_cloud *cloud = untouched;
    function = "dbs_cloud_load";
    status = dbs_cloud_load(path, &cloud);
    touched = cloud != untouched;
    if (status == DBS_OK) dbs_cloud_destroy(cloud);
  } else {
    dbs_boundary *const untouched = (dbs_boundary *)0x1;
    dbs_boundary *boundary = untouched;
    function = "dbs_boundary_load";
    status = dbs_boundary_load(path, &boundary);
    touched = boundary != untouched;
    if (status == DBS_OK) dbs_boundary_destroy(boundary);
  }
  check_failure(status, expected, function, where, file, source_line);
  if (needle != NULL && strstr(dbs_last_error_message(), needle) == NULL) {
    print_error("%s:%d: %s(\"%s\"): message \"%s\" lacks \"%s\"\n", file, source_line, function, name, dbs_last_error_message(), needle);
    _fail(file, source_line);
  }
  if (touched) {
    print_error("%s:%d: %s(\"%s\") failed but wrote its output\n", file, source_line, function, name);
    _fail(file, source_line);
  }
}

int has_draco(void) {
  int32_t draco = -1;
  assert_ok(dbs_has_feature(DBS_FEATURE_DRACO, &draco));
  assert_true(draco == 0 || draco == 1);
  return draco;
}

int reads_with_draco(const char *path) {
  /* since 0.4 .ply and .obj are read by libdbs itself in every build; only .drc needs Draco */
  const size_t length = strlen(path);
  if (length < 4 || strcmp(path + length - 4, ".drc") != 0) return 1;
  if (has_draco()) return 1;
  dbs_cloud *cloud = NULL;
  assert_failure(dbs_cloud_load(path, &cloud), DBS_ERR_UNSUPPORTED, "dbs_cloud_load", "built without Draco");
  assert_null(cloud);
  return 0;
}

void check_failure(int status, int expected, const char *function, const char *needle, const char *file, int line) {
  const char *message = dbs_last_error_message();
  size_t prefix = strlen(function);
  int prefix_ok = strncmp(message, function, prefix) == 0 && message[prefix] == ':';
  int needle_ok = needle == NULL || strstr(message, needle) != NULL;
  if (status != expected || !prefix_ok || !needle_ok) {
    print_error("%s:%d: status %d (%s), expected %d (%s); message \"%s\", expected \"%s: ...%s...\"\n", file, line, status,
                dbs_status_string(status), expected, dbs_status_string(expected), message, function, needle ? needle : "");
    _fail(file, line);
  }
}

void check_ok(int status, const char *call, const char *file, int line) {
  if (status != DBS_OK) {
    print_error("%s:%d: %s returned %d (%s): %s\n", file, line, call, status, dbs_status_string(status), dbs_last_error_message());
    _fail(file, line);
  }
}
