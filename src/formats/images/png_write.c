/* PNG writer: 8/16-bit grey, grey+alpha, RGB, RGBA with the sRGB curve or linear codes,
 * text metadata as tEXt (ASCII) or iTXt (UTF-8) chunks. The chunks and their CRCs are
 * written here (PNG spec, ISO/IEC 15948); the image data is filtered with one fixed
 * filter and compressed by libdeflate in strips of about a megabyte, in parallel for
 * large images, joined into the single zlib stream PNG requires (deflate_join.c). The
 * strips depend only on the image size, so the bytes are the same for any thread count.
 * Written atomically to a file, or into memory (the same bytes). */
#define _POSIX_C_SOURCE 200809L
#include <libdeflate.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "formats/images/deflate_join.h"
#include "base/image_internal.h"
#include "formats/images/png_encode.h"
#include "base/png_quantize.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* Raw (filtered) bytes per strip: large enough that restarting the compressor's window
 * at a strip costs little, small enough that a 2048 x 2048 RGB image has a dozen. */
#define STRIP_BYTES ((size_t)1 << 20)
/* Strips encoded ahead of the first one not yet written: bounds the memory held at once. */
#define STRIPS_IN_FLIGHT 16
/* Filter type of every row (PNG spec 9.2): Up, the difference from the row above,
 * suits textures whose structure runs down the image (wood grain, rendered surfaces) and
 * costs one subtraction; see docs/images.md for the measurements behind the choice. */
#define ROW_FILTER 2
/* libdeflate level when the desc leaves it at 0. */
#define DEFAULT_LEVEL 6

/* ------------------------------------------------------------------ chunks */

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

typedef struct png_out {
    sk__png_sink *sink;
    bool ok;
} png_out;

static void emit(png_out *o, const void *data, size_t size)
{
    if (o->ok && size > 0) o->ok = o->sink->write(o->sink->context, data, size);
}

/* A chunk: length, type, data and the CRC-32 of type and data (`crc` given, or 0 to
 * compute it here). */
static void emit_chunk_crc(png_out *o, const char type[4], const uint8_t *data, size_t size,
                           uint32_t crc)
{
    uint8_t head[8], tail[4];
    put32(head, (uint32_t)size);
    memcpy(head + 4, type, 4);
    put32(tail, crc);
    emit(o, head, 8);
    emit(o, data, size);
    emit(o, tail, 4);
}

static uint32_t chunk_crc(const char type[4], const uint8_t *data, size_t size)
{
    /* (libdeflate_crc32 with a NULL buffer returns the initial value, not crc) */
    uint32_t crc = libdeflate_crc32(0, type, 4);
    return size > 0 ? libdeflate_crc32(crc, data, size) : crc;
}

static void emit_chunk(png_out *o, const char type[4], const uint8_t *data, size_t size)
{
    emit_chunk_crc(o, type, data, size, chunk_crc(type, data, size));
}

/* ------------------------------------------------------------------ text */

static bool is_ascii(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s >= 0x80) return false;
    return true;
}

static bool is_valid_utf8(const unsigned char *s)
{
    while (*s) {
        unsigned c = *s++;
        int extra;
        unsigned min;
        if (c < 0x80) continue;
        if ((c & 0xe0) == 0xc0) {
            extra = 1;
            min = 0x80;
            c &= 0x1f;
        } else if ((c & 0xf0) == 0xe0) {
            extra = 2;
            min = 0x800;
            c &= 0x0f;
        } else if ((c & 0xf8) == 0xf0) {
            extra = 3;
            min = 0x10000;
            c &= 0x07;
        } else {
            return false;
        }
        for (int k = 0; k < extra; k++, s++) {
            if ((*s & 0xc0) != 0x80) return false;
            c = (c << 6) | (*s & 0x3f);
        }
        if (c < min || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff)) return false;
    }
    return true;
}

