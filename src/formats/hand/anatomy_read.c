/* The anatomy data file (JSON): fingers' link lengths and each DOF's limits, over the defaults of
 * sk_hand_anatomy_default. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

static sk_result parse_finger(const cJSON *obj, const char *path, int f, sk_hand_finger_data *fd,
                              sk_error *err)
{
    static const char *const keys[] = {"cmc_x_hb", "cmc_y_hl",   "cmc_z_hb",  "mc_dx_hb",
                                       "mc_dy_hl", "phalanx_hl", "mount_deg", NULL};
    sk_result r = sk__hand_json_expect_object(obj, path, err);
    if (r == SK_OK) r = sk__hand_json_check_keys(obj, path, keys, err);
    if (r == SK_OK)
        r = sk__hand_json_number(obj, path, "cmc_x_hb", -1, 1, false, &fd->cmc_x_hb, err);
    if (r == SK_OK)
        r = sk__hand_json_number(obj, path, "cmc_y_hl", -1, 1, false, &fd->cmc_y_hl, err);
    if (r == SK_OK)
        r = sk__hand_json_number(obj, path, "cmc_z_hb", -1, 1, false, &fd->cmc_z_hb, err);
    if (r == SK_OK)
        r = sk__hand_json_number(obj, path, "mc_dx_hb", -1, 1, false, &fd->mc_dx_hb, err);
    if (r == SK_OK)
        r = sk__hand_json_number(obj, path, "mc_dy_hl", 0.01, 1, false, &fd->mc_dy_hl, err);
    if (r != SK_OK) return r;
    const cJSON *ph = cJSON_GetObjectItemCaseSensitive(obj, "phalanx_hl");
    if (ph) {
        int want = f == SK_HAND_THUMB ? 2 : 3;
        if (!cJSON_IsArray(ph) || cJSON_GetArraySize(ph) != want)
            return sk_fail(err, SK_ERROR_PARSE, "%s.phalanx_hl: expected an array of %d numbers",
                           path, want);
        for (int i = 0; i < want; i++) {
            const cJSON *v = cJSON_GetArrayItem(ph, i);
            if (!cJSON_IsNumber(v) || !(v->valuedouble >= 0.01 && v->valuedouble <= 1.0))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "%s.phalanx_hl[%d] must be a number in [0.01, 1]", path, i);
            fd->phalanx_hl[i] = v->valuedouble;
        }
    }
    const cJSON *mount = cJSON_GetObjectItemCaseSensitive(obj, "mount_deg");
    if (mount) {
        char mpath[160];
        snprintf(mpath, sizeof mpath, "%s.mount_deg", path);
        static const char *const mkeys[] = {"splay", "tilt", "roll", NULL};
        static const char *const mkeys_finger[] = {"tilt", "roll", NULL};
        r = sk__hand_json_expect_object(mount, mpath, err);
        if (r == SK_OK)
            r = sk__hand_json_check_keys(mount, mpath, f == SK_HAND_THUMB ? mkeys : mkeys_finger,
                                         err);
        double splay = fd->thumb_splay * SK_RAD_TO_DEG, tilt = fd->mount_tilt * SK_RAD_TO_DEG,
               roll = fd->mount_roll * SK_RAD_TO_DEG;
        if (r == SK_OK)
            r = sk__hand_json_number(mount, mpath, "splay", -180, 180, false, &splay, err);
        if (r == SK_OK)
            r = sk__hand_json_number(mount, mpath, "tilt", -180, 180, false, &tilt, err);
        if (r == SK_OK)
            r = sk__hand_json_number(mount, mpath, "roll", -180, 180, false, &roll, err);
        if (r != SK_OK) return r;
        fd->thumb_splay = splay * SK_DEG_TO_RAD;
        fd->mount_tilt = tilt * SK_DEG_TO_RAD;
        fd->mount_roll = roll * SK_DEG_TO_RAD;
    }
    return SK_OK;
}

static sk_result parse_dof(const cJSON *obj, const char *path, int d, sk_hand_dof_data *dd,
                           sk_error *err)
{
    static const char *const keys_rot[] = {"min_deg", "max_deg", "relaxed_deg", "stiffness", NULL};
    static const char *const keys_tr[] = {"min_mm", "max_mm", "relaxed_mm", "stiffness", NULL};
    bool tr = sk_hand_dof(d)->translation;
    const char *const *keys = tr ? keys_tr : keys_rot;
    sk_result r = sk__hand_json_expect_object(obj, path, err);
    if (r == SK_OK) r = sk__hand_json_check_keys(obj, path, keys, err);
    double lim = tr ? 1e4 : 360.0;
    double mn = sk__hand_to_file_units(d, dd->min), mx = sk__hand_to_file_units(d, dd->max);
    double rel = sk__hand_to_file_units(d, dd->relaxed), k = dd->stiffness;
    if (r == SK_OK) r = sk__hand_json_number(obj, path, keys[0], -lim, lim, false, &mn, err);
    if (r == SK_OK) r = sk__hand_json_number(obj, path, keys[1], -lim, lim, false, &mx, err);
    if (r == SK_OK) r = sk__hand_json_number(obj, path, keys[2], -lim, lim, false, &rel, err);
    if (r == SK_OK) r = sk__hand_json_number(obj, path, "stiffness", 1e-9, 1e9, false, &k, err);
    if (r != SK_OK) return r;
    if (mn > mx)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: %s = %g is above %s = %g", path,
                       keys[0], mn, keys[1], mx);
    if (rel < mn || rel > mx)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s.%s = %g is out of range [%g, %g]", path,
                       keys[2], rel, mn, mx);
    dd->min = sk__hand_from_file_units(d, mn);
    dd->max = sk__hand_from_file_units(d, mx);
    dd->relaxed = sk__hand_from_file_units(d, rel);
    dd->stiffness = k;
    return SK_OK;
}

sk_result sk_hand_anatomy_parse(const char *text, size_t length, const char *source_name,
                                sk_hand_anatomy *out, sk_error *err)
{
    sk_hand_anatomy_default(out);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse(text, length, source_name, &root, err);
    if (r != SK_OK) return r;
    static const char *const keys[] = {"hand", "fingers", "dofs", NULL};
    r = sk__hand_json_expect_object(root, "", err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, "", keys, err);
    const cJSON *hand = cJSON_GetObjectItemCaseSensitive(root, "hand");
    if (r == SK_OK && hand) {
        static const char *const hkeys[] = {"length_mm", "breadth_mm", NULL};
        r = sk__hand_json_expect_object(hand, "hand", err);
        if (r == SK_OK) r = sk__hand_json_check_keys(hand, "hand", hkeys, err);
        if (r == SK_OK)
            r = sk__hand_json_number(hand, "hand", "length_mm", 60, 400, false,
                                     &out->hand_length_mm, err);
        if (r == SK_OK)
            r = sk__hand_json_number(hand, "hand", "breadth_mm", 30, 200, false,
                                     &out->hand_breadth_mm, err);
    }
    const cJSON *fingers = cJSON_GetObjectItemCaseSensitive(root, "fingers");
    if (r == SK_OK && fingers) {
        r = sk__hand_json_expect_object(fingers, "fingers", err);
        for (const cJSON *it = fingers ? fingers->child : NULL; r == SK_OK && it; it = it->next) {
            if (sk_preset_is_doc_key(it->string)) continue;
            int f = sk__hand_finger_by_letter(it->string);
            char path[96];
            snprintf(path, sizeof path, "fingers.%s", it->string);
            if (f < 0) {
                r = sk_fail(err, SK_ERROR_PARSE, "%s: unknown finger (T, I, M, R or L)", path);
                break;
            }
            r = parse_finger(it, path, f, &out->finger[f], err);
        }
    }
    const cJSON *dofs = cJSON_GetObjectItemCaseSensitive(root, "dofs");
    if (r == SK_OK && dofs) {
        r = sk__hand_json_expect_object(dofs, "dofs", err);
        for (const cJSON *it = dofs ? dofs->child : NULL; r == SK_OK && it; it = it->next) {
            if (sk_preset_is_doc_key(it->string)) continue;
            char path[96];
            snprintf(path, sizeof path, "dofs.%s", it->string);
            int d;
            r = sk__hand_dof_by_name(it->string, path, &d, err);
            if (r == SK_OK) r = parse_dof(it, path, d, &out->dof[d], err);
        }
    }
    cJSON_Delete(root);
    if (r != SK_OK) sk_error_prefix(err, r, "%s", source_name);
    return r;
}

static sk_result parse_into(const char *text, size_t length, const char *source, void *out,
                            sk_error *err)
{
    return sk_hand_anatomy_parse(text, length, source, out, err);
}

sk_result sk_hand_anatomy_load_file(const char *path, sk_hand_anatomy *out, sk_error *err)
{
    return sk__hand_parse_file(path, parse_into, out, err);
}
