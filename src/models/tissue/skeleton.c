/* The character's skeleton (Shigemori & Kawai sec. 2: a hierarchy of bones whose motion
 * comes from outside data): rest positions from the joints' offsets and world poses from
 * local rotations, BVH style (rest frames aligned with the world). */
#include <string.h>

#include "models/tissue/tissue_internal.h"

sk_result sk__skeleton_build(const sk_tissue_character_desc *d, sk__skeleton *s, sk_error *err)
{
    memset(s, 0, sizeof *s);
    s->count = d->joint_count;
    s->root = -1;
    for (int j = 0; j < d->joint_count; j++) {
        s->parent[j] = d->joints[j].parent[0] ? sk__joint_find(d, d->joints[j].parent) : -1;
        if (s->parent[j] < 0) s->root = j;
        s->offset[j] =
            sk_v3d(d->joints[j].offset_mm[0], d->joints[j].offset_mm[1], d->joints[j].offset_mm[2]);
    }
    if (s->root < 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "joints: no root");
    /* breadth-first order from the root: parents before children */
    int n = 0;
    s->order[n++] = s->root;
    for (int head = 0; head < n; head++)
        for (int j = 0; j < s->count; j++)
            if (s->parent[j] == s->order[head]) s->order[n++] = j;
    if (n != s->count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joints: not every joint hangs from the root");
    for (int k = 0; k < n; k++) {
        int j = s->order[k], p = s->parent[j];
        s->rest[j] = p < 0 ? s->offset[j] : sk_v3d_add(s->rest[p], s->offset[j]);
    }
    return SK_OK;
}

void sk__skeleton_pose(const sk__skeleton *s, const sk_quatd *local, sk_vec3d root,
                       sk_tissue_pose *out)
{
    for (int k = 0; k < s->count; k++) {
        int j = s->order[k], p = s->parent[j];
        if (p < 0) {
            out->rotation[j] = local[j];
            out->position[j] = root;
        } else {
            out->rotation[j] = sk_qd_normalize(sk_qd_mul(out->rotation[p], local[j]));
            out->position[j] =
                sk_v3d_add(out->position[p], sk_qd_rotate(out->rotation[p], s->offset[j]));
        }
    }
}

void sk_tissue_model_pose(const sk_tissue_model *m, const sk_quatd *local, sk_vec3d root_mm,
                          sk_tissue_pose *out)
{
    sk__skeleton_pose(&m->skeleton, local, root_mm, out);
}
