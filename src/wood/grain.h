/* Grain (Kawai 2000 sec. 4.2 eq. (1), sec. 4.4): the fibre slope G'(t, y) = g'(y) + dg'(t, y)
 * on the ring of growth time t, and its integral along y, the phase table Phi(t, y) of
 * eq. (3). */
#ifndef SK_WOOD_GRAIN_H
#define SK_WOOD_GRAIN_H

#include <math.h>

#include "shitsukan/wood.h"
#include "wood/numeric.h"

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

/* Row blend and column position of (t, y) in the dg grid. */
static inline void sk__grain_grid_pos(const sk__grain *g, double t, double y, int *i,
                                      double *a, int *j, double *u)
{
    double ut = t * g->inv_dt;
    if (ut < 0.0) ut = 0.0;
    if (ut > (double)(g->nt - 1)) ut = (double)(g->nt - 1);
    int ii = (int)ut;
    if (ii > g->nt - 2) ii = g->nt - 2;
    *i = ii;
    *a = ut - ii;
    double ym = y - sk__floor_d(y * g->inv_period) * g->period;
    double uy = ym * g->inv_dy;
    int jj = (int)uy;
    if (jj > g->ny - 1) jj = g->ny - 1;
    if (jj < 0) jj = 0;
    *j = jj;
    *u = uy - jj;
}

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
/* Phi(t, y) = integral from 0 to y of G'(t, y') dy' (closed forms + the dg table), and
 * optionally its derivative dPhi/dy = G'(t, y). dg is linear between samples along y, so
 * the table holds the exact integral at the samples and the lookup adds the exact
 * quadratic in between: dPhi/dy is the interpolated dg, consistent with the fibre. */
static inline double sk__phase_eval(const sk__grain *g, double t, double y, double *slope)
{
    double P = g->spiral * y, G = g->spiral;
    if (g->wavy_amplitude != 0.0) {
        double s, c;
        sk__sincos(y * g->inv_wavelength, &s, &c);
        P += g->wavy_amplitude * g->wavy_wavelength * (1.0 - c);
        G += g->wavy_amplitude * s;
    }
    if (g->inter_slope != 0.0) {
        double s = g->inter_slope * sin(2.0 * SK_PI * t / g->inter_period);
        P += s * y;
        G += s;
    }
    if (g->table_count) {
        P += sk__grain_table_integral(g, y);
        G += sk__grain_table_slope(g, y);
    }
    if (g->dg) {
        /* dg is linear between samples along y: the exact integral adds a quadratic */
        int i, j;
        double a, u;
        sk__grain_grid_pos(g, t, y, &i, &a, &j, &u);
        size_t row = (size_t)g->ny + 1;
        double v[2], d[2];
        for (int e = 0; e < 2; e++) {
            const float *dg = g->dg + (size_t)(i + e) * row, *ph = g->phi + (size_t)(i + e) * row;
            double slope_j = (double)dg[j + 1] - dg[j];
            d[e] = dg[j] + u * slope_j;
            v[e] = ph[j] + g->dy * u * (dg[j] + 0.5 * u * slope_j);
        }
        P += v[0] + a * (v[1] - v[0]);
        G += d[0] + a * (d[1] - d[0]);
    }
    if (slope) *slope = G;
    return P;
}
/* phi of eq. (3): Phi(t, y) / R(t, theta), where R(T(r, theta), theta) = r. */
static inline double sk__phase_phi(double Phi, double r) { return Phi / (r > 1e-6 ? r : 1e-6); }

#endif
