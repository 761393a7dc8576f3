/* The thesis's deformation defect (4.1.5): polygons spanning two links stretch, and on
 * the flexion side they sink into the finger. Measured on a pose for one finger's links:
 * the volume the mesh loses (divergence theorem) and the vertices of a moved link that
 * end up inside the neighbouring segment's flesh (that segment's primitive, carried
 * rigidly by its link). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

static double mesh_volume(const float *pos, const uint32_t *tri, size_t T)
{
    double v = 0;
    for (size_t t = 0; t < T; t++) {
        const float *a = pos + 3 * tri[3 * t], *b = pos + 3 * tri[3 * t + 1],
                    *c = pos + 3 * tri[3 * t + 2];
        v += (double)a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) -
             (double)a[1] * ((double)b[0] * c[2] - (double)b[2] * c[0]) +
             (double)a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
    }
    return v / 6.0;
}

/* The main (non-nail) primitive of a link. */
static const sk__hand_prim *link_prim(const sk__hand_field *f, int link)
{
    for (int i = 0; i < f->count; i++)
        if (f->prim[i].link == link && !f->prim[i].nail) return &f->prim[i];
    return NULL;
}

sk_result sk_hand_surface_defect(const sk_hand_surface *s, const double dofs[SK_HAND_DOF_COUNT],
                                 sk_hand_skinning method, sk_hand_finger finger,
                                 sk_hand_defect *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    if ((int)finger < 0 || finger >= SK_HAND_FINGER_COUNT)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "finger = %d is out of range [0, 4]",
                       (int)finger);
    sk_mesh posed;
    sk_result r = sk_hand_surface_pose(s, dofs, method, &posed, err);
    if (r != SK_OK) return r;
    const sk_mesh *m = &s->mesh;
    out->rest_volume_mm3 = mesh_volume(m->positions, m->indices, m->triangle_count);
    out->posed_volume_mm3 = mesh_volume(posed.positions, posed.indices, posed.triangle_count);
    out->volume_lost_mm3 = out->rest_volume_mm3 - out->posed_volume_mm3;
    int first = sk__hand_first_link(finger), count = sk__hand_link_count_of_finger(finger);
    /* the finger's flesh volume: its phalanges as elliptic frusta */
    double finger_volume = 0;
    for (int k = 1; k < count; k++) {
        const sk__hand_prim *p = link_prim(&s->field, first + k);
        if (!p) continue;
        finger_volume += SK_PI * p->length *
                         (p->rx[0] * p->rz[0] + p->rx[1] * p->rz[1] +
                          0.5 * (p->rx[0] * p->rz[1] + p->rx[1] * p->rz[0])) /
                         3.0;
    }
    out->volume_lost_percent = finger_volume > 0 ? 100.0 * out->volume_lost_mm3 / finger_volume : 0;
    sk_hand_frames fr;
    sk_hand_forward(&s->skeleton, dofs, &fr);
    bool left = s->skeleton.side == SK_HAND_SIDE_LEFT;
    const uint16_t *nearest = s->links[0];
    for (size_t v = 0; v < m->vertex_count; v++) {
        int link = nearest[4 * v];
        if (link < first || link >= first + count) continue;
        out->vertex_count++;
        int neighbours[2] = {s->skeleton.parent[link], link + 1 < first + count ? link + 1 : -1};
        for (int k = 0; k < 2; k++) {
            int nlink = neighbours[k];
            const sk__hand_prim *p = nlink >= 0 ? link_prim(&s->field, nlink) : NULL;
            if (!p) continue;
            /* the posed vertex in the neighbour's relaxed frame */
            sk_vec3d x = sk_v3d(posed.positions[3 * v], posed.positions[3 * v + 1],
                                posed.positions[3 * v + 2]);
            sk_vec3d o = fr.point[sk_hand_link_point(nlink)],
                     b = s->bind.point[sk_hand_link_point(nlink)];
            sk_vec3d local = sk_m3d_apply(sk_m3d_transpose(fr.rotation[nlink]), sk_v3d_sub(x, o));
            sk_vec3d rest = sk_v3d_add(b, sk_m3d_apply(s->bind.rotation[nlink], local));
            if (left) rest.x = -rest.x;
            double e = sk__hand_prim_eval(p, rest);
            if (e < -0.5) {
                out->inside_count++;
                if (-e > out->max_depth_mm) out->max_depth_mm = -e;
                break;
            }
        }
    }
    sk_mesh_free(&posed);
    return SK_OK;
}
