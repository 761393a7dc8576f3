/* The unified end-grain attribute array C'(t, theta) (Kawai 2000 sec. 6.3): the ring
 * reflectance (earlywood/latewood profile across each ring) times an independent
 * brightness shift per cell of the end grain (sec. 6.1, 6.2), looked up through the grain
 * transform. */
#ifndef SK_WOOD_ATTRIBUTES_H
#define SK_WOOD_ATTRIBUTES_H

#include <stdint.h>

#include "shitsukan/wood.h"
#include "wood/numeric.h"

typedef struct sk__attributes {
    sk_vec3f earlywood, latewood, vessel; /* linear RGB */
    /* latewood weight across a ring (u = t - floor(t)): 0 up to early_end, rising linearly
       to 1 at late_start, 1 until the ring's end */
    double early_end, late_start, per_year; /* per_year = integral over one ring */
    double shift;                           /* largest darkening of a cell */
    double cell, inv_cell;
    uint64_t seed;
} sk__attributes;

/* A desc colour (sRGB-encoded) as linear RGB. */
sk_vec3f sk__linear_from_srgb3(const float srgb[3]);

void sk__attributes_init(sk__attributes *attr, const sk_wood_desc *desc);

static inline double sk__attributes_weight(const sk__attributes *a, double u)
{
    if (u < a->early_end) return 0.0;
    if (u < a->late_start) return (u - a->early_end) / (a->late_start - a->early_end);
    return 1.0;
}

/* Integral of the latewood weight from t = 0. */
static inline double sk__attributes_integral(const sk__attributes *a, double t)
{
    double whole = sk__floor_d(t), u = t - whole, v;
    if (u < a->early_end) v = 0.0;
    else if (u < a->late_start)
        v = 0.5 * (u - a->early_end) * (u - a->early_end) / (a->late_start - a->early_end);
    else v = 0.5 * (a->late_start - a->early_end) + (u - a->late_start);
    return whole * a->per_year + v;
}

/* Latewood weight at time t averaged over [t - half, t + half] (half in years, >= 0). */
static inline double sk__attributes_latewood(const sk__attributes *a, double t, double half)
{
    if (half < 1e-6) return sk__attributes_weight(a, t - sk__floor_d(t));
    return (sk__attributes_integral(a, t + half) - sk__attributes_integral(a, t - half)) /
           (2.0 * half);
}

/* Brightness factor in [1 - shift, 1] of the end-grain cell holding (x0, z0). */
static inline double sk__attributes_shift(const sk__attributes *a, double x0, double z0)
{
    if (a->shift == 0.0) return 1.0;
    int64_t cx = sk__floor_i64(x0 * a->inv_cell), cz = sk__floor_i64(z0 * a->inv_cell);
    return 1.0 - a->shift * sk_u64_to_unit_d(sk__wood_hash(a->seed, cx, cz, 0));
}

#endif
