/* Seeded gradient noise (Perlin 1985, with the quintic fade of Perlin 2002) in 2D and
 * 3D, its analytic gradient, periodic variants, and fractal Brownian motion.
 * Gradients come from a hash of (seed, lattice point), so no permutation table and any
 * seed is free. Output is scaled by the bound of gradient noise with unit gradients,
 * sqrt(N)/2, into [-1, 1]. */
#include <math.h>
#include <stdio.h>

#include "shitsukan/core.h"
#include "base/fbm_fields.h"

/* 64 unit vectors evenly spaced in angle (2D gradients). */
static const float k_grad2[64][2] = {
    {1.000000000f, 0.000000000f},   {0.995184727f, 0.098017140f},   {0.980785280f, 0.195090322f},
    {0.956940336f, 0.290284677f},   {0.923879533f, 0.382683432f},   {0.881921264f, 0.471396737f},
    {0.831469612f, 0.555570233f},   {0.773010453f, 0.634393284f},   {0.707106781f, 0.707106781f},
    {0.634393284f, 0.773010453f},   {0.555570233f, 0.831469612f},   {0.471396737f, 0.881921264f},
    {0.382683432f, 0.923879533f},   {0.290284677f, 0.956940336f},   {0.195090322f, 0.980785280f},
    {0.098017140f, 0.995184727f},   {0.000000000f, 1.000000000f},   {-0.098017140f, 0.995184727f},
    {-0.195090322f, 0.980785280f},  {-0.290284677f, 0.956940336f},  {-0.382683432f, 0.923879533f},
    {-0.471396737f, 0.881921264f},  {-0.555570233f, 0.831469612f},  {-0.634393284f, 0.773010453f},
    {-0.707106781f, 0.707106781f},  {-0.773010453f, 0.634393284f},  {-0.831469612f, 0.555570233f},
    {-0.881921264f, 0.471396737f},  {-0.923879533f, 0.382683432f},  {-0.956940336f, 0.290284677f},
    {-0.980785280f, 0.195090322f},  {-0.995184727f, 0.098017140f},  {-1.000000000f, 0.000000000f},
    {-0.995184727f, -0.098017140f}, {-0.980785280f, -0.195090322f}, {-0.956940336f, -0.290284677f},
    {-0.923879533f, -0.382683432f}, {-0.881921264f, -0.471396737f}, {-0.831469612f, -0.555570233f},
    {-0.773010453f, -0.634393284f}, {-0.707106781f, -0.707106781f}, {-0.634393284f, -0.773010453f},
    {-0.555570233f, -0.831469612f}, {-0.471396737f, -0.881921264f}, {-0.382683432f, -0.923879533f},
    {-0.290284677f, -0.956940336f}, {-0.195090322f, -0.980785280f}, {-0.098017140f, -0.995184727f},
    {0.000000000f, -1.000000000f},  {0.098017140f, -0.995184727f},  {0.195090322f, -0.980785280f},
    {0.290284677f, -0.956940336f},  {0.382683432f, -0.923879533f},  {0.471396737f, -0.881921264f},
    {0.555570233f, -0.831469612f},  {0.634393284f, -0.773010453f},  {0.707106781f, -0.707106781f},
    {0.773010453f, -0.634393284f},  {0.831469612f, -0.555570233f},  {0.881921264f, -0.471396737f},
    {0.923879533f, -0.382683432f},  {0.956940336f, -0.290284677f},  {0.980785280f, -0.195090322f},
    {0.995184727f, -0.098017140f},
};

/* The 12 cube-edge directions of Perlin 2002 (padded to 16), scaled to unit length. */
#define R2 0.70710678f
static const float k_grad3[16][3] = {
    {R2, R2, 0},  {-R2, R2, 0},  {R2, -R2, 0}, {-R2, -R2, 0}, {R2, 0, R2},  {-R2, 0, R2},
    {R2, 0, -R2}, {-R2, 0, -R2}, {0, R2, R2},  {0, -R2, R2},  {0, R2, -R2}, {0, -R2, -R2},
    {R2, R2, 0},  {-R2, R2, 0},  {0, -R2, R2}, {0, -R2, -R2},
};
#undef R2

#define NOISE2_SCALE 1.41421356f /* 2 / sqrt(2) */
#define NOISE3_SCALE 1.15470054f /* 2 / sqrt(3) */

static inline uint64_t seed_key(uint64_t seed) { return sk_mix64(seed ^ 0x5851f42d4c957f2dULL); }

static inline uint64_t corner_hash2(uint64_t key, int32_t x, int32_t y)
{
    return sk_mix64(key ^ ((uint64_t)(uint32_t)x * 0x9e3779b97f4a7c15ULL) ^
                    ((uint64_t)(uint32_t)y * 0xc2b2ae3d27d4eb4fULL));
}

static inline uint64_t corner_hash3(uint64_t key, int32_t x, int32_t y, int32_t z)
{
    return sk_mix64(key ^ ((uint64_t)(uint32_t)x * 0x9e3779b97f4a7c15ULL) ^
                    ((uint64_t)(uint32_t)y * 0xc2b2ae3d27d4eb4fULL) ^
                    ((uint64_t)(uint32_t)z * 0x165667b19e3779f9ULL));
}

