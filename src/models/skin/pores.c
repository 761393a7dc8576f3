/* Pores (paper sec. 3.1: hair pores sit where furrows cross, one sweat pore opens at the
 * centre of each ridge; the paper leaves them out of its model). Each is a smooth pit
 * depth (1 - r^2/R^2)^2 for r < R, placed at the level-1 furrow junctions (hair) and at
 * the profile centres of the cells of one level (sweat), each place taken with the
 * given density, radius and depth varied by +-20 %. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

#define SK__SALT_PORE 0x504f5245ULL

typedef struct candidate {
    double x, y;
} candidate;

static int bucket_of(const sk__pore_grid *g, double x, double y)
{
    int bx = (int)(x * g->inv_w), by = (int)(y * g->inv_h);
    if (bx >= g->nx) bx = g->nx - 1;
    if (by >= g->ny) by = g->ny - 1;
    return by * g->nx + bx;
}

/* Unique level-1 furrow junctions in the tile period, in a fixed order. */
static sk_result junctions(const sk_skin *skin, candidate **out, size_t *count, sk_error *err)
{
    const sk__level *lv = &skin->levels[0];
    double w = skin->period[0], h = skin->period[1];
    candidate *c = malloc(sizeof(candidate) * (lv->use_count ? lv->use_count : 1));
    if (!c) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for pores");
    size_t n = 0;
    for (uint32_t i = 0; i < lv->cell_count; i++)
        for (uint32_t k = 0; k < lv->cells[i].use_count; k++) {
            uint32_t u = lv->cells[i].first_use + k;
            c[n].x = sk__wrap(skin->origin[2 * i] + lv->vxy[2 * u], w);
            c[n].y = sk__wrap(skin->origin[2 * i + 1] + lv->vxy[2 * u + 1], h);
            n++;
        }
    /* Drop repeats (each junction is a corner of several cells): bucket the candidates
       and keep the first of every cluster closer than eps (distances wrap). */
    double eps = 1e-6 * lv->spacing;
    sk__pore_grid g = {0};
    g.nx = (int)fmax(1, fmin(2048, floor(sqrt((double)n))));
    g.ny = g.nx;
    g.inv_w = g.nx / w, g.inv_h = g.ny / h;
    uint32_t *start = calloc((size_t)g.nx * g.ny + 1, sizeof(uint32_t));
    uint32_t *items = malloc(sizeof(uint32_t) * (n ? n : 1));
    uint32_t *fill = malloc(sizeof(uint32_t) * ((size_t)g.nx * g.ny + 1));
    bool *keep = malloc(sizeof(bool) * (n ? n : 1));
    if (!start || !items || !fill || !keep) {
        free(c), free(start), free(items), free(fill), free(keep);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for pores");
    }
    for (size_t i = 0; i < n; i++) start[bucket_of(&g, c[i].x, c[i].y) + 1]++;
    for (int b = 0; b < g.nx * g.ny; b++) start[b + 1] += start[b];
    memcpy(fill, start, sizeof(uint32_t) * ((size_t)g.nx * g.ny + 1));
    for (size_t i = 0; i < n; i++) items[fill[bucket_of(&g, c[i].x, c[i].y)]++] = (uint32_t)i;
    size_t kept = 0;
    for (size_t i = 0; i < n; i++) {
        keep[i] = true;
        int bx = (int)(c[i].x * g.inv_w), by = (int)(c[i].y * g.inv_h);
        for (int dy = -1; dy <= 1 && keep[i]; dy++)
            for (int dx = -1; dx <= 1 && keep[i]; dx++) {
                int qx = sk_imodpos(bx + dx, g.nx), qy = sk_imodpos(by + dy, g.ny);
                int b = qy * g.nx + qx;
                for (uint32_t q = start[b]; q < start[b + 1]; q++) {
                    uint32_t j = items[q];
                    if (j >= i || !keep[j]) continue;
                    double ddx = fabs(c[j].x - c[i].x), ddy = fabs(c[j].y - c[i].y);
                    ddx = fmin(ddx, w - ddx), ddy = fmin(ddy, h - ddy);
                    if (ddx < eps && ddy < eps) {
                        keep[i] = false;
                        break;
                    }
                }
            }
        if (keep[i]) c[kept++] = c[i];
    }
    free(start), free(items), free(fill), free(keep);
    *out = c;
    *count = kept;
    return SK_OK;
}

