/* Simplification of the meshed hand surface to the thesis's triangle count (about 8000,
 * sec. 4.1.3) by quadric error edge collapses (Garland & Heckbert 1997): every collapse
 * keeps the mesh a closed 2-manifold of the same topology (the link condition of Dey et
 * al. 1999) and no triangle turns over or degenerates into a sliver. Deterministic: one
 * thread, ties broken by vertex index. Then a tangential relaxation that moves each
 * vertex toward the centre of its neighbours within its tangent plane and back onto the
 * implicit surface. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"
#include "base/keyed_index.h"

#define MAX_RING 64

typedef struct heap_entry {
    double cost;
    double p[3];
    uint32_t a, b, sa, sb;
} heap_entry;

typedef struct simplifier {
    sk__hand_trimesh *m;
    double *q; /* 10 per vertex: the symmetric 4x4 quadric */
    uint32_t *stamp;
    bool *vdead, *tdead;
    uint32_t *start, *count, *cap, *pool;
    size_t pool_used, pool_cap;
    heap_entry *heap; /* the edges of a pass */
    double length_weight;
    bool oom;
} simplifier;

static const double *P(const simplifier *s, uint32_t v) { return s->m->pos + 3 * (size_t)v; }

static void tri_normal(const double *a, const double *b, const double *c, double n[3])
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
           w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
}

/* 4 sqrt(3) area / sum of squared edges: 1 for an equilateral triangle. */
static double quality(const double *a, const double *b, const double *c)
{
    double n[3];
    tri_normal(a, b, c, n);
    double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double l = 0;
    for (int k = 0; k < 3; k++) {
        double e1 = b[k] - a[k], e2 = c[k] - b[k], e3 = a[k] - c[k];
        l += e1 * e1 + e2 * e2 + e3 * e3;
    }
    return l > 0 ? 2.0 * sqrt(3.0) * area2 / l : 0.0;
}

/* Appends triangle t to vertex v's list (moving the list to the pool's end if full). */
static void adj_append(simplifier *s, uint32_t v, uint32_t t)
{
    if (s->count[v] == s->cap[v]) {
        uint32_t ncap = 2 * s->cap[v] + 4;
        if (s->pool_used + ncap > s->pool_cap) {
            size_t n = 2 * s->pool_cap + ncap;
            uint32_t *p = realloc(s->pool, n * sizeof *p);
            if (!p) {
                s->oom = true;
                return;
            }
            s->pool = p, s->pool_cap = n;
        }
        memcpy(s->pool + s->pool_used, s->pool + s->start[v], s->count[v] * sizeof *s->pool);
        s->start[v] = (uint32_t)s->pool_used;
        s->cap[v] = ncap;
        s->pool_used += ncap;
    }
    s->pool[s->start[v] + s->count[v]++] = t;
}

/* Drops dead triangles from v's list; returns its live count. */
static uint32_t adj_compact(simplifier *s, uint32_t v)
{
    uint32_t *l = s->pool + s->start[v], n = 0;
    for (uint32_t i = 0; i < s->count[v]; i++)
        if (!s->tdead[l[i]]) l[n++] = l[i];
    s->count[v] = n;
    return n;
}

/* Neighbour vertices of v: on a closed manifold each triangle around v gives the
 * vertex after v in its winding, every neighbour once. Returns the count, or -1 if
 * more than MAX_RING. */
static int ring(simplifier *s, uint32_t v, uint32_t *out)
{
    uint32_t c = adj_compact(s, v);
    if (c > MAX_RING) return -1;
    const uint32_t *l = s->pool + s->start[v];
    for (uint32_t i = 0; i < c; i++) {
        const uint32_t *t = s->m->tri + 3 * (size_t)l[i];
        out[i] = t[0] == v ? t[1] : (t[1] == v ? t[2] : t[0]);
    }
    return (int)c;
}

static double quadric_eval(const double *q, const double *p)
{
    /* q: a11 a12 a13 a14 a22 a23 a24 a33 a34 a44 */
    double x = p[0], y = p[1], z = p[2];
    return q[0] * x * x + 2 * q[1] * x * y + 2 * q[2] * x * z + 2 * q[3] * x + q[4] * y * y +
           2 * q[5] * y * z + 2 * q[6] * y + q[7] * z * z + 2 * q[8] * z + q[9];
}

