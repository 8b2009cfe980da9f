/*
 * dbs-param: parameterize a point cloud inside a four-sided boundary.
 *
 *   dbs-param CLOUD BOUNDARY -o RESULT [options]
 *
 * Written in C99 on the public API (dbs.h) only; the file formats and the command line are
 * described in FORMATS.md. Progress goes to stderr, a summary to stdout. Every failure ends
 * with exit status 1 (2 for a bad command line) and one line "dbs-param: <message>".
 */
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dbs.h"
#include "library_message.h"

#define EXIT_USAGE 2

static const char *const usage_text =
    "usage: dbs-param CLOUD BOUNDARY -o RESULT [options]\n"
    "       dbs-param CLOUD --auto-boundary -o RESULT [options]\n"
    "\n"
    "Parameterizes the points of CLOUD (.xyz .txt .ply .obj .drc) inside the four-sided\n"
    "BOUNDARY file, or inside the boundary found from the cloud's own outline\n"
    "(--auto-boundary; dbs-boundary writes it to a file), and writes each point's (u,v) to\n"
    "RESULT (.csv .ply .drc).\n"
    "\n"
    "options (defaults in brackets):\n"
    "  -o, --output PATH          result file (required)\n"
    "  --accuracy D               mean-distance target in cloud units [unset: relative]\n"
    "  --relative-accuracy F      target as a fraction of the bounding-box diagonal [1e-3]\n"
    "  --max-level N              quadtree depth, 0 = a single base surface [4]\n"
    "  --initial-grid N           grid points per side of a new patch [5]\n"
    "  --max-grid N               largest grid before subdividing [11]\n"
    "  --smoothing G              smoothing weight gamma of the curve projection [0.5]\n"
    "  --solver linear|ceres      curve-projection solver [linear]; ceres needs a libdbs\n"
    "                             built with Ceres\n"
    "  --loss none|huber|cauchy|soft_l1\n"
    "                             robust loss of the ceres solver [none]\n"
    "  --loss-scale S             scale of the loss in cloud units, 0 = derived [0]\n"
    "  --ceres-iterations N       Ceres iterations per solve [25]\n"
    "  --ceres-tolerance F        Ceres function tolerance [1e-6]\n"
    "  --threads N                worker threads, 0 = all hardware threads [0]\n"
    "  --near F                   subcloud 'near' limit, fraction of a patch diagonal [0.25]\n"
    "  --own F                    subcloud 'own' limit, fraction of a patch diagonal [0.05]\n"
    "  --noise-floor 0|1          raise the target to the cloud's noise floor [1]\n"
    "  --repair 0|1               last-resort repair of points the surfaces never reached [1]\n"
    "  --smooth-turned 0|1        smooth the (u,v) on turned sheets of the surface: fewer folds,\n"
    "                             more points on turned sheets [0]\n"
    "  --coarse-pass 0|1|2        where the surfaces pleated, a second pass from a coarse root;\n"
    "                             the better result is kept, 1 folds first, 2 fit first [1]\n"
    "  --fit-to-target 0|1        a patch whose largest grid misses the target is fitted to its\n"
    "                             error sample and kept a leaf where that comes within 0.85\n"
    "                             times it [1]\n"
    "  --auto-boundary            no BOUNDARY: the cloud's outline cut at its four corners\n"
    "                             (dbs_boundary_detect)\n"
    "  --outline-neighbours N     neighbourhood of the outline with --auto-boundary [24]\n"
    "  --crop                     points outside the boundary get no (u,v) and no row in RESULT\n"
    "                             instead of being clamped onto the domain's edge\n"
    "  --strict                   a gross mismatch of cloud and boundary is an error, not a warning\n"
    "  --corner-tolerance F       corners of BOUNDARY may miss by F times its size; they are\n"
    "                             snapped together [1e-6]\n"
    "  --report DIR               also write a validation report into DIR: mesh files,\n"
    "                             pictures and summary.json (see dbs_report_write)\n"
    "  -q, --quiet                no progress and no summary\n"
    "  -h, --help                 this text\n"
    "  --version                  the version of dbs-param and of libdbs\n";

/* ---- failure reporting ------------------------------------------------------------ */

