/* shitsukan presets: JSON parameter sets bound to a module's desc struct through a
 * schema (a table of fields with types, ranges and docs), with command-line overrides
 * ("--set key.path=value"). Errors name the full key path, e.g.
 * "levels[1].profile[0].points[2][0] = 12 is out of range [0, 10]".
 *
 * Thread-safety: a schema is immutable data; an sk_preset belongs to one thread. */
#ifndef SHITSUKAN_PRESET_H
#define SHITSUKAN_PRESET_H

#include <stddef.h>
#include <stdio.h>

#include "shitsukan/core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sk_field_type {
    SK_FIELD_FLOAT = 1, /* float; JSON number in [min, max], stored times `scale` */
    SK_FIELD_DOUBLE,    /* double; as FLOAT */
    SK_FIELD_INT,       /* int; JSON integer in [min, max] */
    SK_FIELD_SEED,      /* uint64_t; JSON integer in [0, 2^53] */
    SK_FIELD_BOOL,      /* bool; JSON true/false */
    SK_FIELD_ENUM,      /* int; JSON string, one of `names` (index = stored value) */
    SK_FIELD_STRING,    /* char[count]; JSON string shorter than count */
    SK_FIELD_FLOATS,    /* float[count]; JSON array of numbers, each in [min, max]; with a
                           count_offset the length may be min_count..count and is stored
                           as an int there, otherwise it must be exactly count */
    SK_FIELD_OBJECT,    /* nested struct described by `schema` */
    SK_FIELD_ARRAY      /* struct[count] of `elem_size` bytes, each described by `schema`;
                           length min_count..count stored as an int at count_offset */
} sk_field_type;

struct sk_schema;

typedef struct sk_schema_field {
    const char *key; /* JSON key; NULL for the single field of an array element that
                        is itself a value (e.g. a point [x, z] in a list of points) */
    sk_field_type type;
    size_t offset;       /* offsetof(desc, field) */
    double min, max;     /* accepted range of numbers (as written in JSON, before scale) */
    double scale;        /* stored = JSON value * scale (e.g. SK_DEG_TO_RAD); 0 = 1 */
    int count;           /* STRING: buffer size; FLOATS/ARRAY: maximum length */
    int min_count;       /* FLOATS/ARRAY with count_offset: minimum length */
    size_t count_offset; /* FLOATS/ARRAY: offsetof the int length; SK_FIELD_FIXED = fixed */
    size_t elem_size;    /* ARRAY: sizeof one element */
    const struct sk_schema *schema; /* OBJECT / ARRAY element */
    const char *const *names;       /* ENUM: value names, NULL-terminated */
    const char *doc;                /* one line: meaning, unit and default */
} sk_schema_field;

#define SK_FIELD_FIXED ((size_t)-1)

typedef struct sk_schema {
    const char *name; /* e.g. "skin" */
    const sk_schema_field *fields;
    int field_count;
} sk_schema;

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

/* Top-level string value of `key` (e.g. "description"), or NULL. */
const char *sk_preset_get_string(const sk_preset *preset, const char *key);

/* JSON text of a desc as the schema sees it (the inverse of bind; free with free()). */
char *sk_schema_to_json(const sk_schema *schema, const void *desc);

/* The schema as JSON (free with free()), for interfaces that build a control per key:
 * {"name": ..., "fields": [{"key", "type" (float double int seed bool enum string floats
 * object array), "min", "max" (numbers, as written in JSON), "min_count", "max_count"
 * (floats, arrays), "max_length" (strings), "names" (enums), "doc", "fields" (objects,
 * array elements; an element field with "key": null is the element itself)}]}. */
char *sk_schema_describe_json(const sk_schema *schema);

/* Writes one line per key path with its type, range and doc ("levels[].jitter  float
 * [0, 1]  maximum jitter as a fraction of the spacing; default 0"). */
void sk_schema_print(const sk_schema *schema, FILE *out);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_PRESET_H */