/* A PNG keyword is 1-79 printable Latin-1 characters without leading, trailing or
 * doubled spaces (PNG spec 11.3.4.2); keys are restricted to the ASCII part of that. */
static sk_result check_text(const char *key, const char *value, sk_error *err)
{
    size_t n = strlen(key);
    bool ok = n >= 1 && n <= 79 && key[0] != ' ' && key[n - 1] != ' ';
    for (size_t i = 0; ok && i < n; i++) {
        unsigned char c = (unsigned char)key[i];
        if (c < 0x20 || c > 0x7e || (c == ' ' && key[i + 1] == ' ')) ok = false;
    }
    if (!ok)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata key \"%s\" is not a PNG keyword (1-79 printable ASCII "
                       "characters, no leading, trailing or double spaces)",
                       key);
    if (!is_valid_utf8((const unsigned char *)value))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata value of \"%s\" is not valid UTF-8", key);
    return SK_OK;
}

/* The entry's key and value, terminated (the entries are caller-filled fixed arrays). */
static void entry_text(const sk_image_metadata_entry *e, char *key, char *value)
{
    memcpy(key, e->key, sizeof e->key);
    key[sizeof e->key - 1] = '\0';
    memcpy(value, e->value, sizeof e->value);
    value[sizeof e->value - 1] = '\0';
}

