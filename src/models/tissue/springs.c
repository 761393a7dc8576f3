/* The springs (Shigemori & Kawai sec. 4, Fig. 2): skin points joined along the skin
 * triangles' edges, skin points to fat points, fat points to each other and to muscle and
 * bone points. Between points that are grid neighbours: fat to fat and fat to tissue in
 * the character's neighbourhood (18 or 26), skin to fat in the 26-neighbourhood (a vertex
 * at a convex corner of the cuberille skin reaches the fat only diagonally), and where the
 * skin lies on the tissue with no fat point around it, skin to the tissue points beside it
 * (the paper does not say what joins the skin where the fat is thinner than the grid).
 * Every spring gets a colour, its direction on the lattice and the parity of its first
 * end along that direction, so the springs of one colour share no point. */
#include <stdlib.h>
#include <string.h>

#include "models/tissue/tissue_internal.h"

int sk__lattice_directions(int neighbourhood, int dirs[13][3])
{
    int n = 0;
    for (int z = -1; z <= 1; z++)
        for (int y = -1; y <= 1; y++)
            for (int x = -1; x <= 1; x++) {
                int first = x != 0 ? x : (y != 0 ? y : z);
                int len2 = x * x + y * y + z * z;
                if (first <= 0 || len2 > (neighbourhood >= 26 ? 3 : 2)) continue;
                dirs[n][0] = x;
                dirs[n][1] = y;
                dirs[n][2] = z;
                n++;
            }
    return n;
}

int sk__lattice_direction_index(int dirs[13][3], int count, const int d[3])
{
    for (int k = 0; k < count; k++) {
        if (dirs[k][0] == d[0] && dirs[k][1] == d[1] && dirs[k][2] == d[2]) return k;
        if (dirs[k][0] == -d[0] && dirs[k][1] == -d[1] && dirs[k][2] == -d[2]) return k;
    }
    return -1;
}

static bool is_free(const sk_tissue_model *m, size_t p) { return p < m->skin_count + m->fat_count; }
static bool is_skin(const sk_tissue_model *m, size_t p) { return p < m->skin_count; }

/* Class of the spring between points p and q, grid neighbours along a direction that is
 * (`near`) or is not in the character's neighbourhood; -1 for none. `on_tissue[p]` marks
 * skin points with no fat point among their 26 neighbours. */
static int spring_class(const sk_tissue_model *m, const uint8_t *on_tissue, size_t p, size_t q,
                        bool near)
{
    bool fp = is_free(m, p), fq = is_free(m, q), sp = is_skin(m, p), sq = is_skin(m, q);
    if (!fp && !fq) return -1; /* both driven */
    if (sp && sq) return -1;   /* skin springs follow the triangles */
    if (sp || sq) {
        if (fp && fq) return SK__SPRING_SKIN_FAT;
        return on_tissue[sp ? p : q] ? SK__SPRING_ANCHOR : -1;
    }
    if (!near) return -1;
    return (fp && fq) ? SK__SPRING_FAT : SK__SPRING_ANCHOR;
}

static int colour_of(const sk__grid *g, int dirs[13][3], int nd, size_t *gi, size_t *gj)
{
    int a[3], b[3], d[3];
    sk__grid_coords(g, *gi, a);
    sk__grid_coords(g, *gj, b);
    for (int k = 0; k < 3; k++) d[k] = b[k] - a[k];
    int first = d[0] != 0 ? 0 : (d[1] != 0 ? 1 : 2);
    if (d[first] < 0) { /* canonical direction: the first end is the lower one */
        size_t t = *gi;
        *gi = *gj;
        *gj = t;
        for (int k = 0; k < 3; k++) a[k] = b[k];
    }
    int k = sk__lattice_direction_index(dirs, nd, d);
    return k < 0 ? -1 : 2 * k + (a[first] & 1);
}

