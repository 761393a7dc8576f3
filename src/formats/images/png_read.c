/* PNG reader (libpng): every colour type and bit depth into float images, palette and
 * low-bit grey expanded, text chunks into metadata, size caps checked before allocating. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/image_internal.h"
#include "formats/images/png_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* Everything that changes after setjmp lives here, outside the frame of the function that
 * calls setjmp, so no local can be clobbered by the long jump. */
typedef struct png_reader {
    sk__png_error error;
    const char *path;
    sk_error *err;
    sk_result result; /* set when the reader itself (not libpng) rejects the file */
    FILE *fp;
    long long file_size;
    png_structp png;
    png_infop info;
    sk_png_encoding encoding;
    sk_image *image;
    sk_image_metadata *metadata;
    int file_bit_depth;  /* from IHDR (1-16), reported to the caller */
    int sample_depth;    /* after expansion: 8 or 16 */
    unsigned char *rows; /* one row, or the whole image when interlaced */
    float *lut16;        /* 16-bit sRGB codes to linear */
    float lut8[256];     /* 8-bit colour codes to linear */
} png_reader;

/* Channels after expansion: palette to RGB(A), tRNS to an alpha channel. */
static int expanded_channels(png_structp png, png_infop info, int color_type)
{
    bool trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    switch (color_type) {
    case PNG_COLOR_TYPE_GRAY:
        return trns ? 2 : 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        return 2;
    case PNG_COLOR_TYPE_RGB:
        return trns ? 4 : 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
        return 4;
    case PNG_COLOR_TYPE_PALETTE:
        return trns ? 4 : 3;
    default:
        return 0;
    }
}

static void convert_row(png_reader *r, const unsigned char *src, int y)
{
    sk_image *im = r->image;
    float *dst = sk_image_pixel(im, 0, y);
    size_t n = (size_t)im->width * (size_t)im->channels;
    int alpha = (im->channels == 2 || im->channels == 4) ? im->channels - 1 : -1;
    for (size_t i = 0; i < n; i++) {
        bool is_alpha = (int)(i % (size_t)im->channels) == alpha;
        if (r->sample_depth == 16) {
            unsigned code = ((unsigned)src[2 * i] << 8) | src[2 * i + 1]; /* big-endian */
            if (is_alpha || r->encoding == SK_PNG_ENCODING_LINEAR)
                dst[i] = (float)code / 65535.0f;
            else
                dst[i] = r->lut16 ? r->lut16[code] : (float)sk__srgb_decode(code / 65535.0);
        } else {
            dst[i] = is_alpha ? (float)src[i] / 255.0f : r->lut8[src[i]];
        }
    }
}

/* Latin-1 (tEXt/zTXt text, every keyword) to UTF-8, stopping before the output is full. */
static size_t latin1_to_utf8(char *dst, size_t cap, const char *src, size_t len)
{
    size_t o = 0;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)src[i];
        size_t need = c < 0x80 ? 1 : 2;
        if (o + need >= cap) break;
        if (c < 0x80) {
            dst[o++] = (char)c;
        } else {
            dst[o++] = (char)(0xc0 | (c >> 6));
            dst[o++] = (char)(0x80 | (c & 0x3f));
        }
    }
    dst[o] = '\0';
    return o;
}

static void collect_text(png_reader *r)
{
    png_textp text = NULL;
    int count = 0;
    png_get_text(r->png, r->info, &text, &count);
    for (int i = 0; i < count; i++) {
        char key[sizeof r->metadata->entries[0].key];
        char value[sizeof r->metadata->entries[0].value];
        size_t key_len = latin1_to_utf8(key, sizeof key, text[i].key, strlen(text[i].key));
        const char *v = text[i].text ? text[i].text : "";
        size_t value_len;
        if (text[i].compression >= PNG_ITXT_COMPRESSION_NONE) { /* iTXt: already UTF-8 */
            value_len = text[i].itxt_length;
            sk__image_metadata_add_read(r->metadata, key, key_len, v, value_len);
        } else {
            value_len = latin1_to_utf8(value, sizeof value, v, text[i].text_length);
            sk__image_metadata_add_read(r->metadata, key, key_len, value, value_len);
        }
    }
}