static sk_result check_metadata(const sk_image_metadata *meta, sk_error *err)
{
    if (!meta) return SK_OK;
    if (meta->count < 0 || meta->count > SK_IMAGE_MAX_METADATA)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata count = %d is out of range [0, %d]", meta->count,
                       SK_IMAGE_MAX_METADATA);
    for (int i = 0; i < meta->count; i++) {
        char key[sizeof meta->entries[0].key], value[sizeof meta->entries[0].value];
        entry_text(&meta->entries[i], key, value);
        sk_result r = check_text(key, value, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

/* tEXt is Latin-1, so anything beyond ASCII goes into an iTXt chunk (UTF-8, no
 * compression, empty language tag and translated keyword). */
static void emit_text(png_out *o, const sk_image_metadata_entry *e)
{
    char key[sizeof e->key], value[sizeof e->value];
    entry_text(e, key, value);
    uint8_t data[sizeof e->key + sizeof e->value + 8];
    size_t nk = strlen(key), nv = strlen(value), n = 0;
    memcpy(data, key, nk + 1);
    n = nk + 1;
    bool ascii = is_ascii(value);
    if (!ascii) {
        data[n++] = 0; /* compression flag */
        data[n++] = 0; /* compression method */
        data[n++] = 0; /* language tag */
        data[n++] = 0; /* translated keyword */
    }
    memcpy(data + n, value, nv);
    emit_chunk(o, ascii ? "tEXt" : "iTXt", data, n + nv);
}

static void emit_header(png_out *o, const sk_image_rows *image, int bit_depth,
                        sk_png_encoding encoding, const sk_image_metadata *meta)
{
    static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const uint8_t color_types[5] = {0, 0, 4, 2, 6}; /* grey, grey+alpha, RGB, RGBA */
    emit(o, signature, sizeof signature);
    uint8_t ihdr[13];
    put32(ihdr, (uint32_t)image->width);
    put32(ihdr + 4, (uint32_t)image->height);
    ihdr[8] = (uint8_t)bit_depth;
    ihdr[9] = color_types[image->channels];
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering with the five basic filters */
    ihdr[12] = 0; /* not interlaced */
    emit_chunk(o, "IHDR", ihdr, sizeof ihdr);
    /* sRGB data says so, with the gAMA and cHRM values the PNG spec recommends beside an
       sRGB chunk (11.3.3.5); linear data (height, normal and mask maps) gets no colour-space
       chunk at all: a gAMA of 1.0 would make some viewers brighten it. */
    if (encoding == SK_PNG_ENCODING_SRGB) {
        uint8_t intent = 0; /* perceptual */
        emit_chunk(o, "sRGB", &intent, 1);
        uint8_t gama[4];
        put32(gama, 45455);
        emit_chunk(o, "gAMA", gama, 4);
        static const uint32_t chrm_values[8] = {31270, 32900, 64000, 33000,
                                                30000, 60000, 15000, 6000};
        uint8_t chrm[32];
        for (int i = 0; i < 8; i++) put32(chrm + 4 * i, chrm_values[i]);
        emit_chunk(o, "cHRM", chrm, sizeof chrm);
    }
    for (int i = 0; meta && i < meta->count; i++) emit_text(o, &meta->entries[i]);
}

/* ------------------------------------------------------------------ image data */

typedef struct png_job {
    const sk_image_rows *rows; /* the pixels */
    const sk_image *image;     /* or NULL: rows come from rows->get_row */
    sk__png_quantizer *quantizer;
    size_t row_bytes; /* sample bytes of a row (without the filter byte) */
    int rows_per_strip, strips, level;
} png_job;

/* One strip's IDAT data: the zlib header before the first strip's DEFLATE bytes, room for
 * the Adler-32 after the last's. */
typedef struct strip_out {
    uint8_t *bytes;
    size_t size, raw_size;
    uint32_t adler, crc; /* Adler-32 of the strip's filtered bytes; the chunk's CRC */
} strip_out;

/* What one thread needs to encode strips. */
typedef struct strip_worker {
    struct libdeflate_compressor *compressor;
    uint8_t *prev, *cur, *raw;
    float *samples; /* one row from get_row */
} strip_worker;

static void worker_free(strip_worker *w)
{
    if (w->compressor) libdeflate_free_compressor(w->compressor);
    free(w->prev);
    free(w->cur);
    free(w->raw);
    free(w->samples);
    memset(w, 0, sizeof *w);
}

static bool worker_init(strip_worker *w, const png_job *job)
{
    memset(w, 0, sizeof *w);
    w->compressor = libdeflate_alloc_compressor(job->level);
    w->prev = malloc(job->row_bytes);
    w->cur = malloc(job->row_bytes);
    w->raw = malloc((size_t)job->rows_per_strip * (job->row_bytes + 1));
    bool samples_ok = true;
    if (!job->image) {
        w->samples = malloc(sizeof(float) * (size_t)job->rows->width * (size_t)job->rows->channels);
        samples_ok = w->samples != NULL;
    }
    if (w->compressor && w->prev && w->cur && w->raw && samples_ok) return true;
    worker_free(w);
    return false;
}

/* Row y as PNG sample codes. */
static void quantize_row(const png_job *job, strip_worker *w, int y, uint8_t *out)
{
    const float *src;
    if (job->image) {
        src = sk_image_pixel(job->image, 0, y);
    } else {
        job->rows->get_row(job->rows->user, y, w->samples);
        src = w->samples;
    }
    sk__png_quantize_row(job->quantizer, src, job->rows->width, out);
}

/* The Up filter of a row (PNG spec 9.2): its bytes minus those of the row above. */
static void filter_up(uint8_t *restrict out, const uint8_t *restrict cur,
                      const uint8_t *restrict above, size_t n)
{
#pragma omp simd
    for (size_t i = 0; i < n; i++) out[i] = (uint8_t)(cur[i] - above[i]);
}

/* Filters and compresses strip s into out (false on allocation failure). */
static bool encode_strip(const png_job *job, strip_worker *w, int s, strip_out *out)
{
    int height = job->rows->height;
    int y0 = s * job->rows_per_strip;
    int y1 = y0 + job->rows_per_strip < height ? y0 + job->rows_per_strip : height;
    size_t rb = job->row_bytes, n = (size_t)(y1 - y0) * (rb + 1);
    if (y0 > 0)
        quantize_row(job, w, y0 - 1, w->prev);
    else
        memset(w->prev, 0, rb); /* the row above the first is zeros */
    for (int y = y0; y < y1; y++) {
        uint8_t *row = w->raw + (size_t)(y - y0) * (rb + 1);
        quantize_row(job, w, y, w->cur);
        row[0] = ROW_FILTER;
        filter_up(row + 1, w->cur, w->prev, rb);
        uint8_t *t = w->prev;
        w->prev = w->cur;
        w->cur = t;
    }
    bool first = s == 0, last = s == job->strips - 1;
    size_t bound = libdeflate_deflate_compress_bound(w->compressor, n);
    size_t stored = sk__deflate_stored_bound(n);
    size_t cap = 2 + (bound > stored ? bound : stored) + 5 + 4;
    out->bytes = malloc(cap);
    if (!out->bytes) return false;
    out->raw_size = n;
    out->adler = libdeflate_adler32(1, w->raw, n);
    size_t head = first ? 2 : 0;
    if (first) {
        out->bytes[0] = 0x78; /* deflate, 32 KiB window */
        out->bytes[1] = 0x9c; /* default level flag, check bits: 0x789c % 31 == 0 */
    }
    uint8_t *d = out->bytes + head;
    size_t m = libdeflate_deflate_compress(w->compressor, w->raw, n, d, cap - head - 9);
    /* a strip that does not compress or join (never seen: the walk reads what libdeflate
       writes) is stored, which joins by construction */
    if (m == 0 || (!last && !sk__deflate_make_continuable(d, &m)))
        m = sk__deflate_store(w->raw, n, last, d);
    out->size = head + m;
    if (!last) out->crc = chunk_crc("IDAT", out->bytes, out->size);
    return true;
}

/* Strips in order: each is written as soon as it and every strip before it are done. */
typedef struct strip_queue {
    strip_out *outs; /* per strip; bytes == NULL once written */
    bool *done;
    int next;       /* the first strip not yet written */
    uint32_t adler; /* of the strips written */
} strip_queue;

/* Writes the strips from queue->next on that are done (under the caller's lock; next is
 * also read outside it, atomically). */
static void write_ready_strips(png_out *o, const png_job *job, strip_queue *q, bool ok)
{
    int next = q->next;
    for (; next < job->strips && q->done[next]; next++) {
        strip_out *so = &q->outs[next];
        if (ok && o->ok) {
            q->adler =
                next == 0 ? so->adler : sk__adler32_combine(q->adler, so->adler, so->raw_size);
            if (next == job->strips - 1) {
                put32(so->bytes + so->size, q->adler);
                so->size += 4;
                so->crc = chunk_crc("IDAT", so->bytes, so->size);
            }
            emit_chunk_crc(o, "IDAT", so->bytes, so->size, so->crc);
        }
        free(so->bytes);
        so->bytes = NULL;
    }
#pragma omp atomic write
    q->next = next;
}

/* Encodes the strips, in parallel when there are several, and writes them as IDAT chunks
 * in order: a strip done before an earlier one waits in memory, and a thread does not start
 * a strip STRIPS_IN_FLIGHT or more ahead of the first unwritten one (which bounds that
 * memory; the strip holding it back is being encoded, so the wait is short). No barrier
 * between strips: a thread is never idle while there are strips to encode. */
static sk_result emit_image_data(png_out *o, const png_job *job, sk_error *err)
{
    strip_queue q = {.outs = calloc((size_t)job->strips, sizeof *q.outs),
                     .done = calloc((size_t)job->strips, sizeof *q.done),
                     .adler = 1};
    if (!q.outs || !q.done) {
        free(q.outs), free(q.done);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the PNG strips");
    }
    bool memory_ok = true;
    /* small images stay on the calling thread: a parallel region would cost more than
       their one strip */
#pragma omp parallel if (job->strips > 1)
    {
        strip_worker w;
        bool have = worker_init(&w, job);
        if (!have) {
#pragma omp atomic write
            memory_ok = false;
        }
#pragma omp for schedule(dynamic, 1)
        for (int s = 0; s < job->strips; s++) {
            for (;;) {
                int next;
#pragma omp atomic read
                next = q.next;
                if (s - next < STRIPS_IN_FLIGHT) break;
                struct timespec pause = {0, 100000};
                nanosleep(&pause, NULL);
            }
            bool ok;
#pragma omp atomic read
            ok = memory_ok;
            if (ok && have && !encode_strip(job, &w, s, &q.outs[s])) {
#pragma omp atomic write
                memory_ok = false;
            }
#pragma omp critical(sk_png_strips)
            {
                q.done[s] = true;
                bool all_ok;
#pragma omp atomic read
                all_ok = memory_ok;
                write_ready_strips(o, job, &q, all_ok);
            }
        }
        if (have) worker_free(&w);
    }
    for (int s = 0; s < job->strips; s++) free(q.outs[s].bytes); /* after a failure */
    free(q.outs);
    free(q.done);
    if (!memory_ok)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory while compressing the PNG");
    return SK_OK;
}

/* The desc with its defaults filled in, checked. */
static sk_result resolve_desc(const sk_png_write_desc *desc, sk_png_write_desc *d, sk_error *err)
{
    sk_result r;
    memset(d, 0, sizeof *d);
    if (desc) *d = *desc;
    if (d->bit_depth == 0) d->bit_depth = 8;
    if (d->bit_depth != 8 && d->bit_depth != 16)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "bit_depth = %d: must be 8 or 16",
                       d->bit_depth);
    if (d->compression_level == 0) d->compression_level = DEFAULT_LEVEL;
    r = sk_check_range_i(err, "compression_level", d->compression_level, 1, 9);
    if (r != SK_OK) return r;
    if (d->encoding == SK_PNG_ENCODING_DEFAULT) d->encoding = SK_PNG_ENCODING_SRGB;
    if (d->encoding != SK_PNG_ENCODING_SRGB && d->encoding != SK_PNG_ENCODING_LINEAR)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "encoding = %d is not a sk_png_encoding",
                       (int)d->encoding);
    return check_metadata(d->metadata, err);
}

