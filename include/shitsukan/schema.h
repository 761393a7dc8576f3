/* shitsukan schemas: the keys of a desc struct as a static table of fields (JSON key, type,
 * offset, accepted range, default, one line of documentation). A key's range and default
 * are stated once, here, and read by everything that needs them: a model's validation
 * (sk_schema_check) and its defaults (sk_schema_apply_defaults), the preset binder and
 * --help-keys (shitsukan/preset.h), the docs' key tables and the studio's controls.
 *
 * The types and the functions below are in the base library: a model states its schema
 * and checks its desc against it without the preset reader (the formats layer).
 *
 * Thread-safety: a schema is immutable data; every function here is thread-safe. */
#ifndef SHITSUKAN_SCHEMA_H
#define SHITSUKAN_SCHEMA_H

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

/* Flags of a field (sk_schema_field.flags). */
enum {
    /* 0 (the value of an all-zero desc) stands for the default and is accepted besides
       [min, max]: a preset may give any value in [0, max] (one in (0, min) fails the
       model's check), the model checks the resolved value against [min, max]. */
    SK_FIELD_ZERO = 1u << 0,
    /* The range is (min, max]: the value must exceed min (a required size); a preset may
       give min itself, which the model's check refuses ("(required)" when it is 0). */
    SK_FIELD_OPEN_MIN = 1u << 1,
    /* A nested desc of another model that checks and resolves it where it is used: passed
       over by sk_schema_check and sk_schema_apply_defaults. */
    SK_FIELD_OWN = 1u << 2
};

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
    const char *doc;                /* one line: meaning and unit */
    unsigned flags;                 /* SK_FIELD_ZERO, SK_FIELD_OPEN_MIN, SK_FIELD_OWN */
    /* The default, as written in JSON. A number: what a stored 0 becomes (0 = none: the
       value of the all-zero desc is the default); ENUM: the index of the default name;
       FLOATS: each element that is 0 becomes `def`, unless `defs` is given. */
    double def;
    const double *defs;   /* FLOATS: `count` defaults that replace the elements when all
                             are 0 (a colour); NULL = `def` per element */
    const char *def_text; /* the default in words when the model computes it from other
                             keys ("1 - specular"); sk_schema_apply_defaults leaves these
                             to the model */
} sk_schema_field;

#define SK_FIELD_FIXED ((size_t)-1)

typedef struct sk_schema {
    const char *name; /* e.g. "skin" */
    const sk_schema_field *fields;
    int field_count;
    const char *c_type; /* the struct the fields describe ("sk_skin_level"), or NULL */
} sk_schema;

/* ------------------------------------------------------------- stating fields */
/* One macro per kind of field, so that every schema states its fields alike:
 *   SK_SCHEMA_FLOAT(sk_wood_log_desc, radius_mm, "radius_mm", 1, 2000,
 *                   .flags = SK_FIELD_ZERO, .def = 150, .doc = "radius the tables cover (mm)")
 * T is the struct, `member` its member, `k` the JSON key; the trailing designated
 * initializers give the doc (always) and the flags, default and scale where they apply. */
#define SK_SCHEMA_OF(name_, T, fields_)                                                            \
    {                                                                                              \
        .name = name_, .fields = fields_,                                                          \
        .field_count = (int)(sizeof(fields_) / sizeof((fields_)[0])), .c_type = #T                 \
    }
#define SK_SCHEMA_FLOAT(T, member, k, lo, hi, ...)                                                 \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOAT, .offset = offsetof(T, member), .min = lo, .max = hi,     \
        __VA_ARGS__                                                                                \
    }
#define SK_SCHEMA_DOUBLE(T, member, k, lo, hi, ...)                                                \
    {                                                                                              \
        .key = k, .type = SK_FIELD_DOUBLE, .offset = offsetof(T, member), .min = lo, .max = hi,    \
        __VA_ARGS__                                                                                \
    }
/* A float angle stored in radians, written in degrees (the key ends in _deg). */
#define SK_SCHEMA_DEG(T, member, k, lo, hi, ...)                                                   \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOAT, .offset = offsetof(T, member), .min = lo, .max = hi,     \
        .scale = SK_DEG_TO_RAD, __VA_ARGS__                                                        \
    }
#define SK_SCHEMA_INT(T, member, k, lo, hi, ...)                                                   \
    {                                                                                              \
        .key = k, .type = SK_FIELD_INT, .offset = offsetof(T, member), .min = lo, .max = hi,       \
        __VA_ARGS__                                                                                \
    }
#define SK_SCHEMA_SEED(T, member, k, ...)                                                          \
    {                                                                                              \
        .key = k, .type = SK_FIELD_SEED, .offset = offsetof(T, member), .min = 0,                  \
        .max = 9007199254740992.0, __VA_ARGS__                                                     \
    }
#define SK_SCHEMA_BOOL(T, member, k, ...)                                                          \
    {                                                                                              \
        .key = k, .type = SK_FIELD_BOOL, .offset = offsetof(T, member), __VA_ARGS__                \
    }
#define SK_SCHEMA_ENUM(T, member, k, names_, ...)                                                  \
    {                                                                                              \
        .key = k, .type = SK_FIELD_ENUM, .offset = offsetof(T, member), .names = names_,           \
        __VA_ARGS__                                                                                \
    }
