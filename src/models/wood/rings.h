/* Annual rings (Kawai 2000 sec. 4.4): the ring radius R(t, theta) of growth time t as a
 * table over (t, theta), piecewise linear in both, and its exact inverse T(r, theta). */
#ifndef SK_WOOD_RINGS_H
#define SK_WOOD_RINGS_H

#include <math.h>
#include <stdint.h>

#include "shitsukan/wood.h"
#include "models/wood/numeric.h"

typedef struct sk__rings {
    double width; /* d: mean growth per year (mm) */
    double dt;    /* t step of the table in years (1 / dt is an integer) */
    double inv_dt;
    int per_year;       /* knots per year, 1 / dt */
    double inside;      /* smallest R at the last knot: every r below is inside the table */
    int nt;             /* knots t_i = i dt, i = 0 .. nt - 1 */
    double t_max;       /* (nt - 1) dt */
    int years;          /* whole years the table covers (= t_max) */
    int ntheta;         /* theta intervals (a power of two; 1 for round rings) */
    double theta_scale; /* ntheta / (2 pi) */
    float *R;           /* column j (theta_j = j / theta_scale), knot i: R[j * nt + i];
                           ntheta + 1 columns, the last repeating column 0 */
    float *end_slope;   /* per column: dR/dt beyond the last knot */
    float *mean;        /* per knot: mean of R over theta */
    double mean_end_slope;
    /* Guess index for T: guess[j * nguess + k] is the last knot i whose radius in both
       columns j, j + 1 is at most k guess_step, so a search starts below the answer. */
    double guess_step, inv_guess_step;
    int nguess;
    uint16_t *guess;
    /* Per whole year j = 0 .. years: max over theta of |dR/dtheta| at t = j (mm/rad), a
       Lipschitz bound the vessel index uses. */
    float *lipschitz;
    double lipschitz_end_slope;
    /* Per whole year: smallest and largest R over theta, and their growth beyond. */
    float *year_min, *year_max;
    double min_end_slope, max_end_slope;
} sk__rings;

/* Builds the tables from a resolved, validated desc. */
sk_result sk__rings_build(sk__rings *rings, const sk_wood_desc *desc, sk_error *err);
void sk__rings_free(sk__rings *rings);
size_t sk__rings_memory(const sk__rings *rings);

/* The column coordinate u = theta ntheta / (2 pi) of an angle, split into its whole part
 * (column j before wrapping around) and the weight f = u - j of column j + 1; without
 * branches, so vector loops use it. */
static inline double sk__rings_column_split(double theta_scale, double theta, double *f)
{
    double u = theta * theta_scale, fl = sk__floor_vec(u);
    *f = u - fl;
    return fl;
}

/* The column j (wrapped around the tree) of a whole column coordinate. */
static inline int sk__rings_column_wrap(const sk__rings *rg, double whole)
{
    return (int)((int64_t)whole & (int64_t)(rg->ntheta - 1)); /* ntheta is a power of two */
}

/* Column pair (j, j + 1) and weight f of the angle theta (any real value). */
static inline void sk__rings_column(const sk__rings *rg, double theta, int *j, double *f)
{
    *j = sk__rings_column_wrap(rg, sk__rings_column_split(rg->theta_scale, theta, f));
}

static inline double sk__rings_col_value(const float *c0, const float *c1, double f, int i)
{
    return (double)c0[i] + f * ((double)c1[i] - (double)c0[i]);
}

/* The table columns around one angle, found once for several lookups at that angle. */
typedef struct sk__rings_at {
    const float *c0, *c1; /* columns j and j + 1 */
    double f;             /* weight of column j + 1 */
    int j;
} sk__rings_at;

/* The columns j, j + 1 with weight f (as sk__rings_column finds them). */
static inline sk__rings_at sk__rings_at_column(const sk__rings *rg, int j, double f)
{
    sk__rings_at at;
    at.j = j;
    at.f = f;
    at.c0 = rg->R + (size_t)j * (size_t)rg->nt;
    at.c1 = at.c0 + rg->nt;
    return at;
}

static inline sk__rings_at sk__rings_at_angle(const sk__rings *rg, double theta)
{
    int j;
    double f;
    sk__rings_column(rg, theta, &j, &f);
    return sk__rings_at_column(rg, j, f);
}

/* R(t, theta) at the angle of `at`. */
static inline double sk__rings_R_at(const sk__rings *rg, const sk__rings_at *at, double t)
{
    if (t <= 0.0) return 0.0;
    double u = t * rg->inv_dt;
    if (u >= (double)(rg->nt - 1)) {
        double last = sk__rings_col_value(at->c0, at->c1, at->f, rg->nt - 1);
        double slope =
            rg->end_slope[at->j] + at->f * (rg->end_slope[at->j + 1] - rg->end_slope[at->j]);
        return last + (t - rg->t_max) * slope;
    }
    int i = (int)u;
    double a = u - i;
    double r0 = sk__rings_col_value(at->c0, at->c1, at->f, i);
    double r1 = sk__rings_col_value(at->c0, at->c1, at->f, i + 1);
    return r0 + a * (r1 - r0);
}

