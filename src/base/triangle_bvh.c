/* A bounding volume hierarchy of triangles for the simulated range scanner (thesis 4.1.1:
 * laser rays and camera occlusion) and nearest-point queries. Built on one thread by
 * median splits of the triangle centroids along the widest axis, so the same mesh always
 * gives the same tree; queries are read-only and run on any number of threads. */
#include <stdlib.h>
#include <string.h>

#include "base/keyed_index.h"
#include "base/triangle_bvh.h"

#define LEAF_SIZE 4
#define STACK_SIZE 96

typedef struct builder {
    sk__triangle_bvh *bvh;
    const sk_vec3d (*tri)[3];
    sk_vec3d *centroid;
    uint32_t *order;
    sk__keyed_index *scratch;
} builder;

static void grow(double lo[3], double hi[3], sk_vec3d p)
{
    double q[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; k++) {
        if (q[k] < lo[k]) lo[k] = q[k];
        if (q[k] > hi[k]) hi[k] = q[k];
    }
}

static uint32_t build_node(builder *b, uint32_t first, uint32_t count)
{
    uint32_t id = b->bvh->node_count++;
    sk__triangle_bvh_node *node = &b->bvh->nodes[id];
    double clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < 3; k++) node->lo[k] = INFINITY, node->hi[k] = -INFINITY;
    for (uint32_t i = first; i < first + count; i++) {
        uint32_t t = b->order[i];
        for (int v = 0; v < 3; v++) grow(node->lo, node->hi, b->tri[t][v]);
        grow(clo, chi, b->centroid[t]);
    }
    if (count <= LEAF_SIZE) {
        node->first = first;
        node->count = count;
        return id;
    }
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    sk__keyed_index *s = b->scratch + first;
    for (uint32_t i = 0; i < count; i++) {
        sk_vec3d c = b->centroid[b->order[first + i]];
        s[i].key = axis == 0 ? c.x : axis == 1 ? c.y : c.z;
        s[i].index = b->order[first + i];
    }
    qsort(s, count, sizeof *s, sk__keyed_index_compare);
    for (uint32_t i = 0; i < count; i++) b->order[first + i] = s[i].index;
    uint32_t half = count / 2;
    node->count = 0;
    build_node(b, first, half);
    uint32_t right = build_node(b, first + half, count - half);
    b->bvh->nodes[id].first = right;
    return id;
}

sk_result sk__triangle_bvh_build(sk__triangle_bvh *bvh, const sk_vec3d (*triangles)[3],
                                 uint32_t count, sk_error *err)
{
    memset(bvh, 0, sizeof *bvh);
    if (count == 0) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "mesh has no triangles");
    if (count > (1u << 26))
        return sk_fail(err, SK_ERROR_LIMIT, "mesh has %u triangles (at most 2^26)", count);
    /* a median-split tree of n >= 1 triangles has fewer than 2n / LEAF_SIZE * 2 + 1 nodes */
    uint32_t max_nodes = 2 * count + 1;
    builder b = {bvh, triangles, malloc(sizeof(sk_vec3d) * count), malloc(sizeof(uint32_t) * count),
                 malloc(sizeof(sk__keyed_index) * count)};
    bvh->nodes = malloc(sizeof *bvh->nodes * max_nodes);
    bvh->tri = malloc(sizeof *bvh->tri * count);
    bvh->original = malloc(sizeof *bvh->original * count);
    if (!b.centroid || !b.order || !b.scratch || !bvh->nodes || !bvh->tri || !bvh->original) {
        free(b.centroid), free(b.order), free(b.scratch);
        sk__triangle_bvh_free(bvh);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "triangle hierarchy of %u triangles", count);
    }
    for (uint32_t t = 0; t < count; t++) {
        for (int v = 0; v < 3; v++) {
            sk_vec3d p = triangles[t][v];
            if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z)) {
                free(b.centroid), free(b.order), free(b.scratch);
                sk__triangle_bvh_free(bvh);
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "triangle %u has a non-finite vertex", t);
            }
        }
        b.centroid[t] = sk_v3d_scale(
            sk_v3d_add(sk_v3d_add(triangles[t][0], triangles[t][1]), triangles[t][2]), 1.0 / 3.0);
        b.order[t] = t;
    }
    bvh->triangle_count = count;
    build_node(&b, 0, count);
    for (uint32_t i = 0; i < count; i++) {
        bvh->original[i] = b.order[i];
        memcpy(bvh->tri[i], triangles[b.order[i]], sizeof bvh->tri[i]);
    }
    free(b.centroid), free(b.order), free(b.scratch);
    return SK_OK;
}

