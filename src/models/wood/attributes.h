/* The unified end-grain attribute array C'(t, theta) (Kawai 2000 sec. 6.3): the ring
 * reflectance (earlywood/latewood profile across each ring) plus an independent
 * brightness shift per cell of the end grain (sec. 6.1, 6.2), looked up through the grain
 * transform. */
#ifndef SK_WOOD_ATTRIBUTES_H
#define SK_WOOD_ATTRIBUTES_H

#include <stdint.h>

#include "shitsukan/wood.h"
#include "models/wood/numeric.h"

#define SK__SHIFT_TABLE 4096

typedef struct sk__attributes {
    sk_vec3f earlywood, latewood, vessel; /* linear RGB */
    /* latewood weight across a ring (u = t - floor(t)): 0 up to early_end, rising linearly
       to 1 at late_start, 1 until the ring's end */
    double early_end, late_start, per_year; /* per_year = integral over one ring */
    double shift;                           /* spread of the cells' shifts */
    bool shift_add;                         /* the paper's added shift (else multiplied) */
    double rows_per_year;                   /* cell rows per unit of t */
    double length, inv_length;              /* fibre length (0 = endless) */
    uint64_t seed;
    /* the sRGB curve both ways on [0, 1] at SK__SHIFT_TABLE + 1 points, linear between
       (errors below 2e-5, a twentieth of an 8-bit code), for the added shift */
    float to_srgb[SK__SHIFT_TABLE + 1], from_srgb[SK__SHIFT_TABLE + 1];
} sk__attributes;

/* value f(x) of a table of SK__SHIFT_TABLE + 1 points over [0, 1], x clamped */
static inline float sk__attributes_table(const float *table, float x)
{
    x = x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x);
    float u = x * (float)SK__SHIFT_TABLE;
    int i = (int)u;
    i = i > SK__SHIFT_TABLE - 1 ? SK__SHIFT_TABLE - 1 : i;
    return table[i] + (u - (float)i) * (table[i + 1] - table[i]);
}

/* A linear colour channel c with the cell's shift applied (u: the cell's uniform number,
 * sk__attributes_cell): the paper's brightness plus shift (u - 1/2), or c (1 - shift u). */
static inline float sk__attributes_shifted(const sk__attributes *a, float c, double u)
{
    if (!a->shift_add) return c * (float)(1.0 - a->shift * u);
    float v = sk__attributes_table(a->to_srgb, c) + (float)(a->shift * (u - 0.5));
    return sk__attributes_table(a->from_srgb, v);
}

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
    if (u < a->early_end)
        v = 0.0;
    else if (u < a->late_start)
        v = 0.5 * (u - a->early_end) * (u - a->early_end) / (a->late_start - a->early_end);
    else
        v = 0.5 * (a->late_start - a->early_end) + (u - a->late_start);
    return whole * a->per_year + v;
}

/* Latewood weight at time t averaged over [t - half, t + half] (half in years, >= 0). */
static inline double sk__attributes_latewood(const sk__attributes *a, double t, double half)
{
    double whole = sk__floor_d(t), u = t - whole;
    if (half < 1e-6) return sk__attributes_weight(a, u);
    /* a box inside the earlywood or the latewood plateau of one ring averages to 0 or 1 */
    if (u - half >= 0.0 && u + half < a->early_end) return 0.0;
    if (u - half >= a->late_start && u + half < 1.0) return 1.0;
    return (sk__attributes_integral(a, t + half) - sk__attributes_integral(a, t - half)) /
           (2.0 * half);
}

/* The uniform number in [0, 1) of the cell of C'(t, theta0) (theta0 in [0, 2 pi))
 * holding the fibre through height y, whose brightness shift it draws. Row i of the array
 * has round(2 pi (i + 1/2)) cells around the tree, so cells are about square at the
 * nominal radius (i + 1/2) cell. */
static inline double sk__attributes_cell(const sk__attributes *a, double t, double theta0, double y)
{
    int64_t row = sk__floor_i64(t * a->rows_per_year);
    int64_t cells = (int64_t)(6.283185307179586 * ((double)row + 0.5) + 0.5);
    if (cells < 1) cells = 1;
    int64_t cell = (int64_t)(theta0 * (0.15915494309189535 * (double)cells));
    if (cell >= cells) cell = cells - 1;
    int64_t segment = 0;
    if (a->length > 0.0) {
        /* fibre ends staggered by a per-cell offset */
        double offset = sk_u64_to_unit_d(sk__wood_hash(a->seed ^ 0x66696272ULL, row, cell, 0));
        segment = sk__floor_i64(y * a->inv_length + offset);
    }
    return sk_u64_to_unit_d(sk__wood_hash(a->seed, row, cell, segment));
}

#endif