static void add_pore(sk__pore *list, uint32_t *n, const sk_skin *skin,
                     const sk_skin_pore_kind *kind, uint64_t salt, uint64_t id, double x, double y)
{
    sk_rng rng = sk_rng_make(skin->desc.seed, SK__SALT_PORE, salt, id);
    if (sk_rng_uniform(&rng) >= kind->density) return;
    sk__pore *p = &list[(*n)++];
    p->x = (float)sk__wrap(x, skin->period[0]);
    p->y = (float)sk__wrap(y, skin->period[1]);
    p->radius = kind->radius_mm * (float)sk_rng_range(&rng, 0.8, 1.2);
    p->depth = kind->depth_mm * (float)sk_rng_range(&rng, 0.8, 1.2);
}

sk_result sk__build_pores(sk_skin *skin, sk_error *err)
{
    const sk_skin_pores *pd = &skin->desc.pores;
    sk__pore_grid *g = &skin->pores;
    bool hair = pd->hair.depth_mm > 0, sweat = pd->sweat.depth_mm > 0;
    if (!hair && !sweat) return SK_OK;
    candidate *junc = NULL;
    size_t nj = 0;
    if (hair) {
        sk_result r = junctions(skin, &junc, &nj, err);
        if (r != SK_OK) return r;
    }
    int sl = pd->sweat_level - 1;
    size_t ns = sweat ? skin->levels[sl].cell_count : 0;
    sk__pore *list = malloc(sizeof(sk__pore) * (nj + ns + 1));
    if (!list) {
        free(junc);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for pores");
    }
    uint32_t n = 0;
    for (size_t i = 0; i < nj; i++) add_pore(list, &n, skin, &pd->hair, 1, i, junc[i].x, junc[i].y);
    free(junc);
    for (size_t i = 0; i < ns; i++) {
        const sk__cell *c = &skin->levels[sl].cells[i];
        double wx, wy;
        sk__to_world(skin, sl, (uint32_t)i, c->cx, c->cy, &wx, &wy);
        add_pore(list, &n, skin, &pd->sweat, 2, i, wx, wy);
    }
    float rmax = 1e-6f;
    for (uint32_t i = 0; i < n; i++) rmax = fmaxf(rmax, list[i].radius);
    double w = skin->period[0], h = skin->period[1];
    g->max_radius = rmax;
    g->nx = (int)fmax(1, fmin(2048, floor(w / rmax)));
    g->ny = (int)fmax(1, fmin(2048, floor(h / rmax)));
    g->inv_w = g->nx / w, g->inv_h = g->ny / h;
    size_t nb = (size_t)g->nx * g->ny;
    /* each bucket's own pores first (a counting sort) */
    uint32_t *own = calloc(nb + 1, sizeof(uint32_t)), *fill = malloc(sizeof(uint32_t) * (nb + 1));
    sk__pore *sorted = malloc(sizeof(sk__pore) * (n ? n : 1));
    g->start = calloc(nb + 1, sizeof(uint32_t));
    g->near = malloc(sizeof(sk__pore_near) * (9 * (size_t)n + 1));
    if (!own || !fill || !sorted || !g->start || !g->near) {
        free(list), free(own), free(fill), free(sorted);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for pores");
    }
    for (uint32_t i = 0; i < n; i++) own[bucket_of(g, list[i].x, list[i].y) + 1]++;
    for (size_t b = 0; b < nb; b++) own[b + 1] += own[b];
    memcpy(fill, own, sizeof(uint32_t) * (nb + 1));
    for (uint32_t i = 0; i < n; i++) sorted[fill[bucket_of(g, list[i].x, list[i].y)]++] = list[i];
    free(list);
    /* Then every bucket's list of its neighbours' pores: bucket t sees neighbour t + d (one
       wrap at most) with its pores moved by the period crossed. Neighbours in a fixed
       order, so a point sums its pores in the same order wherever it is. */
    for (int pass = 0; pass < 2; pass++) {
        for (int r = 0; r < 9; r++) {
            int dx = r % 3 - 1, dy = r / 3 - 1;
            for (uint32_t i = 0; i < n; i++) {
                int sb = bucket_of(g, sorted[i].x, sorted[i].y);
                int tx = sb % g->nx - dx, ty = sb / g->nx - dy;
                double ox = 0, oy = 0;
                if (tx < 0)
                    tx += g->nx, ox = w; /* t sees the pore across its right edge */
                else if (tx >= g->nx)
                    tx -= g->nx, ox = -w;
                if (ty < 0)
                    ty += g->ny, oy = h;
                else if (ty >= g->ny)
                    ty -= g->ny, oy = -h;
                size_t t = (size_t)ty * g->nx + tx;
                if (pass == 0) {
                    g->start[t + 1]++;
                } else {
                    sk__pore_near *q = &g->near[fill[t]++];
                    q->x = sorted[i].x + ox, q->y = sorted[i].y + oy;
                    q->radius = sorted[i].radius, q->depth = sorted[i].depth;
                }
            }
        }
        if (pass == 0) {
            for (size_t b = 0; b < nb; b++) g->start[b + 1] += g->start[b];
            memcpy(fill, g->start, sizeof(uint32_t) * (nb + 1));
        }
    }
    g->count = n;
    free(own), free(fill), free(sorted);
    return SK_OK;
}

