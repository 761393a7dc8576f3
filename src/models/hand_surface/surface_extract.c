/* Meshing of the implicit hand surface: the field sampled on a narrow band of a grid
 * (blocks whose centre value proves they hold no surface are skipped, the others
 * evaluated with only the primitives near them), and marching tetrahedra on the Kuhn
 * split of every cube (6 tetrahedra around the main diagonal, consistent across faces).
 * The piecewise-linear level set it gives is closed, manifold and free of
 * self-intersections by construction. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

#define BLOCK 8
#define BP (BLOCK + 1)

void sk__hand_trimesh_free(sk__hand_trimesh *m)
{
    free(m->pos);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

static bool grow(void **data, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) return true;
    size_t n = *cap ? *cap : 1024;
    while (n < need) n *= 2;
    void *p = realloc(*data, n * elem);
    if (!p) return false;
    *data = p;
    *cap = n;
    return true;
}

/* Open-addressing map from a grid edge to its vertex. */
typedef struct edge_map {
    uint64_t *keys; /* key + 1, 0 = empty */
    uint32_t *values;
    size_t cap, used;
} edge_map;

static uint64_t hash64(uint64_t k) { return sk_mix64(k * 0x9e3779b97f4a7c15ULL); }

static bool map_init(edge_map *m, size_t cap)
{
    m->cap = cap;
    m->used = 0;
    m->keys = calloc(cap, sizeof *m->keys);
    m->values = malloc(cap * sizeof *m->values);
    return m->keys && m->values;
}

static void map_free(edge_map *m)
{
    free(m->keys);
    free(m->values);
}

static bool map_rehash(edge_map *m)
{
    edge_map n;
    if (!map_init(&n, m->cap * 2)) {
        map_free(&n);
        return false;
    }
    for (size_t i = 0; i < m->cap; i++) {
        if (!m->keys[i]) continue;
        size_t j = hash64(m->keys[i]) & (n.cap - 1);
        while (n.keys[j]) j = (j + 1) & (n.cap - 1);
        n.keys[j] = m->keys[i];
        n.values[j] = m->values[i];
    }
    n.used = m->used;
    map_free(m);
    *m = n;
    return true;
}

typedef struct extract_ctx {
    const sk__hand_field *field;
    double cell;
    sk_vec3d lo;
    long nx, ny, nz; /* grid points per axis */
    edge_map map;
    sk__hand_trimesh *out;
    bool oom;
} extract_ctx;

/* The vertex on the edge from grid point a (value va) to b (value vb). */
static uint32_t edge_vertex(extract_ctx *c, long ia[3], int code, double va, double vb)
{
    uint64_t key = ((((uint64_t)ia[2] * (uint64_t)c->ny + (uint64_t)ia[1]) * (uint64_t)c->nx +
                     (uint64_t)ia[0]) *
                        7 +
                    (uint64_t)code) +
                   1;
    edge_map *m = &c->map;
    if ((m->used + 1) * 2 > m->cap && !map_rehash(m)) {
        c->oom = true;
        return 0;
    }
    size_t j = hash64(key) & (m->cap - 1);
    while (m->keys[j]) {
        if (m->keys[j] == key) return m->values[j];
        j = (j + 1) & (m->cap - 1);
    }
    sk__hand_trimesh *o = c->out;
    if (!grow((void **)&o->pos, &o->vertex_cap, o->vertex_count + 1, 3 * sizeof *o->pos)) {
        c->oom = true;
        return 0;
    }
    int d = code + 1;
    double t = va / (va - vb);
    t = t < 1e-3 ? 1e-3 : (t > 1.0 - 1e-3 ? 1.0 - 1e-3 : t);
    double *p = o->pos + 3 * o->vertex_count;
    p[0] = c->lo.x + c->cell * ((double)ia[0] + t * (d & 1));
    p[1] = c->lo.y + c->cell * ((double)ia[1] + t * ((d >> 1) & 1));
    p[2] = c->lo.z + c->cell * ((double)ia[2] + t * ((d >> 2) & 1));
    m->keys[j] = key;
    m->values[j] = (uint32_t)o->vertex_count;
    m->used++;
    return (uint32_t)o->vertex_count++;
}

