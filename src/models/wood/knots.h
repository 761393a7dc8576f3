/* Knots: branches as cones from the pith (after Larsson et al. 2022, "Procedural texturing
 * of solid wood with knots": every strand of the tree, stem or branch, has its own field
 * of formation time, merged by a smooth minimum), with the stem's grain flowing round
 * them. Beyond Kawai 2000, who names the other tissues as future work (sec. 8). */
#ifndef SK_WOOD_KNOTS_H
#define SK_WOOD_KNOTS_H

#include <stdbool.h>
#include <stdint.h>

#include "shitsukan/wood.h"
#include "models/wood/rings.h"

typedef struct sk__knots {
    bool on;
    uint64_t seed;
    double spacing, inv_spacing, phase; /* whorl k sits at (k + phase) spacing, jittered */
    double y_jitter;                    /* largest shift of a whorl along the axis */
    int per_whorl;
    double rise, rise_jitter; /* radians */
    double tan_lo, tan_hi;    /* tangents of the smallest and largest rise */
    double growth;            /* a branch's ring width (mm a year) */
    double size_jitter;       /* relative, either way */
    double dead;              /* years a branch lives, 0 = alive throughout */
    double stub, darkening, bark, collar, reach;
    double azimuth_jitter; /* fraction of the spacing between branches */
    sk_vec3f bark_color;   /* linear */
} sk__knots;

/* What a knot does at a point: where the stem's texture is looked up instead (the grain
 * deflected round the knot) and how the fibre turns there, the merged formation time,
 * and how much of the point is the knot's own wood. */
typedef struct sk__knot_hit {
    double theta_shift;  /* look the stem up at theta + theta_shift */
    double psi_u, psi_y; /* derivatives of the deflection map (see sk__knots_hit) */
    double t;            /* formation time: the stem's, merged with a live branch's */
    double knot;         /* weight of the knot's wood, [0, 1] (filtered over the footprint) */
    double bark;         /* weight of bark within it (dead knots), [0, 1] */
    double t_knot;       /* the knot's own ring time there (years of the branch) */
    double half_knot;    /* the footprint's half width in those years */
    sk_vec3d axis;       /* the branch's direction, tree frame (its fibres) */
} sk__knot_hit;

/* From a resolved, validated desc. */
void sk__knots_init(sk__knots *knots, const sk_wood_desc *desc);

/* The knot nearest the tree-frame point (r, theta, y) of stem formation time t_stem, if
 * one is in reach: its effect in *hit. `footprint` (mm, >= 0) softens the knot's edge. */
bool sk__knots_hit(const sk__knots *knots, const sk__rings *rings, double r, double theta, double y,
                   double t_stem, double footprint, sk__knot_hit *hit);

#endif
