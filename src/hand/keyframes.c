/* Keyframe animation, thesis 4.2.2-4.2.3: partial inputs (pinned angles, torques) at
 * keys, interpolated frame by frame by cubic Bezier curves (or Catmull-Rom), the
 * equilibrium solved at every frame by the caller. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

double sk_hand_interpolate(sk_hand_interp interp, double p0, double p1, double p2, double p3,
                           double t)
{
    if (interp == SK_HAND_INTERP_CATMULL_ROM) {
        double t2 = t * t, t3 = t2 * t;
        return 0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 +
                      (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3);
    }
    /* cubic Bezier with control values (p1, p1, p2, p2) over a linear time axis (time
       handles at 1/3 and 2/3): B(t) = p1 + (p2 - p1)(3t^2 - 2t^3), at rest at each key */
    return p1 + (p2 - p1) * t * t * (3.0 - 2.0 * t);
}

int sk_hand_animation_frame_count(const sk_hand_animation *a)
{
    return a->key_count < 2 ? a->key_count : (a->key_count - 1) * a->steps + 1;
}

/* Value of one channel (the keys where `has` is set) at key position u. */
static double channel_value(const sk_hand_animation *a, const bool *has, const double *val,
                            size_t stride, double u)
{
    int idx[SK_HAND_MAX_KEYS], n = 0;
    for (int k = 0; k < a->key_count; k++)
        if (*(const bool *)((const char *)has + k * stride)) idx[n++] = k;
#define VAL(k) (*(const double *)((const char *)val + (size_t)(k)*stride))
    if (u <= idx[0]) return VAL(idx[0]);
    if (u >= idx[n - 1]) return VAL(idx[n - 1]);
    int s = 0;
    while (s + 1 < n - 1 && idx[s + 1] <= u) s++;
    double t = (u - idx[s]) / (double)(idx[s + 1] - idx[s]);
    double p1 = VAL(idx[s]), p2 = VAL(idx[s + 1]);
    double p0 = s > 0 ? VAL(idx[s - 1]) : p1;
    double p3 = s + 2 < n ? VAL(idx[s + 2]) : p2;
#undef VAL
    return sk_hand_interpolate(a->interp, p0, p1, p2, p3, t);
}

void sk_hand_animation_input(const sk_hand_animation *a, int frame, sk_hand_input *out)
{
    memset(out, 0, sizeof *out);
    if (a->key_count == 0) return;
    double u = a->key_count < 2 ? 0.0 : (double)frame / a->steps;
    const size_t stride = sizeof(sk_hand_key);
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        bool any_pin = false, any_torque = false;
        for (int k = 0; k < a->key_count; k++) {
            any_pin |= a->keys[k].has_pin[d];
            any_torque |= a->keys[k].has_torque[d];
        }
        if (any_pin) {
            out->pinned[d] = true;
            out->pin_value[d] =
                channel_value(a, &a->keys[0].has_pin[d], &a->keys[0].pin[d], stride, u);
        }
        if (any_torque)
            out->torque[d] =
                channel_value(a, &a->keys[0].has_torque[d], &a->keys[0].torque[d], stride, u);
    }
}

void sk_hand_animation_driven(const sk_hand_animation *a, bool driven[SK_HAND_DOF_COUNT])
{
    for (int d = 0; d < SK_HAND_DOF_COUNT; d++) {
        driven[d] = false;
        for (int k = 0; k < a->key_count; k++)
            driven[d] |=
                a->keys[k].has_pin[d] || (a->keys[k].has_torque[d] && a->keys[k].torque[d] != 0.0);
    }
}

static sk_result parse_values(const cJSON *obj, const char *path, bool file_units, bool *has,
                              double *val, sk_error *err)
{
    sk_result r = sk_hand__json_expect_object(obj, path, err);
    for (const cJSON *t = obj->child; r == SK_OK && t; t = t->next) {
        char tpath[200];
        snprintf(tpath, sizeof tpath, "%s.%s", path, t->string);
        int d;
        r = sk_hand__dof_by_name(t->string, tpath, &d, err);
        if (r != SK_OK) break;
        if (!cJSON_IsNumber(t) || !isfinite(t->valuedouble) || fabs(t->valuedouble) > 1e6)
            return sk_fail(err, SK_ERROR_PARSE, "%s: expected a finite number", tpath);
        has[d] = true;
        val[d] = file_units ? sk_hand__from_file_units(d, t->valuedouble) : t->valuedouble;
    }
    return r;
}

static sk_result parse_animation(const cJSON *root, sk_hand_animation *a, sk_error *err)
{
    static const char *const keys[] = {
        "constraints", "side", "hand_length_mm", "hand_breadth_mm", "interpolation", "steps", "fps",
        "keys",        NULL};
    sk_result r = sk_hand__json_expect_object(root, "", err);
    if (r == SK_OK) r = sk_hand__json_check_keys(root, "", keys, err);
    const char *constraints = NULL, *side = NULL, *interp = NULL;
    if (r == SK_OK) r = sk_hand__json_string(root, "", "constraints", &constraints, err);
    if (r == SK_OK) r = sk_hand__json_string(root, "", "side", &side, err);
    if (r == SK_OK) r = sk_hand__json_string(root, "", "interpolation", &interp, err);
    double steps = 30, fps = 30;
    if (r == SK_OK) r = sk_hand__json_number(root, "", "steps", 1, 10000, false, &steps, err);
    if (r == SK_OK) r = sk_hand__json_number(root, "", "fps", 1, 1000, false, &fps, err);
    if (r == SK_OK)
        r = sk_hand__json_number(root, "", "hand_length_mm", 60, 400, false, &a->hand_length_mm,
                                 err);
    if (r == SK_OK)
        r = sk_hand__json_number(root, "", "hand_breadth_mm", 30, 200, false, &a->hand_breadth_mm,
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
        r = sk_hand__json_expect_object(item, path, err);
        if (r == SK_OK) r = sk_hand__json_check_keys(item, path, kkeys, err);
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
    sk_result r = sk_hand__json_parse(text, length, name, &root, err);
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
