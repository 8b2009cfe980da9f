/* Version queries, status names and the per-thread last-error message. */
#define _POSIX_C_SOURCE 200809L /* pthreads */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "capi_support.h"

static void version_macros_equal_runtime(void **state) {
  (void)state;
  char expected[32];
  snprintf(expected, sizeof expected, "%d.%d.%d", DBS_VERSION_MAJOR, DBS_VERSION_MINOR, DBS_VERSION_PATCH);
  assert_string_equal(dbs_version_string(), expected);
  assert_int_equal(dbs_version_number(), DBS_VERSION_NUMBER);
  assert_int_equal(dbs_version_number(), DBS_VERSION_MAJOR * 10000 + DBS_VERSION_MINOR * 100 + DBS_VERSION_PATCH);
}

static void at_least_version_compares(void **state) {
  (void)state;
  assert_true(DBS_AT_LEAST_VERSION(DBS_VERSION_MAJOR, DBS_VERSION_MINOR, DBS_VERSION_PATCH));
  assert_true(DBS_AT_LEAST_VERSION(0, 0, 0));
  assert_false(DBS_AT_LEAST_VERSION(DBS_VERSION_MAJOR, DBS_VERSION_MINOR, DBS_VERSION_PATCH + 1));
  assert_false(DBS_AT_LEAST_VERSION(DBS_VERSION_MAJOR, DBS_VERSION_MINOR + 1, 0));
  assert_false(DBS_AT_LEAST_VERSION(DBS_VERSION_MAJOR + 1, 0, 0));
}

/* dbs_has_feature tells the truth: a PLY cloud loads in every build (since 0.4), a .drc file
 * with Draco, and without it the load is refused as unsupported; unknown ids and a NULL out
 * are refused. */
static void features_are_reported(void **state) {
  (void)state;
  char path[512];
  temp_file(path, sizeof path, "feature.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load(path, &cloud));
  dbs_cloud_destroy(cloud);
  temp_file(path, sizeof path, "feature.drc", "DRACO, or not\n");
  if (reads_with_draco(path)) { /* without Draco it has checked that the load is refused */
    cloud = NULL;
    assert_failure(dbs_cloud_load(path, &cloud), DBS_ERR_PARSE, "dbs_cloud_load", "feature.drc");
    assert_null(cloud);
  }
  int32_t out = -7;
  /* The optional rooms: the build's own definitions say what was built. */
  assert_ok(dbs_has_feature(DBS_FEATURE_VALIDATION, &out));
#ifdef DBS_HAVE_VALIDATION
  assert_int_equal(out, 1);
#else
  assert_int_equal(out, 0);
#endif
  assert_ok(dbs_has_feature(DBS_FEATURE_REPORT, &out));
#ifdef DBS_HAVE_REPORT
  assert_int_equal(out, 1);
#else
  assert_int_equal(out, 0);
#endif
  assert_ok(dbs_has_feature(DBS_FEATURE_CERES, &out));
#ifdef DBS_HAVE_CERES
  assert_int_equal(out, 1);
#else
  assert_int_equal(out, 0);
#endif
  out = -7;
  assert_failure(dbs_has_feature(4, &out), DBS_ERR_OUT_OF_RANGE, "dbs_has_feature", "feature 4 is outside its range [0, 4)");
  assert_failure(dbs_has_feature(-1, &out), DBS_ERR_OUT_OF_RANGE, "dbs_has_feature", "feature -1 ");
  assert_int_equal(out, -7);
  assert_failure(dbs_has_feature(DBS_FEATURE_DRACO, NULL), DBS_ERR_NULL_ARGUMENT, "dbs_has_feature", "'out'");
}

static void every_status_has_its_name(void **state) {
  (void)state;
  static const struct {
    int status;
    const char *name;
  } names[] = {
      {DBS_OK, "ok"},
      {DBS_ERR_NULL_ARGUMENT, "null argument"},
      {DBS_ERR_INVALID_ARGUMENT, "invalid argument"},
      {DBS_ERR_OUT_OF_RANGE, "out of range"},
      {DBS_ERR_NON_FINITE, "non-finite value"},
      {DBS_ERR_EMPTY, "empty"},
      {DBS_ERR_DEGENERATE, "degenerate geometry"},
      {DBS_ERR_IO, "input/output error"},
      {DBS_ERR_PARSE, "parse error"},
      {DBS_ERR_UNSUPPORTED, "unsupported"},
      {DBS_ERR_CANCELLED, "cancelled"},
      {DBS_ERR_NO_MEMORY, "out of memory"},
      {DBS_ERR_BUFFER_TOO_SMALL, "buffer too small"},
      {DBS_ERR_NUMERICAL, "numerical failure"},
      {DBS_ERR_INTERNAL, "internal error"},
  };
  const size_t count = sizeof names / sizeof names[0];
  for (size_t i = 0; i < count; ++i) {
    assert_string_equal(dbs_status_string(names[i].status), names[i].name);
    for (size_t j = 0; j < i; ++j) assert_string_not_equal(names[i].name, names[j].name);
  }
  /* the codes are pinned */
  assert_int_equal(DBS_ERR_NULL_ARGUMENT, -1);
  assert_int_equal(DBS_ERR_NUMERICAL, -13);
  assert_int_equal(DBS_ERR_INTERNAL, -99);
}

static void unknown_status_is_named_unknown(void **state) {
  (void)state;
  const int unknown[] = {1, 42, -14, -98, -100, -2147483647 - 1, 2147483647};
  for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) assert_string_equal(dbs_status_string(unknown[i]), "unknown status");
}

