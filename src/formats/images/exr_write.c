/* OpenEXR writer (C API): one scanline or tiled part, FLOAT or HALF channels, NONE / RLE /
 * ZIPS / ZIP / PIZ compression, string attributes for metadata, written atomically
 * through pwrite. */
#define _POSIX_C_SOURCE 200809L
#include <libdeflate.h>
#include <stdlib.h>
#include <string.h>

#include "formats/images/exr_internal.h"
#include "base/image_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* Names of the attributes EXR itself defines for a single-part image; metadata must not
 * take them over. */
static const char *const reserved_names[] = {"channels",
                                             "compression",
                                             "dataWindow",
                                             "displayWindow",
                                             "lineOrder",
                                             "pixelAspectRatio",
                                             "screenWindowCenter",
                                             "screenWindowWidth",
                                             "tiles",
                                             "name",
                                             "type",
                                             "version",
                                             "chunkCount",
                                             "maxSamplesPerPixel"};

static const char *const default_names[5][4] = {
    {NULL}, {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};

typedef struct exr_writer {
    const sk_image *image;
    const char *names[4];
    exr_pixel_type_t pixel_type;
    exr_compression_t compression;
    int zip_level; /* deflate level of ZIP / ZIPS */
    int tile_size;
    const sk_image_metadata *metadata;
    bool long_names;
} exr_writer;

static sk_result check_desc(exr_writer *w, const sk_exr_write_desc *desc, sk_error *err)
{
    sk_exr_write_desc d = {0};
    if (desc) d = *desc;
    switch (d.pixel_type) {
    case SK_EXR_PIXEL_DEFAULT:
    case SK_EXR_PIXEL_FLOAT:
        w->pixel_type = EXR_PIXEL_FLOAT;
        break;
    case SK_EXR_PIXEL_HALF:
        w->pixel_type = EXR_PIXEL_HALF;
        break;
    default:
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "pixel_type = %d is not a sk_exr_pixel_type",
                       (int)d.pixel_type);
    }
    /* The default favours speed: ZIP at deflate level 1 writes a float map in about
       three quarters of the time of level 4 for files a few percent larger, and a
       quarter of the size of an uncompressed one for shaded images (docs/images.md,
       "EXR compression"). */
    int default_level = 4;
    switch (d.compression) {
    case SK_EXR_COMPRESSION_NONE:
        w->compression = EXR_COMPRESSION_NONE;
        break;
    case SK_EXR_COMPRESSION_DEFAULT:
        w->compression = EXR_COMPRESSION_ZIP;
        default_level = 1;
        break;
    case SK_EXR_COMPRESSION_ZIP:
        w->compression = EXR_COMPRESSION_ZIP;
        break;
    case SK_EXR_COMPRESSION_PIZ:
        w->compression = EXR_COMPRESSION_PIZ;
        break;
    case SK_EXR_COMPRESSION_RLE:
        w->compression = EXR_COMPRESSION_RLE;
        break;
    case SK_EXR_COMPRESSION_ZIPS:
        w->compression = EXR_COMPRESSION_ZIPS;
        break;
    default:
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "compression = %d is not a sk_exr_compression", (int)d.compression);
    }
    if (d.compression_level != 0 &&
        sk_check_range_i(err, "compression_level", d.compression_level, 1, 9) != SK_OK)
        return SK_ERROR_INVALID_ARGUMENT;
    w->zip_level = d.compression_level ? d.compression_level : default_level;
    if (d.tile_size != 0 && (d.tile_size < 8 || d.tile_size > 4096))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "tile_size = %d is out of range [8, 4096] (0 = scanlines)", d.tile_size);
    w->tile_size = d.tile_size;
    int channels = w->image->channels;
    for (int c = 0; c < channels; c++) {
        const char *name = d.channel_names ? d.channel_names[c] : default_names[channels][c];
        size_t len = name ? strlen(name) : 0;
        if (len == 0 || len > 255)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "channel_names[%d] must be 1-255 bytes long", c);
        for (int k = 0; k < c; k++)
            if (strcmp(w->names[k], name) == 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "channel_names[%d] = \"%s\" repeats channel_names[%d]", c, name, k);
        if (len > 31) w->long_names = true;
        w->names[c] = name;
    }
    w->metadata = d.metadata;
    if (d.metadata) {
        if (d.metadata->count < 0 || d.metadata->count > SK_IMAGE_MAX_METADATA)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "metadata count = %d is out of range [0, %d]", d.metadata->count,
                           SK_IMAGE_MAX_METADATA);
        for (int i = 0; i < d.metadata->count; i++) {
            const sk_image_metadata_entry *e = &d.metadata->entries[i];
            size_t len = strnlen(e->key, sizeof e->key);
            if (len == 0 || len == sizeof e->key ||
                strnlen(e->value, sizeof e->value) == sizeof e->value)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "metadata entry %d has an empty or unterminated key or value", i);
            if (len > 31) w->long_names = true;
            for (size_t k = 0; k < sizeof reserved_names / sizeof reserved_names[0]; k++)
                if (strcmp(e->key, reserved_names[k]) == 0)
                    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                                   "metadata key \"%s\" is an attribute EXR defines itself",
                                   e->key);
        }
    }
    return SK_OK;
}

