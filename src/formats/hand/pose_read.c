/* Reader of a hand pose file: the "dofs" object written by sk_hand_pose_write_json
 * (degrees; mm for the wrist translations), any DOF missing keeping its relaxed value
 * (thesis eq. 3.7's theta_bar). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

sk_result sk_hand_pose_parse(const char *text, size_t length, const char *source_name,
                             const sk_hand_skeleton *skeleton, double dofs[SK_HAND_DOF_COUNT],
                             sk_error *err)
{
    sk_hand_relaxed(skeleton, dofs);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse(text, length, source_name, &root, err);
    static const char *const keys[] = {"dofs", "side", "units", "points_mm", "solve", NULL};
    if (r == SK_OK) r = sk__hand_json_expect_object(root, "", err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, "", keys, err);
    const cJSON *d = r == SK_OK ? cJSON_GetObjectItemCaseSensitive(root, "dofs") : NULL;
    if (r == SK_OK && !d)
        r = sk_fail(err, SK_ERROR_PARSE, "dofs: missing (an object of DOF names and values)");
    if (r == SK_OK) r = sk__hand_json_expect_object(d, "dofs", err);
    for (const cJSON *it = d && r == SK_OK ? d->child : NULL; it && r == SK_OK; it = it->next) {
        if (sk_preset_is_doc_key(it->string)) continue;
        char path[96];
        snprintf(path, sizeof path, "dofs.%s", it->string);
        int dof;
        r = sk__hand_dof_by_name(it->string, path, &dof, err);
        if (r != SK_OK) break;
        if (!cJSON_IsNumber(it) || !isfinite(it->valuedouble) || fabs(it->valuedouble) > 1e6)
            r = sk_fail(err, SK_ERROR_PARSE, "%s: expected a finite number", path);
        else
            dofs[dof] = sk__hand_from_file_units(dof, it->valuedouble);
    }
    cJSON_Delete(root);
    if (r != SK_OK) sk_error_prefix(err, r, "%s", source_name ? source_name : "pose");
    return r;
}

typedef struct pose_target {
    const sk_hand_skeleton *skeleton;
    double *dofs;
} pose_target;

static sk_result parse_into(const char *text, size_t length, const char *source, void *ctx,
                            sk_error *err)
{
    pose_target *t = ctx;
    return sk_hand_pose_parse(text, length, source, t->skeleton, t->dofs, err);
}

sk_result sk_hand_pose_load_file(const char *path, const sk_hand_skeleton *skeleton,
                                 double dofs[SK_HAND_DOF_COUNT], sk_error *err)
{
    pose_target t = {skeleton, dofs};
    return sk__hand_parse_file(path, parse_into, &t, err);
}
