/* Hierarchy (paper sec. 3.2.3 (1), Figs. 8 and 9): inside every cell of a level, the
 * centre points of the next level that fall in it are Voronoi-divided among themselves
 * and clipped to the (straight) parent polygon, with parent-child links kept. The points
 * come from one lattice per level over the whole tile, so children of neighbouring
 * parents continue one another's layout; a parent that catches no point gets one child at
 * its centre. Children take the parent's boundary unchanged; the parent's perturbation
 * carries them (see skin_internal.h, Frames), so they tile the perturbed parent. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

/* Boundary tags are negative: -(parent use index) - 2. */
static int64_t parent_tag(uint32_t use) { return -(int64_t)use - 2; }

typedef struct child_point {
    uint32_t parent;
    uint32_t order; /* lattice index, or UINT32_MAX for a parent's fallback centre */
    double x, y;    /* y space, frame of the level-1 ancestor */
} child_point;

typedef struct dist_item {
    double d2;
    uint32_t j;
} dist_item;

static int dist_cmp(const void *pa, const void *pb)
{
    const dist_item *a = pa, *b = pb;
    if (a->d2 != b->d2) return a->d2 < b->d2 ? -1 : 1;
    return a->j < b->j ? -1 : (a->j > b->j);
}

/* A clipped child polygon kept between the parallel clipping and the layout: in its own
 * slot of a shared slab when it has few vertices (almost always), else on the heap. */
#define SK__CHILD_SLOT 16
typedef struct child_poly {
    int n;
    double *x, *y;
    int64_t *tag;
    bool heap;
} child_poly;

typedef struct child_slab {
    double *x, *y;
    int64_t *tag;
} child_slab;

static bool child_poly_keep(child_poly *cp, const child_slab *slab, uint32_t ci, const sk__poly *p)
{
    cp->n = p->n;
    cp->heap = p->n > SK__CHILD_SLOT;
    if (cp->heap) {
        cp->x = malloc(sizeof(double) * (size_t)p->n);
        cp->y = malloc(sizeof(double) * (size_t)p->n);
        cp->tag = malloc(sizeof(int64_t) * (size_t)p->n);
        if (!cp->x || !cp->y || !cp->tag) return false;
    } else {
        size_t o = (size_t)ci * SK__CHILD_SLOT;
        cp->x = slab->x + o, cp->y = slab->y + o, cp->tag = slab->tag + o;
    }
    memcpy(cp->x, p->x, sizeof(double) * (size_t)p->n);
    memcpy(cp->y, p->y, sizeof(double) * (size_t)p->n);
    memcpy(cp->tag, p->tag, sizeof(int64_t) * (size_t)p->n);
    return true;
}

static void child_polys_free(child_poly *polys, uint32_t n, child_slab *slab)
{
    for (uint32_t i = 0; i < n; i++)
        if (polys[i].heap) free(polys[i].x), free(polys[i].y), free(polys[i].tag);
    free(polys);
    free(slab->x), free(slab->y), free(slab->tag);
}

/* Clips child i (of `n` siblings starting at `first`) to the parent polygon. */
static bool clip_child(const sk__level *lv, const sk__level *plv, uint32_t parent, const double *zs,
                       uint32_t first, uint32_t n, uint32_t i, dist_item *order, sk__poly *poly)
{
    const sk__cell *pc = &plv->cells[parent];
    const double(*mi)[2] = (const double(*)[2])lv->minv;
    double zx = zs[2 * (first + i)], zy = zs[2 * (first + i) + 1];
    poly->n = (int)pc->use_count;
    if (poly->n > SK__POLY_MAX) return false;
    for (uint32_t k = 0; k < pc->use_count; k++) {
        uint32_t u = pc->first_use + k;
        double x = plv->vxy[2 * u], y = plv->vxy[2 * u + 1];
        poly->x[k] = mi[0][0] * x + mi[0][1] * y - zx;
        poly->y[k] = mi[1][0] * x + mi[1][1] * y - zy;
        poly->tag[k] = parent_tag(u);
    }
    uint32_t m = 0;
    for (uint32_t j = 0; j < n; j++) {
        if (j == i) continue;
        double vx = zs[2 * (first + j)] - zx, vy = zs[2 * (first + j) + 1] - zy;
        order[m].d2 = vx * vx + vy * vy;
        order[m].j = j;
        m++;
    }
    if (m > 16) qsort(order, m, sizeof *order, dist_cmp);
    for (uint32_t q = 0; q < m; q++) {
        uint32_t j = order[q].j;
        if (m > 16) {
            double rmax2 = 0;
            for (int k = 0; k < poly->n; k++) {
                double d2 = poly->x[k] * poly->x[k] + poly->y[k] * poly->y[k];
                if (d2 > rmax2) rmax2 = d2;
            }
            if (order[q].d2 > 4.0 * rmax2) break; /* security radius reached */
        }
        double vx = zs[2 * (first + j)] - zx, vy = zs[2 * (first + j) + 1] - zy;
        double vv = vx * vx + vy * vy;
        if (vv <= 0.0) continue;
        if (!sk__poly_clip(poly, vx, vy, 0.5 * vv, (int64_t)(first + j))) return false;
    }
    return true;
}