static void edge_cost(simplifier *s, uint32_t a, uint32_t b, heap_entry *e)
{
    double q[10];
    for (int k = 0; k < 10; k++) q[k] = s->q[10 * (size_t)a + k] + s->q[10 * (size_t)b + k];
    const double *pa = P(s, a), *pb = P(s, b);
    double mid[3] = {0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])};
    double len2 = 0;
    for (int k = 0; k < 3; k++) len2 += (pa[k] - pb[k]) * (pa[k] - pb[k]);
    /* optimal point: solve A p = -b by Cramer's rule when well conditioned */
    sk_mat3d A = {{{q[0], q[1], q[2]}, {q[1], q[4], q[5]}, {q[2], q[5], q[7]}}};
    double det = sk_m3d_det(A);
    double scale = q[0] + q[4] + q[7];
    double best[3], best_err = DBL_MAX;
    if (fabs(det) > 1e-9 * scale * scale * scale && scale > 0) {
        sk_vec3d x = sk_m3d_solve_cramer(A, sk_v3d(-q[3], -q[6], -q[8]), det);
        double p[3] = {x.x, x.y, x.z};
        double d2 = 0;
        for (int k = 0; k < 3; k++) d2 += (p[k] - mid[k]) * (p[k] - mid[k]);
        if (d2 <= len2) {
            memcpy(best, p, sizeof best);
            best_err = quadric_eval(q, p);
        }
    }
    const double *cand[3] = {mid, pa, pb};
    for (int i = 0; i < 3; i++) {
        double err = quadric_eval(q, cand[i]);
        if (err < best_err - 1e-12 * fabs(best_err)) {
            best_err = err;
            memcpy(best, cand[i], sizeof best);
        }
    }
    e->cost = fmax(best_err, 0.0) + s->length_weight * len2 * len2;
    memcpy(e->p, best, sizeof best);
    e->a = a, e->b = b, e->sa = s->stamp[a], e->sb = s->stamp[b];
}

/* Whether v's triangles that do not contain `other` stay well shaped with v at p. */
static bool ring_ok(simplifier *s, uint32_t v, uint32_t other, const double *p)
{
    const uint32_t *l = s->pool + s->start[v];
    for (uint32_t i = 0; i < s->count[v]; i++) {
        const uint32_t *t = s->m->tri + 3 * (size_t)l[i];
        if (t[0] == other || t[1] == other || t[2] == other) continue;
        const double *c[3], *o[3];
        for (int k = 0; k < 3; k++) {
            o[k] = P(s, t[k]);
            c[k] = t[k] == v ? p : o[k];
        }
        double n0[3], n1[3];
        tri_normal(o[0], o[1], o[2], n0);
        tri_normal(c[0], c[1], c[2], n1);
        double l0 = sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
        double l1 = sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
        if (l1 <= 0.0) return false;
        if (l0 > 0.0 && (n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2]) < 0.5 * l0 * l1)
            return false;
        /* no new slivers (a sliver of the marching tetrahedra may only get better) */
        double qn = quality(c[0], c[1], c[2]);
        if (qn < 0.02 && qn < quality(o[0], o[1], o[2])) return false;
    }
    return true;
}

static bool can_collapse(simplifier *s, uint32_t a, uint32_t b, const double *p)
{
    uint32_t ra[MAX_RING], rb[MAX_RING];
    int na = ring(s, a, ra), nb = ring(s, b, rb);
    if (na < 0 || nb < 0 || na + nb > MAX_RING) return false;
    /* the two triangles on edge ab and their third vertices */
    uint32_t third[2];
    int shared = 0;
    const uint32_t *l = s->pool + s->start[a];
    for (uint32_t i = 0; i < s->count[a]; i++) {
        const uint32_t *t = s->m->tri + 3 * (size_t)l[i];
        if (t[0] != b && t[1] != b && t[2] != b) continue;
        if (shared == 2) return false;
        for (int k = 0; k < 3; k++)
            if (t[k] != a && t[k] != b) third[shared] = t[k];
        shared++;
    }
    if (shared != 2) return false;
    /* link condition: the common neighbours are exactly those two */
    int common = 0;
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++)
            if (ra[i] == rb[j]) {
                if (ra[i] != third[0] && ra[i] != third[1]) return false;
                common++;
            }
    if (common != 2) return false;
    /* the third vertices keep at least 3 neighbours */
    for (int k = 0; k < 2; k++)
        if (adj_compact(s, third[k]) <= 3) return false;
    return ring_ok(s, a, b, p) && ring_ok(s, b, a, p);
}

static void adj_remove(simplifier *s, uint32_t v, uint32_t t)
{
    uint32_t *l = s->pool + s->start[v];
    for (uint32_t i = 0; i < s->count[v]; i++)
        if (l[i] == t) {
            l[i] = l[--s->count[v]];
            return;
        }
}

