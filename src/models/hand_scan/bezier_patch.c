/* The bicubic Bezier patch of thesis 4.1.4, eq. (4.3): Q(u, v) = u^T G P G^T v. As printed,
 * G's last row starts with +1; the cubic Bernstein basis (and the patch's own corner
 * property Q(0, 0) = P00) needs -1, so G here has rows [1 0 0 0], [-3 3 0 0], [3 -6 3 0],
 * [-1 3 -3 1], and u^T G = [(1-u)^3, 3u(1-u)^2, 3u^2(1-u), u^3]. */
#include "models/hand_scan/scan_internal.h"

void sk_hand_bernstein3(double t, double out[4])
{
    double s = 1.0 - t;
    out[0] = s * s * s;
    out[1] = 3.0 * t * s * s;
    out[2] = 3.0 * t * t * s;
    out[3] = t * t * t;
}

/* Derivatives of the four Bernstein values. */
static void bernstein3_derivative(double t, double out[4])
{
    double s = 1.0 - t;
    out[0] = -3.0 * s * s;
    out[1] = 3.0 * s * s - 6.0 * t * s;
    out[2] = 6.0 * t * s - 3.0 * t * t;
    out[3] = 3.0 * t * t;
}

sk_vec3d sk_hand_patch_eval(const sk_hand_patch *patch, double u, double v, sk_vec3d *du,
                            sk_vec3d *dv)
{
    double bu[4], bv[4], du_[4], dv_[4];
    sk_hand_bernstein3(u, bu);
    sk_hand_bernstein3(v, bv);
    if (du) bernstein3_derivative(u, du_);
    if (dv) bernstein3_derivative(v, dv_);
    sk_vec3d q = {0, 0, 0}, qu = {0, 0, 0}, qv = {0, 0, 0};
    for (int i = 0; i < 4; i++) {
        /* the row of P_i. weighted by the v basis, then by the u basis */
        sk_vec3d row = {0, 0, 0}, row_v = {0, 0, 0};
        for (int j = 0; j < 4; j++) {
            row = sk_v3d_add(row, sk_v3d_scale(patch->p[i][j], bv[j]));
            if (dv) row_v = sk_v3d_add(row_v, sk_v3d_scale(patch->p[i][j], dv_[j]));
        }
        q = sk_v3d_add(q, sk_v3d_scale(row, bu[i]));
        if (du) qu = sk_v3d_add(qu, sk_v3d_scale(row, du_[i]));
        if (dv) qv = sk_v3d_add(qv, sk_v3d_scale(row_v, bu[i]));
    }
    if (du) *du = qu;
    if (dv) *dv = qv;
    return q;
}
