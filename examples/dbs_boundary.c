/*
 * dbs-boundary: the four-sided boundary of a scan, found from its points, written as a
 * boundary file (docs/FORMATS.md) that dbs-param reads.
 *
 * Exit status: 0 on success, 1 when the library refuses the input (the message names the
 * problem), 2 on a usage error.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dbs.h"
#include "library_message.h"

#define EXIT_USAGE 2

static const char *const usage_text =
    "usage: dbs-boundary CLOUD -o BOUNDARY [options]\n"
    "\n"
    "Finds the outline of the open scan CLOUD (.xyz .txt .ply .obj .drc), cuts it at four\n"
    "corners and writes the four sides to BOUNDARY (the boundary file of dbs-param).\n"
    "\n"
    "options (defaults in brackets):\n"
    "  -o, --output PATH          boundary file (required)\n"
    "  --corners X,Y,Z;X,Y,Z;X,Y,Z;X,Y,Z  (or with '/' between the points)\n"
    "                             the corners (0,0), (1,0), (1,1), (0,1): the outline is cut\n"
    "                             at its points nearest to them [where it turns most]\n"
    "  --outline-neighbours N     nearest points a point's angular gap is judged on [24]\n"
    "  --report DIR               also write boundary.png (the points, the four sides in\n"
    "                             colours, the corners, the holes) and boundary.json into DIR\n"
    "  --threads N                worker threads, 0 = all hardware threads [0]; with\n"
    "                             --corners all of them\n"
    "  -q, --quiet                no summary\n"
    "  -h, --help                 this text\n"
    "  --version                  the version of libdbs\n";

static void usage_error(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fputs("dbs-boundary: ", stderr);
  vfprintf(stderr, format, args);
  fputc('\n', stderr);
  va_end(args);
  exit(EXIT_USAGE);
}

/* A failed library call: what was being done, then the library's own message (one line). */
static void library_error(int status, const char *doing) {
  char text[1024];
  library_message(status, text, sizeof text);
  fprintf(stderr, "dbs-boundary: %s: %s\n", doing, text);
}

static int parse_int(const char *option, const char *text) {
  char *end = NULL;
  errno = 0;
  const long value = strtol(text, &end, 10);
  if (end == text || *end != '\0') usage_error("%s: '%s' is not an integer", option, text);
  if (errno == ERANGE || value < -2147483647L || value > 2147483647L) usage_error("%s: '%s' is too large for an integer", option, text);
  return (int)value;
}

/* "x,y,z;x,y,z;x,y,z;x,y,z" into 12 numbers. */
static void parse_corners(const char *text, double *xyz) {
  const char *p = text;
  for (int k = 0; k < 12; ++k) {
    char *end = NULL;
    errno = 0;
    xyz[k] = strtod(p, &end);
    if (end == p || errno == ERANGE) usage_error("--corners: '%s' is not four points x,y,z separated by ';' (number %d)", text, k + 1);
    /* points apart by ';' (or '/', which needs no quoting in a shell or a CMake list) */
    const int point_end = k % 3 == 2;
    const int ok = k == 11 ? *end == '\0' : (point_end ? (*end == ';' || *end == '/') : *end == ',');
    if (!ok) usage_error("--corners: '%s' is not four points x,y,z separated by ';' (after number %d)", text, k + 1);
    p = end + 1;
  }
}

struct command_line {
  const char *cloud_path;
  const char *boundary_path;
  const char *corners_text;
  int neighbours; /* -1: the default */
  const char *report_dir;
  int threads;
  int quiet;
};

/* The value of option `arg` (at argv[*i]): after '=' or the next argument. */
static const char *option_value(int argc, char **argv, int *i, const char *arg, size_t flag_length) {
  if (arg[flag_length] == '=') return arg + flag_length + 1;
  if (*i + 1 >= argc) usage_error("%s needs a value", arg);
  return argv[++*i];
}

