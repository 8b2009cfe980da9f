/* libdbs keeps no global state: several threads may parameterize at once, even sharing the
 * same (read-only) cloud, boundary and options handles, and each gets exactly the result a
 * lone call gives. */
#define _POSIX_C_SOURCE 200809L /* pthreads */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define THREADS 4

struct shared_inputs {
  const dbs_cloud *cloud;
  const dbs_boundary *boundary;
  const dbs_options *options;
};

struct run {
  const struct shared_inputs *inputs;
  int status;
  size_t count;
  double *uv;
  double *distances;
  double patches;
};

static void *parameterize_on_thread(void *arg) {
  struct run *run = arg;
  dbs_result *result = NULL;
  run->status = dbs_parameterize(run->inputs->cloud, run->inputs->boundary, run->inputs->options, &result);
  if (run->status != DBS_OK) return NULL;
  if (dbs_result_point_count(result, &run->count) == DBS_OK) {
    run->uv = malloc(sizeof(double) * 2 * run->count);
    run->distances = malloc(sizeof(double) * run->count);
    if (!run->uv || !run->distances || dbs_result_uv(result, run->uv, run->count) != DBS_OK ||
        dbs_result_distances(result, run->distances, run->count) != DBS_OK || dbs_result_stat(result, DBS_STAT_PATCHES, &run->patches) != DBS_OK)
      run->status = DBS_ERR_INTERNAL;
  }
  dbs_result_destroy(result);
  return NULL;
}

static void concurrent_calls_give_the_lone_result(void **state) {
  (void)state;
  struct shared_inputs inputs;
  dbs_cloud *cloud = bump_cloud(40, 0.2);
  dbs_boundary *boundary = square_boundary(5);
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  assert_ok(dbs_options_set_double(options, DBS_OPT_ACCURACY, 1e-6)); /* subdivides to the maximum */
  assert_ok(dbs_options_set_int(options, DBS_OPT_MAX_LEVEL, 2));
  assert_ok(dbs_options_set_int(options, DBS_OPT_THREADS, 2));            /* each call has workers too */
  inputs.cloud = cloud;
  inputs.boundary = boundary;
  inputs.options = options;

  struct run lone = {&inputs, -1, 0, NULL, NULL, 0};
  parameterize_on_thread(&lone);
  assert_int_equal(lone.status, DBS_OK);
  assert_true(lone.patches == 21.0);

  struct run runs[THREADS];
  pthread_t threads[THREADS];
  for (int t = 0; t < THREADS; ++t) {
    runs[t] = lone;
    runs[t].status = -1;
    runs[t].uv = runs[t].distances = NULL;
    assert_int_equal(pthread_create(&threads[t], NULL, parameterize_on_thread, &runs[t]), 0);
  }
  for (int t = 0; t < THREADS; ++t) assert_int_equal(pthread_join(threads[t], NULL), 0);
  for (int t = 0; t < THREADS; ++t) {
    assert_int_equal(runs[t].status, DBS_OK);
    assert_int_equal(runs[t].count, lone.count);
    assert_true(runs[t].patches == lone.patches);
    assert_memory_equal(runs[t].uv, lone.uv, sizeof(double) * 2 * lone.count);
    assert_memory_equal(runs[t].distances, lone.distances, sizeof(double) * lone.count);
    free(runs[t].uv);
    free(runs[t].distances);
  }
  free(lone.uv);
  free(lone.distances);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(concurrent_calls_give_the_lone_result),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