/* The image (validated) as rows: its own pixels, or those of get_row. */
typedef struct png_source {
    sk_image_rows rows;
    const sk_image *image; /* NULL for rows from get_row */
} png_source;

static sk_result source_of_image(const sk_image *image, png_source *src, sk_error *err)
{
    sk_result r = sk__image_validate(image, err);
    if (r != SK_OK) return r;
    src->rows = (sk_image_rows){
        .width = image->width, .height = image->height, .channels = image->channels};
    src->image = image;
    return SK_OK;
}

/* Encodes with a resolved desc. */
static sk_result encode(const png_source *src, const sk_png_write_desc *d, sk__png_sink *sink,
                        const char *name, sk_error *err)
{
    const sk_image_rows *image = &src->rows;
    sk__png_quantizer *q = malloc(sizeof *q);
    if (!q) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    sk__png_quantizer_init(q, image->channels, d->bit_depth, d->encoding);
    png_job job = {
        .rows = image, .image = src->image, .quantizer = q, .level = d->compression_level};
    job.row_bytes = (size_t)image->width * (size_t)image->channels * (size_t)(d->bit_depth / 8);
    size_t rows = STRIP_BYTES / (job.row_bytes + 1);
    job.rows_per_strip = rows < 1 ? 1 : (rows > (size_t)image->height ? image->height : (int)rows);
    job.strips = (image->height + job.rows_per_strip - 1) / job.rows_per_strip;

    png_out o = {.sink = sink, .ok = true};
    emit_header(&o, image, d->bit_depth, d->encoding, d->metadata);
    sk_result r = emit_image_data(&o, &job, err);
    if (r == SK_OK) emit_chunk(&o, "IEND", NULL, 0);
    free(q);
    if (r == SK_OK && !o.ok) r = sk_fail(err, SK_ERROR_IO, "%s: PNG write failed", name);
    return r;
}

