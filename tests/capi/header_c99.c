/* Compiled as strict C99 with -Wall -Wextra -pedantic -Werror: dbs.h must stand alone. */
#include "dbs.h"

int dbs_header_c99_check(void);
int dbs_header_c99_check(void) { return DBS_AT_LEAST_VERSION(0, 0, 0) ? DBS_OK : DBS_ERR_INTERNAL; }