/* Which straight parent holds each point (frame F(level), where the levels above are
   straight and nested), and the point in that frame; points are independent. */
static void locate_points(sk_skin *skin, int level, const double *xy, uint32_t count,
                          uint32_t *parent_of, float *local)
{
#pragma omp parallel for schedule(static) if (count >= SK__PARALLEL_ITEMS)
    for (long i = 0; i < (long)count; i++)
        parent_of[i] = sk__locate_straight(skin, level - 1, xy[2 * i], xy[2 * i + 1], &local[2 * i],
                                           &local[2 * i + 1]);
}

/* Sorted by parent, then by lattice index (a counting sort); a parent that catches no
   point gets one child at its centre. Returns the number of children written to pts. */
static size_t sort_by_parent(const sk__level *plv, const uint32_t *parent_of, const float *local,
                             uint32_t count, uint32_t *slot, child_point *pts)
{
    for (uint32_t i = 0; i < count; i++)
        if (parent_of[i] != SK__SKIN_NONE) slot[parent_of[i]]++;
    size_t np = 0;
    for (uint32_t p = 0; p < plv->cell_count; p++) {
        uint32_t n = slot[p];
        slot[p] = (uint32_t)np; /* first slot of parent p */
        np += n ? n : 1;
        if (!n) {
            pts[slot[p]].parent = p;
            pts[slot[p]].order = UINT32_MAX;
            pts[slot[p]].x = plv->cells[p].cx, pts[slot[p]].y = plv->cells[p].cy;
        }
    }
    for (uint32_t i = 0; i < count; i++) {
        uint32_t p = parent_of[i];
        if (p == SK__SKIN_NONE) continue;
        child_point *cp = &pts[slot[p]++];
        cp->parent = p;
        cp->order = i;
        cp->x = local[2 * i], cp->y = local[2 * i + 1];
    }
    return np;
}

/* The level's children: the `count` lattice points xy placed in their parents and sorted
   by parent, with the parents' fallback centres, into a new array *pts_out (*np_out). */
static sk_result gather_children(sk_skin *skin, int level, const double *xy, uint32_t count,
                                 child_point **pts_out, size_t *np_out, sk_error *err)
{
    sk__level *plv = &skin->levels[level - 1];
    size_t total = (size_t)count + plv->cell_count;
    child_point *pts = malloc(sizeof(child_point) * total);
    uint32_t *slot = calloc(plv->cell_count, sizeof(uint32_t));
    if (!pts || !slot) {
        free(pts);
        free(slot);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d", level + 1);
    }
    uint32_t *parent_of = malloc(sizeof(uint32_t) * (count ? count : 1));
    float *local = malloc(sizeof(float) * 2 * (count ? count : 1));
    if (!parent_of || !local) {
        free(pts), free(slot), free(parent_of), free(local);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d", level + 1);
    }
    locate_points(skin, level, xy, count, parent_of, local);
    size_t np = sort_by_parent(plv, parent_of, local, count, slot, pts);
    free(slot), free(parent_of), free(local);
    if (np + plv->cell_count > SK_SKIN_MAX_CELLS) {
        free(pts);
        return sk_fail(err, SK_ERROR_LIMIT,
                       "level %d would have %zu cells; at most %d are "
                       "supported",
                       level + 1, np, SK_SKIN_MAX_CELLS);
    }
    *pts_out = pts;
    *np_out = np;
    return SK_OK;
}

/* The level's cells from the sorted children: parent links, sites (y space) and their
   images zs in z space, and each parent's run of children. */
static void cells_from_points(sk__level *lv, sk__level *plv, const child_point *pts,
                              uint32_t n_cells, double *zs)
{
    double(*mi)[2] = lv->minv;
    for (uint32_t i = 0; i < n_cells; i++) {
        sk__cell *c = &lv->cells[i];
        c->parent = pts[i].parent;
        c->sx = (float)pts[i].x, c->sy = (float)pts[i].y;
        zs[2 * i] = mi[0][0] * pts[i].x + mi[0][1] * pts[i].y;
        zs[2 * i + 1] = mi[1][0] * pts[i].x + mi[1][1] * pts[i].y;
        c->zx = (float)zs[2 * i], c->zy = (float)zs[2 * i + 1];
        sk__cell *pc = &plv->cells[c->parent];
        if (pc->child_count == 0) pc->first_child = i;
        pc->child_count++;
    }
}

