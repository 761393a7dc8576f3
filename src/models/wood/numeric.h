/* Small numeric helpers for the wood module's per-sample code: floor, hashing and the
 * elementary functions without library calls. At -O2 on x86-64 floor(), atan2() and
 * sin() are calls the compiler can neither schedule across nor vectorize; these inline
 * versions use classic range reductions, a small table and short series, with errors
 * below 1e-9, far under the single-precision data they feed. */
#ifndef SK_WOOD_NUMERIC_H
#define SK_WOOD_NUMERIC_H

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "shitsukan/core.h"

/* floor(x) as an integer, for |x| < 2^62. */
static inline int64_t sk__floor_i64(double x)
{
    int64_t i = (int64_t)x;
    return i - (x < (double)i);
}

static inline double sk__floor_d(double x) { return (double)sk__floor_i64(x); }

/* floor(x) for |x| < 2^51 as a double, without integer conversions (so loops of it
 * vectorize): adding and removing 1.5 2^52 rounds x to an integer, then step down if that
 * went up. Equal to sk__floor_d in that range (beyond it, deterministic but not exact). */
static inline double sk__floor_vec(double x)
{
    const double round = 6755399441055744.0; /* 1.5 2^52 */
    double a = (x + round) - round;
    return a > x ? a - 1.0 : a;
}

/* One 64-bit mix of a seed and three integer ids: leaner than sk_hash (which mixes every
 * id separately) for lookups made millions of times per image; distinct small ids give
 * independent-looking bits. */
#define SK__WOOD_HASH_A 0x9e3779b97f4a7c15ULL
#define SK__WOOD_HASH_B 0xc2b2ae3d27d4eb4fULL
#define SK__WOOD_HASH_C 0x165667b19e3779f9ULL
static inline uint64_t sk__wood_hash(uint64_t seed, int64_t a, int64_t b, int64_t c)
{
    return sk_mix64(seed + (uint64_t)a * SK__WOOD_HASH_A + (uint64_t)b * SK__WOOD_HASH_B +
                    (uint64_t)c * SK__WOOD_HASH_C);
}

/* The 16-bit field `which` (0-3) of a hash as a number in [0, 1): four independent
 * uniform numbers from one hash. */
static inline double sk__hash_unit16(uint64_t h, int which)
{
    return (double)((h >> (which * 16)) & 0xffffu) * (1.0 / 65536.0);
}

/* Coverage of a shape at signed distance x inside its edge (mm), the edge a linear ramp
 * over the footprint (mm); a step when the footprint is 0. */
static inline double sk__edge_ramp(double x, double footprint)
{
    if (footprint <= 0.0) return x > 0.0 ? 1.0 : 0.0;
    double v = 0.5 + x / footprint;
    return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
}

/* atan2(y, x) in (-pi, pi]: the ratio q in [0, 1] of the smaller to the larger magnitude
 * is moved next to the nearest of c = 0, 1/4, .., 1 by atan(q) = atan(c) +
 * atan((q - c) / (1 + q c)), leaving |u| <= 1/8 for the series (error < u^11 / 11).
 * Branch-free (selects only), so loops of it vectorize; atan2(0, 0) = 0. */
static inline double sk__atan2(double y, double x)
{
    double ax = fabs(x), ay = fabs(y);
    int swap = ay > ax;
    double num = swap ? ax : ay, den = swap ? ay : ax;
    double q = num / (den == 0.0 ? 1.0 : den);
    double k = (double)(int)(q * 4.0 + 0.5), c = 0.25 * k;
    /* atan(c) */
    double atan_c = k < 0.5 ? 0.0 : 0.24497866312686414;
    atan_c = k < 1.5 ? atan_c : 0.46364760900080612;
    atan_c = k < 2.5 ? atan_c : 0.64350110879328439;
    atan_c = k < 3.5 ? atan_c : 0.78539816339744831;
    double u = (q - c) / (1.0 + q * c), u2 = u * u;
    double a =
        atan_c + u * (1.0 + u2 * (-1.0 / 3 + u2 * (1.0 / 5 + u2 * (-1.0 / 7 + u2 * (1.0 / 9)))));
    a = swap ? 1.5707963267948966 - a : a;
    a = x < 0.0 ? 3.1415926535897931 - a : a;
    return y < 0.0 ? -a : a;
}

/* sin and cos of 2 pi k / 256, k = 0 .. 255 (numeric.c). */
extern const double sk__sin_cos_table[256][2];

/* sin and cos of x (|x| < 1e9): x = k pi/128 + b with |b| <= pi/256 (pi/128 split in two
 * parts so b keeps its precision), the table at k, and the series of sin b and cos b
 * (errors below 1e-17) joined by the addition formulas. In two steps so that loops can
 * vectorize the arithmetic: sk__sincos_reduce gives k (as a double) and the series,
 * sk__sincos_join looks up the table and joins them. */
static inline void sk__sincos_reduce(double x, double *k, double *sb, double *cb)
{
    double kf = sk__floor_vec(x * 40.743665431525208 + 0.5);
    double b = (x - kf * 0.024543692605220713) - kf * 9.495469541415925e-13, b2 = b * b;
    *k = kf;
    *sb = b * (1.0 + b2 * (-1.0 / 6 + b2 * (1.0 / 120)));
    *cb = 1.0 + b2 * (-0.5 + b2 * (1.0 / 24 + b2 * (-1.0 / 720)));
}

static inline void sk__sincos_join(double k, double sb, double cb, double *s, double *c)
{
    const double *t = sk__sin_cos_table[(int64_t)k & 255];
    *s = t[0] * cb + t[1] * sb;
    *c = t[1] * cb - t[0] * sb;
}

static inline void sk__sincos(double x, double *s, double *c)
{
    double k, sb, cb;
    sk__sincos_reduce(x, &k, &sb, &cb);
    sk__sincos_join(k, sb, cb, s, c);
}

/* asin(x) for |x| <= 1: the Taylor series on |x| <= 1/2 (to x^23, error < 2e-10), and
 * asin x = pi/2 - 2 asin(sqrt((1 - x) / 2)) beyond, which maps into that range. */
static inline double sk__asin(double x)
{
    double ax = fabs(x), z = ax;
    int big = ax > 0.5;
    if (big) z = sqrt(0.5 * (1.0 - ax));
    double z2 = z * z;
    double p =
        z *
        (1.0 +
         z2 *
             (1.0 / 6 +
              z2 * (3.0 / 40 +
                    z2 * (15.0 / 336 +
                          z2 * (105.0 / 3456 +
                                z2 * (945.0 / 42240 +
                                      z2 * (10395.0 / 599040 +
                                            z2 * (135135.0 / 9676800 +
                                                  z2 * (2027025.0 / 175472640 +
                                                        z2 * (34459425.0 / 3530096640 +
                                                              z2 * (654729075.0 / 78033715200 +
                                                                    z2 * (13749310575.0 /
                                                                          1886805196800))))))))))));
    if (big) p = 1.5707963267948966 - 2.0 * p;
    return x < 0.0 ? -p : p;
}

#endif
