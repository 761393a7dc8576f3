/* Strict JSON reading for the hand's data files (constraint sets, anatomy, keyframes):
 * the library's one JSON reader (src/formats/json_strict.h: trailing text, repeated keys and
 * inexact integers refused), then unknown keys, wrong types and out-of-range numbers are
 * errors naming the key path. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "formats/json_strict.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

sk_result sk__hand_json_parse(const char *text, size_t length, const char *source_name, cJSON **out,
                              sk_error *err)
{
    /* the callers prefix errors with the source name */
    (void)source_name;
    return sk__json_parse(text, length, NULL, out, err);
}

sk_result sk__hand_json_check_keys(const cJSON *object, const char *path,
                                   const char *const *allowed, sk_error *err)
{
    for (const cJSON *item = object->child; item; item = item->next) {
        if (sk_preset_is_doc_key(item->string)) continue;
        bool known = false;
        for (int i = 0; allowed && allowed[i]; i++)
            if (strcmp(allowed[i], item->string) == 0) known = true;
        if (!known)
            return sk_fail(err, SK_ERROR_PARSE, "%s%s%s: unknown key", path, path[0] ? "." : "",
                           item->string);
    }
    return SK_OK;
}

sk_result sk__hand_json_number(const cJSON *object, const char *path, const char *key, double lo,
                               double hi, bool required, double *out, sk_error *err)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(object, key);
    const char *dot = path[0] ? "." : "";
    if (!item) {
        if (required) return sk_fail(err, SK_ERROR_PARSE, "%s%s%s: missing", path, dot, key);
        return SK_OK;
    }
    if (!cJSON_IsNumber(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s%s%s: expected a number", path, dot, key);
    double v = item->valuedouble;
    if (!isfinite(v))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s%s%s is not a finite number", path, dot,
                       key);
    if (v < lo || v > hi)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s%s%s = %g is out of range [%g, %g]", path,
                       dot, key, v, lo, hi);
    *out = v;
    return SK_OK;
}

sk_result sk__hand_json_string(const cJSON *object, const char *path, const char *key,
                               const char **out, sk_error *err)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(object, key);
    *out = NULL;
    if (!item) return SK_OK;
    if (!cJSON_IsString(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s%s%s: expected a string", path, path[0] ? "." : "",
                       key);
    *out = item->valuestring;
    return SK_OK;
}

sk_result sk__hand_json_expect_object(const cJSON *item, const char *path, sk_error *err)
{
    if (!cJSON_IsObject(item))
        return sk_fail(err, SK_ERROR_PARSE, "%s: expected an object",
                       path[0] ? path : "(top level)");
    return SK_OK;
}

sk_result sk__hand_dof_by_name(const char *name, const char *path, int *dof, sk_error *err)
{
    int d = sk_hand_dof_find(name);
    if (d < 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s: unknown DOF \"%s\" (names like \"L.MCP.flex\"; see docs/hand.md)", path,
                       name);
    *dof = d;
    return SK_OK;
}

sk_result sk__hand_write_text_file(const char *path, const char *text, sk_error *err)
{
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    size_t n = strlen(text);
    if (fwrite(text, 1, n, file.fp) != n) {
        return sk_atomic_file_write_failed(&file, err);
    }
    return sk_atomic_file_commit(&file, err);
}

sk_result sk__hand_parse_file(const char *path, sk__hand_parse_fn parse, void *ctx, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = parse(text, size, path, ctx, err);
    free(text);
    return r;
}

int sk__hand_finger_by_letter(const char *name)
{
    static const char letters[SK_HAND_FINGER_COUNT] = {'T', 'I', 'M', 'R', 'L'};
    for (int i = 0; i < SK_HAND_FINGER_COUNT; i++)
        if (name[0] == letters[i] && name[1] == '\0') return i;
    return -1;
}