void sk__triangle_bvh_free(sk__triangle_bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->tri);
    free(bvh->original);
    memset(bvh, 0, sizeof *bvh);
}

/* Slab test; returns the entry parameter or INFINITY on a miss. */
static double ray_box(const sk__triangle_bvh_node *n, const double o[3], const double inv[3],
                      const int zero[3], double t_min, double t_max)
{
    double t0 = t_min, t1 = t_max;
    for (int k = 0; k < 3; k++) {
        if (zero[k]) {
            if (o[k] < n->lo[k] || o[k] > n->hi[k]) return INFINITY;
            continue;
        }
        double a = (n->lo[k] - o[k]) * inv[k], b = (n->hi[k] - o[k]) * inv[k];
        if (a > b) {
            double s = a;
            a = b;
            b = s;
        }
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return INFINITY;
    }
    return t0;
}

/* Moller-Trumbore, two-sided; returns t or INFINITY. */
static double ray_triangle(const sk_vec3d tri[3], sk_vec3d o, sk_vec3d d)
{
    sk_vec3d e1 = sk_v3d_sub(tri[1], tri[0]), e2 = sk_v3d_sub(tri[2], tri[0]);
    sk_vec3d p = sk_v3d_cross(d, e2);
    double det = sk_v3d_dot(e1, p);
    if (det == 0.0) return INFINITY;
    double inv = 1.0 / det;
    sk_vec3d s = sk_v3d_sub(o, tri[0]);
    double u = sk_v3d_dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return INFINITY;
    sk_vec3d q = sk_v3d_cross(s, e1);
    double v = sk_v3d_dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return INFINITY;
    return sk_v3d_dot(e2, q) * inv;
}

static bool traverse(const sk__triangle_bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                     double t_max, bool any, sk__triangle_hit *hit)
{
    if (bvh->node_count == 0) return false;
    double oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z}, inv[3];
    int zero[3];
    for (int k = 0; k < 3; k++) {
        zero[k] = dd[k] == 0.0;
        inv[k] = zero[k] ? 0.0 : 1.0 / dd[k];
    }
    uint32_t stack[STACK_SIZE];
    int top = 0;
    stack[top++] = 0;
    double best = t_max;
    uint32_t best_tri = 0;
    bool found = false;
    while (top > 0) {
        const sk__triangle_bvh_node *n = &bvh->nodes[stack[--top]];
        if (ray_box(n, oo, inv, zero, t_min, best) == INFINITY) continue;
        if (n->count > 0) {
            for (uint32_t i = n->first; i < n->first + n->count; i++) {
                double t = ray_triangle(bvh->tri[i], o, d);
                if (t > t_min && t < best) {
                    best = t;
                    best_tri = i;
                    found = true;
                    if (any) return true;
                }
            }
            continue;
        }
        uint32_t left = (uint32_t)(n - bvh->nodes) + 1, right = n->first;
        double tl = ray_box(&bvh->nodes[left], oo, inv, zero, t_min, best);
        double tr = ray_box(&bvh->nodes[right], oo, inv, zero, t_min, best);
        /* nearer child on top of the stack */
        if (tl <= tr) {
            if (tr != INFINITY && top < STACK_SIZE) stack[top++] = right;
            if (tl != INFINITY && top < STACK_SIZE) stack[top++] = left;
        } else {
            if (tl != INFINITY && top < STACK_SIZE) stack[top++] = left;
            if (tr != INFINITY && top < STACK_SIZE) stack[top++] = right;
        }
    }
    if (found && hit) {
        hit->t = best;
        hit->triangle = best_tri;
    }
    return found;
}

