/* Standard MIDI File framing (MIDI 1.0 Detailed Specification, Standard MIDI Files 1.0):
 * the MThd header, MTrk chunks, variable-length quantities, running status, meta and
 * system exclusive events, each checked against the bytes that are really there so an
 * error names the byte offset. The notes and tempo changes are written again as a plain
 * file for libsmf (sk__midi_plain, showcase_internal.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

typedef struct byte_buffer {
    uint8_t *data;
    size_t size, cap;
    bool failed;
} byte_buffer;

static void put(byte_buffer *b, const uint8_t *bytes, size_t n)
{
    if (b->failed) return;
    if (b->size + n > b->cap) {
        size_t cap = b->cap ? b->cap : 256;
        while (cap < b->size + n) cap *= 2;
        uint8_t *p = realloc(b->data, cap);
        if (!p) {
            b->failed = true;
            return;
        }
        b->data = p, b->cap = cap;
    }
    memcpy(b->data + b->size, bytes, n);
    b->size += n;
}

static void put_u32(byte_buffer *b, uint32_t v)
{
    uint8_t x[4] = {(uint8_t)(v >> 24), (uint8_t)(v >> 16), (uint8_t)(v >> 8), (uint8_t)v};
    put(b, x, 4);
}

static void put_vlq(byte_buffer *b, uint32_t v)
{
    uint8_t x[4];
    int n = 0;
    x[3] = (uint8_t)(v & 0x7f);
    n = 1;
    while ((v >>= 7) != 0 && n < 4) {
        x[3 - n] = (uint8_t)(0x80 | (v & 0x7f));
        n++;
    }
    put(b, x + 4 - n, (size_t)n);
}

static uint32_t be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}
static unsigned be16(const uint8_t *p) { return (unsigned)p[0] << 8 | p[1]; }

typedef struct framer {
    const uint8_t *data;
    size_t length;
    const char *name;
    sk_error *err;
} framer;

static sk_result fail_at(const framer *f, size_t offset, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static sk_result fail_at(const framer *f, size_t offset, const char *fmt, ...)
{
    char detail[384];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    return sk_fail(f->err, SK_ERROR_PARSE, "%s: byte %zu: %s", f->name, offset, detail);
}

/* A variable-length quantity at p (at most 4 bytes) within [p, end). */
static sk_result read_vlq(const framer *f, size_t *p, size_t end, uint32_t *value)
{
    uint32_t v = 0;
    size_t start = *p;
    for (int n = 0; n < 4; n++) {
        if (*p >= end)
            return fail_at(f, start, "a variable-length number runs past the end of its track");
        uint8_t c = f->data[(*p)++];
        v = (v << 7) | (c & 0x7f);
        if (!(c & 0x80)) {
            *value = v;
            return SK_OK;
        }
    }
    return fail_at(f, start, "a variable-length number longer than 4 bytes");
}

/* One track chunk's events [p, end): checked, and its notes, tempi and end written to
 * `out`; offsets[k] gets the source offset of plain event k. */
