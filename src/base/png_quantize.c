/* Float samples to PNG sample codes: linear rounding, and the sRGB curve of IEC 61966-2-1
 * through an exact table (the code boundaries straight from the curve in double, so the
 * table gives the codes that rounding 255 sRGB(v) gives, without a power per sample). */
#include "base/png_quantize.h"

#include <math.h>

#include "base/image_internal.h"

void sk__png_quantizer_init(sk__png_quantizer *q, int channels, int bit_depth,
                            sk_png_encoding encoding)
{
    q->channels = channels;
    q->bit_depth = bit_depth;
    q->encoding = encoding;
    if (encoding != SK_PNG_ENCODING_SRGB || bit_depth != 8) return;
    for (int k = 0; k < 255; k++) {
        double exact = sk__srgb_decode((k + 0.5) / 255.0);
        float f = (float)exact;
        if ((double)f < exact) f = nextafterf(f, INFINITY);
        q->boundary[k] = f;
    }
    q->boundary[255] = INFINITY;
    /* boundaries and bucket starts both ascend: one sweep */
    unsigned code = 0;
    for (uint32_t b = 0; b < SK__SRGB8_BUCKETS; b++) {
        uint32_t bits = SK__SRGB8_BUCKET_BASE + (b << SK__SRGB8_BUCKET_SHIFT);
        float start;
        memcpy(&start, &bits, sizeof start);
        while (code < 255 && start >= q->boundary[code]) code++;
        q->bucket[b] = (uint8_t)code;
    }
}

static inline unsigned linear_code(float v, double max_code)
{
    if (!(v > 0.0f)) return 0; /* also NaN */
    if (v >= 1.0f) return (unsigned)max_code;
    return (unsigned)((double)v * max_code + 0.5); /* floor: the sum is positive */
}

static inline unsigned srgb16_code(float v)
{
    if (!(v > 0.0f)) return 0;
    return (unsigned)(sk__srgb_encode(v >= 1.0f ? 1.0 : (double)v) * 65535.0 + 0.5);
}

void sk__png_quantize_row(const sk__png_quantizer *q, const float *src, int width, uint8_t *out)
{
    int channels = q->channels;
    /* grey + alpha and RGBA carry a linear alpha last */
    int colour = (channels == 2 || channels == 4) ? channels - 1 : channels;
    bool srgb = q->encoding == SK_PNG_ENCODING_SRGB;
    if (q->bit_depth == 8) {
        for (int x = 0; x < width; x++, src += channels, out += channels) {
            for (int c = 0; c < colour; c++)
                out[c] =
                    (uint8_t)(srgb ? sk__png_srgb8_code(q, src[c]) : linear_code(src[c], 255.0));
            if (colour < channels) out[colour] = (uint8_t)linear_code(src[colour], 255.0);
        }
        return;
    }
    for (int x = 0; x < width; x++, src += channels) {
        for (int c = 0; c < channels; c++, out += 2) {
            unsigned code = srgb && c < colour ? srgb16_code(src[c]) : linear_code(src[c], 65535.0);
            out[0] = (uint8_t)(code >> 8); /* PNG samples are big-endian */
            out[1] = (uint8_t)(code & 0xff);
        }
    }
}
