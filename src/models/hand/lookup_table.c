/* Lookup-table potentials of thesis 3.2.3: over the plane of a joint-angle pair, a grid
 * (about 100 x 100) holds the squared distance to the nearest measured sample (the
 * potential of Figs. 3.11, 3.13) and its x and y gradients (Figs. 3.12, 3.14); values
 * between nodes are bilinearly interpolated. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"

void sk_hand_lut_free(sk_hand_lut *lut)
{
    if (!lut) return;
    free(lut->value);
    free(lut->grad_x);
    free(lut->grad_y);
    memset(lut, 0, sizeof *lut);
}

sk_result sk_hand_lut_build(sk_hand_lut *lut, int dof_x, int dof_y, const double *xs,
                            const double *ys, int count, const sk_hand_lut_desc *desc,
                            sk_error *err)
{
    memset(lut, 0, sizeof *lut);
    sk_hand_lut_desc d = {0};
    if (desc) d = *desc;
    sk_schema_apply_defaults(&sk_hand_lut_schema, &d);
    if (d.interp != SK_HAND_LUT_INTERP_HERMITE && d.interp != SK_HAND_LUT_INTERP_BILINEAR)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "interp = %d is not a lookup interpolation",
                       (int)d.interp);
    sk_result r = sk_schema_check(&sk_hand_lut_schema, &d, "", err);
    if (r == SK_OK) r = sk_check_range_i(err, "sample count", count, 1, 10000000);
    if (r != SK_OK) return r;
    if (!sk_hand_dof(dof_x) || !sk_hand_dof(dof_y) || dof_x == dof_y)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "a lookup table needs two different DOFs");
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    for (int k = 0; k < count; k++) {
        if (!isfinite(xs[k]) || !isfinite(ys[k]))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sample %d is not finite", k);
        minx = fmin(minx, xs[k]);
        maxx = fmax(maxx, xs[k]);
        miny = fmin(miny, ys[k]);
        maxy = fmax(maxy, ys[k]);
    }
    int n = d.resolution;
    /* at least about a degree of extent, so a single sample still gets a grid */
    double rx = fmax(maxx - minx, 0.02), ry = fmax(maxy - miny, 0.02);
    lut->dof_x = dof_x;
    lut->dof_y = dof_y;
    lut->n = n;
    lut->weight = d.weight;
    lut->interp = d.interp;
    lut->x0 = 0.5 * (minx + maxx) - rx * (0.5 + d.margin);
    lut->y0 = 0.5 * (miny + maxy) - ry * (0.5 + d.margin);
    lut->h_x = rx * (1.0 + 2.0 * d.margin) / (n - 1);
    lut->h_y = ry * (1.0 + 2.0 * d.margin) / (n - 1);
    size_t nodes = (size_t)n * (size_t)n;
    lut->value = malloc(nodes * sizeof *lut->value);
    lut->grad_x = malloc(nodes * sizeof *lut->grad_x);
    lut->grad_y = malloc(nodes * sizeof *lut->grad_y);
    if (!lut->value || !lut->grad_x || !lut->grad_y) {
        sk_hand_lut_free(lut);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a %dx%d lookup table", n, n);
    }
    /* brute force nearest sample per node: independent nodes, identical for any thread
       count */
#pragma omp parallel for schedule(static)
    for (int j = 0; j < n; j++) {
        double py = lut->y0 + j * lut->h_y;
        for (int i = 0; i < n; i++) {
            double px = lut->x0 + i * lut->h_x;
            double best = INFINITY, bx = 0.0, by = 0.0;
            for (int k = 0; k < count; k++) {
                double dx = px - xs[k], dy = py - ys[k];
                double q = dx * dx + dy * dy;
                if (q < best) {
                    best = q;
                    bx = dx;
                    by = dy;
                }
            }
            size_t at = (size_t)j * n + i;
            lut->value[at] = best;
            lut->grad_x[at] = 2.0 * bx;
            lut->grad_y[at] = 2.0 * by;
        }
    }
    return SK_OK;
}

/* Cubic Hermite basis on [0, 1]: values at 0 and 1, slopes at 0 and 1, and their
 * derivatives. */
static void hermite(double s, double h[4], double dh[4])
{
    double s2 = s * s, s3 = s2 * s;
    h[0] = 2 * s3 - 3 * s2 + 1;
    h[1] = -2 * s3 + 3 * s2;
    h[2] = s3 - 2 * s2 + s;
    h[3] = s3 - s2;
    dh[0] = 6 * s2 - 6 * s;
    dh[1] = -6 * s2 + 6 * s;
    dh[2] = 3 * s2 - 4 * s + 1;
    dh[3] = 3 * s2 - 2 * s;
}

/* Second derivatives of the cubic Hermite basis. */
static void hermite_dd(double s, double ddh[4])
{
    ddh[0] = 12 * s - 6;
    ddh[1] = -12 * s + 6;
    ddh[2] = 6 * s - 4;
    ddh[3] = 6 * s - 2;
}

/* Value, gradient and cross derivative at a point inside the grid (u, v in nodes); with
 * `second` also the second derivatives f_xx, f_yy (bilinear: 0). */
static void eval_inside2(const sk_hand_lut *lut, double u, double v, double out[4],
                         double second[2]);

