/* Shared helpers of the libFuzzer targets (fuzz_support.h). */
#define _POSIX_C_SOURCE 200809L /* getpid */
#include "fuzz_support.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void fuzz_check(int condition, const char *text, const char *file, int line) {
  if (condition) return;
  fprintf(stderr, "%s:%d: libdbs broke its promise: %s (last error: %s)\n", file, line, text, dbs_last_error_message());
  abort();
}

/* ---- the input as a file ---------------------------------------------------------- */

#define FUZZ_FILES 4
static char fuzz_paths[FUZZ_FILES][512];
static int fuzz_path_count = 0;

static void remove_fuzz_files(void) {
  for (int i = 0; i < fuzz_path_count; ++i) remove(fuzz_paths[i]);
}

const char *fuzz_path(const char *name) {
  char wanted[512];
  const char *dir = getenv("TMPDIR");
  if (!dir || !*dir) dir = "/tmp";
  snprintf(wanted, sizeof wanted, "%s/dbs_fuzz_%ld_%s", dir, (long)getpid(), name);
  for (int i = 0; i < fuzz_path_count; ++i)
    if (strcmp(fuzz_paths[i], wanted) == 0) return fuzz_paths[i];
  FUZZ_CHECK(fuzz_path_count < FUZZ_FILES);
  if (fuzz_path_count == 0) atexit(remove_fuzz_files);
  memcpy(fuzz_paths[fuzz_path_count], wanted, sizeof wanted);
  return fuzz_paths[fuzz_path_count++];
}

const char *fuzz_file(const char *name, const uint8_t *data, size_t size) {
  const char *path = fuzz_path(name);
  FILE *f = fopen(path, "wb");
  if (!f || (size > 0 && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
    fprintf(stderr, "fuzz: cannot write %s\n", path);
    abort();
  }
  return path;
}

/* ---- decoding bytes --------------------------------------------------------------- */

uint8_t fuzz_byte(struct fuzz_bytes *in) {
  if (in->size == 0) return 0;
  --in->size;
  return *in->data++;
}

int fuzz_int(struct fuzz_bytes *in, int lo, int hi) { return lo + (int)(fuzz_byte(in) % (unsigned)(hi - lo + 1)); }

double fuzz_double(struct fuzz_bytes *in) {
  static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.5, 1e300, -1e300, 1e160, -1e160, 1e9, -1e9,
                                   1e-300, DBL_MAX, -DBL_MAX, DBL_MIN, 4.9406564584124654e-324, 1e75, 1e-100};
  const size_t n_special = sizeof special / sizeof special[0];
  const uint8_t b = fuzz_byte(in);
  if (b < 192) return (double)((int)b - 64) / 8.0; /* -8 .. 15.875 in steps of 1/8 */
  if (b < 192 + n_special) return special[b - 192];
  switch (b) {
  case 250: return NAN;
  case 251: return INFINITY;
  case 252: return -INFINITY;
  default: {
    double raw = 0.0;
    uint8_t bytes[sizeof raw];
    for (size_t i = 0; i < sizeof raw; ++i) bytes[i] = fuzz_byte(in);
    memcpy(&raw, bytes, sizeof raw);
    return raw;
  }
  }
}

/* ---- one dbs_parameterize run ----------------------------------------------------- */

#define MAX_SIDE 6

/* Side s of the unit square at z = 0 with n points, running as the corner conventions say:
 * bottom (0,0)->(1,0), right (1,0)->(1,1), top (0,1)->(1,1), left (0,0)->(0,1). */
static void square_side(int s, int n, double *xyz) {
  static const double from[4][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}};
  static const double to[4][2] = {{1, 0}, {1, 1}, {1, 1}, {0, 1}};
  for (int i = 0; i < n; ++i) {
    const double t = (double)i / (n - 1);
    xyz[3 * i] = from[s][0] + t * (to[s][0] - from[s][0]);
    xyz[3 * i + 1] = from[s][1] + t * (to[s][1] - from[s][1]);
    xyz[3 * i + 2] = 0.0;
  }
}

