/* Strict JSON text for the calibrated-potential files: the library's one JSON reader
 * (src/formats/json_strict.h: exactly one value, nothing after it, no key twice in an object, no
 * inexact integer), then limits of these files: no number that overflows to infinity,
 * at most 64 levels of nesting and 1024 keys in an object. */
#include <math.h>
#include <string.h>

#include "models/hand/potential_internal.h"
#include "formats/json_strict.h"
#include "formats/hand/hand_json_internal.h"

/* Depth-first check of every object and number below `item`. */
static sk_result check_tree(const cJSON *item, int depth, sk_error *err)
{
    if (depth > 64) return sk_fail(err, SK_ERROR_PARSE, "JSON nested deeper than 64 levels");
    if (cJSON_IsNumber(item) && !isfinite(item->valuedouble))
        return sk_fail(err, SK_ERROR_PARSE, "%s%sa number is too large",
                       item->string ? item->string : "", item->string ? ": " : "");
    int members = 0;
    for (const cJSON *c = item->child; c; c = c->next) {
        if (cJSON_IsObject(item) && ++members > 1024)
            return sk_fail(err, SK_ERROR_LIMIT, "an object with more than 1024 keys");
        sk_result r = check_tree(c, depth + 1, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

sk_result sk__hand_json_parse_strict(const char *text, size_t length, cJSON **out, sk_error *err)
{
    *out = NULL;
    cJSON *root = NULL;
    sk_result r = sk__json_parse(text, length, NULL, &root, err);
    if (r != SK_OK) return r;
    r = check_tree(root, 0, err);
    if (r != SK_OK) {
        cJSON_Delete(root);
        return r;
    }
    *out = root;
    return SK_OK;
}
