/* Cell geometry as the renderer sees it, for tests, debugging and overlays: a cell's
 * boundary is its straight polygon with every shared edge replaced by its perturbed
 * polyline (paper Fig. 4), then carried into the world by the perturbation of each level
 * above (the pieces on the parent's boundary follow the parent's polyline exactly). */
#include <math.h>
#include <stdlib.h>

#include "models/skin/skin_internal.h"

/* The edge whose perturbation shapes a straight boundary piece of a level-k cell with
 * line (nx, ny, d): walk up while the piece lies on the parent's boundary. */
static bool boundary_edge(const sk_skin *skin, int k, uint32_t c, const sk__use *piece,
                          int *edge_level, const sk__use **edge_use)
{
    for (int j = k - 1; j >= 0; j--) {
        c = skin->levels[j + 1].cells[c].parent;
        const sk__level *lv = &skin->levels[j];
        const sk__cell *pc = &lv->cells[c];
        const sk__use *found = NULL;
        for (uint32_t q = 0; q < pc->use_count; q++) {
            const sk__use *u = &lv->uses[pc->first_use + q];
            if (u->nx == piece->nx && u->ny == piece->ny && u->d == piece->d) found = u;
        }
        if (!found) return false;
        if (found->edge != SK__SKIN_NONE && lv->perturbed) {
            *edge_level = j;
            *edge_use = found;
            return true;
        }
    }
    return false;
}

static void emit(const sk_skin *skin, int k, uint32_t c, double x, double y, bool carry,
                 sk_vec2d *pts, size_t max, size_t *n)
{
    if (*n < max) {
        double wx, wy;
        if (!carry) {
            wx = x, wy = y;
        } else if (k == 0) {
            wx = x + skin->origin[2 * c], wy = y + skin->origin[2 * c + 1];
        } else {
            sk__to_world(skin, k - 1, skin->levels[k].cells[c].parent, x, y, &wx, &wy);
        }
        pts[*n].x = wx, pts[*n].y = wy;
    }
    (*n)++;
}

/* Points of use q of a cell (from its start, not including the next use's start). */
static size_t edge_points(const sk_skin *skin, int k, uint32_t cell, uint32_t q, int subdivide,
                          bool carry, sk_vec2d *points, size_t max_points, size_t n)
{
    const sk__level *lv = &skin->levels[k];
    const sk__cell *c = &lv->cells[cell];
    uint32_t ui = c->first_use + q, un = q + 1 == c->use_count ? c->first_use : ui + 1;
    const sk__use *u = &lv->uses[ui];
    double ax = lv->vxy[2 * ui], ay = lv->vxy[2 * ui + 1];
    double bx = lv->vxy[2 * un], by = lv->vxy[2 * un + 1];
    if (u->edge != SK__SKIN_NONE && lv->perturbed) {
        const sk__edge *e = &lv->edges[u->edge];
        const float *f = lv->f + e->f_first;
        int fc = lv->f_count;
        /* the left cell runs the edge a -> b (its outward normal opposes the edge's s
           direction), the right one b -> a */
        bool is_left = (u->nx * e->asx + u->ny * e->asy) < 0.0f;
        for (int i = 0; i < fc - 1; i++) {
            int j0 = is_left ? i : fc - 1 - i, j1 = is_left ? i + 1 : fc - 2 - i;
            for (int s = 0; s < subdivide; s++) {
                double tt = (double)s / subdivide;
                double t = ((double)j0 + tt * (j1 - j0)) / (fc - 1);
                double ff = f[j0] + tt * (f[j1] - f[j0]);
                double px = e->ax + t * (e->bx - e->ax) + ff * e->dx - u->shx;
                double py = e->ay + t * (e->by - e->ay) + ff * e->dy - u->shy;
                emit(skin, k, cell, px, py, carry, points, max_points, &n);
            }
        }
        return n;
    }
    int el;
    const sk__use *eu;
    if (k > 0 && boundary_edge(skin, k, cell, u, &el, &eu)) {
        /* parameters along the piece: its ends and the ancestor polyline's vertices */
        const sk__level *alv = &skin->levels[el];
        const sk__edge *e = &alv->edges[eu->edge];
        double ta = e->atx * (ax + eu->shx - e->ax) + e->aty * (ay + eu->shy - e->ay);
        double tb = e->atx * (bx + eu->shx - e->ax) + e->aty * (by + eu->shy - e->ay);
        int fc = alv->f_count;
        double lo = fmin(ta, tb), hi = fmax(ta, tb);
        int i0 = (int)floor(lo * (fc - 1)) + 1, i1 = (int)ceil(hi * (fc - 1)) - 1;
        double prev = 0.0;
        int count = i1 >= i0 ? i1 - i0 + 1 : 0;
        for (int ii = 0; ii <= count; ii++) {
            double next = 1.0;
            if (ii < count) {
                int i = ta < tb ? i0 + ii : i1 - ii;
                next = ((double)i / (fc - 1) - ta) / (tb - ta);
                if (!(next > prev + 1e-9 && next < 1 - 1e-9)) continue;
            }
            for (int s = 0; s < subdivide; s++) {
                double frac = prev + (next - prev) * s / subdivide;
                emit(skin, k, cell, ax + frac * (bx - ax), ay + frac * (by - ay), carry, points,
                     max_points, &n);
            }
            prev = next;
        }
        return n;
    }
    for (int s = 0; s < subdivide; s++) {
        double t = (double)s / subdivide;
        emit(skin, k, cell, ax + t * (bx - ax), ay + t * (by - ay), carry, points, max_points, &n);
    }
    return n;
}