/* Clip every child to its parent in parallel (each child is independent) into new
 *polys_out and *slab (freed here on failure). */
static sk_result clip_children(const sk__level *lv, const sk__level *plv, const double *zs,
                               int level, child_poly **polys_out, child_slab *slab, sk_error *err)
{
    uint32_t n_cells = lv->cell_count;
    uint32_t max_family = 0;
    for (uint32_t p = 0; p < plv->cell_count; p++)
        if (plv->cells[p].child_count > max_family) max_family = plv->cells[p].child_count;
    child_poly *polys = calloc(n_cells ? n_cells : 1, sizeof(child_poly));
    size_t slab_n = (size_t)(n_cells ? n_cells : 1) * SK__CHILD_SLOT;
    slab->x = malloc(sizeof(double) * slab_n), slab->y = malloc(sizeof(double) * slab_n);
    slab->tag = malloc(sizeof(int64_t) * slab_n);
    if (!polys || !slab->x || !slab->y || !slab->tag) {
        child_polys_free(polys, 0, slab);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d", level + 1);
    }
    int failed = 0;
#pragma omp parallel if (n_cells >= SK__PARALLEL_HEAVY_ITEMS)
    {
        dist_item *ord = malloc(sizeof(dist_item) * (max_family ? max_family : 1));
        sk__poly *pl = malloc(sizeof(sk__poly));
#pragma omp for schedule(dynamic, 16)
        for (long q = 0; q < (long)n_cells; q++) {
            uint32_t ci = (uint32_t)q, p = lv->cells[ci].parent;
            const sk__cell *pc = &plv->cells[p];
            if (!ord || !pl ||
                !clip_child(lv, plv, p, zs, pc->first_child, pc->child_count, ci - pc->first_child,
                            ord, pl) ||
                pl->n < 3 || !child_poly_keep(&polys[ci], slab, ci, pl)) {
#pragma omp atomic write
                failed = 1;
            }
        }
        free(ord);
        free(pl);
    }
    if (failed) {
        sk_result res =
            sk_fail(err, SK_ERROR_NUMERIC, "level %d: a cell could not be built", level + 1);
        child_polys_free(polys, n_cells, slab);
        return res;
    }
    *polys_out = polys;
    return SK_OK;
}

/* Room for every child's vertex uses (lv->uses, lv->vxy and *tags grown to the total),
   and each cell's run of them; *use_count is the total. */
static sk_result place_uses(sk__level *lv, const child_poly *polys, size_t use_cap, int64_t **tags,
                            size_t *use_count, int level, sk_error *err)
{
    uint32_t n_cells = lv->cell_count;
    size_t total_uses = 0;
    for (uint32_t ci = 0; ci < n_cells; ci++) total_uses += (size_t)polys[ci].n;
    if (total_uses > use_cap) {
        use_cap = total_uses;
        sk__use *nu = realloc(lv->uses, sizeof(sk__use) * use_cap);
        double *nv = realloc(lv->vxy, sizeof(double) * 2 * use_cap);
        int64_t *nt = realloc(*tags, sizeof(int64_t) * use_cap);
        if (nu) lv->uses = nu;
        if (nv) lv->vxy = nv;
        if (nt) *tags = nt;
        if (!nu || !nv || !nt)
            return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d", level + 1);
    }
    *use_count = 0;
    for (uint32_t ci = 0; ci < n_cells; ci++) {
        lv->cells[ci].first_use = (uint32_t)*use_count;
        lv->cells[ci].use_count = (uint32_t)polys[ci].n;
        *use_count += (size_t)polys[ci].n;
    }
    return SK_OK;
}

/* Lay the polygons out (in y space), each child on its own: the vertices, the centroid and
   each edge's line, the parent's own where the edge is a piece of the parent's boundary. */