/* Set while a progress line without its newline stands on stderr. */
static int progress_line_open = 0;

static void fail_message(const char *format, va_list args) {
  if (progress_line_open) {
    fputc('\n', stderr);
    progress_line_open = 0;
  }
  fputs("dbs-param: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
}

static void usage_error(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fail_message(format, args);
  va_end(args);
  exit(EXIT_USAGE);
}

/* Reports a failed library call: what was being done, then the library's own message. */
static void library_error(int status, const char *doing) {
  char text[1024];
  library_message(status, text, sizeof text);
  if (progress_line_open) {
    fputc('\n', stderr);
    progress_line_open = 0;
  }
  fprintf(stderr, "dbs-param: %s: %s", doing, text);
  /* Corners that miss by more than the tolerance: say how to accept them (same line). */
  if (status == DBS_ERR_DEGENERATE && strstr(text, " apart (tolerance") != NULL)
    fputs("; --corner-tolerance F snaps corners that miss by up to F times the boundary's size", stderr);
  fputc('\n', stderr);
}

/* ---- numeric arguments ------------------------------------------------------------ */

static double parse_double(const char *option, const char *text) {
  char *end = NULL;
  double value;
  errno = 0;
  value = strtod(text, &end);
  if (end == text || *end != '\0') usage_error("%s: '%s' is not a number", option, text);
  if (errno == ERANGE && (value > 1.0 || value < -1.0)) usage_error("%s: '%s' is out of the range of a double", option, text);
  return value;
}

static int32_t parse_int(const char *option, const char *text) {
  char *end = NULL;
  long value;
  errno = 0;
  value = strtol(text, &end, 10);
  if (end == text || *end != '\0') usage_error("%s: '%s' is not an integer", option, text);
  if (errno == ERANGE || value < INT32_MIN || value > INT32_MAX) usage_error("%s: '%s' is too large for an integer", option, text);
  return (int32_t)value;
}

/* ---- command line ----------------------------------------------------------------- */

enum value_kind { VALUE_NONE, VALUE_INT, VALUE_DOUBLE, VALUE_SOLVER, VALUE_LOSS, VALUE_FLAG /* no value: sets the int option to 1 */ };

/* One library option as given on the command line. */
struct option_value {
  const char *flag; /* "--max-level" */
  int32_t id;       /* DBS_OPT_* */
  enum value_kind kind;
  const char *text; /* the argument as typed, for messages */
  int32_t int_value;
  double double_value;
  int given;
};

static struct option_value library_options[] = {
    {"--accuracy", DBS_OPT_ACCURACY, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--relative-accuracy", DBS_OPT_RELATIVE_ACCURACY, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--max-level", DBS_OPT_MAX_LEVEL, VALUE_INT, NULL, 0, 0.0, 0},
    {"--initial-grid", DBS_OPT_INITIAL_GRID, VALUE_INT, NULL, 0, 0.0, 0},
    {"--max-grid", DBS_OPT_MAX_GRID, VALUE_INT, NULL, 0, 0.0, 0},
    {"--smoothing", DBS_OPT_SMOOTHING, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--solver", DBS_OPT_SOLVER, VALUE_SOLVER, NULL, 0, 0.0, 0},
    {"--threads", DBS_OPT_THREADS, VALUE_INT, NULL, 0, 0.0, 0},
    {"--near", DBS_OPT_SUBCLOUD_NEAR, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--own", DBS_OPT_SUBCLOUD_OWN, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--noise-floor", DBS_OPT_NOISE_FLOOR, VALUE_INT, NULL, 0, 0.0, 0},
    {"--repair", DBS_OPT_REPAIR, VALUE_INT, NULL, 0, 0.0, 0},
    {"--smooth-turned", DBS_OPT_SMOOTH_TURNED, VALUE_INT, NULL, 0, 0.0, 0},
    {"--coarse-pass", DBS_OPT_COARSE_PASS, VALUE_INT, NULL, 0, 0.0, 0},
    {"--fit-to-target", DBS_OPT_FIT_TO_TARGET, VALUE_INT, NULL, 0, 0.0, 0},
    {"--loss", DBS_OPT_LOSS, VALUE_LOSS, NULL, 0, 0.0, 0},
    {"--loss-scale", DBS_OPT_LOSS_SCALE, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--ceres-iterations", DBS_OPT_CERES_MAX_ITERATIONS, VALUE_INT, NULL, 0, 0.0, 0},
    {"--ceres-tolerance", DBS_OPT_CERES_FUNCTION_TOLERANCE, VALUE_DOUBLE, NULL, 0, 0.0, 0},
    {"--outline-neighbours", DBS_OPT_OUTLINE_NEIGHBOURS, VALUE_INT, NULL, 0, 0.0, 0},
    {"--crop", DBS_OPT_CROP, VALUE_FLAG, NULL, 0, 0.0, 0},
    {"--strict", DBS_OPT_STRICT, VALUE_FLAG, NULL, 0, 0.0, 0},
};
#define LIBRARY_OPTION_COUNT (sizeof library_options / sizeof library_options[0])

struct command_line {
  const char *cloud_path;
  const char *boundary_path;
  const char *result_path;
  const char *report_dir;
  double corner_tolerance; /* relative; < 0: the library's default */
  int auto_boundary;       /* the boundary from the cloud's outline, no BOUNDARY file */
  int quiet;
};

static struct option_value *find_library_option(const char *flag, size_t flag_length) {
  size_t i;
  for (i = 0; i < LIBRARY_OPTION_COUNT; ++i) {
    if (strlen(library_options[i].flag) == flag_length && strncmp(library_options[i].flag, flag, flag_length) == 0) return &library_options[i];
  }
  return NULL;
}

static void store_option_value(struct option_value *option, const char *text) {
  option->text = text;
  option->given = 1;
  switch (option->kind) {
    case VALUE_INT:
      option->int_value = parse_int(option->flag, text);
      break;
    case VALUE_DOUBLE:
      option->double_value = parse_double(option->flag, text);
      break;
    case VALUE_SOLVER:
      if (strcmp(text, "linear") == 0) {
        option->int_value = DBS_SOLVER_LINEAR;
      } else if (strcmp(text, "ceres") == 0) {
        option->int_value = DBS_SOLVER_CERES;
      } else {
        usage_error("--solver: '%s' is not a solver (linear or ceres)", text);
      }
      break;
    case VALUE_LOSS:
      if (strcmp(text, "none") == 0) {
        option->int_value = DBS_LOSS_NONE;
      } else if (strcmp(text, "huber") == 0) {
        option->int_value = DBS_LOSS_HUBER;
      } else if (strcmp(text, "cauchy") == 0) {
        option->int_value = DBS_LOSS_CAUCHY;
      } else if (strcmp(text, "soft_l1") == 0) {
        option->int_value = DBS_LOSS_SOFT_L1;
      } else {
        usage_error("--loss: '%s' is not a loss (none, huber, cauchy or soft_l1)", text);
      }
      break;
    case VALUE_FLAG:
      option->int_value = 1;
      break;
    case VALUE_NONE:
      break;
  }
}

static void print_version(void) {
  printf("dbs-param (libdbs %s, dbs.h %d.%d.%d)\n", dbs_version_string(), DBS_VERSION_MAJOR, DBS_VERSION_MINOR, DBS_VERSION_PATCH);
}

static void parse_command_line(int argc, char **argv, struct command_line *cmd) {
  int i;
  int positional = 0;
  int options_ended = 0;
  memset(cmd, 0, sizeof *cmd);
  cmd->corner_tolerance = -1.0;
  for (i = 1; i < argc; ++i) {
    const char *arg = argv[i];
    if (!options_ended && arg[0] == '-' && arg[1] != '\0') {
      const char *equals = strchr(arg, '=');
      size_t flag_length = equals != NULL ? (size_t)(equals - arg) : strlen(arg);
      struct option_value *option;
      if (strcmp(arg, "--") == 0) {
        options_ended = 1;
      } else if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
        fputs(usage_text, stdout);
        exit(EXIT_SUCCESS);
      } else if (strcmp(arg, "--version") == 0) {
        print_version();
        exit(EXIT_SUCCESS);
      } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
        cmd->quiet = 1;
      } else if (strcmp(arg, "--auto-boundary") == 0) {
        cmd->auto_boundary = 1;
      } else if (strcmp(arg, "-o") == 0 || (flag_length == 8 && strncmp(arg, "--output", 8) == 0)) {
        if (equals != NULL) {
          cmd->result_path = equals + 1;
        } else if (i + 1 < argc) {
          cmd->result_path = argv[++i];
        } else {
          usage_error("%s needs a value (the result file)", arg);
        }
      } else if (flag_length == 8 && strncmp(arg, "--report", 8) == 0) {
        if (equals != NULL) {
          cmd->report_dir = equals + 1;
        } else if (i + 1 < argc) {
          cmd->report_dir = argv[++i];
        } else {
          usage_error("%s needs a value (the report directory)", arg);
        }
      } else if (flag_length == 18 && strncmp(arg, "--corner-tolerance", 18) == 0) {
        if (equals == NULL && i + 1 >= argc) usage_error("%s needs a value (a fraction of the boundary's size)", arg);
        cmd->corner_tolerance = parse_double("--corner-tolerance", equals != NULL ? equals + 1 : argv[++i]);
        if (!(cmd->corner_tolerance >= 0.0)) usage_error("--corner-tolerance: %g is not a fraction >= 0", cmd->corner_tolerance);
      } else if ((option = find_library_option(arg, flag_length)) != NULL) {
        if (option->kind == VALUE_FLAG) {
          if (equals != NULL) usage_error("%.*s takes no value", (int)flag_length, arg);
          store_option_value(option, "");
        } else if (equals != NULL) {
          store_option_value(option, equals + 1);
        } else if (i + 1 < argc) {
          store_option_value(option, argv[++i]);
        } else {
          usage_error("%s needs a value", arg);
        }
      } else {
        usage_error("unknown option '%s' (see --help)", arg);
      }
    } else if (positional == 0) {
      cmd->cloud_path = arg;
      ++positional;
    } else if (positional == 1) {
      cmd->boundary_path = arg;
      ++positional;
    } else {
      usage_error("unexpected argument '%s' (usage: dbs-param CLOUD BOUNDARY -o RESULT [options])", arg);
    }
  }
  if (cmd->auto_boundary && cmd->boundary_path != NULL) usage_error("--auto-boundary finds the boundary from the cloud: no BOUNDARY file '%s' with it", cmd->boundary_path);
  if (cmd->auto_boundary && cmd->corner_tolerance >= 0.0) usage_error("--corner-tolerance applies to a BOUNDARY file, not to --auto-boundary");
  if (cmd->cloud_path == NULL || (cmd->boundary_path == NULL && !cmd->auto_boundary))
    usage_error("missing %s (usage: dbs-param CLOUD BOUNDARY -o RESULT [options])", cmd->cloud_path == NULL ? (cmd->auto_boundary ? "CLOUD" : "CLOUD and BOUNDARY") : "BOUNDARY");
  if (cmd->result_path == NULL || cmd->result_path[0] == '\0') usage_error("missing -o RESULT (a .csv, .ply or .drc file)");
}

/* Applies one option; returns 0 or prints the library's message and returns the status. */
static int apply_option(dbs_options *options, const struct option_value *option) {
  int status;
  char doing[256];
  if (!option->given) return DBS_OK;
  if (option->kind == VALUE_DOUBLE) {
    status = dbs_options_set_double(options, option->id, option->double_value);
  } else {
    status = dbs_options_set_int(options, option->id, option->int_value);
  }
  if (status != DBS_OK) {
    snprintf(doing, sizeof doing, "%s %s", option->flag, option->text);
    library_error(status, doing);
  }
  return status;
}

/* Applies a pair of options bound by lower <= upper (initial/max grid, own/near) in the order
 * that lets any consistent pair through whatever the defaults are; an inconsistent pair is
 * then refused by the library with its own message. */
static int apply_ordered_pair(dbs_options *options, const struct option_value *lower, const struct option_value *upper) {
  double current_lower = 0.0;
  double new_upper;
  int upper_first;
  if (lower->kind == VALUE_INT) {
    int32_t value = 0;
    dbs_options_get_int(options, lower->id, &value);
    current_lower = value;
    new_upper = upper->int_value;
  } else {
    dbs_options_get_double(options, lower->id, &current_lower);
    new_upper = upper->double_value;
  }
  upper_first = upper->given && new_upper >= current_lower;
  if (upper_first) return apply_option(options, upper) != DBS_OK || apply_option(options, lower) != DBS_OK;
  return apply_option(options, lower) != DBS_OK || apply_option(options, upper) != DBS_OK;
}

static int build_options(dbs_options *options) {
  const struct option_value *initial_grid = find_library_option("--initial-grid", 14);
  const struct option_value *max_grid = find_library_option("--max-grid", 10);
  const struct option_value *own = find_library_option("--own", 5);
  const struct option_value *near = find_library_option("--near", 6);
  size_t i;
  for (i = 0; i < LIBRARY_OPTION_COUNT; ++i) {
    const struct option_value *option = &library_options[i];
    if (option == initial_grid || option == max_grid || option == own || option == near) continue;
    if (apply_option(options, option) != DBS_OK) return 1;
  }
  if (apply_ordered_pair(options, initial_grid, max_grid)) return 1;
  return apply_ordered_pair(options, own, near);
}

/* ---- output checks ---------------------------------------------------------------- */

static int has_result_extension(const char *path) {
  static const char *const extensions[] = {".csv", ".ply", ".drc"};
  const char *dot = strrchr(path, '.');
  size_t i;
  if (dot == NULL || strchr(dot, '/') != NULL) return 0;
  for (i = 0; i < sizeof extensions / sizeof extensions[0]; ++i) {
    const char *a = dot;
    const char *b = extensions[i];
    while (*a != '\0' && *b != '\0' && (*a | 0x20) == *b) ++a, ++b;
    if (*a == '\0' && *b == '\0') return 1;
  }
  return 0;
}

/* Checked before the (possibly long) run: 0 when the result file can be created, else the
 * errno of the failed attempt (-1 when the C library gave none). A file that did not exist before is removed again. */
static int result_open_error(const char *path) {
  FILE *existing = fopen(path, "rb");
  FILE *probe;
  if (existing != NULL) fclose(existing);
  errno = 0;
  probe = fopen(path, "ab");
  if (probe == NULL) return errno != 0 ? errno : -1;
  fclose(probe);
  if (existing == NULL) remove(path);
  return 0;
}

/* ---- progress and summary --------------------------------------------------------- */

struct progress_state {
  int last_percent;
  char last_stage[32];
};

static int show_progress(double fraction, const char *stage, void *payload) {
  struct progress_state *state = (struct progress_state *)payload;
  int percent = (int)(fraction * 100.0 + 0.5);
  if (stage == NULL) stage = "";
  if (percent == state->last_percent && strcmp(stage, state->last_stage) == 0) return 0;
  state->last_percent = percent;
  snprintf(state->last_stage, sizeof state->last_stage, "%s", stage);
  fprintf(stderr, "\r[%3d%%] %-14s", percent, state->last_stage);
  fflush(stderr);
  progress_line_open = 1;
  return 0;
}

static double stat_of(const dbs_result *result, int32_t stat) {
  double value = 0.0;
  dbs_result_stat(result, stat, &value);
  return value;
}

/* A likely mistake in the inputs (the library's warning callback): on stderr, even with
 * --quiet, since the run goes on and exits 0. */
static void print_warning(const char *message, void *payload) {
  (void)payload;
  if (progress_line_open) {
    fputc('\n', stderr);
    progress_line_open = 0;
  }
  fprintf(stderr, "dbs-param: warning: %s\n", message);
}

/* The noise floor raised a target the user gave: say so on stderr (even with --quiet, since
 * the result is then judged against another target than the one asked for). */
static void warn_if_target_raised(const dbs_result *result) {
  const int given = library_options[0].given || library_options[1].given; /* --accuracy, --relative-accuracy */
  const double used = stat_of(result, DBS_STAT_ACCURACY), requested = stat_of(result, DBS_STAT_REQUESTED_ACCURACY);
  if (given && used > requested)
    fprintf(stderr, "dbs-param: warning: the accuracy %.6g asked for is below the cloud's noise floor; %.6g was used (estimated noise %.6g; --noise-floor 0 keeps the target)\n", requested, used,
            stat_of(result, DBS_STAT_NOISE));
}

static void print_summary(const dbs_result *result, const char *result_path, double corner_snap) {
  size_t points = 0;
  dbs_result_point_count(result, &points);
  printf("points          %lu\n", (unsigned long)points);
  printf("patches         %.0f (%.0f leaves)\n", stat_of(result, DBS_STAT_PATCHES), stat_of(result, DBS_STAT_LEAVES));
  printf("levels          %.0f\n", stat_of(result, DBS_STAT_LEVELS));
  printf("iterations      %.0f\n", stat_of(result, DBS_STAT_ITERATIONS));
  if (stat_of(result, DBS_STAT_SOLVER) == DBS_SOLVER_CERES) {
    printf("solver          ceres (%.0f Ceres iterations", stat_of(result, DBS_STAT_CERES_ITERATIONS));
    if (stat_of(result, DBS_STAT_LOSS_SCALE) > 0.0) printf(", robust loss of scale %.6g", stat_of(result, DBS_STAT_LOSS_SCALE));
    printf(")\n");
  } else {
    printf("solver          linear\n");
  }
  printf("mean distance   %.6g\n", stat_of(result, DBS_STAT_MEAN_DISTANCE));
  printf("max distance    %.6g\n", stat_of(result, DBS_STAT_MAX_DISTANCE));
  const double used = stat_of(result, DBS_STAT_ACCURACY), requested = stat_of(result, DBS_STAT_REQUESTED_ACCURACY);
  printf("noise           %.6g (estimated sigma along the normal)\n", stat_of(result, DBS_STAT_NOISE));
  printf("accuracy        %.6g (%s)\n", used, stat_of(result, DBS_STAT_ACCURACY_MET) != 0.0 ? "met" : "not met");
  if (used > requested)
    printf("                raised from the requested %.6g (%s) to the noise floor\n", requested, stat_of(result, DBS_STAT_REQUESTED_MET) != 0.0 ? "met" : "not met");
  printf("folds           %.2f %% of %.0f points judged (%.0f folded, %.0f undecided, %.0f sharing a (u,v))\n", 100.0 * stat_of(result, DBS_STAT_FOLDED_SHARE),
         stat_of(result, DBS_STAT_JUDGED_POINTS), stat_of(result, DBS_STAT_FOLDED_POINTS), stat_of(result, DBS_STAT_UNDECIDED_POINTS), stat_of(result, DBS_STAT_COINCIDENT_POINTS));
  printf("collapsed       %.0f of the undecided points squeezed in (u,v)\n", stat_of(result, DBS_STAT_COLLAPSED_POINTS));
  printf("turned          %.2f %% of the judged points on the surface lie on a sheet of it turned against the cloud (%.0f points)\n", 100.0 * stat_of(result, DBS_STAT_TURNED_SHARE),
         stat_of(result, DBS_STAT_TURNED_POINTS));
  if (stat_of(result, DBS_STAT_REPAIRED_POINTS) > 0.0) printf("repaired        %.0f points\n", stat_of(result, DBS_STAT_REPAIRED_POINTS));
  if (stat_of(result, DBS_STAT_SMOOTHED_POINTS) > 0.0) printf("smoothed        %.0f points on and around turned sheets\n", stat_of(result, DBS_STAT_SMOOTHED_POINTS));
  if (stat_of(result, DBS_STAT_PASSES) > 1.0)
    printf("passes          2: the surfaces pleated, a coarse pass ran too; kept: the %s pass\n", stat_of(result, DBS_STAT_COARSE) != 0.0 ? "coarse" : "first");
  printf("inputs          boundary %.3g spacings from the cloud, cloud/boundary size %.3g, domain covered %.1f %%, %.0f points clamped\n",
         stat_of(result, DBS_STAT_BOUNDARY_GAP), stat_of(result, DBS_STAT_SCALE_RATIO), 100.0 * stat_of(result, DBS_STAT_COVERAGE), stat_of(result, DBS_STAT_CLAMPED_POINTS));
  if (stat_of(result, DBS_STAT_CROPPED_POINTS) > 0.0)
    printf("cropped         %.0f points outside the boundary: no (u,v), not in the result file\n", stat_of(result, DBS_STAT_CROPPED_POINTS));
  if (corner_snap > 0.0) printf("corners         snapped together, the farthest end moved %.6g\n", corner_snap);
  printf("time            %.3f s\n", stat_of(result, DBS_STAT_SECONDS));
  printf("result          %s\n", result_path);
}

/* ---- main ------------------------------------------------------------------------- */

int main(int argc, char **argv) {
  struct command_line cmd;
  struct progress_state progress = {-1, ""};
  dbs_options *options = NULL;
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_result *result = NULL;
  double corner_snap = 0.0;
  int status;
  int open_error;
  int exit_code = EXIT_FAILURE;

  parse_command_line(argc, argv, &cmd);
  if (!has_result_extension(cmd.result_path)) usage_error("%s: the result must end in .csv, .ply or .drc", cmd.result_path);
  /* --report needs a libdbs built with the report: refuse it before any work otherwise. */
  if (cmd.report_dir != NULL) {
    int32_t has_report = 0;
    if ((status = dbs_has_feature(DBS_FEATURE_REPORT, &has_report)) != DBS_OK) {
      library_error(status, "asking for the report");
      return EXIT_FAILURE;
    }
    if (!has_report) {
      fprintf(stderr, "dbs-param: --report %s: this libdbs was built without the report (DBS_WITH_REPORT=OFF)\n", cmd.report_dir);
      return EXIT_FAILURE;
    }
  }

  status = dbs_options_create(&options);
  if (status != DBS_OK) {
    library_error(status, "creating options");
    return EXIT_FAILURE;
  }
  if (build_options(options)) goto done;
  if (!cmd.quiet && (status = dbs_options_set_progress(options, show_progress, &progress)) != DBS_OK) {
    library_error(status, "setting the progress callback");
    goto done;
  }
  if ((status = dbs_options_set_warning(options, print_warning, NULL)) != DBS_OK) {
    library_error(status, "setting the warning callback");
    goto done;
  }
  if ((open_error = result_open_error(cmd.result_path)) != 0) {
    fprintf(stderr, "dbs-param: %s: cannot create the result file%s%s\n", cmd.result_path, open_error > 0 ? ": " : "", open_error > 0 ? strerror(open_error) : "");
    goto done;
  }
  if ((status = dbs_cloud_load(cmd.cloud_path, &cloud)) != DBS_OK) {
    library_error(status, "reading the cloud");
    goto done;
  }
  if (cmd.auto_boundary) {
    if ((status = dbs_boundary_detect(cloud, options, &boundary)) != DBS_OK) {
      library_error(status, "finding the boundary from the cloud");
      goto done;
    }
  } else if ((status = cmd.corner_tolerance >= 0.0 ? dbs_boundary_load_tolerant(cmd.boundary_path, cmd.corner_tolerance, 1, &corner_snap, &boundary)
                                                   : dbs_boundary_load(cmd.boundary_path, &boundary)) != DBS_OK) {
    library_error(status, "reading the boundary");
    goto done;
  }
  if ((status = dbs_parameterize(cloud, boundary, options, &result)) != DBS_OK) {
    library_error(status, "parameterizing");
    goto done;
  }
  if (progress_line_open) {
    fputc('\n', stderr);
    progress_line_open = 0;
  }
  warn_if_target_raised(result);
  if ((status = dbs_result_save(result, cloud, cmd.result_path)) != DBS_OK) {
    library_error(status, "writing the result");
    goto done;
  }
  if (cmd.report_dir != NULL && (status = dbs_report_write(result, cloud, options, cmd.report_dir)) != DBS_OK) {
    library_error(status, "writing the report");
    goto done;
  }
  if (!cmd.quiet) print_summary(result, cmd.result_path, corner_snap);
  if (!cmd.quiet && cmd.auto_boundary) {
    size_t holes = 0;
    dbs_boundary_hole_count(boundary, &holes);
    printf("boundary        found from the cloud's outline, %zu hole%s inside it\n", holes, holes == 1 ? "" : "s");
  }
  if (!cmd.quiet && cmd.report_dir != NULL) printf("report          %s\n", cmd.report_dir);
  exit_code = EXIT_SUCCESS;

done:
  dbs_result_destroy(result);
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  dbs_options_destroy(options);
  return exit_code;
}
