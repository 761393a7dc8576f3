/* A desc checked against its schema: every number within the range its field states,
 * named by its key path as a preset writes it (the ranges are stated once, in the
 * schema; the preset binder checks the same ranges on JSON values). */
#include <stdio.h>
#include <string.h>

#include "shitsukan/schema.h"

#define PATH_SIZE 256

static void path_key(char *dst, const char *parent, const char *key)
{
    if (!key)
        snprintf(dst, PATH_SIZE, "%s", parent);
    else if (parent[0])
        snprintf(dst, PATH_SIZE, "%s.%s", parent, key);
    else
        snprintf(dst, PATH_SIZE, "%s", key);
}

/* A stored value in JSON units: radians back to degrees as the preset wrote them. */
static double json_value(const sk_schema_field *f, double stored)
{
    if (f->scale == 0.0 || f->scale == 1.0) return stored;
    if (f->scale == SK_DEG_TO_RAD) return stored * SK_RAD_TO_DEG;
    return stored / f->scale;
}

static sk_result check_number(const sk_schema_field *f, double stored, const char *path,
                              sk_error *err)
{
    double v = json_value(f, stored);
    if ((f->flags & SK_FIELD_ZERO) && v == 0.0) return SK_OK;
    if (f->flags & SK_FIELD_OPEN_MIN) {
        if (!(v > f->min) || v > f->max)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = %g is out of range (%g, %g]%s",
                           path, v, f->min, f->max, v == 0.0 ? " (required)" : "");
        return SK_OK;
    }
    if (f->type == SK_FIELD_INT)
        return sk_check_range_i(err, path, (long long)stored, (long long)f->min, (long long)f->max);
    return sk_check_range_f(err, path, v, f->min, f->max);
}

static int stored_count(const sk_schema_field *f, const unsigned char *base)
{
    if (f->count_offset == SK_FIELD_FIXED) return f->count;
    int n;
    memcpy(&n, base + f->count_offset, sizeof n);
    return n;
}

static int name_count(const char *const *names)
{
    int n = 0;
    while (names && names[n]) n++;
    return n;
}

static sk_result check_object(const sk_schema *schema, const unsigned char *base, const char *path,
                              sk_error *err);

sk_result sk_schema_check_field(const sk_schema_field *f, const void *base_in, const char *path,
                                sk_error *err)
{
    const unsigned char *base = base_in, *ptr = base + f->offset;
    char epath[PATH_SIZE];
    sk_result r;
    if (f->flags & SK_FIELD_OWN) return SK_OK;
    switch (f->type) {
    case SK_FIELD_FLOAT: {
        float v;
        memcpy(&v, ptr, sizeof v);
        return check_number(f, v, path, err);
    }
    case SK_FIELD_DOUBLE: {
        double v;
        memcpy(&v, ptr, sizeof v);
        return check_number(f, v, path, err);
    }
    case SK_FIELD_INT: {
        int v;
        memcpy(&v, ptr, sizeof v);
        return check_number(f, v, path, err);
    }
    case SK_FIELD_ENUM: {
        int v;
        memcpy(&v, ptr, sizeof v);
        return sk_check_range_i(err, path, v, 0, name_count(f->names) - 1);
    }
    case SK_FIELD_FLOATS: {
        int n = stored_count(f, base);
        if (n < 0 || n > f->count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s (count) = %d is out of range [0, %d]", path, n, f->count);
        for (int i = 0; i < n; i++) {
            float v;
            memcpy(&v, ptr + (size_t)i * sizeof v, sizeof v);
            snprintf(epath, sizeof epath, "%s[%d]", path, i);
            if ((r = check_number(f, v, epath, err)) != SK_OK) return r;
        }
        return SK_OK;
    }
    case SK_FIELD_OBJECT:
        return check_object(f->schema, ptr, path, err);
    case SK_FIELD_ARRAY: {
        int n = stored_count(f, base);
        if (n < 0 || n > f->count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s (count) = %d is out of range [0, %d]", path, n, f->count);
        const sk_schema *es = f->schema;
        bool bare = es->field_count == 1 && es->fields[0].key == NULL;
        for (int i = 0; i < n; i++) {
            const unsigned char *elem = ptr + (size_t)i * f->elem_size;
            snprintf(epath, sizeof epath, "%s[%d]", path, i);
            r = bare ? sk_schema_check_field(&es->fields[0], elem, epath, err)
                     : check_object(es, elem, epath, err);
            if (r != SK_OK) return r;
        }
        return SK_OK;
    }
    case SK_FIELD_SEED:
    case SK_FIELD_BOOL:
    case SK_FIELD_STRING:
        return SK_OK;
    }
    return SK_OK;
}

static sk_result check_object(const sk_schema *schema, const unsigned char *base, const char *path,
                              sk_error *err)
{
    for (int i = 0; i < schema->field_count; i++) {
        const sk_schema_field *f = &schema->fields[i];
        char kpath[PATH_SIZE];
        path_key(kpath, path, f->key);
        sk_result r = sk_schema_check_field(f, base, kpath, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

sk_result sk_schema_check(const sk_schema *schema, const void *desc, const char *path,
                          sk_error *err)
{
    return check_object(schema, desc, path ? path : "", err);
}
