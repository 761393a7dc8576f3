/* Deterministic stratified sampling: every sample is a function of (seed, pixel, use,
 * index), never of a sequential generator, so images do not depend on thread count or
 * tile order. 2D patterns are multi-jittered (Chiu, Shirley, Wang 1994): jittered in an
 * m x n grid and N-rooks in each axis, with the sub-strata permuted by a keyed bijection. */
#ifndef SK_RENDER_SAMPLING_H
#define SK_RENDER_SAMPLING_H

#include <math.h>

#include "shitsukan/core.h"

/* What a 2D pattern is used for; distinct uses get independent patterns. */
enum {
    SK__SAMPLE_PIXEL = 0, /* position in the pixel */
    SK__SAMPLE_AO = 1,    /* occlusion ray directions */
    SK__SAMPLE_LIGHT = 2  /* + light index: points on area lights */
};

/* A bijection of [0, 2^bits) keyed by `key`: each step (xor, odd multiply, xorshift) is
 * invertible modulo 2^bits. */
static inline uint32_t sk__scramble(uint32_t x, uint32_t mask, uint64_t key)
{
    uint32_t k0 = (uint32_t)key, k1 = (uint32_t)(key >> 32);
    x ^= k0 & mask;
    x = (x * 0x9e3779b1u) & mask;
    x ^= (x & mask) >> 3;
    x = (x * (k1 | 1u)) & mask;
    x ^= x >> 5;
    x = (x + (k1 >> 7)) & mask;
    x = (x * 0x2c1b3c6du) & mask;
    x ^= x >> 4;
    return x;
}

/* Element i of a keyed random permutation of [0, n), by cycle walking the bijection of the
 * enclosing power of two (fewer than two steps on average). */
static inline uint32_t sk__permute(uint32_t i, uint32_t n, uint64_t key)
{
    if (n <= 1) return 0;
    uint32_t mask = n - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do {
        i = sk__scramble(i, mask, key);
    } while (i >= n);
    return i;
}

/* Key of the pattern for one pixel and use. */
static inline uint64_t sk__pattern_key(uint64_t seed, uint64_t pixel, uint32_t use)
{
    return sk_hash(seed, pixel, use, 0x5a3c1e);
}

/* Point i of a multi-jittered pattern of n points in [0, 1)^2. The order of the points is
 * itself permuted per key, so patterns of two uses do not correlate sample by sample. */
static inline sk_vec2f sk__pattern_2d(uint64_t key, uint32_t i, uint32_t n)
{
    uint32_t m = (uint32_t)ceil(sqrt((double)n)); /* columns */
    uint32_t rows = (n + m - 1) / m;
    uint32_t j = sk__permute(i, n, key ^ 0x243f6a8885a308d3ULL);
    uint32_t c = j % m, r = j / m;
    /* sub-column of cell (c, r) within column c, and sub-row within row r */
    uint32_t sx = sk__permute(r, rows, sk_mix64(key + 0x13198a2e03707344ULL + c));
    uint32_t sy = sk__permute(c, m, sk_mix64(key + 0xa4093822299f31d0ULL + r));
    uint64_t h = sk_hash(key, j, 0x82efa98e, 0);
    float jx = (float)(h >> 40) * 0x1.0p-24f;
    float jy = (float)((h >> 16) & 0xffffffu) * 0x1.0p-24f;
    sk_vec2f p;
    p.x = ((float)c + ((float)sx + jx) / (float)rows) / (float)m;
    p.y = ((float)r + ((float)sy + jy) / (float)m) / (float)rows;
    /* rounding can reach 1.0 in float; keep the half-open interval */
    if (p.x >= 1.0f) p.x = 0x1.fffffep-1f;
    if (p.y >= 1.0f) p.y = 0x1.fffffep-1f;
    return p;
}

/* Uniform square -> unit disk, area preserving and low distortion (Shirley and Chiu 1997,
 * concentric mapping). */
static inline sk_vec2f sk__square_to_disk(sk_vec2f u)
{
    float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return sk_v2f(0.0f, 0.0f);
    float r, phi;
    if (fabsf(a) > fabsf(b)) {
        r = a;
        phi = (SK_PI_F / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (SK_PI_F / 2.0f) - (SK_PI_F / 4.0f) * (a / b);
    }
    return sk_v2f(r * cosf(phi), r * sinf(phi));
}

/* Cosine-weighted direction about the unit normal n (Malley's method: lift the disk). */
static inline sk_vec3f sk__cosine_hemisphere(sk_vec3f n, sk_vec2f u)
{
    sk_vec2f d = sk__square_to_disk(u);
    float z = sqrtf(fmaxf(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    sk_vec3f t, b;
    sk_v3f_basis(n, &t, &b);
    return sk_v3f_add(sk_v3f_add(sk_v3f_scale(t, d.x), sk_v3f_scale(b, d.y)), sk_v3f_scale(n, z));
}

#endif
