/* The tree object: the resolved desc and every table built from it (Kawai 2000). */
#ifndef SK_WOOD_INTERNAL_H
#define SK_WOOD_INTERNAL_H

#include "shitsukan/wood.h"
#include "models/wood/attributes.h"
#include "models/wood/batch.h"
#include "models/wood/frame.h"
#include "models/wood/grain.h"
#include "models/wood/knots.h"
#include "models/wood/rays.h"
#include "models/wood/rings.h"
#include "models/wood/shade.h"
#include "models/wood/vessels.h"

struct sk_wood {
    sk_wood_desc desc; /* resolved */
    sk__wood_frame frame;
    sk__rings rings;
    sk__grain grain;
    sk__vessels vessels;
    sk__attributes attr;
    sk__knots knots;
    sk__rays rays;
    sk__shading shading;
    sk_vec3f axis; /* the tree's +y in the scene */
    sk_wood_stats stats;
};

/* sk_wood_eval_filtered for `count` <= SK__WOOD_BATCH scene points (points[0..2]: the
 * arrays of x, y and z) with one normal; `flags` (SK__WOOD_EVAL_*) asks for the optional
 * outputs. It runs in two stages, which a planar cut may run apart (cut.c). */
void sk__wood_eval_batch(const sk_wood *wood, int count, const float *const points[3],
                         sk_vec3f normal, float footprint_mm, unsigned flags, sk__wood_batch *out);

/* What a point's place on the cross-section (tree-frame x and z) alone determines, one
 * array entry per point: radius, angle, T(r, theta) with its ring width and dR/dtheta,
 * the footprint's half width in years and the ring profile's latewood weight
 * (box-filtered over it). */
typedef struct sk__wood_section {
    double *r, *cos_t, *sin_t, *theta, *t, *width, *dR, *half, *late;
} sk__wood_section;
#define SK__WOOD_SECTION_FIELDS 9

/* The first stage, for `count` <= SK__WOOD_BATCH tree-frame points (x, z) seen with the
 * scene normal `normal`. */
void sk__wood_section_eval(const sk_wood *wood, int count, const float *x, const float *z,
                           sk_vec3f normal, float footprint_mm, const sk__wood_section *out);

/* The second stage: the points of `section` at tree heights y (grain, end-grain lookup,
 * vessels, albedo, fibre, dive). */
void sk__wood_eval_section_batch(const sk_wood *wood, int count, const sk__wood_section *section,
                                 const double *y, sk_vec3f normal, float footprint_mm,
                                 unsigned flags, sk__wood_batch *out);

/* The unit direction towards the tree top in the surface of unit normal n (any tangent on
 * end grain): the `up` of every sample evaluated with that normal. */
sk_vec3f sk__wood_surface_up(const sk_wood *wood, sk_vec3f n);

#endif
