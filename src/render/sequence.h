/* The path integrator's low-discrepancy samples: the 2D Sobol sequence (dimensions 0 and
 * 1, a (0, 2)-sequence in base 2), Owen-scrambled and shuffled by hashing (Burley,
 * "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020, sec. 3-5), with the improved
 * Laine-Karras permutation of that paper's follow-up (Vegard's constants). Higher
 * dimensions are padded by independent 2D pairs: each pair gets its own index shuffle and
 * scrambles, keyed by (seed, pixel, pair), so every number is a pure function of
 * (seed, pixel, sample, dimension) and the image depends on neither threads nor tiles. */
#ifndef SK_RENDER_SEQUENCE_H
#define SK_RENDER_SEQUENCE_H

#include "shitsukan/core.h"

static inline uint32_t sk__reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

/* A hash whose output bit k depends only on input bits 0..k (Burley 2020, listing 3). */
static inline uint32_t sk__laine_karras(uint32_t x, uint32_t seed)
{
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

/* Owen's nested uniform scramble in base 2 (most significant digit first). */
static inline uint32_t sk__owen_scramble(uint32_t x, uint32_t seed)
{
    return sk__reverse_bits(sk__laine_karras(sk__reverse_bits(x), seed));
}

/* Sobol dimension 1 (direction numbers of the primitive polynomial x + 1). */
static inline uint32_t sk__sobol_dim1(uint32_t i)
{
    uint32_t r = 0;
    for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return r;
}

static inline float sk__unit_float(uint32_t x) { return (float)(x >> 8) * 0x1.0p-24f; }

/* Point `sample` of the scrambled 2D pair `pair` of a pixel: in [0, 1)^2. */
static inline sk_vec2f sk__sobol_pair(uint64_t seed, uint64_t pixel, uint32_t sample, uint32_t pair)
{
    uint64_t h = sk_hash(seed, pixel, pair, 0x50b01);
    uint64_t g = sk_mix64(h);
    uint32_t i = sk__owen_scramble(sample, (uint32_t)h);
    uint32_t x = sk__owen_scramble(sk__reverse_bits(i), (uint32_t)(h >> 32));
    uint32_t y = sk__owen_scramble(sk__sobol_dim1(i), (uint32_t)g);
    return sk_v2f(sk__unit_float(x), sk__unit_float(y));
}

#endif
