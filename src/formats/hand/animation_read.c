/* Keyframed animations from JSON: per-DOF keys with their interpolation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

static sk_result parse_values(const cJSON *obj, const char *path, bool file_units, bool *has,
                              double *val, sk_error *err)
{
    sk_result r = sk__hand_json_expect_object(obj, path, err);
    for (const cJSON *t = obj->child; r == SK_OK && t; t = t->next) {
        char tpath[200];
        snprintf(tpath, sizeof tpath, "%s.%s", path, t->string);
        int d;
        r = sk__hand_dof_by_name(t->string, tpath, &d, err);
        if (r != SK_OK) break;
        if (!cJSON_IsNumber(t) || !isfinite(t->valuedouble) || fabs(t->valuedouble) > 1e6)
            return sk_fail(err, SK_ERROR_PARSE, "%s: expected a finite number", tpath);
        has[d] = true;
        val[d] = file_units ? sk__hand_from_file_units(d, t->valuedouble) : t->valuedouble;
    }
    return r;
}

static sk_result parse_animation(const cJSON *root, sk_hand_animation *a, sk_error *err)
{
    static const char *const keys[] = {
        "constraints", "side", "hand_length_mm", "hand_breadth_mm", "interpolation", "steps", "fps",
        "keys",        NULL};
    sk_result r = sk__hand_json_expect_object(root, "", err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, "", keys, err);
    const char *constraints = NULL, *side = NULL, *interp = NULL;
    if (r == SK_OK) r = sk__hand_json_string(root, "", "constraints", &constraints, err);
    if (r == SK_OK) r = sk__hand_json_string(root, "", "side", &side, err);
    if (r == SK_OK) r = sk__hand_json_string(root, "", "interpolation", &interp, err);
    double steps = 30, fps = 30;
    if (r == SK_OK) r = sk__hand_json_number(root, "", "steps", 1, 10000, false, &steps, err);
    if (r == SK_OK) r = sk__hand_json_number(root, "", "fps", 1, 1000, false, &fps, err);
    if (r == SK_OK)
        r = sk__hand_json_number(root, "", "hand_length_mm", 60, 400, false, &a->hand_length_mm,
                                 err);
    if (r == SK_OK)
        r = sk__hand_json_number(root, "", "hand_breadth_mm", 30, 200, false, &a->hand_breadth_mm,
                                 err);
    if (r != SK_OK) return r;
    if (steps != floor(steps))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "steps = %g is not an integer", steps);
    a->steps = (int)steps;
    a->fps = fps;
    snprintf(a->constraints, sizeof a->constraints, "%s", constraints ? constraints : "natural");
    if (constraints && strlen(constraints) >= sizeof a->constraints)
        return sk_fail(err, SK_ERROR_LIMIT, "constraints: longer than %zu characters",
                       sizeof a->constraints - 1);
    a->side = SK_HAND_SIDE_RIGHT;
    if (side && strcmp(side, "left") == 0)
        a->side = SK_HAND_SIDE_LEFT;
    else if (side && strcmp(side, "right") != 0)
        return sk_fail(err, SK_ERROR_PARSE, "side = \"%s\": expected \"right\" or \"left\"", side);
    a->interp = SK_HAND_INTERP_BEZIER;
    if (interp && strcmp(interp, "catmull-rom") == 0)
        a->interp = SK_HAND_INTERP_CATMULL_ROM;
    else if (interp && strcmp(interp, "bezier") != 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "interpolation = \"%s\": expected \"bezier\" or \"catmull-rom\"", interp);
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(root, "keys");
    if (!list || !cJSON_IsArray(list))
        return sk_fail(err, SK_ERROR_PARSE, "keys: expected an array of keys");
    int k = 0;
    for (const cJSON *item = list->child; item; item = item->next, k++) {
        char path[64];
        snprintf(path, sizeof path, "keys[%d]", k);
        if (k >= SK_HAND_MAX_KEYS)
            return sk_fail(err, SK_ERROR_LIMIT, "%s: more than %d keys", path, SK_HAND_MAX_KEYS);
        static const char *const kkeys[] = {"pin", "torque", NULL};
        r = sk__hand_json_expect_object(item, path, err);
        if (r == SK_OK) r = sk__hand_json_check_keys(item, path, kkeys, err);
        if (r != SK_OK) return r;
        sk_hand_key *key = &a->keys[k];
        const cJSON *pin = cJSON_GetObjectItemCaseSensitive(item, "pin");
        const cJSON *torque = cJSON_GetObjectItemCaseSensitive(item, "torque");
        char sub[96];
        if (pin) {
            snprintf(sub, sizeof sub, "%s.pin", path);
            r = parse_values(pin, sub, true, key->has_pin, key->pin, err);
        }
        if (r == SK_OK && torque) {
            snprintf(sub, sizeof sub, "%s.torque", path);
            r = parse_values(torque, sub, false, key->has_torque, key->torque, err);
        }
        if (r != SK_OK) return r;
    }
    if (k < 1) return sk_fail(err, SK_ERROR_PARSE, "keys: at least one key is needed");
    a->key_count = k;
    if ((long long)(k - 1) * a->steps + 1 > 1000000)
        return sk_fail(err, SK_ERROR_LIMIT, "(keys - 1) x steps = %lld frames is more than 1000000",
                       (long long)(k - 1) * a->steps);
    return SK_OK;
}

sk_result sk_hand_animation_parse(const char *text, size_t length, const char *name,
                                  sk_hand_animation *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse(text, length, name, &root, err);
    if (r == SK_OK) {
        r = parse_animation(root, out, err);
        cJSON_Delete(root);
    }
    if (r != SK_OK) sk_error_prefix(err, r, "%s", name);
    return r;
}

sk_result sk_hand_animation_load_file(const char *path, sk_hand_animation *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_hand_animation_parse(text, size, path, out, err);
    free(text);
    return r;
}
