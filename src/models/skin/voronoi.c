/* Level 1: Voronoi division of the tile by its centre points (paper sec. 2 and 3.2.1 (1)),
 * periodic: the tile is a torus, each cell is clipped by the bisectors of the nearby
 * images of every point, found ring by ring on a bucket grid until the security radius
 * (twice the cell's farthest vertex) is covered. Done in pre-stretch space. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

#define SK__BOX_TAG (-1)
#define SK__IMG_BIAS 2048
#define SK__IMG_MAX 2000

static int64_t level1_tag(uint32_t j, int m, int n)
{
    return ((int64_t)j << 24) | ((int64_t)(m + SK__IMG_BIAS) << 12) | (int64_t)(n + SK__IMG_BIAS);
}
static void level1_untag(int64_t tag, uint32_t *j, int *m, int *n)
{
    *j = (uint32_t)(tag >> 24);
    *m = (int)((tag >> 12) & 4095) - SK__IMG_BIAS;
    *n = (int)(tag & 4095) - SK__IMG_BIAS;
}

typedef struct bucket_grid {
    int gx, gy;
    uint32_t *start, *items;
} bucket_grid;

static sk_result bucket_build(bucket_grid *g, const double *f, uint32_t count, int gx, int gy,
                              sk_error *err)
{
    g->gx = gx, g->gy = gy;
    size_t nb = (size_t)gx * (size_t)gy;
    g->start = calloc(nb + 1, sizeof(uint32_t));
    g->items = malloc(sizeof(uint32_t) * (count ? count : 1));
    if (!g->start || !g->items) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    uint32_t *slot = malloc(sizeof(uint32_t) * (count ? count : 1));
    if (!slot) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    for (uint32_t i = 0; i < count; i++) {
        int bx = (int)(f[2 * i] * gx), by = (int)(f[2 * i + 1] * gy);
        if (bx >= gx) bx = gx - 1;
        if (by >= gy) by = gy - 1;
        slot[i] = (uint32_t)by * (uint32_t)gx + (uint32_t)bx;
        g->start[slot[i] + 1]++;
    }
    for (size_t b = 0; b < nb; b++) g->start[b + 1] += g->start[b];
    uint32_t *fill = malloc(sizeof(uint32_t) * (nb + 1));
    if (!fill) {
        free(slot);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    memcpy(fill, g->start, sizeof(uint32_t) * (nb + 1));
    for (uint32_t i = 0; i < count; i++) g->items[fill[slot[i]]++] = i;
    free(fill);
    free(slot);
    return SK_OK;
}

static int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

/* One cell: clips a box around site i by the bisectors of nearby images. */
static bool voronoi_cell(const double *z, uint32_t i, const double p[2][2], const bucket_grid *g,
                         const double *f, double w_min, double box, sk__poly *poly)
{
    double zi_x = z[2 * i], zi_y = z[2 * i + 1];
    poly->n = 4;
    double bx[4] = {-box, box, box, -box}, by[4] = {-box, -box, box, box};
    for (int k = 0; k < 4; k++) poly->x[k] = bx[k], poly->y[k] = by[k], poly->tag[k] = SK__BOX_TAG;
    int bi = (int)(f[2 * i] * g->gx), bj = (int)(f[2 * i + 1] * g->gy);
    if (bi >= g->gx) bi = g->gx - 1;
    if (bj >= g->gy) bj = g->gy - 1;
    int max_ring = 2 * (g->gx + g->gy) + 8;
    for (int r = 0; r <= max_ring; r++) {
        for (int dj = -r; dj <= r; dj++)
            for (int di = -r; di <= r; di++) {
                if (abs(di) != r && abs(dj) != r) continue;
                int cx = bi + di, cy = bj + dj;
                int m = floor_div(cx, g->gx), n = floor_div(cy, g->gy);
                if (abs(m) > SK__IMG_MAX || abs(n) > SK__IMG_MAX) return false;
                int wx = cx - m * g->gx, wy = cy - n * g->gy;
                uint32_t b = (uint32_t)wy * (uint32_t)g->gx + (uint32_t)wx;
                for (uint32_t q = g->start[b]; q < g->start[b + 1]; q++) {
                    uint32_t j = g->items[q];
                    if (j == i && m == 0 && n == 0) continue;
                    /* image of j relative to site i */
                    double vx = z[2 * j] + m * p[0][0] + n * p[0][1] - zi_x;
                    double vy = z[2 * j + 1] + m * p[1][0] + n * p[1][1] - zi_y;
                    double vv = vx * vx + vy * vy;
                    if (vv <= 0.0) continue; /* coincident points: no bisector */
                    if (!sk__poly_clip(poly, vx, vy, 0.5 * vv, level1_tag(j, m, n))) return false;
                }
            }
        double rmax2 = 0;
        for (int k = 0; k < poly->n; k++) {
            double d2 = poly->x[k] * poly->x[k] + poly->y[k] * poly->y[k];
            if (d2 > rmax2) rmax2 = d2;
        }
        if (r * w_min >= 2.0 * sqrt(rmax2)) return true;
    }
    return false;
}

