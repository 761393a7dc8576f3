/* Annual rings (Kawai 2000 sec. 4.4): R(t, theta) = integral over t of the ring width
 * w(t, theta) = d m(year) (1 + a n(t, theta)), with a per-year width factor m (lognormal,
 * mean 1) and fractal noise n around the ring. w > 0 keeps R increasing in t, so rings
 * never cross and T(r, theta) is a well-defined inverse. */
#include "models/wood/rings.h"

#include <stdlib.h>
#include <string.h>

#include "base/parallel.h"

/* Per-year width factor m_k = exp(sigma z_k - sigma^2 / 2), z_k ~ N(0, 1) cut at 3 sd. */
static double year_factor(uint64_t seed, double sigma, int year)
{
    if (sigma == 0.0) return 1.0;
    double z = sk_rand_normal(seed, 0x77696474ULL /* "widt" */, (uint64_t)year, 0);
    z = sk_clampd(z, -3.0, 3.0);
    return exp(sigma * z - 0.5 * sigma * sigma);
}

static int pow2_at_least(int n)
{
    int p = 1;
    while (p < n) p <<= 1;
    return p;
}

void sk__rings_free(sk__rings *rg)
{
    free(rg->R);
    free(rg->end_slope);
    free(rg->mean);
    free(rg->guess);
    free(rg->lipschitz);
    free(rg->year_min);
    free(rg->year_max);
    memset(rg, 0, sizeof *rg);
}

size_t sk__rings_memory(const sk__rings *rg)
{
    size_t cols = (size_t)rg->ntheta + 1;
    return cols * (size_t)rg->nt * sizeof(float) + cols * sizeof(float) +
           (size_t)rg->nt * sizeof(float) +
           (size_t)rg->ntheta * (size_t)rg->nguess * sizeof(uint16_t) +
           3 * ((size_t)rg->years + 1) * sizeof(float);
}

