/* Grain functions (Kawai 2000 sec. 4.2, eq. (1)): straight, spiral g1, wavy A sin(y / lambda),
 * interlocked (the slope alternating with the growth layer, s sin(2 pi t / P), the decision
 * for the paper's Fig. 2a), a tabulated g(y), and the fractal fluctuation dg(t, y) whose
 * largest magnitude is the desc's bound. dg is periodic along y (period log.length_mm)
 * with zero mean per ring, so its phase integral is periodic too and the texture has no
 * end along the axis. */
#include "models/wood/grain.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

void sk__grain_free(sk__grain *grain)
{
    free(grain->dg);
    free(grain->phi);
    memset(grain, 0, sizeof *grain);
}

size_t sk__grain_memory(const sk__grain *grain)
{
    if (!grain->dg) return 0;
    return 2 * (size_t)grain->nt * ((size_t)grain->ny + 1) * sizeof(float);
}

static void build_table(sk__grain *g, const sk_wood_grain_desc *gd)
{
    g->table_count = gd->table_count;
    for (int k = 0; k < gd->table_count; k++) {
        g->table_y[k] = gd->table[k].y_mm;
        g->table_g[k] = gd->table[k].slope;
    }
    g->table_cum[0] = 0.0;
    for (int k = 1; k < g->table_count; k++)
        g->table_cum[k] = g->table_cum[k - 1] + 0.5 * (g->table_g[k - 1] + g->table_g[k]) *
                                                    (g->table_y[k] - g->table_y[k - 1]);
    g->table_cum_at_zero = 0.0;
    if (g->table_count > 0) {
        /* integral from the first point to 0 (the table's own antiderivative at 0) */
        g->table_cum_at_zero = 0.0;
        g->table_cum_at_zero = sk__grain_table_integral(g, 0.0);
    }
}

double sk__grain_table_slope(const sk__grain *g, double y)
{
    int n = g->table_count;
    if (n == 0) return 0.0;
    if (y <= g->table_y[0]) return g->table_g[0];
    if (y >= g->table_y[n - 1]) return g->table_g[n - 1];
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (g->table_y[mid] <= y)
            lo = mid;
        else
            hi = mid;
    }
    double u = (y - g->table_y[lo]) / (g->table_y[hi] - g->table_y[lo]);
    return g->table_g[lo] + u * (g->table_g[hi] - g->table_g[lo]);
}

/* Antiderivative of the piecewise-linear table from its first point, minus its value at
 * y = 0 (table_cum_at_zero), i.e. the integral from 0 to y. */
double sk__grain_table_integral(const sk__grain *g, double y)
{
    int n = g->table_count;
    if (n == 0) return 0.0;
    double v;
    if (y <= g->table_y[0]) {
        v = g->table_g[0] * (y - g->table_y[0]);
    } else if (y >= g->table_y[n - 1]) {
        v = g->table_cum[n - 1] + g->table_g[n - 1] * (y - g->table_y[n - 1]);
    } else {
        int lo = 0, hi = n - 1;
        while (hi - lo > 1) {
            int mid = (lo + hi) / 2;
            if (g->table_y[mid] <= y)
                lo = mid;
            else
                hi = mid;
        }
        double h = g->table_y[hi] - g->table_y[lo], s = y - g->table_y[lo];
        v = g->table_cum[lo] + g->table_g[lo] * s +
            (g->table_g[hi] - g->table_g[lo]) * s * s / (2.0 * h);
    }
    return v - g->table_cum_at_zero;
}

sk_result sk__grain_build(sk__grain *g, const sk_wood_desc *desc, double t_max, sk_error *err)
{
    memset(g, 0, sizeof *g);
    const sk_wood_grain_desc *gd = &desc->grain;
    g->spiral = gd->spiral_slope;
    g->wavy_amplitude = gd->wavy_amplitude;
    g->wavy_wavelength = gd->wavy_wavelength_mm;
    g->inv_wavelength = gd->wavy_wavelength_mm > 0.0f ? 1.0 / gd->wavy_wavelength_mm : 0.0;
    g->inter_slope = gd->interlocked_slope;
    g->inter_period = gd->interlocked_period_years;
    build_table(g, gd);
    if (gd->fluctuation == 0.0f) return SK_OK;

    /* The grid resolves 4 fBm octaves: the finest has period scale / 8 along y and
       years / 8 across rings; sample at half of that. Capped at 4 M samples. */
    double scale = gd->fluctuation_scale_mm, years = gd->fluctuation_years;
    int periods = (int)lround(desc->log.length_mm / scale);
    if (periods < 1) periods = 1;
    g->period = periods * scale;
    g->ny = periods * 16;
    if (g->ny > 16384) g->ny = 16384;
    g->dy = g->period / g->ny;
    g->dt = years / 16.0;
    g->nt = (int)ceil(t_max / g->dt) + 2;
    while ((size_t)g->nt * (size_t)(g->ny + 1) > ((size_t)4 << 20)) {
        g->dt *= 2.0;
        g->nt = (int)ceil(t_max / g->dt) + 2;
    }
    g->inv_dt = 1.0 / g->dt;
    g->inv_dy = 1.0 / g->dy;
    g->inv_period = 1.0 / g->period;
    size_t row = (size_t)g->ny + 1, count = (size_t)g->nt * row;
    g->dg = malloc(count * sizeof(float));
    g->phi = malloc(count * sizeof(float));
    if (!g->dg || !g->phi) {
        sk__grain_free(g);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory for the grain table");
    }
    uint64_t seed = sk_hash(desc->seed, 0x6772616eULL /* "gran" */, 0, 0);
    sk_fbm_desc fbm = {4, 2.0f, 0.5f};
    const int big = 1 << 20; /* t is not periodic: a period far beyond any table */
    double peak = 0.0;
#pragma omp parallel for schedule(static)                                                          \
    reduction(max                                                                                  \
              : peak) if (sk__parallel_worth((double)g->nt * g->ny, 80.0))
    for (int i = 0; i < g->nt; i++) {
        float *r = g->dg + (size_t)i * row;
        double mean = 0.0;
        for (int j = 0; j < g->ny; j++) {
            r[j] = sk_fbm2_periodic(seed, (float)(i * g->dt / years), (float)j * periods / g->ny,
                                    big, periods, &fbm);
            mean += r[j];
        }
        /* zero mean per ring: the phase integral over one period vanishes */
        mean /= g->ny;
        for (int j = 0; j < g->ny; j++) {
            r[j] = (float)(r[j] - mean);
            peak = fmax(peak, fabs(r[j]));
        }
        r[g->ny] = r[0];
    }
    /* |dg| reaches the stated bound (the paper's "dg at most 0.02") */
    float s = peak > 0.0 ? (float)(gd->fluctuation / peak) : 0.0f;
    for (size_t k = 0; k < count; k++) g->dg[k] *= s;
    if (!sk__phase_build(g)) {
        sk__grain_free(g);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory for the phase table");
    }
    return SK_OK;
}

double sk__grain_slope(const sk__grain *g, double t, double y)
{
    double G;
    sk__phase_eval(g, t, y, &G);
    return G;
}
