/* A bounding volume hierarchy over triangles in double precision: the hand's simulated
 * range scanner casts its rays through it (thesis 4.1.1), the hand surface asks it for
 * nearest points. */
#ifndef SK_TRIANGLE_BVH_H
#define SK_TRIANGLE_BVH_H

#include <stdbool.h>
#include <stdint.h>

#include "shitsukan/core.h"

/* Squared distance from p to an axis-aligned box (0 inside). */
static inline double sk__box_distance2(const double lo[3], const double hi[3], sk_vec3d p)
{
    double q[3] = {p.x, p.y, p.z}, d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double e = q[k] < lo[k] ? lo[k] - q[k] : (q[k] > hi[k] ? q[k] - hi[k] : 0.0);
        d2 += e * e;
    }
    return d2;
}
static inline double sk__dist2(sk_vec3d a, sk_vec3d b)
{
    sk_vec3d d = sk_v3d_sub(a, b);
    return sk_v3d_dot(d, d);
}

/* A bounding volume hierarchy over triangles (double precision), built on one thread by
 * median splits of the centroids along the widest axis, so it is the same on every run.
 * Answers first hits of rays, any hit (occlusion) and nearest points. */
typedef struct sk__triangle_bvh_node {
    double lo[3], hi[3];
    uint32_t first; /* leaf: first triangle; inner: index of the right child (left = next) */
    uint32_t count; /* triangles in a leaf; 0 for an inner node */
} sk__triangle_bvh_node;

typedef struct sk__triangle_bvh {
    uint32_t triangle_count, node_count;
    sk__triangle_bvh_node *nodes;
    sk_vec3d (*tri)[3]; /* vertices, in leaf order */
    uint32_t *original; /* leaf order -> caller's triangle index */
} sk__triangle_bvh;

sk_result sk__triangle_bvh_build(sk__triangle_bvh *bvh, const sk_vec3d (*triangles)[3],
                                 uint32_t count, sk_error *err);
void sk__triangle_bvh_free(sk__triangle_bvh *bvh);

typedef struct sk__triangle_hit {
    double t;
    uint32_t triangle; /* leaf-order index into bvh->tri */
} sk__triangle_hit;

/* First hit with t in (t_min, t_max), or false. */
bool sk__triangle_bvh_intersect(const sk__triangle_bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                                double t_max, sk__triangle_hit *hit);
/* Any hit with t in (t_min, t_max). */
bool sk__triangle_bvh_occluded(const sk__triangle_bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                               double t_max);
/* Nearest point of the triangles to p; returns the squared distance (below max_d2, else
 * max_d2 is returned and *closest untouched). */
double sk__triangle_bvh_nearest(const sk__triangle_bvh *bvh, sk_vec3d p, double max_d2,
                                sk_vec3d *closest);

/* Unit normal of a leaf-order triangle (right-handed winding). */
sk_vec3d sk__triangle_bvh_normal(const sk__triangle_bvh *bvh, uint32_t triangle);

/* ------------------------------------------------------------- geometry */
/* The point of triangle (a, b, c) nearest to p (by its Voronoi regions). */
sk_vec3d sk__closest_on_triangle(sk_vec3d p, sk_vec3d a, sk_vec3d b, sk_vec3d c);

#endif
