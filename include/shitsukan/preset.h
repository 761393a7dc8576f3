/* shitsukan presets: JSON parameter sets bound to a module's desc struct through a
 * schema (shitsukan/schema.h: a table of fields with types, ranges, defaults and docs),
 * with command-line overrides ("--set key.path=value"). Errors name the full key path,
 * e.g. "levels[1].profile[0].points[2][0] = 12 is out of range [0, 10]".
 *
 * Thread-safety: a schema is immutable data; an sk_preset belongs to one thread. */
#ifndef SHITSUKAN_PRESET_H
#define SHITSUKAN_PRESET_H

#include <stddef.h>
#include <stdio.h>

#include "shitsukan/core.h"
#include "shitsukan/schema.h" /* the schema types (sk_schema, sk_schema_field) */

#ifdef __cplusplus
extern "C" {
#endif

/* Keys accepted (and ignored) in every JSON object for documentation: "description",
 * "source", "notes", "figure" (strings or arrays of strings). Modules that read their own
 * JSON files (e.g. hand constraint sets) use this to accept the same keys. */
bool sk_preset_is_doc_key(const char *key);

/* A parsed JSON preset (a tree that --set can edit before it is bound). */
typedef struct sk_preset sk_preset;

/* Empty preset "{}". */
sk_result sk_preset_create(sk_preset **out, sk_error *err);
/* Parses JSON text; `source_name` (e.g. the file name) prefixes parse errors. */
sk_result sk_preset_parse(sk_preset **out, const char *text, size_t length, const char *source_name,
                          sk_error *err);
/* Reads and parses a file (at most 16 MiB). */
sk_result sk_preset_load_file(sk_preset **out, const char *path, sk_error *err);
void sk_preset_free(sk_preset *preset);

/* Applies "key.path=value": the value is parsed as JSON (number, true/false, null, array,
 * object, quoted string); anything else is taken as a string. Missing object keys along
 * the path are created; an array index may be at most the array's current length (equal
 * appends). `null` removes the key (back to the default). */
sk_result sk_preset_set(sk_preset *preset, const char *assignment, sk_error *err);

/* Binds the preset onto `desc` through `schema`: every key must be a field of the schema
 * (or a documentation key), every value must have the field's type and range. Fields
 * absent from the JSON keep the value already in `desc` (normally zero = default). */
sk_result sk_preset_bind(const sk_preset *preset, const sk_schema *schema, void *desc,
                         sk_error *err);

/* Moves the top-level `key` (if present) of `preset` into a new preset `out` holding only
 * it (an empty one when absent), so that two schemas bind the two parts. */
sk_result sk_preset_detach(sk_preset *preset, const char *key, sk_preset **out, sk_error *err);

/* Top-level string value of `key` (e.g. "description"), or NULL. */
const char *sk_preset_get_string(const sk_preset *preset, const char *key);

/* JSON text of a desc as the schema sees it (the inverse of bind; free with free()). */
char *sk_schema_to_json(const sk_schema *schema, const void *desc);

/* The schema as JSON (free with free()), for interfaces that build a control per key:
 * {"name": ..., "fields": [{"key", "type" (float double int seed bool enum string floats
 * object array), "min", "max" (numbers, as written in JSON), "min_count", "max_count"
 * (floats, arrays), "max_length" (strings), "names" (enums), "doc", "default" (in words,
 * e.g. "0 = 150"), "fields" (objects, array elements; an element field with "key": null
 * is the element itself)}]}. "min" is the least a JSON value may be (0 for a key whose 0
 * means its default). */
char *sk_schema_describe_json(const sk_schema *schema);

/* sk_schema_print, sk_schema_print_markdown (--help-keys): in shitsukan/schema.h. */

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_PRESET_H */
