/* The paper's dilation (Shigemori & Kawai sec. 4): "for every grid point with a positive
 * value, add to the grid points around it (itself included) a value inversely
 * proportional to their distance", repeated a few times, so the isosurface lies a chosen
 * distance outside the tissue. The weight of an offset d (within the radius) is
 * 1 / max(|d|, spacing), normalised so a point whose whole neighbourhood is positive
 * gains exactly 1 per pass (then the threshold means the same at any spacing). Done in
 * blocks of 8^3 points: blocks far from every positive point are skipped, blocks deep
 * inside take the whole kernel at once. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tissue/tissue_internal.h"

#define BLOCK 8

typedef struct kernel {
    int count, reach; /* offsets, and the largest |component| in cells */
    ptrdiff_t *step;  /* offset as a change of grid index */
    int (*d)[3];
    float *w;
} kernel;

static sk_result make_kernel(const sk__grid *g, double radius_mm, kernel *k, sk_error *err)
{
    double rc = radius_mm / g->spacing;
    int reach = (int)floor(rc + 1e-9);
    int side = 2 * reach + 1, cap = side * side * side;
    k->step = malloc((size_t)cap * sizeof *k->step);
    k->d = malloc((size_t)cap * sizeof *k->d);
    k->w = malloc((size_t)cap * sizeof *k->w);
    if (!k->step || !k->d || !k->w) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the dilation");
    k->count = 0;
    k->reach = reach;
    double total = 0.0;
    for (int z = -reach; z <= reach; z++)
        for (int y = -reach; y <= reach; y++)
            for (int x = -reach; x <= reach; x++) {
                double r = sqrt((double)(x * x + y * y + z * z));
                if (r > rc + 1e-9) continue;
                int i = k->count++;
                k->d[i][0] = x;
                k->d[i][1] = y;
                k->d[i][2] = z;
                k->step[i] = ((ptrdiff_t)z * g->n[1] + y) * g->n[0] + x;
                k->w[i] = (float)(1.0 / fmax(r, 1.0));
                total += k->w[i];
            }
    for (int i = 0; i < k->count; i++) k->w[i] = (float)(k->w[i] / total);
    return SK_OK;
}

static void free_kernel(kernel *k)
{
    free(k->step);
    free(k->d);
    free(k->w);
}

typedef struct blocks {
    int n[3];
    size_t count;
    uint8_t *any, *full; /* some / all points positive */
} blocks;

static void block_flags(const sk__grid *g, const uint8_t *positive, blocks *b)
{
#pragma omp parallel for schedule(dynamic, 16)
    for (size_t bi = 0; bi < b->count; bi++) {
        int bx = (int)(bi % (size_t)b->n[0]), by = (int)((bi / (size_t)b->n[0]) % (size_t)b->n[1]);
        int bz = (int)(bi / ((size_t)b->n[0] * (size_t)b->n[1]));
        bool any = false, all = true;
        for (int z = bz * BLOCK; z < (bz + 1) * BLOCK; z++)
            for (int y = by * BLOCK; y < (by + 1) * BLOCK; y++)
                for (int x = bx * BLOCK; x < (bx + 1) * BLOCK; x++) {
                    bool in = x < g->n[0] && y < g->n[1] && z < g->n[2] && positive[sk__grid_index(g, x, y, z)];
                    any |= in;
                    all &= in;
                }
        b->any[bi] = any;
        b->full[bi] = all;
    }
}

/* Whether every block within `reach` blocks of block (bx, by, bz) has the flag. */
static bool around(const blocks *b, const uint8_t *flag, int bx, int by, int bz, int reach, bool want_all)
{
    for (int z = bz - reach; z <= bz + reach; z++)
        for (int y = by - reach; y <= by + reach; y++)
            for (int x = bx - reach; x <= bx + reach; x++) {
                bool inside = x >= 0 && y >= 0 && z >= 0 && x < b->n[0] && y < b->n[1] && z < b->n[2];
                bool f = inside && flag[((size_t)z * (size_t)b->n[1] + (size_t)y) * (size_t)b->n[0] + (size_t)x];
                if (want_all && !f) return false;
                if (!want_all && f) return true;
            }
    return want_all;
}

