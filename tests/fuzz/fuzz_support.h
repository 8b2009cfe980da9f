/* Shared helpers of the libFuzzer targets: the fuzz input as a file, and a decoder that turns
 * the input's bytes into a small cloud, boundary and options for dbs_parameterize. */
#ifndef DBS_FUZZ_SUPPORT_H
#define DBS_FUZZ_SUPPORT_H

#include <stddef.h>
#include <stdint.h>

#include "dbs.h"

/* Stops the process with a message when an invariant of a libdbs result is broken: the
 * fuzzer reports it as a crash, with the input that caused it. */
#define FUZZ_CHECK(condition) fuzz_check((condition), #condition, __FILE__, __LINE__)
void fuzz_check(int condition, const char *text, const char *file, int line);

/* A path in the temporary directory ($TMPDIR or /tmp) unique to this process, ending in
 * `name`, for a file libdbs writes; removed when the process exits. */
const char *fuzz_path(const char *name);
/* fuzz_path(name) (its extension picks the reader) holding the `size` bytes of `data`; the file is
 * removed when the process exits. The string lives until the next call with the same name. */
const char *fuzz_file(const char *name, const uint8_t *data, size_t size);

/* The bytes of a fuzz input, consumed from the front; an exhausted input reads as zeros. */
struct fuzz_bytes {
  const uint8_t *data;
  size_t size;
};
uint8_t fuzz_byte(struct fuzz_bytes *in);
/* An integer in [lo, hi] taken from one byte. */
int fuzz_int(struct fuzz_bytes *in, int lo, int hi);
/* A coordinate: mostly small multiples of 1/8 (coincident points, collinear rows), else one
 * of the values that break geometry (0, NaN, +-Inf, 1e300, 1e160, 1e-300, DBL_MAX,
 * denormals, ...) or the raw next 8 bytes. */
double fuzz_double(struct fuzz_bytes *in);

/* The inputs of one dbs_parameterize run decoded from the fuzz input: a grid of up to 8 x 8
 * points over the unit square with heights from the input, then up to 8 coordinates
 * replaced by fuzz_double; the unit square's boundary with 2 to 6 points per side, then up
 * to 6 of its coordinates replaced (degenerate or crossing sides, corners apart, non-finite
 * values); options that keep a run cheap (one thread, at most level 1, grids of at most 7: a run of a
 * level-1 quadtree takes about a second under the sanitizers).
 * Returns 0 and the three handles (the caller destroys them), or the status of the call
 * that refused the decoded cloud or boundary (nothing is left to destroy). */
int fuzz_decode_run(struct fuzz_bytes *in, dbs_cloud **cloud, dbs_boundary **boundary, dbs_options **options);

/* Checks what a successful dbs_parameterize promises: every (u,v) in [0,1]^2, every
 * distance finite and non-negative, every patch id a leaf of the result's quadtree with
 * the level the point reports. */
void fuzz_check_result(const dbs_result *result, size_t point_count);

#endif
