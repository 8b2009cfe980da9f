#include "library_message.h"

#include <stdio.h>
#include <string.h>

#include "dbs.h"

void library_message(int status, char *text, size_t size) {
  const char *message = dbs_last_error_message();
  if (message == NULL || message[0] == '\0') message = dbs_status_string(status);
  snprintf(text, size, "%s", message);
  text[strcspn(text, "\r\n")] = '\0';
}