/* Level 1's layout: the tile, its periods in pre-stretch space and the bucket grid. */
typedef struct level1_layout {
    double w, h;    /* the tile's periods (y space) */
    double p[2][2]; /* the periods in pre-stretch space (columns) */
    int gx, gy;     /* buckets along each period */
    double w_min;   /* the narrowest bucket width */
    double box;     /* half size of the box every cell is clipped from */
} level1_layout;

/* The layout for `count` sites: about 1.4 times the mean site spacing per bucket. */
static void level1_layout_init(const sk_skin *skin, uint32_t count, level1_layout *lay)
{
    const sk__level *L = &skin->levels[0];
    double w = skin->period[0], h = skin->period[1];
    double p[2][2] = {{L->minv[0][0] * w, L->minv[0][1] * h},
                      {L->minv[1][0] * w, L->minv[1][1] * h}};
    double area = fabs(p[0][0] * p[1][1] - p[0][1] * p[1][0]);
    double len1 = hypot(p[0][0], p[1][0]), len2 = hypot(p[0][1], p[1][1]);
    double target = sqrt(area / count) * 1.4;
    lay->gx = (int)fmax(1.0, fmin(4096.0, floor(len1 / target)));
    lay->gy = (int)fmax(1.0, fmin(4096.0, floor(len2 / target)));
    lay->w_min = fmin(area / (lay->gy * len1), area / (lay->gx * len2));
    lay->box = len1 + len2;
    lay->w = w, lay->h = h;
    memcpy(lay->p, p, sizeof p);
}

/* Every site in pre-stretch space (z) and as fractions of the tile (f). */
static void level1_sites(const sk__level *L, const double *xy, uint32_t count, double w, double h,
                         double *z, double *f)
{
    for (uint32_t i = 0; i < count; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        z[2 * i] = L->minv[0][0] * x + L->minv[0][1] * y;
        z[2 * i + 1] = L->minv[1][0] * x + L->minv[1][1] * y;
        f[2 * i] = x / w;
        f[2 * i + 1] = y / h;
    }
}

/* The level's uses as they are made, with each one's tag and start vertex. */
typedef struct level1_uses {
    size_t cap, count;
    sk__use *uses;
    int64_t *tags;
    double *vxy;
} level1_uses;

/* Room for `more` uses (twice what is needed when growing); false when out of memory. */
static inline bool uses_reserve(level1_uses *u, size_t more)
{
    if (u->count + more <= u->cap) return true;
    u->cap = (u->count + more) * 2;
    sk__use *nu = realloc(u->uses, sizeof(sk__use) * u->cap);
    int64_t *nt = realloc(u->tags, sizeof(int64_t) * u->cap);
    double *nv = realloc(u->vxy, sizeof(double) * 2 * u->cap);
    if (nu) u->uses = nu;
    if (nt) u->tags = nt;
    if (nv) u->vxy = nv;
    return nu && nt && nv;
}

/* Whether no vertex of the cell is left from the box it was clipped from. */
static inline bool cell_bounded(const sk__poly *poly)
{
    for (int k = 0; k < poly->n; k++)
        if (poly->tag[k] == SK__BOX_TAG) return false;
    return true;
}