/* R(j, theta) at the whole year j at the angle of `at`: a knot of the table (the value
 * sk__rings_R_at gives, without its interpolation). */
static inline double sk__rings_R_year_at(const sk__rings *rg, const sk__rings_at *at, int j)
{
    int i = j * rg->per_year;
    if (j > 0 && i < rg->nt - 1) return sk__rings_col_value(at->c0, at->c1, at->f, i);
    return sk__rings_R_at(rg, at, (double)j);
}

/* R(t, theta): radius of the ring formed at time t (years) in direction theta. */
static inline double sk__rings_R(const sk__rings *rg, double t, double theta)
{
    sk__rings_at at = sk__rings_at_angle(rg, theta);
    return sk__rings_R_at(rg, &at, t);
}

/* T(r, theta): formation time at radius r >= 0 in direction theta, the exact inverse of
 * sk__rings_R. Optional outputs: `width` = dR/dt there (mm per year) and `dR_dtheta`. */
static inline double sk__rings_T_at(const sk__rings *rg, const sk__rings_at *at, double r,
                                    double *width, double *dR_dtheta)
{
    const float *c0 = at->c0, *c1 = at->c1;
    double f = at->f;
    int j = at->j, last = rg->nt - 1;
    /* beyond the table (only past its smallest last radius: col_value lies between the
       columns' values) */
    double r_last;
    if (r >= rg->inside && r >= (r_last = sk__rings_col_value(c0, c1, f, last))) {
        double s0 = rg->end_slope[j], s1 = rg->end_slope[j + 1];
        double slope = s0 + f * (s1 - s0);
        double t = rg->t_max + (r - r_last) / slope;
        if (width) *width = slope;
        if (dR_dtheta)
            *dR_dtheta =
                (((double)c1[last] - c0[last]) + (t - rg->t_max) * (s1 - s0)) * rg->theta_scale;
        return t;
    }
    if (r < 0.0) r = 0.0;
    int k = (int)(r * rg->inv_guess_step);
    if (k >= rg->nguess) k = rg->nguess - 1;
    int i = rg->guess[(size_t)j * (size_t)rg->nguess + (size_t)k];
    double r1 = sk__rings_col_value(c0, c1, f, i + 1);
    /* the guess is the knot or one below it: a step without a branch, then (rarely) more */
    i += r1 <= r && i + 1 < last;
    r1 = sk__rings_col_value(c0, c1, f, i + 1);
    while (r1 <= r && i + 1 < last) {
        i++;
        r1 = sk__rings_col_value(c0, c1, f, i + 1);
    }
    double r0 = sk__rings_col_value(c0, c1, f, i);
    double a = (r - r0) / (r1 - r0);
    if (width) *width = (r1 - r0) * rg->inv_dt;
    if (dR_dtheta) {
        double d0 = (double)c1[i] - c0[i], d1 = (double)c1[i + 1] - c0[i + 1];
        *dR_dtheta = (d0 + a * (d1 - d0)) * rg->theta_scale;
    }
    return ((double)i + a) * rg->dt;
}

static inline double sk__rings_T(const sk__rings *rg, double r, double theta, double *width,
                                 double *dR_dtheta)
{
    sk__rings_at at = sk__rings_at_angle(rg, theta);
    return sk__rings_T_at(rg, &at, r, width, dR_dtheta);
}

/* Mean over theta of R(t, theta) (at a whole year, the table's knot). */
static inline double sk__rings_mean(const sk__rings *rg, double t)
{
    if (t <= 0.0) return 0.0;
    double u = t * rg->inv_dt;
    if (u >= (double)(rg->nt - 1))
        return rg->mean[rg->nt - 1] + (t - rg->t_max) * rg->mean_end_slope;
    int i = (int)u;
    double a = u - i;
    return rg->mean[i] + a * ((double)rg->mean[i + 1] - rg->mean[i]);
}

/* Bound on |dR/dtheta| over the whole ring at the whole year j >= 0. */
static inline double sk__rings_lipschitz(const sk__rings *rg, int j)
{
    if (j < 0) return 0.0;
    if (j <= rg->years) return rg->lipschitz[j];
    return rg->lipschitz[rg->years] + (j - rg->years) * rg->lipschitz_end_slope;
}

/* Smallest and largest R(j, theta) over theta at the whole year j >= 0. */
static inline void sk__rings_year_bounds(const sk__rings *rg, int j, double *lo, double *hi)
{
    if (j <= 0) {
        *lo = *hi = 0.0;
    } else if (j <= rg->years) {
        *lo = rg->year_min[j];
        *hi = rg->year_max[j];
    } else {
        *lo = rg->year_min[rg->years] + (j - rg->years) * rg->min_end_slope;
        *hi = rg->year_max[rg->years] + (j - rg->years) * rg->max_end_slope;
    }
}

#endif