void sk__pores_eval(const sk_skin *skin, double x, double y, float *h, float grad[2])
{
    const sk__pore_grid *g = &skin->pores;
    x = sk__wrap(x, skin->period[0]);
    y = sk__wrap(y, skin->period[1]);
    int bx = (int)(x * g->inv_w), by = (int)(y * g->inv_h);
    if (bx >= g->nx) bx = g->nx - 1;
    if (by >= g->ny) by = g->ny - 1;
    size_t b = (size_t)by * g->nx + bx;
    float sum = 0, gx = 0, gy = 0;
    for (uint32_t i = g->start[b]; i < g->start[b + 1]; i++) {
        const sk__pore_near *p = &g->near[i];
        float qx = (float)(x - p->x), qy = (float)(y - p->y);
        float r2 = qx * qx + qy * qy, R2 = p->radius * p->radius;
        if (r2 >= R2) continue;
        float u = r2 / R2, om = 1.0f - u;
        sum -= p->depth * om * om;
        /* d/dq of -D (1 - u)^2 = 4 D (1 - u) q / R^2 */
        gx += 4.0f * p->depth * om * qx / R2;
        gy += 4.0f * p->depth * om * qy / R2;
    }
    *h = sum;
    grad[0] = gx, grad[1] = gy;
}

float sk__pores_deepest(const sk_skin *skin)
{
    /* A point of bucket b is reached only by the pores of b's list, and the pores that
       reach it overlap one another: its pit is at most the depth of one of them plus the
       depths of the others of the list that overlap that one. */
    const sk__pore_grid *g = &skin->pores;
    if (!g->count) return 0.0f;
    double deepest = 0.0;
    size_t nb = (size_t)g->nx * g->ny;
    for (size_t b = 0; b < nb; b++)
        for (uint32_t i = g->start[b]; i < g->start[b + 1]; i++) {
            const sk__pore_near *p = &g->near[i];
            double sum = p->depth;
            for (uint32_t j = g->start[b]; j < g->start[b + 1]; j++) {
                const sk__pore_near *q = &g->near[j];
                double dx = p->x - q->x, dy = p->y - q->y, reach = (double)p->radius + q->radius;
                if (j != i && dx * dx + dy * dy < reach * reach) sum += q->depth;
            }
            deepest = deepest > sum ? deepest : sum;
        }
    return (float)deepest;
}