static int compare_edge(const void *x, const void *y)
{
    const uint32_t *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* The lattice directions of the springs (the 26-neighbourhood's half) and which of them are
 * in the character's neighbourhood. */
typedef struct spring_lattice {
    int dirs[13][3];
    int nd;
    bool near[13];
} spring_lattice;

/* The unsorted springs: their ends, classes and colours. */
typedef struct spring_lists {
    uint32_t *si, *sj;
    uint8_t *sc, *col;
} spring_lists;

/* Marks the skin points with no fat point among their 26 neighbours. */
static void find_on_tissue(const sk_tissue_model *m, const spring_lattice *lat, uint8_t *on_tissue)
{
    const sk__grid *g = &m->grid;
    int nd = lat->nd;
    const int(*dirs)[3] = lat->dirs;
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < m->skin_count; p++) {
        int c[3];
        sk__grid_coords(g, m->grid_of[p], c);
        bool fat = false;
        for (int k = 0; k < nd && !fat; k++)
            for (int sgn = -1; sgn <= 1 && !fat; sgn += 2) {
                int x = c[0] + sgn * dirs[k][0], y = c[1] + sgn * dirs[k][1],
                    z = c[2] + sgn * dirs[k][2];
                if (x < 0 || y < 0 || z < 0 || x >= g->n[0] || y >= g->n[1] || z >= g->n[2])
                    continue;
                int32_t q = m->grid_point[sk__grid_index(g, x, y, z)];
                fat = q >= 0 && (size_t)q >= m->skin_count &&
                      (size_t)q < m->skin_count + m->fat_count;
            }
        on_tissue[p] = !fat;
    }
}

/* The class of the lattice spring from point p (at grid coordinates c) towards direction
 * k, -1 for none (off the grid, no point there or no spring); *q is the point there. */
static inline int lattice_spring(const sk_tissue_model *m, const spring_lattice *lat,
                                 const uint8_t *on_tissue, size_t p, const int c[3], int k,
                                 int32_t *q)
{
    const sk__grid *g = &m->grid;
    const int *d = lat->dirs[k];
    int x = c[0] + d[0], y = c[1] + d[1], z = c[2] + d[2];
    if (x >= g->n[0] || y >= g->n[1] || y < 0 || z >= g->n[2] || z < 0) return -1;
    *q = m->grid_point[sk__grid_index(g, x, y, z)];
    return *q >= 0 ? spring_class(m, on_tissue, p, (size_t)*q, lat->near[k]) : -1;
}

/* Each point's first lattice spring in start[] (springs towards the half-directions, point
 * by point); returns how many there are. */
static size_t count_lattice_springs(const sk_tissue_model *m, const spring_lattice *lat,
                                    const uint8_t *on_tissue, size_t *start)
{
    size_t np = m->point_count;
    start[0] = 0;
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < np; p++) {
        int c[3];
        sk__grid_coords(&m->grid, m->grid_of[p], c);
        size_t n = 0;
        for (int k = 0; k < lat->nd; k++) {
            int32_t q;
            if (lattice_spring(m, lat, on_tissue, p, c, k, &q) >= 0) n++;
        }
        start[p + 1] = n;
    }
    for (size_t p = 0; p < np; p++) start[p + 1] += start[p];
    return start[np];
}

/* The skin triangles' edges (lower point first), sorted, each once; returns how many. */
static size_t unique_skin_edges(const sk_tissue_model *m, uint32_t *edges)
{
    size_t ne = 0;
    for (size_t t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->triangles[3 * t + (size_t)k],
                     b = m->triangles[3 * t + (size_t)(k + 1) % 3];
            edges[2 * ne] = a < b ? a : b;
            edges[2 * ne + 1] = a < b ? b : a;
            ne++;
        }
    qsort(edges, ne, 2 * sizeof *edges, compare_edge);
    size_t unique = 0;
    for (size_t e = 0; e < ne; e++)
        if (unique == 0 || compare_edge(edges + 2 * e, edges + 2 * (unique - 1)) != 0) {
            edges[2 * unique] = edges[2 * e];
            edges[2 * unique + 1] = edges[2 * e + 1];
            unique++;
        }
    return unique;
}

/* The lattice springs, each point's from start[p], with their classes and colours (the
 * direction and the parity of the first end along it). */
static void fill_lattice_springs(const sk_tissue_model *m, const spring_lattice *lat,
                                 const uint8_t *on_tissue, const size_t *start,
                                 const spring_lists *s)
{
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < m->point_count; p++) {
        int c[3];
        sk__grid_coords(&m->grid, m->grid_of[p], c);
        size_t n = start[p];
        for (int k = 0; k < lat->nd; k++) {
            int32_t q;
            int cls = lattice_spring(m, lat, on_tissue, p, c, k, &q);
            if (cls < 0) continue;
            const int *d = lat->dirs[k];
            s->si[n] = (uint32_t)p;
            s->sj[n] = (uint32_t)q;
            s->sc[n] = (uint8_t)cls;
            s->col[n] = (uint8_t)(2 * k + (c[d[0] ? 0 : (d[1] ? 1 : 2)] & 1));
            n++;
        }
    }
}

/* The skin springs along the unique edges, after the `lattice` lattice springs; fails when
 * an edge's ends are not grid neighbours. */