sk_result sk__png_encode(const sk_image *image, const sk_png_write_desc *desc, sk__png_sink *sink,
                         const char *name, sk_error *err)
{
    png_source src;
    sk_png_write_desc d;
    sk_result r = source_of_image(image, &src, err);
    if (r == SK_OK) r = resolve_desc(desc, &d, err);
    return r == SK_OK ? encode(&src, &d, sink, name, err) : r;
}

static bool file_write(void *context, const void *data, size_t size)
{
    return fwrite(data, 1, size, (FILE *)context) == size;
}

/* Encodes a checked source into a file. */
static sk_result write_file(const png_source *src, const char *path, const sk_png_write_desc *desc,
                            sk_error *err)
{
    sk_png_write_desc d;
    sk_result r = resolve_desc(desc, &d, err);
    if (r != SK_OK) return r;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    sk_atomic_file file;
    r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    sk__png_sink sink = {file_write, file.fp};
    r = encode(src, &d, &sink, path, err);
    if (r == SK_ERROR_IO && ferror(file.fp))
        return sk_atomic_file_write_failed(&file, err); /* names the reason */
    if (r != SK_OK) {
        sk_atomic_file_abort(&file);
        return r;
    }
    return sk_atomic_file_commit(&file, err);
}

sk_result sk_image_write_png(const sk_image *image, const char *path, const sk_png_write_desc *desc,
                             sk_error *err)
{
    png_source src;
    sk_result r = source_of_image(image, &src, err);
    return r == SK_OK ? write_file(&src, path, desc, err) : r;
}

