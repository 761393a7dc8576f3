/* Binds a preset tree onto a desc struct through its schema: type, range and key checks,
 * every error naming the full key path (e.g. "levels[1].profile[0].points[2][0]"). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "formats/preset_tree.h"

#define PATH_SIZE 256
#define MAX_SAFE_INTEGER 9007199254740992.0 /* 2^53 */

static void path_key(char *dst, const char *parent, const char *key)
{
    if (!key)
        snprintf(dst, PATH_SIZE, "%s", parent);
    else if (parent[0])
        snprintf(dst, PATH_SIZE, "%s.%s", parent, key);
    else
        snprintf(dst, PATH_SIZE, "%s", key);
}

static void path_index(char *dst, const char *parent, int index)
{
    snprintf(dst, PATH_SIZE, "%s[%d]", parent, index);
}

static const char *json_type_name(const cJSON *item)
{
    if (cJSON_IsNumber(item)) return "a number";
    if (cJSON_IsString(item)) return "a string";
    if (cJSON_IsBool(item)) return "a boolean";
    if (cJSON_IsArray(item)) return "an array";
    if (cJSON_IsObject(item)) return "an object";
    if (cJSON_IsNull(item)) return "null";
    return "an unknown value";
}

static sk_result type_error(sk_error *err, const char *path, const char *expected,
                            const cJSON *item)
{
    if (cJSON_IsString(item))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: expected %s, got the string \"%.64s\"",
                       path, expected, item->valuestring);
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: expected %s, got %s", path, expected,
                   json_type_name(item));
}

/* Levenshtein distance of short keys, for "did you mean" hints. */
static int edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 63 || lb > 63) return 99;
    int row[64];
    for (size_t j = 0; j <= lb; j++) row[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int up = row[j];
            int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            int best = diag + cost;
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

static sk_result unknown_key(sk_error *err, const char *path, const char *key,
                             const sk_schema *schema)
{
    const char *closest = NULL;
    int best = 3;
    char accepted[320] = "";
    size_t used = 0;
    for (int i = 0; i < schema->field_count; i++) {
        const char *k = schema->fields[i].key;
        if (!k) continue;
        int d = edit_distance(key, k);
        if (d < best) {
            best = d;
            closest = k;
        }
        int n = snprintf(accepted + used, sizeof accepted - used, "%s%s", used ? ", " : "", k);
        if (n < 0 || (size_t)n >= sizeof accepted - used) break;
        used += (size_t)n;
    }
    if (closest)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: unknown key (did you mean '%s'?)", path,
                       closest);
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: unknown key; accepted keys: %s", path,
                   accepted);
}

static sk_result check_doc_value(const cJSON *item, const char *path, sk_error *err)
{
    if (cJSON_IsString(item)) return SK_OK;
    if (cJSON_IsArray(item)) {
        const cJSON *e;
        cJSON_ArrayForEach(e, item) if (!cJSON_IsString(e)) return type_error(err, path, "a string",
                                                                              e);
        return SK_OK;
    }
    return type_error(err, path, "a string or an array of strings", item);
}

static sk_result bind_object(const cJSON *obj, const sk_schema *schema, unsigned char *base,
                             const char *path, sk_error *err);

static sk_result bind_number(const cJSON *item, const sk_schema_field *f, const char *path,
                             double *value, sk_error *err)
{
    if (!cJSON_IsNumber(item)) return type_error(err, path, "a number", item);
    *value = item->valuedouble;
    double lo, hi;
    sk_schema_field_json_range(f, &lo, &hi);
    return sk_check_range_f(err, path, *value, lo, hi);
}

static sk_result bind_count(const sk_schema_field *f, const cJSON *item, const char *path,
                            unsigned char *base, int *n, sk_error *err)
{
    *n = cJSON_GetArraySize(item);
    bool fixed = f->count_offset == SK_FIELD_FIXED;
    int lo = fixed ? f->count : f->min_count, hi = f->count;
    if (*n < lo || *n > hi) {
        if (lo == hi)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: expected an array of exactly %d elements, got %d", path, lo, *n);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s: array length %d is out of range [%d, %d]", path, *n, lo, hi);
    }
    if (!fixed) memcpy(base + f->count_offset, n, sizeof *n);
    return SK_OK;
}

