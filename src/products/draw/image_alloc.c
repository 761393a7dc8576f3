/* Allocation and checking of the images the draw module creates or reads (sizes capped
 * by SK_IMAGE_MAX_DIMENSION and SK_IMAGE_MAX_BYTES, overflow-checked). */
#include <stdlib.h>

#include "products/draw/draw_internal.h"

static sk_result check_size(int width, int height, int channels, const char *what, size_t *bytes,
                            sk_error *err)
{
    if (channels < 1 || channels > 4)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s channels = %d is out of range [1, 4]",
                       what, channels);
    if (width < 1 || height < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s size %d x %d is invalid (width and height must be at least 1)", what,
                       width, height);
    if (width > SK_IMAGE_MAX_DIMENSION || height > SK_IMAGE_MAX_DIMENSION)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "%s size %d x %d exceeds the limit of %d pixels per side", what, width,
                       height, SK_IMAGE_MAX_DIMENSION);
    size_t n;
    if (!sk_size_mul((size_t)width, (size_t)height, &n) || !sk_size_mul(n, (size_t)channels, &n) ||
        !sk_size_mul(n, sizeof(float), &n) || n > SK_IMAGE_MAX_BYTES)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "%s of %d x %d x %d floats exceeds the limit of %llu bytes", what, width,
                       height, channels, (unsigned long long)SK_IMAGE_MAX_BYTES);
    *bytes = n;
    return SK_OK;
}

sk_result sk__image_alloc(sk_image *img, int width, int height, int channels, const char *what,
                          sk_error *err)
{
    size_t bytes = 0;
    sk_result r = check_size(width, height, channels, what, &bytes, err);
    if (r != SK_OK) return r;
    float *data = calloc(bytes / sizeof(float), sizeof(float));
    if (!data)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: cannot allocate %d x %d x %d floats", what,
                       width, height, channels);
    img->width = width;
    img->height = height;
    img->channels = channels;
    img->data = data;
    return SK_OK;
}

sk_result sk__image_check(const sk_image *img, const char *name, sk_error *err)
{
    if (!img) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is NULL", name);
    size_t bytes = 0;
    sk_result r = check_size(img->width, img->height, img->channels, name, &bytes, err);
    if (r != SK_OK) return r;
    if (!img->data) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s has no pixel data", name);
    return SK_OK;
}
