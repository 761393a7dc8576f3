/* The fitting-error measure of thesis 4.1.4 / Table 4.1: "各パッチ内でパラメータ u, v について
 * 100 等分し、10000 のセグメントに分割した。パッチのフィッティングに用いた各計測点から最近傍の
 * セグメントとの距離を誤差とした" - each patch split 100 x 100 in (u, v) into 10,000 facets,
 * the error of a data point its distance to the nearest facet. A facet is the pair of
 * triangles of its grid cell; the nearest one is found exactly by a quadtree of boxes over
 * the facet grid, searched after a first guess from the facets around the point's own
 * parameters. */
#include <stdlib.h>

#include "models/hand_scan/scan_internal.h"

#define LEAF 2 /* facets per leaf side */

typedef struct qnode {
    double lo[3], hi[3];
    int a0, a1, b0, b1; /* facet range [a0, a1) x [b0, b1) */
    int child[4];       /* -1 = none; all -1 in a leaf */
} qnode;

typedef struct facet_grid {
    int n;
    const sk_vec3d *v; /* (n + 1)^2 vertices: v[a * (n + 1) + b] = Q(a / n, b / n) */
    qnode *nodes;
    int count;
} facet_grid;

static int build(facet_grid *g, int a0, int a1, int b0, int b1)
{
    int id = g->count++;
    qnode *q = &g->nodes[id];
    q->a0 = a0, q->a1 = a1, q->b0 = b0, q->b1 = b1;
    for (int k = 0; k < 4; k++) q->child[k] = -1;
    for (int k = 0; k < 3; k++) q->lo[k] = INFINITY, q->hi[k] = -INFINITY;
    if (a1 - a0 <= LEAF && b1 - b0 <= LEAF) {
        for (int a = a0; a <= a1; a++)
            for (int b = b0; b <= b1; b++) {
                sk_vec3d p = g->v[a * (g->n + 1) + b];
                double c[3] = {p.x, p.y, p.z};
                for (int k = 0; k < 3; k++) {
                    if (c[k] < q->lo[k]) q->lo[k] = c[k];
                    if (c[k] > q->hi[k]) q->hi[k] = c[k];
                }
            }
        return id;
    }
    int am = a1 - a0 > LEAF ? (a0 + a1) / 2 : a1, bm = b1 - b0 > LEAF ? (b0 + b1) / 2 : b1;
    int ranges[4][4] = {{a0, am, b0, bm}, {am, a1, b0, bm}, {a0, am, bm, b1}, {am, a1, bm, b1}};
    int k = 0;
    for (int c = 0; c < 4; c++) {
        if (ranges[c][0] >= ranges[c][1] || ranges[c][2] >= ranges[c][3]) continue;
        int child = build(g, ranges[c][0], ranges[c][1], ranges[c][2], ranges[c][3]);
        g->nodes[id].child[k++] = child;
        for (int e = 0; e < 3; e++) {
            if (g->nodes[child].lo[e] < g->nodes[id].lo[e])
                g->nodes[id].lo[e] = g->nodes[child].lo[e];
            if (g->nodes[child].hi[e] > g->nodes[id].hi[e])
                g->nodes[id].hi[e] = g->nodes[child].hi[e];
        }
    }
    return id;
}

/* Squared distance to triangle (a, b, c) if below `best`, else `best`: the distance to
 * its plane bounds it from below and is cheap. */
static inline double triangle_distance2(sk_vec3d p, sk_vec3d a, sk_vec3d b, sk_vec3d c, double best)
{
    sk_vec3d n = sk_v3d_cross(sk_v3d_sub(b, a), sk_v3d_sub(c, a));
    double h = sk_v3d_dot(sk_v3d_sub(p, a), n), nn = sk_v3d_dot(n, n);
    if (h * h >= best * nn) return best;
    double d2 = sk__dist2(p, sk__closest_on_triangle(p, a, b, c));
    return d2 < best ? d2 : best;
}

