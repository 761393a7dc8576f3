/* BVH export of hand motion: the link tree as a BVH hierarchy whose rest pose is the
 * skeleton with every DOF at zero (OFFSETs in mm), the root with 6 channels and every
 * joint with 3 rotation channels in the model's 3-2-1 order (Zrotation Yrotation
 * Xrotation, eq. 3.4). BVH rest frames are aligned with the world, so each channel
 * triple is the joint's rotation relative to its rest orientation. The file itself is
 * written by the general BVH writer (include/shitsukan/bvh.h). */
#include <stdlib.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/bvh.h"

/* Adds the chain from `link` to the finger's tip under BVH joint `parent`; bvh_joint[l]
 * receives the BVH index of each link. */
static sk_result add_chain(sk_bvh *b, const sk_hand_skeleton *s, const sk_hand_frames *ref,
                           int link, int parent, int *bvh_joint)
{
    int prev = s->parent[link];
    sk_vec3d offset =
        sk_v3d_sub(ref->point[sk_hand_link_point(link)], ref->point[sk_hand_link_point(prev)]);
    sk_result r = sk_bvh_add_joint(b, sk_hand_link_name(link), parent, offset, "ZYX", false,
                                   &bvh_joint[link], NULL);
    if (r != SK_OK) return r;
    bool last = link == SK_HAND_LINK_COUNT - 1 || s->parent[link + 1] != link;
    if (!last) return add_chain(b, s, ref, link + 1, bvh_joint[link], bvh_joint);
    char name[SK_BVH_NAME_SIZE];
    snprintf(name, sizeof name, "%s_end", sk_hand_link_name(link));
    int tip = sk_hand_link_end_point(link);
    return sk_bvh_add_joint(b, name, bvh_joint[link],
                            sk_v3d_sub(ref->point[tip], ref->point[sk_hand_link_point(link)]), NULL,
                            true, NULL, NULL);
}

static void put_angles(double *m, sk_mat3d local)
{
    double x, y, z;
    sk_hand_euler321_from_matrix(local, &x, &y, &z);
    m[0] = z * SK_RAD_TO_DEG;
    m[1] = y * SK_RAD_TO_DEG;
    m[2] = x * SK_RAD_TO_DEG;
}

/* The hand's motion as a BVH skeleton and motion (b initialised here). */
static sk_result build(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                       double frame_time, sk_bvh *b, sk_error *err)
{
    double zero[SK_HAND_DOF_COUNT] = {0};
    sk_hand_frames ref, cur;
    sk_hand_forward(s, zero, &ref);
    sk_bvh_init(b);
    int bvh_joint[SK_HAND_LINK_COUNT];
    sk_result r =
        sk_bvh_add_joint(b, "Hand", -1, sk_v3d(0, 0, 0), "xyzZYX", false, &bvh_joint[0], err);
    for (int f = 0; r == SK_OK && f < SK_HAND_FINGER_COUNT; f++)
        r = add_chain(b, s, &ref, sk__hand_first_link(f), bvh_joint[0], bvh_joint);
    if (r == SK_OK) r = sk_bvh_alloc_motion(b, frame_count, frame_time, err);
    if (r != SK_OK) return r;
    for (int fr = 0; fr < frame_count; fr++) {
        const double *q = dofs + (size_t)fr * SK_HAND_DOF_COUNT;
        double *m = b->motion + (size_t)fr * (size_t)b->channels_per_frame;
        sk_hand_forward(s, q, &cur);
        /* global rotation relative to rest: G = R R_ref^T; local = G_parent^T G */
        sk_mat3d g[SK_HAND_LINK_COUNT];
        for (int l = 0; l < SK_HAND_LINK_COUNT; l++)
            g[l] = sk_m3d_mul(cur.rotation[l], sk_m3d_transpose(ref.rotation[l]));
        m[0] = cur.point[0].x;
        m[1] = cur.point[0].y;
        m[2] = cur.point[0].z;
        put_angles(m + 3, g[0]);
        for (int l = 1; l < SK_HAND_LINK_COUNT; l++)
            put_angles(m + b->channel_first[bvh_joint[l]],
                       sk_m3d_mul(sk_m3d_transpose(g[s->parent[l]]), g[l]));
    }
    return SK_OK;
}

sk_result sk_hand_bvh_write_stream(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                                   double frame_time, FILE *out)
{
    sk_bvh *b = malloc(sizeof *b);
    if (!b) return SK_ERROR_OUT_OF_MEMORY;
    sk_result r = build(s, dofs, frame_count, frame_time, b, NULL);
    if (r == SK_OK) r = sk_bvh_write_stream(b, out);
    sk_bvh_free(b);
    free(b);
    return r;
}

sk_result sk_hand_bvh_write(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                            double frame_time, const char *path, sk_error *err)
{
    if (frame_count < 1) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no frames to write");
    if (!(frame_time > 0.0))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame time %g must be positive",
                       frame_time);
    sk_bvh *b = malloc(sizeof *b);
    if (!b) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    sk_result r = build(s, dofs, frame_count, frame_time, b, err);
    if (r == SK_OK) r = sk_bvh_write(b, path, err);
    sk_bvh_free(b);
    free(b);
    return r;
}
