/* dbs_parameterize on a small cloud and boundary decoded from the fuzz input
 * (fuzz_decode_run: NaN, Inf, 1e300, duplicates, degenerate sides, corners apart), one
 * thread, at most level 1, sometimes cancelled by the progress callback at a step the input
 * picks. A run either fails with a documented status, leaving the handle untouched, or
 * gives a result whose every (u,v), distance and patch id is what dbs.h promises; the
 * progress rises in [0,1] and every warning is a non-empty line. */
#include <math.h>
#include <string.h>

#include "fuzz_support.h"

struct progress {
  double last;
  int calls;
  int cancel_at; /* the call that cancels; 0: none */
};

static int on_progress(double fraction, const char *stage, void *payload) {
  struct progress *p = payload;
  FUZZ_CHECK(fraction >= p->last && fraction <= 1.0);
  FUZZ_CHECK(stage != NULL && stage[0] != '\0');
  p->last = fraction;
  return ++p->calls == p->cancel_at;
}

static void on_warning(const char *message, void *payload) {
  (void)payload;
  FUZZ_CHECK(message != NULL && message[0] != '\0' && strchr(message, '\n') == NULL);
}

/* Everything else a result answers: statistics, the surface at a (u,v) from the input. */
static void read_result(const dbs_result *result, struct fuzz_bytes *in) {
  for (int32_t stat = 0; stat <= 40; ++stat) {
    double value = 0.0;
    const int status = dbs_result_stat(result, stat, &value);
    FUZZ_CHECK(status == DBS_OK || status == DBS_ERR_OUT_OF_RANGE);
  }
  double mean = 0.0;
  FUZZ_CHECK(dbs_result_stat(result, DBS_STAT_MEAN_DISTANCE, &mean) == DBS_OK && isfinite(mean));
  const double u = fuzz_double(in), v = fuzz_double(in);
  double xyz[3], normal[3];
  const int status = dbs_result_evaluate(result, u, v, xyz, normal);
  FUZZ_CHECK(status == DBS_OK || status == DBS_ERR_NON_FINITE || status == DBS_ERR_OUT_OF_RANGE || status == DBS_ERR_NUMERICAL);
  if (status == DBS_OK) FUZZ_CHECK(isfinite(xyz[0]) && isfinite(xyz[1]) && isfinite(xyz[2]));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  struct fuzz_bytes in = {data, size};
  const int cancel_at = fuzz_byte(&in) % 16;
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_options *options = NULL;
  if (fuzz_decode_run(&in, &cloud, &boundary, &options) != DBS_OK) return 0;
  struct progress progress = {0.0, 0, cancel_at};
  FUZZ_CHECK(dbs_options_set_progress(options, on_progress, &progress) == DBS_OK);
  FUZZ_CHECK(dbs_options_set_warning(options, on_warning, NULL) == DBS_OK);

  dbs_result *result = NULL;
  const int status = dbs_parameterize(cloud, boundary, options, &result);
  if (status == DBS_OK) {
    size_t n = 0;
    FUZZ_CHECK(cancel_at == 0 || progress.calls < cancel_at);
    FUZZ_CHECK(progress.last == 1.0);
    FUZZ_CHECK(dbs_cloud_count(cloud, &n) == DBS_OK);
    fuzz_check_result(result, n);
    read_result(result, &in);
    dbs_result_destroy(result);
  } else {
    FUZZ_CHECK(status == DBS_ERR_DEGENERATE || status == DBS_ERR_NUMERICAL || status == DBS_ERR_OUT_OF_RANGE ||
               status == DBS_ERR_CANCELLED || status == DBS_ERR_NON_FINITE);
    FUZZ_CHECK(status != DBS_ERR_CANCELLED || progress.calls == cancel_at);
    FUZZ_CHECK(result == NULL && dbs_last_error_message()[0] != '\0');
  }
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  return 0;
}
