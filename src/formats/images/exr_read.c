/* OpenEXR reader (C API): single-part scanline or tiled images (base level), HALF / FLOAT /
 * UINT channels decoded to floats by the library, data window as the image, channels
 * mapped back to Y / R,G,B / A order by name, string attributes into metadata. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "formats/images/exr_internal.h"
#include "base/image_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

typedef struct exr_reader {
    const char *path;
    sk_error *err;
    exr_context_t ctxt;
    sk__exr_io io;
    exr_attr_box2i_t window;
    int width, height;
    int channels;
    const char *names[4]; /* selected file channels in image order (owned by the context) */
    sk_image *image;
} exr_reader;

/* Where a channel goes in the image: Y first, then R, G, B, then other names (in the
 * file's alphabetical order), alpha last. */
static int order_key(const char *name)
{
    static const char *const known[] = {"Y", "R", "G", "B"};
    for (int i = 0; i < 4; i++)
        if (strcmp(name, known[i]) == 0) return i;
    return strcmp(name, "A") == 0 ? 6 : 5;
}

/* Which channels are kept when there are more than 4: the colour and alpha channels
 * first, then the others alphabetically. */
static bool is_known_name(const char *name) { return order_key(name) != 5; }

static sk_result select_channels(exr_reader *r)
{
    const exr_attr_chlist_t *list = NULL;
    exr_result_t rv = exr_get_channels(r->ctxt, 0, &list);
    if (rv != EXR_ERR_SUCCESS || !list || list->num_channels < 1)
        return sk_fail(r->err, SK_ERROR_PARSE, "%s: EXR has no channels", r->path);
    const char *picked[4];
    int count = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < list->num_channels && count < 4; i++) {
            const exr_attr_chlist_entry_t *e = &list->entries[i];
            if (is_known_name(e->name.str) != (pass == 0)) continue;
            if (e->x_sampling != 1 || e->y_sampling != 1)
                return sk_fail(r->err, SK_ERROR_UNSUPPORTED,
                               "%s: channel \"%s\" is subsampled (%d x %d), which is not "
                               "supported",
                               r->path, e->name.str, e->x_sampling, e->y_sampling);
            picked[count++] = e->name.str;
        }
    /* Stable insertion sort by order key keeps the alphabetical order of other names. */
    for (int i = 1; i < count; i++)
        for (int j = i; j > 0 && order_key(picked[j - 1]) > order_key(picked[j]); j--) {
            const char *t = picked[j];
            picked[j] = picked[j - 1];
            picked[j - 1] = t;
        }
    memcpy(r->names, picked, sizeof picked);
    r->channels = count;
    return SK_OK;
}

static void bind_channels(exr_reader *r, exr_decode_pipeline_t *dec, int x0, int y0)
{
    sk_image *im = r->image;
    for (int i = 0; i < dec->channel_count; i++) {
        exr_coding_channel_info_t *c = &dec->channels[i];
        int k = -1;
        for (int j = 0; j < r->channels; j++)
            if (strcmp(r->names[j], c->channel_name) == 0) k = j;
        c->user_data_type = EXR_PIXEL_FLOAT;
        c->user_bytes_per_element = 4;
        c->user_pixel_stride = (int32_t)(im->channels * (int)sizeof(float));
        c->user_line_stride = (int32_t)((size_t)im->width * (size_t)im->channels * sizeof(float));
        /* NULL skips a channel that is not kept. */
        c->decode_to_ptr = k < 0 ? NULL : (uint8_t *)(sk_image_pixel(im, x0, y0) + k);
    }
}

/* Decodes one chunk whose top-left pixel is (x0, y0) in image coordinates. */
static exr_result_t read_chunk(exr_reader *r, exr_decode_pipeline_t *dec,
                               const exr_chunk_info_t *cinfo, bool *first, int x0, int y0)
{
    if (x0 < 0 || y0 < 0 || cinfo->width < 1 || cinfo->height < 1 ||
        x0 + (int64_t)cinfo->width > r->width || y0 + (int64_t)cinfo->height > r->height)
        return EXR_ERR_CORRUPT_CHUNK;
    exr_result_t rv = *first ? exr_decoding_initialize(r->ctxt, 0, cinfo, dec)
                             : exr_decoding_update(r->ctxt, 0, cinfo, dec);
    if (rv != EXR_ERR_SUCCESS) return rv;
    bind_channels(r, dec, x0, y0);
    if (*first) {
        rv = exr_decoding_choose_default_routines(r->ctxt, 0, dec);
        if (rv != EXR_ERR_SUCCESS) return rv;
        *first = false;
    }
    return exr_decoding_run(r->ctxt, 0, dec);
}

