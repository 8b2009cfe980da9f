/* dbs_boundary_load on the fuzz input as a boundary file. A load either fails with a
 * documented status and a message, leaving the handle untouched, or gives four sides of at
 * least 2 finite points whose corners coincide exactly, which dbs_boundary_save writes and
 * dbs_boundary_load reads back bit for bit. The tolerant loader runs on the same file. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_support.h"

static int is_load_error(int status) {
  return status == DBS_ERR_PARSE || status == DBS_ERR_NON_FINITE || status == DBS_ERR_EMPTY || status == DBS_ERR_DEGENERATE ||
         status == DBS_ERR_OUT_OF_RANGE || status == DBS_ERR_IO || status == DBS_ERR_INVALID_ARGUMENT;
}

/* The points of one side, malloc'ed; its count in *n. */
static double *side_points(const dbs_boundary *boundary, int32_t side, size_t *n) {
  FUZZ_CHECK(dbs_boundary_side_count(boundary, side, n) == DBS_OK && *n >= 2);
  double *xyz = malloc(sizeof(double) * 3 * *n);
  FUZZ_CHECK(xyz != NULL);
  FUZZ_CHECK(dbs_boundary_side_points(boundary, side, xyz, *n) == DBS_OK);
  for (size_t i = 0; i < 3 * *n; ++i) FUZZ_CHECK(isfinite(xyz[i]));
  return xyz;
}

static void check_boundary(const dbs_boundary *boundary) {
  size_t n[4];
  double *side[4];
  for (int32_t s = 0; s < 4; ++s) side[s] = side_points(boundary, s, &n[s]);
  /* bottom[0]=left[0], bottom[end]=right[0], top[0]=left[end], top[end]=right[end] */
  const double *b = side[DBS_SIDE_BOTTOM], *r = side[DBS_SIDE_RIGHT], *t = side[DBS_SIDE_TOP], *l = side[DBS_SIDE_LEFT];
  FUZZ_CHECK(memcmp(b, l, 3 * sizeof(double)) == 0);
  FUZZ_CHECK(memcmp(b + 3 * (n[0] - 1), r, 3 * sizeof(double)) == 0);
  FUZZ_CHECK(memcmp(t, l + 3 * (n[3] - 1), 3 * sizeof(double)) == 0);
  FUZZ_CHECK(memcmp(t + 3 * (n[2] - 1), r + 3 * (n[1] - 1), 3 * sizeof(double)) == 0);

  dbs_boundary *again = NULL;
  const char *saved = fuzz_path("saved_boundary.txt");
  FUZZ_CHECK(dbs_boundary_save(boundary, saved) == DBS_OK);
  FUZZ_CHECK(dbs_boundary_load(saved, &again) == DBS_OK);
  for (int32_t s = 0; s < 4; ++s) {
    size_t m = 0;
    double *read_back = side_points(again, s, &m);
    FUZZ_CHECK(m == n[s] && memcmp(read_back, side[s], sizeof(double) * 3 * m) == 0);
    free(read_back);
    free(side[s]);
  }
  dbs_boundary_destroy(again);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const char *path = fuzz_file("boundary.txt", data, size);
  dbs_boundary *boundary = NULL;
  int status = dbs_boundary_load(path, &boundary);
  if (status == DBS_OK) {
    check_boundary(boundary);
    dbs_boundary_destroy(boundary);
  } else {
    FUZZ_CHECK(is_load_error(status) && boundary == NULL && dbs_last_error_message()[0] != '\0');
  }
  /* the largest tolerance the tolerant loader takes: corners far apart are made to meet */
  double snap = -1.0;
  boundary = NULL;
  status = dbs_boundary_load_tolerant(path, 0.1, 1, &snap, &boundary);
  if (status == DBS_OK) {
    FUZZ_CHECK(isfinite(snap) && snap >= 0.0);
    check_boundary(boundary);
    dbs_boundary_destroy(boundary);
  } else {
    FUZZ_CHECK(is_load_error(status) && boundary == NULL && snap == -1.0);
  }
  return 0;
}
