/* dbs_cloud_load on the fuzz input as a file named FUZZ_CLOUD_NAME (one target per reader:
 * its extension picks the .xyz, .ply, .obj or .drc reader). A load either fails with a
 * documented status and a message, leaving the handle untouched, or gives a cloud of at
 * least one point, every coordinate finite, inside its own bounds. */
#include <math.h>
#include <stdlib.h>

#include "fuzz_support.h"

#ifndef FUZZ_CLOUD_NAME
#error "FUZZ_CLOUD_NAME: the file name (and so the reader) of this target"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  dbs_cloud *cloud = NULL;
  const int status = dbs_cloud_load(fuzz_file(FUZZ_CLOUD_NAME, data, size), &cloud);
  if (status != DBS_OK) {
    FUZZ_CHECK(status == DBS_ERR_PARSE || status == DBS_ERR_NON_FINITE || status == DBS_ERR_EMPTY ||
               status == DBS_ERR_UNSUPPORTED || status == DBS_ERR_IO || status == DBS_ERR_OUT_OF_RANGE);
    FUZZ_CHECK(cloud == NULL);
    FUZZ_CHECK(dbs_last_error_message()[0] != '\0');
    return 0;
  }
  size_t n = 0;
  double lo[3], hi[3];
  FUZZ_CHECK(dbs_cloud_count(cloud, &n) == DBS_OK && n >= 1);
  FUZZ_CHECK(dbs_cloud_bounds(cloud, lo, hi) == DBS_OK);
  double *xyz = malloc(sizeof(double) * 3 * n);
  FUZZ_CHECK(xyz != NULL);
  FUZZ_CHECK(dbs_cloud_points(cloud, xyz, n - 1) == DBS_ERR_BUFFER_TOO_SMALL);
  FUZZ_CHECK(dbs_cloud_points(cloud, xyz, n) == DBS_OK);
  for (size_t i = 0; i < 3 * n; ++i) {
    FUZZ_CHECK(isfinite(xyz[i]));
    FUZZ_CHECK(xyz[i] >= lo[i % 3] && xyz[i] <= hi[i % 3]);
  }
  free(xyz);
  dbs_cloud_destroy(cloud);
  return 0;
}
