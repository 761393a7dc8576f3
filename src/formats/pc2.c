/* PC2 point caches (include/shitsukan/pointcache.h): a streaming, atomic writer and a
 * strict reader. Little-endian on every host. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/pointcache.h"

static const char k_signature[12] = "POINTCACHE2";

static void put_u32(uint8_t *p, uint32_t v)
{
    for (int i = 0; i < 4; i++) p[i] = (uint8_t)(v >> (8 * i));
}
static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static void put_f32(uint8_t *p, float f)
{
    uint32_t v;
    memcpy(&v, &f, 4);
    put_u32(p, v);
}
static float get_f32(const uint8_t *p)
{
    uint32_t v = get_u32(p);
    float f;
    memcpy(&f, &v, 4);
    return f;
}

sk_result sk_pc2_open(sk_pc2_writer *w, const char *path, int points, float start_frame,
                      float sample_rate, int samples, sk_error *err)
{
    memset(w, 0, sizeof *w);
    if (points < 1 || samples < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "a point cache needs points (%d) and samples (%d)", points, samples);
    if (!isfinite(start_frame) || !(sample_rate > 0.0f) || !isfinite(sample_rate))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "start frame %g and sample rate %g must be finite, the rate > 0",
                       start_frame, sample_rate);
    sk_result r = sk_atomic_file_open(&w->file, path, err);
    if (r != SK_OK) return r;
    uint8_t h[SK_PC2_HEADER_BYTES];
    memcpy(h, k_signature, 12);
    put_u32(h + 12, 1);
    put_u32(h + 16, (uint32_t)points);
    put_f32(h + 20, start_frame);
    put_f32(h + 24, sample_rate);
    put_u32(h + 28, (uint32_t)samples);
    if (fwrite(h, 1, sizeof h, w->file.fp) != sizeof h)
        return sk_atomic_file_write_failed(&w->file, err);
    w->points = points;
    w->samples = samples;
    return SK_OK;
}

sk_result sk_pc2_append(sk_pc2_writer *w, const float *xyz, sk_error *err)
{
    if (!w->file.fp) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "point cache is not open");
    if (w->written >= w->samples)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "point cache already has its %d samples",
                       w->samples);
    uint8_t buf[4096 * 12];
    size_t n = (size_t)w->points * 3;
    for (size_t i = 0; i < n;) {
        size_t chunk = n - i < sizeof buf / 4 ? n - i : sizeof buf / 4;
        for (size_t k = 0; k < chunk; k++) {
            if (!isfinite(xyz[i + k]))
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sample %d, point %zu is not finite",
                               w->written, (i + k) / 3);
            put_f32(buf + 4 * k, xyz[i + k]);
        }
        if (fwrite(buf, 4, chunk, w->file.fp) != chunk)
            return sk_atomic_file_write_failed(&w->file, err);
        i += chunk;
    }
    w->written++;
    return SK_OK;
}

sk_result sk_pc2_close(sk_pc2_writer *w, sk_error *err)
{
    if (w->written != w->samples) {
        int written = w->written, samples = w->samples;
        sk_pc2_abort(w);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "point cache closed after %d of its %d samples", written, samples);
    }
    return sk_atomic_file_commit(&w->file, err);
}

void sk_pc2_abort(sk_pc2_writer *w) { sk_atomic_file_abort(&w->file); }

sk_result sk_pc2_parse(const void *data, size_t size, const char *source_name, sk_pc2 *out,
                       sk_error *err)
{
    memset(out, 0, sizeof *out);
    const uint8_t *p = data;
    const char *name = source_name ? source_name : "PC2";
    if (!p || size < SK_PC2_HEADER_BYTES)
        return sk_fail(err, SK_ERROR_PARSE, "%s: %zu bytes is shorter than a PC2 header (32)", name,
                       size);
    if (memcmp(p, k_signature, 12) != 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s: no \"POINTCACHE2\" signature", name);
    uint32_t version = get_u32(p + 12), points = get_u32(p + 16), samples = get_u32(p + 28);
    float start = get_f32(p + 20), rate = get_f32(p + 24);
    if (version != 1)
        return sk_fail(err, SK_ERROR_PARSE, "%s: version %u (only 1 is defined)", name, version);
    if (!isfinite(start) || !isfinite(rate))
        return sk_fail(err, SK_ERROR_PARSE, "%s: start frame or sample rate is not finite", name);
    if (points == 0 || points > INT32_MAX || samples > INT32_MAX)
        return sk_fail(err, SK_ERROR_PARSE, "%s: %u points, %u samples is not a point cache", name,
                       points, samples);
    /* the counts must fit the bytes that follow: checked before anything is allocated */
    size_t body = size - SK_PC2_HEADER_BYTES, values;
    if (!sk_size_mul((size_t)points * 3, (size_t)samples, &values) || values > body / 4)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s: truncated: %u samples of %u points need %.0f bytes, the file has %zu",
                       name, samples, points, 12.0 * points * (double)samples, body);
    if (values * 4 != body)
        return sk_fail(err, SK_ERROR_PARSE, "%s: %zu bytes after the last sample", name,
                       body - values * 4);
    out->xyz = malloc((values ? values : 1) * sizeof *out->xyz);
    if (!out->xyz) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: out of memory", name);
    for (size_t i = 0; i < values; i++) {
        out->xyz[i] = get_f32(p + SK_PC2_HEADER_BYTES + 4 * i);
        if (!isfinite(out->xyz[i])) {
            sk_pc2_free(out);
            return sk_fail(err, SK_ERROR_PARSE, "%s: value %zu (sample %zu) is not finite", name, i,
                           i / (3 * (size_t)points));
        }
    }
    out->points = (int)points;
    out->samples = (int)samples;
    out->start_frame = start;
    out->sample_rate = rate;
    return SK_OK;
}

sk_result sk_pc2_read(const char *path, size_t max_bytes, sk_pc2 *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    char *data = NULL;
    size_t size = 0;
    sk_result r = sk_read_file(path, max_bytes ? max_bytes : ((size_t)1 << 30), &data, &size, err);
    if (r != SK_OK) return r;
    r = sk_pc2_parse(data, size, path, out, err);
    free(data);
    return r;
}

void sk_pc2_free(sk_pc2 *pc2)
{
    if (!pc2) return;
    free(pc2->xyz);
    memset(pc2, 0, sizeof *pc2);
}
