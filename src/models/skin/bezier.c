/* Section shape (paper sec. 3.2.1 (2), Figs. 5-7, parameter 5): a chain of cubic Bezier
 * segments in the body plane (x', z'), x' from 0 at the centre to 10 at the boundary;
 * the height at x' is Bz(t) where Bx(t) = x' (x is monotone, so t is unique).
 * Each segment's z(x) is tabulated at 256 even steps of x with its exact value and slope
 * (t by bisection) and read back as a cubic Hermite curve: relative error below 1e-6, no
 * per-pixel root finding, and segment joints (where the slope may jump, Fig. 13a) fall on
 * table ends.
 * Roundness (parameter 6) scales the x of every control point but the last (which stays
 * on the boundary, x = 10) by g: below the last segment that is z(x' / g); the last
 * segment is solved by a Newton step from a table of t over (g, x'). */
#include <math.h>

#include "models/skin/skin_internal.h"

static void power_basis(const float p[4], double c[4])
{
    c[0] = p[0];
    c[1] = 3.0 * (p[1] - p[0]);
    c[2] = 3.0 * (p[2] - 2.0 * p[1] + p[0]);
    c[3] = p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0];
}
static double poly3(const double c[4], double t)
{
    return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
}
static double poly3_d(const double c[4], double t)
{
    return (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1];
}

/* t[i] in [0, 1] with Bx(t[i]) = xq[i] for a monotone Bx, i < n (bisection, for the tables;
 * the n searches run side by side, their steps independent of one another). */
static void solve_t(const double xc[4], const double *xq, int n, int iterations, double *t)
{
    enum { MAX = SK__PROFILE_TABLE };
    double lo[MAX], hi[MAX];
    for (int i = 0; i < n; i++) lo[i] = 0.0, hi[i] = 1.0;
    for (int it = 0; it < iterations; it++)
        for (int i = 0; i < n; i++) {
            double mid = 0.5 * (lo[i] + hi[i]);
            if (poly3(xc, mid) < xq[i])
                lo[i] = mid;
            else
                hi[i] = mid;
        }
    for (int i = 0; i < n; i++) t[i] = 0.5 * (lo[i] + hi[i]);
}

void sk__profile_prepare(sk__profile *p)
{
    for (int s = 0; s < p->segment_count; s++) {
        double xc[4], zc[4];
        power_basis(p->x[s], xc);
        power_basis(p->z[s], zc);
        double x0 = p->x[s][0], x3 = p->x[s][3];
        p->seg_x0[s] = (float)x0;
        p->seg_inv_w[s] = (float)((SK__PROFILE_TABLE - 1) / (x3 - x0));
        double zs[SK__PROFILE_TABLE], ms[SK__PROFILE_TABLE], xs[SK__PROFILE_TABLE];
        double ts[SK__PROFILE_TABLE];
        for (int i = 0; i < SK__PROFILE_TABLE; i++)
            xs[i] = x0 + (x3 - x0) * i / (SK__PROFILE_TABLE - 1);
        solve_t(xc, xs, SK__PROFILE_TABLE, 40, ts);
        for (int i = 0; i < SK__PROFILE_TABLE; i++) {
            double t = i == 0 ? 0.0 : (i == SK__PROFILE_TABLE - 1 ? 1.0 : ts[i]);
            double dx = poly3_d(xc, t), dz = poly3_d(zc, t);
            if (dx < 1e-9) {
                /* vertical tangent of x (repeated control x): chord slope */
                double t2 = t < 0.5 ? t + 1e-4 : t - 1e-4;
                dx = poly3(xc, t2) - poly3(xc, t);
                dz = poly3(zc, t2) - poly3(zc, t);
                if (fabs(dx) < 1e-12) dx = 1e-12;
            }
            zs[i] = poly3(zc, t);
            ms[i] = dz / dx * (x3 - x0) / (SK__PROFILE_TABLE - 1);
        }
        for (int i = 0; i + 1 < SK__PROFILE_TABLE; i++) {
            /* Hermite curve through (z, m) at both ends of the step, in power form */
            float *a = p->zpoly[s][i];
            a[0] = (float)zs[i];
            a[1] = (float)ms[i];
            a[2] = (float)(3.0 * (zs[i + 1] - zs[i]) - 2.0 * ms[i] - ms[i + 1]);
            a[3] = (float)(2.0 * (zs[i] - zs[i + 1]) + ms[i] + ms[i + 1]);
        }
    }
    int last = p->segment_count - 1;
    p->last_start = p->x[last][0];
    double xc[4], zc[4];
    power_basis(p->x[last], xc);
    power_basis(p->z[last], zc);
    for (int i = 0; i < 4; i++) p->last_xc[i] = (float)xc[i], p->last_zc[i] = (float)zc[i];
    p->last_xd3 = (float)(xc[3] - 10.0);
    p->last_zd[0] = (float)zc[1], p->last_zd[1] = (float)(2.0 * zc[2]);
    p->last_zd[2] = (float)(3.0 * zc[3]);
    /* t at the grid points (g, x'), then the bilinear coefficients of every cell */
    double tg[SK__GUESS_G + 1][SK__GUESS_X + 1];
    for (int gi = 0; gi <= SK__GUESS_G; gi++) {
        double g = p->g_min + (1.0 - p->g_min) * gi / SK__GUESS_G;
        double gc[4] = {g * xc[0], g * xc[1], g * xc[2], g * xc[3] + (1.0 - g) * 10.0};
        double xs[SK__GUESS_X + 1];
        for (int i = 0; i <= SK__GUESS_X; i++) xs[i] = 10.0 * i / SK__GUESS_X;
        solve_t(gc, xs, SK__GUESS_X + 1, 32, tg[gi]);
    }
    for (int gi = 0; gi < SK__GUESS_G; gi++)
        for (int i = 0; i < SK__GUESS_X; i++) {
            float *b = p->t_guess[gi][i];
            b[0] = (float)tg[gi][i];
            b[1] = (float)(tg[gi][i + 1] - tg[gi][i]);
            b[2] = (float)(tg[gi + 1][i] - tg[gi][i]);
            b[3] = (float)(tg[gi + 1][i + 1] - tg[gi + 1][i] - tg[gi][i + 1] + tg[gi][i]);
        }
    p->g_step_inv = p->g_min < 1.0f ? (float)SK__GUESS_G / (1.0f - p->g_min) : 0.0f;
}

