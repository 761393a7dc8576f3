/* The skeleton's motion from motion capture (Shigemori & Kawai sec. 5: "bones move by
 * external input data"): a BVH bound to the character by joint names. Each character
 * joint takes the world rotation (relative to rest) of its motion joint, so motions whose
 * skeletons have joints the character lacks (or the reverse) still drive it; the root
 * takes its motion joint's world position in the motion's length unit. Frames are
 * interpolated by slerp and lerp, so the simulation can sample any time. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

struct sk_tissue_bvh_motion {
    const sk_tissue_model *model;
    int joints;                      /* character joints */
    int bound[SK_TISSUE_MAX_JOINTS]; /* motion joint of each character joint, or -1 */
    int bound_count;
    int frames;
    double frame_time;
    sk_quatd *world; /* frames x joints: world rotation of bound joints */
    sk_vec3d *root;  /* frames: root position, mm */
    bool moves_root;
};

/* "ns:Name" -> "Name" */
static const char *without_namespace(const char *name)
{
    const char *c = strrchr(name, ':');
    return c ? c + 1 : name;
}

static int bind_joint(const sk_tissue_character_desc *d, const sk_bvh *bvh, int j)
{
    const char *name = d->joints[j].name;
    for (int k = 0; k < d->joint_map_count; k++)
        if (strcmp(d->joint_map[k].joint, name) == 0) {
            int b = sk_bvh_find(bvh, d->joint_map[k].motion);
            if (b >= 0 && !bvh->end_site[b]) return b;
        }
    int b = sk_bvh_find(bvh, name);
    if (b >= 0 && !bvh->end_site[b]) return b;
    for (int k = 0; k < bvh->joint_count; k++)
        if (!bvh->end_site[k] && strcmp(without_namespace(bvh->name[k]), name) == 0) return k;
    return -1;
}

sk_result sk_tissue_bvh_motion_create(const sk_tissue_model *model, const sk_bvh *bvh,
                                      double unit_mm, sk_tissue_bvh_motion **out, sk_error *err)
{
    *out = NULL;
    if (!(unit_mm >= 0.0) || unit_mm > 1e4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "motion unit %g mm is out of range [0, 1e4] (0 = the character's)", unit_mm);
    if (bvh->frame_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "the motion has no frames");
    const sk_tissue_character_desc *d = &model->desc;
    double unit = unit_mm > 0 ? unit_mm : d->motion_unit_mm;
    sk_tissue_bvh_motion *m = calloc(1, sizeof *m);
    if (!m) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    m->model = model;
    m->joints = d->joint_count;
    for (int j = 0; j < m->joints; j++) {
        m->bound[j] = bind_joint(d, bvh, j);
        m->bound_count += m->bound[j] >= 0;
    }
    if (m->bound_count == 0) {
        free(m);
        return sk_fail(err, SK_ERROR_NOT_FOUND,
                       "no joint of the motion drives the character \"%s\" (its root is \"%s\"; "
                       "bind other names "
                       "with the character's joint_map)",
                       d->name, d->joints[model->skeleton.root].name);
    }
    m->frames = bvh->frame_count;
    m->frame_time = bvh->frame_time;
    m->world = malloc((size_t)m->frames * (size_t)m->joints * sizeof *m->world);
    m->root = malloc((size_t)m->frames * sizeof *m->root);
    sk_mat3d *rot = malloc(SK_BVH_MAX_JOINTS * sizeof *rot);
    sk_vec3d *pos = malloc(SK_BVH_MAX_JOINTS * sizeof *pos);
    if (!m->world || !m->root || !rot || !pos) {
        free(rot);
        free(pos);
        sk_tissue_bvh_motion_destroy(m);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %d frames of motion",
                       bvh->frame_count);
    }
    int root = model->skeleton.root, broot = m->bound[root];
    m->moves_root = broot >= 0;
    for (int f = 0; f < m->frames; f++) {
        sk_bvh_pose(bvh, f, rot, pos);
        for (int j = 0; j < m->joints; j++) {
            sk_quatd q = m->bound[j] >= 0 ? sk_m3d_to_qd(rot[m->bound[j]]) : sk_qd_identity();
            /* the same hemisphere as the previous frame, so interpolation takes the short way */
            if (f > 0 &&
                sk_qd_dot(q, m->world[(size_t)(f - 1) * (size_t)m->joints + (size_t)j]) < 0.0)
                q = sk_qd(-q.w, -q.x, -q.y, -q.z);
            m->world[(size_t)f * (size_t)m->joints + (size_t)j] = q;
        }
        m->root[f] = broot >= 0 ? sk_v3d_scale(pos[broot], unit) : model->skeleton.rest[root];
    }
    free(rot);
    free(pos);
    *out = m;
    return SK_OK;
}

void sk_tissue_bvh_motion_destroy(sk_tissue_bvh_motion *m)
{
    if (!m) return;
    free(m->world);
    free(m->root);
    free(m);
}

int sk_tissue_bvh_motion_bound_joints(const sk_tissue_bvh_motion *m) { return m->bound_count; }

static void sample(void *user, double seconds, sk_quatd *local, sk_vec3d *root_mm)
{
    const sk_tissue_bvh_motion *m = user;
    const sk__skeleton *s = &m->model->skeleton;
    double f = seconds / m->frame_time;
    int f0;
    double t;
    if (!(f > 0.0)) {
        f0 = 0;
        t = 0.0;
    } else if (f >= m->frames - 1) {
        f0 = m->frames - 1;
        t = 0.0;
    } else {
        f0 = (int)floor(f);
        t = f - f0;
    }
    int f1 = f0 + 1 < m->frames ? f0 + 1 : f0;
    const sk_quatd *a = m->world + (size_t)f0 * (size_t)m->joints,
                   *b = m->world + (size_t)f1 * (size_t)m->joints;
    sk_quatd world[SK_TISSUE_MAX_JOINTS];
    /* unbound joints turn with their parent */
    for (int k = 0; k < s->count; k++) {
        int j = s->order[k], p = s->parent[j];
        if (m->bound[j] >= 0)
            world[j] = t > 0.0 ? sk_qd_slerp(a[j], b[j], t) : a[j];
        else
            world[j] = p >= 0 ? world[p] : sk_qd_identity();
        local[j] = p >= 0 ? sk_qd_normalize(sk_qd_mul(sk_qd_conj(world[p]), world[j])) : world[j];
    }
    sk_vec3d r0 = m->root[f0], r1 = m->root[f1];
    *root_mm = sk_v3d_add(r0, sk_v3d_scale(sk_v3d_sub(r1, r0), t));
}

sk_tissue_motion sk_tissue_bvh_motion_get(const sk_tissue_bvh_motion *m)
{
    sk_tissue_motion out = {sample, (void *)m, (m->frames - 1) * m->frame_time};
    return out;
}
