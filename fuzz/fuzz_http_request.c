/* Fuzz harness: the studio server's request parser and its mapping of request paths
 * onto files under the served root (which must never leave it). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "http.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    http_request req;
    if (http_parse_request((const char *)data, size, &req) != HTTP_PARSE_OK) return 0;
    char rel[HTTP_MAX_PATH + 16];
    if (!http_relative_path(req.path, rel, sizeof rel)) return 0;
    /* a mapped path is relative, has no dot segment and no backslash */
    if (rel[0] == '/' || strstr(rel, "..") == rel || strstr(rel, "/.") || strchr(rel, '\\') ||
        rel[0] == '.')
        abort();
    (void)http_mime_type(rel);
    return 0;
}
