/* Strict JSON text for the calibrated-potential files: exactly one value, nothing after
 * it, no key twice in an object, no number that overflows to infinity. */
#include <math.h>
#include <string.h>

#include "hand/potential_private.h"

static int line_at(const char *text, const char *at)
{
    int line = 1;
    for (const char *c = text; c < at; c++) line += *c == '\n';
    return line;
}

/* Depth-first check of every object and number below `item`. */
static sk_result check_tree(const cJSON *item, int depth, sk_error *err)
{
    if (depth > 64) return sk_fail(err, SK_ERROR_PARSE, "JSON nested deeper than 64 levels");
    if (cJSON_IsNumber(item) && !isfinite(item->valuedouble))
        return sk_fail(err, SK_ERROR_PARSE, "%s%sa number is too large", item->string ? item->string : "",
                       item->string ? ": " : "");
    int members = 0;
    for (const cJSON *c = item->child; c; c = c->next) {
        if (cJSON_IsObject(item) && ++members > 1024)
            return sk_fail(err, SK_ERROR_LIMIT, "an object with more than 1024 keys");
        if (cJSON_IsObject(item))
            for (const cJSON *o = item->child; o != c; o = o->next)
                if (o->string && c->string && strcmp(o->string, c->string) == 0)
                    return sk_fail(err, SK_ERROR_PARSE, "key \"%.64s\" appears twice in one object", c->string);
        sk_result r = check_tree(c, depth + 1, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

sk_result sk_hand__json_parse_strict(const char *text, size_t length, cJSON **out, sk_error *err)
{
    *out = NULL;
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(text, length, &end, false);
    if (!root) {
        const char *stop = end && end >= text && end <= text + length ? end : text;
        return sk_fail(err, SK_ERROR_PARSE, "line %d: malformed JSON", line_at(text, stop));
    }
    const char *p = end ? end : text + length;
    while (p < text + length && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) p++;
    if (p < text + length) {
        cJSON_Delete(root);
        return sk_fail(err, SK_ERROR_PARSE, "line %d: text after the JSON value", line_at(text, p));
    }
    sk_result r = check_tree(root, 0, err);
    if (r != SK_OK) {
        cJSON_Delete(root);
        return r;
    }
    *out = root;
    return SK_OK;
}