/* Points each channel of the encoder at the interleaved floats of the block starting at
 * pixel (x0, y0); the library converts to HALF where the file wants it. */
static void bind_channels(const exr_writer *w, exr_encode_pipeline_t *enc, int x0, int y0)
{
    const sk_image *im = w->image;
    for (int i = 0; i < enc->channel_count; i++) {
        exr_coding_channel_info_t *c = &enc->channels[i];
        int k = 0;
        while (k < im->channels - 1 && strcmp(w->names[k], c->channel_name) != 0) k++;
        c->user_data_type = EXR_PIXEL_FLOAT;
        c->user_bytes_per_element = 4;
        c->user_pixel_stride = (int32_t)(im->channels * (int)sizeof(float));
        c->user_line_stride = (int32_t)((size_t)im->width * (size_t)im->channels * sizeof(float));
        c->encode_from_ptr = (const uint8_t *)(sk_image_pixel(im, x0, y0) + k);
    }
}

/* Chunks encoded before they are written, by raw bytes: bounds the memory held at once. */
#define CHUNK_BYTES_IN_FLIGHT ((size_t)16 << 20)

/* One chunk: where it is, and its encoded bytes once done. */
typedef struct chunk_slot {
    exr_chunk_info_t info;
    int x0, y0, tx, ty;
    uint8_t *bytes;
    size_t size;
} chunk_slot;

/* What a thread encodes chunks with; the deflate state first, so that the pipeline's
 * user data serves sk__exr_zip_compress as well. */
typedef struct chunk_worker {
    sk__exr_zip zip;
    const exr_writer *writer;
    exr_encode_pipeline_t enc;
    bool started;
    chunk_slot *slot; /* the chunk being encoded */
} chunk_worker;

/* The pipeline's last stage: keep the chunk's bytes instead of writing them (they are
 * written in order afterwards). */
static exr_result_t keep_chunk(exr_encode_pipeline_t *encode)
{
    chunk_worker *w = encode->encoding_user_data;
    chunk_slot *slot = w->slot;
    if (w->zip.chunk && encode->compressed_buffer == w->zip.chunk) {
        slot->bytes = w->zip.chunk; /* ours already */
        w->zip.chunk = NULL;
    } else {
        slot->bytes = malloc(encode->compressed_bytes ? encode->compressed_bytes : 1);
        if (!slot->bytes) return EXR_ERR_OUT_OF_MEMORY;
        memcpy(slot->bytes, encode->compressed_buffer, encode->compressed_bytes);
    }
    slot->size = encode->compressed_bytes;
    return EXR_ERR_SUCCESS;
}

static exr_result_t encode_chunk(chunk_worker *w, exr_const_context_t ctxt, chunk_slot *slot)
{
    exr_encode_pipeline_t *enc = &w->enc;
    exr_result_t rv = w->started ? exr_encoding_update(ctxt, 0, &slot->info, enc)
                                 : exr_encoding_initialize(ctxt, 0, &slot->info, enc);
    if (rv != EXR_ERR_SUCCESS) return rv;
    bind_channels(w->writer, enc, slot->x0, slot->y0);
    if (!w->started) {
        rv = exr_encoding_choose_default_routines(ctxt, 0, enc);
        if (rv != EXR_ERR_SUCCESS) return rv;
        w->started = true;
        enc->encoding_user_data = w;
        if (w->zip.compressor) enc->compress_fn = sk__exr_zip_compress;
        enc->yield_until_ready_fn = NULL;
        enc->write_fn = keep_chunk;
    }
    w->slot = slot;
    return exr_encoding_run(ctxt, 0, enc);
}

