/* Per-pixel query records (paper sec. 3.2.3 (2): find the polygon holding a point at every
 * level, then its section profile, sec. 3.2.1 (2)): for every use of a finished level, a
 * fan record (site, the two vertices, the gauge and the edge to unwarp) and a sector
 * record (profile centre, the two vertices, the gauge of x' and the normal pair for the
 * roundness), each one cache line, so a pixel's tests read one record each. */
#include <math.h>
#include <stdlib.h>

#include "models/skin/skin_internal.h"

/* The rays from origin o to the use's start vertex (a) and the next use's (b), with the
 * margins of the tests against them. */
static void rays(float ox, float oy, const sk__use *u, const sk__use *v, float *a, float *b)
{
    a[0] = u->vx - ox, a[1] = u->vy - oy, a[2] = (fabsf(a[0]) + fabsf(a[1])) * SK__SECTOR_MARGIN;
    b[0] = v->vx - ox, b[1] = v->vy - oy, b[2] = (fabsf(b[0]) + fabsf(b[1])) * SK__SECTOR_MARGIN;
}

sk_result sk__build_query_records(sk__level *lv, sk_error *err)
{
    size_t n = lv->use_count ? lv->use_count : 1;
    /* one record per cache line (both are 64 bytes) */
    lv->fans = aligned_alloc(64, sizeof(sk__fan) * n);
    lv->sectors = aligned_alloc(64, sizeof(sk__sector) * n);
    if (!lv->fans || !lv->sectors)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the query records");
#pragma omp parallel for schedule(static) if (lv->cell_count >= SK__PARALLEL_ITEMS)
    for (long ci = 0; ci < (long)lv->cell_count; ci++) {
        uint32_t c = (uint32_t)ci;
        const sk__cell *cell = &lv->cells[c];
        uint32_t first = cell->first_use, count = cell->use_count;
        for (uint32_t k = 0; k < count; k++) {
            const sk__use *u = &lv->uses[first + k];
            const sk__use *v = &lv->uses[first + (k + 1 == count ? 0 : k + 1)];
            /* distances from the site and the centre to the line, in double */
            double hs = (double)u->d - ((double)u->nx * cell->sx + (double)u->ny * cell->sy);
            double hc = (double)u->d - ((double)u->nx * cell->cx + (double)u->ny * cell->cy);
            double hv = (double)v->d - ((double)v->nx * cell->cx + (double)v->ny * cell->cy);
            if (hs < 1e-12) hs = 1e-12;
            if (hc < 1e-12) hc = 1e-12;
            if (hv < 1e-12) hv = 1e-12;

            sk__fan *f = &lv->fans[first + k];
            float a[3], b[3];
            f->sx = cell->sx, f->sy = cell->sy;
            rays(cell->sx, cell->sy, u, v, a, b);
            f->ax = a[0], f->ay = a[1], f->an = a[2], f->bx = b[0], f->by = b[1], f->bn = b[2];
            f->gx = (float)(u->nx / hs), f->gy = (float)(u->ny / hs);
            f->shx = u->shx, f->shy = u->shy;
            f->edge = lv->perturbed ? u->edge : SK__SKIN_NONE;
            f->cell = c;
            f->parent = cell->parent;
            /* The support lies within h_apex of the edge's line, which is (1 - gauge) hs
               away: clear of it below 1 - h_apex / hs, here with 1 % and 1e-5 hs to spare. */
            f->gcut = -1.0f;
            if (f->edge != SK__SKIN_NONE)
                f->gcut = (float)(1.0 - 1e-5 - 1.01 * lv->edges[f->edge].h_apex / hs);

            sk__sector *s = &lv->sectors[first + k];
            s->cx = cell->cx, s->cy = cell->cy;
            rays(cell->cx, cell->cy, u, v, a, b);
            s->ax = a[0], s->ay = a[1], s->an = a[2], s->bx = b[0], s->by = b[1], s->bn = b[2];
            s->gx = (float)(u->nx / hc), s->gy = (float)(u->ny / hc);
            s->nx = u->nx, s->ny = u->ny, s->h = (float)hc;
            s->mx = v->nx, s->my = v->ny, s->hm = (float)hv;
        }
    }
    return SK_OK;
}
