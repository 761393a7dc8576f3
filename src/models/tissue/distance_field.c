/* Distance from every grid point to the tissue (for the fat regions that say how thick
 * the fat is beside a bone or muscle): the exact Euclidean distance transform of
 * Felzenszwalb & Huttenlocher ("Distance transforms of sampled functions", Theory of
 * Computing 8, 2012), one lower envelope of parabolas per grid line and axis. */
#include <math.h>
#include <stdlib.h>

#include "models/tissue/tissue_internal.h"

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

/* One pass along axis `axis` over every line of the box (n[] points, `sq` its squared
 * distances in cells, x fastest), in place. Lines without any finite value are left. */
static void pass(const int n[3], int axis, float *sq, double *scratch, int *vscratch, int longest)
{
    size_t stride = axis == 0 ? 1 : (axis == 1 ? (size_t)n[0] : (size_t)n[0] * (size_t)n[1]);
    int len = n[axis];
    int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2; /* the other two axes */
    long lines = (long)n[a] * n[b];
#pragma omp parallel
    {
        int t = sk_thread_index();
        double *f = scratch + (size_t)t * 3 * (size_t)(longest + 1);
        double *d = f + longest + 1, *z = d + longest + 1;
        int *v = vscratch + (size_t)t * (size_t)(longest + 1);
#pragma omp for schedule(dynamic, 64)
        for (long line = 0; line < lines; line++) {
            int c[3];
            c[axis] = 0;
            c[a] = (int)(line % n[a]);
            c[b] = (int)(line / n[a]);
            size_t base =
                ((size_t)c[2] * (size_t)n[1] + (size_t)c[1]) * (size_t)n[0] + (size_t)c[0];
            bool any = false;
            for (int q = 0; q < len; q++) {
                f[q] = sq[base + (size_t)q * stride];
                any |= f[q] < FAR;
            }
            if (!any) continue;
            transform_line(f, d, len, v, z);
            for (int q = 0; q < len; q++) sq[base + (size_t)q * stride] = (float)fmin(d[q], FAR);
        }
    }
}

sk_result sk__distance_to_tissue(const sk__grid *g, const sk__label *labels, const int lo[3],
                                 const int hi[3], float *distance, sk_error *err)
{
    int n[3] = {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
    int longest = n[0] > n[1] ? n[0] : n[1];
    if (n[2] > longest) longest = n[2];
    int threads = sk_threads_max();
    double *scratch = malloc((size_t)threads * 3 * (size_t)(longest + 1) * sizeof *scratch);
    int *vscratch = malloc((size_t)threads * (size_t)(longest + 1) * sizeof *vscratch);
    if (!scratch || !vscratch) {
        free(scratch);
        free(vscratch);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the distance field");
    }
#pragma omp parallel for schedule(static)
    for (int z = 0; z < n[2]; z++)
        for (int y = 0; y < n[1]; y++)
            for (int x = 0; x < n[0]; x++) {
                sk__label l = labels[sk__grid_index(g, lo[0] + x, lo[1] + y, lo[2] + z)];
                distance[((size_t)z * (size_t)n[1] + (size_t)y) * (size_t)n[0] + (size_t)x] =
                    l != SK__LABEL_NONE ? 0.0f : (float)FAR;
            }
    for (int axis = 0; axis < 3; axis++) pass(n, axis, distance, scratch, vscratch, longest);
    size_t count = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < count; i++) distance[i] = (float)(sqrt(distance[i]) * g->spacing);
    free(scratch);
    free(vscratch);
    return SK_OK;
}