static double facet_distance2(const facet_grid *g, int a, int b, sk_vec3d p, double best)
{
    int w = g->n + 1;
    sk_vec3d v00 = g->v[a * w + b], v10 = g->v[(a + 1) * w + b];
    sk_vec3d v11 = g->v[(a + 1) * w + b + 1], v01 = g->v[a * w + b + 1];
    best = triangle_distance2(p, v00, v10, v11, best);
    return triangle_distance2(p, v00, v11, v01, best);
}

static double nearest(const facet_grid *g, sk_vec3d p, double best)
{
    int stack[64], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const qnode *q = &g->nodes[stack[--top]];
        if (sk__box_distance2(q->lo, q->hi, p) >= best) continue;
        if (q->child[0] < 0) {
            for (int a = q->a0; a < q->a1; a++)
                for (int b = q->b0; b < q->b1; b++) best = facet_distance2(g, a, b, p, best);
            continue;
        }
        /* push the farther children first, so the nearest is searched first */
        double dist[4];
        int order[4], m = 0;
        for (int c = 0; c < 4 && q->child[c] >= 0; c++) {
            dist[m] = sk__box_distance2(g->nodes[q->child[c]].lo, g->nodes[q->child[c]].hi, p);
            order[m++] = q->child[c];
        }
        for (int i = 1; i < m; i++)
            for (int j = i; j > 0 && dist[j] > dist[j - 1]; j--) {
                double t = dist[j];
                dist[j] = dist[j - 1], dist[j - 1] = t;
                int o = order[j];
                order[j] = order[j - 1], order[j - 1] = o;
            }
        for (int i = 0; i < m; i++)
            if (dist[i] < best && top < 64) stack[top++] = order[i];
    }
    return best;
}

sk_result sk_hand_patch_facet_distances(const sk_hand_patch *patch, int splits,
                                        const sk_vec3d *points, size_t count, const double *u_hint,
                                        const double *v_hint, double *distance, sk_error *err)
{
    if (splits == 0) splits = 100;
    sk_result r = sk_check_range_i(err, "facet_splits", splits, 1, 1024);
    if (r != SK_OK) return r;
    int w = splits + 1;
    sk_vec3d *v = malloc(sizeof *v * (size_t)w * (size_t)w);
    /* halving gives at most 2 ceil(s / LEAF) leaves per side, and a quadtree has fewer
       than 4/3 as many nodes as leaves */
    int leaves = 2 * ((splits + LEAF - 1) / LEAF);
    int max_nodes = 2 * leaves * leaves + 64;
    qnode *nodes = malloc(sizeof *nodes * (size_t)max_nodes);
    if (!v || !nodes) {
        free(v), free(nodes);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "facet grid of %d x %d", splits, splits);
    }
    for (int a = 0; a < w; a++)
        for (int b = 0; b < w; b++)
            v[a * w + b] =
                sk_hand_patch_eval(patch, (double)a / splits, (double)b / splits, NULL, NULL);
    facet_grid g = {splits, v, nodes, 0};
    build(&g, 0, splits, 0, splits);
    for (size_t k = 0; k < count; k++) {
        double best = INFINITY;
        if (u_hint && v_hint) {
            /* first guess: the facets around the point's own parameters */
            int a = (int)(u_hint[k] * splits), b = (int)(v_hint[k] * splits);
            a = a < 0 ? 0 : (a >= splits ? splits - 1 : a);
            b = b < 0 ? 0 : (b >= splits ? splits - 1 : b);
            for (int da = -1; da <= 1; da++)
                for (int db = -1; db <= 1; db++) {
                    int aa = a + da, bb = b + db;
                    if (aa < 0 || bb < 0 || aa >= splits || bb >= splits) continue;
                    best = facet_distance2(&g, aa, bb, points[k], best);
                }
        }
        distance[k] = sqrt(nearest(&g, points[k], best));
    }
    free(v);
    free(nodes);
    return SK_OK;
}