size_t sk_skin_cell_outline(const sk_skin *skin, int level, uint32_t cell, int subdivide,
                            sk_vec2d *points, size_t max_points)
{
    if (!skin || level < 1 || level > skin->level_count) return 0;
    const sk__level *lv = &skin->levels[level - 1];
    if (cell >= lv->cell_count) return 0;
    if (subdivide < 1) subdivide = 1;
    size_t n = 0;
    for (uint32_t q = 0; q < lv->cells[cell].use_count; q++)
        n = edge_points(skin, level - 1, cell, q, subdivide, true, points, max_points, n);
    return n;
}

size_t sk__cell_polygon(const sk_skin *skin, int level, uint32_t cell, sk_vec2d *points,
                        size_t max_points)
{
    if (!skin || level < 1 || level > skin->level_count) return 0;
    const sk__level *lv = &skin->levels[level - 1];
    if (cell >= lv->cell_count) return 0;
    size_t n = 0;
    for (uint32_t q = 0; q < lv->cells[cell].use_count; q++)
        n = edge_points(skin, level - 1, cell, q, 1, false, points, max_points, n);
    return n;
}

size_t sk_skin_cell_edge(const sk_skin *skin, int level, uint32_t cell, uint32_t edge,
                         int subdivide, uint32_t *neighbour, sk_vec2d *points, size_t max_points)
{
    if (neighbour) *neighbour = UINT32_MAX;
    if (!skin || level < 1 || level > skin->level_count) return 0;
    const sk__level *lv = &skin->levels[level - 1];
    if (cell >= lv->cell_count || edge >= lv->cells[cell].use_count) return 0;
    if (subdivide < 1) subdivide = 1;
    if (neighbour) *neighbour = lv->uses[lv->cells[cell].first_use + edge].neighbour;
    return edge_points(skin, level - 1, cell, edge, subdivide, true, points, max_points, 0);
}

sk_result sk_skin_cell_info_get(const sk_skin *skin, int level, uint32_t cell,
                                sk_skin_cell_info *out, sk_error *err)
{
    if (!skin || !out)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin and out must not be NULL");
    if (level < 1 || level > skin->level_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "level = %d is out of range [1, %d]", level,
                       skin->level_count);
    const sk__level *lv = &skin->levels[level - 1];
    if (cell >= lv->cell_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "cell = %u is out of range [0, %u]", cell,
                       lv->cell_count - 1);
    const sk__cell *c = &lv->cells[cell];
    out->parent = level == 1 ? UINT32_MAX : c->parent;
    out->first_child = level < skin->level_count ? c->first_child : 0;
    out->child_count = level < skin->level_count ? c->child_count : 0;
    out->edge_count = c->use_count;
    if (level == 1) {
        out->site.x = skin->origin[2 * cell], out->site.y = skin->origin[2 * cell + 1];
    } else {
        sk__to_world(skin, level - 2, c->parent, c->sx, c->sy, &out->site.x, &out->site.y);
    }
    sk__to_world(skin, level - 1, cell, c->cx, c->cy, &out->centre.x, &out->centre.y);
    return SK_OK;
}
