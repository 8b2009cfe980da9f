/* dbs_cloud_load_with_options: progress and cancellation while loading big files (issue 14,
 * item 4). A callback cancelling at its first call gives DBS_ERR_CANCELLED with *out untouched,
 * from every reader; the fractions rise monotonically through "read" (0 to 0.5) and "parse"
 * (0.5 to 1), every 4 MiB at least, and end with exactly 1 ("done"); a cancel in the middle
 * stops the load; the cloud is the one dbs_cloud_load gives. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define MAX_CALLS 4096

typedef struct {
  int calls;
  double fraction[MAX_CALLS];
  char stage[MAX_CALLS][16];
  int cancel_at_call;      /* cancel at this call (0-based); -1: never */
  double cancel_above;     /* cancel at the first fraction above this; > 1: never */
} recorder;

static int record(double fraction, const char *stage, void *payload) {
  recorder *r = payload;
  const int k = r->calls++;
  if (k < MAX_CALLS) {
    r->fraction[k] = fraction;
    snprintf(r->stage[k], sizeof r->stage[k], "%s", stage);
  }
  return k == r->cancel_at_call || fraction > r->cancel_above;
}

static dbs_options *options_with(recorder *r, int cancel_at_call, double cancel_above) {
  memset(r, 0, sizeof *r);
  r->cancel_at_call = cancel_at_call;
  r->cancel_above = cancel_above;
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_progress(options, record, r));
  return options;
}

/* The points of the big test files: a 200,000-point helix, values no short decimal holds. */
#define BIG 200000
static void big_point(int i, double p[3]) {
  p[0] = cos(i * 0.001) * 1000.0 / 3.0;
  p[1] = sin(i * 0.001) * 1000.0 / 7.0;
  p[2] = i * 0.0123456789;
}

/* Writes the big cloud as .xyz (about 11 MB), .obj (the same with "v ") or binary .ply
 * (4.8 MB of doubles) into `path`. */
static void write_big(const char *path, const char *kind) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  double p[3];
  if (strcmp(kind, "ply") == 0) {
    fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\nend_header\n", BIG);
    for (int i = 0; i < BIG; ++i) {
      big_point(i, p);
      fwrite(p, sizeof p, 1, f); /* little-endian hosts only: checked below */
    }
  } else {
    const char *prefix = strcmp(kind, "obj") == 0 ? "v " : "";
    for (int i = 0; i < BIG; ++i) {
      big_point(i, p);
      fprintf(f, "%s%.17g %.17g %.17g\n", prefix, p[0], p[1], p[2]);
    }
  }
  assert_int_equal(fclose(f), 0);
}

static int little_endian_host(void) {
  const uint16_t one = 1;
  return *(const unsigned char *)&one == 1;
}

static const char *kinds[] = {"xyz", "obj", "ply"};

static void big_path(char *buffer, size_t size, const char *kind) {
  char name[64];
  snprintf(name, sizeof name, "big_cloud.%s", kind);
  temp_path(buffer, size, name);
}

static void cancel_at_the_first_call(void **state) {
  (void)state;
  for (int k = 0; k < 3; ++k) {
    char path[512];
    big_path(path, sizeof path, kinds[k]);
    write_big(path, kinds[k]);
    recorder r;
    dbs_options *options = options_with(&r, 0, 2.0);
    dbs_cloud *sentinel = (dbs_cloud *)(uintptr_t)0x1, *out = sentinel;
    assert_failure(dbs_cloud_load_with_options(path, options, &out), DBS_ERR_CANCELLED, "dbs_cloud_load_with_options", "cancelled");
    assert_ptr_equal(out, sentinel);
    assert_int_equal(r.calls, 1);
    assert_true(r.fraction[0] == 0.0);
    assert_string_equal(r.stage[0], "read");
    dbs_options_destroy(options);
  }
}

static void progress_rises_to_one(void **state) {
  (void)state;
  for (int k = 0; k < 3; ++k) {
    if (strcmp(kinds[k], "ply") == 0 && !little_endian_host()) continue;
    char path[512];
    big_path(path, sizeof path, kinds[k]);
    write_big(path, kinds[k]);
    recorder r;
    dbs_options *options = options_with(&r, -1, 2.0);
    dbs_cloud *cloud = NULL, *plain = NULL;
    assert_ok(dbs_cloud_load_with_options(path, options, &cloud));
    assert_ok(dbs_cloud_load(path, &plain));
    /* monotone, stages in order, fractions in their stage's range, exactly 1 at the end */
    assert_true(r.calls >= 4 && r.calls < MAX_CALLS);
    int reads = 0, parses = 0;
    for (int c = 0; c < r.calls; ++c) {
      if (c > 0) assert_true(r.fraction[c] >= r.fraction[c - 1]);
      if (strcmp(r.stage[c], "read") == 0) {
        assert_int_equal(parses, 0);
        assert_true(r.fraction[c] >= 0.0 && r.fraction[c] <= 0.5);
        ++reads;
      } else if (strcmp(r.stage[c], "parse") == 0) {
        assert_true(r.fraction[c] >= 0.5 && r.fraction[c] <= 1.0);
        ++parses;
      } else {
        assert_string_equal(r.stage[c], "done");
        assert_int_equal(c, r.calls - 1);
      }
    }
    assert_true(r.fraction[r.calls - 1] == 1.0);
    /* at least every 4 MiB: the 4.8 MB PLY reports once more than its two stage starts in
     * each stage, the 11 MB text files twice more */
    const int between = strcmp(kinds[k], "ply") == 0 ? 1 : 2;
    assert_true(reads >= 1 + between);
    assert_true(parses >= 1 + between);
    /* the same cloud as dbs_cloud_load */
    size_t n = 0, m = 0;
    assert_ok(dbs_cloud_count(cloud, &n));
    assert_ok(dbs_cloud_count(plain, &m));
    assert_int_equal(n, BIG);
    assert_int_equal(m, BIG);
    double *a = malloc(sizeof(double) * 3 * BIG), *b = malloc(sizeof(double) * 3 * BIG);
    assert_non_null(a);
    assert_non_null(b);
    assert_ok(dbs_cloud_points(cloud, a, BIG));
    assert_ok(dbs_cloud_points(plain, b, BIG));
    assert_memory_equal(a, b, sizeof(double) * 3 * BIG);
    double p[3];
    big_point(BIG - 1, p);
    assert_memory_equal(a + 3 * (BIG - 1), p, sizeof p);
    free(a);
    free(b);
    dbs_cloud_destroy(cloud);
    dbs_cloud_destroy(plain);
    dbs_options_destroy(options);
  }
}

