/* Broad (medullary) rays: radial ribbons of ray tissue placed on the end grain in
 * (t, theta) and along the fibre in y, looked up through the grain transform (beyond
 * Kawai 2000: the radial tissues of sec. 3.2, named as future work in sec. 8). */
#ifndef SK_WOOD_RAYS_H
#define SK_WOOD_RAYS_H

#include <stdbool.h>
#include <stdint.h>

#include "shitsukan/wood.h"
#include "models/wood/rings.h"

typedef struct sk__rays {
    bool on;
    uint64_t seed;
    double spacing; /* between the rays of one of the two staggered sets (mm) */
    double width, height, jitter;
    double band_years; /* a ray's radial length in years of mean growth */
    double row;        /* distance between ray rows along the fibre (mm) */
    sk_vec3f color;    /* linear */
} sk__rays;

/* From a resolved, validated desc. */
void sk__rays_init(sk__rays *rays, const sk_wood_desc *desc);

/* Coverage in [0, 1] by ray tissue of the end-grain point at formation time t, angle
 * theta0 in [0, 2 pi) and radius r0, at height y. The outlines are softened over the
 * footprint's extent in each of the ray's directions: `across` (mm round the tree),
 * `along` (mm up the fibre) and `radial` (mm out from the pith), each the pixel's
 * footprint times the part of that direction that lies in the surface (a face nearly in
 * a ray's plane crosses its edge in a sharp line); 0 for point sampling. */
double sk__rays_coverage(const sk__rays *rays, const sk__rings *rings, double t, double theta0,
                         double r0, double y, double across, double along, double radial);

#endif
