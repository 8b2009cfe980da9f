/* The message of a failed libdbs call, as the command-line tools print it. */
#ifndef DBS_EXAMPLES_LIBRARY_MESSAGE_H
#define DBS_EXAMPLES_LIBRARY_MESSAGE_H

#include <stddef.h>

/* The last failure's message on this thread (the status's name when there is none), cut to
 * its first line (one line by contract; a tool's stderr keeps it so), into text[size]. */
void library_message(int status, char *text, size_t size);

#endif