static inline float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
static inline float fade_deriv(float t) { return 30.0f * t * t * (t * (t - 2.0f) + 1.0f); }

/* Core of 2D noise on lattice cell (ix, iy) .. (ix1, iy1) (ix1 = ix + 1 unless wrapped). */
static float noise2_cell(uint64_t key, int32_t ix, int32_t iy, int32_t ix1, int32_t iy1, float fx,
                         float fy, float *grad)
{
    const float *g00 = k_grad2[corner_hash2(key, ix, iy) >> 58];
    const float *g10 = k_grad2[corner_hash2(key, ix1, iy) >> 58];
    const float *g01 = k_grad2[corner_hash2(key, ix, iy1) >> 58];
    const float *g11 = k_grad2[corner_hash2(key, ix1, iy1) >> 58];
    float n00 = g00[0] * fx + g00[1] * fy;
    float n10 = g10[0] * (fx - 1.0f) + g10[1] * fy;
    float n01 = g01[0] * fx + g01[1] * (fy - 1.0f);
    float n11 = g11[0] * (fx - 1.0f) + g11[1] * (fy - 1.0f);
    float u = fade(fx), v = fade(fy);
    float k1 = n10 - n00, k2 = n01 - n00, k3 = n00 - n10 - n01 + n11;
    float n = n00 + u * k1 + v * k2 + u * v * k3;
    if (grad) {
        float du = fade_deriv(fx), dv = fade_deriv(fy);
        for (int a = 0; a < 2; a++) {
            float ga = g00[a] + u * (g10[a] - g00[a]) + v * (g01[a] - g00[a]) +
                       u * v * (g00[a] - g10[a] - g01[a] + g11[a]);
            grad[a] = NOISE2_SCALE * ga;
        }
        grad[0] += NOISE2_SCALE * du * (k1 + v * k3);
        grad[1] += NOISE2_SCALE * dv * (k2 + u * k3);
    }
    return NOISE2_SCALE * n;
}

float sk_noise2_grad(uint64_t seed, float x, float y, float grad[2])
{
    float flx = floorf(x), fly = floorf(y);
    int32_t ix = (int32_t)flx, iy = (int32_t)fly;
    return noise2_cell(seed_key(seed), ix, iy, ix + 1, iy + 1, x - flx, y - fly, grad);
}

float sk_noise2(uint64_t seed, float x, float y) { return sk_noise2_grad(seed, x, y, NULL); }

float sk_noise2_periodic(uint64_t seed, float x, float y, int period_x, int period_y)
{
    if (period_x < 1) period_x = 1;
    if (period_y < 1) period_y = 1;
    float flx = floorf(x), fly = floorf(y);
    int32_t ix = sk_imodpos((int)flx % period_x, period_x);
    int32_t iy = sk_imodpos((int)fly % period_y, period_y);
    int32_t ix1 = ix + 1 == period_x ? 0 : ix + 1;
    int32_t iy1 = iy + 1 == period_y ? 0 : iy + 1;
    return noise2_cell(seed_key(seed), ix, iy, ix1, iy1, x - flx, y - fly, NULL);
}

