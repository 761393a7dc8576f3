/* Float samples to PNG sample codes (private to the PNG writer and sk_image_codes8): linear
 * rounding, the sRGB curve for colour channels (alpha stays linear), 8 or 16 bits big-endian. */
#ifndef SK_IO_PNG_QUANTIZE_H
#define SK_IO_PNG_QUANTIZE_H

#include <stdint.h>
#include <string.h>

#include "shitsukan/image.h"

/* 8-bit sRGB codes by table: a float in [2^-20, 1) falls in one of these buckets by its
 * exponent and top 10 mantissa bits (relative width 2^-10); no bucket holds more than one
 * code boundary (boundaries are at least 0.9 % apart in relative terms), so the code is
 * the bucket's first code or the next, told by one comparison with the exact boundary. */
#define SK__SRGB8_BUCKET_SHIFT 13
#define SK__SRGB8_BUCKET_BASE 0x35800000u /* the float 2^-20, below the first boundary */
#define SK__SRGB8_BUCKETS ((0x3f800000u - SK__SRGB8_BUCKET_BASE) >> SK__SRGB8_BUCKET_SHIFT)

typedef struct sk__png_quantizer {
    int channels, bit_depth;
    sk_png_encoding encoding;
    /* code k + 1 starts at the float boundary[k]: the smallest float not below the exact
       linear value sRGB^-1((k + 0.5) / 255); boundary[255] = infinity */
    float boundary[256];
    uint8_t bucket[SK__SRGB8_BUCKETS]; /* the code at each bucket's smallest float */
} sk__png_quantizer;

/* Sets up the codes for images of `channels` channels (1-4). */
void sk__png_quantizer_init(sk__png_quantizer *q, int channels, int bit_depth,
                            sk_png_encoding encoding);

/* One row of `width` pixels into PNG sample bytes (width * channels * bit_depth / 8).
 * Values are clamped to [0, 1] (NaN to 0) and rounded to the nearest code: exactly
 * floor(v max + 1/2) in double for linear samples, and for sRGB samples the code whose
 * interval of the curve holds v (the same as rounding 255 sRGB(v) in double, or
 * floor(65535 sRGB(v) + 1/2) at 16 bits). */
void sk__png_quantize_row(const sk__png_quantizer *q, const float *src, int width, uint8_t *out);

/* The 8-bit sRGB code of one value (the table lookup the rows use). */
static inline unsigned sk__png_srgb8_code(const sk__png_quantizer *q, float v)
{
    if (!(v >= 0x1p-20f)) return 0; /* also NaN and negatives */
    if (v >= 1.0f) return 255;
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    unsigned code = q->bucket[(bits - SK__SRGB8_BUCKET_BASE) >> SK__SRGB8_BUCKET_SHIFT];
    return code + (v >= q->boundary[code]);
}

#endif
