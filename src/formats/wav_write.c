/* WAV (RIFF WAVE, linear PCM) writer: 16-bit little-endian samples, interleaved
 * channels, written through an atomic file. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "shitsukan/io.h"

static void le16(uint8_t *p, unsigned v) { p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8); }
static void le32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16),
    p[3] = (uint8_t)(v >> 24);
}

int16_t sk_wav_sample_16(float v)
{
    if (!(v > -1.0f)) v = v == v ? -1.0f : 0.0f; /* NaN is silence */
    if (v > 1.0f) v = 1.0f;
    return (int16_t)lrintf(v * 32767.0f);
}

sk_result sk_wav_write(const char *path, const float *samples, size_t frames, int channels,
                       int sample_rate, sk_error *err)
{
    sk_result r;
    if ((r = sk_check_range_i(err, "channels", channels, 1, 8)) != SK_OK ||
        (r = sk_check_range_i(err, "sample_rate", sample_rate, 1000, 384000)) != SK_OK)
        return r;
    size_t count, bytes;
    if (!sk_size_mul(frames, (size_t)channels, &count) || !sk_size_mul(count, 2, &bytes) ||
        bytes > 0xffffffffu - 44)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "%zu sample frames of %d channels do not fit a WAV file (4 GiB)", frames,
                       channels);
    if (count > 0 && !samples) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no samples given");
    sk_atomic_file f;
    if ((r = sk_atomic_file_open(&f, path, err)) != SK_OK) return r;
    uint8_t h[44] = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'A', 'V', 'E', 'f', 'm', 't', ' '};
    le32(h + 4, (uint32_t)(36 + bytes));
    le32(h + 16, 16);
    le16(h + 20, 1); /* PCM */
    le16(h + 22, (unsigned)channels);
    le32(h + 24, (uint32_t)sample_rate);
    le32(h + 28, (uint32_t)sample_rate * (uint32_t)channels * 2);
    le16(h + 32, (unsigned)channels * 2);
    le16(h + 34, 16);
    h[36] = 'd', h[37] = 'a', h[38] = 't', h[39] = 'a';
    le32(h + 40, (uint32_t)bytes);
    fwrite(h, 1, sizeof h, f.fp);
    uint8_t buf[8192];
    size_t fill = 0;
    for (size_t i = 0; i < count; i++) {
        le16(buf + fill, (uint16_t)sk_wav_sample_16(samples[i]));
        fill += 2;
        if (fill == sizeof buf) {
            fwrite(buf, 1, fill, f.fp);
            fill = 0;
        }
    }
    if (fill) fwrite(buf, 1, fill, f.fp);
    return sk_atomic_file_commit(&f, err);
}