/* Cell i's site (its frame's origin), pre-stretch site, parent and range of uses. */
static inline void cell_init(sk_skin *skin, uint32_t i, const double *xy, const double *z,
                             size_t first_use, int use_count)
{
    sk__cell *c = &skin->levels[0].cells[i];
    skin->origin[2 * i] = xy[2 * i];
    skin->origin[2 * i + 1] = xy[2 * i + 1];
    c->zx = (float)z[2 * i], c->zy = (float)z[2 * i + 1];
    c->sx = 0, c->sy = 0;
    c->parent = SK__SKIN_NONE;
    c->first_use = (uint32_t)first_use;
    c->use_count = (uint32_t)use_count;
}

/* The cell's polygon from pre-stretch space to y space (the level's m). */
static inline void poly_to_y_space(const sk__level *L, sk__poly *poly)
{
    for (int k = 0; k < poly->n; k++) {
        double lx = poly->x[k], ly = poly->y[k];
        poly->x[k] = L->m[0][0] * lx + L->m[0][1] * ly;
        poly->y[k] = L->m[1][0] * lx + L->m[1][1] * ly;
    }
}

/* One use per edge of the cell's polygon: its start vertex, outward normal and offset, and
 * the cell across it (from the edge's tag). */
static inline void append_uses(level1_uses *u, const sk__poly *poly)
{
    for (int k = 0; k < poly->n; k++) {
        sk__use *use = &u->uses[u->count];
        memset(use, 0, sizeof *use);
        int k1 = (k + 1) % poly->n;
        use->vx = (float)poly->x[k], use->vy = (float)poly->y[k];
        u->vxy[2 * u->count] = poly->x[k], u->vxy[2 * u->count + 1] = poly->y[k];
        double ex = poly->x[k1] - poly->x[k], ey = poly->y[k1] - poly->y[k];
        double len = hypot(ex, ey);
        use->nx = (float)(ey / len), use->ny = (float)(-ex / len);
        use->d = (float)((ey * poly->x[k] - ex * poly->y[k]) / len);
        uint32_t j;
        int m, n;
        level1_untag(poly->tag[k], &j, &m, &n);
        use->neighbour = j;
        use->edge = SK__SKIN_NONE;
        u->tags[u->count] = poly->tag[k];
        u->count++;
    }
}

/* Every cell of level 1: its Voronoi polygon (bounded), its record and its uses. */
static sk_result level1_cells(sk_skin *skin, const double *xy, uint32_t count, const double *z,
                              const double *f, const bucket_grid *g, const level1_layout *lay,
                              sk__poly *poly, level1_uses *u, sk_error *err)
{
    sk__level *L = &skin->levels[0];
    for (uint32_t i = 0; i < count; i++) {
        if (!voronoi_cell(z, i, lay->p, g, f, lay->w_min, lay->box, poly) || poly->n < 3)
            return sk_fail(err, SK_ERROR_NUMERIC,
                           "level 1: the Voronoi cell of centre point %u could not be built", i);
        if (!cell_bounded(poly))
            return sk_fail(err, SK_ERROR_NUMERIC, "level 1: cell %u is unbounded", i);
        if (!uses_reserve(u, (size_t)poly->n))
            return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level-1 cells");
        cell_init(skin, i, xy, z, u->count, poly->n);
        /* to y space, relative to the site (the cell's frame origin) */
        poly_to_y_space(L, poly);
        sk__cell *c = &L->cells[i];
        double cx, cy;
        sk__polygon_centroid(poly->x, poly->y, poly->n, &cx, &cy);
        c->cx = (float)cx, c->cy = (float)cy;
        append_uses(u, poly);
    }
    return SK_OK;
}

/* The edge key of use ui of cell i (tagged with cell j's image (m, n)) and the use's shift
 * to the frame of the edge's left cell. */
