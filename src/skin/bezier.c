/* Section shape (paper sec. 3.2.1 (2), Figs. 5-7, parameter 5): a chain of cubic Bezier
 * segments in the body plane (x', z'), x' from 0 at the centre to 10 at the boundary;
 * the height at x' is Bz(t) where Bx(t) = x' (x is monotone, so t is unique).
 * Each segment's z(x) is tabulated at 256 even steps of x with its exact value and slope
 * (t by bisection) and read back as a cubic Hermite curve: relative error below 1e-6, no
 * per-pixel root finding, and segment joints (where the slope may jump, Fig. 13a) fall on
 * table ends.
 * Roundness (parameter 6) moves the control points along x by a factor g: the points of
 * every segment but the last scale by g (x' = g x), those of the last segment move by the
 * affine map that keeps the boundary at x = 10, so the curve stays monotone. */
#include <math.h>

#include "skin/skin_internal.h"

static void power_basis(const float p[4], double c[4])
{
    c[0] = p[0];
    c[1] = 3.0 * (p[1] - p[0]);
    c[2] = 3.0 * (p[2] - 2.0 * p[1] + p[0]);
    c[3] = p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0];
}
static double poly3(const double c[4], double t) { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
static double poly3_d(const double c[4], double t) { return (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]; }

void sk__profile_prepare(sk__profile *p)
{
    for (int s = 0; s < p->segment_count; s++) {
        double xc[4], zc[4];
        power_basis(p->x[s], xc);
        power_basis(p->z[s], zc);
        double x0 = p->x[s][0], x3 = p->x[s][3];
        p->seg_x0[s] = (float)x0;
        p->seg_inv_w[s] = (float)((SK__PROFILE_TABLE - 1) / (x3 - x0));
        for (int i = 0; i < SK__PROFILE_TABLE; i++) {
            double xq = x0 + (x3 - x0) * i / (SK__PROFILE_TABLE - 1);
            double lo = 0.0, hi = 1.0;
            for (int it = 0; it < 60; it++) {
                double mid = 0.5 * (lo + hi);
                if (poly3(xc, mid) < xq) lo = mid;
                else hi = mid;
            }
            double t = i == 0 ? 0.0 : (i == SK__PROFILE_TABLE - 1 ? 1.0 : 0.5 * (lo + hi));
            double dx = poly3_d(xc, t), dz = poly3_d(zc, t);
            if (dx < 1e-9) {
                /* vertical tangent of x (repeated control x): chord slope */
                double t2 = t < 0.5 ? t + 1e-4 : t - 1e-4;
                dx = poly3(xc, t2) - poly3(xc, t);
                dz = poly3(zc, t2) - poly3(zc, t);
                if (fabs(dx) < 1e-12) dx = 1e-12;
            }
            p->zx[s][i][0] = (float)poly3(zc, t);
            p->zx[s][i][1] = (float)(dz / dx * (x3 - x0) / (SK__PROFILE_TABLE - 1));
        }
    }
    p->last_start = p->x[p->segment_count - 1][0];
}

float sk__profile_z(const sk__profile *p, float x, float *dz_dx)
{
    int last = p->segment_count - 1, j = 0;
    while (j < last && x > p->x[j][3]) j++;
    float u = (x - p->seg_x0[j]) * p->seg_inv_w[j];
    if (!(u > 0.0f)) u = 0.0f;
    if (u > (float)(SK__PROFILE_TABLE - 1)) u = (float)(SK__PROFILE_TABLE - 1);
    int i = (int)u;
    if (i > SK__PROFILE_TABLE - 2) i = SK__PROFILE_TABLE - 2;
    float t = u - (float)i;
    const float(*tab)[2] = p->zx[j];
    float ih = p->seg_inv_w[j];
    float z0 = tab[i][0], z1 = tab[i + 1][0], m0 = tab[i][1], m1 = tab[i + 1][1];
    /* cubic Hermite on [0, 1] */
    float t2 = t * t, t3 = t2 * t;
    float z = (2 * t3 - 3 * t2 + 1) * z0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * z1 +
              (t3 - t2) * m1;
    float dz = (6 * t2 - 6 * t) * z0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * z1 +
               (3 * t2 - 2 * t) * m1;
    *dz_dx = dz * ih;
    return z;
}

float sk__bezier_solve(const sk__profile *p, float g, float xq, float *dz_dx, float *dz_dg)
{
    float ls = p->last_start;
    float x, dxdq, dxdg;
    if (g == 1.0f) {
        x = xq, dxdq = 1.0f, dxdg = 0.0f;
    } else if (xq <= g * ls) {
        float ig = 1.0f / g;
        x = xq * ig, dxdq = ig, dxdg = -xq * ig * ig;
    } else {
        float den = 10.0f - g * ls, k = (10.0f - ls) / den;
        x = ls + (xq - g * ls) * k;
        dxdq = k;
        dxdg = ls * k * (xq - 10.0f) / den;
    }
    float slope;
    float z = sk__profile_z(p, x, &slope);
    *dz_dx = slope * dxdq;
    *dz_dg = slope * dxdg;
    return z;
}
