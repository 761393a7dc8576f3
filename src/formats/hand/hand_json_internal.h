/* What the hand's file readers and writers share: strict JSON reading in which every
 * error names the key path, whole-file reading and atomic text writing. */
#ifndef SK_HAND_JSON_INTERNAL_H
#define SK_HAND_JSON_INTERNAL_H

#include <cjson/cJSON.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"

/* ----- strict JSON reading (cJSON): every error names the key path ----- */
/* Parses text; on failure names the line of the error (callers prefix the source). */
sk_result sk__hand_json_parse(const char *text, size_t length, const char *source_name, cJSON **out,
                              sk_error *err);
/* Fails if `object` has a key that is neither in `allowed` (NULL-terminated) nor a
 * documentation key. */
sk_result sk__hand_json_check_keys(const cJSON *object, const char *path,
                                   const char *const *allowed, sk_error *err);
/* Reads a finite number in [lo, hi] at object[key] into *out (absent: leaves *out,
 * returns SK_OK unless `required`). */
sk_result sk__hand_json_number(const cJSON *object, const char *path, const char *key, double lo,
                               double hi, bool required, double *out, sk_error *err);
/* Reads a string at object[key] (absent: *out = NULL). */
sk_result sk__hand_json_string(const cJSON *object, const char *path, const char *key,
                               const char **out, sk_error *err);
/* Requires `item` to be an object. */
sk_result sk__hand_json_expect_object(const cJSON *item, const char *path, sk_error *err);
/* Reads a whole data file (at most SK_HAND_MAX_FILE_BYTES) and hands it to a parser
 * `parse(text, length, path, ctx, err)`. */
typedef sk_result (*sk__hand_parse_fn)(const char *text, size_t length, const char *source_name,
                                       void *ctx, sk_error *err);
sk_result sk__hand_parse_file(const char *path, sk__hand_parse_fn parse, void *ctx, sk_error *err);

/* Writes text through an atomic file (temp + rename). */
sk_result sk__hand_write_text_file(const char *path, const char *text, sk_error *err);

/* A constraint set read from a JSON object (the format of sk_hand_constraints_parse)
 * that may also hold the keys in `extra` (NULL-terminated, may be NULL). Errors name the
 * key path below `path`. */
sk_result sk__hand_constraints_from_json(const cJSON *object, const char *path,
                                         const sk_hand_skeleton *skeleton, const char *const *extra,
                                         sk_hand_constraints *out, sk_error *err);

/* Parses text as exactly one JSON value: trailing text, duplicate keys and numbers that
 * overflow are errors ("line N: ..."). */
sk_result sk__hand_json_parse_strict(const char *text, size_t length, cJSON **out, sk_error *err);

#endif