static void eval_inside(const sk_hand_lut *lut, double u, double v, double out[4])
{
    eval_inside2(lut, u, v, out, NULL);
}

static void eval_inside2(const sk_hand_lut *lut, double u, double v, double out[4],
                         double second[2])
{
    int n = lut->n;
    int i = (int)u, j = (int)v;
    if (i > n - 2) i = n - 2;
    if (j > n - 2) j = n - 2;
    double s = u - i, t = v - j;
    size_t c[4] = {(size_t)j * n + i, (size_t)j * n + i + 1, (size_t)(j + 1) * n + i,
                   (size_t)(j + 1) * n + i + 1};
    if (lut->interp == SK_HAND_LUT_INTERP_BILINEAR) {
        double w[4] = {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
        out[0] = out[1] = out[2] = 0.0;
        for (int k = 0; k < 4; k++) {
            out[0] += w[k] * lut->value[c[k]];
            out[1] += w[k] * lut->grad_x[c[k]];
            out[2] += w[k] * lut->grad_y[c[k]];
        }
        out[3] = 0.0;
        if (second) second[0] = second[1] = 0.0;
        return;
    }
    /* bicubic Hermite with zero twist: exact for separable functions such as the
       squared distance to one sample */
    double hs[4], dhs[4], ht[4], dht[4];
    hermite(s, hs, dhs);
    hermite(t, ht, dht);
    double hx = lut->h_x, hy = lut->h_y;
    double f = 0, fs = 0, ft = 0, fst = 0;
    for (int b = 0; b < 2; b++) {
        for (int a = 0; a < 2; a++) {
            size_t k = c[b * 2 + a];
            double val = lut->value[k], gx = lut->grad_x[k] * hx, gy = lut->grad_y[k] * hy;
            f += val * hs[a] * ht[b] + gx * hs[2 + a] * ht[b] + gy * hs[a] * ht[2 + b];
            fs += val * dhs[a] * ht[b] + gx * dhs[2 + a] * ht[b] + gy * dhs[a] * ht[2 + b];
            ft += val * hs[a] * dht[b] + gx * hs[2 + a] * dht[b] + gy * hs[a] * dht[2 + b];
            fst += val * dhs[a] * dht[b] + gx * dhs[2 + a] * dht[b] + gy * dhs[a] * dht[2 + b];
        }
    }
    out[0] = f;
    out[1] = fs / hx;
    out[2] = ft / hy;
    out[3] = fst / (hx * hy);
    if (!second) return;
    double dds[4], ddt[4], fss = 0, ftt = 0;
    hermite_dd(s, dds);
    hermite_dd(t, ddt);
    for (int b = 0; b < 2; b++)
        for (int a = 0; a < 2; a++) {
            size_t k = c[b * 2 + a];
            double val = lut->value[k], gx = lut->grad_x[k] * hx, gy = lut->grad_y[k] * hy;
            fss += val * dds[a] * ht[b] + gx * dds[2 + a] * ht[b] + gy * dds[a] * ht[2 + b];
            ftt += val * hs[a] * ddt[b] + gx * hs[2 + a] * ddt[b] + gy * hs[a] * ddt[2 + b];
        }
    second[0] = fss / (hx * hx);
    second[1] = ftt / (hy * hy);
}

double sk__hand_lut_eval_hessian(const sk_hand_lut *lut, double x, double y, double g[2],
                                 double h[3])
{
    int n = lut->n;
    double u = (x - lut->x0) / lut->h_x, v = (y - lut->y0) / lut->h_y;
    double cu = sk_clampd(u, 0.0, n - 1), cv = sk_clampd(v, 0.0, n - 1);
    double f[4], dd[2];
    eval_inside2(lut, cu, cv, f, dd);
    double dx = (u - cu) * lut->h_x, dy = (v - cv) * lut->h_y;
    double value = f[0] + f[1] * dx + f[2] * dy + f[3] * dx * dy + dx * dx + dy * dy;
    g[0] = lut->weight * (f[1] + f[3] * dy + 2.0 * dx);
    g[1] = lut->weight * (f[2] + f[3] * dx + 2.0 * dy);
    /* beyond the border the continuation is quadratic along the outside axes */
    h[0] = lut->weight * (u != cu ? 2.0 : dd[0]);
    h[1] = lut->weight * (v != cv ? 2.0 : dd[1]);
    h[2] = lut->weight * f[3];
    return lut->weight * value;
}

double sk_hand_lut_eval(const sk_hand_lut *lut, double x, double y, double *gx, double *gy)
{
    int n = lut->n;
    double u = (x - lut->x0) / lut->h_x, v = (y - lut->y0) / lut->h_y;
    double cu = sk_clampd(u, 0.0, n - 1), cv = sk_clampd(v, 0.0, n - 1);
    double f[4];
    eval_inside(lut, cu, cv, f);
    /* beyond the border: continue with the slope and add the squared distance */
    double dx = (u - cu) * lut->h_x, dy = (v - cv) * lut->h_y;
    double value = f[0] + f[1] * dx + f[2] * dy + f[3] * dx * dy + dx * dx + dy * dy;
    if (gx) *gx = lut->weight * (f[1] + f[3] * dy + 2.0 * dx);
    if (gy) *gy = lut->weight * (f[2] + f[3] * dx + 2.0 * dy);
    return lut->weight * value;
}
