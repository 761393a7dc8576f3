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

/* A multi-jittered pattern of n points in [0, 1)^2 for one pixel and use: n = m x rows
 * cells (m = ceil(sqrt(n)) columns; when n < m x rows the last row is partly empty). */
typedef struct sk__pattern {
    uint64_t key;
    uint32_t n, m, rows;
    float inv_m, inv_rows;
} sk__pattern;

static inline sk__pattern sk__pattern_make(uint64_t seed, uint64_t pixel, uint32_t use, uint32_t n)
{
    sk__pattern p;
    p.key = sk_hash(seed, pixel, use, 0x5a3c1e);
    p.n = n;
    p.m = (uint32_t)ceil(sqrt((double)n));
    p.rows = (n + p.m - 1) / p.m;
    p.inv_m = 1.0f / (float)p.m;
    p.inv_rows = 1.0f / (float)p.rows;
    return p;
}

/* Point i of the pattern. The order of the points is itself permuted per key, so patterns
 * of two uses do not correlate sample by sample. */
static inline sk_vec2f sk__pattern_point(const sk__pattern *p, uint32_t i)
{
    uint64_t key = p->key;
    uint32_t j = sk__permute(i, p->n, key ^ 0x243f6a8885a308d3ULL);
    uint32_t c = j % p->m, r = j / p->m;
    /* sub-column of cell (c, r) within column c, and sub-row within row r */
    uint32_t sx = sk__permute(r, p->rows, sk_mix64(key + 0x13198a2e03707344ULL + c));
    uint32_t sy = sk__permute(c, p->m, sk_mix64(key + 0xa4093822299f31d0ULL + r));
    uint64_t h = sk_mix64(key ^ (0x82efa98ec4e6c89bULL * (j + 1)));
    float jx = (float)(h >> 40) * 0x1.0p-24f;
    float jy = (float)((h >> 16) & 0xffffffu) * 0x1.0p-24f;
    sk_vec2f q;
    q.x = ((float)c + ((float)sx + jx) * p->inv_rows) * p->inv_m;
    q.y = ((float)r + ((float)sy + jy) * p->inv_m) * p->inv_rows;
    /* rounding can reach 1.0 in float; keep the half-open interval */
    if (q.x >= 1.0f) q.x = 0x1.fffffep-1f;
    if (q.y >= 1.0f) q.y = 0x1.fffffep-1f;
    return q;
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
