/* Lookup-table potentials of thesis 3.2.3: over the plane of a joint-angle pair, a grid
 * (about 100 x 100) holds the squared distance to the nearest measured sample (the
 * potential of Figs. 3.11, 3.13) and its x and y gradients (Figs. 3.12, 3.14); values
 * between nodes are bilinearly interpolated. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"

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
    if (d.resolution == 0) d.resolution = 100;
    if (d.margin == 0.0) d.margin = 0.25;
    if (d.weight == 0.0) d.weight = 1.0;
    sk_result r = sk_check_range_i(err, "resolution", d.resolution, 8, 1024);
    if (r == SK_OK) r = sk_check_range_f(err, "margin", d.margin, 0.0, 4.0);
    if (r == SK_OK) r = sk_check_range_f(err, "weight", d.weight, 1e-12, 1e6);
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

double sk_hand_lut_eval(const sk_hand_lut *lut, double x, double y, double *gx, double *gy)
{
    int n = lut->n;
    double u = (x - lut->x0) / lut->h_x, v = (y - lut->y0) / lut->h_y;
    /* outside the grid: the border value plus the squared distance to the border */
    double ou = 0.0, ov = 0.0;
    if (u < 0.0) ou = u, u = 0.0;
    if (u > n - 1) ou = u - (n - 1), u = n - 1;
    if (v < 0.0) ov = v, v = 0.0;
    if (v > n - 1) ov = v - (n - 1), v = n - 1;
    int i = (int)u, j = (int)v;
    if (i > n - 2) i = n - 2;
    if (j > n - 2) j = n - 2;
    double s = u - i, t = v - j;
    size_t a = (size_t)j * n + i, b = a + 1, c = a + n, e = c + 1;
    double w00 = (1 - s) * (1 - t), w10 = s * (1 - t), w01 = (1 - s) * t, w11 = s * t;
    double value = w00 * lut->value[a] + w10 * lut->value[b] + w01 * lut->value[c] + w11 * lut->value[e];
    double ddx = ou * lut->h_x, ddy = ov * lut->h_y;
    value += ddx * ddx + ddy * ddy;
    if (gx) {
        *gx = lut->weight * (w00 * lut->grad_x[a] + w10 * lut->grad_x[b] + w01 * lut->grad_x[c] +
                             w11 * lut->grad_x[e] + 2.0 * ddx);
    }
    if (gy) {
        *gy = lut->weight * (w00 * lut->grad_y[a] + w10 * lut->grad_y[b] + w01 * lut->grad_y[c] +
                             w11 * lut->grad_y[e] + 2.0 * ddy);
    }
    return lut->weight * value;
}