static exr_result_t read_pixels(exr_reader *r, exr_storage_t storage)
{
    exr_decode_pipeline_t dec = EXR_DECODE_PIPELINE_INITIALIZER;
    exr_chunk_info_t cinfo;
    bool first = true;
    exr_result_t rv = EXR_ERR_SUCCESS;
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t lines = 1;
        rv = exr_get_scanlines_per_chunk(r->ctxt, 0, &lines);
        if (rv == EXR_ERR_SUCCESS && lines < 1) rv = EXR_ERR_INVALID_ATTR;
        for (int64_t y = r->window.min.y; rv == EXR_ERR_SUCCESS && y <= r->window.max.y;
             y += lines) {
            rv = exr_read_scanline_chunk_info(r->ctxt, 0, (int)y, &cinfo);
            if (rv == EXR_ERR_SUCCESS)
                rv = read_chunk(r, &dec, &cinfo, &first, 0, cinfo.start_y - r->window.min.y);
        }
    } else {
        uint32_t tw = 0, th = 0;
        rv = exr_get_tile_descriptor(r->ctxt, 0, &tw, &th, NULL, NULL);
        if (rv == EXR_ERR_SUCCESS && (tw < 1 || th < 1)) rv = EXR_ERR_INVALID_ATTR;
        int64_t nx = rv == EXR_ERR_SUCCESS ? ((int64_t)r->width + tw - 1) / tw : 0;
        int64_t ny = rv == EXR_ERR_SUCCESS ? ((int64_t)r->height + th - 1) / th : 0;
        /* Level (0, 0) is the full-resolution image of a mipmapped or ripmapped file. */
        for (int64_t ty = 0; rv == EXR_ERR_SUCCESS && ty < ny; ty++)
            for (int64_t tx = 0; rv == EXR_ERR_SUCCESS && tx < nx; tx++) {
                rv = exr_read_tile_chunk_info(r->ctxt, 0, (int)tx, (int)ty, 0, 0, &cinfo);
                if (rv == EXR_ERR_SUCCESS)
                    rv = read_chunk(r, &dec, &cinfo, &first, (int)(tx * tw), (int)(ty * th));
            }
    }
    if (!first) exr_decoding_destroy(r->ctxt, &dec);
    return rv;
}

static void collect_metadata(exr_reader *r, sk_image_metadata *meta)
{
    int32_t count = 0;
    if (exr_get_attribute_count(r->ctxt, 0, &count) != EXR_ERR_SUCCESS) return;
    for (int32_t i = 0; i < count; i++) {
        const exr_attribute_t *a = NULL;
        if (exr_get_attribute_by_index(r->ctxt, 0, EXR_ATTR_LIST_FILE_ORDER, i, &a) !=
                EXR_ERR_SUCCESS ||
            !a || a->type != EXR_ATTR_STRING || !a->string || !a->name)
            continue;
        const char *s = a->string->str ? a->string->str : "";
        size_t len = a->string->length > 0 ? (size_t)a->string->length : 0;
        /* A string attribute may hold NUL bytes; metadata values are C strings. */
        size_t text_len = strnlen(s, len);
        sk__image_metadata_add_read(meta, a->name, strlen(a->name), s, text_len);
    }
}

/* The best compression ratio each method can reach (deflate 1032:1, EXR's RLE 64:1 on
 * 128-byte runs, B44A 32 bytes to 3); DWA stacks RLE and deflate, so it gets a loose
 * bound. A file smaller than its pixel data divided by this is not a valid file. */
static double max_ratio(exr_compression_t c)
{
    switch (c) {
    case EXR_COMPRESSION_NONE:
        return 1.0;
    case EXR_COMPRESSION_RLE:
        return 64.0;
    case EXR_COMPRESSION_B44:
    case EXR_COMPRESSION_B44A:
        return 16.0;
    case EXR_COMPRESSION_DWAA:
    case EXR_COMPRESSION_DWAB:
        return 65536.0;
    default:
        return 1032.0;
    }
}

/* Rejects a header whose pixel data the file cannot hold, before the image is allocated
 * (a few hundred bytes must not make the reader reserve gigabytes). */
