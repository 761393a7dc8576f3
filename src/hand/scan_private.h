/* Private pieces of the scan pipeline (thesis 4.1): the triangle hierarchy that the
 * simulated scanner casts rays into, point-triangle distances, the scan target, and small
 * helpers shared by the stages. */
#ifndef SK_HAND_SCAN_PRIVATE_H
#define SK_HAND_SCAN_PRIVATE_H

#include <math.h>
#include <stdint.h>

#include "shitsukan/hand.h"

/* ------------------------------------------------------ triangle hierarchy */
/* A bounding volume hierarchy over triangles (double precision), built on one thread by
 * median splits of the centroids along the widest axis, so it is the same on every run.
 * Answers first hits of rays, any hit (occlusion) and nearest points. */
typedef struct sk_hand__bvh_node {
    double lo[3], hi[3];
    uint32_t first; /* leaf: first triangle; inner: index of the right child (left = next) */
    uint32_t count; /* triangles in a leaf; 0 for an inner node */
} sk_hand__bvh_node;

typedef struct sk_hand__bvh {
    uint32_t triangle_count, node_count;
    sk_hand__bvh_node *nodes;
    sk_vec3d (*tri)[3]; /* vertices, in leaf order */
    uint32_t *original; /* leaf order -> caller's triangle index */
} sk_hand__bvh;

sk_result sk_hand__bvh_build(sk_hand__bvh *bvh, const sk_vec3d (*triangles)[3], uint32_t count,
                             sk_error *err);
void sk_hand__bvh_free(sk_hand__bvh *bvh);

typedef struct sk_hand__ray_hit {
    double t;
    uint32_t triangle; /* leaf-order index into bvh->tri */
} sk_hand__ray_hit;

/* First hit with t in (t_min, t_max), or false. */
bool sk_hand__bvh_intersect(const sk_hand__bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                            double t_max, sk_hand__ray_hit *hit);
/* Any hit with t in (t_min, t_max). */
bool sk_hand__bvh_occluded(const sk_hand__bvh *bvh, sk_vec3d o, sk_vec3d d, double t_min,
                           double t_max);
/* Nearest point of the triangles to p; returns the squared distance (below max_d2, else
 * max_d2 is returned and *closest untouched). */
double sk_hand__bvh_nearest(const sk_hand__bvh *bvh, sk_vec3d p, double max_d2, sk_vec3d *closest);

/* Unit normal of a leaf-order triangle (right-handed winding). */
sk_vec3d sk_hand__bvh_normal(const sk_hand__bvh *bvh, uint32_t triangle);

/* ------------------------------------------------------------- geometry */
/* The point of triangle (a, b, c) nearest to p (by its Voronoi regions). */
sk_vec3d sk_hand__closest_on_triangle(sk_vec3d p, sk_vec3d a, sk_vec3d b, sk_vec3d c);
/* Squared distance from p to an axis-aligned box (0 inside). */
static inline double sk_hand__box_distance2(const double lo[3], const double hi[3], sk_vec3d p)
{
    double q[3] = {p.x, p.y, p.z}, d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double e = q[k] < lo[k] ? lo[k] - q[k] : (q[k] > hi[k] ? q[k] - hi[k] : 0.0);
        d2 += e * e;
    }
    return d2;
}
static inline double sk_hand__dist2(sk_vec3d a, sk_vec3d b)
{
    sk_vec3d d = sk_v3d_sub(a, b);
    return sk_v3d_dot(d, d);
}

/* ---------------------------------------------------------- scan target */
struct sk_hand_scan_target {
    sk_hand__bvh bvh;
    sk_hand_sdf_fn sdf;
    void *sdf_user;
    double lo[3], hi[3]; /* bounds of the vertices */
};

/* Refines a ray's hit on the mesh onto the implicit surface (secant steps along the ray);
 * false when there is no implicit or it does not converge near the mesh hit. */
bool sk_hand__target_refine(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d,
                            double t_mesh, double *t);

/* ---------------------------------------------------------- link frames */
/* Link coordinates of p: distance along the link's axis from its base (mm, unclamped) and
 * the angle about it in the link frame, atan2(z, x) of the frame's X and Z axes. */
void sk_hand__link_coordinates(const sk_hand_link_geometry *links, int link, sk_vec3d p,
                               double *along, double *angle);
/* Is the link a phalanx (its cross-sections are closed rings around it)? */
bool sk_hand__link_is_phalanx(int link);

/* Wraps an angle into (-pi, pi]. */
static inline double sk_hand__wrap_angle(double a)
{
    while (a > SK_PI) a -= 2.0 * SK_PI;
    while (a <= -SK_PI) a += 2.0 * SK_PI;
    return a;
}

#endif /* SK_HAND_SCAN_PRIVATE_H */
