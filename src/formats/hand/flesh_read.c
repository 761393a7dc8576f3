/* The flesh description file (JSON): pad sizes and finger thickness over sk_hand_flesh_default. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

/* An array of exactly `n` finite numbers in [lo, hi] at object[key] (absent: unchanged). */
static sk_result number_array(const cJSON *obj, const char *path, const char *key, int n, double lo,
                              double hi, double *out, sk_error *err)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(obj, key);
    if (!a) return SK_OK;
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != n)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: expected an array of %d numbers", path, key, n);
    int i = 0;
    for (const cJSON *it = a->child; it; it = it->next, i++) {
        if (!cJSON_IsNumber(it))
            return sk_fail(err, SK_ERROR_PARSE, "%s.%s[%d]: expected a number", path, key, i);
        double v = it->valuedouble;
        if (!isfinite(v))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s.%s[%d] is not a finite number", path,
                           key, i);
        if (v < lo || v > hi)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s.%s[%d] = %g is out of range [%g, %g]", path, key, i, v, lo, hi);
        out[i] = v;
    }
    return SK_OK;
}

/* An optional sub-object: NULL if absent; fails if it is not an object or has unknown keys. */
static sk_result section(const cJSON *root, const char *key, const char *const *keys,
                         const cJSON **out, sk_error *err)
{
    *out = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!*out) return SK_OK;
    sk_result r = sk__hand_json_expect_object(*out, key, err);
    if (r == SK_OK) r = sk__hand_json_check_keys(*out, key, keys, err);
    return r;
}

static sk_result parse_pad(const cJSON *root, const char *key, sk_hand_flesh_pad *pad,
                           sk_error *err)
{
    static const char *const keys[] = {"centre_x_hb", "centre_y_hl", "centre_z_mm",
                                       "radius_mm",   "angle_deg",   NULL};
    const cJSON *o;
    sk_result r = section(root, key, keys, &o, err);
    if (r != SK_OK || !o) return r;
    r = sk__hand_json_number(o, key, "centre_x_hb", -1, 1, false, &pad->centre_x_hb, err);
    if (r == SK_OK)
        r = sk__hand_json_number(o, key, "centre_y_hl", -0.5, 1, false, &pad->centre_y_hl, err);
    if (r == SK_OK)
        r = sk__hand_json_number(o, key, "centre_z_mm", -50, 50, false, &pad->centre_z_mm, err);
    if (r == SK_OK) r = number_array(o, key, "radius_mm", 3, 1, 100, pad->radius_mm, err);
    if (r == SK_OK)
        r = sk__hand_json_number(o, key, "angle_deg", -180, 180, false, &pad->angle_deg, err);
    return r;
}

static sk_result parse_fingers(const cJSON *fingers, sk_hand_flesh *out, sk_error *err)
{
    sk_result r = sk__hand_json_expect_object(fingers, "fingers", err);
    for (const cJSON *it = fingers->child; r == SK_OK && it; it = it->next) {
        if (sk_preset_is_doc_key(it->string)) continue;
        int f = sk__hand_finger_by_letter(it->string);
        char path[96];
        snprintf(path, sizeof path, "fingers.%s", it->string);
        if (f < 0)
            return sk_fail(err, SK_ERROR_PARSE, "%s: unknown finger (T, I, M, R or L)", path);
        static const char *const keys[] = {"breadth_mm", "thickness_mm", "metacarpal_breadth_mm",
                                           "metacarpal_thickness_mm", NULL};
        r = sk__hand_json_expect_object(it, path, err);
        if (r == SK_OK) r = sk__hand_json_check_keys(it, path, keys, err);
        int stations = f == SK_HAND_THUMB ? 3 : 4;
        sk_hand_flesh_finger *ff = &out->finger[f];
        if (r == SK_OK)
            r = number_array(it, path, "breadth_mm", stations, 2, 80, ff->breadth_mm, err);
        if (r == SK_OK)
            r = number_array(it, path, "thickness_mm", stations, 2, 80, ff->thickness_mm, err);
        if (r == SK_OK)
            r = number_array(it, path, "metacarpal_breadth_mm", 2, 2, 80, ff->metacarpal_breadth_mm,
                             err);
        if (r == SK_OK)
            r = number_array(it, path, "metacarpal_thickness_mm", 2, 2, 80,
                             ff->metacarpal_thickness_mm, err);
    }
    return r;
}

