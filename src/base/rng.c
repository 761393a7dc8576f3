/* Normal samples for the hash-based random numbers of core.h (Box-Muller transform). */
#include <math.h>

#include "shitsukan/core.h"

static double box_muller(uint64_t h1, uint64_t h2)
{
    /* u1 in (0, 1] so log(u1) is finite; u2 in [0, 1). */
    double u1 = 1.0 - sk_u64_to_unit_d(h1);
    double u2 = sk_u64_to_unit_d(h2);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * SK_PI * u2);
}

double sk_rng_normal(sk_rng *r)
{
    uint64_t h1 = sk_rng_next_u64(r);
    uint64_t h2 = sk_rng_next_u64(r);
    return box_muller(h1, h2);
}

double sk_rand_normal(uint64_t seed, uint64_t a, uint64_t b, uint64_t c)
{
    sk_rng r = sk_rng_make(seed, a, b, c);
    return sk_rng_normal(&r);
}