static sk_result frame_track(const framer *f, size_t p, size_t end, int track, byte_buffer *out,
                             long **offsets, int *count)
{
    size_t cap = 64;
    long *off = malloc(cap * sizeof *off);
    if (!off) return sk_fail(f->err, SK_ERROR_OUT_OF_MEMORY, "out of memory reading a track");
    int n = 0;
    uint8_t running = 0;
    uint64_t ticks = 0, pending = 0; /* absolute ticks; delta carried over dropped events */
    bool ended = false;
    sk_result r = SK_OK;
    while (p < end && r == SK_OK) {
        uint32_t delta;
        size_t event_start = p;
        if ((r = read_vlq(f, &p, end, &delta)) != SK_OK) break;
        ticks += delta;
        pending += delta;
        if (ticks > 0x7fffffffu) {
            r = fail_at(f, event_start, "track %d runs past 2^31 ticks", track);
            break;
        }
        if (p >= end) {
            r = fail_at(f, event_start, "an event's time without the event (track %d ends)", track);
            break;
        }
        size_t at = p;
        uint8_t status = f->data[p];
        bool keep = false;
        uint8_t plain[6];
        size_t plain_n = 0;
        if (status == 0xff) { /* meta event: FF type length data */
            if (p + 2 > end) {
                r = fail_at(f, at, "a meta event cut off by the end of track %d", track);
                break;
            }
            uint8_t type = f->data[p + 1];
            p += 2;
            uint32_t len;
            if ((r = read_vlq(f, &p, end, &len)) != SK_OK) break;
            if (len > end - p) {
                r = fail_at(f, at, "meta event 0x%02x claims %u bytes, its track has %zu left",
                            type, len, end - p);
                break;
            }
            if (type == 0x2f) {
                if (len != 0) {
                    r = fail_at(f, at, "end-of-track event with length %u (must be 0)", len);
                    break;
                }
                plain[0] = 0xff, plain[1] = 0x2f, plain[2] = 0, plain_n = 3, keep = true;
                ended = true;
            } else if (type == 0x51) {
                if (len != 3) {
                    r = fail_at(f, at, "tempo event with length %u (must be 3)", len);
                    break;
                }
                const uint8_t *t = f->data + p;
                if (t[0] == 0 && t[1] == 0 && t[2] == 0) {
                    r = fail_at(f, at, "tempo of 0 microseconds per quarter note");
                    break;
                }
                plain[0] = 0xff, plain[1] = 0x51, plain[2] = 3, plain[3] = t[0], plain[4] = t[1],
                plain[5] = t[2];
                plain_n = 6, keep = true;
            }
            p += len;
            running = 0; /* running status does not survive a meta event */
        } else if (status == 0xf0 || status == 0xf7) { /* system exclusive: F0/F7 length data */
            p++;
            uint32_t len;
            if ((r = read_vlq(f, &p, end, &len)) != SK_OK) break;
            if (len > end - p) {
                r = fail_at(f, at, "system exclusive event claims %u bytes, its track has %zu left",
                            len, end - p);
                break;
            }
            p += len;
            running = 0;
        } else {
            if (status & 0x80) {
                if (status >= 0xf0) {
                    r = fail_at(
                        f, at,
                        "status byte 0x%02x is not allowed in a MIDI file (only channel messages, "
                        "0xF0/0xF7 system exclusive and 0xFF meta events)",
                        status);
                    break;
                }
                running = status;
                p++;
            } else if (!running) {
                r = fail_at(f, at,
                            "data byte 0x%02x without a status byte (no running status here)",
                            status);
                break;
            }
            uint8_t kind = running & 0xf0;
            int data_bytes = (kind == 0xc0 || kind == 0xd0) ? 1 : 2;
            if (p + (size_t)data_bytes > end) {
                r = fail_at(f, at, "a channel message cut off by the end of track %d", track);
                break;
            }
            for (int k = 0; k < data_bytes; k++)
                if (f->data[p + (size_t)k] & 0x80) {
                    r = fail_at(f, p + (size_t)k, "data byte 0x%02x has its top bit set",
                                f->data[p + (size_t)k]);
                    break;
                }
            if (r != SK_OK) break;
            if (kind == 0x80 || kind == 0x90) {
                plain[0] = running, plain[1] = f->data[p], plain[2] = f->data[p + 1], plain_n = 3,
                keep = true;
            }
            p += (size_t)data_bytes;
        }
        if (r != SK_OK) break;
        if (keep) {
            put_vlq(out, (uint32_t)pending);
            put(out, plain, plain_n);
            pending = 0;
            if ((size_t)n == cap) {
                long *q = realloc(off, 2 * cap * sizeof *off);
                if (!q) {
                    r = sk_fail(f->err, SK_ERROR_OUT_OF_MEMORY, "out of memory reading a track");
                    break;
                }
                off = q, cap *= 2;
            }
            off[n++] = (long)at;
        }
        if (ended) break;
    }
    if (r == SK_OK && !ended)
        r = fail_at(f, end, "track %d has no end-of-track event (FF 2F 00)", track);
    if (r == SK_OK && p != end)
        r = fail_at(f, p, "%zu bytes after the end-of-track event of track %d", end - p, track);
    if (r != SK_OK) {
        free(off);
        return r;
    }
    *offsets = off;
    *count = n;
    return SK_OK;
}

