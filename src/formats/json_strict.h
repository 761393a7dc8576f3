/* Private: the one JSON reader of the library. Presets, scene files, --set values and the
 * hand's data files (constraint sets, anatomy, animations) all parse through it, so they
 * accept and refuse the same texts. */
#ifndef SK_IO_JSON_STRICT_H
#define SK_IO_JSON_STRICT_H

#include <stddef.h>

#include <cjson/cJSON.h>

#include "shitsukan/core.h"

/* Parses exactly one JSON value spanning the whole text (white space around it only) and
 * refuses, beyond malformed JSON: a NUL byte, a key given twice in one object, and an
 * integer literal beyond 2^53 (it cannot be held exactly as a double, so a seed of
 * 2^53 + 1 would silently become 2^53; write such numbers with a fraction or exponent).
 * Errors read "<source_name>:<line>:<column>: <what>" ("line L: <what> (column C)" when
 * source_name is NULL, "<what>" when it is "", for a one-line value such as --set's); a duplicate
 * key is "<key path>: key given twice", the key path as the schema binder writes it
 * ("levels[1].jitter"). Results: SK_ERROR_PARSE for text that is not JSON,
 * SK_ERROR_INVALID_ARGUMENT for JSON that is refused (duplicate key, inexact integer). On success
 * *out is the tree (free with cJSON_Delete). */
sk_result sk__json_parse(const char *text, size_t length, const char *source_name, cJSON **out,
                         sk_error *err);

#endif
