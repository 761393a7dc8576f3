/* 3-2-1 Euler frames and forward kinematics, thesis 3.1.1-3.1.2: A_{j,j-1} =
 * A1(th_j1) A2(th_j2) A3(th_j3) (eq. 3.4), frames chained along each finger (eq. 3.5),
 * joint positions x = r_-1 + sum_j A_{j-1} r_j (eq. 3.6). The left hand is the mirror
 * image of the right one in the plane x = 0. */
#include <math.h>

#include "models/hand/hand_internal.h"

/* cos and sin of an angle; most joints turn about one or two of their three axes, and
   the others' 0 needs no library call (sin(+-0) = +-0 and cos(+-0) = 1 exactly). */
static inline void cos_sin(double a, double *c, double *s)
{
    if (a == 0.0) {
        *c = 1.0;
        *s = a;
    } else {
        *c = cos(a);
        *s = sin(a);
    }
}

sk_mat3d sk_hand_euler321(double x, double y, double z)
{
    /* The direction-cosine product A1 A2 A3 of the thesis maps parent coordinates to
       child coordinates; its transpose, the rotation of the child frame in the parent,
       is Rz(z) Ry(y) Rx(x). Written out to keep the chain cheap. */
    double cx, sx, cy, sy, cz, sz;
    cos_sin(x, &cx, &sx);
    cos_sin(y, &cy, &sy);
    cos_sin(z, &cz, &sz);
    sk_mat3d r = {{{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                   {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                   {-sy, cy * sx, cy * cx}}};
    return r;
}

void sk_hand_euler321_from_matrix(sk_mat3d r, double *x, double *y, double *z)
{
    double cy = hypot(r.m[0][0], r.m[1][0]);
    *y = atan2(-r.m[2][0], cy);
    if (cy > 1e-12) {
        *z = atan2(r.m[1][0], r.m[0][0]);
        *x = atan2(r.m[2][1], r.m[2][2]);
    } else {
        /* gimbal lock: only z - x (or z + x) is defined; put it all in x */
        *z = 0.0;
        *x = atan2(-r.m[1][2], r.m[1][1]);
    }
}

/* Euler angles (x, y, z) of a link's joint from the DOF values (right-hand signs). */
static void link_angles(int link, const double *dofs, double angle[3])
{
    angle[0] = angle[1] = angle[2] = 0.0;
    int count = 0;
    int first = sk__hand_first_dof_of_link(link, &count);
    for (int i = first; i < first + count; i++) {
        const sk_hand_dof_info *info = sk_hand_dof(i);
        if (info->translation) continue;
        angle[info->axis - 'X'] = info->sign * dofs[i];
    }
}

static sk_mat3d mirror_rotation(sk_mat3d r)
{
    /* M R M with M = diag(-1, 1, 1) */
    r.m[0][1] = -r.m[0][1];
    r.m[0][2] = -r.m[0][2];
    r.m[1][0] = -r.m[1][0];
    r.m[2][0] = -r.m[2][0];
    return r;
}

void sk_hand_forward(const sk_hand_skeleton *s, const double dofs[SK_HAND_DOF_COUNT],
                     sk_hand_frames *out)
{
    double a[3];
    link_angles(0, dofs, a);
    out->rotation[0] = sk_hand_euler321(a[0], a[1], a[2]);
    out->point[0] = sk_v3d(dofs[0], dofs[1], dofs[2]);
    for (int link = 1; link < SK_HAND_LINK_COUNT; link++) {
        int parent = s->parent[link];
        const sk_mat3d *rp = &out->rotation[parent];
        sk_vec3d base =
            sk_v3d_add(out->point[sk_hand_link_point(parent)], sk_m3d_apply(*rp, s->offset[link]));
        out->point[sk_hand_link_point(link)] = base;
        link_angles(link, dofs, a);
        out->rotation[link] =
            sk_m3d_mul(sk_m3d_mul(*rp, s->mount[link]), sk_hand_euler321(a[0], a[1], a[2]));
        /* the last link of a finger ends at the fingertip */
        bool last = link == SK_HAND_LINK_COUNT - 1 || s->parent[link + 1] != link;
        if (last) {
            sk_vec3d tip = sk_m3d_apply(out->rotation[link], sk_v3d(0.0, s->length[link], 0.0));
            out->point[sk_hand_link_end_point(link)] = sk_v3d_add(base, tip);
        }
    }
    if (s->side == SK_HAND_SIDE_LEFT) {
        for (int i = 0; i < SK_HAND_POINT_COUNT; i++) out->point[i].x = -out->point[i].x;
        for (int i = 0; i < SK_HAND_LINK_COUNT; i++)
            out->rotation[i] = mirror_rotation(out->rotation[i]);
    }
}