/* Fills the tables for `years` whole years; returns false on allocation failure. */
static bool build_tables(sk__rings *rg, const sk_wood_desc *desc, int years, const double *factor)
{
    const sk_wood_rings_desc *rd = &desc->rings;
    double a = rd->fluctuation;
    rg->years = years;
    rg->dt = years <= 1024 ? 0.25 : (years <= 2048 ? 0.5 : 1.0);
    rg->inv_dt = 1.0 / rg->dt;
    rg->nt = (int)lround(years / rg->dt) + 1;
    rg->t_max = (rg->nt - 1) * rg->dt;
    int ntheta = 1;
    if (a > 0.0) {
        /* 4 octaves: the finest has about 8 lobes-worth of bumps; 8 samples each */
        ntheta = pow2_at_least((int)ceil(rd->fluctuation_lobes * 64.0));
        if (ntheta < 64) ntheta = 64;
        if (ntheta > 2048) ntheta = 2048;
        while (ntheta > 64 && (size_t)(ntheta + 1) * (size_t)rg->nt > ((size_t)8 << 20))
            ntheta >>= 1;
    }
    rg->ntheta = ntheta;
    rg->theta_scale = ntheta / (2.0 * SK_PI);
    size_t cols = (size_t)ntheta + 1, nt = (size_t)rg->nt;
    rg->R = malloc(cols * nt * sizeof(float));
    rg->end_slope = malloc(cols * sizeof(float));
    rg->mean = malloc(nt * sizeof(float));
    rg->lipschitz = malloc(((size_t)years + 1) * sizeof(float));
    rg->year_min = malloc(((size_t)years + 1) * sizeof(float));
    rg->year_max = malloc(((size_t)years + 1) * sizeof(float));
    if (!rg->R || !rg->end_slope || !rg->mean || !rg->lipschitz || !rg->year_min || !rg->year_max)
        return false;

    /* The noise n(t, theta) varies over fluctuation_years; sample it on a coarser t grid
       and interpolate linearly (4 octaves: the finest period is years / 8). */
    double dtn = rd->fluctuation_years / 8.0;
    if (dtn < rg->dt) dtn = rg->dt;
    int nn = (int)ceil(rg->t_max / dtn) + 2;
    double rho = rd->fluctuation_lobes / (2.0 * SK_PI);
    uint64_t noise_seed = sk_hash(desc->seed, 0x72696e67ULL /* "ring" */, 1, 0);
    sk_fbm_desc fbm = {4, 2.0f, 0.5f};
    bool ok = true;

#pragma omp parallel if (sk__parallel_worth((double)ntheta,                                        \
                                            (a > 0.0 ? 100.0 * nn : 0.0) + 10.0 * rg->nt))
    {
        double *noise = a > 0.0 ? malloc((size_t)nn * sizeof(double)) : NULL;
        if (a > 0.0 && !noise) {
#pragma omp atomic write
            ok = false;
        }
#pragma omp for schedule(dynamic, 4)
        for (int j = 0; j < ntheta; j++) {
            if (a > 0.0 && !noise) continue;
            double theta = j / rg->theta_scale;
            double cx = rho * cos(theta), cz = rho * sin(theta);
            if (noise)
                for (int m = 0; m < nn; m++)
                    noise[m] = sk_fbm3(noise_seed, (float)cx, (float)cz,
                                       (float)(m * dtn / rd->fluctuation_years), &fbm);
            float *col = rg->R + (size_t)j * nt;
            col[0] = 0.0f;
            double R = 0.0;
            for (int i = 1; i < rg->nt; i++) {
                double t0 = (i - 1) * rg->dt, t1 = i * rg->dt;
                int year = (int)floor(t0 + 1e-9);
                double w[2];
                for (int e = 0; e < 2; e++) {
                    double t = e ? t1 : t0, n = 0.0;
                    if (noise) {
                        double um = t / dtn;
                        int m = (int)um;
                        if (m > nn - 2) m = nn - 2;
                        double fm = um - m;
                        n = noise[m] + fm * (noise[m + 1] - noise[m]);
                    }
                    w[e] = rg->width * factor[year] * (1.0 + a * n);
                }
                R += 0.5 * rg->dt * (w[0] + w[1]);
                col[i] = (float)R;
            }
            rg->end_slope[j] =
                (float)(((double)col[rg->nt - 1] - (double)col[rg->nt - 2]) / rg->dt);
        }
        free(noise);
    }
    if (!ok) return false;
    memcpy(rg->R + (size_t)ntheta * nt, rg->R, nt * sizeof(float));
    rg->end_slope[ntheta] = rg->end_slope[0];

    double mean_end = 0.0;
    for (int j = 0; j < ntheta; j++) mean_end += rg->end_slope[j];
    rg->mean_end_slope = mean_end / ntheta;
    for (size_t i = 0; i < nt; i++) {
        double s = 0.0;
        for (int j = 0; j < ntheta; j++) s += rg->R[(size_t)j * nt + i];
        rg->mean[i] = (float)(s / ntheta);
    }
    int per_year = rg->per_year = (int)lround(1.0 / rg->dt);
    double end_lip = 0.0;
    for (int j = 0; j < ntheta; j++)
        end_lip = fmax(end_lip, fabs((double)rg->end_slope[j + 1] - rg->end_slope[j]));
    rg->lipschitz_end_slope = end_lip * rg->theta_scale;
    rg->min_end_slope = INFINITY;
    rg->max_end_slope = 0.0;
    for (int j = 0; j < ntheta; j++) {
        rg->min_end_slope = fmin(rg->min_end_slope, rg->end_slope[j]);
        rg->max_end_slope = fmax(rg->max_end_slope, rg->end_slope[j]);
    }
    for (int y = 0; y <= years; y++) {
        size_t i = (size_t)y * (size_t)per_year;
        double s = 0.0, lo = INFINITY, hi = 0.0;
        for (int j = 0; j < ntheta; j++) {
            double r = rg->R[(size_t)j * nt + i];
            double d = (double)rg->R[(size_t)(j + 1) * nt + i] - r;
            s = fmax(s, fabs(d));
            lo = fmin(lo, r);
            hi = fmax(hi, r);
        }
        rg->lipschitz[y] = (float)(s * rg->theta_scale * (1.0 + 1e-6));
        rg->year_min[y] = (float)lo;
        rg->year_max[y] = (float)hi;
    }
    return true;
}

