/* Constraint sets from JSON: named DOF pairs and rows of coefficients (thesis sec. 3.3). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "models/hand/potential_internal.h"
#include "models/hand/solver_internal.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

/* "X:Y" -> two DOF indices. */
static sk_result parse_pair_name(const char *text, const char *path, int *x, int *y, sk_error *err)
{
    const char *colon = strchr(text, ':');
    if (!colon || strchr(colon + 1, ':'))
        return sk_fail(err, SK_ERROR_PARSE, "%s = \"%s\": expected \"DOF:DOF\"", path, text);
    char left[64];
    size_t n = (size_t)(colon - text);
    if (n >= sizeof left) n = sizeof left - 1;
    memcpy(left, text, n);
    left[n] = '\0';
    sk_result r = sk__hand_dof_by_name(left, path, x, err);
    if (r == SK_OK) r = sk__hand_dof_by_name(colon + 1, path, y, err);
    if (r == SK_OK && *x == *y)
        r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: a pair needs two different DOFs", path);
    return r;
}

static sk_result parse_row(const cJSON *item, const char *path, const sk_hand_skeleton *s,
                           bool absolute, double b_scale, sk_hand_constraints *c, sk_error *err)
{
    static const char *const keys[] = {"pair", "terms", "A", "b", "W", "printed", "label", NULL};
    sk_result r = sk__hand_json_expect_object(item, path, err);
    if (r == SK_OK) r = sk__hand_json_check_keys(item, path, keys, err);
    const char *pair = NULL, *label = NULL, *printed = NULL;
    if (r == SK_OK) r = sk__hand_json_string(item, path, "pair", &pair, err);
    if (r == SK_OK) r = sk__hand_json_string(item, path, "label", &label, err);
    if (r == SK_OK) r = sk__hand_json_string(item, path, "printed", &printed, err);
    double b = 0.0, w = 0.0;
    if (r == SK_OK) r = sk__hand_json_number(item, path, "b", -1e6, 1e6, false, &b, err);
    if (r == SK_OK) r = sk__hand_json_number(item, path, "W", -1e9, 1e9, true, &w, err);
    if (r != SK_OK) return r;
    const cJSON *terms = cJSON_GetObjectItemCaseSensitive(item, "terms");
    char wpath[160];
    snprintf(wpath, sizeof wpath, "%s", path);
    if (w == 0.0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s.W = 0: a weight must be non-zero", path);
    if ((pair != NULL) == (terms != NULL))
        return sk_fail(err, SK_ERROR_PARSE, "%s: give either \"pair\" (with \"A\") or \"terms\"",
                       path);
    int dof[SK_HAND_ROW_MAX_TERMS];
    double coeff[SK_HAND_ROW_MAX_TERMS];
    int n = 0;
    char ppath[200];
    if (pair) {
        snprintf(ppath, sizeof ppath, "%s.pair", path);
        double a = 0.0;
        r = parse_pair_name(pair, ppath, &dof[0], &dof[1], err);
        if (r == SK_OK) r = sk__hand_json_number(item, path, "A", -1e6, 1e6, true, &a, err);
        if (r != SK_OK) return r;
        /* "X:Y" with A, b reads y = A x + b, i.e. the row A x - y + b = 0 */
        coeff[0] = a;
        coeff[1] = -1.0;
        n = 2;
    } else {
        if (cJSON_GetObjectItemCaseSensitive(item, "A"))
            return sk_fail(err, SK_ERROR_PARSE, "%s.A: only rows with \"pair\" take A", path);
        snprintf(ppath, sizeof ppath, "%s.terms", path);
        r = sk__hand_json_expect_object(terms, ppath, err);
        if (r != SK_OK) return r;
        for (const cJSON *t = terms->child; t; t = t->next) {
            char tpath[260];
            snprintf(tpath, sizeof tpath, "%s.%s", ppath, t->string);
            if (n >= SK_HAND_ROW_MAX_TERMS)
                return sk_fail(err, SK_ERROR_LIMIT, "%s: more than %d terms", ppath,
                               SK_HAND_ROW_MAX_TERMS);
            r = sk__hand_dof_by_name(t->string, tpath, &dof[n], err);
            if (r != SK_OK) return r;
            if (!cJSON_IsNumber(t) || !isfinite(t->valuedouble))
                return sk_fail(err, SK_ERROR_PARSE, "%s: expected a number", tpath);
            coeff[n++] = t->valuedouble;
        }
        if (n == 0) return sk_fail(err, SK_ERROR_PARSE, "%s: no terms", ppath);
    }
    char rowlabel[64];
    if (label)
        snprintf(rowlabel, sizeof rowlabel, "%s", label);
    else if (pair)
        snprintf(rowlabel, sizeof rowlabel, "%s", pair);
    else
        snprintf(rowlabel, sizeof rowlabel, "%s", path);
    return sk__hand_constraints_add_row(c, s, dof, coeff, n, b * b_scale, w, absolute, rowlabel,
                                        wpath, err);
}

sk_result sk__hand_constraints_from_json(const cJSON *root, const char *at,
                                         const sk_hand_skeleton *s, const char *const *extra,
                                         sk_hand_constraints *out, sk_error *err)
{
    const char *keys[24] = {"reading", "angles", "b_unit", "stiffness", "rows"};
    for (int i = 0, n = 5; extra && extra[i] && n < 23; i++) keys[n++] = extra[i];
    sk_result r = sk__hand_json_expect_object(root, at, err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, at, keys, err);
    const char *angles = NULL, *b_unit = NULL, *reading = NULL;
    if (r == SK_OK) r = sk__hand_json_string(root, "", "angles", &angles, err);
    if (r == SK_OK) r = sk__hand_json_string(root, "", "b_unit", &b_unit, err);
    if (r == SK_OK) r = sk__hand_json_string(root, "", "reading", &reading, err);
    if (r != SK_OK) return r;
    bool absolute = false;
    if (angles && strcmp(angles, "absolute") == 0)
        absolute = true;
    else if (angles && strcmp(angles, "displacement") != 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "angles = \"%s\": expected \"displacement\" or \"absolute\"", angles);
    double b_scale = SK_DEG_TO_RAD;
    if (b_unit && strcmp(b_unit, "rad") == 0)
        b_scale = 1.0;
    else if (b_unit && strcmp(b_unit, "deg") != 0)
        return sk_fail(err, SK_ERROR_PARSE, "b_unit = \"%s\": expected \"deg\" or \"rad\"", b_unit);

    const cJSON *stiff = cJSON_GetObjectItemCaseSensitive(root, "stiffness");
    if (stiff) {
        r = sk__hand_json_expect_object(stiff, "stiffness", err);
        for (const cJSON *t = stiff->child; r == SK_OK && t; t = t->next) {
            if (sk_preset_is_doc_key(t->string)) continue;
            char path[96];
            snprintf(path, sizeof path, "stiffness.%s", t->string);
            int d;
            r = sk__hand_dof_by_name(t->string, path, &d, err);
            if (r != SK_OK) break;
            if (!cJSON_IsNumber(t) || !isfinite(t->valuedouble))
                return sk_fail(err, SK_ERROR_PARSE, "%s: expected a number", path);
            if (!(t->valuedouble > 0.0))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "%s = %g: stiffness must be positive", path, t->valuedouble);
            out->has_stiffness[d] = true;
            out->stiffness[d] = t->valuedouble;
        }
        if (r != SK_OK) return r;
    }
    const cJSON *rows = cJSON_GetObjectItemCaseSensitive(root, "rows");
    if (!rows) return sk_fail(err, SK_ERROR_PARSE, "rows: missing");
    if (!cJSON_IsArray(rows)) return sk_fail(err, SK_ERROR_PARSE, "rows: expected an array");
    int i = 0;
    for (const cJSON *item = rows->child; item; item = item->next, i++) {
        char path[64];
        snprintf(path, sizeof path, "rows[%d]", i);
        r = parse_row(item, path, s, absolute, b_scale, out, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

sk_result sk_hand_constraints_parse(const char *text, size_t length, const char *source_name,
                                    const sk_hand_skeleton *s, sk_hand_constraints *out,
                                    sk_error *err)
{
    memset(out, 0, sizeof *out);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse(text, length, source_name, &root, err);
    if (r == SK_OK) {
        r = sk__hand_constraints_from_json(root, "", s, NULL, out, err);
        cJSON_Delete(root);
    }
    /* K + A'WA must be positive definite (negative weights may break it) */
    if (r == SK_OK) r = sk__hand_check_positive_definite(s, out, err);
    if (r != SK_OK) {
        sk_error_prefix(err, r, "%s", source_name);
        memset(out, 0, sizeof *out);
    }
    return r;
}

sk_result sk_hand_constraints_load_file(const char *path, const sk_hand_skeleton *s,
                                        sk_hand_constraints *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_hand_constraints_parse(text, size, path, s, out, err);
    free(text);
    return r;
}