/* Flips the diagonal of two triangles on edge (a, b) when the other diagonal makes them
 * better shaped and the pair is nearly flat (Delaunay-like flips keep collapses from
 * running into slivers). Returns the number of flips. */
static size_t flip_pass(simplifier *s, const uint32_t *live, size_t live_n)
{
    sk__hand_trimesh *m = s->m;
    size_t flips = 0;
    for (size_t li = 0; li < live_n; li++) {
        size_t t1 = live[li];
        if (s->tdead[t1]) continue;
        for (int k = 0; k < 3; k++) {
            uint32_t *A = m->tri + 3 * t1;
            uint32_t a = A[k], b = A[(k + 1) % 3], c = A[(k + 2) % 3];
            /* the other triangle on a -> b runs b -> a -> d */
            uint32_t t2 = UINT32_MAX, d = 0;
            const uint32_t *l = s->pool + s->start[b];
            for (uint32_t i = 0; i < s->count[b]; i++) {
                uint32_t ti = l[i];
                if (ti == t1 || s->tdead[ti]) continue;
                const uint32_t *B = m->tri + 3 * (size_t)ti;
                for (int j = 0; j < 3; j++)
                    if (B[j] == b && B[(j + 1) % 3] == a) t2 = ti, d = B[(j + 2) % 3];
            }
            if (t2 == UINT32_MAX || c == d) continue;
            const double *pa = P(s, a), *pb = P(s, b), *pc = P(s, c), *pd = P(s, d);
            double n1[3], n2[3];
            tri_normal(pa, pb, pc, n1);
            tri_normal(pb, pa, pd, n2);
            double l1 = sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
            double l2 = sqrt(n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]);
            if (l1 <= 0 || l2 <= 0 ||
                n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] < 0.95 * l1 * l2)
                continue;
            double before = fmin(quality(pa, pb, pc), quality(pb, pa, pd));
            double after = fmin(quality(pa, pd, pc), quality(pd, pb, pc));
            if (after <= before * 1.05) continue;
            /* the new triangles must face the same way */
            double m1[3], m2[3];
            tri_normal(pa, pd, pc, m1);
            tri_normal(pd, pb, pc, m2);
            if (m1[0] * n1[0] + m1[1] * n1[1] + m1[2] * n1[2] <= 0 ||
                m2[0] * n1[0] + m2[1] * n1[1] + m2[2] * n1[2] <= 0)
                continue;
            /* the edge c-d must not exist yet */
            uint32_t rc[MAX_RING];
            int nc = ring(s, c, rc);
            bool exists = nc < 0;
            for (int i = 0; i < nc && !exists; i++) exists = rc[i] == d;
            if (exists) continue;
            uint32_t *B = m->tri + 3 * (size_t)t2;
            A[0] = a, A[1] = d, A[2] = c;
            B[0] = d, B[1] = b, B[2] = c;
            adj_remove(s, a, t2);
            adj_remove(s, b, (uint32_t)t1);
            adj_append(s, c, t2);
            adj_append(s, d, (uint32_t)t1);
            flips++;
            break;
        }
    }
    return flips;
}

static void collapse(simplifier *s, uint32_t a, uint32_t b, const double *p)
{
    const uint32_t *l = s->pool + s->start[b];
    uint32_t n = s->count[b];
    for (uint32_t i = 0; i < n; i++) {
        uint32_t ti = l[i];
        uint32_t *t = s->m->tri + 3 * (size_t)ti;
        if (s->tdead[ti]) continue;
        if (t[0] == a || t[1] == a || t[2] == a) {
            s->tdead[ti] = true;
            continue;
        }
        for (int k = 0; k < 3; k++)
            if (t[k] == b) t[k] = a;
        adj_append(s, a, ti);
        l = s->pool + s->start[b]; /* the pool may have moved */
    }
    adj_compact(s, a);
    memcpy(s->m->pos + 3 * (size_t)a, p, 3 * sizeof *p);
    for (int k = 0; k < 10; k++) s->q[10 * (size_t)a + k] += s->q[10 * (size_t)b + k];
    s->vdead[b] = true;
    s->count[b] = 0;
    s->stamp[a]++;
}

