/* Presets: JSON parameter trees (cJSON), loading with line/column errors, and "--set
 * key.path=value" edits applied before the tree is bound to a desc. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "formats/json_strict.h"
#include "formats/preset_tree.h"
#include "shitsukan/io.h"

#define PRESET_MAX_FILE_BYTES ((size_t)16 << 20)

bool sk_preset_is_doc_key(const char *key)
{
    return strcmp(key, "description") == 0 || strcmp(key, "source") == 0 ||
           strcmp(key, "notes") == 0 || strcmp(key, "figure") == 0;
}

sk_result sk_preset_create(sk_preset **out, sk_error *err)
{
    *out = NULL;
    sk_preset *p = calloc(1, sizeof *p);
    if (!p) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    p->root = cJSON_CreateObject();
    if (!p->root) {
        free(p);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    *out = p;
    return SK_OK;
}

void sk_preset_free(sk_preset *preset)
{
    if (!preset) return;
    cJSON_Delete(preset->root);
    free(preset);
}

sk_result sk_preset_parse(sk_preset **out, const char *text, size_t length, const char *source_name,
                          sk_error *err)
{
    *out = NULL;
    const char *name = source_name ? source_name : "preset";
    cJSON *root = NULL;
    sk_result r = sk__json_parse(text, length, name, &root, err);
    if (r != SK_OK) return r;
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return sk_fail(err, SK_ERROR_PARSE, "%s: the top level must be a JSON object", name);
    }
    sk_preset *p = calloc(1, sizeof *p);
    if (!p) {
        cJSON_Delete(root);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    p->root = root;
    *out = p;
    return SK_OK;
}

sk_result sk_preset_load_file(sk_preset **out, const char *path, sk_error *err)
{
    *out = NULL;
    char *text;
    size_t size;
    sk_result r = sk_read_file(path, PRESET_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_preset_parse(out, text, size, path, err);
    free(text);
    return r;
}

const char *sk_preset_get_string(const sk_preset *preset, const char *key)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(preset->root, key);
    return cJSON_IsString(item) ? item->valuestring : NULL;
}

/* ------------------------------------------------------------- --set edits */

/* One step of a key path: an object key or an array index. */
typedef struct path_step {
    bool is_index;
    long index;
    char key[128];
} path_step;

#define MAX_PATH_STEPS 32

static sk_result parse_path(const char *path, size_t len, path_step *steps, int *count,
                            sk_error *err)
{
    *count = 0;
    size_t i = 0;
    bool expect_key = true;
    while (i < len) {
        if (*count == MAX_PATH_STEPS)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "--set: key path '%.*s' is too deep",
                           (int)len, path);
        path_step *s = &steps[*count];
        memset(s, 0, sizeof *s);
        if (path[i] == '[') {
            char *endp;
            errno = 0;
            long idx = strtol(path + i + 1, &endp, 10);
            if (endp == path + i + 1 || *endp != ']' || idx < 0 || errno)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "--set: bad array index in key path '%.*s'", (int)len, path);
            s->is_index = true;
            s->index = idx;
            i = (size_t)(endp - path) + 1;
            expect_key = false;
        } else {
            if (!expect_key) {
                if (path[i] != '.')
                    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                                   "--set: expected '.' or '[' in key path '%.*s'", (int)len, path);
                i++;
            }
            size_t start = i;
            while (i < len && path[i] != '.' && path[i] != '[') i++;
            size_t klen = i - start;
            if (klen == 0 || klen >= sizeof s->key)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "--set: empty or too long key in key path '%.*s'", (int)len, path);
            memcpy(s->key, path + start, klen);
            s->key[klen] = '\0';
            expect_key = false;
        }
        (*count)++;
    }
    if (*count == 0 || steps[0].is_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "--set: key path must start with a key");
    return SK_OK;
}

/* "nan", "inf", "-Infinity", ...: not JSON, but parsed as numbers so that the binder
   names the key in its "not a finite number" error. */
