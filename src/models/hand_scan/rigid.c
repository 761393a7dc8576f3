/* Rigid transforms x' = R x + t of the scan pipeline (thesis 4.1.1): where the cast lay in
 * each scan, and the registration of the back scan onto the palm scan. */
#include <math.h>

#include "models/hand_scan/scan_internal.h"

sk_hand_rigid sk_hand_rigid_identity(void)
{
    sk_hand_rigid t = {sk_m3d_identity(), {0.0, 0.0, 0.0}};
    return t;
}

sk_vec3d sk_hand_rigid_apply(const sk_hand_rigid *t, sk_vec3d p)
{
    return sk_v3d_add(sk_m3d_apply(t->rotation, p), t->translation);
}

sk_hand_rigid sk_hand_rigid_inverse(const sk_hand_rigid *t)
{
    sk_hand_rigid inv;
    inv.rotation = sk_m3d_transpose(t->rotation);
    inv.translation = sk_v3d_scale(sk_m3d_apply(inv.rotation, t->translation), -1.0);
    return inv;
}

sk_hand_rigid sk_hand_rigid_compose(const sk_hand_rigid *a, const sk_hand_rigid *b)
{
    sk_hand_rigid c;
    c.rotation = sk_m3d_mul(a->rotation, b->rotation);
    c.translation = sk_hand_rigid_apply(a, b->translation);
    return c;
}

void sk_hand_rigid_difference(const sk_hand_rigid *a, const sk_hand_rigid *b, double *angle_deg,
                              double *translation_mm)
{
    /* angle of R_a R_b^T from its trace: cos = (tr - 1) / 2 */
    sk_mat3d d = sk_m3d_mul(a->rotation, sk_m3d_transpose(b->rotation));
    double c = 0.5 * (d.m[0][0] + d.m[1][1] + d.m[2][2] - 1.0);
    c = c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c);
    /* acos loses precision near 0: use the skew part for small angles */
    double sx = d.m[2][1] - d.m[1][2], sy = d.m[0][2] - d.m[2][0], sz = d.m[1][0] - d.m[0][1];
    double s = 0.5 * sqrt(sx * sx + sy * sy + sz * sz);
    if (angle_deg) *angle_deg = atan2(s, c) * SK_RAD_TO_DEG;
    if (translation_mm) *translation_mm = sk_v3d_length(sk_v3d_sub(a->translation, b->translation));
}