static bool fail_own(png_reader *r, sk_result result, const char *what)
{
    r->result = sk_fail(r->err, result, "%s: %s", r->path, what);
    return false;
}

/* Drives libpng; returns false after a libpng error (message in r->error) or a rejection
 * by the reader (r->result set, message in r->err). */
static bool read_body(png_reader *r)
{
    if (setjmp(png_jmpbuf(r->png))) return false;
    png_init_io(r->png, r->fp);
    png_set_sig_bytes(r->png, 8);
    /* The caps of image.h decide (with SK_ERROR_LIMIT), not libpng's own defaults. */
    png_set_user_limits(r->png, 0x7fffffffu, 0x7fffffffu);
    png_read_info(r->png, r->info);

    png_uint_32 width, height;
    int bit_depth, color_type, interlace;
    png_get_IHDR(r->png, r->info, &width, &height, &bit_depth, &color_type, &interlace, NULL, NULL);
    r->file_bit_depth = bit_depth;
    int channels = expanded_channels(r->png, r->info, color_type);
    if (channels == 0) return fail_own(r, SK_ERROR_PARSE, "unknown PNG colour type");
    /* Before libpng allocates its row buffers and before the image is allocated. */
    sk_result size_ok = sk__image_check_size(width, height, channels, r->err);
    if (size_ok != SK_OK) {
        r->result = size_ok;
        sk_error_prefix(r->err, size_ok, "%s", r->path);
        return false;
    }
    /* Deflate cannot compress better than 1032:1, so the file must hold at least its
       pixel bytes / 1032: a tiny file claiming a huge image is rejected here instead of
       making the reader allocate gigabytes before it runs out of data. */
    int file_channels = color_type == PNG_COLOR_TYPE_GRAY_ALPHA  ? 2
                        : color_type == PNG_COLOR_TYPE_RGB       ? 3
                        : color_type == PNG_COLOR_TYPE_RGB_ALPHA ? 4
                                                                 : 1;
    double raw_bytes = (double)height * ceil((double)width * file_channels * bit_depth / 8.0);
    if (raw_bytes > 1032.0 * (double)r->file_size + 4096.0)
        return fail_own(r, SK_ERROR_PARSE,
                        "the header claims more pixel data than the file can hold");

    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r->png);
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(r->png);
    if (png_get_valid(r->png, r->info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(r->png);
    int passes = png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);
    r->sample_depth = png_get_bit_depth(r->png, r->info);
    size_t sample_bytes = r->sample_depth == 16 ? 2 : 1;
    size_t row_bytes = (size_t)width * (size_t)channels * sample_bytes;
    if (png_get_channels(r->png, r->info) != channels ||
        png_get_rowbytes(r->png, r->info) != row_bytes)
        return fail_own(r, SK_ERROR_PARSE, "unexpected PNG layout after expansion");

    sk_result created = sk_image_create(r->image, (int)width, (int)height, channels, r->err);
    if (created != SK_OK) {
        r->result = created;
        sk_error_prefix(r->err, created, "%s", r->path);
        return false;
    }
    size_t buffer_rows = passes > 1 ? (size_t)height : 1;
    r->rows = malloc(buffer_rows * row_bytes);
    /* Building the table costs as much as decoding 65536 samples: small images decode
       each sample directly. */
    bool need_lut16 = r->sample_depth == 16 && r->encoding == SK_PNG_ENCODING_SRGB &&
                      (size_t)width * height * (size_t)channels > 65536;
    if (need_lut16) r->lut16 = malloc(65536 * sizeof(float));
    if (!r->rows || (need_lut16 && !r->lut16))
        return fail_own(r, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    for (int c = 0; c < 256; c++)
        r->lut8[c] = r->encoding == SK_PNG_ENCODING_SRGB ? (float)sk__srgb_decode(c / 255.0)
                                                         : (float)c / 255.0f;
    if (r->lut16)
        for (int c = 0; c < 65536; c++) r->lut16[c] = (float)sk__srgb_decode(c / 65535.0);

    if (passes > 1) {
        /* Interlaced: libpng fills the rows in place over the passes. */
        for (int pass = 0; pass < passes; pass++)
            for (png_uint_32 y = 0; y < height; y++)
                png_read_row(r->png, r->rows + (size_t)y * row_bytes, NULL);
        for (png_uint_32 y = 0; y < height; y++)
            convert_row(r, r->rows + (size_t)y * row_bytes, (int)y);
    } else {
        for (png_uint_32 y = 0; y < height; y++) {
            png_read_row(r->png, r->rows, NULL);
            convert_row(r, r->rows, (int)y);
        }
    }
    /* Text chunks may also follow the image data. */
    png_read_end(r->png, r->info);
    if (r->metadata) collect_text(r);
    return true;
}

sk_result sk_image_read_png(sk_image *image, const char *path, const sk_png_read_desc *desc,
                            sk_image_metadata *metadata, int *bit_depth, sk_error *err)
{
    if (!image || !path)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "image and path must not be NULL");
    memset(image, 0, sizeof *image);
    if (metadata) memset(metadata, 0, sizeof *metadata);
    if (bit_depth) *bit_depth = 0;
    sk_png_encoding encoding = desc ? desc->encoding : SK_PNG_ENCODING_DEFAULT;
    if (encoding == SK_PNG_ENCODING_DEFAULT) encoding = SK_PNG_ENCODING_SRGB;
    if (encoding != SK_PNG_ENCODING_SRGB && encoding != SK_PNG_ENCODING_LINEAR)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "encoding = %d is not a sk_png_encoding",
                       (int)encoding);

    FILE *fp;
    long long file_size;
    sk_result opened = sk_open_regular_file(path, &fp, &file_size, err);
    if (opened != SK_OK) return opened;
    unsigned char signature[8];
    size_t got = fread(signature, 1, sizeof signature, fp);
    if (got != sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0) {
        bool io = ferror(fp) != 0;
        fclose(fp);
        return sk_fail(err, io ? SK_ERROR_IO : SK_ERROR_PARSE, "%s: %s", path,
                       io ? "read failed" : "not a PNG file (bad signature)");
    }

    png_reader *r = calloc(1, sizeof *r);
    if (!r) {
        fclose(fp);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    r->path = path;
    r->err = err;
    r->fp = fp;
    r->file_size = file_size;
    r->encoding = encoding;
    r->image = image;
    r->metadata = metadata;
    r->png = png_create_read_struct_2(PNG_LIBPNG_VER_STRING, &r->error, sk__png_on_error,
                                      sk__png_on_warning, NULL, sk__png_malloc, sk__png_free);
    if (r->png) r->info = png_create_info_struct(r->png);
    sk_result result = SK_OK;
    if (!r->png || !r->info) {
        result = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: cannot set up libpng", path);
    } else if (!read_body(r)) {
        if (r->result != SK_OK)
            result = r->result;
        else if (ferror(fp))
            result = sk_fail(err, SK_ERROR_IO, "%s: read failed (%s)", path, r->error.message);
        else
            result = sk_fail(err, SK_ERROR_PARSE, "%s: malformed or truncated PNG (%s)", path,
                             r->error.message);
    }
    int depth = r->file_bit_depth;
    png_destroy_read_struct(&r->png, &r->info, NULL);
    free(r->rows);
    free(r->lut16);
    free(r);
    fclose(fp);
    if (result != SK_OK) {
        sk_image_free(image);
        if (metadata) memset(metadata, 0, sizeof *metadata);
        return result;
    }
    if (bit_depth) *bit_depth = depth;
    return SK_OK;
}