static void dilate_block(const sk__grid *g, const kernel *k, const uint8_t *positive, float *value, int bx, int by,
                         int bz)
{
    for (int z = bz * BLOCK; z < (bz + 1) * BLOCK && z < g->n[2]; z++)
        for (int y = by * BLOCK; y < (by + 1) * BLOCK && y < g->n[1]; y++)
            for (int x = bx * BLOCK; x < (bx + 1) * BLOCK && x < g->n[0]; x++) {
                size_t i = sk__grid_index(g, x, y, z);
                bool inner = x >= k->reach && y >= k->reach && z >= k->reach && x < g->n[0] - k->reach &&
                             y < g->n[1] - k->reach && z < g->n[2] - k->reach;
                float sum = 0.0f;
                if (inner) {
                    for (int o = 0; o < k->count; o++) sum += positive[(ptrdiff_t)i + k->step[o]] ? k->w[o] : 0.0f;
                } else {
                    for (int o = 0; o < k->count; o++) {
                        int qx = x + k->d[o][0], qy = y + k->d[o][1], qz = z + k->d[o][2];
                        if (qx < 0 || qy < 0 || qz < 0 || qx >= g->n[0] || qy >= g->n[1] || qz >= g->n[2]) continue;
                        sum += positive[sk__grid_index(g, qx, qy, qz)] ? k->w[o] : 0.0f;
                    }
                }
                value[i] += sum;
            }
}

sk_result sk__dilate(const sk__grid *g, const uint8_t *seed, int passes, double radius_mm, float *value,
                     sk_error *err)
{
    kernel k = {0};
    blocks b = {{(g->n[0] + BLOCK - 1) / BLOCK, (g->n[1] + BLOCK - 1) / BLOCK, (g->n[2] + BLOCK - 1) / BLOCK}, 0, NULL,
                NULL};
    b.count = (size_t)b.n[0] * (size_t)b.n[1] * (size_t)b.n[2];
    uint8_t *positive = malloc(g->count);
    b.any = malloc(b.count);
    b.full = malloc(b.count);
    sk_result r = make_kernel(g, radius_mm, &k, err);
    if (r == SK_OK && (!positive || !b.any || !b.full))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the dilation");
    if (r == SK_OK) {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < g->count; i++) value[i] = seed[i] ? 1.0f : 0.0f;
        int reach_blocks = (k.reach + BLOCK - 1) / BLOCK;
        for (int pass = 0; pass < passes; pass++) {
#pragma omp parallel for schedule(static)
            for (size_t i = 0; i < g->count; i++) positive[i] = value[i] > 0.0f;
            block_flags(g, positive, &b);
#pragma omp parallel for schedule(dynamic, 8)
            for (size_t bi = 0; bi < b.count; bi++) {
                int bx = (int)(bi % (size_t)b.n[0]), by = (int)((bi / (size_t)b.n[0]) % (size_t)b.n[1]);
                int bz = (int)(bi / ((size_t)b.n[0] * (size_t)b.n[1]));
                if (!around(&b, b.any, bx, by, bz, reach_blocks, false)) continue; /* nothing in reach */
                if (around(&b, b.full, bx, by, bz, reach_blocks, true)) {         /* the whole kernel */
                    for (int z = bz * BLOCK; z < (bz + 1) * BLOCK && z < g->n[2]; z++)
                        for (int y = by * BLOCK; y < (by + 1) * BLOCK && y < g->n[1]; y++)
                            for (int x = bx * BLOCK; x < (bx + 1) * BLOCK && x < g->n[0]; x++)
                                value[sk__grid_index(g, x, y, z)] += 1.0f;
                    continue;
                }
                dilate_block(g, &k, positive, value, bx, by, bz);
            }
        }
    }
    free_kernel(&k);
    free(positive);
    free(b.any);
    free(b.full);
    return r;
}