/* A char array member: its size is the buffer's. */
#define SK_SCHEMA_STRING(T, member, k, ...)                                                        \
    {                                                                                              \
        .key = k, .type = SK_FIELD_STRING, .offset = offsetof(T, member),                          \
        .count = (int)sizeof(((T *)0)->member), __VA_ARGS__                                        \
    }
/* A float array member of exactly n elements. */
#define SK_SCHEMA_FLOATS(T, member, k, n, lo, hi, ...)                                             \
    {                                                                                              \
        .key = k, .type = SK_FIELD_FLOATS, .offset = offsetof(T, member), .min = lo, .max = hi,    \
        .count = n, .count_offset = SK_FIELD_FIXED, __VA_ARGS__                                    \
    }
/* An array member of exactly as many elements as it has, each described by `sub`. */
#define SK_SCHEMA_FIXED_ARRAY(T, member, k, sub, ...)                                              \
    {                                                                                              \
        .key = k, .type = SK_FIELD_ARRAY, .offset = offsetof(T, member),                           \
        .count = (int)(sizeof(((T *)0)->member) / sizeof(((T *)0)->member[0])),                    \
        .min_count = (int)(sizeof(((T *)0)->member) / sizeof(((T *)0)->member[0])),                \
        .count_offset = SK_FIELD_FIXED, .elem_size = sizeof(((T *)0)->member[0]),                  \
        .schema = &(sub), __VA_ARGS__                                                              \
    }
/* The single field of an array element that is itself n numbers (a point [x, z]). */
#define SK_SCHEMA_ELEMENT_FLOATS(n, lo, hi, ...)                                                   \
    {                                                                                              \
        .key = NULL, .type = SK_FIELD_FLOATS, .offset = 0, .min = lo, .max = hi, .count = n,       \
        .count_offset = SK_FIELD_FIXED, __VA_ARGS__                                                \
    }
#define SK_SCHEMA_OBJECT(T, member, k, sub, ...)                                                   \
    {                                                                                              \
        .key = k, .type = SK_FIELD_OBJECT, .offset = offsetof(T, member), .schema = &(sub),        \
        __VA_ARGS__                                                                                \
    }
/* An array member of structs described by `sub`, its length in member `count_member`
 * (min_n..the array's size elements in JSON). */
#define SK_SCHEMA_ARRAY(T, member, k, count_member, min_n, sub, ...)                               \
    {                                                                                              \
        .key = k, .type = SK_FIELD_ARRAY, .offset = offsetof(T, member),                           \
        .count = (int)(sizeof(((T *)0)->member) / sizeof(((T *)0)->member[0])),                    \
        .min_count = min_n, .count_offset = offsetof(T, count_member),                             \
        .elem_size = sizeof(((T *)0)->member[0]), .schema = &(sub), __VA_ARGS__                    \
    }

/* ------------------------------------------------------------------ use */

/* The range a JSON value of a number field may take: [min, max], and 0 besides for a
 * field whose 0 means the default (SK_FIELD_ZERO), min itself for (min, max]. */
void sk_schema_field_json_range(const sk_schema_field *field, double *lo, double *hi);

/* The field at a key path ("shading.specular"; an array's element fields as
 * "levels[].jitter_rate", a FLOATS element as "size_mm[]"), or NULL. */
const sk_schema_field *sk_schema_find(const sk_schema *schema, const char *key_path);

/* Checks every number of `desc` (a desc the model has resolved, or one whose zeros are
 * accepted as they are) against its field's range, in schema order; arrays up to their
 * stored length. Messages name the key path as a preset writes it (`path` prefixes it,
 * "" for none) and the value in JSON units: "levels[1].jitter_rate = 1.5 is out of range
 * [0, 1]", "bones[0].radius_mm = 0 is out of range (0, 1000] (required)". Strings, booleans
 * and seeds are not checked; the rules between keys are the model's. */
sk_result sk_schema_check(const sk_schema *schema, const void *desc, const char *path,
                          sk_error *err);
/* The same for one field of the struct at `base`, `path` its full key path. */
sk_result sk_schema_check_field(const sk_schema_field *field, const void *base, const char *path,
                                sk_error *err);

/* A field's accepted range and its default in words, as --help-keys and the docs' key
 * tables print them: "[0, 1]", "0 or [1, 2000]", "(0, 1000]", "3 x [0, 1]", "a|b|c",
 * "1..8 elements"; "0 = 150", "default 64" (when a preset cannot give 0), "all 0 = [0.82,
 * 0.64, 0.44]", "0 = 1 - specular", "default figure", "required". Empty when there is
 * none (strings, objects). */
void sk_schema_field_range_text(const sk_schema_field *field, char *buf, size_t size);
void sk_schema_field_default_text(const sk_schema_field *field, char *buf, size_t size);

/* Writes one line per key path with its type, range, doc and default (--help-keys):
 * "levels[].jitter_rate  number  [0, 1]  maximum jitter as a fraction of the spacing;
 * default 0". Arrays' elements as "levels[].key". */
void sk_schema_print(const sk_schema *schema, FILE *out);
/* The same as a Markdown table (| key | type | range | default | meaning |), the form of
 * the docs' key tables (--help-keys=markdown). A nested desc of another model
 * (SK_FIELD_OWN) is one row: its keys are in that model's table. */
void sk_schema_print_markdown(const sk_schema *schema, FILE *out);

/* Replaces the zeros of `desc` by the stated defaults (def, defs; not def_text), through
 * nested objects and array elements up to their stored length. */
void sk_schema_apply_defaults(const sk_schema *schema, void *desc);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_SCHEMA_H */
