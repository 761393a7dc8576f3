/* Anatomy of the skeleton: segment lengths as fractions of hand length and breadth
 * (Buchholz, Armstrong, Goldstein 1992), the relaxed posture theta_bar (thesis 3.1.4) and
 * joint limits and spring stiffness per DOF (3.2.1). The same numbers, each with its
 * source, are in presets/hand/anatomy.json (a test keeps the two equal). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

/* One DOF: limits, relaxed value (degrees, mm for translations), stiffness. */
typedef struct dof_row {
    double min, max, relaxed, stiffness;
} dof_row;

static const dof_row default_dofs[SK_HAND_DOF_COUNT] = {
    /* wrist: places the hand in the scene (the forearm is not modelled) */
    {-1000, 1000, 0, 1},
    {-1000, 1000, 0, 1},
    {-1000, 1000, 0, 1},
    {-180, 180, 0, 1},
    {-180, 180, 0, 1},
    {-180, 180, 0, 1},
    /* thumb: AAOS active ranges (CMC extension 20 / flexion 15, abduction 70; MCP 0-50;
       IP -20..80); relaxed so that the thumb rests slightly flexed and palmar-abducted
       beside the index finger, its pad radial and palmar of the index's proximal
       phalanx (the resting pattern of Taylor & Schwarz 1955) */
    {-20, 15, 10, 1},
    {0, 70, 25, 2},
    {0, 50, 10, 1},
    {-5, 5, 0, 4},
    {-20, 80, 10, 1},
    /* index: CMC nearly rigid; MCP -45..90, abduction +-20 (AAOS); PIP 0-100, DIP 0-90
       (AAOS); relaxed at the lower bounds of Bain et al. 2015's functional ranges (19,
       23, 10), each finger toward the little one 5, 5 and 3 degrees more flexed: the
       flexion cascade of the resting hand (Taylor & Schwarz 1955) */
    {-2, 2, 0, 50},
    {-2, 2, 0, 50},
    {-45, 90, 19, 1},
    {-20, 20, 0, 2},
    {0, 100, 23, 1},
    {0, 90, 10, 1},
    /* middle */
    {-2, 2, 0, 50},
    {-2, 2, 0, 50},
    {-45, 90, 24, 1},
    {-20, 20, 0, 2},
    {0, 100, 28, 1},
    {0, 90, 13, 1},
    /* ring: CMC flexion about 10 degrees (Batmanabane & Malathi 1985) */
    {0, 10, 0, 5},
    {-5, 5, 0, 10},
    {-45, 90, 29, 1},
    {-20, 20, 0, 2},
    {0, 100, 33, 1},
    {0, 90, 16, 1},
    /* little: CMC flexion about 20 degrees (same source) */
    {0, 20, 0, 3},
    {-5, 5, 0, 10},
    {-45, 90, 34, 1},
    {-20, 20, 0, 2},
    {0, 100, 38, 1},
    {0, 90, 19, 1},
};

/* Buchholz et al. 1992: CMC centres 0.073 HL distal of the wrist centre, lateral offsets
 * in hand breadths; metacarpal and phalanx lengths in hand lengths. The thumb's mount is
 * its metacarpal's direction at zero CMC angles (35 degrees radial in the palm plane, pad
 * turned toward the fingers, i.e. rolled 90 degrees against the fingers' frames). */
static const sk_hand_finger_data default_fingers[SK_HAND_FINGER_COUNT] = {
    {0.196, 0.073, 0.0, 0.0, 0.251, {0.196, 0.158, 0.0}, 0, 0, 0},
    {0.126, 0.073, 0.0, 0.126, 0.374, {0.265, 0.143, 0.097}, 0, 0, 0},
    {0.0, 0.073, 0.0, 0.0, 0.373, {0.277, 0.170, 0.108}, 0, 0, 0},
    {-0.129, 0.073, 0.0, -0.077, 0.336, {0.259, 0.165, 0.107}, 0, 0, 0},
    {-0.223, 0.073, 0.0, -0.170, 0.295, {0.206, 0.117, 0.093}, 0, 0, 0},
};

/* Thumb mount (degrees): splay toward the radial side in the palm plane, tilt toward the
 * palm, roll about its own axis. */
#define THUMB_SPLAY_DEG (-35.0)
#define THUMB_TILT_DEG 0.0
#define THUMB_ROLL_DEG (-90.0)

void sk_hand_anatomy_default(sk_hand_anatomy *out)
{
    memset(out, 0, sizeof *out);
    /* a round adult size between the men's and women's means of the 1988 US Army
       anthropometric survey (Gordon et al. 1989) */
    out->hand_length_mm = 190.0;
    out->hand_breadth_mm = 85.0;
    memcpy(out->finger, default_fingers, sizeof default_fingers);
    out->finger[SK_HAND_THUMB].thumb_splay = THUMB_SPLAY_DEG * SK_DEG_TO_RAD;
    out->finger[SK_HAND_THUMB].mount_tilt = THUMB_TILT_DEG * SK_DEG_TO_RAD;
    out->finger[SK_HAND_THUMB].mount_roll = THUMB_ROLL_DEG * SK_DEG_TO_RAD;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        out->dof[i].min = sk_hand__from_file_units(i, default_dofs[i].min);
        out->dof[i].max = sk_hand__from_file_units(i, default_dofs[i].max);
        out->dof[i].relaxed = sk_hand__from_file_units(i, default_dofs[i].relaxed);
        out->dof[i].stiffness = default_dofs[i].stiffness;
    }
}