static sk_result check_file_holds_pixels(exr_reader *r, int64_t w, int64_t h)
{
    const exr_attr_chlist_t *list = NULL;
    exr_compression_t compression = EXR_COMPRESSION_NONE;
    if (exr_get_channels(r->ctxt, 0, &list) != EXR_ERR_SUCCESS ||
        exr_get_compression(r->ctxt, 0, &compression) != EXR_ERR_SUCCESS)
        return sk_fail(r->err, SK_ERROR_PARSE, "%s: bad header", r->path);
    double raw = 0.0;
    for (int i = 0; i < list->num_channels; i++) {
        const exr_attr_chlist_entry_t *e = &list->entries[i];
        double xs = e->x_sampling > 0 ? e->x_sampling : 1,
               ys = e->y_sampling > 0 ? e->y_sampling : 1;
        raw += ceil((double)w / xs) * ceil((double)h / ys) *
               (e->pixel_type == EXR_PIXEL_HALF ? 2.0 : 4.0);
    }
    if (raw > max_ratio(compression) * (double)r->io.size + 65536.0)
        return sk_fail(r->err, SK_ERROR_PARSE,
                       "%s: the header claims %.0f bytes of pixels, more than the %lld-byte "
                       "file can hold",
                       r->path, raw, (long long)r->io.size);
    return SK_OK;
}

static sk_result read_image(exr_reader *r, sk_image_metadata *meta)
{
    const char *p = r->path;
    int parts = 0;
    exr_result_t rv = exr_get_count(r->ctxt, &parts);
    if (rv != EXR_ERR_SUCCESS)
        return sk__exr_fail(r->err, &r->io, rv, SK_ERROR_PARSE, p, "bad header");
    if (parts != 1)
        return sk_fail(r->err, SK_ERROR_UNSUPPORTED,
                       "%s: multi-part EXR (%d parts) is not supported", p, parts);
    exr_storage_t storage;
    rv = exr_get_storage(r->ctxt, 0, &storage);
    if (rv != EXR_ERR_SUCCESS)
        return sk__exr_fail(r->err, &r->io, rv, SK_ERROR_PARSE, p, "bad header");
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return sk_fail(r->err, SK_ERROR_UNSUPPORTED, "%s: deep EXR images are not supported", p);
    rv = exr_get_data_window(r->ctxt, 0, &r->window);
    if (rv != EXR_ERR_SUCCESS)
        return sk__exr_fail(r->err, &r->io, rv, SK_ERROR_PARSE, p, "bad header");
    int64_t w = (int64_t)r->window.max.x - r->window.min.x + 1;
    int64_t h = (int64_t)r->window.max.y - r->window.min.y + 1;
    sk_result res = select_channels(r);
    if (res != SK_OK) return res;
    /* Before anything is allocated for pixels. */
    if (w < 1 || h < 1)
        return sk_fail(r->err, SK_ERROR_PARSE, "%s: data window (%d, %d) - (%d, %d) is empty", p,
                       r->window.min.x, r->window.min.y, r->window.max.x, r->window.max.y);
    res = sk__image_check_size(w, h, r->channels, r->err);
    if (res != SK_OK) {
        sk_error_prefix(r->err, res, "%s: data window", p);
        return res;
    }
    res = check_file_holds_pixels(r, w, h);
    if (res != SK_OK) return res;
    r->width = (int)w;
    r->height = (int)h;
    res = sk_image_create(r->image, r->width, r->height, r->channels, r->err);
    if (res != SK_OK) return res;
    rv = read_pixels(r, storage);
    if (rv != EXR_ERR_SUCCESS)
        return sk__exr_fail(r->err, &r->io, rv, SK_ERROR_PARSE, p, "malformed or truncated EXR");
    if (meta) collect_metadata(r, meta);
    return SK_OK;
}

sk_result sk_image_read_exr(sk_image *image, const char *path, sk_image_metadata *metadata,
                            sk_error *err)
{
    if (!image || !path)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "image and path must not be NULL");
    memset(image, 0, sizeof *image);
    if (metadata) memset(metadata, 0, sizeof *metadata);
    exr_reader r;
    memset(&r, 0, sizeof r);
    r.path = path;
    r.err = err;
    r.image = image;
    long long file_size;
    sk_result opened = sk_open_regular_fd(path, &r.io.fd, &file_size, err);
    if (opened != SK_OK) return opened;
    r.io.size = (int64_t)file_size;
    exr_context_initializer_t init = sk__exr_initializer(&r.io, false);
    exr_result_t rv = exr_start_read(&r.ctxt, path, &init);
    sk_result result;
    if (rv != EXR_ERR_SUCCESS)
        result = sk__exr_fail(err, &r.io, rv, SK_ERROR_PARSE, path, "not a valid EXR file");
    else
        result = read_image(&r, metadata);
    if (r.ctxt) exr_finish(&r.ctxt);
    close(r.io.fd);
    if (result != SK_OK) {
        sk_image_free(image);
        if (metadata) memset(metadata, 0, sizeof *metadata);
    }
    return result;
}
