/* Bezier control points that move with their links, thesis 4.1.5: "各パッチの制御点 ... 骨格
 * モデルの一つのリンクに属する" - every control point belongs to one link and moves rigidly with
 * it (the thesis); or, with smooth weights, blends the rigid motions of up to 4 links
 * (linear blend skinning of the control points, which moves the patch as a whole because
 * a patch is linear in its control points). */
#include "models/hand/hand_internal.h"
#include "models/hand_scan/scan_internal.h"

typedef struct link_motion {
    sk_mat3d rotation; /* pose frame * rest frame^T */
    sk_vec3d from, to; /* the link's base joint at rest and in the pose */
} link_motion;

static sk_vec3d move(const link_motion *m, sk_vec3d p)
{
    return sk_v3d_add(sk_m3d_apply(m->rotation, sk_v3d_sub(p, m->from)), m->to);
}

sk_result sk_hand_patches_pose(const sk_hand_patch *patches, int count, const sk_hand_frames *rest,
                               const sk_hand_frames *pose, const sk_hand_patch_weights *weights,
                               sk_hand_patch *out, sk_error *err)
{
    if (count < 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch count %d is negative", count);
    link_motion motion[SK_HAND_LINK_COUNT];
    for (int l = 0; l < SK_HAND_LINK_COUNT; l++) {
        motion[l].rotation = sk_m3d_mul(pose->rotation[l], sk_m3d_transpose(rest->rotation[l]));
        motion[l].from = rest->point[sk_hand_link_point(l)];
        motion[l].to = pose->point[sk_hand_link_point(l)];
    }
    /* check everything first: `out` may be `patches` */
    for (int k = 0; k < count; k++) {
        if (patches[k].link < 0 || patches[k].link >= SK_HAND_LINK_COUNT)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch %d: link %d is not in [0, %d)", k,
                           patches[k].link, SK_HAND_LINK_COUNT);
        for (int c = 0; weights && c < 16; c++) {
            const sk_hand_patch_weights *w = &weights[16 * k + c];
            double sum = 0.0;
            for (int i = 0; i < SK_HAND_PATCH_MAX_INFLUENCES; i++) {
                if (w->link[i] < 0) continue;
                if (w->link[i] >= SK_HAND_LINK_COUNT || !(w->weight[i] >= 0.0f))
                    return sk_fail(
                        err, SK_ERROR_INVALID_ARGUMENT,
                        "weights[%d]: influence %d has link %d (range [0, %d)) or weight %g (>= 0)",
                        16 * k + c, i, w->link[i], SK_HAND_LINK_COUNT, (double)w->weight[i]);
                sum += w->weight[i];
            }
            if (!(sum > 1e-6))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "weights[%d]: the weights sum to %g (must be > 0)", 16 * k + c, sum);
        }
    }
    for (int k = 0; k < count; k++) {
        sk_hand_patch p = patches[k];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                if (!weights) {
                    p.p[i][j] = move(&motion[p.link], p.p[i][j]);
                    continue;
                }
                const sk_hand_patch_weights *w = &weights[16 * k + 4 * i + j];
                sk_vec3d sum = {0, 0, 0};
                double wsum = 0.0;
                for (int c = 0; c < SK_HAND_PATCH_MAX_INFLUENCES; c++)
                    if (w->link[c] >= 0) wsum += w->weight[c];
                for (int c = 0; c < SK_HAND_PATCH_MAX_INFLUENCES; c++) {
                    if (w->link[c] < 0) continue;
                    sum = sk_v3d_add(sum, sk_v3d_scale(move(&motion[w->link[c]], p.p[i][j]),
                                                       w->weight[c] / wsum));
                }
                p.p[i][j] = sum;
            }
        out[k] = p;
    }
    return SK_OK;
}

sk_result sk_hand_patch_weights_from_surface(const sk_hand_surface *surface,
                                             const sk_hand_patch *patches, int count,
                                             sk_hand_patch_weights *out, sk_error *err)
{
    if (count < 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch count %d is negative", count);
    const sk_mesh *m = sk_hand_surface_mesh(surface);
    const uint16_t *links;
    const float *weights;
    sk_hand_surface_weights(surface, SK_HAND_WEIGHTS_SMOOTH, &links, &weights);
    if (m->vertex_count == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the surface has no vertices");
#pragma omp parallel for schedule(static)
    for (int c = 0; c < 16 * count; c++) {
        int k = c / 16, i = (c % 16) / 4, j = c % 4;
        /* the patch point the control point mostly shapes (its Greville point) */
        sk_vec3d q = sk_hand_patch_eval(&patches[k], i / 3.0, j / 3.0, NULL, NULL);
        size_t best = 0;
        double best_d2 = INFINITY;
        for (size_t v = 0; v < m->vertex_count; v++) {
            const float *p = m->positions + 3 * v;
            double d2 = sk__dist2(q, sk_v3d(p[0], p[1], p[2]));
            if (d2 < best_d2) best_d2 = d2, best = v;
        }
        sk_hand_patch_weights *w = &out[c];
        for (int s = 0; s < SK_HAND_PATCH_MAX_INFLUENCES; s++) {
            float wt = weights[4 * best + (size_t)s];
            w->link[s] = wt > 0.0f ? (int16_t)links[4 * best + (size_t)s] : -1;
            w->weight[s] = wt > 0.0f ? wt : 0.0f;
        }
    }
    return SK_OK;
}
