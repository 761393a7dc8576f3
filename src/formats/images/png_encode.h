/* The PNG encoder behind sk_image_write_png, writing to any byte sink (private). */
#ifndef SK_IO_PNG_ENCODE_H
#define SK_IO_PNG_ENCODE_H

#include <stdbool.h>
#include <stddef.h>

#include "shitsukan/image.h"

/* Where the encoded bytes go, in order; `write` returns false on failure. */
typedef struct sk__png_sink {
    bool (*write)(void *context, const void *data, size_t size);
    void *context;
} sk__png_sink;

/* Encodes `image` as a PNG into `sink` (desc may be NULL: sk_png_write_desc's defaults).
 * `name` labels error messages (a path, or e.g. "texture"). Bad arguments are reported
 * before anything is written; a failing sink gives SK_ERROR_IO. */
sk_result sk__png_encode(const sk_image *image, const sk_png_write_desc *desc, sk__png_sink *sink,
                         const char *name, sk_error *err);

#endif