static bool build_guess(sk__rings *rg)
{
    size_t nt = (size_t)rg->nt;
    double rmax = 0.0;
    for (int j = 0; j <= rg->ntheta; j++) rmax = fmax(rmax, rg->R[(size_t)j * nt + nt - 1]);
    rg->guess_step = rg->width * rg->dt;
    rg->inv_guess_step = 1.0 / rg->guess_step;
    rg->nguess = (int)ceil(rmax / rg->guess_step) + 1;
    rg->guess = malloc((size_t)rg->ntheta * (size_t)rg->nguess * sizeof(uint16_t));
    if (!rg->guess) return false;
#pragma omp parallel for schedule(                                                                 \
    static) if (sk__parallel_worth((double)rg->ntheta * rg->nguess, 3.0))
    for (int j = 0; j < rg->ntheta; j++) {
        const float *c0 = rg->R + (size_t)j * nt, *c1 = c0 + nt;
        uint16_t *g = rg->guess + (size_t)j * (size_t)rg->nguess;
        size_t i = 0;
        for (int k = 0; k < rg->nguess; k++) {
            double r = k * rg->guess_step;
            while (i + 2 < nt && fmax(c0[i + 1], c1[i + 1]) <= r) i++;
            g[k] = (uint16_t)i;
        }
    }
    return true;
}

sk_result sk__rings_build(sk__rings *rg, const sk_wood_desc *desc, sk_error *err)
{
    memset(rg, 0, sizeof *rg);
    const sk_wood_rings_desc *rd = &desc->rings;
    rg->width = rd->width_mm;
    double radius = desc->log.radius_mm;
    uint64_t year_seed = sk_hash(desc->seed, 0x72696e67ULL, 2, 0);
    double *factor = malloc((SK_WOOD_MAX_RINGS + 1) * sizeof(double));
    if (!factor) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory for rings");
    /* Years until the mean radius covers the log, allowing for the fluctuation. */
    double need = radius * 1.02 / (1.0 - 0.6 * rd->fluctuation), Rbar = 0.0;
    int years = 0;
    while (Rbar < need && years < SK_WOOD_MAX_RINGS) {
        factor[years] = year_factor(year_seed, rd->width_variation, years);
        Rbar += rg->width * factor[years];
        years++;
    }
    for (int y = years; y <= SK_WOOD_MAX_RINGS; y++)
        factor[y] = year_factor(year_seed, rd->width_variation, y);
    if (Rbar < need) {
        free(factor);
        return sk_fail(err, SK_ERROR_LIMIT,
                       "log.radius_mm = %g with rings.width_mm = %g needs more than %d rings",
                       radius, rg->width, SK_WOOD_MAX_RINGS);
    }
    years += 1;
    for (;;) {
        if (!build_tables(rg, desc, years, factor)) {
            free(factor);
            sk__rings_free(rg);
            return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory for the ring table");
        }
        /* Every direction must reach the log's radius inside the table. */
        double rmin = INFINITY;
        for (int j = 0; j < rg->ntheta; j++)
            rmin = fmin(rmin, rg->R[(size_t)j * (size_t)rg->nt + (size_t)rg->nt - 1]);
        rg->inside = rmin;
        if (rmin >= radius || years >= SK_WOOD_MAX_RINGS) break;
        double width = rg->width;
        sk__rings_free(rg);
        rg->width = width;
        years = years + years / 2 + 1;
        if (years > SK_WOOD_MAX_RINGS) years = SK_WOOD_MAX_RINGS;
    }
    free(factor);
    if (!build_guess(rg)) {
        sk__rings_free(rg);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "wood: out of memory for the ring index");
    }
    return SK_OK;
}