sk_result sk_image_write_png_rows(const sk_image_rows *rows, const char *path,
                                  const sk_png_write_desc *desc, sk_error *err)
{
    if (!rows || !rows->get_row)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "rows and rows->get_row must not be NULL");
    sk_result r = sk__image_check_size(rows->width, rows->height, rows->channels, err);
    if (r != SK_OK) return r;
    png_source src = {.rows = *rows, .image = NULL};
    return write_file(&src, path, desc, err);
}

/* A growing buffer as a sink. */
typedef struct memory_sink {
    uint8_t *data;
    size_t size, capacity;
} memory_sink;

static bool memory_write(void *context, const void *data, size_t size)
{
    memory_sink *m = context;
    if (size > m->capacity - m->size) {
        size_t capacity = m->capacity ? m->capacity : 1 << 16;
        while (capacity - m->size < size) {
            if (capacity > SIZE_MAX / 2) return false;
            capacity *= 2;
        }
        uint8_t *grown = realloc(m->data, capacity);
        if (!grown) return false;
        m->data = grown;
        m->capacity = capacity;
    }
    memcpy(m->data + m->size, data, size);
    m->size += size;
    return true;
}

sk_result sk_image_write_png_memory(const sk_image *image, const sk_png_write_desc *desc,
                                    uint8_t **out_data, size_t *out_size, sk_error *err)
{
    if (!out_data || !out_size)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out_data or out_size is NULL");
    *out_data = NULL;
    *out_size = 0;
    png_source src;
    sk_png_write_desc d;
    sk_result r = source_of_image(image, &src, err);
    if (r == SK_OK) r = resolve_desc(desc, &d, err);
    if (r != SK_OK) return r;
    memory_sink m = {0};
    sk__png_sink sink = {memory_write, &m};
    r = encode(&src, &d, &sink, "PNG in memory", err);
    if (r == SK_ERROR_IO) /* the only way memory fails */
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a PNG of %dx%d", image->width,
                    image->height);
    if (r != SK_OK) {
        free(m.data);
        return r;
    }
    *out_data = m.data;
    *out_size = m.size;
    return SK_OK;
}
