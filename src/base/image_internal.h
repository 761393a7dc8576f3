/* Private helpers shared by the image readers and writers (not installed). */
#ifndef SK_IO_IMAGE_INTERNAL_H
#define SK_IO_IMAGE_INTERNAL_H

#include <stddef.h>

#include "shitsukan/image.h"

/* Checks an image size against the caps of image.h without allocating: SK_ERROR_LIMIT
 * beyond the caps, SK_ERROR_INVALID_ARGUMENT for sizes below 1 or channels outside 1-4.
 * Readers call it with the sizes from a file header before allocating anything. */
sk_result sk__image_check_size(long long width, long long height, int channels, sk_error *err);

/* Checks that an image passed to a writer is well formed. */
sk_result sk__image_validate(const sk_image *image, sk_error *err);

/* Adds an entry found in a file: the key and value are truncated to fit (at a UTF-8
 * boundary) and entries beyond SK_IMAGE_MAX_METADATA are dropped, so that an image with
 * long comments still loads. */
void sk__image_metadata_add_read(sk_image_metadata *meta, const char *key, size_t key_len,
                                 const char *value, size_t value_len);

/* The sRGB curve in double precision (see sk_srgb_from_linear / sk_linear_from_srgb). */
double sk__srgb_encode(double linear);
double sk__srgb_decode(double encoded);

#endif