static exr_result_t write_slot(const exr_writer *w, exr_context_t ctxt, const chunk_slot *slot)
{
    if (w->tile_size == 0)
        return exr_write_scanline_chunk(ctxt, 0, slot->y0, slot->bytes, slot->size);
    return exr_write_tile_chunk(ctxt, 0, slot->tx, slot->ty, 0, 0, slot->bytes, slot->size);
}

/* Encodes the chunks in parallel (each thread its own pipeline and, for ZIP and ZIPS,
 * its own libdeflate compressor) and writes them in order, a bounded number at a time.
 * A chunk's bytes depend only on its pixels, so the file does not depend on the thread
 * count. */
static exr_result_t write_pixels(const exr_writer *w, exr_context_t ctxt)
{
    const sk_image *im = w->image;
    int chunks, per_row = 1;
    int32_t lines = 1;
    if (w->tile_size == 0) {
        exr_result_t rv = exr_get_scanlines_per_chunk(ctxt, 0, &lines);
        if (rv != EXR_ERR_SUCCESS) return rv;
        chunks = (im->height + lines - 1) / lines;
    } else {
        per_row = (im->width + w->tile_size - 1) / w->tile_size;
        chunks = per_row * ((im->height + w->tile_size - 1) / w->tile_size);
    }
    size_t chunk_bytes = (size_t)im->width * (size_t)im->channels * sizeof(float) *
                         (size_t)(w->tile_size ? w->tile_size : lines);
    int in_flight = (int)(CHUNK_BYTES_IN_FLIGHT / chunk_bytes);
    if (in_flight < 1) in_flight = 1;
    if (in_flight > chunks) in_flight = chunks;
    chunk_slot *slots = calloc((size_t)in_flight, sizeof *slots);
    if (!slots) return EXR_ERR_OUT_OF_MEMORY;
    bool zip = w->compression == EXR_COMPRESSION_ZIP || w->compression == EXR_COMPRESSION_ZIPS;
    exr_result_t result = EXR_ERR_SUCCESS;
    /* images of a megabyte or less are encoded on the calling thread */
    bool parallel = chunks > 1 && (size_t)im->width * im->height * im->channels * sizeof(float) >
                                      ((size_t)1 << 20);
#pragma omp parallel if (parallel)
    {
        chunk_worker wk;
        memset(&wk, 0, sizeof wk);
        wk.writer = w;
        if (zip && !(wk.zip.compressor = libdeflate_alloc_compressor(w->zip_level))) {
#pragma omp critical(sk_exr_result)
            result = EXR_ERR_OUT_OF_MEMORY;
        }
        for (int g = 0; g < chunks; g += in_flight) {
            int count = chunks - g < in_flight ? chunks - g : in_flight;
#pragma omp single
            for (int k = 0; k < count && result == EXR_ERR_SUCCESS; k++) {
                chunk_slot *slot = &slots[k];
                int c = g + k;
                if (w->tile_size == 0) {
                    slot->x0 = 0;
                    slot->y0 = c * lines;
                    result = exr_write_scanline_chunk_info(ctxt, 0, slot->y0, &slot->info);
                } else {
                    slot->tx = c % per_row;
                    slot->ty = c / per_row;
                    slot->x0 = slot->tx * w->tile_size;
                    slot->y0 = slot->ty * w->tile_size;
                    result =
                        exr_write_tile_chunk_info(ctxt, 0, slot->tx, slot->ty, 0, 0, &slot->info);
                }
            }
#pragma omp for schedule(dynamic, 1)
            for (int k = 0; k < count; k++) {
                exr_result_t seen;
#pragma omp atomic read
                seen = result;
                if (seen != EXR_ERR_SUCCESS) continue;
                exr_result_t rv = encode_chunk(&wk, ctxt, &slots[k]);
                if (rv != EXR_ERR_SUCCESS) {
#pragma omp critical(sk_exr_result)
                    if (result == EXR_ERR_SUCCESS) result = rv;
                }
            }
#pragma omp single
            for (int k = 0; k < count; k++) {
                if (result == EXR_ERR_SUCCESS) result = write_slot(w, ctxt, &slots[k]);
                free(slots[k].bytes);
                slots[k].bytes = NULL;
            }
        }
        if (wk.started) exr_encoding_destroy(ctxt, &wk.enc);
        if (wk.zip.compressor) libdeflate_free_compressor(wk.zip.compressor);
        free(wk.zip.scratch);
        free(wk.zip.chunk);
    }
    free(slots);
    return result;
}

