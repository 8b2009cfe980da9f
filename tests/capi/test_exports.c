/* The shared library's ABI: only dbs_* leaves it, every function of dbs.h does, and the
 * SONAME carries the ABI major. Reads the built library with binutils (nm, objdump). */
#define _POSIX_C_SOURCE 200809L /* popen */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_support.h"

#define MAX_NAMES 256
#define NAME_SIZE 128

/* The version node of capi/dbs.map, attached to every exported function. */
#define VERSION_NODE "DBS_0"

struct names {
  char name[MAX_NAMES][NAME_SIZE];
  size_t count;
};

static int contains(const struct names *names, const char *name) {
  for (size_t i = 0; i < names->count; ++i)
    if (strcmp(names->name[i], name) == 0) return 1;
  return 0;
}

static void add(struct names *names, const char *name) {
  assert_true(names->count < MAX_NAMES);
  assert_true(strlen(name) < NAME_SIZE);
  strcpy(names->name[names->count++], name);
}

static int is_shared_library(void) {
  const char *file = DBS_LIBRARY_FILE;
  size_t n = strlen(file);
  return !(n > 2 && strcmp(file + n - 2, ".a") == 0);
}

/* The functions declared in dbs.h: every line starting with DBS_API, the identifier before '('. */
static void header_functions(struct names *out) {
  FILE *header = fopen(DBS_TEST_DATA_DIR "/../include/dbs.h", "r");
  assert_non_null(header);
  char line[1024];
  while (fgets(line, sizeof line, header)) {
    if (strncmp(line, "DBS_API ", 8) != 0) continue;
    char *paren = strchr(line, '(');
    assert_non_null(paren);
    char *start = paren;
    while (start > line && (isalnum((unsigned char)start[-1]) || start[-1] == '_')) --start;
    *paren = '\0';
    add(out, start);
  }
  fclose(header);
}

/* The dynamic symbols the library defines, as nm lists them: split into functions and data
 * named dbs_* (with their version checked) and anything else, which must not exist. */
static void exported_symbols(struct names *functions, struct names *data) {
  FILE *nm = popen("nm -D --defined-only '" DBS_LIBRARY_FILE "'", "r");
  assert_non_null(nm);
  char line[1024];
  size_t lines = 0;
  while (fgets(line, sizeof line, nm)) {
    ++lines;
    char address[64], type, symbol[512];
    assert_int_equal(sscanf(line, "%63s %c %511s", address, &type, symbol), 3);
    char *at = strchr(symbol, '@');
    if (at) {
      /* the version binutils read from .gnu.version: the default version DBS_0 */
      if (strcmp(at, "@@" VERSION_NODE) != 0) fail_msg("symbol not in version " VERSION_NODE ": %s", line);
      *at = '\0';
    }
    if (type == 'A') {
      /* the only absolute symbol a version script creates is its version node */
      if (strcmp(symbol, VERSION_NODE) != 0) fail_msg("unexpected absolute symbol: %s", line);
      continue;
    }
    if (strncmp(symbol, "dbs_", 4) != 0) fail_msg("exported symbol outside the dbs_ namespace: %s", line);
    if (type == 'T')
      add(functions, symbol);
    else
      add(data, symbol);
  }
  assert_int_equal(pclose(nm), 0);
  assert_true(lines > 0);
}

static void only_the_api_is_exported(void **state) {
  (void)state;
  if (!is_shared_library()) skip();
  static struct names declared, functions, data;
  header_functions(&declared);
  exported_symbols(&functions, &data);
  /* the parse found the API: it only grows (47 functions in 0.1.0), first to last */
  assert_true(declared.count >= 47);
  assert_string_equal(declared.name[0], "dbs_version_number");
  assert_true(contains(&declared, "dbs_parameterize") && contains(&declared, "dbs_patches_stats"));
  for (size_t i = 0; i < declared.count; ++i)
    if (!contains(&functions, declared.name[i])) fail_msg("%s is declared in dbs.h but not exported", declared.name[i]);
  for (size_t i = 0; i < functions.count; ++i)
    if (!contains(&declared, functions.name[i])) fail_msg("%s is exported but not declared in dbs.h", functions.name[i]);
  assert_int_equal(functions.count, declared.count);
  assert_int_equal(data.count, 0); /* the API exports functions only */
}

static void soname_carries_the_abi_major(void **state) {
  (void)state;
  if (!is_shared_library()) skip();
  FILE *objdump = popen("objdump -p '" DBS_LIBRARY_FILE "'", "r");
  assert_non_null(objdump);
  char line[1024], soname[256] = "";
  while (fgets(line, sizeof line, objdump)) {
    char key[64], value[256];
    if (sscanf(line, "%63s %255s", key, value) == 2 && strcmp(key, "SONAME") == 0) strcpy(soname, value);
  }
  assert_int_equal(pclose(objdump), 0);
  assert_string_equal(soname, "libdbs.so.0");
  /* behind it, the file named after the release */
  const char *file = strrchr(DBS_LIBRARY_FILE, '/');
  file = file ? file + 1 : DBS_LIBRARY_FILE;
  char expected[64];
  snprintf(expected, sizeof expected, "libdbs.so.%d.%d.%d", DBS_VERSION_MAJOR, DBS_VERSION_MINOR, DBS_VERSION_PATCH);
  assert_string_equal(file, expected);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(only_the_api_is_exported),
      cmocka_unit_test(soname_carries_the_abi_major),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
