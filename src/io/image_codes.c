/* Float samples to the integer codes of 8- and 16-bit image files, by the rule the PNG
 * writer uses (linear: round(v * max); sRGB: the nearest code of the sRGB curve; alpha
 * stays linear), for callers that encode files themselves (e.g. a browser's canvas). */
#include <math.h>

#include "io/image_internal.h"

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
    /* code k + 1 starts at linear value threshold[k], straight from the curve in double,
       so a binary search gives the code nearest to 255 * srgb(v) */
    double threshold[255];
    bool srgb = encoding != SK_PNG_ENCODING_LINEAR;
    if (srgb)
        for (int k = 0; k < 255; k++) threshold[k] = sk__srgb_decode((k + 0.5) / 255.0);
    size_t n = pixels * (size_t)channels;
    for (size_t i = 0; i < n; i++) {
        float v = samples[i];
        int c = (int)(i % (size_t)channels);
        if (!srgb || is_alpha(c, channels)) {
            codes[i] = (uint8_t)linear_code(v, 255);
            continue;
        }
        if (!(v > 0.0f)) {
            codes[i] = 0;
            continue;
        }
        unsigned lo = 0, hi = 255;
        while (lo < hi) {
            unsigned mid = (lo + hi + 1) / 2;
            if ((double)v >= threshold[mid - 1]) lo = mid;
            else hi = mid - 1;
        }
        codes[i] = (uint8_t)lo;
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