static bool is_non_finite_word(const char *text)
{
    static const char *const words[] = {"nan", "inf", "infinity", NULL};
    const char *t = (text[0] == '-' || text[0] == '+') ? text + 1 : text;
    for (int i = 0; words[i]; i++)
        if (strcasecmp(t, words[i]) == 0) return true;
    return false;
}

/* Parses the value of an assignment: the whole text as JSON (a number, true/false, null,
 * array, object or quoted string), else a non-finite number word, else a plain string
 * (so "5junk" or "0x10" reach the binder as strings, which names the key and the type it
 * expects). JSON that is refused (an inexact integer, a repeated key) is an error. */
static sk_result parse_value(const char *assignment, const char *text, cJSON **out, sk_error *err)
{
    sk_error parse_err = {0};
    sk_result r = sk__json_parse(text, strlen(text), "", out, &parse_err);
    if (r == SK_OK) return SK_OK;
    if (r != SK_ERROR_PARSE) {
        return sk_fail(err, r, "--set '%s': %s", assignment, parse_err.message);
    }
    *out = is_non_finite_word(text) ? cJSON_CreateNumber(strtod(text, NULL))
                                    : cJSON_CreateString(text);
    if (!*out) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    return SK_OK;
}

sk_result sk_preset_set(sk_preset *preset, const char *assignment, sk_error *err)
{
    const char *eq = strchr(assignment, '=');
    if (!eq)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "--set '%s': expected key.path=value",
                       assignment);
    path_step steps[MAX_PATH_STEPS];
    int count;
    sk_result r = parse_path(assignment, (size_t)(eq - assignment), steps, &count, err);
    if (r != SK_OK) return r;
    cJSON *value = NULL;
    r = parse_value(assignment, eq + 1, &value, err);
    if (r != SK_OK) return r;
    bool remove = cJSON_IsNull(value);

    cJSON *node = preset->root;
    for (int k = 0; k < count; k++) {
        const path_step *s = &steps[k];
        bool last = k == count - 1;
        if (s->is_index) {
            if (!cJSON_IsArray(node)) {
                cJSON_Delete(value);
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "--set '%.*s': [%ld] indexes a value that is not an array",
                               (int)(eq - assignment), assignment, s->index);
            }
            long size = cJSON_GetArraySize(node);
            if (s->index > size || (remove && s->index >= size)) {
                cJSON_Delete(value);
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "--set '%.*s': index %ld is out of range [0, %ld]",
                               (int)(eq - assignment), assignment, s->index, size);
            }
            if (last) {
                if (remove) {
                    cJSON_DeleteItemFromArray(node, (int)s->index);
                    cJSON_Delete(value);
                } else if (s->index == size) {
                    cJSON_AddItemToArray(node, value);
                } else {
                    cJSON_ReplaceItemInArray(node, (int)s->index, value);
                }
                return SK_OK;
            }
            if (s->index == size) {
                cJSON *child = steps[k + 1].is_index ? cJSON_CreateArray() : cJSON_CreateObject();
                cJSON_AddItemToArray(node, child);
            }
            node = cJSON_GetArrayItem(node, (int)s->index);
        } else {
            if (!cJSON_IsObject(node)) {
                cJSON_Delete(value);
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "--set '%.*s': '%s' is inside a value that is not an object",
                               (int)(eq - assignment), assignment, s->key);
            }
            cJSON *child = cJSON_GetObjectItemCaseSensitive(node, s->key);
            if (last) {
                if (remove) {
                    cJSON_DeleteItemFromObjectCaseSensitive(node, s->key);
                    cJSON_Delete(value);
                } else if (child) {
                    cJSON_ReplaceItemInObjectCaseSensitive(node, s->key, value);
                } else {
                    cJSON_AddItemToObject(node, s->key, value);
                }
                return SK_OK;
            }
            if (!child) {
                child = steps[k + 1].is_index ? cJSON_CreateArray() : cJSON_CreateObject();
                cJSON_AddItemToObject(node, s->key, child);
            }
            node = child;
        }
    }
    cJSON_Delete(value);
    return SK_OK;
}