sk_result sk__hand_simplify(sk__hand_trimesh *m, size_t target, sk_error *err)
{
    size_t V = m->vertex_count, T = m->tri_count;
    if (T <= target) return SK_OK;
    simplifier s = {.m = m};
    s.q = calloc(V * 10, sizeof *s.q);
    s.stamp = calloc(V, sizeof *s.stamp);
    s.vdead = calloc(V, sizeof *s.vdead);
    s.tdead = calloc(T, sizeof *s.tdead);
    s.start = malloc(V * sizeof *s.start);
    s.count = calloc(V, sizeof *s.count);
    s.cap = malloc(V * sizeof *s.cap);
    s.pool_cap = 3 * T + 8 * V;
    s.pool = malloc(s.pool_cap * sizeof *s.pool);
    sk_result r = SK_OK;
    if (!s.q || !s.stamp || !s.vdead || !s.tdead || !s.start || !s.count || !s.cap || !s.pool) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory simplifying the surface");
        goto done;
    }
    /* vertex -> triangle lists and area-weighted plane quadrics */
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) s.count[m->tri[3 * t + k]]++;
    for (size_t v = 0; v < V; v++) {
        s.start[v] = (uint32_t)s.pool_used;
        s.cap[v] = s.count[v] + 4;
        s.pool_used += s.cap[v];
        s.count[v] = 0;
    }
    double mean_len2 = 0;
    for (size_t t = 0; t < T; t++) {
        const uint32_t *tv = m->tri + 3 * t;
        for (int k = 0; k < 3; k++) s.pool[s.start[tv[k]] + s.count[tv[k]]++] = (uint32_t)t;
        double n[3];
        tri_normal(P(&s, tv[0]), P(&s, tv[1]), P(&s, tv[2]), n);
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; k++) {
            const double *a = P(&s, tv[k]), *b = P(&s, tv[(k + 1) % 3]);
            mean_len2 += (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                         (a[2] - b[2]) * (a[2] - b[2]);
        }
        if (l <= 0) continue;
        double area = 0.5 * l;
        for (int k = 0; k < 3; k++) n[k] /= l;
        const double *a = P(&s, tv[0]);
        double d = -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]);
        double K[10] = {n[0] * n[0], n[0] * n[1], n[0] * n[2], n[0] * d, n[1] * n[1],
                        n[1] * n[2], n[1] * d,    n[2] * n[2], n[2] * d, d * d};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 10; j++) s.q[10 * (size_t)tv[k] + j] += area * K[j];
    }
    mean_len2 /= (double)(3 * T);
    /* a price on long edges (as large as the quadric error of a strongly curved
       collapse at the target edge length) keeps the triangles of about equal size, as
       the thesis's resampled mesh; the quadrics place the kept vertices */
    double target_len2 = mean_len2 * (double)T / (double)target;
    s.length_weight = 1.0 / target_len2;
    /* passes: every live edge costed (in parallel), then collapsed cheapest first,
       each vertex at most once per pass so the costs used stay exact */
    size_t alive = T;
    bool *touched = calloc(V, sizeof *touched);
    s.heap = malloc(3 * T * sizeof *s.heap);
    sk__keyed_index *keys = malloc(3 * T * sizeof *keys);
    uint32_t *live = malloc(T * sizeof *live);
    size_t live_n = T;
    for (size_t t = 0; t < T; t++) live[t] = (uint32_t)t;
    if (!touched || !s.heap || !keys || !live) {
        free(keys), free(live), free(touched);
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory simplifying the surface");
        goto done;
    }
    for (int pass = 0; pass < 200 && alive > target && !s.oom; pass++) {
        size_t n = 0, nl = 0;
        for (size_t i = 0; i < live_n; i++) {
            uint32_t t = live[i];
            if (s.tdead[t]) continue;
            live[nl++] = t;
            const uint32_t *tv = m->tri + 3 * (size_t)t;
            for (int k = 0; k < 3; k++) {
                uint32_t a = tv[k], b = tv[(k + 1) % 3];
                if (a < b) s.heap[n].a = a, s.heap[n++].b = b; /* each edge once on a closed mesh */
            }
        }
#pragma omp parallel for schedule(static) if (n > 20000)
        for (size_t i = 0; i < n; i++) {
            edge_cost(&s, s.heap[i].a, s.heap[i].b, &s.heap[i]);
            keys[i].key = s.heap[i].cost;
            keys[i].index = (uint32_t)i;
        }
        live_n = nl;
        qsort(keys, n, sizeof *keys, sk__keyed_index_compare);
        memset(touched, 0, V * sizeof *touched);
        size_t done_here = 0;
        for (size_t i = 0; i < n && alive > target && !s.oom; i++) {
            const heap_entry *e = &s.heap[keys[i].index];
            if (touched[e->a] || touched[e->b] || s.vdead[e->a] || s.vdead[e->b]) continue;
            if (!can_collapse(&s, e->a, e->b, e->p)) continue;
            collapse(&s, e->a, e->b, e->p);
            touched[e->a] = true;
            alive -= 2;
            done_here++;
        }
        size_t flips = flip_pass(&s, live, live_n);
        if (done_here == 0 && flips == 0) break;
    }
    free(touched), free(keys), free(live);
    if (s.oom) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory simplifying the surface");
        goto done;
    }
    /* compact: live vertices in index order */
    {
        uint32_t *remap = malloc(V * sizeof *remap);
        if (!remap) {
            r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory simplifying the surface");
            goto done;
        }
        size_t nv = 0;
        for (size_t v = 0; v < V; v++) {
            remap[v] = UINT32_MAX;
            if (s.vdead[v]) continue;
            remap[v] = (uint32_t)nv;
            memmove(m->pos + 3 * nv, m->pos + 3 * v, 3 * sizeof *m->pos);
            nv++;
        }
        size_t nt = 0;
        for (size_t t = 0; t < T; t++) {
            if (s.tdead[t]) continue;
            for (int k = 0; k < 3; k++) m->tri[3 * nt + k] = remap[m->tri[3 * t + k]];
            nt++;
        }
        m->vertex_count = nv;
        m->tri_count = nt;
        free(remap);
    }
