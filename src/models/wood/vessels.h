/* Vessels (Kawai 2000 sec. 5): vertical tubes seen as circles on the end grain, tested at
 * a point's end-grain position after the grain transform. Diffuse-porous vessels
 * (sec. 5.3) fill a square grid of cells of area 1 / rho, one vessel placed uniformly in
 * each; ring-porous vessels (sec. 5.4) sit in rows after each ring boundary, ring j
 * holding round(P R(j)) per row. Both are generated from (seed, cell or ring/row/index),
 * so the grid and the (ring, angle) buckets are the spatial index and nothing is stored
 * per vessel. */
#ifndef SK_WOOD_VESSELS_H
#define SK_WOOD_VESSELS_H

#include <stdbool.h>
#include <stdint.h>

#include "models/wood/batch.h"
#include "models/wood/rings.h"

typedef struct sk__vessel {
    double x, z;   /* end-grain centre (tree frame, mm) */
    double radius; /* mm */
} sk__vessel;

typedef struct sk__vessel_size {
    double mean, sd, lo, hi; /* radius ~ Normal(mean, sd) cut at 3 sd, at least lo */
} sk__vessel_size;

#define SK__NORMAL_TABLE 1024

typedef struct sk__diffuse_index {
    bool on;
    uint64_t seed;
    sk__vessel_size size;
    double cell, inv_cell; /* grid cell size (mm): one vessel per cell, cell^2 = 1 / rho */
} sk__diffuse_index;

typedef struct sk__ring_index {
    bool on;
    uint64_t seed;
    sk__vessel_size size;
    double density; /* P */
    double jitter;
    double pitch;                  /* radial distance between rows (mm) */
    double offset_min, offset_max; /* range of a centre's distance past its ring boundary */
    int rows;
} sk__ring_index;

typedef struct sk__vessels {
    sk__diffuse_index diffuse;
    sk__ring_index ring;
    /* standard normal quantiles at u = k / SK__NORMAL_TABLE, cut at +-3 (radius draws) */
    float normal_quantile[SK__NORMAL_TABLE + 1];
} sk__vessels;

/* From a resolved, validated desc. */
void sk__vessels_init(sk__vessels *vessels, const sk_wood_desc *desc);

/* The vessel of diffuse cell (cx, cz); false if there are no diffuse vessels. */
bool sk__diffuse_cell_vessel(const sk__vessels *vessels, int64_t cx, int64_t cz, sk__vessel *out);
/* Vessels per row of ring j (j >= 1; 0 for j <= 0). */
int sk__ring_vessel_count(const sk__ring_index *index, const sk__rings *rings, int j);
/* Vessel k (0 <= k < count) of row `row` of ring j. */
void sk__ring_vessel(const sk__vessels *vessels, const sk__rings *rings, int j, int row, int k,
                     sk__vessel *out);

/* Coverage in [0, 1] of the end-grain point (x0, z0) = r0 (cos theta0, sin theta0) of
 * formation time t by any vessel; with footprint > 0 outlines are softened over that
 * width, with 0 the answer is 0 or 1 (inside a circle: distance < radius). */
double sk__vessels_coverage(const sk__vessels *vessels, const sk__rings *rings, double x0,
                            double z0, double r0, double theta0, double t, double footprint);
/* sk__vessels_coverage_at for `count` <= SK__WOOD_BATCH points (arrays), into cover. */
void sk__vessels_coverage_batch(const sk__vessels *vessels, const sk__rings *rings, int count,
                                const sk__rings_at *at0, const double *x0, const double *z0,
                                const double *r0, const double *theta0, const double *t,
                                double footprint, double *cover);

/* The same with the ring table columns of theta0 already found (sk__rings_at_angle). */
double sk__vessels_coverage_at(const sk__vessels *vessels, const sk__rings *rings,
                               const sk__rings_at *at0, double x0, double z0, double r0,
                               double theta0, double t, double footprint);

/* Coverage of one vessel at distance d (the rule both the index and a scan use): the
 * outline is a linear ramp of width min(footprint, radius), which keeps the integrated
 * area of a pore within 10 % of pi radius^2 however small it is against the footprint
 * (a ramp a whole pixel wide would inflate sub-pixel pores up to several times). */
static inline double sk__vessel_cover(double d, double radius, double footprint)
{
    if (footprint <= 0.0) return d < radius ? 1.0 : 0.0;
    double w = footprint < radius ? footprint : radius;
    double c = 0.5 + (radius - d) / w;
    c = c > 0.0 ? c : 0.0; /* clamped to [0, 1] by selects (c is never -0) */
    return c < 1.0 ? c : 1.0;
}

/* How far from its centre a vessel of the largest radius can cover a point. */
static inline double sk__vessel_reach(double radius_max, double footprint)
{
    return radius_max + 0.5 * (footprint < radius_max ? footprint : radius_max);
}

#endif