static void emit(extract_ctx *c, uint32_t a, uint32_t b, uint32_t d, sk_vec3d inside,
                 sk_vec3d outside)
{
    sk__hand_trimesh *o = c->out;
    const double *pa = o->pos + 3 * a, *pb = o->pos + 3 * b, *pd = o->pos + 3 * d;
    sk_vec3d e1 = sk_v3d(pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
    sk_vec3d e2 = sk_v3d(pd[0] - pa[0], pd[1] - pa[1], pd[2] - pa[2]);
    sk_vec3d n = sk_v3d_cross(e1, e2);
    if (sk_v3d_dot(n, sk_v3d_sub(outside, inside)) < 0.0) {
        uint32_t t = b;
        b = d;
        d = t;
    }
    if (!grow((void **)&o->tri, &o->tri_cap, o->tri_count + 1, 3 * sizeof *o->tri)) {
        c->oom = true;
        return;
    }
    uint32_t *t = o->tri + 3 * o->tri_count++;
    t[0] = a, t[1] = b, t[2] = d;
}

/* Marching tetrahedra in one cube with corner values v (bit 0 = +x, 1 = +y, 2 = +z). */
static void cube(extract_ctx *c, long i, long j, long k, const double v[8])
{
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (int t = 0; t < 6; t++) {
        int corner[4];
        corner[0] = 0;
        corner[1] = 1 << perm[t][0];
        corner[2] = corner[1] | (1 << perm[t][1]);
        corner[3] = 7;
        int in[4], out[4], ni = 0, no = 0;
        for (int q = 0; q < 4; q++) {
            if (v[corner[q]] < 0.0)
                in[ni++] = corner[q];
            else
                out[no++] = corner[q];
        }
        if (ni == 0 || no == 0) continue;
        uint32_t e[4];
        int ea[4], eb[4], ne = 0;
        if (ni == 1 || no == 1) {
            int apex = ni == 1 ? in[0] : out[0];
            int *others = ni == 1 ? out : in;
            for (int q = 0; q < 3; q++) ea[ne] = apex, eb[ne++] = others[q];
        } else {
            ea[0] = in[0], eb[0] = out[0];
            ea[1] = in[0], eb[1] = out[1];
            ea[2] = in[1], eb[2] = out[1];
            ea[3] = in[1], eb[3] = out[0];
            ne = 4;
        }
        for (int q = 0; q < ne; q++) {
            int a = ea[q], b = eb[q];
            int lo = (a & b) == a ? a : b, hi = lo == a ? b : a;
            long g[3] = {i + (lo & 1), j + ((lo >> 1) & 1), k + ((lo >> 2) & 1)};
            e[q] = edge_vertex(c, g, (lo ^ hi) - 1, v[lo], v[hi]);
            if (c->oom) return;
        }
        /* the first edge of each triangle runs from an inside corner to an outside one */
        int ia = v[ea[0]] < 0.0 ? ea[0] : eb[0], oa = ia == ea[0] ? eb[0] : ea[0];
        sk_vec3d pin = sk_v3d(c->lo.x + c->cell * (double)(i + (ia & 1)),
                              c->lo.y + c->cell * (double)(j + ((ia >> 1) & 1)),
                              c->lo.z + c->cell * (double)(k + ((ia >> 2) & 1)));
        sk_vec3d pout = sk_v3d(c->lo.x + c->cell * (double)(i + (oa & 1)),
                               c->lo.y + c->cell * (double)(j + ((oa >> 1) & 1)),
                               c->lo.z + c->cell * (double)(k + ((oa >> 2) & 1)));
        emit(c, e[0], e[1], e[2], pin, pout);
        if (ne == 4) emit(c, e[0], e[2], e[3], pin, pout);
    }
}

sk_result sk__hand_extract(const sk__hand_field *f, double cell, sk__hand_trimesh *out,
                           sk_error *err)
{
    memset(out, 0, sizeof *out);
    extract_ctx c = {.field = f, .cell = cell, .out = out};
    double margin = 2.0 * cell;
    c.lo = sk_v3d(f->lo.x - margin, f->lo.y - margin, f->lo.z - margin);
    long nb[3];
    double ext[3] = {f->hi.x - f->lo.x + 2 * margin, f->hi.y - f->lo.y + 2 * margin,
                     f->hi.z - f->lo.z + 2 * margin};
    for (int a = 0; a < 3; a++) nb[a] = (long)ceil(ext[a] / (cell * BLOCK));
    c.nx = nb[0] * BLOCK + 1, c.ny = nb[1] * BLOCK + 1, c.nz = nb[2] * BLOCK + 1;
    if ((double)c.nx * (double)c.ny * (double)c.nz > 4e9)
        return sk_fail(err, SK_ERROR_LIMIT, "cell_mm = %g makes a grid of more than 4e9 points",
                       cell);
    long block_count = nb[0] * nb[1] * nb[2];
    /* classify blocks: which primitives reach them, and whether they may hold surface */
    double bsize = cell * BLOCK, half_diag = 0.5 * sqrt(3.0) * bsize;
    double reach = 0.0;
    for (int i = 0; i < f->count; i++) reach = fmax(reach, f->prim[i].blend);
    reach += f->root_blend + 1.0;
    int *lists = malloc((size_t)block_count * SK_HAND__MAX_PRIMS * sizeof *lists);
    int *counts = calloc((size_t)block_count, sizeof *counts);
    long *active = malloc((size_t)block_count * sizeof *active);
    if (!lists || !counts || !active) {
        free(lists), free(counts), free(active);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the surface grid");
    }
    long active_count = 0;
#pragma omp parallel for schedule(dynamic, 16) if (block_count > 256)
    for (long b = 0; b < block_count; b++) {
        long bx = b % nb[0], by = (b / nb[0]) % nb[1], bz = b / (nb[0] * nb[1]);
        sk_vec3d blo = sk_v3d(c.lo.x + bx * bsize, c.lo.y + by * bsize, c.lo.z + bz * bsize);
        sk_vec3d bhi = sk_v3d(blo.x + bsize, blo.y + bsize, blo.z + bsize);
        int *list = lists + b * SK_HAND__MAX_PRIMS, n = 0;
        for (int i = 0; i < f->count; i++) {
            const sk__hand_prim *p = &f->prim[i];
            if (p->lo.x - reach > bhi.x || p->hi.x + reach < blo.x || p->lo.y - reach > bhi.y ||
                p->hi.y + reach < blo.y || p->lo.z - reach > bhi.z || p->hi.z + reach < blo.z)
                continue;
            list[n++] = i;
        }
        counts[b] = n;
        if (n == 0) continue;
        sk_vec3d mid = sk_v3d_scale(sk_v3d_add(blo, bhi), 0.5);
        double v = sk__hand_field_eval_list(f, list, n, mid);
        if (fabs(v) > 1.5 * half_diag + 1.0) counts[b] = -n; /* no surface: skipped */
    }
    for (long b = 0; b < block_count; b++)
        if (counts[b] > 0) active[active_count++] = b;
    float *values = malloc((size_t)active_count * BP * BP * BP * sizeof *values);
    if (!values) {
        free(lists), free(counts), free(active);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the surface grid");
    }
#pragma omp parallel for schedule(dynamic, 4) if (active_count > 16)
    for (long a = 0; a < active_count; a++) {
        long b = active[a];
        long bx = b % nb[0], by = (b / nb[0]) % nb[1], bz = b / (nb[0] * nb[1]);
        const int *list = lists + b * SK_HAND__MAX_PRIMS;
        float *v = values + (size_t)a * BP * BP * BP;
        for (int z = 0; z < BP; z++)
            for (int y = 0; y < BP; y++)
                for (int x = 0; x < BP; x++) {
                    sk_vec3d p = sk_v3d(c.lo.x + cell * (double)(bx * BLOCK + x),
                                        c.lo.y + cell * (double)(by * BLOCK + y),
                                        c.lo.z + cell * (double)(bz * BLOCK + z));
                    v[(z * BP + y) * BP + x] =
                        (float)sk__hand_field_eval_list(f, list, counts[b], p);
                }
    }
    sk_result r = SK_OK;
    if (!map_init(&c.map, 1u << 16))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the surface grid");
    for (long a = 0; a < active_count && r == SK_OK; a++) {
        long b = active[a];
        long bx = b % nb[0], by = (b / nb[0]) % nb[1], bz = b / (nb[0] * nb[1]);
        const float *v = values + (size_t)a * BP * BP * BP;
        for (int z = 0; z < BLOCK && !c.oom; z++)
            for (int y = 0; y < BLOCK; y++)
                for (int x = 0; x < BLOCK; x++) {
                    double cv[8];
                    int neg = 0;
                    for (int q = 0; q < 8; q++) {
                        cv[q] = v[((z + (q >> 2)) * BP + y + ((q >> 1) & 1)) * BP + x + (q & 1)];
                        neg += cv[q] < 0.0;
                    }
                    if (neg == 0 || neg == 8) continue;
                    cube(&c, bx * BLOCK + x, by * BLOCK + y, bz * BLOCK + z, cv);
                }
        if (c.oom) r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the surface mesh");
    }
    map_free(&c.map);
    free(values), free(lists), free(counts), free(active);
    if (r != SK_OK) sk__hand_trimesh_free(out);
    return r;
}