float sk_noise3_grad(uint64_t seed, float x, float y, float z, float grad[3])
{
    float flx = floorf(x), fly = floorf(y), flz = floorf(z);
    int32_t ix = (int32_t)flx, iy = (int32_t)fly, iz = (int32_t)flz;
    float f[3] = {x - flx, y - fly, z - flz};
    uint64_t key = seed_key(seed);
    const float *g[8];
    float n[8];
    for (int c = 0; c < 8; c++) {
        int cx = c & 1, cy = (c >> 1) & 1, cz = (c >> 2) & 1;
        g[c] = k_grad3[corner_hash3(key, ix + cx, iy + cy, iz + cz) >> 60];
        n[c] = g[c][0] * (f[0] - (float)cx) + g[c][1] * (f[1] - (float)cy) +
               g[c][2] * (f[2] - (float)cz);
    }
    float w[3] = {fade(f[0]), fade(f[1]), fade(f[2])};
    /* trilinear blend of the corner values with weights w */
    float result = 0.0f;
    float dw[3] = {0, 0, 0}, gsum[3] = {0, 0, 0};
    for (int c = 0; c < 8; c++) {
        int b[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
        float wt[3];
        for (int a = 0; a < 3; a++) wt[a] = b[a] ? w[a] : 1.0f - w[a];
        float weight = wt[0] * wt[1] * wt[2];
        result += weight * n[c];
        if (grad) {
            for (int a = 0; a < 3; a++) {
                gsum[a] += weight * g[c][a];
                /* d weight / d w_a, times corner value */
                float others = 1.0f;
                for (int o = 0; o < 3; o++)
                    if (o != a) others *= wt[o];
                dw[a] += (b[a] ? 1.0f : -1.0f) * others * n[c];
            }
        }
    }
    if (grad)
        for (int a = 0; a < 3; a++) grad[a] = NOISE3_SCALE * (gsum[a] + dw[a] * fade_deriv(f[a]));
    return NOISE3_SCALE * result;
}

float sk_noise3(uint64_t seed, float x, float y, float z)
{
    return sk_noise3_grad(seed, x, y, z, NULL);
}

/* ------------------------------------------------------------------ fBm */

static const sk_schema_field fbm_fields[] = {
    SK__FBM_FIELDS(sk_fbm_desc, octaves, lacunarity, gain),
};
const sk_schema sk__fbm_schema = SK_SCHEMA_OF("fbm", sk_fbm_desc, fbm_fields);

sk_fbm_desc sk_fbm_desc_resolved(const sk_fbm_desc *desc)
{
    sk_fbm_desc d = {0};
    if (desc) d = *desc;
    sk_schema_apply_defaults(&sk__fbm_schema, &d);
    return d;
}

sk_result sk_fbm_desc_validate(const sk_fbm_desc *desc, const char *name, sk_error *err)
{
    return sk_schema_check(&sk__fbm_schema, desc, name, err);
}

/* The fBm parameters of one sample: zeros at the schema's defaults, clamped to its ranges
   (read from the fields directly: this runs per sample, sk_fbm_desc_resolved per desc). */
static inline void fbm_params(const sk_fbm_desc *desc, int *octaves, float *lac, float *gain)
{
    const sk_schema_field *fo = &fbm_fields[0], *fl = &fbm_fields[1], *fg = &fbm_fields[2];
    int o = desc && desc->octaves ? desc->octaves : (int)fo->def;
    float l = desc && desc->lacunarity != 0.0f ? desc->lacunarity : (float)fl->def;
    float g = desc && desc->gain != 0.0f ? desc->gain : (float)fg->def;
    *octaves = o < (int)fo->min ? (int)fo->min : (o > (int)fo->max ? (int)fo->max : o);
    *lac = sk_clampf(l, (float)fl->min, (float)fl->max);
    *gain = sk_clampf(g, (float)fg->min, (float)fg->max);
}

/* Per-octave seed and offset, so octaves are independent and not all zero at the origin. */
static inline uint64_t octave_seed(uint64_t seed, int k)
{
    return sk_hash(seed, 0xfb3, (uint64_t)k, 0);
}
static inline float octave_offset(uint64_t seed, int k, int axis)
{
    return 1000.0f * (float)sk_rand_uniform(seed, 0xfb4, (uint64_t)k, (uint64_t)axis);
}

float sk_fbm2(uint64_t seed, float x, float y, const sk_fbm_desc *desc)
{
    int octaves;
    float lac, gain;
    fbm_params(desc, &octaves, &lac, &gain);
    float sum = 0.0f, amp = 1.0f, norm = 0.0f, freq = 1.0f;
    for (int k = 0; k < octaves; k++) {
        sum += amp * sk_noise2(octave_seed(seed, k), x * freq + octave_offset(seed, k, 0),
                               y * freq + octave_offset(seed, k, 1));
        norm += amp;
        amp *= gain;
        freq *= lac;
    }
    return sum / norm;
}

float sk_fbm3(uint64_t seed, float x, float y, float z, const sk_fbm_desc *desc)
{
    int octaves;
    float lac, gain;
    fbm_params(desc, &octaves, &lac, &gain);
    float sum = 0.0f, amp = 1.0f, norm = 0.0f, freq = 1.0f;
    for (int k = 0; k < octaves; k++) {
        sum += amp * sk_noise3(octave_seed(seed, k), x * freq + octave_offset(seed, k, 0),
                               y * freq + octave_offset(seed, k, 1),
                               z * freq + octave_offset(seed, k, 2));
        norm += amp;
        amp *= gain;
        freq *= lac;
    }
    return sum / norm;
}

float sk_fbm2_periodic(uint64_t seed, float x, float y, int period_x, int period_y,
                       const sk_fbm_desc *desc)
{
    int octaves;
    float lac, gain;
    fbm_params(desc, &octaves, &lac, &gain);
    if (period_x < 1) period_x = 1;
    if (period_y < 1) period_y = 1;
    float sum = 0.0f, amp = 1.0f, norm = 0.0f, scale = 1.0f;
    for (int k = 0; k < octaves; k++) {
        /* integer periods per octave; frequency chosen so the octave tiles exactly */
        int px = (int)lroundf((float)period_x * scale), py = (int)lroundf((float)period_y * scale);
        if (px < 1) px = 1;
        if (py < 1) py = 1;
        float fx = (float)px / (float)period_x, fy = (float)py / (float)period_y;
        /* any offset keeps the period (the lattice wraps in its own coordinates); a
           fractional one keeps the octaves' zero points apart, so no grid shows */
        float ox = octave_offset(seed, k, 0), oy = octave_offset(seed, k, 1);
        sum += amp * sk_noise2_periodic(octave_seed(seed, k), x * fx + ox, y * fy + oy, px, py);
        norm += amp;
        amp *= gain;
        scale *= lac;
    }
    return sum / norm;
}