static sk_result fill_skin_springs(const sk_tissue_model *m, int dirs[13][3], int nd,
                                   const uint32_t *edges, size_t unique, size_t lattice,
                                   const spring_lists *s, sk_error *err)
{
    const sk__grid *g = &m->grid;
    for (size_t e = 0; e < unique; e++) {
        size_t n = lattice + e, gi = m->grid_of[edges[2 * e]], gj = m->grid_of[edges[2 * e + 1]];
        int c = colour_of(g, dirs, nd, &gi, &gj);
        if (c < 0)
            return sk_fail(err, SK_ERROR_NUMERIC,
                           "a skin edge joins points that are not grid neighbours");
        s->si[n] = (uint32_t)m->grid_point[gi];
        s->sj[n] = (uint32_t)m->grid_point[gj];
        s->sc[n] = SK__SPRING_SKIN;
        s->col[n] = (uint8_t)c;
    }
    return SK_OK;
}

/* The springs in the model, sorted by colour (stable counting sort), with their rest
 * lengths and the count of each class; the model takes oi, oj, oc and orest. */
static void store_springs(sk_tissue_model *m, int nd, size_t total, const spring_lists *s,
                          uint32_t *oi, uint32_t *oj, uint8_t *oc, double *orest)
{
    /* stable counting sort by colour */
    m->colour_count = 2 * nd;
    size_t count[27] = {0};
    for (size_t k = 0; k < total; k++) count[s->col[k]]++;
    m->colour_start[0] = 0;
    for (int c = 0; c < m->colour_count; c++)
        m->colour_start[c + 1] = m->colour_start[c] + count[c];
    size_t fill[27];
    memcpy(fill, m->colour_start, sizeof fill);
    for (size_t k = 0; k < total; k++) {
        size_t o = fill[s->col[k]]++;
        oi[o] = s->si[k];
        oj[o] = s->sj[k];
        oc[o] = s->sc[k];
    }
    memset(m->class_count, 0, sizeof m->class_count);
    for (size_t k = 0; k < total; k++) {
        orest[k] = sk_v3d_length(sk_v3d_sub(m->rest[oi[k]], m->rest[oj[k]]));
        m->class_count[oc[k]]++;
    }
    m->spring_count = total;
    m->spring_i = oi;
    m->spring_j = oj;
    m->spring_class = oc;
    m->spring_rest = orest;
}

sk_result sk__model_springs(sk_tissue_model *m, sk_error *err)
{
    spring_lattice lat;
    int own[13][3];
    lat.nd = sk__lattice_directions(26, lat.dirs);
    int no = sk__lattice_directions(m->neighbourhood, own);
    for (int k = 0; k < lat.nd; k++)
        lat.near[k] = sk__lattice_direction_index(own, no, lat.dirs[k]) >= 0;
    size_t np = m->point_count;
    size_t *start = malloc((np + 1) * sizeof *start);
    uint32_t *edges = malloc((m->triangle_count ? m->triangle_count : 1) * 6 * sizeof *edges);
    uint8_t *on_tissue = calloc(np ? np : 1, 1);
    if (!start || !edges || !on_tissue) {
        free(start);
        free(edges);
        free(on_tissue);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the springs");
    }
    /* skin points with no fat point among their 26 neighbours */
    find_on_tissue(m, &lat, on_tissue);
    /* lattice springs from each point towards the half-directions */
    size_t lattice = count_lattice_springs(m, &lat, on_tissue, start);
    /* skin springs along the triangles' edges, each once */
    size_t unique = unique_skin_edges(m, edges);
    size_t total = lattice + unique;
    spring_lists s = {malloc(total * sizeof *s.si), malloc(total * sizeof *s.sj), malloc(total),
                      malloc(total)};
    uint32_t *oi = malloc(total * sizeof *oi), *oj = malloc(total * sizeof *oj);
    uint8_t *oc = malloc(total);
    double *orest = malloc(total * sizeof *orest);
    sk_result r = SK_OK;
    if (!s.si || !s.sj || !s.sc || !s.col || !oi || !oj || !oc || !orest)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu springs", total);
    if (r == SK_OK) {
        fill_lattice_springs(m, &lat, on_tissue, start, &s);
        r = fill_skin_springs(m, lat.dirs, lat.nd, edges, unique, lattice, &s, err);
    }
    if (r == SK_OK) {
        store_springs(m, lat.nd, total, &s, oi, oj, oc, orest);
        oi = oj = NULL;
        oc = NULL;
        orest = NULL;
    }
    free(start);
    free(edges);
    free(on_tissue);
    free(s.si);
    free(s.sj);
    free(s.sc);
    free(s.col);
    free(oi);
    free(oj);
    free(oc);
    free(orest);
    return r;
}
