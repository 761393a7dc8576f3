/* Section shape (paper sec. 3.2.1 (2), Figs. 5-7, parameter 5): a chain of cubic Bezier
 * segments in the body plane (x', z'), x' from 0 at the centre to 10 at the boundary.
 * The height at x' is Bz(t) with Bx(t) = x' (x is monotone, so t is unique); roundness
 * (parameter 6) scales the x of every control point but the last by g. */
#include <math.h>

#include "skin/skin_internal.h"

static inline float bez(const float p[4], float t)
{
    float s = 1.0f - t;
    return s * s * s * p[0] + 3.0f * s * s * t * p[1] + 3.0f * s * t * t * p[2] + t * t * t * p[3];
}
static inline float bez_d(const float p[4], float t)
{
    float s = 1.0f - t;
    return 3.0f * (s * s * (p[1] - p[0]) + 2.0f * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
}

float sk__bezier_solve(const sk__profile *pr, float g, float xq, float *dz_dx, float *dz_dg)
{
    int last = pr->segment_count - 1;
    int j = 0;
    /* segment holding xq (segment ends scale by g, except the chain's end at 10) */
    while (j < last && xq > g * pr->x[j][3]) j++;
    float x[4];
    for (int i = 0; i < 4; i++) x[i] = g * pr->x[j][i];
    if (j == last) x[3] = pr->x[j][3];
    const float *z = pr->z[j];
    float x0 = x[0], x3 = x[3];
    if (xq <= x0) {
        *dz_dx = 0, *dz_dg = 0;
        return z[0];
    }
    if (xq >= x3) {
        *dz_dx = 0, *dz_dg = 0;
        return z[3];
    }
    /* Newton on Bx(t) = xq inside a shrinking bracket. */
    float lo = 0.0f, hi = 1.0f, t = (xq - x0) / (x3 - x0);
    for (int it = 0; it < 24; it++) {
        float v = bez(x, t) - xq;
        if (v > 0) hi = t;
        else lo = t;
        if (fabsf(v) < 1e-6f * (x3 - x0)) break;
        float d = bez_d(x, t);
        float tn = d > 0 ? t - v / d : 0.5f * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5f * (lo + hi);
        t = tn;
    }
    float dx = bez_d(x, t), dz = bez_d(z, t);
    if (dx < 1e-4f * (x3 - x0)) {
        /* a flat spot of Bx (repeated control x): slope from a short chord */
        float t2 = t < 0.5f ? t + 1e-3f : t - 1e-3f;
        float ddx = bez(x, t2) - bez(x, t);
        dx = ddx / (t2 - t);
        dz = (bez(z, t2) - bez(z, t)) / (t2 - t);
        if (fabsf(dx) < 1e-12f) dx = 1e-12f;
    }
    float slope = dz / dx;
    *dz_dx = slope;
    /* dBx/dg at fixed t: the scaled control points' share */
    float s = 1.0f - t;
    float b[4] = {s * s * s, 3.0f * s * s * t, 3.0f * s * t * t, t * t * t};
    float xg = 0;
    for (int i = 0; i < 4; i++)
        if (!(j == last && i == 3)) xg += b[i] * pr->x[j][i];
    *dz_dg = -slope * xg;
    return bez(z, t);
}