static exr_result_t define_part(const exr_writer *w, exr_context_t ctxt, const char **step)
{
    int part = 0;
    const sk_image *im = w->image;
    *step = "cannot define the image";
    exr_result_t rv =
        exr_add_part(ctxt, NULL, w->tile_size ? EXR_STORAGE_TILED : EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS && w->long_names) rv = exr_set_longname_support(ctxt, 1);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctxt, part, im->width, im->height, w->compression);
    if (rv == EXR_ERR_SUCCESS &&
        (w->compression == EXR_COMPRESSION_ZIP || w->compression == EXR_COMPRESSION_ZIPS))
        rv = exr_set_zip_compression_level(ctxt, part, w->zip_level);
    if (rv == EXR_ERR_SUCCESS && w->tile_size)
        rv = exr_set_tile_descriptor(ctxt, part, (uint32_t)w->tile_size, (uint32_t)w->tile_size,
                                     EXR_TILE_ONE_LEVEL, EXR_TILE_ROUND_DOWN);
    for (int c = 0; rv == EXR_ERR_SUCCESS && c < im->channels; c++)
        rv = exr_add_channel(ctxt, part, w->names[c], w->pixel_type, EXR_PERCEPTUALLY_LOGARITHMIC,
                             1, 1);
    if (rv != EXR_ERR_SUCCESS) return rv;
    *step = "cannot store metadata";
    for (int i = 0; rv == EXR_ERR_SUCCESS && w->metadata && i < w->metadata->count; i++)
        rv = exr_attr_set_string(ctxt, part, w->metadata->entries[i].key,
                                 w->metadata->entries[i].value);
    if (rv != EXR_ERR_SUCCESS) return rv;
    *step = "cannot write the header";
    return exr_write_header(ctxt);
}

sk_result sk_image_write_exr(const sk_image *image, const char *path, const sk_exr_write_desc *desc,
                             sk_error *err)
{
    sk_result r = sk__image_validate(image, err);
    if (r != SK_OK) return r;
    if (!path) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "output path is NULL");
    exr_writer w;
    memset(&w, 0, sizeof w);
    w.image = image;
    r = check_desc(&w, desc, err);
    if (r != SK_OK) return r;

    sk_atomic_file file;
    r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    sk__exr_io io;
    memset(&io, 0, sizeof io);
    io.fd = fileno(file.fp);
    exr_context_initializer_t init = sk__exr_initializer(&io, true);
    exr_context_t ctxt = NULL;
    const char *step = "cannot start writing";
    exr_result_t rv = exr_start_write(&ctxt, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS) rv = define_part(&w, ctxt, &step);
    if (rv == EXR_ERR_SUCCESS) {
        step = "cannot write pixels";
        rv = write_pixels(&w, ctxt);
    }
    /* exr_finish writes the chunk offset table, so its result matters too. */
    exr_result_t finish = ctxt ? exr_finish(&ctxt) : EXR_ERR_SUCCESS;
    if (rv == EXR_ERR_SUCCESS && finish != EXR_ERR_SUCCESS) {
        rv = finish;
        step = "cannot finish the file";
    }
    if (rv != EXR_ERR_SUCCESS) {
        sk_atomic_file_abort(&file);
        sk_result fallback = rv == EXR_ERR_WRITE_IO ? SK_ERROR_IO : SK_ERROR_INVALID_ARGUMENT;
        return sk__exr_fail(err, &io, rv, fallback, path, step);
    }
    return sk_atomic_file_commit(&file, err);
}
