/* shitsukan images: float images with 1-4 interleaved channels, PNG (8/16-bit; read with
 * libpng, written by our own encoder with libdeflate) and OpenEXR (32-bit float / 16-bit
 * half, OpenEXR's C API) readers and writers, with text metadata (PNG tEXt/iTXt chunks,
 * EXR string attributes).
 *
 * Thread-safety: all functions are thread-safe on distinct images. */
#ifndef SHITSUKAN_IMAGE_H
#define SHITSUKAN_IMAGE_H

#include "shitsukan/core.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Caps on what sk_image_create (and every reader) accepts; larger requests fail with
 * SK_ERROR_LIMIT before allocating. */
#define SK_IMAGE_MAX_DIMENSION 65536
#define SK_IMAGE_MAX_BYTES (8ull << 30) /* 8 GiB of float samples */

/* Row-major, top row first, channels interleaved: pixel (x, y) channel c is
 * data[((size_t)y * width + x) * channels + c]. Values are linear unless a writer is
 * told otherwise. 1 channel = grey/value, 2 = grey + alpha, 3 = RGB, 4 = RGBA. */
typedef struct sk_image {
    int width, height, channels;
    float *data;
} sk_image;

/* Allocates a zero-filled image (1 <= channels <= 4, 1 <= width, height <= 65536). */
sk_result sk_image_create(sk_image *image, int width, int height, int channels, sk_error *err);
void sk_image_free(sk_image *image);
static inline float *sk_image_pixel(const sk_image *image, int x, int y)
{
    return image->data + ((size_t)y * (size_t)image->width + (size_t)x) * (size_t)image->channels;
}

/* Key/value text stored with an image (e.g. "shitsukan:height_scale_mm" = "0.120"). */

/* Metadata keys that mean the same thing in every module's maps. */
#define SK_IMAGE_KEY_MM_PER_PIXEL "shitsukan:mm_per_pixel" /* size of one pixel in mm */
#define SK_IMAGE_MAX_METADATA 32
typedef struct sk_image_metadata_entry {
    char key[80];
    char value[400];
} sk_image_metadata_entry;
typedef struct sk_image_metadata {
    int count;
    sk_image_metadata_entry entries[SK_IMAGE_MAX_METADATA];
} sk_image_metadata;

/* Adds or replaces an entry; fails with SK_ERROR_LIMIT when full or too long. */
sk_result sk_image_metadata_set(sk_image_metadata *meta, const char *key, const char *value,
                                sk_error *err);
/* NULL if absent. */
const char *sk_image_metadata_get(const sk_image_metadata *meta, const char *key);

/* ------------------------------------------------------------------------ PNG */
typedef enum sk_png_encoding {
    SK_PNG_ENCODING_DEFAULT = 0, /* = SK_PNG_ENCODING_SRGB */
    SK_PNG_ENCODING_SRGB,        /* data is linear; written with the sRGB transfer curve
                                    (alpha stays linear) and an sRGB chunk */
    SK_PNG_ENCODING_LINEAR       /* data written as is (height maps, normal maps, masks) */
} sk_png_encoding;

typedef struct sk_png_write_desc {
    int bit_depth;                     /* 8 or 16; 0 = 8 */
    sk_png_encoding encoding;          /* 0 = sRGB */
    const sk_image_metadata *metadata; /* optional tEXt chunks */
    int compression_level;             /* deflate level 1 (fastest) .. 9 (smallest) of libdeflate;
                                          0 = 6 (within a few percent of libpng's size at zlib
                                          level 6, about twice as fast). Level 1 is about twice
                                          as fast again for files 5-40 % larger; 9 is many times
                                          slower (docs/images.md). */
} sk_png_write_desc;

/* Values are clamped to [0, 1] (NaN to 0) and rounded to the nearest code (sRGB codes by
 * an exact table of the curve's code boundaries). Every row uses the Up filter; images
 * of more than about a megabyte of rows are compressed in strips in parallel (OpenMP),
 * joined into one zlib stream: the file's bytes depend on the image and desc only, not
 * on the thread count. Metadata keys
 * must be PNG keywords (1-79 printable ASCII characters, no leading, trailing or double
 * spaces) and values UTF-8: ASCII values go into tEXt chunks, others into iTXt chunks.
 * Linear files carry no colour-space chunk (no sRGB, no gAMA). `desc` may be NULL. */
sk_result sk_image_write_png(const sk_image *image, const char *path, const sk_png_write_desc *desc,
                             sk_error *err);
/* The same bytes into memory (e.g. to embed in a glTF file): *out_data (free with free())
 * and *out_size, which are NULL and 0 on failure. */
sk_result sk_image_write_png_memory(const sk_image *image, const sk_png_write_desc *desc,
                                    uint8_t **out_data, size_t *out_size, sk_error *err);

/* An image given row by row, for files derived from data kept in another form (a map
 * stored as 16-bit codes, normals shaded on the way out): no float copy of the whole
 * image is made. get_row writes row y (top first) as width * channels floats; the writer
 * calls it from several threads at once, for any row in any order and possibly more than
 * once, so it must be thread-safe and give the same values each time. */
typedef struct sk_image_rows {
    int width, height, channels;
    void (*get_row)(void *user, int y, float *row);
    void *user;
} sk_image_rows;

/* The same file as sk_image_write_png of the image the rows make. */
sk_result sk_image_write_png_rows(const sk_image_rows *rows, const char *path,
                                  const sk_png_write_desc *desc, sk_error *err);

typedef struct sk_png_read_desc {
    sk_png_encoding encoding; /* 0 = sRGB: decode 8/16-bit sRGB codes to linear floats;
                                 LINEAR: code / max_code */
} sk_png_read_desc;

