/* Small numeric helpers for the wood module's per-sample code: floor, hashing and the
 * elementary functions without library calls. At -O2 on x86-64 floor(), atan2(), sin(),
 * exp() are calls the compiler cannot schedule across; these inline versions use classic
 * range reductions and short Taylor series, with errors below 1e-9 (absolute, or
 * relative for exp), far under the single-precision data they feed. */
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

/* One 64-bit mix of a seed and three integer ids: leaner than sk_hash (which mixes every
 * id separately) for lookups made millions of times per image; distinct small ids give
 * independent-looking bits. */
static inline uint64_t sk__wood_hash(uint64_t seed, int64_t a, int64_t b, int64_t c)
{
    return sk_mix64(seed + (uint64_t)a * 0x9e3779b97f4a7c15ULL + (uint64_t)b * 0xc2b2ae3d27d4eb4fULL +
                    (uint64_t)c * 0x165667b19e3779f9ULL);
}

/* atan2(y, x) in (-pi, pi]: the ratio q in [0, 1] of the smaller to the larger magnitude
 * is moved next to the nearest of c = 0, 1/4, .., 1 by atan(q) = atan(c) +
 * atan((q - c) / (1 + q c)), leaving |u| <= 1/8 for the series (error < u^11 / 11). */
static inline double sk__atan2(double y, double x)
{
    static const double atan_c[5] = {0.0, 0.24497866312686414, 0.46364760900080612,
                                     0.64350110879328439, 0.78539816339744831};
    double ax = fabs(x), ay = fabs(y);
    int swap = ay > ax;
    double num = swap ? ax : ay, den = swap ? ay : ax;
    if (den == 0.0) return 0.0;
    double q = num / den;
    int k = (int)(q * 4.0 + 0.5);
    double c = 0.25 * k;
    double u = (q - c) / (1.0 + q * c), u2 = u * u;
    double a = atan_c[k] +
               u * (1.0 + u2 * (-1.0 / 3 + u2 * (1.0 / 5 + u2 * (-1.0 / 7 + u2 * (1.0 / 9)))));
    if (swap) a = 1.5707963267948966 - a;
    if (x < 0.0) a = 3.1415926535897931 - a;
    return y < 0.0 ? -a : a;
}

/* sin and cos of x (|x| < 1e6): x = k pi/2 + r with |r| <= pi/4 (pi/2 split in two parts
 * so r keeps its precision), then the Taylor series of sin r and cos r (to r^11, r^12). */
static inline void sk__sincos(double x, double *s, double *c)
{
    double kf = (double)sk__floor_i64(x * 0.63661977236758134 + 0.5);
    double r = (x - kf * 1.5707963267341256) - kf * 6.0771005065061922e-11;
    double r2 = r * r;
    double sr = r * (1.0 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800))))));
    double cr = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 + r2 * (1.0 / 479001600))))));
    switch ((int64_t)kf & 3) {
    case 0: *s = sr; *c = cr; break;
    case 1: *s = cr; *c = -sr; break;
    case 2: *s = -sr; *c = -cr; break;
    default: *s = -cr; *c = sr; break;
    }
}

/* asin(x) for |x| <= 1: the Taylor series on |x| <= 1/2 (to x^23, error < 2e-10), and
 * asin x = pi/2 - 2 asin(sqrt((1 - x) / 2)) beyond, which maps into that range. */
static inline double sk__asin(double x)
{
    double ax = fabs(x), z = ax;
    int big = ax > 0.5;
    if (big) z = sqrt(0.5 * (1.0 - ax));
    double z2 = z * z;
    double p = z * (1.0 + z2 * (1.0 / 6 + z2 * (3.0 / 40 + z2 * (15.0 / 336 + z2 * (105.0 / 3456 + z2 * (945.0 / 42240 + z2 * (10395.0 / 599040 + z2 * (135135.0 / 9676800 + z2 * (2027025.0 / 175472640 + z2 * (34459425.0 / 3530096640 + z2 * (654729075.0 / 78033715200 + z2 * (13749310575.0 / 1886805196800))))))))))));
    if (big) p = 1.5707963267948966 - 2.0 * p;
    return x < 0.0 ? -p : p;
}

/* exp(x) for x in [-700, 700] (clamped): x = k ln 2 + r with |r| <= ln(2) / 2, the series
 * of e^r to r^9, and 2^k put into the exponent bits. */
static inline double sk__exp(double x)
{
    x = x < -700.0 ? -700.0 : (x > 700.0 ? 700.0 : x);
    double kf = (double)sk__floor_i64(x * 1.4426950408889634 + 0.5);
    double r = (x - kf * 0.69314718036912382) - kf * 1.9082149292705877e-10;
    double e = 1.0 + r * (1.0 + r * (1.0 / 2 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720 + r * (1.0 / 5040 + r * (1.0 / 40320 + r * (1.0 / 362880)))))))));
    uint64_t bits = (uint64_t)((int64_t)kf + 1023) << 52;
    double scale;
    memcpy(&scale, &bits, sizeof scale);
    return e * scale;
}

/* log(x) for normal x > 0: x = m 2^e with m in [sqrt(1/2), sqrt(2)), then
 * log m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its series to s^13. */
static inline double sk__log(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    int64_t e = (int64_t)((bits >> 52) & 0x7ff) - 1023;
    bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
    double m;
    memcpy(&m, &bits, sizeof m);
    if (m > 1.4142135623730951) {
        m *= 0.5;
        e++;
    }
    double s = (m - 1.0) / (m + 1.0), s2 = s * s;
    double l = 2.0 * s * (1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 * (1.0 / 11 + s2 * (1.0 / 13)))))));
    return l + (double)e * 0.69314718055994531;
}

/* x^n for x > 0. */
static inline double sk__pow(double x, double n) { return sk__exp(n * sk__log(x)); }

#endif
