/* Float images: allocation within the caps of image.h, text metadata, the sRGB transfer
 * curve of IEC 61966-2-1 and writing by file extension. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/image_internal.h"
#include "base/io_internal.h"
#include "shitsukan/image.h"

sk_result sk__image_check_size(long long width, long long height, int channels, sk_error *err)
{
    if (channels < 1 || channels > 4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "channels = %d is out of range [1, 4]",
                       channels);
    if (width < 1 || height < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "image size %lld x %lld: width and height must be at least 1", width,
                       height);
    if (width > SK_IMAGE_MAX_DIMENSION || height > SK_IMAGE_MAX_DIMENSION)
        return sk_fail(err, SK_ERROR_LIMIT, "image size %lld x %lld exceeds the cap of %d per side",
                       width, height, SK_IMAGE_MAX_DIMENSION);
    size_t bytes;
    if (!sk_size_mul((size_t)width, (size_t)height, &bytes) ||
        !sk_size_mul(bytes, (size_t)channels * sizeof(float), &bytes) ||
        (unsigned long long)bytes > SK_IMAGE_MAX_BYTES)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "image of %lld x %lld x %d floats exceeds the cap of %llu bytes", width,
                       height, channels, (unsigned long long)SK_IMAGE_MAX_BYTES);
    return SK_OK;
}

sk_result sk_image_create(sk_image *image, int width, int height, int channels, sk_error *err)
{
    if (!image) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "image is NULL");
    memset(image, 0, sizeof *image);
    sk_result r = sk__image_check_size(width, height, channels, err);
    if (r != SK_OK) return r;
    size_t count = (size_t)width * (size_t)height * (size_t)channels;
    float *data = calloc(count, sizeof(float));
    if (!data)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for a %d x %d x %d image", width,
                       height, channels);
    image->width = width;
    image->height = height;
    image->channels = channels;
    image->data = data;
    return SK_OK;
}

void sk_image_free(sk_image *image)
{
    if (!image) return;
    free(image->data);
    memset(image, 0, sizeof *image);
}

sk_result sk__image_validate(const sk_image *image, sk_error *err)
{
    if (!image) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "image is NULL");
    sk_result r = sk__image_check_size(image->width, image->height, image->channels, err);
    if (r != SK_OK) return r;
    if (!image->data) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "image has no data");
    return SK_OK;
}

/* ------------------------------------------------------------------ metadata */

sk_result sk_image_metadata_set(sk_image_metadata *meta, const char *key, const char *value,
                                sk_error *err)
{
    if (!meta || !key || !value)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "metadata, key and value must not be NULL");
    if (!key[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "metadata key is empty");
    size_t key_len = strlen(key), value_len = strlen(value);
    if (key_len >= sizeof meta->entries[0].key)
        return sk_fail(err, SK_ERROR_LIMIT, "metadata key \"%.40s...\" is %zu bytes, at most %zu",
                       key, key_len, sizeof meta->entries[0].key - 1);
    if (value_len >= sizeof meta->entries[0].value)
        return sk_fail(err, SK_ERROR_LIMIT, "metadata value of \"%s\" is %zu bytes, at most %zu",
                       key, value_len, sizeof meta->entries[0].value - 1);
    if (meta->count < 0 || meta->count > SK_IMAGE_MAX_METADATA)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "metadata count = %d is out of range [0, %d]", meta->count,
                       SK_IMAGE_MAX_METADATA);
    int slot = meta->count;
    for (int i = 0; i < meta->count; i++)
        if (strcmp(meta->entries[i].key, key) == 0) slot = i;
    if (slot == SK_IMAGE_MAX_METADATA)
        return sk_fail(err, SK_ERROR_LIMIT, "metadata is full (%d entries); cannot add \"%s\"",
                       SK_IMAGE_MAX_METADATA, key);
    memcpy(meta->entries[slot].key, key, key_len + 1);
    memcpy(meta->entries[slot].value, value, value_len + 1);
    if (slot == meta->count) meta->count++;
    return SK_OK;
}

const char *sk_image_metadata_get(const sk_image_metadata *meta, const char *key)
{
    if (!meta || !key) return NULL;
    for (int i = 0; i < meta->count && i < SK_IMAGE_MAX_METADATA; i++)
        if (strcmp(meta->entries[i].key, key) == 0) return meta->entries[i].value;
    return NULL;
}

/* Copies at most `cap - 1` bytes of `src` (length `len`) into `dst`, never cutting a UTF-8
 * sequence in half, and NUL-terminates. */
static void copy_utf8_truncated(char *dst, size_t cap, const char *src, size_t len)
{
    size_t n = len < cap - 1 ? len : cap - 1;
    if (n < len)
        while (n > 0 && ((unsigned char)src[n] & 0xc0) == 0x80) n--;
    memcpy(dst, src, n);
    dst[n] = '\0';
}

void sk__image_metadata_add_read(sk_image_metadata *meta, const char *key, size_t key_len,
                                 const char *value, size_t value_len)
{
    if (!meta || key_len == 0) return;
    char k[sizeof meta->entries[0].key];
    copy_utf8_truncated(k, sizeof k, key, key_len);
    int slot = meta->count;
    for (int i = 0; i < meta->count; i++)
        if (strcmp(meta->entries[i].key, k) == 0) slot = i;
    if (slot >= SK_IMAGE_MAX_METADATA) return;
    memcpy(meta->entries[slot].key, k, sizeof k);
    copy_utf8_truncated(meta->entries[slot].value, sizeof meta->entries[slot].value, value,
                        value_len);
    if (slot == meta->count) meta->count++;
}

/* ------------------------------------------------------------------ sRGB */

/* IEC 61966-2-1 piecewise curve, evaluated in double so that the float result is the
 * rounded value of the exact curve (up to pow's own error). The linear segment also
 * covers negative inputs and the power segment extends above 1 (no clamping here). */
double sk__srgb_encode(double linear)
{
    if (linear <= 0.0031308) return 12.92 * linear;
    return 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

double sk__srgb_decode(double encoded)
{
    if (encoded <= 0.04045) return encoded / 12.92;
    return pow((encoded + 0.055) / 1.055, 2.4);
}

float sk_srgb_from_linear(float linear)
{
    return isnan(linear) ? linear : (float)sk__srgb_encode(linear);
}

float sk_linear_from_srgb(float encoded)
{
    return isnan(encoded) ? encoded : (float)sk__srgb_decode(encoded);
}

/* ------------------------------------------------------------------ by extension */