done:
    free(s.q), free(s.stamp), free(s.vdead), free(s.tdead), free(s.start), free(s.count),
        free(s.cap), free(s.pool);
    free(s.heap);
    return r;
}

void sk__hand_relax(sk__hand_trimesh *m, const sk__hand_field *field, int iterations)
{
    size_t V = m->vertex_count, T = m->tri_count;
    uint32_t *off = calloc(V + 1, sizeof *off), *nbr = malloc(6 * T * sizeof *nbr);
    double *next = malloc(3 * V * sizeof *next), *normal = calloc(3 * V, sizeof *normal);
    if (!off || !nbr || !next || !normal) goto done;
    /* each triangle's directed edges give every neighbour once on a closed manifold */
    for (size_t t = 0; t < T; t++)
        for (int k = 0; k < 3; k++) off[m->tri[3 * t + k] + 1]++;
    for (size_t v = 0; v < V; v++) off[v + 1] += off[v];
    {
        uint32_t *fill = calloc(V, sizeof *fill);
        if (!fill) goto done;
        for (size_t t = 0; t < T; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t a = m->tri[3 * t + k], b = m->tri[3 * t + (k + 1) % 3];
                nbr[off[a] + fill[a]++] = b;
            }
        free(fill);
    }
    for (int it = 0; it < iterations; it++) {
        memset(normal, 0, 3 * V * sizeof *normal);
        for (size_t t = 0; t < T; t++) {
            const uint32_t *tv = m->tri + 3 * t;
            double n[3];
            tri_normal(m->pos + 3 * tv[0], m->pos + 3 * tv[1], m->pos + 3 * tv[2], n);
            for (int k = 0; k < 3; k++)
                for (int j = 0; j < 3; j++) normal[3 * tv[k] + j] += n[j];
        }
#pragma omp parallel for schedule(static) if (V > 4096)
        for (size_t v = 0; v < V; v++) {
            const double *p = m->pos + 3 * v;
            double c[3] = {0, 0, 0};
            uint32_t n = off[v + 1] - off[v];
            for (uint32_t i = off[v]; i < off[v + 1]; i++)
                for (int j = 0; j < 3; j++) c[j] += m->pos[3 * nbr[i] + j];
            double *nv = normal + 3 * v;
            double l = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
            double d[3];
            for (int j = 0; j < 3; j++) d[j] = (n ? c[j] / n : p[j]) - p[j];
            if (l > 0) {
                double dn = (d[0] * nv[0] + d[1] * nv[1] + d[2] * nv[2]) / (l * l);
                for (int j = 0; j < 3; j++) d[j] -= dn * nv[j];
            }
            sk_vec3d x = sk_v3d(p[0] + 0.5 * d[0], p[1] + 0.5 * d[1], p[2] + 0.5 * d[2]);
            sk_vec3d onto;
            sk__hand_field_project(field, x, &onto);
            /* at most 0.3 mm off the relaxed point (keeps thin gaps open) */
            sk_vec3d mv = sk_v3d_sub(onto, x);
            double ml = sk_v3d_length(mv);
            if (ml > 0.3) onto = sk_v3d_add(x, sk_v3d_scale(mv, 0.3 / ml));
            next[3 * v] = onto.x, next[3 * v + 1] = onto.y, next[3 * v + 2] = onto.z;
        }
        memcpy(m->pos, next, 3 * V * sizeof *next);
    }
done:
    free(off), free(nbr), free(next), free(normal);
}
