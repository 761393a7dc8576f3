/* Strict JSON reading (see json_strict.h): cJSON parses, then the whole text must have
 * been one value, no object may repeat a key and no integer literal may lose digits. */
#include "formats/json_strict.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KEY_PATH_SIZE 256

/* Line and column (1-based) of byte `offset`. */
static void line_col(const char *text, size_t offset, int *line, int *col)
{
    *line = 1;
    *col = 1;
    for (size_t i = 0; i < offset; i++) {
        if (text[i] == '\n') {
            (*line)++;
            *col = 1;
        } else {
            (*col)++;
        }
    }
}

static sk_result fail_at(sk_error *err, sk_result result, const char *text, size_t offset,
                         const char *source_name, const char *fmt, ...)
{
    char what[SK_ERROR_MESSAGE_SIZE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    int line, col;
    line_col(text, offset, &line, &col);
    if (source_name && !source_name[0]) return sk_fail(err, result, "%s", what);
    if (source_name) return sk_fail(err, result, "%s:%d:%d: %s", source_name, line, col, what);
    return sk_fail(err, result, "line %d: %s (column %d)", line, what, col);
}

/* The first integer literal (outside strings) beyond 2^53, or NULL; its length in *len. */
static const char *find_inexact_integer(const char *text, size_t length, size_t *len)
{
    static const char k_max[] = "9007199254740992"; /* 2^53, 16 digits */
    bool in_string = false;
    for (size_t i = 0; i < length; i++) {
        char c = text[i];
        if (in_string) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
            continue;
        }
        if (c != '-' && !(c >= '0' && c <= '9')) continue;
        size_t start = i, digits_start = c == '-' ? i + 1 : i, end = digits_start;
        while (end < length && text[end] >= '0' && text[end] <= '9') end++;
        bool fraction = end < length && (text[end] == '.' || text[end] == 'e' || text[end] == 'E');
        size_t digits = end - digits_start;
        /* skip the rest of the token (fraction, exponent) */
        size_t stop = end;
        while (stop < length && (isalnum((unsigned char)text[stop]) || text[stop] == '.' ||
                                 text[stop] == '+' || text[stop] == '-'))
            stop++;
        if (!fraction &&
            (digits > 16 || (digits == 16 && memcmp(text + digits_start, k_max, 16) > 0))) {
            *len = end - start;
            return text + start;
        }
        i = stop - 1;
    }
    return NULL;
}

static int compare_keys(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Finds a key given twice anywhere in the tree; writes its key path. */
static bool find_duplicate_key(const cJSON *item, const char *path, char *found)
{
    if (cJSON_IsObject(item)) {
        int n = cJSON_GetArraySize(item);
        if (n > 1) {
            const char **keys = malloc(sizeof *keys * (size_t)n);
            if (keys) {
                int k = 0;
                for (const cJSON *c = item->child; c; c = c->next) keys[k++] = c->string;
                qsort(keys, (size_t)n, sizeof *keys, compare_keys);
                for (int i = 1; i < n; i++)
                    if (strcmp(keys[i - 1], keys[i]) == 0) {
                        snprintf(found, KEY_PATH_SIZE, "%s%s%s", path, path[0] ? "." : "", keys[i]);
                        free(keys);
                        return true;
                    }
                free(keys);
            } else {
                /* without memory for the sort, the quadratic check */
                for (const cJSON *a = item->child; a; a = a->next)
                    for (const cJSON *b = a->next; b; b = b->next)
                        if (strcmp(a->string, b->string) == 0) {
                            snprintf(found, KEY_PATH_SIZE, "%s%s%s", path, path[0] ? "." : "",
                                     a->string);
                            return true;
                        }
            }
        }
        for (const cJSON *c = item->child; c; c = c->next) {
            char child[KEY_PATH_SIZE];
            snprintf(child, sizeof child, "%s%s%s", path, path[0] ? "." : "", c->string);
            if (find_duplicate_key(c, child, found)) return true;
        }
    } else if (cJSON_IsArray(item)) {
        int i = 0;
        for (const cJSON *c = item->child; c; c = c->next, i++) {
            char child[KEY_PATH_SIZE];
            snprintf(child, sizeof child, "%s[%d]", path, i);
            if (find_duplicate_key(c, child, found)) return true;
        }
    }
    return false;
}

sk_result sk__json_parse(const char *text, size_t length, const char *source_name, cJSON **out,
                         sk_error *err)
{
    *out = NULL;
    const char *nul = memchr(text, '\0', length);
    if (nul)
        return fail_at(err, SK_ERROR_PARSE, text, (size_t)(nul - text), source_name,
                       "contains a NUL byte");
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(text, length, &end, false);
    if (!root) {
        size_t offset = end && end >= text && end <= text + length ? (size_t)(end - text) : 0;
        return fail_at(err, SK_ERROR_PARSE, text, offset, source_name, "malformed JSON");
    }
    for (const char *c = end; c && c < text + length; c++)
        if (!isspace((unsigned char)*c)) {
            cJSON_Delete(root);
            return fail_at(err, SK_ERROR_PARSE, text, (size_t)(c - text), source_name,
                           "unexpected text after the JSON value");
        }
    size_t len = 0;
    const char *big = find_inexact_integer(text, length, &len);
    if (big) {
        cJSON_Delete(root);
        return fail_at(err, SK_ERROR_INVALID_ARGUMENT, text, (size_t)(big - text), source_name,
                       "integer %.*s is beyond 2^53 = 9007199254740992 and cannot be held "
                       "exactly",
                       (int)(len > 40 ? 40 : len), big);
    }
    char path[KEY_PATH_SIZE];
    if (find_duplicate_key(root, "", path)) {
        cJSON_Delete(root);
        /* as the binder's errors: the key path alone */
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: key given twice", path);
    }
    *out = root;
    return SK_OK;
}
