/* A JSON document written to a file the way every JSON output of the library is:
 * indented, one final newline, through sk_atomic_file (no partial file on failure). */
#ifndef SK_IO_JSON_FILE_H
#define SK_IO_JSON_FILE_H

#include <cjson/cJSON.h>

#include "shitsukan/core.h"

/* Writes `root` to `path` and deletes it (a NULL root: out of memory while building it). */
sk_result sk__json_write_file(cJSON *root, const char *path, sk_error *err);

#endif
