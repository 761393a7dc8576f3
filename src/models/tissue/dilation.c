/* The paper's dilation (Shigemori & Kawai sec. 4): "for every grid point with a positive
 * value, add to the grid points around it (itself included) a value inversely
 * proportional to their distance", repeated a few times, so the isosurface lies a chosen
 * distance outside the tissue. The weight of an offset d (within the radius) is
 * 1 / max(|d|, spacing), normalised so a point whose whole neighbourhood is positive
 * gains exactly 1 per pass (then the threshold means the same at any spacing).
 *
 * Work is spent only where the kernel straddles the edge of the positive points: running
 * counts of positive points in the box around each point (separable, three sliding
 * sums) tell the points with none in reach (unchanged) and those with every point in
 * reach positive (plus 1) from the few that need the weighted sum. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

typedef struct kernel {
    int count, reach; /* offsets, and the largest |component| in cells */
    ptrdiff_t *step;  /* offset as a change of grid index */
    float *w;
} kernel;

static sk_result make_kernel(const sk__grid *g, double radius_mm, kernel *k, sk_error *err)
{
    double rc = radius_mm / g->spacing;
    int reach = (int)floor(rc + 1e-9);
    int side = 2 * reach + 1, cap = side * side * side;
    k->step = malloc((size_t)cap * sizeof *k->step);
    k->w = malloc((size_t)cap * sizeof *k->w);
    if (!k->step || !k->w)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the dilation");
    k->count = 0;
    k->reach = reach;
    double total = 0.0;
    for (int z = -reach; z <= reach; z++)
        for (int y = -reach; y <= reach; y++)
            for (int x = -reach; x <= reach; x++) {
                double r = sqrt((double)(x * x + y * y + z * z));
                if (r > rc + 1e-9) continue;
                int i = k->count++;
                k->step[i] = ((ptrdiff_t)z * g->n[1] + y) * g->n[0] + x;
                k->w[i] = (float)(1.0 / fmax(r, 1.0));
                total += k->w[i];
            }
    for (int i = 0; i < k->count; i++) k->w[i] = (float)(k->w[i] / total);
    return SK_OK;
}

/* count[i] = sum of src over the window [-reach, reach] along `axis` around i (0 outside
 * the grid). */
static void window_sums(const sk__grid *g, int axis, int reach, const uint16_t *src, uint16_t *dst)
{
    size_t stride =
        axis == 0 ? 1 : (axis == 1 ? (size_t)g->n[0] : (size_t)g->n[0] * (size_t)g->n[1]);
    int n = g->n[axis], a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
    long lines = (long)g->n[a] * g->n[b];
#pragma omp parallel for schedule(static)
    for (long line = 0; line < lines; line++) {
        int c[3];
        c[axis] = 0;
        c[a] = (int)(line % g->n[a]);
        c[b] = (int)(line / g->n[a]);
        size_t base = sk__grid_index(g, c[0], c[1], c[2]);
        unsigned sum = 0;
        for (int q = 0; q <= reach && q < n; q++) sum += src[base + (size_t)q * stride];
        for (int q = 0; q < n; q++) {
            dst[base + (size_t)q * stride] = (uint16_t)sum;
            if (q + reach + 1 < n) sum += src[base + (size_t)(q + reach + 1) * stride];
            if (q - reach >= 0) sum -= src[base + (size_t)(q - reach) * stride];
        }
    }
}

sk_result sk__dilate(const sk__grid *g, const uint8_t *seed, int passes, double radius_mm,
                     float *value, sk_error *err)
{
    kernel k = {0};
    uint16_t *a = malloc(g->count * sizeof *a), *b = malloc(g->count * sizeof *b);
    uint8_t *positive = malloc(g->count);
    sk_result r = make_kernel(g, radius_mm, &k, err);
    if (r == SK_OK && (!a || !b || !positive))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the dilation");
    if (r == SK_OK && (2 * k.reach + 1) * (2 * k.reach + 1) * (2 * k.reach + 1) > 65535)
        r = sk_fail(err, SK_ERROR_LIMIT, "skin.dilation_radius_mm reaches %d cells, more than 19",
                    k.reach);
    if (r == SK_OK) {
        const unsigned full = (unsigned)((2 * k.reach + 1) * (2 * k.reach + 1) * (2 * k.reach + 1));
        const int R = k.reach;
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < g->count; i++) value[i] = seed[i] ? 1.0f : 0.0f;
        for (int pass = 0; pass < passes; pass++) {
#pragma omp parallel for schedule(static)
            for (size_t i = 0; i < g->count; i++) {
                positive[i] = value[i] > 0.0f;
                a[i] = positive[i];
            }
            /* positive points in the box of side 2 reach + 1 around every point */
            window_sums(g, 0, R, a, b);
            window_sums(g, 1, R, b, a);
            window_sums(g, 2, R, a, b);
#pragma omp parallel for schedule(dynamic, 2)
            for (int z = 0; z < g->n[2]; z++)
                for (int y = 0; y < g->n[1]; y++)
                    for (int x = 0; x < g->n[0]; x++) {
                        size_t i = sk__grid_index(g, x, y, z);
                        unsigned in_box = b[i];
                        if (in_box == 0) continue; /* no positive point in reach */
                        bool inner = x >= R && y >= R && z >= R && x < g->n[0] - R &&
                                     y < g->n[1] - R && z < g->n[2] - R;
                        if (inner && in_box == full) { /* the whole kernel */
                            value[i] += 1.0f;
                            continue;
                        }
                        float sum = 0.0f;
                        if (inner) {
                            for (int o = 0; o < k.count; o++)
                                sum += positive[(ptrdiff_t)i + k.step[o]] ? k.w[o] : 0.0f;
                        } else {
                            /* near the grid's edge (never reached by the tissue's dilation,
                               which the grid's margin keeps inside): offsets checked */
                            int o = 0;
                            for (int dz = -R; dz <= R; dz++)
                                for (int dy = -R; dy <= R; dy++)
                                    for (int dx = -R; dx <= R; dx++) {
                                        double rr = sqrt((double)(dx * dx + dy * dy + dz * dz));
                                        if (rr > radius_mm / g->spacing + 1e-9) continue;
                                        int qx = x + dx, qy = y + dy, qz = z + dz;
                                        if (qx >= 0 && qy >= 0 && qz >= 0 && qx < g->n[0] &&
                                            qy < g->n[1] && qz < g->n[2] &&
                                            positive[sk__grid_index(g, qx, qy, qz)])
                                            sum += k.w[o];
                                        o++;
                                    }
                        }
                        value[i] += sum;
                    }
        }
    }
    free(k.step);
    free(k.w);
    free(a);
    free(b);
    free(positive);
    return r;
}