/* Reads any PNG (grey, grey+alpha, RGB, RGBA, palette; 1-16 bits) into floats; palette
 * images become RGB/RGBA. `metadata` (optional) receives the tEXt/zTXt/iTXt chunks,
 * `bit_depth` (optional) the file's bit depth. `desc` may be NULL.
 *
 * A tRNS chunk becomes an alpha channel; alpha is always linear (code / max). The
 * encoding in `desc` decides how colour codes are decoded; the file's own sRGB/gAMA/iCCP
 * chunks are not applied. Text is returned as UTF-8 (tEXt/zTXt are converted from
 * Latin-1), over-long keys and values are cut to fit, entries beyond the 32nd dropped.
 * Errors: a missing file is SK_ERROR_NOT_FOUND, another open failure SK_ERROR_IO, a size
 * beyond the caps SK_ERROR_LIMIT (checked from the header, before allocating), anything
 * malformed or truncated SK_ERROR_PARSE. */
sk_result sk_image_read_png(sk_image *image, const char *path, const sk_png_read_desc *desc,
                            sk_image_metadata *metadata, int *bit_depth, sk_error *err);

/* The integer codes the PNG writer stores for `pixels` x `channels` float samples
 * (interleaved): LINEAR round(v * max); SRGB (0 = default) the code nearest to
 * max * srgb(v) for colour channels, alpha (channel 2 of 2, 4 of 4) linear; values
 * clamped to [0, 1], NaN to 0. For callers that encode files themselves. */
void sk_image_codes8(const float *samples, size_t pixels, int channels, sk_png_encoding encoding,
                     uint8_t *codes);
void sk_image_codes16(const float *samples, size_t pixels, int channels, sk_png_encoding encoding,
                      uint16_t *codes);

/* ------------------------------------------------------------------------ EXR */
typedef enum sk_exr_pixel_type {
    SK_EXR_PIXEL_DEFAULT = 0, /* = FLOAT */
    SK_EXR_PIXEL_FLOAT,       /* 32-bit float */
    SK_EXR_PIXEL_HALF         /* 16-bit half float */
} sk_exr_pixel_type;

typedef enum sk_exr_compression {
    SK_EXR_COMPRESSION_DEFAULT = 0, /* = ZIP at level 1: see docs/images.md, "EXR compression" */
    SK_EXR_COMPRESSION_NONE,
    SK_EXR_COMPRESSION_ZIP, /* lossless deflate (libdeflate), 16 scanlines per block */
    SK_EXR_COMPRESSION_PIZ, /* lossless wavelet, good for noisy renders */
    SK_EXR_COMPRESSION_RLE, /* lossless run lengths (flat areas only) */
    SK_EXR_COMPRESSION_ZIPS /* lossless deflate, one scanline per block */
} sk_exr_compression;

typedef struct sk_exr_write_desc {
    sk_exr_pixel_type pixel_type;
    sk_exr_compression compression;
    /* Deflate level of ZIP and ZIPS, 1 (fastest) .. 9 (smallest); 0 = 1 for the default
       compression, 4 (OpenEXR's own default) when ZIP or ZIPS is asked for. */
    int compression_level;
    /* Channel names; NULL = by channel count: 1 "Y", 2 "Y","A", 3 "R","G","B",
       4 "R","G","B","A". */
    const char *const *channel_names;
    const sk_image_metadata *metadata; /* optional string attributes */
    /* 0 = scanline image; otherwise a tiled image (one level) with square tiles of this
       many pixels, range 8..4096 (texture caches read tiles faster). */
    int tile_size;
} sk_exr_write_desc;

/* Linear data is written as is (EXR is linear by convention); HALF rounds each float to
 * the nearest half (ties to even), values beyond +-65504 become +-infinity. Images of
 * more than a megabyte have their chunks encoded in parallel (OpenMP; ZIP and ZIPS by
 * libdeflate) and written in order: the bytes do not depend on the thread count. Channel names
 * must be unique and 1-255 bytes; metadata keys must not be EXR's own attribute names
 * (channels, compression, dataWindow, ...). `desc` may be NULL. */
sk_result sk_image_write_exr(const sk_image *image, const char *path, const sk_exr_write_desc *desc,
                             sk_error *err);

/* Reads a scanline or tiled single-part EXR (half, float or uint channels). Channels are
 * ordered as the writer names them (Y/R,G,B/A); other names follow alphabetically, up to
 * 4 channels. `metadata` (optional) receives the string attributes.
 *
 * The image is the data window (the display window is ignored); a tiled file gives its
 * full-resolution level. With more than 4 channels, Y, R, G, B and A are kept first, then
 * others alphabetically. Subsampled channels, deep and multi-part files are
 * SK_ERROR_UNSUPPORTED; a missing file SK_ERROR_NOT_FOUND; sizes beyond the caps
 * SK_ERROR_LIMIT; malformed or truncated files SK_ERROR_PARSE. */
sk_result sk_image_read_exr(sk_image *image, const char *path, sk_image_metadata *metadata,
                            sk_error *err);

/* Writes PNG or EXR by the path's extension (".png" -> sRGB 8-bit PNG, ".exr" -> float EXR). */
sk_result sk_image_write_auto(const sk_image *image, const char *path,
                              const sk_image_metadata *metadata, sk_error *err);

/* sRGB transfer functions (IEC 61966-2-1): 12.92 x below 0.0031308, else
 * 1.055 x^(1/2.4) - 0.055, and the exact inverse. Not clamped: the linear segment also
 * serves negative values and the power segment continues above 1; NaN stays NaN. */
float sk_srgb_from_linear(float linear);
float sk_linear_from_srgb(float encoded);

#ifdef __cplusplus
}
#endif

#endif /* SHITSUKAN_IMAGE_H */
