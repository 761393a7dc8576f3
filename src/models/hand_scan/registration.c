/* Registration of the back scan onto the palm scan by least squares on the 9 markers
 * (thesis 4.1.1; the kind of transform is not stated there, so it is rigid): the Kabsch
 * solution, R = V diag(1, 1, det(V U^T)) U^T from the SVD H = U S V^T of the
 * cross-covariance of the centred point sets (LAPACKE dgesvd), t = mean(to) - R mean(from).
 * The determinant term keeps R a rotation when the points are nearly coplanar. */
#include <lapacke.h>
#include <math.h>

#include "models/hand_scan/scan_internal.h"

sk_result sk_hand_register_rigid(const sk_vec3d *from, const sk_vec3d *to, int count,
                                 sk_hand_rigid *out, double *residual_mm, sk_error *err)
{
    if (count < 3)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "registration needs 3 or more points (got %d)", count);
    sk_vec3d cf = {0, 0, 0}, ct = {0, 0, 0};
    for (int i = 0; i < count; i++) {
        if (!isfinite(from[i].x + from[i].y + from[i].z) || !isfinite(to[i].x + to[i].y + to[i].z))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "registration: point %d is not finite",
                           i);
        cf = sk_v3d_add(cf, from[i]);
        ct = sk_v3d_add(ct, to[i]);
    }
    cf = sk_v3d_scale(cf, 1.0 / count);
    ct = sk_v3d_scale(ct, 1.0 / count);
    /* H = sum (from_i - cf)(to_i - ct)^T, column-major for LAPACK */
    double h[9] = {0}, spread = 0.0;
    for (int i = 0; i < count; i++) {
        sk_vec3d a = sk_v3d_sub(from[i], cf), b = sk_v3d_sub(to[i], ct);
        double av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z};
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) h[c * 3 + r] += av[r] * bv[c];
        spread += sk_v3d_dot(a, a);
    }
    double s[3], u[9], vt[9], superb[2];
    lapack_int info =
        LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'A', 'A', 3, 3, h, 3, s, u, 3, vt, 3, superb);
    if (info != 0)
        return sk_fail(err, SK_ERROR_NUMERIC, "registration: the SVD did not converge (%d)",
                       (int)info);
    /* the points must not lie on one line: the second singular value carries the rotation
       about that line */
    if (!(s[1] > 1e-12 * (spread > 0 ? spread : 1.0)))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "registration: the points are (nearly) on one line");
    /* R = V D U^T; V = vt^T. Element (r, c) of M column-major is m[c * 3 + r]. */
    double uu[3][3], vv[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            uu[r][c] = u[c * 3 + r];
            vv[r][c] = vt[r * 3 + c]; /* V(r, c) = VT(c, r) */
        }
    double det_v = vv[0][0] * (vv[1][1] * vv[2][2] - vv[1][2] * vv[2][1]) -
                   vv[0][1] * (vv[1][0] * vv[2][2] - vv[1][2] * vv[2][0]) +
                   vv[0][2] * (vv[1][0] * vv[2][1] - vv[1][1] * vv[2][0]);
    double det_u = uu[0][0] * (uu[1][1] * uu[2][2] - uu[1][2] * uu[2][1]) -
                   uu[0][1] * (uu[1][0] * uu[2][2] - uu[1][2] * uu[2][0]) +
                   uu[0][2] * (uu[1][0] * uu[2][1] - uu[1][1] * uu[2][0]);
    double d[3] = {1.0, 1.0, det_u * det_v < 0.0 ? -1.0 : 1.0};
    sk_hand_rigid t;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double sum = 0.0;
            for (int k = 0; k < 3; k++) sum += vv[r][k] * d[k] * uu[c][k];
            t.rotation.m[r][c] = sum;
        }
    t.translation = sk_v3d_sub(ct, sk_m3d_apply(t.rotation, cf));
    if (residual_mm)
        for (int i = 0; i < count; i++)
            residual_mm[i] = sk_v3d_length(sk_v3d_sub(sk_hand_rigid_apply(&t, from[i]), to[i]));
    *out = t;
    return SK_OK;
}
