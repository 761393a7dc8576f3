/* Topology check of a triangle mesh: a closed, oriented 2-manifold (every edge shared by
 * exactly two triangles wound oppositely, every vertex's triangles one fan), which the
 * hand surface and each of its levels of detail must be (thesis 4.1.3: one surface). */
#include <stdlib.h>
#include <string.h>

#include "models/hand_surface/surface_internal.h"

typedef struct directed_edge {
    uint32_t from, to, next; /* triangle (from, to, next) */
} directed_edge;

static int compare_edges(const void *a, const void *b)
{
    const directed_edge *x = a, *y = b;
    if (x->from != y->from) return x->from < y->from ? -1 : 1;
    return x->to < y->to ? -1 : (x->to > y->to);
}

static const directed_edge *find_edge(const directed_edge *e, size_t n, uint32_t from, uint32_t to)
{
    directed_edge key = {from, to, 0};
    return bsearch(&key, e, n, sizeof *e, compare_edges);
}

int sk__hand_mesh_topology(const uint32_t *tri, size_t triangle_count, size_t vertex_count,
                           long *euler, uint8_t *bad)
{
    size_t n = 3 * triangle_count;
    if (triangle_count == 0) return 0;
    directed_edge *e = malloc(n * sizeof *e);
    if (!e) return -1;
    for (size_t t = 0; t < triangle_count; t++)
        for (int k = 0; k < 3; k++)
            e[3 * t + k] =
                (directed_edge){tri[3 * t + k], tri[3 * t + (k + 1) % 3], tri[3 * t + (k + 2) % 3]};
    qsort(e, n, sizeof *e, compare_edges);
    int ok = 1;
    if (bad) memset(bad, 0, vertex_count);
    for (size_t i = 0; i < n && (ok || bad); i++) {
        if (e[i].from >= vertex_count || e[i].to >= vertex_count) {
            ok = 0;
            bad = NULL; /* nothing to mark it on */
            continue;
        }
        /* a degenerate triangle, an edge used twice the same way, or one without its twin */
        bool wrong = e[i].from == e[i].to ||
                     (i + 1 < n && e[i].from == e[i + 1].from && e[i].to == e[i + 1].to) ||
                     !find_edge(e, n, e[i].to, e[i].from);
        if (!wrong) continue;
        ok = 0;
        if (bad) bad[e[i].from] = bad[e[i].to] = 1;
    }
    /* fans: around vertex v, triangle (v, w, x) leads from neighbour w to x; one cycle
       through every outgoing edge of v means one disc of triangles */
    size_t lo = 0, used = 0;
    while ((ok || bad) && lo < n) {
        size_t hi = lo;
        while (hi < n && e[hi].from == e[lo].from) hi++;
        used++;
        uint32_t v = e[lo].from, w = e[lo].to;
        size_t steps = 0;
        do {
            const directed_edge *d = find_edge(e + lo, hi - lo, v, w);
            if (!d) break;
            w = d->next;
            steps++;
        } while (w != e[lo].to && steps <= hi - lo);
        if (steps != hi - lo || w != e[lo].to) {
            ok = 0;
            if (bad && v < vertex_count) bad[v] = 1;
        }
        lo = hi;
    }
    if (ok && used != vertex_count) ok = 0; /* a vertex no triangle uses */
    free(e);
    if (ok && euler) *euler = (long)vertex_count - (long)(n / 2) + (long)triangle_count;
    return ok;
}