static sk_result parse_flesh(const cJSON *root, sk_hand_flesh *out, sk_error *err)
{
    static const char *const keys[] = {
        "reference_breadth_mm", "fingers", "palm",  "wrist", "thenar",
        "hypothenar",           "webs",    "nails", "blend", NULL};
    sk_result r = sk__hand_json_expect_object(root, "", err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, "", keys, err);
    if (r == SK_OK)
        r = sk__hand_json_number(root, "", "reference_breadth_mm", 30, 200, false,
                                 &out->reference_breadth_mm, err);
    const cJSON *fingers = cJSON_GetObjectItemCaseSensitive(root, "fingers");
    if (r == SK_OK && fingers) r = parse_fingers(fingers, out, err);
    const cJSON *o = NULL;
    static const char *const palm_keys[] = {"palmar_shift_mm", NULL};
    if (r == SK_OK) r = section(root, "palm", palm_keys, &o, err);
    if (r == SK_OK && o)
        r = sk__hand_json_number(o, "palm", "palmar_shift_mm", -20, 20, false,
                                 &out->palm_palmar_shift_mm, err);
    static const char *const wrist_keys[] = {"breadth_mm", "thickness_mm", "stump_length_mm", NULL};
    if (r == SK_OK) r = section(root, "wrist", wrist_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk__hand_json_number(o, "wrist", "breadth_mm", 10, 200, false, &out->wrist_breadth_mm,
                                 err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "wrist", "thickness_mm", 10, 200, false,
                                     &out->wrist_thickness_mm, err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "wrist", "stump_length_mm", 0, 200, false,
                                     &out->stump_length_mm, err);
    }
    if (r == SK_OK) r = parse_pad(root, "thenar", &out->thenar, err);
    if (r == SK_OK) r = parse_pad(root, "hypothenar", &out->hypothenar, err);
    static const char *const web_keys[] = {"reach", "thickness_mm", "thumb_thickness_mm", NULL};
    if (r == SK_OK) r = section(root, "webs", web_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk__hand_json_number(o, "webs", "reach", 0, 0.8, false, &out->web_reach, err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "webs", "thickness_mm", 1, 40, false,
                                     &out->web_thickness_mm, err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "webs", "thumb_thickness_mm", 1, 40, false,
                                     &out->thumb_web_thickness_mm, err);
    }
    static const char *const nail_keys[] = {"length", "breadth", "thickness_mm", NULL};
    if (r == SK_OK) r = section(root, "nails", nail_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk__hand_json_number(o, "nails", "length", 0.1, 0.9, false, &out->nail_length, err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "nails", "breadth", 0.1, 0.95, false, &out->nail_breadth,
                                     err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "nails", "thickness_mm", 0, 3, false,
                                     &out->nail_thickness_mm, err);
    }
    static const char *const blend_keys[] = {"joint_mm", "root_mm", "palm_mm", NULL};
    if (r == SK_OK) r = section(root, "blend", blend_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk__hand_json_number(o, "blend", "joint_mm", 0.1, 20, false, &out->blend_joint_mm, err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "blend", "root_mm", 0.1, 20, false, &out->blend_root_mm,
                                     err);
        if (r == SK_OK)
            r = sk__hand_json_number(o, "blend", "palm_mm", 0.1, 30, false, &out->blend_palm_mm,
                                     err);
    }
    return r;
}

sk_result sk_hand_flesh_parse(const char *text, size_t length, const char *source_name,
                              sk_hand_flesh *out, sk_error *err)
{
    sk_hand_flesh_default(out);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse(text, length, source_name, &root, err);
    if (r == SK_OK) r = parse_flesh(root, out, err);
    cJSON_Delete(root);
    if (r != SK_OK) sk_error_prefix(err, r, "%s", source_name ? source_name : "flesh");
    return r;
}

static sk_result parse_into(const char *text, size_t length, const char *source, void *out,
                            sk_error *err)
{
    return sk_hand_flesh_parse(text, length, source, out, err);
}

sk_result sk_hand_flesh_load_file(const char *path, sk_hand_flesh *out, sk_error *err)
{
    return sk__hand_parse_file(path, parse_into, out, err);
}