void sk__midi_plain_free(sk__midi_plain *plain)
{
    if (!plain) return;
    for (int t = 0; t < plain->track_count; t++)
        if (plain->offset) free(plain->offset[t]);
    free(plain->offset);
    free(plain->event_count);
    free(plain->bytes);
    memset(plain, 0, sizeof *plain);
}

sk_result sk__midi_plain_make(const uint8_t *data, size_t length, const char *name,
                              sk__midi_plain *out, sk_error *err)
{
    memset(out, 0, sizeof *out);
    framer f = {data, length, name, err};
    if (length > SK_MELODY_MAX_BYTES)
        return sk_fail(err, SK_ERROR_LIMIT, "%s: %zu bytes: a melody file may have at most %u",
                       name, length, SK_MELODY_MAX_BYTES);
    if (length < 14 || memcmp(data, "MThd", 4) != 0)
        return fail_at(&f, 0,
                       "not a Standard MIDI File (it must start with an MThd chunk of 14 bytes)");
    uint32_t header_length = be32(data + 4);
    if (header_length != 6) return fail_at(&f, 4, "MThd length %u (must be 6)", header_length);
    unsigned format = be16(data + 8), tracks = be16(data + 10), division = be16(data + 12);
    if (format > 1)
        return fail_at(
            &f, 8, "format %u: only formats 0 (one track) and 1 (tracks played together) are read",
            format);
    if (tracks == 0) return fail_at(&f, 10, "no tracks (the header says 0)");
    if (format == 0 && tracks != 1)
        return fail_at(&f, 10, "format 0 with %u tracks (must be 1)", tracks);
    if (division & 0x8000)
        return fail_at(&f, 12, "SMPTE time division is not supported (ticks per quarter only)");
    if (division == 0) return fail_at(&f, 12, "0 ticks per quarter note");

    byte_buffer b = {0};
    uint8_t header[14];
    memcpy(header, data, 14);
    put(&b, header, 14);
    out->event_count = calloc(tracks, sizeof *out->event_count);
    out->offset = calloc(tracks, sizeof *out->offset);
    if (!out->event_count || !out->offset) {
        free(b.data);
        sk__midi_plain_free(out);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory reading %s", name);
    }
    size_t p = 14;
    sk_result r = SK_OK;
    int found = 0;
    while (p < length && r == SK_OK) {
        if (length - p < 8) {
            r = fail_at(&f, p, "%zu bytes after the last chunk, too few for a chunk header",
                        length - p);
            break;
        }
        const uint8_t *id = data + p;
        for (int k = 0; k < 4 && r == SK_OK; k++)
            if (id[k] < 0x20 || id[k] > 0x7e)
                r = fail_at(&f, p, "a chunk's type is not 4 ASCII letters");
        if (r != SK_OK) break;
        uint32_t len = be32(data + p + 4);
        if (len > length - p - 8) {
            r = fail_at(&f, p, "chunk \"%.4s\" claims %u bytes, the file has %zu left",
                        (const char *)id, len, length - p - 8);
            break;
        }
        if (memcmp(id, "MTrk", 4) == 0) {
            if ((unsigned)found >= tracks) {
                r = fail_at(&f, p, "more track chunks than the %u the header declares", tracks);
                break;
            }
            byte_buffer t = {0};
            r = frame_track(&f, p + 8, p + 8 + len, found + 1, &t, &out->offset[found],
                            &out->event_count[found]);
            if (r == SK_OK) {
                out->track_count = found + 1;
                put(&b, (const uint8_t *)"MTrk", 4);
                put_u32(&b, (uint32_t)t.size);
                put(&b, t.data, t.size);
                if (t.failed) b.failed = true;
            }
            free(t.data);
            found++;
        }
        /* other chunk types are skipped, as the standard asks */
        p += 8 + (size_t)len;
    }
    if (r == SK_OK && (unsigned)found < tracks)
        r = fail_at(&f, length, "the header declares %u tracks, the file holds %d", tracks, found);
    if (r == SK_OK && b.failed)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory reading %s", name);
    if (r != SK_OK) {
        free(b.data);
        sk__midi_plain_free(out);
        return r;
    }
    out->bytes = b.data;
    out->size = b.size;
    return SK_OK;
}
