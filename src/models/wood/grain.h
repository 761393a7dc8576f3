/* Grain (Kawai 2000 sec. 4.2 eq. (1), sec. 4.4): the fibre slope G'(t, y) = g'(y) + dg'(t, y)
 * on the ring of growth time t, and its integral along y, the phase table Phi(t, y) of
 * eq. (3). */
#ifndef SK_WOOD_GRAIN_H
#define SK_WOOD_GRAIN_H

#include <math.h>

#include "shitsukan/wood.h"
#include "models/wood/numeric.h"

typedef struct sk__grain {
    /* closed-form parts of g'(y) (and the interlocked slope, which depends on t) */
    double spiral, wavy_amplitude, wavy_wavelength, inv_wavelength, inter_slope, inter_period;
    /* tabulated g(y): points, and the integral from the first point at each point */
    int table_count;
    double table_y[SK_WOOD_MAX_GRAIN_POINTS], table_g[SK_WOOD_MAX_GRAIN_POINTS];
    double table_cum[SK_WOOD_MAX_GRAIN_POINTS];
    double table_cum_at_zero; /* the table's integral from the first point to y = 0 */
    /* fractal fluctuation dg'(t, y) on a grid over t in [0, (nt - 1) dt] and one period of
       y; row i holds ny + 1 samples, the last repeating the first. NULL without dg. */
    int nt, ny;
    double dt, dy, period, inv_dt, inv_dy, inv_period;
    float *dg;
    float *phi; /* Phi of dg: integral of dg from y = 0 (phase.c) */
} sk__grain;

/* Sets up g and the dg table for t in [0, t_max] (a resolved, validated desc). */
sk_result sk__grain_build(sk__grain *grain, const sk_wood_desc *desc, double t_max, sk_error *err);
void sk__grain_free(sk__grain *grain);
size_t sk__grain_memory(const sk__grain *grain);

/* The tabulated g(y) and its integral from y = 0. */
double sk__grain_table_slope(const sk__grain *grain, double y);
double sk__grain_table_integral(const sk__grain *grain, double y);

/* G'(t, y) = g'(y) + dg'(t, y): the fibre's tangential slope r dtheta/dy (the derivative
 * of the phase integral, see sk__phase_eval). */
double sk__grain_slope(const sk__grain *grain, double t, double y);

/* Phase table (phase.c): fills grain->phi from grain->dg (false on allocation failure). */
bool sk__phase_build(sk__grain *grain);

/* The terms of Phi(t, y) and G'(t, y) that depend on y alone (a planar cut along the
 * rings has one y per row, so they are found once for many points). */
typedef struct sk__phase_y {
    double P, G; /* spiral, wavy and tabulated terms */
    int j;       /* dg grid column of y and the weight u of column j + 1 */
    double u;
    double dy_u, half_u; /* dy u and u / 2, the factors of the quadratic in between */
} sk__phase_y;

static inline sk__phase_y sk__phase_at_y(const sk__grain *g, double y)
{
    sk__phase_y py;
    py.P = g->spiral * y;
    py.G = g->spiral;
    if (g->wavy_amplitude != 0.0) {
        double s, c;
        sk__sincos(y * g->inv_wavelength, &s, &c);
        py.P += g->wavy_amplitude * g->wavy_wavelength * (1.0 - c);
        py.G += g->wavy_amplitude * s;
    }
    if (g->table_count) {
        py.P += sk__grain_table_integral(g, y);
        py.G += sk__grain_table_slope(g, y);
    }
    py.j = 0;
    py.u = py.dy_u = py.half_u = 0.0;
    if (g->dg) {
        double ym = y - sk__floor_d(y * g->inv_period) * g->period;
        double uy = ym * g->inv_dy;
        int jj = (int)uy;
        if (jj > g->ny - 1) jj = g->ny - 1;
        if (jj < 0) jj = 0;
        py.j = jj;
        py.u = uy - jj;
        py.dy_u = g->dy * py.u;
        py.half_u = 0.5 * py.u;
    }
    return py;
}

/* Phi(t, y) = integral from 0 to y of G'(t, y') dy' (closed forms + the dg table) given
 * the y terms `py` = sk__phase_at_y(y), and optionally dPhi/dy = G'(t, y). dg is linear
 * between samples along y, so the table holds the exact integral at the samples and the
 * lookup adds the exact quadratic in between: dPhi/dy is the interpolated dg, consistent
 * with the fibre. */
static inline double sk__phase_eval_y(const sk__grain *g, const sk__phase_y *py, double t, double y,
                                      double *slope)
{
    double P = py->P, G = py->G;
    if (g->inter_slope != 0.0) {
        double s = g->inter_slope * sin(2.0 * SK_PI * t / g->inter_period);
        P += s * y;
        G += s;
    }
    if (g->dg) {
        /* row blend of t in the dg grid */
        double ut = t * g->inv_dt;
        if (ut < 0.0) ut = 0.0;
        if (ut > (double)(g->nt - 1)) ut = (double)(g->nt - 1);
        int i = (int)ut;
        if (i > g->nt - 2) i = g->nt - 2;
        double a = ut - i, u = py->u, dy_u = py->dy_u, half_u = py->half_u;
        size_t row = (size_t)g->ny + 1, at = (size_t)i * row + (size_t)py->j;
        const float *dg0 = g->dg + at, *dg1 = dg0 + row, *ph0 = g->phi + at, *ph1 = ph0 + row;
        /* rows i and i + 1: dg linear in y, its integral quadratic */
        double s0 = (double)dg0[1] - dg0[0], s1 = (double)dg1[1] - dg1[0];
        double d0 = dg0[0] + u * s0, d1 = dg1[0] + u * s1;
        double v0 = ph0[0] + dy_u * (dg0[0] + half_u * s0);
        double v1 = ph1[0] + dy_u * (dg1[0] + half_u * s1);
        P += v0 + a * (v1 - v0);
        G += d0 + a * (d1 - d0);
    }
    if (slope) *slope = G;
    return P;
}

/* Phi(t, y) and optionally dPhi/dy = G'(t, y). */
static inline double sk__phase_eval(const sk__grain *g, double t, double y, double *slope)
{
    sk__phase_y py = sk__phase_at_y(g, y);
    return sk__phase_eval_y(g, &py, t, y, slope);
}
/* phi of eq. (3): Phi(t, y) / R(t, theta), where R(T(r, theta), theta) = r. */
static inline double sk__phase_phi(double Phi, double r) { return Phi / (r > 1e-6 ? r : 1e-6); }

#endif
