/* Least-squares fitting of one bicubic Bezier patch to range data, thesis 4.1.4:
 * chord-length parameters (the parameterisation given with eq. 4.4), the control points
 * B = (A^T A)^-1 A^T S (eqs. 4.4, 4.5), then parameter correction: a perpendicular from
 * every data point to the patch, u_new = u_old + delta (u_{i+1} - u_{i-1}) / 2 (eq. 4.6)
 * with delta = (P - S(u, v)) . S_u / |S_u| (eq. 4.7), v alike, and a refit, repeated until
 * the updates are small.
 *
 * Eq. (4.6) as printed multiplies a length (delta, mm) by a parameter step; the factor
 * that makes it a parameter change is the parameter spacing per unit length along the
 * patch, (u_{i+1} - u_{i-1}) / |Q_{i+1} - Q_{i-1}| for chord-length parameters, which is
 * 1 / |S_u| on the patch itself. So the step here is delta / |S_u| (the foot-point Newton
 * step of the parameter-correction method the thesis cites); a step that would move the
 * point's foot farther from it is halved, so no correction ever increases the error. */
#include <lapacke.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_scan/scan_internal.h"

void sk_hand_chord_parameters(const sk_vec3d *row, size_t count, double *u)
{
    if (count == 0) return;
    if (count == 1) {
        u[0] = 0.5;
        return;
    }
    double total = 0.0;
    for (size_t i = 1; i < count; i++) total += sqrt(sk__dist2(row[i], row[i - 1]));
    u[0] = 0.0;
    double run = 0.0;
    for (size_t i = 1; i < count; i++) {
        run += sqrt(sk__dist2(row[i], row[i - 1]));
        u[i] = total > 0.0 ? run / total : (double)i / (double)(count - 1);
    }
    u[count - 1] = 1.0;
}

/* Eq. (4.5) on points relative to their centroid (a ridge, if one is needed, then pulls
 * undetermined control points to the centroid rather than to the origin). */
static sk_result least_squares(const sk_vec3d *pts, size_t n, const double *u, const double *v,
                               sk_vec3d centroid, sk_hand_patch *out, bool *regularised,
                               sk_error *err)
{
    double m[16 * 16] = {0}, rhs[16 * 3] = {0};
    for (size_t k = 0; k < n; k++) {
        double bu[4], bv[4], b[16];
        sk_hand_bernstein3(u[k], bu);
        sk_hand_bernstein3(v[k], bv);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) b[4 * i + j] = bu[i] * bv[j];
        sk_vec3d p = sk_v3d_sub(pts[k], centroid);
        for (int a = 0; a < 16; a++) {
            double ba = b[a];
            double *row = m + 16 * a;
            for (int c = a; c < 16; c++) row[c] += ba * b[c];
            rhs[3 * a] += ba * p.x;
            rhs[3 * a + 1] += ba * p.y;
            rhs[3 * a + 2] += ba * p.z;
        }
    }
    double trace = 0.0;
    for (int a = 0; a < 16; a++) trace += m[17 * a];
    double mm[16 * 16], rr[16 * 3];
    memcpy(mm, m, sizeof mm);
    memcpy(rr, rhs, sizeof rr);
    lapack_int info = LAPACKE_dposv(LAPACK_ROW_MAJOR, 'U', 16, 3, mm, 16, rr, 3);
    if (info > 0) {
        /* A^T A singular: too few points, or all of them on a few parameter lines */
        memcpy(mm, m, sizeof mm);
        memcpy(rr, rhs, sizeof rr);
        double ridge = 1e-9 * (trace > 0.0 ? trace / 16.0 : 1.0);
        for (int a = 0; a < 16; a++) mm[17 * a] += ridge;
        info = LAPACKE_dposv(LAPACK_ROW_MAJOR, 'U', 16, 3, mm, 16, rr, 3);
        if (regularised) *regularised = true;
    }
    if (info != 0)
        return sk_fail(err, SK_ERROR_NUMERIC,
                       "patch fit: the normal equations could not be solved (%d)", (int)info);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            const double *c = rr + 3 * (4 * i + j);
            out->p[i][j] = sk_v3d(c[0] + centroid.x, c[1] + centroid.y, c[2] + centroid.z);
        }
    return SK_OK;
}

static double rms(const sk_hand_patch *patch, const sk_vec3d *pts, size_t n, const double *u,
                  const double *v)
{
    double sum = 0.0;
    for (size_t k = 0; k < n; k++)
        sum += sk__dist2(pts[k], sk_hand_patch_eval(patch, u[k], v[k], NULL, NULL));
    return sqrt(sum / (double)n);
}

