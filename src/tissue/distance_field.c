/* Distance from every grid point to the tissue (for the fat regions that say how thick
 * the fat is beside a bone or muscle): the exact Euclidean distance transform of
 * Felzenszwalb & Huttenlocher ("Distance transforms of sampled functions", Theory of
 * Computing 8, 2012), one lower envelope of parabolas per grid line and axis. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "tissue/tissue_internal.h"

#define FAR 1e20 /* squared distance of a point with no tissue found yet */

/* d[q] = min_p (q - p)^2 + f[p] over one line of n values (f may be FAR). v, z: scratch
 * of n and n + 1 entries. */
static void transform_line(const double *f, double *d, int n, int *v, double *z)
{
    int k = 0;
    v[0] = 0;
    z[0] = -HUGE_VAL;
    z[1] = HUGE_VAL;
    for (int q = 1; q < n; q++) {
        /* z[0] is -infinity, so the search stops at k = 0 at the latest */
        double s = ((f[q] + (double)q * q) - (f[v[k]] + (double)v[k] * v[k])) / (2.0 * (q - v[k]));
        while (s <= z[k]) {
            k--;
            s = ((f[q] + (double)q * q) - (f[v[k]] + (double)v[k] * v[k])) / (2.0 * (q - v[k]));
        }
        k++;
        v[k] = q;
        z[k] = s;
        z[k + 1] = HUGE_VAL;
    }
    k = 0;
    for (int q = 0; q < n; q++) {
        while (z[k + 1] < q) k++;
        double dq = (double)(q - v[k]);
        d[q] = dq * dq + f[v[k]];
    }
}

/* One pass along axis `axis` over every line of the grid, in place on `sq` (squared
 * distances in cells). Lines without any finite value are left alone. */
static void pass(const sk__grid *g, int axis, float *sq, double *scratch, int *vscratch, int longest)
{
    size_t stride = axis == 0 ? 1 : (axis == 1 ? (size_t)g->n[0] : (size_t)g->n[0] * (size_t)g->n[1]);
    int n = g->n[axis];
    int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2; /* the other two axes */
    long lines = (long)g->n[a] * g->n[b];
#pragma omp parallel
    {
        int t = omp_get_thread_num();
        double *f = scratch + (size_t)t * 3 * (size_t)(longest + 1);
        double *d = f + longest + 1, *z = d + longest + 1;
        int *v = vscratch + (size_t)t * (size_t)(longest + 1);
#pragma omp for schedule(dynamic, 64)
        for (long line = 0; line < lines; line++) {
            int c[3];
            c[axis] = 0;
            c[a] = (int)(line % g->n[a]);
            c[b] = (int)(line / g->n[a]);
            size_t base = sk__grid_index(g, c[0], c[1], c[2]);
            bool any = false;
            for (int q = 0; q < n; q++) {
                f[q] = sq[base + (size_t)q * stride];
                any |= f[q] < FAR;
            }
            if (!any) continue;
            transform_line(f, d, n, v, z);
            for (int q = 0; q < n; q++) sq[base + (size_t)q * stride] = (float)fmin(d[q], FAR);
        }
    }
}

sk_result sk__distance_to_tissue(const sk__grid *g, const sk__label *labels, double cap_mm, float *distance,
                                 sk_error *err)
{
    int longest = g->n[0] > g->n[1] ? g->n[0] : g->n[1];
    if (g->n[2] > longest) longest = g->n[2];
    int threads = omp_get_max_threads();
    double *scratch = malloc((size_t)threads * 3 * (size_t)(longest + 1) * sizeof *scratch);
    int *vscratch = malloc((size_t)threads * (size_t)(longest + 1) * sizeof *vscratch);
    if (!scratch || !vscratch) {
        free(scratch);
        free(vscratch);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the distance field");
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < g->count; i++) distance[i] = labels[i] != SK__LABEL_NONE ? 0.0f : (float)FAR;
    for (int axis = 0; axis < 3; axis++) pass(g, axis, distance, scratch, vscratch, longest);
    float cap = (float)cap_mm;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < g->count; i++) distance[i] = fminf((float)(sqrt(distance[i]) * g->spacing), cap);
    free(scratch);
    free(vscratch);
    return SK_OK;
}