static void cancel_while_parsing(void **state) {
  (void)state;
  char path[512];
  big_path(path, sizeof path, "xyz");
  write_big(path, "xyz");
  recorder r;
  dbs_options *options = options_with(&r, -1, 0.6);
  dbs_cloud *sentinel = (dbs_cloud *)(uintptr_t)0x1, *out = sentinel;
  assert_failure(dbs_cloud_load_with_options(path, options, &out), DBS_ERR_CANCELLED, "dbs_cloud_load_with_options", "\"parse\"");
  assert_ptr_equal(out, sentinel);
  assert_string_equal(r.stage[r.calls - 1], "parse");
  assert_true(r.fraction[r.calls - 1] > 0.6 && r.fraction[r.calls - 1] < 1.0);
  dbs_options_destroy(options);
}

static void small_files_and_null_options(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "small_progress.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  /* NULL options: dbs_cloud_load */
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load_with_options(path, NULL, &cloud));
  size_t n = 0;
  assert_ok(dbs_cloud_count(cloud, &n));
  assert_int_equal(n, 3);
  dbs_cloud_destroy(cloud);
  /* a small file: each stage once at its start, then "done" */
  recorder r;
  dbs_options *options = options_with(&r, -1, 2.0);
  assert_ok(dbs_cloud_load_with_options(path, options, &cloud));
  assert_int_equal(r.calls, 3);
  assert_string_equal(r.stage[0], "read");
  assert_string_equal(r.stage[1], "parse");
  assert_string_equal(r.stage[2], "done");
  assert_true(r.fraction[0] == 0.0 && r.fraction[1] == 0.5 && r.fraction[2] == 1.0);
  dbs_cloud_destroy(cloud);
  /* the errors of dbs_cloud_load, named by this function */
  dbs_cloud *sentinel = (dbs_cloud *)(uintptr_t)0x1, *out = sentinel;
  temp_file(path, sizeof path, "bad_progress.xyz", "0 0 0\n1 x 0\n");
  assert_failure(dbs_cloud_load_with_options(path, options, &out), DBS_ERR_PARSE, "dbs_cloud_load_with_options", "bad_progress.xyz:2");
  assert_ptr_equal(out, sentinel);
  assert_failure(dbs_cloud_load_with_options(NULL, options, &out), DBS_ERR_NULL_ARGUMENT, "dbs_cloud_load_with_options", "path");
  assert_failure(dbs_cloud_load_with_options(path, options, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_cloud_load_with_options", "out");
  dbs_options_destroy(options);
}

static void drc_reports_before_and_after_decoding(void **state) {
  (void)state;
  if (!has_draco()) skip();
  /* a .drc written by dbs_result_save from a parameterized plane */
  dbs_cloud *plane = plane_cloud(11, 6);
  dbs_boundary *boundary = plane_boundary(5);
  dbs_result *result = parameterize_or_fail(plane, boundary, NULL);
  char path[512];
  temp_path(path, sizeof path, "progress.drc");
  assert_ok(dbs_result_save(result, plane, path));
  recorder r;
  dbs_options *options = options_with(&r, -1, 2.0);
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load_with_options(path, options, &cloud));
  assert_int_equal(r.calls, 2);
  assert_string_equal(r.stage[0], "decode");
  assert_true(r.fraction[0] == 0.0);
  assert_string_equal(r.stage[1], "done");
  assert_true(r.fraction[1] == 1.0);
  dbs_cloud_destroy(cloud);
  dbs_options_destroy(options);
  /* cancelled before decoding */
  options = options_with(&r, 0, 2.0);
  dbs_cloud *sentinel = (dbs_cloud *)(uintptr_t)0x1, *out = sentinel;
  assert_failure(dbs_cloud_load_with_options(path, options, &out), DBS_ERR_CANCELLED, "dbs_cloud_load_with_options", "\"decode\"");
  assert_ptr_equal(out, sentinel);
  dbs_options_destroy(options);
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(plane);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(cancel_at_the_first_call),
      cmocka_unit_test(progress_rises_to_one),
      cmocka_unit_test(cancel_while_parsing),
      cmocka_unit_test(small_files_and_null_options),
      cmocka_unit_test(drc_reports_before_and_after_decoding),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