/* Binds one JSON value to field f of the struct at `base`. */
static sk_result bind_value(const cJSON *item, const sk_schema_field *f, unsigned char *base,
                            const char *path, sk_error *err)
{
    unsigned char *ptr = base + f->offset;
    double scale = f->scale != 0.0 ? f->scale : 1.0;
    double v = 0.0;
    sk_result r;
    switch (f->type) {
    case SK_FIELD_FLOAT: {
        if ((r = bind_number(item, f, path, &v, err)) != SK_OK) return r;
        float fv = (float)(v * scale);
        memcpy(ptr, &fv, sizeof fv);
        return SK_OK;
    }
    case SK_FIELD_DOUBLE: {
        if ((r = bind_number(item, f, path, &v, err)) != SK_OK) return r;
        double dv = v * scale;
        memcpy(ptr, &dv, sizeof dv);
        return SK_OK;
    }
    case SK_FIELD_INT: {
        if ((r = bind_number(item, f, path, &v, err)) != SK_OK) return r;
        if (v != floor(v))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %g is not an integer", path, v);
        int iv = (int)v;
        memcpy(ptr, &iv, sizeof iv);
        return SK_OK;
    }
    case SK_FIELD_SEED: {
        if (!cJSON_IsNumber(item)) return type_error(err, path, "a number", item);
        v = item->valuedouble;
        if (!isfinite(v) || v < 0 || v > MAX_SAFE_INTEGER || v != floor(v))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s = %g must be an integer in [0, 9007199254740992]", path, v);
        uint64_t sv = (uint64_t)v;
        memcpy(ptr, &sv, sizeof sv);
        return SK_OK;
    }
    case SK_FIELD_BOOL: {
        if (!cJSON_IsBool(item)) return type_error(err, path, "true or false", item);
        bool bv = cJSON_IsTrue(item);
        memcpy(ptr, &bv, sizeof bv);
        return SK_OK;
    }
    case SK_FIELD_ENUM: {
        if (!cJSON_IsString(item)) return type_error(err, path, "a string", item);
        char names[320] = "";
        size_t used = 0;
        for (int i = 0; f->names && f->names[i]; i++) {
            if (strcmp(f->names[i], item->valuestring) == 0) {
                memcpy(ptr, &i, sizeof i);
                return SK_OK;
            }
            int n =
                snprintf(names + used, sizeof names - used, "%s%s", used ? ", " : "", f->names[i]);
            if (n > 0 && (size_t)n < sizeof names - used) used += (size_t)n;
        }
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = \"%s\" is not one of: %s", path,
                       item->valuestring, names);
    }
    case SK_FIELD_STRING: {
        if (!cJSON_IsString(item)) return type_error(err, path, "a string", item);
        size_t len = strlen(item->valuestring);
        if (len >= (size_t)f->count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: string of %zu characters is longer than %d", path, len,
                           f->count - 1);
        memcpy(ptr, item->valuestring, len + 1);
        return SK_OK;
    }
    case SK_FIELD_FLOATS: {
        if (!cJSON_IsArray(item)) return type_error(err, path, "an array of numbers", item);
        int n;
        if ((r = bind_count(f, item, path, base, &n, err)) != SK_OK) return r;
        int i = 0;
        const cJSON *e;
        cJSON_ArrayForEach(e, item)
        {
            char epath[PATH_SIZE];
            path_index(epath, path, i);
            if ((r = bind_number(e, f, epath, &v, err)) != SK_OK) return r;
            float fv = (float)(v * scale);
            memcpy(ptr + (size_t)i * sizeof(float), &fv, sizeof fv);
            i++;
        }
        return SK_OK;
    }
    case SK_FIELD_OBJECT:
        return bind_object(item, f->schema, ptr, path, err);
    case SK_FIELD_ARRAY: {
        if (!cJSON_IsArray(item)) return type_error(err, path, "an array", item);
        int n;
        if ((r = bind_count(f, item, path, base, &n, err)) != SK_OK) return r;
        const sk_schema *es = f->schema;
        bool bare = es->field_count == 1 && es->fields[0].key == NULL;
        int i = 0;
        const cJSON *e;
        cJSON_ArrayForEach(e, item)
        {
            char epath[PATH_SIZE];
            path_index(epath, path, i);
            unsigned char *elem = ptr + (size_t)i * f->elem_size;
            memset(elem, 0, f->elem_size); /* absent keys of an element mean defaults */
            r = bare ? bind_value(e, &es->fields[0], elem, epath, err)
                     : bind_object(e, es, elem, epath, err);
            if (r != SK_OK) return r;
            i++;
        }
        return SK_OK;
    }
    }
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: field has an unknown type", path);
}

static sk_result bind_object(const cJSON *obj, const sk_schema *schema, unsigned char *base,
                             const char *path, sk_error *err)
{
    if (!cJSON_IsObject(obj)) return type_error(err, path[0] ? path : "preset", "an object", obj);
    const cJSON *item;
    cJSON_ArrayForEach(item, obj)
    {
        char kpath[PATH_SIZE];
        path_key(kpath, path, item->string);
        for (const cJSON *prev = obj->child; prev != item; prev = prev->next)
            if (strcmp(prev->string, item->string) == 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: key given twice", kpath);
        if (sk_preset_is_doc_key(item->string)) {
            sk_result r = check_doc_value(item, kpath, err);
            if (r != SK_OK) return r;
            continue;
        }
        const sk_schema_field *field = NULL;
        for (int i = 0; i < schema->field_count; i++)
            if (schema->fields[i].key && strcmp(schema->fields[i].key, item->string) == 0)
                field = &schema->fields[i];
        if (!field) return unknown_key(err, kpath, item->string, schema);
        sk_result r = bind_value(item, field, base, kpath, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

sk_result sk_preset_bind(const sk_preset *preset, const sk_schema *schema, void *desc,
                         sk_error *err)
{
    return bind_object(preset->root, schema, desc, "", err);
}