static int flag_is(const char *arg, const char *flag, size_t *flag_length) {
  const size_t n = strlen(flag);
  *flag_length = n;
  return strncmp(arg, flag, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

static void parse_command_line(int argc, char **argv, struct command_line *cmd) {
  memset(cmd, 0, sizeof *cmd);
  cmd->neighbours = -1;
  for (int i = 1; i < argc; ++i) {
    const char *arg = argv[i];
    size_t n = 0;
    if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
      fputs(usage_text, stdout);
      exit(EXIT_SUCCESS);
    } else if (strcmp(arg, "--version") == 0) {
      printf("dbs-boundary, libdbs %s\n", dbs_version_string());
      exit(EXIT_SUCCESS);
    } else if (strcmp(arg, "-q") == 0 || strcmp(arg, "--quiet") == 0) {
      cmd->quiet = 1;
    } else if (strcmp(arg, "-o") == 0) {
      if (i + 1 >= argc) usage_error("-o needs a value (the boundary file)");
      cmd->boundary_path = argv[++i];
    } else if (flag_is(arg, "--output", &n)) {
      cmd->boundary_path = option_value(argc, argv, &i, arg, n);
    } else if (flag_is(arg, "--corners", &n)) {
      cmd->corners_text = option_value(argc, argv, &i, arg, n);
    } else if (flag_is(arg, "--outline-neighbours", &n)) {
      cmd->neighbours = parse_int("--outline-neighbours", option_value(argc, argv, &i, arg, n));
    } else if (flag_is(arg, "--report", &n)) {
      cmd->report_dir = option_value(argc, argv, &i, arg, n);
    } else if (flag_is(arg, "--threads", &n)) {
      cmd->threads = parse_int("--threads", option_value(argc, argv, &i, arg, n));
    } else if (arg[0] == '-' && arg[1] != '\0') {
      usage_error("unknown option '%s' (see --help)", arg);
    } else if (cmd->cloud_path == NULL) {
      cmd->cloud_path = arg;
    } else {
      usage_error("unexpected argument '%s' (usage: dbs-boundary CLOUD -o BOUNDARY [options])", arg);
    }
  }
  if (cmd->cloud_path == NULL) usage_error("missing CLOUD (usage: dbs-boundary CLOUD -o BOUNDARY [options])");
  if (cmd->report_dir != NULL && cmd->report_dir[0] == '\0') usage_error("--report needs a directory");
  if (cmd->boundary_path == NULL || cmd->boundary_path[0] == '\0') usage_error("missing -o BOUNDARY (the boundary file to write)");
  if (cmd->corners_text != NULL && cmd->neighbours != -1) usage_error("--outline-neighbours applies to the detection; --corners uses the default neighbourhood");
}

static void print_summary(const dbs_boundary *boundary, size_t points, const char *path) {
  static const char *const names[4] = {"bottom", "right", "top", "left"};
  printf("points          %zu\n", points);
  for (int32_t side = 0; side < 4; ++side) {
    size_t count = 0;
    dbs_boundary_side_count(boundary, side, &count);
    double *xyz = malloc(3 * count * sizeof(double));
    if (xyz == NULL) return;
    dbs_boundary_side_points(boundary, side, xyz, count);
    double length = 0.0;
    for (size_t k = 1; k < count; ++k) {
      const double dx = xyz[3 * k] - xyz[3 * k - 3], dy = xyz[3 * k + 1] - xyz[3 * k - 2], dz = xyz[3 * k + 2] - xyz[3 * k - 1];
      length += sqrt(dx * dx + dy * dy + dz * dz);
    }
    printf("%-6s          %zu points, length %.6g, from (%.6g, %.6g, %.6g)\n", names[side], count, length, xyz[0], xyz[1], xyz[2]);
    free(xyz);
  }
  size_t holes = 0;
  dbs_boundary_hole_count(boundary, &holes);
  printf("holes           %zu\n", holes);
  printf("boundary        %s\n", path);
}

int main(int argc, char **argv) {
  struct command_line cmd;
  dbs_cloud *cloud = NULL;
  dbs_boundary *boundary = NULL;
  dbs_options *options = NULL;
  int status, exit_code = EXIT_FAILURE;
  double corners[12];
  size_t points = 0;

  parse_command_line(argc, argv, &cmd);
  if (cmd.corners_text != NULL) parse_corners(cmd.corners_text, corners);
  if ((status = dbs_options_create(&options)) != DBS_OK) {
    library_error(status, "creating options");
    return EXIT_FAILURE;
  }
  if (cmd.neighbours != -1 && (status = dbs_options_set_int(options, DBS_OPT_OUTLINE_NEIGHBOURS, cmd.neighbours)) != DBS_OK) {
    library_error(status, "--outline-neighbours");
    goto done;
  }
  if ((status = dbs_options_set_int(options, DBS_OPT_THREADS, cmd.threads)) != DBS_OK) {
    library_error(status, "--threads");
    goto done;
  }
  if ((status = dbs_cloud_load(cmd.cloud_path, &cloud)) != DBS_OK) {
    library_error(status, "reading the cloud");
    goto done;
  }
  dbs_cloud_count(cloud, &points);
  status = cmd.corners_text != NULL ? dbs_boundary_from_corners(cloud, corners, &boundary) : dbs_boundary_detect(cloud, options, &boundary);
  if (status != DBS_OK) {
    library_error(status, "finding the boundary");
    goto done;
  }
  if ((status = dbs_boundary_save(boundary, cmd.boundary_path)) != DBS_OK) {
    library_error(status, "writing the boundary");
    goto done;
  }
  if (!cmd.quiet) print_summary(boundary, points, cmd.boundary_path);
  if (cmd.report_dir != NULL) {
    if ((status = dbs_boundary_report_write(boundary, cloud, cmd.report_dir)) != DBS_OK) {
      library_error(status, "writing the report");
      goto done;
    }
    if (!cmd.quiet) printf("report          %s\n", cmd.report_dir);
  }
  exit_code = EXIT_SUCCESS;

done:
  dbs_boundary_destroy(boundary);
  dbs_cloud_destroy(cloud);
  dbs_options_destroy(options);
  return exit_code;
}