static inline void level1_edge_key(sk_skin *skin, uint32_t i, uint32_t ui, int64_t tag, double w,
                                   double h, sk__edge_key *key, double *left_site)
{
    uint32_t j;
    int m, n;
    level1_untag(tag, &j, &m, &n);
    bool left = i < j || (i == j && (m > 0 || (m == 0 && n > 0)));
    key->side = left ? SK__SIDE_LEFT : SK__SIDE_RIGHT;
    uint32_t lo = left ? i : j, hi = left ? j : i;
    int cm = left ? m : -m, cn = left ? n : -n;
    key->k0 = ((uint64_t)lo << 32) | hi;
    key->k1 = ((uint64_t)(cm + SK__IMG_BIAS) << 16) | (uint64_t)(cn + SK__IMG_BIAS);
    /* Shift from this cell's frame to the left cell's frame: the left frame's
       origin is the left site; a right cell sees the left site's image at
       -(m, n) periods, so y_left = y_right + site_right - site_left + (m, n). */
    sk__use *u = &skin->levels[0].uses[ui];
    if (left) {
        u->shx = 0, u->shy = 0;
    } else {
        double sx = skin->origin[2 * i] - skin->origin[2 * j] - m * w;
        double sy = skin->origin[2 * i + 1] - skin->origin[2 * j + 1] - n * h;
        u->shx = (float)sx, u->shy = (float)sy;
    }
    left_site[2 * ui] = 0, left_site[2 * ui + 1] = 0;
}

/* Level 1's edge records from the keys of every use. */
static sk_result level1_edges(sk_skin *skin, uint32_t count, const int64_t *tags, size_t use_count,
                              double w, double h, sk_error *err)
{
    const sk__level *L = &skin->levels[0];
    /* Edge keys: (lower cell, higher cell, image) from both sides. */
    sk__edge_key *keys = malloc(sizeof(sk__edge_key) * (use_count ? use_count : 1));
    double *left_site = malloc(sizeof(double) * 2 * (use_count ? use_count : 1));
    if (!keys || !left_site) {
        free(keys);
        free(left_site);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level-1 edges");
    }
    for (uint32_t i = 0; i < count; i++) {
        const sk__cell *c = &L->cells[i];
        for (uint32_t k = 0; k < c->use_count; k++) {
            uint32_t ui = c->first_use + k;
            level1_edge_key(skin, i, ui, tags[ui], w, h, &keys[ui], left_site);
        }
    }
    sk_result res = sk__build_edges(skin, 0, keys, left_site, err);
    free(keys);
    free(left_site);
    return res;
}

sk_result sk__build_level1(sk_skin *skin, const double *xy, uint32_t count, sk_error *err)
{
    sk__level *L = &skin->levels[0];
    level1_layout lay;
    level1_layout_init(skin, count, &lay);

    sk_result res = SK_OK;
    double *z = malloc(sizeof(double) * 2 * count);
    double *f = malloc(sizeof(double) * 2 * count);
    bucket_grid g = {0};
    sk__poly *poly = malloc(sizeof(sk__poly));
    level1_uses u = {.cap = (size_t)count * 8 + 16};
    u.uses = malloc(sizeof(sk__use) * u.cap);
    u.tags = malloc(sizeof(int64_t) * u.cap);
    u.vxy = malloc(sizeof(double) * 2 * u.cap);
    L->cells = calloc(count, sizeof(sk__cell));
    skin->origin = malloc(sizeof(double) * 2 * count);
    if (!z || !f || !poly || !u.uses || !u.tags || !u.vxy || !L->cells || !skin->origin) {
        res = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for level-1 cells");
        goto done;
    }
    level1_sites(L, xy, count, lay.w, lay.h, z, f);
    res = bucket_build(&g, f, count, lay.gx, lay.gy, err);
    if (res != SK_OK) goto done;
    res = level1_cells(skin, xy, count, z, f, &g, &lay, poly, &u, err);
    if (res != SK_OK) goto done;
    L->cell_count = count;
    L->uses = u.uses;
    L->use_count = (uint32_t)u.count;
    L->vxy = u.vxy;
    u.uses = NULL;
    u.vxy = NULL;
    res = level1_edges(skin, count, u.tags, u.count, lay.w, lay.h, err);

done:
    free(z);
    free(f);
    free(g.start);
    free(g.items);
    free(poly);
    free(u.uses);
    free(u.tags);
    free(u.vxy);
    return res;
}
