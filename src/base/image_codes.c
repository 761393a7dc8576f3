/* Float samples to the integer codes of 8- and 16-bit image files, by the rule the PNG
 * writer uses (linear: round(v * max); sRGB: the nearest code of the sRGB curve; alpha
 * stays linear), for callers that encode files themselves (e.g. a browser's canvas). */
#include <math.h>

#include "base/image_internal.h"
#include "base/png_quantize.h"

static unsigned linear_code(double v, unsigned max_code)
{
    if (!(v > 0.0)) return 0; /* also NaN */
    if (v >= 1.0) return max_code;
    return (unsigned)floor(v * max_code + 0.5);
}

static bool is_alpha(int channel, int channels)
{
    return (channels == 2 && channel == 1) || (channels == 4 && channel == 3);
}

void sk_image_codes8(const float *samples, size_t pixels, int channels, sk_png_encoding encoding,
                     uint8_t *codes)
{
    /* the writer's own quantiser (its exact sRGB table), row by row of at most 2^20 pixels */
    sk__png_quantizer q;
    sk__png_quantizer_init(&q, channels, 8, encoding);
    const size_t row = (size_t)1 << 20;
    for (size_t done = 0; done < pixels; done += row) {
        size_t n = pixels - done < row ? pixels - done : row;
        sk__png_quantize_row(&q, samples + done * (size_t)channels, (int)n,
                             codes + done * (size_t)channels);
    }
}

void sk_image_codes16(const float *samples, size_t pixels, int channels, sk_png_encoding encoding,
                      uint16_t *codes)
{
    size_t n = pixels * (size_t)channels;
    for (size_t i = 0; i < n; i++) {
        float v = samples[i];
        int c = (int)(i % (size_t)channels);
        if (encoding == SK_PNG_ENCODING_LINEAR || is_alpha(c, channels) || !(v > 0.0f))
            codes[i] = (uint16_t)linear_code(v, 65535);
        else
            codes[i] = (uint16_t)linear_code(sk__srgb_encode(v >= 1.0f ? 1.0 : v), 65535);
    }
}