static sk_result parse_finger(const cJSON *obj, const char *path, int f, sk_hand_finger_data *fd,
                              sk_error *err)
{
    static const char *const keys[] = {"cmc_x_hb", "cmc_y_hl",   "cmc_z_hb",  "mc_dx_hb",
                                       "mc_dy_hl", "phalanx_hl", "mount_deg", NULL};
    sk_result r = sk_hand__json_expect_object(obj, path, err);
    if (r == SK_OK) r = sk_hand__json_check_keys(obj, path, keys, err);
    if (r == SK_OK)
        r = sk_hand__json_number(obj, path, "cmc_x_hb", -1, 1, false, &fd->cmc_x_hb, err);
    if (r == SK_OK)
        r = sk_hand__json_number(obj, path, "cmc_y_hl", -1, 1, false, &fd->cmc_y_hl, err);
    if (r == SK_OK)
        r = sk_hand__json_number(obj, path, "cmc_z_hb", -1, 1, false, &fd->cmc_z_hb, err);
    if (r == SK_OK)
        r = sk_hand__json_number(obj, path, "mc_dx_hb", -1, 1, false, &fd->mc_dx_hb, err);
    if (r == SK_OK)
        r = sk_hand__json_number(obj, path, "mc_dy_hl", 0.01, 1, false, &fd->mc_dy_hl, err);
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
        r = sk_hand__json_expect_object(mount, mpath, err);
        if (r == SK_OK)
            r = sk_hand__json_check_keys(mount, mpath, f == SK_HAND_THUMB ? mkeys : mkeys_finger,
                                         err);
        double splay = fd->thumb_splay * SK_RAD_TO_DEG, tilt = fd->mount_tilt * SK_RAD_TO_DEG,
               roll = fd->mount_roll * SK_RAD_TO_DEG;
        if (r == SK_OK)
            r = sk_hand__json_number(mount, mpath, "splay", -180, 180, false, &splay, err);
        if (r == SK_OK)
            r = sk_hand__json_number(mount, mpath, "tilt", -180, 180, false, &tilt, err);
        if (r == SK_OK)
            r = sk_hand__json_number(mount, mpath, "roll", -180, 180, false, &roll, err);
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
    sk_result r = sk_hand__json_expect_object(obj, path, err);
    if (r == SK_OK) r = sk_hand__json_check_keys(obj, path, keys, err);
    double lim = tr ? 1e4 : 360.0;
    double mn = sk_hand__to_file_units(d, dd->min), mx = sk_hand__to_file_units(d, dd->max);
    double rel = sk_hand__to_file_units(d, dd->relaxed), k = dd->stiffness;
    if (r == SK_OK) r = sk_hand__json_number(obj, path, keys[0], -lim, lim, false, &mn, err);
    if (r == SK_OK) r = sk_hand__json_number(obj, path, keys[1], -lim, lim, false, &mx, err);
    if (r == SK_OK) r = sk_hand__json_number(obj, path, keys[2], -lim, lim, false, &rel, err);
    if (r == SK_OK) r = sk_hand__json_number(obj, path, "stiffness", 1e-9, 1e9, false, &k, err);
    if (r != SK_OK) return r;
    if (mn > mx)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: %s = %g is above %s = %g", path,
                       keys[0], mn, keys[1], mx);
    if (rel < mn || rel > mx)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s.%s = %g is out of range [%g, %g]", path,
                       keys[2], rel, mn, mx);
    dd->min = sk_hand__from_file_units(d, mn);
    dd->max = sk_hand__from_file_units(d, mx);
    dd->relaxed = sk_hand__from_file_units(d, rel);
    dd->stiffness = k;
    return SK_OK;
}

sk_result sk_hand_anatomy_parse(const char *text, size_t length, const char *source_name,
                                sk_hand_anatomy *out, sk_error *err)
{
    sk_hand_anatomy_default(out);
    cJSON *root = NULL;
    sk_result r = sk_hand__json_parse(text, length, source_name, &root, err);
    if (r != SK_OK) return r;
    static const char *const keys[] = {"hand", "fingers", "dofs", NULL};
    r = sk_hand__json_expect_object(root, "", err);
    if (r == SK_OK) r = sk_hand__json_check_keys(root, "", keys, err);
    const cJSON *hand = cJSON_GetObjectItemCaseSensitive(root, "hand");
    if (r == SK_OK && hand) {
        static const char *const hkeys[] = {"length_mm", "breadth_mm", NULL};
        r = sk_hand__json_expect_object(hand, "hand", err);
        if (r == SK_OK) r = sk_hand__json_check_keys(hand, "hand", hkeys, err);
        if (r == SK_OK)
            r = sk_hand__json_number(hand, "hand", "length_mm", 60, 400, false,
                                     &out->hand_length_mm, err);
        if (r == SK_OK)
            r = sk_hand__json_number(hand, "hand", "breadth_mm", 30, 200, false,
                                     &out->hand_breadth_mm, err);
    }
    const cJSON *fingers = cJSON_GetObjectItemCaseSensitive(root, "fingers");
    if (r == SK_OK && fingers) {
        r = sk_hand__json_expect_object(fingers, "fingers", err);
        for (const cJSON *it = fingers ? fingers->child : NULL; r == SK_OK && it; it = it->next) {
            if (sk_preset_is_doc_key(it->string)) continue;
            int f = sk_hand__finger_by_letter(it->string);
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
        r = sk_hand__json_expect_object(dofs, "dofs", err);
        for (const cJSON *it = dofs ? dofs->child : NULL; r == SK_OK && it; it = it->next) {
            if (sk_preset_is_doc_key(it->string)) continue;
            char path[96];
            snprintf(path, sizeof path, "dofs.%s", it->string);
            int d;
            r = sk_hand__dof_by_name(it->string, path, &d, err);
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
    return sk_hand__parse_file(path, parse_into, out, err);
}
