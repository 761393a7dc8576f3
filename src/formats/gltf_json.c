/* Checked access to the glTF JSON tree for the reader: members of the expected type and
 * range, or an SK_ERROR_PARSE naming the JSON path ("accessors[3].count: ..."). */
#include <math.h>
#include <stdio.h>

#include "formats/gltf_doc_internal.h"

const cJSON *sk__json_member(const cJSON *obj, const char *key)
{
    return cJSON_GetObjectItemCaseSensitive(obj, key);
}

int sk__json_count(const cJSON *array)
{
    int n = 0;
    const cJSON *item;
    cJSON_ArrayForEach(item, array) n++;
    return n;
}

static sk_result missing(const char *where, const char *key, sk_error *err)
{
    return sk_fail(err, SK_ERROR_PARSE, "%s.%s: required property is missing", where, key);
}

sk_result sk__json_int(const cJSON *obj, const char *where, const char *key, bool required,
                       long long lo, long long hi, long long def, long long *out, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    if (!item) {
        *out = def;
        return required ? missing(where, key, err) : SK_OK;
    }
    double v = item->valuedouble;
    if (!cJSON_IsNumber(item) || !isfinite(v) || v != floor(v))
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be an integer", where, key);
    if (v < (double)lo || v > (double)hi)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s = %.17g is out of range [%lld, %lld]", where,
                       key, v, lo, hi);
    *out = (long long)v;
    return SK_OK;
}

sk_result sk__json_index_item(const cJSON *item, const char *where, const char *key, int count,
                              const char *array, int *out, sk_error *err)
{
    double v = item->valuedouble;
    *out = -1;
    if (!cJSON_IsNumber(item) || !isfinite(v) || v != floor(v) || v < 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be an index (an integer >= 0)", where,
                       key);
    if (v >= (double)count)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s = %.17g is not an index of %s (%d of them)",
                       where, key, v, array, count);
    *out = (int)v;
    return SK_OK;
}

sk_result sk__json_index(const cJSON *obj, const char *where, const char *key, bool required,
                         int count, const char *array, int *out, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    *out = -1;
    if (!item) return required ? missing(where, key, err) : SK_OK;
    return sk__json_index_item(item, where, key, count, array, out, err);
}

sk_result sk__json_array(const cJSON *obj, const char *where, const char *key, bool required,
                         int min_items, const cJSON **out, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    *out = NULL;
    if (!item) return required ? missing(where, key, err) : SK_OK;
    if (!cJSON_IsArray(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be an array", where, key);
    if (min_items > 0) {
        int n = 0;
        const cJSON *e;
        cJSON_ArrayForEach(e, item) if (++n >= min_items) break;
        if (n < min_items)
            return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must have at least %d item%s", where, key,
                           min_items, min_items == 1 ? "" : "s");
    }
    *out = item;
    return SK_OK;
}

sk_result sk__json_object(const cJSON *obj, const char *where, const char *key, bool required,
                          const cJSON **out, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    *out = NULL;
    if (!item) return required ? missing(where, key, err) : SK_OK;
    if (!cJSON_IsObject(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be an object", where, key);
    *out = item;
    return SK_OK;
}

sk_result sk__json_string(const cJSON *obj, const char *where, const char *key, bool required,
                          const char **out, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    *out = NULL;
    if (!item) return required ? missing(where, key, err) : SK_OK;
    if (!cJSON_IsString(item) || !item->valuestring)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be a string", where, key);
    *out = item->valuestring;
    return SK_OK;
}

sk_result sk__json_numbers(const cJSON *obj, const char *where, const char *key, int n, double *out,
                           bool *found, sk_error *err)
{
    const cJSON *item = sk__json_member(obj, key);
    *found = false;
    if (!item) return SK_OK;
    if (!cJSON_IsArray(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must be an array", where, key);
    if (sk__json_count(item) != n)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: must have exactly %d numbers", where, key, n);
    int k = 0;
    const cJSON *e;
    cJSON_ArrayForEach(e, item)
    {
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble))
            return sk_fail(err, SK_ERROR_PARSE, "%s.%s[%d]: must be a finite number", where, key,
                           k);
        out[k++] = e->valuedouble;
    }
    *found = true;
    return SK_OK;
}

sk_result sk__json_indices(const cJSON *obj, const char *where, const char *key, int count,
                           const char *array, int *out, int *n, sk_error *err)
{
    const cJSON *list, *item;
    sk_result r = sk__json_array(obj, where, key, false, 0, &list, err);
    *n = 0;
    if (r != SK_OK) return r;
    cJSON_ArrayForEach(item, list)
    {
        char at[48];
        int index;
        snprintf(at, sizeof at, "%s[%d]", key, *n);
        if ((r = sk__json_index_item(item, where, at, count, array, &index, err)) != SK_OK)
            return r;
        if (out) out[*n] = index;
        ++*n;
    }
    return SK_OK;
}