static inline double clamp01(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

/* One step of eqs. (4.6, 4.7) moving (u, v) of a point toward its foot on the patch,
 * halved until it brings the foot no farther. Returns the squared distance before the
 * step (the point's residual for the patch as it is) and the parameter change. */
static double correct_point(const sk_hand_patch *patch, sk_vec3d p, double *u, double *v,
                            double *change)
{
    sk_vec3d su, sv;
    sk_vec3d s = sk_hand_patch_eval(patch, *u, *v, &su, &sv);
    double d0 = sk__dist2(p, s);
    sk_vec3d e = sk_v3d_sub(p, s);
    double lu = sk_v3d_dot(su, su), lv = sk_v3d_dot(sv, sv);
    /* eq. (4.7): delta = e . S_u / |S_u|; eq. (4.6) scaled by 1 / |S_u| (file comment) */
    double du = lu > 1e-24 ? sk_v3d_dot(e, su) / lu : 0.0;
    double dv = lv > 1e-24 ? sk_v3d_dot(e, sv) / lv : 0.0;
    *change = 0.0;
    for (int half = 0; half < 6; half++) {
        double nu = clamp01(*u + du), nv = clamp01(*v + dv);
        double d1 = sk__dist2(p, sk_hand_patch_eval(patch, nu, nv, NULL, NULL));
        if (d1 <= d0) {
            double cu = fabs(nu - *u), cv = fabs(nv - *v);
            *change = cu > cv ? cu : cv;
            *u = nu, *v = nv;
            break;
        }
        du *= 0.5;
        dv *= 0.5;
    }
    return d0;
}

sk_result sk_hand_patch_fit(const sk_vec3d *points, size_t count, double *u, double *v,
                            const sk_hand_patch_fit_desc *desc, sk_hand_patch *out,
                            sk_hand_patch_fit_info *info, double *rms_history, sk_error *err)
{
    sk_hand_patch_fit_desc d = desc ? *desc : (sk_hand_patch_fit_desc){0};
    const sk_schema *schema = sk_schema_find(&sk_hand_scan_schema, "fit")->schema;
    sk_schema_apply_defaults(schema, &d);
    if (d.min_improvement < 0) d.min_improvement = 0;
    sk_result r = sk_schema_check(schema, &d, "fit", err);
    if (r != SK_OK) return r;
    if (count < 16)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch fit: %zu points (16 or more needed)",
                       count);
    sk_vec3d centroid = {0, 0, 0};
    for (size_t k = 0; k < count; k++) {
        if (!isfinite(points[k].x + points[k].y + points[k].z))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "patch fit: point %zu is not finite", k);
        if (!(u[k] >= 0.0 && u[k] <= 1.0 && v[k] >= 0.0 && v[k] <= 1.0))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "patch fit: parameters (%g, %g) of point %zu are not in [0, 1]", u[k],
                           v[k], k);
        centroid = sk_v3d_add(centroid, points[k]);
    }
    centroid = sk_v3d_scale(centroid, 1.0 / (double)count);
    sk_hand_patch_fit_info fi = {0};
    sk_hand_patch patch = *out;
    r = least_squares(points, count, u, v, centroid, &patch, &fi.regularised, err);
    if (r != SK_OK) return r;
    fi.rms_initial_mm = fi.rms_final_mm = rms(&patch, points, count, u, v);
    if (rms_history) rms_history[0] = fi.rms_initial_mm;
    double previous = fi.rms_initial_mm;
    for (int it = 1; it <= d.max_iterations && !d.no_correction; it++) {
        double largest = 0.0, sum = 0.0;
        for (size_t k = 0; k < count; k++) {
            double moved;
            sum += correct_point(&patch, points[k], &u[k], &v[k], &moved);
            if (moved > largest) largest = moved;
        }
        /* the residuals before this correction are those of the last fit */
        double now = sqrt(sum / (double)count);
        if (it > 1) {
            if (rms_history) rms_history[it - 1] = now;
            if (now > (1.0 - d.min_improvement) * previous) {
                /* stalled: the last correction and fit stand */
                fi.converged = true;
                break;
            }
            previous = now;
        }
        r = least_squares(points, count, u, v, centroid, &patch, &fi.regularised, err);
        if (r != SK_OK) return r;
        fi.iterations = it;
        fi.last_update = largest;
        if (largest < d.tolerance) {
            fi.converged = true;
            break;
        }
    }
    if (fi.iterations > 0) {
        fi.rms_final_mm = rms(&patch, points, count, u, v);
        if (rms_history) rms_history[fi.iterations] = fi.rms_final_mm;
    }
    /* keep the caller's link, side and place in the layout */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) out->p[i][j] = patch.p[i][j];
    if (info) *info = fi;
    return SK_OK;
}
