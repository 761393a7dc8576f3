/* Fibre direction and dive angle (Kawai 2000 sec. 4.1, 7.1). A fibre stays on its ring
 * surface t = const and advances around the tree by dtheta/dy = G / r (eq. 2), so its
 * tangent per unit height is e_y + r dtheta/dy e_theta plus, where the ring is not round,
 * the radial drift dR/dtheta dtheta/dy e_r. The dive angle is the paper's alpha: the angle
 * between the fibre and the cut surface, positive diving upwards (sec. 7.3). */
#ifndef SK_WOOD_FIBRE_H
#define SK_WOOD_FIBRE_H

#include "shitsukan/wood.h"
#include "models/wood/numeric.h"

/* Unit tangent, oriented up the tree, of the fibre through tree-frame point (r, theta) on
 * a ring surface whose radius changes by dR/dtheta around the ring, for the slope
 * G = r dtheta/dy: proportional to e_y + G e_theta + (G / r) dR/dtheta e_r. */
static inline sk_vec3d sk__fibre_direction(double G, double dR_dtheta, double r, double c, double s)
{
    double radial = G * dR_dtheta / (r > 1e-6 ? r : 1.0); /* selects: loops vectorize */
    radial = r > 1e-6 ? radial : 0.0;
    /* e_r = (cos, 0, sin), e_theta = (-sin, 0, cos), e_y = (0, 1, 0) */
    double fx = radial * c - G * s, fz = radial * s + G * c;
    double inv = 1.0 / sqrt(fx * fx + 1.0 + fz * fz);
    return sk_v3d(fx * inv, inv, fz * inv);
}

/* alpha = asin(-f . n) for the unit fibre f (up the tree) and the unit outward normal n:
 * positive when the fibre goes into the wood towards the tree top (sec. 7.3). */
static inline double sk__fibre_dive(sk_vec3f fibre, sk_vec3f normal)
{
    double d = -(double)sk_v3f_dot(fibre, normal);
    return sk__asin(d < -1.0 ? -1.0 : (d > 1.0 ? 1.0 : d));
}

#endif
