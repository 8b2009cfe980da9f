/* libdbs under a host's comma locale (de_DE: "0,5"), as CAD programs often set it: every
 * number it writes keeps its decimal point (result .csv, summary.json, meshes, error messages)
 * and every file it reads is read the same. The locale is set for this thread with
 * uselocale(), the way a host's GUI thread would have it; scripts/setup.sh installs it. */
#define _GNU_SOURCE
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

static locale_t comma_locale(void) {
  locale_t comma = newlocale(LC_ALL_MASK, "de_DE.UTF-8", (locale_t)0);
  if (comma == (locale_t)0) skip(); /* reported as skipped, not passed: scripts/setup.sh installs it */
  return comma;
}

/* A number written with a decimal comma: a digit, a comma, a digit. JSON puts a comma only
 * after a value, before a line end or a blank, never between two digits. */
static int has_decimal_comma(const char *text) {
  for (const char *c = strchr(text, ','); c; c = strchr(c + 1, ','))
    if (c > text && c[-1] >= '0' && c[-1] <= '9' && c[1] >= '0' && c[1] <= '9') return 1;
  return 0;
}

static char *file_text(const char *path) {
  size_t size = 0;
  char *text = read_all(path, &size);
  assert_non_null(text);
  assert_true(size > 0);
  return text;
}

/* A .csv whose every line has as many commas as its header: a decimal comma would add one. */
static void assert_csv_fields_line_up(const char *path) {
  char *text = file_text(path);
  int header = -1, lines = 0;
  for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
    int commas = 0;
    for (const char *c = line; *c; ++c) commas += *c == ',';
    if (header < 0) header = commas;
    assert_int_equal(commas, header);
    ++lines;
  }
  assert_true(header >= 3 && lines > 100);
  free(text);
}

static void numbers_keep_their_point_under_a_comma_locale(void **state) {
  (void)state;
  locale_t comma = comma_locale();
  locale_t previous = uselocale(comma);
  char probe[16];
  snprintf(probe, sizeof probe, "%.1f", 0.5);
  assert_string_equal(probe, "0,5"); /* the locale is in force for this thread */

  /* Reading: a cloud and a boundary written with points load as before. */
  char cloud_path[512], boundary_path[512];
  temp_file(cloud_path, sizeof cloud_path, "locale.xyz", "0.5 0.25 0.125\n1.5 0.25 0.125\n0.5 1.25 0.125\n");
  dbs_cloud *cloud = NULL;
  assert_ok(dbs_cloud_load(cloud_path, &cloud));
  double xyz[9];
  assert_ok(dbs_cloud_points(cloud, xyz, 3));
  assert_true(xyz[0] == 0.5 && xyz[1] == 0.25 && xyz[2] == 0.125 && xyz[3] == 1.5);
  dbs_cloud_destroy(cloud);
  temp_file(boundary_path, sizeof boundary_path, "locale_boundary.txt", "bottom\n0 0 0\n1.5 0 0\nright\n1.5 0 0\n1.5 1.5 0\ntop\n0 1.5 0\n1.5 1.5 0\nleft\n0 0 0\n0 1.5 0\n");
  dbs_boundary *loaded = NULL;
  assert_ok(dbs_boundary_load(boundary_path, &loaded));
  dbs_boundary_destroy(loaded);
  /* A number beyond the double range is infinite, refused: read through strtod under this
   * locale, "1.5e400" would have been 1. */
  temp_file(cloud_path, sizeof cloud_path, "locale_overflow.xyz", "0.5 0.25 0.125\n1.5e400 0.25 0.125\n");
  dbs_cloud *refused = NULL;
  assert_failure(dbs_cloud_load(cloud_path, &refused), DBS_ERR_NON_FINITE, "dbs_cloud_load", "locale_overflow.xyz:2");

  /* Writing: the result .csv, the report's summary.json and meshes. */
  cloud = bump_cloud(30, 0.1);
  dbs_boundary *boundary = square_boundary(20);
  dbs_options *options = NULL;
  assert_ok(dbs_options_create(&options));
  dbs_result *result = parameterize_or_fail(cloud, boundary, options);
  char path[512];
  temp_path(path, sizeof path, "locale_result.csv");
  assert_ok(dbs_result_save(result, cloud, path));
  assert_csv_fields_line_up(path);
  int32_t report = 0;
  assert_ok(dbs_has_feature(DBS_FEATURE_REPORT, &report));
  if (report) {
    char dir[512];
    temp_path(dir, sizeof dir, "locale_report");
    assert_ok(dbs_report_write(result, cloud, options, dir));
    char file[600];
    snprintf(file, sizeof file, "%s/summary.json", dir);
    char *json = file_text(file);
    assert_false(has_decimal_comma(json));
    assert_non_null(strstr(json, "\"relative_accuracy\": 0.001")); /* a number with its point */
    free(json);
    snprintf(file, sizeof file, "%s/mesh.obj", dir);
    char *obj = file_text(file);
    int vertex_lines = 0, with_point = 0;
    for (char *line = strtok(obj, "\n"); line; line = strtok(NULL, "\n")) {
      if (line[0] != 'v') continue;  /* v and vt lines: blank-separated numbers, no comma */
      assert_null(strchr(line, ','));
      with_point += strchr(line, '.') != NULL;
      ++vertex_lines;
    }
    assert_true(vertex_lines > 100 && with_point > vertex_lines / 2);
    free(obj);
  }
  /* Error messages: a number in one keeps its point too (std::to_string would write 1,500000). */
  assert_failure(dbs_options_set_double(options, DBS_OPT_SMOOTHING, 1.5), DBS_ERR_OUT_OF_RANGE, "dbs_options_set_double", "1.5");
  assert_false(has_decimal_comma(dbs_last_error_message()));
  double point[3];
  assert_failure(dbs_result_evaluate(result, 1.5, 0.25, point, NULL), DBS_ERR_OUT_OF_RANGE, "dbs_result_evaluate", "= 1.5 is outside [0, 1]");
  assert_false(has_decimal_comma(dbs_last_error_message()));

  dbs_result_destroy(result);
  dbs_options_destroy(options);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  uselocale(previous);
  freelocale(comma);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(numbers_keep_their_point_under_a_comma_locale),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
