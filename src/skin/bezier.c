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

#include "skin/skin_internal.h"

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

/* t in [0, 1] with Bx(t) = xq for a monotone Bx (bisection, for the tables). */
static double solve_t(const double xc[4], double xq, int iterations)
{
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < iterations; it++) {
        double mid = 0.5 * (lo + hi);
        if (poly3(xc, mid) < xq)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
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
        for (int i = 0; i < SK__PROFILE_TABLE; i++) {
            double xq = x0 + (x3 - x0) * i / (SK__PROFILE_TABLE - 1);
            double t = i == 0 ? 0.0 : (i == SK__PROFILE_TABLE - 1 ? 1.0 : solve_t(xc, xq, 40));
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
    int last = p->segment_count - 1;
    p->last_start = p->x[last][0];
    double xc[4], zc[4];
    power_basis(p->x[last], xc);
    power_basis(p->z[last], zc);
    for (int i = 0; i < 4; i++) p->last_xc[i] = (float)xc[i], p->last_zc[i] = (float)zc[i];
    for (int gi = 0; gi < 9; gi++) {
        double g = p->g_min + (1.0 - p->g_min) * gi / 8.0;
        double gc[4] = {g * xc[0], g * xc[1], g * xc[2], g * xc[3] + (1.0 - g) * 10.0};
        for (int i = 0; i < 129; i++) p->t_guess[gi][i] = (float)solve_t(gc, 10.0 * i / 128.0, 32);
    }
    p->g_step_inv = p->g_min < 1.0f ? 8.0f / (1.0f - p->g_min) : 0.0f;
}

void sk__last_segment_guess(const sk__profile *p, float g, float xq, sk__newton *s)
{
    const float *xc = p->last_xc;
    float *c = s->c;
    c[0] = g * xc[0], c[1] = g * xc[1], c[2] = g * xc[2], c[3] = g * xc[3] + (1.0f - g) * 10.0f;
    float gu = (g - p->g_min) * p->g_step_inv;
    if (!(gu > 0.0f)) gu = 0.0f;
    if (gu > 7.999f) gu = 7.999f;
    int gi = (int)gu;
    float gf = gu - (float)gi;
    float xu = xq * 12.8f;
    if (!(xu > 0.0f)) xu = 0.0f;
    if (xu > 127.999f) xu = 127.999f;
    int xi = (int)xu;
    float xf = xu - (float)xi;
    const float *r0 = p->t_guess[gi], *r1 = p->t_guess[gi + 1];
    float t0 = r0[xi] + (r0[xi + 1] - r0[xi]) * xf, t1 = r1[xi] + (r1[xi + 1] - r1[xi]) * xf;
    float t = p->g_step_inv > 0.0f ? t0 + (t1 - t0) * gf : t0;
    float dx = (3.0f * c[3] * t + 2.0f * c[2]) * t + c[1];
    if (dx < 1e-6f) dx = 1e-6f;
    s->t = t;
    s->inv = 1.0f / dx;
}

float sk__last_segment_finish(const sk__profile *p, float xq, const sk__newton *s,
                              float *dz_dx, float *dz_dg)
{
    const float *xc = p->last_xc, *zc = p->last_zc, *c = s->c;
    /* One Newton step from the table's guess (error ~1e-3) leaves ~1e-6; the reciprocal
       of Bx' is refined for the new t instead of dividing again (relative error ~1e-6). */
    float t = s->t, inv = s->inv;
    float v = ((c[3] * t + c[2]) * t + c[1]) * t + c[0] - xq;
    t -= v * inv;
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    float dx1 = (3.0f * c[3] * t + 2.0f * c[2]) * t + c[1];
    if (dx1 < 1e-6f) dx1 = 1e-6f;
    inv = inv * (2.0f - dx1 * inv);
    float dz = (3.0f * zc[3] * t + 2.0f * zc[2]) * t + zc[1];
    float slope = dz * inv;
    *dz_dx = slope;
    /* dBx/dg at fixed t = Bx(t) - 10 t^3 */
    float xg = ((xc[3] * t + xc[2]) * t + xc[1]) * t + xc[0] - 10.0f * t * t * t;
    *dz_dg = -slope * xg;
    return ((zc[3] * t + zc[2]) * t + zc[1]) * t + zc[0];
}

/* The unscaled profile z(x) and its slope (cubic Hermite on the segment's table). */
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

float sk__profile_scaled(const sk__profile *p, float g, float xq, float *dz_dx, float *dz_dg)
{
    float ig = g == 1.0f ? 1.0f : 1.0f / g, slope;
    float z = profile_z(p, xq * ig, &slope);
    *dz_dx = slope * ig;
    *dz_dg = -slope * xq * ig * ig;
    return z;
}
