/* Level-1 lookup grid: squares over the tile period listing the level-1 cells (with the
 * tile shift of the image) whose straight polygon meets them, so a point finds its cell
 * by testing a few convex polygons. */
#include <math.h>
#include <stdlib.h>

#include "models/skin/skin_internal.h"

/* Separating-axis test of a convex polygon against a rectangle. */
static bool poly_meets_rect(const sk__level *lv, const sk__cell *c, double ox, double oy, double x0,
                            double y0, double x1, double y1)
{
    for (uint32_t k = 0; k < c->use_count; k++) {
        const sk__use *u = &lv->uses[c->first_use + k];
        /* the rectangle corner farthest inside the half-plane must be inside */
        double cx = u->nx > 0 ? x0 : x1, cy = u->ny > 0 ? y0 : y1;
        if (u->nx * (cx - ox) + u->ny * (cy - oy) > u->d + 1e-6 * (fabs(u->d) + 1e-3)) return false;
    }
    return true;
}

/* Calls fn for every (square, shift) the cell covers; returns the number of entries. */
static size_t cover_cell(const sk_skin *skin, uint32_t i, uint32_t *start, uint32_t *cells,
                         double *shift, bool fill)
{
    const sk__level *lv = &skin->levels[0];
    const sk__grid *g = &skin->grid;
    const sk__cell *c = &lv->cells[i];
    double w = skin->period[0], h = skin->period[1];
    double ox = skin->origin[2 * i], oy = skin->origin[2 * i + 1];
    double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
    for (uint32_t k = 0; k < c->use_count; k++) {
        double x = ox + lv->vxy[2 * (c->first_use + k)],
               y = oy + lv->vxy[2 * (c->first_use + k) + 1];
        bx0 = fmin(bx0, x), bx1 = fmax(bx1, x), by0 = fmin(by0, y), by1 = fmax(by1, y);
    }
    double sw = w / g->nx, sh = h / g->ny;
    size_t n = 0;
    int m0 = (int)ceil((0.0 - bx1) / w) - 1, m1 = (int)floor((w - bx0) / w) + 1;
    int n0 = (int)ceil((0.0 - by1) / h) - 1, n1 = (int)floor((h - by0) / h) + 1;
    for (int mj = n0; mj <= n1; mj++)
        for (int mi = m0; mi <= m1; mi++) {
            double sx = mi * w, sy = mj * h;
            int gx0 = (int)floor((bx0 + sx) / sw), gx1 = (int)floor((bx1 + sx) / sw);
            int gy0 = (int)floor((by0 + sy) / sh), gy1 = (int)floor((by1 + sy) / sh);
            if (gx0 < 0) gx0 = 0;
            if (gy0 < 0) gy0 = 0;
            if (gx1 >= g->nx) gx1 = g->nx - 1;
            if (gy1 >= g->ny) gy1 = g->ny - 1;
            for (int gy = gy0; gy <= gy1; gy++)
                for (int gx = gx0; gx <= gx1; gx++) {
                    double x0 = gx * sw, y0 = gy * sh;
                    if (!poly_meets_rect(lv, c, ox + sx, oy + sy, x0, y0, x0 + sw, y0 + sh))
                        continue;
                    size_t sq = (size_t)gy * (size_t)g->nx + (size_t)gx;
                    if (fill) {
                        uint32_t e = start[sq]++;
                        cells[e] = i;
                        shift[2 * e] = ox + sx;
                        shift[2 * e + 1] = oy + sy;
                    } else {
                        start[sq + 1]++;
                    }
                    n++;
                }
        }
    return n;
}

sk_result sk__build_grid(sk_skin *skin, sk_error *err)
{
    sk__grid *g = &skin->grid;
    const sk__level *lv = &skin->levels[0];
    double w = skin->period[0], h = skin->period[1];
    double side = 0.5 * sqrt(w * h / lv->cell_count);
    g->nx = (int)fmax(1.0, fmin(2048.0, floor(w / side)));
    g->ny = (int)fmax(1.0, fmin(2048.0, floor(h / side)));
    g->inv_w = g->nx / w;
    g->inv_h = g->ny / h;
    size_t nsq = (size_t)g->nx * (size_t)g->ny;
    g->start = calloc(nsq + 1, sizeof(uint32_t));
    if (!g->start) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the grid");
    size_t total = 0;
    for (uint32_t i = 0; i < lv->cell_count; i++)
        total += cover_cell(skin, i, g->start, NULL, NULL, false);
    if (total > 0xffffffffu) return sk_fail(err, SK_ERROR_LIMIT, "level-1 grid too large");
    for (size_t s = 0; s < nsq; s++) g->start[s + 1] += g->start[s];
    g->cell = malloc(sizeof(uint32_t) * (total ? total : 1));
    g->shift = malloc(sizeof(double) * 2 * (total ? total : 1));
    uint32_t *fill = malloc(sizeof(uint32_t) * (nsq + 1));
    if (!g->cell || !g->shift || !fill) {
        free(fill);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the grid");
    }
    for (size_t s = 0; s <= nsq; s++) fill[s] = g->start[s];
    for (uint32_t i = 0; i < lv->cell_count; i++)
        cover_cell(skin, i, fill, g->cell, g->shift, true);
    free(fill);
    return SK_OK;
}