/* What a second thread saw: its message before and after its own failure. */
struct thread_record {
  char before[256];
  char after[256];
  int status;
};

static void *fail_on_other_thread(void *arg) {
  struct thread_record *record = arg;
  snprintf(record->before, sizeof record->before, "%s", dbs_last_error_message());
  double min, max;
  record->status = dbs_option_bounds(12345, &min, &max);
  snprintf(record->after, sizeof record->after, "%s", dbs_last_error_message());
  return NULL;
}

static void last_error_is_per_thread(void **state) {
  (void)state;
  size_t count = 0;
  assert_failure(dbs_cloud_count(NULL, &count), DBS_ERR_NULL_ARGUMENT, "dbs_cloud_count", "'cloud'");
  char mine[256];
  snprintf(mine, sizeof mine, "%s", dbs_last_error_message());

  struct thread_record record;
  pthread_t thread;
  assert_int_equal(pthread_create(&thread, NULL, fail_on_other_thread, &record), 0);
  assert_int_equal(pthread_join(thread, NULL), 0);

  /* the new thread started with no message, failed with its own ... */
  assert_string_equal(record.before, "");
  assert_int_equal(record.status, DBS_ERR_INVALID_ARGUMENT);
  assert_non_null(strstr(record.after, "dbs_option_bounds: "));
  assert_non_null(strstr(record.after, "12345"));
  /* ... and this thread's message did not change */
  assert_string_equal(dbs_last_error_message(), mine);
}

static void success_keeps_the_last_message(void **state) {
  (void)state;
  dbs_options *options = NULL;
  assert_failure(dbs_options_create(NULL), DBS_ERR_NULL_ARGUMENT, "dbs_options_create", "'out'");
  assert_ok(dbs_options_create(&options));
  int32_t level = -1;
  assert_ok(dbs_options_get_int(options, DBS_OPT_MAX_LEVEL, &level));
  assert_string_equal(dbs_last_error_message(), "dbs_options_create: argument 'out' is NULL");
  dbs_options_destroy(options);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(version_macros_equal_runtime),
      cmocka_unit_test(at_least_version_compares),
      cmocka_unit_test(features_are_reported),
      cmocka_unit_test(every_status_has_its_name),
      cmocka_unit_test(unknown_status_is_named_unknown),
      cmocka_unit_test(last_error_is_per_thread),
      cmocka_unit_test(success_keeps_the_last_message),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