static void lay_out_children(sk__level *lv, const sk__level *plv, const child_poly *polys,
                             const double *zs, int64_t *tags)
{
    uint32_t n_cells = lv->cell_count;
    double(*m)[2] = lv->m;
#pragma omp parallel if (n_cells >= SK__PARALLEL_ITEMS)
    {
        double px[SK__POLY_MAX], py[SK__POLY_MAX];
#pragma omp for schedule(static)
        for (long q = 0; q < (long)n_cells; q++) {
            uint32_t ci = (uint32_t)q;
            const child_poly *cp = &polys[ci];
            sk__cell *c = &lv->cells[ci];
            double zx = zs[2 * ci], zy = zs[2 * ci + 1];
            int n = cp->n;
            for (int k = 0; k < n; k++) {
                double lx = cp->x[k] + zx, ly = cp->y[k] + zy;
                px[k] = m[0][0] * lx + m[0][1] * ly;
                py[k] = m[1][0] * lx + m[1][1] * ly;
            }
            double cx, cy;
            sk__polygon_centroid(px, py, n, &cx, &cy);
            c->cx = (float)cx, c->cy = (float)cy;
            for (int k = 0; k < n; k++) {
                size_t ui = c->first_use + (size_t)k;
                sk__use *u = &lv->uses[ui];
                memset(u, 0, sizeof *u);
                int k1 = (k + 1) % n;
                int64_t tag = cp->tag[k];
                u->vx = (float)px[k], u->vy = (float)py[k];
                lv->vxy[2 * ui] = px[k];
                lv->vxy[2 * ui + 1] = py[k];
                u->edge = SK__SKIN_NONE;
                u->neighbour = SK__SKIN_NONE;
                if (tag < 0) {
                    /* a piece of the parent's boundary: the parent's own line */
                    const sk__use *pu = &plv->uses[(uint32_t)(-tag - 2)];
                    u->nx = pu->nx, u->ny = pu->ny, u->d = pu->d;
                } else {
                    double ex = px[k1] - px[k], ey = py[k1] - py[k];
                    double len = hypot(ex, ey);
                    u->nx = (float)(ey / len), u->ny = (float)(-ex / len);
                    u->d = (float)((ey * px[k] - ex * py[k]) / len);
                    u->neighbour = (uint32_t)tag;
                }
                tags[ui] = tag;
            }
        }
    }
}

/* The level's edges (sk__build_edges) from each use's key: the pair of cells it lies
   between, seen from the left one, with that cell's site; parent-boundary uses have none. */
static sk_result link_edges(sk_skin *skin, int level, const int64_t *tags, size_t use_count,
                            sk_error *err)
{
    sk__level *lv = &skin->levels[level];
    sk__edge_key *keys = malloc(sizeof(sk__edge_key) * (use_count ? use_count : 1));
    double *left_site = malloc(sizeof(double) * 2 * (use_count ? use_count : 1));
    if (!keys || !left_site) {
        free(keys);
        free(left_site);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d edges", level + 1);
    }
    for (uint32_t i = 0; i < lv->cell_count; i++) {
        const sk__cell *c = &lv->cells[i];
        for (uint32_t k = 0; k < c->use_count; k++) {
            uint32_t ui = c->first_use + k;
            if (tags[ui] < 0) {
                keys[ui].side = SK__SIDE_NONE;
                continue;
            }
            uint32_t j = (uint32_t)tags[ui];
            bool left = i < j;
            keys[ui].k0 = left ? ((uint64_t)i << 32 | j) : ((uint64_t)j << 32 | i);
            keys[ui].k1 = 0;
            keys[ui].side = left ? SK__SIDE_LEFT : SK__SIDE_RIGHT;
            left_site[2 * ui] = left ? c->sx : lv->cells[j].sx;
            left_site[2 * ui + 1] = left ? c->sy : lv->cells[j].sy;
        }
    }
    sk_result res = sk__build_edges(skin, level, keys, left_site, err);
    free(keys);
    free(left_site);
    return res;
}

sk_result sk__build_children(sk_skin *skin, int level, const double *xy, uint32_t count,
                             sk_error *err)
{
    sk__level *lv = &skin->levels[level];
    sk__level *plv = &skin->levels[level - 1];
    child_point *pts = NULL;
    size_t np = 0;
    sk_result res = gather_children(skin, level, xy, count, &pts, &np, err);
    if (res != SK_OK) return res;

    uint32_t n_cells = (uint32_t)np;
    lv->cells = calloc(n_cells ? n_cells : 1, sizeof(sk__cell));
    double *zs = malloc(sizeof(double) * 2 * (n_cells ? n_cells : 1));
    size_t use_cap = (size_t)n_cells * 8 + 16, use_count = 0;
    lv->uses = malloc(sizeof(sk__use) * use_cap);
    lv->vxy = malloc(sizeof(double) * 2 * use_cap);
    int64_t *tags = malloc(sizeof(int64_t) * use_cap);
    if (!lv->cells || !zs || !lv->uses || !lv->vxy || !tags) {
        res = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level %d", level + 1);
        goto done;
    }
    lv->cell_count = n_cells;
    cells_from_points(lv, plv, pts, n_cells, zs);
    /* Clip every child to its parent in parallel (each child is independent), then lay
       the polygons out in order. */
    child_poly *polys = NULL;
    child_slab slab;
    res = clip_children(lv, plv, zs, level, &polys, &slab, err);
    if (res != SK_OK) goto done;
    res = place_uses(lv, polys, use_cap, &tags, &use_count, level, err);
    if (res == SK_OK) lay_out_children(lv, plv, polys, zs, tags);
    child_polys_free(polys, n_cells, &slab);
    if (res != SK_OK) goto done;
    lv->use_count = (uint32_t)use_count;
    res = link_edges(skin, level, tags, use_count, err);

done:
    free(pts);
    free(zs);
    free(tags);
    return res;
}