void sk__last_segment_guess(const sk__profile *p, float g, float xq, sk__newton *s)
{
    const float *xc = p->last_xc;
    float *c = s->c;
    c[0] = g * xc[0], c[1] = g * xc[1], c[2] = g * xc[2], c[3] = 10.0f + g * p->last_xd3;
    /* g in [1 - roundness, 1) and x' in [0, 10) here; the clamps only guard rounding */
    float gu = (g - p->g_min) * p->g_step_inv, xu = xq * (SK__GUESS_X / 10.0f);
    if (!(gu > 0.0f)) gu = 0.0f;
    if (gu > SK__GUESS_G - 0.001f) gu = SK__GUESS_G - 0.001f;
    if (!(xu > 0.0f)) xu = 0.0f;
    if (xu > SK__GUESS_X - 0.001f) xu = SK__GUESS_X - 0.001f;
    int gi = (int)gu, xi = (int)xu;
    float gf = gu - (float)gi, xf = xu - (float)xi;
    const float *b = p->t_guess[gi][xi];
    float t = b[0] + b[1] * xf + gf * (b[2] + b[3] * xf);
    float dx = (3.0f * c[3] * t + 2.0f * c[2]) * t + c[1];
    if (dx < 1e-6f) dx = 1e-6f;
    s->t = t;
    s->inv = 1.0f / dx;
}

float sk__last_segment_finish(const sk__profile *p, float xq, const sk__newton *s, float *dz_dx,
                              float *dz_dg)
{
    const float *xc = p->last_xc, *zc = p->last_zc, *zd = p->last_zd, *c = s->c;
    /* One Newton step from the table's guess (error ~1e-3) leaves ~1e-6; the reciprocal
       of Bx' is refined for the new t instead of dividing again (relative error ~1e-6). */
    float t = s->t, inv = s->inv;
    float v = ((c[3] * t + c[2]) * t + c[1]) * t + c[0] - xq;
    t -= v * inv;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    float dx1 = (3.0f * c[3] * t + 2.0f * c[2]) * t + c[1];
    if (dx1 < 1e-6f) dx1 = 1e-6f;
    inv = inv * (2.0f - dx1 * inv);
    float slope = ((zd[2] * t + zd[1]) * t + zd[0]) * inv;
    *dz_dx = slope;
    /* dBx/dg at fixed t = Bx(t) - 10 t^3 */
    float xg = ((p->last_xd3 * t + xc[2]) * t + xc[1]) * t + xc[0];
    *dz_dg = -slope * xg;
    return ((zc[3] * t + zc[2]) * t + zc[1]) * t + zc[0];
}

/* The unscaled profile z(x) and its slope (the Hermite curve of the step holding x). */
static float profile_z(const sk__profile *p, float x, float *dz_dx)
{
    int last = p->segment_count - 1, j = 0;
    while (j < last && x > p->x[j][3]) j++;
    float u = (x - p->seg_x0[j]) * p->seg_inv_w[j];
    if (!(u > 0.0f)) u = 0.0f;
    if (u > (float)(SK__PROFILE_TABLE - 1)) u = (float)(SK__PROFILE_TABLE - 1);
    int i = (int)u;
    if (i > SK__PROFILE_TABLE - 2) i = SK__PROFILE_TABLE - 2;
    float t = u - (float)i;
    const float *a = p->zpoly[j][i];
    *dz_dx = ((3.0f * a[3] * t + 2.0f * a[2]) * t + a[1]) * p->seg_inv_w[j];
    return ((a[3] * t + a[2]) * t + a[1]) * t + a[0];
}
float sk__profile_scaled(const sk__profile *p, float g, float xq, float *dz_dx, float *dz_dg)
{
    float ig = g == 1.0f ? 1.0f : 1.0f / g, slope;
    float z = profile_z(p, xq * ig, &slope);
    *dz_dx = slope * ig;
    *dz_dg = -slope * xq * ig * ig;
    return z;
}
