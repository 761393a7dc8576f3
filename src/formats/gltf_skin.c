/* Skins of the glTF document (glTF 2.0 sec. 3.7.3): joints with a common root, and their
 * inverse bind matrices, given or computed as the inverses of the joints' world transforms
 * as the nodes stand (the bind pose), with the last row exactly (0, 0, 0, 1). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_internal.h"

static int root_of(const sk_gltf *gltf, int node)
{
    while (gltf->nodes[node].parent != SK_GLTF_NONE) node = gltf->nodes[node].parent;
    return node;
}

static sk_result check_joints(const sk_gltf *gltf, const int *joints, int count, sk_error *err)
{
    if (!joints || count < 1 || count > SK__GLTF_MAX_JOINTS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joint_count = %d is out of range [1, %d] (or joints is NULL)", count,
                       SK__GLTF_MAX_JOINTS);
    for (int j = 0; j < count; j++) {
        if (joints[j] < 0 || joints[j] >= gltf->node_count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[%d] = %d is not a node of the document (%d nodes)", j, joints[j],
                           gltf->node_count);
        if (gltf->nodes[joints[j]].mesh != SK_GLTF_NONE &&
            gltf->nodes[joints[j]].skin != SK_GLTF_NONE)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[%d] = %d is a skinned mesh node, not a joint", j, joints[j]);
        if (root_of(gltf, joints[j]) != root_of(gltf, joints[0]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[%d] = %d and joints[0] = %d have no common root", j, joints[j],
                           joints[0]);
    }
    /* quadratic, but skins have tens of joints; a duplicate is a glTF error */
    for (int j = 0; j < count; j++)
        for (int k = 0; k < j; k++)
            if (joints[j] == joints[k])
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joints[%d] = %d repeats joints[%d]",
                               j, joints[j], k);
    return SK_OK;
}

/* Given matrices: finite, affine (last row 0 0 0 1 within float noise, then exact). */
static sk_result copy_given(const float *given, int count, float *out, sk_error *err)
{
    static const int last_row[4] = {3, 7, 11, 15};
    for (int j = 0; j < count; j++) {
        const float *m = given + 16 * j;
        for (int k = 0; k < 16; k++)
            if (!isfinite(m[k]))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "inverse_bind[%d][%d] is not finite",
                               j, k);
        for (int k = 0; k < 4; k++) {
            float want = k == 3 ? 1.0f : 0.0f;
            if (fabsf(m[last_row[k]] - want) > 1e-6f)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "inverse_bind[%d][%d] = %g: the last row of an inverse bind "
                               "matrix must be (0, 0, 0, 1) (column-major: elements 3, 7, 11, 15)",
                               j, last_row[k], (double)m[last_row[k]]);
        }
        memcpy(out + 16 * j, m, 16 * sizeof(float));
        for (int k = 0; k < 4; k++) out[16 * j + last_row[k]] = k == 3 ? 1.0f : 0.0f;
    }
    return SK_OK;
}

static sk_result compute_from_nodes(const sk_gltf *gltf, const int *joints, int count, float *out,
                                    sk_error *err)
{
    for (int j = 0; j < count; j++) {
        double world[16], inv[16];
        sk__gltf_node_world(gltf, joints[j], world);
        if (!sk__gltf_affine_inverse(world, inv))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[%d] = %d: its world transform is singular (a zero scale), "
                           "so it has no inverse bind matrix",
                           j, joints[j]);
        for (int k = 0; k < 16; k++) out[16 * j + k] = (float)inv[k];
    }
    return SK_OK;
}

sk_result sk_gltf_add_skin(sk_gltf *gltf, const char *name, const int *joints, int joint_count,
                           const float *inverse_bind, int *out_index, sk_error *err)
{
    if (!gltf || !out_index)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "gltf or out_index is NULL");
    *out_index = SK_GLTF_NONE;
    int index = gltf->skin_count;
    sk_result r = check_joints(gltf, joints, joint_count, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "skins[%d]", index);
    r = sk__gltf_grow((void **)&gltf->skins, gltf->skin_count, &gltf->skin_capacity,
                      sizeof *gltf->skins, "skins", err);
    if (r != SK_OK) return r;
    sk__gltf_skin s = {0};
    s.joint_count = joint_count;
    s.joints = malloc((size_t)joint_count * sizeof(int));
    s.inverse_bind = malloc((size_t)joint_count * 16 * sizeof(float));
    s.name = sk__gltf_name(name, "skin", index);
    if (!s.joints || !s.inverse_bind || !s.name) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    } else {
        memcpy(s.joints, joints, (size_t)joint_count * sizeof(int));
        r = inverse_bind ? copy_given(inverse_bind, joint_count, s.inverse_bind, err)
                         : compute_from_nodes(gltf, joints, joint_count, s.inverse_bind, err);
    }
    if (r != SK_OK) {
        free(s.joints);
        free(s.inverse_bind);
        free(s.name);
        return sk_error_prefix(err, r, "skins[%d]", index);
    }
    gltf->skins[index] = s;
    gltf->skin_count++;
    *out_index = index;
    return SK_OK;
}
