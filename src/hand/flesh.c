/* Flesh sizes of the hand surface (thesis 4.1 builds its surface from a scanned cast;
 * here the surface is built from the skeleton with published anthropometry): the
 * built-in values of presets/hand/flesh.json and a strict reader of that format. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

void sk_hand_flesh_default(sk_hand_flesh *f)
{
    memset(f, 0, sizeof *f);
    f->reference_breadth_mm = 85;
    static const double breadth[5][4] = {{22, 21, 17.5, 0},
                                         {19, 20, 17.5, 15.5},
                                         {19, 20.5, 18, 16},
                                         {17, 19, 16.5, 15},
                                         {15.5, 16.5, 15, 13.5}};
    static const double thickness[5][4] = {{20, 18, 13.5, 0},
                                           {20, 18, 15, 12.5},
                                           {20.5, 18.5, 15, 13},
                                           {19, 17, 14, 12},
                                           {17, 15, 12.5, 11}};
    static const double mc_breadth[5][2] = {{18, 21}, {22, 30}, {20, 22}, {18, 20}, {20, 27}};
    static const double mc_thickness[5][2] = {{18, 19}, {28, 26}, {30, 27}, {28, 25}, {24, 22}};
    for (int i = 0; i < SK_HAND_FINGER_COUNT; i++) {
        memcpy(f->finger[i].breadth_mm, breadth[i], sizeof breadth[i]);
        memcpy(f->finger[i].thickness_mm, thickness[i], sizeof thickness[i]);
        memcpy(f->finger[i].metacarpal_breadth_mm, mc_breadth[i], sizeof mc_breadth[i]);
        memcpy(f->finger[i].metacarpal_thickness_mm, mc_thickness[i], sizeof mc_thickness[i]);
    }
    f->palm_palmar_shift_mm = 3;
    f->wrist_breadth_mm = 60;
    f->wrist_thickness_mm = 38;
    f->stump_length_mm = 30;
    f->thenar = (sk_hand_flesh_pad){0.17, 0.2, 8, {15, 22, 11}, -30};
    f->hypothenar = (sk_hand_flesh_pad){-0.33, 0.24, 5, {12, 26, 10}, 5};
    f->web_reach = 0.38;
    f->web_thickness_mm = 9;
    f->thumb_web_thickness_mm = 11;
    f->nail_length = 0.55;
    f->nail_breadth = 0.75;
    f->nail_thickness_mm = 0.5;
    f->blend_joint_mm = 3;
    f->blend_root_mm = 5;
    f->blend_palm_mm = 8;
}

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
    sk_result r = sk_hand__json_expect_object(*out, key, err);
    if (r == SK_OK) r = sk_hand__json_check_keys(*out, key, keys, err);
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
    r = sk_hand__json_number(o, key, "centre_x_hb", -1, 1, false, &pad->centre_x_hb, err);
    if (r == SK_OK)
        r = sk_hand__json_number(o, key, "centre_y_hl", -0.5, 1, false, &pad->centre_y_hl, err);
    if (r == SK_OK)
        r = sk_hand__json_number(o, key, "centre_z_mm", -50, 50, false, &pad->centre_z_mm, err);
    if (r == SK_OK) r = number_array(o, key, "radius_mm", 3, 1, 100, pad->radius_mm, err);
    if (r == SK_OK)
        r = sk_hand__json_number(o, key, "angle_deg", -180, 180, false, &pad->angle_deg, err);
    return r;
}

static sk_result parse_fingers(const cJSON *fingers, sk_hand_flesh *out, sk_error *err)
{
    sk_result r = sk_hand__json_expect_object(fingers, "fingers", err);
    for (const cJSON *it = fingers->child; r == SK_OK && it; it = it->next) {
        if (sk_preset_is_doc_key(it->string)) continue;
        int f = sk_hand__finger_by_letter(it->string);
        char path[96];
        snprintf(path, sizeof path, "fingers.%s", it->string);
        if (f < 0)
            return sk_fail(err, SK_ERROR_PARSE, "%s: unknown finger (T, I, M, R or L)", path);
        static const char *const keys[] = {"breadth_mm", "thickness_mm", "metacarpal_breadth_mm",
                                           "metacarpal_thickness_mm", NULL};
        r = sk_hand__json_expect_object(it, path, err);
        if (r == SK_OK) r = sk_hand__json_check_keys(it, path, keys, err);
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
    sk_result r = sk_hand__json_expect_object(root, "", err);
    if (r == SK_OK) r = sk_hand__json_check_keys(root, "", keys, err);
    if (r == SK_OK)
        r = sk_hand__json_number(root, "", "reference_breadth_mm", 30, 200, false,
                                 &out->reference_breadth_mm, err);
    const cJSON *fingers = cJSON_GetObjectItemCaseSensitive(root, "fingers");
    if (r == SK_OK && fingers) r = parse_fingers(fingers, out, err);
    const cJSON *o = NULL;
    static const char *const palm_keys[] = {"palmar_shift_mm", NULL};
    if (r == SK_OK) r = section(root, "palm", palm_keys, &o, err);
    if (r == SK_OK && o)
        r = sk_hand__json_number(o, "palm", "palmar_shift_mm", -20, 20, false,
                                 &out->palm_palmar_shift_mm, err);
    static const char *const wrist_keys[] = {"breadth_mm", "thickness_mm", "stump_length_mm", NULL};
    if (r == SK_OK) r = section(root, "wrist", wrist_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk_hand__json_number(o, "wrist", "breadth_mm", 10, 200, false, &out->wrist_breadth_mm,
                                 err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "wrist", "thickness_mm", 10, 200, false,
                                     &out->wrist_thickness_mm, err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "wrist", "stump_length_mm", 0, 200, false,
                                     &out->stump_length_mm, err);
    }
    if (r == SK_OK) r = parse_pad(root, "thenar", &out->thenar, err);
    if (r == SK_OK) r = parse_pad(root, "hypothenar", &out->hypothenar, err);
    static const char *const web_keys[] = {"reach", "thickness_mm", "thumb_thickness_mm", NULL};
    if (r == SK_OK) r = section(root, "webs", web_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk_hand__json_number(o, "webs", "reach", 0, 0.8, false, &out->web_reach, err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "webs", "thickness_mm", 1, 40, false,
                                     &out->web_thickness_mm, err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "webs", "thumb_thickness_mm", 1, 40, false,
                                     &out->thumb_web_thickness_mm, err);
    }
    static const char *const nail_keys[] = {"length", "breadth", "thickness_mm", NULL};
    if (r == SK_OK) r = section(root, "nails", nail_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk_hand__json_number(o, "nails", "length", 0.1, 0.9, false, &out->nail_length, err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "nails", "breadth", 0.1, 0.95, false, &out->nail_breadth,
                                     err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "nails", "thickness_mm", 0, 3, false,
                                     &out->nail_thickness_mm, err);
    }
    static const char *const blend_keys[] = {"joint_mm", "root_mm", "palm_mm", NULL};
    if (r == SK_OK) r = section(root, "blend", blend_keys, &o, err);
    if (r == SK_OK && o) {
        r = sk_hand__json_number(o, "blend", "joint_mm", 0.1, 20, false, &out->blend_joint_mm, err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "blend", "root_mm", 0.1, 20, false, &out->blend_root_mm,
                                     err);
        if (r == SK_OK)
            r = sk_hand__json_number(o, "blend", "palm_mm", 0.1, 30, false, &out->blend_palm_mm,
                                     err);
    }
    return r;
}

sk_result sk_hand_flesh_parse(const char *text, size_t length, const char *source_name,
                              sk_hand_flesh *out, sk_error *err)
{
    sk_hand_flesh_default(out);
    cJSON *root = NULL;
    sk_result r = sk_hand__json_parse(text, length, source_name, &root, err);
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
    return sk_hand__parse_file(path, parse_into, out, err);
}