bool sk__triangle_bvh_intersect(const sk__triangle_bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                                double t_max, sk__triangle_hit *hit)
{
    return traverse(bvh, o, d, t_min, t_max, false, hit);
}

bool sk__triangle_bvh_occluded(const sk__triangle_bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                               double t_max)
{
    return traverse(bvh, o, d, t_min, t_max, true, NULL);
}

sk_vec3d sk__triangle_bvh_normal(const sk__triangle_bvh *bvh, uint32_t triangle)
{
    const sk_vec3d *t = bvh->tri[triangle];
    return sk_v3d_normalize(sk_v3d_cross(sk_v3d_sub(t[1], t[0]), sk_v3d_sub(t[2], t[0])));
}

sk_vec3d sk__closest_on_triangle(sk_vec3d p, sk_vec3d a, sk_vec3d b, sk_vec3d c)
{
    /* Which of the 7 Voronoi regions (3 vertices, 3 edges, the face) holds p, from the
       signs of dot products with the edges. */
    sk_vec3d ab = sk_v3d_sub(b, a), ac = sk_v3d_sub(c, a), ap = sk_v3d_sub(p, a);
    double d1 = sk_v3d_dot(ab, ap), d2 = sk_v3d_dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    sk_vec3d bp = sk_v3d_sub(p, b);
    double d3 = sk_v3d_dot(ab, bp), d4 = sk_v3d_dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return sk_v3d_add(a, sk_v3d_scale(ab, d1 / (d1 - d3)));
    sk_vec3d cp = sk_v3d_sub(p, c);
    double d5 = sk_v3d_dot(ab, cp), d6 = sk_v3d_dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return sk_v3d_add(a, sk_v3d_scale(ac, d2 / (d2 - d6)));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return sk_v3d_add(b, sk_v3d_scale(sk_v3d_sub(c, b), w));
    }
    double denom = 1.0 / (va + vb + vc);
    double v = vb * denom, w = vc * denom;
    return sk_v3d_add(a, sk_v3d_add(sk_v3d_scale(ab, v), sk_v3d_scale(ac, w)));
}

double sk__triangle_bvh_nearest(const sk__triangle_bvh *bvh, sk_vec3d p, double max_d2,
                                sk_vec3d *closest)
{
    if (bvh->node_count == 0) return max_d2;
    uint32_t stack[STACK_SIZE];
    int top = 0;
    stack[top++] = 0;
    double best = max_d2;
    while (top > 0) {
        const sk__triangle_bvh_node *n = &bvh->nodes[stack[--top]];
        if (sk__box_distance2(n->lo, n->hi, p) >= best) continue;
        if (n->count > 0) {
            for (uint32_t i = n->first; i < n->first + n->count; i++) {
                sk_vec3d q =
                    sk__closest_on_triangle(p, bvh->tri[i][0], bvh->tri[i][1], bvh->tri[i][2]);
                double d2 = sk__dist2(p, q);
                if (d2 < best) {
                    best = d2;
                    if (closest) *closest = q;
                }
            }
            continue;
        }
        uint32_t left = (uint32_t)(n - bvh->nodes) + 1, right = n->first;
        double dl = sk__box_distance2(bvh->nodes[left].lo, bvh->nodes[left].hi, p);
        double dr = sk__box_distance2(bvh->nodes[right].lo, bvh->nodes[right].hi, p);
        if (dl <= dr) {
            if (dr < best && top < STACK_SIZE) stack[top++] = right;
            if (dl < best && top < STACK_SIZE) stack[top++] = left;
        } else {
            if (dl < best && top < STACK_SIZE) stack[top++] = left;
            if (dr < best && top < STACK_SIZE) stack[top++] = right;
        }
    }
    return best;
}