int fuzz_decode_run(struct fuzz_bytes *in, dbs_cloud **cloud, dbs_boundary **boundary, dbs_options **options) {
  /* the fixed-size head: sizes, options, numbers of edits */
  const int nx = fuzz_int(in, 2, 8), ny = fuzz_int(in, 2, 8);
  int side_n[4];
  for (int s = 0; s < 4; ++s) side_n[s] = fuzz_int(in, 2, MAX_SIDE);
  const int max_level = fuzz_int(in, 0, 1);
  const int initial_grid = fuzz_int(in, 3, 5);
  const int max_grid = fuzz_int(in, initial_grid, 7);
  const uint8_t flags = fuzz_byte(in);
  const int cloud_edits = fuzz_int(in, 0, 8), boundary_edits = fuzz_int(in, 0, 6);

  dbs_options *o = NULL;
  int status = dbs_options_create(&o);
  if (status != DBS_OK) return status;
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_THREADS, 1) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_MAX_LEVEL, max_level) == DBS_OK);
  /* the cross rule initial <= max: the smallest initial grid first */
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_INITIAL_GRID, 3) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_MAX_GRID, max_grid) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_INITIAL_GRID, initial_grid) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_REPAIR, flags & 1) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_int(o, DBS_OPT_NOISE_FLOOR, (flags >> 1) & 1) == DBS_OK);
  if (flags & 4) {
    /* any value: the setters refuse what is out of range, and the run keeps the default */
    const int status_set = dbs_options_set_double(o, DBS_OPT_ACCURACY, fuzz_double(in));
    FUZZ_CHECK(status_set == DBS_OK || status_set == DBS_ERR_NON_FINITE || status_set == DBS_ERR_OUT_OF_RANGE);
  }
  if (flags & 8) (void)dbs_options_set_double(o, DBS_OPT_RELATIVE_ACCURACY, fuzz_double(in));
  if (flags & 16) (void)dbs_options_set_double(o, DBS_OPT_SMOOTHING, fuzz_double(in));

  /* the cloud: a grid over the unit square, some coordinates replaced, heights last */
  const int n = nx * ny;
  double xyz[3 * 64];
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double *p = xyz + 3 * (j * nx + i);
      p[0] = (double)i / (nx - 1);
      p[1] = (double)j / (ny - 1);
      p[2] = 0.0;
    }
  for (int e = 0; e < cloud_edits; ++e) {
    const int target = fuzz_int(in, 0, n - 1);
    const uint8_t how = fuzz_byte(in);
    if (how % 4 == 3) /* a duplicate of another point */
      memcpy(xyz + 3 * target, xyz + 3 * (how / 4 % n), 3 * sizeof(double));
    else
      xyz[3 * target + how % 4] = fuzz_double(in);
  }

  /* the boundary: the unit square, some coordinates or whole corners moved */
  double sides[4][3 * MAX_SIDE];
  for (int s = 0; s < 4; ++s) square_side(s, side_n[s], sides[s]);
  for (int e = 0; e < boundary_edits; ++e) {
    const uint8_t how = fuzz_byte(in);
    const int s = how % 4, coord = (how / 4) % 3;
    if ((how / 12) % 2 == 0) {
      const int i = fuzz_int(in, 0, side_n[s] - 1);
      sides[s][3 * i + coord] = fuzz_double(in);
    } else {
      /* corner s (0,0), (1,0), (1,1), (0,1) moved in both sides that share it */
      static const int first_side[4] = {0, 0, 1, 2}, first_end[4] = {0, 1, 1, 1};
      static const int second_side[4] = {3, 1, 2, 3}, second_end[4] = {0, 0, 1, 1};
      const double value = fuzz_double(in);
      const int a = first_side[s], b = second_side[s];
      sides[a][3 * (first_end[s] ? side_n[a] - 1 : 0) + coord] = value;
      sides[b][3 * (second_end[s] ? side_n[b] - 1 : 0) + coord] = value;
    }
  }
  for (int k = 0; k < n; ++k) {
    if (in->size == 0) break;
    xyz[3 * k + 2] += ((double)fuzz_byte(in) - 128.0) / 256.0;
  }

  dbs_cloud *c = NULL;
  dbs_boundary *b = NULL;
  status = dbs_cloud_create(xyz, (size_t)n, &c);
  if (status == DBS_OK)
    status = dbs_boundary_create(sides[0], (size_t)side_n[0], sides[1], (size_t)side_n[1], sides[2], (size_t)side_n[2],
                                 sides[3], (size_t)side_n[3], &b);
  FUZZ_CHECK(status != DBS_ERR_INTERNAL);
  if (status != DBS_OK) {
    dbs_cloud_destroy(c);
    dbs_options_destroy(o);
    return status;
  }
  *cloud = c;
  *boundary = b;
  *options = o;
  return DBS_OK;
}

void fuzz_check_result(const dbs_result *result, size_t point_count) {
  size_t n = 0, patch_count = 0;
  const dbs_patches *patches = NULL;
  FUZZ_CHECK(dbs_result_point_count(result, &n) == DBS_OK && n == point_count);
  FUZZ_CHECK(dbs_result_patches(result, &patches) == DBS_OK && dbs_patches_count(patches, &patch_count) == DBS_OK);
  double *uv = malloc(sizeof(double) * 2 * n), *distance = malloc(sizeof(double) * n);
  int32_t *patch = malloc(sizeof(int32_t) * n), *level = malloc(sizeof(int32_t) * n);
  FUZZ_CHECK(uv && distance && patch && level);
  FUZZ_CHECK(dbs_result_uv(result, uv, n) == DBS_OK);
  FUZZ_CHECK(dbs_result_distances(result, distance, n) == DBS_OK);
  FUZZ_CHECK(dbs_result_point_patches(result, patch, n) == DBS_OK);
  FUZZ_CHECK(dbs_result_point_levels(result, level, n) == DBS_OK);
  for (size_t i = 0; i < n; ++i) {
    FUZZ_CHECK(uv[2 * i] >= 0.0 && uv[2 * i] <= 1.0 && uv[2 * i + 1] >= 0.0 && uv[2 * i + 1] <= 1.0);
    FUZZ_CHECK(isfinite(distance[i]) && distance[i] >= 0.0);
    FUZZ_CHECK(patch[i] >= 0 && (size_t)patch[i] < patch_count);
    int32_t leaf = 0, patch_level = -1;
    FUZZ_CHECK(dbs_patches_is_leaf(patches, (size_t)patch[i], &leaf) == DBS_OK && leaf == 1);
    FUZZ_CHECK(dbs_patches_level(patches, (size_t)patch[i], &patch_level) == DBS_OK && patch_level == level[i]);
  }
  free(uv);
  free(distance);
  free(patch);
  free(level);
}
