/* Per-pixel query records (paper sec. 3.2.3 (2): find the polygon holding a point at every
 * level, then its section profile, sec. 3.2.1 (2)): for every use of a finished level, a
 * fan record (site, the two vertices, the gauge and the edge to unwarp) and a sector
 * record (profile centre, the two vertices, the gauge of x' and the normal pair for the
 * roundness), each one cache line, so a pixel's tests read one record each. */
#include <math.h>
#include <stdlib.h>

#include "skin/skin_internal.h"

sk_result sk__build_query_records(sk__level *lv, sk_error *err)
{
    size_t n = lv->use_count ? lv->use_count : 1;
    /* one record per cache line (both are 64 bytes) */
    lv->fans = aligned_alloc(64, sizeof(sk__fan) * n);
    lv->sectors = aligned_alloc(64, sizeof(sk__sector) * n);
    if (!lv->fans || !lv->sectors)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the query records");
#pragma omp parallel for schedule(static)
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
            f->sx = cell->sx, f->sy = cell->sy;
            f->ax = u->vx - cell->sx, f->ay = u->vy - cell->sy;
            f->bx = v->vx - cell->sx, f->by = v->vy - cell->sy;
            f->an = (fabsf(f->ax) + fabsf(f->ay)) * SK__SECTOR_MARGIN;
            f->bn = (fabsf(f->bx) + fabsf(f->by)) * SK__SECTOR_MARGIN;
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
            s->ax = u->vx - cell->cx, s->ay = u->vy - cell->cy;
            s->bx = v->vx - cell->cx, s->by = v->vy - cell->cy;
            s->an = (fabsf(s->ax) + fabsf(s->ay)) * SK__SECTOR_MARGIN;
            s->bn = (fabsf(s->bx) + fabsf(s->by)) * SK__SECTOR_MARGIN;
            s->gx = (float)(u->nx / hc), s->gy = (float)(u->ny / hc);
            s->nx = u->nx, s->ny = u->ny, s->h = (float)hc;
            s->mx = v->nx, s->my = v->ny, s->hm = (float)hv;
        }
    }
    return SK_OK;
}
