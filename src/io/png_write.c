/* PNG writer (libpng): 8/16-bit grey, grey+alpha, RGB, RGBA with the sRGB curve or linear
 * codes, text metadata as tEXt (ASCII) or iTXt (UTF-8) chunks, written atomically to a file
 * or into memory (the same bytes). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "io/image_internal.h"
#include "io/png_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* Everything that changes after setjmp lives here, outside the frame of the function that
 * calls setjmp, so no local can be clobbered by the long jump. */
typedef struct png_writer {
    sk__png_error error;
    const sk_image *image;
    int bit_depth;
    int compression_level;
    sk_png_encoding encoding;
    FILE *fp;
    png_structp png;
    png_infop info;
    unsigned char *row;
    /* Code k + 1 starts at linear value threshold8[k] (8-bit sRGB quantisation). */
    double threshold8[255];
    sk_image_metadata text_store; /* writable copy: png_text wants non-const strings */
    png_text texts[SK_IMAGE_MAX_METADATA];
    int text_count;
} png_writer;

static bool is_alpha_channel(int channel, int channels)
{
    return (channels == 2 && channel == 1) || (channels == 4 && channel == 3);
}

static unsigned quantize_linear(double v, unsigned max_code)
{
    if (!(v > 0.0)) return 0; /* also NaN */
    if (v >= 1.0) return max_code;
    return (unsigned)floor(v * max_code + 0.5);
}

static unsigned quantize_srgb8(const png_writer *w, float v)
{
    if (!(v > 0.0f)) return 0;
    unsigned lo = 0, hi = 255; /* answer in [lo, hi] */
    while (lo < hi) {
        unsigned mid = (lo + hi + 1) / 2;
        if ((double)v >= w->threshold8[mid - 1])
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

static unsigned quantize(const png_writer *w, float v, int channel)
{
    unsigned max_code = w->bit_depth == 16 ? 65535u : 255u;
    if (w->encoding == SK_PNG_ENCODING_LINEAR || is_alpha_channel(channel, w->image->channels))
        return quantize_linear(v, max_code);
    if (w->bit_depth == 8) return quantize_srgb8(w, v);
    if (!(v > 0.0f)) return 0;
    return quantize_linear(sk__srgb_encode(v >= 1.0f ? 1.0 : v), max_code);
}

static void fill_row(png_writer *w, int y)
{
    const sk_image *im = w->image;
    const float *src = sk_image_pixel(im, 0, y);
    size_t n = (size_t)im->width * (size_t)im->channels;
    for (size_t i = 0; i < n; i++) {
        unsigned code = quantize(w, src[i], (int)(i % (size_t)im->channels));
        if (w->bit_depth == 16) {
            w->row[2 * i] = (unsigned char)(code >> 8); /* PNG samples are big-endian */
            w->row[2 * i + 1] = (unsigned char)(code & 0xff);
        } else {
            w->row[i] = (unsigned char)code;
        }
    }
}

/* Drives libpng; returns false after a libpng error (message in w->error). */
static bool write_body(png_writer *w)
{
    if (setjmp(png_jmpbuf(w->png))) return false;
    static const int color_types[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                       PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    png_init_io(w->png, w->fp);
    png_set_compression_level(w->png, w->compression_level);
    png_set_IHDR(w->png, w->info, (png_uint_32)w->image->width, (png_uint_32)w->image->height,
                 w->bit_depth, color_types[w->image->channels], PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    /* Linear data (height, normal and mask maps) gets no colour-space chunk at all: a
       gAMA of 1.0 would make some viewers brighten it, and it must not claim sRGB. */
    if (w->encoding == SK_PNG_ENCODING_SRGB)
        png_set_sRGB_gAMA_and_cHRM(w->png, w->info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (w->text_count > 0) png_set_text(w->png, w->info, w->texts, w->text_count);
    png_write_info(w->png, w->info);
    for (int y = 0; y < w->image->height; y++) {
        fill_row(w, y);
        png_write_row(w->png, w->row);
    }
    png_write_end(w->png, NULL);
    return true;
}

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
static sk_result check_text(const sk_image_metadata_entry *e, sk_error *err)
{
    size_t n = strlen(e->key);
    bool ok = n >= 1 && n <= 79 && e->key[0] != ' ' && e->key[n - 1] != ' ';
    for (size_t i = 0; ok && i < n; i++) {
        unsigned char c = (unsigned char)e->key[i];
        if (c < 0x20 || c > 0x7e || (c == ' ' && e->key[i + 1] == ' ')) ok = false;
    }
    if (!ok)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata key \"%s\" is not a PNG keyword (1-79 printable ASCII "
                       "characters, no leading, trailing or double spaces)",
                       e->key);
    if (!is_valid_utf8((const unsigned char *)e->value))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata value of \"%s\" is not valid UTF-8", e->key);
    return SK_OK;
}

static sk_result prepare_texts(png_writer *w, const sk_image_metadata *meta, sk_error *err)
{
    if (!meta) return SK_OK;
    if (meta->count < 0 || meta->count > SK_IMAGE_MAX_METADATA)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata count = %d is out of range [0, %d]", meta->count,
                       SK_IMAGE_MAX_METADATA);
    w->text_store = *meta;
    for (int i = 0; i < meta->count; i++) {
        sk_image_metadata_entry *e = &w->text_store.entries[i];
        /* Terminate defensively: the entries are caller-filled fixed-size arrays. */
        e->key[sizeof e->key - 1] = '\0';
        e->value[sizeof e->value - 1] = '\0';
        sk_result r = check_text(e, err);
        if (r != SK_OK) return r;
        png_text *t = &w->texts[i];
        memset(t, 0, sizeof *t);
        t->key = e->key;
        t->text = e->value;
        t->text_length = strlen(e->value);
        /* tEXt is Latin-1, so anything beyond ASCII goes into an iTXt chunk (UTF-8). */
        if (is_ascii(e->value)) {
            t->compression = PNG_TEXT_COMPRESSION_NONE;
        } else {
            t->compression = PNG_ITXT_COMPRESSION_NONE;
            t->itxt_length = t->text_length;
            t->lang = (png_charp) "";
            t->lang_key = (png_charp) "";
        }
    }
    w->text_count = meta->count;
    return SK_OK;
}

/* Checks the image and the desc and fills in the desc's defaults. */
static sk_result resolve_desc(const sk_image *image, const sk_png_write_desc *desc,
                              sk_png_write_desc *out, sk_error *err)
{
    sk_result r = sk__image_validate(image, err);
    if (r != SK_OK) return r;
    sk_png_write_desc d = {0};
    if (desc) d = *desc;
    if (d.bit_depth == 0) d.bit_depth = 8;
    if (d.bit_depth != 8 && d.bit_depth != 16)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "bit_depth = %d: must be 8 or 16",
                       d.bit_depth);
    if (d.compression_level == 0) d.compression_level = 6;
    r = sk_check_range_i(err, "compression_level", d.compression_level, 1, 9);
    if (r != SK_OK) return r;
    if (d.encoding == SK_PNG_ENCODING_DEFAULT) d.encoding = SK_PNG_ENCODING_SRGB;
    if (d.encoding != SK_PNG_ENCODING_SRGB && d.encoding != SK_PNG_ENCODING_LINEAR)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "encoding = %d is not a sk_png_encoding",
                       (int)d.encoding);
    *out = d;
    return SK_OK;
}

