/* Private pieces of the scan pipeline (thesis 4.1): the triangle hierarchy that the
 * simulated scanner casts rays into, point-triangle distances, the scan target, and small
 * helpers shared by the stages. */
#ifndef SK_HAND_SCAN_INTERNAL_H
#define SK_HAND_SCAN_INTERNAL_H

#include <math.h>
#include <stdint.h>

#include "shitsukan/hand_scan.h"
#include "base/triangle_bvh.h"

/* ---------------------------------------------------------- scan target */
struct sk_hand_scan_target {
    sk__triangle_bvh bvh;
    sk_hand_sdf_fn sdf;
    void *sdf_user;
    double lo[3], hi[3]; /* bounds of the vertices */
};

/* Refines a ray's hit on the mesh onto the implicit surface (secant steps along the ray);
 * false when there is no implicit or it does not converge near the mesh hit. */
bool sk__hand_target_refine(const sk_hand_scan_target *target, sk_vec3d o, sk_vec3d d,
                            double t_mesh, double *t);

/* ---------------------------------------------------------- link frames */
/* Link coordinates of p: distance along the link's axis from its base (mm, unclamped) and
 * the angle about it in the link frame, atan2(z, x) of the frame's X and Z axes. */
void sk__hand_link_coordinates(const sk_hand_link_geometry *links, int link, sk_vec3d p,
                               double *along, double *angle);
/* Is the link a phalanx (its cross-sections are closed rings around it)? */
bool sk__hand_link_is_phalanx(int link);

/* Wraps an angle into (-pi, pi]. */
static inline double sk__hand_wrap_angle(double a)
{
    while (a > SK_PI) a -= 2.0 * SK_PI;
    while (a <= -SK_PI) a += 2.0 * SK_PI;
    return a;
}

#endif /* SK_HAND_SCAN_INTERNAL_H */