/* Encodes the image into an open stream (a file or memory); `name` labels messages. */
static sk_result write_stream(const sk_image *image, const sk_png_write_desc *d, FILE *fp,
                              const char *name, sk_error *err)
{
    png_writer *w = calloc(1, sizeof *w);
    if (!w) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    w->image = image;
    w->bit_depth = d->bit_depth;
    w->encoding = d->encoding;
    w->compression_level = d->compression_level;
    w->fp = fp;
    sk_result r = prepare_texts(w, d->metadata, err);
    if (r != SK_OK) {
        free(w);
        return r;
    }
    /* Thresholds in double straight from the curve (not through float) so that the
       search gives the same code as rounding 255 * srgb(v). */
    for (int k = 0; k < 255; k++) w->threshold8[k] = sk__srgb_decode((k + 0.5) / 255.0);
    size_t row_bytes = (size_t)image->width * (size_t)image->channels * (size_t)(d->bit_depth / 8);
    w->row = malloc(row_bytes);
    if (w->row)
        w->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w->error, sk__png_on_error,
                                         sk__png_on_warning);
    if (w->png) w->info = png_create_info_struct(w->png);
    if (!w->row || !w->png || !w->info) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: cannot set up libpng", name);
    } else if (!write_body(w)) {
        r = sk_fail(err, SK_ERROR_IO, "%s: PNG write failed (%s)", name, w->error.message);
    }
    png_destroy_write_struct(&w->png, &w->info);
    free(w->row);
    free(w);
    return r;
}

sk_result sk_image_write_png(const sk_image *image, const char *path, const sk_png_write_desc *desc,
                             sk_error *err)
{
    sk_png_write_desc d;
    sk_result r = resolve_desc(image, desc, &d, err);
    if (r != SK_OK) return r;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    sk_atomic_file file;
    if ((r = sk_atomic_file_open(&file, path, err)) != SK_OK) return r;
    if ((r = write_stream(image, &d, file.fp, path, err)) != SK_OK) {
        sk_atomic_file_abort(&file);
        return r;
    }
    return sk_atomic_file_commit(&file, err);
}

sk_result sk_image_write_png_memory(const sk_image *image, const sk_png_write_desc *desc,
                                    uint8_t **out_data, size_t *out_size, sk_error *err)
{
    if (!out_data || !out_size)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "out_data or out_size is NULL");
    *out_data = NULL;
    *out_size = 0;
    sk_png_write_desc d;
    sk_result r = resolve_desc(image, desc, &d, err);
    if (r != SK_OK) return r;
    char *buffer = NULL;
    size_t size = 0;
    FILE *fp = open_memstream(&buffer, &size);
    if (!fp) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a PNG stream");
    r = write_stream(image, &d, fp, "PNG in memory", err);
    if (fclose(fp) != 0 && r == SK_OK)
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a PNG of %dx%d",
                    image->width, image->height);
    if (r != SK_OK) {
        free(buffer);
        return r;
    }
    *out_data = (uint8_t *)buffer;
    *out_size = size;
    return SK_OK;
}
